"""Is a wall force averaged over a wider window around its peak less noisy between beds?

usage: python3 chute_peak_window.py REFERENCE_PREFIX [OTHER_PREFIX]
e.g.   python3 chute_peak_window.py data/chute_rock_45/seed data/chute_rock_45_bullet/seed
Reads PREFIX1..3/forces.csv (time_s, then the wall's x force: the first object's)
of three beds, and for each window width (10, 30, 50, 100, 200 ms) prints the
largest force averaged over that window anywhere in the run (the windowed
peak, called that: it is not the impact-phase peak chute.peak.force_n, which
also restricts the search to the impact phase), the beds' relative standard
deviation, the standard error of their mean, and, with a second prefix, the
other engine's three-bed mean against the reference's. Issue 14: the peak
force's bed-to-bed noise bounds how finely the Bullet fit can be judged.
"""
import csv
import sys

import numpy as np

WINDOWS_S = [0.01, 0.03, 0.05, 0.1, 0.2]


def read_force(folder):
    """(time_s, x force) of a run's wall from its forces.csv."""
    with open(f"{folder}/forces.csv", newline="") as f:
        rows = list(csv.reader(f))[1:]
    return np.array([float(r[0]) for r in rows]), np.array([float(r[1]) for r in rows])


def windowed_peak(time_s, force, window_s):
    """The largest mean of |force| over [t - w/2, t + w/2] for t at every sample (w: window_s)."""
    magnitude = np.abs(force)
    best = 0.0
    for t in time_s:
        inside = (time_s >= t - 0.5 * window_s) & (time_s <= t + 0.5 * window_s)
        best = max(best, float(magnitude[inside].mean()))
    return best


def bed_statistics(values):
    """(mean, relative standard deviation, relative standard error of the mean) of the beds' values."""
    values = np.asarray(values, dtype=float)
    mean = float(values.mean())
    sd = float(values.std(ddof=1)) / mean
    return mean, sd, sd / np.sqrt(len(values))


def main(reference, other=None):
    print("window_s,reference_beds,mean_n,sd_pct,se_of_mean_pct" + (",other_mean_error_pct" if other else ""))
    for w in WINDOWS_S:
        ref = [windowed_peak(*read_force(f"{reference}{s}"), w) for s in (1, 2, 3)]
        mean, sd, se = bed_statistics(ref)
        line = f"{w:g},{' '.join(f'{v:.4g}' for v in ref)},{mean:.4g},{100 * sd:.1f},{100 * se:.1f}"
        if other:
            them = [windowed_peak(*read_force(f"{other}{s}"), w) for s in (1, 2, 3)]
            line += f",{100 * (np.mean(them) / mean - 1):.1f}"
        print(line)


if __name__ == "__main__":
    main(*sys.argv[1:3])
