"""A committed reference run (data/NAME) as the paper sees it: never rerun here
(scripts/make-canonical-data.sh remakes it), but stale when its scene or the
code of its solver changed since the commit its manifest records.
"""
import os
import subprocess

from code_version import sha256_file, solver_folders
from values import read_json


def _git(root, *args):
    return subprocess.run(["git", "-C", root, *args], capture_output=True, text=True)


def changed_since(root, commit, folders):
    """Files of `folders` that differ between `commit` and the working tree; None if the commit is unknown."""
    if _git(root, "cat-file", "-e", f"{commit}^{{commit}}").returncode != 0:
        return None
    diff = _git(root, "diff", "--name-only", commit, "--", *folders)
    untracked = _git(root, "ls-files", "--others", "--exclude-standard", "--", *folders)
    return sorted(set(diff.stdout.split()) | set(untracked.stdout.split()))


def _scene_reasons(root, manifest):
    scene = manifest.get("scene", {})
    path = scene.get("path", "")
    if not path:
        return []
    if not os.path.exists(os.path.join(root, path)):
        return [f"scene {path}: no longer exists"]
    if sha256_file(os.path.join(root, path)) != scene.get("sha256"):
        return [f"scene {path}: changed since the data were made"]
    return []


def data_code_versions(root, libraries, manifest, solvers, current):
    """{component: version} of the code that made the data: the current hash when
    nothing changed since its clean commit, else 'commit X (+ uncommitted changes)'."""
    build = manifest.get("build", {})
    commit, dirty = build.get("git_commit", "unknown"), bool(build.get("git_dirty", False))
    versions, reasons = {}, []
    for solver in solvers:
        key = f"solver {solver}"
        try:
            folders = solver_folders(libraries, solver)
        except KeyError:
            versions[key] = "absent"
            continue
        changed = changed_since(root, commit, folders)
        if changed is None:
            reasons.append(f"code of {key}: commit {commit[:10]} is not in this repository")
        elif changed:
            reasons.append(f"code of {key}: {len(changed)} file(s) changed since commit {commit[:10]} "
                           f"(e.g. {changed[0]})")
        if changed == [] and not dirty:
            versions[key] = current[key]
        else:
            versions[key] = f"commit {commit[:10]}" + (" + uncommitted changes" if dirty else "")
    return versions, reasons


def data_status(root, libraries, entry, current_code):
    """(code versions, stale reasons, manifest) of a data entry; reasons empty when fresh."""
    path = os.path.join(root, entry.path, "manifest.json")
    manifest = read_json(path)
    versions, reasons = data_code_versions(root, libraries, manifest, entry.solvers, current_code)
    return versions, _scene_reasons(root, manifest) + reasons, manifest
