"""Impact pressure coefficient against Froude number on the chute (experiments/dem_chute.yaml).

usage: python3 dem_chute.py EXPERIMENT_DIR [PUBLISHED_CSV]
Reads EXPERIMENT_DIR/summary.csv (one row per run: chute.mean.* and
chute.peak.*, the solver column naming the engine) and, where present, each
run's folder EXPERIMENT_DIR/NAME/chute_impact.csv (the flow and the wall's
force per frame; the impact-phase frames are drawn as small dots). Writes
dem_chute.png: p/(rho v^2) against Fr = v / sqrt(g h cos slope), each run's
impact-phase mean (filled) and peak (open), beside the hydrostatic + dynamic
design form

    p = 1/2 k rho g h cos(slope) + alpha rho v^2,  i.e.  p/(rho v^2) = alpha + k / (2 Fr^2),

drawn for k = 1 and alpha = 1 and 2 (the range quoted for granular and
debris flows in the design literature; sources in experiments/dem_chute.yaml,
the numbers not checked against them). Also writes dem_chute_fits.csv: per solver,
k and alpha fitted by least squares to the runs' means (C is linear in
alpha and k/(2 Fr^2)), the number of runs and the RMS residual.

Over the runs it draws the published coefficients of
experiments/published/impact_pressure_coefficient.csv (each row a band: a
coefficient range or one fitted value over a Froude range, with its
citation; a second argument names another such file), and marks every
point (each run's mean and peak) inside or outside them by one rule: inside
when its coefficient lies within [lowest c_min, highest c_max] of the rows
whose Froude range holds its Froude number; a point no row covers counts as
outside. Writes dem_chute_published.csv: per point its statistic, Fr, C,
the band at its Fr and whether it is inside; the last rows count them.
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

ORDER = ["liggghts", "bullet", "ode"]
LABEL = {"liggghts": "LIGGGHTS", "bullet": "Bullet", "ode": "ODE"}
COLOUR = {"liggghts": "tab:blue", "bullet": "tab:orange", "ode": "tab:green"}
DESIGN = [(1.0, 1.0, "--"), (1.0, 2.0, ":")]  # (k, alpha, line style)
PUBLISHED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "published",
                         "impact_pressure_coefficient.csv")
PUBLISHED_COLUMNS = ["id", "kind", "fr_min", "fr_max", "c_min", "c_max", "flow", "citation", "url", "note"]


def load_published(path):
    """The rows of a published-coefficient table (comment lines start with #).

    ValueError naming the file and the row when a column is missing, a
    number is not a positive finite one, a range is reversed, a kind is not
    range or fit, or a row has no citation."""
    with open(path, newline="") as f:
        lines = [line for line in f if not line.lstrip().startswith("#")]
    reader = csv.DictReader(lines)
    missing = [c for c in PUBLISHED_COLUMNS if c not in (reader.fieldnames or [])]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")
    rows = []
    for n, row in enumerate(reader, start=1):
        where = f"{path}: row {n} ({row.get('id') or 'no id'})"
        if not (row["citation"] or "").strip():
            raise ValueError(f"{where}: no citation")
        if row["kind"] not in ("range", "fit"):
            raise ValueError(f"{where}: kind '{row['kind']}' is neither range nor fit")
        values = {}
        for key in ("fr_min", "fr_max", "c_min", "c_max"):
            value = number(row[key])
            if value is None or value <= 0:
                raise ValueError(f"{where}: {key} '{row[key]}' is not a positive number")
            values[key] = value
        if values["fr_min"] > values["fr_max"] or values["c_min"] > values["c_max"]:
            raise ValueError(f"{where}: a range with its minimum above its maximum")
        rows.append({**row, **values})
    if not rows:
        raise ValueError(f"{path}: no rows")
    return rows


def published_band(froude, rows):
    """(lowest c_min, highest c_max) of the rows whose Froude range holds `froude`; None when none does."""
    covering = [r for r in rows if r["fr_min"] <= froude <= r["fr_max"]]
    if not covering:
        return None
    return min(r["c_min"] for r in covering), max(r["c_max"] for r in covering)


def within_published(froude, coefficient, rows):
    """Whether the point (Fr, C) lies inside the published band at its Froude number (False outside any row)."""
    band = published_band(froude, rows)
    return band is not None and band[0] <= coefficient <= band[1]


def draw_published(ax, rows):
    colours = ["tab:purple", "tab:brown", "tab:olive", "tab:cyan"]
    for n, r in enumerate(rows):
        colour = colours[n % len(colours)]
        label = f"published ({r['kind']}): {r['id']}"
        if r["c_max"] > r["c_min"]:
            ax.fill_between([r["fr_min"], r["fr_max"]], r["c_min"], r["c_max"], color=colour, alpha=0.15, label=label)
        else:
            ax.plot([r["fr_min"], r["fr_max"]], [r["c_min"]] * 2, color=colour, lw=2, alpha=0.6, label=label)


def published_points(rows, published):
    """[(name, solver, statistic, Fr, C, band, inside)] for each run's mean and peak."""
    out = []
    for r in rows:
        for statistic in ("mean", "peak"):
            fr, c = number(r.get(f"chute.{statistic}.froude")), number(r.get(f"chute.{statistic}.coefficient"))
            if fr and c and c > 0:
                band = published_band(fr, published)
                out.append((r["name"], r.get("solver", "liggghts"), statistic, fr, c, band,
                            within_published(fr, c, published)))
    return out


def write_published_points(path, points):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["name", "solver", "statistic", "froude", "coefficient", "band_low", "band_high", "inside"])
        for name, solver, statistic, fr, c, band, inside in points:
            low, high = band if band else ("", "")
            w.writerow([name, solver, statistic, f"{fr:.4g}", f"{c:.4g}", low, high, int(inside)])
        for statistic in ("mean", "peak"):
            mine = [p for p in points if p[2] == statistic]
            w.writerow(["count", "", statistic, "", "", "", "", f"{sum(p[6] for p in mine)}/{len(mine)}"])


