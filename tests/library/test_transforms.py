"""Transformations of 3-space (Goldman ch 12-13): the chapter-12 formulas equal the chapter-13
matrices; rotations against scipy; mirrors are involutions with determinant -1; projections land
on their plane."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.spatial.transform import Rotation

from goldman_lib import transforms as tf

finite = st.floats(-20, 20, allow_nan=False)
vec3 = st.tuples(finite, finite, finite).map(np.array)
direction = vec3.filter(lambda v: np.linalg.norm(v) > 1e-2)
points = st.lists(st.tuples(finite, finite, finite), min_size=1, max_size=6).map(np.array)
angle = st.floats(-360, 360, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(points, direction, angle, vec3)
def test_rotation_formula_equals_matrix_and_scipy(P, axis, deg, Q):
    a = tf.rotate(P, axis, deg, point=Q)
    b = tf.apply(P, tf.rotation(axis, deg, point=Q))
    ref = Rotation.from_rotvec(np.radians(deg) * axis / np.linalg.norm(axis)).apply(P - Q) + Q
    assert np.allclose(a, b, atol=1e-9) and np.allclose(a, ref, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(points, vec3, direction)
def test_mirror_is_an_involution_with_determinant_minus_one(P, Q, N):
    M = tf.mirror(Q, N)
    assert np.allclose(tf.reflect(P, Q, N), tf.apply(P, M), atol=1e-9)
    assert np.allclose(M @ M, np.eye(4), atol=1e-9) and np.isclose(np.linalg.det(M), -1)
    # the mirror fixes the plane and the midpoint of P and its image lies on it
    mid = (P + tf.reflect(P, Q, N)) / 2
    assert np.allclose((mid - Q) @ N, 0, atol=1e-8 * (1 + np.abs(P).max()) * np.linalg.norm(N))


@settings(max_examples=60, deadline=None)
@given(points, st.floats(-5, 5, allow_nan=False), direction, vec3)
def test_scalings_formula_equals_matrix(P, s, w, Q):
    assert np.allclose(tf.scale(P, s, Q), tf.apply(P, tf.scaling(s, Q)), atol=1e-9)
    assert np.allclose(tf.scale_along(P, s, w, Q), tf.apply(P, tf.nonuniform_scaling(s, w, Q)), atol=1e-8)
    assert np.isclose(np.linalg.det(tf.nonuniform_scaling(s, w, Q)), s)


@settings(max_examples=60, deadline=None)
@given(points, vec3, direction, vec3)
def test_projections_formula_equals_matrix_and_land_on_the_plane(P, Q, N, E):
    n = N / np.linalg.norm(N)
    ortho = tf.project_orthogonal(P, Q, N)
    assert np.allclose(ortho, tf.apply(P, tf.orthogonal_projection(Q, N)), atol=1e-8)
    assert np.allclose((ortho - Q) @ n, 0, atol=1e-8 * (1 + np.abs(P).max() + np.abs(Q).max()))
    if abs((Q - E) @ n) < 1e-1 or np.any(np.abs((P - E) @ n) < 1e-1):
        return
    persp = tf.project_perspective(P, E, Q, N)
    assert np.allclose(persp, tf.apply(P, tf.perspective(E, Q, N)), rtol=1e-7, atol=1e-6)
    assert np.allclose((persp - Q) @ n, 0, atol=1e-6 * (1 + np.abs(persp).max()))
    # the image lies on the line of sight: persp - E parallel to P - E
    assert np.allclose(np.cross(persp - E, P - E), 0, atol=1e-6 * (1 + np.abs(persp - E).max() * np.abs(P - E).max()))


def test_by_hand_and_the_row_convention():
    # translation in the last row
    assert tf.translation([1, 2, 3])[3].tolist() == [1, 2, 3, 1]
    # 90 degrees about z takes x to y: row vector times matrix
    R = tf.rotation([0, 0, 1], 90)
    assert np.allclose(np.array([1, 0, 0, 1]) @ R, [0, 1, 0, 1])
    # composition: first translate, then scale = A @ B
    assert np.allclose(tf.apply([[0, 0, 0]], tf.compose(tf.translation([1, 0, 0]), tf.scaling(3))), [[3, 0, 0]])
    # perspective from the origin onto z = 1 divides by z
    assert tf.apply([[3, 6, 3]], tf.perspective([0, 0, 0], [0, 0, 1], [0, 0, 1])).tolist() == [[1, 2, 1]]


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match="axis must be a nonzero vector"):
        tf.rotation([0, 0, 0], 30)
    with pytest.raises(ValueError, match="eye must not lie on the plane"):
        tf.perspective([0, 0, 1], [0, 0, 1], [0, 0, 1])
    with pytest.raises(ValueError, match=r"points\[0\] is sent to infinity"):
        tf.apply([[1, 1, 0]], tf.perspective([0, 0, 0], [0, 0, 1], [0, 0, 1]))
    with pytest.raises(ValueError, match="M must be a 4x4 matrix"):
        tf.apply([[1, 1, 0]], np.eye(3))


def test_homogeneous_coordinates_before_the_divide_and_vectors_ignore_translation():
    # perspective from the origin onto z = 2 (c = 2): [x y z 1] M = (2x, 2y, 2z, z), worked by hand
    M = tf.perspective([0, 0, 0], [0, 0, 2], [0, 0, 1])
    assert tf.homogeneous([[3, 6, 4]], M).tolist() == [[6, 12, 8, 4]]
    assert tf.apply([[3, 6, 4]], M).tolist() == [[1.5, 3, 2]]
    # a vector is not moved by a translation; a rotation turns it as it turns points about the origin
    T = tf.compose(tf.rotation([0, 0, 1], 90), tf.translation([5, 0, 0]))
    assert np.allclose(tf.apply_to_vectors([[1, 0, 0]], T), [[0, 1, 0]])
    assert np.allclose(tf.apply([[1, 0, 0]], T), [[5, 1, 0]])
    # vector image = difference of point images (any affine map)
    A = tf.compose(tf.mirror([1, 2, 0], [1, 1, 1]), tf.nonuniform_scaling(2, [0, 1, 1], [1, 0, 0]))
    P, R = np.array([[1.0, 2, 3]]), np.array([[-1.0, 0.5, 2]])
    assert np.allclose(tf.apply_to_vectors(P - R, A), tf.apply(P, A) - tf.apply(R, A))
    with pytest.raises(ValueError, match="M must be affine"):
        tf.apply_to_vectors([[1, 0, 0]], M)


# -- the map fixed by four points and their images; the inverse of a rigid motion (§13.1, §13.3) --------

def test_affine_from_points_by_hand_and_against_lstsq():
    # sources: the unit frame moved to (1, 0, 0); images: turned 90° about z, then sent down by 1 in y
    M = tf.affine_from_points([[1, 0, 0], [2, 0, 0], [1, 1, 0], [1, 0, 1]],
                                      [[0, 0, 0], [0, 1, 0], [-1, 0, 0], [0, 0, 1]])
    assert M.tolist() == [[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 1]]
    rng = np.random.default_rng(13)
    for _ in range(50):
        P, Q = rng.uniform(-3, 3, (4, 3)), rng.uniform(-3, 3, (4, 3))
        if abs(np.linalg.det(P[1:] - P[0])) < 0.5:
            continue
        H = np.c_[P, np.ones(4)]                         # [P_i 1] X = [Q_i 1], solved by least squares
        X = np.linalg.lstsq(H, np.c_[Q, np.ones(4)], rcond=None)[0]
        M = tf.affine_from_points(P, Q)
        assert np.allclose(M, X, atol=1e-9)
        assert np.allclose(M[:, 3], [0, 0, 0, 1])
        assert np.allclose(np.c_[P, np.ones(4)] @ M, np.c_[Q, np.ones(4)], atol=1e-9)   # row convention


def test_affine_from_points_refuses_a_coplanar_frame():
    with pytest.raises(ValueError, match="sources must be affinely independent"):
        tf.affine_from_points([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], np.eye(4)[:, :3])
    with pytest.raises(ValueError, match="sources must hold four 3D points"):
        tf.affine_from_points(np.zeros((3, 3)), np.zeros((3, 3)))


def test_rigid_inverse_against_numpy_and_by_hand():
    # 90° about z through (1, 0, 0): back by -90° about the same line; the row -t Rᵀ is (1, 1, 0)
    M = tf.rotation([0, 0, 1], 90, point=[1, 0, 0])
    assert np.allclose(tf.rigid_inverse(M), [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [1, 1, 0, 1]])
    rng = np.random.default_rng(31)
    for _ in range(30):
        M = tf.compose(tf.rotation(rng.normal(size=3), rng.uniform(-180, 180), point=rng.normal(size=3)),
                               tf.mirror(rng.normal(size=3), rng.normal(size=3)),
                               tf.translation(rng.normal(size=3)))
        assert np.allclose(tf.rigid_inverse(M), np.linalg.inv(M), atol=1e-12)
    with pytest.raises(ValueError, match="must be a rigid motion"):
        tf.rigid_inverse(tf.scaling(2))
    with pytest.raises(ValueError, match="must be affine"):
        tf.rigid_inverse(tf.perspective([0, 0, 5], [0, 0, 0], [0, 0, 1]))
