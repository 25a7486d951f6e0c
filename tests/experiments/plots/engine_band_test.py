"""experiments/plots/engine_band.py: spreads across engines and across seeds."""
import math
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
from engine_band import band, band_table, engine_values, pair_rmse, rmse  # noqa: E402


def rows_of(values_by_engine, observable="x"):
    rows = []
    for engine, values in values_by_engine.items():
        for k, v in enumerate(values):
            rows.append({"name": "{}_{}".format(engine, k), "solver": engine, observable: repr(v)})
    return rows


class BandTest(unittest.TestCase):
    def test_shifted_engines_give_the_shift_as_engine_spread_and_the_seeds_as_seed_spread(self):
        b = band({"a": [1.0, 2.0, 3.0], "b": [11.0, 12.0, 13.0], "c": [21.0, 22.0, 23.0]})
        self.assertAlmostEqual(b["seed_spread"], 1.0)
        self.assertAlmostEqual(b["engine_std"], 10.0)
        self.assertAlmostEqual(b["engine_range"], 20.0)
        self.assertAlmostEqual(b["ratio"], 10.0)
        self.assertEqual(b["engines"]["b"]["n"], 3)
        self.assertAlmostEqual(b["engines"]["b"]["mean"], 12.0)
        self.assertAlmostEqual(b["engines"]["b"]["std"], 1.0)

    def test_engines_that_agree_have_no_engine_spread_whatever_the_seeds(self):
        rng = np.random.default_rng(5)
        seeds = list(rng.normal(0.0, 3.0, 4))
        b = band({"a": seeds, "b": seeds[::-1], "c": seeds[1:] + seeds[:1]})
        self.assertAlmostEqual(b["engine_std"], 0.0)
        self.assertAlmostEqual(b["engine_range"], 0.0)
        self.assertAlmostEqual(b["seed_spread"], float(np.std(seeds, ddof=1)))

    def test_pooled_seed_spread_weights_engines_by_their_degrees_of_freedom(self):
        b = band({"a": [0.0, 2.0], "b": [0.0, 0.0, 0.0, 0.0, 0.0]})
        # sum of squares 2 over 1 + 4 degrees of freedom
        self.assertAlmostEqual(b["seed_spread"], math.sqrt(2.0 / 5.0))

    def test_exact_seeds_and_differing_engines_give_an_infinite_ratio(self):
        b = band({"a": [1.0, 1.0], "b": [2.0, 2.0]})
        self.assertEqual(b["seed_spread"], 0.0)
        self.assertTrue(math.isinf(b["ratio"]))

    def test_one_engine_has_no_band(self):
        self.assertIsNone(band({"a": [1.0, 2.0]}))


class TableTest(unittest.TestCase):
    def test_runs_without_the_observable_are_left_out(self):
        rows = rows_of({"a": [1.0, 3.0], "b": [5.0, 7.0]})
        rows.append({"name": "c_0", "solver": "c", "x": ""})
        self.assertEqual(sorted(engine_values(rows, "x")), ["a", "b"])
        table = band_table(rows, ["x", "missing"])
        self.assertEqual([name for name, _ in table], ["x"])
        self.assertAlmostEqual(table[0][1]["engine_range"], 4.0)


class SurfaceTest(unittest.TestCase):
    def test_rmse_of_a_constant_offset_is_the_offset(self):
        a = np.random.default_rng(3).random((7, 5))
        self.assertAlmostEqual(rmse(a, a + 0.25), 0.25)
        self.assertEqual(rmse(a, a), 0.0)

    def test_fields_of_different_shapes_are_refused(self):
        with self.assertRaises(ValueError):
            rmse(np.zeros((2, 3)), np.zeros((3, 2)))

    def test_pairs_group_within_and_across_engines(self):
        base = np.zeros((4, 4))
        fields = [(e, base + off) for e in ("a", "b", "c") for off in (0.0, 1.0, 2.0)]
        pairs = pair_rmse(fields)
        self.assertEqual(len(pairs[("a", "a")]), 3)
        self.assertEqual(len(pairs[("a", "b")]), 9)
        self.assertEqual(sum(len(v) for v in pairs.values()), 36)
        self.assertAlmostEqual(sorted(pairs[("b", "b")])[-1], 2.0)


if __name__ == "__main__":
    unittest.main()
