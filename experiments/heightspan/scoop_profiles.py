"""Profiles along the drag of a scoop's ground change (issue 12): the model's against the LIGGGHTS seeds' mean.

For each scene (deep: data/ref_scoop, shallow: data/ref_scoop_shallow) the ground's change
(final minus initial surface, 2.5 mm cells) is summed across the drag (over y: m^2 of
cross-section per x), and its centre line (the mean over the bucket's middle, y in
[0.035, 0.065] m) is drawn too; the model's runs (repose run / experiment folders with
height_initial.npy and height_final.npy, or frames/height_NNNN.npy) beside the seeds' mean.
Prints the budget: volume removed (the trench, change < 0), added (change > 0) and added
beyond x = 0.15 m (the dump side), in cm^3. Usage:
  python3 scoop_profiles.py --out FIG.png --deep RUN [RUN ...] --shallow RUN [RUN ...] [--label L ...]
A RUN may end in :frames/height_0008.npy to use a frame as the final surface.
"""
import argparse
import os

import numpy as np

CELL_M, DUMP_X_M = 0.0025, 0.15
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data")
SCENES = {"deep": "ref_scoop", "shallow": "ref_scoop_shallow"}


def load(run):
    folder, _, final = run.partition(":")
    h0 = np.load(os.path.join(folder, "height_initial.npy"))
    h1 = np.load(os.path.join(folder, final or "height_final.npy"))
    return h0, h1


def budget(d):
    a = CELL_M * CELL_M * 1e6
    xs = (np.arange(d.shape[1]) + 0.5) * CELL_M
    return (np.clip(d, None, 0).sum() * a, np.clip(d, 0, None).sum() * a,
            np.clip(d[:, xs > DUMP_X_M], 0, None).sum() * a)


def profiles(d):
    ys = (np.arange(d.shape[0]) + 0.5) * CELL_M
    mid = (ys > 0.035) & (ys < 0.065)
    return d.sum(axis=0) * CELL_M, d[mid].mean(axis=0)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--out", required=True)
    p.add_argument("--deep", nargs="*", default=[])
    p.add_argument("--shallow", nargs="*", default=[])
    p.add_argument("--label", nargs="*", default=[])
    a = p.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    for col, (key, runs) in enumerate((("deep", a.deep), ("shallow", a.shallow))):
        seeds = [load(os.path.join(DATA, SCENES[key], f"seed{s}")) for s in (1, 2, 3)]
        d_ref = np.mean([h1 - h0 for h0, h1 in seeds], axis=0)
        xs = (np.arange(d_ref.shape[1]) + 0.5) * CELL_M
        curves = [("LIGGGHTS seeds' mean", d_ref, "k")]
        for n, run in enumerate(runs):
            h0, h1 = load(run)
            label = a.label[n] if n < len(a.label) else run
            curves.append((label, h1 - h0, None))
        for label, d, colour in curves:
            area, centre = profiles(d)
            axes[0, col].plot(xs, area * 1e4, label=label, color=colour, lw=2 if colour else 1.2)
            axes[1, col].plot(xs, centre * 1e3, label=label, color=colour, lw=2 if colour else 1.2)
            cut, fill, beyond = budget(d)
            print(f"{key:8s} {label:40s} removed {cut:7.1f} added {fill:6.1f} net {cut + fill:6.1f} "
                  f"added beyond x=0.15 {beyond:6.1f} cm^3")
        axes[0, col].set_title(f"{key} scoop ({SCENES[key]})")
        axes[0, col].set_ylabel("change summed across y (cm^2)")
        axes[1, col].set_ylabel("centre-line change, y 35-65 mm (mm)")
        axes[1, col].set_xlabel("x along the drag (m)")
        for ax in axes[:, col]:
            ax.axhline(0, color="grey", lw=0.5)
            ax.axvline(DUMP_X_M, color="grey", ls=":", lw=0.8)
        axes[0, col].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
