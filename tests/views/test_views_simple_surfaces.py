"""Chapter 19 views: the ray-traced gallery and the three.js scene change with every control."""

import numpy as np
import pytest

from goldman_lib import simple_surfaces as S
from goldman_lib.camera import Camera
from goldman_lib.views import simple_surfaces as V


def test_make_surface_builds_every_kind_on_the_floor():
    for kind in V.SURFACES:
        s = V.make_surface(kind)
        assert isinstance(s, S.Surface)
        if s.bounding_sphere is not None:
            c, r = s.bounding_sphere
            pos, _ = s.mesh(12)
            assert pos[:, 2].min() >= -1e-9, kind           # standing on the floor z = 0
    with pytest.raises(ValueError, match="kind"):
        V.make_surface("klein bottle")


@pytest.fixture(scope="module")
def gallery():
    return V.gallery_view(width=48, height_px=36)


def test_gallery_image_changes_with_each_control(gallery):
    base = gallery.set_values(kind="cylinder", radius=0.8, height=1.6)["image"].copy()
    assert base.shape == (36, 48, 3) and np.all((base >= 0) & (base <= 1))
    for change in ({"radius": 1.2}, {"height": 0.6}, {"kind": "sphere"}, {"light0_x": -4.0}, {"light0_I": 0.3}):
        img = gallery.set_values(**change)["image"]
        assert np.abs(img - base).mean() > 1e-3, change
        gallery.set_values(kind="cylinder", radius=0.8, height=1.6, light0_x=3.0, light0_I=1.0)
    cone = gallery.set_values(kind="cone", half_angle=20.0)["image"].copy()
    assert np.abs(gallery.set_values(half_angle=50.0)["image"] - cone).mean() > 1e-3
    torus = gallery.set_values(kind="torus", R=1.0, r=0.3)["image"].copy()
    r = gallery.set_values(R=1.4)
    assert np.abs(r["image"] - torus).mean() > 1e-3 and "solve the quartic" in r["status"]
    assert np.abs(gallery.set_values(r=0.55)["image"] - r["image"]).mean() > 1e-3


def test_gallery_shows_the_surface_where_its_own_intersection_says(gallery):
    r = gallery.set_values(kind="sphere", radius=0.8)
    assert gallery.last_error is None
    # the centre pixel's primary ray: the library's sphere is hit there, and the pixel is not the sky
    img = r["image"]
    sky = np.array([0.62, 0.76, 0.92])
    assert np.abs(img[18, 24] - sky).max() > 0.05


def test_scene_mesh_changes_with_the_controls_and_the_light_moves():
    view = V.surface_scene_view(resolution=10)
    a = view.set_values(kind="torus", R=1.0)["positions"].copy()
    b = view.set_values(R=1.3)["positions"]
    assert a.shape == b.shape and np.abs(a - b).max() > 0.2
    c = view.set_values(kind="polygon (non-convex)")
    assert len(c["triangles"]) == 8                       # a 10-vertex star: 8 triangles
    assert np.array_equal(view.scene.data("surface")["triangles"], c["triangles"])
    view.set_values(light0_z=2.0)
    assert view.scene.lights[0].position[2] == 2.0
    assert np.allclose(view.scene.data("lights")["positions"][0, 2], 2.0)
    colours = set()
    for kind in V.SURFACES:
        view.set_values(kind=kind)
        assert view.last_error is None, kind
        colours.add(view.scene.data("surface")["color"])
    assert len(colours) == len(V.SURFACES)                 # each surface keeps its own colour
    assert view.static_png()[:4] == b"\x89PNG"


def test_torus_ray_view_hits_by_hand_and_the_bound():
    view = V.torus_ray_view()
    # along the x-axis from x = -4: the tube circles of radius 0.5 about x = +-1.5: t = 2, 3, 5, 6
    r = view.set_values(ox=-4.0, oz=0.0, angle=0.0, R=1.5, r=0.5)
    assert np.allclose(r["t"], [2, 3, 5, 6]) and r["solved"]
    assert np.allclose(r["normals"][[0, 3]], [[-1, 0, 0], [1, 0, 0]])
    drawn = view.figure.axes[0].lines[2].get_xydata()                  # the hit dots, in the x-z plane
    assert np.allclose(drawn, [[-2, 0], [-1, 0], [1, 0], [2, 0]])
    # above the slab (z = 1 > r): the quartic is skipped and nothing is hit
    r = view.set_values(oz=1.0)
    assert not r["solved"] and len(r["t"]) == 0 and "skipped" in r["status"]
    # down the axis: passes the bound, no root (the hole)
    r = view.set_values(ox=0.0, oz=2.5, angle=-90.0)
    assert r["solved"] and len(r["t"]) == 0
    # a larger tube radius changes what is drawn
    before = view.set_values(ox=-3.5, oz=0.3, angle=0.0, r=0.3)["hits"].copy()
    after = view.set_values(r=0.6)["hits"]
    assert before.shape != after.shape or np.abs(before - after).max() > 0.1
    assert view.drag is not None


def test_the_render_control_renders_what_the_gallery_shows_at_full_size(gallery):
    from goldman_lib import ray_tracing as rt

    rc = V.gallery_render_control(gallery, 32, 24, samples=2, depth=1)
    gallery.set_values(kind="sphere", radius=1.0, light0_x=-2.0)
    image = rc.render()
    assert image.shape == (24, 32, 3) and rc.progress.fraction == 1.0 and rc.last_error is None
    # the same scene rendered directly, from the view's own values
    v = gallery.values()
    scene = rt.Scene([S.Plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], V._FLOOR), V.make_surface("sphere", radius=1.0)],
                     gallery.light_control.lights({k: x for k, x in v.items() if k.startswith("light")}),
                     ambient_light=0.25, background=(0.62, 0.76, 0.92))
    direct = rt.render(scene, Camera(V._EYE, V._TARGET, fov=40.0), 32, 24, depth=1, samples=2)
    assert np.array_equal(image, direct)
    gallery.set_values(kind="torus")
    assert not np.array_equal(rc.render(), image)                          # it follows the view


def test_the_render_control_reports_a_refused_render_in_its_status(gallery):
    rc = V.gallery_render_control(gallery, 32, 24, samples=99)
    assert rc.render() is None and "samples" in rc.last_error
    with pytest.raises(TypeError, match="gallery"):
        V.gallery_render_control(object())
