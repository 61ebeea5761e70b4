"""Tests of goldman_lib.bspline (Goldman chapter 27).

Expected values come from references independent of the code under test:
- scipy.interpolate.BSpline (curve values, BSpline.design_matrix for the basis, .derivative());
- scipy.interpolate.PPoly.from_spline (the polynomial pieces, "every spline is a B-spline");
- scipy.interpolate.bisplev and products of scipy BSpline bases (tensor-product surfaces);
- geomdl.NURBS.Curve (rational curves) and the exact circle and sphere (radius 1 to 1e-12);
- hand-computed values (blossom labels, small knot vectors);
- hypothesis properties stating the theorems of §27.2-27.9: partition of unity, local support,
  local de Boor == global de Boor, C^(p-m) smoothness at a knot of multiplicity m, the
  spline -> B-spline round trip, local control, the convex hull of each span.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.polynomial import Polynomial
from scipy.interpolate import BSpline, PPoly, bisplev
from scipy.spatial import Delaunay

from goldman_lib import bspline as bs
from goldman_lib import bspline

FAST = settings(max_examples=40, deadline=None, derandomize=True)


@st.composite
def splines(draw, dims=(1, 2, 3), max_degree=5, max_extra=6, clamped=None):
    """(ctrl, knots, degree) with random interior knots (repeats allowed up to the degree)."""
    p = draw(st.integers(0, max_degree))
    n1 = p + 1 + draw(st.integers(0, max_extra))
    d = draw(st.sampled_from(dims))
    seed = draw(st.integers(0, 2 ** 32 - 1))
    rng = np.random.default_rng(seed)
    m = n1 - p - 1
    pool = np.round(rng.uniform(0.05, 0.95, size=max(m, 1)), 2)
    inner = np.sort(rng.choice(pool, size=m))             # repeats happen
    # cap the multiplicity at p (so the curve stays continuous), at 1 for p == 0
    vals, counts = np.unique(inner, return_counts=True)
    if (counts > max(p, 1)).any():
        inner = np.sort(rng.uniform(0.05, 0.95, size=m))
    is_clamped = draw(st.booleans()) if clamped is None else clamped
    if is_clamped:
        knots = np.r_[np.zeros(p + 1), inner, np.ones(p + 1)]
    else:
        knots = np.r_[np.sort(rng.uniform(-1, 0, size=p)), 0.0, inner, 1.0, np.sort(rng.uniform(1, 2, size=p))]
    ctrl = rng.uniform(-5, 5, size=(n1, d))
    return ctrl, knots, p


def params(knots, p, count=37, seed=0):
    lo, hi = knots[p], knots[len(knots) - p - 1]
    rng = np.random.default_rng(seed)
    return np.r_[lo, hi, np.unique(knots[(knots >= lo) & (knots <= hi)]), rng.uniform(lo, hi, count)]


def scipy_derivative(knots, ctrl, p, order, u):
    """The order-th derivative by scipy: BSpline.derivative, or (it refuses internal knots of
    high multiplicity) the piecewise polynomial PPoly.from_spline(...).derivative."""
    u = np.asarray(u, dtype=float)
    ctrl = np.asarray(ctrl, dtype=float)
    if order > p:
        return np.zeros(u.shape + (ctrl.shape[1],))
    if order == 0:
        return BSpline(knots, ctrl, p)(u)
    try:
        return BSpline(knots, ctrl, p).derivative(order)(u)
    except ValueError:
        cols = [PPoly.from_spline(BSpline(knots, ctrl[:, c], p)).derivative(order)(u) for c in range(ctrl.shape[1])]
        return np.stack(cols, -1)


# ------------------------------------------------------------------ knot vectors

def test_check_knots_returns_floats():
    out = bs.check_knots([0, 0, 1, 2, 2], 1, 3)
    assert out.dtype == float and out.tolist() == [0.0, 0.0, 1.0, 2.0, 2.0]


def test_check_knots_non_decreasing_message():
    with pytest.raises(ValueError, match=r"knots must be non-decreasing; knots\[3\]=0.2 < knots\[2\]=0.5"):
        bs.check_knots([0, 0, 0.5, 0.2, 1, 1], 1)


def test_check_knots_multiplicity():
    with pytest.raises(ValueError, match=r"knots may repeat a knot at most degree\+1 = 3 times; knots\[3\]=0.5 appears 4"):
        bs.check_knots([0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1], 2)


def test_check_knots_length():
    with pytest.raises(ValueError, match=r"knots must have length n_ctrl \+ degree \+ 1 = 4 \+ 2 \+ 1 = 7; got 6"):
        bs.check_knots([0, 0, 0, 1, 1, 1], 2, 4)


def test_check_knots_too_few_and_domain():
    with pytest.raises(ValueError, match="at least 2\\*\\(degree\\+1\\) = 6 knots"):
        bs.check_knots([0, 0, 1, 1], 2)
    with pytest.raises(ValueError, match="non-empty domain"):
        bs.check_knots([0, 1, 1, 2], 1)


def test_check_knots_name_shape_finite_type():
    with pytest.raises(ValueError, match=r"knots_u must be non-decreasing"):
        bs.check_knots([1, 0, 0, 1], 1, name="knots_u")
    with pytest.raises(ValueError, match="1-D"):
        bs.check_knots([[0, 1], [2, 3]], 1)
    with pytest.raises(ValueError, match="finite"):
        bs.check_knots([0, 0, np.nan, 1, 1], 1)
    with pytest.raises(TypeError, match="knots"):
        bs.check_knots("0011", 1)
    with pytest.raises(TypeError, match="degree"):
        bs.check_knots([0, 0, 1, 1], 1.5)
    with pytest.raises(ValueError, match="degree"):
        bs.check_knots([0, 0, 1, 1], -1)


def test_clamped_and_uniform_knots():
    assert bs.clamped_knots(4, 3).tolist() == [0, 0, 0, 0, 1, 1, 1, 1]
    assert bs.clamped_knots(6, 2, [0.25, 0.5, 0.5]).tolist() == [0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1]
    np.testing.assert_allclose(bs.uniform_knots(5, 3), [-1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2, 2.5])
    t = bs.uniform_knots(7, 2)
    assert (t[2], t[7]) == (0.0, 1.0)
    with pytest.raises(ValueError, match="interior must hold"):
        bs.clamped_knots(6, 2, [0.5])
    with pytest.raises(ValueError, match="interior must lie in"):
        bs.clamped_knots(5, 2, [0.5, 1.5])
    with pytest.raises(ValueError, match="n_ctrl must be at least degree\\+1"):
        bs.clamped_knots(2, 2)
    with pytest.raises(ValueError, match="n_ctrl must be at least degree\\+1"):
        bs.uniform_knots(2, 3)


def test_find_span_against_searchsorted_and_hand_values():
    knots = [0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1]
    assert bs.find_span(knots, 2, [0, 0.1, 0.25, 0.3, 0.5, 0.9, 1.0]).tolist() == [2, 2, 3, 3, 5, 5, 5]
    assert bs.find_span(knots, 2, [0.25, 0.5, 1.0, 0.0], side="left").tolist() == [2, 3, 5, 2]
    assert isinstance(bs.find_span(knots, 2, 0.3), int)


def test_u_outside_domain_names_u():
    with pytest.raises(ValueError, match=r"u must lie in the domain \[knots\[2\], knots\[5\]\] = \[0, 1\]; u\[1\] is 1.5"):
        bs.de_boor([[0, 0]] * 5, [0, 0, 0, .3, .6, 1, 1, 1], 2, [0.5, 1.5])
    with pytest.raises(ValueError, match="u must lie in the domain"):
        bs.basis(bs.uniform_knots(5, 2), 2, -0.01)
    with pytest.raises(ValueError, match="u must be finite"):
        bs.de_boor([[0, 0]] * 3, [0, 0, 0, 1, 1, 1], 2, np.nan)


def test_ctrl_count_must_match_knots():
    with pytest.raises(ValueError, match="knots must have length len\\(ctrl\\)"):
        bs.de_boor([[0, 0]] * 4, [0, 0, 0, 1, 1, 1], 2, 0.5)
    with pytest.raises(ValueError, match="ctrl must have shape"):
        bs.de_boor([0, 1, 2], [0, 0, 0, 1, 1, 1], 2, 0.5)


# ------------------------------------------------------------------ §27.2-27.3 evaluation against scipy

@FAST
@given(splines())
def test_de_boor_matches_scipy(spl):
    ctrl, knots, p = spl
    u = params(knots, p)
    ref = BSpline(knots, ctrl, p)(u)
    np.testing.assert_allclose(bs.de_boor(ctrl, knots, p, u), ref, atol=1e-10)
    np.testing.assert_allclose(bs.global_de_boor(ctrl, knots, p, u), ref, atol=1e-10)


@FAST
@given(splines(dims=(2,), max_degree=4))
def test_local_de_boor_from_blossoming_equals_global(spl):
    ctrl, knots, p = spl
    u = params(knots, p, count=9)
    np.testing.assert_allclose(bs.local_de_boor(ctrl, knots, p, u), bs.global_de_boor(ctrl, knots, p, u), atol=1e-10)
    np.testing.assert_allclose(bs.local_de_boor(ctrl, knots, p, u), BSpline(knots, ctrl, p)(u), atol=1e-10)


def test_de_boor_shapes_and_large_input():
    rng = np.random.default_rng(3)
    ctrl = rng.normal(size=(50, 3))
    knots = bs.clamped_knots(50, 3)
    u = rng.uniform(0, 1, size=(7, 1000))       # several blocks, unsorted
    out = bs.de_boor(ctrl, knots, 3, u)
    assert out.shape == (7, 1000, 3)
    np.testing.assert_allclose(out, BSpline(knots, ctrl, 3)(u), atol=1e-12)
    assert bs.de_boor(ctrl, knots, 3, 0.5).shape == (3,)


@pytest.mark.parametrize("p", [0, 1, 3, 5])
def test_de_boor_gives_the_same_bits_for_sorted_shuffled_and_single_parameters(p):
    """Sorted parameters find their spans by placing the knots among them, shuffled ones by a binary
    search per parameter, single ones alone: every path runs the same pyramid to the same bits."""
    rng = np.random.default_rng(p)
    inner = [0.1, 0.3, 0.3, 0.5, 0.7, 0.7, 0.9] if p >= 2 else [0.1, 0.3, 0.5, 0.7, 0.9]   # doubled knots from p = 2
    knots = np.r_[np.zeros(p + 1), inner, np.ones(p + 1)]
    ctrl = rng.normal(size=(len(knots) - p - 1, 2))
    u = np.sort(np.r_[np.linspace(0, 1, 6001), knots])                  # every knot, and long runs
    out = bs.de_boor(ctrl, knots, p, u)
    np.testing.assert_allclose(out, BSpline(knots, ctrl, p)(u), atol=1e-12)
    perm = rng.permutation(u.size)
    assert np.array_equal(bs.de_boor(ctrl, knots, p, u[perm]), out[perm])
    assert np.array_equal(bs.de_boor(ctrl, knots, p, u[::-1]), out[::-1])
    assert all(np.array_equal(bs.de_boor(ctrl, knots, p, x), out[i]) for i, x in list(enumerate(u))[::251])
    if p:
        left = bs.derivative(ctrl, knots, p, u, side="left")
        assert np.array_equal(bs.derivative(ctrl, knots, p, u[perm], side="left"), left[perm])


@FAST
@given(splines(dims=(1,)))
def test_basis_matches_scipy_design_matrix(spl):
    _, knots, p = spl
    u = params(knots, p)
    ref = BSpline.design_matrix(u, knots, p).toarray()
    got = bs.basis(knots, p, u)
    assert got.shape == u.shape + (len(knots) - p - 1,)
    np.testing.assert_allclose(got, ref, atol=1e-12)


@FAST
@given(splines(dims=(1,)))
def test_partition_of_unity_and_local_support(spl):
    _, knots, p = spl
    u = params(knots, p)
    N = bs.basis(knots, p, u)
    assert (N >= -1e-14).all()
    np.testing.assert_allclose(N.sum(-1), 1.0, atol=1e-12)
    for i in range(N.shape[1]):
        lo, hi = bs.support(knots, p, i)
        outside = (u < lo) | (u > hi)
        assert np.all(N[outside, i] == 0.0)
    # at most p+1 functions are non-zero anywhere
    assert ((N != 0).sum(-1) <= p + 1).all()


def test_blossom_labels_give_the_control_points():
    rng = np.random.default_rng(5)
    knots = np.array([0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1])
    ctrl = rng.normal(size=(7, 2))
    labels = bs.control_point_labels(knots, 3)
    assert labels[0] == (0.0, 0.0, 0.0) and labels[3] == (0.2, 0.5, 0.7)
    for k in range(3, 7):                    # every non-empty span
        for i in range(k - 3, k + 1):        # the control points of that span
            np.testing.assert_allclose(bs.blossom(ctrl, knots, 3, labels[i], span=k), ctrl[i], atol=1e-12)


def test_blossom_is_symmetric_and_multiaffine():
    rng = np.random.default_rng(6)
    knots = bs.clamped_knots(6, 3, [0.5, 0.5])      # span 4 = [0.5, 0.5] is empty
    ctrl = rng.normal(size=(6, 2))
    a = rng.uniform(0, 1, 3)
    b1 = bs.blossom(ctrl, knots, 3, a, span=5)
    np.testing.assert_allclose(bs.blossom(ctrl, knots, 3, a[::-1], span=5), b1, atol=1e-12)
    np.testing.assert_allclose(bs.blossom(ctrl, knots, 3, a[[1, 2, 0]], span=5), b1, atol=1e-12)
    x, y, lam = 0.1, 0.9, 0.3
    mix = bs.blossom(ctrl, knots, 3, [(1 - lam) * x + lam * y, a[1], a[2]], span=5)
    parts = (1 - lam) * bs.blossom(ctrl, knots, 3, [x, a[1], a[2]], span=5) + lam * bs.blossom(ctrl, knots, 3, [y, a[1], a[2]], span=5)
    np.testing.assert_allclose(mix, parts, atol=1e-12)
    with pytest.raises(ValueError, match="args must hold degree = 3"):
        bs.blossom(ctrl, knots, 3, [0.5, 0.5])
    with pytest.raises(ValueError, match="span must index a non-empty"):
        bs.blossom(ctrl, knots, 3, a, span=4)


def test_de_boor_steps_levels():
    knots = [0, 0, 0, 0.5, 1, 1, 1]
    ctrl = np.array([[0.0, 0], [1, 2], [2, 2], [3, 0]])
    steps = bs.de_boor_steps(ctrl, knots, 2, 0.75)
    assert [len(s) for s in steps] == [3, 2, 1]
    np.testing.assert_allclose(steps[0], ctrl[1:])
    np.testing.assert_allclose(steps[-1][0], BSpline(np.array(knots, float), ctrl, 2)(0.75), atol=1e-12)
    with pytest.raises(ValueError, match="u must be a scalar"):
        bs.de_boor_steps(ctrl, knots, 2, [0.1, 0.2])


# ------------------------------------------------------------------ §27.4 derivatives and smoothness

@FAST
@given(splines(max_degree=5), st.integers(1, 3))
def test_derivative_matches_scipy(spl, order):
    ctrl, knots, p = spl
    u = params(knots, p, count=15, seed=1)
    interior = np.unique(knots[p + 1:len(knots) - p - 1])
    u = u[~np.isin(u, interior)]            # off the knots the derivative is two-sided
    ref = scipy_derivative(knots, ctrl, p, order, u)
    scale = 1 + np.abs(ref).max()
    np.testing.assert_allclose(bs.derivative(ctrl, knots, p, u, order), ref, atol=1e-8 * scale)


def test_derivative_ctrl_matches_scipy_derivative_coefficients():
    rng = np.random.default_rng(1)
    knots = np.array([0, 0, 0, 0, 0.3, 0.6, 0.6, 1, 1, 1, 1])
    ctrl = rng.normal(size=(7, 2))
    Q, t1, p1 = bs.derivative_ctrl(ctrl, knots, 3)
    ref = BSpline(knots, ctrl, 3).derivative()
    np.testing.assert_allclose(t1, ref.t[:len(t1)] if len(ref.t) == len(t1) else knots[1:-1])
    u = np.linspace(0, 1, 21)
    np.testing.assert_allclose(bs.de_boor(Q, t1, p1, u), ref(u), atol=1e-10)
    with pytest.raises(ValueError, match="degree must be >= 1"):
        bs.derivative_ctrl([[0.0], [1], [2]], [0, 0.3, 0.6, 1], 0)


@FAST
@given(st.integers(1, 5), st.data())
def test_smoothness_at_a_knot_of_multiplicity_m(p, data):
    m = data.draw(st.integers(1, p))
    rng = np.random.default_rng(data.draw(st.integers(0, 10 ** 6)))
    knots = np.r_[np.zeros(p + 1), 0.3, [0.55] * m, 0.8, np.ones(p + 1)]
    ctrl = rng.uniform(-3, 3, size=(len(knots) - p - 1, 2))
    assert bs.continuity_at(knots, p, 0.55) == p - m
    for r in range(p + 1):
        left = bs.derivative(ctrl, knots, p, 0.55, r, side="left")
        right = bs.derivative(ctrl, knots, p, 0.55, r, side="right")
        # independent: scipy's pieces on each side of the knot, evaluated at the knot
        # (scipy evaluates at a knot with the span on its right; one ulp below it, the left span)
        ref_left = scipy_derivative(knots, ctrl, p, r, np.nextafter(0.55, 0))
        np.testing.assert_allclose(left, ref_left, atol=1e-8 * (1 + np.abs(left).max()))
        np.testing.assert_allclose(right, scipy_derivative(knots, ctrl, p, r, 0.55), atol=1e-8 * (1 + np.abs(right).max()))
        if r <= p - m:
            np.testing.assert_allclose(left, right, atol=1e-8 * (1 + np.abs(right).max()))
    jumps = bs.derivative_jumps(ctrl, knots, p, 0.55)
    assert np.all(jumps[:p - m + 1] <= 1e-8 * (1 + jumps.max()))
    assert jumps[p - m + 1] > 1e-6      # generic control points: the next derivative jumps


def test_derivative_jumps_needs_interior_value():
    with pytest.raises(ValueError, match="strictly inside"):
        bs.derivative_jumps([[0], [1], [0]], [0, 0, 0, 1, 1, 1], 2, 0.0)


def test_discontinuous_curve_at_full_multiplicity():
    knots = [0, 0, 0.5, 0.5, 1, 1]       # degree 1, knot 0.5 twice: P1 and P2 are the two sides
    ctrl = [[0.0, 0], [1, 1], [2, 0], [3, 1]]
    assert bs.continuity_at(knots, 1, 0.5) == -1
    np.testing.assert_allclose(bs.derivative(ctrl, knots, 1, 0.5, 0, side="left"), [1, 1])
    np.testing.assert_allclose(bs.derivative(ctrl, knots, 1, 0.5, 0, side="right"), [2, 0])


# ------------------------------------------------------------------ §27.6 every spline is a B-spline

def ppoly_global_pieces(knots, ctrl, p):
    """scipy's pieces (local power form about each break) re-expanded in the global variable."""
    out = []
    for c in range(ctrl.shape[1]):
        pp = PPoly.from_spline(BSpline(knots, ctrl[:, c], p))
        per = []
        for i in range(len(pp.x) - 1):
            if pp.x[i] < pp.x[i + 1]:
                local = Polynomial(pp.c[::-1, i])            # in (u - x_i), lowest first
                glob = local(Polynomial([-pp.x[i], 1]))
                per.append(np.pad(glob.coef, (0, p + 1 - len(glob.coef))))
        out.append(per)
    return np.transpose(np.array(out), (1, 2, 0)), np.unique(pp.x)


