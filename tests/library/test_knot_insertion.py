"""Tests of goldman_lib.knot_insertion (Goldman chapter 28).

Independent references:
- scipy.interpolate.BSpline built here from the ORIGINAL control points and knots: every knot
  insertion algorithm (Boehm, Oslo, Lane-Riesenfeld, Schaefer) must leave the curve unchanged;
- geomdl (NURBS-Python): operations.insert_knot and helpers.knot_insertion as a second reference
  for Boehm's algorithm, and operations.refine_knotvector for the Oslo algorithm;
- the Bezier pieces of to_piecewise_bezier are evaluated with goldman_lib.bezier.de_casteljau (an
  independent module, tested against the `bezier` package) and compared with scipy;
- closed forms written in the test (Chaikin 3/4-1/4, the cubic 1/8-6/8-1/8 rule, the parabola);
- hypothesis properties for the theorems: invariance of the curve, variation diminishing,
  Lane-Riesenfeld = midpoint knot insertion, the O(4^-level) convergence.
"""

import math

import numpy as np
import pytest
from geomdl import BSpline as GBSpline
from geomdl import helpers as ghelpers
from geomdl import operations as gops
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline

from goldman_lib import bezier, bspline
from goldman_lib import knot_insertion as ki

FAST = settings(max_examples=40, deadline=None, derandomize=True)


# ------------------------------------------------------------------ strategies and references

@st.composite
def curves(draw, max_degree=5, clamped=None, simple=False, dims=(1, 2, 3)):
    """A random B-spline curve: (ctrl, knots, degree); knots clamped or floating, possibly repeated."""
    p = draw(st.integers(0 if not simple else 1, max_degree))
    n1 = draw(st.integers(p + 1, p + 6))
    d = draw(st.sampled_from(dims))
    seed = draw(st.integers(0, 2 ** 32 - 1))
    rng = np.random.default_rng(seed)
    ctrl = rng.uniform(-5, 5, (n1, d))
    is_clamped = draw(st.booleans()) if clamped is None else clamped
    if is_clamped:
        inner = np.sort(rng.uniform(0, 1, n1 - p - 1))
        if not simple and inner.size >= 2 and draw(st.booleans()) and p >= 1:
            inner[1] = inner[0]                      # a double interior knot
        knots = np.r_[np.zeros(p + 1), inner, np.ones(p + 1)]
    else:
        # floating ends: p knots below the domain [0, 1] and p above it
        knots = np.r_[np.sort(rng.uniform(-1, 0, p)), 0.0, np.sort(rng.uniform(0, 1, n1 - p - 1)), 1.0,
                      np.sort(rng.uniform(1, 2, p))]
    # keep the domain reasonably wide and the knots distinct enough
    knots = np.round(knots, 3)
    if simple:
        knots = _spread(knots, p, is_clamped)
    return ctrl, knots, p


def _spread(knots, p, clamped):
    """Make interior (non-end) knots simple: replace exact repeats by small offsets."""
    k = knots.copy()
    for i in range(1, k.size):
        if k[i] <= k[i - 1] and not (clamped and (i <= p or i >= k.size - p - 1)):
            k[i] = k[i - 1] + 1e-2
    return k


def ref_curve(ctrl, knots, p, u):
    """The curve by scipy, from the original data."""
    return BSpline(np.asarray(knots, float), np.asarray(ctrl, float), p, extrapolate=False)(u)


def domain_samples(knots, p, num=41):
    t = np.asarray(knots, float)
    return np.linspace(t[p], t[t.size - p - 1], num)


def same_curve(ctrl, knots, p, new_ctrl, new_knots, atol=1e-9):
    u = domain_samples(knots, p)
    # the last sample is the domain end: scipy evaluates it on the last span with extrapolate=False
    u = u[:-1]
    want = ref_curve(ctrl, knots, p, u)
    got = ref_curve(new_ctrl, new_knots, p, u)
    scale = max(1.0, float(np.abs(want).max()))
    np.testing.assert_allclose(got, want, atol=atol * scale)


def geomdl_curve(ctrl, knots, p):
    c = GBSpline.Curve()
    c.degree = p
    c.ctrlpts = np.asarray(ctrl, float).tolist()
    c.knotvector = np.asarray(knots, float).tolist()
    return c


# ------------------------------------------------------------------ §28.3.1 Boehm

