"""Regression tests for the issue "Every input gets bounded work and a clear answer", Part IV
(Bezier curves to subdivision surfaces): the adversarial probe's examples, each of which hung,
ran out of memory, returned NaN/inf silently or named the wrong parameter.

Every size parameter is checked against the work budget before any work starts, so each call
below returns (or raises) at once; a time limit makes a regression fail instead of hang.
"""

import math
import signal
import time
from contextlib import contextmanager

import numpy as np
import pytest

from goldman_lib import bezier, blossom, bspline, knot_insertion as ki
from goldman_lib import subdivision_matrices as sm
from goldman_lib import subdivision_surfaces as ss
from goldman_lib.validation import MAX_ITEMS, finite_result

C = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
POLYGON = [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]]
KNOTS = [0, 0, 0, 0, 1, 2, 2, 2, 2]
NET = [[[i, j, (i * j) % 2] for j in range(3)] for i in range(3)]


@contextmanager
def time_limit(seconds=5.0):
    def handler(signum, frame):
        raise TimeoutError(f"took longer than {seconds} s")
    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def raises_fast(call, exc, pattern):
    start = time.process_time()     # CPU time: the suite runs beside two browsers
    with time_limit(), pytest.raises(exc, match=pattern):
        call()
    assert time.process_time() - start < 1.0, "the budget is checked before the work starts"


# -- hangs and memory: every level, count, degree and size parameter has a budget ----------------
BUDGET = [
    ("centroid_averaging(cube(), 12)", lambda: ss.centroid_averaging(ss.cube(), 12), r"levels must be <= 8: "),
    ("centroid_averaging(cube(), 10**12)", lambda: ss.centroid_averaging(ss.cube(), 10 ** 12), r"levels must be <= 8"),
    ("split_and_average(C, 3, 40)", lambda: ss.split_and_average(C, 3, 40), r"levels must be <= \d+: "),
    ("split_and_average(C, 10**12, 1)", lambda: ss.split_and_average(C, 10 ** 12, 1), r"degree must be <= "),
    ("box_spline_split_and_average levels", lambda: ss.box_spline_split_and_average(NET, levels=40), r"levels must be <="),
    ("prism(10**12)", lambda: ss.prism(10 ** 12), r"n must be <= "),
    ("quad_star rings", lambda: ss.quad_star(5, 10 ** 12), r"rings must be <= "),
    ("quad_star valence", lambda: ss.quad_star(10 ** 12), r"valence must be <= "),
    ("triangle_vertex_stencil(1e308)", lambda: ss.triangle_vertex_stencil(1e308), r"valence must be <= "),
    ("bezier_subdivision_matrices(1001)", lambda: sm.bezier_subdivision_matrices(1001), r"n must be <= 1000: .*overflow"),
    ("bezier_subdivision_matrices(10**12)", lambda: sm.bezier_subdivision_matrices(10 ** 12), r"n must be <= 1000"),
    ("bspline_subdivision_matrices(10**12)", lambda: sm.bspline_subdivision_matrices(10 ** 12), r"n must be <= 1000"),
    ("normal_curve_control_points(10**12)", lambda: sm.normal_curve_control_points(10 ** 12), r"n must be <= 1000"),
    ("normal_curve(10**12, t)", lambda: sm.normal_curve(10 ** 12, 0.5), r"n must be <= 1000"),
    ("attractor levels", lambda: sm.attractor(sm.curve_ifs(C)[0], 10 ** 12, sm.curve_ifs(C)[1]), r"levels must be <= "),
    ("curve_as_attractor levels", lambda: sm.curve_as_attractor(C, 10 ** 12), r"levels must be <= "),
    ("elevate_degree(C, 10**5)", lambda: bezier.elevate_degree(C, 10 ** 5), r"times must be <= 3157: "),
    ("elevate_degree(C, 10**12)", lambda: bezier.elevate_degree(C, 10 ** 12), r"times must be <= 3157"),
    ("bernstein(10**6, t)", lambda: bezier.bernstein(10 ** 6, 0.5), r"n must be <= 4471: "),
    ("bernstein(10**12, t)", lambda: bezier.bernstein(10 ** 12, 0.5), r"n must be <= 4471"),
    ("bernstein over many t", lambda: bezier.bernstein(100, np.zeros(10 ** 6)), r"n must be <= "),
    ("subdivide_uniform depth", lambda: bezier.subdivide_uniform(C, 10 ** 12), r"depth must be <= 20"),
    ("curve_crossings samples", lambda: bezier.curve_crossings(C, [0, 1], [0, 1], samples=10 ** 12), r"samples must be <= "),
    ("patch_grid nu", lambda: bezier.patch_grid(NET, 10 ** 12, 21), r"nu must be <= "),
    ("patch_grid nv", lambda: bezier.patch_grid(NET, 21, 10 ** 12), r"nv must be <= "),
    ("clamped_knots n_ctrl", lambda: bspline.clamped_knots(10 ** 12, 3), r"n_ctrl must be <= "),
    ("uniform_knots n_ctrl", lambda: bspline.uniform_knots(10 ** 12, 3), r"n_ctrl must be <= "),
    ("lane_riesenfeld levels", lambda: ki.lane_riesenfeld(C, 3, 10 ** 12), r"levels must be <= 20"),
    ("lane_riesenfeld_knots n_ctrl", lambda: ki.lane_riesenfeld_knots(10 ** 12, 3), r"n_ctrl must be <= "),
    ("lane_riesenfeld_knots degree", lambda: ki.lane_riesenfeld_knots(3, 10 ** 12), r"degree"),
    ("schaefer levels", lambda: ki.schaefer(POLYGON, KNOTS, 3, 40), r"levels must be <= "),
    ("variation_diminishing samples",
     lambda: ki.variation_diminishing(POLYGON, KNOTS, 3, [0, 1], [0, 1], samples=10 ** 12), r"samples must be <= "),
]


