"""experiments/heightspan/dump_flank.py: the flank of a dumped heap, measured alike on the model and the DEM."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "heightspan"))
import dump_flank  # noqa: E402


def cone(slope_deg, peak_m=0.02, centre_m=(0.2, 0.05)):
    """A round heap on the bed of the scoop scenes' grid (104 x 40 cells of 2.5 mm)."""
    x = (np.arange(104) + 0.5) * dump_flank.CELL_M
    y = (np.arange(40) + 0.5) * dump_flank.CELL_M
    r = np.hypot(x[None, :] - centre_m[0], y[:, None] - centre_m[1])
    return dump_flank.BED_M + np.maximum(0.0, peak_m - r * np.tan(np.radians(slope_deg)))


def measured(h, along=False):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "height_final.npy")
        np.save(path, h)
        return dump_flank.flank(path, along=along)


class DumpFlank(unittest.TestCase):
    def test_a_round_heap_measures_its_own_slope(self):
        for slope in (12.0, 18.0, 25.0):
            peak, mean, _, rays = measured(cone(slope))
            self.assertEqual(rays, 16)
            self.assertAlmostEqual(mean, slope, delta=1.0)
            self.assertAlmostEqual(peak, 0.02, delta=0.002)

    def test_along_the_channel_a_ridge_across_it_measures_its_free_flanks_alone(self):
        # a ridge across the channel, 22 deg along x, leaning on the side walls: 6 deg across y
        x = (np.arange(104) + 0.5) * dump_flank.CELL_M
        y = (np.arange(40) + 0.5) * dump_flank.CELL_M
        h = dump_flank.BED_M + np.maximum(0.0, 0.02 - np.abs(x[None, :] - 0.2) * np.tan(np.radians(22.0))
                                          - np.abs(y[:, None] - 0.05) * np.tan(np.radians(6.0)))
        _, along, _, rays = measured(h, along=True)
        self.assertEqual(rays, 6)  # 0, +-22.5 deg and their opposites
        self.assertAlmostEqual(along, 22.0, delta=1.5)
        self.assertLess(measured(h)[1], along - 3.0)  # the 16-ray mean takes in the walls' shallow side
        self.assertAlmostEqual(measured(cone(18.0), along=True)[1], 18.0, delta=1.0)  # a round heap: all alike

    def test_a_one_cell_spike_beside_the_heap_does_not_become_its_peak(self):
        h = cone(18.0)
        h[24, 90] += 0.06  # material stacked in one cell, 1.7 cm from the heap's top
        peak, mean, _, _ = measured(h)
        self.assertAlmostEqual(peak, 0.02, delta=0.002)
        self.assertAlmostEqual(mean, 18.0, delta=1.0)

    def test_the_median_keeps_a_plane_and_drops_a_spike(self):
        h = np.add.outer(np.arange(6) * 0.001, np.arange(8) * 0.002)
        self.assertTrue(np.allclose(dump_flank.median3(h)[1:-1, 1:-1], h[1:-1, 1:-1]))
        h[3, 4] += 1.0
        # the spike goes: what is left lies within its neighbours' heights (0.011 +- 0.003 m)
        self.assertAlmostEqual(dump_flank.median3(h)[3, 4], 0.011, delta=0.003)


if __name__ == "__main__":
    unittest.main()
