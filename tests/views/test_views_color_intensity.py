"""Chapter 16 views draw what goldman_lib.lighting computes: a ray-cast sphere lit pixel by pixel
(material sliders, the light-position control, the light dragged in the side view), the ambient,
diffuse and specular terms beside their total under two lights, and red, green and blue light mixing
on a wall.  Expected values are worked by hand (Lambert's cosine on the unit sphere, whose normal at
P is P itself)."""

import dataclasses

import numpy as np
import pytest

from goldman_lib import lighting
from goldman_lib.lighting import Material
from goldman_lib.views import color_intensity as ci

RED = (0xd1 / 255, 0x49 / 255, 0x5b / 255)


def test_sphere_pixels_are_points_of_the_unit_sphere_seen_from_the_eye():
    found, points, normals = ci.sphere_pixels(64)
    assert found.shape == (64, 64) and len(points) == found.sum() == len(normals)
    assert np.allclose(np.linalg.norm(points, axis=1), 1.0) and np.allclose(normals, points)
    assert np.all(points[:, 2] > 0)                       # the eye at z = 6 sees the upper half only
    # the silhouette: the ray grazes the sphere where its distance from the centre is 1; a ray through
    # the window point (x, 0, 0) from (0, 0, 6) passes the centre at distance 6x / sqrt(36 + x^2)
    xs = np.linspace(-ci.WINDOW, ci.WINDOW, 64)
    row = found[32]
    assert np.array_equal(row, 6 * np.abs(xs) / np.sqrt(36 + xs ** 2) <= 1.0)
    assert not found[0, 0] and found[32, 32]


def test_the_pictures_rays_come_from_the_camera_through_the_window_grid():
    # the rays of camera(n): pixel (i, j) meets the plane z = 0 at (-W + j 2W/(n-1), W - i 2W/(n-1)), the
    # outermost pixel centres on the window's edges (the pictures' framing); camera() frames the
    # window edge to edge, pixel centres half a pixel inside
    n, W = 9, ci.WINDOW
    eye, d = ci.camera(n).rays()
    on_plane = eye + (-eye[2] / d[..., 2])[..., None] * d
    grid = -W + np.arange(n) * 2 * W / (n - 1)
    assert np.allclose(on_plane[..., 0], grid[None, :], atol=1e-12)
    assert np.allclose(on_plane[..., 1], grid[::-1, None], atol=1e-12)
    assert np.allclose(on_plane[..., 2], 0.0, atol=1e-12)
    full = ci.camera()
    eye, d = dataclasses.replace(full, width=4, height=4).rays()
    corner = eye + (-eye[2] / d[0, 0, 2]) * d[0, 0]
    assert corner[:2] == pytest.approx([-W + W / 4, W - W / 4])


def test_the_sphere_is_lit_by_lamberts_cosine_worked_by_hand():
    view = ci.shaded_sphere_view(size=48)
    r = view.set_values(ka=0.0, kd=0.8, ks=0.0, Ia=0.0, light0_x=4.0, light0_y=-1.0, light0_z=3.0, light0_I=1.0,
                        colour="#ffffff", light0_colour="#ffffff")
    _, points, _ = ci.sphere_pixels(48)
    L = np.array([4.0, -1.0, 3.0])
    to_light = (L - points) / np.linalg.norm(L - points, axis=1)[:, None]
    expected = 0.8 * np.maximum(np.einsum("ij,ij->i", to_light, points), 0)    # the normal at P is P
    assert np.allclose(r["intensity"], expected[:, None])
    assert np.allclose(r["light"], L) and view.last_error is None
    # the brightest point is the one whose normal points most nearly at the light
    assert np.argmax(expected) == np.argmax(r["intensity"][:, 0])


def test_material_and_light_sliders_change_the_picture_in_place():
    view = ci.shaded_sphere_view(size=48)
    im = view.figure.axes[0].images[0]
    first = view.set_values(light0_x=-4.0)["image"].copy()
    assert im.get_array() is not None and np.allclose(np.asarray(im.get_array()), first)
    second = view.set_values(light0_x=4.0)["image"]
    assert view.figure.axes[0].images[0] is im
    # the light went from left to right: the left half got darker, the right half brighter
    assert first[:, :24].sum() > second[:, :24].sum() and first[:, 24:].sum() < second[:, 24:].sum()
    # a larger exponent shrinks the highlight: fewer pixels near the peak
    wide = view.set_values(ks=1.0, n=5.0, kd=0.0, ka=0.0)["intensity"][:, 0]
    narrow = view.set_values(n=150.0)["intensity"][:, 0]
    assert (narrow > 0.5).sum() < (wide > 0.5).sum()
    # the colour picker colours the diffuse light; ambient is I_a k_a C everywhere
    r = view.set_values(ka=0.5, kd=0.0, ks=0.0, Ia=0.8, colour="#d1495b")
    assert np.allclose(r["intensity"], 0.4 * np.array(RED))


def test_dragging_the_light_in_the_side_view_moves_its_x_and_z(hooks):
    view = ci.shaded_sphere_view(size=32)
    drag = view.drag
    x, z = view.values()["light0_x"], view.values()["light0_z"]
    hooks["press_at"](drag, x, z)
    hooks["move_to"](drag, -4.0, 2.0)
    hooks["release"](drag)
    assert view.values()["light0_x"] == pytest.approx(-4.0) and view.values()["light0_z"] == pytest.approx(2.0)
    assert np.allclose(view.last_result["light"][[0, 2]], [-4.0, 2.0])


