"""The shared drag helper: a press near a point grabs it, motions move it, sliders follow, and the
view's plain update runs once per motion."""

import ipywidgets as widgets
import numpy as np
import pytest
from matplotlib.figure import Figure

from goldman_lib.widgets.drag import PointDrag, drag_sliders
from goldman_lib.widgets.interactive import InteractiveView, float_slider


def _view():
    fig = Figure()
    ax = fig.add_subplot()
    ax.set_xlim(-2, 12), ax.set_ylim(-2, 12)
    (line,) = ax.plot([1, 5], [1, 5], "o-")
    calls = []

    def update(x0, y0, x1, y1):
        calls.append((x0, y0, x1, y1))
        line.set_data([x0, x1], [y0, y1])
        return {"points": np.array([[x0, y0], [x1, y1]]), "status": "ok"}

    controls = {"x0": float_slider("x0", 1, 0, 10, 0.1), "y0": float_slider("y0", 1, 0, 10, 0.1),
                "x1": float_slider("x1", 5, 0, 10, 0.1), "y1": float_slider("y1", 5, 0, 10, 0.1)}
    view = InteractiveView(controls=controls, views=[widgets.HTML("")], update=update, figure=fig)
    return view, ax, calls


def test_a_drag_moves_the_nearest_point_and_its_sliders_follow(hooks):
    view, ax, calls = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    calls.clear()
    hooks["press_at"](drag, 5.05, 4.95)            # near point 1
    hooks["move_to"](drag, 7.23, 2.0)
    hooks["move_to"](drag, 8.0, 3.04)
    hooks["release"](drag)
    assert view.values() == {"x0": 1.0, "y0": 1.0, "x1": 8.0, "y1": 3.0}   # snapped to the 0.1 steps
    assert calls == [(1.0, 1.0, 7.2, 2.0), (1.0, 1.0, 8.0, 3.0)]            # one update per motion
    hooks["move_to"](drag, 2.0, 2.0)               # released: motions do nothing
    assert len(calls) == 2


def test_a_press_far_from_every_point_grabs_nothing_and_drags_stay_in_range(hooks):
    view, ax, calls = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    calls.clear()
    hooks["press_at"](drag, 9.0, 9.0)
    hooks["move_to"](drag, 3.0, 3.0)
    hooks["release"](drag)
    assert calls == [] and view.values()["x1"] == 5.0
    hooks["press_at"](drag, 1.0, 1.0)
    hooks["move_to"](drag, -1.0, 11.0)              # past the sliders' ranges: clamped
    assert view.values()["x0"] == 0.0 and view.values()["y0"] == 10.0


def test_point_drag_reports_index_and_data_coordinates(hooks):
    fig = Figure()
    ax = fig.add_subplot()
    ax.set_xlim(-1, 1), ax.set_ylim(-1, 1)
    got = []
    d = PointDrag(ax, lambda: np.array([[0.0, 0.0], [0.5, 0.5]]), lambda k, x, y: got.append((k, x, y)),
                  on_release=lambda k: got.append(("released", k)))
    hooks["press_at"](d, 0.01, -0.01)
    hooks["move_to"](d, -0.25, 0.75)
    hooks["release"](d)
    assert got[0][0] == 0 and np.allclose(got[0][1:], (-0.25, 0.75)) and got[1] == ("released", 0)
    d.enabled = False
    hooks["press_at"](d, 0.5, 0.5)
    hooks["move_to"](d, 0.0, 0.0)
    assert len(got) == 2
    d.disconnect()


def test_drag_sliders_refuses_unknown_controls():
    view, ax, _ = _view()
    with pytest.raises(KeyError, match="x9"):
        drag_sliders(view, ax, [("x9", "y0")])


def _pixel_event(drag, name, px, py):
    from matplotlib.backend_bases import MouseEvent

    canvas = drag.ax.figure.canvas
    canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=1))


def test_the_drag_plan_grabs_a_point_and_takes_it_where_it_says(hooks):
    view, ax, _ = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    view.figure.canvas.draw()
    plan = hooks["drag_plan"](drag, distance=40)
    assert plan["index"] == 0
    assert np.allclose(plan["start"], hooks["screen_position"](drag, 0))
    assert np.hypot(*np.subtract(plan["end"], plan["start"])) == pytest.approx(40.0)
    assert plan["figure"] == [view.figure.bbox.width, view.figure.bbox.height]
    x0, y0 = plan["start"]
    _pixel_event(drag, "button_press_event", x0, y0)
    _pixel_event(drag, "motion_notify_event", *plan["end"])
    _pixel_event(drag, "button_release_event", *plan["end"])
    now = hooks["screen_position"](drag, 0)
    assert np.hypot(now[0] - plan["end"][0], now[1] - plan["end"][1]) < 6   # within a 0.1 slider step
    assert view.values()["x1"] == 5.0 and view.values()["y1"] == 5.0