@FAST
@given(splines(max_degree=4, clamped=True))
def test_bspline_to_pieces_matches_scipy_ppoly(spl):
    ctrl, knots, p = spl
    pieces, breaks = bs.bspline_to_pieces(ctrl, knots, p)
    ref, ref_breaks = ppoly_global_pieces(knots, ctrl, p)
    np.testing.assert_allclose(breaks, ref_breaks)
    np.testing.assert_allclose(pieces, ref, atol=1e-7 * (1 + np.abs(ref).max()))


@FAST
@given(splines(max_degree=4, clamped=True))
def test_every_spline_is_a_bspline_round_trip(spl):
    """Pieces from scipy (with the smoothness the knots give) -> B-spline form -> same curve."""
    ctrl, knots, p = spl
    pieces, breaks = ppoly_global_pieces(knots, ctrl, p)
    interior = breaks[1:-1]
    continuity = [p - int(np.sum(knots == b)) for b in interior]
    c2, k2, p2 = bs.spline_to_bspline(pieces, breaks, continuity)
    np.testing.assert_allclose(k2, knots)
    np.testing.assert_allclose(c2, ctrl, atol=1e-7 * (1 + np.abs(ctrl).max()))


def test_spline_to_bspline_hand_example_and_errors():
    # u^2 on [0, 1] and 1 + 2(u-1) + 0 (u-1)^2 = 2u - 1 on [1, 2]: a C^1 join at 1
    pieces = [[[0.0], [0.0], [1.0]], [[-1.0], [2.0], [0.0]]]
    ctrl, knots, p = bs.spline_to_bspline(pieces, [0, 1, 2], [1])
    assert knots.tolist() == [0, 0, 0, 1, 2, 2, 2]
    u = np.linspace(0, 2, 11)
    np.testing.assert_allclose(bs.de_boor(ctrl, knots, p, u)[:, 0], np.where(u <= 1, u ** 2, 2 * u - 1), atol=1e-12)


