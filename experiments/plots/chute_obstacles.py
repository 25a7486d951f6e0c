"""Pressure coefficient against Froude number on the wall and the posts (experiments/chute_obstacles.yaml).

usage: python3 chute_obstacles.py EXPERIMENT_DIR [FLOW_DIR]
Reads EXPERIMENT_DIR/summary.csv (chute.mean.* and chute.peak.* of the wall,
the first object) and each run's forces.csv (the x force on every object,
in scene order: the wall, then the posts) and chute_impact.csv (the impact
frames). A post's load: its force averaged over its own impact phase, as
long as the wall's (impact frames x frame interval) and starting when the
post first carries 5 % of its peak; its peak, the largest force averaged
over 10 ms. Its pressure p = F / (b h), b = POST_WIDTH_M, and C = p / (rho
v^2) with h, v, rho and Fr the flow's mean in the window upstream of the
wall (downstream of the posts, where the posts have thinned the flow: a
poor approximation, said so in the figure) or, given FLOW_DIR (a run of
experiments/dem_chute_release.yaml), the flow arriving at the posts: its
run liggghts_short_SLOPE_HEIGHT (the wall where the first row of posts
stands, the same block per unit width) for the run named *_SLOPE_HEIGHT.
Writes chute_obstacles.csv (per run and object: Fr, C of the mean and the
peak) and chute_obstacles.png (C against Fr, the wall and the posts, with
the design form C = alpha + k/(2 Fr^2) for k = 1, alpha = 1 and 2, and its
fit to the wall's means and to the posts' means).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from dem_chute import DESIGN, design_coefficient, fit_design_form  # noqa: E402
from figure_output import save  # noqa: E402

POST_WIDTH_M = 0.012
FRAME_S = 0.01
COLOUR = {"liggghts": "tab:blue", "bullet": "tab:orange", "ode": "tab:green"}


def read_forces(path):
    """(times, [x force per object]) from a forces.csv, objects in column order."""
    with open(path) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array([[float(v) for v in r] for r in rows[1:]])
    fx = [k for k, name in enumerate(header) if name.endswith("_fx_n")]
    return data[:, 0], [data[:, k] for k in fx]


def smoothed(t, f, window_s):
    """Moving average of f over window_s (samples at times t, roughly even)."""
    if len(t) < 2:
        return np.asarray(f, dtype=float)
    n = max(1, int(round(window_s / float(np.median(np.diff(t))))))
    return np.convolve(f, np.ones(n) / n, mode="same")


def post_load(t, f, duration_s):
    """(mean force over the post's impact phase, peak of the 10 ms average); (0, 0) if never loaded."""
    s = smoothed(t, f, FRAME_S)
    peak = float(np.max(s)) if len(s) else 0.0
    if peak <= 0.0:
        return 0.0, 0.0
    start = t[np.argmax(f >= 0.05 * peak)]  # the raw force: the centred average rises half a window early
    phase = (t >= start) & (t <= start + duration_s)
    return float(np.mean(f[phase])), peak


def coefficient(force_n, width_m, depth_m, density_kg_m3, speed_m_s):
    """p / (rho v^2) with p = F / (width h)."""
    return force_n / (width_m * depth_m) / (density_kg_m3 * speed_m_s ** 2)


def read_summary(experiment_dir):
    with open(os.path.join(experiment_dir, "summary.csv")) as f:
        return list(csv.DictReader(f))


def number(row, key):
    value = row.get(key, "")
    return float(value) if value not in ("", None) else None


FLOW_KEYS = ("chute.mean.froude", "chute.mean.depth_m", "chute.mean.speed_m_s", "chute.mean.bulk_density_kg_m3")


def incoming_flows(flow_dir):
    """{(slope, height): (Fr, h, v, rho)} of FLOW_DIR's liggghts_short_SLOPE_HEIGHT runs ({} without one)."""
    flows = {}
    for run in read_summary(flow_dir) if flow_dir else []:
        parts = run["name"].split("_")
        if run["name"].startswith("liggghts_short_") and len(parts) == 4:
            values = tuple(number(run, k) for k in FLOW_KEYS)
            if None not in values:
                flows[(parts[2], parts[3])] = values
    return flows


def rows_of(experiment_dir, flow_dir=None):
    out = []
    flows = incoming_flows(flow_dir)
    for run in read_summary(experiment_dir):
        folder = os.path.join(experiment_dir, run["name"])
        fr, h, v, rho = (number(run, k) for k in FLOW_KEYS)
        if None in (fr, h, v, rho) or not os.path.isfile(os.path.join(folder, "forces.csv")):
            continue
        base = {"run": run["name"], "solver": run["solver"], "slope_deg": number(run, "chute.slope_deg"),
                "froude": fr, "depth_m": h, "speed_m_s": v, "bulk_density_kg_m3": rho,
                "solid_fraction": rho / 2500.0}
        out.append(dict(base, object="wall", flow="at the wall", mean_coefficient=number(run, "chute.mean.coefficient"),
                        peak_coefficient=number(run, "chute.peak.coefficient"),
                        peak_froude=number(run, "chute.peak.froude"),
                        mean_force_n=number(run, "chute.mean.force_n"), peak_force_n=number(run, "chute.peak.force_n")))
        duration = FRAME_S * (number(run, "chute.impact_frame_count") or 1.0)
        t, forces = read_forces(os.path.join(folder, "forces.csv"))
        key = tuple(run["name"].split("_")[-2:])
        flow = flows.get(key)
        pfr, ph, pv, prho = flow if flow else (fr, h, v, rho)
        post = dict(base, froude=pfr, depth_m=ph, speed_m_s=pv, bulk_density_kg_m3=prho, solid_fraction=prho / 2500.0,
                    flow="arriving" if flow else "at the wall")
        for k, f in enumerate(forces[1:], start=1):
            mean_f, peak_f = post_load(t, f, duration)
            out.append(dict(post, object=f"post{k}", mean_coefficient=coefficient(mean_f, POST_WIDTH_M, ph, prho, pv),
                            peak_coefficient=coefficient(peak_f, POST_WIDTH_M, ph, prho, pv), peak_froude=pfr,
                            mean_force_n=mean_f, peak_force_n=peak_f))
    return out


def draw(experiment_dir, rows, flow_note):
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    frs = [r["froude"] for r in rows] or [1.0]
    x = np.linspace(0.7 * min(frs), 1.3 * max(frs), 200)
    for k, alpha, style in DESIGN:
        ax.plot(x, design_coefficient(x, k, alpha), "k" + style, lw=1, label=f"design form k={k:g}, alpha={alpha:g}")
    for r in rows:
        colour = COLOUR.get(r["solver"], "k")
        marker = "s" if r["object"] == "wall" else "o"
        ax.plot(r["froude"], r["mean_coefficient"], marker, color=colour, ms=7 if marker == "s" else 4)
        ax.plot(r["peak_froude"], r["peak_coefficient"], marker, color=colour, mfc="none", ms=7 if marker == "s" else 4)
    for solver, colour in COLOUR.items():
        ax.plot([], [], "s", color=colour, label=f"{solver}: wall (filled mean, open peak)")
        ax.plot([], [], "o", color=colour, ms=4, label=f"{solver}: posts")
    for which, style in (("wall", "-"), ("post", "-.")):
        mine = [r for r in rows if r["solver"] == "liggghts" and r["object"].startswith(which)]
        fit = fit_design_form([r["froude"] for r in mine], [r["mean_coefficient"] for r in mine])
        if fit and fit[0] is not None:
            ax.plot(x, design_coefficient(x, fit[0], fit[1]), style, color="tab:blue", lw=1,
                    label=f"LIGGGHTS {which}s fitted: k={fit[0]:.2g}, alpha={fit[1]:.2g}")
    ax.set_yscale("log")
    ax.set_xlabel("Fr = v / sqrt(g h cos slope) (the flow upstream of the wall)")
    ax.set_ylabel("p / (rho v^2)")
    ax.set_title(f"chute onto staggered posts and a wall (posts: {flow_note})", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, experiment_dir, "chute_obstacles.png", dpi=120)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    experiment_dir = sys.argv[1]
    flow_dir = sys.argv[2] if len(sys.argv) == 3 else None
    rows = rows_of(experiment_dir, flow_dir)
    columns = ["run", "solver", "slope_deg", "object", "flow", "froude", "peak_froude", "depth_m", "speed_m_s",
               "bulk_density_kg_m3", "solid_fraction", "mean_force_n", "peak_force_n", "mean_coefficient",
               "peak_coefficient"]
    with open(os.path.join(experiment_dir, "chute_obstacles.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for r in rows:
            w.writerow([f"{r[c]:.6g}" if isinstance(r[c], float) else r[c] for c in columns])
    draw(experiment_dir, rows, "flow arriving, from the short chute's window" if flow_dir
         else "flow measured at the wall, behind them")
    for r in rows:
        print(f"{r['run']:22s} {r['object']:6s} Fr {r['froude']:.2f} phi {r['solid_fraction']:.2f} "
              f"C mean {r['mean_coefficient']:.2f} peak {r['peak_coefficient']:.2f} F {r['peak_force_n']:.3f} N")


if __name__ == "__main__":
    main()
