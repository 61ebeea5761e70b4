"""Chapter 25 additions to goldman_lib.bezier, against independent references: de Casteljau
evaluation at reparametrised points, the ``bezier`` package (dhermes/bezier) for subdivision, the
52 real intersection cases of its functional tests (../shared/peer-data), closed forms for the
ray-patch intersection, numpy.polynomial derivatives for smooth joins, and the theorems of §25.4
as hypothesis properties."""

import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from goldman_lib import bezier

PEER = Path(__file__).resolve().parents[3] / "shared" / "peer-data"
CASES_FILE = PEER / "bezier_curve_intersections.json"

coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


def polygons(min_deg=1, max_deg=6, dim=2):
    return st.integers(min_deg, max_deg).flatmap(lambda n: arrays(float, (n + 1, dim), elements=coord))


# -- §25.2 subdivision ------------------------------------------------------------------------

@settings(max_examples=60, deadline=None)
@given(polygons(0, 8, 3), st.floats(0.01, 0.99))
def test_subdivided_pieces_are_the_curve_reparametrised(ctrl, t):
    left, right = bezier.subdivide(ctrl, t)
    s = np.linspace(0, 1, 17)
    scale = max(1.0, np.abs(ctrl).max())
    np.testing.assert_allclose(bezier.de_casteljau(left, s), bezier.de_casteljau(ctrl, t * s), atol=1e-11 * scale)
    np.testing.assert_allclose(bezier.de_casteljau(right, s), bezier.de_casteljau(ctrl, t + (1 - t) * s),
                               atol=1e-11 * scale)


def test_subdivide_matches_the_bezier_package():
    bz = pytest.importorskip("bezier")
    rng = np.random.default_rng(25)
    for degree in (1, 2, 3, 5, 9):
        ctrl = rng.uniform(-3, 3, (degree + 1, 2))
        ref_left, ref_right = bz.Curve(np.asfortranarray(ctrl.T), degree).subdivide()
        left, right = bezier.subdivide(ctrl)
        np.testing.assert_allclose(left, ref_left.nodes.T, atol=1e-13)
        np.testing.assert_allclose(right, ref_right.nodes.T, atol=1e-13)


def test_subdivide_closed_form_for_a_cubic_at_one_half():
    # left = P0, (P0+P1)/2, (P0+2P1+P2)/4, (P0+3P1+3P2+P3)/8
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
    left, right = bezier.subdivide(P)
    np.testing.assert_allclose(left, [[0, 0], [0.5, 1.5], [1.25, 2.25], [2, 2.25]])
    np.testing.assert_allclose(right, [[2, 2.25], [2.75, 2.25], [3.5, 1.5], [4, 0]])


def test_subdivide_extrapolates_outside_the_unit_interval():
    P = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
    left, _ = bezier.subdivide(P, 2.0)   # the curve over [0, 2]
    s = np.linspace(0, 1, 5)
    np.testing.assert_allclose(bezier.de_casteljau(left, s), bezier.de_casteljau(P, 2 * s), atol=1e-12)


def test_subdivide_uniform_pieces_cover_the_curve_in_order():
    rng = np.random.default_rng(1)
    P = rng.uniform(-1, 1, (5, 2))
    pieces = bezier.subdivide_uniform(P, 3)
    assert pieces.shape == (8, 5, 2)
    s = np.linspace(0, 1, 7)
    for k, piece in enumerate(pieces):
        np.testing.assert_allclose(bezier.de_casteljau(piece, s), bezier.de_casteljau(P, (k + s) / 8), atol=1e-12)


@pytest.mark.parametrize("call,match", [
    (lambda: bezier.subdivide([[0, 0], [1, 1]], [0.2, 0.4]), "scalar"),
    (lambda: bezier.subdivide([[0, 0], [1, 1]], np.nan), "t must be finite"),
    (lambda: bezier.subdivide([0, 1, 2], 0.5), "shape"),
    (lambda: bezier.subdivide_uniform([[0, 0], [1, 1]], -1), "depth must be >= 0"),
    (lambda: bezier.subdivide_uniform([[0, 0], [1, 1]], 30), "depth must be <= 21"),
])
def test_subdivision_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_subdivide_uniform_depth_must_be_an_integer():
    with pytest.raises(TypeError, match="depth must be an integer"):
        bezier.subdivide_uniform([[0, 0], [1, 1]], 1.5)


# -- §25.3 flatness and rendering ---------------------------------------------------------------

@settings(max_examples=60, deadline=None)
@given(polygons(1, 7, 2))
def test_flatness_bounds_the_distance_to_the_uniformly_parametrised_chord(ctrl):
    t = np.linspace(0, 1, 201)
    chord = (1 - t)[:, None] * ctrl[0] + t[:, None] * ctrl[-1]
    dist = np.linalg.norm(bezier.de_casteljau(ctrl, t) - chord, axis=1).max()
    assert dist <= bezier.flatness(ctrl) + 1e-9


