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


# -- chapter 19: the other simple surfaces --------------------------------------------------------

from numpy.polynomial import Polynomial as Poly   # noqa: E402

R3 = np.sqrt(3.0)


def test_cylinder_hits_by_hand():
    inf_cyl = S.Cylinder([0, 0, 0], [0, 0, 1], 2)
    # y = 1: x^2 = 3, x = +-sqrt 3 from x = -5
    assert np.allclose(inf_cyl.hits([[-5, 1, 7]], [[1, 0, 0]]), [[5 - R3, 5 + R3]])
    # parallel to the axis: inside, no hit; outside, no hit
    assert np.all(np.isinf(inf_cyl.hits([[0.5, 0, 0], [3, 0, 0]], [[0, 0, 1], [0, 0, 1]])))
    c = S.Cylinder([0, 0, 1], [0, 0, 1], 1, height=2)          # 1 <= z <= 3
    # down the axis from z = 5: top cap at t = 2, bottom cap at t = 4
    assert np.allclose(c.hits([[0, 0, 5]], [[0, 0, -1]]), [[2, 4]])
    # oblique: enters the wall at x = -1 (z = 2), leaves through the top cap z = 3 at x = 0
    assert np.allclose(c.hits([[-2, 0, 1]], [[1, 0, 1]]), [[1, 2]])
    # tangent to the wall: one double hit; above the top: none
    assert np.allclose(c.hits([[-3, 1, 2]], [[1, 0, 0]]), [[3, 3]])
    assert np.all(np.isinf(c.hits([[-3, 0, 3.5]], [[1, 0, 0]])))
    # open tube: the ray down the axis meets nothing, the oblique one only the wall
    tube = S.Cylinder([0, 0, 1], [0, 0, 1], 1, height=2, capped=False)
    assert np.all(np.isinf(tube.hits([[0, 0, 5]], [[0, 0, -1]])))
    assert np.allclose(tube.hits([[-2, 0, 1]], [[1, 0, 1]]), [[1, np.inf]])
    # a tilted axis: the cylinder about (1, 1, 0)/sqrt 2 through the origin, radius 1; the ray along z
    # through (1, -1, 0)/sqrt 2 is at distance 1 from the axis (tangent), through the origin: t = -1, 1
    tilt = S.Cylinder([0, 0, 0], [1, 1, 0], 1)
    assert np.allclose(tilt.hits([[0, 0, -3]], [[0, 0, 1]]), [[2, 4]])
    assert c.contains([[0, 0, 2], [0, 0, 0.9], [0.9, 0, 2.9], [1.1, 0, 2]]).tolist() == [True, False, True, False]
    with pytest.raises(TypeError, match="uncapped"):
        tube.contains([[0, 0, 2]])


def test_cone_hits_by_hand():
    k = S.Cone([0, 0, 0], [0, 0, 1], 30)                       # radius z tan 30 = z / sqrt 3
    # at z = 3 the radius is sqrt 3
    assert np.allclose(k.hits([[-5, 0, 3]], [[1, 0, 0]]), [[5 - R3, 5 + R3]])
    # the other nappe (z < 0) is not part of the cone
    assert np.all(np.isinf(k.hits([[-5, 0, -3]], [[1, 0, 0]])))
    # up the axis from below: touches the apex (a double root at t = 1)
    assert np.allclose(k.hits([[0, 0, -1]], [[0, 0, 1]]), [[1, 1]])
    kb = S.Cone([0, 0, 0], [0, 0, 1], 45, height=2)            # radius z, base disc at z = 2
    # down the axis from z = 5: base disc at t = 3, apex at t = 5
    assert np.allclose(kb.hits([[0, 0, 5]], [[0, 0, -1]]), [[3, 5]])
    # horizontal at z = 1: x = +-1
    assert np.allclose(kb.hits([[-5, 0, 1]], [[1, 0, 0]]), [[4, 6]])
    # a ray parallel to a generator (A = 0): from (-3, 0, 0) along (1, 0, 1) it stays at distance...
    # x = -3 + t, z = t: |x| = z at t = 1.5 (x = -1.5); then leaves through the base z = 2 at t = 2
    assert np.allclose(kb.hits([[-3, 0, 0]], [[1, 0, 1]]), [[1.5, 2]])
    assert kb.contains([[0, 0, 1], [0.9, 0, 1], [1.1, 0, 1], [0, 0, 2.1]]).tolist() == [True, True, False, False]
    assert np.allclose(kb.normal([[1, 0, 1], [0.5, 0, 2]]), [[2 ** -0.5, 0, -(2 ** -0.5)], [0, 0, 1]])


