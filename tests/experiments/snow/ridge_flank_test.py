"""experiments/snow/ridge_flank.py: the snow ridge's flank angles."""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "snow"))
from ridge_flank import CELL_M, flanks  # noqa: E402


def ridge(west_deg, east_deg, top_m=0.04, hold_m=0.007, rows=8, cols=70):
    """A plate from x = 0.02 to 0.26 m (cells 5-64) under a ridge: hold_m at
    its edges, flanks at the given angles, flat at top_m between them."""
    x = (np.arange(cols) + 0.5) * CELL_M
    west = hold_m + (x - 0.02) * math.tan(math.radians(west_deg))
    east = hold_m + (0.26 - x) * math.tan(math.radians(east_deg))
    profile = np.minimum(np.minimum(west, east), top_m)
    profile[(x < 0.02) | (x > 0.26)] = 0.0
    return np.tile(profile, (rows, 1))


def flanks_of(depth):
    with tempfile.TemporaryDirectory() as folder:
        np.save(os.path.join(folder, "snow_depth_final.plate.npy"), depth)
        return flanks(folder)


class RidgeFlankTest(unittest.TestCase):
    def test_a_ridge_with_known_flanks_gives_their_angles_and_its_top(self):
        top, west, east = flanks_of(ridge(25.0, 35.0))
        self.assertAlmostEqual(top, 0.04)
        self.assertAlmostEqual(west, 25.0, places=6)
        self.assertAlmostEqual(east, 35.0, places=6)

    def test_the_edge_hold_and_the_flat_top_do_not_bias_the_angle(self):
        for hold in (0.0, 0.004, 0.012):
            _, west, east = flanks_of(ridge(18.5, 18.5, top_m=0.05, hold_m=hold))
            self.assertAlmostEqual(west, 18.5, places=6)
            self.assertAlmostEqual(east, 18.5, places=6)

    def test_the_profile_is_the_mean_over_y(self):
        depth = ridge(30.0, 30.0)
        rng = np.random.default_rng(1)
        bumps = rng.normal(0.0, 0.002, size=depth.shape)
        depth_noisy = depth + bumps - bumps.mean(axis=0)  # zero mean along y: the mean profile is unchanged
        _, west, east = flanks_of(depth_noisy)
        self.assertAlmostEqual(west, 30.0, places=6)
        self.assertAlmostEqual(east, 30.0, places=6)


if __name__ == "__main__":
    unittest.main()