@pytest.mark.parametrize("call,pattern", [b[1:] for b in BUDGET], ids=[b[0] for b in BUDGET])
def test_sizes_are_bounded_before_the_work_starts(call, pattern):
    raises_fast(call, ValueError, pattern)


def test_the_budget_message_says_why():
    with pytest.raises(ValueError) as info:
        ss.centroid_averaging(ss.cube(), 12)
    assert f"over the limit of {MAX_ITEMS // 4:,}" in str(info.value) and "face corners" in str(info.value)


def test_sensible_sizes_still_work():
    assert ss.centroid_averaging(ss.cube(), 2).n_faces == 96
    assert bezier.elevate_degree(C, 50).shape == (54, 2)
    assert bezier.bernstein(1500, 0.5).shape == (1501,)           # the recurrence above degree 1000
    L, R = sm.bezier_subdivision_matrices(1000)
    assert np.allclose(L.sum(axis=1), 1) and np.allclose(R.sum(axis=1), 1)
    assert ki.lane_riesenfeld(C, 3, 20).shape == (2 ** 20 + 3, 2)


def test_bezier_matrices_unchanged():
    """The vectorised build gives the entries of comb(i, j) t^j (1-t)^(i-j), bit for bit."""
    for n, t in ((3, 0.5), (5, 0.3), (7, -0.4), (12, 1.7)):
        L, R = sm.bezier_subdivision_matrices(n, t)
        for i in range(n + 1):
            for j in range(i + 1):
                assert L[i, j] == math.comb(i, j) * t ** j * (1 - t) ** (i - j)
            for j in range(i, n + 1):
                k, m = j - i, n - i
                assert R[i, j] == math.comb(m, k) * t ** k * (1 - t) ** (m - k)


