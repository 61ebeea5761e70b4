"""goldman_lib.ifs hot paths against their peers, timed in the same run.

- the chaos game, Barnsley fern, 1,000,000 points, against the numpy peer (:func:`numpy_chaos_game`:
  the same algorithm as a numpy user writes it, structure of arrays, all map choices drawn at once
  with ``Generator.choice``; it returns our points exactly) and a numba loop when numba is installed
  (target: within 1.2x of the numpy peer); the plain-Python loop is printed for scale;
- the deterministic algorithm, Sierpinski gasket to 3^13 = 1,594,323 points from one point
  (target: under 50 ms for about a million points);
- the Hausdorff distance of 5,000 against 5,000 points on every kind of set (overlapping, a little
  apart, far apart, one inside the hull of the other, a fractal against a fractal, clusters), against
  scipy's directed_hausdorff both ways; target within 2x on each.

The plain loops are the textbook algorithms written point by point in Python; they are timed on
fewer points (20,000 for the chaos game, 3^9 for the deterministic algorithm) and scaled
linearly to the full size, as the printed lines say.  Ours and the peers are timed in interleaved
rounds (best of several), so that machine load hits both alike.  Run: ``python -m benchmarks.bench_ifs``.
"""

from __future__ import annotations

import random

import numpy as np

from benchmarks.timing import best_time, best_times, fmt_time, report, report_targets
from goldman_lib import ifs
from goldman_lib.fixed_point import hausdorff_distance

TARGET = 0.050
#: The chaos game: at most this multiple of the numpy peer (and of numba's loop, if installed), same run.
CHAOS_TARGET = 1.2
#: Hausdorff distance: at most this multiple of scipy's directed_hausdorff (both directions), same run,
#: on every kind of set.
HAUSDORFF_TARGET = 2.0
CHAOS_CHAINS, CHAOS_BURN_IN = 4096, 20
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


