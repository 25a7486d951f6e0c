"""experiments/heightspan/flank_ensemble.py: the scoop's flank over beds and sigma jitters."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "heightspan"))
import flank_ensemble  # noqa: E402


class FlankEnsemble(unittest.TestCase):
    def test_reads_a_calibrations_fitted_values_by_name(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "parameters.yaml")
            with open(path, "w") as f:
                f.write("# comment\nheightspan.sand.sigma: 0.18  # +- 0.002 1\nheightspan.wedge_fraction: 1  # +- 0.01 1\n")
            self.assertEqual(flank_ensemble.read_parameters(path), {"sand.sigma": 0.18, "wedge_fraction": 1.0})
            with open(path, "w") as f:
                f.write("ground.sand.sigma: 0.18\n")
            with self.assertRaises(SystemExit):
                flank_ensemble.read_parameters(path)

    def test_material_values_go_to_the_ground_model_and_the_rest_to_heightspan(self):
        args = flank_ensemble.overrides({"sand.alpha": 0.3, "intake_layer_m": 0.005})
        self.assertEqual(args, ["--set", "ground_model.materials.sand.alpha=0.3",
                                "--set", "heightspan.intake_layer_m=0.005"])

    def test_the_jitter_moves_sigma_alone_and_symmetrically_within_5e_4(self):
        values = {"sand.sigma": 0.2, "sand.alpha": 0.3}
        sigmas = [flank_ensemble.jittered(values, f)["sand.sigma"] for f in flank_ensemble.JITTER]
        self.assertEqual(len(sigmas), 11)
        self.assertAlmostEqual(np.mean(sigmas), 0.2, places=15)
        self.assertAlmostEqual(max(sigmas) / 0.2 - 1.0, 5e-4, places=12)
        self.assertEqual(flank_ensemble.jittered(values, 1e-4)["sand.alpha"], 0.3)
        self.assertEqual(values["sand.sigma"], 0.2)  # the fitted values are not changed

    def test_summary_is_over_every_draw_with_per_bed_means(self):
        s = flank_ensemble.summary([[15.0, 17.0], [16.0, 18.0], [14.0, 16.0]])
        self.assertAlmostEqual(s["mean"], 16.0)
        self.assertAlmostEqual(s["sd"], np.std([15, 17, 16, 18, 14, 16], ddof=1))
        self.assertAlmostEqual(s["sem"], s["sd"] / np.sqrt(6))
        self.assertTrue(np.allclose(s["per_bed"], [16.0, 17.0, 15.0]))

    def test_held_mass_is_read_between_rows_and_compared_with_the_seeds_mean(self):
        with tempfile.TemporaryDirectory() as d:
            def csv(name, text):
                path = os.path.join(d, name)
                with open(path, "w") as f:
                    f.write(text)
                return path
            model = csv("model.csv", "time_s,bucket_volume_m3,bucket_mass_kg,in_flight_m3\n"
                                     "0.9,0,0.10,0\n1.1,0,0.12,0\n1.4,0,0.08,0\n1.7,0,0.08,0\n")
            seed_a = csv("a.csv", "time_s,bucket_mass_kg\n0,0\n1.0,0.10\n2.0,0.10\n")
            seed_b = csv("b.csv", "time_s,bucket_mass_kg\n0,0\n1.0,0.12\n2.0,0.06\n")
            self.assertTrue(np.allclose(flank_ensemble.held_at(model, [1.0, 1.25, 1.6]), [0.11, 0.10, 0.08]))
            # seeds' mean at 1.0 / 1.3 / 1.6 s: 0.11, 0.101, 0.092
            errors = flank_ensemble.held_error_percent([model], [seed_a, seed_b])
            expected = 100.0 * (np.array([0.11, 0.12 - 0.04 * 0.2 / 0.3, 0.08]) / np.array([0.11, 0.101, 0.092]) - 1.0)
            self.assertTrue(np.allclose(errors, expected))


if __name__ == "__main__":
    unittest.main()
