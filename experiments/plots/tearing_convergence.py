"""The tear under mesh refinement (experiments/tearing_convergence.yaml):
tearing_convergence.csv (per rule and cell count: work per unit tear length,
peak grip force, path deviation and tortuosity, and each measure's change
from the previous mesh in percent) and tearing_convergence.png (the measures
against the cell size, one line per rule).
Usage: python3 tearing_convergence.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
from figure_output import save

WIDTH_M = 0.1  # scenes/tearing_convergence.yaml
QUANTITIES = (("tear.work_per_length_j_per_m", "work per tear length (J/m)", 1.0),
              ("grip.peak_force_n", "peak grip force (N)", 1.0),
              ("tear.deviation_m", "path deviation (mm)", 1e3),
              ("tear.tortuosity", "tortuosity", 1.0))


def by_rule(folder):
    """{rule: [(cells, row), ...]} sorted by cells, from summary.csv (runs <rule>_<cells>)."""
    runs = {}
    with open(os.path.join(folder, "summary.csv")) as f:
        for row in csv.DictReader(f):
            rule, cells = row["name"].rsplit("_", 1)
            runs.setdefault(rule, []).append((int(cells), row))
    return {rule: sorted(rows, key=lambda r: r[0]) for rule, rows in runs.items()}


def main():
    folder = sys.argv[1]
    runs = by_rule(folder)
    with open(os.path.join(folder, "tearing_convergence.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["rule", "cells", "cell_mm"] + [q for q, _, _ in QUANTITIES] +
                     [q + "_change_pct" for q, _, _ in QUANTITIES] + ["wall_s", "simulated_time_s"])
        for rule, rows in runs.items():
            previous = None
            for cells, row in rows:
                values = [float(row[q]) for q, _, _ in QUANTITIES]
                changes = ["" if previous is None or previous[i] == 0 else
                           f"{100 * (v / previous[i] - 1):.1f}" for i, v in enumerate(values)]
                out.writerow([rule, cells, f"{1e3 * WIDTH_M / cells:.3g}"] + [f"{v:.6g}" for v in values] +
                             changes + [row["wall_s"], row["simulated_time_s"]])
                previous = values
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(13, 3.4))
    for ax, (key, label, scale) in zip(axes, QUANTITIES):
        for rule, rows in runs.items():
            ax.plot([1e3 * WIDTH_M / c for c, _ in rows], [scale * float(r[key]) for _, r in rows], "o-", label=rule)
        ax.set_xscale("log")
        ax.set_xlabel("cell size (mm)")
        ax.set_ylabel(label)
    axes[0].legend(title="tear rule")
    fig.suptitle("The same tear on finer meshes: the seed's strain limit against the energy limit")
    fig.tight_layout()
    save(fig, folder, "tearing_convergence.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
