"""The bucket's load over a height-span scoop run (experiments/scenes/heightspan_scoop.yaml).

Reads RUN_FOLDER/held_mass.csv (written by `repose run ... --solver heightspan`)
and writes RUN_FOLDER/held_mass.png: the mass each held object carries and the
material in the air against time, with the scene's stages (from its keyframe
times, given on the command line or the scoop scene's defaults) shaded.
Usage: python3 heightspan_scoop.py RUN_FOLDER [t_fill t_lift t_carry t_tip] (MPLBACKEND=Agg).
"""
import csv
import os
import sys

import matplotlib.pyplot as plt

# the scoop scene's stage ends (s): dragged (filled), lifted and turned upright, carried, tipped
DEFAULT_STAGES = [1.2, 1.8, 2.3, 2.8]
DENSITY_KG_M3 = 1600.0  # heightspan.bulk_density_kg_m3 of the scoop scene, for the material in the air


def main():
    folder = sys.argv[1]
    stages = [float(t) for t in sys.argv[2:6]] if len(sys.argv) >= 6 else DEFAULT_STAGES
    with open(os.path.join(folder, "held_mass.csv")) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time_s"]) for r in rows]
    objects = [k[: -len("_mass_kg")] for k in rows[0] if k.endswith("_mass_kg")]
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for name in objects:
        ax.plot(t, [1e3 * float(r[name + "_mass_kg"]) for r in rows], label=f"held by {name}")
    ax.plot(t, [1e3 * DENSITY_KG_M3 * float(r["in_flight_m3"]) for r in rows], label="in the air", linestyle="--")
    names = ["scoop", "lift", "carry", "tip", "pour"]
    edges = [0.0] + stages + [t[-1]]
    for k in range(len(edges) - 1):
        if k % 2 == 0:
            ax.axvspan(edges[k], edges[k + 1], color="0.93")
        ax.text(0.5 * (edges[k] + edges[k + 1]), ax.get_ylim()[1] * 0.95, names[k], ha="center", va="top", fontsize=8)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("mass (g)")
    ax.legend(loc="center right", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "held_mass.png"), dpi=120)


if __name__ == "__main__":
    main()