def test_ellipsoid_hits_by_hand():
    e = S.Ellipsoid([1, 0, 0], [3, 2, 1])
    assert np.allclose(e.hits([[1, -5, 0]], [[0, 1, 0]]), [[3, 7]])
    # z = 0.5: (x/3)^2 = 0.75, x = 1 +- 3 sqrt(0.75)
    assert np.allclose(e.hits([[-5, 0, 0.5]], [[1, 0, 0]]), [[6 - 1.5 * R3, 6 + 1.5 * R3]])
    assert np.allclose(e.normal([[4, 0, 0], [1, 0, 1]]), [[1, 0, 0], [0, 0, 1]])
    # rotated: axes swap x and y, so the semi-axis 3 lies along y
    rot = S.Ellipsoid([0, 0, 0], [3, 2, 1], axes=[[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
    assert np.allclose(rot.hits([[0, -5, 0]], [[0, 1, 0]]), [[2, 8]])
    assert e.contains([[3.9, 0, 0], [1, 0, 1.1]]).tolist() == [True, False]


def test_elliptic_cylinder_and_cone_by_hand():
    ec = S.EllipticCylinder([0, 0, 0], [0, 0, 1], [2, 1], major=[1, 0, 0])
    # y = 0.5: (x/2)^2 = 0.75, x = +- sqrt 3
    assert np.allclose(ec.hits([[-5, 0.5, 0]], [[1, 0, 0]]), [[5 - R3, 5 + R3]])
    ek = S.EllipticCone([0, 0, 0], [0, 0, 1], [45, 30], major=[1, 0, 0])
    # at z = 3: x semi-axis 3, y semi-axis 3 tan 30 = sqrt 3
    assert np.allclose(ek.hits([[-5, 0, 3], [0, -5, 3]], [[1, 0, 0], [0, 1, 0]]), [[2, 8], [5 - R3, 5 + R3]])


def test_quadric_matches_the_special_surfaces():
    rng = np.random.default_rng(3)
    o, d = rng.normal(size=(300, 3)) * 3, rng.normal(size=(300, 3))
    sphere = S.Quadric([1, 1, 1, 0, 0, 0, -2, 0, 0, 1 - 4])          # (x-1)^2 + y^2 + z^2 = 4
    assert np.allclose(sphere.hits(o, d), S.Sphere([1, 0, 0], 2).hits(o, d), atol=1e-9, equal_nan=False)
    Q = np.diag([1.0, 1.0, 0.0, -1.0])                                # x^2 + y^2 = 1, as a matrix
    assert np.allclose(S.Quadric(Q).hits(o, d), S.Cylinder([0, 0, 0], [0, 0, 1], 1).hits(o, d), atol=1e-9)
    # the hyperboloid of one sheet x^2 + y^2 - z^2 = 1: at z = 2, x^2 = 5 - y^2
    h = S.Quadric([1, 1, -1, 0, 0, 0, 0, 0, 0, -1])
    assert np.allclose(h.hits([[-5, 1, 2]], [[1, 0, 0]]), [[3, 7]])
    assert h.contains([[2, 0, 0], [0, 0, 0], [0, 0, 5]]).tolist() == [False, True, True]   # f <= 0: around the axis
    with pytest.raises(ValueError, match="symmetric"):
        S.Quadric([[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]])


def _torus_quartic(o, d, R, r):
    """The torus quartic along one ray, by polynomial arithmetic (numpy.polynomial, not the library)."""
    x, y, z = (Poly([o[k], d[k]]) for k in range(3))
    f = (x * x + y * y + z * z + R * R - r * r) ** 2 - 4 * R * R * (x * x + y * y)
    return f.coef[::-1]


def test_torus_by_hand_and_against_numpy_roots():
    T = S.Torus([0, 0, 0], [0, 0, 1], 2, 0.5)
    assert np.allclose(T.hits([[-5, 0, 0]], [[1, 0, 0]]), [[2.5, 3.5, 6.5, 7.5]])
    # along y at x = 2: through the tube's centre twice: y = +-0.5 around... y^2 + 4 = R^2 -> the core circle
    # at (2, 0): enters at z from above: the ray (2, 0, 3) down -z meets z = +-0.5: t = 2.5, 3.5
    assert np.allclose(T.hits([[2, 0, 3]], [[0, 0, -1]]), [[2.5, 3.5, np.inf, np.inf]])
    # tangent to the top of the tube (z = 0.5) along y at x = 2: a double root where y = 0
    assert np.allclose(T.hits([[2, -4, 0.5]], [[0, 1, 0]])[0, :2], [4, 4], atol=1e-6)
    rng = np.random.default_rng(19)
    center, axis, R, r = np.array([0.3, -0.2, 0.5]), np.array([0.2, 0.3, 1.0]), 1.5, 0.6
    T = S.Torus(center, axis, R, r)
    o = rng.normal(size=(400, 3)) * 3
    d = rng.normal(size=(400, 3))
    d[::3] = center + rng.normal(size=(134, 3)) * 0.8 - o[::3]         # a third aimed near the torus
    got = T.hits(o, d)
    w = axis / np.linalg.norm(axis)
    u = np.cross(w, [1.0, 0, 0]); u /= np.linalg.norm(u)
    v = np.cross(w, u)
    F = np.array([u, v, w])
    checked = 0
    for k in range(400):
        roots = np.roots(_torus_quartic((o[k] - center) @ F.T, d[k] @ F.T, R, r))
        if np.any((np.abs(roots.imag) > 1e-9) & (np.abs(roots.imag) < 1e-4)):
            continue                                                  # nearly tangent: real or not is a coin toss
        real = np.sort(roots.real[np.abs(roots.imag) <= 1e-9])
        expected = np.full(4, np.inf)
        expected[:len(real)] = real
        assert np.allclose(got[k], expected, rtol=1e-7, atol=1e-7), k
        checked += 1
    assert checked > 390
    assert np.isfinite(got).sum() > 200


def test_torus_bound_skips_work_and_changes_nothing():
    rng = np.random.default_rng(5)
    o = rng.normal(size=(2000, 3)) * 6
    d = rng.normal(size=(2000, 3))
    bounded, plain = S.Torus([0, 0, 0], [0, 0, 1], 1, 0.3), S.Torus([0, 0, 0], [0, 0, 1], 1, 0.3, bound=False)
    a, b = bounded.hits(o, d), plain.hits(o, d)
    assert plain.quartics_solved == 2000
    assert bounded.quartics_solved < 600                              # most random rays miss the bound
    assert np.array_equal(a, b)
    assert np.isfinite(a).any()


def _fd_gradient(f, P, h=1e-6):
    return np.stack([(f(P + h * e) - f(P - h * e)) / (2 * h) for e in np.eye(3)], -1)


IMPLICIT = {
    # name: (surface, implicit function written here, independent of the library)
    "sphere": (S.Sphere([0.2, 0.1, 0], 1.2), lambda P: ((P - [0.2, 0.1, 0]) ** 2).sum(-1) - 1.44),
    "cylinder": (S.Cylinder([0, 0, 0], [0, 0, 1], 1.1), lambda P: P[..., 0] ** 2 + P[..., 1] ** 2 - 1.21),
    "cone": (S.Cone([0, 0, -1], [0, 0, 1], 40), lambda P: P[..., 0] ** 2 + P[..., 1] ** 2
             - (P[..., 2] + 1) ** 2 * np.tan(np.radians(40)) ** 2),
    "ellipsoid": (S.Ellipsoid([0, 0, 0], [2, 1.5, 1]), lambda P: (P[..., 0] / 2) ** 2 + (P[..., 1] / 1.5) ** 2
                  + P[..., 2] ** 2 - 1),
    "quadric": (S.Quadric([1, -1, 1, 0.5, 0, 0, 0.2, 0, 0, -1]),
                lambda P: P[..., 0] ** 2 - P[..., 1] ** 2 + P[..., 2] ** 2 + 0.5 * P[..., 0] * P[..., 1]
                + 0.2 * P[..., 0] - 1),
    "torus": (S.Torus([0, 0, 0], [0, 0, 1], 1.5, 0.5), lambda P: ((P ** 2).sum(-1) + 2.25 - 0.25) ** 2
              - 9 * (P[..., 0] ** 2 + P[..., 1] ** 2)),
    "revolution": (S.SurfaceOfRevolution([0, 0, -1], [0, 0, 1], [0.5, 0.6, -0.2], 2, capped=False),
                   lambda P: P[..., 0] ** 2 + P[..., 1] ** 2
                   - (0.5 + 0.6 * (P[..., 2] + 1) - 0.2 * (P[..., 2] + 1) ** 2) ** 2),
}


@pytest.mark.parametrize("name", sorted(IMPLICIT))
def test_normals_are_the_gradient_of_the_implicit_equation(name):
    surface, f = IMPLICIT[name]
    rng = np.random.default_rng(11)
    o = rng.normal(size=(400, 3)) * 5
    d = rng.normal(size=(400, 3)) * 0.5 - o * 0.2
    t = surface.intersect(o, d)
    hit = np.isfinite(t)
    assert hit.sum() > 30
    P = o[hit] + t[hit, None] * d[hit]
    assert np.abs(f(P)).max() < 1e-6 * np.abs(_fd_gradient(f, P)).max()          # the hits lie on the surface
    g = _fd_gradient(f, P)
    g /= np.linalg.norm(g, axis=1, keepdims=True)
    n = surface.normal(P)
    assert np.allclose(n, g, atol=1e-5)
    # and each mesh's vertices lie on the surface
    pos, tri = surface.mesh(16)
    assert tri.min() >= 0 and tri.max() < len(pos)
    scale = np.abs(_fd_gradient(f, pos)).max()
    on_wall = np.abs(f(pos)) < (1e-2 if name == "quadric" else 1e-6) * scale   # marching tetrahedra interpolate
    assert on_wall.mean() > 0.5


def test_polygon_l_shape_inside_by_hand():
    L = S.Polygon([[0, 0, 1], [3, 0, 1], [3, 1, 1], [1, 1, 1], [1, 3, 1], [0, 3, 1]])
    assert not L.convex
    inside = [[0.5, 0.5, 1], [2.5, 0.5, 1], [0.5, 2.5, 1], [0.9, 0.9, 1]]
    outside = [[2, 2, 1], [1.5, 1.5, 1], [3.5, 0.5, 1], [-0.1, 1, 1], [0.5, 3.1, 1]]
    assert L.inside(inside).tolist() == [True] * 4
    assert L.inside(outside).tolist() == [False] * 5
    o = np.array(inside + outside) + [0, 0, 2]
    t = L.intersect(o, [[0, 0, -1]] * len(o))
    assert t.tolist() == [2.0] * 4 + [np.inf] * 5
    assert np.allclose(L.normal([[0.5, 0.5, 1]]), [[0, 0, 1]])
    pos, tri = L.mesh(8)
    area = np.abs(np.cross(pos[tri[:, 1]] - pos[tri[:, 0]], pos[tri[:, 2]] - pos[tri[:, 0]])[:, 2]).sum() / 2
    assert area == pytest.approx(5.0)                                 # the L's area: 3 + 2
    tri_ = S.Polygon([[0, 0, 0], [2, 0, 0], [0, 2, 0]])
    assert tri_.convex and tri_.inside([[0.5, 0.5, 0], [1.5, 1.5, 0], [1, 1, 0]]).tolist() == [True, False, True]
    with pytest.raises(ValueError, match="coplanar"):
        S.Polygon([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]])


def test_surface_of_revolution_by_hand():
    # a constant profile is the capped cylinder
    rng = np.random.default_rng(2)
    o, d = rng.normal(size=(300, 3)) * 3, rng.normal(size=(300, 3))
    sor = S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1.0], 2)
    cyl = S.Cylinder([0, 0, 0], [0, 0, 1], 1, height=2)
    assert np.allclose(sor.intersect(o, d), cyl.intersect(o, d), atol=1e-9)
    # r(z) = 2 - z on [0, 1]: a frustum; horizontal at z = 0.5 meets it at x = +-1.5
    fr = S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [2, -1], 1)
    assert np.allclose(fr.hits([[-5, 0, 0.5]], [[1, 0, 0]])[0, :2], [3.5, 6.5])
    # r(z) = 1 + z^2 on [-1, 1] (base at z = -1): the ray x = 1.5, y = 0 upward meets 1 + z^2 = 1.5 at z = +-sqrt .5
    vase = S.SurfaceOfRevolution([0, 0, -1], [0, 0, 1], [2, -2, 1], 2)     # 1 + (z+1-1)^2 in terms of z+1
    h = vase.hits([[1.5, 0, -3]], [[0, 0, 1]])[0]      # bottom cap (r = 2) at t = 2, the wall twice, top cap at t = 4
    assert np.allclose(h[:4], [2, 3 - np.sqrt(0.5), 3 + np.sqrt(0.5), 4])
    assert vase.contains([[0, 0, 0], [1.1, 0, 0], [1.1, 0, 0.9], [0, 0, 1.1]]).tolist() == [True, False, True, False]
    with pytest.raises(ValueError, match="positive"):
        S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1, -1], 2)


