"""experiments/plots/debris_render3d.py: finding the program, reading its series, the grid."""
import os
import stat
import sys
import tempfile
import unittest

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import debris_render3d  # noqa: E402

# Stands in for `repose render RUN -o PREFIX.png --frames N`: writes PREFIX_000.png
# and PREFIX_002.png (a red and a blue image) and prints their paths.
FAKE = """#!/usr/bin/python3
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
prefix = sys.argv[sys.argv.index("-o") + 1][:-4]
for k, rgb in ((0, (1, 0, 0)), (2, (0, 0, 1))):
    plt.imsave("{}_{:03d}.png".format(prefix, k), np.tile(np.array(rgb, float), (12, 16, 1)))
    print("{}_{:03d}.png".format(prefix, k))
"""


def fake_program(folder):
    path = os.path.join(folder, "fake_repose")
    with open(path, "w") as f:
        f.write(FAKE)
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


class DebrisRender3dTest(unittest.TestCase):
    def test_the_program_is_the_experiments_own_first(self):
        with tempfile.TemporaryDirectory() as d:
            program = fake_program(d)
            self.assertEqual(debris_render3d.repose_program({"REPOSE_EXE": program, "REPOSE": "/nowhere"}), program)
            self.assertEqual(debris_render3d.repose_program({"REPOSE_EXE": "/nowhere", "REPOSE": program}), program)

    def test_the_series_is_read_from_the_programs_output_in_frame_order(self):
        with tempfile.TemporaryDirectory() as d:
            paths = debris_render3d.render_series(fake_program(d), d, os.path.join(d, "run_3d"), frames=2)
            self.assertEqual([debris_render3d.frame_index(p) for p in paths], [0, 2])
            self.assertTrue(all(os.path.getsize(p) > 0 for p in paths))

    def test_the_grid_holds_every_frame(self):
        with tempfile.TemporaryDirectory() as d:
            paths = debris_render3d.render_series(fake_program(d), d, os.path.join(d, "run_3d"), frames=2)
            out = os.path.join(d, "grid.png")
            debris_render3d.compose(paths, ["t = 0", "t = 1"], "run", out, columns=2)
            img = mpimg.imread(out)[..., :3]
            red = np.all(np.abs(img - [1, 0, 0]) < 0.05, axis=-1).sum()
            blue = np.all(np.abs(img - [0, 0, 1]) < 0.05, axis=-1).sum()
            self.assertGreater(red, 1000)
            self.assertGreater(blue, 1000)


if __name__ == "__main__":
    unittest.main()
