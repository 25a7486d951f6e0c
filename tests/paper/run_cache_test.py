"""paper/tools/run_cache.py: a cached folder is fresh until an input changes, then
stale with the reason; missing when never run; absent when optional and not there."""
import json
import os
import tempfile
import unittest

import tools_path  # noqa: F401
from code_version import cmake_libraries
from fake_repository import make_repository, write
from inputs import ExperimentInput
from run_cache import ABSENT, FRESH, MISSING, STALE, previous_wall_s, record_path, status_of

ENTRY = ExperimentInput("press", "experiment", "experiments/press.yaml", ("ground",), ("quick",), estimate_s=42.0)
ENGINES = ["Bullet 3.24"]


class RunCacheTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        self.cache = os.path.join(self.root, "runs", "paper")
        make_repository(self.root)

    def tearDown(self):
        self.scratch.cleanup()

    def status(self, entry=ENTRY, engines=ENGINES):
        return status_of(self.root, self.cache, cmake_libraries(self.root), entry, engines)

    def pretend_run(self, wall_s=12.5):
        """What run_entry leaves: the folder with its manifest, and the record beside it."""
        status = self.status()
        write(self.cache, "press/manifest.json", json.dumps({"total_wall_s": wall_s}))
        with open(record_path(self.cache, "press"), "w") as f:
            json.dump({"fingerprint": status.current}, f)

    def test_never_run_is_missing_with_the_first_estimate(self):
        status = self.status()
        self.assertEqual(status.state, MISSING)
        self.assertEqual(previous_wall_s(status), 42.0)

    def test_a_run_is_fresh_and_its_manifest_gives_the_estimate(self):
        self.pretend_run()
        status = self.status()
        self.assertEqual((status.state, status.reasons), (FRESH, []))
        self.assertEqual(previous_wall_s(status), 12.5)

    def test_a_changed_scene_makes_it_stale_with_the_reason(self):
        self.pretend_run()
        write(self.root, "experiments/scenes/press.yaml", "name: press\nseed: 9\n")
        status = self.status()
        self.assertEqual(status.state, STALE)
        self.assertIn("input experiments/scenes/press.yaml: changed", status.reasons)

    def test_changed_code_makes_it_stale_and_keeps_the_version_it_was_made_with(self):
        self.pretend_run()
        made_with = self.status().code["solver ground"]
        write(self.root, "models/ground/erosion.cpp", "// changed\n")
        status = self.status()
        self.assertEqual((status.state, status.reasons), (STALE, ["code of solver ground: changed"]))
        self.assertEqual(status.code["solver ground"], made_with)
        self.assertNotEqual(status.current["code"]["solver ground"], made_with)

    def test_a_folder_without_its_record_is_missing(self):
        self.pretend_run()
        os.remove(record_path(self.cache, "press"))
        self.assertEqual(self.status().state, MISSING)

    def test_an_optional_experiment_not_written_yet_is_absent(self):
        entry = ExperimentInput("scoop", "experiment", "experiments/scoop.yaml", ("heightspan",), ("quick",),
                                optional=True)
        status = self.status(entry)
        self.assertEqual(status.state, ABSENT)
        self.assertFalse(status.usable)

    def test_a_solver_with_no_library_yet_is_absent_code(self):
        entry = ExperimentInput("press", "experiment", "experiments/press.yaml", ("heightspan",), ("quick",))
        self.assertEqual(self.status(entry).current["code"]["solver heightspan"], "absent")


if __name__ == "__main__":
    unittest.main()
