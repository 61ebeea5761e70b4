"""Tests of goldman_lib.bezier (Goldman chapter 24).

Expected values come from references independent of the code under test:
- hand-computed exact values (the book's small examples);
- the closed form C(n, k) t^k (1-t)^(n-k) with scipy.special.comb, scipy.stats.binom.pmf, and
  numpy.polynomial.Polynomial products (t^k (1-t)^(n-k)) and their .deriv();
- the `bezier` package (dhermes, compiled): Curve.evaluate_multi, evaluate_hodograph, elevate;
- scipy.interpolate.bisplev (a bicubic Bezier patch is a B-spline with knots 0,0,0,0,1,1,1,1);
- scipy.spatial.ConvexHull for the hull;
- hypothesis properties stating the theorems of §24.4-24.6.
"""

import math

import bezier as bz
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from numpy.polynomial import Polynomial
from scipy.interpolate import bisplev
from scipy.spatial import ConvexHull
from scipy.special import comb
from scipy.stats import binom

from goldman_lib import bezier as gb

FAST = settings(max_examples=30, deadline=None, derandomize=True)

coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


@st.composite
def ctrl_polygons(draw, dims=(1, 2, 3), max_degree=7):
    n = draw(st.integers(0, max_degree))
    d = draw(st.sampled_from(dims))
    return draw(arrays(float, (n + 1, d), elements=coord))


unit = st.floats(0, 1, allow_nan=False)


# ------------------------------------------------------------------ independent references

def bernstein_closed(n, t):
    t = np.asarray(t, dtype=float)[..., None]
    k = np.arange(n + 1)
    return comb(n, k) * t ** k * (1 - t) ** (n - k)


def bernstein_polys(n):
    T = Polynomial([0, 1])
    S = Polynomial([1, -1])
    return [math.comb(n, k) * T ** k * S ** (n - k) for k in range(n + 1)]


def curve_polys(ctrl):
    """Each coordinate of the Bezier curve as a numpy Polynomial."""
    ctrl = np.asarray(ctrl, dtype=float)
    B = bernstein_polys(len(ctrl) - 1)
    return [sum((B[k] * ctrl[k, c] for k in range(len(ctrl))), Polynomial([0.0])) for c in range(ctrl.shape[1])]


def bz_curve(ctrl):
    ctrl = np.asarray(ctrl, dtype=float)
    return bz.Curve(np.asfortranarray(ctrl.T), len(ctrl) - 1)


RNG = np.random.default_rng(2024)
CASES = [(n, d) for n in (1, 2, 3, 5, 7, 10) for d in (1, 2, 3, 4)]


# ------------------------------------------------------------------ §24.2 de Casteljau

def test_quadratic_midpoint_by_hand():
    assert gb.de_casteljau([[0, 0], [1, 2], [2, 0]], 0.5).tolist() == [1.0, 1.0]


def test_cubic_by_hand():
    # (P0 + 3 P1 + 3 P2 + P3) / 8
    assert np.allclose(gb.de_casteljau([[0, 0], [0, 1], [1, 1], [1, 0]], 0.5), [0.5, 0.75])
    # at t = 1/3: weights 8/27, 12/27, 6/27, 1/27
    assert np.allclose(gb.de_casteljau([[0, 0], [0, 1], [1, 1], [1, 0]], 1 / 3), [7 / 27, 18 / 27])


@pytest.mark.parametrize("n,d", CASES)
def test_de_casteljau_matches_bezier_package_and_closed_form(n, d):
    ctrl = RNG.uniform(-5, 5, (n + 1, d))
    s = np.linspace(0, 1, 37)
    ref = bz_curve(ctrl).evaluate_multi(s).T
    assert np.allclose(gb.de_casteljau(ctrl, s), ref, atol=1e-12)
    assert np.allclose(gb.bernstein_evaluate(ctrl, s), ref, atol=1e-12)
    assert np.allclose(gb.de_casteljau(ctrl, s), bernstein_closed(n, s) @ ctrl, atol=1e-12)


def test_result_shape_follows_t():
    ctrl = RNG.random((4, 3))
    t = RNG.random((2, 5))
    out = gb.de_casteljau(ctrl, t)
    assert out.shape == (2, 5, 3)
    assert np.allclose(out, bernstein_closed(3, t) @ ctrl)
    assert gb.de_casteljau(ctrl, 0.3).shape == (3,)
    assert gb.bernstein_evaluate(ctrl, t).shape == (2, 5, 3)
    assert gb.de_casteljau(ctrl, np.zeros(0)).shape == (0, 3)


def test_degree_zero_curve_is_constant():
    assert gb.de_casteljau([[3.0, 4.0]], [0.0, 0.5, 2.0]).tolist() == [[3, 4]] * 3


def test_extrapolation_outside_unit_interval_is_the_polynomial():
    ctrl = RNG.random((4, 2))
    t = np.array([-1.0, -0.25, 1.5, 3.0])
    polys = curve_polys(ctrl)
    ref = np.stack([p(t) for p in polys], axis=-1)
    assert np.allclose(gb.de_casteljau(ctrl, t), ref)
    assert np.allclose(gb.bernstein_evaluate(ctrl, t), ref)


