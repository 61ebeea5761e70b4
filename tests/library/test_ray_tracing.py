"""Recursive ray tracing (Goldman ch. 17) against closed forms and values worked by hand."""

import dataclasses
import math

import numpy as np
import pytest

from goldman_lib import ray_tracing as rt
from goldman_lib.camera import Camera
from goldman_lib.lighting import Light, Material
from goldman_lib.simple_surfaces import Plane, Sphere


def _angle_to(v, axis):
    v, axis = np.asarray(v, float), np.asarray(axis, float)
    return math.degrees(math.acos(abs(v @ axis) / np.linalg.norm(v) / np.linalg.norm(axis)))


# -- Snell's law and total internal reflection (§17.5) -----------------------------------------------

def test_refract_thirty_degrees_into_glass_by_hand():
    # sin 30 = 1/2, so sin(theta2) = (1/2) / 1.5 = 1/3 and cos(theta2) = sqrt(8)/3
    d = [math.sin(math.radians(30)), 0.0, -math.cos(math.radians(30))]
    T = rt.refract(d, [0, 0, 1], 1.0, 1.5)
    assert T == pytest.approx([1 / 3, 0.0, -math.sqrt(8) / 3], abs=1e-12)
    # the normal may be given on either side
    assert rt.refract(d, [0, 0, -1], 1.0, 1.5) == pytest.approx(T, abs=1e-12)
    # and the ray runs back the way it came (reversibility of light)
    back = rt.refract([-T[0], 0.0, -T[2]], [0, 0, 1], 1.5, 1.0)
    assert back == pytest.approx([-d[0], 0.0, -d[2]], abs=1e-12)


def test_snell_sine_ratio_over_many_angles_and_indices():
    rng = np.random.default_rng(17)
    for _ in range(200):
        theta1 = rng.uniform(0, 89)
        n1, n2 = rng.uniform(1.0, 2.5, size=2)
        azimuth = rng.uniform(0, 2 * np.pi)
        d = np.array([math.sin(math.radians(theta1)) * math.cos(azimuth),
                      math.sin(math.radians(theta1)) * math.sin(azimuth), -math.cos(math.radians(theta1))])
        T = rt.refract(3.0 * d, [0, 0, 2.0], n1, n2)
        s2 = n1 / n2 * math.sin(math.radians(theta1))
        if s2 > 1:
            assert T is None
            continue
        T = np.asarray(T)
        assert np.linalg.norm(T) == pytest.approx(1.0, abs=1e-12)
        assert T[2] < 0                                              # it goes on through the surface
        assert n1 * math.sin(math.radians(theta1)) == pytest.approx(n2 * math.sin(math.radians(_angle_to(T, [0, 0, 1]))),
                                                                     abs=1e-9)
        # the refracted ray stays in the plane of incidence (same azimuth)
        assert abs(np.cross(d, T) @ [0, 0, 1]) < 1e-12 or np.cross(d, T) @ np.cross([0, 0, 1], d) > -1e-12


def test_critical_angle_and_total_internal_reflection():
    assert rt.critical_angle(1.5, 1.0) == pytest.approx(math.degrees(math.asin(2 / 3)), abs=1e-12)
    assert rt.critical_angle(1.5, 1.0) == pytest.approx(41.8103149, abs=1e-6)
    assert rt.critical_angle(1.33, 1.33) is None and rt.critical_angle(1.0, 2.4) is None
    for theta, passes in ((41.7, True), (41.9, False), (60.0, False), (0.0, True)):
        d = [math.sin(math.radians(theta)), 0.0, -math.cos(math.radians(theta))]
        assert (rt.refract(d, [0, 0, 1], 1.5, 1.0) is not None) == passes
    # just below the critical angle the refracted ray grazes the surface (theta2 near 90 degrees)
    d = [math.sin(math.radians(41.81)), 0.0, -math.cos(math.radians(41.81))]
    assert _angle_to(rt.refract(d, [0, 0, 1], 1.5, 1.0), [0, 0, 1]) > 88.0
    T, tir = rt.refract_rays([[1, 0, -1], [0, 1, -1], [0, 0, -1]], [[0, 0, 1]] * 3, [1.5, 1.0, 1.5], 1.0)
    assert tir.tolist() == [True, False, False] and np.all(T[0] == 0)


