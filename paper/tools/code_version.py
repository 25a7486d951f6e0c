"""The code version of a solver: a hash of the source folders it is built from.

The folders come from the CMake library graph (`repose_add_library(NAME FOLDER
DEPS...)` in models/, validation/, experiments/): solver `ground` is target
repose_ground, built from models/ground and, transitively, every repose_*
library it links. Only these folders decide the solver's results, so an edit
elsewhere leaves its runs fresh. The hash is of the files' contents as they
are in the working tree (committed or not).
"""
import hashlib
import os
import re

CMAKE_FILES = ("models/CMakeLists.txt", "validation/CMakeLists.txt", "experiments/CMakeLists.txt")
ADD_LIBRARY = re.compile(r"repose_add_library\(\s*(\S+)\s+(\S+)([^)]*)\)")
# what drives a command beside the solvers (the runner writes summary.csv; calibrate fits)
COMMAND_TARGETS = {"experiment": ("experiments/runner",), "calibrate": ("experiments/runner",)}
COMMAND_LIBRARIES = {"experiment": (), "calibrate": ("repose_calibration",)}
SKIPPED = ("__pycache__",)


def sha256_file(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _files_under(root, relative):
    top = os.path.join(root, relative)
    if os.path.isfile(top):
        return [relative]
    files = []
    for folder, dirs, names in os.walk(top):
        dirs[:] = sorted(d for d in dirs if d not in SKIPPED)
        for name in names:
            if not name.endswith(".pyc"):
                files.append(os.path.relpath(os.path.join(folder, name), root))
    return sorted(files)


def tree_hash(root, relatives):
    """SHA-256 over (path, content hash) of every file under the given files/folders."""
    h = hashlib.sha256()
    for relative in sorted(set(relatives)):
        for path in _files_under(root, relative):
            h.update(f"{path}\0{sha256_file(os.path.join(root, path))}\n".encode())
    return h.hexdigest()


def cmake_libraries(root):
    """{target: (folder, [repose_* deps])} from the repose_add_library lines."""
    libraries = {}
    for cmake in CMAKE_FILES:
        path = os.path.join(root, cmake)
        if not os.path.exists(path):
            continue
        base = os.path.dirname(cmake)
        with open(path, encoding="utf-8") as f:
            text = re.sub(r"#.*", "", f.read())
        for name, folder, deps in ADD_LIBRARY.findall(text):
            libraries[name] = (f"{base}/{folder}", [d for d in deps.split() if d.startswith("repose_")])
    return libraries


def library_folders(libraries, target):
    """The folders of `target` and of every repose_* library it links, transitively."""
    if target not in libraries:
        raise KeyError(target)
    seen, stack, folders = set(), [target], set()
    while stack:
        name = stack.pop()
        if name in seen or name not in libraries:
            continue
        seen.add(name)
        folder, deps = libraries[name]
        folders.add(folder)
        stack.extend(deps)
    return sorted(folders)


def solver_folders(libraries, solver):
    """Folders of solver NAME (target repose_NAME); KeyError when no such library exists yet.

    `--solver liggghts` runs dem scenes through repose_liggghts and terrain
    (debris) scenes through repose_liggghts_debris, which links it and the
    debris set-up the rigid engines share (validation/rigid, models/terrain):
    an input made from a terrain scene lists solver `liggghts_debris`, so that
    the dem inputs do not go stale whenever the debris code changes.
    """
    return library_folders(libraries, "repose_" + solver.replace("-", "_"))


def command_folders(libraries, command):
    folders = set(COMMAND_TARGETS.get(command, ()))
    for target in COMMAND_LIBRARIES.get(command, ()):
        folders.update(library_folders(libraries, target))
    return sorted(folders)


def code_versions(root, libraries, command, solvers):
    """{component: hash}: one per solver (missing solvers as 'absent') and one for the command."""
    versions = {}
    for solver in solvers:
        try:
            versions[f"solver {solver}"] = tree_hash(root, solver_folders(libraries, solver))
        except KeyError:
            versions[f"solver {solver}"] = "absent"
    if command in COMMAND_TARGETS:
        versions[f"repose {command}"] = tree_hash(root, command_folders(libraries, command))
    return versions