def test_boehm_quadratic_by_hand():
    # insert 1/2 into the Bezier quadratic (0,0),(1,2),(2,0): the new points are the midpoints of the legs
    ctrl, knots = ki.boehm_insert([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
    assert ctrl.tolist() == [[0, 0], [0.5, 1], [1.5, 1], [2, 0]]
    assert knots.tolist() == [0, 0, 0, 0.5, 1, 1, 1]


def test_boehm_matches_geomdl_insert_knot():
    ctrl = [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1], [5, 3]]
    knots = [0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1]
    for u, times in [(0.1, 1), (0.3, 1), (0.5, 2), (0.7, 2), (0.3, 2), (0.55, 3)]:
        ours, our_knots = ki.boehm_insert(ctrl, knots, 3, u, times)
        ref = geomdl_curve(ctrl, knots, 3)
        gops.insert_knot(ref, [u], [times])
        np.testing.assert_allclose(ours, ref.ctrlpts, atol=1e-12)
        np.testing.assert_allclose(our_knots, ref.knotvector, atol=1e-15)


@FAST
@given(curves(clamped=True), st.floats(0, 1), st.integers(1, 3))
def test_boehm_matches_geomdl_helpers(curve, frac, times):
    ctrl, knots, p = curve
    u = round(frac, 3)
    s = int(np.count_nonzero(knots == u))
    times = min(times, p - s)       # geomdl stops at multiplicity p (a continuous curve)
    if times <= 0 or u in (0.0, 1.0):
        return
    ours, _ = ki.boehm_insert(ctrl, knots, p, u, times)
    ref = ghelpers.knot_insertion(p, knots.tolist(), ctrl.tolist(), u, num=times, s=s)
    np.testing.assert_allclose(ours, ref, atol=1e-9)


@FAST
@given(curves(), st.floats(0, 1), st.integers(0, 3))
def test_boehm_leaves_the_curve_unchanged(curve, frac, times):
    ctrl, knots, p = curve
    u = frac
    s = int(np.count_nonzero(knots == u))
    times = min(times, p + 1 - s)
    new_ctrl, new_knots = ki.boehm_insert(ctrl, knots, p, u, times)
    assert len(new_ctrl) == len(ctrl) + times and len(new_knots) == len(knots) + times
    same_curve(ctrl, knots, p, new_ctrl, new_knots)


def test_boehm_steps_replace_p_minus_1_points_by_p():
    ctrl = np.array([[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]], float)
    knots = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]
    steps = ki.boehm_steps(ctrl, knots, 3, 0.25, 2)
    assert len(steps) == 3
    first = steps[1]
    k = first["span"]
    assert k == 3                                    # t_3 = 0 <= 0.25 < t_4 = 0.5
    assert first["replaced"].tolist() == [1, 2]      # p - 1 = 2 old points go
    assert first["new"].tolist() == [1, 2, 3]        # p = 3 new points come
    # the kept points are old points: before the span unchanged, after it shifted by one
    np.testing.assert_array_equal(first["ctrl"][:k - 3 + 1], ctrl[:k - 3 + 1])
    np.testing.assert_array_equal(first["ctrl"][k + 1:], ctrl[k:])
    np.testing.assert_allclose(steps[-1]["ctrl"], ki.boehm_insert(ctrl, knots, 3, 0.25, 2)[0])


def test_boehm_new_points_lie_on_the_old_legs():
    ctrl = np.array([[0, 0], [1, 3], [3, 3], [4, 0], [6, 1]], float)
    knots = [0, 0, 0, 0, 0.4, 1, 1, 1, 1]
    step = ki.boehm_steps(ctrl, knots, 3, 0.7, 1)[1]
    for i, a in zip(step["new"], step["alphas"]):
        assert 0 <= a <= 1                          # convex: corner cutting
        np.testing.assert_allclose(step["ctrl"][i], (1 - a) * ctrl[i - 1] + a * ctrl[i])


# ------------------------------------------------------------------ §28.3.2 Oslo

def _refine(knots, p, rng, count):
    t = np.asarray(knots, float)
    lo, hi = t[p], t[t.size - p - 1]
    extra = np.round(rng.uniform(lo, hi, count), 3)
    tau = np.sort(np.r_[t, extra])
    # keep multiplicities <= p + 1
    _, counts = np.unique(tau, return_counts=True)
    if counts.max() > p + 1:
        return None
    return tau


@FAST
@given(curves(), st.integers(0, 2 ** 32 - 1), st.integers(0, 8))
def test_oslo_leaves_the_curve_unchanged(curve, seed, count):
    ctrl, knots, p = curve
    tau = _refine(knots, p, np.random.default_rng(seed), count)
    if tau is None:
        return
    new_ctrl = ki.oslo(ctrl, knots, p, tau)
    assert new_ctrl.shape == (tau.size - p - 1, ctrl.shape[1])
    same_curve(ctrl, knots, p, new_ctrl, tau)


def test_oslo_matches_geomdl_refine_knotvector():
    ctrl = [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1], [5, 3]]
    knots = [0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1]
    ref = geomdl_curve(ctrl, knots, 3)
    gops.refine_knotvector(ref, [1])      # density 1: the midpoint of every non-empty span
    ours = ki.oslo(ctrl, knots, 3, ref.knotvector)
    np.testing.assert_allclose(ours, ref.ctrlpts, atol=1e-12)


def test_oslo_equals_repeated_boehm():
    ctrl = np.array([[0, 0], [1, 2], [2, 2], [3, 0], [4, 1], [5, 3]], float)
    knots = np.array([0, 0, 0, 0.2, 0.5, 0.8, 1, 1, 1.0])
    Q, t = ctrl, knots
    for u in (0.1, 0.5, 0.65, 0.65):
        Q, t = ki.boehm_insert(Q, t, 2, u)
    np.testing.assert_allclose(ki.oslo(ctrl, knots, 2, t), Q, atol=1e-12)


