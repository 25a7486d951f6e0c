"""paper/tools/provenance.py: each run folder with its commit, seeds and times; engines listed once."""
import json
import os
import tempfile
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from fake_repository import write
from provenance import provenance_rows, write_provenance

EXPERIMENT = {"format": "repose-experiment-manifest", "total_wall_s": 115.2,
              "build": {"git_commit": "9494a8fb6e70a0283fb5", "git_dirty": False, "libraries": {"Bullet": "3.24"}},
              "runs": [{"seed": s} for s in (1, 2, 3, 4, 1, 2, 3, 4)]}
DATA = {"format": "repose-run-manifest", "total_wall_s": 48.6, "scene": {"seed": 21},
        "build": {"git_commit": "4453300155aa", "git_dirty": True, "libraries": {"Bullet": "3.23"}},
        "results": {"run_cpu_s": 19.1, "bed_cpu_s": 4.6, "liggghts_version": "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, x)"}}


class ProvenanceTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        write(self.root, "runs/paper/tearing/manifest.json", json.dumps(EXPERIMENT))
        write(self.root, "data/dem_pile/manifest.json", json.dumps(DATA))
        self.statuses = [SimpleNamespace(entry=SimpleNamespace(id="tearing"), state="fresh",
                                         folder=os.path.join(self.root, "runs/paper/tearing")),
                         SimpleNamespace(entry=SimpleNamespace(id="dem_pile"), state="stale",
                                         folder=os.path.join(self.root, "data/dem_pile"))]

    def tearDown(self):
        self.scratch.cleanup()

    def test_rows(self):
        tearing, pile = provenance_rows(self.root, self.statuses)
        self.assertEqual((tearing["folder"], tearing["commit"], tearing["seeds"], tearing["runs"], tearing["wall_s"]),
                         ("runs/paper/tearing", "9494a8fb6e", "1--4", 8, "115.2"))
        self.assertEqual((pile["commit"], pile["seeds"], pile["cpu_s"], pile["engines"]["LIGGGHTS"]),
                         ("4453300155+dirty", "21", "23.7", "LIGGGHTS-PUBLIC 3.8.0"))

    def test_engine_versions_that_differ_name_their_runs(self):
        path = os.path.join(self.root, "provenance.tex")
        write_provenance(path, self.root, self.statuses)
        with open(path) as f:
            text = f.read()
        self.assertIn("Bullet & 3.23 (dem\\_pile); 3.24 (tearing) \\\\", text)
        self.assertEqual(text.count("\\label{tab:provenance}"), 1)


if __name__ == "__main__":
    unittest.main()
