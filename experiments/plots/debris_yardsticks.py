"""The debris flow's yardsticks (experiments/terrain_debris.yaml, issue 14).

A comparison of engines means something only beside two yardsticks: the
reference's own seed-to-seed noise and the error of doing nothing. Each
engine runs on several random beds (the scene's seed draws the elements'
radii and placement); the runs are folders NAME_seed_N (an experiment's seed
sweep) grouped by NAME. LIGGGHTS (group `liggghts`) is the reference.

Per observable:
  seeds        each group's seed mean and spread (sample standard deviation);
               for a curve or a map the mean over time or cells of the seeds'
               mean, and as spread the group's own leave-one-out noise (below)
  noise        LIGGGHTS' own seed-to-seed noise: each LIGGGHTS seed against
               the mean of the other seeds, the RMS over seeds (for a curve
               or a map: the RMS over time or cells first)
  error        a group's difference to LIGGGHTS' mean: for a number the
               difference of the seed means; for a curve or a map each seed's
               RMS difference to LIGGGHTS' mean curve or map, RMS over seeds
               (LIGGGHTS' own row: its seeds against their own mean)
  doing nothing  the same error for a run in which nothing moves: runout,
               front speed, force, impulse and parts moved 0; the front stays
               where it starts; the height map stays the undisturbed terrain
               with the source on it (height_initial)
The deposit map is the final height map less the bare terrain (the `terrain`
run's height_final, else the lowest of all maps), compared on the cells where
any run (or the source) lies more than 1 cm above the terrain, so the
untouched hill does not dilute it.
"""
import csv
import json
import math
import os
import re

import numpy as np

from manifest_results import lookup

REFERENCE = "liggghts"
SEED_FOLDER = re.compile(r"^(?P<group>.+)_seed_(?P<seed>\d+)$")
SCALARS = [  # (key, manifest results path, unit, scale to the unit)
    ("runout", "runout_m", "m", 1.0),
    ("peak_front_speed", "peak_front_speed_m_s", "m/s", 1.0),
    ("house_peak_force", "building.house.peak_force_n", "MN", 1e-6),
    ("house_impulse", "building.house.impulse_n_s", "MN s", 1e-6),
    ("house_parts_moved", "building.house.parts_moved", "parts", 1.0),
    ("house_joints_broken", "building.house.joints_broken", "joints", 1.0),
    ("barn_peak_force", "building.barn.peak_force_n", "MN", 1e-6),
]
CURVES = [("front", "front_m", "m"), ("deposit_map", None, "m")]
DEPOSIT_THRESHOLD_M = 0.01


def read_front(folder):
    with open(os.path.join(folder, "front.csv")) as f:
        rows = list(csv.DictReader(f))
    return np.array([float(r["time_s"]) for r in rows]), np.array([float(r["front_m"]) for r in rows])


def read_seed_run(folder):
    """One run folder: its scalars (in the table's units), front curve and height maps."""
    with open(os.path.join(folder, "manifest.json")) as f:
        results = json.load(f).get("results", {})
    scalars = {}
    for key, path, _, scale in SCALARS:
        v = lookup(results, path)
        scalars[key] = None if v is None else v * scale
    t, front = read_front(folder)
    return {"scalars": scalars, "front_t": t, "front": front,
            "initial": np.load(os.path.join(folder, "height_initial.npy")),
            "final": np.load(os.path.join(folder, "height_final.npy"))}


def group_seed_runs(experiment_dir):
    """{group: {seed: run folder}} for every folder NAME_seed_N holding front.csv."""
    groups = {}
    for name in sorted(os.listdir(experiment_dir)):
        m = SEED_FOLDER.match(name)
        folder = os.path.join(experiment_dir, name)
        if m and os.path.exists(os.path.join(folder, "front.csv")):
            groups.setdefault(m.group("group"), {})[int(m.group("seed"))] = folder
    return groups


def rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x ** 2)))


def leave_one_out_noise(values):
    """RMS over the items of each one's RMS difference to the mean of the others (2 or more).

    The items are numbers, curves or maps of one shape."""
    if len(values) < 2:
        raise ValueError("the noise needs 2 or more seeds, got {}".format(len(values)))
    arrays = [np.asarray(v, dtype=float) for v in values]
    return rms([rms(a - np.mean([o for j, o in enumerate(arrays) if j != i], axis=0)) for i, a in enumerate(arrays)])


def error_to_reference(values, reference_mean):
    """RMS over the items of each one's RMS difference to the reference mean."""
    return rms([rms(np.asarray(v, dtype=float) - reference_mean) for v in values])


def on_times(t_target, t, y):
    """y(t) on the times t_target (held at its last value past its end)."""
    return np.interp(t_target, t, y)