def test_de_casteljau_steps_by_hand():
    steps = gb.de_casteljau_steps([[0, 0], [1, 2], [2, 0]], 0.25)
    assert [s.shape for s in steps] == [(3, 2), (2, 2), (1, 2)]
    assert np.allclose(steps[1], [[0.25, 0.5], [1.25, 1.5]])
    assert np.allclose(steps[2], [[0.5, 0.75]])


@FAST
@given(ctrl_polygons(), unit)
def test_steps_shapes_and_last_point(ctrl, t):
    steps = gb.de_casteljau_steps(ctrl, t)
    n = len(ctrl) - 1
    assert [s.shape[0] for s in steps] == list(range(n + 1, 0, -1))
    assert np.allclose(steps[-1][0], bernstein_closed(n, t) @ ctrl, atol=1e-9)


# ------------------------------------------------------------------ §24.3 Bernstein

@pytest.mark.parametrize("n", [0, 1, 2, 3, 7, 15, 30])
def test_bernstein_against_comb_and_polynomial_products(n):
    t = np.concatenate([[0.0, 1.0, 0.5, 1e-12, 1 - 1e-12], np.linspace(0, 1, 23)])
    got = gb.bernstein(n, t)
    assert got.shape == (len(t), n + 1)
    assert np.allclose(got, bernstein_closed(n, t), rtol=1e-12, atol=1e-15)
    polys = bernstein_polys(n)
    # monomial-form evaluation loses up to ~ n eps sum|coef| to cancellation (why Bernstein is used)
    bound = max((n + 1) * 1e-15 * np.abs(p.coef).sum() for p in polys)
    assert np.allclose(got, np.stack([p(t) for p in polys], axis=-1), rtol=0, atol=max(bound, 1e-14))
    assert np.allclose(got, binom.pmf(np.arange(n + 1), n, t[:, None]), rtol=1e-10, atol=1e-15)


def test_bernstein_exact_endpoints():
    assert gb.bernstein(5, 0.0).tolist() == [1, 0, 0, 0, 0, 0]
    assert gb.bernstein(5, 1.0).tolist() == [0, 0, 0, 0, 0, 1]
    assert gb.bernstein(4, 0.5)[2] == 6 / 16


def test_bernstein_very_high_degree_uses_stable_recurrence():
    n = 1100   # binomials overflow a float here
    t = np.array([0.0, 0.3, 0.5, 0.9, 1.0])
    got = gb.bernstein(n, t)
    assert np.all(np.isfinite(got)) and np.all(got >= 0)
    assert np.allclose(got.sum(axis=-1), 1.0)
    assert np.allclose(got, binom.pmf(np.arange(n + 1), n, t[:, None]), atol=1e-12)


def test_bernstein_shape_follows_t():
    assert gb.bernstein(3, np.zeros((2, 4))).shape == (2, 4, 4)
    assert gb.bernstein(0, 0.7).tolist() == [1.0]


@FAST
@given(st.integers(0, 30), arrays(float, 5, elements=unit))
def test_partition_of_unity_and_nonnegativity(n, t):
    B = gb.bernstein(n, t)
    assert np.all(B >= 0)
    assert np.allclose(B.sum(axis=-1), 1.0)


# ------------------------------------------------------------------ §24.4 properties

@FAST
@given(ctrl_polygons())
def test_endpoint_interpolation(ctrl):
    out = gb.de_casteljau(ctrl, [0.0, 1.0])
    assert np.allclose(out[0], ctrl[0]) and np.allclose(out[1], ctrl[-1])


affine2 = arrays(float, (2, 2), elements=st.floats(-3, 3))


@FAST
@given(ctrl_polygons(dims=(2,)), affine2, arrays(float, 2, elements=coord), arrays(float, 6, elements=unit))
def test_affine_invariance(ctrl, L, shift, t):
    M = np.zeros((3, 3))
    M[:2, :2], M[2, :2], M[2, 2] = L, shift, 1.0
    mapped_curve = gb.de_casteljau(gb.apply_affine(ctrl, M), t)
    curve_mapped = gb.apply_affine(gb.de_casteljau(ctrl, t), M)
    # reference for the map itself: homogeneous row vectors times M
    hom = np.c_[gb.de_casteljau(ctrl, t), np.ones(len(t))] @ M
    assert np.allclose(curve_mapped, hom[:, :2], atol=1e-9)
    assert np.allclose(mapped_curve, curve_mapped, atol=1e-8)


def test_apply_affine_row_vector_convention_3d():
    M = np.eye(4)
    M[3, :3] = [1, 2, 3]          # translation in the last row
    M[:3, :3] = [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]   # x -> y (row vector times M)
    assert gb.apply_affine([1.0, 0.0, 0.0], M).tolist() == [1.0, 3.0, 3.0]


@FAST
@given(ctrl_polygons(dims=(2,)), arrays(float, 20, elements=unit))
def test_convex_hull_property(ctrl, t):
    pts = gb.de_casteljau(ctrl, t)
    assert np.all(gb.convex_hull_contains(ctrl, pts, tol=1e-9))


def test_convex_hull_matches_scipy():
    pts = RNG.random((40, 2))
    ours = gb.convex_hull(pts)
    ref = pts[ConvexHull(pts).vertices]
    assert sorted(map(tuple, ours)) == sorted(map(tuple, ref))
    # counter-clockwise: positive signed area
    x, y = ours[:, 0], ours[:, 1]
    assert 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) > 0


