"""The paper's run folders: where each experiment's folder is, whether it is
fresh, stale (and why) or missing, and running `repose` to make it.

CACHE/ID/            the folder `repose experiment|calibrate` writes (atomically)
CACHE/ID.paper.json  the fingerprint it was made from, beside it (repose --force
                     replaces the folder, never this record before it succeeds)
A data entry's folder is the committed one (data/NAME); it is never run here.
"""
import json
import os
import subprocess
import sys
import time
from dataclasses import dataclass, field

from code_version import code_versions
from data_folder import data_status
from fingerprint import changes, fingerprint

FRESH, STALE, MISSING, ABSENT = "fresh", "stale", "missing", "absent"


@dataclass
class RunStatus:
    entry: object
    folder: str                 # absolute
    state: str                  # fresh | stale | missing | absent (optional file not there)
    reasons: list = field(default_factory=list)
    code: dict = field(default_factory=dict)      # code versions the folder was made with
    current: dict = field(default_factory=dict)   # fingerprint it would be made with now

    @property
    def usable(self):
        return self.state in (FRESH, STALE)


def shown_path(root, path):
    """A path as messages show it: relative inside the repository, absolute outside."""
    relative = os.path.relpath(path, root)
    return path if relative.startswith("..") else relative


def record_path(cache, entry_id):
    return os.path.join(cache, f"{entry_id}.paper.json")


def _read_record(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def status_of(root, cache, libraries, entry, engines):
    """The state of one entry of inputs.yaml, with the reasons when stale."""
    if entry.command == "data":
        folder = os.path.join(root, entry.path)
        if not os.path.exists(os.path.join(folder, "manifest.json")):
            return RunStatus(entry, folder, ABSENT if entry.optional else MISSING, [f"{entry.path}: no manifest.json"])
        current = code_versions(root, libraries, "data", entry.solvers)
        code, reasons, _ = data_status(root, libraries, entry, current)
        return RunStatus(entry, folder, STALE if reasons else FRESH, reasons, code, {"code": current})
    folder = os.path.join(cache, entry.id)
    if not os.path.exists(os.path.join(root, entry.path)):
        state = ABSENT if entry.optional else MISSING
        return RunStatus(entry, folder, state, [f"{entry.path}: no such file"])
    current = fingerprint(root, libraries, entry, engines)
    record = _read_record(record_path(cache, entry.id))
    if record is None or not os.path.exists(os.path.join(folder, "manifest.json")):
        return RunStatus(entry, folder, MISSING, ["never run into " + shown_path(root, folder)], {}, current)
    reasons = changes(record["fingerprint"], current)
    return RunStatus(entry, folder, STALE if reasons else FRESH, reasons, record["fingerprint"]["code"], current)


def previous_wall_s(status):
    """Wall time of the last run of this entry (its manifest), or the entry's estimate."""
    try:
        with open(os.path.join(status.folder, "manifest.json"), encoding="utf-8") as f:
            manifest = json.load(f)
        return float(manifest.get("total_wall_s", manifest.get("wall_time_s")))
    except (OSError, ValueError, TypeError):
        return status.entry.estimate_s


def run_entry(root, cache, repose_bin, status, log=sys.stdout):
    """Runs `repose experiment|calibrate FILE --out CACHE/ID --force`, its progress lines
    passed through; writes the record only once the folder is in place."""
    entry = status.entry
    os.makedirs(cache, exist_ok=True)
    command = ["nice", repose_bin, entry.command, entry.path, "--out", status.folder, "--force"]
    print(f"  $ {' '.join(command[1:])}", file=log, flush=True)
    start = time.monotonic()
    process = subprocess.Popen(command, cwd=root, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    for line in process.stdout:
        if not line.startswith("repose: "):   # the solvers' own percentage lines: too many to pass on
            print(f"  | {line.rstrip()}", file=log, flush=True)
    if process.wait() != 0:
        raise RuntimeError(f"{entry.id}: `{' '.join(command[1:])}` failed (exit status {process.returncode})")
    record = {"id": entry.id, "made_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
              "wall_s": time.monotonic() - start, "fingerprint": status.current}
    with open(record_path(cache, entry.id), "w", encoding="utf-8") as f:
        json.dump(record, f, indent=2)
    status.state, status.reasons, status.code = FRESH, [], status.current["code"]
