"""Engine disagreement as a band: an observable's spread across engines beside
its spread across seeds (issue 11, item 3), from an experiment's summary.csv
rows (csv.DictReader: name, solver, then the measures).

A run belongs to the engine its `solver` column names; its seed is whatever
else tells the runs apart (the sweep's values). For one observable:

  per engine    n, mean and sample standard deviation over its seeds
  seed_spread   the pooled within-engine standard deviation,
                sqrt(sum((n_e - 1) s_e^2) / sum(n_e - 1)): how far two beds
                of the same engine differ
  engine_std    the sample standard deviation of the engines' means
  engine_range  the largest engine mean minus the smallest
  ratio         engine_std / seed_spread (inf when the seeds agree exactly)

The engines' means carry seed noise of seed_spread / sqrt(n) each, so an
engine_std well above that is disagreement the seeds cannot explain.

Surfaces (final height fields on the scene's grid) compare as pairs of runs:
pair_rmse gives the RMSE of every pair, grouped by (engine, engine) with
within-engine pairs (two beds) apart from cross-engine pairs.
"""
import math

import numpy as np


def engine_values(rows, observable):
    """{engine: [values]} of the rows whose `observable` is set, in row order."""
    out = {}
    for row in rows:
        text = row.get(observable, "")
        if text is None or text == "":
            continue
        out.setdefault(row["solver"], []).append(float(text))
    return out


def band(values_by_engine):
    """The band of one observable (see the module doc) as a dict; None
    without at least two engines. Engines with one value count in the engine
    spread but not in the seed spread."""
    engines = sorted(values_by_engine)
    if len(engines) < 2:
        return None
    per_engine = {}
    pooled_ss = 0.0
    pooled_dof = 0
    for engine in engines:
        v = np.asarray(values_by_engine[engine], dtype=float)
        std = float(v.std(ddof=1)) if v.size > 1 else float("nan")
        per_engine[engine] = {"n": int(v.size), "mean": float(v.mean()), "std": std}
        if v.size > 1:
            pooled_ss += float(((v - v.mean()) ** 2).sum())
            pooled_dof += v.size - 1
    means = np.array([per_engine[e]["mean"] for e in engines])
    seed_spread = math.sqrt(pooled_ss / pooled_dof) if pooled_dof > 0 else float("nan")
    engine_std = float(means.std(ddof=1))
    if seed_spread > 0:
        ratio = engine_std / seed_spread
    else:
        ratio = float("inf") if engine_std > 0 else float("nan")
    return {
        "engines": per_engine,
        "seed_spread": seed_spread,
        "engine_std": engine_std,
        "engine_range": float(means.max() - means.min()),
        "ratio": ratio,
    }


def band_table(rows, observables):
    """[(observable, band)] for each observable with a band, in the given order."""
    table = []
    for observable in observables:
        b = band(engine_values(rows, observable))
        if b is not None:
            table.append((observable, b))
    return table


def rmse(a, b):
    """Root-mean-square difference of two arrays of one shape (NaN cells skipped)."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    if a.shape != b.shape:
        raise ValueError("engine_band: fields of shapes {} and {} cannot be compared".format(a.shape, b.shape))
    d = (a - b)[np.isfinite(a - b)]
    return float(np.sqrt(np.mean(d * d))) if d.size else float("nan")


def pair_rmse(fields):
    """fields: [(engine, array)]. Returns {(engine_a, engine_b): [rmse]} over
    every pair of runs, engine_a <= engine_b: (e, e) holds the within-engine
    pairs (different seeds), (e, f) the cross-engine pairs."""
    out = {}
    for i in range(len(fields)):
        for j in range(i + 1, len(fields)):
            (ea, fa), (eb, fb) = fields[i], fields[j]
            key = tuple(sorted((ea, eb)))
            out.setdefault(key, []).append(rmse(fa, fb))
    return out
