"""Everything a cached run depends on, and what changed since it was made.

A fingerprint is a JSON object of named components, each a hash or a version:
  experiment   the experiment (or calibration) file's SHA-256
  inputs       every file or folder the file names (scenes, reference data,
               plot scripts), what those scenes name in turn (meshes,
               contours), and the entry's depends_on, by content hash
  code         per solver involved, a hash of its source folders
               (code_version.py), and one for the command that ran it
  engines      the library versions `repose --version` prints and the
               LIGGGHTS version
A run is stale when any component differs; `changes` says which, in words.
"""
import os
import subprocess
import tempfile

import yaml

from code_version import code_versions, sha256_file, tree_hash

SCENE_SUFFIXES = (".yaml", ".yml")


def _strings(node):
    if isinstance(node, str):
        yield node
    elif isinstance(node, dict):
        for value in node.values():
            yield from _strings(value)
    elif isinstance(node, list):
        for value in node:
            yield from _strings(value)


def _yaml(path):
    try:
        with open(path, encoding="utf-8") as f:
            return yaml.safe_load(f)
    except (OSError, yaml.YAMLError):
        return None


def referenced_paths(root, path, depth=2):
    """Repository-relative files/folders a YAML file names (relative to itself), recursively."""
    found = set()
    base = os.path.dirname(os.path.join(root, path))
    for text in _strings(_yaml(os.path.join(root, path))):
        if "/" not in text and "." not in text:
            continue
        candidate = os.path.normpath(os.path.join(base, text))
        if not os.path.exists(candidate) or not candidate.startswith(os.path.abspath(root) + os.sep):
            continue
        relative = os.path.relpath(candidate, root)
        found.add(relative)
        if depth > 1 and relative.endswith(SCENE_SUFFIXES) and os.path.isfile(candidate):
            found.update(referenced_paths(root, relative, depth - 1))
    return sorted(found)


def engine_versions(repose_bin):
    """Library lines of `repose --version` (not the commit: code is hashed per solver) and LIGGGHTS'."""
    out = subprocess.run([repose_bin, "--version"], capture_output=True, text=True, check=True).stdout
    lines = [line for line in out.splitlines()[3:] if line.strip()]
    try:
        with tempfile.TemporaryDirectory() as scratch:   # liggghts writes log.liggghts where it runs
            lig = subprocess.run(["liggghts", "-h"], capture_output=True, text=True, timeout=30,
                                 cwd=scratch).stdout.splitlines()
        lines.append(lig[0] if lig else "LIGGGHTS: no version printed")
    except (OSError, subprocess.TimeoutExpired):
        lines.append("LIGGGHTS: not installed")
    return lines


def fingerprint(root, libraries, entry, engines):
    """The fingerprint of an experiment or calibration entry (inputs.ExperimentInput)."""
    named = referenced_paths(root, entry.path) + list(entry.depends_on)
    inputs = {p: tree_hash(root, [p]) if os.path.exists(os.path.join(root, p)) else "absent" for p in named}
    return {"experiment": {entry.path: sha256_file(os.path.join(root, entry.path))},
            "inputs": inputs,
            "code": code_versions(root, libraries, entry.command, entry.solvers),
            "engines": list(engines)}


def _dict_changes(label, old, new):
    reasons = []
    for key in sorted(set(old) | set(new)):
        if key not in old:
            reasons.append(f"{label} {key}: new")
        elif key not in new:
            reasons.append(f"{label} {key}: no longer used")
        elif old[key] != new[key]:
            reasons.append(f"{label} {key}: changed")
    return reasons


def changes(old, new):
    """Why a run made with fingerprint `old` is stale now (empty: fresh)."""
    reasons = []
    reasons += _dict_changes("experiment file", old.get("experiment", {}), new["experiment"])
    reasons += _dict_changes("input", old.get("inputs", {}), new["inputs"])
    reasons += _dict_changes("code of", old.get("code", {}), new["code"])
    old_engines, new_engines = old.get("engines", []), new["engines"]
    for line in sorted(set(old_engines) ^ set(new_engines)):
        reasons.append(f"engine {'now' if line in new_engines else 'was'}: {line}")
    return reasons