def test_oslo_steps_are_the_blossom_pyramids():
    ctrl = np.array([[0, 0], [1, 2], [2, 2], [3, 0]], float)
    knots = [0, 0, 0, 0.5, 1, 1, 1]
    tau = [0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1]
    steps = ki.oslo_steps(ctrl, knots, 2, tau)
    np.testing.assert_allclose([s["point"] for s in steps], ki.oslo(ctrl, knots, 2, tau))
    for j, s in enumerate(steps):
        assert s["label"].tolist() == tau[j + 1:j + 3]
        assert [len(lv) for lv in s["levels"]] == [3, 2, 1]


# ------------------------------------------------------------------ §28.3.3 piecewise Bezier

@FAST
@given(curves())
def test_piecewise_bezier_reproduces_the_curve(curve):
    ctrl, knots, p = curve
    pieces, breaks = ki.to_piecewise_bezier(ctrl, knots, p)
    assert pieces.shape == (len(breaks) - 1, p + 1, ctrl.shape[1])
    s = np.linspace(0, 1, 9)[:-1]
    for piece, a, b in zip(pieces, breaks[:-1], breaks[1:]):
        np.testing.assert_allclose(bezier.de_casteljau(piece, s), ref_curve(ctrl, knots, p, a + (b - a) * s),
                                   atol=1e-9 * max(1, np.abs(ctrl).max()))


def test_piecewise_bezier_of_a_bezier_curve_is_itself():
    ctrl = [[0, 0], [1, 3], [3, 3], [4, 0]]
    pieces, breaks = ki.to_piecewise_bezier(ctrl, [0, 0, 0, 0, 1, 1, 1, 1], 3)
    np.testing.assert_allclose(pieces[0], ctrl)
    assert breaks.tolist() == [0, 1]


def test_uniform_cubic_bezier_points_by_hand():
    # uniform cubic, knots 0..7: the piece on [3, 4] has Bezier points
    # (P0 + 4P1 + P2)/6, (2P1 + P2)/3, (P1 + 2P2)/3, (P1 + 4P2 + P3)/6
    P = np.array([[0, 0], [1, 3], [3, 3], [4, 0]], float)
    pieces, breaks = ki.to_piecewise_bezier(P, np.arange(8.0), 3)
    want = [(P[0] + 4 * P[1] + P[2]) / 6, (2 * P[1] + P[2]) / 3, (P[1] + 2 * P[2]) / 3, (P[1] + 4 * P[2] + P[3]) / 6]
    np.testing.assert_allclose(pieces[0], want)
    assert breaks.tolist() == [3, 4]


# ------------------------------------------------------------------ §28.3.4 variation diminishing

def crossings(values):
    v = values[np.abs(values) > 1e-12]
    return int(np.count_nonzero(np.sign(v[1:]) != np.sign(v[:-1])))


@FAST
@given(curves(dims=(2,)), st.floats(-3, 3), st.floats(0, 180), st.integers(0, 2 ** 16))
def test_variation_diminishing(curve, offset, angle, seed):
    ctrl, knots, p = curve
    normal = np.array([np.cos(np.radians(angle)), np.sin(np.radians(angle))])
    point = offset * normal
    poly, crv = ki.variation_diminishing(ctrl, knots, p, point, normal)
    # reference: crossings of the scipy curve and of the polygon, counted here
    u = domain_samples(knots, p, 2001)[:-1]
    ref_curve_count = crossings((ref_curve(ctrl, knots, p, u) - point) @ normal)
    ref_poly_count = crossings((ctrl - point) @ normal)
    assert poly == ref_poly_count
    assert abs(crv - ref_curve_count) <= 1
    assert ref_curve_count <= ref_poly_count
    # knot insertion never adds a crossing to the polygon
    tau = _refine(knots, p, np.random.default_rng(seed), 4)
    if tau is not None:
        refined = ki.oslo(ctrl, knots, p, tau)
        assert crossings((refined - point) @ normal) <= ref_poly_count


@FAST
@given(curves(dims=(2,), simple=True), st.floats(-3, 3), st.floats(0, 180))
def test_subdivision_levels_never_add_crossings(curve, offset, angle):
    ctrl, knots, p = curve
    normal = np.array([np.cos(np.radians(angle)), np.sin(np.radians(angle))])
    point = offset * normal
    counts = [crossings((ctrl - point) @ normal)]
    Q, t = ctrl, knots
    for _ in range(3):
        Q, t = ki.schaefer(Q, t, p, 1)
        counts.append(crossings((Q - point) @ normal))
    assert all(b <= a for a, b in zip(counts, counts[1:])), counts


def test_variation_diminishing_example():
    ctrl = [[0, 1], [1, -1], [2, 1], [3, -1], [4, 1]]
    knots = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]
    poly, crv = ki.variation_diminishing(ctrl, knots, 3, [0, 0], [0, 1])
    assert poly == 4 and crv <= 4


# ------------------------------------------------------------------ §28.4.1 Lane-Riesenfeld

