"""paper/tools/code_version.py: a solver's folders from the CMake library graph, hashed by content."""
import os
import tempfile
import unittest

import tools_path
from code_version import cmake_libraries, code_versions, solver_folders, tree_hash
from fake_repository import make_repository, write


class CodeVersionTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.root = self.scratch.name
        make_repository(self.root)

    def tearDown(self):
        self.scratch.cleanup()

    def test_a_solver_is_its_folder_and_what_it_links(self):
        libraries = cmake_libraries(self.root)
        self.assertEqual(solver_folders(libraries, "ground"), ["models/core/base", "models/ground"])
        with self.assertRaises(KeyError):
            solver_folders(libraries, "heightspan")

    def test_the_hash_follows_content_not_time(self):
        before = tree_hash(self.root, ["models/ground"])
        os.utime(os.path.join(self.root, "models/ground/erosion.cpp"), (1, 1))
        self.assertEqual(tree_hash(self.root, ["models/ground"]), before)
        write(self.root, "models/ground/erosion.cpp", "// changed\n")
        self.assertNotEqual(tree_hash(self.root, ["models/ground"]), before)

    def test_a_solver_without_a_library_is_absent(self):
        versions = code_versions(self.root, cmake_libraries(self.root), "data", ["heightspan", "ground"])
        self.assertEqual(versions["solver heightspan"], "absent")
        self.assertEqual(len(versions["solver ground"]), 64)

    def test_the_repositorys_solvers_are_found(self):
        libraries = cmake_libraries(tools_path.REPOSITORY)
        for solver in ("ground", "liggghts", "bullet", "ode", "snow", "tearing", "terrain"):
            self.assertIn("models/core/base", solver_folders(libraries, solver), solver)

    def test_liggghts_terrain_inputs_name_the_debris_library_and_dem_ones_do_not(self):
        libraries = cmake_libraries(tools_path.REPOSITORY)
        self.assertIn("validation/liggghts_debris", solver_folders(libraries, "liggghts_debris"))
        self.assertIn("validation/liggghts", solver_folders(libraries, "liggghts_debris"))
        self.assertNotIn("validation/liggghts_debris", solver_folders(libraries, "liggghts"))


if __name__ == "__main__":
    unittest.main()
