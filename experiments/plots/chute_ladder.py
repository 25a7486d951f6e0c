"""The chute's speed/accuracy ladder (experiments/chute_ladder.yaml).

usage: python3 chute_ladder.py EXPERIMENT_DIR
Reads each run folder EXPERIMENT_DIR/RUNG_SLOPE_SEED (manifest.json,
height_final.npy) and the LIGGGHTS seeds of the repository,
data/chute_rock/seedN (35 deg) and data/chute_rock_45/seedN (45 deg), the
yardstick: their mean. Per slope and rung: the CPU time of a run (its
process's, bed settling apart), the deposit RMSE (height_final against the
seeds' mean final map, averaged over the rung's runs) and the relative
errors of the rung's mean front arrival, peak and final wall force against
the seeds' mean. Beside them: the LIGGGHTS seeds scored leave-one-out (each
against the other seeds' mean: the noise floor) and doing nothing (each
seed's initial map against the mean final map).
Writes chute_ladder.csv and chute_ladder.png (deposit RMSE against CPU time,
one panel per slope, and the peak wall force's error).
"""
import csv
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from figure_output import save  # noqa: E402
from manifest_results import lookup  # noqa: E402

REPOSITORY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
DATA = {35: "data/chute_rock", 45: "data/chute_rock_45"}
SEEDS = [1, 2, 3]
MEASURES = ["chute.front_arrival_s", "chute.peak.force_n", "chute.final_force_n"]
SHORT = {"chute.front_arrival_s": "front", "chute.peak.force_n": "peak_force", "chute.final_force_n": "final_force"}
LABEL = {"liggghts": "LIGGGHTS (seeds)", "bullet_fitted": "Bullet fitted", "bullet_unfitted": "Bullet unfitted",
         "ode": "ODE", "ground": "ground heuristic", "nothing": "do nothing"}
MARKER = {"liggghts": "o", "bullet_fitted": "s", "bullet_unfitted": "D", "ode": "^", "ground": "*"}
RUN_NAME = re.compile(r"^(?P<rung>.+)_(?P<slope>\d+)_(?P<seed>\d+)$")


def rmse(a, b):
    """Root-mean-square difference of two maps of one shape."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        raise ValueError(f"maps of shapes {a.shape} and {b.shape}")
    return float(np.sqrt(np.mean((a - b) ** 2)))


def leave_one_out_rmse(maps):
    """Mean over the maps of each one's RMSE against the mean of the others (2 or more maps)."""
    if len(maps) < 2:
        raise ValueError("leave-one-out needs 2 or more maps")
    return float(np.mean([rmse(m, np.mean([o for j, o in enumerate(maps) if j != i], axis=0))
                          for i, m in enumerate(maps)]))


def relative_error(values, reference):
    """(mean(values) - reference) / reference, None when either is missing."""
    values = [v for v in values if v is not None]
    if not values or reference is None or reference == 0.0:
        return None
    return float(np.mean(values)) / reference - 1.0


def read_run(folder):
    with open(os.path.join(folder, "manifest.json")) as f:
        manifest = json.load(f)
    results = manifest.get("results", {})
    cpu = lookup(results, "run_cpu_s")
    if cpu is None:  # a heuristic: the CPU time of the calling thread
        cpu = float(manifest.get("run", {}).get("cpu_s", 0.0))
    return {"final": np.load(os.path.join(folder, "height_final.npy")),
            "initial": np.load(os.path.join(folder, "height_initial.npy")),
            "cpu_s": cpu, "bed_cpu_s": lookup(results, "bed_cpu_s") or 0.0,
            "measures": {m: lookup(results, m) for m in MEASURES}}


def ladder_rows(slope, seeds, rungs):
    """seeds: the LIGGGHTS runs (read_run); rungs: {rung: [runs]}. One dict per row."""
    mean_final = np.mean([s["final"] for s in seeds], axis=0)
    reference = {m: float(np.mean([s["measures"][m] for s in seeds])) for m in MEASURES}
    rows = [{"slope_deg": slope, "rung": "liggghts", "runs": len(seeds),
             "cpu_s": float(np.mean([s["cpu_s"] for s in seeds])),
             "bed_cpu_s": float(np.mean([s["bed_cpu_s"] for s in seeds])),
             "deposit_rmse_mm": 1e3 * leave_one_out_rmse([s["final"] for s in seeds])}]
    for m in MEASURES:  # each seed against the other seeds' mean, in magnitude
        errors = [relative_error([s["measures"][m]], np.mean([o["measures"][m] for o in seeds if o is not s]))
                  for s in seeds]
        rows[0][SHORT[m] + "_error"] = float(np.mean(np.abs(errors)))
    rows.append({"slope_deg": slope, "rung": "nothing", "runs": len(seeds), "cpu_s": 0.0, "bed_cpu_s": 0.0,
                 "deposit_rmse_mm": 1e3 * float(np.mean([rmse(s["initial"], mean_final) for s in seeds]))})
    for rung, runs in rungs.items():
        row = {"slope_deg": slope, "rung": rung, "runs": len(runs),
               "cpu_s": float(np.mean([r["cpu_s"] for r in runs])),
               "bed_cpu_s": float(np.mean([r["bed_cpu_s"] for r in runs])),
               "deposit_rmse_mm": 1e3 * float(np.mean([rmse(r["final"], mean_final) for r in runs]))}
        for m in MEASURES:
            row[SHORT[m] + "_error"] = relative_error([r["measures"][m] for r in runs], reference[m])
        rows.append(row)
    return rows