def test_convex_hull_contains_outside_and_degenerate_hulls():
    tri = [[0, 0], [1, 2], [2, 0]]
    assert gb.convex_hull_contains(tri, [[1, 0.5], [1, 2.5], [-0.1, 0], [2, 0]]).tolist() == [True, False, False, True]
    seg = [[0, 0], [1, 1], [2, 2]]
    assert gb.convex_hull_contains(seg, [[0.5, 0.5], [0.5, 0.6], [3, 3]]).tolist() == [True, False, False]
    assert gb.convex_hull_contains([[1, 1], [1, 1]], [[1, 1], [1, 2]]).tolist() == [True, False]


def test_variation_count_by_hand():
    ctrl = [[0, 0], [1, 2], [2, -2], [3, 1]]
    assert gb.variation_count(ctrl, [0, 0], [0, 1]) == 2       # signs 0, +, -, + (the 0 is skipped)
    assert gb.variation_count(ctrl, [0, 5], [0, 1]) == 0
    assert gb.variation_count(ctrl, [1.5, 0], [1, 0]) == 1     # the vertical line x = 1.5
    # the crossings of y = 0 by the curve itself: real roots in (0, 1) of its y polynomial
    y = curve_polys(ctrl)[1]
    roots = [r.real for r in y.roots() if abs(r.imag) < 1e-12 and 1e-9 < r.real < 1 - 1e-9]
    assert gb.curve_crossings(ctrl, [0, 0], [0, 1]) == len(roots)


@FAST
@given(ctrl_polygons(dims=(2,)), arrays(float, 2, elements=coord), arrays(float, 2, elements=st.floats(-1, 1)))
def test_variation_diminishing(ctrl, p, nrm):
    if np.linalg.norm(nrm) < 1e-3:
        nrm = np.array([0.0, 1.0])
    assert gb.curve_crossings(ctrl, p, nrm, samples=401) <= gb.variation_count(ctrl, p, nrm)


# ------------------------------------------------------------------ §24.5 derivatives

def test_hodograph_by_hand_and_against_bezier_package():
    ctrl = np.array([[0, 0], [1, 2], [2, 0.0]])
    assert gb.hodograph(ctrl).tolist() == [[2, 4], [2, -4]]
    ctrl = RNG.random((6, 3))
    c = bz_curve(ctrl)
    for s in (0.0, 0.3, 1.0):
        assert np.allclose(gb.de_casteljau(gb.hodograph(ctrl), s), c.evaluate_hodograph(s)[:, 0])
        assert np.allclose(gb.derivative(ctrl, s), c.evaluate_hodograph(s)[:, 0])


def test_hodograph_of_constant_is_zero_curve():
    assert gb.hodograph([[1.0, 2.0]]).tolist() == [[0.0, 0.0]]


@pytest.mark.parametrize("n,d", [(1, 2), (3, 2), (5, 3), (7, 1)])
def test_derivative_matches_numpy_polynomial(n, d):
    ctrl = RNG.uniform(-3, 3, (n + 1, d))
    polys = curve_polys(ctrl)
    t = np.linspace(-0.5, 1.5, 11)
    for order in range(n + 3):
        ref = np.stack([p.deriv(order)(t) if order else p(t) for p in polys], axis=-1)
        got = gb.derivative(ctrl, t, order)
        assert got.shape == (11, d)
        assert np.allclose(got, ref, atol=1e-8 * max(1, math.factorial(min(order, n)) * 3 ** order))


@FAST
@given(ctrl_polygons(), st.floats(0.05, 0.95))
def test_derivative_is_de_casteljau_of_hodograph_and_finite_difference(ctrl, t):
    d1 = gb.derivative(ctrl, t)
    assert np.allclose(d1, gb.de_casteljau(gb.hodograph(ctrl), t), atol=1e-9)
    h = 1e-5
    fd = (gb.de_casteljau(ctrl, t + h) - gb.de_casteljau(ctrl, t - h)) / (2 * h)
    assert np.allclose(d1, fd, atol=1e-4 * (1 + np.abs(ctrl).max() * len(ctrl) ** 3))


def test_elevate_by_hand_and_against_bezier_package():
    ctrl = np.array([[0, 0], [1, 2], [2, 0.0]])
    assert np.allclose(gb.elevate_degree(ctrl), [[0, 0], [2 / 3, 4 / 3], [4 / 3, 4 / 3], [2, 0]])
    ctrl = RNG.random((5, 3))
    ref = bz_curve(ctrl).elevate().elevate().nodes.T
    assert np.allclose(gb.elevate_degree(ctrl, times=2), ref)
    assert np.array_equal(gb.elevate_degree(ctrl, 0), ctrl)


@FAST
@given(ctrl_polygons(), st.integers(1, 3), arrays(float, 9, elements=unit))
def test_degree_elevation_preserves_curve(ctrl, times, t):
    Q = gb.elevate_degree(ctrl, times)
    assert Q.shape == (len(ctrl) + times, ctrl.shape[1])
    assert np.allclose(gb.de_casteljau(Q, t), bernstein_closed(len(ctrl) - 1, t) @ ctrl, atol=1e-8)


# ------------------------------------------------------------------ §24.5.1 smooth joins

