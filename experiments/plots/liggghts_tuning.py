"""LIGGGHTS speed against its settings (experiments/liggghts_tuning.yaml).

usage: python3 liggghts_tuning.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv and each run's liggghts_manifest.json and
height_final.npy. Per run: particle-steps per CPU second, simulated time per
CPU second, each as a ratio to the run named `default`; neighbour builds and
dangerous builds; the time step as a fraction of the Rayleigh time; and the
RMSE of its final surface against the default run's (0 when the settings
change only the speed). Writes liggghts_tuning.csv and liggghts_tuning.png.
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

COLUMNS = ["name", "time_step_rayleigh_fraction", "run_cpu_s", "particle_steps_per_cpu_s", "speedup_particle_steps",
           "simulated_s_per_cpu_s", "speedup_simulated_time", "neighbor_builds", "dangerous_builds",
           "surface_rmse_vs_default_mm"]


def read_run(folder, row):
    with open(os.path.join(folder, row["name"], "liggghts_manifest.json")) as f:
        manifest = json.load(f)
    cpu = float(row["run_cpu_s"])
    return {
        "name": row["name"],
        "time_step_rayleigh_fraction": manifest["time_step_s"] / manifest["rayleigh_time_s"],
        "run_cpu_s": cpu,
        "particle_steps_per_cpu_s": float(row["particle_steps_per_cpu_s"]),
        "simulated_s_per_cpu_s": manifest["simulated_time_s"] / cpu,
        "neighbor_builds": int(float(row["neighbor.builds"])),
        "dangerous_builds": int(float(row["neighbor.dangerous_builds"])),
        "height_final": np.load(os.path.join(folder, row["name"], "height_final.npy")),
    }


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        runs = [read_run(folder, row) for row in csv.DictReader(f)]
    default = next(r for r in runs if r["name"] == "default")
    for r in runs:
        r["speedup_particle_steps"] = r["particle_steps_per_cpu_s"] / default["particle_steps_per_cpu_s"]
        r["speedup_simulated_time"] = r["simulated_s_per_cpu_s"] / default["simulated_s_per_cpu_s"]
        diff = r["height_final"] - default["height_final"]
        r["surface_rmse_vs_default_mm"] = 1e3 * float(np.sqrt(np.nanmean(diff ** 2)))
    with open(os.path.join(folder, "liggghts_tuning.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        w.writerows(runs)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    names = [r["name"] for r in runs]
    y = np.arange(len(runs))
    ax.barh(y - 0.2, [r["speedup_particle_steps"] for r in runs], 0.4, label="particle-steps per CPU s")
    ax.barh(y + 0.2, [r["speedup_simulated_time"] for r in runs], 0.4, label="simulated time per CPU s")
    for k, r in enumerate(runs):
        note = "{:.2f} mm".format(r["surface_rmse_vs_default_mm"])
        if r["dangerous_builds"]:
            note += ", {} dangerous builds".format(r["dangerous_builds"])
        ax.text(0.02, k, note, va="center", fontsize=7, color="white")
    ax.axvline(1.0, color="0.3", lw=0.8)
    ax.set_yticks(y, names)
    ax.invert_yaxis()
    ax.set_xlabel("speed relative to the default settings (RMSE of the final surface against the default's)")
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("LIGGGHTS on the 19k-grain reference bed")
    fig.tight_layout()
    save(fig, folder, "liggghts_tuning.png", dpi=130)
    for r in runs:
        print("{:18s} dt {:.3f} T_R  {:.2e} particle-steps/CPU s (x{:.2f}), simulated time x{:.2f}, "
              "{} builds, {} dangerous, surface {:.3f} mm from default".format(
                  r["name"], r["time_step_rayleigh_fraction"], r["particle_steps_per_cpu_s"],
                  r["speedup_particle_steps"], r["speedup_simulated_time"], r["neighbor_builds"],
                  r["dangerous_builds"], r["surface_rmse_vs_default_mm"]))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
