"""Tensile tests along (MD) and across (CD) the grain
(experiments/tearing_tensile.yaml): tearing_tensile.csv (per direction and
measure: mean and standard deviation over seeds, and the MD/CD ratio of the
means) and tearing_tensile.png (each seed's force-strain curve).
Usage: python3 tearing_tensile.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

MEASURES = ("tensile.stiffness_n_per_m", "tensile.strength_n_per_m", "tensile.strain_at_peak")


def main():
    folder = sys.argv[1]
    rows = {"md": [], "cd": []}
    with open(os.path.join(folder, "summary.csv")) as f:
        for row in csv.DictReader(f):
            rows[row["name"].rsplit("_", 1)[0]].append(row)
    with open(os.path.join(folder, "tearing_tensile.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["measure", "md_mean", "md_std", "cd_mean", "cd_std", "md_over_cd", "seeds"])
        for m in MEASURES:
            md = np.array([float(r[m]) for r in rows["md"]])
            cd = np.array([float(r[m]) for r in rows["cd"]])
            out.writerow([m, f"{md.mean():.6g}", f"{md.std(ddof=1):.3g}", f"{cd.mean():.6g}", f"{cd.std(ddof=1):.3g}",
                          f"{md.mean() / cd.mean():.4g}", len(md)])
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for direction, colour in (("md", "C0"), ("cd", "C1")):
        for k, r in enumerate(rows[direction]):
            path = os.path.join(folder, r["name"], "tensile.csv")
            if not os.path.exists(path):
                continue
            data = np.genfromtxt(path, delimiter=",", names=True)
            ax.plot(100 * data["strain"], 1e-3 * data["force_per_width_n_per_m"], color=colour, lw=0.8,
                    label=direction.upper() if k == 0 else None)
    ax.set_xlabel("strain (%)")
    ax.set_ylabel("force per width (kN/m)")
    ax.legend()
    fig.tight_layout()
    save(fig, folder, "tearing_tensile.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
