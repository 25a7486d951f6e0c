"""The speed/accuracy ladder of the tearing sheet (experiments/tearing_ladder.yaml):
tearing_ladder.csv (per rung: integrator, step, cells, CPU and wall time per
simulated second, work per unit tear length, peak grip force, and their
errors against the yardstick, and the tear path's RMS distance from the
yardstick's) and tearing_ladder.png (each rung at its (CPU time per
simulated second, error), one panel per error).

The yardstick is the run named YARDSTICK (the explicit integrator on the
finest mesh; the experiment file says why); without it (a partial run) the
finest explicit run stands in, and the CSV and the figure say so.
The path is the tear's 8-connected set of torn cells (the largest; the notch
counts) from torn_time_s.npy, one point per row of cells (its centroid), as
models/tearing/tear_path.h measures it; a rung's path error is the RMS over
its rows of the distance to the yardstick's path averaged over the same
band of y, on the rows both tears reach.
Usage: python3 tearing_ladder.py RUN_FOLDER (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from figure_output import save
from matplotlib.ticker import FuncFormatter
from scipy import ndimage

WIDTH_M = 0.1  # scenes/tearing_convergence.yaml
YARDSTICK = "explicit_200"
LADDERS = {"explicit": ("explicit", "o-"), "implicit": ("implicit", "s-"), "implicit_dt1": ("implicit", "^--")}


def rungs(folder):
    """[(name, ladder, cells, row)] from summary.csv, runs named <ladder>_<cells>."""
    out = []
    with open(os.path.join(folder, "summary.csv")) as f:
        for row in csv.DictReader(f):
            ladder, cells = row["name"].rsplit("_", 1)
            out.append((row["name"], ladder, int(cells), row))
    return sorted(out, key=lambda r: (r[1], r[2]))


def tear_path(folder, name):
    """(y, x) in m of the tear's centroid per row of cells, top row first."""
    torn = np.load(os.path.join(folder, name, "torn_time_s.npy")) >= 0.0
    labels, count = ndimage.label(torn, structure=np.ones((3, 3)))
    if count == 0:
        return np.zeros(0), np.zeros(0)
    sizes = ndimage.sum(torn, labels, index=range(1, count + 1))
    tear = labels == 1 + int(np.argmax(sizes))
    h = WIDTH_M / torn.shape[1]
    rows = [j for j in range(torn.shape[0]) if tear[j].any()][::-1]
    return (np.array([(j + 0.5) * h for j in rows]),
            np.array([(np.flatnonzero(tear[j]).mean() + 0.5) * h for j in rows]))


def path_rms_m(path, reference, cell_m):
    """RMS distance of path from reference over the rows both reach (m); None when none."""
    y, x = path
    y_ref, x_ref = reference
    differences = []
    for yj, xj in zip(y, x):
        band = np.abs(y_ref - yj) <= 0.5 * cell_m + 1e-12
        if band.any():
            differences.append(xj - x_ref[band].mean())
    return float(np.sqrt(np.mean(np.square(differences)))) if differences else None


def path_rms_mm(path, reference, cell_m):
    rms = path_rms_m(path, reference, cell_m)
    return float("nan") if rms is None else 1e3 * rms


def relative_error(value, reference):
    return abs(value / reference - 1.0) if reference != 0.0 else float("nan")


def table(folder, runs, yardstick):
    _, _, _, ref = yardstick
    reference_path = tear_path(folder, yardstick[0])
    rows = []
    for name, ladder, cells, row in runs:
        f = lambda key: float(row[key])  # noqa: E731
        rows.append({
            "rung": name, "integrator": LADDERS.get(ladder, (ladder,))[0],
            "step_over_stable": f"{f('time_step_s') / f('stable_time_step_s'):.3g}",
            "cells": cells, "cell_mm": f"{1e3 * WIDTH_M / cells:.3g}", "steps": int(f("steps")),
            "simulated_time_s": f"{f('simulated_time_s'):.4g}", "run_cpu_s": f"{f('run_cpu_s'):.4g}",
            "run_wall_s": f"{f('run_wall_s'):.4g}",
            "cpu_s_per_simulated_s": f"{f('cpu_s_per_simulated_s'):.4g}",
            "wall_s_per_simulated_s": f"{f('wall_s_per_simulated_s'):.4g}",
            "work_per_length_j_per_m": f"{f('tear.work_per_length_j_per_m'):.4g}",
            "work_error": relative_error(f("tear.work_per_length_j_per_m"), float(ref["tear.work_per_length_j_per_m"])),
            "peak_force_n": f"{f('grip.peak_force_n'):.4g}",
            "peak_force_error": relative_error(f("grip.peak_force_n"), float(ref["grip.peak_force_n"])),
            "path_rms_mm": path_rms_mm(tear_path(folder, name), reference_path, WIDTH_M / cells),
            "deviation_mm": f"{1e3 * f('tear.deviation_m'):.3g}",
            "yardstick": name == yardstick[0]})
    return rows


