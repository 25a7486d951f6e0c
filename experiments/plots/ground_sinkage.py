"""Resting depth against load of experiments/ground_sinkage.yaml
(ground_sinkage.png): the free box in the ground model beside Bekker's plate
sinkage of its weight, and the dropped sphere in the ground model and in
LIGGGHTS beside Bekker's static sinkage of a sphere under its weight (the
dropped sphere sinks deeper: the ground also takes up its impact energy).
Usage: python3 ground_sinkage.py RUN_FOLDER (MPLBACKEND=Agg).

Bekker's law p = (k_c / b + k_phi) z^n with the ground model's defaults
(models/ground/bekker_bearing.h: dry sand, Wong 2008, Table 2.3). A sphere of
radius R at sinkage z presses a disc of radius a = sqrt(2 R z - z^2), of
smaller width b = sqrt(3) a (the ground model's second-moment width,
models/ground/bearing_sinkage.h), so it bears W = p(z, b) pi a^2.
"""
import csv
import math
import os
import sys

# ground_model.bearing's defaults (SI): n, k_c (N/m^(n+1)), k_phi (N/m^(n+2))
DRY_SAND = {"n": 1.1, "k_c": 990.0, "k_phi": 1528430.0}
BOX_FOOTPRINT_M2 = 0.01  # scenes/ground_free_box.yaml: 10 cm x 10 cm
BOX_WIDTH_M = 0.1
SPHERE_RADIUS_M = 0.006  # scenes/dem_free_sphere.yaml


def bekker_pressure(z, width, law=DRY_SAND):
    """Pa holding a plate of smaller width `width` (m) at sinkage z (m)."""
    return (law["k_c"] / width + law["k_phi"]) * z ** law["n"]


def plate_sinkage(load_n, area_m2, width_m, law=DRY_SAND):
    """Bekker's sinkage (m) of a plate under load_n spread over area_m2."""
    return (load_n / area_m2 / (law["k_c"] / width_m + law["k_phi"])) ** (1.0 / law["n"])


def sphere_load(z, radius, law=DRY_SAND):
    """The load (N) a sphere bears at sinkage z (0 <= z <= radius)."""
    a = math.sqrt(max(0.0, 2.0 * radius * z - z * z))
    if a == 0.0:
        return 0.0
    return bekker_pressure(z, math.sqrt(3.0) * a, law) * math.pi * a * a


def sphere_sinkage(load_n, radius, law=DRY_SAND):
    """Bekker's sinkage (m) of a sphere under load_n, by bisection on [0, R]."""
    lo, hi = 0.0, radius
    if sphere_load(hi, radius, law) <= load_n:
        return hi
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if sphere_load(mid, radius, law) < load_n:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def series(rows, prefix, body):
    """[(weight N, resting depth m)] of the runs named PREFIX_*, sorted by weight."""
    out = []
    for row in rows:
        if not row["name"].startswith(prefix + "_"):
            continue
        w, d = row.get(f"free_bodies.{body}.weight_n", ""), row.get(f"free_bodies.{body}.resting_depth_m", "")
        if w and d:
            out.append((float(w), float(d)))
    return sorted(out)


def main():
    import matplotlib.pyplot as plt
    from figure_output import save

    folder = sys.argv[1]
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    fig, (box_ax, ball_ax) = plt.subplots(1, 2, figsize=(10, 4))
    box = series(rows, "ground_box", "box")
    if box:
        loads = [w for w, _ in box]
        grid = [min(loads) * (max(loads) / min(loads)) ** (k / 50) for k in range(51)]
        box_ax.plot(grid, [1e3 * plate_sinkage(w, BOX_FOOTPRINT_M2, BOX_WIDTH_M) for w in grid], "k-",
                    label="Bekker plate, weight / footprint")
        box_ax.plot(loads, [1e3 * d for _, d in box], "o", label="ground model + ODE")
    box_ax.set(xscale="log", yscale="log", xlabel="weight (N)", ylabel="resting depth (mm)",
               title="free box set down on sand (10 cm x 10 cm)")
    box_ax.legend(fontsize=8)
    for prefix, label, marker in (("ground_sphere", "ground model + ODE", "o"), ("liggghts_sphere", "LIGGGHTS (DEM)", "s")):
        s = series(rows, prefix, "ball")
        if s:
            ball_ax.plot([w for w, _ in s], [1e3 * d for _, d in s], marker, label=label)
    weights = [float(r["free_bodies.ball.weight_n"]) for r in rows if r.get("free_bodies.ball.weight_n")]
    if weights:
        grid = [min(weights) * (max(weights) / min(weights)) ** (k / 50) for k in range(51)]
        ball_ax.plot(grid, [1e3 * sphere_sinkage(w, SPHERE_RADIUS_M) for w in grid], "k-",
                     label="Bekker sphere, static weight")
    ball_ax.set(xscale="log", xlabel="weight (N)", ylabel="resting depth (mm)",
                title="6 mm sphere dropped at 0.5 m/s")
    ball_ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, folder, "ground_sinkage.png", dpi=110)
    plt.close(fig)
    for row in rows:
        for body in ("box", "ball"):
            w = row.get(f"free_bodies.{body}.weight_n", "")
            if w:
                d = float(row[f"free_bodies.{body}.resting_depth_m"])
                print(f"{row['name']:32s} weight {float(w):9.4f} N  resting depth {1e3 * d:7.3f} mm")


if __name__ == "__main__":
    main()
