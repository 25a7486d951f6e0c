"""experiments/plots/chute_peak_window.py: the windowed peak of a wall force and the beds' noise."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import chute_peak_window  # noqa: E402


class WindowedPeak(unittest.TestCase):
    def test_a_box_pulse_keeps_its_height_in_narrower_windows_and_is_diluted_in_wider_ones(self):
        t = np.arange(0.0, 1.0, 0.001)
        force = np.where((t >= 0.4) & (t < 0.45), -2.0, 0.0)  # 50 ms of 2 N, pushing in -x
        self.assertAlmostEqual(chute_peak_window.windowed_peak(t, force, 0.02), 2.0)
        self.assertAlmostEqual(chute_peak_window.windowed_peak(t, force, 0.2), 2.0 * 0.05 / 0.2, delta=0.02)

    def test_bed_statistics(self):
        mean, sd, se = chute_peak_window.bed_statistics([1.0, 2.0, 3.0])
        self.assertAlmostEqual(mean, 2.0)
        self.assertAlmostEqual(sd, 0.5)
        self.assertAlmostEqual(se, 0.5 / np.sqrt(3))


if __name__ == "__main__":
    unittest.main()