def test_flatness_of_a_quadratic_is_the_middle_point_offset():
    # |P1 - (P0 + P2)/2|, the closed form for a quadratic
    assert bezier.flatness([[0, 0], [1, 2], [2, 0]]) == pytest.approx(2.0)
    # a straight but unevenly parametrised quadratic: straight (0) but not evenly spaced (0.8)
    assert bezier.flatness([[0, 0], [1.8, 0], [2, 0]], even=False) == 0.0
    assert bezier.flatness([[0, 0], [1.8, 0], [2, 0]]) == pytest.approx(0.8)
    assert bezier.is_flat([[0, 0], [1.8, 0], [2, 0]], 0.1, even=False)
    assert not bezier.is_flat([[0, 0], [1.8, 0], [2, 0]], 0.1)


def test_flatness_quarters_with_each_midpoint_subdivision():
    # for a quadratic P1 - (P0+P2)/2 halves in both pieces' second differences: a factor 4
    P = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
    left, right = bezier.subdivide(P)
    assert bezier.flatness(left) == pytest.approx(bezier.flatness(P) / 4)
    assert bezier.flatness(right) == pytest.approx(bezier.flatness(P) / 4)


@pytest.mark.parametrize("tol", [1e-1, 1e-2, 1e-4])
def test_render_by_subdivision_stays_within_tol_of_the_curve(tol):
    P = np.array([[0.0, 0.0], [0.5, 3.0], [2.0, -1.0], [3.5, 2.5], [4.0, 0.5]])
    t, pts = bezier.render_by_subdivision(P, tol)
    assert t[0] == 0 and t[-1] == 1 and np.all(np.diff(t) > 0)
    np.testing.assert_allclose(pts, bezier.de_casteljau(P, t), atol=1e-12)
    # the curve between consecutive vertices stays within tol of the segment (uniformly parametrised)
    for t0, t1, p0, p1 in zip(t[:-1], t[1:], pts[:-1], pts[1:]):
        s = np.linspace(0, 1, 9)
        seg = (1 - s)[:, None] * p0 + s[:, None] * p1
        assert np.linalg.norm(bezier.de_casteljau(P, t0 + (t1 - t0) * s) - seg, axis=1).max() <= tol + 1e-12


def test_render_by_subdivision_uses_more_points_for_smaller_tol_and_few_on_a_line():
    P = np.array([[0.0, 0.0], [1.0, 2.5], [3.0, 2.5], [4.0, 0.5]])
    counts = [len(bezier.render_by_subdivision(P, tol)[0]) for tol in (1e-1, 1e-2, 1e-3)]
    assert counts[0] < counts[1] < counts[2]
    assert len(bezier.render_by_subdivision([[0, 0], [1, 1], [2, 2], [3, 3]], 1e-6)[0]) == 2


@pytest.mark.parametrize("call,match", [
    (lambda: bezier.render_by_subdivision([[0, 0], [1, 1]], 0.0), "tol must be positive"),
    (lambda: bezier.render_by_subdivision([[0, 0], [1, 1]], 0.1, max_depth=41), "max_depth must be <= 40"),
    (lambda: bezier.is_flat([[0, 0], [1, 1]], -1.0), "tol must be >= 0"),
])
def test_rendering_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# -- §25.3.1 curve-curve intersection ---------------------------------------------------------

def _peer_cases():
    if not CASES_FILE.exists():
        return []
    return json.loads(CASES_FILE.read_text())["cases"]


PEER_CASES = _peer_cases()


@pytest.mark.skipif(not PEER.exists(), reason=f"peer data folder {PEER} is absent (the shared folder sits beside the repository)")
def test_peer_data_has_the_52_cases():
    assert len(PEER_CASES) == 52
    assert sum(not c["expected"] for c in PEER_CASES) == 3


@pytest.mark.skipif(not PEER.exists(), reason=f"peer data folder {PEER} is absent (the shared folder sits beside the repository)")
@pytest.mark.parametrize("case", PEER_CASES, ids=[f"case{c['id']}" for c in PEER_CASES])
def test_intersect_curves_against_the_bezier_package_cases(case):
    expected = np.array(case["expected"], dtype=float).reshape(-1, 2)
    got = bezier.intersect_curves(case["a"], case["b"])
    assert got.shape == expected.shape, f"found {len(got)} intersections, expected {len(expected)}: {got.tolist()}"
    if len(expected) == 0:
        return
    tol = 1e-4 if case["tangent"] else 1e-6
    # both lists are sorted by s as in the source
    np.testing.assert_allclose(got, expected, atol=tol, rtol=0)
    # and every transversal pair of a mixed case to 1e-6
    for pair_tangent, g, e in zip(case["pair_is_tangent"], got, expected):
        if not pair_tangent:
            np.testing.assert_allclose(g, e, atol=1e-6, rtol=0)
    np.testing.assert_allclose(bezier.de_casteljau(case["a"], got[:, 0]), np.array(case["points"]), atol=tol)


def test_intersect_curves_agrees_with_the_bezier_package_on_random_cubics():
    bz = pytest.importorskip("bezier")
    rng = np.random.default_rng(7)
    checked = 0
    for _ in range(12):
        a, b = rng.uniform(0, 1, (4, 2)), rng.uniform(0, 1, (4, 2))
        ref = bz.Curve(np.asfortranarray(a.T), 3).intersect(bz.Curve(np.asfortranarray(b.T), 3)).T
        ref = ref[np.argsort(ref[:, 0])]
        got = bezier.intersect_curves(a, b)
        assert got.shape == ref.shape
        np.testing.assert_allclose(got, ref, atol=1e-9)
        checked += len(ref)
    assert checked > 5


