"""A debris flow on generated terrain hitting buildings, per engine (experiments/terrain_debris.yaml).

usage: python3 terrain_debris.py EXPERIMENT_DIR
Reads every run folder EXPERIMENT_DIR/NAME that holds front.csv (a rigid
engine's debris run, validation/rigid/debris_run.h: terrain.obj, parts.json,
frames/elements_NNN.npy (x y z r), frames/parts_NNN.npy (x y z qw qx qy qz),
front.csv, buildings.csv, building_forces.csv; LIGGGHTS' debris run writes
the same files, validation/liggghts_debris) and writes, per run:
  debris_NAME_frames.png  the collapse as a series of six frames seen from
                          above: the terrain shaded by height, the elements
                          coloured by layer (radius), each building part's
                          outline (red once it has moved more than 5 cm);
and for all runs together debris_front.png: the front along the flow, its
speed, the joints broken and the force of the elements on each building
(binned, building_forces.csv) against time, one colour per engine (its
seeds NAME_seed_N in the same colour), one line style per building.
With LIGGGHTS on two or more beds (folders liggghts_seed_N) it writes the
yardsticks (debris_yardsticks.py): debris_yardsticks.csv and .txt (per
observable and engine: seed mean and spread, difference to LIGGGHTS' mean,
LIGGGHTS' seed-to-seed noise, doing nothing's error) and
debris_yardsticks.png (each engine's error beside the noise and doing nothing).
A run folder with terrain_mesh.obj (the terrain solver's) gets its contour
and mesh figure through terrain_figure.py: the chain from key contours on.
Each debris run's collapse in 3-D (debris_render3d.py: `repose render` on the
run folder, OSMesa): render3d/debris_NAME_3d_NNN.png, six frames from an
oblique camera (terrain, elements as spheres, building parts grey in place
and red once moved), and debris_NAME_3d_frames.png, the six side by side.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402
from figure_output import save  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import debris_render3d  # noqa: E402
import debris_yardsticks  # noqa: E402
import terrain_figure  # noqa: E402

MOVED_M = 0.05  # as DebrisRunOptions::moved_threshold_m
PANELS = 6


def rotate(q, points):
    """Rotates rows of `points` by the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return points @ r.T


def convex_hull_2d(points):
    """Counter-clockwise convex hull of 2-D points (monotone chain), first point not repeated."""
    pts = sorted(set(map(tuple, np.round(points, 9))))
    if len(pts) < 3:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def part_outlines(hulls, poses):
    """Each part's outline seen from above: the xy hull of its posed vertices."""
    return [convex_hull_2d((rotate(pose[3:7], h) + pose[:3])[:, :2]) for h, pose in zip(hulls, poses)]


