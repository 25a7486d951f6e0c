"""Snow probability against the number of directions
(experiments/snow_convergence.yaml): convergence.csv (N, RMS and largest
error of P against the N = 1024 run, per snow map, over all its cells)
and convergence.png (log-log, with the 1/sqrt(N) line).
Usage: python3 snow_convergence.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

REFERENCE = 1024
MAPS = ("ground", "table")


def load(folder, n, name):
    return np.load(os.path.join(folder, f"directions_{n}", f"snow_probability.{name}.npy"))


def main():
    folder = sys.argv[1]
    counts = sorted(int(d.split("_")[1]) for d in os.listdir(folder) if d.startswith("directions_"))
    counts = [n for n in counts if n != REFERENCE]
    rows = []
    for n in counts:
        row = {"directions": n}
        for name in MAPS:
            diff = load(folder, n, name) - load(folder, REFERENCE, name)
            row[f"rms_{name}"] = float(np.sqrt(np.mean(diff ** 2)))
            row[f"max_{name}"] = float(np.abs(diff).max())
        rows.append(row)
    with open(os.path.join(folder, "convergence.csv"), "w", newline="") as f:
        out = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        out.writeheader()
        for row in rows:
            out.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})
    fig, ax = plt.subplots(figsize=(5, 4))
    for name in MAPS:
        ax.loglog(counts, [r[f"rms_{name}"] for r in rows], "o-", label=f"{name}: RMS error")
    first = rows[0]["rms_ground"]
    ax.loglog(counts, [first * (counts[0] / n) ** 0.5 for n in counts], "k--", label="1/sqrt(N)")
    ax.set_xlabel("snowfall directions N")
    ax.set_ylabel(f"error of P against N = {REFERENCE}")
    ax.legend()
    fig.tight_layout()
    save(fig, folder, "convergence.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
