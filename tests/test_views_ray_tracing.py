"""Chapter 17's view draws what goldman_lib.ray_tracing computes: the image of the chapter's scene
(the same pixels as render), updated in place by the depth, index and light sliders, and the ray
tree of the chosen pixel in the x-z side view, chosen by sliders or a click, with the light dragged."""

import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent

from goldman_lib import ray_tracing as rt
from goldman_lib.views import ray_tracing as rv


def _render(depth, index, light):
    return rt.render(rt.default_scene(index=index, lights=[light]), rt.default_camera(), rv.WIDTH, rv.HEIGHT, depth)


def test_the_image_is_the_library_render_and_is_updated_in_place():
    view = rv.ray_tracing_view()
    ax_img, _ = view.axes
    artist = ax_img.images[0]
    r = view.set_values(light0_x=0.5, light0_z=4.0, depth=2, index=1.3)
    light, = view.light_control.lights(view.values())
    assert light.position == (0.5, -1.5, 4.0)
    assert np.allclose(r["image"], _render(2, 1.3, light), atol=1e-12)
    assert len(ax_img.images) == 1 and ax_img.images[0] is artist          # imshow once, set_data after
    assert np.array_equal(np.asarray(artist.get_array()), r["image"])
    assert r["pixel"].tolist() == r["image"][view.values()["py"], view.values()["px"]].tolist()


def test_each_slider_changes_what_is_drawn():
    view = rv.ray_tracing_view()
    base = view.last_result["image"].copy()
    for values in (dict(light0_x=-5.0), dict(light0_z=2.0), dict(light0_I=0.4), dict(depth=0), dict(index=2.0)):
        view.set_values(**values)
        assert not np.allclose(view.last_result["image"], base), values
        view.set_values(**{"light0_x": -2.5, "light0_z": 5.0, "light0_I": 1.0, "depth": 3, "index": 1.5})
        assert np.allclose(view.last_result["image"], base)


def test_the_ray_tree_of_the_chosen_pixel():
    view = rv.ray_tracing_view()
    r = view.set_values(depth=0, px=80, py=60)
    kinds = [rv.KINDS[k] for k in r["kinds"]]
    assert kinds[0] == "primary" and set(kinds) <= {"primary", "shadow"}
    # the primary ray starts at the eye, seen from the side: (x, z) = (-7, 2.2)
    assert np.allclose(r["segments"][0, 0], [-7.0, 2.2])
    # a pixel on the glass sphere has reflected and refracted rays at depth 3
    r = view.set_values(depth=3, px=52, py=70)
    assert {"reflected", "refracted", "shadow"} <= {rv.KINDS[k] for k in r["kinds"]}
    tree = rt.ray_tree(rt.default_scene(), rt.default_camera(), 52, 70, 3, rv.WIDTH, rv.HEIGHT, miss_length=4.0)
    assert np.allclose(r["segments"], [[s.start[[0, 2]], s.end[[0, 2]]] for s in tree])
    assert r["blocked"].tolist() == [s.kind == "shadow" and s.light == 0 for s in tree]
    # pixel (52, 70)'s tree has shadow rays that pass the glass sphere with k_t = 0.88 of the light
    assert any(s.kind == "shadow" and s.hit and s.light == pytest.approx(0.88) for s in tree)
    assert "2 through glass" in r["status"]
    assert "at most 30" in r["status"]
    r = view.set_values(index=1.0)
    assert "none (no total internal reflection)" in r["status"]


def test_clicking_the_image_chooses_the_pixel():
    view = rv.ray_tracing_view()
    ax_img, _ = view.axes
    fig = ax_img.figure
    fig.canvas.draw()
    x, y = ax_img.transData.transform((120.2, 30.7))
    event = MouseEvent("button_press_event", fig.canvas, x, y, button=1)
    fig.canvas.callbacks.process("button_press_event", event)
    assert (view.values()["px"], view.values()["py"]) == (120, 31)
    assert view.last_result["segments"][0, 0].tolist() == [-7.0, 2.2]


def test_dragging_the_light_in_the_side_view():
    view = rv.ray_tracing_view()
    before = view.last_result["image"].copy()
    _, ax_side = view.axes
    ax_side.figure.canvas.draw()
    view.drag.press_at(-2.5, 5.0)
    view.drag.move_to(1.0, 3.0)
    view.drag.release()
    assert view.values()["light0_x"] == 1.0 and view.values()["light0_z"] == 3.0
    assert not np.allclose(view.last_result["image"], before)
