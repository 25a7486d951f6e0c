"""The debris collapse in 3-D: a run folder's frames rendered by `repose render RUN_DIR`
(OSMesa, experiments/debris/debris_render.h) and set side by side.

render_series(folder, prefix) runs `repose render FOLDER -o PREFIX.png --frames N`,
which writes PREFIX_NNN.png (NNN the frame's index in the run: the terrain, the
elements as spheres coloured by radius, the building parts grey in place and
red once moved, one oblique camera for the series); compose() sets them in a
grid titled with each frame's time and joints broken. The program is the one
the experiment runs in (REPOSE_EXE, set by `repose experiment`), else REPOSE,
else the repository's build/bin/repose.
"""
import os
import re
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

FRAME_PNG = re.compile(r"_(\d{3})\.png$")


def repose_program(environ=None):
    """The repose program to render with, or None when there is none."""
    environ = os.environ if environ is None else environ
    for key in ("REPOSE_EXE", "REPOSE"):
        path = environ.get(key)
        if path and os.access(path, os.X_OK):
            return path
    here = os.path.dirname(os.path.abspath(__file__))
    built = os.path.join(here, "..", "..", "build", "bin", "repose")
    return built if os.access(built, os.X_OK) else None


def render_series(program, folder, prefix, frames=6):
    """Runs `repose render` on a debris run folder; returns the PNGs written, in frame order."""
    out = subprocess.run([program, "render", folder, "-o", prefix + ".png", "--frames", str(frames)],
                         check=True, capture_output=True, text=True).stdout
    paths = [line.strip() for line in out.splitlines() if line.strip()]
    for p in paths:
        if not FRAME_PNG.search(p) or not os.path.exists(p):
            raise RuntimeError("repose render: unexpected output line {!r}".format(p))
    return paths


def compose(paths, labels, title, out_path, columns=3):
    """The frames in a grid (each titled with its label), written to out_path."""
    rows = (len(paths) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4.6 * columns, 3.6 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, path, label in zip(axes.flat, paths, labels):
        ax.imshow(mpimg.imread(path))
        ax.set_title(label, fontsize=9)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out_path, dpi=110)
    plt.close(fig)


def frame_index(path):
    return int(FRAME_PNG.search(path).group(1))