def test_the_drag_plan_is_none_when_no_point_is_inside_the_axes(hooks):
    view, ax, _ = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    ax.set_xlim(20, 30)
    assert hooks["drag_plan"](drag) is None
    with pytest.raises(ValueError, match="distance"):
        hooks["drag_plan"](drag, distance=-1)
    with pytest.raises(ValueError, match="index"):
        hooks["screen_position"](drag, 2)


def _draggable_factories():
    from goldman_lib.views import factories

    import inspect

    def drags(f, depth=1):
        # a factory that makes its points draggable calls drag_sliders, LightControl.drag_in or
        # PointDrag, itself or through a helper of its module
        if any(word in inspect.getsource(f) for word in ("drag_sliders(", ".drag_in(", "PointDrag(")):
            return True
        helpers = [f.__globals__.get(n) for n in f.__code__.co_names]
        return depth > 0 and any(inspect.isfunction(h) and h.__module__ == f.__module__ and drags(h, depth - 1)
                                 for h in helpers)

    return [(name, f) for name, f in factories() if drags(f)]


@pytest.mark.parametrize("name,factory", _draggable_factories(), ids=lambda v: v if isinstance(v, str) else "")
def test_every_drag_plan_takes_its_point_to_the_mouse(name, factory, hooks):
    """What the browser test does with a real mouse in every view with draggable points, here with
    matplotlib events on Agg: press on the planned point, move in four steps, and at the end the
    point is under the mouse (to its sliders' steps) and only it moved."""
    import matplotlib.pyplot as plt

    view = factory()
    drag = view.drag
    view.figure.canvas.draw()
    plan = hooks["drag_plan"](drag)
    assert plan is not None, f"{name}: no point can be dragged 40 px"
    others = np.delete(np.asarray(drag.get_points(), float).reshape(-1, 2), plan["index"], axis=0)
    start, end = np.array(plan["start"]), np.array(plan["end"])
    _pixel_event(drag, "button_press_event", *start)
    for k in range(1, 5):
        _pixel_event(drag, "motion_notify_event", *(start + (end - start) * k / 4))
    now = np.array(hooks["screen_position"](drag, plan["index"]))
    _pixel_event(drag, "button_release_event", *end)
    assert np.hypot(*(now - end)) <= 10.0, f"{name}: the point is {np.hypot(*(now - end)):.1f} px from the mouse"
    after = np.delete(np.asarray(drag.get_points(), float).reshape(-1, 2), plan["index"], axis=0)
    if name != "ifs_editor.ifs_editor":      # there the three grips are one map's images: they move together
        assert np.allclose(after, others), f"{name}: points other than the dragged one moved"
    assert view.last_error is None, view.last_error
    plt.close(view.figure)


def test_interactive_view_find_names_its_rules(hooks):
    view, _, _ = _view()
    assert hooks["find_view"](view.uid) is view
    assert f"goldman-view-{view.uid}" in view._dom_classes
    with pytest.raises(TypeError, match="uid"):
        hooks["find_view"]("0")
    with pytest.raises(ValueError, match="uid"):
        hooks["find_view"](-1)


def test_the_point_ends_where_the_mouse_lets_go_even_if_motions_were_lost(hooks):
    """A browser may drop motion events while the kernel draws; the release still carries the
    mouse's position, and the held point ends there (once: no second update if it is already there)."""
    view, ax, calls = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    calls.clear()
    hooks["press_at"](drag, 1.0, 1.0)
    hooks["move_to"](drag, 2.0, 2.0)                 # the motions to (4, 3) never arrived
    hooks["release"](drag, 4.0, 3.0)
    assert view.values()["x0"] == 4.0 and view.values()["y0"] == 3.0
    assert calls == [(2.0, 2.0, 5.0, 5.0), (4.0, 3.0, 5.0, 5.0)]
    calls.clear()
    hooks["press_at"](drag, 4.0, 3.0)
    hooks["move_to"](drag, 6.0, 3.0)
    hooks["release"](drag, 6.0, 3.0)                 # released where the last motion was: no extra update
    assert calls == [(6.0, 3.0, 5.0, 5.0)]
    calls.clear()
    hooks["release"](drag, 8.0, 8.0)                 # nothing held: a release moves nothing
    assert calls == [] and view.values()["x1"] == 5.0


def test_the_drag_plan_also_gives_data_coordinates_and_the_scale(hooks):
    view, ax, _ = _view()
    drag = drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1")])
    view.figure.canvas.draw()
    plan = hooks["drag_plan"](drag, distance=40)
    assert plan["start_data"] == hooks["position"](drag, 0) == [1.0, 1.0]
    scale = np.array(plan["pixels_per_unit"])
    assert np.allclose((np.array(plan["end_data"]) - plan["start_data"]) * scale,
                       np.abs(np.subtract(plan["end"], plan["start"])))
    assert np.allclose(ax.transData.transform(plan["end_data"]), plan["end"])
