"""experiments/plots/ground_sinkage.py: Bekker's plate, sphere and wheel sinkage."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
from ground_sinkage import (bekker_pressure, bekker_wheel_sinkage, compaction_resistance_n,  # noqa: E402
                            cylinder_rule_sinkage, plate_sinkage, rigid_floor_travel_m, series, sphere_load,
                            sphere_sinkage)


class BekkerTest(unittest.TestCase):
    def test_plate_sinkage_inverts_the_pressure(self):
        for z in (1e-4, 3e-3, 0.02):
            p = bekker_pressure(z, 0.1)
            self.assertAlmostEqual(plate_sinkage(p * 0.01, 0.01, 0.1) / z, 1.0, places=12)

    def test_plate_sinkage_of_two_kilograms_by_hand(self):
        # (19.62 N / 0.01 m^2 / (990 / 0.1 + 1528430))^(1 / 1.1)
        self.assertAlmostEqual(plate_sinkage(19.62, 0.01, 0.1), (1962.0 / 1538330.0) ** (1 / 1.1), places=15)

    def test_sphere_bears_its_load_at_its_sinkage_and_spreads_it(self):
        r = 0.006
        for load in (0.01, 0.05, 0.2):  # below 0.66 N, which buries a 6 mm sphere
            z = sphere_sinkage(load, r)
            self.assertAlmostEqual(sphere_load(z, r) / load, 1.0, places=9)
        # the patch widens with depth: ten times the load sinks a sphere less than ten^(1/n) times deeper
        self.assertLess(sphere_sinkage(0.2, r) / sphere_sinkage(0.02, r), 10 ** (1 / 1.1))

    def test_a_load_no_sphere_bears_buries_it_to_its_radius(self):
        self.assertEqual(sphere_sinkage(1e9, 0.006), 0.006)

    def test_series_takes_the_named_runs_sorted_by_weight(self):
        rows = [
            {"name": "ground_box_2", "free_bodies.box.weight_n": "19.6", "free_bodies.box.resting_depth_m": "0.002"},
            {"name": "ground_box_0.5", "free_bodies.box.weight_n": "4.9", "free_bodies.box.resting_depth_m": "0.001"},
            {"name": "ground_sphere_1000", "free_bodies.box.weight_n": "", "free_bodies.box.resting_depth_m": ""},
        ]
        self.assertEqual(series(rows, "ground_box", "box"), [(4.9, 0.001), (19.6, 0.002)])
        self.assertEqual(series(rows, "ground_sphere", "box"), [])


class WheelTest(unittest.TestCase):
    def test_the_bearing_rule_bears_the_load_on_the_chords_patch(self):
        r, width = 0.1, 0.1
        for load in (20.0, 80.0, 300.0):
            z = cylinder_rule_sinkage(load, r, width)
            chord = 2 * math.sqrt(2 * r * z - z * z)
            self.assertAlmostEqual(bekker_pressure(z, min(width, chord)) * width * chord / load, 1.0, places=9)

    def test_bekkers_wheel_sinkage_grows_as_the_load_to_two_over_two_n_plus_one(self):
        self.assertAlmostEqual(bekker_wheel_sinkage(160.0) / bekker_wheel_sinkage(80.0), 2 ** (2 / 3.2), places=12)
        # a front half bearing sinks a wheel deeper than a whole chord at uniform pressure does
        self.assertGreater(bekker_wheel_sinkage(80.0), cylinder_rule_sinkage(80.0))

    def test_compaction_resistance_is_the_work_of_pressing_the_rut_per_length(self):
        z, width, steps = 0.01, 0.1, 20000
        work = sum(bekker_pressure((k + 0.5) * z / steps, width) * width * z / steps for k in range(steps))
        self.assertAlmostEqual(compaction_resistance_n(z, width) / work, 1.0, places=6)

    def test_a_wheel_on_a_rigid_floor_rolls_below_friction_and_slips_above(self):
        # rolling: a = (tau / r) / (m + I / r^2), I = m r^2 / 2; slipping: a = mu g
        self.assertAlmostEqual(rigid_floor_travel_m(0.5, 8.0, 0.1, 0.8), 0.5 * 5.0 / 12.0 * 0.64, places=12)
        self.assertAlmostEqual(rigid_floor_travel_m(100.0, 8.0, 0.1, 0.8), 0.5 * 0.5 * 9.81 * 0.64, places=12)


if __name__ == "__main__":
    unittest.main()
