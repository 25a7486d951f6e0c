"""Column collapse runout against aspect ratio (experiments/dem_column_collapse.yaml).

usage: python3 dem_column_collapse.py EXPERIMENT_DIR
Reads EXPERIMENT_DIR/summary.csv (runs slot_<H0> or strip_<H0>, a periodic
strip, and cylinder_<H0>), fits
(L_inf - L0)/L0 = k a^n by least squares in log-log space separately for
small (a <= A_SMALL) and large (a >= A_LARGE) aspect ratios, and writes
dem_column_collapse.png (the runs, the fits and the published laws) and
dem_column_collapse_fits.csv (geometry, range, k, n, points, and the
published law for that range: its prefactor and exponent).

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
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from figure_output import save  # noqa: E402

A_SMALL = 2.5
A_LARGE = 3.0

PREFIXES = {"slot": ("slot_", "strip_"), "cylinder": ("cylinder_",)}
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


def main(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    fits = []
    for ax, shape, title in zip(axes, ["slot", "cylinder"], ["quasi-2-D (slot or periodic strip)", "axisymmetric (cylinder)"]):
        data = sorted((float(r["column.aspect_ratio"]), float(r["column.runout_normalised"]))
                      for r in rows if r["name"].startswith(PREFIXES[shape]) and r["column.runout_normalised"])
        data = [(a, r) for a, r in data if r > 0]
        if not data:
            continue
        a = np.array([d[0] for d in data])
        r = np.array([d[1] for d in data])
        ax.loglog(a, r, "o", color="C0", label="DEM (LIGGGHTS)")
        for k, n, lo, hi, label in PUBLISHED[shape]:
            x = np.geomspace(lo, hi, 20)
            ax.loglog(x, k * x ** n, "--", color="0.4" if n == 1 else "0.1", label=label)
        for name, sel, color in [("small", a <= A_SMALL, "C1"), ("large", a >= A_LARGE, "C2")]:
            kn = fit(a[sel], r[sel])
            if kn is None:
                continue
            k, n = kn
            x = np.geomspace(a[sel].min(), a[sel].max(), 20)
            ax.loglog(x, k * x ** n, "-", color=color, label="fit a {} {}: {:.2f} a$^{{{:.2f}}}$".format(
                "<=" if name == "small" else ">=", A_SMALL if name == "small" else A_LARGE, k, n))
            law = PUBLISHED[shape][0 if name == "small" else 1]
            fits.append((shape, name, a[sel].min(), a[sel].max(), k, n, int(sel.sum()), law[0], law[1]))
        ax.set_title(title)
        ax.set_xlabel("aspect ratio a = H$_0$/L$_0$")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8, loc="upper left")
    axes[0].set_ylabel("normalised runout (L$_\\infty$ - L$_0$)/L$_0$")
    fig.suptitle("Granular column collapse: DEM reference vs published laws")
    fig.tight_layout()
    save(fig, folder, "dem_column_collapse.png", dpi=130)
    with open(os.path.join(folder, "dem_column_collapse_fits.csv"), "w") as f:
        f.write("geometry,range,a_min,a_max,prefactor,exponent,points,published_prefactor,published_exponent\n")
        for row in fits:
            f.write("{},{},{},{},{},{},{},{},{}\n".format(*row))
    for shape, name, lo, hi, k, n, count, k_pub, n_pub in fits:
        print("{} {} a ({:.2f}..{:.2f}, {} runs): runout = {:.2f} a^{:.2f}; published {:.2f} a^{:.2f}".format(
            shape, name, lo, hi, count, k, n, k_pub, n_pub))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