def test_refract_refuses_bad_input_by_name():
    with pytest.raises(ValueError, match="n2"):
        rt.refract([0, 0, -1], [0, 0, 1], 1.0, 0.0)
    with pytest.raises(ValueError, match="direction"):
        rt.refract([0, 0, 0], [0, 0, 1], 1.0, 1.5)
    with pytest.raises(ValueError, match="n1"):
        rt.refract_rays([[0, 0, -1]] * 2, [[0, 0, 1]] * 2, [1.0, 1.0, 1.0], 1.5)


# -- the camera and the tracer ---------------------------------------------------------------------

def _rays(camera, width, height):
    """The primary rays of ``camera`` at ``width`` x ``height``, flat: origins and directions (h*w, 3)."""
    eye, d = dataclasses.replace(camera, width=width, height=height).rays()
    d = d.reshape(-1, 3)
    return np.broadcast_to(eye, d.shape).copy(), d


def test_render_sizes_the_camera_and_checks_its_eye():
    # the image size is the camera's; width and height override it (the same view, more pixels)
    scene, cam = _one_sphere(), Camera((0, -5, 0), (0, 0, 0), fov=30, width=6, height=4)
    assert rt.render(scene, cam, depth=0).shape == (4, 6, 3)
    assert np.array_equal(rt.render(scene, cam, 12, 8, depth=0),
                          rt.render(scene, dataclasses.replace(cam, width=12, height=8), depth=0))
    assert rt.default_camera().width == 160 and rt.render(scene, rt.default_camera(), depth=0).shape == (120, 160, 3)
    with pytest.raises(ValueError, match=r"camera\.eye"):
        rt.render(scene, Camera((0, -1e61, 0), (0, 0, 0)), 4, 3)
    with pytest.raises(TypeError, match="goldman_lib.camera.Camera"):
        rt.ray_cast(scene, object(), 4, 3)


def _one_sphere(light=(0.0, -5.0, 5.0)):
    m = Material(colour=(1.0, 0.5, 0.25), ambient=0.2, diffuse=0.6, specular=0.3, exponent=10)
    return rt.Scene([Sphere((0, 0, 0), 1, m)], [Light(light)], ambient_light=0.5, background=(0, 0, 0))


def test_one_sphere_centre_pixel_by_hand():
    scene = _one_sphere()
    cam = Camera((0, -5, 0), (0, 0, 0), fov=30)
    img = rt.render(scene, cam, 5, 5, depth=2)
    # the centre ray hits (0, -1, 0) with N = (0, -1, 0); L = (0, -4, 5)/sqrt(41), so L.N = 4/sqrt(41);
    # R = 2 (L.N) N - L = (0, -4, -5)/sqrt(41), V = (0, -1, 0), so R.V = 4/sqrt(41).
    c = np.array([1.0, 0.5, 0.25])
    cos = 4 / math.sqrt(41)
    expected = 0.5 * 0.2 * c + 0.6 * cos * c + 0.3 * cos ** 10
    assert img[2, 2] == pytest.approx(expected, abs=1e-12)
    assert np.all(img[0, 0] == 0)                            # the corner ray misses: the black background


def test_shadow_ray_leaves_ambient_only():
    floor = Material(colour=(0.5, 0.6, 0.7), ambient=0.4, diffuse=0.8, specular=0.0)
    occluder = Material(colour=(1, 0, 0))
    scene = rt.Scene([Plane((0, 0, 0), (0, 0, 1), floor), Sphere((0, 0, 1), 0.5, occluder)],
                     [Light((0, 0, 5))], ambient_light=0.5)
    colours = rt.trace(scene, [[0, -3, 3], [3, -3, 3]], [[0, 3, -3], [0, 3, -3]], depth=0)
    ambient = 0.5 * 0.4 * np.array([0.5, 0.6, 0.7])
    assert colours[0] == pytest.approx(ambient, abs=1e-12)    # (0,0,0) is behind the sphere: ambient only
    # (3,0,0) sees the light: L = (-3, 0, 5)/sqrt(34), L.N = 5/sqrt(34)
    assert colours[1] == pytest.approx(ambient + 0.8 * 5 / math.sqrt(34) * np.array([0.5, 0.6, 0.7]), abs=1e-12)
    tree = rt.ray_tree(scene, Camera((0, -3, 3), (0, 0, 0), fov=45), 0, 0, depth=0, width=1, height=1)
    shadow = [s for s in tree if s.kind == "shadow"]
    assert len(shadow) == 1 and shadow[0].hit                # blocked, and it ends on the occluder
    assert shadow[0].end == pytest.approx([0, 0, 0.5], abs=1e-6)