def test_smooth_join_by_hand():
    P = [[0, 0], [1, 1], [2, 0]]
    assert gb.smooth_join(P, "C0").tolist() == [[2, 0]]
    assert gb.smooth_join(P, "C1").tolist() == [[2, 0], [3, -1]]
    assert gb.smooth_join(P, "C1", ratio=2).tolist() == [[2, 0], [4, -2]]
    assert gb.smooth_join(P, "G1", ratio=0.25).tolist() == [[2, 0], [2.25, -0.25]]
    # C2: Q2 = 2 Q1 - Q0 + (P2 - 2 P1 + P0) = (6, -2) - (2, 0) + (0, -2) = (4, -4)
    assert gb.smooth_join(P, "C2").tolist() == [[2, 0], [3, -1], [4, -4]]
    # next curve of degree 4 after a quadratic: Q1 = P2 + (2/4)(P2 - P1)
    assert gb.smooth_join(P, "C1", degree=4).tolist() == [[2, 0], [2.5, -0.5]]


@FAST
@given(ctrl_polygons(dims=(2, 3)), st.sampled_from(["C1", "G1", "C2"]),
       st.floats(0.25, 4), st.integers(2, 5), st.data())
def test_smooth_join_gives_the_asked_continuity(ctrl, cont, ratio, m, data):
    if len(ctrl) < 2 or np.linalg.norm(ctrl[-1] - ctrl[-2]) < 1e-2:
        ctrl = np.vstack([ctrl, ctrl[-1] + 1.0])
    lead = gb.smooth_join(ctrl, cont, ratio=ratio, degree=m)
    rest = data.draw(arrays(float, (m + 1 - len(lead), ctrl.shape[1]), elements=coord))
    Q = np.vstack([lead, rest])
    # independent check by numpy.polynomial: in the global parameter the first curve spans an
    # interval of length 1, the second one of length `ratio`
    pa, pb = curve_polys(ctrl), curve_polys(Q)
    da = np.array([p.deriv(1)(1.0) for p in pa])
    db = np.array([p.deriv(1)(0.0) for p in pb]) / ratio
    assert np.allclose([p(0.0) for p in pb], ctrl[-1])
    if cont == "G1":
        assert np.allclose(np.cross(np.r_[da, 0][:3], np.r_[db, 0][:3]), 0, atol=1e-6 * (1 + np.abs(ctrl).max() ** 2) * 25)
        assert da @ db > 0
    else:
        assert np.allclose(da, db, atol=1e-7 * (1 + np.abs(ctrl).max()) * 10)
    if cont == "C2":
        dda = np.array([p.deriv(2)(1.0) if len(ctrl) > 2 else 0.0 for p in pa])
        ddb = np.array([p.deriv(2)(0.0) for p in pb]) / ratio ** 2
        assert np.allclose(dda, ddb, atol=1e-6 * (1 + np.abs(ctrl).max()) * 100)
    report = gb.join_continuity(ctrl, Q, tol=1e-7, ratio=ratio if cont != "G1" else 1.0)
    assert report["C0"] and report["G1"] or np.linalg.norm(ctrl[-1] - ctrl[-2]) == 0
    if cont in ("C1", "C2"):
        assert report["C1"]
    if cont == "C2":
        assert report["C2"]


def test_join_continuity_cases():
    P = [[0, 0], [1, 1], [2, 0]]
    assert gb.join_continuity(P, [[3, 0], [4, 0]]) == {"C0": False, "G1": False, "C1": False, "C2": False}
    assert gb.join_continuity(P, [[2, 0], [3, 1], [4, 0]]) == {"C0": True, "G1": False, "C1": False, "C2": False}
    assert gb.join_continuity(P, [[2, 0], [4, -2], [5, 0]]) == {"C0": True, "G1": True, "C1": False, "C2": False}
    assert gb.join_continuity(P, [[2, 0], [4, -2], [5, 0]], ratio=2) == {"C0": True, "G1": True, "C1": True, "C2": False}
    assert gb.join_continuity(P, [[2, 0], [3, -1], [4, -4]]) == {"C0": True, "G1": True, "C1": True, "C2": True}


# ------------------------------------------------------------------ §24.6 patches

def patch_closed(net, u, v):
    m, n = net.shape[0] - 1, net.shape[1] - 1
    return np.einsum("...i,...j,ijc->...c", bernstein_closed(m, u), bernstein_closed(n, v), net)


@pytest.mark.parametrize("m,n,d", [(1, 1, 3), (3, 3, 3), (2, 4, 3), (3, 1, 2), (0, 2, 3)])
def test_patch_against_closed_form(m, n, d):
    net = RNG.uniform(-2, 2, (m + 1, n + 1, d))
    u = RNG.random((3, 4))
    v = RNG.random((3, 4))
    assert np.allclose(gb.patch_de_casteljau(net, u, v), patch_closed(net, u, v))
    ug, vg = np.linspace(0, 1, 7), np.linspace(0, 1, 5)
    grid = gb.patch_evaluate_grid(net, ug, vg)
    assert grid.shape == (7, 5, d)
    U, V = np.meshgrid(ug, vg, indexing="ij")
    assert np.allclose(grid, patch_closed(net, U, V))
    assert np.allclose(gb.patch_grid(net, 7, 5), grid)