def test_spline_to_bspline_rejects_wrong_smoothness():
    pieces = [[[0.0], [0.0], [1.0]], [[0.0], [1.0], [0.0]]]     # u^2 then u: C^0 only at u = 1
    with pytest.raises(ValueError, match="pieces must join with the stated continuity"):
        bs.spline_to_bspline(pieces, [0, 1, 2], 1)
    ctrl, knots, p = bs.spline_to_bspline(pieces, [0, 1, 2], 0)
    assert knots.tolist() == [0, 0, 0, 1, 1, 2, 2, 2]
    with pytest.raises(ValueError, match="breaks must be strictly increasing"):
        bs.spline_to_bspline(pieces, [0, 2, 1], 0)
    with pytest.raises(ValueError, match="breaks must hold"):
        bs.spline_to_bspline(pieces, [0, 1], 0)
    with pytest.raises(ValueError, match="continuity must be <= 1"):
        bs.spline_to_bspline(pieces, [0, 1, 2], 2)


# ------------------------------------------------------------------ §27.7 properties

@FAST
@given(splines(dims=(2,), max_degree=4), st.data())
def test_local_control(spl, data):
    ctrl, knots, p = spl
    i = data.draw(st.integers(0, len(ctrl) - 1))
    moved = ctrl.copy()
    moved[i] += [1.5, -2.0]
    u = params(knots, p, count=60, seed=2)
    lo, hi = bs.support(knots, p, i)
    assert bs.affected_span(knots, p, i) == (max(lo, knots[p]), min(hi, knots[len(knots) - p - 1]))
    diff = np.abs(bs.de_boor(moved, knots, p, u) - bs.de_boor(ctrl, knots, p, u)).max(-1)
    # a continuous curve (p >= 1) is unchanged at the ends of the affected span as well
    outside = ((u <= lo) | (u >= hi)) if p >= 1 else ((u < lo) | (u > hi))
    assert np.all(diff[outside] < 1e-12)


