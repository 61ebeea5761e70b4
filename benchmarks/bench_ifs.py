"""goldman_lib.ifs hot paths against a plain-Python loop, timed in the same run.

- the chaos game, Barnsley fern, 1,000,000 points (target: under 50 ms);
- the deterministic algorithm, Sierpinski gasket to 3^13 = 1,594,323 points from one point
  (target: under 50 ms for about a million points);
- the Hausdorff distance of 5,000 against 5,000 points, overlapping and a little apart (reference:
  scipy's directed_hausdorff; target within 3x).

The plain loops are the textbook algorithms written point by point in Python; they are timed on
fewer points (20,000 for the chaos game, 3^9 for the deterministic algorithm) and scaled
linearly to the full size, as the printed lines say.  Run: ``python -m benchmarks.bench_ifs``.
"""

from __future__ import annotations

import random

import numpy as np

from benchmarks.timing import best_time, best_times, fmt_time, report, report_targets
from goldman_lib import ifs
from goldman_lib.fixed_point import hausdorff_distance

TARGET = 0.050
#: Hausdorff distance: at most this multiple of scipy's directed_hausdorff (both directions), same run.
HAUSDORFF_TARGET = 3.0
CHAOS_POINTS = 1_000_000
LOOP_CHAOS_POINTS = 20_000
DET_LEVELS, LOOP_DET_LEVELS = 13, 9


def plain_chaos_game(system, n, seed=0):
    """The chaos game point by point in plain Python (the baseline)."""
    maps = [(M[0][0], M[0][1], M[1][0], M[1][1], M[2][0], M[2][1]) for M in system.maps.tolist()]
    weights = system.probabilities.tolist()
    rnd = random.Random(seed)
    choices = rnd.choices(range(len(maps)), weights=weights, k=n + 20)
    x = y = 0.0
    out = []
    for step, i in enumerate(choices):
        a, b, c, d, e, f = maps[i]
        x, y = x * a + y * c + e, x * b + y * d + f
        if step >= 20:
            out.append((x, y))
    return out


def plain_deterministic(system, levels):
    """The deterministic algorithm point by point in plain Python (the baseline)."""
    maps = [(M[0][0], M[0][1], M[1][0], M[1][1], M[2][0], M[2][1]) for M in system.maps.tolist()]
    pts = [(0.0, 0.0)]
    for _ in range(levels):
        pts = [(x * a + y * c + e, x * b + y * d + f) for (a, b, c, d, e, f) in maps for (x, y) in pts]
    return pts


def main() -> dict[str, float]:
    fern = ifs.barnsley_fern()
    gasket = ifs.sierpinski()
    out = {}

    chaos = best_time(lambda: ifs.chaos_game(fern, CHAOS_POINTS, rng=0), repeat=5)
    loop = best_time(lambda: plain_chaos_game(fern, LOOP_CHAOS_POINTS), repeat=3) * CHAOS_POINTS / LOOP_CHAOS_POINTS
    report(f"chaos game, fern, {CHAOS_POINTS:,} points", chaos, loop,
           f"plain loop (timed at {LOOP_CHAOS_POINTS:,}, scaled)")
    print(f"    target {fmt_time(TARGET)}: {'ok' if chaos < TARGET else 'OVER'}")
    out["chaos"] = chaos

    n_det = 3 ** DET_LEVELS
    det = best_time(lambda: ifs.deterministic(gasket, DET_LEVELS, start=[[0.0, 0.0]]), repeat=5)
    loop = best_time(lambda: plain_deterministic(gasket, LOOP_DET_LEVELS), repeat=3) * 3 ** (DET_LEVELS - LOOP_DET_LEVELS)
    report(f"deterministic, gasket, {n_det:,} points", det, loop,
           f"plain loop (timed at {3 ** LOOP_DET_LEVELS:,}, scaled)")
    print(f"    target {fmt_time(TARGET)}: {'ok' if det < TARGET else 'OVER'}")
    out["deterministic"] = det

    from scipy.spatial.distance import directed_hausdorff

    rng = np.random.default_rng(0)
    A, B = rng.uniform(0, 1, (5000, 2)), rng.uniform(0, 1, (5000, 2))
    ratios = {}
    for label, key, (X, Y) in (("overlapping", "hausdorff_overlap", (A, B)),
                               ("a little apart", "hausdorff_apart", (A, B + [0.3, 0.1]))):
        ref = max(directed_hausdorff(X, Y)[0], directed_hausdorff(Y, X)[0])
        assert hausdorff_distance(X, Y) == ref
        ours, theirs = best_times(lambda: hausdorff_distance(X, Y),
                                  lambda: max(directed_hausdorff(X, Y)[0], directed_hausdorff(Y, X)[0]), repeat=5)
        report(f"Hausdorff distance, 5,000 x 5,000, {label}", ours, theirs, "scipy directed_hausdorff x2")
        out[key] = ours
        ratios[key] = ours / theirs
    report_targets(ratios, {key: HAUSDORFF_TARGET for key in ratios})
    return out


if __name__ == "__main__":
    main()