def test_patch_broadcasting_and_scalars():
    net = RNG.random((3, 3, 3))
    assert gb.patch_de_casteljau(net, 0.2, 0.7).shape == (3,)
    out = gb.patch_de_casteljau(net, np.linspace(0, 1, 4)[:, None], np.linspace(0, 1, 6)[None, :])
    assert out.shape == (4, 6, 3)
    assert np.allclose(out, gb.patch_evaluate_grid(net, np.linspace(0, 1, 4), np.linspace(0, 1, 6)))


def test_bicubic_patch_matches_scipy_bisplev():
    net = RNG.uniform(-1, 1, (4, 4, 3))
    knots = np.array([0, 0, 0, 0, 1, 1, 1, 1.0])
    u, v = np.linspace(0, 1, 13), np.linspace(0, 1, 9)
    ref = np.stack([bisplev(u, v, (knots, knots, net[:, :, c].ravel(), 3, 3)) for c in range(3)], axis=-1)
    assert np.allclose(gb.patch_evaluate_grid(net, u, v), ref, atol=1e-12)


def test_patch_corners_interpolate():
    net = RNG.random((4, 3, 3))
    assert np.allclose(gb.patch_de_casteljau(net, [0, 0, 1, 1], [0, 1, 0, 1]),
                       [net[0, 0], net[0, -1], net[-1, 0], net[-1, -1]])


@FAST
@given(st.integers(0, 4), st.integers(0, 4), unit, arrays(float, 5, elements=unit), st.data())
def test_patch_at_fixed_v_is_bezier_curve_in_u(m, n, v0, u, data):
    net = data.draw(arrays(float, (m + 1, n + 1, 3), elements=coord))
    # the row curves evaluated at v0 (closed form) are the control points of the curve in u
    rows_at_v = np.einsum("j,ijc->ic", bernstein_closed(n, v0), net)
    assert np.allclose(gb.patch_de_casteljau(net, u, np.full_like(u, v0)), gb.de_casteljau(rows_at_v, u), atol=1e-9)
    # and the same the other way: at fixed u a Bezier curve in v
    cols_at_u = np.einsum("i,ijc->jc", bernstein_closed(m, v0), net)
    assert np.allclose(gb.patch_de_casteljau(net, np.full_like(u, v0), u), gb.de_casteljau(cols_at_u, u), atol=1e-9)


def test_patch_derivatives_and_normal():
    net = RNG.uniform(-1, 1, (4, 3, 3))
    u, v = np.array([0.1, 0.5, 0.8]), np.array([0.3, 0.9, 0.5])
    su, sv = gb.patch_derivatives(net, u, v)
    h = 1e-6
    assert np.allclose(su, (patch_closed(net, u + h, v) - patch_closed(net, u - h, v)) / (2 * h), atol=1e-6)
    assert np.allclose(sv, (patch_closed(net, u, v + h) - patch_closed(net, u, v - h)) / (2 * h), atol=1e-6)
    nrm = gb.patch_normal(net, u, v)
    assert np.allclose(np.linalg.norm(nrm, axis=-1), 1)
    assert np.allclose(np.einsum("...c,...c->...", nrm, su), 0, atol=1e-9)
    assert np.allclose(np.einsum("...c,...c->...", nrm, sv), 0, atol=1e-9)
    flat = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]
    assert gb.patch_normal(flat, 0.3, 0.6).tolist() == [0, 0, 1]
    # a collapsed edge: the normal at the degenerate corner is reported as zero, not NaN
    cone = [[[0, 0, 1], [0, 0, 1]], [[1, 0, 0], [0, 1, 0]]]
    assert gb.patch_normal(cone, 0.0, 0.5).tolist() == [0, 0, 0]


def test_classes_delegate():
    c = gb.BezierCurve([[0, 0], [1, 2], [2, 0]])
    assert c.degree == 2 and c.dimension == 2
    assert c(0.5).tolist() == [1, 1] and c.evaluate(0.5).tolist() == [1, 1]
    assert c.derivative(0.5, 2).tolist() == [0, -8]
    assert c.hodograph().ctrl.tolist() == [[2, 4], [2, -4]]
    assert c.elevate(2).degree == 4
    assert len(c.steps(0.3)) == 3
    assert "degree=2" in repr(c)
    p = gb.BezierPatch(RNG.random((4, 4, 3)))
    assert p.degree == (3, 3) and p.dimension == 3
    assert p.grid(5, 6).shape == (5, 6, 3)
    assert np.allclose(p(0.2, 0.4), patch_closed(p.ctrl, 0.2, 0.4))
    assert p.normal(0.5, 0.5).shape == (3,)
    assert len(p.derivatives(0.5, 0.5)) == 2


# ------------------------------------------------------------------ bad input

Q = [[0, 0], [1, 2], [2, 0]]
NET = np.zeros((2, 2, 3))
NAN_Q = [[0, 0], [1, np.nan], [2, 0]]

