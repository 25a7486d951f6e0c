"""The provenance appendix (generated/provenance.tex): every run folder the paper
used, with its manifest's commit, seeds and wall times, and the engine versions
the runs were made with."""
import os

from latex import GENERATED_HEADER, escape
from run_cache import shown_path
from values import read_json


def _seeds(manifest):
    if manifest.get("format") == "repose-experiment-manifest":
        seeds = sorted({r.get("seed") for r in manifest.get("runs", []) if r.get("seed") is not None})
    else:
        seed = manifest.get("scene", {}).get("seed", manifest.get("results", {}).get("seed"))
        seeds = [] if seed is None else [seed]
    if len(seeds) > 2 and seeds == list(range(seeds[0], seeds[-1] + 1)):
        return f"{seeds[0]}--{seeds[-1]}"
    return ", ".join(str(s) for s in seeds) or "--"


def _cpu_s(manifest):
    results = manifest.get("results", {})
    cpu = [results.get(k) for k in ("run_cpu_s", "bed_cpu_s") if isinstance(results.get(k), (int, float))]
    return f"{sum(cpu):.1f}" if cpu else "--"


def _engines(manifest):
    engines = dict(manifest.get("build", {}).get("libraries", {}))
    lig = manifest.get("results", {}).get("liggghts_version")
    if lig:
        engines["LIGGGHTS"] = lig.replace("LIGGGHTS (Version ", "").split(",")[0]
    return engines


def provenance_rows(root, statuses):
    """One row per run folder used: (folder, state, commit, seeds, wall s, CPU s, runs inside)."""
    rows = []
    for status in statuses:
        manifest = read_json(os.path.join(status.folder, "manifest.json"))
        build = manifest.get("build", {})
        commit = build.get("git_commit", "unknown")[:10] + ("+dirty" if build.get("git_dirty") else "")
        runs = len(manifest.get("runs", [])) or 1
        rows.append({"id": status.entry.id, "folder": shown_path(root, status.folder), "state": status.state,
                     "commit": commit, "seeds": _seeds(manifest), "runs": runs,
                     "wall_s": f"{float(manifest.get('total_wall_s', 0.0)):.1f}", "cpu_s": _cpu_s(manifest),
                     "engines": _engines(manifest)})
    return rows


def _engine_lines(rows):
    versions = {}
    for row in rows:
        for name, version in row["engines"].items():
            versions.setdefault(name, {}).setdefault(version, []).append(row["id"])
    lines = []
    for name in sorted(versions, key=str.lower):
        parts = [escape(v) + ("" if len(versions[name]) == 1 else " (" + escape(", ".join(ids)) + ")")
                 for v, ids in sorted(versions[name].items())]
        lines.append(f"{escape(name)} & {'; '.join(parts)} \\\\\n")
    return lines


def write_provenance(path, root, statuses):
    rows = provenance_rows(root, statuses)
    head = "run folder & state & commit & seeds & runs & wall (s) & CPU (s) \\\\\n"
    out = [GENERATED_HEADER, "\\begin{longtable}{llllrrr}\n",
           "\\caption{Every run folder this paper's numbers, tables and figures come from (state when built: "
           "fresh, or stale with the reasons the build printed).}\\label{tab:provenance}\\\\\n",
           "\\toprule\n", head, "\\midrule\n\\endfirsthead\n\\toprule\n", head, "\\midrule\n\\endhead\n"]
    for r in rows:
        out.append(f"\\path{{{r['folder']}}} & {r['state']} & \\texttt{{{escape(r['commit'])}}} & {r['seeds']} & "
                   f"{r['runs']} & {r['wall_s']} & {r['cpu_s']} \\\\\n")
    out += ["\\bottomrule\n\\end{longtable}\n\n", "\\begin{longtable}{lp{0.7\\textwidth}}\n",
            "\\caption{Engine and library versions recorded in those manifests.}\\label{tab:engines}\\\\\n",
            "\\toprule\nengine & version (runs, where they differ) \\\\\n\\midrule\n\\endfirsthead\n",
            "\\toprule\nengine & version (runs, where they differ) \\\\\n\\midrule\n\\endhead\n"]
    out += _engine_lines(rows)
    out.append("\\bottomrule\n\\end{longtable}\n")
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(out)