def test_convex_hull_of_each_span():
    rng = np.random.default_rng(8)
    ctrl = rng.uniform(-2, 2, size=(8, 2))
    knots = bs.clamped_knots(8, 3, [0.2, 0.4, 0.6, 0.8])
    for k in range(3, 8):
        u = np.linspace(knots[k], knots[k + 1], 25)
        hull = Delaunay(ctrl[k - 3:k + 1])
        assert (hull.find_simplex(bs.de_boor(ctrl, knots, 3, u), tol=1e-9) >= 0).all()


def test_clamped_curve_interpolates_end_points():
    rng = np.random.default_rng(9)
    ctrl = rng.normal(size=(6, 3))
    knots = bs.clamped_knots(6, 3)
    np.testing.assert_allclose(bs.de_boor(ctrl, knots, 3, [0.0, 1.0]), ctrl[[0, -1]], atol=1e-14)


def test_bezier_is_a_bspline_with_clamped_knots():
    from scipy.special import comb
    ctrl = np.array([[0.0, 0], [1, 2], [3, 2.5], [4, 0.5]])
    t = np.linspace(0, 1, 11)[:, None]
    k = np.arange(4)
    bern = comb(3, k) * t ** k * (1 - t) ** (3 - k)
    np.testing.assert_allclose(bs.de_boor(ctrl, [0, 0, 0, 0, 1, 1, 1, 1], 3, t[:, 0]), bern @ ctrl, atol=1e-14)