BAD = [
    ("de_casteljau shape", lambda: gb.de_casteljau([0, 1, 2], 0.5), ValueError, r"ctrl must have shape \(n, d\)"),
    ("de_casteljau empty", lambda: gb.de_casteljau(np.zeros((0, 2)), 0.5), ValueError, r"ctrl must hold at least 1"),
    ("de_casteljau nan ctrl", lambda: gb.de_casteljau(NAN_Q, 0.5), ValueError, r"ctrl must be finite; ctrl\[1, 1\] is nan"),
    ("de_casteljau nan t", lambda: gb.de_casteljau(Q, [0, 0.1, 0.2, np.nan]), ValueError, r"t must be finite; t\[3\] is nan"),
    ("de_casteljau inf t", lambda: gb.de_casteljau(Q, np.inf), ValueError, r"t must be finite; t is inf"),
    ("de_casteljau str t", lambda: gb.de_casteljau(Q, "0.5"), TypeError, r"t must be numeric"),
    ("steps array t", lambda: gb.de_casteljau_steps(Q, [0.1, 0.2]), ValueError, r"t must be a scalar"),
    ("steps nan ctrl", lambda: gb.de_casteljau_steps(NAN_Q, 0.1), ValueError, r"ctrl must be finite"),
    ("bernstein negative n", lambda: gb.bernstein(-1, 0.5), ValueError, r"n must be >= 0"),
    ("bernstein float n", lambda: gb.bernstein(2.5, 0.5), TypeError, r"n must be an integer"),
    ("bernstein inf t", lambda: gb.bernstein(3, [0, np.inf]), ValueError, r"t must be finite; t\[1\] is inf"),
    ("bernstein_evaluate shape", lambda: gb.bernstein_evaluate(np.zeros((2, 2, 2)), 0.5), ValueError, r"ctrl must have shape"),
    ("bernstein_evaluate nan t", lambda: gb.bernstein_evaluate(Q, np.nan), ValueError, r"t must be finite"),
    ("hodograph nan", lambda: gb.hodograph(NAN_Q), ValueError, r"ctrl must be finite"),
    ("hodograph empty", lambda: gb.hodograph(np.zeros((0, 3))), ValueError, r"ctrl must hold at least 1"),
    ("derivative order -1", lambda: gb.derivative(Q, 0.5, order=-1), ValueError, r"order must be >= 0; got -1"),
    ("derivative order 1.5", lambda: gb.derivative(Q, 0.5, order=1.5), TypeError, r"order must be an integer; got 1.5"),
    ("derivative order bool", lambda: gb.derivative(Q, 0.5, order=True), TypeError, r"order must be an integer"),
    ("derivative nan t", lambda: gb.derivative(Q, [np.nan]), ValueError, r"t must be finite; t\[0\] is nan"),
    ("elevate times -1", lambda: gb.elevate_degree(Q, -1), ValueError, r"times must be >= 0"),
    ("elevate times 0.5", lambda: gb.elevate_degree(Q, 0.5), TypeError, r"times must be an integer"),
    ("smooth_join continuity", lambda: gb.smooth_join(Q, "C3"), ValueError, r"continuity must be one of"),
    ("smooth_join ratio", lambda: gb.smooth_join(Q, "C1", ratio=0), ValueError, r"ratio must be positive"),
    ("smooth_join degree", lambda: gb.smooth_join(Q, "C2", degree=1), ValueError, r"degree must be >= 2"),
    ("smooth_join G1 degenerate", lambda: gb.smooth_join([[0, 0], [1, 1], [1, 1]], "G1"), ValueError, r"ctrl must have distinct last two"),
    ("join_continuity dims", lambda: gb.join_continuity(Q, [[2, 0, 0], [3, 0, 0]]), ValueError, r"a and b must hold points of the same dimension"),
    ("join_continuity nan b", lambda: gb.join_continuity(Q, NAN_Q), ValueError, r"b must be finite"),
    ("join_continuity tol", lambda: gb.join_continuity(Q, Q, tol=-1), ValueError, r"tol must be positive"),
    ("variation zero normal", lambda: gb.variation_count(Q, [0, 0], [0, 0]), ValueError, r"line_normal must be a nonzero"),
    ("variation point dim", lambda: gb.variation_count(Q, [0, 0, 0], [0, 1]), ValueError, r"line_point must hold 2-dimensional"),
    ("crossings samples", lambda: gb.curve_crossings(Q, [0, 0], [0, 1], samples=1), ValueError, r"samples must be >= 2"),
    ("convex_hull 3d", lambda: gb.convex_hull(np.zeros((4, 3))), ValueError, r"points must hold 2-dimensional"),
    ("hull_contains 3d ctrl", lambda: gb.convex_hull_contains(np.zeros((3, 3)), [0, 0]), ValueError, r"ctrl must hold 2-dimensional"),
    ("hull_contains nan points", lambda: gb.convex_hull_contains(Q, [[0, np.nan]]), ValueError, r"points must be finite"),
    ("apply_affine shape", lambda: gb.apply_affine(Q, np.eye(4)), ValueError, r"M must hold 3-dimensional|M must have shape"),
    ("apply_affine projective", lambda: gb.apply_affine(Q, [[1, 0, 1], [0, 1, 0], [0, 0, 1]]), ValueError, r"M must be affine|M must have last column"),
    ("patch shape", lambda: gb.patch_de_casteljau(np.zeros((3, 2)), 0.5, 0.5), ValueError, r"ctrl must have shape \(m, n, d\)"),
    ("patch uv shapes", lambda: gb.patch_de_casteljau(NET, [0.1, 0.2], [0.1, 0.2, 0.3]), ValueError, r"u and v must have the same"),
    ("patch nan v", lambda: gb.patch_de_casteljau(NET, 0.5, [0.1, np.nan]), ValueError, r"v must be finite; v\[1\] is nan"),
    ("patch inf ctrl", lambda: gb.patch_de_casteljau(np.full((2, 2, 3), np.inf), 0.5, 0.5), ValueError, r"ctrl must be finite"),
    ("grid 2d u", lambda: gb.patch_evaluate_grid(NET, np.zeros((2, 2)), [0.5]), ValueError, r"u must be a 1-D array"),
    ("grid inf u", lambda: gb.patch_evaluate_grid(NET, [np.inf], [0.5]), ValueError, r"u must be finite"),
    ("patch_grid nu", lambda: gb.patch_grid(NET, 1, 5), ValueError, r"nu must be >= 2"),
    ("patch_grid nv float", lambda: gb.patch_grid(NET, 3, 2.5), TypeError, r"nv must be an integer"),
    ("derivatives nan u", lambda: gb.patch_derivatives(NET, np.nan, 0.5), ValueError, r"u must be finite"),
    ("normal 2d net", lambda: gb.patch_normal(np.zeros((2, 2, 2)), 0.5, 0.5), ValueError, r"ctrl must hold 3-dimensional"),
    ("BezierCurve nan", lambda: gb.BezierCurve(NAN_Q), ValueError, r"ctrl must be finite"),
    ("BezierPatch shape", lambda: gb.BezierPatch(Q), ValueError, r"ctrl must have shape \(m, n, d\)"),
]


