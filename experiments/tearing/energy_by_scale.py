"""Where a tear run's bending and kinetic energy sit by length scale.

For each run folder of the tearing solver (displacement_z_m.npy and
velocity_{x,y,z}_m_per_s.npy on the vertex grid, torn_time_s.npy on the
cells, manifest.json), smooths the out-of-plane displacement z and the
velocities by full-weighting restriction (weights 1 2 1 / 4 along each
axis, mirrored at the edges: a wave of two cells vanishes, long waves
pass) onto grids of 2, 4, 8 ... times the cell, and prints on each grid of
spacing H:
  - the bending energy of the sheet's terms (sheet_model.h: 1/2 D/H^2
    (second difference)^2 along each mesh line, plus the twist terms'
    D/H^2 (mixed difference)^2 per cell when the run had them) over the
    intact sheet below the tear tip (rows up to `margin_mm` below the
    lowest torn cell), and over the rest (the flaps and the grips) clear
    of the torn columns by 2 H on either side (which smoothing blurs);
  - the kinetic energy of the smoothed velocities (vertex masses
    grammage x H^2, halved on the edges) there and over the whole sheet;
all per metre of tear (J/m, as the ledger's energy.*_per_length; J for a
run that did not tear, "below the tip" then below the notch). The
energy at spacing H is that of the motion a mesh of cell H can hold; what
it loses from one H to the next sits in waves between them. The fields are
the run's last state (a snapshot); D is taken uniform (the model weighs
each term by its cells' fibre density, mean 1) and the kinetic energy
over the whole sheet smooths across the tear too, so the totals only
approximate the ledger's; compare runs at the same H.

Usage: /usr/bin/python3 experiments/tearing/energy_by_scale.py [--margin-mm 5] RUN_FOLDER...
"""
import argparse
import json
import os

import numpy as np
import yaml

SPACINGS_MM = (0.5, 1.0, 2.0, 4.0, 8.0)


def setting(manifest, key, default):
    """A tearing key of the run's resolved scene."""
    section = yaml.safe_load(manifest["scene"]["resolved_yaml"]).get("tearing", {})
    return section.get(key, default)


def result(results, path):
    x = results
    for part in path.split("."):
        x = x[part]
    return x["value"] if isinstance(x, dict) and "value" in x else x


def bending_energy(z, h, d, twist):
    """The sheet's bending (and twist) terms' energy of an out-of-plane z (J)."""
    k = d / (h * h)
    e = 0.5 * k * (np.sum((z[:, :-2] - 2 * z[:, 1:-1] + z[:, 2:]) ** 2) +
                   np.sum((z[:-2, :] - 2 * z[1:-1, :] + z[2:, :]) ** 2))
    if twist:
        e += k * np.sum((z[:-1, :-1] - z[:-1, 1:] + z[1:, 1:] - z[1:, :-1]) ** 2)
    return e


def restrict(z):
    """Full weighting onto every second vertex (odd vertex counts)."""
    padded = np.pad(z, 1, mode="reflect")
    rows = 0.25 * padded[:-2, :] + 0.5 * padded[1:-1, :] + 0.25 * padded[2:, :]
    both = 0.25 * rows[:, :-2] + 0.5 * rows[:, 1:-1] + 0.25 * rows[:, 2:]
    return both[::2, ::2]


def kinetic_energy(velocities, spacing, grammage):
    """1/2 m v^2 of vertices of mass grammage x their share of the cells (J)."""
    ny, nx = velocities[0].shape
    wy = np.ones(ny)
    wx = np.ones(nx)
    wy[[0, -1]] = wx[[0, -1]] = 0.5
    mass = grammage * spacing * spacing * np.outer(wy, wx)
    return 0.5 * sum(np.sum(mass * v * v) for v in velocities)


def spectrum(folder, margin_mm):
    """Per grid spacing (mm): bending below the tip, kinetic below the tip and
    over the sheet (J/m); and the run's cells, twist, depth below the tip."""
    manifest = json.load(open(os.path.join(folder, "manifest.json")))
    results = manifest["results"]
    z = np.load(os.path.join(folder, "displacement_z_m.npy"))  # rows: y up
    velocities = [np.load(os.path.join(folder, f"velocity_{a}_m_per_s.npy")) for a in "xyz"]
    torn = np.load(os.path.join(folder, "torn_time_s.npy")) >= 0
    cells = torn.shape[1]
    h = float(setting(manifest, "width_m", 0.1)) / cells
    d = float(setting(manifest, "bending_stiffness_n_m", 3.0e-4))
    grammage = float(setting(manifest, "grammage_kg_per_m2", 0.08))
    twist = bool(setting(manifest, "twist_stiffness", False))
    below_m = int(np.nonzero(torn.any(axis=1))[0].min()) * h - margin_mm * 1e-3
    length = result(results, "tear.length_m") or 1.0  # J where the run did not tear
    torn_x = (np.nonzero(torn.any(axis=0))[0] + 0.5) * h
    table = {}
    spacing = h
    while True:
        rows = int(np.floor(below_m / spacing + 1e-9)) + 1
        x = np.arange(z.shape[1]) * spacing
        # the flaps: columns clear of the tear by 2 H (smoothing blurs across it)
        left = x < torn_x.min() - 2 * spacing
        right = x > torn_x.max() + 2 * spacing
        flaps = sum(bending_energy(z[rows:, side], spacing, d, twist) for side in (left, right))
        table[round(spacing * 1e3, 3)] = (bending_energy(z[:rows, :], spacing, d, twist) / length, flaps / length,
                                          kinetic_energy([v[:rows, :] for v in velocities], spacing, grammage) / length,
                                          kinetic_energy(velocities, spacing, grammage) / length)
        if z.shape[0] % 2 == 0 or z.shape[1] % 2 == 0 or z.shape[0] < 5:
            break
        z = restrict(z)
        velocities = [restrict(v) for v in velocities]
        spacing *= 2
    return cells, below_m, twist, table


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--margin-mm", type=float, default=5.0)
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()
    names = ("bending (+twist) below the tip", "bending (+twist) above it, clear of the tear by 2 H",
             "kinetic below the tip", "kinetic, whole sheet")
    runs = [(folder, spectrum(folder, args.margin_mm)) for folder in args.runs]
    for k, name in enumerate(names):
        print(f"{name}, held on a grid of spacing H (J/m of tear; J where the run did not tear)")
        print("run cells below_mm twist | " + " ".join(f"H={s:g}mm" for s in SPACINGS_MM))
        for folder, (cells, below_m, twist, table) in runs:
            row = " ".join(f"{table[s][k]:.4f}" if s in table else "-" for s in SPACINGS_MM)
            print(f"{folder} {cells} {below_m * 1e3:.1f} {int(twist)} | {row}")

if __name__ == "__main__":
    main()
