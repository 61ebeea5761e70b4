"""Mass-points and projective space (Goldman ch 14): the law of the lever by hand, agreement with
the perspective formula of chapter 12, and pseudoperspective keeping lines and depth order."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from goldman_lib import mass_points as mp
from goldman_lib import transforms as tf

finite = st.floats(-10, 10, allow_nan=False)


def test_law_of_the_lever_by_hand():
    # 3 kg at 0 and 1 kg at 4 balance at 1 with 4 kg
    s = mp.add(mp.mass_point([0.0], 3), mp.mass_point([4.0], 1))
    assert s.tolist() == [4.0, 4.0] and mp.point_of(s).tolist() == [1.0]
    assert mp.center_of_mass([[0, 0], [6, 0], [0, 6]], [1, 1, 1]).tolist() == [2.0, 2.0]
    # a mass-point plus a vector translates the point; cancelling masses give a vector
    assert mp.point_of(mp.add(mp.mass_point([1, 1], 2), mp.vector([2, 0]))).tolist() == [2.0, 1.0]
    v = mp.add(mp.mass_point([1, 0], 1), mp.mass_point([0, 0], -1))
    assert v.tolist() == [1.0, 0.0, 0.0] and mp.mass_of(v) == 0
    with pytest.raises(ValueError, match="a must have nonzero mass"):
        mp.point_of(v)
    with pytest.raises(ValueError, match="m must be nonzero"):
        mp.mass_point([1, 1], 0)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(finite, finite, finite), min_size=1, max_size=5), st.floats(0.1, 5), st.floats(0.1, 5))
def test_scaling_a_mass_point_keeps_its_projective_point(P, m, c):
    a = mp.mass_point(P, m)
    assert np.all(mp.same_projective_point(a, mp.scale(c, a)))
    assert np.allclose(mp.point_of(mp.scale(c, a)), P, atol=1e-9)


def test_projective_factor_by_hand():
    # b = 3 a, b = -a/2 (negative factors count), a point at infinity scaled by -3
    assert mp.projective_factor([1, -2, 4, 1], [3, -6, 12, 3]) == pytest.approx(3.0, abs=1e-15)
    assert mp.projective_factor([1, -2, 4, 1], [-0.5, 1, -2, -0.5]) == pytest.approx(-0.5, abs=1e-15)
    assert mp.projective_factor([0, 1, 1, 0], [0, -3, -3, 0]) == pytest.approx(-3.0, abs=1e-15)
    # (1, -2, 4) and (1/2, -1, 2) are different affine points: no factor
    assert mp.projective_factor([1, -2, 4, 1], [1, -2, 4, 2]) is None
    got = mp.projective_factor([[1, 0, 1], [1, 0, 1]], [[2, 0, 2], [1, 0, 2]])
    assert got[0] == pytest.approx(2.0) and np.isnan(got[1])
    with pytest.raises(ValueError, match="nonzero"):
        mp.projective_factor([0, 0, 0], [1, 0, 1])


def test_perspective_by_mass_points_equals_chapter_12():
    rng = np.random.default_rng(2)
    E, Q, N = np.array([0.5, -1, -4.0]), np.array([0, 0, 1.0]), np.array([0.1, 0.2, 1.0])
    P = rng.uniform(-3, 3, (40, 3)) + [0, 0, 6]
    assert np.allclose(mp.point_of(mp.perspective_mass(P, E, Q, N)), tf.project_perspective(P, E, Q, N))


def test_pseudoperspective_keeps_depth_order_and_lines():
    E, Q, N = np.zeros(3), np.array([0, 0, 1.0]), np.array([0, 0, 1.0])
    # depth order along one line of sight is kept, while perspective sends all to one point
    P = np.array([[1, 1, 2.0], [2, 2, 4.0], [3, 3, 6.0]])
    assert np.allclose(tf.project_perspective(P, E, Q, N), [[0.5, 0.5, 1.0]] * 3)
    depth = mp.pseudodepth(P, E, Q, N)
    assert depth.tolist() == [0.5, 0.75, 1 - 1 / 6] and np.all(np.diff(depth) > 0)
    # matrix form equals the formula; collinear points stay collinear
    M = mp.pseudoperspective_matrix(E, Q, N)
    rng = np.random.default_rng(4)
    A, B = rng.uniform(-2, 2, 3) + [0, 0, 5], rng.uniform(-2, 2, 3) + [0, 0, 5]
    line = A + np.linspace(0, 1, 7)[:, None] * (B - A)
    img = tf.apply(line, M)
    assert np.allclose(img, mp.pseudoperspective(line, E, Q, N))
    d = img - img[0]
    assert np.allclose(np.cross(d[1:], d[-1]), 0, atol=1e-9)
    with pytest.raises(ValueError, match="points must lie in front of the eye"):
        mp.pseudodepth([[0, 0, -1]], E, Q, N)


def test_general_frame_pseudoperspective_matrix_equals_formula():
    rng = np.random.default_rng(8)
    E, Q, N = np.array([1.0, 2, -3]), np.array([0.0, 0, 2]), np.array([0.2, -0.1, 1.0])
    P = rng.uniform(-2, 2, (30, 3)) + [0, 0, 6]
    assert np.allclose(tf.apply(P, mp.pseudoperspective_matrix(E, Q, N)), mp.pseudoperspective(P, E, Q, N))


# -- pseudodepth and the frustum matrix's depth ----------------------------------------------------------------


def test_normalized_pseudodepth_is_the_frustum_matrix_depth():
    # OpenGL's frustum matrix maps eye depth s (near n, far f) to z = (f + n)/(f - n) - 2 f n / ((f - n) s)
    rng = np.random.default_rng(144)
    for n, f, c in ((0.1, 100.0, 1.0), (1.0, 50.0, 2.5), (2.0, 3.0, 0.5)):
        s = rng.uniform(n, f, 200)
        delta = 1 - c / s
        opengl = (f + n) / (f - n) - 2 * f * n / ((f - n) * s)
        assert np.allclose(mp.normalized_depth(delta, c, n, f), opengl, rtol=0, atol=1e-12)
    assert mp.normalized_depth([1 - 1 / 0.5, 1 - 1 / 8.0], 1.0, 0.5, 8.0).tolist() == [-1.0, 1.0]


def test_normalized_pseudodepth_comes_from_the_pseudoperspective_points():
    eye, plane_point, normal = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 2.0]), np.array([0.0, 0.0, 1.0])
    P = np.array([[0.3, -1.0, 4.0], [1.0, 2.0, 9.0], [-2.0, 0.5, 30.0]])
    c = (plane_point - eye) @ normal
    s = (P - eye) @ normal
    z = mp.normalized_depth(mp.pseudodepth(P, eye, plane_point, normal), c, 3.0, 40.0)
    assert np.allclose(z, (40 + 3) / (40 - 3) - 2 * 40 * 3 / ((40 - 3) * s), atol=1e-12)
    assert np.all(np.diff(z[np.argsort(s)]) > 0)                        # depth order kept


def test_depth_resolution_is_one_step_over_the_slope():
    n, f, bits = 0.5, 200.0, 16
    s = np.array([1.0, 10.0, 100.0])
    step = 2.0 / 2 ** bits
    h = 1e-6
    slope = (mp.normalized_depth(1 - 1 / (s + h), 1.0, n, f) - mp.normalized_depth(1 - 1 / (s - h), 1.0, n, f)) / (2 * h)
    assert np.allclose(mp.depth_resolution(s, n, f, bits) * slope, step, rtol=1e-6)
    # ten times the near distance: ten times finer everywhere (far fixed and large)
    assert np.allclose(mp.depth_resolution(s, 10 * n, f, bits) / mp.depth_resolution(s, n, f, bits),
                       (f - 10 * n) / (10 * (f - n)), rtol=1e-12)


def test_depth_functions_refuse_bad_input():
    with pytest.raises(ValueError, match="far must be greater than near"):
        mp.normalized_depth([0.5], 1.0, 5.0, 2.0)
    with pytest.raises(ValueError, match="c must be nonzero"):
        mp.normalized_depth([0.5], 0.0, 1.0, 2.0)
    with pytest.raises(ValueError, match="depths must be positive"):
        mp.depth_resolution([-1.0], 1.0, 2.0)
    with pytest.raises(ValueError, match="bits"):
        mp.depth_resolution([1.0], 1.0, 2.0, bits=100)
