"""experiments/plots/dem_chute.py: the design form and its fit."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import dem_chute  # noqa: E402


class DesignForm(unittest.TestCase):
    def test_limits(self):
        self.assertAlmostEqual(dem_chute.design_coefficient(1.0, 1.0, 1.5), 2.0)
        self.assertAlmostEqual(dem_chute.design_coefficient(1e4, 1.0, 1.5), 1.5, places=7)

    def test_fit_recovers_k_and_alpha(self):
        fr = [0.5, 1.0, 2.0, 4.0, 8.0]
        c = [dem_chute.design_coefficient(f, 0.8, 1.7) for f in fr]
        k, alpha, rms = dem_chute.fit_design_form(fr, c)
        self.assertAlmostEqual(k, 0.8, places=9)
        self.assertAlmostEqual(alpha, 1.7, places=9)
        self.assertLess(rms, 1e-9)

    def test_too_few_or_inseparable_points(self):
        self.assertIsNone(dem_chute.fit_design_form([2.0], [1.0]))
        k, alpha, _ = dem_chute.fit_design_form([2.0, 2.0], [1.0, 3.0])
        self.assertIsNone(k)
        self.assertAlmostEqual(alpha, 2.0)


if __name__ == "__main__":
    unittest.main()
