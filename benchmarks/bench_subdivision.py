"""goldman_lib.bezier's subdivision (chapter 25) against the ``bezier`` package, timed in the same run.

- ``subdivide`` of a degree-3 and a degree-9 planar curve at t = 1/2 against
  ``bezier.Curve.subdivide`` (dhermes/bezier: compiled Fortran behind a Python object layer).
- ``intersect_curves`` on pairs of random cubics (several crossings each) and on a tangential pair
  of parabolas against ``bezier.Curve.intersect`` (its default geometric algorithm):
  :func:`bench_intersect`, run by ``benchmarks.bench_bezier`` with its targets.

Results are checked to agree before anything is timed; ours and the reference are timed in
interleaved rounds (best of several), so machine load hits both alike.
"""

from __future__ import annotations

import numpy as np

from benchmarks.timing import best_times, report
from goldman_lib import bezier as gb


def bench_subdivide(rng) -> dict[str, float]:
    import bezier as bz

    ratios = {}
    for degree in (3, 9):
        ctrl = rng.uniform(-1, 1, (degree + 1, 2))
        nodes = np.asfortranarray(ctrl.T)
        curve = bz.Curve(nodes, degree)
        left, right = curve.subdivide()
        ours = gb.subdivide(ctrl)
        err = max(float(np.abs(ours[0] - left.nodes.T).max()), float(np.abs(ours[1] - right.nodes.T).max()))
        if err > 1e-13:
            raise AssertionError(f"subdivide disagrees with bezier.Curve.subdivide by {err:.3g}")
        # the reference includes building its Curve object, as ours includes validating the array
        t_ref, t_ours = best_times(lambda: bz.Curve(nodes, degree, copy=False).subdivide(), lambda: gb.subdivide(ctrl))
        report(f"subdivide degree {degree}", t_ours, t_ref, "bezier")
        ratios[f"subdivide_{degree}"] = t_ours / t_ref
    return ratios


def _pairs(rng, count=6):
    """Random cubic pairs that cross (each pair has 1 or more intersections), plus a tangential pair."""
    import bezier as bz

    pairs = []
    while len(pairs) < count:
        a, b = rng.uniform(0, 1, (4, 2)), rng.uniform(0, 1, (4, 2))
        ref = bz.Curve(np.asfortranarray(a.T), 3).intersect(bz.Curve(np.asfortranarray(b.T), 3))
        if ref.shape[1] >= 2:
            pairs.append((a, b))
    tangent = (np.array([[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]]), np.array([[0.0, 1.0], [0.5, 0.0], [1.0, 1.0]]))
    return pairs, tangent


def bench_intersect(rng) -> dict[str, float]:
    import bezier as bz

    pairs, tangent = _pairs(rng)
    ref_curves = [(bz.Curve(np.asfortranarray(a.T), len(a) - 1), bz.Curve(np.asfortranarray(b.T), len(b) - 1))
                  for a, b in pairs]
    found = 0
    for (a, b), (ca, cb) in zip(pairs, ref_curves):
        ref = ca.intersect(cb).T
        ref = ref[np.argsort(ref[:, 0])]
        ours = gb.intersect_curves(a, b)
        if ours.shape != ref.shape or np.abs(ours - ref).max() > 1e-9:
            raise AssertionError(f"intersect_curves disagrees with bezier.Curve.intersect: {ours} vs {ref}")
        found += len(ref)

    def ours_all():
        for a, b in pairs:
            gb.intersect_curves(a, b)

    def ref_all():
        for ca, cb in ref_curves:
            ca.intersect(cb)

    t_ours, t_ref = best_times(ours_all, ref_all, repeat=5)
    report(f"intersect_curves {len(pairs)} cubic pairs ({found} points)", t_ours, t_ref, "bezier")
    ratios = {"intersect_cubics": t_ours / t_ref}

    ta, tb = tangent
    cta, ctb = bz.Curve(np.asfortranarray(ta.T), 2), bz.Curve(np.asfortranarray(tb.T), 2)
    ours = gb.intersect_curves(ta, tb)
    try:
        ref = cta.intersect(ctb).T
    except Exception as exc:  # the bezier package may refuse some tangent cases
        print(f"bezier.Curve.intersect on the tangential pair: {type(exc).__name__}: {exc}")
        return ratios
    if ours.shape != (1, 2) or np.abs(ours - [0.5, 0.5]).max() > 1e-6:
        raise AssertionError(f"intersect_curves on the tangential pair gave {ours}")
    t_ours, t_ref = best_times(lambda: gb.intersect_curves(ta, tb), lambda: cta.intersect(ctb), repeat=5)
    report(f"intersect_curves tangential parabolas ({len(ref)} point)", t_ours, t_ref, "bezier")
    ratios["intersect_tangent"] = t_ours / t_ref
    return ratios


def main() -> dict[str, float]:
    """subdivide only: the intersection cases run (with their 10x targets) in ``bench_bezier``."""
    return bench_subdivide(np.random.default_rng(25))


if __name__ == "__main__":
    main()
