"""Figures of a calibration run folder (written by `repose calibrate`).

usage: MPLBACKEND=Agg /usr/bin/python3 calibration_figures.py RUN_DIR

Reads RUN_DIR/calibration.json and RUN_DIR/data/ and writes into RUN_DIR:
  maps_SCENE.png       reference, fitted heuristic and their difference (mm)
  transects_SCENE.png  height profiles along the scene's transects
  cost.png             cost against iteration for every start of the fit
  ladder.png           the speed/accuracy ladder: wall time against surface RMSE
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from figure_output import save  # noqa: E402


def load(run_dir, name):
    return np.load(os.path.join(run_dir, "data", name))


def maps(run_dir, scene):
    name = scene["name"]
    reference = load(run_dir, f"{name}_reference.npy") * 1e3
    fitted = load(run_dir, f"{name}_heuristic_fitted.npy") * 1e3
    diff = fitted - reference
    lo, hi = min(reference.min(), fitted.min()), max(reference.max(), fitted.max())
    fig, axes = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
    for ax, field, title in ((axes[0], reference, "reference"), (axes[1], fitted, "heuristic (fitted)")):
        im = ax.imshow(field, origin="lower", vmin=lo, vmax=hi, cmap="viridis")
        ax.set_title(f"{name}: {title}")
        fig.colorbar(im, ax=ax, label="height (mm)")
    m = max(abs(diff.min()), abs(diff.max()), 1e-9)
    im = axes[2].imshow(diff, origin="lower", vmin=-m, vmax=m, cmap="RdBu_r")
    axes[2].set_title(f"heuristic - reference (RMSE {scene['rmse_fitted_m'] * 1e3:.2f} mm)")
    fig.colorbar(im, ax=axes[2], label="difference (mm)")
    for ax in axes:
        ax.set_xlabel("cell i (x)")
        ax.set_ylabel("cell j (y)")
    out = f"maps_{name}.png"
    save(fig, run_dir, out, dpi=110)
    plt.close(fig)


def transects(run_dir, scene):
    name = scene["name"]
    files = sorted(f for f in os.listdir(os.path.join(run_dir, "data")) if f.startswith(f"{name}_transect_"))
    if not files:
        return
    fig, axes = plt.subplots(len(files), 1, figsize=(8, 3.2 * len(files)), squeeze=False, constrained_layout=True)
    for ax, f in zip(axes[:, 0], files):
        with open(os.path.join(run_dir, "data", f)) as fh:
            rows = list(csv.DictReader(fh))
        s = [float(r["distance_m"]) * 1e3 for r in rows]
        if rows and "reference_seed_min_m" in rows[0]:
            ax.fill_between(s, [float(r["reference_seed_min_m"]) * 1e3 for r in rows],
                            [float(r["reference_seed_max_m"]) * 1e3 for r in rows], color="0.85",
                            label="reference, range of its seeds")
        for key, label, style in (("start_m", "start", ":"), ("reference_m", "reference (mean of seeds)", "-"),
                                  ("heuristic_initial_m", "heuristic, initial parameters", "--"),
                                  ("heuristic_fitted_m", "heuristic, fitted", "-")):
            ax.plot(s, [float(r[key]) * 1e3 for r in rows], style, label=label)
        r0, r1 = rows[0], rows[-1]
        ax.set_title(f"{name}: ({float(r0['x_m']):.3f}, {float(r0['y_m']):.3f}) to "
                     f"({float(r1['x_m']):.3f}, {float(r1['y_m']):.3f}) m")
        ax.set_xlabel("distance along the transect (mm)")
        ax.set_ylabel("height (mm)")
        ax.legend(fontsize=8)
    save(fig, run_dir, f"transects_{name}.png", dpi=110)
    plt.close(fig)


def cost(run_dir, calibration):
    fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
    for k, start in enumerate(calibration["starts"]):
        c = start["cost_per_iteration"]
        best = " (best)" if k == calibration["best_start"] else ""
        ax.semilogy(range(len(c)), c, "o-", ms=3, label=f"start {k}{best}")
    ax.set_xlabel("iteration")
    ax.set_ylabel("cost (0.5 sum of squared residuals)")
    ax.set_title("Levenberg-Marquardt cost per start")
    ax.legend(fontsize=8)
    save(fig, run_dir, "cost.png", dpi=110)
    plt.close(fig)


def ladder(run_dir, calibration):
    lad = calibration.get("ladder")
    if not lad:
        return
    fig, ax = plt.subplots(figsize=(8, 4.8), constrained_layout=True)
    markers = {"ground": "o", "ground-multires": "s", "liggghts": "^", "bullet": "v", "ode": "D"}
    # every rung at its measured (time, error); numbered on the plot, named in the legend
    for n, r in enumerate(lad["rungs"], start=1):
        t = r["cpu_time_s"] if r.get("cpu_time_s") is not None else r["wall_time_s"]
        ax.loglog([t], [r["rmse_m"] * 1e3], markers.get(r["kind"], "x"), label=f"{n}: {r['label']}")
        ax.annotate(str(n), (t, r["rmse_m"] * 1e3), fontsize=8, xytext=(4, 3), textcoords="offset points")
    if lad.get("noise_floor_m") is not None:
        # the band reaches down past every rung: below its top, a rung is as close as another DEM run
        noise = lad["noise_floor_m"] * 1e3
        low = 0.7 * min([noise] + [r["rmse_m"] * 1e3 for r in lad["rungs"] if r["rmse_m"] > 0])
        ax.axhspan(low, noise, color="0.85", zorder=0, label=f"within the reference's noise floor ({noise:.2f} mm, seed to seed)")
        ax.set_ylim(bottom=low)
    ax.set_xlabel("CPU time (s)")
    ax.set_ylabel("RMSE of the surface change against the reference (mm)")
    ax.set_title(f"speed/accuracy ladder: {lad['scene']}\n(reference: {lad['yardstick']})", fontsize=9)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    save(fig, run_dir, "ladder.png", dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run_dir = sys.argv[1]
    with open(os.path.join(run_dir, "calibration.json")) as fh:
        calibration = json.load(fh)
    for scene in calibration["scenes"]:
        maps(run_dir, scene)
        transects(run_dir, scene)
    cost(run_dir, calibration)
    ladder(run_dir, calibration)


if __name__ == "__main__":
    main()
