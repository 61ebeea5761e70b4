"""goldman_lib.surfaces (Goldman chapter 18) against closed forms and numpy.roots: curvature of spheres,
cylinders and tori in implicit and parametric form, ray hits of implicit spheres and tori against the
roots of their quadratic and quartic in t, Newton on parametric surfaces, normals of deformed surfaces
by the inverse transpose against differences of the deformed parametrisation.

Sign convention (module docstring): H = -1/r on a sphere with outward normals; tests compare |H|
against the closed forms and check that the implicit and parametric forms agree in sign."""

import numpy as np
import pytest

from goldman_lib import surfaces as sf


def sphere_points(r, n=50, seed=0):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return r * p / np.linalg.norm(p, axis=1)[:, None]


def test_sphere_curvature_both_forms():
    for r in (0.5, 2.0, 7.0):
        s = sf.implicit_sphere([1.0, -2.0, 0.5], r)
        P = sphere_points(r) + [1.0, -2.0, 0.5]
        H, K = sf.curvature_implicit(s.f, s.grad, s.hess, P)
        assert np.allclose(K, 1 / r ** 2) and np.allclose(np.abs(H), 1 / r)
        H2, K2 = sf.curvature_implicit(s.f, None, None, P)             # central differences of f
        assert np.allclose(K2, 1 / r ** 2, rtol=1e-5) and np.allclose(np.abs(H2), 1 / r, rtol=1e-5)
        u, v = np.meshgrid(np.linspace(0, 6, 7), np.linspace(-1.4, 1.4, 5))
        Hp, Kp = sf.parametric_sphere(r).curvature(u, v)
        assert Hp.shape == u.shape
        assert np.allclose(Kp, 1 / r ** 2, rtol=1e-6) and np.allclose(np.abs(Hp), 1 / r, rtol=1e-6)
        assert np.all(np.sign(Hp) == np.sign(H[0]))                     # both forms: outward normals, same sign


def test_cylinder_curvature_both_forms():
    for r in (0.4, 1.5):
        c = sf.implicit_cylinder(r)
        ang = np.linspace(0, 6, 9)
        P = np.stack([r * np.cos(ang), r * np.sin(ang), np.linspace(-1, 1, 9)], -1)
        H, K = c.curvature(P)
        assert np.allclose(K, 0, atol=1e-12) and np.allclose(np.abs(H), 1 / (2 * r))
        Hp, Kp = sf.parametric_cylinder(r).curvature(ang, np.linspace(-0.5, 0.5, 9))
        assert np.allclose(Kp, 0, atol=1e-6) and np.allclose(np.abs(Hp), 1 / (2 * r), rtol=1e-6)
        assert np.allclose(Hp, H, rtol=1e-6)


def torus_point(R, r, u, v):
    return np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)], -1)


def test_torus_curvature_both_forms_against_the_closed_form():
    R, r = 2.0, 0.6
    u, v = np.meshgrid(np.linspace(0, 6.2, 8), np.linspace(0, 6.2, 11))
    u, v = u.ravel(), v.ravel()
    K_exact = np.cos(v) / (r * (R + r * np.cos(v)))
    H_exact = (R + 2 * r * np.cos(v)) / (2 * r * (R + r * np.cos(v)))   # |H|
    Hp, Kp = sf.parametric_torus(R, r).curvature(u, v)
    assert np.allclose(Kp, K_exact, atol=1e-6) and np.allclose(np.abs(Hp), H_exact, atol=1e-6)
    t = sf.implicit_torus(R, r)
    Hi, Ki = t.curvature(torus_point(R, r, u, v))
    assert np.allclose(Ki, K_exact, atol=1e-9) and np.allclose(np.abs(Hi), H_exact, atol=1e-9)
    assert np.allclose(Hi, Hp, atol=1e-6)
    # outer equator by hand: K = 1/(r (R + r)), |H| = (R + 2r)/(2 r (R + r))
    assert Ki[np.argmin(np.abs(v - 0) + np.abs(u))] == pytest.approx(1 / (0.6 * 2.6))


