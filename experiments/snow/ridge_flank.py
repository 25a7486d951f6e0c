"""The flank angles of the snow ridge on the plate of experiments/scenes/snowfall_ridge.yaml (issue 13).

The plate's depth map (snow_depth_final.plate.npy, 4 mm cells; the plate spans
x = 0.02-0.26 m and the whole y) is averaged over y (the ridge is endless along
y), and on each side of its highest cell the samples between 20 % and 80 % of
that height are fitted by a line, as validation/particles pile_flank_angles
measures the dem_pile grains' angle of repose (18.5 +- 2.4 deg): the flank is
atan(|slope|). Prints each folder's west and east flank, then the mean and the
standard deviation over all flanks. Usage:
  python3 experiments/snow/ridge_flank.py FOLDER [...]
e.g. data/snowfall_ridge_c0/seed1 ... against a `repose run
experiments/scenes/snowfall_ridge.yaml --solver snow` folder.
"""
import math
import sys

import numpy as np

CELL_M, PLATE_X_M = 0.004, (0.02, 0.26)


def side_angle(x, d, peak):
    keep = (d >= 0.2 * peak) & (d <= 0.8 * peak)
    if keep.sum() < 3:
        return float("nan")
    slope = np.polyfit(x[keep], d[keep], 1)[0]
    return math.degrees(math.atan(abs(slope)))


def flanks(folder):
    depth = np.load(f"{folder}/snow_depth_final.plate.npy")
    x = (np.arange(depth.shape[1]) + 0.5) * CELL_M
    on = (x > PLATE_X_M[0]) & (x < PLATE_X_M[1])
    x, profile = x[on], depth[:, on].mean(axis=0)
    top = int(np.argmax(profile))
    peak = profile[top]
    return peak, side_angle(x[: top + 1], profile[: top + 1], peak), side_angle(x[top:], profile[top:], peak)


def main(folders):
    angles = []
    for folder in folders:
        peak, west, east = flanks(folder)
        angles += [west, east]
        print(f"{folder}: ridge top {peak * 1000:.1f} mm, west flank {west:.2f} deg, east flank {east:.2f} deg")
    a = np.array(angles)
    print(f"all flanks: {a.mean():.2f} +- {a.std(ddof=1) if len(a) > 1 else 0:.2f} deg (mean +- sd over {len(a)})")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: ridge_flank.py FOLDER [...]")
    main(sys.argv[1:])