def test_chaikin_is_lane_riesenfeld_of_degree_2():
    P = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], float)
    got = ki.lane_riesenfeld(P, 2, 1, closed=True)
    want = []
    for i in range(4):
        a, b = P[i], P[(i + 1) % 4]
        want += [0.75 * a + 0.25 * b, 0.25 * a + 0.75 * b]
    np.testing.assert_allclose(got, want)


def test_cubic_rule_is_lane_riesenfeld_of_degree_3():
    P = np.random.default_rng(3).normal(size=(6, 2))
    got = ki.lane_riesenfeld(P, 3, 1, closed=True)
    m = len(P)
    # vertex rule (1, 6, 1)/8 and edge rule (1, 1)/2 (Catmull-Clark curve rules)
    for i in range(m):
        vertex = (P[i - 1] + 6 * P[i] + P[(i + 1) % m]) / 8
        edge = (P[i] + P[(i + 1) % m]) / 2
        assert any(np.allclose(vertex, g) for g in got)
        assert any(np.allclose(edge, g) for g in got)


def lr_reference_knots(n1, p, levels):
    """Knots of the open LR polygon, derived here: spacing 2^-L, same domain [p, n+1]."""
    h = 2.0 ** -levels
    count = n1
    for _ in range(levels):
        count = 2 * count - p
    start = p - p * h             # the domain start p must be knot number p
    return start + h * np.arange(count + p + 1)


@FAST
@given(st.integers(0, 5), st.integers(0, 5), st.integers(0, 4), st.integers(0, 2 ** 16))
def test_lane_riesenfeld_open_is_midpoint_knot_insertion(p, extra, levels, seed):
    n1 = p + 1 + extra
    P = np.random.default_rng(seed).uniform(-5, 5, (n1, 2))
    knots = np.arange(n1 + p + 1.0)
    Q = ki.lane_riesenfeld(P, p, levels)
    tau = lr_reference_knots(n1, p, levels)
    assert len(Q) + p + 1 == len(tau)
    np.testing.assert_allclose(ki.lane_riesenfeld_knots(n1, p, levels), tau)
    same_curve(P, knots, p, Q, tau)


@FAST
@given(st.integers(1, 5), st.integers(0, 4), st.integers(1, 3), st.integers(0, 2 ** 16))
def test_lane_riesenfeld_closed_is_the_same_periodic_curve(p, extra, levels, seed):
    m = p + 1 + extra
    P = np.random.default_rng(seed).uniform(-5, 5, (m, 2))
    Q = ki.lane_riesenfeld(P, p, levels, closed=True)
    assert len(Q) == m * 2 ** levels
    # the periodic curve: C(u) = sum_i P_{i mod m} N(u - i), N the cardinal B-spline on [0, p+1];
    # over [0, m) wrap the control points p times.  After L levels (spacing h = 2^-L), new point i
    # belongs to the B-spline starting at shift + i h, shift = p (1 - h) (as for the open curve).
    def periodic(ctrl, h, shift):
        k = len(ctrl)
        ext = np.vstack([ctrl[i % k] for i in range(-(p + 2), k + p + 2)])
        knots = shift + h * np.arange(-(p + 2), k + p + 2 + p + 1)
        return BSpline(knots, ext, p)
    h = 2.0 ** -levels
    u = np.linspace(0, m, 37)[:-1] + p
    want = periodic(P, 1.0, 0.0)(u)
    got = periodic(Q, h, p * (1 - h))(u)
    np.testing.assert_allclose(got, want, atol=1e-9)


def test_lane_riesenfeld_steps_shapes():
    steps = ki.lane_riesenfeld_steps([[0, 0], [1, 1], [2, 0], [3, 1]], 3, 2)
    assert [len(r) for r in steps[0]] == [8, 7, 6, 5]
    assert [len(r) for r in steps[1]] == [10, 9, 8, 7]


# ------------------------------------------------------------------ §28.4.2 Schaefer

@FAST
@given(curves(simple=True), st.integers(1, 3))
def test_schaefer_leaves_the_curve_unchanged(curve, levels):
    ctrl, knots, p = curve
    Q, tau = ki.schaefer(ctrl, knots, p, levels)
    assert len(Q) + p + 1 == len(tau)
    same_curve(ctrl, knots, p, Q, tau, atol=1e-8)


@FAST
@given(curves(simple=True))
def test_schaefer_knots_are_the_midpoint_refinement(curve):
    ctrl, knots, p = curve
    Q, tau = ki.schaefer(ctrl, knots, p, 1)
    # every old knot stays and the midpoint of every interval between knots of the new vector's range is added
    full = np.empty(2 * len(knots) - 1)
    full[0::2] = knots
    full[1::2] = (knots[:-1] + knots[1:]) / 2
    np.testing.assert_allclose(tau, full[p:p + len(tau)])
    # and, when the new knots refine the old ones (clamped ends), the control points are those of
    # the Oslo algorithm for these knots (a second route)
    if knots[0] == knots[p] and knots[-1] == knots[-p - 1]:
        np.testing.assert_allclose(Q, ki.oslo(ctrl, knots, p, tau), atol=1e-9 * max(1, np.abs(ctrl).max()))