def test_intersect_curves_line_and_parabola_closed_form():
    # y = 4t(1-t) against y = 3/4: t = 1/4, 3/4; the line's parameter is x/2 = t
    got = bezier.intersect_curves([[0, 0], [1, 2], [2, 0]], [[0, 0.75], [2, 0.75]])
    np.testing.assert_allclose(got, [[0.25, 0.25], [0.75, 0.75]], atol=1e-14)


def test_intersect_curves_tangential_parabolas_meet_once():
    # y = 2x(1-x)... as Bezier: a(s) = (s, 2s(1-s)), b(t) = (t, 1 - 2t(1-t)): a - b = 0 only at s = t = 1/2,
    # where both have slope 0: one tangential contact, returned once
    got = bezier.intersect_curves([[0, 0], [0.5, 1], [1, 0]], [[0, 1], [0.5, 0], [1, 1]])
    assert got.shape == (1, 2)
    np.testing.assert_allclose(got, [[0.5, 0.5]], atol=1e-8)


def test_intersect_curves_two_close_crossings_in_one_flat_pair():
    # the parabola y = (x - 1/2)^2 and the line y = 1e-6: crossings at x = 1/2 -+ 1e-3, close enough
    # to share a flat pair of pieces; both are found
    parabola = [[0, 0.25], [0.5, -0.25], [1, 0.25]]
    got = bezier.intersect_curves(parabola, [[0, 1e-6], [1, 1e-6]])
    np.testing.assert_allclose(got, [[0.499, 0.499], [0.501, 0.501]], atol=1e-12)


def test_intersect_curves_scalar_path_matches_the_array_path():
    """Small curves (at most bezier_intersection._SMALL points) take the scalar path; the array path
    it replaces for them gives the same intersections on random, near-tangent and near-coincident pairs."""
    from goldman_lib import bezier_intersection as bi

    rng = np.random.default_rng(3)
    cases = [(rng.uniform(0, 1, (da + 1, 2)), rng.uniform(0, 1, (db + 1, 2))) for da, db in rng.integers(1, 6, (150, 2))]
    for eps in (0.0, 1e-9, 1e-6, 1e-4, -1e-6):
        c = rng.uniform(0.2, 0.8)
        cases.append(([[0, c * c], [0.5, c * c - c], [1, (1 - c) ** 2]], [[0, eps], [1, eps]]))
    for _ in range(40):
        a = rng.uniform(0, 1, (4, 2))
        cases.append((a, a + rng.normal(0, 1e-3, (4, 2))))
    for a, b in cases:
        small = bezier.intersect_curves(a, b)
        keep, bi._SMALL = bi._SMALL, 1
        try:
            array = bezier.intersect_curves(a, b)
        finally:
            bi._SMALL = keep
        assert small.shape == array.shape, (a, b, small, array)
        if len(small):
            np.testing.assert_allclose(small, array, atol=1e-6)


def test_intersect_curves_with_a_point():
    # a degree-0 curve is a point: on the line y = x at the line's parameter 1/2, and off it
    np.testing.assert_allclose(bezier.intersect_curves([[1, 1]], [[0, 0], [2, 2]]), [[0.0, 0.5]], atol=1e-14)
    assert bezier.intersect_curves([[1, 1.5]], [[0, 0], [2, 2]]).shape == (0, 2)


def test_intersect_curves_uneven_parametrisation():
    # a straight quadratic x(s) = 3.6 s - 1.6 s^2 crossing x = 1: s = (3.6 - sqrt(6.56)) / 3.2
    got = bezier.intersect_curves([[0, 0], [1.8, 0], [2, 0]], [[1, -1], [1, 1]])
    np.testing.assert_allclose(got, [[(3.6 - np.sqrt(6.56)) / 3.2, 0.5]], atol=1e-14)


@pytest.mark.parametrize("call,match", [
    (lambda: bezier.intersect_curves([[0, 0, 0], [1, 1, 1]], [[0, 1], [1, 0]]), "2-dimensional"),
    (lambda: bezier.intersect_curves([[0, 0], [1, 1]], [[0, 1], [1, np.inf]]), "b must be finite"),
    (lambda: bezier.intersect_curves([[0, 0], [1, 1]], [[0, 1], [1, 0]], tol=0), "tol must be positive"),
    (lambda: bezier.intersect_curves([[0, 0], [1, 1]], [[0, 1], [1, 0]], max_depth=0), "max_depth must be >= 1"),
    (lambda: bezier.intersection_boxes([[0, 0], [1, 1]], [[0, 1], [1, 0]], 31), "level must be <= 30"),
])
def test_intersection_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_intersection_boxes_shrink_around_the_intersections():
    a = [[0, 0], [1, 2], [2, 0]]
    b = [[0, 0.75], [2, 0.75]]
    ba0, bb0, ia0, ib0 = bezier.intersection_boxes(a, b, 0)
    np.testing.assert_allclose(ba0, [[[0, 0], [2, 2]]])
    for level in (2, 4, 8):
        ba, bb, ia, ib = bezier.intersection_boxes(a, b, level)
        widths = ia[:, 1] - ia[:, 0]
        if level <= 4:     # nothing is flat yet: every kept piece has been halved `level` times
            np.testing.assert_allclose(widths, 2.0 ** -level)
        else:              # pieces that became flat earlier stay as they were
            assert np.all(widths >= 2.0 ** -level) and np.all(widths <= 2.0 ** -4)
        # every kept piece of a contains (in parameter) or touches one of the intersections 1/4, 3/4
        for lo, hi in ia:
            assert (lo - 1e-12 <= 0.25 <= hi + 1e-12) or (lo - 1e-12 <= 0.75 <= hi + 1e-12) or hi - lo >= 0.5


