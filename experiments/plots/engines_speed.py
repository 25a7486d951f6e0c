"""Speed of the particle references on the same beds (experiments/engines_speed.yaml).

usage: python3 engines_speed.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (runs SOLVER_SIZE, the solver column naming
the engine) and each run's manifest.json (the scene's time.duration_s);
writes engines_speed.csv (solver, grains, steps, particle-steps per CPU
second, CPU seconds per simulated second of the run, the bed's CPU seconds)
and engines_speed.png (both rates against the grain count, one line per
engine).
"""
import csv
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_output import save  # noqa: E402

ORDER = ["liggghts", "bullet", "ode"]
LABEL = {"liggghts": "LIGGGHTS", "bullet": "Bullet", "ode": "ODE"}
DURATION = re.compile(r"^time:\n(?:  .*\n)*?  duration_s: ([-+0-9.eE]+)$", re.M)


def simulated_s(folder, name):
    with open(os.path.join(folder, name, "manifest.json")) as f:
        scene = json.load(f)["scene"]["resolved_yaml"]
    match = DURATION.search(scene)
    if not match:
        sys.exit("engines_speed: {}: no time.duration_s in the run's scene".format(name))
    return float(match.group(1))


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["particle_steps_per_cpu_s"]]
    if not rows:
        sys.exit("engines_speed: summary.csv has no run with particle_steps_per_cpu_s")
    table = []
    for r in rows:
        cpu_per_sim = float(r["run_cpu_s"]) / simulated_s(folder, r["name"])
        table.append((r["solver"], int(float(r["grain_count"])), int(float(r["steps"])),
                      float(r["particle_steps_per_cpu_s"]), cpu_per_sim, float(r["bed_cpu_s"])))
    table.sort(key=lambda t: (ORDER.index(t[0]) if t[0] in ORDER else len(ORDER), t[1]))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for index, solver in enumerate(dict.fromkeys(t[0] for t in table)):
        mine = [t for t in table if t[0] == solver]
        label = LABEL.get(solver, solver)
        axes[0].loglog([t[1] for t in mine], [t[3] for t in mine], "o-", color="C{}".format(3 * index), label=label)
        axes[1].loglog([t[1] for t in mine], [t[4] for t in mine], "o-", color="C{}".format(3 * index), label=label)
    axes[0].set_ylabel("particle-steps per CPU second")
    axes[1].set_ylabel("CPU seconds per simulated second")
    for ax in axes:
        ax.set_xlabel("grains")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle("Particle references on the same beds (one core)")
    fig.tight_layout()
    save(fig, folder, "engines_speed.png", dpi=130)
    with open(os.path.join(folder, "engines_speed.csv"), "w") as f:
        f.write("solver,grain_count,steps,particle_steps_per_cpu_s,cpu_s_per_simulated_s,bed_cpu_s\n")
        for t in table:
            f.write("{},{},{},{!r},{!r},{!r}\n".format(*t))
    for t in table:
        print("{} {} grains: {:.3g} particle-steps/CPU-s, {:.3g} CPU s per simulated s (bed {:.1f} CPU s)".format(
            t[0], t[1], t[3], t[4], t[5]))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
