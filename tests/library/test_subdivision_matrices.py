"""goldman_lib.subdivision_matrices against independent references.

- Bezier subdivision matrices reproduce the dhermes/bezier package's Curve.subdivide and the
  closed form of the halves (the curve on [0, 1/2] reparametrised), for degrees 0..8;
- uniform B-spline subdivision matrices: the known cubic masks written here, and the halves of a
  segment evaluated by scipy.interpolate.BSpline;
- rows sum to one (hypothesis, random degrees and split parameters);
- the curve is the attractor of {P^-1 L P, P^-1 R P}: the attractor's points are the curve at
  dyadic parameters (de Casteljau), Hausdorff distance to a dense sample small, drawn both by
  goldman_lib.ifs (planar quadratics) and by the general-dimension deterministic algorithm;
- normal curves: Bernstein values written here, and every Bezier curve is an affine image;
- fractals with control points: affine invariance (moving the control points moves the attractor
  by the affine map between the control triangles), and the Sierpinski matrices give the gasket.
"""

import math

import bezier as bz
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline
from scipy.spatial.distance import cdist

from goldman_lib import ifs
from goldman_lib import subdivision_matrices as sm

FAST = settings(max_examples=30, deadline=None, derandomize=True)


def bezier_points(P, t):
    t = np.asarray(t, dtype=float)
    n = len(P) - 1
    B = np.stack([math.comb(n, k) * t ** k * (1 - t) ** (n - k) for k in range(n + 1)], -1)
    return B @ P


@pytest.mark.parametrize("n", range(0, 9))
def test_bezier_matrices_match_the_bezier_package(n):
    P = np.random.default_rng(n).normal(size=(n + 1, 2))
    L, R = sm.bezier_subdivision_matrices(n)
    left, right = bz.Curve(np.asfortranarray(P.T), n).subdivide()
    np.testing.assert_allclose(L @ P, left.nodes.T, atol=1e-12)
    np.testing.assert_allclose(R @ P, right.nodes.T, atol=1e-12)


@FAST
@given(st.integers(1, 7), st.floats(0.05, 0.95), st.integers(0, 2 ** 31))
def test_any_split_parameter_gives_the_two_pieces(n, t, seed):
    P = np.random.default_rng(seed).normal(size=(n + 1, 3))
    L, R = sm.bezier_subdivision_matrices(n, t)
    np.testing.assert_allclose(L.sum(1), 1) and np.testing.assert_allclose(R.sum(1), 1)
    s = np.linspace(0, 1, 9)
    np.testing.assert_allclose(bezier_points(L @ P, s), bezier_points(P, t * s), atol=1e-10)
    np.testing.assert_allclose(bezier_points(R @ P, s), bezier_points(P, t + (1 - t) * s), atol=1e-10)


def test_cubic_bspline_matrices_are_the_known_masks():
    L, R = sm.bspline_subdivision_matrices(3)
    np.testing.assert_allclose(8 * L, [[4, 4, 0, 0], [1, 6, 1, 0], [0, 4, 4, 0], [0, 1, 6, 1]])
    np.testing.assert_allclose(8 * R, [[1, 6, 1, 0], [0, 4, 4, 0], [0, 1, 6, 1], [0, 0, 4, 4]])
    L2, _ = sm.bspline_subdivision_matrices(2)
    np.testing.assert_allclose(4 * L2, [[3, 1, 0], [1, 3, 0], [0, 3, 1]])  # Chaikin


@pytest.mark.parametrize("n", range(1, 7))
def test_bspline_matrices_give_the_halves_of_a_segment(n):
    P = np.random.default_rng(10 + n).normal(size=(n + 1, 2))
    L, R = sm.bspline_subdivision_matrices(n)
    assert np.allclose(L.sum(1), 1) and np.allclose(R.sum(1), 1)
    knots = np.arange(2 * n + 2, dtype=float)            # the segment is [n, n + 1]
    half = n + (np.arange(2 * n + 2) - n) / 2            # spacing 1/2, segment [n, n + 1/2]
    u = np.linspace(0, 0.5, 11)
    np.testing.assert_allclose(BSpline(half, L @ P, n)(n + u), BSpline(knots, P, n)(n + u), atol=1e-12)
    np.testing.assert_allclose(BSpline(half + 0.5, R @ P, n)(n + 0.5 + u), BSpline(knots, P, n)(n + 0.5 + u), atol=1e-12)