def _shadow_scene(*transmits, attenuate=True):
    """A white matte floor (k_a = 0, k_d = 0.9) under a light at (0, 0, 5), with a sphere of radius 0.4
    at heights 1.5, 3, ... for each given transmission coefficient (0: opaque)."""
    floor = Material(colour=(1, 1, 1), ambient=0.0, diffuse=0.9, specular=0.0)
    spheres = [Sphere((0, 0, 1.5 + 1.5 * k), 0.4, Material(colour=(1, 1, 1), transmit=t, index=1.5))
               for k, t in enumerate(transmits)]
    return rt.Scene([Plane((0, 0, 0), (0, 0, 1), floor), *spheres], [Light((0, 0, 5))], ambient_light=0.3,
                    shadow_transmission=attenuate)


def test_shadow_rays_are_attenuated_by_transmission():
    # the ray from (-2, 0, 2) along (1, 0, -1) meets the floor at the origin, below every sphere; the light
    # is straight above, L.N = 1, so unshadowed the point gets k_d I = 0.9 in each channel (k_a = 0)
    o, d = [[-2, 0, 2]], [[1, 0, -1]]
    lit = 0.9 * np.ones(3)
    assert rt.trace(_shadow_scene(), o, d, depth=0)[0] == pytest.approx(lit, abs=1e-12)
    assert rt.trace(_shadow_scene(0.7), o, d, depth=0)[0] == pytest.approx(0.7 * lit, abs=1e-12)     # t
    assert rt.trace(_shadow_scene(0.7, 0.5), o, d, depth=0)[0] == pytest.approx(0.35 * lit, abs=1e-12)  # t1 t2
    assert rt.trace(_shadow_scene(0.0), o, d, depth=0)[0] == pytest.approx(np.zeros(3), abs=1e-12)   # opaque
    assert rt.trace(_shadow_scene(0.7, 0.0), o, d, depth=0)[0] == pytest.approx(np.zeros(3), abs=1e-12)
    # the old tracer: a transparent object casts a full shadow
    assert rt.trace(_shadow_scene(0.7, attenuate=False), o, d, depth=0)[0] == pytest.approx(np.zeros(3), abs=1e-12)
    # light_fraction says the same; in_shadow says that something lies between
    P, N = [[0, 0, 0], [3, 0, 0]], [[0, 0, 1], [0, 0, 1]]
    assert rt.light_fraction(_shadow_scene(0.7, 0.5), P, N)[:, 0] == pytest.approx([0.35, 1.0], abs=1e-15)
    assert rt.in_shadow(_shadow_scene(0.7, 0.5), P, N)[:, 0].tolist() == [True, False]
    assert rt.light_fraction(_shadow_scene(0.7, attenuate=False), P, N)[:, 0].tolist() == [0.0, 1.0]
    # the ray tree records it: the shadow ray ends on the first sphere and carries t1 t2 of the light
    tree = rt.ray_tree(_shadow_scene(0.7, 0.5), Camera((-2, 0, 2), (0, 0, 0), fov=45), 0, 0, depth=0, width=1, height=1)
    shadow = [s for s in tree if s.kind == "shadow"]
    assert len(shadow) == 1 and shadow[0].hit and shadow[0].light == pytest.approx(0.35, abs=1e-15)
    assert shadow[0].end == pytest.approx([0, 0, 1.1], abs=1e-6)
    with pytest.raises(TypeError, match="shadow_transmission must be True or False"):
        rt.Scene([], [], shadow_transmission="yes")