def design_coefficient(froude, k, alpha):
    """The design form's p/(rho v^2) at Froude number `froude`."""
    return alpha + k / (2.0 * froude * froude)


def fit_design_form(froude, coefficient):
    """(k, alpha, rms) of C = alpha + k/(2 Fr^2) by least squares; None for fewer than 2 points.

    With all Froude numbers equal the two are not separable: k is then None and
    alpha the mean coefficient."""
    froude = np.asarray(froude, dtype=float)
    coefficient = np.asarray(coefficient, dtype=float)
    if len(froude) < 2:
        return None
    x = 1.0 / (2.0 * froude * froude)
    if np.ptp(x) == 0.0:
        alpha = float(np.mean(coefficient))
        return None, alpha, float(np.sqrt(np.mean((coefficient - alpha) ** 2)))
    a = np.column_stack([np.ones_like(x), x])
    (alpha, k), *_ = np.linalg.lstsq(a, coefficient, rcond=None)
    rms = float(np.sqrt(np.mean((a @ np.array([alpha, k]) - coefficient) ** 2)))
    return float(k), float(alpha), rms


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def read_rows(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return [r for r in rows if number(r.get("chute.mean.froude")) and number(r.get("chute.mean.coefficient"))]


def impact_frames(folder, name):
    """(Fr, C) of a run's impact-phase frames, or empty lists when its folder has no chute_impact.csv."""
    path = os.path.join(folder, name, "chute_impact.csv")
    if not os.path.exists(path):
        return [], []
    fr, c = [], []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["impact"] == "1" and float(row["froude"]) > 0 and float(row["coefficient"]) > 0:
                fr.append(float(row["froude"]))
                c.append(float(row["coefficient"]))
    return fr, c


def main(folder, published_path=PUBLISHED):
    rows = read_rows(folder)
    published = load_published(published_path)
    solvers = sorted({r.get("solver", "liggghts") for r in rows},
                     key=lambda e: (ORDER.index(e) if e in ORDER else len(ORDER), e))
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    fits = []
    all_fr = []
    for solver in solvers:
        mine = [r for r in rows if r.get("solver", "liggghts") == solver]
        colour = COLOUR.get(solver, "k")
        for r in mine:
            fr, c = impact_frames(folder, r["name"])
            ax.scatter(fr, c, s=4, color=colour, alpha=0.25, linewidths=0)
            all_fr += fr
        fr_mean = [float(r["chute.mean.froude"]) for r in mine]
        c_mean = [float(r["chute.mean.coefficient"]) for r in mine]
        all_fr += fr_mean
        ax.scatter(fr_mean, c_mean, s=36, color=colour, label=f"{LABEL.get(solver, solver)}: impact-phase mean")
        peaks = [(number(r.get("chute.peak.froude")), number(r.get("chute.peak.coefficient"))) for r in mine]
        peaks = [(f, c) for f, c in peaks if f and c and c > 0]
        if peaks:
            ax.scatter(*zip(*peaks), s=36, facecolors="none", edgecolors=colour,
                       label=f"{LABEL.get(solver, solver)}: peak force")
        result = fit_design_form(fr_mean, c_mean)
        if result:
            k, alpha, rms = result
            fits.append((solver, k, alpha, len(mine), rms))
    draw_published(ax, published)
    points = published_points(rows, published)
    outside = [(p[3], p[4]) for p in points if not p[6]]
    if outside:
        ax.scatter(*zip(*outside), s=60, marker="x", color="tab:red", linewidths=1,
                   label="outside the published band at its Fr")
    write_published_points(os.path.join(folder, "dem_chute_published.csv"), points)
    lo = 0.5 * min(all_fr) if all_fr else 0.3
    hi = 2.0 * max(all_fr) if all_fr else 20.0
    fr = np.geomspace(lo, hi, 200)
    for k, alpha, style in DESIGN:
        ax.plot(fr, design_coefficient(fr, k, alpha), "k" + style, lw=1,
                label=f"design form, k = {k:g}, $\\alpha$ = {alpha:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("Froude number Fr = v / $\\sqrt{g h \\cos\\zeta}$")
    ax.set_ylabel("pressure coefficient p / ($\\rho v^2$)")
    ax.set_title("Granular chute flow against a wall")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, folder, "dem_chute.png", dpi=150)
    with open(os.path.join(folder, "dem_chute_fits.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["solver", "k", "alpha", "runs", "rms"])
        for solver, k, alpha, n, rms in fits:
            w.writerow([solver, "" if k is None else f"{k:.6g}", f"{alpha:.6g}", n, f"{rms:.6g}"])


if __name__ == "__main__":
    main(*sys.argv[1:3])