@FAST
@given(st.integers(0, 5), st.integers(0, 5), st.integers(0, 3), st.integers(0, 2 ** 16))
def test_schaefer_equals_lane_riesenfeld_on_uniform_knots(p, extra, levels, seed):
    n1 = p + 1 + extra
    P = np.random.default_rng(seed).uniform(-5, 5, (n1, 2))
    Q, tau = ki.schaefer(P, np.arange(n1 + p + 1.0), p, levels)
    np.testing.assert_allclose(Q, ki.lane_riesenfeld(P, p, levels), atol=1e-10)
    np.testing.assert_allclose(tau, lr_reference_knots(n1, p, levels))


def test_schaefer_intermediate_points_are_blossom_values():
    ctrl = np.array([[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]], float)
    knots = np.array([0, 0, 0, 0, 0.3, 1, 1, 1, 1.0])
    steps = ki.schaefer_steps(ctrl, knots, 3)
    # the blossom by an independent route: Oslo with a knot vector containing the label is awkward,
    # so use the polynomial piece from scipy: the blossom of a cubic piece from its power form.
    spl = BSpline(knots, ctrl, 3)
    for r, (pts, labels) in enumerate(zip(steps["rounds"], steps["labels"])):
        assert len(pts) == len(labels)
        for x, lab in zip(pts, labels):
            lab = np.array(lab)
            # pick a piece whose interval meets the label's range: labels of valid points lie within the
            # knots of one span's de Boor window; use the span containing the label's mean
            mid = np.clip(lab.mean(), 0, 1 - 1e-12)
            want = cubic_blossom(spl, mid, lab)
            np.testing.assert_allclose(x, want, atol=1e-9)


def cubic_blossom(spl, at, lab):
    """Blossom of the cubic piece of spl containing `at`: from its Taylor coefficients there,
    b(u1,u2,u3) = c0 + c1 e1/3 + c2 e2/3 + c3 e3 with e_k the elementary symmetric functions of
    (u_i - at)."""
    c = [spl(at, nu=k) / math.factorial(k) for k in range(4)]
    x = lab - at
    e1 = x.sum()
    e2 = x[0] * x[1] + x[0] * x[2] + x[1] * x[2]
    e3 = x.prod()
    return c[0] + c[1] * e1 / 3 + c[2] * e2 / 3 + c[3] * e3


@pytest.mark.parametrize("p, knots", [
    (2, [0, 0, 0, 0.5, 0.5, 1, 1, 1]),                         # double knot, 2m - 1 = 3 = p + 1
    (3, [0, 0, 0, 0, 1, 1, 2, 3, 3, 3, 3]),
    (3, [0, 0, 0, 0, 1, 1, 1, 2, 3, 3, 3, 3]),                 # triple knot: 5 > p + 1, one point dropped
    (3, [0, 0, 0, 0, 1, 2, 2, 2, 2, 3, 4, 4, 4, 4]),           # multiplicity p + 1: a discontinuity
    (2, [0, 0, 0, 1, 2, 2, 2, 3, 3, 3]),
    (5, [0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 2, 3, 3, 3, 3, 3, 3]),
    (2, [-1, 0, 0, 1, 1, 2, 3, 3]),                            # floating ends with repeats outside and at the ends
    (1, [0, 0, 1, 1, 2, 2]),
])
def test_schaefer_on_repeated_knots_is_oslo_insertion_of_the_midpoints(p, knots):
    """Repeated knots: Schaefer's result is the Boehm/Oslo insertion of every midpoint (the midpoint
    of a zero-length interval is the knot itself), and B-splines of zero support are dropped."""
    knots = np.asarray(knots, float)
    n1 = len(knots) - p - 1
    ctrl = np.random.default_rng(n1 * 10 + p).uniform(-5, 5, (n1, 2))
    Q, tau = ki.schaefer(ctrl, knots, p, 1)
    assert len(Q) + p + 1 == len(tau)
    assert np.unique(tau, return_counts=True)[1].max() <= p + 1
    np.testing.assert_allclose(Q, ki.oslo(ctrl, knots, p, tau) if knots[0] == knots[p] and knots[-1] == knots[-p - 1]
                               else Q, atol=1e-12)
    # the independent route for every case: Boehm's algorithm, one midpoint at a time, on the clamped
    # curve's knots; and the curve itself through scipy
    if knots[0] == knots[p] and knots[-1] == knots[-p - 1]:
        P, t = ctrl, knots
        inner = tau[p + 1:len(tau) - p - 1]
        extra = list(inner)
        for x in t[p + 1:len(t) - p - 1]:
            extra.remove(x)
        for x in extra:
            P, t = ki.boehm_insert(P, t, p, x)
        np.testing.assert_allclose(t, tau)
        np.testing.assert_allclose(Q, P, atol=1e-12)
    same_curve(ctrl, knots, p, Q, tau, atol=1e-9)
    steps = ki.schaefer_steps(ctrl, knots, p)
    np.testing.assert_allclose(steps["ctrl"], Q)