def _independent_pixel(scene, o, d):
    """A small depth-0 ray tracer written for this test: nearest hit by the quadratic and the plane
    equation, then I_a k_a C + sum over lights of f (k_d C I (L.N) + k_s S I (R.V)^n), f the product of
    the transmit coefficients of the spheres the segment to the light crosses (Whitted 1980)."""
    o, d = np.asarray(o, float), np.asarray(d, float) / np.linalg.norm(d)
    best, hit = np.inf, None
    for obj in scene.objects:
        if isinstance(obj, Plane):
            n = np.asarray(obj.unit_normal, dtype=float)
            den = d @ n
            t = ((obj.point - o) @ n) / den if den != 0 else np.inf
            normal = n
        else:
            oc = o - obj.center
            b, c = oc @ d, oc @ oc - obj.radius ** 2
            disc = b * b - c
            t = -b - math.sqrt(disc) if disc >= 0 else np.inf
            normal = None
        if 1e-9 < t < best:
            best, hit = t, (obj, normal)
    obj, normal = hit
    P = o + best * d
    N = normal if normal is not None else (P - obj.center) / obj.radius
    if N @ d > 0:
        N = -N
    m = obj.material
    colour = m.ambient * np.asarray(scene.ambient_light) * np.asarray(m.colour)
    V = -d
    for light in scene.lights:
        Lvec = np.asarray(light.position) - P
        dist = np.linalg.norm(Lvec)
        L = Lvec / dist
        if L @ N <= 0:
            continue
        f = 1.0
        for other in scene.objects:
            if other is obj or isinstance(other, Plane):
                continue
            oc = P - other.center
            b, c = oc @ L, oc @ oc - other.radius ** 2
            disc = b * b - c
            if disc >= 0 and any(1e-9 < t < dist for t in (-b - math.sqrt(disc), -b + math.sqrt(disc))):
                f *= other.material.transmit
        R = 2 * (L @ N) * N - L
        spec = max(R @ V, 0.0) ** m.exponent if m.specular > 0 else 0.0
        colour = colour + f * light.rgb * (m.diffuse * np.asarray(m.colour) * (L @ N)
                                           + m.specular * np.asarray(m.specular_colour) * spec)
    return colour


def test_glass_shadow_pixel_matches_an_independent_tracer():
    scene, camera = rt.default_scene(), rt.default_camera()
    # pixels of a 40 x 30 image whose floor point lies in the glass sphere's shadow
    o, d = _rays(camera, 40, 30)
    colours = rt.trace(scene, o, d, depth=0)
    glass = scene.objects[1]
    found = 0
    for i in range(len(o)):
        di = d[i] / np.linalg.norm(d[i])
        if di[2] >= 0:
            continue
        P = o[i] - o[i][2] / di[2] * di                      # where the ray meets the floor z = 0
        to_light = np.asarray(scene.lights[0].position) - P
        oc = P - glass.center
        u = to_light / np.linalg.norm(to_light)
        if (oc @ u) ** 2 - (oc @ oc - glass.radius ** 2) <= 0.01:      # the shadow ray clearly misses the glass
            continue
        ours = _independent_pixel(scene, o[i], d[i])
        assert colours[i] == pytest.approx(ours, abs=1e-9), i
        found += 1
    assert found >= 3                                          # the glass ball's shadow is in view
    # and each of those points gets k_t = 0.88 of the light, not none of it
    assert rt.MATERIALS["glass"].transmit == 0.88


def test_mirror_reflection_angle_and_weight():
    mirror = Material(colour=(0.2, 0.2, 0.2), reflect=0.6)
    scene = rt.Scene([Plane((0, 0, 0), (0, 0, 1), mirror)], [Light((0, 0, 4))])
    # a ray coming down at 30 degrees from the normal leaves at 30 degrees on the other side
    d = np.array([math.sin(math.radians(30)), 0.0, -math.cos(math.radians(30))])
    segments = []
    rt.trace(scene, [-d * 2], [d], depth=1, record=segments)
    reflected = [s for s in segments if s.kind == "reflected"]
    assert len(reflected) == 1 and reflected[0].weight == pytest.approx(0.6)
    r = reflected[0].end - reflected[0].start
    assert r / np.linalg.norm(r) == pytest.approx([d[0], 0, -d[2]], abs=1e-12)
    # the mirror's colour: its local light plus 0.6 of the (white) background it sees
    colour1 = rt.trace(rt.Scene([Plane((0, 0, 0), (0, 0, 1), mirror)], [Light((0, 0, 4))], background=(1, 1, 1)),
                       [-d * 2], [d], depth=1)
    colour0 = rt.trace(rt.Scene([Plane((0, 0, 0), (0, 0, 1), mirror)], [Light((0, 0, 4))], background=(1, 1, 1)),
                       [-d * 2], [d], depth=0)
    assert (colour1 - colour0)[0] == pytest.approx([0.6, 0.6, 0.6], abs=1e-12)


