"""Quaternions (Goldman ch 15) against scipy.spatial.transform.Rotation / Slerp and hand values."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.spatial.transform import Rotation, Slerp

from goldman_lib import quaternions as qt

finite = st.floats(-10, 10, allow_nan=False)
vec3 = st.tuples(finite, finite, finite)
nonzero_vec3 = vec3.filter(lambda v: np.linalg.norm(v) > 1e-3)
angle = st.floats(-720, 720, allow_nan=False)
quat = st.tuples(finite, finite, finite, finite).filter(lambda q: np.linalg.norm(q) > 1e-3)


def scipy_quat(q):
    """(w, x, y, z) -> scipy's (x, y, z, w)."""
    q = np.asarray(q, float)
    return np.concatenate([q[..., 1:], q[..., :1]], axis=-1)


def test_hamilton_rules_by_hand():
    i, j, k, one = [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [1, 0, 0, 0]
    assert qt.multiply(i, i).tolist() == [-1, 0, 0, 0]
    assert qt.multiply(j, k).tolist() == [0, 1, 0, 0] and qt.multiply(k, i).tolist() == [0, 0, 1, 0]
    assert qt.multiply(k, j).tolist() == [0, -1, 0, 0]
    assert qt.multiply(one, [1, 2, 3, 4]).tolist() == [1, 2, 3, 4]
    # (1 + 2i + 3j + 4k)(5 + 6i + 7j + 8k) worked by hand: (-60, 12, 30, 24)
    assert qt.multiply([1, 2, 3, 4], [5, 6, 7, 8]).tolist() == [-60, 12, 30, 24]


def test_norm_conjugate_inverse_by_hand():
    assert float(qt.norm([1, 2, 2, 4])) == 5.0
    assert qt.conjugate([1, 2, 3, 4]).tolist() == [1, -2, -3, -4]
    assert np.allclose(qt.multiply([1, 2, 3, 4], qt.inverse([1, 2, 3, 4])), [1, 0, 0, 0])
    with pytest.raises(ValueError, match="q must be nonzero"):
        qt.inverse([0, 0, 0, 0])


def test_complex_numbers_rotate_and_scale_the_plane():
    z = qt.complex_rotation(30, 2.0)
    out = qt.complex_multiply([[1.0, 0.0], [0.0, 1.0]], z)
    c, s = np.cos(np.radians(30)), np.sin(np.radians(30))
    assert np.allclose(out, [[2 * c, 2 * s], [-2 * s, 2 * c]])
    with pytest.raises(TypeError, match="z must be a complex number"):
        qt.complex_multiply([[1, 0]], "i")


@settings(max_examples=60, deadline=None)
@given(nonzero_vec3, angle, vec3)
def test_rotation_matches_scipy(axis, deg, v):
    q = qt.from_axis_angle(axis, deg)
    u = np.asarray(axis) / np.linalg.norm(axis)
    ref = Rotation.from_rotvec(np.radians(deg) * u)
    assert np.allclose(qt.rotate(q, v), ref.apply(v), atol=1e-9)
    assert np.allclose(np.asarray(v) @ qt.to_matrix(q)[:3, :3], ref.apply(v), atol=1e-9)
    assert np.allclose(qt.to_matrix(q)[:3, :3], ref.as_matrix().T, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(quat)
def test_from_matrix_inverts_to_matrix_and_matches_scipy(q):
    unit = np.asarray(q) / np.linalg.norm(q)
    back = qt.from_matrix(qt.to_matrix(unit))
    assert np.allclose(back, unit if unit[0] >= 0 else -unit, atol=1e-9) or np.isclose(abs(unit[0]), 0, atol=1e-9)
    ref = Rotation.from_matrix(qt.to_matrix(unit)[:3, :3].T).as_quat()
    assert np.allclose(np.abs(np.dot(scipy_quat(back), ref)), 1, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(quat, quat, vec3)
def test_rotation_preserves_length_and_composes_like_matrices(p, q, v):
    rotated = qt.rotate(q, v)
    assert np.isclose(np.linalg.norm(rotated), np.linalg.norm(v), atol=1e-9)
    both = qt.rotate(qt.multiply(p, q), v)  # first q, then p
    assert np.allclose(both, qt.rotate(p, qt.rotate(q, v)), atol=1e-8)
    M = qt.to_matrix(q) @ qt.to_matrix(p)  # row convention: first q then p
    assert np.allclose(qt.to_matrix(qt.multiply(p, q)), M, atol=1e-9)


def test_conformal_map_scales_by_the_norm_squared():
    q = 2 * qt.from_axis_angle([0, 0, 1], 90)
    assert np.allclose(qt.conformal_map(q, [1, 0, 0]), [0, 4, 0])


@settings(max_examples=40, deadline=None)
@given(quat, quat, st.floats(0, 1))
def test_slerp_matches_scipy_on_the_shorter_arc(a, b, t):
    a = np.asarray(a) / np.linalg.norm(a)
    b = np.asarray(b) / np.linalg.norm(b)
    ours = qt.slerp(a, b, t)
    ref = Slerp([0, 1], Rotation.from_quat(np.stack([scipy_quat(a), scipy_quat(b)])))([t]).as_quat()[0]
    assert np.isclose(abs(np.dot(scipy_quat(ours), ref)), 1, atol=1e-8)


def test_slerp_takes_the_shorter_arc_and_keeps_constant_speed():
    a = qt.from_axis_angle([0, 0, 1], 0)
    b = -qt.from_axis_angle([0, 0, 1], 90)   # same rotation as +q
    _, ang = qt.to_axis_angle(qt.slerp(a, b, np.linspace(0, 1, 5)))
    assert np.allclose(ang, [0, 22.5, 45, 67.5, 90])


def test_key_frames_and_the_distortion_of_matrix_interpolation():
    keys = np.stack([qt.from_axis_angle([0, 0, 1], 0), qt.from_axis_angle([0, 0, 1], 120),
                     qt.from_axis_angle([1, 0, 0], 120)])
    q = qt.key_frames(keys, [0, 1, 3], [0.5, 2.0, 5.0])
    _, ang = qt.to_axis_angle(q[0])
    assert np.isclose(ang, 60)
    assert np.allclose(q[2], keys[2])  # clamped
    # Halfway between identity and a 120° turn, the linear blend of the matrices is not a rotation:
    # its x/y singular values are |1 + cos 120°| / 2 ... = 0.5 (a closed form).
    M = qt.matrix_lerp(np.eye(3), qt.to_matrix(keys[1])[:3, :3], 0.5)
    assert np.isclose(qt.matrix_distortion(M), 0.5)
    assert qt.matrix_distortion(qt.to_matrix(q[0])) < 1e-12
    with pytest.raises(ValueError, match="times must be strictly increasing"):
        qt.key_frames(keys, [0, 1, 1], 0.5)


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match="axis must be nonzero"):
        qt.from_axis_angle([0, 0, 0], 30)
    with pytest.raises(ValueError, match="q must hold quaternions"):
        qt.multiply([1, 0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match="M must be a rotation matrix"):
        qt.from_matrix(np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="t must be finite"):
        qt.slerp([1, 0, 0, 0], [0, 1, 0, 0], np.nan)


def test_complex_polar_inverts_complex_rotation_like_cmath():
    import cmath

    for z in (3 - 4j, -1 + 1j, -2.0, 0.5j, 1e-300 + 0j):
        r, deg = cmath.polar(z)
        ours = qt.complex_polar(z)
        assert np.isclose(ours[0], r, rtol=1e-15, atol=0) and np.isclose(ours[1], np.degrees(deg), atol=1e-12)
    assert qt.complex_polar(0) == (0.0, 0.0)
    with pytest.raises(TypeError, match="z must be a complex number"):
        qt.complex_polar("1+i")
    with pytest.raises(ValueError, match="z must be finite"):
        qt.complex_polar(complex(np.inf, 0))


def test_matrix_key_frames_blend_the_key_matrices_linearly():
    keys = np.stack([qt.from_axis_angle([0, 0, 1], 0), qt.from_axis_angle([0, 0, 1], 90),
                     qt.from_axis_angle([1, 0, 0], 90)])
    # scipy's matrices are column-convention: transpose for the book's rows
    R = [np.eye(3), Rotation.from_rotvec([0, 0, np.pi / 2]).as_matrix().T,
         Rotation.from_rotvec([np.pi / 2, 0, 0]).as_matrix().T]
    M = qt.matrix_key_frames(keys, [0, 1, 3], [0.25, 2.0, -1.0, 9.0])
    assert M.shape == (4, 4, 4)
    assert np.allclose(M[0, :3, :3], 0.75 * R[0] + 0.25 * R[1])
    assert np.allclose(M[1, :3, :3], 0.5 * R[1] + 0.5 * R[2])
    assert np.allclose(M[2, :3, :3], R[0]) and np.allclose(M[3, :3, :3], R[2])    # clamped
    # the blend of the identity and a quarter turn about z scales the xy-plane by |1 + i| / 2
    assert np.isclose(qt.matrix_distortion(qt.matrix_key_frames(keys, [0, 1, 3], 0.5)), 1 - np.sqrt(2) / 2)
    with pytest.raises(ValueError, match="times must be strictly increasing"):
        qt.matrix_key_frames(keys, [0, 2, 1], 0.5)
    with pytest.raises(ValueError, match="orientations must be nonzero"):
        qt.matrix_key_frames([[0, 0, 0, 0], [1, 0, 0, 0]], [0, 1], 0.5)


def test_bad_input_names_the_parameter_of_each_function():
    with pytest.raises(ValueError, match="q0 must be nonzero"):
        qt.slerp([0, 0, 0, 0], [1, 0, 0, 0], 0.5)
    with pytest.raises(ValueError, match="q1 must hold quaternions"):
        qt.slerp([1, 0, 0, 0], [1, 0, 0], 0.5)
    with pytest.raises(ValueError, match="tol must be positive"):
        qt.from_matrix(np.eye(3), tol=-1)
    with pytest.raises(ValueError, match="angle must be one number"):
        qt.complex_rotation([], 1.0)
    with pytest.raises(ValueError, match="z is too large"):
        qt.complex_multiply([[1.0, 1.0]], 1e308 + 1e308j)
    with pytest.raises(ValueError, match="t is too large"):
        qt.matrix_lerp(np.eye(3), -np.eye(3), 1e308)


# -- the chapter's framing: pure quaternions, mirrors, nlerp, the stereographic picture of S³ ---------

def test_one_sided_product_leaves_three_space_and_the_sandwich_does_not():
    # q = 90° about z = (√2/2, 0, 0, √2/2), v = (1, 0, 1): q v = (-q⃗·v, w v + q⃗ × v), worked by hand
    q, v = qt.from_axis_angle([0, 0, 1], 90), np.array([1.0, 0.0, 1.0])
    h = np.sqrt(0.5)
    assert np.allclose(qt.multiply(q, qt.pure(v)), [-h, h, h, h])
    assert np.allclose(qt.multiply(qt.multiply(q, qt.pure(v)), qt.conjugate(q)), [0, 0, 1, 1])
    assert qt.pure([[1, 2, 3], [4, 5, 6]]).shape == (2, 4)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-3, 3), min_size=3, max_size=3).filter(lambda n: np.linalg.norm(n) > 0.1),
       st.lists(st.floats(-3, 3), min_size=3, max_size=3))