def collect(experiment_dir):
    """{slope: {rung: [runs]}} from the experiment's run folders."""
    by_slope = {}
    for name in sorted(os.listdir(experiment_dir)):
        match = RUN_NAME.match(name)
        folder = os.path.join(experiment_dir, name)
        if not match or not os.path.isfile(os.path.join(folder, "manifest.json")):
            continue
        slope = int(match["slope"])
        by_slope.setdefault(slope, {}).setdefault(match["rung"], []).append(read_run(folder))
    return by_slope


def write_csv(path, rows):
    columns = ["slope_deg", "rung", "runs", "cpu_s", "bed_cpu_s", "deposit_rmse_mm"] + \
              [SHORT[m] + "_error" for m in MEASURES]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for r in rows:
            w.writerow(["" if r.get(c) is None else (f"{r[c]:.6g}" if isinstance(r[c], float) else r[c])
                        for c in columns])


def draw(path_dir, rows):
    slopes = sorted({r["slope_deg"] for r in rows})
    fig, axes = plt.subplots(2, len(slopes), figsize=(5.5 * len(slopes), 8), squeeze=False)
    for k, slope in enumerate(slopes):
        ax, bx = axes[0][k], axes[1][k]
        mine = [r for r in rows if r["slope_deg"] == slope]
        noise = next(r for r in mine if r["rung"] == "liggghts")
        nothing = next(r for r in mine if r["rung"] == "nothing")
        ax.axhline(noise["deposit_rmse_mm"], color="tab:blue", ls=":", label="LIGGGHTS seed-to-seed noise")
        ax.axhline(nothing["deposit_rmse_mm"], color="grey", ls="--", label="do nothing")
        names, peak = [], []
        for r in mine:
            if r["rung"] == "nothing":
                continue
            ax.loglog([max(r["cpu_s"], 1e-3)], [r["deposit_rmse_mm"]], MARKER.get(r["rung"], "x"), ms=9,
                      label=LABEL.get(r["rung"], r["rung"]))
            names.append(LABEL.get(r["rung"], r["rung"]))
            peak.append(100 * r.get("peak_force_error") if r.get("peak_force_error") is not None else np.nan)
        ax.set_xlabel("CPU s per run (0.8 s of flow; beds apart)")
        ax.set_ylabel("deposit RMSE against the LIGGGHTS mean (mm)")
        ax.set_title(f"{slope} deg" + (" (Bullet fit)" if slope == 35 else " (held out)"))
        ax.legend(fontsize=7)
        bx.barh(names, peak, color="tab:orange")
        bx.axvline(0, color="k", lw=0.5)
        bx.set_xlabel("peak wall force error (%; LIGGGHTS: seed-to-seed)")
    fig.tight_layout()
    save(fig, path_dir, "chute_ladder.png", dpi=120)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    experiment_dir = sys.argv[1]
    rows = []
    for slope, rungs in sorted(collect(experiment_dir).items()):
        seeds = [read_run(os.path.join(REPOSITORY, DATA[slope], f"seed{s}")) for s in SEEDS]
        rows += ladder_rows(slope, seeds, rungs)
    write_csv(os.path.join(experiment_dir, "chute_ladder.csv"), rows)
    draw(experiment_dir, rows)
    for r in rows:
        errs = " ".join(f"{SHORT[m]} {100 * r[SHORT[m] + '_error']:+.1f}%" for m in MEASURES
                        if r.get(SHORT[m] + "_error") is not None)
        print(f"{r['slope_deg']} deg {LABEL.get(r['rung'], r['rung']):18s} cpu {r['cpu_s']:8.3f} s "
              f"deposit {r['deposit_rmse_mm']:5.1f} mm {errs}")


if __name__ == "__main__":
    main()
