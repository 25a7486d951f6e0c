"""Full against half resolution contact (experiments/ground_multires.yaml):
multires.csv (median step time of each, the speed ratio, the RMSE and the
largest difference of the final heights on the fine grid) and multires.png
(the two final fields and their difference).
Usage: python3 ground_multires.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

FULL, HALF = "simple_false", "simple_true"


def main():
    folder = sys.argv[1]
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = {row["name"]: row for row in csv.DictReader(f)}
    full = np.load(os.path.join(folder, FULL, "height_final.npy"))
    half = np.load(os.path.join(folder, HALF, "height_final.npy"))
    diff = half - full
    rmse = float(np.sqrt(np.mean(diff ** 2)))
    # over the cells either run changed: the contact's own error, not diluted by the untouched field
    initial = np.load(os.path.join(folder, FULL, "height_initial.npy"))
    changed = (full != initial) | (half != initial)
    rmse_changed = float(np.sqrt(np.mean(diff[changed] ** 2))) if changed.any() else 0.0
    t_full = float(rows[FULL]["step_wall_s_median"])
    t_half = float(rows[HALF]["step_wall_s_median"])
    with open(os.path.join(folder, "multires.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["step_ms_full", "step_ms_half", "speed_ratio", "rmse_m", "rmse_changed_cells_m",
                      "max_abs_diff_m", "changed_cells"])
        out.writerow([f"{1e3 * t_full:.4f}", f"{1e3 * t_half:.4f}", f"{t_full / t_half:.3f}", f"{rmse:.6g}",
                      f"{rmse_changed:.6g}", f"{float(np.abs(diff).max()):.6g}", int(changed.sum())])

    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    limit = max(1e-9, float(np.abs(diff).max()))
    for ax, field, title in ((axes[0], full, "full resolution"), (axes[1], half, "half resolution")):
        image = ax.imshow(1e3 * field, origin="lower", cmap="viridis")
        ax.set_title(f"{title}: height (mm)")
        fig.colorbar(image, ax=ax, fraction=0.046)
    image = axes[2].imshow(1e3 * diff, origin="lower", cmap="RdBu_r", vmin=-1e3 * limit, vmax=1e3 * limit)
    axes[2].set_title(f"half - full (mm), RMSE {1e3 * rmse:.3f} mm")
    fig.colorbar(image, ax=axes[2], fraction=0.046)
    fig.tight_layout()
    save(fig, folder, "multires.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
