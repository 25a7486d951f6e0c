"""Engine disagreement as a band (experiments/engines_band.yaml).

usage: python3 engines_band.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (one scene, several engines by the solver
column, several seeds each) and each run's height_final.npy; writes
  engines_band.csv          per observable: each engine's n, mean and std
                            over seeds, the seed spread (pooled std), the
                            engine spread (std and range of the engines'
                            means) and their ratio (engine_band.py defines them)
  engines_band_surface.csv  RMSE between the final surfaces of every pair of
                            runs, grouped by engine pair (a, a: two beds of
                            one engine; a, b: across engines)
  engines_band.png          per observable every run, each engine's mean +-
                            seed std, and the band of the engines' means
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from engine_band import band_table, pair_rmse  # noqa: E402
from figure_output import save  # noqa: E402

OBSERVABLES = [
    ("pile.flank_angle_mean_deg", "pile flank angle (deg)", 1.0),
    ("pile.flank_angle_std_deg", "flank angle std over azimuths (deg)", 1.0),
    ("column.runout_normalised", "normalised runout (L - L0)/L0", 1.0),
    ("column.front_final_m", "runout front (mm)", 1000.0),
    ("column.height_final_m", "final height (mm)", 1000.0),
    ("column.height_initial_m", "settled column height (mm)", 1000.0),
]
PLOTTED = 4
ORDER = ["liggghts", "bullet", "ode"]
LABEL = {"liggghts": "LIGGGHTS", "bullet": "Bullet", "ode": "ODE"}


def engine_order(engines):
    return sorted(engines, key=lambda e: (ORDER.index(e) if e in ORDER else len(ORDER), e))


def write_band(folder, table, engines):
    with open(os.path.join(folder, "engines_band.csv"), "w") as f:
        head = ["observable"]
        for e in engines:
            head += [e + "_n", e + "_mean", e + "_std"]
        f.write(",".join(head + ["seed_spread", "engine_std", "engine_range", "ratio"]) + "\n")
        for observable, b in table:
            cells = [observable]
            for e in engines:
                s = b["engines"].get(e, {"n": 0, "mean": float("nan"), "std": float("nan")})
                cells += [str(s["n"]), repr(s["mean"]), repr(s["std"])]
            cells += [repr(b["seed_spread"]), repr(b["engine_std"]), repr(b["engine_range"]), repr(b["ratio"])]
            f.write(",".join(cells) + "\n")


def surfaces(folder, rows):
    fields = []
    for r in rows:
        path = os.path.join(folder, r["name"], "height_final.npy")
        if os.path.exists(path):
            fields.append((r["solver"], np.load(path)))
    pairs = pair_rmse(fields)
    with open(os.path.join(folder, "engines_band_surface.csv"), "w") as f:
        f.write("engine_a,engine_b,pairs,rmse_mean_m,rmse_min_m,rmse_max_m\n")
        for (a, b), values in sorted(pairs.items()):
            f.write("{},{},{},{!r},{!r},{!r}\n".format(a, b, len(values), float(np.mean(values)),
                                                      float(np.min(values)), float(np.max(values))))
    return pairs


def draw_observable(ax, rows, observable, label, scale, b, engines):
    for i, e in enumerate(engines):
        values = [float(r[observable]) * scale for r in rows if r["solver"] == e and r.get(observable)]
        ax.scatter([i] * len(values), values, s=14, color="0.55", zorder=2)
        s = b["engines"][e]
        ax.errorbar([i], [s["mean"] * scale], yerr=[s["std"] * scale], fmt="o", color="C{}".format(i),
                    capsize=5, zorder=3)
    means = [b["engines"][e]["mean"] * scale for e in engines]
    ax.axhspan(min(means), max(means), color="C3", alpha=0.15, zorder=1)
    ax.set_xticks(range(len(engines)), [LABEL.get(e, e) for e in engines])
    ax.set_xlim(-0.6, len(engines) - 0.4)
    ax.set_ylabel(label)
    ax.set_title("engines/seeds: {:.2g}".format(b["ratio"]), fontsize=9)
    ax.grid(alpha=0.3, axis="y")


def draw_surfaces(ax, pairs, engines):
    keys = [(a, b) for a in engines for b in engines if a <= b and (a, b) in pairs]
    keys.sort(key=lambda k: (k[0] != k[1], engines.index(k[0]), engines.index(k[1])))
    for i, k in enumerate(keys):
        v = np.array(pairs[k]) * 1000.0
        ax.scatter([i] * len(v), v, s=14, color="C0" if k[0] == k[1] else "C3")
    ax.set_xticks(range(len(keys)), ["{}\n{}".format(LABEL.get(a, a), LABEL.get(b, b)) for a, b in keys],
                  fontsize=7)
    ax.set_ylabel("final surface RMSE between runs (mm)")
    ax.set_title("blue: same engine, red: across", fontsize=9)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3, axis="y")


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    table = band_table(rows, [o[0] for o in OBSERVABLES])
    if not table:
        sys.exit("engines_band: summary.csv needs runs of at least two solvers with the observables set")
    engines = engine_order({e for _, b in table for e in b["engines"]})
    write_band(folder, table, engines)
    pairs = surfaces(folder, rows)
    fig, axes = plt.subplots(1, PLOTTED + 1, figsize=(3.1 * (PLOTTED + 1), 3.6))
    bands = dict(table)
    for ax, (observable, label, scale) in zip(axes, OBSERVABLES[:PLOTTED]):
        if observable in bands:
            draw_observable(ax, rows, observable, label, scale, bands[observable], engines)
    draw_surfaces(axes[-1], pairs, engines)
    fig.suptitle("Engine spread (shaded: range of the engines' means) beside seed spread (bars: std over seeds)",
                 fontsize=10)
    fig.tight_layout()
    save(fig, folder, "engines_band.png", dpi=130)
    for observable, b in table:
        means = ", ".join("{} {:.4g} +- {:.2g}".format(LABEL.get(e, e), b["engines"][e]["mean"],
                                                      b["engines"][e]["std"]) for e in engines)
        print("{}: {}; seed spread {:.3g}, engine std {:.3g} (range {:.3g}), ratio {:.2g}".format(
            observable, means, b["seed_spread"], b["engine_std"], b["engine_range"], b["ratio"]))
    for (a, b), values in sorted(pairs.items()):
        print("surface RMSE {}-{}: {:.2f} mm over {} pairs".format(a, b, 1000 * float(np.mean(values)), len(values)))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
