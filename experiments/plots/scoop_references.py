"""The mass a bucket holds over a scoop, per engine and seed, in one figure and one table.

Reads FOLDER/held_mass.csv of each run folder given (a height-span run's, or a
particle reference's: data/ref_scoop/seedN, data/ref_scoop_bullet/seedN; the
<object>_mass_kg columns, validation/particles/held_mass_series.h), plots the
held mass against time, one line per folder coloured by its label, and
prints the mass at each stage time (Markdown table) to standard output.
Usage:
  python3 scoop_references.py OUT.png --stages 1.0 1.3 1.6 2.3 LABEL=FOLDER [LABEL=FOLDER ...]
(MPLBACKEND=Agg). Several folders may share a label (the seeds of one engine).
"""
import argparse
import csv
import os

import matplotlib.pyplot as plt


def read_held(folder, column="bucket_mass_kg"):
    with open(os.path.join(folder, "held_mass.csv")) as f:
        rows = list(csv.DictReader(f))
    return [float(r["time_s"]) for r in rows], [float(r[column]) for r in rows]


def at(ts, ms, t):
    """Linear between samples, held outside (as TimeSeries::at)."""
    if t <= ts[0]:
        return ms[0]
    if t >= ts[-1]:
        return ms[-1]
    for k in range(1, len(ts)):
        if t <= ts[k]:
            a = (t - ts[k - 1]) / (ts[k] - ts[k - 1]) if ts[k] > ts[k - 1] else 1.0
            return (1 - a) * ms[k - 1] + a * ms[k]
    return ms[-1]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--stages", type=float, nargs="+", default=[1.0, 1.3, 1.6, 2.3])
    parser.add_argument("--object", default="bucket")
    parser.add_argument("runs", nargs="+", help="LABEL=FOLDER")
    args = parser.parse_args()
    colours = {}
    fig, ax = plt.subplots(figsize=(7, 3.5))
    print("| run | " + " | ".join(f"{t:g} s (g)" for t in args.stages) + " |")
    print("|---|" + "---|" * len(args.stages))
    for run in args.runs:
        label, folder = run.split("=", 1)
        ts, ms = read_held(folder, args.object + "_mass_kg")
        first = label not in colours
        colour = colours.setdefault(label, f"C{len(colours)}")
        ax.plot(ts, [1e3 * m for m in ms], color=colour, lw=1, label=label if first else None)
        print(f"| {label} {os.path.basename(os.path.normpath(folder))} | " +
              " | ".join(f"{1e3 * at(ts, ms, t):.1f}" for t in args.stages) + " |")
    for t in args.stages:
        ax.axvline(t, color="0.7", lw=0.8, ls=":")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"mass held by the {args.object} (g)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    main()
