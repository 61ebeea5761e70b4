"""Chapter 4, affine transformations: every map against a closed form written here, the algebra of
§4.3 (composition laws) and the geometry of §4.4 as hypothesis properties, inverses against
numpy.linalg, and ``affine_from_points`` round trips on random non-collinear triangles."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from goldman_lib import affine

SETTINGS = settings(max_examples=60, deadline=None)
coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord).map(np.array)
angle = st.floats(-720, 720, allow_nan=False, allow_infinity=False)
factor = st.floats(0.1, 5, allow_nan=False).flatmap(lambda s: st.sampled_from([s, -s]))
SQ3 = math.sqrt(3)
R2 = math.sqrt(2) / 2


def area2(tri):
    u, v = tri[1] - tri[0], tri[2] - tri[0]
    return u[0] * v[1] - u[1] * v[0]


triangle = st.tuples(point, point, point).map(np.array).filter(lambda t: abs(area2(t)) > 0.5)


def random_map(draw_angle, s, t, h):
    return affine.from_parameters(angle=draw_angle, scale=s, shear=h, translate=t)


maps = st.builds(random_map, angle, st.tuples(factor, factor), st.tuples(coord, coord),
                 st.floats(-2, 2, allow_nan=False))


# --- the row-vector convention (§4.5) ------------------------------------------------------------

def test_row_vector_convention_translation_in_last_row():
    M = affine.translation([2, -1])
    np.testing.assert_array_equal(M, [[1, 0, 0], [0, 1, 0], [2, -1, 1]])
    np.testing.assert_array_equal(np.array([1.0, 1.0, 1.0]) @ M, [3, 0, 1])
    np.testing.assert_array_equal(affine.apply([[1, 1]], M), [[3, 0]])


def test_compose_applies_the_first_map_first():
    # rotate (1, 0) by 90 to (0, 1), then translate by (1, 0): (1, 1); the other order gives (0, 2)
    np.testing.assert_allclose(affine.apply([1, 0], affine.compose(affine.rotation(90), affine.translation([1, 0]))),
                               [1, 1], atol=1e-15)
    np.testing.assert_allclose(affine.apply([1, 0], affine.compose(affine.translation([1, 0]), affine.rotation(90))),
                               [0, 2], atol=1e-15)


def test_apply_keeps_shape_and_vectors_ignore_translation():
    P = np.arange(24.0).reshape(3, 4, 2)
    M = affine.rotation(30) @ affine.translation([5, 7])
    assert affine.apply(P, M).shape == (3, 4, 2)
    np.testing.assert_allclose(affine.apply_vectors([[1, 2]], affine.translation([5, 7])), [[1, 2]])
    np.testing.assert_allclose(affine.affine_coordinates([[2, 3]]), [[2, 3, 1]])
    np.testing.assert_allclose(affine.vector_coordinates([[2, 3]]), [[2, 3, 0]])
    np.testing.assert_allclose(affine.affine_coordinates(P) @ M, np.concatenate([affine.apply(P, M),
                                                                                   np.ones((3, 4, 1))], axis=-1))


# --- closed forms of §4.2 and §4.7 ---------------------------------------------------------------

@pytest.mark.parametrize("a, P, expected", [
    (90, [1, 0], [0, 1]), (180, [1, 2], [-1, -2]), (270, [1, 0], [0, -1]), (-90, [0, 1], [1, 0]),
    (30, [1, 0], [SQ3 / 2, 0.5]), (60, [2, 0], [1, SQ3]), (45, [1, 1], [0, math.sqrt(2)]),
    (120, [1, 0], [-0.5, SQ3 / 2]), (360, [3, 4], [3, 4]),
])
def test_rotation_about_origin_closed_forms(a, P, expected):
    np.testing.assert_allclose(affine.apply(P, affine.rotation(a)), expected, atol=1e-15)


def test_rotation_by_multiples_of_90_is_exact():
    np.testing.assert_array_equal(affine.rotation(90)[:2, :2], [[0, 1], [-1, 0]])
    np.testing.assert_array_equal(affine.apply([[2, 1]], affine.rotation(90, center=[1, 1])), [[1, 2]])


@pytest.mark.parametrize("a, Q, P, expected", [
    (90, [1, 1], [3, 1], [1, 3]), (180, [1, 2], [4, 6], [-2, -2]), (45, [1, 1], [2, 1], [1 + R2, 1 + R2]),
    (-90, [2, 0], [2, 3], [5, 0]), (60, [0, 1], [2, 1], [1, 1 + SQ3]),
])
def test_rotation_about_a_point_closed_forms(a, Q, P, expected):
    np.testing.assert_allclose(affine.apply(P, affine.rotation(a, center=Q)), expected, atol=1e-14)


@given(point, point, factor)
@SETTINGS
def test_uniform_scaling_about_a_point(P, Q, s):
    np.testing.assert_allclose(affine.apply(P, affine.scaling(s, center=Q)), Q + s * (P - Q), atol=1e-12)


@given(point, point, factor, st.floats(0, 360, allow_nan=False))
@SETTINGS
def test_nonuniform_scaling_along_a_direction(P, Q, s, theta):
    # write P - Q = a w + b n in the orthonormal frame (w, n); the image is Q + s a w + b n
    w = np.array([math.cos(math.radians(theta)), math.sin(math.radians(theta))])
    n = np.array([-w[1], w[0]])
    a, b = (P - Q) @ w, (P - Q) @ n
    M = affine.directional_scaling(s, 3.7 * w, center=Q)
    np.testing.assert_allclose(affine.apply(P, M), Q + s * a * w + b * n, atol=1e-11)
    vals, vecs = np.linalg.eig(affine.linear_part(M).T)   # column-vector form for numpy
    np.testing.assert_allclose(sorted(vals.real), sorted([s, 1.0]), atol=1e-12)


def test_nonuniform_scaling_axes_and_shear_closed_forms():
    np.testing.assert_allclose(affine.apply([[1, 1]], affine.scaling([2, 3], center=[1, 0])), [[1, 3]])
    np.testing.assert_allclose(affine.apply([[1, 0], [0, 1]], affine.directional_scaling(3, [1, 1])),
                               [[2, 1], [1, 2]], atol=1e-15)
    np.testing.assert_allclose(affine.apply([[1, 2], [3, 0]], affine.shear(0.5)), [[2, 2], [3, 0]])
    np.testing.assert_allclose(affine.apply([[1, 2]], affine.shear(1, center=[0, 1])), [[2, 2]])


def test_mirror_closed_forms_and_properties():
    np.testing.assert_allclose(affine.apply([[1, 2], [5, -3]], affine.mirror([0, 0], [1, 1])), [[2, 1], [-3, 5]],
                               atol=1e-14)
    np.testing.assert_allclose(affine.apply([[3, 5]], affine.mirror([0, 1], [1, 0])), [[3, -3]], atol=1e-14)
    np.testing.assert_allclose(affine.apply([[4, 7]], affine.mirror([2, 0], [0, 3])), [[0, 7]], atol=1e-14)
    M = affine.mirror([1, 2], [3, -1])
    np.testing.assert_allclose(M @ M, np.eye(3), atol=1e-14)
    assert np.linalg.det(M[:2, :2]) == pytest.approx(-1)
    np.testing.assert_allclose(affine.apply([[1, 2], [4, 1]], M), [[1, 2], [4, 1]], atol=1e-14)  # the line is fixed
    assert affine.is_rigid(M) and affine.is_similarity(M) and not affine.is_conformal(M)  # §4.6: no mirrors


# --- the algebra of §4.3 --------------------------------------------------------------------------

@given(point, point)
@SETTINGS
def test_translations_commute_and_add(u, v):
    A, B = affine.translation(u), affine.translation(v)
    np.testing.assert_allclose(A @ B, B @ A)
    np.testing.assert_allclose(A @ B, affine.translation(u + v), atol=1e-12)
    assert affine.commute(A, B)


@given(angle, angle, point)
@SETTINGS
def test_rotations_about_the_same_point_commute_and_add(a, b, Q):
    A, B = affine.rotation(a, Q), affine.rotation(b, Q)
    np.testing.assert_allclose(A @ B, B @ A, atol=1e-10)
    np.testing.assert_allclose(A @ B, affine.rotation(a + b, Q), atol=1e-10)
    assert affine.commute(A, B)


@given(angle, point, factor)
@SETTINGS
def test_rotation_and_uniform_scaling_about_a_point_are_conjugates(a, Q, s):
    T = affine.translation
    np.testing.assert_allclose(affine.rotation(a, Q), T(-Q) @ affine.rotation(a) @ T(Q), atol=1e-11)
    np.testing.assert_allclose(affine.scaling(s, Q), T(-Q) @ affine.scaling(s) @ T(Q), atol=1e-11)
    np.testing.assert_allclose(affine.rotation(a, Q) @ affine.scaling(s, Q), affine.scaling(s, Q) @ affine.rotation(a, Q),
                               atol=1e-10)


def test_rotation_and_translation_do_not_commute():
    assert not affine.commute(affine.rotation(90), affine.translation([1, 0]))
    assert not affine.commute(affine.rotation(90, [0, 0]), affine.rotation(90, [1, 0]))
    assert affine.commute(affine.rotation(180, [0, 0]), affine.scaling(-1))


@given(maps, maps, maps)
@SETTINGS
def test_composition_is_associative_and_compose_is_the_product(A, B, C):
    np.testing.assert_allclose((A @ B) @ C, A @ (B @ C), rtol=1e-10, atol=1e-8)
    np.testing.assert_allclose(affine.compose(A, B, C), A @ B @ C, rtol=1e-10, atol=1e-8)
    P = np.array([[0.3, -1.2], [2.0, 0.5]])
    np.testing.assert_allclose(affine.apply(P, affine.compose(A, B)), affine.apply(affine.apply(P, A), B),
                               rtol=1e-9, atol=1e-8)


@given(maps)
@SETTINGS
def test_inverse_against_numpy_linalg(M):
    inv = affine.inverse(M)
    np.testing.assert_allclose(inv, np.linalg.inv(M), rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(inv @ M, np.eye(3), atol=1e-9)
    np.testing.assert_allclose(M @ inv, np.eye(3), atol=1e-9)
    np.testing.assert_array_equal(inv[:, 2], [0, 0, 1])


@given(point, angle, point, factor)
@SETTINGS
def test_inverses_of_the_basic_maps(v, a, Q, s):
    np.testing.assert_allclose(affine.inverse(affine.translation(v)), affine.translation(-v), atol=1e-12)
    np.testing.assert_allclose(affine.inverse(affine.rotation(a, Q)), affine.rotation(-a, Q), atol=1e-10)
    np.testing.assert_allclose(affine.inverse(affine.scaling(s, Q)), affine.scaling(1 / s, Q), atol=1e-9)


@given(maps, st.lists(st.tuples(point, st.floats(-3, 3, allow_nan=False)), min_size=2, max_size=5))
@SETTINGS
def test_affine_maps_preserve_affine_combinations(M, pairs):
    P = np.array([p for p, _ in pairs])
    c = np.array([w for _, w in pairs])
    c[-1] = 1 - c[:-1].sum()              # weights summing to 1
    lhs = affine.apply(affine.affine_combination(P, c), M)
    rhs = affine.affine_combination(affine.apply(P, M), c)
    np.testing.assert_allclose(lhs, rhs, rtol=1e-9, atol=1e-7)
    # and vectors: A(P + v) = A(P) + A(v)
    v = P[1] - P[0]
    np.testing.assert_allclose(affine.apply(P[0] + v, M), affine.apply(P[0], M) + affine.apply_vectors(v, M),
                               rtol=1e-9, atol=1e-8)


# --- the geometry of §4.4 -------------------------------------------------------------------------

@given(maps, point, point, st.floats(-3, 3, allow_nan=False))
@SETTINGS
def test_lines_go_to_lines_with_ratios_and_parallels_kept(M, P, Q, t):
    R = (1 - t) * P + t * Q
    AP, AQ, AR = affine.apply(np.array([P, Q, R]), M)
    np.testing.assert_allclose(AR, (1 - t) * AP + t * AQ, rtol=1e-9, atol=1e-7)
    v = Q - P
    w1 = affine.apply(P + 2 * v, M) - affine.apply(P, M)
    w2 = affine.apply(Q + v, M) - affine.apply(Q, M)
    np.testing.assert_allclose(w1, 2 * w2, rtol=1e-9, atol=1e-7)   # parallel segments stay parallel, ratio 2


@given(angle, point, point)
@SETTINGS
def test_rigid_and_conformal_maps(a, Q, v):
    M = affine.rotation(a, Q) @ affine.translation(v)
    assert affine.is_rigid(M) and affine.is_conformal(M)
    P = np.array([[0, 0], [3, 4]])
    assert np.linalg.norm(np.diff(affine.apply(P, M), axis=0)) == pytest.approx(5)
    assert affine.is_conformal(affine.scaling(3, Q)) and not affine.is_rigid(affine.scaling(3, Q))
    assert not affine.is_conformal(affine.shear(1)) and not affine.is_conformal(affine.directional_scaling(2, v + 1))


# --- §4.7: the map fixed by a point and two vectors, by three points --------------------------------

@given(triangle, triangle)
@SETTINGS
def test_affine_from_points_round_trips(src, dst):
    M = affine.affine_from_points(src, dst)
    np.testing.assert_allclose(affine.apply(src, M), dst, rtol=1e-9, atol=1e-8)
    back = affine.affine_from_points(dst, src)
    np.testing.assert_allclose(M @ back, np.eye(3), atol=1e-7)
    np.testing.assert_allclose(affine.inverse(M), back, rtol=1e-7, atol=1e-7)
    # the same map from the point src[0] and the two edge vectors
    N = affine.affine_from_point_and_vectors(src[0], src[1:] - src[0], dst[0], dst[1:] - dst[0])
    np.testing.assert_allclose(N, M, rtol=1e-9, atol=1e-8)


@given(triangle, triangle, point)
@SETTINGS
def test_affine_from_points_preserves_barycentric_coordinates(src, dst, P):
    M = affine.affine_from_points(src, dst)
    b = affine.barycentric_coordinates(P, src)
    np.testing.assert_allclose(b, np.linalg.solve(np.vstack([src.T, np.ones(3)]), np.append(P, 1.0)),
                               rtol=1e-8, atol=1e-8)
    np.testing.assert_allclose(affine.apply(P, M), b @ dst, rtol=1e-8, atol=1e-6)


@given(maps, triangle)
@SETTINGS
def test_every_map_is_recovered_from_three_points(M, src):
    np.testing.assert_allclose(affine.affine_from_points(src, affine.apply(src, M)), M, rtol=1e-7, atol=1e-7)


def test_affine_from_points_closed_form_and_singular_images():
    M = affine.affine_from_points([[0, 0], [1, 0], [0, 1]], [[1, 1], [3, 1], [1, 4]])
    np.testing.assert_allclose(M, [[2, 0, 0], [0, 3, 0], [1, 1, 1]], atol=1e-14)
    # collinear images are allowed: the map collapses the plane onto a line
    M = affine.affine_from_points([[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 1], [2, 2]])
    assert abs(np.linalg.det(M[:2, :2])) < 1e-12
    with pytest.raises(ValueError, match="invertible"):
        affine.inverse(M)


def test_barycentric_and_affine_combination_closed_forms():
    np.testing.assert_allclose(affine.barycentric_coordinates([[1 / 3, 1 / 3], [1, 0]], [[0, 0], [1, 0], [0, 1]]),
                               [[1 / 3, 1 / 3, 1 / 3], [0, 1, 0]], atol=1e-15)
    np.testing.assert_allclose(affine.affine_combination([[0, 0], [4, 0], [0, 4]], [0.5, 0.25, 0.25]), [1, 1])


@given(maps)
@SETTINGS
def test_parameters_round_trip_and_fixed_point(M):
    np.testing.assert_allclose(affine.from_parameters(**affine.to_parameters(M)), M, rtol=1e-9, atol=1e-8)
    L = M[:2, :2]
    if abs(np.linalg.det(np.eye(2) - L)) > 1e-3:
        F = affine.fixed_point(M)
        np.testing.assert_allclose(affine.apply(F, M), F, rtol=1e-7, atol=1e-6)


# --- bad input: one test per rule -----------------------------------------------------------------

def test_collinear_points_raise():
    with pytest.raises(ValueError, match="src points must not be collinear"):
        affine.affine_from_points([[0, 0], [1, 1], [2, 2]], [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError, match="triangle must not be collinear"):
        affine.barycentric_coordinates([0, 0], [[0, 0], [1, 0], [3, 0]])
    with pytest.raises(ValueError, match="vectors must be linearly independent"):
        affine.affine_from_point_and_vectors([0, 0], [[1, 2], [2, 4]], [0, 0], [[1, 0], [0, 1]])


def test_shapes_and_types_raise():
    with pytest.raises(ValueError, match="three 2D points"):
        affine.affine_from_points([[0, 0], [1, 0]], [[0, 0], [1, 0]])
    with pytest.raises(ValueError, match=r"v must have shape \(d,\)"):
        affine.translation([[1, 2]])
    with pytest.raises(ValueError, match="2-dimensional"):
        affine.translation([1, 2, 3])
    with pytest.raises(TypeError, match="angle must be a real number"):
        affine.rotation("90")
    with pytest.raises(ValueError, match="factor must be a number or a pair"):
        affine.scaling([1, 2, 3])
    with pytest.raises(ValueError, match="must have last column"):
        affine.apply([0, 0], [[1, 0, 1], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="shape \\(3, 3\\)"):
        affine.compose(np.eye(2))
    with pytest.raises(ValueError, match="center must be finite"):
        affine.rotation(30, center=[0, np.nan])


def test_degenerate_parameters_raise():
    with pytest.raises(ValueError, match="direction must be a nonzero vector"):
        affine.directional_scaling(2, [0, 0])
    with pytest.raises(ValueError, match="direction must be a nonzero vector"):
        affine.mirror([0, 0], [0, 0])
    with pytest.raises(ValueError, match="M must be invertible"):
        affine.inverse(affine.scaling(0))
    with pytest.raises(ValueError, match="weights must sum to 1"):
        affine.affine_combination([[0, 0], [1, 1]], [1, 1])
    with pytest.raises(ValueError, match="one weight per point"):
        affine.affine_combination([[0, 0], [1, 1]], [1])


# --- §4.6 conformal transformations revisited ---------------------------------------------------

def test_conformal_means_no_mirror():
    M = affine.mirror([1, 2], [3, -1])
    assert affine.is_rigid(M) and affine.is_similarity(M) and not affine.is_conformal(M)
    assert not affine.is_conformal(affine.similarity(2, 30, [1, 0], reflect=True))
    assert affine.is_conformal(affine.similarity(2, 30, [1, 0]))
    assert not affine.is_similarity(affine.shear(1)) and not affine.is_conformal(affine.shear(1))
    assert affine.is_conformal(affine.scaling(0))   # the degenerate uniform scaling


@given(angle, st.floats(0.1, 5), point, point)
@SETTINGS
def test_conformal_from_point_and_vector(a, s, P, Q):
    v = np.array([np.cos(np.radians(a + 10)), np.sin(np.radians(a + 10))]) * 1.5
    M_true = affine.similarity(s, a, Q)
    Pimg = affine.apply(P, M_true)
    vimg = affine.apply_vectors(v, M_true)
    M = affine.conformal_from_point_and_vector(P, v, Pimg, vimg)
    np.testing.assert_allclose(M, M_true, atol=1e-9 * max(1, np.abs(M_true).max()))
    assert affine.is_conformal(M)


def test_conformal_from_point_and_vector_errors():
    with pytest.raises(ValueError, match="vector must be a nonzero"):
        affine.conformal_from_point_and_vector([0, 0], [0, 0], [1, 1], [1, 0])
