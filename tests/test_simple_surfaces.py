"""goldman_lib.simple_surfaces: ray hits and normals against values worked by hand (Goldman ch. 19)."""

import numpy as np
import pytest

from goldman_lib import simple_surfaces as S


def test_sphere_hits_by_hand():
    s = S.Sphere([1, 2, 3], 2)
    # along +x through the centre from x = -4: enters at x = -1 (t = 3), leaves at x = 3 (t = 7)
    assert S.Sphere([1, 2, 3], 2).hits([[-4, 2, 3]], [[1, 0, 0]]).tolist() == [[3.0, 7.0]]
    # direction not unit: t in units of the direction
    assert s.intersect([[-4, 2, 3]], [[2, 0, 0]]).tolist() == [1.5]
    # a ray at height 1 above the centre: x^2 + 1 = 4, x = +-sqrt 3
    t = s.hits([[-4, 3, 3]], [[1, 0, 0]])[0]
    assert np.allclose(t, [5 - np.sqrt(3), 5 + np.sqrt(3)])
    # tangent (height 2): one double root; a miss: inf; behind the origin: inf
    assert np.allclose(s.hits([[-4, 4, 3]], [[1, 0, 0]]), [[5, 5]])
    assert s.intersect([[-4, 5, 3]], [[1, 0, 0]]).tolist() == [np.inf]
    assert s.intersect([[10, 2, 3]], [[1, 0, 0]]).tolist() == [np.inf]


def test_sphere_normal_and_inside():
    s = S.Sphere([0, 0, 0], 2)
    assert np.allclose(s.normal([[0, 2, 0], [np.sqrt(2), 0, np.sqrt(2)]]), [[0, 1, 0], [0.5 ** 0.5, 0, 0.5 ** 0.5]])
    assert s.contains([[0, 0, 1.9], [0, 0, 2.1]]).tolist() == [True, False]


def test_sphere_against_numpy_roots():
    rng = np.random.default_rng(7)
    s = S.Sphere([0.3, -0.2, 0.1], 1.3)
    o, d = rng.normal(size=(200, 3)) * 3, rng.normal(size=(200, 3))
    got = s.hits(o, d)
    for k in range(200):
        oc = o[k] - s.center
        r = np.roots([d[k] @ d[k], 2 * d[k] @ oc, oc @ oc - 1.3 ** 2])
        real = np.sort(r.real[abs(r.imag) < 1e-9])
        if len(real) == 2:
            assert np.allclose(got[k], real, atol=1e-9)
        else:
            assert np.all(np.isinf(got[k]))


def test_plane_by_hand():
    p = S.Plane([0, 0, 2], [0, 0, -3])
    assert p.intersect([[1, 1, 0], [0, 0, 0], [0, 0, 0]], [[0, 0, 1], [1, 0, 0], [0, 0, -1]]).tolist() == \
        [2.0, np.inf, np.inf]
    assert np.allclose(p.normal([[5, 5, 2]]), [[0, 0, -1]])
    assert p.contains([[0, 0, 3], [0, 0, 1]]).tolist() == [True, False]     # behind the normal


def test_quadratic_roots_stable_for_tiny_roots():
    # t^2 - 1e8 t + 1 = 0: roots 1e8 and 1e-8; the naive formula loses the small one
    r = S.quadratic_roots([1.0], [-1e8], [1.0])[0]
    assert r[0] == pytest.approx(1e-8, rel=1e-12) and r[1] == pytest.approx(1e8, rel=1e-12)


@pytest.mark.parametrize("bad, word", [
    (lambda: S.Sphere([0, 0, 0], 0), "radius"),
    (lambda: S.Sphere([0, 0], 1), "center"),
    (lambda: S.Plane([0, 0, 0], [0, 0, 0]), "normal"),
    (lambda: S.Sphere([0, 0, 0], 1).intersect([[0, 0, 0]], [[0, 0, 0]]), "directions"),
    (lambda: S.Sphere([0, 0, 0], 1).intersect([[0, 0, 0]] * 2, [[0, 0, 1]] * 3), "origins"),
])
def test_bad_input(bad, word):
    with pytest.raises(ValueError, match=word):
        bad()


def test_a_plane_has_no_inside_is_not_an_error_but_a_sphere_has_one():
    assert S.Plane([0, 0, 0], [0, 0, 1]).contains([[0, 0, -1]]).tolist() == [True]