# -- §25.3.2 surfaces -------------------------------------------------------------------------

def _graph_patch():
    """The bicubic patch (x, y, f(x, y)) with f(x, y) = x^2 + x y on [0, 1]^2: a graph whose
    control net is known in closed form (x^2 has Bezier coefficients 0, 0, 1/3, 1 in degree 3,
    xy the products of 0, 1/3, 2/3, 1)."""
    g = np.arange(4) / 3.0
    xsq = np.array([0.0, 0.0, 1.0 / 3.0, 1.0])
    X, Y = np.meshgrid(g, g, indexing="ij")
    Z = xsq[:, None] + X * Y
    return np.stack([X, Y, Z], axis=-1)


def test_graph_patch_is_what_it_claims():
    net = _graph_patch()
    u = np.linspace(0, 1, 5)
    pts = bezier.patch_evaluate_grid(net, u, u)
    np.testing.assert_allclose(pts[..., 2], pts[..., 0] ** 2 + pts[..., 0] * pts[..., 1], atol=1e-14)


def test_subdivide_patch_quadrants_are_the_patch_reparametrised():
    rng = np.random.default_rng(3)
    net = rng.uniform(-1, 1, (3, 4, 3))
    parts = bezier.subdivide_patch(net, 0.3, 0.6)
    s = np.linspace(0, 1, 5)
    S, T = np.meshgrid(s, s, indexing="ij")
    for i, (u0, u1) in enumerate(((0, 0.3), (0.3, 1))):
        for j, (v0, v1) in enumerate(((0, 0.6), (0.6, 1))):
            np.testing.assert_allclose(bezier.patch_de_casteljau(parts[i, j], S, T),
                                       bezier.patch_de_casteljau(net, u0 + (u1 - u0) * S, v0 + (v1 - v0) * T),
                                       atol=1e-12)


def test_patch_flatness_bounds_the_distance_to_the_corner_triangles():
    rng = np.random.default_rng(4)
    for _ in range(20):
        net = rng.uniform(-1, 1, (4, 3, 3))
        u = np.linspace(0, 1, 41)
        U, V = np.meshgrid(u, u, indexing="ij")
        S = bezier.patch_de_casteljau(net, U, V)
        c00, c10, c11, c01 = net[0, 0], net[-1, 0], net[-1, -1], net[0, -1]
        lower = (U >= V)[..., None]     # triangle c00 c10 c11 below the diagonal u = v
        tri = np.where(lower, c00 + U[..., None] * (c10 - c00) + V[..., None] * (c11 - c10),
                       c00 + V[..., None] * (c01 - c00) + U[..., None] * (c11 - c01))
        assert np.linalg.norm(S - tri, axis=-1).max() <= bezier.patch_flatness(net) + 1e-12


def test_render_patch_counts_grow_as_the_tolerance_shrinks_and_cover_the_domain():
    net = _graph_patch()
    counts = []
    for tol in (1e-1, 1e-2, 1e-3):
        corners, domains = bezier.render_patch_by_subdivision(net, tol)
        area = ((domains[:, 1] - domains[:, 0]) * (domains[:, 3] - domains[:, 2])).sum()
        assert area == pytest.approx(1.0)
        # corners are the patch at the domain corners
        np.testing.assert_allclose(corners[:, 0], bezier.patch_de_casteljau(net, domains[:, 0], domains[:, 2]), atol=1e-12)
        np.testing.assert_allclose(corners[:, 2], bezier.patch_de_casteljau(net, domains[:, 1], domains[:, 3]), atol=1e-12)
        counts.append(len(domains))
    assert counts[0] < counts[1] < counts[2]
    # a planar bilinear patch (a parallelogram) is flat at once
    flat = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]
    assert len(bezier.render_patch_by_subdivision(flat, 1e-6)[1]) == 1


@pytest.mark.parametrize("x,y", [(0.2, 0.7), (0.5, 0.5), (0.9, 0.1), (0.0, 1.0)])
def test_vertical_ray_hits_the_graph_patch_at_f(x, y):
    net = _graph_patch()
    hits = bezier.intersect_ray_patch(net, [x, y, 5.0], [0, 0, -1])
    # closed form: the patch is (u, v, u^2 + u v), so u = x, v = y and s = 5 - f(x, y)
    np.testing.assert_allclose(hits, [[x, y, 5.0 - (x * x + x * y)]], atol=1e-10)