@pytest.mark.parametrize("bad, word", [
    (lambda: S.Cylinder([0, 0, 0], [0, 0, 0], 1), "axis"),
    (lambda: S.Cylinder([0, 0, 0], [0, 0, 1], -1), "radius"),
    (lambda: S.Cylinder([0, 0, 0], [0, 0, 1], 1, height=0), "height"),
    (lambda: S.Cone([0, 0, 0], [0, 0, 1], 90), "half_angle"),
    (lambda: S.Torus([0, 0, 0], [0, 0, 1], 1, 0), "r"),
    (lambda: S.Polygon([[0, 0, 0], [1, 0, 0], [2, 0, 0]]), "vertices"),
    (lambda: S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1] * 9, 1), "profile"),
    (lambda: S.Sphere([0, 0, 0], 1).mesh(10 ** 6), "resolution"),
])
def test_bad_input_ch19(bad, word):
    with pytest.raises(ValueError, match=word):
        bad()


def test_bounding_spheres_enclose_the_meshes():
    surfaces = [S.Sphere([1, 0, 0], 2), S.Cylinder([0, 0, 1], [1, 1, 0], 0.5, height=3),
                S.Cone([0, 0, 0], [0, 1, 0], 35, height=2), S.Ellipsoid([0, 1, 0], [1, 2, 3]),
                S.Torus([0, 0, 1], [1, 0, 0], 2, 0.5), S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1, 1, -0.5], 2),
                S.Polygon([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]),
                S.EllipticCone([0, 0, 0], [0, 0, 1], [50, 20], height=1.5)]
    for s in surfaces:
        c, r = s.bounding_sphere
        pos, _ = s.mesh(24)
        assert np.linalg.norm(pos - c, axis=1).max() <= r * (1 + 1e-9), type(s).__name__
    assert S.Cylinder([0, 0, 0], [0, 0, 1], 1).bounding_sphere is None


