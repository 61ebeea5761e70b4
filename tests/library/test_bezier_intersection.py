"""Tangential curve-curve intersection (Goldman §25.3.1): goldman_lib.bezier_intersection.intersect_curves
at tangencies, near-tangencies and contacts within tolerance.

Expected values come from closed forms (parabolas y = +-x^2, a cubic and its tangent line, the
reflection of a parabola arc across one of its tangent lines, symmetric cubic circle arcs) and
from the ``bezier`` package (dhermes/bezier, ``Curve.intersect``); the transversal cases and the
scalar/array agreement are in ``tests/library/test_bezier_subdivision.py``.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest

from goldman_lib import bezier
from goldman_lib import bezier_intersection as bi


def _quadratic_graph(x0, x1, k=1.0, c=0.0):
    """Control points of y = k x^2 + c over [x0, x1], parametrised by x = x0 + s (x1 - x0)."""
    return np.array([[x0, k * x0 * x0 + c], [(x0 + x1) / 2, k * x0 * x1 + c], [x1, k * x1 * x1 + c]])


def _cubic_graph(f, x0, x1):
    """Control points of the cubic graph y = f(x) over [x0, x1] (x linear in s): interpolation in
    the Bernstein basis at s = 0, 1/3, 2/3, 1."""
    s = np.array([0.0, 1 / 3, 2 / 3, 1.0])
    x = x0 + (x1 - x0) * s
    M = np.array([[comb(3, i) * si ** i * (1 - si) ** (3 - i) for i in range(4)] for si in s])
    return np.stack([np.linalg.solve(M, x), np.linalg.solve(M, f(x))], axis=1)


def _circle_arc(center, radius, half_angle, direction):
    """The usual cubic approximation (handles 4/3 tan(theta/4)) of a circle arc of the given half
    angle (degrees) centred on ``direction`` (degrees): symmetric, so its middle point b(1/2) lies
    on the circle with the tangent there perpendicular to the radius."""
    a0, a1 = np.radians(direction - half_angle), np.radians(direction + half_angle)
    k = 4 / 3 * np.tan((a1 - a0) / 4)
    p0, p3 = np.array([np.cos(a0), np.sin(a0)]), np.array([np.cos(a1), np.sin(a1)])
    t0, t3 = np.array([-p0[1], p0[0]]), np.array([-p3[1], p3[0]])
    return np.asarray(center, float) + radius * np.array([p0, p0 + k * t0, p3 - k * t3, p3])


def _reference(a, b):
    """bezier.Curve.intersect, sorted by s (skips the test if the package is absent)."""
    bz = pytest.importorskip("bezier")
    a, b = np.asarray(a, float), np.asarray(b, float)
    ref = bz.Curve(np.asfortranarray(a.T), len(a) - 1).intersect(bz.Curve(np.asfortranarray(b.T), len(b) - 1)).T
    return ref[np.argsort(ref[:, 0])]


def _rotate(P, degrees, shift=(0.0, 0.0)):
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    return np.asarray(P, float) @ np.array([[c, s], [-s, c]]) + np.asarray(shift)


@pytest.mark.parametrize("x0, x1, y0, y1", [(-1, 1, -1, 1), (-1, 1, -0.5, 1.5), (-0.3, 1.1, -0.7, 0.4), (-2, 0.5, -0.25, 3)])
def test_parabolas_touch_once_at_the_vertex(x0, x1, y0, y1):
    # y = x^2 and y = -x^2 meet only at the origin, tangentially: x = 0 at s = -x0 / (x1 - x0)
    a, b = _quadratic_graph(x0, x1), _quadratic_graph(y0, y1, k=-1.0)
    expected = [[-x0 / (x1 - x0), -y0 / (y1 - y0)]]
    got = bezier.intersect_curves(a, b)
    np.testing.assert_allclose(got, expected, atol=1e-8)
    np.testing.assert_allclose(got, _reference(a, b), atol=1e-8)
    # the contact does not depend on where the pair sits (rotation and translation: affine invariance)
    for degrees in (30, 90, 200):
        moved = bezier.intersect_curves(_rotate(a, degrees, (0.3, -2)), _rotate(b, degrees, (0.3, -2)))
        np.testing.assert_allclose(moved, expected, atol=1e-8)


def test_parabola_arc_and_its_reflection_across_a_tangent_line():
    # a parabola arc lies on one side of each of its tangent lines; its mirror image across the
    # tangent at a(s0) lies on the other side, so the two meet once, tangentially, at (s0, s0)
    rng = np.random.default_rng(5)
    for _ in range(40):
        a = rng.uniform(-1, 1, (3, 2))
        s0 = rng.uniform(0.05, 0.95)
        point = (1 - s0) ** 2 * a[0] + 2 * s0 * (1 - s0) * a[1] + s0 ** 2 * a[2]
        tangent = (1 - s0) * (a[1] - a[0]) + s0 * (a[2] - a[1])
        n = np.array([-tangent[1], tangent[0]]) / np.hypot(*tangent)
        b = a - 2 * ((a - point) @ n)[:, None] * n
        got = bezier.intersect_curves(a, b)
        np.testing.assert_allclose(got, [[s0, s0]], atol=1e-8)
        np.testing.assert_allclose(got, _reference(a, b), atol=1e-8)


@pytest.mark.parametrize("c", [0.3, 0.2, -0.4, 0.45])
def test_cubic_and_its_tangent_line(c):
    # y = x^3 - x and its tangent at x = c: x^3 - x - (f(c) + f'(c)(x - c)) = (x - c)^2 (x + 2c),
    # a tangential contact at x = c and a crossing at x = -2c; both curves run over x in [-1, 1]
    def f(x):
        return x ** 3 - x

    def line(x):
        return f(c) + (3 * c * c - 1) * (x - c)

    cubic = _cubic_graph(f, -1.0, 1.0)
    tangent = np.array([[-1.0, line(-1.0)], [1.0, line(1.0)]])
    got = bezier.intersect_curves(cubic, tangent)
    expected = np.array(sorted([[(c + 1) / 2] * 2, [(1 - 2 * c) / 2] * 2]))
    assert got.shape == (2, 2), got
    np.testing.assert_allclose(got, expected, atol=1e-8)
    crossing = int(np.argmin(np.abs(expected[:, 0] - (1 - 2 * c) / 2)))
    np.testing.assert_allclose(got[crossing], expected[crossing], atol=1e-12)     # the transversal one exactly
    np.testing.assert_allclose(got, _reference(cubic, tangent), atol=1e-8)


@pytest.mark.parametrize("degrees", [0, 37, 150])
def test_circle_arcs_touching(degrees):
    # unit circle round the origin and its cubic arc round (1, 0); touching it from outside: the
    # unit circle round (2, 0); from inside: the circle of radius 2 round (-1, 0).  By symmetry every
    # arc passes through (1, 0) at t = 1/2 with a vertical tangent: one contact at (1/2, 1/2)
    a = _circle_arc((0, 0), 1, 45, 0)
    for b in (_circle_arc((2, 0), 1, 45, 180), _circle_arc((2, 0), 1, 20, 180), _circle_arc((-1, 0), 2, 30, 0)):
        ra, rb = _rotate(a, degrees, (1, 2)), _rotate(b, degrees, (1, 2))
        got = bezier.intersect_curves(ra, rb)
        np.testing.assert_allclose(got, [[0.5, 0.5]], atol=1e-7)
        np.testing.assert_allclose(got, _reference(ra, rb), atol=1e-7)


@pytest.mark.parametrize("eps", [1e-4, 1e-6, 1e-8])
def test_near_tangent_crossings_close_together_are_both_found(eps):
    # y = x^2 against the line y = eps and against the parabola y = 2 eps - x^2: crossings at
    # x = -+sqrt(eps), 2 sqrt(eps) apart, both over x in [-1, 1] (s = t = (x + 1) / 2)
    r = np.sqrt(eps)
    expected = [[(1 - r) / 2] * 2, [(1 + r) / 2] * 2]
    a = _quadratic_graph(-1, 1)
    for b in (np.array([[-1, eps], [1, eps]]), _quadratic_graph(-1, 1, k=-1.0, c=2 * eps)):
        got = bezier.intersect_curves(a, b)
        assert got.shape == (2, 2), got
        np.testing.assert_allclose(got, expected, atol=1e-10)
        np.testing.assert_allclose(got, _reference(a, b), atol=1e-9)


@pytest.mark.parametrize("eps", [1e-12, 1e-13, 0.0])
def test_contact_within_tolerance_is_one_point(eps):
    # the same pairs with eps below the tolerance (1e-10): the two crossings, sqrt(eps) from the
    # vertex, are where the curves stay within tol of each other -- one contact, near s = t = 1/2
    a = _quadratic_graph(-1, 1)
    for b in (np.array([[-1, eps], [1, eps]]), _quadratic_graph(-1, 1, k=-1.0, c=2 * eps)):
        got = bezier.intersect_curves(a, b)
        assert got.shape == (1, 2), got
        np.testing.assert_allclose(got, [[0.5, 0.5]], atol=max(np.sqrt(eps), 1e-8))


@pytest.mark.parametrize("gap", [1e-6, 1e-3, 0.1])
def test_parabolas_just_apart_do_not_meet(gap):
    # y = x^2 and y = -x^2 - gap are gap apart at the vertex and farther elsewhere
    got = bezier.intersect_curves(_quadratic_graph(-1, 1), _quadratic_graph(-1, 1, k=-1.0, c=-gap))
    assert got.shape == (0, 2)


def test_a_tangential_contact_settles_its_pair_without_subdividing():
    """The chords of the two parabolas are parallel and the arcs bend apart (one convex, one concave
    over a common direction), so Newton's method is tried on the whole pair at once; its tangential
    contact ends the search there: one Newton run, no halving (the benchmark's tangential pair)."""
    a, b = [[0, 0], [0.5, 1], [1, 0]], [[0, 1], [0.5, 0], [1, 1]]
    runs, halvings = [], []
    newton, halves = bi._newton_small, bi._Piece.halves

    def counting_newton(*args, **kwargs):
        runs.append(args[2:4])
        return newton(*args, **kwargs)

    def counting_halves(self):
        halvings.append(self)
        return halves(self)

    try:
        bi._newton_small, bi._Piece.halves = counting_newton, counting_halves
        got = bezier.intersect_curves(a, b)
    finally:
        bi._newton_small, bi._Piece.halves = newton, halves
    np.testing.assert_allclose(got, [[0.5, 0.5]], atol=1e-12)
    assert len(runs) == 1 and not halvings


def test_may_touch_needs_opposite_bending_and_common_slopes():
    P = bi._Piece
    cap = P((0.0, 0.5, 1.0), (0.0, 1.0, 0.0), 0.0, 1.0)         # concave over x
    cup = P((0.0, 0.5, 1.0), (1.0, 0.0, 1.0), 0.0, 1.0)         # convex over x
    higher_cap = P((0.0, 0.5, 1.0), (1.0, 2.0, 1.0), 0.0, 1.0)
    line = P((0.0, 1.0), (0.5, 0.5), 0.0, 1.0)
    flat_cap = P((0.0, 0.5, 1.0), (0.0, 0.1, 0.0), 0.0, 1.0)   # slopes within +-0.2
    rising = P((0.0, 1.0), (0.0, 1.0), 0.0, 1.0)                # slope 1
    s_curve = P((0.0, 0.3, 0.7, 1.0), (0.0, 1.0, -1.0, 0.0), 0.0, 1.0)   # inflection: turns both ways
    assert bi._may_touch(cap, cup) and bi._may_touch(cup, cap)
    assert bi._may_touch(cap, line) and bi._may_touch(line, cup)
    assert bi._may_touch(P((1.0, 0.5, 0.0), (1.0, 0.0, 1.0), 0.0, 1.0), cap)   # the cup run backwards
    assert not bi._may_touch(cap, higher_cap)                   # both concave: f - g neither convex nor concave
    assert not bi._may_touch(s_curve, line)
    assert not bi._may_touch(flat_cap, rising)                  # the slopes never agree: no tangency


NEAR_TANGENT_PAIRS = [
    # a parabola arc against its mirror image across a tangent line, nudged: two crossings a few
    # 1e-4 to 1e-3 apart in parameter, both distinct (the curves part by more than tol between them)
    ([[0.087252158, 0.124659212], [0.735076899, -0.984489902], [-0.86703424, 0.564641087]],
     [[0.516641252, 0.09493112], [-0.27785106, -0.91436123], [1.522454555, 0.399208586]]),
    ([[0.559493648, 0.175837799], [0.93836753, -0.201627526], [0.794196276, 0.003809856]],
     [[1.064957156, -0.351467899], [0.703847846, 0.043026157], [0.903005974, -0.109701995]]),
    ([[-0.450664991, 0.933598927], [0.674675147, -0.741877365], [0.691779731, -0.357794835]],
     [[0.171176272, -2.115142031], [0.550421198, -0.132777326], [0.716606917, -0.479469529]]),
    # a cubic and a line close to one of its tangents
    ([[-0.305093148, 0.296558163], [0.488721742, -0.787461004], [0.689867492, 0.32558751], [-0.893802078, -0.494662344]],
     [[0.289987555, -0.347997477], [0.308521239, -0.02687187]]),
]


@pytest.mark.parametrize("a, b", NEAR_TANGENT_PAIRS)
def test_near_tangent_pairs_against_the_bezier_package(a, b):
    got = bezier.intersect_curves(a, b)
    ref = _reference(a, b)
    assert got.shape == ref.shape == (2, 2), (got, ref)
    np.testing.assert_allclose(got, ref, atol=1e-9)
    points_a, points_b = bezier.de_casteljau(a, got[:, 0]), bezier.de_casteljau(b, got[:, 1])
    assert np.abs(points_a - points_b).max() < 1e-12
    halfway = (got[0] + got[1]) / 2                            # two crossings, not one contact
    assert np.abs(bezier.de_casteljau(a, halfway[:1]) - bezier.de_casteljau(b, halfway[1:])).max() > 1e-9


def test_fat_line_apart():
    P = bi._Piece
    cap = P((0.0, 0.5, 1.0), (0.0, 1.0, 0.0), 0.0, 1.0)          # fat line: 0 <= y <= 1 (control points)
    below = P((0.0, 1.0), (-0.1, -0.2), 0.0, 1.0)
    crossing = P((0.0, 1.0), (-0.1, 0.2), 0.0, 1.0)
    inside = P((0.2, 0.8), (0.9, 0.9), 0.0, 1.0)              # within the fat line, above the curve itself
    assert bi._fat_line_apart(cap, below, 1e-12)
    assert not bi._fat_line_apart(cap, crossing, 1e-12)
    assert not bi._fat_line_apart(cap, inside, 1e-12)          # the test is conservative
    assert not bi._fat_line_apart(cap, below, 0.2)             # within the padding


@pytest.mark.parametrize("a, b, kwargs, error, match", [
    (np.array([[0, np.nan], [1, 2.0]]), np.array([[0, 0.75], [2, 0.75]]), {}, ValueError, r"a must be finite; a\[0, 1\] is nan"),
    (np.array([[0, 0], [1, 2.0]]), np.array([[0, 1], [1, np.inf]]), {}, ValueError, r"b must be finite; b\[1, 1\] is inf"),
    (np.array([[0, 0], [1, 2e200]]), np.array([[0, 1], [1, 0.0]]), {}, ValueError, "a is too large in magnitude"),
    (np.array([[0, 0], [1, 2.0]]), np.array([[0, 1], [1, 0.0]]), {"tol": float("nan")}, ValueError, "tol must be finite"),
    (np.array([[0, 0], [1, 2.0]]), np.array([[0, 1], [1, 0.0]]), {"tol": 0.0}, ValueError, "tol must be positive"),
    (np.array([[0, 0], [1, 2.0]]), np.array([[0, 1], [1, 0.0]]), {"max_depth": True}, TypeError, "max_depth must be an integer"),
    (np.array([[0, 0], [1, 2.0]]), np.array([[0, 1], [1, 0.0]]), {"max_depth": 61}, ValueError, "max_depth must be <= 60"),
])
def test_float_arrays_are_checked_like_any_input(a, b, kwargs, error, match):
    """Small float64 arrays skip numpy's checks for the same checks on plain floats; a bad one
    still gets the general message naming the parameter."""
    with pytest.raises(error, match=match):
        bezier.intersect_curves(a, b, **kwargs)


def test_float_arrays_and_lists_give_the_same_answer():
    rng = np.random.default_rng(12)
    for _ in range(20):
        a, b = rng.uniform(0, 1, (4, 2)), rng.uniform(0, 1, (3, 2))
        fast = bezier.intersect_curves(a, b)
        np.testing.assert_array_equal(fast, bezier.intersect_curves(a.tolist(), b.tolist()))
        np.testing.assert_array_equal(fast, bezier.intersect_curves(a, b, tol=np.float64(1e-10), max_depth=np.int64(40)))


def test_a_cubic_pieces_box_and_flatness_written_out_are_the_loops_bit_for_bit():
    """_Piece writes out a cubic's bounding box and even flatness (the scalar path's hot spots);
    they must be min/max and the loop max_k |P_k - ((1 - k/n) P_0 + (k/n) P_n)| exactly (so every
    pruning decision, and every answer, is what it was), and agree with polygons.flatness."""
    from goldman_lib.kernels import polygons
    rng = np.random.default_rng(7)
    for _ in range(2000):
        P = rng.normal(size=(4, 2)) * 10.0 ** rng.integers(-6, 6)
        if rng.random() < 0.2:
            P[rng.integers(0, 4)] = P[rng.integers(0, 4)]          # repeated points, ties in the box
        xs, ys = tuple(P[:, 0].tolist()), tuple(P[:, 1].tolist())
        piece = bi._Piece(xs, ys, 0.0, 1.0)
        assert (piece.x0, piece.x1, piece.y0, piece.y1) == (min(xs), max(xs), min(ys), max(ys))
        f = 0.0
        for k in range(1, 3):
            w = k / 3
            dx = xs[k] - ((1.0 - w) * xs[0] + w * xs[3])
            dy = ys[k] - ((1.0 - w) * ys[0] + w * ys[3])
            f = max(f, dx * dx + dy * dy)
        assert piece.flat() == f ** 0.5
        assert abs(piece.flat() - float(polygons.flatness(P))) <= 1e-15 * max(1.0, np.abs(P).max())