def test_mirror_sandwich_is_the_mirror_of_chapter_12(n, v):
    from goldman_lib import transforms

    got = qt.mirror(n, v)
    assert np.allclose(got, transforms.reflect([v], [0, 0, 0], n)[0], atol=1e-9)
    assert np.allclose(got, np.asarray(v) @ transforms.mirror([0, 0, 0], n)[:3, :3], atol=1e-9)
    N = qt.pure(np.asarray(n) / np.linalg.norm(n))
    minus = -qt.multiply(qt.multiply(N, qt.pure(v)), qt.conjugate(N))     # -N v N* is the same map
    assert np.allclose(minus[1:], got, atol=1e-9) and abs(minus[0]) < 1e-9


def test_mirror_by_hand():
    assert np.allclose(qt.mirror([1, 1, 0], [1, 0, 0]), [0, -1, 0])     # the plane x = -y swaps and negates
    with pytest.raises(ValueError, match="normal"):
        qt.mirror([0, 0, 0], [1, 0, 0])


@pytest.mark.parametrize("n1,n2", [([1, 0, 0], [1, 1, 0]), ([0, 0, 1], [0, 1, 2]), ([1, -2, 2], [2, 2, 1])])
def test_two_mirrors_make_a_rotation_by_twice_the_angle_between_them(n1, n2):
    n1, n2 = np.array(n1, float), np.array(n2, float)
    phi = np.arccos(n1 @ n2 / np.linalg.norm(n1) / np.linalg.norm(n2))
    axis = np.cross(n1, n2)
    reference = Rotation.from_rotvec(2 * phi * axis / np.linalg.norm(axis))   # scipy, column vectors
    v = np.array([0.3, -1.1, 0.7])
    q = qt.rotation_from_mirrors(n1, n2)
    assert np.allclose(qt.rotate(q, v), reference.apply(v))
    assert np.allclose(qt.mirror(n2, qt.mirror(n1, v)), reference.apply(v))


