"""Column collapse runout against aspect ratio (experiments/dem_column_collapse.yaml).

usage: python3 dem_column_collapse.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (runs slot_<H0> or strip_<H0>, a periodic
strip, and cylinder_<H0> or quarter_cylinder_<H0>, a quarter between two
symmetry walls, each name optionally after a prefix such as
bullet_), fits
(L_inf - L0)/L0 = k a^n by least squares in log-log space separately for
small (a <= RANGES[shape][0]) and large (a >= RANGES[shape][1]) aspect
ratios, each the side of the published law's own transition (planar: the
gap between 1.8 and 2.8, widened to 2.5 and 3; axisymmetric: 1.7, with
large a from 2 to leave the transition out), per solver
(the summary's solver column: LIGGGHTS, Bullet, ODE), and writes
dem_column_collapse.png (the runs, the fits and the published laws) and
dem_column_collapse_fits.csv (solver, geometry, range, k, n, points, the
published law for that range: its prefactor and exponent, and the runs'
runout over the law's at their a: the geometric mean of the ratios).

Published laws (experiments with sand and glass beads):
  planar, Lube et al. 2005 / Lajeunesse et al. 2005:
      1.2 a for a < 1.8;  1.9 a^(2/3) for a > 2.8
  axisymmetric, Lube et al. 2004 (Lajeunesse et al. 2004 alike):
      1.24 a for a < 1.7; 1.6 a^(1/2) for a > 1.7
  Balmforth & Kerswell 2005: exponents near 1 at small a, and at large a
      near 2/3 in narrow slots (0.65 +- 0.05) and higher in wide channels.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from figure_output import save  # noqa: E402

RANGES = {"slot": (2.5, 3.0), "cylinder": (1.7, 2.0)}  # small a up to, large a from

SHAPES = {"slot": re.compile(r"(^|_)(slot|strip)_"), "cylinder": re.compile(r"(^|_)cylinder_")}
ORDER = ["liggghts", "bullet", "ode"]
LABEL = {"liggghts": "LIGGGHTS", "bullet": "Bullet", "ode": "ODE"}
PUBLISHED = {
    "slot": [(1.2, 1.0, 0.3, 1.8, "Lube 2005: 1.2 a"), (1.9, 2.0 / 3.0, 2.8, 10, "Lube 2005: 1.9 a$^{2/3}$")],
    "cylinder": [(1.24, 1.0, 0.3, 1.7, "Lube 2004: 1.24 a"), (1.6, 0.5, 1.7, 10, "Lube 2004: 1.6 a$^{1/2}$")],
}


def fit(a, r):
    """k, n of r = k a^n (least squares on logs); None for fewer than 2 points."""
    if len(a) < 2:
        return None
    n, log_k = np.polyfit(np.log(a), np.log(r), 1)
    return math.exp(log_k), n


def solvers_of(rows):
    present = {r.get("solver", "liggghts") for r in rows}
    return sorted(present, key=lambda e: (ORDER.index(e) if e in ORDER else len(ORDER), e))


def draw_solver(ax, rows, shape, solver, index, fits):
    data = sorted((float(r["column.aspect_ratio"]), float(r["column.runout_normalised"]))
                  for r in rows if SHAPES[shape].search(r["name"]) and r.get("solver", "liggghts") == solver
                  and r["column.runout_normalised"])
    data = [(a, r) for a, r in data if r > 0]
    if not data:
        return
    a = np.array([d[0] for d in data])
    r = np.array([d[1] for d in data])
    color = "C{}".format(3 * index)
    ax.loglog(a, r, "o", color=color, label="DEM ({})".format(LABEL.get(solver, solver)))
    a_small, a_large = RANGES[shape]
    for name, sel, style in [("small", a <= a_small, "-"), ("large", a >= a_large, "-.")]:
        kn = fit(a[sel], r[sel])
        if kn is None:
            continue
        k, n = kn
        x = np.geomspace(a[sel].min(), a[sel].max(), 20)
        ax.loglog(x, k * x ** n, style, color=color, label="{} fit a {} {}: {:.2f} a$^{{{:.2f}}}$".format(
            LABEL.get(solver, solver), "<=" if name == "small" else ">=",
            a_small if name == "small" else a_large, k, n))
        law = PUBLISHED[shape][0 if name == "small" else 1]
        ratio = math.exp(float(np.mean(np.log(r[sel] / (law[0] * a[sel] ** law[1])))))
        fits.append((solver, shape, name, a[sel].min(), a[sel].max(), k, n, int(sel.sum()), law[0], law[1], ratio))


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    titles = {"slot": "quasi-2-D (slot or periodic strip)", "cylinder": "axisymmetric (cylinder or its quarter)"}
    shapes = [s for s in titles if any(SHAPES[s].search(r["name"]) for r in rows)]
    if not shapes:
        sys.exit("dem_column_collapse: summary.csv has no slot_, strip_ or cylinder_ runs")
    fig, axes = plt.subplots(1, len(shapes), figsize=(5.5 * len(shapes) + 0.5, 4.5), sharey=True, squeeze=False)
    axes = axes[0]
    fits = []
    for ax, shape in zip(axes, shapes):
        title = titles[shape]
        for k, n, lo, hi, label in PUBLISHED[shape]:
            x = np.geomspace(lo, hi, 20)
            ax.loglog(x, k * x ** n, "--", color="0.4" if n == 1 else "0.1", label=label)
        for index, solver in enumerate(solvers_of(rows)):
            draw_solver(ax, rows, shape, solver, index, fits)
        ax.set_title(title)
        ax.set_xlabel("aspect ratio a = H$_0$/L$_0$")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="upper left")
    axes[0].set_ylabel("normalised runout (L$_\\infty$ - L$_0$)/L$_0$")
    fig.suptitle("Granular column collapse: DEM reference vs published laws")
    fig.tight_layout()
    save(fig, folder, "dem_column_collapse.png", dpi=130)
    with open(os.path.join(folder, "dem_column_collapse_fits.csv"), "w") as f:
        f.write("solver,geometry,range,a_min,a_max,prefactor,exponent,points,published_prefactor,published_exponent,"
                "ratio_to_published\n")
        for row in fits:
            f.write("{},{},{},{},{},{},{},{},{},{},{}\n".format(*row))
    for solver, shape, name, lo, hi, k, n, count, k_pub, n_pub, ratio in fits:
        print("{} {} {} a ({:.2f}..{:.2f}, {} runs): runout = {:.2f} a^{:.2f}; published {:.2f} a^{:.2f}; "
              "runs / published law {:.2f}".format(solver, shape, name, lo, hi, count, k, n, k_pub, n_pub, ratio))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
