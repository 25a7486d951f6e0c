"""paper/tools/data_folder.py: committed reference data go stale when their scene or their
solver's code changed since the commit their manifest records."""
import json
import subprocess
import tempfile
import unittest

import tools_path  # noqa: F401
from code_version import cmake_libraries, code_versions, sha256_file
from data_folder import data_status
from fake_repository import make_repository, write
from inputs import ExperimentInput

ENTRY = ExperimentInput("pile", "data", "data/pile", ("ground",), ())


def git(root, *args):
    return subprocess.run(["git", "-C", root, *args], capture_output=True, text=True, check=True).stdout.strip()


class DataFolderTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        make_repository(self.root)
        git(self.root, "init", "-q")
        git(self.root, "add", "-A")
        git(self.root, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "start")
        self.commit = git(self.root, "rev-parse", "HEAD")

    def tearDown(self):
        self.scratch.cleanup()

    def manifest(self, commit=None, dirty=False):
        scene = "experiments/scenes/press.yaml"
        write(self.root, "data/pile/manifest.json", json.dumps({
            "scene": {"path": scene, "sha256": sha256_file(f"{self.root}/{scene}")},
            "build": {"git_commit": commit or self.commit, "git_dirty": dirty}}))

    def status(self):
        libraries = cmake_libraries(self.root)
        return data_status(self.root, libraries, ENTRY, code_versions(self.root, libraries, "data", ENTRY.solvers))

    def test_unchanged_since_a_clean_commit_is_fresh_at_the_current_version(self):
        self.manifest()
        versions, reasons, _ = self.status()
        self.assertEqual(reasons, [])
        libraries = cmake_libraries(self.root)
        self.assertEqual(versions, code_versions(self.root, libraries, "data", ENTRY.solvers))

    def test_changed_code_is_named_with_the_commit(self):
        self.manifest()
        write(self.root, "models/ground/erosion.cpp", "// changed\n")
        versions, reasons, _ = self.status()
        self.assertEqual(reasons, [f"code of solver ground: 1 file(s) changed since commit {self.commit[:10]} "
                                   "(e.g. models/ground/erosion.cpp)"])
        self.assertEqual(versions["solver ground"], f"commit {self.commit[:10]}")

    def test_a_changed_scene_is_named(self):
        self.manifest()
        write(self.root, "experiments/scenes/press.yaml", "name: press\nseed: 5\n")
        self.assertEqual(self.status()[1], ["scene experiments/scenes/press.yaml: changed since the data were made"])

    def test_a_dirty_tree_is_a_version_of_its_own(self):
        self.manifest(dirty=True)
        versions, reasons, _ = self.status()
        self.assertEqual(reasons, [])
        self.assertEqual(versions["solver ground"], f"commit {self.commit[:10]} + uncommitted changes")

    def test_an_unknown_commit_is_named(self):
        self.manifest(commit="0123456789" * 4)
        self.assertEqual(self.status()[1], ["code of solver ground: commit 0123456789 is not in this repository"])


if __name__ == "__main__":
    unittest.main()
