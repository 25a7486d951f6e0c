"""Paper torn across against along the grain (experiments/tearing_grain.yaml):
tearing_grain.csv (per grain and quantity: mean, standard deviation over
seeds, and in how many seeds across exceeds along, paired by seed) and
tearing_grain.png (each seed's pair joined by a line).
Usage: python3 tearing_grain.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

QUANTITIES = (("tear.tortuosity", "tortuosity", 1.0), ("tear.roughness_m", "roughness (mm)", 1e3),
              ("grip.peak_force_n", "peak grip force (N)", 1.0))
GRAINS = ("across", "along")


def by_seed(folder):
    """{grain: {seed: row}} from summary.csv (runs across_<seed>, along_<seed>)."""
    runs = {g: {} for g in GRAINS}
    with open(os.path.join(folder, "summary.csv")) as f:
        for row in csv.DictReader(f):
            grain, seed = row["name"].rsplit("_", 1)
            if grain in runs:
                runs[grain][int(seed)] = row
    return runs


def main():
    folder = sys.argv[1]
    runs = by_seed(folder)
    seeds = sorted(set(runs["across"]) & set(runs["along"]))
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(11, 3.6))
    with open(os.path.join(folder, "tearing_grain.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["quantity", "across_mean", "across_std", "along_mean", "along_std", "across_larger", "seeds"])
        for ax, (key, label, scale) in zip(axes, QUANTITIES):
            across = np.array([float(runs["across"][s][key]) for s in seeds])
            along = np.array([float(runs["along"][s][key]) for s in seeds])
            out.writerow([key, f"{across.mean():.6g}", f"{across.std(ddof=1):.6g}", f"{along.mean():.6g}",
                          f"{along.std(ddof=1):.6g}", int((across > along).sum()), len(seeds)])
            for a, b in zip(across, along):
                ax.plot([0, 1], [scale * a, scale * b], "o-", color="0.5", lw=0.8, ms=3)
            ax.set_xticks([0, 1], ["across", "along"])
            ax.set_xlim(-0.4, 1.4)
            ax.set_ylabel(label)
    fig.suptitle(f"Tearing across and along the grain, {len(seeds)} seeds (paired)")
    fig.tight_layout()
    save(fig, folder, "tearing_grain.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
