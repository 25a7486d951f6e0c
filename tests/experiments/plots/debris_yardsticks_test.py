"""experiments/plots/debris_yardsticks.py: the debris flow's noise and doing-nothing yardsticks."""
import json
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import debris_yardsticks as y  # noqa: E402


def fake_run(runout, front_end, final_value, initial_value=1.0):
    t = np.linspace(0.0, 8.0, 21)
    return {"scalars": {k: (runout if k == "runout" else 1.0) for k, *_ in y.SCALARS},
            "front_t": t, "front": np.linspace(5.0, front_end, 21),
            "initial": np.array([[0.0, initial_value], [0.0, 0.0]]),
            "final": np.array([[0.0, 0.0], [final_value, 0.0]])}


def by(rows, observable, group):
    return next(r for r in rows if r["observable"] == observable and r["group"] == group)


class DebrisYardsticksTest(unittest.TestCase):
    def test_the_noise_of_three_numbers_is_each_against_the_mean_of_the_other_two(self):
        # 1 against 3.5 (2.5), 3 against 2.5 (0.5), 4 against 2 (2): RMS sqrt((6.25 + 0.25 + 4) / 3)
        self.assertAlmostEqual(y.leave_one_out_noise([1.0, 3.0, 4.0]), math.sqrt(10.5 / 3))
        self.assertEqual(y.leave_one_out_noise([2.0, 2.0, 2.0]), 0.0)
        with self.assertRaises(ValueError):
            y.leave_one_out_noise([1.0])

    def test_the_table_takes_its_noise_from_the_reference_seeds_spread_and_its_error_from_their_mean(self):
        groups = {"liggghts": [fake_run(50.0, 50.0, 2.0), fake_run(52.0, 52.0, 2.0), fake_run(54.0, 54.0, 2.0)],
                  "bullet": [fake_run(60.0, 60.0, 3.0), fake_run(62.0, 62.0, 3.0), fake_run(64.0, 64.0, 3.0)]}
        rows = y.yardstick_rows(groups, terrain=np.zeros((2, 2)))
        runout_l, runout_b = by(rows, "runout", "liggghts"), by(rows, "runout", "bullet")
        # each seed against the other two: 3, 0, 3 m; RMS sqrt(6)
        self.assertAlmostEqual(runout_l["noise"], math.sqrt(6.0))
        self.assertAlmostEqual(runout_b["noise"], math.sqrt(6.0))  # the reference's noise on every row
        self.assertAlmostEqual(runout_l["spread"], 2.0)
        self.assertAlmostEqual(runout_b["mean"], 62.0)
        self.assertAlmostEqual(runout_b["error"], 10.0)
        self.assertAlmostEqual(runout_l["error"], 0.0)
        self.assertAlmostEqual(runout_b["nothing"], 52.0)  # a runout of 0
        self.assertAlmostEqual(runout_b["error_over_noise"], 10.0 / math.sqrt(6.0))
        # the front: the seeds' fronts differ by a ramp to 2 m at the end
        front_l = by(rows, "front", "liggghts")
        self.assertGreater(front_l["noise"], 0.0)
        self.assertLess(front_l["noise"], 3.0)
        self.assertGreater(by(rows, "front", "bullet")["error"], front_l["noise"])
        # doing nothing leaves the front at 5 m while the reference's runs to 52 m
        self.assertGreater(front_l["nothing"], 20.0)
        # the height map on the cells any run or the source covers (two of four): the reference
        # seeds agree (noise 0); Bullet's deposit is 1 m higher on one of them, the source 1 m on the other
        maps_l, maps_b = by(rows, "deposit_map", "liggghts"), by(rows, "deposit_map", "bullet")
        self.assertEqual(maps_l["noise"], 0.0)
        self.assertAlmostEqual(maps_b["error"], math.sqrt(0.5))
        self.assertAlmostEqual(maps_b["nothing"], math.sqrt((4.0 + 1.0) / 2))

    def test_seed_folders_are_grouped_by_their_name_and_other_folders_left_out(self):
        with tempfile.TemporaryDirectory() as d:
            for name in ["liggghts_seed_1", "liggghts_seed_2", "bullet_unbreakable_seed_3", "terrain", "ode_seed_1"]:
                os.makedirs(os.path.join(d, name))
                if name != "ode_seed_1":  # no front.csv: not a debris run
                    open(os.path.join(d, name, "front.csv"), "w").close()
            groups = y.group_seed_runs(d)
            self.assertEqual(sorted(groups), ["bullet_unbreakable", "liggghts"])
            self.assertEqual(sorted(groups["liggghts"]), [1, 2])

    def test_a_run_folder_is_read_in_the_tables_units(self):
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "manifest.json"), "w") as f:
                json.dump({"results": {"runout_m": 50.0, "building": {"house": {"peak_force_n": 2.5e6}}}}, f)
            with open(os.path.join(d, "front.csv"), "w") as f:
                f.write("time_s,front_m,front_speed_m_s,mean_speed_m_s,joints_broken\n0,5,0,0,0\n0.4,6,1,1,0\n")
            np.save(os.path.join(d, "height_initial.npy"), np.zeros((2, 2)))
            np.save(os.path.join(d, "height_final.npy"), np.ones((2, 2)))
            run = y.read_seed_run(d)
            self.assertEqual(run["scalars"]["runout"], 50.0)
            self.assertEqual(run["scalars"]["house_peak_force"], 2.5)
            self.assertIsNone(run["scalars"]["house_impulse"])
            np.testing.assert_array_equal(run["front"], [5.0, 6.0])


if __name__ == "__main__":
    unittest.main()