# ------------------------------------------------------------------ §27.8 surfaces

def test_surface_grid_matches_bisplev():
    rng = np.random.default_rng(10)
    net = rng.normal(size=(7, 6, 3))
    tu = bs.clamped_knots(7, 3, [0.2, 0.5, 0.7])
    tv = bs.clamped_knots(6, 2, [0.3, 0.3, 0.8])
    u, v = np.linspace(0, 1, 13), np.linspace(0, 1, 9)
    ref = np.stack([bisplev(u, v, (tu, tv, net[:, :, c].ravel(), 3, 2)) for c in range(3)], -1)
    np.testing.assert_allclose(bs.surface_grid(net, tu, tv, 3, 2, u, v), ref, atol=1e-12)
    U, V = np.meshgrid(u, v, indexing="ij")
    np.testing.assert_allclose(bs.surface_de_boor(net, tu, tv, 3, 2, U, V), ref, atol=1e-12)


@FAST
@given(splines(dims=(1,), max_degree=3, clamped=False), splines(dims=(1,), max_degree=3))
def test_surface_is_product_of_scipy_bases(a, b):
    _, tu, pu = a
    _, tv, pv = b
    rng = np.random.default_rng(0)
    net = rng.normal(size=(len(tu) - pu - 1, len(tv) - pv - 1, 2))
    u, v = params(tu, pu, 6), params(tv, pv, 5)
    Nu = BSpline.design_matrix(u, tu, pu).toarray()
    Nv = BSpline.design_matrix(v, tv, pv).toarray()
    ref = np.einsum("ai,ijd,bj->abd", Nu, net, Nv)
    np.testing.assert_allclose(bs.surface_grid(net, tu, tv, pu, pv, u, v), ref, atol=1e-10)
    np.testing.assert_allclose(bs.surface_de_boor(net, tu, tv, pu, pv, u[:, None], v[None, :]), ref, atol=1e-10)


