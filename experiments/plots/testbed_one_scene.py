"""One scene, many solvers (experiments/testbed_one_scene.yaml): each run's final
surface against the committed LIGGGHTS run of the same scene (data/dem_indent,
found from this script's place in the repository). testbed.csv: per solver
the RMSE of the final surface and of the change dh = final - initial, and R^2
of dh, over the cells one grain (REGION_CELLS) in from the walls; testbed.png:
the LIGGGHTS dh and each solver's dh on one colour scale.
Usage: python3 testbed_one_scene.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "dem_indent")
REGION_CELLS = 2   # 2 cells of 4 mm: one grain diameter from the walls, where the bed is disturbed by them


def change(folder):
    h0 = np.load(os.path.join(folder, "height_initial.npy"))
    h1 = np.load(os.path.join(folder, "height_final.npy"))
    r = REGION_CELLS
    return h1[r:-r, r:-r], (h1 - h0)[r:-r, r:-r]


def scores(final, dh, ref_final, ref_dh):
    rmse = float(np.sqrt(np.mean((final - ref_final) ** 2)))
    rmse_dh = float(np.sqrt(np.mean((dh - ref_dh) ** 2)))
    total = float(np.sum((ref_dh - ref_dh.mean()) ** 2))
    r2 = 1.0 - float(np.sum((dh - ref_dh) ** 2)) / total if total > 0 else float("nan")
    return rmse, rmse_dh, r2


def main():
    folder = sys.argv[1]
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    ref_final, ref_dh = change(REFERENCE)
    fields = {"liggghts (data/dem_indent)": ref_dh}
    with open(os.path.join(folder, "testbed.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["solver", "wall_s", "rmse_final_m", "rmse_dh_m", "r2_dh"])
        for row in rows:
            final, dh = change(os.path.join(folder, row["name"]))
            rmse, rmse_dh, r2 = scores(final, dh, ref_final, ref_dh)
            out.writerow([row["solver"], row["wall_s"], f"{rmse:.6g}", f"{rmse_dh:.6g}", f"{r2:.4g}"])
            fields[row["solver"]] = dh
    limit = max(float(np.abs(v).max()) for v in fields.values()) * 1e3 or 1.0
    fig, axes = plt.subplots(1, len(fields), figsize=(2.6 * len(fields), 2.8), squeeze=False)
    for ax, (name, dh) in zip(axes[0], fields.items()):
        image = ax.imshow(1e3 * dh, origin="lower", cmap="RdBu_r", vmin=-limit, vmax=limit)
        ax.set_title(name, fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.colorbar(image, ax=list(axes[0]), fraction=0.02, label="height change (mm)")
    save(fig, folder, "testbed.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
