"""Chapter 21 view: two shading modes of one sphere side by side, lit by the shared light control;
the images change in place with the mode pickers, the facets, the exponent and the light (sliders or
a drag of its marker)."""

import numpy as np
import pytest

from goldman_lib import lighting, rasteriser, shading
from goldman_lib.camera import Camera
from goldman_lib.views import shading as sv


def test_the_images_are_what_the_rasteriser_renders():
    view = sv.shading_view()
    r = view.set_values(mode_a="uniform", mode_b="phong", facets=6, exponent=20.0)
    V, T = shading.uv_sphere(6, 12)
    cam = Camera(width=128, height=128, **sv.SHADING_CAMERA)
    light = lighting.Light((2.5, -4.0, 3.0))
    m = lighting.Material(colour=(0.85, 0.35, 0.25), ambient=0.25, diffuse=0.7, specular=0.5, exponent=20.0)
    expected = shading.render(V, T, cam, light, m, mode="uniform", ambient_light=0.3, background=(1, 1, 1),
                              cull_backfaces=True)
    assert np.allclose(r["images"][0], expected) and r["triangles"] == 2 * 12 * 5
    first = view.figure.axes[1].images[0]
    view.set_values(mode_a="gouraud")
    assert view.figure.axes[1].images[0] is first                     # updated in place
    assert np.allclose(first.get_array(), view.last_result["images"][0])


def test_modes_facets_exponent_and_light_change_the_picture():
    view = sv.shading_view()
    base = view.set_values(mode_a="uniform", mode_b="phong")["images"].copy()
    assert np.abs(base[0] - base[1]).max() > 0.1                      # uniform shows its facets
    finer = view.set_values(facets=16)["images"]
    assert np.abs(finer[0] - base[0]).max() > 0.05
    sharper = view.set_values(exponent=100.0)["images"]
    assert np.abs(sharper[1] - finer[1]).max() > 0.05
    moved = view.set_values(light0_x=-4.0, light0_z=-3.0)["images"]
    # the lit side moves from upper right to lower left
    h = moved.shape[1]
    i, j = h // 2 + 25, h // 2 - 25
    assert moved[1, i, j].sum() > sharper[1, i, j].sum() + 0.3


def test_dragging_the_light_marker_moves_the_light(hooks):
    view = sv.shading_view()
    hooks["press_at"](view.drag, 2.5, 3.0)
    hooks["move_to"](view.drag, -3.0, -2.0)
    hooks["release"](view.drag)
    assert view.values()["light0_x"] == pytest.approx(-3.0) and view.values()["light0_z"] == pytest.approx(-2.0)
    assert np.allclose(view.last_result["light"], [-3.0, -4.0, -2.0])
    marker = view.figure.axes[0].lines[0]
    assert np.allclose(marker.get_data(), [[-3.0], [-2.0]])


def test_mach_band_view_draws_the_rendered_profiles_and_the_library_slopes():
    view = sv.mach_band_view()
    r = view.set_values(row=86, facets=6, show="Gouraud and Phong")
    V, T = shading.uv_sphere(6, 12)
    cam = Camera(width=160, height=160, **sv.SHADING_CAMERA)
    m = lighting.Material(**sv.MACH_MATERIAL)
    ids = rasteriser.rasterise_triangles(cam.project(V)[:, :3], T, 160, 160).triangle[86]
    for k, mode in enumerate(("gouraud", "phong")):
        image = shading.render(V, T, cam, lighting.Light(sv.MACH_LIGHT), m, mode=mode, ambient_light=0.3,
                               background=(1, 1, 1))
        assert np.allclose(r["images"][k], image)
        grey, slope = shading.scanline_profile(image, 86)
        assert np.allclose(r["grey"][k], grey) and np.allclose(r["slope"][k], slope)
        e = shading.edge_slopes(grey, ids)
        assert r["edges"].tolist() == e.columns.tolist() and np.allclose(r["jumps"][k], e.jump)
    assert "column 80" in r["status"]
    grey_axes = view.figure.axes[2]
    assert np.allclose(grey_axes.lines[0].get_ydata(), r["grey"][0])


def test_mach_band_view_toggles_the_profiles_and_follows_the_row():
    view = sv.mach_band_view()
    view.set_values(show="Phong")
    grey_axes = view.figure.axes[2]
    assert [line.get_visible() for line in grey_axes.lines[:2]] == [False, True]
    view.set_values(show="Gouraud")
    assert [line.get_visible() for line in grey_axes.lines[:2]] == [True, False]
    first = view.figure.axes[0].images[0]
    r = view.set_values(row=3)
    assert view.figure.axes[0].images[0] is first                      # updated in place
    assert len(r["edges"]) == 0 and "no mesh edge" in r["status"]      # the row misses the sphere
    with pytest.raises(ValueError, match="show"):
        sv.mach_band_view(show="both")