def test_saddle_and_paraboloid_by_hand():
    # z = x^2 - y^2 at the origin: principal curvatures 2 and -2: K = -4, H = 0
    H, K = sf.parametric_graph(lambda u, v: u * u - v * v).curvature(0.0, 0.0)
    assert K == pytest.approx(-4.0, abs=1e-6) and H == pytest.approx(0.0, abs=1e-6)
    # z = x^2 + y^2: both 2 at the origin: K = 4, |H| = 2
    H, K = sf.parametric_graph(lambda u, v: u * u + v * v).curvature(0.0, 0.0)
    assert K == pytest.approx(4.0, abs=1e-6) and abs(H) == pytest.approx(2.0, abs=1e-6)


def test_normals_by_gradient_and_cross_product():
    assert np.allclose(sf.implicit_normal(lambda P: 2 * P, [[0.0, 0.0, -3.0]]), [[0, 0, -1]])
    n = sf.parametric_sphere(1.0).normal_at(np.pi / 2, np.pi / 4)
    assert np.allclose(n, [0, np.sqrt(0.5), np.sqrt(0.5)])
    # the torus normal (cos u cos v, sin u cos v, sin v), outward
    u, v = 0.7, 2.1
    assert np.allclose(sf.parametric_torus(2.0, 0.5).normal_at(u, v),
                       [np.cos(u) * np.cos(v), np.sin(u) * np.cos(v), np.sin(v)], atol=1e-8)
    assert np.allclose(sf.implicit_torus(2.0, 0.5).normal([torus_point(2.0, 0.5, u, v)]),
                       [[np.cos(u) * np.cos(v), np.sin(u) * np.cos(v), np.sin(v)]])


def test_implicit_sphere_hits_against_numpy_roots():
    rng = np.random.default_rng(3)
    o = rng.uniform(-4, 4, (200, 3))
    d = rng.normal(size=(200, 3))
    c, r = np.array([0.3, -0.2, 0.1]), 1.7
    got = sf.implicit_sphere(c, r).hits(o, d)
    for k in range(200):
        oc = o[k] - c
        roots = np.roots([d[k] @ d[k], 2 * d[k] @ oc, oc @ oc - r * r])
        real = np.sort(roots[np.abs(roots.imag) < 1e-9].real)
        if len(real) == 2 and abs(real[0] - real[1]) > 1e-6:
            assert np.allclose(got[k], real, atol=1e-9)
        elif len(real) == 0:
            assert np.all(np.isinf(got[k]))


def test_implicit_torus_hits_against_the_roots_of_its_quartic():
    R, r = 1.5, 0.5
    torus = sf.implicit_torus(R, r)
    rng = np.random.default_rng(4)
    o = rng.uniform(-3, 3, (150, 3))
    d = rng.normal(size=(150, 3))
    got = torus.hits(o, d)
    checked = 0
    for k in range(150):
        ox, oy, oz = o[k]
        dx, dy, dz = d[k]
        # |o + t d|^2 + R^2 - r^2 = a t^2 + b t + c;  x^2 + y^2 = e t^2 + f t + g
        a, b, c = d[k] @ d[k], 2 * o[k] @ d[k], o[k] @ o[k] + R * R - r * r
        e, f, g = dx * dx + dy * dy, 2 * (ox * dx + oy * dy), ox * ox + oy * oy
        quartic = np.polysub(np.polymul([a, b, c], [a, b, c]), 4 * R * R * np.array([e, f, g]))
        roots = np.roots(quartic)
        real = np.sort(roots[np.abs(roots.imag) < 1e-7].real)
        if len(real) and np.min(np.diff(np.r_[real, np.inf])) < 1e-3:
            continue                                  # a near-tangent ray: two close roots
        finite = got[k][np.isfinite(got[k])]
        assert len(finite) == len(real) and np.allclose(finite, real, atol=1e-8), (k, finite, real)
        checked += 1
    assert checked > 100