@pytest.mark.parametrize("call,exc,pattern", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_names_the_parameter(call, exc, pattern):
    with pytest.raises(exc, match=pattern):
        call()


def test_no_nan_for_legitimate_edge_cases():
    # degree 0 curve: derivative, hodograph, elevation all well defined
    c = [[1.0, 2.0, 3.0]]
    assert gb.derivative(c, [0.2, 0.4], 1).tolist() == [[0, 0, 0]] * 2
    assert gb.elevate_degree(c).tolist() == [[1, 2, 3]] * 2
    assert gb.smooth_join(c, "C1", degree=2).tolist() == [[1, 2, 3], [1, 2, 3]]


@pytest.mark.parametrize("n", [0, 1, 1001])
def test_bernstein_evaluate_low_and_very_high_degree(n):
    ctrl = RNG.uniform(-1, 1, (n + 1, 2))
    t = np.array([0.0, 0.37, 0.5, 1.0])
    ref = binom.pmf(np.arange(n + 1), n, t[:, None]) @ ctrl
    assert np.allclose(gb.bernstein_evaluate(ctrl, t), ref, atol=1e-12)
    assert gb.bernstein_evaluate(ctrl, 0.25).shape == (2,)


# ------------------------------------------------------------------ §24.1 Neville's interpolation

@pytest.mark.parametrize("n", [0, 1, 2, 3, 5, 8])
def test_neville_matches_numpy_polyfit_through_the_points(n):
    rng = np.random.default_rng(n)
    pts = rng.uniform(-3, 3, size=(n + 1, 2))
    nodes = np.sort(rng.uniform(-1, 2, size=n + 1)) + np.arange(n + 1) * 0.1   # distinct, unequal gaps
    t = np.linspace(-1, 2.5, 41)
    got = gb.neville(pts, t, nodes=nodes)
    for c in range(2):
        ref = Polynomial.fit(nodes, pts[:, c], n)(t) if n else np.full(t.shape, pts[0, c])
        assert np.allclose(got[:, c], ref, rtol=0, atol=1e-8 * max(1.0, np.abs(ref).max()))
    assert np.allclose(gb.neville(pts, nodes, nodes=nodes), pts, atol=1e-12)  # L(t_i) = P_i


def test_neville_default_nodes_are_equally_spaced_and_differ_from_bezier():
    pts = [[0, 0], [1, 2], [3, 2], [4, 0]]
    assert np.allclose(gb.neville(pts, [0, 1 / 3, 2 / 3, 1]), pts)
    assert not np.allclose(gb.de_casteljau(pts, 1 / 3), pts[1])       # Bezier only approximates


def test_neville_rejects_bad_nodes():
    with pytest.raises(ValueError, match="nodes must be distinct"):
        gb.neville([[0, 0], [1, 1]], 0.5, nodes=[1, 1])
    with pytest.raises(ValueError, match="one parameter per point"):
        gb.neville([[0, 0], [1, 1]], 0.5, nodes=[0, 0.5, 1])


# ------------------------------------------------------------------ §24.5 differentiating de Casteljau

@pytest.mark.parametrize("n,d", [(0, 2), (1, 2), (2, 3), (3, 2), (6, 1), (9, 3)])
def test_last_leg_of_the_pyramid_is_the_derivative(n, d):
    ctrl = RNG.uniform(-4, 4, size=(n + 1, d))
    t = np.linspace(-0.3, 1.3, 17)
    point, vel = gb.de_casteljau_with_derivative(ctrl, t)
    polys = curve_polys(ctrl)
    ref_p = np.stack([p(t) for p in polys], -1)
    ref_v = np.stack([p.deriv()(t) if n else np.zeros_like(t) for p in polys], -1)
    assert np.allclose(point, ref_p, atol=1e-9)
    assert np.allclose(vel, ref_v, atol=1e-9)
    # and it is n times the last leg of the levels drawn by de_casteljau_steps
    if n:
        last = gb.de_casteljau_steps(ctrl, 0.3)[-2]
        assert np.allclose(gb.de_casteljau_with_derivative(ctrl, 0.3)[1], n * (last[1] - last[0]))


@pytest.mark.parametrize("n", [1, 3, 7, 15])
def test_de_casteljau_ends_are_the_end_points_exactly(n):
    """P(0) = P_0 and P(1) = P_n bit for bit, alone and among 10,000 parameters (the lerp
    (1-t) a + t b is exact at both ends; a + t (b - a) is not at t = 1)."""
    P = np.random.default_rng(n).normal(size=(n + 1, 2)) * 1e3 + 0.1
    t = np.linspace(0.0, 1.0, 10_000)
    out = gb.de_casteljau(P, t)
    assert (out[0] == P[0]).all() and (out[-1] == P[-1]).all()
    assert (gb.de_casteljau(P, 0.0) == P[0]).all() and (gb.de_casteljau(P, 1.0) == P[-1]).all()


# -- CurveSampler: the views' drawing path (Bernstein form as one matrix, §24.3) -------------------

@pytest.mark.parametrize("degree", [0, 1, 2, 3, 5, 7, 12])
@pytest.mark.parametrize("dim", [1, 2, 3])
def test_curve_sampler_draws_de_casteljaus_points(degree, dim):
    rng = np.random.default_rng(100 * degree + dim)
    P = rng.uniform(-50, 50, size=(degree + 1, dim))
    t = np.linspace(0.0, 1.0, 401)
    got = gb.curve_sampler(degree, 401)(P)
    assert got.shape == (401, dim)
    np.testing.assert_allclose(got, gb.de_casteljau(P, t), rtol=0, atol=2e-14 * 50 * (degree + 1))
    # the endpoints interpolate the end control points (B_0(0) = B_n(1) = 1 exactly)
    np.testing.assert_array_equal(got[0], P[0])
    np.testing.assert_array_equal(got[-1], P[-1])


def test_curve_sampler_against_numpy_polynomial_power_form():
    """A cubic in Bernstein form equals its power form, computed by numpy.polynomial."""
    P = np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 3.0], [5.0, 0.0]])
    t = np.array([0.0, 0.1, 0.5, 0.9, 1.0, 1.5, -0.5])
    # power-form coefficients of sum_k C(3,k) t^k (1-t)^(3-k) P_k, written out
    c0, c1, c2, c3 = P[0], 3 * (P[1] - P[0]), 3 * (P[2] - 2 * P[1] + P[0]), P[3] - 3 * P[2] + 3 * P[1] - P[0]
    want = np.stack([np.polynomial.polynomial.polyval(t, [c0[i], c1[i], c2[i], c3[i]]) for i in range(2)], axis=1)
    np.testing.assert_allclose(gb.CurveSampler(3, t)(P), want, rtol=0, atol=1e-13)
    np.testing.assert_allclose(gb.CurveSampler(3, t)(P)[2], [2.5, 2.25], rtol=0, atol=1e-15)