def test_total_internal_reflection_inside_a_glass_sphere():
    glass = Material(reflect=0.1, transmit=0.8, index=1.5)
    scene = rt.Scene([Sphere((0, 0, 0), 1, glass)], [Light((0, 0, 5))])
    # from (0, 0.9, 0) along +x the ray meets the inside wall 64.2 degrees from the normal (> 41.8)
    segments = []
    rt.trace(scene, [[0, 0.9, 0]], [[1, 0, 0]], depth=1, record=segments)
    level1 = [s for s in segments if s.level == 1 and s.kind != "shadow"]
    assert [s.kind for s in level1] == ["reflected"]
    assert level1[0].weight == pytest.approx(0.1 + 0.8)      # all the transmitted light goes along the mirror ray
    # from (0, 0.5, 0) the angle is 30 degrees: both a refracted and a reflected ray
    segments = []
    rt.trace(scene, [[0, 0.5, 0]], [[1, 0, 0]], depth=1, record=segments)
    kinds = sorted(s.kind for s in segments if s.level == 1 and s.kind != "shadow")
    assert kinds == ["reflected", "refracted"]
    refracted = next(s for s in segments if s.kind == "refracted")
    # leaving glass: sin(theta2) = 1.5 sin 30 = 0.75
    P = refracted.start
    assert math.sin(math.radians(_angle_to(refracted.end - P, P))) == pytest.approx(0.75, abs=1e-6)


def test_a_glass_sphere_passes_a_ray_through_its_centre_straight():
    glass = Material(reflect=0.0, transmit=1.0, index=1.5, ambient=0, diffuse=0, specular=0)
    scene = rt.Scene([Sphere((0, 0, 0), 1, glass)], [], ambient_light=0.0, background=(0.3, 0.6, 0.9))
    segments = []
    colour = rt.trace(scene, [[-5, 0, 0]], [[1, 0, 0]], depth=3, record=segments)
    assert colour[0] == pytest.approx([0.3, 0.6, 0.9], abs=1e-12)   # a clear ball seen head on: the background
    ends = [s.end for s in segments if s.kind == "refracted"]
    assert ends[0] == pytest.approx([1, 0, 0], abs=1e-6) and ends[1][1:] == pytest.approx([0, 0], abs=1e-12)


# -- whole images ----------------------------------------------------------------------------------

def _primary_object(scene, camera, width, height):
    o, d = _rays(camera, width, height)
    ts = np.stack([obj.intersect(o, d) for obj in scene.objects])
    which = np.where(np.isfinite(ts).any(axis=0), ts.argmin(axis=0), -1)
    return which.reshape(height, width)


def test_depth_zero_and_one_differ_only_on_mirror_and_glass():
    scene, cam = rt.default_scene(), rt.default_camera()
    img0 = rt.render(scene, cam, 64, 48, depth=0)
    img1 = rt.render(scene, cam, 64, 48, depth=1)
    img3 = rt.render(scene, cam, 64, 48, depth=3)
    for img in (img0, img1, img3):
        assert img.shape == (48, 64, 3) and img.min() >= 0 and img.max() <= 1
    which = _primary_object(scene, cam, 64, 48)
    special = np.isin(which, [k for k, obj in enumerate(scene.objects)
                              if obj.material.reflect > 0 or obj.material.transmit > 0])
    differs = np.any(np.abs(img1 - img0) > 1e-12, axis=2)
    assert differs.any() and not np.any(differs & ~special)
    assert differs[special].mean() > 0.9                     # and nearly everywhere there
    # the index of refraction changes only what is seen through the glass sphere
    glass = [k for k, obj in enumerate(scene.objects) if obj.material.transmit > 0]
    other = rt.render(rt.default_scene(index=1.2), cam, 64, 48, depth=3)
    changed = np.any(np.abs(other - img3) > 1e-12, axis=2)
    assert changed.any()
    assert not np.any(changed & (which != glass[0]) & ~special)


def test_render_matches_trace_pixel_by_pixel():
    scene, cam = rt.default_scene(), rt.default_camera()
    img = rt.render(scene, cam, 16, 12, depth=2)
    o, d = dataclasses.replace(cam, width=16, height=12).ray(5, 7)
    assert img[7, 5] == pytest.approx(np.clip(rt.trace(scene, o, d, depth=2)[0], 0, 1), abs=1e-12)


