"""paper/tools/values.py: key paths into JSON, cells of CSV, and no value without its source."""
import os
import tempfile
import unittest

import tools_path  # noqa: F401
from values import ValueMissing, csv_value, format_value, json_value, lookup

DOC = {"parameters": [{"name": "ground.sand.alpha", "value": 0.5}, {"name": "ground.sand.sigma", "value": 0.1}],
       "runs": [{"name": "a", "measures": {"streaks.ball.rms_m": 0.003}}], "ladder": {"rungs": [1, 2, 3]}}


class ValuesTest(unittest.TestCase):
    def test_select_by_a_value_with_dots(self):
        self.assertEqual(lookup(DOC, "parameters[name=ground.sand.sigma].value"), 0.1)

    def test_index_and_keys_holding_dots(self):
        self.assertEqual(lookup(DOC, "runs[0].measures.streaks.ball.rms_m"), 0.003)

    def test_count_of_a_list(self):
        self.assertEqual(lookup(DOC, "ladder.rungs.#count"), 3)

    def test_a_missing_key_or_selection_raises(self):
        for path in ("parameters[name=ground.mud.alpha].value", "ladder.yardstick", "runs[3]"):
            with self.assertRaises((KeyError, IndexError), msg=path):
                lookup(DOC, path)

    def test_files_missing_or_without_the_value_name_the_file(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "t.csv"), "w") as f:
                f.write("case,ms\nsweep,1.5\nno_sweep,\n")
            self.assertEqual(csv_value(folder, "t.csv", (("case", "sweep"),), "ms"), "1.5")
            with self.assertRaisesRegex(ValueMissing, "t.csv"):
                csv_value(folder, "t.csv", (("case", "no_sweep"),), "ms")
            with self.assertRaisesRegex(ValueMissing, "no such file"):
                json_value(folder, "calibration.json", "x")

    def test_format_scales_numbers_and_refuses_nan(self):
        self.assertEqual(format_value("0.00261", "{:.2f}", 1000.0), "2.61")
        self.assertEqual(format_value("determined", "{:.2f}", 1.0), "determined")
        with self.assertRaises(ValueMissing):
            format_value(float("nan"), "{:.2f}", 1.0)


if __name__ == "__main__":
    unittest.main()
