"""Points and vectors (Goldman ch 9-10): the type rules, and the products against numpy and the
coordinate-free definitions."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from goldman_lib import vectors as vc
from goldman_lib.vectors import Point, Vector

finite = st.floats(-100, 100, allow_nan=False)
vec3 = st.lists(finite, min_size=3, max_size=3)


def test_the_type_rules():
    P, Q, v = Point([1, 2, 3]), Point([0, 0, 1]), Vector([1, 1, 1])
    assert isinstance(P - Q, Vector) and (P - Q) == Vector([1, 2, 2])
    assert isinstance(P + v, Point) and isinstance(v + P, Point) and isinstance(P - v, Point)
    assert isinstance(v + v, Vector) and isinstance(3 * v, Vector) and isinstance(v / 2, Vector)
    for illegal in (lambda: P + Q, lambda: 2 * P, lambda: P * 2, lambda: -P, lambda: v - P, lambda: v * v):
        with pytest.raises(TypeError):
            illegal()
    with pytest.raises(TypeError, match="dot takes vectors"):
        vc.dot(P, v)
    with pytest.raises(ValueError, match="cannot combine a 3D point with a 2D vector"):
        P + Vector([1, 1])


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(finite, finite), min_size=2, max_size=6), st.data())
def test_affine_combinations_do_not_depend_on_the_origin(pts, data):
    pts = np.array(pts)
    w = np.array(data.draw(st.lists(st.floats(-3, 3), min_size=len(pts), max_size=len(pts))))
    w = np.append(w[:-1], 1 - w[:-1].sum())
    shift = np.array([17.5, -4.25])
    a = vc.affine_combination(pts, w).coords
    b = vc.affine_combination(pts + shift, w).coords - shift
    assert np.allclose(a, b, atol=1e-6)
    assert np.allclose(a, w @ pts, atol=1e-6)


def test_affine_combination_refuses_weights_not_summing_to_one():
    with pytest.raises(ValueError, match="weights must sum to 1"):
        vc.affine_combination([[0, 0], [1, 1]], [0.5, 0.6])
    with pytest.raises(TypeError, match="points must be points, not vectors"):
        vc.affine_combination([Vector([0, 0]), Vector([1, 1])], [0.5, 0.5])
    assert vc.affine_combination([Point([0, 0]), Point([2, 4])], [0.5, 0.5]) == Point([1, 2])


@settings(max_examples=80, deadline=None)
@given(vec3, vec3, vec3)
def test_products_against_numpy_and_the_coordinate_free_definitions(u, v, w):
    u, v, w = map(np.array, (u, v, w))
    assert np.isclose(vc.dot(u, v), np.dot(u, v), rtol=1e-9, atol=1e-6)
    assert np.isclose(vc.dot_from_lengths(u, v), np.dot(u, v), rtol=1e-6, atol=1e-6 * (1 + np.abs(u).max() * np.abs(v).max()))
    assert np.allclose(vc.cross(u, v), np.cross(u, v), atol=1e-9)
    with np.errstate(all="ignore"):
        reference = np.linalg.det(np.stack([u, v, w]))
    assert np.isclose(vc.det(u, v, w), reference, rtol=1e-6, atol=1e-3)
    c = np.cross(u, v)
    if np.linalg.norm(c) > 1e-3 * (1 + np.linalg.norm(u) * np.linalg.norm(v)):
        normal = c + 0.3 * u - 0.2 * v   # any vector on the right-handed side
        assert np.allclose(vc.cross_from_geometry(u, v, normal), c, rtol=1e-6, atol=1e-6 * (1 + np.linalg.norm(c)))
    # Appendix A: the associator equals (u.v) w - (v.w) u
    assert np.allclose(vc.cross_associator(u, v, w), np.dot(u, v) * w - np.dot(v, w) * u, rtol=1e-6, atol=1e-3)


def test_products_vectorise_over_leading_axes():
    rng = np.random.default_rng(3)
    u, v, w = rng.normal(size=(3, 5, 4, 3))
    assert vc.dot(u, v).shape == (5, 4) and vc.cross(u, v).shape == (5, 4, 3) and vc.det(u, v, w).shape == (5, 4)
    assert np.allclose(vc.det(u, v, w), np.linalg.det(np.stack([u, v, w], axis=-2)))


def test_cross_product_is_not_associative_by_hand():
    i, j = [1, 0, 0], [0, 1, 0]
    # (i x i) x j = 0, i x (i x j) = i x k = -j
    assert vc.cross_associator(i, i, j).tolist() == [0, 1, 0]


def test_angles_and_lengths_by_hand():
    assert vc.length([3, 4]) == 5.0
    assert np.isclose(vc.angle_between([1, 0, 0], [-1, 1e-9, 0]), 180, atol=1e-6)
    assert np.isclose(vc.angle_between([1, 0], [0, 2]), 90)
    with pytest.raises(ValueError, match="u and v must be nonzero"):
        vc.angle_between([0, 0, 0], [1, 0, 0])
    with pytest.raises(TypeError, match="a point has no length"):
        vc.length(Point([1, 1]))


def test_combination_kind_by_the_sum_of_the_weights():
    assert vc.combination_kind([0.5, 0.5]) == "point"       # the midpoint
    assert vc.combination_kind([2, -1]) == "point"          # 2P - Q = P + (P - Q)
    assert vc.combination_kind([1, -1]) == "vector"         # P - Q
    assert vc.combination_kind([3, -2, -1]) == "vector"
    assert vc.combination_kind([1, 1]) == "undefined"       # P + Q
    with pytest.raises(ValueError, match="weights must be a non-empty 1D"):
        vc.combination_kind([])


def test_weighted_sum_from_origin_moves_with_the_origin_unless_affine():
    pts = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 2.0]])
    # by hand: weights (1, 1, 1) from the origin (1, 1): (1, 1) + (-1, -1) + (3, -1) + (-1, 1) = (2, 0)
    assert vc.weighted_sum_from_origin(pts, [1, 1, 1], [1, 1]).tolist() == [2.0, 0.0]
    # from (0, 0) the same weights give the coordinate sum (4, 2): the location moved
    assert vc.weighted_sum_from_origin(pts, [1, 1, 1], [0, 0]).tolist() == [4.0, 2.0]
    # weights (0.5, 0.25, 0.25) sum to 1: (1, 0.5) from every origin
    origins = np.array([[0.0, 0.0], [1.0, 1.0], [-7.0, 3.5]])
    assert np.allclose(vc.weighted_sum_from_origin(pts, [0.5, 0.25, 0.25], origins), [[1.0, 0.5]] * 3)
    # in general the location moves by (1 - sum w) times the move of the origin
    w = np.array([0.7, 0.9, -0.1])
    a, b = vc.weighted_sum_from_origin(pts, w, origins[:2])
    assert np.allclose(b - a, (1 - w.sum()) * (origins[1] - origins[0]))
    with pytest.raises(ValueError, match="one entry per point"):
        vc.weighted_sum_from_origin(pts, [1, 0], [0, 0])


def test_det_cofactor_terms_by_hand_and_against_numpy():
    # rows (2, 1, 3), (1, -1, 2), (4, 0, 1): 2(-1 - 0) - 1(1 - 8) + 3(0 + 4) = -2 + 7 + 12 = 17
    terms = vc.det_cofactor_terms([2, 1, 3], [1, -1, 2], [4, 0, 1])
    assert terms.tolist() == [-2.0, 7.0, 12.0]
    rng = np.random.default_rng(11)
    u, v, w = rng.normal(size=(3, 20, 3))
    assert np.allclose(vc.det_cofactor_terms(u, v, w).sum(-1), np.linalg.det(np.stack([u, v, w], axis=-2)))