def write_csv(folder, rows, yardstick_note):
    with open(os.path.join(folder, "tearing_ladder.csv"), "w", newline="") as f:
        f.write(f"# errors against {yardstick_note}\n")
        out = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        out.writeheader()
        for row in rows:
            out.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in row.items()})


def label(row):
    step = "" if row["integrator"] == "explicit" else f", dt {row['step_over_stable']}x stable"
    return f"{row['integrator']} {row['cells']}$^2${step}"


def figure(folder, rows, runs, yardstick_note):
    panels = (("work_error", "work per tear length: |relative error| (%)", 100.0, "log"),
              ("peak_force_error", "peak grip force: |relative error| (%)", 100.0, "log"),
              ("path_rms_mm", "tear path: RMS distance from the yardstick's (mm)", 1.0, "linear"))
    fig, axes = plt.subplots(1, len(panels), figsize=(15, 4.6))
    by_ladder = {}
    for (name, ladder, _, _), row in zip(runs, rows):
        by_ladder.setdefault(ladder, []).append(row)
    for ax, (key, ylabel, scale, yscale) in zip(axes, panels):
        for ladder, group in by_ladder.items():
            points = [(float(r["cpu_s_per_simulated_s"]), scale * r[key], r) for r in group
                      if not r["yardstick"] and np.isfinite(r[key]) and (yscale == "linear" or r[key] > 0.0)]
            if not points:
                continue
            style = LADDERS.get(ladder, (ladder, "x-"))[1]
            ax.plot([p[0] for p in points], [p[1] for p in points], style, label=label(points[0][2]).split(" ")[0] +
                    ("" if ladder == "explicit" else f" (dt {points[0][2]['step_over_stable']}x stable)"))
            for x, y, r in points:
                ax.annotate(f"{r['cells']}$^2$", (x, y), fontsize=8, xytext=(4, 3), textcoords="offset points")
        for r in rows:
            if r["yardstick"]:
                ax.axvline(float(r["cpu_s_per_simulated_s"]), color="0.5", ls=":", label=f"yardstick ({label(r)})")
        ax.set_xscale("log")
        ax.set_yscale(yscale)
        ax.set_xlabel("CPU time per simulated second (s/s)")
        ax.set_ylabel(ylabel)
        if yscale == "linear":
            ax.set_ylim(bottom=0.0)
        else:
            # plain numbers; the minor ticks labelled too when the axis spans less than a decade
            plain = FuncFormatter(lambda v, _: f"{v:g}")
            ax.yaxis.set_major_formatter(plain)
            low, high = ax.get_ylim()
            if high < 10.0 * low:
                ax.yaxis.set_minor_formatter(plain)
    if all(float(r["deviation_mm"]) == 0.0 for r in rows):
        axes[-1].set_title("every tear ran straight down: the distance is\nwhere each mesh puts the notch's column", fontsize=9)
    axes[0].legend(fontsize=8)
    fig.suptitle("The tearing sheet's speed/accuracy ladder (the seed's twist, seed 1, energy tear rule; "
                 f"errors against {yardstick_note})", fontsize=10)
    fig.tight_layout()
    save(fig, folder, "tearing_ladder.png", dpi=110)
    plt.close(fig)


def main():
    folder = sys.argv[1]
    runs = rungs(folder)
    finest = [r for r in runs if r[0] == YARDSTICK]
    note = "the explicit run on the finest mesh"
    if not finest:
        finest = [max((r for r in runs if r[1] == "explicit"), key=lambda r: r[2])]
        note = f"{finest[0][0]}, standing in for the missing {YARDSTICK}"
    yardstick = finest[0]
    note = f"{yardstick[0]} ({note})" if yardstick[0] == YARDSTICK else note
    rows = table(folder, runs, yardstick)
    write_csv(folder, rows, note)
    figure(folder, rows, runs, note)


if __name__ == "__main__":
    main()
