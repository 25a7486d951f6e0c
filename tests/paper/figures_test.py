"""paper/tools/figures.py: the plot script writes PDF where the paper wants it; an
experiment without a folder gets a placeholder page; a figure not written is an error."""
import os
import tempfile
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from fake_repository import write
from figures import write_figures
from inputs import parse_inputs

PLOT = """import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__))))
import matplotlib.pyplot as plt
from figure_output import save
fig = plt.figure()
save(fig, sys.argv[1], "curve.png", dpi=50)
"""
INPUTS = """
experiments:
  - {id: run, command: experiment, file: e.yaml}
  - {id: later, command: experiment, file: l.yaml, optional: true}
figures:
  curve: {from: run, script: plots/curve.py, output: curve.pdf}
  wrong: {from: run, script: plots/curve.py, output: other.pdf}
  later: {from: later, script: plots/curve.py, output: curve.pdf}
"""


class FiguresTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        write(self.root, "plots/curve.py", PLOT)
        with open(os.path.join(tools_path.REPOSITORY, "experiments", "plots", "figure_output.py")) as f:
            write(self.root, "plots/figure_output.py", f.read())
        os.makedirs(os.path.join(self.root, "run"))
        self.statuses = {"run": SimpleNamespace(usable=True, folder=os.path.join(self.root, "run")),
                         "later": SimpleNamespace(usable=False, folder="")}

    def tearDown(self):
        self.scratch.cleanup()

    def test_pdf_from_the_script_and_a_placeholder_for_what_did_not_run(self):
        inputs = parse_inputs(INPUTS.replace("  wrong: {from: run, script: plots/curve.py, output: other.pdf}\n", ""))
        out = os.path.join(self.root, "figures")
        write_figures(self.root, out, inputs, self.statuses)
        for name in ("curve", "later"):
            with open(os.path.join(out, f"{name}.pdf"), "rb") as f:
                self.assertEqual(f.read(4), b"%PDF", name)
        self.assertEqual(os.listdir(os.path.join(self.root, "run")), [], "no PNG beside the data in PDF mode")

    def test_a_figure_the_script_does_not_write_is_named(self):
        with self.assertRaisesRegex(RuntimeError, "figures.wrong: plots/curve.py wrote no other.pdf"):
            write_figures(self.root, os.path.join(self.root, "figures"), parse_inputs(INPUTS), self.statuses)


if __name__ == "__main__":
    unittest.main()