def test_oblique_ray_through_a_bilinear_patch_closed_form():
    # the hyperbolic paraboloid z = u v over the unit square; the ray (0,0,-1) + s (1, 1, 2) meets
    # it where 2s - 1 = s^2, i.e. s = 1: u = v = 1 ... and a second ray with a known single hit
    net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    hits = bezier.intersect_ray_patch(net, [0, 0, -1], [1, 1, 2])
    np.testing.assert_allclose(hits, [[1.0, 1.0, 1.0]], atol=1e-7)
    # ray (0.5, 0, 1) + s (0, 1, -1): u = 1/2, z = 1 - s = v/2 with v = s  => s = 2/3
    hits = bezier.intersect_ray_patch(net, [0.5, 0, 1], [0, 1, -1])
    np.testing.assert_allclose(hits, [[0.5, 2 / 3, 2 / 3]], atol=1e-12)


def test_ray_patch_misses_and_two_hits_in_order():
    net = _graph_patch()
    assert bezier.intersect_ray_patch(net, [2, 2, 5], [0, 0, -1]).shape == (0, 3)
    assert bezier.intersect_ray_patch(net, [0.5, 0.5, 5], [0, 0, 1]).shape == (0, 3)   # pointing away
    # a dome z = 1 - (2u-1)^2 along u (degree 2 in u): a horizontal ray at height 0.75 enters and leaves
    g = np.array([0.0, 0.5, 1.0])
    X, Y = np.meshgrid(g, g, indexing="ij")
    Z = np.array([0.0, 2.0, 0.0])[:, None] + 0 * Y
    dome = np.stack([X, Y, Z], axis=-1)
    hits = bezier.intersect_ray_patch(dome, [-1, 0.5, 0.75], [1, 0, 0])
    # z = 4u(1-u) = 0.75 at u = 1/4, 3/4: s = 1.25, 1.75
    np.testing.assert_allclose(hits, [[0.25, 0.5, 1.25], [0.75, 0.5, 1.75]], atol=1e-12)


@pytest.mark.parametrize("call,match", [
    (lambda: bezier.intersect_ray_patch(np.zeros((2, 2, 2)), [0, 0], [0, 1]), "3-dimensional"),
    (lambda: bezier.intersect_ray_patch(_graph_patch(), [0, 0, 1], [0, 0, 0]), "direction must be a nonzero"),
    (lambda: bezier.subdivide_patch(_graph_patch(), [0.5, 0.2], 0.5), "u must be a scalar"),
    (lambda: bezier.render_patch_by_subdivision(_graph_patch(), -1), "tol must be positive"),
])
def test_surface_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# -- §25.4 variation diminishing ---------------------------------------------------------------

@settings(max_examples=40, deadline=None)
@given(polygons(1, 6, 2), st.floats(-5, 5), st.floats(0, 180))
def test_subdivided_polygon_counts_decrease_to_the_curve_crossings(ctrl, c, angle):
    normal = [np.cos(np.radians(angle)), np.sin(np.radians(angle))]
    point = [c * normal[0], c * normal[1]]
    counts = bezier.subdivision_variation_counts(ctrl, point, normal, max_depth=6, tol=1e-9)
    assert all(a >= b for a, b in zip(counts, counts[1:])), counts
    assert counts[0] == bezier.variation_count(ctrl, point, normal, tol=1e-9)
    assert counts[-1] >= bezier.curve_crossings(ctrl, point, normal, samples=4001, tol=1e-9)


def test_subdivision_counts_reach_the_curve_count():
    # cubic y = 1 - 9t + 12t^2... (control ordinates 1, -2, 0, 1) against y = -0.7: the curve's minimum is
    # above -0.7 (closed form: min of (1-t)^3 - 6t(1-t)^2 + t^3 on [0, 1] is about -0.62)
    ctrl = [[0, 1], [1, -2], [2, 0], [3, 1]]
    t = np.linspace(0, 1, 100001)
    y = (1 - t) ** 3 - 6 * t * (1 - t) ** 2 + t ** 3
    assert y.min() > -0.7
    assert bezier.subdivision_variation_counts(ctrl, [0, -0.7], [0, 1], 4) == [2, 2, 0, 0, 0]


# -- §25.5 smooth joins -------------------------------------------------------------------------

@settings(max_examples=50, deadline=None)
@given(polygons(1, 6, 2), st.floats(0.05, 0.95))
def test_subdivided_halves_join_with_full_order(ctrl, t):
    left, right = bezier.subdivide(ctrl, t)
    n = len(ctrl) - 1
    assert bezier.join_order(left, right, ratio=(1 - t) / t, tol=1e-7) == n


def test_smooth_continuation_is_the_polynomial_extended():
    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]])
    for ratio in (0.5, 1.0, 2.0):
        Q = bezier.smooth_continuation(P, ratio)
        s = np.linspace(0, 1, 9)
        np.testing.assert_allclose(bezier.de_casteljau(Q, s), bezier.de_casteljau(P, 1 + ratio * s), atol=1e-12)