def test_surface_errors_name_the_knot_vector():
    net = np.zeros((4, 4, 3))
    with pytest.raises(ValueError, match="knots_v must have length"):
        bs.surface_grid(net, bs.clamped_knots(4, 3), bs.clamped_knots(5, 3), 3, 3, [0.5], [0.5])
    with pytest.raises(ValueError, match="v must lie in the domain"):
        bs.surface_de_boor(net, bs.clamped_knots(4, 3), bs.clamped_knots(4, 3), 3, 3, 0.5, 1.5)
    with pytest.raises(ValueError, match="u must be a 1-D"):
        bs.surface_grid(net, bs.clamped_knots(4, 3), bs.clamped_knots(4, 3), 3, 3, 0.5, [0.5])


# ------------------------------------------------------------------ §27.9 NURBS

def test_nurbs_curve_matches_geomdl():
    from geomdl import NURBS

    rng = np.random.default_rng(11)
    ctrl = rng.uniform(-2, 2, size=(7, 3))
    w = rng.uniform(0.3, 3.0, size=7)
    knots = [0, 0, 0, 0, 0.2, 0.55, 0.7, 1, 1, 1, 1]
    crv = NURBS.Curve()
    crv.degree = 3
    crv.ctrlptsw = [list(p * wi) + [wi] for p, wi in zip(ctrl, w)]
    crv.knotvector = knots
    u = np.linspace(0, 1, 23)
    ref = np.array(crv.evaluate_list(list(u)))
    np.testing.assert_allclose(bs.nurbs_curve(ctrl, w, knots, 3, u), ref, atol=1e-12)