def test_ray_tree_structure():
    scene, cam = rt.default_scene(), rt.default_camera()
    glass = scene.objects[1]
    # a pixel on the glass sphere: aim at its centre
    o, d = np.array(cam.eye), glass.center - cam.eye
    segments = []
    rt.trace(scene, o, d, depth=3, record=segments)
    assert segments[0].kind == "primary" and np.allclose(segments[0].start, cam.eye) and segments[0].hit
    kinds = {s.kind for s in segments}
    assert kinds == {"primary", "reflected", "refracted", "shadow"}
    rays = [s for s in segments if s.kind != "shadow"]
    assert len(rays) <= rt.ray_tree_size(3) and max(s.level for s in rays) == 3
    assert len(segments) <= rt.ray_tree_size(3, lights=len(scene.lights))
    tree = rt.ray_tree(scene, cam, 80, 60, depth=0)
    assert [s.kind for s in tree] in (["primary"], ["primary", "shadow"])


def test_ray_tree_size_closed_form():
    assert [rt.ray_tree_size(d) for d in range(5)] == [1, 3, 7, 15, 31]
    assert rt.ray_tree_size(3, lights=2) == 45


def test_work_budgets():
    scene, cam = rt.default_scene(), rt.default_camera()
    with pytest.raises(ValueError, match="width|height"):
        rt.render(scene, cam, 100_000, 1_000, depth=0)
    with pytest.raises(ValueError, match="max_rays = 10,000,000"):
        rt.render(scene, cam, 3000, 3000, depth=4)      # 9 million primary rays and their shadow rays
    with pytest.raises(ValueError, match="max_rays"):
        rt.render(scene, cam, 4, 4, depth=1, max_rays=0)
    with pytest.raises(ValueError, match="depth"):
        rt.render(scene, cam, 4, 4, depth=rt.MAX_DEPTH + 1)
    with pytest.raises(TypeError, match="objects"):
        rt.Scene([object()], [])
    with pytest.raises(ValueError, match="background"):
        rt.Scene([], [], background=(2, 0, 0))


def test_the_bounding_sphere_cull_changes_no_pixel(monkeypatch):
    """Chapter 19's surfaces in one scene: culling rays by each surface's bounding_sphere() gives the
    image the tracer makes without it (every object tested against every ray)."""
    from goldman_lib import simple_surfaces as ss

    shiny = Material(colour=(0.9, 0.9, 0.2), reflect=0.5)
    glass = Material(colour=(0.9, 0.9, 1.0), transmit=0.8, reflect=0.1, index=1.4)
    objects = [ss.Plane((0, 0, 0), (0, 0, 1), Material(colour=(0.7, 0.7, 0.7))),
               ss.Torus((0.5, 1.5, 0.4), (0, 0, 1), 0.8, 0.3, material=shiny),
               ss.Cylinder((1.5, -1.5, 0.0), (0, 0, 1), 0.5, height=1.5, material=glass),
               ss.Cone((-0.5, -0.3, 1.6), (0, 0, -1), 25.0, height=1.6),
               ss.Ellipsoid((2.5, 0.5, 0.8), (0.6, 0.4, 0.8), material=glass),
               ss.Polygon([[-1.5, 1.0, 0.01], [-0.5, 1.0, 0.01], [-1.0, 2.2, 1.0]], material=shiny),
               Sphere((0.8, 0.0, 0.5), 0.5, glass)]
    scene = rt.Scene(objects, [Light((-2.0, -2.0, 5.0)), Light((3.0, 2.0, 4.0), intensity=0.5)])
    cam = Camera((-6.0, -1.0, 2.5), (0.5, 0.2, 0.6), fov=45)
    culled = rt.render(scene, cam, 48, 36, depth=3)
    assert all(rt._bounding_sphere(obj) is not None for obj in objects[1:])
    monkeypatch.setattr(rt, "_bounding_sphere", lambda obj: None)
    plain = rt.render(scene, cam, 48, 36, depth=3)
    assert np.abs(culled - plain).max() < 1e-9
    assert len(np.unique(culled.reshape(-1, 3).round(3), axis=0)) > 50     # a picture, not a blank


def test_640x480_at_depth_5_of_the_default_scene_is_within_the_budget():
    """Issue 18: the budget counts the rays traced, not a full binary tree per pixel (640 * 480 * 63
    = 19.4 million, which the old budget refused): the default scene spawns secondary rays at few
    pixels."""
    counts = {}
    img = rt.render(rt.default_scene(), rt.default_camera(), 640, 480, depth=5, counts=counts)
    assert img.shape == (480, 640, 3)
    pixels = 640 * 480
    assert pixels <= counts["rays"] < 2 * pixels                 # primary rays, and a few secondary ones
    assert counts["rays"] + counts["shadow"] <= rt.MAX_ITEMS < pixels * (2 ** 6 - 1)


