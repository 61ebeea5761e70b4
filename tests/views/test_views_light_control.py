"""The light-position control: sliders <-> lights, markers, the drag, and a SceneView lit in place."""

import numpy as np
import pytest
from matplotlib.figure import Figure

from goldman_lib.lighting import Light
from goldman_lib.widgets.interactive import InteractiveView
from goldman_lib.widgets.light_control import LightControl
from goldman_lib.widgets.three import SceneView


def test_two_lights_round_trip_through_the_sliders():
    c = LightControl([Light((1, 2, 3), colour=(1, 0, 0), intensity=0.5), (0, 0, 4)], box=(-5, 5))
    assert len(c.controls) == 10
    lights = c.lights(c.defaults())
    assert lights[0].position == (1.0, 2.0, 3.0) and lights[0].colour == (1.0, 0.0, 0.0)
    assert lights[0].intensity == 0.5 and lights[1].position == (0.0, 0.0, 4.0)
    moved = c.lights({**c.defaults(), "light1_z": -2.0, "light0_colour": "#00ff00"})
    assert moved[1].position == (0.0, 0.0, -2.0) and moved[0].colour == (0.0, 1.0, 0.0)
    assert np.allclose(c.marker_positions(c.defaults()), [[1, 2, 3], [0, 0, 4]])


def test_positions_outside_the_box_are_clamped_and_bad_boxes_refused():
    c = LightControl([(10, 0, 0)], box=(-6, 6), colour=False)
    assert c.controls["light0_x"].value == 6.0 and "light0_colour" not in c.controls
    with pytest.raises(ValueError, match="box"):
        LightControl(box=(3, 1))
    with pytest.raises(ValueError, match="lights"):
        LightControl([])


def _view(control, seen):
    fig = Figure()
    ax = fig.add_subplot()
    ax.set_xlim(-6, 6), ax.set_ylim(-6, 6)
    fig.canvas.draw()

    def update(**values):
        seen.append(control.lights(values))
        return {"status": "ok"}

    view = InteractiveView(controls=control.controls, views=[], update=update)
    return view, ax


def test_dragging_the_marker_moves_the_light_and_its_sliders(hooks):
    c = LightControl([(1.0, 0.0, 2.0)], colour=False)
    seen = []
    view, ax = _view(c, seen)
    drag = c.drag_in(view, ax, plane="xz")
    hooks["press_at"](drag, 1.0, 2.0)
    hooks["move_to"](drag, -3.0, 4.0)
    hooks["release"](drag)
    assert view.controls["light0_x"].value == pytest.approx(-3.0)
    assert view.controls["light0_z"].value == pytest.approx(4.0)
    assert seen[-1][0].position == pytest.approx((-3.0, 0.0, 4.0))
    with pytest.raises(ValueError, match="plane"):
        c.drag_in(view, ax, plane="xx")


def test_the_scene_is_lit_and_marked_in_place():
    c = LightControl([(2.0, 2.0, 2.0)])
    scene = SceneView(lights=c.lights(c.defaults()))
    c.show_in_scene(scene, c.defaults())
    first = scene._light_objects[0]
    c.show_in_scene(scene, {**c.defaults(), "light0_y": -4.0, "light0_I": 1.5})
    assert scene._light_objects[0] is first and tuple(first.position) == (2.0, -4.0, 2.0)
    assert first.intensity == 1.5
    assert np.allclose(scene.data("lights")["positions"], [[2, -4, 2]])
    with pytest.raises(ValueError, match="lights"):
        scene.set_lights([Light(), Light()])


def test_the_static_picture_follows_the_light():
    scene_a = SceneView(lights=[Light((0, 0, 5))], axes=0)
    scene_b = SceneView(lights=[Light((0, 0, -5))], axes=0)
    tri = [[0, 1, 2]]
    for s in (scene_a, scene_b):
        s.add_mesh("m", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], tri)
    assert scene_a.to_png() != scene_b.to_png()


def test_vertex_colours_live_and_static():
    pos = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]
    tri = [[0, 1, 2], [1, 3, 2]]
    s = SceneView(axes=0)
    s.add_mesh("m", pos, tri, colors=np.zeros((4, 3)), lit=False)
    dark = s.to_png()
    geom_attr = s._items["m"]["geometry"].attributes["color"]
    s.set_colors("m", np.ones((4, 3)) * [1.0, 0.2, 0.2])
    assert s._items["m"]["geometry"].attributes["color"] is geom_attr       # in place
    assert np.allclose(geom_attr.array[0], [1.0, 0.2, 0.2])
    assert s.to_png() != dark
    assert s._items["m"]["object"].material.vertexColors == "VertexColors"
    with pytest.raises(ValueError, match="colors"):
        s.set_colors("m", np.ones((3, 3)))
    with pytest.raises(ValueError, match="colors"):
        s.add_mesh("n", pos, tri, colors=np.full((4, 3), 2.0))
    s.add_mesh("plain", pos, tri)
    with pytest.raises(ValueError, match="without per-vertex colors"):
        s.set_colors("plain", np.zeros((4, 3)))


def test_axes_keeps_the_other_coordinates_where_the_light_starts():
    from goldman_lib.lighting import Light
    from goldman_lib.widgets.light_control import LightControl

    control = LightControl([Light((0.5, 0.5, 0.99), intensity=1.0)], box=(0.0, 1.0), axes="xy")
    assert sorted(control.controls) == ["light0_I", "light0_colour", "light0_x", "light0_y"]
    assert control.controls["light0_I"].value == 1.0          # a Light's intensity starts the slider
    (light,) = control.lights({**control.defaults(), "light0_x": 0.25})
    assert light.position == (0.25, 0.5, 0.99)
    assert control.marker_positions(control.defaults()).tolist() == [[0.5, 0.5, 0.99]]
    import pytest
    for bad in ("", "xw", "xx", 3):
        with pytest.raises(ValueError, match="axes"):
            LightControl([(0, 0, 1)], axes=bad)
    with pytest.raises(ValueError, match="plane"):
        control.drag_in(None, None, plane="xz")