def deposit_mask(maps, terrain):
    """Cells where any of the maps lies more than DEPOSIT_THRESHOLD_M above the terrain."""
    return np.any([m - terrain > DEPOSIT_THRESHOLD_M for m in maps], axis=0)


def yardstick_rows(groups, terrain=None):
    """groups: {group: [read_seed_run(...) per seed]}, the reference among them.

    One dict per (observable, group): observable, unit, group, seeds,
    mean, spread, error (to the reference mean), noise (the reference's),
    nothing (doing nothing's error), error_over_noise."""
    ref = groups[REFERENCE]
    t = ref[0]["front_t"]
    maps = [r["final"] for runs in groups.values() for r in runs] + [ref[0]["initial"]]
    if terrain is None:
        terrain = np.min(maps + [r["initial"] for runs in groups.values() for r in runs], axis=0)
    mask = deposit_mask(maps, terrain)

    def curve(run, key):
        if key == "front":
            return on_times(t, run["front_t"], run["front"])
        return (run["final"] - terrain)[mask]  # the depth above the bare terrain

    rows = []
    for key, _, unit, _ in SCALARS:
        ref_values = [r["scalars"][key] for r in ref]
        if any(v is None for v in ref_values):
            continue
        ref_mean = float(np.mean(ref_values))
        noise = leave_one_out_noise(ref_values)
        for group, runs in groups.items():
            values = [r["scalars"][key] for r in runs]
            if any(v is None for v in values):
                continue
            rows.append(row(key, unit, group, values, float(np.mean(values)) - ref_mean, noise, abs(ref_mean)))
    for key, _, unit in CURVES:
        ref_curves = [curve(r, key) for r in ref]
        ref_mean = np.mean(ref_curves, axis=0)
        noise = leave_one_out_noise(ref_curves)
        if key == "front":  # the front stays where it starts
            nothing = np.full_like(ref_mean, np.mean([r["front"][0] for r in ref]))
        else:  # the undisturbed terrain with the source on it
            nothing = (np.mean([r["initial"] for r in ref], axis=0) - terrain)[mask]
        for group, runs in groups.items():
            curves = [curve(r, key) for r in runs]
            # mean: over time (cells) of the seeds' mean; spread: the group's own seed-to-seed noise
            spread = leave_one_out_noise(curves) if len(curves) > 1 else float("nan")
            rows.append(row(key, unit, group, [float(np.mean(curves))], error_to_reference(curves, ref_mean), noise,
                            rms(nothing - ref_mean), spread=spread, seeds=len(curves)))
    return rows


def row(observable, unit, group, values, error, noise, nothing, spread=None, seeds=None):
    """A table row; spread defaults to the values' sample standard deviation."""
    values = [float(v) for v in values]
    if spread is None:
        spread = float(np.std(values, ddof=1)) if len(values) > 1 else float("nan")
    if seeds is None:
        seeds = len(values)
    return {"observable": observable, "unit": unit, "group": group, "seeds": seeds,
            "mean": float(np.mean(values)), "spread": spread, "error": float(error), "noise": float(noise),
            "nothing": float(nothing), "error_over_noise": abs(error) / noise if noise > 0 else (math.nan if error == 0 else math.inf)}


def write_csv(path, rows):
    keys = ["observable", "unit", "group", "seeds", "mean", "spread", "error", "noise", "nothing", "error_over_noise"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([r[k] if isinstance(r[k], str) or isinstance(r[k], int) else "{:.6g}".format(r[k]) for k in keys])


def format_table(rows):
    """A plain-text table (the experiment file's header quotes it)."""
    lines = ["{:<28} {:<24} {:>3} {:>18} {:>10} {:>10} {:>10} {:>9}".format(
        "observable (unit)", "engine", "n", "seed mean +- sd", "err to L", "L noise", "nothing", "err/noise")]
    for r in rows:
        lines.append("{:<28} {:<24} {:>3} {:>18} {:>10.3g} {:>10.3g} {:>10.3g} {:>9.2f}".format(
            "{} ({})".format(r["observable"], r["unit"]), r["group"], r["seeds"],
            "{:.3g} +- {:.2g}".format(r["mean"], r["spread"]), r["error"], r["noise"], r["nothing"],
            r["error_over_noise"]))
    return "\n".join(lines)


def yardsticks(experiment_dir):
    """Reads the seed runs of an experiment folder; None when LIGGGHTS has fewer than 2 seeds."""
    folders = group_seed_runs(experiment_dir)
    if len(folders.get(REFERENCE, {})) < 2:
        return None
    groups = {g: [read_seed_run(f) for _, f in sorted(seeds.items())] for g, seeds in folders.items()}
    terrain_file = os.path.join(experiment_dir, "terrain", "height_final.npy")
    terrain = np.load(terrain_file) if os.path.exists(terrain_file) else None
    return yardstick_rows(groups, terrain)
