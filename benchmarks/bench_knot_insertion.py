"""goldman_lib.knot_insertion against geomdl (NURBS-Python) and a plain-Python loop, timed in the same run.

- ``boehm_insert``: one knot inserted (p = 3, 200 control points), and the same knot 3 times,
  against ``geomdl.operations.insert_knot`` on a ``BSpline.Curve`` (and
  ``geomdl.helpers.knot_insertion``, the bare routine without the object's bookkeeping), and a
  plain-Python textbook loop over lists;
- ``oslo``: the knot vector of ``geomdl.operations.refine_knotvector`` (density 1: geomdl inserts
  the midpoint of every span and raises every knot to multiplicity p, 200 control points -> 1183), against that geomdl call and
  against repeated plain-Python Boehm insertion of the same knots;
- ``lane_riesenfeld`` / ``schaefer``: levels 1..8 of a 20-point cubic timed alone, with the
  number of points per level (no reference library implements them).

A single insertion into 200 points is a few dozen array operations; at that size most of
``boehm_insert``'s time is the validation at the public boundary (``bspline.check_knots`` about
15 us), which the bare Python loop skips, so the plain loop wins there; Oslo with many knots is
where the vectorised blossom pyramids pay.

Every result is checked against the reference before anything is timed, and the functions are
timed in interleaved rounds (best of several) so that machine load hits all alike.
"""

from __future__ import annotations

import copy
from collections import Counter

import numpy as np

from benchmarks.timing import best_time, best_times, fmt_time, report, report_targets
from goldman_lib import knot_insertion as ki

DEGREE = 3
N_CTRL = 200


def _curve(rng):
    ctrl = rng.uniform(-1, 1, (N_CTRL, 2))
    inner = np.linspace(0, 1, N_CTRL - DEGREE + 1)[1:-1]
    knots = np.r_[np.zeros(DEGREE + 1), inner, np.ones(DEGREE + 1)]
    return ctrl, knots


def _geomdl_curve(ctrl, knots):
    from geomdl import BSpline

    c = BSpline.Curve()
    c.degree = DEGREE
    c.ctrlpts = ctrl.tolist()
    c.knotvector = knots.tolist()
    return c


def boehm_python(ctrl, knots, p, u):
    """Boehm's algorithm as a textbook loop over Python lists (the plain-Python baseline)."""
    k = 0
    while not (knots[k] <= u < knots[k + 1]):
        k += 1
    new = []
    for i in range(len(ctrl) + 1):
        if i <= k - p:
            new.append(ctrl[i])
        elif i > k:
            new.append(ctrl[i - 1])
        else:
            a = (u - knots[i]) / (knots[i + p] - knots[i])
            new.append([(1 - a) * x + a * y for x, y in zip(ctrl[i - 1], ctrl[i])])
    return new, knots[:k + 1] + [u] + knots[k + 1:]


def bench_boehm(rng) -> dict[str, float]:
    from geomdl import helpers, operations

    ctrl, knots = _curve(rng)
    u = 0.123456
    base = _geomdl_curve(ctrl, knots)
    ratios = {}
    for times in (1, 3):
        ref = copy.deepcopy(base)
        operations.insert_knot(ref, [u], [times])
        ours, our_knots = ki.boehm_insert(ctrl, knots, DEGREE, u, times)
        err = float(np.abs(ours - np.array(ref.ctrlpts)).max())
        if err > 1e-12 or not np.allclose(our_knots, ref.knotvector):
            raise AssertionError(f"boehm_insert disagrees with geomdl insert_knot by {err:.3g}")
        s = 0
        kv, cp = knots.tolist(), ctrl.tolist()

        def geomdl_op():
            c = _geomdl_curve(ctrl, knots)       # insert_knot changes the curve in place
            operations.insert_knot(c, [u], [times])

        def geomdl_helper():
            return helpers.knot_insertion(DEGREE, kv, cp, u, num=times, s=s)

        def python_loop():
            c, t = cp, kv
            for _ in range(times):
                c, t = boehm_python(c, t, DEGREE, u)
            return c

        np.testing.assert_allclose(python_loop(), ours, atol=1e-12)
        np.testing.assert_allclose(geomdl_helper(), ours, atol=1e-12)
        t_ours, t_op, t_help, t_py = best_times(lambda: ki.boehm_insert(ctrl, knots, DEGREE, u, times),
                                                geomdl_op, geomdl_helper, python_loop)
        label = f"boehm_insert x{times} ({N_CTRL} pts, p={DEGREE})"
        report(f"{label} vs insert_knot", t_ours, t_op, "geomdl")
        report(f"{label} vs knot_insertion", t_ours, t_help, "geomdl helper")
        report(f"{label} vs Python loop", t_ours, t_py, "python")
        ratios[f"boehm_x{times}_vs_geomdl"] = t_ours / t_op
        ratios[f"boehm_x{times}_vs_helper"] = t_ours / t_help
        ratios[f"boehm_x{times}_vs_python"] = t_ours / t_py
    return ratios