def read_front(folder):
    with open(os.path.join(folder, "front.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_forces(folder):
    """building_forces.csv as (time_s, {building: force_n}); None when the run has none."""
    path = os.path.join(folder, "building_forces.csv")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return None
    names = [k for k in rows[0] if k != "time_s"]
    return np.array([float(r["time_s"]) for r in rows]), {k: np.array([float(r[k]) for r in rows]) for k in names}


def draw_frames(folder, name, out_dir):
    v, f = terrain_figure.read_obj(os.path.join(folder, "terrain.obj"))
    tri = mtri.Triangulation(v[:, 0], v[:, 1], f)
    with open(os.path.join(folder, "parts.json")) as fp:
        hulls = [np.array(p["hull_m"]) for p in json.load(fp)["parts"]]
    front = read_front(folder)
    count = len(front["time_s"])
    picks = sorted(set(np.linspace(0, count - 1, PANELS).round().astype(int)))
    parts0 = np.load(os.path.join(folder, "frames", "parts_000.npy")).reshape(-1, 7)
    e0 = np.load(os.path.join(folder, "frames", "elements_000.npy"))
    lo = np.minimum(e0[:, :2].min(axis=0), parts0[:, :2].min(axis=0) if len(parts0) else e0[:, :2].min(axis=0)) - 15
    hi = np.maximum(e0[:, :2].max(axis=0), parts0[:, :2].max(axis=0) if len(parts0) else e0[:, :2].max(axis=0)) + 15
    fig, axes = plt.subplots(2, (len(picks) + 1) // 2, figsize=(4.2 * ((len(picks) + 1) // 2), 8.4), squeeze=False)
    for ax, k in zip(axes.flat, picks):
        e = np.load(os.path.join(folder, "frames", "elements_{:03d}.npy".format(k)))
        parts = np.load(os.path.join(folder, "frames", "parts_{:03d}.npy".format(k))).reshape(-1, 7)
        ax.tripcolor(tri, v[:, 2], cmap="terrain", shading="gouraud")
        ax.tricontour(tri, v[:, 2], levels=12, colors="k", linewidths=0.3, alpha=0.5)
        lo = np.minimum(lo, e[:, :2].min(axis=0))
        hi = np.maximum(hi, e[:, :2].max(axis=0))
        ax.scatter(e[:, 0], e[:, 1], s=(e[:, 3] * 4) ** 2, c=e[:, 3], cmap="copper", vmin=0, edgecolors="none")
        for p, outline in enumerate(part_outlines(hulls, parts)):
            moved = np.linalg.norm(parts[p, :3] - parts0[p, :3]) > MOVED_M
            closed = np.vstack([outline, outline[:1]])
            ax.fill(closed[:, 0], closed[:, 1], color="tab:red" if moved else "tab:blue", alpha=0.5)
            ax.plot(closed[:, 0], closed[:, 1], color="k", lw=0.5)
        ax.set_title("{}: t = {:.1f} s, {} joints broken".format(name, front["time_s"][k], int(front["joints_broken"][k])),
                     fontsize=9)
    for ax in axes.flat:
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)", fontsize=8)
        ax.set_ylabel("y (m)", fontsize=8)
    fig.tight_layout()
    save(fig, out_dir, "debris_{}_frames.png".format(name), dpi=110)
    plt.close(fig)


def draw_frames_3d(program, folder, name, out_dir):
    """The run's collapse in 3-D: six rendered frames and their grid."""
    series_dir = os.path.join(out_dir, "render3d")
    os.makedirs(series_dir, exist_ok=True)
    paths = debris_render3d.render_series(program, folder, os.path.join(series_dir, "debris_{}_3d".format(name)),
                                          PANELS)
    front = read_front(folder)
    labels = ["t = {:.1f} s, {} joints broken".format(front["time_s"][k], int(front["joints_broken"][k]))
              for k in map(debris_render3d.frame_index, paths)]
    debris_render3d.compose(paths, labels, "{}: the collapse in 3-D (grey: part in place, red: moved)".format(name),
                            os.path.join(out_dir, "debris_{}_3d_frames.png".format(name)))


STYLES = ["-", "--", ":", "-."]


def engine_of(name):
    """A run's group: NAME for NAME_seed_N, else the name itself."""
    m = debris_yardsticks.SEED_FOLDER.match(name)
    return m.group("group") if m else name


def draw_fronts(runs, out_dir):
    fig, axes = plt.subplots(1, 4, figsize=(18, 4))
    engines = list(dict.fromkeys(engine_of(name) for name, _ in runs))
    for name, folder in runs:
        engine = engine_of(name)
        colour = "C{}".format(engines.index(engine))
        first = name == engine or name.endswith("_seed_1")  # one legend entry per engine
        label = engine if first else None
        d = read_front(folder)
        axes[0].plot(d["time_s"], d["front_m"], color=colour, label=label)
        axes[1].plot(d["time_s"], d["front_speed_m_s"], color=colour, label=label and label + " front")
        axes[1].plot(d["time_s"], d["mean_speed_m_s"], "--", color=colour, label=label and label + " mean element")
        axes[2].step(d["time_s"], d["joints_broken"], where="post", color=colour, label=label)
        forces = read_forces(folder)
        if forces is not None:
            t, by_building = forces
            for j, (building, f) in enumerate(by_building.items()):
                axes[3].plot(t, f / 1e6, STYLES[j % len(STYLES)], color=colour,
                             label=label and "{} {}".format(label, building))
    labels = ["front along the flow (m)", "speed (m/s)", "joints broken", "force of the elements on a building (MN)"]
    for ax, label in zip(axes, labels):
        ax.set_xlabel("time (s)")
        ax.set_ylabel(label)
        ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, out_dir, "debris_front.png", dpi=110)
    plt.close(fig)


def draw_yardsticks(rows, out_dir):
    """Per observable: each engine's error to LIGGGHTS' mean beside LIGGGHTS' noise and doing nothing."""
    observables = list(dict.fromkeys(r["observable"] for r in rows))
    cols = 3
    fig, axes = plt.subplots((len(observables) + cols - 1) // cols, cols, figsize=(15, 3.2 * ((len(observables) + 2) // 3)),
                             squeeze=False)
    for ax, observable in zip(axes.flat, observables):
        mine = [r for r in rows if r["observable"] == observable and r["group"] != debris_yardsticks.REFERENCE]
        ax.bar(range(len(mine)), [abs(r["error"]) for r in mine], color="tab:orange")
        ax.set_xticks(range(len(mine)))
        ax.set_xticklabels([r["group"] for r in mine], rotation=20, fontsize=7)
        ref = rows[[r["observable"] for r in rows].index(observable)]
        ax.axhline(ref["noise"], color="tab:blue", ls=":", label="LIGGGHTS seed-to-seed noise")
        ax.axhline(ref["nothing"], color="k", ls="--", label="doing nothing")
        ax.set_title("{} ({}): |error| to LIGGGHTS' mean".format(observable, ref["unit"]), fontsize=9)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(observables):]:
        ax.axis("off")
    fig.tight_layout()
    save(fig, out_dir, "debris_yardsticks.png", dpi=110)
    plt.close(fig)