def _mirror_corridor():
    """Two mirrors facing each other (the planes x = -1 and x = 1) and a camera between them looking
    along +x: every ray hits a mirror and spawns one reflected ray, on every level."""
    mirror = Material(colour=(0.9, 0.9, 0.9), ambient=0.1, diffuse=0.1, specular=0.0, reflect=0.9)
    scene = rt.Scene([Plane((-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), mirror),
                      Plane((1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), mirror)],
                     [Light((0.0, 0.0, 5.0))], background=(0.0, 0.0, 0.0))
    camera = Camera((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), up=(0.0, 0.0, 1.0), fov=40.0)
    return scene, camera


def test_a_hall_of_mirrors_is_refused_at_the_level_that_passes_the_budget():
    scene, camera = _mirror_corridor()
    counts = {}
    # 32 x 24 = 768 rays on every level, each with one shadow ray: 1,536 per level; a budget of
    # 5,000 holds levels 0-2 (4,608) and refuses level 3 before tracing it
    with pytest.raises(ValueError, match=r"max_rays: tracing level 3 .* over the budget max_rays = 5,000"):
        rt.render(scene, camera, 32, 24, depth=12, counts=counts, max_rays=5000)
    assert counts == {"rays": 3 * 768, "shadow": 3 * 768}           # it stopped there
    full = {}
    rt.render(scene, camera, 32, 24, depth=12, counts=full)         # the default budget holds all 13 levels
    assert full == {"rays": 13 * 768, "shadow": 13 * 768}


# -- the safeguards, switched off to show what they prevent (§17.3, §17.5) ----------------------------

def _with(scene, **kw):
    return rt.Scene(scene.objects, scene.lights, scene.ambient_light, scene.background, scene.shadow_transmission, **kw)


def _changed(a, b):
    return np.any(np.abs(a - b) > 1e-3, axis=2)


def test_the_default_safeguards_are_the_scene_as_before():
    scene, camera = rt.default_scene(), rt.default_camera()
    base = rt.render(scene, camera, 48, 36, 3)
    explicit = _with(scene, shadow_offset=None, precision="float64", index_ratio="n1/n2")
    assert np.array_equal(base, rt.render(explicit, camera, 48, 36, 3))
    # float64 with no offset at all: a self-hit at t ~ 1e-16 hides under t > EPS, so no pixel changes
    # (the secondary rays start 1e-7 elsewhere: the last bits move, nothing a display shows)
    assert not _changed(base, rt.render(_with(scene, shadow_offset=0.0), camera, 48, 36, 3)).any()


def test_shadow_acne_appears_in_single_precision_without_an_offset_and_an_offset_removes_it():
    scene, camera = rt.default_scene(), rt.default_camera()
    base = rt.render(scene, camera, 80, 60, 3)
    acne = rt.render(_with(scene, shadow_offset=0.0, precision="float32"), camera, 80, 60, 3)
    fixed = rt.render(_with(scene, shadow_offset=1e-4, precision="float32"), camera, 80, 60, 3)
    changed = _changed(base, acne)
    assert changed.mean() > 0.03                             # speckles over the spheres
    assert np.all(acne[changed].sum(axis=1) < base[changed].sum(axis=1) + 1e-9) or \
        np.mean(acne[changed].sum(axis=1) < base[changed].sum(axis=1)) > 0.8    # self-shadowed: darker
    o, d = _rays(camera, 80, 60)
    t_floor = scene.objects[0].intersect(o, d).reshape(60, 80)
    t_spheres = np.min([obj.intersect(o, d) for obj in scene.objects[1:]], axis=0).reshape(60, 80)
    on_spheres = np.isfinite(t_spheres) & (t_spheres < t_floor)
    assert changed[on_spheres].mean() > 0.3 and changed[~on_spheres].mean() < changed[on_spheres].mean() / 5
    assert _changed(base, fixed).mean() < 0.002               # the offset past the rounding error: gone


