"""Chapter 22 view: the algorithm picker and the step-through show the frames hidden_surfaces.frames
computes, in place; only the heedless painter's finished image differs from the z-buffer's off the edges."""

import numpy as np

from goldman_lib import hidden_surfaces as hs
from goldman_lib.views import hidden_surfaces as hv


def test_steps_show_the_algorithms_frames_in_place():
    view = hv.hidden_surfaces_view()
    camera = hs.default_camera(120, 90)
    polygons, colours = hs.default_scene()
    image = view.figure.axes[0].images[0]
    for name in ("BSP tree", "scan line", "z-buffer"):
        frames = hs.frames(name, polygons, camera)
        r = view.set_values(algorithm=name, step=2)
        assert r["steps"] == len(frames) and np.array_equal(r["frame"], frames[1])
        assert view.figure.axes[0].images[0] is image
        assert np.allclose(image.get_array(), hs.shade(frames[1], polygons, colours, camera))
    first = view.set_values(algorithm="depth sort", step=1)["frame"].copy()
    later = view.set_values(step=8)["frame"]
    assert (later >= 0).sum() > (first >= 0).sum()
    r = view.set_values(step=10_000 if 10_000 <= view.controls["step"].max else view.controls["step"].max)
    assert r["step"] == r["steps"]


def test_only_the_heedless_painter_is_wrong():
    view = hv.hidden_surfaces_view()
    for name in hs.ALGORITHMS:
        r = view.set_values(algorithm=name, step=0)
        assert (r["wrong"] > 50) == (name == "heedless painter"), name
    assert "pixels differ" in r["status"]
