"""Angle of repose against rolling friction (experiments/dem_repose_angle.yaml,
experiments/dem_repose_angle_engines.yaml).

usage: python3 dem_repose_angle.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (runs mu_r_<value>, each name optionally
after a prefix such as bullet_) and each run's pile_flank_angles.csv;
writes dem_repose_angle.png (per solver, the summary's solver column: mean
+- standard deviation over azimuths, and every azimuth's angle) and
dem_repose_angle.csv (solver, rolling friction, mean, std, azimuth count).
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_output import save  # noqa: E402

RUN = re.compile(r"(^|_)mu_r_([-+0-9.eE]+)$")
ORDER = ["liggghts", "bullet", "ode"]
LABEL = {"liggghts": "LIGGGHTS", "bullet": "Bullet", "ode": "ODE"}


def sweep_value(name):
    return float(RUN.search(name).group(2))


def solvers_of(rows):
    present = {r["solver"] for r in rows}
    return sorted(present, key=lambda e: (ORDER.index(e) if e in ORDER else len(ORDER), e))


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = [r for r in csv.DictReader(f) if RUN.search(r["name"])]
    rows.sort(key=lambda r: sweep_value(r["name"]))
    if not rows:
        sys.exit("dem_repose_angle: summary.csv has no mu_r_* runs")
    table = []
    fig, ax = plt.subplots(figsize=(6, 4.2))
    solvers = solvers_of(rows)
    for index, solver in enumerate(solvers):
        mu, mean, std = [], [], []
        for r in (r for r in rows if r["solver"] == solver):
            m = sweep_value(r["name"])
            with open(os.path.join(folder, r["name"], "pile_flank_angles.csv")) as f:
                angles = [float(a["angle_deg"]) for a in csv.DictReader(f)]
            ax.scatter([m] * len(angles), angles, s=8, color="C{}".format(3 * index), alpha=0.3, zorder=1)
            mu.append(m)
            mean.append(float(r["pile.flank_angle_mean_deg"]))
            std.append(float(r["pile.flank_angle_std_deg"]))
            table.append((solver, m, mean[-1], std[-1], len(angles)))
        label = "mean $\\pm$ std over azimuths"
        if len(solvers) > 1:
            label = "{}: {}".format(LABEL.get(solver, solver), label)
        ax.errorbar(mu, mean, yerr=std, fmt="o-", color="C{}".format(3 * index), capsize=4, zorder=2, label=label)
    ax.scatter([], [], s=8, color="0.6", label="each azimuth")
    ax.set_xlabel("rolling friction coefficient $\\mu_r$ (cdt)")
    ax.set_ylabel("pile flank angle (deg)")
    engines = ", ".join(LABEL.get(s, s) for s in solvers)
    ax.set_title("Angle of repose ({}): cylinder of ~1,500 grains released".format(engines), fontsize=10)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    save(fig, folder, "dem_repose_angle.png", dpi=130)
    with open(os.path.join(folder, "dem_repose_angle.csv"), "w") as f:
        f.write("solver,rolling_friction,flank_angle_mean_deg,flank_angle_std_deg,azimuth_count\n")
        for row in table:
            f.write("{},{},{},{},{}\n".format(*row))
    for row in table:
        print("{}: mu_r = {:.3g}: {:.1f} +- {:.1f} deg".format(*row[:4]))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