def test_join_order_matches_derivative_comparison():
    from math import comb
    from numpy.polynomial import Polynomial

    def derivs(ctrl, t, r):
        ctrl = np.asarray(ctrl, float)
        n = len(ctrl) - 1
        polys = [sum(comb(n, k) * ctrl[k, c] * Polynomial([0, 1]) ** k * Polynomial([1, -1]) ** (n - k)
                     for k in range(n + 1)) for c in range(ctrl.shape[1])]
        return np.array([p.deriv(r)(t) if r else p(t) for p in polys])

    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]])
    Q = bezier.smooth_continuation(P, 1.0)
    rng = np.random.default_rng(5)
    for k in range(-1, 4):
        R = Q.copy()
        if k < 3:
            R[k + 1] += rng.uniform(0.5, 1.0, 2)     # break C^(k+1), keep C^k
        order = bezier.join_order(P, R)
        assert order == k
        # the reference: derivatives of both pieces at the join (equal intervals)
        matches = [np.allclose(derivs(P, 1.0, r), derivs(R, 0.0, r)) for r in range(4)]
        expected = -1
        for r, ok in enumerate(matches):
            if not ok:
                break
            expected = r
        assert order == expected


def test_join_order_elevates_the_lower_degree_and_agrees_with_join_continuity():
    a = [[0, 0], [1, 1], [2, 0]]
    b = [[2, 0], [3, -1], [4, 0]]
    assert bezier.join_order(a, b) == 1
    assert bezier.join_continuity(a, b)["C1"] and not bezier.join_continuity(a, b)["C2"]
    line = [[0, 0], [1, 1]]
    assert bezier.join_order(line, [[1, 1], [1.5, 1.5], [2, 2]]) == 2    # one straight line: C^infinity
    assert bezier.join_order(line, [[5, 5], [6, 6]]) == -1


@pytest.mark.parametrize("call,match", [
    (lambda: bezier.join_order([[0, 0], [1, 1]], [[1, 1, 0], [2, 2, 0]]), "same dimension"),
    (lambda: bezier.join_order([[0, 0], [1, 1]], [[1, 1], [2, 2]], ratio=0), "ratio must be positive"),
    (lambda: bezier.smooth_continuation([[0, 0], [1, 1]], ratio=-1), "ratio must be positive"),
    (lambda: bezier.subdivision_variation_counts([[0, 0], [1, 1]], [0, 0], [0, 0]), "nonzero"),
])
def test_join_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# -- §25.3.2 surface-surface intersection --------------------------------------------------------
# Closed forms: a bilinear patch with evenly spaced control points is the affine map of [0, 1]^2,
# and z = x^2 + y^2 over [-1, 1]^2 is exactly a biquadratic patch: x = 2u - 1 has Bezier
# coefficients (-1, 0, 1) and x^2 = (2u - 1)^2 has (1, -1, 1) (degree 3: (1, -1/3, -1/3, 1)).

def _paraboloid(degree):
    xs = {2: [-1.0, 0.0, 1.0], 3: [-1.0, -1 / 3, 1 / 3, 1.0]}[degree]
    sq = {2: [1.0, -1.0, 1.0], 3: [1.0, -1 / 3, -1 / 3, 1.0]}[degree]
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    Z = np.add.outer(sq, sq)
    return np.stack([X, Y, Z], axis=-1)


def _plane(c, half=1.5):
    return np.array([[[-half, -half, c], [-half, half, c]], [[half, -half, c], [half, half, c]]])


def test_paraboloid_net_is_the_closed_form():
    # the reference surface itself, at random parameters, before using it as one
    rng = np.random.default_rng(3)
    u, v = rng.uniform(0, 1, (2, 50))
    x, y = 2 * u - 1, 2 * v - 1
    for degree in (2, 3):
        np.testing.assert_allclose(bezier.patch_de_casteljau(_paraboloid(degree), u, v),
                                   np.stack([x, y, x * x + y * y], -1), atol=1e-12)


def test_intersect_patches_planes_meet_in_a_known_segment():
    floor = np.array([[[0.0, 0, 0], [0, 2, 0]], [[2, 0, 0], [2, 2, 0]]])            # z = 0, (x, y) = 2 (u, v)
    s = np.linspace(0, 1, 4)
    S, T = np.meshgrid(s, s, indexing="ij")
    ramp = np.stack([2 * S, 0.5 + T, 2 * S - 1], axis=-1)                              # z = x - 1, bicubic net
    points, params = bezier.intersect_patches(floor, ramp, tol=1e-3)
    y = points[:, 1]
    np.testing.assert_allclose(points[:, [0, 2]], np.tile([1.0, 0.0], (len(points), 1)), atol=1e-12)
    assert y.min() == pytest.approx(0.5, abs=1e-12) and y.max() == pytest.approx(1.5, abs=1e-12)
    assert np.diff(np.sort(y)).max() <= 0.5 + 1e-12
    np.testing.assert_allclose(params, np.stack([np.full_like(y, 0.5), y / 2, np.full_like(y, 0.5), y - 0.5], -1),
                               atol=1e-12)


