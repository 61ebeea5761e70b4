"""goldman_lib.bezier against compiled references, timed in the same run.

- a degree-7 2D curve at 10,000 parameters: ``de_casteljau`` and ``bernstein_evaluate`` against
  ``bezier.Curve.evaluate_multi`` (dhermes/bezier, compiled Fortran); targets (issue 19 §5):
  de_casteljau within 3x, bernstein_evaluate (the fast path for drawing) within 1.5x.
- the evaluation the views use: a cubic at 400 parameters (the curves of the chapter 24-26 views),
  redrawn on every drag by ``curve_sampler(3, 400)`` (the Bernstein basis at those parameters made
  once, each curve one checked matrix product), against the same peer; target within 1.5x.
  ``de_casteljau`` at that size is printed beside it, without a target: see below.
- a bicubic patch on a 100 x 100 grid: ``patch_evaluate_grid`` (and, for reference,
  ``patch_de_casteljau`` on the same points) against ``scipy.interpolate.bisplev`` with the
  equivalent B-spline (knots 0,0,0,0,1,1,1,1 in each direction; one call per coordinate);
  target: at least as fast.
- ``bezier.intersect_curves`` (chapter 25, :mod:`goldman_lib.bezier_intersection`) on six crossing
  cubic pairs and on a tangential pair against ``bezier.Curve.intersect`` (the cases of
  ``benchmarks.bench_subdivision.bench_intersect``); target (issue 19 §5): within 3x, the
  tangential case included.

The results are checked to agree before anything is timed, and ours and the reference are timed
in interleaved rounds (best of several), so that machine load hits both alike.

A note on de_casteljau: its pyramid holds n rows of (d, len(t)) points, about 1.3 MB here.  Fresh
arrays per call cost a page fault per 4 KB (glibc maps blocks above 128 KB afresh and unmaps them
on free), and on 4 KB pages TLB misses: that, not the arithmetic, was most of its time.  The kernel
(:func:`goldman_lib.kernels.pyramids.casteljau_apex`) now keeps the rows in a per-thread scratch on
2 MiB pages.  What is left is the arithmetic: n(n+1)/2 nodes of three numpy passes each (84
passes over 20,000 numbers at degree 7), about four times the operations of the peer's O(n)
Horner form, which ``bernstein_evaluate`` uses.  At the views' size (a cubic at 400 parameters)
the peer takes about 4 us, less than the checks of a public call (as_points, as_parameter, the
finiteness of the result: about 6 us) and numpy's dispatch of the pyramid's 19 array operations
(about 0.6 us each).  So the views draw with :class:`goldman_lib.bezier.CurveSampler`, whose
checks are one pass over the control points and whose arithmetic is one matrix product.
"""

from __future__ import annotations

import numpy as np

from benchmarks.timing import best_times, report, report_targets
from goldman_lib import bezier as gb

CURVE_DEGREE = 7
CURVE_SAMPLES = 10_000
PATCH_GRID = 100
VIEW_SAMPLES = 400