# -- no silent NaN or infinity -----------------------------------------------------------------------
OVERFLOW = [
    ("de_casteljau", lambda: bezier.de_casteljau(C, 1e150), "t"),
    ("de_casteljau array t", lambda: bezier.de_casteljau(C, [0.5, 1e150]), r"t .* at t\[1\] = 1e\+150$|t"),
    ("de_casteljau_steps", lambda: bezier.de_casteljau_steps(C, 1e150), "t"),
    ("bernstein", lambda: bezier.bernstein(3, 1e150), "t"),
    ("bernstein_evaluate", lambda: bezier.bernstein_evaluate(C, 1e150), "t"),
    ("derivative", lambda: bezier.derivative(C, 1e200), "t"),
    ("subdivide", lambda: bezier.subdivide(C, 1e150), "t"),
    ("smooth_continuation", lambda: bezier.smooth_continuation(C, 1e308), "ratio"),
    ("smooth_join", lambda: bezier.smooth_join(C, "C2", ratio=1e200), "ratio"),
    ("curve evaluate", lambda: bezier.BezierCurve(C).evaluate(1e150), "t"),
    ("blossom", lambda: blossom.blossom(C, [1e150] * 3), "args"),
    ("blossom_steps", lambda: blossom.blossom_steps(C, [1e150] * 3), "args"),
    ("control_points_on_interval", lambda: blossom.control_points_on_interval(C, 0, 1e150), "b"),
    ("subdivide_by_blossom", lambda: blossom.subdivide_by_blossom(C, 1e150), "t"),
    ("homogeneous_blossom", lambda: blossom.homogeneous_blossom(C, [[1e150, 1]] * 3), "args"),
    ("derivative_by_blossom", lambda: blossom.derivative_by_blossom(C, 1e200), "t"),
    ("normal_curve", lambda: sm.normal_curve(3, 1e150), "t"),
    ("bezier_subdivision_matrices", lambda: sm.bezier_subdivision_matrices(3, 1e308), "t"),
    ("patch_de_casteljau", lambda: bezier.patch_de_casteljau(NET, 0.5, 1e200), "v"),
    ("patch_evaluate_grid", lambda: bezier.patch_evaluate_grid(NET, [1e200], [0.5]), "u"),
    ("patch_derivatives", lambda: bezier.patch_derivatives(NET, 1e200, 0.7), "u"),
    ("patch_normal", lambda: bezier.BezierPatch(NET).normal(0.5, -1e200), "v"),
    ("nurbs_curve", lambda: bspline.nurbs_curve(POLYGON, [1, 1e308, 1, 1, 1], KNOTS, 3, 0.5), "weights"),
]


@pytest.mark.parametrize("call,name", [b[1:] for b in OVERFLOW], ids=[b[0] for b in OVERFLOW])
def test_an_overflow_names_the_input(call, name):
    raises_fast(call, ValueError, rf"^{name} .*overflows? float64")


def test_extrapolation_that_fits_still_works():
    assert np.all(np.isfinite(bezier.de_casteljau(C, 1e50)))
    assert bezier.de_casteljau(C, -2.0).tolist() == [22.0, -36.0]


def test_finite_result_names_the_entry():
    with pytest.raises(ValueError, match=r"at t\[1\] = 1e\+300"):
        finite_result(np.array([[0.0], [np.inf]]), "t", np.array([0.0, 1e300]))


TOLERANCES = [
    ("render_by_subdivision", lambda tol: bezier.render_by_subdivision(C, tol=tol)),
    ("intersect_curves", lambda tol: bezier.intersect_curves(C, C[::-1], tol=tol)),
    ("check_rows_sum_to_one", lambda tol: sm.check_rows_sum_to_one(np.eye(2), tol=tol)),
    ("multiplicity", lambda tol: bspline.multiplicity(KNOTS, 0, tol=tol)),
    ("render", lambda tol: ki.render_by_subdivision(POLYGON, KNOTS, 3, tol=tol)),
]


@pytest.mark.parametrize("call", [b[1] for b in TOLERANCES], ids=[b[0] for b in TOLERANCES])
@pytest.mark.parametrize("tol", [math.nan, math.inf, -1.0])
def test_tolerances_are_finite_and_positive(call, tol):
    raises_fast(lambda: call(tol), ValueError, r"tol must be")