def test_surface_of_revolution_against_numpy_roots_with_the_bound():
    rng = np.random.default_rng(71)
    c, h = [0.8, -0.6, 0.3125], 1.6
    sor = S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], c, h, capped=False)
    o = rng.normal(size=(300, 3)) * 3
    d = rng.uniform(-1.5, 1.5, (300, 3)) + [0, 0, 0.8] - o
    got = sor.hits(o, d)
    checked = 0
    for k in range(300):
        x, y, z = (Poly([o[k, i], d[k, i]]) for i in range(3))
        g = x * x + y * y - (c[0] + c[1] * z + c[2] * z * z) ** 2
        r = np.roots(g.coef[::-1])
        if np.any((np.abs(r.imag) > 1e-9) & (np.abs(r.imag) < 1e-4)):
            continue
        real = np.sort(r.real[np.abs(r.imag) <= 1e-9])
        zs = o[k, 2] + real * d[k, 2]
        keep = real[(zs >= 1e-7) & (zs <= h - 1e-7)]
        mine = got[k][np.isfinite(got[k])]
        assert len(mine) == len(keep) and np.allclose(mine, keep, rtol=1e-7, atol=1e-7), k
        checked += 1
    assert checked > 280 and np.isfinite(got).any(axis=1).sum() > 50