def test_quadratic_curve_is_the_attractor_of_its_ifs_drawn_by_goldman_lib_ifs():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 1.0]])
    L, R = sm.bezier_subdivision_matrices(2)
    system = sm.control_point_ifs(P, (L, R))
    pts = ifs.deterministic(system, 8)                      # starts at the fixed point of map 0: P0
    expected = bezier_points(P, np.arange(2 ** 8) / 2 ** 8)  # dyadic parameters k / 2^8, in order
    np.testing.assert_allclose(pts, expected, atol=1e-12)
    dense = bezier_points(P, np.linspace(0, 1, 2001))
    chaos = ifs.chaos_game(system, 3000, rng=1)
    hausdorff = max(cdist(chaos, dense).min(1).max(), cdist(dense, chaos).min(1).max())
    assert hausdorff < 0.02


@pytest.mark.parametrize("n,d", [(3, 2), (4, 2), (5, 3), (3, 3)])
def test_lifted_curves_are_attractors_in_higher_dimensions(n, d):
    P = np.random.default_rng(n * 10 + d).normal(size=(n + 1, d))
    Phat = sm.lift_control_points(P)
    assert Phat.shape == (n + 1, n + 1) and abs(np.linalg.det(Phat)) > 1e-9
    np.testing.assert_array_equal(Phat[:, :d], P)
    maps, _ = sm.curve_ifs(P)
    L, R = sm.bezier_subdivision_matrices(n)
    np.testing.assert_allclose(Phat @ maps[0], L @ Phat, atol=1e-10)
    np.testing.assert_allclose(Phat @ maps[1], R @ Phat, atol=1e-10)
    pts = sm.curve_as_attractor(P, levels=7)
    # every block of n+1 points is the control polygon of the piece on [k/128, (k+1)/128]:
    ends = pts.reshape(-1, n + 1, d)[:, 0]
    np.testing.assert_allclose(ends, bezier_points(P, np.arange(128) / 128), atol=1e-9)
    dense = bezier_points(P, np.linspace(0, 1, 3001))
    assert max(cdist(pts, dense).min(1).max(), cdist(dense, pts).min(1).max()) < 0.01 * np.ptp(P)


def test_bspline_segment_is_the_attractor_of_its_ifs():
    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
    pts = sm.curve_as_attractor(P, levels=8, kind="bspline")
    u = np.linspace(3, 4, 1001)
    segment = BSpline(np.arange(8.0), P, 3)(u)
    assert max(cdist(pts, segment).min(1).max(), cdist(segment, pts).min(1).max()) < 0.01


def test_normal_curve_and_its_affine_images():
    t = np.linspace(0, 1, 7)
    N = sm.normal_curve(3, t)
    np.testing.assert_allclose(N, np.stack([3 * t * (1 - t) ** 2, 3 * t ** 2 * (1 - t), t ** 3], -1))
    E = sm.normal_curve_control_points(3)
    np.testing.assert_allclose(bezier_points(E, t), N, atol=1e-12)
    P = np.random.default_rng(4).normal(size=(4, 2))
    np.testing.assert_allclose(P[0] + N @ (P[1:] - P[0]), bezier_points(P, t), atol=1e-12)
    # in barycentric coordinates b(t) = (B_0, ..., B_n)(t) of the simplex the maps are L and R themselves
    L, R = sm.bezier_subdivision_matrices(3)
    b = np.column_stack([1 - N.sum(1), N])
    np.testing.assert_allclose(b @ L, np.column_stack([1 - sm.normal_curve(3, t / 2).sum(1), sm.normal_curve(3, t / 2)]), atol=1e-12)
    np.testing.assert_allclose(b @ R, np.column_stack([1 - sm.normal_curve(3, (1 + t) / 2).sum(1), sm.normal_curve(3, (1 + t) / 2)]), atol=1e-12)
    np.testing.assert_allclose(sm.curve_as_attractor(E, 5).reshape(-1, 4, 3)[:, 0], sm.normal_curve(3, np.arange(32) / 32), atol=1e-12)


@FAST
@given(st.floats(-0.6, 0.9), st.integers(0, 2 ** 31))
def test_fractals_move_with_their_control_points(middle, seed):
    rng = np.random.default_rng(seed)
    P = np.array([[0.0, 0.0], [1.0, 1.5], [2.0, 0.0]])
    A = np.eye(3)
    A[:2, :2] = rng.normal(size=(2, 2)) + 2 * np.eye(2)
    A[2, :2] = rng.normal(size=2)
    Q = np.column_stack([P, np.ones(3)]) @ A
    mats = sm.fractal_matrices(middle)
    f_P = ifs.deterministic(sm.control_point_ifs(P, mats), 7, start=P[[0, 2]])
    f_Q = ifs.deterministic(sm.control_point_ifs(Q[:, :2], mats), 7, start=Q[[0, 2], :2])
    np.testing.assert_allclose(np.column_stack([f_P, np.ones(len(f_P))]) @ A[:, :2], f_Q, atol=1e-8)
    # the attractor is a curve from P0 to P2 (consecutive copies meet)
    np.testing.assert_allclose(f_P[0], P[0]) and np.testing.assert_allclose(f_P[-1], P[2])
    np.testing.assert_allclose(f_P[1:-1:2], f_P[2::2], atol=1e-9)


