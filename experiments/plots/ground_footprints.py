"""The final images of every run of experiments/ground_footprints.yaml side by
side (footprints.png), with a height-change map per run (footprint_changes.png).
Usage: python3 ground_footprints.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import math
import os
import sys

import matplotlib.image as mpimg
import matplotlib.pyplot as plt
import numpy as np
from figure_output import save


def run_names(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        return [row["name"] for row in csv.DictReader(f)]


def grid_figure(count):
    cols = min(4, count)
    rows = math.ceil(count / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 2.8 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    return fig, axes.flat


def main():
    folder = sys.argv[1]
    names = run_names(folder)
    fig, axes = grid_figure(len(names))
    for ax, name in zip(axes, names):
        ax.imshow(mpimg.imread(os.path.join(folder, name, "height_final.png")))
        ax.set_title(name, fontsize=9)
    fig.tight_layout()
    save(fig, folder, "footprints.png", dpi=110)
    plt.close(fig)

    fig, axes = grid_figure(len(names))
    for ax, name in zip(axes, names):
        h0 = np.load(os.path.join(folder, name, "height_initial.npy"))
        h1 = np.load(os.path.join(folder, name, "height_final.npy"))
        change = 1e3 * (h1 - h0)
        limit = max(1e-9, np.abs(change).max())
        image = ax.imshow(change, origin="lower", cmap="RdBu_r", vmin=-limit, vmax=limit)
        ax.set_title(f"{name}: change (mm)", fontsize=9)
        fig.colorbar(image, ax=ax, fraction=0.046)
    fig.tight_layout()
    save(fig, folder, "footprint_changes.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
