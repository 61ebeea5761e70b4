"""Vector geometry (Goldman ch 11) against closed forms worked by hand, numpy.linalg.solve and
matplotlib's Path.contains_points."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from matplotlib.path import Path

from goldman_lib import vector_geometry as vg

finite = st.floats(-50, 50, allow_nan=False)
vec3 = st.tuples(finite, finite, finite).map(np.array)


def test_triangle_laws_by_hand():
    assert np.isclose(vg.law_of_cosines(3, 4, 90), 5)
    assert np.isclose(vg.law_of_cosines(1, 1, 60), 1)           # equilateral
    assert np.isclose(vg.law_of_sines(1, 30, 90), 2)            # 30-60-90 triangle: hypotenuse 2
    with pytest.raises(ValueError, match="alpha \\+ beta must be < 180"):
        vg.law_of_sines(1, 100, 90)


def test_distances_by_hand():
    assert vg.point_line_distance([3, 4, 0], [0, 0, 0], [0, 0, 5]) == 5.0
    assert np.isclose(vg.point_line_distance([0, 2], [0, 0], [1, 1]), np.sqrt(2))
    assert vg.point_plane_distance([1, 2, -3], [0, 0, 1], [0, 0, -7]) == 4.0
    # the x axis and the line through (0, 0, 3) along y are 3 apart; parallel lines 2 apart
    assert vg.line_line_distance([0, 0, 0], [1, 0, 0], [5, -1, 3], [0, 1, 0]) == 3.0
    assert vg.line_line_distance([0, 0, 0], [1, 1, 0], [0, 0, 2], [2, 2, 0]) == 2.0
    with pytest.raises(ValueError, match="d2 must be nonzero"):
        vg.line_line_distance([0, 0, 0], [1, 0, 0], [0, 0, 1], [0, 0, 0])


@settings(max_examples=60, deadline=None)
@given(vec3, vec3, vec3, vec3)
def test_skew_line_distance_equals_the_closest_points(p1, d1, p2, d2):
    c = np.cross(d1, d2)
    if np.linalg.norm(c) < 1e-2 * (1 + np.linalg.norm(d1) * np.linalg.norm(d2)):
        return
    A, B, dist = vg.intersect_lines(p1, d1, p2, d2)
    assert np.isclose(dist, vg.line_line_distance(p1, d1, p2, d2), rtol=1e-6, atol=1e-6)
    # the segment AB is perpendicular to both lines
    assert abs(np.dot(B - A, d1)) <= 1e-6 * (1 + np.linalg.norm(B - A) * np.linalg.norm(d1))
    assert abs(np.dot(B - A, d2)) <= 1e-6 * (1 + np.linalg.norm(B - A) * np.linalg.norm(d2))


def test_areas_and_volumes_by_hand():
    assert vg.triangle_area([0, 0], [4, 0], [0, 3]) == 6.0
    assert vg.triangle_area([0, 0, 0], [0, 4, 0], [0, 0, 3]) == 6.0
    L = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [0, 3]]  # an L of area 4 + 2
    assert vg.polygon_area(L) == 6.0
    tilted = np.array([[0, 0, 0], [2, 0, 0], [2, 3, 3], [0, 3, 3]])  # a 2 x 3√2 rectangle
    assert np.isclose(vg.polygon_area(tilted), 6 * np.sqrt(2))
    assert np.isclose(vg.tetrahedron_volume([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]), 1 / 6)
    assert vg.parallelepiped_volume([2, 0, 0], [1, 3, 0], [5, 5, 4]) == 24.0
    with pytest.raises(ValueError, match="at least three distinct vertices"):
        vg.polygon_area([[0, 0], [1, 1]])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.5, 3), min_size=3, max_size=12), vec3, vec3)
def test_newell_normal_equals_the_cross_product_normal_of_a_planar_polygon(radii, u, v):
    if np.linalg.norm(np.cross(u, v)) < 1e-2 * (1 + np.linalg.norm(u) * np.linalg.norm(v)):
        return
    ang = np.linspace(0, 2 * np.pi, len(radii), endpoint=False)
    planar = np.outer(np.array(radii) * np.cos(ang), u) + np.outer(np.array(radii) * np.sin(ang), v)
    N = vg.newell_normal(planar)
    c = np.cross(u, v)
    # a star-shaped polygon around the origin, counterclockwise in the (u, v) frame: N is along u x v
    assert np.allclose(np.cross(N, c), 0, atol=1e-6 * np.linalg.norm(N) * np.linalg.norm(c))
    assert np.dot(N, c) > 0
    area2d = vg.polygon_area(np.stack([np.array(radii) * np.cos(ang), np.array(radii) * np.sin(ang)], 1))
    assert np.isclose(np.linalg.norm(N) / 2, area2d * np.linalg.norm(c), rtol=1e-6)


def test_plane_intersections_against_numpy_solve():
    rng = np.random.default_rng(11)
    for _ in range(50):
        P, N = rng.normal(size=(3, 3)), rng.normal(size=(3, 3))
        X = vg.intersect_three_planes(*zip(P, N))
        ref = np.linalg.solve(N, np.einsum("ij,ij->i", N, P))
        assert np.allclose(X, ref, atol=1e-8 * (1 + np.abs(ref).max()))
    point, direction = vg.intersect_two_planes(([0, 0, 1], [0, 0, 1]), ([2, 0, 0], [1, 0, 0]))
    assert point.tolist() == [2, 0, 1] and direction.tolist() == [0, 1, 0]
    with pytest.raises(ValueError, match="must not be parallel"):
        vg.intersect_two_planes(([0, 0, 0], [0, 0, 1]), ([0, 0, 5], [0, 0, -2]))
    with pytest.raises(ValueError, match="normals must be independent"):
        vg.intersect_three_planes(([0, 0, 0], [1, 0, 0]), ([0, 0, 0], [0, 1, 0]), ([0, 0, 0], [1, 1, 0]))


def test_slerp_moves_at_constant_angular_speed():
    v = vg.slerp([1, 0, 0], [0, 0, 1], np.linspace(0, 1, 7))
    ang = np.degrees(np.arctan2(v[:, 2], v[:, 0]))
    assert np.allclose(ang, np.linspace(0, 90, 7)) and np.allclose(np.linalg.norm(v, axis=1), 1)
    with pytest.raises(ValueError, match="opposite directions"):
        vg.slerp([1, 0], [-1, 0], 0.5)


def test_slerp_of_equal_lengths_stays_on_their_sphere_and_refuses_unequal_lengths():
    # equal lengths r = 3: on the circle of radius 3, at the angle t * 90 degrees (closed form, arctan2)
    v = vg.slerp([3, 0, 0], [0, 0, 3], np.linspace(0, 1, 7))
    assert np.allclose(np.linalg.norm(v, axis=1), 3)
    assert np.allclose(np.degrees(np.arctan2(v[:, 2], v[:, 0])), np.linspace(0, 90, 7))
    # different lengths: the sine weights would give points on no sphere; refused, naming the rule and lengths
    with pytest.raises(ValueError, match=r"same length.*\|v0\| = 1 and \|v1\| = 2"):
        vg.slerp([1, 0, 0], [0, 2, 0], 0.5)
    with pytest.raises(ValueError, match=r"same length.*at index 1"):
        vg.slerp([[1, 0], [1, 0]], [[0, 1], [0, 1.5]], 0.5)
    vg.slerp([1, 0], [0, 1 + 1e-12], 0.5)      # rounding-level differences are accepted


def _angle_sum_winding(poly, q):
    """An independent reference: the total turning of the vectors from q to the vertices / 2π."""
    d = np.asarray(poly, float) - q
    a = np.arctan2(d[:, 1], d[:, 0])
    turn = np.diff(np.append(a, a[0]))
    turn = (turn + np.pi) % (2 * np.pi) - np.pi
    return int(round(turn.sum() / (2 * np.pi)))


def test_winding_numbers_by_hand_and_against_angle_sums():
    star = [[0, 3], [-1.76, -2.43], [2.85, 0.93], [-2.85, 0.93], [1.76, -2.43]]
    assert vg.winding_number(star, [[0, 0], [0, 2.4], [5, 5]]).tolist() == [2, 1, 0]
    assert vg.winding_number(star[::-1], [[0, 0]]).tolist() == [-2]
    assert vg.ray_casting_inside(star, [[0, 0], [0, 2.4]]).tolist() == [False, True]   # even-odd: the centre is out
    rng = np.random.default_rng(5)
    for _ in range(20):
        poly = rng.normal(size=(int(rng.integers(3, 12)), 2)) * 3   # self-intersecting in general
        pts = rng.uniform(-6, 6, size=(300, 2))
        got = vg.winding_number(poly, pts)
        assert got.dtype.kind == "i"
        assert got.tolist() == [_angle_sum_winding(poly, q) for q in pts]


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(0.3, 3), min_size=3, max_size=20), st.integers(0, 2**32 - 1))
def test_inside_tests_agree_with_matplotlib_on_simple_polygons(radii, seed):
    ang = np.linspace(0, 2 * np.pi, len(radii), endpoint=False)
    poly = np.stack([np.array(radii) * np.cos(ang), np.array(radii) * np.sin(ang)], 1)
    pts = np.random.default_rng(seed).uniform(-3.5, 3.5, size=(500, 2))
    ref = Path(poly).contains_points(pts)
    ours = vg.winding_number(poly, pts) != 0
    # points within 1e-9 of an edge may go either way
    assert np.array_equal(ours, ref) and np.array_equal(vg.ray_casting_inside(poly, pts), ours)


# -- additions for the chapter-11 notebook and views: foot_on_plane, nlerp, ray_crossings ----------------

def test_foot_on_plane_by_hand_and_as_the_closest_point():
    # plane z = 1 (normal (0, 0, 5), not unit): the foot drops the z coordinate to 1
    assert vg.foot_on_plane([3, -2, 7], [0, 0, 1], [0, 0, 5]).tolist() == [3.0, -2.0, 1.0]
    # plane x + y + z = 3 through (1, 1, 1): the foot of the origin is (1, 1, 1)
    assert np.allclose(vg.foot_on_plane([0, 0, 0], [3, 0, 0], [1, 1, 1]), [1, 1, 1])
    rng = np.random.default_rng(11)
    Q, P, N = rng.normal(size=(20, 3)), rng.normal(size=3), rng.normal(size=3)
    F = vg.foot_on_plane(Q, P, N)
    assert np.allclose((F - P) @ N, 0, atol=1e-12)                                   # on the plane
    assert np.allclose(np.linalg.norm(Q - F, axis=1), vg.point_plane_distance(Q, P, N))
    assert np.allclose(np.cross(Q - F, N), 0, atol=1e-12)                            # along the normal
    with pytest.raises(ValueError, match="normal must be nonzero"):
        vg.foot_on_plane([1, 2, 3], [0, 0, 0], [0, 0, 0])


def test_nlerp_is_on_the_arc_but_not_at_constant_speed():
    # v0 = x, v1 = y, t = 1/4: the chord point (3/4, 1/4) normalised is at atan(1/3), not 22.5 degrees
    w = vg.nlerp([1, 0], [0, 1], 0.25)
    assert np.allclose(w, np.array([3, 1]) / np.sqrt(10))
    assert not np.isclose(np.degrees(np.arctan2(w[1], w[0])), 22.5)
    ts = np.linspace(0, 1, 9)
    assert np.allclose(np.linalg.norm(vg.nlerp([1, 0, 0], [0, 0, 1], ts), axis=1), 1)
    assert np.allclose(vg.nlerp([1, 0], [0, 1], [0.0, 0.5, 1.0]), vg.slerp([1, 0], [0, 1], [0.0, 0.5, 1.0]))
    with pytest.raises(ValueError, match="opposite"):
        vg.nlerp([1, 0], [-1, 0], 0.5)


def test_ray_crossings_by_hand_and_summing_to_the_winding_number():
    # the square (0,0)-(4,4) from (1, 1): only the right side x = 4 is crossed, going up
    pts, signs = vg.ray_crossings([[0, 0], [4, 0], [4, 4], [0, 4]], [1, 1])
    assert pts.tolist() == [[4.0, 1.0]] and signs.tolist() == [1]
    # the doubled square of exercise 6: from (3, 3) the edges x = 5 and x = 6, both going up
    double = [[0, 0], [6, 0], [6, 6], [1, 6], [1, 1], [5, 1], [5, 5], [0, 5]]
    pts, signs = vg.ray_crossings(double, [3, 3])
    assert pts.tolist() == [[5.0, 3.0], [6.0, 3.0]] and signs.tolist() == [1, 1]
    # from (0.5, 3): x = 1 going down first, then x = 5 and x = 6 going up
    assert vg.ray_crossings(double, [0.5, 3])[1].tolist() == [-1, 1, 1]
    rng = np.random.default_rng(3)
    for _ in range(10):
        poly = rng.normal(size=(int(rng.integers(3, 10)), 2)) * 3
        for q in rng.uniform(-5, 5, size=(30, 2)):
            pts, signs = vg.ray_crossings(poly, q)
            assert int(signs.sum()) == _angle_sum_winding(poly, q)
            assert bool(len(signs) % 2) == bool(vg.ray_casting_inside(poly, q))
            assert np.all(pts[:, 0] > q[0]) and np.all(np.diff(pts[:, 0]) >= 0)