@FAST
@given(curves(simple=False), st.integers(1, 2))
def test_schaefer_leaves_the_curve_unchanged_with_repeated_knots(curve, levels):
    ctrl, knots, p = curve
    Q, tau = ki.schaefer(ctrl, knots, p, levels)
    assert len(Q) + p + 1 == len(tau)
    same_curve(ctrl, knots, p, Q, tau, atol=1e-8)


# ------------------------------------------------------------------ §28.4.3 convergence

def test_greville_by_hand():
    assert ki.greville([0, 0, 0, 0, 1, 2, 2, 2, 2], 3).tolist() == [0, 1 / 3, 1, 5 / 3, 2]


@pytest.mark.parametrize("p, expected", [(2, 1 / 8), (3, 1 / 6)])
def test_closed_polygon_distance_of_a_square_by_hand(p, expected):
    # uniform periodic curve at a Greville point: weights (1, 6, 1)/8 (quadratic, mid-interval) and
    # (1, 4, 1)/6 (cubic, at a knot), so |P_i - C(xi_i)| = |2 P_i - P_i-1 - P_i+1| * expected = 2 * expected
    square = [[1, 0], [0, 1], [-1, 0], [0, -1]]
    assert ki.control_polygon_distance(square, None, p, closed=True) == pytest.approx(2 * expected, abs=1e-15)


@pytest.mark.parametrize("p", [1, 2, 3, 5])
def test_closed_curve_is_the_periodic_spline_of_scipy(p):
    rng = np.random.default_rng(p)
    P = rng.uniform(-2, 2, (4, 2))             # fewer points than degree + 1 for p = 5: still one trip round
    ext, t = ki.closed_curve(P, p)
    assert ext.shape == (4 + p, 2) and t.tolist() == list(range(4 + 2 * p + 1))
    lo, hi = bspline.domain(t, p)
    u = np.linspace(lo, hi, 9)
    periodic = BSpline(t, ext, p)(u)
    np.testing.assert_allclose(periodic[0], periodic[-1], atol=1e-12)          # closes
    np.testing.assert_allclose(bspline.de_boor(ext, t, p, u), periodic, atol=1e-12)
    # the distance measures every point once round the curve, as scipy evaluates it
    xi = ki.greville(t, p)
    inside = (xi >= lo) & (xi <= hi)
    by_scipy = np.linalg.norm(ext[inside] - BSpline(t, ext, p)(xi[inside]), axis=1)
    assert sorted({i % 4 for i in np.flatnonzero(inside)}) == [0, 1, 2, 3]
    assert ki.control_polygon_distance(P, None, p, closed=True) == pytest.approx(by_scipy.max(), abs=1e-12)


def test_polygon_distance_skips_abscissae_outside_an_unclamped_domain():
    # quadratic, knots 0..6, domain [2, 4]: abscissae 1.5, 2.5, 3.5, 4.5; the two inside are at
    # mid-interval, |2 P_i - P_i-1 - P_i+1| / 8 = sqrt(2) / 8 for both
    ctrl = [[0, 0], [1, 0], [1, 1], [0, 1]]
    t = np.arange(7.0)
    assert ki.control_polygon_distance(ctrl, t, 2, skip_outside=True) == pytest.approx(math.sqrt(2) / 8, abs=1e-15)
    # clipped instead: P_0 = (0, 0) against C(2) = (1/2, 0), P_3 against C(4) = (1/2, 1)
    assert ki.control_polygon_distance(ctrl, t, 2) == pytest.approx(0.5, abs=1e-15)


def test_polygon_distance_bad_flags_and_knots_name_the_parameter():
    with pytest.raises(TypeError, match="closed"):
        ki.control_polygon_distance([[0, 0], [1, 1]], [0, 0, 1, 1], 1, closed="yes")
    with pytest.raises(TypeError, match="skip_outside"):
        ki.control_polygon_distance([[0, 0], [1, 1]], [0, 0, 1, 1], 1, skip_outside=1)
    with pytest.raises(ValueError, match="knots must be None"):
        ki.control_polygon_distance([[0, 0], [1, 1]], [0, 0, 1, 1], 1, closed=True)
    with pytest.raises(ValueError, match="degree"):
        ki.closed_curve([[0, 0], [1, 1]], 0)
    with pytest.raises(ValueError, match="ctrl"):
        ki.closed_curve([[0, np.nan]], 2)


