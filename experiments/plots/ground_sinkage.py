"""Resting depth against load of experiments/ground_sinkage.yaml
(ground_sinkage.png): the free box in the ground model beside Bekker's plate
sinkage of its weight, and the dropped sphere in the ground model and in
LIGGGHTS beside Bekker's static sinkage of a sphere under its weight (the
dropped sphere sinks deeper: the ground also takes up its impact energy).
The driven wheel (ground_wheel.png): its rut depth against its weight
beside the ground model's bearing rule for a cylinder and Bekker's
rigid-wheel formula, and its travel against the torque beside Bekker's
compaction resistance and a rigid floor.
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
# scenes/ground_free_wheel.yaml: radius, width, duration, friction of the field contacts
WHEEL_RADIUS_M, WHEEL_WIDTH_M, WHEEL_DURATION_S, WHEEL_FRICTION = 0.1, 0.1, 0.8, 0.5
WHEEL_TORQUE_N_M, WHEEL_TORQUE_SWEEP_KG = 0.5, 8.0


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
    """Bekker's sinkage (m) of a sphere under load_n, on [0, R]."""
    return bisect(lambda z: sphere_load(z, radius, law), load_n, radius)


def bisect(load_at, load_n, hi):
    """The z in [0, hi] at which the increasing load_at(z) equals load_n."""
    lo = 0.0
    if load_at(hi) <= load_n:
        return hi
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if load_at(mid) < load_n else (lo, mid)
    return 0.5 * (lo + hi)


def cylinder_rule_sinkage(load_n, radius=WHEEL_RADIUS_M, width=WHEEL_WIDTH_M, law=DRY_SAND):
    """The ground model's bearing rule (models/ground/bearing_sinkage.h) for a
    wheel: Bekker's pressure at its sinkage z, uniform over the chord's patch
    (width x l, l = 2 sqrt(2 R z - z^2), smaller side b)."""
    def load(z):
        chord = 2.0 * math.sqrt(max(0.0, 2.0 * radius * z - z * z))
        return 0.0 if chord == 0.0 else bekker_pressure(z, min(width, chord), law) * width * chord
    return bisect(load, load_n, radius)


def bekker_wheel_sinkage(load_n, radius=WHEEL_RADIUS_M, width=WHEEL_WIDTH_M, law=DRY_SAND):
    """Bekker's rigid-wheel sinkage (Wong 2008, eq. 2.62): the front half of the
    contact bears, z0 = (3 W / ((3 - n)(k_c + b k_phi) sqrt(D)))^(2 / (2n + 1))."""
    n = law["n"]
    k = law["k_c"] + width * law["k_phi"]
    return (3.0 * load_n / ((3.0 - n) * k * math.sqrt(2.0 * radius))) ** (2.0 / (2.0 * n + 1.0))


def compaction_resistance_n(sinkage_m, width=WHEEL_WIDTH_M, law=DRY_SAND):
    """Bekker's compaction resistance of a wheel at sinkage z (Wong 2008, eq. 2.65):
    R_c = b (k_c / b + k_phi) z^(n + 1) / (n + 1), the work of pressing a rut per length."""
    n = law["n"]
    return width * (law["k_c"] / width + law["k_phi"]) * sinkage_m ** (n + 1.0) / (n + 1.0)


def rigid_floor_travel_m(torque, mass, radius=WHEEL_RADIUS_M, duration=WHEEL_DURATION_S):
    """A solid wheel (I = m r^2 / 2) driven from rest on a rigid floor: rolling
    without slip, a = (tau / r) / (1.5 m), while the friction that needs,
    m a, stays within the limit mu m g; beyond it slipping, a = mu g."""
    acceleration = min(torque / radius / (1.5 * mass), WHEEL_FRICTION * 9.81)
    return 0.5 * acceleration * duration * duration


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
    plot_wheel(rows, folder)
    for row in rows:
        for body in ("box", "ball", "wheel"):
            w = row.get(f"free_bodies.{body}.weight_n", "")
            if w:
                d = float(row[f"free_bodies.{body}.resting_depth_m"])
                print(f"{row['name']:32s} weight {float(w):9.4f} N  resting depth {1e3 * d:7.3f} mm")


def plot_wheel(rows, folder):
    import matplotlib.pyplot as plt
    from figure_output import save

    loaded = series(rows, "ground_wheel", "wheel")
    torques = sorted((float(r["name"][len("wheel_torque_"):]), float(r["free_bodies.wheel.travel_m"]))
                     for r in rows if r["name"].startswith("wheel_torque_") and r.get("free_bodies.wheel.travel_m"))
    if not loaded and not torques:
        return
    fig, (sink_ax, drive_ax) = plt.subplots(1, 2, figsize=(10, 4))
    if loaded:
        loads = [w for w, _ in loaded]
        grid = [min(loads) * (max(loads) / min(loads)) ** (k / 50) for k in range(51)]
        sink_ax.plot(grid, [1e3 * cylinder_rule_sinkage(w) for w in grid], "k-",
                     label="bearing rule, cylinder (uniform pressure on the chord)")
        sink_ax.plot(grid, [1e3 * bekker_wheel_sinkage(w) for w in grid], "k--",
                     label="Bekker rigid wheel (front half bears)")
        sink_ax.plot(loads, [1e3 * d for _, d in loaded], "o",
                     label=f"ground model + ODE, {WHEEL_TORQUE_N_M:g} N m")
    sink_ax.set(xscale="log", yscale="log", xlabel="weight (N)", ylabel="rut depth (mm)",
                title="driven wheel (r 10 cm, 10 cm wide)")
    sink_ax.legend(fontsize=8)
    if torques:
        m = WHEEL_TORQUE_SWEEP_KG
        drive_ax.plot([t for t, _ in torques], [1e3 * d for _, d in torques], "o-", label="ground model + ODE")
        grid = [min(t for t, _ in torques) + k * (max(t for t, _ in torques) - min(t for t, _ in torques)) / 50
                for k in range(51)]
        drive_ax.plot(grid, [1e3 * rigid_floor_travel_m(t, m) for t in grid], "k:", label="rigid floor")
        weight = m * 9.81
        for z, style, label in ((cylinder_rule_sinkage(weight), "-", "its rut depth"),
                                (bekker_wheel_sinkage(weight), "--", "Bekker's rolling sinkage")):
            drive_ax.axvline(compaction_resistance_n(z) * WHEEL_RADIUS_M, color="k", ls=style, lw=0.8,
                             label=f"Bekker compaction resistance x r at {label} ({1e3 * z:.1f} mm)")
        drive_ax.set(yscale="log", ylim=(0.1, None), xlabel="torque (N m)", ylabel=f"travel in {WHEEL_DURATION_S:g} s (mm)",
                     title=f"{m:g} kg wheel driven from rest")
        drive_ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, folder, "ground_wheel.png", dpi=110)
    plt.close(fig)
    m = WHEEL_TORQUE_SWEEP_KG
    for z, label in ((cylinder_rule_sinkage(m * 9.81), "bearing rule"), (bekker_wheel_sinkage(m * 9.81), "Bekker wheel")):
        print(f"{m:g} kg wheel, {label}: sinkage {1e3 * z:.2f} mm, compaction resistance x r "
              f"{compaction_resistance_n(z) * WHEEL_RADIUS_M:.3f} N m")
    for t, d in torques:
        print(f"wheel_torque_{t:g}: travel {1e3 * d:7.1f} mm (rigid floor {1e3 * rigid_floor_travel_m(t, m):7.1f} mm)")


if __name__ == "__main__":
    main()