def test_a_light_inside_the_sphere_leaves_only_the_ambient_term_and_bad_colours_are_named():
    view = ci.shaded_sphere_view(size=32)
    r = view.set_values(light0_x=0.0, light0_y=0.0, light0_z=0.5, ka=0.3, Ia=1.0, colour="#ffffff")
    assert np.allclose(r["intensity"], 0.3) and "inside the sphere" in r["status"]
    with pytest.raises(ValueError, match="colour"):
        view.update(**{**view.values(), "colour": "not a colour"})


def test_the_terms_add_up_to_the_total_and_clipping_is_counted():
    view = ci.terms_view(size=40)
    r = view.set_values(ka=0.2, kd=0.6, ks=0.6, n=20.0, Ia=1.0)
    assert np.allclose(r["ambient"] + r["diffuse"] + r["specular"], r["total"])
    _, points, normals = ci.sphere_pixels(40)
    full = Material(colour=(0x3d / 255, 0x7d / 255, 0xd8 / 255), ambient=0.2, diffuse=0.6, specular=0.6, exponent=20)
    lights = view.light_control.lights(view.values())
    assert np.allclose(r["total"], lighting.intensity(points, normals, ci.EYE, lights, full, ambient_light=1.0))
    c = np.array([0x3d, 0x7d, 0xd8]) / 255
    assert np.allclose(r["ambient"], 0.2 * c)                        # I_a k_a C, the same at every pixel
    # the specular highlight takes the light's colour, not the material's: white light, grey highlight
    view.set_values(light1_I=0.0)
    spec = view.last_result["specular"]
    assert np.allclose(spec[:, 0], spec[:, 1]) and np.allclose(spec[:, 1], spec[:, 2])
    # turned up, the total goes over 1 and is clipped in the picture
    r = view.set_values(kd=1.0, ks=1.0, light0_I=2.0, light1_I=2.0)
    assert r["clipped"] > 0.05 and r["images"].max() <= 1.0 and f"{100 * r['clipped']:.1f}%" in r["status"]
    assert r["images"].shape == (4, 40, 40, 3)


def test_rgb_lights_add_and_the_wall_filters():
    view = ci.rgb_mixing_view(size=40)
    r = view.set_values(wall="#ffffff")
    # the centre (0, 0, 0) sees each light at distance 0.5 and height 0.3: cos = 0.6, times 1.6
    assert np.allclose(r["centre"], [0.96, 0.96, 0.96])
    r = view.set_values(wall="#ffff00")                      # a yellow wall absorbs blue
    assert np.allclose(r["centre"], [0.96, 0.96, 0.0])
    r = view.set_values(wall="#ffffff", light2_I=0.0)         # red + green = yellow
    assert np.allclose(r["centre"], [0.96, 0.96, 0.0])
    assert r["image"][..., 2].max() == 0.0


def test_dragging_a_coloured_light_moves_it_over_the_wall(hooks):
    view = ci.rgb_mixing_view(size=32)
    hooks["press_at"](view.drag, 0.0, 0.4)
    hooks["move_to"](view.drag, 1.0, 1.0)
    hooks["release"](view.drag)
    assert np.allclose(view.last_result["lights"][0], [1.0, 1.0, 0.3])


def test_image_sizes_are_bounded():
    with pytest.raises(ValueError, match="size"):
        ci.sphere_pixels(10_000)
    with pytest.raises(ValueError, match="size"):
        ci.shaded_sphere_view(size=4)


def test_the_full_size_render_is_the_view_ray_cast():
    from goldman_lib import ray_tracing as rt
    from goldman_lib.lighting import Light
    from goldman_lib.simple_surfaces import Sphere

    view = ci.shaded_sphere_view(size=32)
    values = view.values()
    calls = []
    img = view.render_full(lambda k, n: calls.append((k, n)), size=(40, 30), samples=1, **values)
    assert img.shape == (30, 40, 3) and calls[-1] == (30, 30)
    m = Material(colour=RED, ambient=values["ka"], diffuse=values["kd"], specular=values["ks"], exponent=values["n"])
    scene = rt.Scene([Sphere((0, 0, 0), 1.0, m)], [Light((3.0, 2.0, 5.0))], ambient_light=values["Ia"],
                     background=ci.BACKGROUND)
    assert img == pytest.approx(rt.ray_cast(scene, ci.camera(), 40, 30), abs=1e-12)
    # the camera sees the window of the small picture: the sphere's top at the same height
    column = img[:, 20].sum(axis=1)
    assert abs(np.flatnonzero(np.abs(column - ci.BACKGROUND.sum()) > 1e-6)[0] - 30 * (1 - 1 / 1.25) / 2) <= 2
    values["ka"] = 0.9
    assert not np.array_equal(img, view.render_full(None, size=(40, 30), samples=1, **values))


def test_the_clamp_check_box_shows_the_unclamped_lambert_term():
    view = ci.shaded_sphere_view(size=48)
    safe = view.set_values(light0_x=4.0, light0_y=1.0, light0_z=-3.0)
    assert view.controls["clamp"].value is True and "not clamped" not in safe["status"]
    unsafe = view.set_values(clamp=False)
    found, points, normals = ci.sphere_pixels(48)
    lit = lighting.diffuse(points, normals, [4.0, 1.0, -3.0], 1.0, 1.0, clamp=False) > 0
    assert np.array_equal(safe["intensity"][lit], unsafe["intensity"][lit])       # the lit side: bit for bit
    # behind the light: mostly darker (the negative term), a few brighter (the leaked highlight, exponent 30)
    assert np.mean(unsafe["intensity"][~lit].sum(axis=1) < safe["intensity"][~lit].sum(axis=1)) > 0.9
    assert np.any(unsafe["intensity"][~lit] < 0) and "not clamped" in unsafe["status"]
    assert np.array_equal(view.set_values(clamp=True)["image"], safe["image"])