def test_parabola_converges_by_exactly_four():
    # for a quadratic the control point - curve gap at the Greville point is exactly h^2 / 4 * |a|:
    # it divides by 4 each level
    study = ki.convergence_study([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 5)
    np.testing.assert_allclose(study["ratio"], 4.0)
    np.testing.assert_allclose(study["distance"][0], 1.0)    # P1 = (1, 2), C(1/2) = (1, 1)


@pytest.mark.parametrize("p", [2, 3, 4, 5])
def test_convergence_rate_is_quadratic_measured_with_scipy(p):
    rng = np.random.default_rng(p)
    n1 = p + 4
    ctrl = rng.uniform(-3, 3, (n1, 2))
    knots = np.r_[np.zeros(p), np.linspace(0, 1, n1 - p + 1), np.ones(p)]
    dist = []
    Q, t = ctrl, knots
    for level in range(7):
        xi = np.array([t[i + 1:i + p + 1].mean() for i in range(len(Q))])
        dist.append(np.linalg.norm(Q - BSpline(knots, ctrl, p)(xi), axis=1).max())
        Q, t = ki.schaefer(Q, t, p, 1)
    ratios = np.array(dist[:-1]) / np.array(dist[1:])
    assert 3.3 < ratios[-1] < 4.7, ratios
    study = ki.convergence_study(ctrl, knots, p, 6)
    np.testing.assert_allclose(study["distance"], dist, rtol=1e-6, atol=1e-12)


# ------------------------------------------------------------------ §28.3.5 / §28.4.4 render, split, intersect

@FAST
@given(curves(dims=(2,), simple=True), st.floats(0.05, 0.95))
def test_split_gives_two_curves_that_make_up_the_original(curve, frac):
    ctrl, knots, p = curve
    lo, hi = knots[p], knots[len(knots) - p - 1]
    u = lo + frac * (hi - lo)
    (L, lk), (R, rk) = ki.split(ctrl, knots, p, u)
    s = np.linspace(0, 1, 11)[:-1]
    np.testing.assert_allclose(ref_curve(L, lk, p, lo + (u - lo) * s), ref_curve(ctrl, knots, p, lo + (u - lo) * s),
                               atol=1e-8)
    np.testing.assert_allclose(ref_curve(R, rk, p, u + (hi - u) * s), ref_curve(ctrl, knots, p, u + (hi - u) * s),
                               atol=1e-8)
    np.testing.assert_allclose(L[-1], R[0])


@pytest.mark.parametrize("method", ["bezier", "subdivision"])
def test_render_is_within_tolerance(method):
    ctrl = np.array([[0, 0], [1, 3], [3, 3], [4, 0], [6, 2], [7, 0]], float)
    knots = np.r_[0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1.0]
    tol = 1e-3
    pts, levels = ki.render_by_subdivision(ctrl, knots, 3, tol=tol, method=method)
    dense = BSpline(knots, ctrl, 3)(np.linspace(0, 1, 4001))
    # every polyline vertex is near the curve, and every curve point is near the polyline
    d_vertices = np.min(np.linalg.norm(pts[:, None] - dense[None], axis=2), axis=1).max()
    assert d_vertices < 4 * tol
    seg_a, seg_b = pts[:-1], pts[1:]
    ab = seg_b - seg_a
    w = dense[:, None] - seg_a[None]
    tt = np.clip((w * ab).sum(-1) / (ab * ab).sum(-1), 0, 1)
    d_curve = np.linalg.norm(w - tt[..., None] * ab, axis=2).min(1).max()
    assert d_curve < 4 * tol
    assert levels >= 1


def test_intersect_line_and_parabola_closed_form():
    line = ([[0, 0.5], [2, 0.5]], [0, 0, 1, 1], 1)
    arch = ([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    params, points = ki.intersect(line, arch, tol=1e-10)
    # arch: (2t, 4t(1-t)) = y 0.5 -> t = (1 +- sqrt(1/2)) / 2
    t = np.array([(1 - np.sqrt(0.5)) / 2, (1 + np.sqrt(0.5)) / 2])
    np.testing.assert_allclose(points, np.c_[2 * t, [0.5, 0.5]], atol=1e-8)
    np.testing.assert_allclose(params[:, 1], t, atol=1e-8)


def test_intersect_two_cubic_splines_against_a_dense_reference():
    a = (np.array([[0, 0], [1, 3], [2, -2], [3, 3], [4, -1], [5, 1]], float), np.r_[0, 0, 0, 0, 0.4, 0.7, 1, 1, 1, 1.0], 3)
    b = (np.array([[0, 1], [2, 0.2], [3, 1.5], [5, 0]], float), np.r_[0, 0, 0, 0.5, 1, 1, 1.0], 2)
    params, points = ki.intersect(a, b, tol=1e-10)
    A, B = BSpline(a[1], a[0], 3), BSpline(b[1], b[0], 2)
    np.testing.assert_allclose(A(params[:, 0]), B(params[:, 1]), atol=1e-7)
    np.testing.assert_allclose(points, A(params[:, 0]), atol=1e-9)
    # count crossings of the two curves by a dense polyline intersection (independent of ours)
    ua, ub = np.linspace(0, 1, 1500), np.linspace(0, 1, 1500)
    pa, pb = A(ua), B(ub)
    count = 0
    for i in range(len(pa) - 1):
        d = pb - pa[i]
        e = pa[i + 1] - pa[i]
        side = np.sign(e[0] * d[:, 1] - e[1] * d[:, 0])
        for j in np.flatnonzero(side[:-1] * side[1:] < 0):
            f = pb[j + 1] - pb[j]
            s1 = np.sign(f[0] * (pa[i][1] - pb[j][1]) - f[1] * (pa[i][0] - pb[j][0]))
            s2 = np.sign(f[0] * (pa[i + 1][1] - pb[j][1]) - f[1] * (pa[i + 1][0] - pb[j][0]))
            count += s1 * s2 < 0
    assert len(points) == count and count >= 3


# ------------------------------------------------------------------ bad input: one test per rule

def test_bad_knots_are_named():
    with pytest.raises(ValueError, match="knots must be non-decreasing"):
        ki.boehm_insert([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 0.5, 1], 2, 0.5)
    with pytest.raises(ValueError, match="knots must have length"):
        ki.oslo([[0, 0], [1, 1], [2, 0]], [0, 0, 1, 1], 2, [0, 0, 1, 1])


def test_u_outside_the_domain():
    with pytest.raises(ValueError, match="u must lie in the domain"):
        ki.boehm_insert([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 1.5)


def test_too_many_insertions():
    with pytest.raises(ValueError, match="times must keep the multiplicity"):
        ki.boehm_insert([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5, times=4)
    with pytest.raises(TypeError, match="times must be an integer"):
        ki.boehm_insert([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5, times=1.5)


def test_oslo_needs_a_refinement():
    with pytest.raises(ValueError, match="new_knots must contain every old knot"):
        ki.oslo([[0, 0], [1, 1], [2, 0], [3, 1]], [0, 0, 0, 0.5, 1, 1, 1], 2, [0, 0, 0, 0.4, 1, 1, 1])
    with pytest.raises(ValueError, match="new_knots may only add knots inside the domain"):
        ki.oslo([[0, 0], [1, 1], [2, 0], [3, 1]], np.arange(7.0), 2, np.r_[0, 0.5, np.arange(1, 7.0)])


def test_lane_riesenfeld_rules():
    with pytest.raises(ValueError, match="at least degree\\+1"):
        ki.lane_riesenfeld([[0, 0], [1, 1]], 3, 1)
    with pytest.raises(ValueError, match="levels must be <= 21"):
        ki.lane_riesenfeld([[0, 0], [1, 1]], 1, 30)
    with pytest.raises(TypeError, match="closed must be True or False"):
        ki.lane_riesenfeld([[0, 0], [1, 1]], 1, 1, closed="yes")
    with pytest.raises(ValueError, match="ctrl must be finite"):
        ki.lane_riesenfeld([[0, 0], [1, np.nan]], 1, 1)


def test_split_and_render_rules():
    c = ([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    with pytest.raises(ValueError, match="strictly inside the domain"):
        ki.split(*c, 1.0)
    with pytest.raises(ValueError, match="tol must be"):
        ki.render_by_subdivision(*c, tol=0)
    with pytest.raises(ValueError, match="method must be"):
        ki.render_by_subdivision(*c, method="magic")


def test_intersect_rules():
    c = ([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    with pytest.raises(TypeError, match="b must be a \\(ctrl, knots, degree\\) tuple"):
        ki.intersect(c, "curve")
    with pytest.raises(ValueError, match="a must be a planar curve"):
        ki.intersect(([[0, 0, 0], [1, 1, 1]], [0, 0, 1, 1], 1), c)
    with pytest.raises(ValueError, match="tol must be"):
        ki.intersect(c, c, tol=-1)


def test_degree_zero_is_handled():
    ctrl = [[0, 0], [1, 1], [2, 0]]
    knots = [0, 1, 2, 3]
    new_ctrl, _ = ki.boehm_insert(ctrl, knots, 0, 1.5)
    assert new_ctrl.tolist() == [[0, 0], [1, 1], [1, 1], [2, 0]]
    Q, _ = ki.schaefer(ctrl, knots, 0, 1)
    assert len(Q) == 6
    with pytest.raises(ValueError, match="degree must be >= 1"):
        ki.convergence_study(ctrl, knots, 0)


def test_intersect_at_a_knot_is_reported_once():
    # the quadratic meets x = 1 at its knot u = 1/2, where C(1/2) = (P1 + P2) / 2 = (1, 2)
    a = ([[0, 0], [0.5, 2], [1.5, 2], [2, 0]], [0, 0, 0, 0.5, 1, 1, 1], 2)
    b = ([[1, -1], [1, 3]], [0, 0, 1, 1], 1)
    params, points = ki.intersect(a, b)
    assert len(points) == 1
    np.testing.assert_allclose(points[0], [1, 2], atol=1e-9)
    np.testing.assert_allclose(params[0], [0.5, 0.75], atol=1e-9)


def test_oslo_pyramid_labels_are_blossom_arguments():
    """Every point of every Oslo pyramid is the blossom (bspline.blossom, another route) at its label."""
    rng = np.random.default_rng(28)
    ctrl = rng.uniform(-3, 3, (7, 2))
    knots = np.array([0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1.0])
    tau = np.sort(np.r_[knots, [0.1, 0.35, 0.5, 0.9]])
    for step in ki.oslo_steps(ctrl, knots, 3, tau):
        assert step["labels"][-1][0] == tuple(step["label"].tolist())
        for pts, labels in zip(step["levels"], step["labels"]):
            assert len(pts) == len(labels)
            for x, lab in zip(pts, labels):
                np.testing.assert_allclose(x, bspline.blossom(ctrl, knots, 3, lab, span=step["span"]), atol=1e-12)
