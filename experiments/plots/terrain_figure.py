"""Contours and mesh of a generated terrain (seed paper 003, fig. 2 (d)-(e)):
left, the key contours (thick) and the generated, smoothed contours coloured
by height with the skeleton's summit points; right, the constrained Delaunay
mesh shaded by height, with the moving elements and building parts on top.
Usage: python3 terrain_figure.py RUN_FOLDER (MPLBACKEND=Agg); writes
RUN_FOLDER/terrain.png from the files terrain_outputs.h writes.
"""
import os
import sys

import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np
from figure_output import save


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                faces.append([int(p.split("/")[0]) - 1 for p in parts[1:4]])
    return np.array(vertices), np.array(faces, dtype=int)


def draw_contours(ax, folder):
    rows = np.load(os.path.join(folder, "contours.npy"))
    heights = rows[:, 3]
    norm = plt.Normalize(heights.min(), heights.max())
    for k in np.unique(rows[:, 0]):
        c = rows[rows[:, 0] == k]
        xy = np.vstack([c[:, 1:3], c[:1, 1:3]])
        key = c[0, 4] > 0
        ax.plot(xy[:, 0], xy[:, 1], color="k" if key else plt.cm.viridis(norm(c[0, 3])),
                lw=1.6 if key else 0.7)
    summits = os.path.join(folder, "summits.npy")
    if os.path.exists(summits):
        s = np.load(summits)
        ax.plot(s[:, 0], s[:, 1], ".", color="tab:red", ms=2, label="skeleton summit points")
        ax.legend(loc="lower right", fontsize=7)
    ax.set_title("key contours (black) and generated contours", fontsize=9)
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax, fraction=0.046, label="height (m)")


def draw_mesh(ax, folder):
    v, f = read_obj(os.path.join(folder, "terrain_mesh.obj"))
    tri = mtri.Triangulation(v[:, 0], v[:, 1], f)
    shade = ax.tripcolor(tri, v[:, 2], cmap="terrain", shading="gouraud")
    ax.triplot(tri, color="k", lw=0.1, alpha=0.4)
    plt.colorbar(shade, ax=ax, fraction=0.046, label="height (m)")
    elements = os.path.join(folder, "elements.npy")
    if os.path.exists(elements):
        e = np.load(elements)
        ax.scatter(e[:, 0], e[:, 1], s=2, c=e[:, 4], cmap="autumn", label="moving elements")
    buildings = os.path.join(folder, "buildings.obj")
    if os.path.exists(buildings):
        bv, bf = read_obj(buildings)
        ax.triplot(mtri.Triangulation(bv[:, 0], bv[:, 1], bf), color="tab:blue", lw=0.6)
    ax.set_title(f"constrained Delaunay mesh: {len(f)} triangles", fontsize=9)


def main():
    folder = sys.argv[1]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    draw_contours(axes[0], folder)
    draw_mesh(axes[1], folder)
    for ax in axes:
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
    fig.tight_layout()
    save(fig, folder, "terrain.png", dpi=130)
    plt.close(fig)


if __name__ == "__main__":
    main()
