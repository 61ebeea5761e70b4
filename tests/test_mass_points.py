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