@pytest.mark.parametrize("degree", [2, 3])
@pytest.mark.parametrize("c", [0.25, 0.5, 0.81])
def test_intersect_patches_paraboloid_and_plane_give_the_circle(degree, c):
    tol = 0.02
    points, params = bezier.intersect_patches(_paraboloid(degree), _plane(c), tol=tol)
    r = np.sqrt(c)
    assert len(points) >= 12
    # on the circle x^2 + y^2 = c, z = c
    np.testing.assert_allclose(np.hypot(points[:, 0], points[:, 1]), r, atol=1e-9)
    np.testing.assert_allclose(points[:, 2], c, atol=1e-9)
    # on both surfaces at the returned parameters (closed forms of both patches)
    u, v, s, t = params.T
    on_a = np.stack([2 * u - 1, 2 * v - 1, (2 * u - 1) ** 2 + (2 * v - 1) ** 2], -1)
    on_b = np.stack([3 * s - 1.5, 3 * t - 1.5, np.full_like(s, c)], -1)
    np.testing.assert_allclose(on_a, points, atol=1e-9)
    np.testing.assert_allclose(on_b, points, atol=1e-9)
    # the whole circle is covered: no gap between consecutive samples larger than a few pieces
    angle = np.sort(np.arctan2(points[:, 1], points[:, 0]))
    gaps = np.diff(np.concatenate([angle, angle[:1] + 2 * np.pi])) * r
    assert gaps.max() < 0.25
    assert len(np.unique(np.round(points, 9), axis=0)) == len(points)       # no repeated samples


def test_intersect_patches_unpolished_samples_are_within_tol():
    c, tol = 0.5, 0.02
    points, params = bezier.intersect_patches(_paraboloid(2), _plane(c), tol=tol, polish=False)
    assert len(points) >= 12
    assert np.abs(np.hypot(points[:, 0], points[:, 1]) - np.sqrt(c)).max() <= tol
    np.testing.assert_allclose(points[:, 2], c, atol=1e-12)
    # a smaller tolerance samples more densely
    finer, _ = bezier.intersect_patches(_paraboloid(2), _plane(c), tol=tol / 4)
    assert len(finer) > len(points)


def test_intersect_patches_swapped_patches_give_the_same_curve():
    p1, x1 = bezier.intersect_patches(_paraboloid(2), _plane(0.5))
    p2, x2 = bezier.intersect_patches(_plane(0.5), _paraboloid(2))
    assert len(p1) == len(p2)
    k1 = np.lexsort(np.round(p1, 9).T)
    k2 = np.lexsort(np.round(p2, 9).T)
    np.testing.assert_allclose(p1[k1], p2[k2], atol=1e-9)
    np.testing.assert_allclose(x1[k1], x2[k2][:, [2, 3, 0, 1]], atol=1e-9)


@pytest.mark.parametrize("b", [_plane(2.5), _plane(-0.01), _plane(0.5) + [5.0, 0.0, 0.0]])
def test_intersect_patches_disjoint_patches_meet_nowhere(b):
    points, params = bezier.intersect_patches(_paraboloid(2), b)
    assert points.shape == (0, 3) and params.shape == (0, 4)


@pytest.mark.parametrize("kwargs,error,match", [
    ({"a": [[0, 0, 0]]}, ValueError, "^a must have shape"),
    ({"b": [[[0, 0]]]}, ValueError, "^b must hold 3-dimensional"),
    ({"a": [[[0, 0, np.nan]]]}, ValueError, "^a must be finite"),
    ({"tol": 0}, ValueError, "^tol must be positive"),
    ({"max_depth": 13}, ValueError, "^max_depth must be <= 12"),
    ({"max_depth": 1.5}, TypeError, "^max_depth must be an integer"),
])
def test_intersect_patches_bad_input(kwargs, error, match):
    args = {"a": _paraboloid(2), "b": _plane(0.5), **kwargs}
    with pytest.raises(error, match=match):
        bezier.intersect_patches(**args)


def _cycles(n, pairs):
    """Connected components of the graph (n vertices, edges pairs) and the vertex degrees."""
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i, j in pairs:
        parent[find(i)] = find(j)
    return len({find(i) for i in range(n)}), np.bincount(np.ravel(pairs), minlength=n)


@pytest.mark.parametrize("c", [0.25, 0.5, 0.81])
def test_intersect_patches_segments_close_the_circle(c):
    points, params, pairs = bezier.intersect_patches(_paraboloid(3), _plane(c), tol=0.02, segments=True)
    components, degree = _cycles(len(points), pairs)
    assert components == 1 and np.all(degree == 2)          # one closed loop through every sample
    # each drawn chord of the circle is short, so the polyline stays near the circle
    chord = np.linalg.norm(points[pairs[:, 0]] - points[pairs[:, 1]], axis=1)
    assert chord.max() < 0.25
    p2, x2 = bezier.intersect_patches(_paraboloid(3), _plane(c), tol=0.02)
    np.testing.assert_array_equal(p2, points)