def test_nurbs_with_unit_weights_is_the_bspline():
    rng = np.random.default_rng(12)
    ctrl = rng.normal(size=(6, 2))
    knots = bs.uniform_knots(6, 2)
    u = np.linspace(0, 1, 17)
    np.testing.assert_allclose(bs.nurbs_curve(ctrl, np.ones(6), knots, 2, u), BSpline(knots, ctrl, 2)(u), atol=1e-13)


def test_nurbs_circle_is_exact():
    ctrl, w, knots, p = bs.nurbs_circle()
    u = np.linspace(0, 1, 2001)
    pts = bs.nurbs_curve(ctrl, w, knots, p, u)
    np.testing.assert_allclose(np.hypot(pts[:, 0], pts[:, 1]), 1.0, atol=1e-12)
    # it goes once around: the angle increases monotonically through 360 degrees
    ang = np.unwrap(np.arctan2(pts[:, 1], pts[:, 0]))
    assert np.all(np.diff(ang) > 0) and math.isclose(ang[-1] - ang[0], 2 * math.pi, abs_tol=1e-12)
    c2, *_ = bs.nurbs_circle(2.5, (1, -1))
    pts = bs.nurbs_curve(c2, w, knots, p, u)
    np.testing.assert_allclose(np.hypot(pts[:, 0] - 1, pts[:, 1] + 1), 2.5, atol=1e-12)
    with pytest.raises(ValueError, match="radius must be positive"):
        bs.nurbs_circle(0)


def test_nurbs_sphere_is_exact():
    ctrl, w, tu, tv, p, q = bs.nurbs_sphere()
    u, v = np.linspace(0, 1, 61), np.linspace(0, 1, 41)
    g = bs.nurbs_surface_grid(ctrl, w, tu, tv, p, q, u, v)
    np.testing.assert_allclose(np.linalg.norm(g, axis=-1), 1.0, atol=1e-12)
    # it covers the sphere: z from -1 to 1, and every longitude
    assert math.isclose(g[..., 2].min(), -1, abs_tol=1e-12) and math.isclose(g[..., 2].max(), 1, abs_tol=1e-12)
    U, V = np.meshgrid(u[::7], v[::5], indexing="ij")
    np.testing.assert_allclose(bs.nurbs_surface(ctrl, w, tu, tv, p, q, U, V), g[::7, ::5], atol=1e-12)
    c3, *_ = bs.nurbs_sphere(2.0, (1, 2, 3))
    g = bs.nurbs_surface_grid(c3, w, tu, tv, p, q, u, v)
    np.testing.assert_allclose(np.linalg.norm(g - [1, 2, 3], axis=-1), 2.0, atol=1e-12)


