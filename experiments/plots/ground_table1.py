"""Table 1 of the ground paper from an experiment folder (experiments/ground_table1.yaml).

Writes table1.csv (time per frame, the paper's, the ratios, the streak
statistics), table1.png (time per frame against the paper's) and streaks.png
(the final surface along the sphere's path for each case).
Usage: python3 ground_table1.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

PAPER_MS = {"no_sweep": 22.1, "substeps_10": 220.5, "sweep": 26.5}
LABELS = {"no_sweep": "no sweep", "substeps_10": "10 substeps", "sweep": "sweep"}


def read_summary(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        return {row["name"]: row for row in csv.DictReader(f)}


def write_table(folder, rows):
    ms = {name: 1e3 * float(rows[name]["step_wall_s_median"]) for name in PAPER_MS}
    with open(os.path.join(folder, "table1.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["case", "ms_per_frame", "paper_ms", "ours_over_paper", "over_no_sweep", "substeps_over_this",
                      "paper_over_no_sweep", "streak_rms_m", "streak_range_m", "streak_ridges"])
        for name in PAPER_MS:
            out.writerow([name, f"{ms[name]:.4f}", PAPER_MS[name], f"{ms[name] / PAPER_MS[name]:.4f}",
                          f"{ms[name] / ms['no_sweep']:.3f}", f"{ms['substeps_10'] / ms[name]:.3f}",
                          f"{PAPER_MS[name] / PAPER_MS['no_sweep']:.3f}", rows[name]["streaks.ball.rms_m"],
                          rows[name]["streaks.ball.range_m"], rows[name]["streaks.ball.ridges"]])
    return ms


def plot_times(folder, ms):
    names = list(PAPER_MS)
    x = np.arange(len(names))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.bar(x - 0.2, [ms[n] for n in names], 0.4, label="repose (this machine)")
    ax.bar(x + 0.2, [PAPER_MS[n] for n in names], 0.4, label="paper")
    ax.set_xticks(x, [LABELS[n] for n in names])
    ax.set_yscale("log")
    ax.set_ylabel("time per frame (ms)")
    ax.set_title("Sphere dragged 10 cells per frame (Table 1)")
    ax.legend()
    fig.tight_layout()
    save(fig, folder, "table1.png", dpi=120)
    plt.close(fig)


def plot_profiles(folder):
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for name in PAPER_MS:
        h = np.load(os.path.join(folder, name, "height_final.npy"))
        ny, nx = h.shape
        # the path runs along y = 0, between the two middle rows of the grid
        row = 0.5 * (h[ny // 2 - 1] + h[ny // 2])
        ax.plot(np.arange(nx), 1e3 * row, label=LABELS[name], lw=1)
    ax.set_xlabel("cell along the drag")
    ax.set_ylabel("final height on the path (mm)")
    ax.set_title("Streaks: the furrow floor along the path")
    ax.legend()
    fig.tight_layout()
    save(fig, folder, "streaks.png", dpi=120)
    plt.close(fig)


def main():
    folder = sys.argv[1]
    rows = read_summary(folder)
    ms = write_table(folder, rows)
    plot_times(folder, ms)
    plot_profiles(folder)


if __name__ == "__main__":
    main()