def test_nlerp_runs_the_slerp_arc_at_another_speed():
    q0, q1 = np.array([1.0, 0, 0, 0]), qt.from_axis_angle([0, 0, 1], 120)
    # t = 1/4: normalise (3/4, 0, 0, 0) + (1/4)(1/2, 0, 0, √3/2) = (7/8, 0, 0, √3/8), worked by hand
    expected = np.array([7 / 8, 0, 0, np.sqrt(3) / 8]) / np.sqrt(49 / 64 + 3 / 64)
    assert np.allclose(qt.nlerp(q0, q1, 0.25), expected)
    assert np.allclose(qt.nlerp(q0, q1, 0.5), qt.slerp(q0, q1, 0.5))
    assert np.allclose(qt.nlerp(q0, -q1, 0.25), expected)                   # the shorter side
    ts = np.linspace(0, 1, 9)
    angles = qt.to_axis_angle(qt.nlerp(q0, q1, ts))[1]
    steps = np.diff(angles)
    assert steps[0] < 14 < steps[4]                                          # bunched at the ends
    assert np.allclose(np.diff(qt.to_axis_angle(qt.slerp(q0, q1, ts))[1]), 15)


def test_stereographic_projection_of_unit_quaternions():
    assert np.allclose(qt.stereographic([1, 0, 0, 0]), 0)                  # the pole's antipode -> origin
    u = np.array([1.0, 2.0, 2.0]) / 3
    for theta in (30.0, 90.0, 200.0, 300.0):
        # (cos(θ/2), sin(θ/2) u) -> sin(θ/2)/(1 + cos(θ/2)) u = tan(θ/4) u
        assert np.allclose(qt.stereographic(qt.from_axis_angle(u, theta)), np.tan(np.radians(theta) / 4) * u)
    assert np.allclose(qt.stereographic([2, 0, 0, 0]), 0)                  # normalised first
    with pytest.raises(ValueError, match="pole"):
        qt.stereographic([-1, 0, 0, 0])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-2, 2), min_size=4, max_size=4).filter(lambda q: np.linalg.norm(q) > 0.1))
