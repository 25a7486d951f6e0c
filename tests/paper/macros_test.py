"""paper/tools/macros.py: a macro per value, 'not yet run' without a folder, an error for a missing key."""
import json
import os
import tempfile
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from inputs import parse_inputs
from macros import latex_number, write_macros
from values import ValueMissing

INPUTS = """
experiments:
  - {id: calibration, command: calibrate, file: c.yaml, modes: [quick]}
  - {id: scoop, command: experiment, file: s.yaml, optional: true}
macros:
  GroundAlpha: {from: calibration, file: calibration.json, key: "alpha", format: "{:.2f}"}
  GroundSpeedup: {from: calibration, file: calibration.json, key: "speedup", format: "{:.1e}"}
  ScoopMass: {from: scoop, file: summary.csv, row: {name: a}, column: mass_kg}
"""


class MacrosTest(unittest.TestCase):
    def test_scientific_notation_is_latex(self):
        self.assertEqual(latex_number("1.2e+04"), r"\ensuremath{1.2\times10^{4}}")
        self.assertEqual(latex_number("1.0e+04"), r"\ensuremath{1.0\times10^{4}}")
        self.assertEqual(latex_number("3.0e-05"), r"\ensuremath{3.0\times10^{-5}}")
        self.assertEqual(latex_number("0.42"), "0.42")
        self.assertEqual(latex_number("not_run"), r"not\_run")

    def test_values_and_not_yet_run(self):
        inputs = parse_inputs(INPUTS)
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "calibration.json"), "w") as f:
                json.dump({"alpha": 0.01648, "speedup": 9456.0}, f)
            statuses = {"calibration": SimpleNamespace(usable=True, folder=folder),
                        "scoop": SimpleNamespace(usable=False, folder="")}
            path = os.path.join(folder, "macros.tex")
            write_macros(path, inputs, statuses, [("PaperMode", "quick")])
            with open(path) as f:
                text = f.read()
        self.assertIn("\\newcommand{\\GroundAlpha}{0.02}\n", text)
        self.assertIn("\\newcommand{\\GroundSpeedup}{\\ensuremath{9.5\\times10^{3}}}\n", text)
        self.assertIn("\\newcommand{\\ScoopMass}{\\notyetrun{scoop}}\n", text)
        self.assertIn("\\newcommand{\\PaperMode}{quick}\n", text)

    def test_a_run_folder_without_the_value_is_an_error(self):
        inputs = parse_inputs(INPUTS)
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "calibration.json"), "w") as f:
                json.dump({"alpha": 0.5}, f)
            statuses = {"calibration": SimpleNamespace(usable=True, folder=folder)}
            with self.assertRaisesRegex(ValueMissing, r"\\GroundSpeedup: .*calibration.json: no value at 'speedup'"):
                write_macros(os.path.join(folder, "macros.tex"), inputs, statuses)
            self.assertFalse(os.path.exists(os.path.join(folder, "macros.tex")))


if __name__ == "__main__":
    unittest.main()