def test_curve_sampler_keeps_the_shape_of_t_and_takes_lists():
    draw = gb.CurveSampler(1, [[0.0, 1.0], [0.25, 0.5]])
    assert draw([[0, 0], [4, 8]]).tolist() == [[[0.0, 0.0], [4.0, 8.0]], [[1.0, 2.0], [2.0, 4.0]]]


def test_curve_sampler_is_made_once_per_degree_and_size():
    assert gb.curve_sampler(3, 400) is gb.curve_sampler(3, 400)
    assert gb.curve_sampler(3, 400) is not gb.curve_sampler(2, 400)
    assert gb.curve_sampler(np.int64(3), 400.0) is gb.curve_sampler(3, 400)


@pytest.mark.parametrize("ctrl, exc, match", [
    (np.array([[0.0, np.nan], [1, 1], [2, 2], [3, 3]]), ValueError, r"ctrl must be finite; ctrl\[0, 1\] is nan"),
    (np.array([[0.0, 0], [1, np.inf], [2, 2], [3, 3]]), ValueError, r"ctrl must be finite"),
    (np.ones((3, 2)), ValueError, r"ctrl must hold 4 control points \(degree 3\)"),
    (np.ones((4, 0)), ValueError, r"at least one coordinate"),
    ([[0, 0], [1, 1], [2, 2], [3, "a"]], TypeError, r"ctrl must be a numeric"),
])
def test_curve_sampler_refuses_bad_control_points(ctrl, exc, match):
    with pytest.raises(exc, match=match):
        gb.curve_sampler(3, 50)(ctrl)


def test_curve_sampler_reports_an_overflow_outside_the_unit_interval():
    with pytest.raises(ValueError, match="t is too large in magnitude"):      # the basis itself overflows
        gb.CurveSampler(3, [0.5, 1e103])
    draw = gb.CurveSampler(3, [0.5, 1e100])                                   # a finite basis, ~1e300
    with pytest.raises(ValueError, match="ctrl is too large"):
        draw([[0.0, 0], [1e10, 0], [0, 1e10], [1e10, 1e10]])


@pytest.mark.parametrize("args, exc, match", [
    ((-1, 10), ValueError, "degree must be >= 0"),
    ((2.5, 10), TypeError, "degree must be an integer"),
    ((3, 1), ValueError, "samples must be >= 2"),
    ((3, 10**9), ValueError, "samples must be <="),
])
def test_curve_sampler_refuses_bad_degree_or_size(args, exc, match):
    with pytest.raises(exc, match=match):
        gb.curve_sampler(*args)