def test_intersect_patches_segments_of_the_planes_are_one_path():
    floor = np.array([[[0.0, 0, 0], [0, 2, 0]], [[2, 0, 0], [2, 2, 0]]])
    ramp = np.array([[[0.0, 0.5, -1], [0, 1.5, -1]], [[2, 0.5, 1], [2, 1.5, 1]]])
    points, params, pairs = bezier.intersect_patches(floor, ramp, segments=True)
    components, degree = _cycles(len(points), pairs)
    assert components == 1 and sorted(degree) == [1, 1] + [2] * (len(points) - 2)
    ends = points[degree == 1]
    np.testing.assert_allclose(ends[np.argsort(ends[:, 1])], [[1, 0.5, 0], [1, 1.5, 0]], atol=1e-12)
    empty = bezier.intersect_patches(floor, ramp + [0, 0, 5], segments=True)
    assert [e.shape for e in empty] == [(0, 3), (0, 4), (0, 2)]


# -- polygon_distance: max |P_k - C(k/n)| (§25.2, §25.4) -------------------------------------------

def test_polygon_distance_of_a_parabola_by_hand_and_by_level():
    # C(t) = (2t, 4t(1-t)) for P = (0,0), (1,2), (2,0): P_1 against C(1/2) = (1, 1) is 1; each uniform
    # subdivision level quarters the second derivative of every piece, so the distance quarters too
    P = [[0, 0], [1, 2], [2, 0]]
    for depth in range(5):
        assert bezier.polygon_distance(bezier.subdivide_uniform(P, depth)) == pytest.approx(4.0 ** -depth, abs=1e-15)


def test_polygon_distance_agrees_with_numpy_polynomial_evaluation():
    from math import comb

    from numpy.polynomial import polynomial as npoly

    rng = np.random.default_rng(5)
    P = rng.uniform(-2, 2, (6, 2))
    n = 5
    # the curve in the power basis, built from the Bernstein expansion independently of the library
    coef = np.zeros((n + 1, 2))
    for j in range(n + 1):
        basis = npoly.polymul(npoly.polypow([0, 1], j), npoly.polypow([1, -1], n - j)) * comb(n, j)
        coef[:len(basis)] += np.outer(basis, P[j])
    on = np.stack([npoly.polyval(np.arange(n + 1) / n, coef[:, i]) for i in range(2)], axis=1)
    assert bezier.polygon_distance(P) == pytest.approx(np.linalg.norm(P - on, axis=1).max(), abs=1e-12)


def test_polygon_distance_edge_cases_and_bad_input():
    assert bezier.polygon_distance([[1.0, 2.0]]) == 0.0                     # degree 0: the point is the curve
    assert bezier.polygon_distance([[0, 0], [3, 4]]) == 0.0                 # a line through its points
    with pytest.raises(ValueError, match="ctrl"):
        bezier.polygon_distance([[0, 0], [np.nan, 1]])
    with pytest.raises(ValueError, match="ctrl"):
        bezier.polygon_distance([1.0, 2.0])


# -- subdivide_patch_uniform and net_distance (§25.3.2) ----------------------------------------------

def _biquadratic_graph():
    """The graph of f(x, y) = x^2 + y^2 over [0, 1]^2 as a biquadratic net: x^2 has Bezier
    coefficients 0, 0, 1 in degree 2, and x = 0, 1/2, 1."""
    g = np.array([0.0, 0.5, 1.0])
    sq = np.array([0.0, 0.0, 1.0])
    X, Y = np.meshgrid(g, g, indexing="ij")
    return np.stack([X, Y, sq[:, None] + sq[None, :]], axis=-1)


def test_subdivided_patch_pieces_are_the_surface_over_their_domains():
    net = _biquadratic_graph()
    nets, domains = bezier.subdivide_patch_uniform(net, 2)
    assert nets.shape == (16, 3, 3, 3) and domains.shape == (16, 4)
    # the domains tile the unit square
    assert np.isclose(((domains[:, 1] - domains[:, 0]) * (domains[:, 3] - domains[:, 2])).sum(), 1.0)
    for sub, (u0, u1, v0, v1) in zip(nets, domains):
        s = np.array([0.0, 0.3, 1.0])
        here = bezier.patch_de_casteljau(sub, s, s[::-1])
        there = bezier.patch_de_casteljau(net, u0 + s * (u1 - u0), v0 + s[::-1] * (v1 - v0))
        np.testing.assert_allclose(here, there, atol=1e-14)


def test_net_distance_of_a_graph_by_hand():
    # only z is off the surface: the middle coefficient 0 of x^2 sits under x(1/2)^2 = 1/4, so the
    # net point (1/2, 1/2, 0) is 1/4 + 1/4 = 1/2 below S(1/2, 1/2); each level of subdivision halves
    # the spacing and quarters the gap
    net = _biquadratic_graph()
    for depth in range(4):
        nets, _ = bezier.subdivide_patch_uniform(net, depth)
        assert bezier.net_distance(nets) == pytest.approx(0.5 * 4.0 ** -depth, abs=1e-14)


def test_patch_subdivision_bad_input():
    with pytest.raises(ValueError, match="depth"):
        bezier.subdivide_patch_uniform(_biquadratic_graph(), 40)
    with pytest.raises(ValueError, match="ctrl"):
        bezier.net_distance([[0.0, 1.0], [1.0, 2.0]])
    with pytest.raises(ValueError, match="ctrl"):
        bezier.net_distance([[[0, 0, np.inf]]])