# -- messages name the parameter -----------------------------------------------------------------------
MESSAGES = [
    ("midpoint_knots([])", lambda: ki.midpoint_knots([]), ValueError, r"^knots must hold at least one knot"),
    ("knots vs ctrl", lambda: bspline.de_boor([[0, 0]], KNOTS, 3, 0.5), ValueError, r"len\(ctrl\) \+ degree \+ 1"),
    ("knots vs ctrl, knot insertion", lambda: ki.boehm_insert([[0, 0]], KNOTS, 3, 0.5), ValueError, r"len\(ctrl\)"),
    ("surface degree_u", lambda: bspline.surface_de_boor(np.zeros((2, 2, 3)), [0, 0, 1, 1], [0, 0, 1, 1], 0, 1, 0.5, 0.5),
     ValueError, r"degree_u"),
    ("surface ctrl rows", lambda: bspline.surface_de_boor(np.zeros((3, 2, 3)), [0, 0, 1, 1], [0, 0, 1, 1], 1, 1, 0.5, 0.5),
     ValueError, r"ctrl\.shape\[0\]"),
    ("blossom args vs ctrl", lambda: blossom.blossom([[0, 0]], [0.5]), ValueError, r"degree of ctrl"),
    ("line dimension vs ctrl", lambda: bezier.variation_count([[0], [1]], [0, 0], [0, 1]), ValueError,
     r"line_point must hold 1-dimensional points .*ctrl"),
    ("smooth_join degree from ctrl", lambda: bezier.smooth_join([[0, 0]], "C1"), ValueError, r"^ctrl must have degree"),
    ("multiplicity knots", lambda: bspline.multiplicity("x", 0), TypeError, r"^knots"),
    ("spline_to_bspline continuity", lambda: bspline.spline_to_bspline([[[0], [0], [1]]] * 2, [0, 1, 2], [[0, 0], [1]]),
     TypeError, r"^continuity"),
    ("Mesh faces", lambda: ss.Mesh(ss.cube().vertices, 3.0), TypeError, r"^faces"),
    ("Mesh faces unused vertex", lambda: ss.Mesh(ss.cube().vertices, [[0, 1, 2]]), ValueError, r"^faces must use every vertex"),
    ("box spline multiplicities", lambda: ss.box_spline_split_and_average(NET, 2.0), TypeError, r"^multiplicities"),
    ("control_point_ifs matrices", lambda: sm.control_point_ifs(C[:3], 0.5), ValueError, r"^matrices"),
    ("curve_ifs ctrl", lambda: sm.curve_ifs("abc"), TypeError, r"^ctrl"),
    ("normal_curve t", lambda: sm.normal_curve(2, 1 + 2j), TypeError, r"^t must be real"),
    ("attractor maps", lambda: sm.attractor([[[0, 1], [1]]], 1, [[0]]), TypeError, r"^maps"),
]


@pytest.mark.parametrize("call,exc,pattern", [b[1:] for b in MESSAGES], ids=[b[0] for b in MESSAGES])
def test_messages_name_the_parameter(call, exc, pattern):
    raises_fast(call, exc, pattern)


def test_convergence_study_of_a_polygon_on_its_curve_is_finite():
    study = ki.convergence_study([[1, 1]] * 3, [0, 0, 0, 1, 1, 1], 2, 2)
    assert np.all(np.isfinite(study["ratio"])) and study["ratio"].tolist() == [0.0, 0.0]


ADAPTIVE = [
    ("render_by_subdivision", lambda: bezier.render_by_subdivision(C, tol=1e-300)),
    ("render_patch_by_subdivision", lambda: bezier.render_patch_by_subdivision(NET, tol=1e-300, max_depth=12)),
    ("knot_insertion.render_by_subdivision", lambda: ki.render_by_subdivision(POLYGON, KNOTS, 3, tol=1e-300, max_levels=20)),
    ("knot_insertion.render_by_subdivision subdivision",
     lambda: ki.render_by_subdivision(POLYGON, KNOTS, 3, tol=1e-300, method="subdivision", max_levels=20)),
]


@pytest.mark.parametrize("call", [b[1] for b in ADAPTIVE], ids=[b[0] for b in ADAPTIVE])
def test_a_tolerance_below_float64_resolution_is_refused(call):
    """Adaptive subdivision's depth is set by tol: a level over the budget raises, naming tol."""
    with time_limit(30), pytest.raises(ValueError, match=r"^tol must be at least 1e-15 times the size of ctrl"):
        call()


def test_a_level_over_the_budget_is_refused():
    """A resolvable tol that still needs more pieces than the budget allows raises, naming tol."""
    with time_limit(60), pytest.raises(ValueError, match=r"^tol = 1e-13 is too small for this curve"):
        bezier.render_by_subdivision(C, tol=1e-13, max_depth=40)
