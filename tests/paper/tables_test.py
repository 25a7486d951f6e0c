"""paper/tools/tables.py: tables from JSON lists and CSV rows; dashes only where allowed."""
import json
import os
import tempfile
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from inputs import parse_inputs
from tables import write_tables
from values import ValueMissing

INPUTS = """
experiments:
  - {id: calibration, command: calibrate, file: c.yaml}
  - {id: table1, command: experiment, file: t.yaml}
tables:
  scores:
    from: calibration
    file: calibration.json
    rows: scenes
    filter: {role: fit}
    caption: "Scores."
    columns:
      - {heading: scene, key: name}
      - {heading: "RMSE (mm)", key: rmse_m, scale: 1000, format: "{:.2f}"}
      - {heading: noise, key: noise_floor.rmse_m, if_missing: "--"}
  narrow:
    from: calibration
    file: calibration.json
    rows: scenes
    caption: "Names cut."
    size: footnotesize
    columns:
      - {heading: scene, key: name, until: " ("}
  times:
    from: table1
    file: table1.csv
    caption: "Times."
    columns:
      - {heading: case, key: case}
      - {heading: ms, key: ms_per_frame, format: "{:.1f}"}
"""


class TablesTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.folder = self.scratch.name
        self.inputs = parse_inputs(INPUTS)

    def tearDown(self):
        self.scratch.cleanup()

    def read(self, name):
        with open(os.path.join(self.folder, "out", f"{name}.tex")) as f:
            return f.read()

    def test_rows_filtered_scaled_and_dashed_where_allowed(self):
        with open(os.path.join(self.folder, "calibration.json"), "w") as f:
            json.dump({"scenes": [{"name": "dem_indent", "role": "fit", "rmse_m": 0.00261},
                                  {"name": "dem_drag", "role": "held_out", "rmse_m": 0.0039}]}, f)
        statuses = {"calibration": SimpleNamespace(usable=True, folder=self.folder),
                    "table1": SimpleNamespace(usable=False, folder="")}
        write_tables(os.path.join(self.folder, "out"), self.inputs, statuses)
        scores = self.read("scores")
        self.assertIn("dem\\_indent & 2.61 & -- \\\\", scores)
        self.assertNotIn("dem\\_drag", scores)
        self.assertIn("\\label{tab:scores}", scores)
        self.assertIn("\\notyetrun{table1}", self.read("times"))

    def test_a_narrow_table_cuts_its_text_and_sets_its_size(self):
        with open(os.path.join(self.folder, "calibration.json"), "w") as f:
            json.dump({"scenes": [{"name": "seed run (against the others)", "role": "held_out"},
                                  {"name": "other", "role": "fit", "rmse_m": 0.001}]}, f)
        statuses = {"calibration": SimpleNamespace(usable=True, folder=self.folder),
                    "table1": SimpleNamespace(usable=False, folder="")}
        write_tables(os.path.join(self.folder, "out"), self.inputs, statuses)
        narrow = self.read("narrow")
        self.assertIn("\\centering\\footnotesize", narrow)
        self.assertIn("seed run \\\\", narrow)
        self.assertNotIn("against", narrow)
        self.assertIn("other \\\\", narrow)
        self.assertIn("\\centering\\small", self.read("scores"))  # the default

    def test_an_unknown_size_is_refused(self):
        with self.assertRaisesRegex(Exception, "tables.narrow.size: 'huge'"):
            parse_inputs(INPUTS.replace("size: footnotesize", "size: huge"))

    def test_a_row_without_a_required_key_is_an_error(self):
        with open(os.path.join(self.folder, "table1.csv"), "w") as f:
            f.write("case,other\nsweep,1\n")
        statuses = {"table1": SimpleNamespace(usable=True, folder=self.folder)}
        with self.assertRaisesRegex(ValueMissing, "tables.times: a row has no 'ms_per_frame'"):
            write_tables(os.path.join(self.folder, "out"), self.inputs, statuses)


if __name__ == "__main__":
    unittest.main()