def test_the_index_ratio_upside_down_bends_the_ray_away_from_the_normal():
    glass = Material(colour=(1, 1, 1), ambient=0, diffuse=0, specular=0, transmit=1.0, index=1.5)
    scene = rt.Scene([Sphere((0, 0, 0), 1.0, glass)], [])
    o, d = np.array([[-5.0, 0.3, 0.0]]), np.array([[1.0, 0.0, 0.0]])
    sin1 = 0.3                                                # the hit point is the unit normal: sin = its y
    for ratio, sin2 in (("n1/n2", sin1 / 1.5), ("n2/n1", sin1 * 1.5)):
        record = []
        rt.trace(_with(scene, index_ratio=ratio), o, d, depth=1, record=record)
        inside = next(s for s in record if s.kind == "refracted")
        T = (inside.end - inside.start) / np.linalg.norm(inside.end - inside.start)
        N = -inside.start / np.linalg.norm(inside.start)      # the inward normal at the entry point
        assert np.linalg.norm(np.cross(T, N)) == pytest.approx(sin2, abs=1e-6)


def test_safeguard_switches_are_validated():
    s = rt.default_scene()
    for kw, err in ((dict(shadow_offset=-1.0), ValueError), (dict(shadow_offset=2.0), ValueError),
                    (dict(shadow_offset="small"), (TypeError, ValueError)), (dict(precision="float16"), ValueError),
                    (dict(index_ratio="n2:n1"), ValueError), (dict(index_ratio=1.5), ValueError)):
        with pytest.raises(err):
            _with(s, **kw)


# -- ray casting, the pictures of chapter 16 ------------------------------------------------------------

def test_ray_cast_is_local_light_at_the_nearest_hit():
    m = Material(colour=(1.0, 0.5, 0.25), ambient=0.2, diffuse=0.6, specular=0.3, exponent=10)
    scene = rt.Scene([Sphere((0, 0, 0), 1.0, m)], [Light((0, -5, 5))], ambient_light=0.5, background=(0, 0, 1))
    camera = Camera((0, -5, 0), (0, 0, 0), up=(0, 0, 1), fov=40)
    img = rt.ray_cast(scene, camera, 9, 7)
    # the centre pixel's ray hits (0, -1, 0), N = (0, -1, 0): L = (0, -4, 5)/sqrt 41, L.N = 4/sqrt 41,
    # R = (0, -4, -5)/sqrt 41 ... R.V = 4/sqrt 41 with V = (0, -1, 0)
    c = 4 / math.sqrt(41)
    expected = np.clip(0.5 * 0.2 * np.array([1.0, 0.5, 0.25]) + 0.6 * c * np.array([1.0, 0.5, 0.25]) + 0.3 * c ** 10,
                       0, 1)
    assert img[3, 4] == pytest.approx(expected, abs=1e-12)
    assert img[0, 0].tolist() == [0.0, 0.0, 1.0]
    calls = []
    assert np.array_equal(img, rt.ray_cast(scene, camera, 9, 7, progress=lambda k, n: calls.append((k, n))))
    assert calls[-1] == (7, 7)
    fine = rt.ray_cast(scene, camera, 18, 14)
    assert rt.ray_cast(scene, camera, 9, 7, samples=2) == pytest.approx(fine.reshape(7, 2, 9, 2, 3).mean(axis=(1, 3)))
    with pytest.raises(TypeError, match="clamp"):
        rt.ray_cast(scene, camera, 9, 7, clamp="yes")
    with pytest.raises(TypeError, match="progress"):
        rt.ray_cast(scene, camera, 9, 7, progress=3)


def test_ray_cast_unclamped_changes_only_what_the_light_is_behind():
    m = Material(colour=(0.8, 0.3, 0.35), ambient=0.15, diffuse=0.7, specular=0.5, exponent=5)
    scene = rt.Scene([Sphere((0, 0, 0), 1.0, m)], [Light((4, 1, -3))], ambient_light=1.0)
    camera = Camera((0, 0, 6), (0, 0, 0), up=(0, 1, 0), fov=24)
    safe, unsafe = rt.ray_cast(scene, camera, 60, 60), rt.ray_cast(scene, camera, 60, 60, clamp=False)
    delta = unsafe.sum(axis=2) - safe.sum(axis=2)
    assert (delta < -1e-3).sum() > 1000 and (delta > 1e-3).sum() > 10     # a dark side and a leaked highlight
    o, d = _rays(camera, 60, 60)
    t = scene.objects[0].intersect(o, d)
    P = o + np.where(np.isfinite(t), t, 0)[:, None] * d
    behind = (np.isfinite(t) & (np.einsum("ij,ij->i", np.array([4.0, 1.0, -3.0]) - P, P) <= 0)).reshape(60, 60)
    assert not _changed(safe, unsafe)[~behind].any()