def test_stereographic_round_trip(q):
    q = np.asarray(q) / np.linalg.norm(q)
    if q[0] < 0:
        q = -q                        # the same rotation, away from the pole
    back = qt.inverse_stereographic(qt.stereographic(q))
    assert np.allclose(back, q, atol=1e-9)
    p = np.array([q[1] - 0.5, 3.0 * q[2], q[3]])
    assert np.isclose(np.linalg.norm(qt.inverse_stereographic(p)), 1.0)
    assert np.allclose(qt.stereographic(qt.inverse_stereographic(p)), p, atol=1e-9)


def test_stereographic_sends_a_great_circle_to_a_circle():
    rng = np.random.default_rng(4)
    a, b = rng.normal(size=4), rng.normal(size=4)
    a /= np.linalg.norm(a)
    b -= (a @ b) * a
    b /= np.linalg.norm(b)
    s = np.linspace(0, 2 * np.pi, 40, endpoint=False)[:, None]
    circle = np.cos(s) * a + np.sin(s) * b                      # a great circle of S³, missing the pole
    assert np.all(circle[:, 0] > -0.999)
    P = qt.stereographic(circle)
    centred = P - P.mean(axis=0)
    assert np.linalg.svd(centred, compute_uv=False)[2] < 1e-9   # in one plane
    # the circumcentre of three of its points is at one distance from them all
    A, B, C = P[0], P[13], P[27]
    ab, ac = B - A, C - A
    n = np.cross(ab, ac)
    centre = A + (np.cross(n, ab) * (ac @ ac) + np.cross(ac, n) * (ab @ ab)) / (2 * n @ n)
    r = np.linalg.norm(P - centre, axis=1)
    assert np.ptp(r) < 1e-9 * r.max()