def numpy_chaos_game(system, n, seed=0, chains=CHAOS_CHAINS, burn_in=CHAOS_BURN_IN):
    """The chaos game as a numpy user writes it (the peer): structure of arrays, x and y apart, for
    ``chains`` chains at once; every map choice drawn up front with ``Generator.choice``; chains
    start at the first map's fixed point and the first ``burn_in`` steps are discarded.  The
    same algorithm, start and draws as ``ifs.chaos_game(system, n, rng=seed)``, so the same points."""
    M = system.maps
    a, b, c, d, e, f = M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1], M[:, 2, 0], M[:, 2, 1]
    x0, y0 = np.linalg.solve((np.eye(2) - M[0, :2, :2]).T, M[0, 2, :2])   # (x, y) = (x, y) L + t
    rng = np.random.default_rng(seed)
    steps = -(-n // chains)
    idx = rng.choice(len(M), size=(burn_in + steps, chains), p=system.probabilities)
    x, y = np.full(chains, x0), np.full(chains, y0)
    xs, ys = np.empty((steps, chains)), np.empty((steps, chains))
    for s in range(burn_in + steps):
        i = idx[s]
        x, y = x * a[i] + y * c[i] + e[i], x * b[i] + y * d[i] + f[i]
        if s >= burn_in:
            xs[s - burn_in], ys[s - burn_in] = x, y
    return np.stack([xs.reshape(-1)[:n], ys.reshape(-1)[:n]], axis=1)


def numba_chaos_game():
    """The same chaos game as one compiled loop over (step, chain), if numba is installed, else None."""
    try:
        import numba
    except ImportError:
        return None

    @numba.njit(cache=False)
    def run(M, idx, x0, y0, burn_in, n):
        steps, chains = idx.shape
        out = np.empty(((steps - burn_in) * chains, 2))
        x, y = np.full(chains, x0), np.full(chains, y0)
        for s in range(steps):
            for j in range(chains):
                i = idx[s, j]
                xj, yj = x[j], y[j]
                x[j] = xj * M[i, 0, 0] + yj * M[i, 1, 0] + M[i, 2, 0]
                y[j] = xj * M[i, 0, 1] + yj * M[i, 1, 1] + M[i, 2, 1]
                if s >= burn_in:
                    out[(s - burn_in) * chains + j, 0] = x[j]
                    out[(s - burn_in) * chains + j, 1] = y[j]
        return out[:n]

    def chaos(system, n, seed=0, chains=CHAOS_CHAINS, burn_in=CHAOS_BURN_IN):
        M = system.maps
        x0, y0 = np.linalg.solve((np.eye(2) - M[0, :2, :2]).T, M[0, 2, :2])
        steps = -(-n // chains)
        idx = np.random.default_rng(seed).choice(len(M), size=(burn_in + steps, chains), p=system.probabilities)
        return run(M, idx, x0, y0, burn_in, n)
    return chaos


def hausdorff_sets(size=5000, seed=0):
    """The kinds of point sets the Hausdorff distance meets, ``size`` points each: two uniform
    samples of the unit square overlapping, a little apart (shifted by (0.3, 0.1)), far apart
    (shifted by (3, 2)), one inside the hull of the other (a square of side 0.2 in the middle), a
    circle inside the square, the fern against another chaos-game sample of the fern, and two samples
    of five tight clusters."""
    rng = np.random.default_rng(seed)
    A, B = rng.uniform(0, 1, (size, 2)), rng.uniform(0, 1, (size, 2))
    t = 2 * np.pi * B[:, 0]
    fern = ifs.barnsley_fern()

    def clusters():
        return rng.normal(0, 0.01, (size, 2)) + rng.integers(0, 5, (size, 1)) * 0.2
    return {"overlapping": (A, B), "a little apart": (A, B + [0.3, 0.1]), "far apart": (A, B + [3.0, 2.0]),
            "inside the hull": (A, 0.4 + 0.2 * B),
            "circle inside": (A, 0.5 + 0.3 * np.stack([np.cos(t), np.sin(t)], axis=1)),
            "fern, two samples": (ifs.chaos_game(fern, size, rng=1), ifs.chaos_game(fern, size, rng=2)),
            "clusters": (clusters(), clusters())}


def main() -> dict[str, float]:
    fern = ifs.barnsley_fern()
    gasket = ifs.sierpinski()
    out = {}

    ours = ifs.chaos_game(fern, CHAOS_POINTS, rng=0)
    peers = [("numpy SoA", numpy_chaos_game)]
    numba_peer = numba_chaos_game()
    if numba_peer is None:
        print("    (numba is not installed: no numba loop)")
    else:
        peers.append(("numba loop", numba_peer))
    for name, peer in peers:
        diff = float(np.abs(peer(fern, CHAOS_POINTS) - ours).max())
        if diff > 1e-12:
            raise AssertionError(f"the {name} chaos game's points differ from ours by {diff:.3g}")
    times = best_times(lambda: ifs.chaos_game(fern, CHAOS_POINTS, rng=0),
                       *[lambda peer=peer: peer(fern, CHAOS_POINTS) for _, peer in peers], repeat=7)
    chaos = times[0]
    ratios = {}
    for (name, _), t_peer in zip(peers, times[1:]):
        report(f"chaos game, fern, {CHAOS_POINTS:,} points", chaos, t_peer, name)
        ratios[f"chaos/{name.split()[0]}"] = chaos / t_peer
    loop = best_time(lambda: plain_chaos_game(fern, LOOP_CHAOS_POINTS), repeat=3) * CHAOS_POINTS / LOOP_CHAOS_POINTS
    report(f"chaos game, fern, {CHAOS_POINTS:,} points", chaos, loop,
           f"plain loop (timed at {LOOP_CHAOS_POINTS:,}, scaled)")
    report_targets(ratios, {key: CHAOS_TARGET for key in ratios})
    out["chaos"] = chaos

    n_det = 3 ** DET_LEVELS
    det = best_time(lambda: ifs.deterministic(gasket, DET_LEVELS, start=[[0.0, 0.0]]), repeat=5)
    loop = best_time(lambda: plain_deterministic(gasket, LOOP_DET_LEVELS), repeat=3) * 3 ** (DET_LEVELS - LOOP_DET_LEVELS)
    report(f"deterministic, gasket, {n_det:,} points", det, loop,
           f"plain loop (timed at {3 ** LOOP_DET_LEVELS:,}, scaled)")
    print(f"    target {fmt_time(TARGET)}: {'ok' if det < TARGET else 'OVER'}")
    out["deterministic"] = det

    from scipy.spatial.distance import directed_hausdorff

    ratios = {}
    for label, (X, Y) in hausdorff_sets().items():
        ref = max(directed_hausdorff(X, Y)[0], directed_hausdorff(Y, X)[0])
        if hausdorff_distance(X, Y) != ref:
            raise AssertionError(f"hausdorff_distance differs from scipy's on sets {label}")
        ours, theirs = best_times(lambda X=X, Y=Y: hausdorff_distance(X, Y),
                                  lambda X=X, Y=Y: max(directed_hausdorff(X, Y)[0], directed_hausdorff(Y, X)[0]),
                                  repeat=7)
        report(f"Hausdorff distance, 5,000 x 5,000, {label}", ours, theirs, "scipy directed_hausdorff x2")
        key = "hausdorff " + label
        out[key] = ours
        ratios[key] = ours / theirs
    report_targets(ratios, {key: HAUSDORFF_TARGET for key in ratios})
    return out


if __name__ == "__main__":
    main()