def bench_curve(rng) -> dict[str, float]:
    import bezier as bz

    ctrl = rng.uniform(-1, 1, (CURVE_DEGREE + 1, 2))
    t = np.linspace(0.0, 1.0, CURVE_SAMPLES)
    ref_curve = bz.Curve(np.asfortranarray(ctrl.T), CURVE_DEGREE)
    ref = ref_curve.evaluate_multi(t).T
    for name, fn in (("de_casteljau", gb.de_casteljau), ("bernstein_evaluate", gb.bernstein_evaluate)):
        err = float(np.abs(fn(ctrl, t) - ref).max())
        if err > 1e-12:
            raise AssertionError(f"{name} disagrees with bezier.Curve.evaluate_multi by {err:.3g}")
    t_ref, t_dc, t_bern = best_times(lambda: ref_curve.evaluate_multi(t),
                                     lambda: gb.de_casteljau(ctrl, t),
                                     lambda: gb.bernstein_evaluate(ctrl, t))
    label = f"degree-{CURVE_DEGREE} 2D curve, {CURVE_SAMPLES} params"
    report(f"de_casteljau       {label}", t_dc, t_ref, "bezier")
    report(f"bernstein_evaluate {label}", t_bern, t_ref, "bezier")

    cubic = rng.uniform(-1, 1, (4, 2))
    tv = np.linspace(0.0, 1.0, VIEW_SAMPLES)
    view_curve = bz.Curve(np.asfortranarray(cubic.T), 3)
    err = float(np.abs(gb.de_casteljau(cubic, tv) - view_curve.evaluate_multi(tv).T).max())
    if err > 1e-12:
        raise AssertionError(f"de_casteljau disagrees with bezier.Curve.evaluate_multi by {err:.3g}")
    err = float(np.abs(gb.curve_sampler(3, VIEW_SAMPLES)(cubic) - view_curve.evaluate_multi(tv).T).max())
    if err > 1e-12:
        raise AssertionError(f"curve_sampler disagrees with bezier.Curve.evaluate_multi by {err:.3g}")
    t_vref, t_dcv, t_view = best_times(lambda: view_curve.evaluate_multi(tv), lambda: gb.de_casteljau(cubic, tv),
                                       lambda: gb.curve_sampler(3, VIEW_SAMPLES)(cubic))
    report(f"de_casteljau       cubic, {VIEW_SAMPLES} params", t_dcv, t_vref, "bezier")
    report(f"curve_sampler      cubic, {VIEW_SAMPLES} params (the views' redraw)", t_view, t_vref, "bezier")
    return {"de_casteljau": t_dc / t_ref, "bernstein_evaluate": t_bern / t_ref, "view_evaluation": t_view / t_vref}


def bench_patch(rng) -> dict[str, float]:
    from scipy.interpolate import bisplev

    net = rng.uniform(-1, 1, (4, 4, 3))
    u = np.linspace(0.0, 1.0, PATCH_GRID)
    v = np.linspace(0.0, 1.0, PATCH_GRID)
    knots = np.array([0, 0, 0, 0, 1, 1, 1, 1], dtype=float)
    tcks = [(knots, knots, np.ascontiguousarray(net[:, :, c]).ravel(), 3, 3) for c in range(3)]

    def reference():
        return [bisplev(u, v, tck) for tck in tcks]

    ref = np.stack(reference(), axis=-1)
    ours = gb.patch_evaluate_grid(net, u, v)
    U, V = np.meshgrid(u, v, indexing="ij")
    for name, got in (("patch_evaluate_grid", ours), ("patch_de_casteljau", gb.patch_de_casteljau(net, U, V))):
        err = float(np.abs(got - ref).max())
        if err > 1e-12:
            raise AssertionError(f"{name} disagrees with scipy.interpolate.bisplev by {err:.3g}")
    t_ref, t_grid, t_dc = best_times(reference,
                                     lambda: gb.patch_evaluate_grid(net, u, v),
                                     lambda: gb.patch_de_casteljau(net, U, V))
    label = f"bicubic patch, {PATCH_GRID}x{PATCH_GRID} grid"
    report(f"patch_evaluate_grid {label}", t_grid, t_ref, "bisplev")
    report(f"patch_de_casteljau  {label}", t_dc, t_ref, "bisplev")
    return {"patch_evaluate_grid": t_grid / t_ref, "patch_de_casteljau": t_dc / t_ref}


def main() -> dict[str, float]:
    rng = np.random.default_rng(24)
    ratios = {**bench_curve(rng), **bench_patch(rng)}
    from benchmarks.bench_subdivision import bench_intersect

    ratios.update(bench_intersect(np.random.default_rng(25)))
    targets = {"de_casteljau": 3.0, "bernstein_evaluate": 1.5, "view_evaluation": 1.5,
               "patch_evaluate_grid": 1.0, "intersect_cubics": 3.0, "intersect_tangent": 3.0}
    report_targets(ratios, {k: v for k, v in targets.items() if k in ratios})
    return ratios


if __name__ == "__main__":
    main()