def write_yardsticks(out_dir):
    """The yardstick table and figure when LIGGGHTS ran two or more beds."""
    rows = debris_yardsticks.yardsticks(out_dir)
    if rows is None:
        return
    debris_yardsticks.write_csv(os.path.join(out_dir, "debris_yardsticks.csv"), rows)
    with open(os.path.join(out_dir, "debris_yardsticks.txt"), "w") as f:
        f.write(debris_yardsticks.format_table(rows) + "\n")
    draw_yardsticks(rows, out_dir)


def main():
    out_dir = sys.argv[1]
    runs = []
    program = debris_render3d.repose_program()
    if program is None:
        print("terrain_debris.py: no repose program (REPOSE_EXE, REPOSE, build/bin/repose): no 3-D frames")
    for name in sorted(os.listdir(out_dir)):
        folder = os.path.join(out_dir, name)
        if os.path.exists(os.path.join(folder, "terrain_mesh.obj")):
            fig, axes = plt.subplots(1, 2, figsize=(12, 5))
            terrain_figure.draw_contours(axes[0], folder)
            terrain_figure.draw_mesh(axes[1], folder)
            for ax in axes:
                ax.set_aspect("equal")
            fig.tight_layout()
            save(fig, out_dir, "debris_terrain.png", dpi=110)
            plt.close(fig)
        if os.path.exists(os.path.join(folder, "front.csv")):
            runs.append((name, folder))
            draw_frames(folder, name, out_dir)
            if program is not None and not os.environ.get("REPOSE_PLOT_PDF_DIR"):
                draw_frames_3d(program, folder, name, out_dir)
    if runs:
        draw_fronts(runs, out_dir)
    write_yardsticks(out_dir)


if __name__ == "__main__":
    main()
