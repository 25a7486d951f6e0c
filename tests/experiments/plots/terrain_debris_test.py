"""experiments/plots/terrain_debris.py: posing parts and their outlines."""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
from terrain_debris import convex_hull_2d, part_outlines, read_forces, rotate  # noqa: E402


class TerrainDebrisTest(unittest.TestCase):
    def test_a_quarter_turn_about_z_takes_x_to_y(self):
        q = (math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4))
        np.testing.assert_allclose(rotate(q, np.array([[1.0, 0.0, 0.0]])), [[0.0, 1.0, 0.0]], atol=1e-12)

    def test_the_hull_of_a_square_with_an_inner_point_is_the_square(self):
        pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]], dtype=float)
        hull = convex_hull_2d(pts)
        self.assertEqual(len(hull), 4)
        area = 0.5 * abs(np.dot(hull[:, 0], np.roll(hull[:, 1], -1)) - np.dot(hull[:, 1], np.roll(hull[:, 0], -1)))
        self.assertAlmostEqual(area, 1.0)

    def test_an_unmoved_prism_outlines_its_footprint_at_its_centre(self):
        hull = np.array([[x, y, z] for x, y in [(-1, -1), (1, -1), (1, 1), (-1, 1)] for z in (-1.5, 1.5)], dtype=float)
        pose = np.array([10.0, 20.0, 5.0, 1.0, 0.0, 0.0, 0.0])
        outline = part_outlines([hull], [pose])[0]
        np.testing.assert_allclose(sorted(map(tuple, outline)), [(9, 19), (9, 21), (11, 19), (11, 21)])

    def test_building_forces_are_read_per_building_and_absent_without_the_file(self):
        with tempfile.TemporaryDirectory() as d:
            self.assertIsNone(read_forces(d))
            with open(os.path.join(d, "building_forces.csv"), "w") as f:
                f.write("time_s,house,barn\n0.05,10,0\n0.1,20,1.5\n")
            t, forces = read_forces(d)
            np.testing.assert_allclose(t, [0.05, 0.1])
            self.assertEqual(list(forces), ["house", "barn"])
            np.testing.assert_allclose(forces["barn"], [0, 1.5])


if __name__ == "__main__":
    unittest.main()
