"""Angle of repose against rolling friction (experiments/dem_repose_angle.yaml).

usage: python3 dem_repose_angle.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (runs mu_r_<value>) and each run's
pile_flank_angles.csv; writes dem_repose_angle.png (mean +- standard
deviation over azimuths, and every azimuth's angle) and
dem_repose_angle.csv (rolling friction, mean, std, azimuth count).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_output import save  # noqa: E402


def sweep_value(name):
    return float(name.rsplit("_", 1)[1])


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["name"].startswith("mu_r_")]
    rows.sort(key=lambda r: sweep_value(r["name"]))
    if not rows:
        sys.exit("dem_repose_angle: summary.csv has no mu_r_* runs")
    mu, mean, std, count = [], [], [], []
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for r in rows:
        m = sweep_value(r["name"])
        angles = []
        with open(os.path.join(folder, r["name"], "pile_flank_angles.csv")) as f:
            angles = [float(a["angle_deg"]) for a in csv.DictReader(f)]
        ax.scatter([m] * len(angles), angles, s=8, color="0.6", zorder=1)
        mu.append(m)
        mean.append(float(r["pile.flank_angle_mean_deg"]))
        std.append(float(r["pile.flank_angle_std_deg"]))
        count.append(len(angles))
    ax.errorbar(mu, mean, yerr=std, fmt="o-", color="C0", capsize=4, zorder=2,
                label="mean $\\pm$ std over azimuths")
    ax.scatter([], [], s=8, color="0.6", label="each azimuth")
    ax.set_xlabel("rolling friction coefficient $\\mu_r$ (cdt)")
    ax.set_ylabel("pile flank angle (deg)")
    ax.set_title("DEM angle of repose: cylinder of ~1,500 grains released")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    save(fig, folder, "dem_repose_angle.png", dpi=130)
    with open(os.path.join(folder, "dem_repose_angle.csv"), "w") as f:
        f.write("rolling_friction,flank_angle_mean_deg,flank_angle_std_deg,azimuth_count\n")
        for row in zip(mu, mean, std, count):
            f.write("{},{},{},{}\n".format(*row))
    for row in zip(mu, mean, std):
        print("mu_r = {:.3g}: {:.1f} +- {:.1f} deg".format(*row))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