def test_fractal_matrices_at_one_half_are_bezier_and_sierpinski_gives_the_gasket():
    L, R = sm.fractal_matrices(0.5)
    np.testing.assert_allclose(np.stack([L, R]), np.stack(sm.bezier_subdivision_matrices(2)))
    T = np.array([[0.0, 0.0], [4.0, 0.0], [1.0, 3.0]])
    gasket = sm.control_point_ifs(T, sm.sierpinski_matrices())
    # the maps are w_k(x) = (x + T_k) / 2, the classical Sierpinski maps of the triangle T
    for k, M in enumerate(gasket.maps):
        np.testing.assert_allclose(M[:2, :2], 0.5 * np.eye(2), atol=1e-12)
        np.testing.assert_allclose(M[2, :2], T[k] / 2, atol=1e-12)


def test_bad_input_rules():
    with pytest.raises(ValueError, match="n must be >= 0"):
        sm.bezier_subdivision_matrices(-1)
    with pytest.raises(TypeError, match="n must be an integer"):
        sm.bspline_subdivision_matrices(2.5)
    with pytest.raises(ValueError, match="row 1 sums to 0.9"):
        sm.check_rows_sum_to_one([[1, 0], [0.5, 0.4]], "L")
    with pytest.raises(ValueError, match="square matrix"):
        sm.check_rows_sum_to_one([[1, 0, 0]], "L")
    with pytest.raises(ValueError, match="at most n = 2 coordinates"):
        sm.lift_control_points(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="affinely dependent"):
        sm.lift_control_points([[0, 0], [1, 1], [2, 2]])
    with pytest.raises(ValueError, match="kind must be"):
        sm.curve_ifs([[0, 0], [1, 2], [2, 0]], kind="nurbs")
    with pytest.raises(ValueError, match="must not be collinear"):
        sm.control_point_ifs([[0, 0], [1, 1], [2, 2]], sm.fractal_matrices())
    with pytest.raises(ValueError, match="rows of matrices\\[1\\] must sum to 1"):
        sm.control_point_ifs([[0, 0], [1, 2], [2, 0]], [np.eye(3), 0.9 * np.eye(3)])
    with pytest.raises(ValueError, match="3 control points"):
        sm.control_point_ifs([[0, 0], [1, 2], [2, 0], [3, 1]], sm.fractal_matrices())
    with pytest.raises(ValueError, match="levels must be <= "):
        sm.attractor(sm.curve_ifs([[0, 0], [1, 2], [2, 0]])[0], 40, [[0, 0]])


def test_contraction_factors_agree_with_the_planar_ifs_and_compose_in_word_order():
    from goldman_lib import ifs as ifs_mod
    quad = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 1.0]])
    maps, _ = sm.curve_ifs(quad)
    planar = ifs_mod.IFS(maps).contraction_factors()
    assert np.allclose(sm.contraction_factors(maps), planar)
    # words in base-k order: index 1 is M_0 then M_1 (X @ M_0 @ M_1)
    two = sm.contraction_factors(maps, 2)
    assert two.shape == (4,)
    assert np.isclose(two[1], np.linalg.svd((maps[0] @ maps[1])[:2, :2], compute_uv=False)[0])
    # a scaling by 1/2 in 3-space: every composition of m maps scales by 2^-m
    half = np.diag([0.5, 0.5, 0.5, 1.0])
    assert np.allclose(sm.contraction_factors(np.stack([half, half]), 3), 0.125)


def test_contraction_factors_validate_their_input():
    maps, _ = sm.curve_ifs([[0, 0], [1, 2], [2, 0]])
    with pytest.raises(ValueError, match="length must be >= 1"):
        sm.contraction_factors(maps, 0)
    with pytest.raises(ValueError, match="length must be <= 20"):
        sm.contraction_factors(maps, 40)
    with pytest.raises(ValueError, match="square matrices"):
        sm.contraction_factors(np.zeros((2, 3, 4)))