def test_nurbs_weights_are_validated():
    ctrl, w, knots, p = bs.nurbs_circle()
    with pytest.raises(ValueError, match=r"weights must be positive; weights\[2\] is -1"):
        bs.nurbs_curve(ctrl, np.r_[w[:2], -1, w[3:]], knots, p, 0.5)
    with pytest.raises(ValueError, match="weights must have shape \\(9,\\)"):
        bs.nurbs_curve(ctrl, w[:5], knots, p, 0.5)
    c, ws, tu, tv, p, q = bs.nurbs_sphere()
    with pytest.raises(ValueError, match="weights must have shape \\(9, 5\\)"):
        bs.nurbs_surface(c, ws.T, tu, tv, p, q, 0.5, 0.5)


def test_classes():
    c = bs.BSplineCurve([[0, 0], [1, 2], [2, 2], [3, 0]], [0, 0, 0, 0.5, 1, 1, 1], 2)
    assert c.sample(5).shape == (5, 2)
    np.testing.assert_allclose(c.basis(0.25).sum(), 1.0)
    n = bs.NURBSCurve(*bs.nurbs_circle())
    assert "NURBSCurve" in repr(n) and n.sample(9).shape == (9, 2)
    # the circle's tangent is perpendicular to the radius; compare with a central difference
    u = np.array([0.1, 0.3, 0.6, 0.9])
    d = n.derivative(u)
    np.testing.assert_allclose(np.sum(d * n.evaluate(u), -1), 0, atol=1e-12)
    h = 1e-6
    np.testing.assert_allclose(d, (n.evaluate(u + h) - n.evaluate(u - h)) / (2 * h), rtol=1e-6)
    np.testing.assert_allclose(n.derivative(u, 0), n.evaluate(u), atol=1e-15)


# ------------------------------------------------------------------ §27.5 the global pyramid

def _piece_polynomials(ctrl, knots, p, k):
    """The polynomial piece on span k, from scipy's B-spline sampled inside the span (independent of goldman_lib)."""
    from numpy.polynomial import Polynomial
    from scipy.interpolate import BSpline
    s = np.linspace(knots[k], knots[k + 1], p + 3)[1:-1]
    vals = BSpline(knots, ctrl, p)(s)
    return [Polynomial.fit(s, vals[:, c], p) for c in range(ctrl.shape[1])]


@pytest.mark.parametrize("interior,p", [([0.25, 0.5, 0.75], 3), ([0.3, 0.6], 2), ([0.4, 0.4, 0.7], 3), ([0.5], 1)])
def test_global_pyramid_apex_holds_every_piece_and_nodes_are_blossoms(interior, p):
    rng = np.random.default_rng(len(interior) + p)
    n1 = len(interior) + p + 1
    knots = bspline.clamped_knots(n1, p, interior)
    ctrl = rng.uniform(-3, 3, size=(n1, 2))
    labels = bspline.global_pyramid_labels(knots, p)
    for u in (-0.2, 0.1, 0.45, 0.8, 1.3):          # any real u: each node is a polynomial in u
        levels = bspline.global_pyramid(ctrl, knots, p, u)
        assert [len(lv) for lv in levels] == [len(lb) for lb in labels] == [n1 - r for r in range(p + 1)]
        for node, info in zip(levels[p], labels[p]):
            for k in info["spans"]:
                ref = np.array([q(u) for q in _piece_polynomials(ctrl, knots, p, k)])
                assert np.allclose(node, ref, atol=1e-8)
        for r in range(p + 1):                     # locality: node (r, i) = b_k(u^r, t_{i+1}..t_{i+p-r}) for its spans
            for node, info in zip(levels[r], labels[r]):
                for k in info["spans"]:
                    args = [u] * r + list(info["knots"])
                    assert np.allclose(node, bspline.blossom(ctrl, knots, p, args, span=k), atol=1e-9)
    u = 0.45
    k = bspline.find_span(knots, p, u)
    assert np.allclose(bspline.global_pyramid(ctrl, knots, p, u)[p][k - p], bspline.de_boor(ctrl, knots, p, u))


def test_global_pyramid_labels_by_hand_and_empty_intervals():
    lv = bspline.global_pyramid_labels([0, 0, 0, 0, 0.5, 1, 1, 1, 1], 3)
    assert lv[0][2]["knots"] == (0.0, 0.5, 1.0) and lv[0][2]["u_count"] == 0
    assert lv[3][0]["interval"] == (0.0, 0.5) and lv[3][0]["spans"] == [3]
    doubled = bspline.global_pyramid_labels([0, 0, 0, 0.5, 0.5, 1, 1, 1], 2)
    assert [d["defined"] for d in doubled[2]] == [True, False, True]
    vals = bspline.global_pyramid([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]], [0, 0, 0, 0.5, 0.5, 1, 1, 1], 2, 0.3)
    assert np.isnan(vals[2][1]).all() and np.isfinite(vals[2][[0, 2]]).all()