# -- §19.4.1 the geometric line-sphere method -----------------------------------------------------------------


def test_the_geometric_line_sphere_method_finds_the_quadratics_roots():
    rng = np.random.default_rng(1941)
    o = rng.uniform(-5, 5, (400, 3))
    d = rng.normal(size=(400, 3)) * rng.uniform(0.1, 3.0, (400, 1))
    c, r = np.array([0.5, -1.0, 2.0]), 2.5
    geo = S.line_sphere_geometric(o, d, c, r)
    alg = S.Sphere(c, r).hits(o, d)
    both = np.isfinite(alg[:, 0])
    assert both.sum() > 50 and (~both).sum() > 50                # hits and misses both tried
    assert np.array_equal(np.isfinite(geo["t"][:, 0]), both)
    assert np.allclose(geo["t"][both], alg[both], rtol=1e-9, atol=1e-9)
    # the foot is the nearest point: its distance is the line's distance to the centre
    foot = o + geo["foot"][:, None] * d
    assert np.allclose(np.einsum("ij,ij->i", c - foot, d), 0.0, atol=1e-9)
    # miss exactly when the distance exceeds the radius
    assert np.array_equal(geo["distance"] <= r, both)


def test_the_geometric_method_by_hand():
    # the line y = 1.2 and a circle of radius 2 about the origin: q = 1.2, half-chord sqrt(4 - 1.44) = 1.6
    r = S.line_sphere_geometric([-5.0, 1.2, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 0.0], 2.0)
    assert r["foot"].tolist() == [2.5] and r["distance"].tolist() == pytest.approx([1.2])
    assert r["t"].tolist()[0] == pytest.approx([(5 - 1.6) / 2, (5 + 1.6) / 2])
    tangent = S.line_sphere_geometric([-5.0, 2.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], 2.0)
    assert tangent["t"].tolist() == [[5.0, 5.0]]


def test_the_geometric_method_refuses_bad_input():
    with pytest.raises(ValueError, match="radius"):
        S.line_sphere_geometric([0, 0, 0], [1, 0, 0], [0, 0, 0], -1.0)
    with pytest.raises(ValueError, match="directions"):
        S.line_sphere_geometric([0, 0, 0], [0, 0, 0], [0, 0, 0], 1.0)
