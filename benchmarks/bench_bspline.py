"""goldman_lib.bspline against scipy and geomdl, timed in the same run.

- ``de_boor`` on a cubic 3D curve with 50 control points at 10,000 parameters against
  ``scipy.interpolate.BSpline`` (compiled; target: within 1.2x, issue 19 §5) and
  ``geomdl.BSpline.Curve`` (pure Python; target: at least 50x faster).  ``global_de_boor`` (the
  global pyramid of §27.3: the full basis matrix times the control points) is printed beside it
  with its ratio, without a target.
- a bicubic B-spline surface with 10 x 10 control points on a 100 x 100 grid: ``surface_grid``
  (basis matrices ``N(u) P N(v)^T`` per coordinate) against ``scipy.interpolate.bisplev`` for the
  three coordinates; target: at least as fast.
- widget callbacks: see ``benchmarks.bench_callbacks`` (``main('knot_editor')``, ``main('bspline.')``).

The results are checked to agree before anything is timed, and ours and the reference are timed in
interleaved rounds (best of several), so that machine load hits both alike.  geomdl is slow, so it
is timed on 1,000 parameters and scaled to 10,000 (it is linear in the number of parameters).
"""

from __future__ import annotations

import numpy as np

from benchmarks.timing import best_time, best_times, report
from goldman_lib import bspline as gb

N_CTRL = 50
CURVE_SAMPLES = 10_000
GEOMDL_SAMPLES = 1_000
NET = 10
GRID = 100


def bench_curve(rng) -> dict[str, float]:
    from geomdl import BSpline as GBS
    from scipy.interpolate import BSpline

    ctrl = rng.uniform(-1, 1, (N_CTRL, 3))
    knots = gb.clamped_knots(N_CTRL, 3)
    u = np.linspace(0.0, 1.0, CURVE_SAMPLES)
    ref = BSpline(knots, ctrl, 3)
    for name, fn in (("de_boor", gb.de_boor), ("global_de_boor", gb.global_de_boor)):
        err = float(np.abs(fn(ctrl, knots, 3, u) - ref(u)).max())
        if err > 1e-12:
            raise AssertionError(f"{name} disagrees with scipy BSpline by {err:.3g}")
    crv = GBS.Curve()
    crv.degree = 3
    crv.ctrlpts = ctrl.tolist()
    crv.knotvector = knots.tolist()
    few = list(u[:: CURVE_SAMPLES // GEOMDL_SAMPLES])
    err = float(np.abs(np.array(crv.evaluate_list(few)) - ref(np.array(few))).max())
    if err > 1e-12:
        raise AssertionError(f"geomdl disagrees with scipy BSpline by {err:.3g}")
    # scipy's construction is included: BSpline(t, c, k)(u) is what a caller with arrays does.  Each
    # of ours is timed in its own interleaved pair with scipy: global_de_boor's 4 MB basis matrix,
    # timed in the same rounds, would evict de_boor's working set and slow it by 20-40%
    t_scipy, t_ours = best_times(lambda: BSpline(knots, ctrl, 3)(u), lambda: gb.de_boor(ctrl, knots, 3, u))
    t_scipy_g, t_global = best_times(lambda: BSpline(knots, ctrl, 3)(u), lambda: gb.global_de_boor(ctrl, knots, 3, u))
    t_geomdl = best_time(lambda: crv.evaluate_list(few), repeat=3) * (CURVE_SAMPLES / len(few))
    label = f"cubic 3D curve, {N_CTRL} ctrl, {CURVE_SAMPLES} params"
    report(f"de_boor        {label}", t_ours, t_scipy, "scipy")
    report(f"global_de_boor {label}", t_global, t_scipy_g, "scipy")
    report(f"geomdl.BSpline.Curve {label}", t_geomdl)
    print(f"{'':<44} de_boor is {t_geomdl / t_ours:.0f}x faster than geomdl", flush=True)
    return {"de_boor/scipy": t_ours / t_scipy, "geomdl/de_boor": t_geomdl / t_ours,
            "global_de_boor/scipy": t_global / t_scipy_g}


def bench_surface(rng) -> dict[str, float]:
    from scipy.interpolate import bisplev

    net = rng.uniform(-1, 1, (NET, NET, 3))
    knots = gb.clamped_knots(NET, 3)
    g = np.linspace(0.0, 1.0, GRID)
    tcks = [(knots, knots, np.ascontiguousarray(net[:, :, c]).ravel(), 3, 3) for c in range(3)]

    def reference():
        return [bisplev(g, g, tck) for tck in tcks]

    ref = np.stack(reference(), axis=-1)
    err = float(np.abs(gb.surface_grid(net, knots, knots, 3, 3, g, g) - ref).max())
    if err > 1e-12:
        raise AssertionError(f"surface_grid disagrees with scipy bisplev by {err:.3g}")
    t_ref, t_ours = best_times(reference, lambda: gb.surface_grid(net, knots, knots, 3, 3, g, g))
    report(f"surface_grid bicubic {NET}x{NET} net, {GRID}x{GRID} grid", t_ours, t_ref, "bisplev")
    return {"surface_grid/bisplev": t_ours / t_ref}


def main() -> dict[str, float]:
    rng = np.random.default_rng(27)
    ratios = {**bench_curve(rng), **bench_surface(rng)}
    for name, limit, better in (("de_boor/scipy", 1.2, "<="), ("geomdl/de_boor", 50.0, ">="),
                                ("surface_grid/bisplev", 1.0, "<=")):
        ok = ratios[name] <= limit if better == "<=" else ratios[name] >= limit
        print(f"target {name} {better} {limit:g}x: {'met' if ok else 'MISSED'} ({ratios[name]:.2f}x)")
    return ratios


if __name__ == "__main__":
    main()