def bench_oslo(rng) -> dict[str, float]:
    from geomdl import operations

    ctrl, knots = _curve(rng)
    ref = _geomdl_curve(ctrl, knots)
    operations.refine_knotvector(ref, [1])
    tau = np.array(ref.knotvector)
    ours = ki.oslo(ctrl, knots, DEGREE, tau)
    err = float(np.abs(ours - np.array(ref.ctrlpts)).max())
    if err > 1e-12:
        raise AssertionError(f"oslo disagrees with geomdl refine_knotvector by {err:.3g}")
    left = Counter(knots.tolist())
    extra = []                                            # tau minus knots, as multisets
    for x in tau.tolist():
        if left[x]:
            left[x] -= 1
        else:
            extra.append(x)
    cp0, kv0 = ctrl.tolist(), knots.tolist()

    def geomdl_refine():
        c = _geomdl_curve(ctrl, knots)
        operations.refine_knotvector(c, [1])

    def python_loop():
        c, t = cp0, kv0
        for x in extra:
            c, t = boehm_python(c, t, DEGREE, x)
        return c

    np.testing.assert_allclose(python_loop(), ours, atol=1e-12)
    t_ours, t_ref, t_py = best_times(lambda: ki.oslo(ctrl, knots, DEGREE, tau), geomdl_refine, python_loop,
                                     repeat=5)
    label = f"oslo, {len(extra)} knots ({N_CTRL} -> {len(ours)} pts)"
    report(f"{label} vs refine_knotvector", t_ours, t_ref, "geomdl")
    report(f"{label} vs Python Boehm loop", t_ours, t_py, "python")
    return {"oslo_vs_geomdl": t_ours / t_ref, "oslo_vs_python": t_ours / t_py}


def bench_subdivision(rng) -> dict[str, float]:
    ctrl = rng.uniform(-1, 1, (20, 2))
    knots = np.arange(20 + DEGREE + 1, dtype=float)
    out = {}
    for level in (1, 4, 8):
        lr = ki.lane_riesenfeld(ctrl, DEGREE, level)
        sc, _ = ki.schaefer(ctrl, knots, DEGREE, level)
        if not np.allclose(lr, sc):
            raise AssertionError("lane_riesenfeld and schaefer disagree on uniform knots")
        t_lr = best_time(lambda: ki.lane_riesenfeld(ctrl, DEGREE, level))
        t_sc = best_time(lambda: ki.schaefer(ctrl, knots, DEGREE, level))
        report(f"lane_riesenfeld level {level} (20 -> {len(lr)} pts)", t_lr)
        report(f"schaefer        level {level} (20 -> {len(sc)} pts)", t_sc)
        print(f"{'':44}      schaefer / lane_riesenfeld = {t_sc / t_lr:.1f}x  "
              f"({fmt_time(t_lr / len(lr))} per point)")
        out[f"lr_level_{level}"] = t_lr
    return out


def main() -> dict[str, float]:
    rng = np.random.default_rng(28)
    ratios = {**bench_boehm(rng), **bench_oslo(rng)}
    bench_subdivision(rng)
    targets = {"boehm_x1_vs_geomdl": 1.0, "oslo_vs_geomdl": 1.0}
    report_targets(ratios, targets)
    return ratios


if __name__ == "__main__":
    main()
