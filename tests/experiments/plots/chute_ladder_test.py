"""experiments/plots/chute_ladder.py: the ladder's yardsticks (RMSE, leave-one-out noise, relative errors)."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import chute_ladder  # noqa: E402


def run(final, initial=None, cpu=1.0, front=0.3, peak=1.0, final_force=0.5):
    final = np.asarray(final, dtype=float)
    return {"final": final, "initial": np.zeros_like(final) if initial is None else np.asarray(initial, dtype=float),
            "cpu_s": cpu, "bed_cpu_s": 0.0,
            "measures": {"chute.front_arrival_s": front, "chute.peak.force_n": peak, "chute.final_force_n": final_force}}


class Yardsticks(unittest.TestCase):
    def test_rmse_of_a_constant_offset_is_the_offset(self):
        self.assertAlmostEqual(chute_ladder.rmse(np.zeros((4, 5)), np.full((4, 5), 0.003)), 0.003)
        with self.assertRaises(ValueError):
            chute_ladder.rmse(np.zeros((2, 2)), np.zeros((2, 3)))

    def test_leave_one_out_of_identical_maps_is_zero_and_of_two_maps_their_rmse(self):
        a = np.arange(6.0).reshape(2, 3)
        self.assertEqual(chute_ladder.leave_one_out_rmse([a, a, a]), 0.0)
        self.assertAlmostEqual(chute_ladder.leave_one_out_rmse([a, a + 2.0]), 2.0)
        with self.assertRaises(ValueError):
            chute_ladder.leave_one_out_rmse([a])

    def test_relative_error_skips_missing_values(self):
        self.assertAlmostEqual(chute_ladder.relative_error([1.1, None, 0.9], 0.8), 0.25)
        self.assertIsNone(chute_ladder.relative_error([None], 1.0))
        self.assertIsNone(chute_ladder.relative_error([1.0], None))

    def test_lookup_reads_dotted_names(self):
        self.assertEqual(chute_ladder.lookup({"chute": {"peak": {"force_n": 2}}}, "chute.peak.force_n"), 2.0)
        self.assertIsNone(chute_ladder.lookup({"chute": {}}, "chute.peak.force_n"))


class Rows(unittest.TestCase):
    def test_a_rung_equal_to_the_seeds_mean_scores_zero_and_doing_nothing_scores_the_deposit(self):
        seeds = [run(np.full((2, 3), v), peak=p) for v, p in ((1.0, 1.0), (2.0, 2.0), (3.0, 3.0))]
        rows = chute_ladder.ladder_rows(35, seeds, {"perfect": [run(np.full((2, 3), 2.0), peak=2.0)]})
        by = {r["rung"]: r for r in rows}
        self.assertEqual(by["perfect"]["deposit_rmse_mm"], 0.0)
        self.assertAlmostEqual(by["perfect"]["peak_force_error"], 0.0)
        self.assertAlmostEqual(by["nothing"]["deposit_rmse_mm"], 2000.0)
        # leave-one-out: |1 - 2.5|, |2 - 2|, |3 - 1.5| m, mean 1 m
        self.assertAlmostEqual(by["liggghts"]["deposit_rmse_mm"], 1000.0)
        self.assertAlmostEqual(by["liggghts"]["peak_force_error"], np.mean([1.5 / 2.5, 0.0, 1.5 / 1.5]))


if __name__ == "__main__":
    unittest.main()
