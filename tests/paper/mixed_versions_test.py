"""paper/tools/mixed_versions.py: runs of one solver made by two code versions are found."""
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from mixed_versions import describe, mixed_versions, remedies


def status(entry_id, command="experiment", path="", **code):
    return SimpleNamespace(entry=SimpleNamespace(id=entry_id, command=command, path=path),
                           code={k.replace("_", " "): v for k, v in code.items()})


class MixedVersionsTest(unittest.TestCase):
    def test_one_version_per_solver_is_not_mixed(self):
        runs = [status("calibration", solver_ground="a"), status("table1", solver_ground="a"),
                status("pile", solver_liggghts="commit 4453300155")]
        self.assertEqual(mixed_versions(runs), {})

    def test_two_versions_of_a_solver_are_mixed_and_named(self):
        runs = [status("calibration", solver_ground="a"), status("table1", solver_ground="b")]
        mixed = mixed_versions(runs)
        self.assertEqual(mixed, {"solver ground": {"a": ["calibration"], "b": ["table1"]}})
        self.assertIn("    b: table1", describe(mixed))

    def test_mixed_committed_data_is_remade_by_the_canonical_data_script(self):
        runs = [status("dem_indent", "data", "data/dem_indent", solver_liggghts="commit 4453300155"),
                status("dem_pile", "data", "data/dem_pile", solver_liggghts="commit 4453300155"),
                status("dem_repose_angle", solver_liggghts="aef0dd"), status("table1", solver_ground="a")]
        lines = remedies(mixed_versions(runs), runs)
        self.assertIn("scripts/make-canonical-data.sh dem_indent dem_pile", lines[0])
        self.assertIn("--full", lines[-1])
        self.assertEqual(len(remedies({"solver ground": {"a": ["x"], "b": ["y"]}}, runs)), 1)

    def test_an_absent_solver_is_no_version(self):
        runs = [status("scoop", solver_heightspan="absent"), status("other", solver_heightspan="h")]
        self.assertEqual(mixed_versions(runs), {})


if __name__ == "__main__":
    unittest.main()
