"""The flank angle of the heap a scoop dumps (issue 12), from a run's final surface.

The heap is the final height field (height_final.npy, 2.5 mm cells) minus the
2.5 cm bed, beyond x = 0.15 m (the dump side of experiments/scenes/ref_scoop*.yaml).
From its highest cell, 16 rays sample it (bilinear, every half cell); along each,
the samples between 20 % and 80 % of the peak are fitted by a line, as
validation/particles pile_flank_angles does: the flank is atan(-slope), and the
mean and standard deviation are over the rays. The field is first passed
through a 3 x 3 median (edge cells: their neighbours inside the grid), on the
model and the DEM alike: it leaves a plane flank as it is but drops a
single-cell spike, which otherwise becomes the "peak" the rays start from (the
height-span model's last particles, dripping off the tipped bucket's edge,
stack in one cell for the final steps: 24 mm and 66 mm spikes beside a 20 mm
heap, issue 12). Usage:
  python3 dump_flank.py RUN_OR_DATA_FOLDER/height_final.npy [...]
e.g. data/ref_scoop/seed1/height_final.npy against a `repose run
experiments/scenes/ref_scoop.yaml --solver heightspan` folder's.

The along-channel flank (along=True; printed beside the flank) keeps only the
rays within 22.5 deg of +-x, the channel's length. Across the channel the
LIGGGHTS heap leans on the box's side walls (10 cm apart, wall friction 0.5):
its height at the walls is 0.64 to 0.72 of its peak's (the seeds' mean, by
scoop), so its rays towards them end at the wall with little or no flank,
while the model's ground, closed at the grid's edge but without wall
friction, lets its heap fall off at its slope rule's angle there.
The 16-ray mean therefore compares different things across the channel; the
along-channel flank compares the heaps' free flanks alone.
"""
import sys

import numpy as np

BED_M, CELL_M, DUMP_X_M = 0.025, 0.0025, 0.15


def bilinear(h, fi, fj):
    i0, j0 = int(np.floor(fi)), int(np.floor(fj))
    if i0 < 0 or j0 < 0 or i0 + 1 >= h.shape[1] or j0 + 1 >= h.shape[0]:
        return None
    u, v = fi - i0, fj - j0
    return ((1 - u) * (1 - v) * h[j0, i0] + u * (1 - v) * h[j0, i0 + 1] + (1 - u) * v * h[j0 + 1, i0]
            + u * v * h[j0 + 1, i0 + 1])


def median3(h):
    """3 x 3 median of each cell (near the edge over the neighbours inside the grid)."""
    p = np.pad(h, 1, constant_values=np.nan)
    stack = np.stack([p[dj:dj + h.shape[0], di:di + h.shape[1]] for dj in range(3) for di in range(3)])
    return np.nanmedian(stack, axis=0)


def flank(path, rays=16, along=False):
    """(peak m, mean flank deg, its sd over the rays, rays with a flank); along: only the rays within 22.5 deg
    of +-x (the six of 16)."""
    h = median3(np.load(path) - BED_M)
    xs = (np.arange(h.shape[1]) + 0.5) * CELL_M
    masked = np.where(xs[None, :] < DUMP_X_M, -np.inf, h)
    j, i = np.unravel_index(np.argmax(masked), h.shape)
    peak = h[j, i]
    angles = []
    for a in np.arange(rays) * 2 * np.pi / rays:
        if along and abs(np.cos(a)) < np.cos(np.radians(22.5)) - 1e-9:
            continue
        s_, z_ = [], []
        for s in np.arange(0.0, 0.1, CELL_M / 2):
            z = bilinear(h, i + s * np.cos(a) / CELL_M, j + s * np.sin(a) / CELL_M)
            if z is None:
                break
            if 0.2 * peak <= z <= 0.8 * peak:
                s_.append(s)
                z_.append(z)
        if len(s_) >= 3:
            angles.append(np.degrees(np.arctan(-np.polyfit(s_, z_, 1)[0])))
    return peak, float(np.mean(angles)), float(np.std(angles, ddof=1)), len(angles)


def main():
    for path in sys.argv[1:]:
        peak, mean, std, n = flank(path)
        _, along, along_std, along_n = flank(path, along=True)
        print(f"{path}: heap peak {peak * 1000:.1f} mm, flank {mean:.1f} +- {std:.1f} deg over {n} rays; "
              f"along the channel {along:.1f} +- {along_std:.1f} deg over {along_n}")


if __name__ == "__main__":
    main()