def test_parametric_newton_hits_and_the_contract():
    sphere = sf.parametric_sphere(1.0)
    t, n = sphere.hit([[0.2, 0.1, -5.0], [3.0, 3.0, -5.0]], [[0, 0, 1.0], [0, 0, 1.0]])
    z = -np.sqrt(1 - 0.05)
    assert t[0] == pytest.approx(5 + z, abs=1e-9) and np.allclose(n[0], [0.2, 0.1, z], atol=1e-8)
    assert np.isinf(t[1]) and np.all(n[1] == 0)
    torus = sf.parametric_torus(2.0, 0.5)
    o = np.array([[5.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 5.0, 0.3]])
    d = np.array([[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
    implicit = sf.implicit_torus(2.0, 0.5)
    assert np.allclose(torus.intersect(o, d), implicit.intersect(o, d), atol=1e-8)
    found = torus.hits(o[:1], d[:1])[0]
    found = found[np.isfinite(found)]                 # the roots Newton reached: true ones, the nearest first
    assert len(found) >= 2 and found[0] == pytest.approx(2.5, abs=1e-8)
    assert all(np.min(np.abs(t - np.array([2.5, 3.5, 6.5, 7.5]))) < 1e-8 for t in found)
    # the normal of a point found by its parameters
    P = torus.point(0.4, 1.0)
    assert np.allclose(torus.normal([P]), [torus.normal_at(0.4, 1.0)], atol=1e-8)


def test_deformed_normals_by_the_inverse_transpose():
    # a linear stretch: the plane x + y = 0 (normal (1, 1, 0)) under x -> 2x becomes x/2 + y = 0
    n = sf.deformed_normals([np.diag([2.0, 1.0, 1.0])], [[1.0, 1.0, 0.0]])
    assert np.allclose(n, [[1, 2, 0]] / np.sqrt(5))
    # twisted and tapered tori: the inverse transpose against the cross product of the deformed
    # parametrisation's partial derivatives (finite differences of A(X(u, v)))
    torus = sf.parametric_torus(1.0, 0.3)
    for A in (sf.twist(60.0), sf.taper(0.4)):
        u, v = np.array([0.3, 2.0, 4.0]), np.array([0.5, 3.0, 5.5])
        P = torus.point(u, v)
        mapped = A.normals(P, torus.normal_at(u, v))
        h = 1e-6
        Y = lambda uu, vv: A.apply(torus.point(uu, vv))  # noqa: E731
        Yu = (Y(u + h, v) - Y(u - h, v)) / (2 * h)
        Yv = (Y(u, v + h) - Y(u, v - h)) / (2 * h)
        cross = np.cross(Yu, Yv)
        assert np.allclose(mapped, cross / np.linalg.norm(cross, axis=1)[:, None], atol=1e-7)
        # the plain transform of the normal (J n) is NOT normal to the tapered surface
        if A.name.startswith("taper"):
            wrong = np.einsum("nij,nj->ni", A.jacobian(P), torus.normal_at(u, v))
            assert np.abs(np.einsum("ij,ij->i", wrong, Yv)).max() > 1e-3
    with pytest.raises(ValueError, match="jacobians"):
        sf.deformed_normals([np.zeros((3, 3))], [[1.0, 0, 0]])


def test_deformed_surface_is_hit_where_the_deformed_points_are():
    base = sf.implicit_sphere([0, 0, 0], 1.0)
    for A in (sf.twist(90.0), sf.taper(0.5)):
        s = sf.DeformedSurface(base, A)
        P = sphere_points(1.0, 20, seed=5)
        Q = A.apply(P)
        assert np.allclose(s.value(Q), 0, atol=1e-12)
        # rays aimed at the deformed points from outside the bound find them (first or a later hit)
        o = Q + 4 * Q / np.linalg.norm(Q, axis=1)[:, None]
        t = s.hits(o, Q - o)
        assert np.all(np.min(np.abs(t - 1.0), axis=1) < 1e-9)
        # normals of the implicit deformed surface = the base normals by the inverse transpose
        assert np.allclose(s.normal(Q), A.normals(P, base.normal(P)), atol=1e-9)


def test_fractal_heights_are_seeded_and_rougher_with_roughness():
    a = sf.fractal_heights(5, 0.5, rng=7)
    assert np.array_equal(a, sf.fractal_heights(5, 0.5, rng=7)) and a.shape == (33, 33)
    smooth, rough = sf.fractal_heights(6, 0.3, rng=1), sf.fractal_heights(6, 0.9, rng=1)
    assert np.abs(np.diff(rough, axis=0)).mean() > np.abs(np.diff(smooth, axis=0)).mean()
    with pytest.raises(ValueError, match="level"):
        sf.fractal_heights(40)
    p, t = sf.height_field_mesh(a)
    assert p.shape == (33 * 33, 3) and t.shape == (2 * 32 * 32, 3)


def test_bad_input_is_named():
    with pytest.raises(TypeError, match="f"):
        sf.ImplicitSurface(3.0)
    with pytest.raises(ValueError, match="samples"):
        sf.ImplicitSurface(lambda P: P[:, 0], samples=1)
    with pytest.raises(ValueError, match="singular"):
        sf.curvature_implicit(lambda P: (P ** 2).sum(1), None, None, [[0.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="r must be smaller"):
        sf.implicit_torus(1.0, 2.0)
    with pytest.raises(ValueError, match=r"X\(u, v\) must return"):
        sf.curvature_parametric(lambda u, v: np.zeros(2), 0.1, 0.2)


# -- §18.3.3 deformed surfaces: map the ray back (instancing) ---------------------------------------------------


def test_an_affine_instance_of_the_unit_sphere_is_the_ellipsoid():
    from goldman_lib.simple_surfaces import Ellipsoid, Sphere

    theta = np.radians(30.0)
    R = np.array([[np.cos(theta), np.sin(theta), 0.0], [-np.sin(theta), np.cos(theta), 0.0], [0.0, 0.0, 1.0]])
    radii, centre = np.array([3.0, 2.0, 0.5]), np.array([1.0, -0.5, 2.0])
    inst = sf.AffineInstance(Sphere([0, 0, 0], 1.0), np.diag(radii) @ R, centre)
    ell = Ellipsoid(centre, radii, axes=R)                    # an independent implementation (§19.4.4)
    rng = np.random.default_rng(1833)
    o = rng.uniform(-6, 6, (300, 3))
    d = centre + rng.uniform(-2, 2, (300, 3)) - o                # aimed near the centre: most rays hit
    a, b = inst.hits(o, d), ell.hits(o, d)
    hit = np.isfinite(b[:, 0])
    assert 40 < hit.sum() < 290 and np.array_equal(np.isfinite(a[:, 0]), hit)
    assert np.allclose(a[hit], b[hit], rtol=1e-9, atol=1e-9)
    P = o[hit] + a[hit, :1] * d[hit]
    assert np.allclose(inst.normal(P), ell.normal(P), atol=1e-9)
    assert np.array_equal(inst.contains(P + 0.01 * ell.normal(P)), np.zeros(len(P), bool))


def test_the_ray_mapped_back_keeps_its_parameter():
    from goldman_lib.simple_surfaces import Sphere

    M = np.array([[1.0, 0.4, 0.0], [0.0, 1.0, 0.0], [0.2, 0.0, 2.0]])      # a shear and a stretch
    inst = sf.AffineInstance(Sphere([0.5, 0, 0], 1.0), M, [0.0, 1.0, 0.0])
    o, d = np.array([[-4.0, 1.2, 0.3]]), np.array([[1.0, 0.0, 0.1]])
    t = inst.intersect(o, d)[0]
    Q = o[0] + t * d[0]
    # the hit lies on the image: its preimage lies on the base sphere
    assert np.linalg.norm(inst.undo(Q[None])[0] - [0.5, 0, 0]) == pytest.approx(1.0, abs=1e-9)


def test_a_singular_map_is_refused():
    from goldman_lib.simple_surfaces import Sphere

    with pytest.raises(ValueError, match="M must be invertible"):
        sf.AffineInstance(Sphere([0, 0, 0], 1.0), np.diag([1.0, 1.0, 0.0]))
    with pytest.raises(TypeError, match="base"):
        sf.AffineInstance("sphere", np.eye(3))


# -- §18.4.3 curvature of deformed surfaces, by formula ---------------------------------------------------


def ellipsoid_points(radii, n=40, seed=3):
    return sphere_points(1.0, n, seed) * np.asarray(radii)


def test_curvature_of_a_stretched_sphere_is_the_ellipsoids_closed_form():
    a, b, c = radii = np.array([3.0, 2.0, 0.5])
    s = sf.implicit_sphere([0, 0, 0], 1.0)
    Q = ellipsoid_points(radii)
    H, K = sf.curvature_deformed(s.f, s.grad, s.hess, np.diag(radii), Q)
    x, y, z = Q.T
    h2 = x ** 2 / a ** 4 + y ** 2 / b ** 4 + z ** 2 / c ** 4
    K_closed = 1 / (a * a * b * b * c * c * h2 ** 2)                     # the ellipsoid's Gaussian curvature
    H_closed = np.abs(x * x + y * y + z * z - a * a - b * b - c * c) / (2 * (a * b * c) ** 2 * h2 ** 1.5)
    assert np.allclose(K, K_closed, rtol=1e-12) and np.allclose(np.abs(H), H_closed, rtol=1e-12)
    assert np.all(H < 0)                                                  # outward normals, as the sphere's
    # by hand at the vertex (3, 0, 0): principal curvatures a/b^2 = 3/4 and a/c^2 = 12
    Hv, Kv = sf.curvature_deformed(s.f, s.grad, s.hess, np.diag(radii), [[3.0, 0.0, 0.0]])
    assert Kv[0] == pytest.approx(9.0) and Hv[0] == pytest.approx(-(0.75 + 12.0) / 2)


def test_curvature_of_a_sheared_torus_against_differences_of_the_deformed_surface():
    T = sf.implicit_torus(1.0, 0.4)
    M = np.array([[1.0, 0.3, 0.0], [0.0, 1.5, 0.0], [0.8, -0.2, 0.7]])    # a shear, a stretch and a squash
    shift = np.array([0.5, -1.0, 2.0])
    u, v = np.meshgrid(np.linspace(0.1, 6.0, 7), np.linspace(0.2, 6.1, 6))
    P = sf.parametric_torus(1.0, 0.4).point(u.ravel(), v.ravel())
    Q = P @ M + shift
    H, K = sf.curvature_deformed(T.f, T.grad, T.hess, M, Q, shift)
    M_inv = np.linalg.inv(M)

    def G(X):                                                               # the deformed surface, G = f o A^-1
        return T.f((X - shift) @ M_inv)

    H_fd, K_fd = sf.curvature_implicit(G, None, None, Q)                 # central differences of G alone
    assert np.allclose(K, K_fd, rtol=1e-5, atol=1e-6) and np.allclose(H, H_fd, rtol=1e-5, atol=1e-6)
    assert np.any(K < 0) and np.any(K > 0)                                 # saddles inside, eggs outside


def test_curvature_under_a_rigid_motion_and_a_uniform_scale():
    T = sf.implicit_torus(2.0, 0.5)
    P = sf.parametric_torus(2.0, 0.5).point(np.linspace(0, 6, 11), np.linspace(0.3, 5.9, 11))
    H0, K0 = T.curvature(P)
    th = np.radians(40.0)
    Rot = np.array([[np.cos(th), 0.0, -np.sin(th)], [0.0, 1.0, 0.0], [np.sin(th), 0.0, np.cos(th)]])
    H1, K1 = sf.curvature_deformed(T.f, T.grad, T.hess, Rot, P @ Rot + [1.0, 2.0, 3.0], [1.0, 2.0, 3.0])
    assert np.allclose(H1, H0, atol=1e-12) and np.allclose(K1, K0, atol=1e-12)
    H2, K2 = sf.curvature_deformed(T.f, T.grad, T.hess, 3.0 * np.eye(3), 3.0 * P)
    assert np.allclose(H2, H0 / 3, atol=1e-12) and np.allclose(K2, K0 / 9, atol=1e-12)


def test_curvature_deformed_refuses_a_singular_map():
    s = sf.implicit_sphere([0, 0, 0], 1.0)
    with pytest.raises(ValueError, match="M must be invertible"):
        sf.curvature_deformed(s.f, s.grad, s.hess, np.diag([1.0, 0.0, 1.0]), [[1.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="M must be a 3x3"):
        sf.curvature_deformed(s.f, s.grad, s.hess, np.eye(2), [[1.0, 0.0, 0.0]])


# -- §18.2 / §18.3.3: the normal of an affine instance, right and wrong -----------------------------------


SHEAR = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.2, 0.0, 1.0]])      # x' = x + 1.2 z


def _tangents(n):
    """Two unit tangents of the unit sphere at points with unit normals n (independent of the library)."""
    a = np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    t1 = np.cross(n, a)
    t1 /= np.linalg.norm(t1, axis=1)[:, None]
    return t1, np.cross(n, t1)


def test_the_default_normal_map_is_unchanged_and_perpendicular():
    from goldman_lib.simple_surfaces import Sphere

    P = sphere_points(1.0, 60, seed=5)
    right = sf.AffineInstance(Sphere([0, 0, 0], 1.0), SHEAR, [0.0, 0.0, 1.0])
    assert right.normal_map == "inverse transpose"
    Q = P @ SHEAR + [0.0, 0.0, 1.0]
    n = right.normal(Q)
    expected = P @ np.linalg.inv(SHEAR).T
    assert np.allclose(n, expected / np.linalg.norm(expected, axis=1)[:, None], atol=1e-12)
    t1, t2 = _tangents(P)
    assert np.abs(np.einsum("ij,ij->i", n, t1 @ SHEAR)).max() < 1e-12     # perpendicular to mapped tangents
    assert np.abs(np.einsum("ij,ij->i", n, t2 @ SHEAR)).max() < 1e-12
    assert right.normal_error(Q).max() < 1e-9


def test_the_linear_part_normal_leans_off_the_surface_by_the_measured_angle():
    from goldman_lib.simple_surfaces import Sphere

    P = sphere_points(1.0, 60, seed=5)
    wrong = sf.AffineInstance(Sphere([0, 0, 0], 1.0), SHEAR, normal_map="linear part")
    Q = P @ SHEAR
    n = wrong.normal(Q)
    assert np.allclose(n, (P @ SHEAR) / np.linalg.norm(P @ SHEAR, axis=1)[:, None], atol=1e-12)
    t1, t2 = _tangents(P)
    off = np.maximum(np.abs(np.einsum("ij,ij->i", n, t1 @ SHEAR)), np.abs(np.einsum("ij,ij->i", n, t2 @ SHEAR)))
    assert off.max() > 0.3                                                  # not perpendicular to the surface
    # the angle error against the cross product of two mapped tangents (the image's true normal)
    true = np.cross(t1 @ SHEAR, t2 @ SHEAR)
    true *= np.sign(np.einsum("ij,ij->i", true, P @ np.linalg.inv(SHEAR).T))[:, None]
    cos = np.einsum("ij,ij->i", n, true) / np.linalg.norm(true, axis=1)
    expected = np.degrees(np.arccos(np.clip(cos, -1, 1)))
    assert np.allclose(wrong.normal_error(Q), expected, atol=1e-6)
    assert 30 < wrong.normal_error(Q).max() < 90
    # where the shear does not act (the normal (0, 1, 0) at (0, 1, 0)) the two agree
    assert wrong.normal_error([[0.0, 1.0, 0.0]])[0] == pytest.approx(0.0, abs=1e-9)


def test_a_rotation_times_a_uniform_scale_maps_normals_either_way():
    from goldman_lib.simple_surfaces import Sphere

    th = np.radians(25.0)
    M = 2.0 * np.array([[np.cos(th), np.sin(th), 0.0], [-np.sin(th), np.cos(th), 0.0], [0.0, 0.0, 1.0]])
    wrong = sf.AffineInstance(Sphere([0, 0, 0], 1.0), M, normal_map="linear part")
    assert wrong.normal_error(sphere_points(1.0, 20) @ M).max() < 1e-9


def test_the_normal_map_is_validated():
    from goldman_lib.simple_surfaces import Sphere

    for bad in ("transpose", "inverse-transpose", None, 1):
        with pytest.raises(ValueError, match="normal_map must be one of"):
            sf.AffineInstance(Sphere([0, 0, 0], 1.0), SHEAR, normal_map=bad)
