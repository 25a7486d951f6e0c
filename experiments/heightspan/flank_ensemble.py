"""The dumped heap's flank of the height-span scoop as an ensemble (issue 12).

The model's flank (dump_flank.py) is not smooth in its inputs: sigma moved by
1e-4 of itself, far inside its standard error, moves the held-out scoop's
flank by up to 3 deg, as the heap's peak cell and the particles' landing
cells change. One run at the fitted point is therefore one draw, where the
reference's flank is the mean over three random beds. This runs the model at
a calibration's fitted parameters on each LIGGGHTS seed's own initial bed
(data/ref_scoop*/seedN/height_initial.npy), each with sigma scaled by
1 + k 1e-4 for k = -5..5, and prints the flank's mean, standard deviation,
standard error and per-bed means beside the seeds' own. It also prints the
mass the bucket holds at the stages (filled, lifted, carried: 1.0, 1.3, 1.6 s)
in the unjittered runs, averaged over the beds, against the seeds' mean (the
issue's held-mass target). --seeds picks the LIGGGHTS seeds (default 1 2 3,
the calibrations' references); a scoop uses those it has (data/ref_scoop*
hold seeds 1-7). The along-channel flank (dump_flank.py: the rays within
22.5 deg of +-x, where neither heap leans on the DEM box's side walls) is
printed the same way on a second line. Usage:
  /usr/bin/python3 experiments/heightspan/flank_ensemble.py runs/FIT/parameters.yaml --out runs/flank_FIT \
      [--deep scenes/ref_scoop.yaml] [--shallow scenes/ref_scoop_shallow.yaml] [--repose build/bin/repose] \
      [--set KEY=VALUE ...] [--seeds 1 2 3 4 5 6 7]
(scenes relative to experiments/; --set is passed to every run, e.g. ground_model.heap_laying=one_pass;
11 runs of about 0.2 s per scoop and bed).
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
import dump_flank  # noqa: E402

SEEDS = (1, 2, 3)
STAGES_S = (1.0, 1.3, 1.6)  # filled, lifted, carried (the calibrations' held-out stages)
JITTER = [k * 1e-4 for k in range(-5, 6)]  # sigma's relative change


def read_parameters(path):
    """The `heightspan.NAME: value` lines of a calibration's parameters.yaml, by NAME."""
    values = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"heightspan\.(\S+):\s*(\S+)", line)
            if m:
                values[m.group(1)] = float(m.group(2))
    if "sand.sigma" not in values:
        raise SystemExit(f"{path}: no heightspan.sand.sigma line (a heightspan calibration's parameters.yaml?)")
    return values


def overrides(values):
    """`repose run --set` arguments for fitted values (the ground's material under ground_model)."""
    args = []
    for name, v in values.items():
        key = "ground_model.materials." + name if name.startswith("sand.") else "heightspan." + name
        args += ["--set", f"{key}={v!r}"]
    return args


def jittered(values, fraction):
    v = dict(values)
    v["sand.sigma"] = values["sand.sigma"] * (1.0 + fraction)
    return v


def summary(per_bed):
    """Mean, sample sd, standard error and per-bed means of a beds x draws array of flanks (deg)."""
    a = np.asarray(per_bed, dtype=float)
    sd = a.std(ddof=1)
    return {"mean": a.mean(), "sd": sd, "sem": sd / np.sqrt(a.size), "per_bed": a.mean(axis=1),
            "min": a.min(), "max": a.max()}


def held_at(csv_path, times_s):
    """The bucket's held mass (kg) at times_s, linear between the rows of a held_mass.csv
    (the model's column bucket_mass_kg and LIGGGHTS' alike)."""
    data = np.genfromtxt(csv_path, delimiter=",", names=True)
    return np.interp(times_s, data["time_s"], data["bucket_mass_kg"])


def held_error_percent(model_csvs, seed_csvs, times_s=STAGES_S):
    """The beds' mean held mass against the seeds' mean at each stage, in % of the seeds' mean."""
    model = np.mean([held_at(c, times_s) for c in model_csvs], axis=0)
    seeds = np.mean([held_at(c, times_s) for c in seed_csvs], axis=0)
    return 100.0 * (model - seeds) / seeds


def run_flank(repose, scene, values, bed, out, extra=()):
    """The run's (flank, along-channel flank), deg."""
    cmd = [repose, "run", os.path.join(ROOT, "experiments", scene), "--solver", "heightspan", *overrides(values),
           *[a for kv in extra for a in ("--set", kv)],
           "--set", "heightspan.frame_interval_s=10", "--set", f"ground.initial_height={{kind: file, path: {bed}}}",
           "--out", out]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"flank_ensemble: {' '.join(cmd)} failed: {done.stderr.strip()}")
    final = os.path.join(out, "height_final.npy")
    return dump_flank.flank(final)[1], dump_flank.flank(final, along=True)[1]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("parameters")
    p.add_argument("--out", required=True)
    p.add_argument("--deep", default="scenes/ref_scoop.yaml")
    p.add_argument("--shallow", default="scenes/ref_scoop_shallow.yaml")
    p.add_argument("--repose", default=os.path.join(ROOT, "build", "bin", "repose"))
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="passed to every repose run")
    p.add_argument("--seeds", type=int, nargs="+", default=list(SEEDS), help="LIGGGHTS seeds (those a scoop has)")
    args = p.parse_args()
    values = read_parameters(args.parameters)
    unjittered = JITTER.index(0.0)
    for name, scene, data in (("deep", args.deep, "ref_scoop"), ("shallow", args.shallow, "ref_scoop_shallow")):
        seed_list = [s for s in args.seeds if os.path.isdir(os.path.join(ROOT, "data", data, f"seed{s}"))]
        beds = [os.path.join(ROOT, "data", data, f"seed{s}") for s in seed_list]
        per_bed = []
        for s, bed in zip(seed_list, beds):
            per_bed.append([run_flank(args.repose, scene, jittered(values, f), os.path.join(bed, "height_initial.npy"),
                                      os.path.join(args.out, name, f"bed{s}", f"{k}"), args.set)
                            for k, f in enumerate(JITTER)])
            print(f"{name} bed {s}: " + " ".join(f"{x:.1f}/{y:.1f}" for x, y in per_bed[-1]), flush=True)
        finals = [os.path.join(bed, "height_final.npy") for bed in beds]
        for which, along in (("flank", False), ("along-channel flank", True)):
            seeds = [dump_flank.flank(f, along=along)[1] for f in finals]
            m = summary([[pair[int(along)] for pair in row] for row in per_bed])
            print(f"{name} {which}: model {m['mean']:.2f} +- {m['sd']:.2f} deg (sem {m['sem']:.2f}; per bed "
                  + " / ".join(f"{x:.2f}" for x in m["per_bed"]) + f"; {m['min']:.1f}..{m['max']:.1f}) against the "
                  + "seeds' " + " / ".join(f"{x:.1f}" for x in seeds) + f" (mean {np.mean(seeds):.2f}, sd "
                  + f"{np.std(seeds, ddof=1):.2f}; seeds {' '.join(map(str, seed_list))})", flush=True)
        errors = held_error_percent([os.path.join(args.out, name, f"bed{s}", f"{unjittered}", "held_mass.csv")
                                     for s in seed_list], [os.path.join(bed, "held_mass.csv") for bed in beds])
        print(f"{name}: held at " + " / ".join(f"{t:g}" for t in STAGES_S) + " s: "
              + " / ".join(f"{e:+.1f}" for e in errors) + " % of the seeds' mean", flush=True)


if __name__ == "__main__":
    main()
