"""paper/tools/fingerprint.py: what a run depends on, and the reasons it is stale."""
import tempfile
import unittest

import tools_path  # noqa: F401
from code_version import cmake_libraries
from fake_repository import make_repository, write
from fingerprint import changes, fingerprint, referenced_paths
from inputs import ExperimentInput

ENTRY = ExperimentInput("press", "experiment", "experiments/press.yaml", ("ground",), ("quick",))
ENGINES = ["Bullet 3.24", "LIGGGHTS 3.8.0"]


class FingerprintTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        make_repository(self.root)

    def tearDown(self):
        self.scratch.cleanup()

    def current(self, engines=ENGINES):
        return fingerprint(self.root, cmake_libraries(self.root), ENTRY, engines)

    def test_the_scene_its_mesh_and_the_plot_are_inputs(self):
        self.assertEqual(referenced_paths(self.root, ENTRY.path),
                         ["experiments/meshes/shoe.obj", "experiments/plots/press.py", "experiments/scenes/press.yaml"])

    def test_nothing_changed_is_fresh(self):
        self.assertEqual(changes(self.current(), self.current()), [])

    def test_a_changed_scene_is_named(self):
        old = self.current()
        write(self.root, "experiments/scenes/press.yaml", "name: press\nseed: 2\nobjects:\n  - {mesh: ../meshes/shoe.obj}\n")
        self.assertEqual(changes(old, self.current()), ["input experiments/scenes/press.yaml: changed"])

    def test_a_changed_mesh_the_scene_names_is_named(self):
        old = self.current()
        write(self.root, "experiments/meshes/shoe.obj", "v 0 0 1\n")
        self.assertEqual(changes(old, self.current()), ["input experiments/meshes/shoe.obj: changed"])

    def test_a_changed_experiment_file_is_named(self):
        old = self.current()
        write(self.root, "experiments/press.yaml", "name: press\nrepeat: 3\nruns:\n  - {name: a, scene: scenes/press.yaml}\n"
                                                    "plot: plots/press.py\n")
        self.assertEqual(changes(old, self.current()), ["experiment file experiments/press.yaml: changed"])

    def test_the_solvers_code_and_what_it_links_are_named(self):
        old = self.current()
        write(self.root, "models/ground/erosion.cpp", "// erosion, fixed\n")
        self.assertEqual(changes(old, self.current()), ["code of solver ground: changed"])
        old = self.current()
        write(self.root, "models/core/base/new.h", "// linked by ground\n")
        self.assertEqual(changes(old, self.current()), ["code of solver ground: changed"])

    def test_code_of_another_solver_leaves_it_fresh(self):
        old = self.current()
        write(self.root, "models/snow/snow.cpp", "// snow, changed\n")
        self.assertEqual(changes(old, self.current()), [])

    def test_the_runner_is_code_of_the_command(self):
        old = self.current()
        write(self.root, "experiments/runner/run.cpp", "// runner, changed\n")
        self.assertEqual(changes(old, self.current()), ["code of repose experiment: changed"])

    def test_what_the_entry_depends_on_beyond_its_file_is_an_input(self):
        entry = ExperimentInput("press", "experiment", "experiments/press.yaml", ("ground",), ("quick",),
                                depends_on=("data/pile",))
        write(self.root, "data/pile/height_final.csv", "1\n")
        libraries = cmake_libraries(self.root)
        old = fingerprint(self.root, libraries, entry, ENGINES)
        write(self.root, "data/pile/height_final.csv", "2\n")
        self.assertEqual(changes(old, fingerprint(self.root, libraries, entry, ENGINES)),
                         ["input data/pile: changed"])

    def test_an_engine_version_change_is_named(self):
        old = self.current()
        reasons = changes(old, self.current(["Bullet 3.25", "LIGGGHTS 3.8.0"]))
        self.assertEqual(reasons, ["engine was: Bullet 3.24", "engine now: Bullet 3.25"])


if __name__ == "__main__":
    unittest.main()
