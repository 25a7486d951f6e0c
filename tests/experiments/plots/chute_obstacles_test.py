"""experiments/plots/chute_obstacles.py: a post's load and its pressure coefficient."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import chute_obstacles  # noqa: E402


class PostLoad(unittest.TestCase):
    def test_a_step_load_gives_its_level_as_mean_and_peak(self):
        t = np.arange(0.0, 1.0, 0.001)
        f = np.where(t >= 0.4, 2.0, 0.0)
        mean, peak = chute_obstacles.post_load(t, f, 0.2)
        self.assertAlmostEqual(mean, 2.0, places=6)
        self.assertAlmostEqual(peak, 2.0, places=6)

    def test_never_loaded_is_zero(self):
        t = np.arange(0.0, 0.5, 0.001)
        self.assertEqual(chute_obstacles.post_load(t, np.zeros_like(t), 0.1), (0.0, 0.0))

    def test_coefficient_is_the_pressure_over_rho_v_squared(self):
        # F = 0.6 N on 1.2 cm x 2 cm: 2500 Pa; rho v^2 = 500 * 2^2 = 2000 Pa
        self.assertAlmostEqual(chute_obstacles.coefficient(0.6, 0.012, 0.02, 500.0, 2.0), 1.25)

    def test_read_forces_takes_the_x_columns_in_order(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "forces.csv")
            with open(path, "w") as f:
                f.write("time_s,wall_fx_n,wall_fy_n,wall_fz_n,post_fx_n,post_fy_n,post_fz_n\n0,1,2,3,4,5,6\n0.1,7,8,9,10,11,12\n")
            t, fx = chute_obstacles.read_forces(path)
        self.assertEqual(list(t), [0.0, 0.1])
        self.assertEqual([list(c) for c in fx], [[1.0, 7.0], [4.0, 10.0]])


class IncomingFlow(unittest.TestCase):
    def test_the_short_chutes_runs_are_found_by_slope_and_release(self):
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "summary.csv"), "w") as f:
                f.write("name,solver,wall_s," + ",".join(chute_obstacles.FLOW_KEYS) + "\n")
                f.write("liggghts_short_35_0.2,liggghts,1,2.0,0.03,1.5,600\n")
                f.write("liggghts_35_0.2,liggghts,1,3.0,0.02,1.8,400\n")
                f.write("liggghts_short_45_0.1,liggghts,1,,,,\n")
            flows = chute_obstacles.incoming_flows(d)
        self.assertEqual(flows, {("35", "0.2"): (2.0, 0.03, 1.5, 600.0)})
        self.assertEqual(chute_obstacles.incoming_flows(None), {})


if __name__ == "__main__":
    unittest.main()
