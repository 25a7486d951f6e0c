"""A small repository on disk for the staleness tests: two libraries (repose_base,
repose_ground on it) and an unrelated one, an experiment naming a scene that
names a mesh, and a data folder."""
import os


def write(root, path, text):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8") as f:
        f.write(text)


def make_repository(root):
    write(root, "models/CMakeLists.txt",
          "repose_add_library(repose_base core/base fmt::fmt)\n"
          "repose_add_library(repose_ground ground repose_base)  # the model\n"
          "repose_add_library(repose_snow snow repose_base)\n")
    write(root, "models/core/base/error.h", "// errors\n")
    write(root, "models/ground/erosion.cpp", "// erosion\n")
    write(root, "models/snow/snow.cpp", "// snow\n")
    write(root, "experiments/runner/run.cpp", "// runner\n")
    write(root, "experiments/meshes/shoe.obj", "v 0 0 0\n")
    write(root, "experiments/scenes/press.yaml", "name: press\nobjects:\n  - {mesh: ../meshes/shoe.obj}\n")
    write(root, "experiments/press.yaml", "name: press\nruns:\n  - {name: a, scene: scenes/press.yaml}\n"
                                          "plot: plots/press.py\n")
    write(root, "experiments/plots/press.py", "print('plot')\n")
