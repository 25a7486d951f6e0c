"""paper/tools/inputs.py: inputs.yaml read once; every broken rule names the entry and key."""
import os
import unittest

import tools_path
from inputs import InputsError, load_inputs, parse_inputs

GOOD = """
experiments:
  - {id: calibration, command: calibrate, file: experiments/c.yaml, solvers: [ground], modes: [quick]}
  - {id: pile, command: data, folder: data/dem_pile, solvers: [liggghts]}
macros:
  GroundAlpha: {from: calibration, file: calibration.json, key: "parameters[name=a].value", format: "{:.2f}"}
  PileAngle: {from: pile, file: runout.csv, row: {k: v}, column: angle}
"""


class InputsTest(unittest.TestCase):
    def test_a_good_file(self):
        inputs = parse_inputs(GOOD)
        self.assertEqual([e.id for e in inputs.experiments], ["calibration", "pile"])
        self.assertEqual(inputs.experiment("pile").path, "data/dem_pile")
        self.assertEqual(inputs.macros[1].source.row, (("k", "v"),))

    def test_broken_rules_are_named(self):
        cases = {
            GOOD.replace("GroundAlpha", "GroundAlpha2"): "letters only",
            GOOD.replace("from: pile", "from: pyle"): "macros.PileAngle.from: no experiment 'pyle'",
            GOOD.replace("command: calibrate", "command: calibrat"): "experiments[0].command",
            GOOD.replace("modes: [quick]", "modes: [fast]"): "experiments[0].modes",
            GOOD.replace("solvers: [liggghts]", "solvers: [liggghts], modes: [full]"): "never run",
            GOOD.replace("format: \"{:.2f}\"", "format: \"{:q}\""): "GroundAlpha.format",
            GOOD.replace("column: angle", "column: angle, colour: red"): "unknown key(s) colour",
            GOOD + "  X: {from: pile, file: m.json}\n": "key: required",
        }
        for text, message in cases.items():
            with self.assertRaises(InputsError, msg=message) as raised:
                parse_inputs(text)
            self.assertIn(message, str(raised.exception))

    def test_the_papers_own_inputs_load(self):
        inputs = load_inputs(os.path.join(tools_path.REPOSITORY, "paper", "inputs.yaml"))
        self.assertIn("calibration", [e.id for e in inputs.experiments])


if __name__ == "__main__":
    unittest.main()
