"""Every 2D view where a learner places points lets the mouse drag them (CONVENTIONS, "Direct
manipulation"; issue 18 §1: chapter 4's "drag the three image points" had sliders only).

"Places points" is read from the controls: two sliders whose names differ in one letter, x for y
or z (``x0``/``y0``, ``qx``/``qy``, ``light0_x``/``light0_y``, ``eye_y``/``eye_z``), in a view with a
matplotlib figure (the three.js views orbit with the mouse instead).  Such a view must have a
``view.drag``, unless it is in :data:`NOT_PLACED_POINTS` with the reason.
"""

import inspect
import itertools

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np
import pytest

from goldman_lib.views import factories
from goldman_lib.widgets.interactive import figure_png

#: Views whose x/y slider pairs are not points the learner places in the 2D drawing.
NOT_PLACED_POINTS = {
    # the four panels are images of the lit sphere; no light marker is drawn in them (the light is
    # dragged in color_intensity.shaded_sphere_view's side view, which draws it)
    "color_intensity.terms_view": "no light marker in the picture",
    # sx/sy are scale factors of a map, tx/ty its translation: the embedded IFS editor
    # (view.editor, ifs_editor.ifs_editor) drags the images of its reference triangle instead
    "conformal_ifs.tao_view": "the embedded editor (view.editor.drag) drags the maps",
    # s_x, s_y are the two scale factors of the map, not a point
    "codo.turtle_shortcoming_view": "sx, sy are scale factors",
    # the picture is a ray-traced image of the surface seen by the camera; the light is not drawn in it
    "simple_surfaces.gallery_view": "no light marker in the picture",
}

_SLIDERS = (widgets.FloatSlider, widgets.IntSlider)


def point_pairs_of(controls) -> list[tuple[str, str]]:
    """Slider pairs whose names differ in one letter, x for y or z, or y for z."""
    names = [k for k, w in controls.items() if isinstance(w, _SLIDERS)]
    pairs = []
    for a, b in itertools.combinations(names, 2):
        if len(a) != len(b):
            continue
        diff = [(p, q) for p, q in zip(a, b) if p != q]
        if len(diff) == 1 and set(diff[0]) <= set("xyz"):
            pairs.append((a, b))
    return pairs


def test_the_point_pair_rule_finds_the_pairs_it_should():
    s = lambda: widgets.FloatSlider()
    controls = {"x0": s(), "y0": s(), "x1": s(), "y1": s(), "qx": s(), "qy": s(), "light0_x": s(),
                "light0_z": s(), "angle": s(), "t": s(), "kind": widgets.Dropdown(options=["x", "y"])}
    assert point_pairs_of(controls) == [("x0", "y0"), ("x1", "y1"), ("qx", "qy"), ("light0_x", "light0_z")]


def _update_parameters(factory):
    """The parameters of the ``update`` a factory defines (its controls' names), read from the
    nested code objects without building the view (building all of them takes minutes here)."""
    found, open_ended = [], []

    def walk(code):
        for c in code.co_consts:
            if hasattr(c, "co_code"):
                if c.co_name == "update":
                    found.extend(c.co_varnames[:c.co_argcount + c.co_kwonlyargcount])
                    open_ended.append(bool(c.co_flags & inspect.CO_VARKEYWORDS))
                walk(c)

    walk(factory.__code__)
    if not open_ended or any(open_ended):
        # update(**values): the names are known only to the built view (few views: build them)
        view = factory()
        found = list(view.controls)
        if view.figure is not None:
            plt.close(view.figure)
    return found


def _drags(factory, depth=1):
    """Does a factory make points draggable (drag_sliders, LightControl.drag_in, PointDrag, itself
    or through a helper of its module)?  The same reading as test_views_drag's."""
    import inspect

    if any(word in inspect.getsource(factory) for word in ("drag_sliders(", ".drag_in(", "PointDrag(")):
        return True
    helpers = [factory.__globals__.get(n) for n in factory.__code__.co_names]
    return depth > 0 and any(inspect.isfunction(h) and h.__module__ == factory.__module__ and _drags(h, depth - 1)
                             for h in helpers)


def _two_d_factories():
    """(name, pairs, drags) of every factory with a matplotlib figure that drags points, or that
    has point pairs among its update's parameters (every parameter is a control: InteractiveView
    passes them by name)."""
    out = []
    for name, factory in factories():
        if "figure_widget(" not in inspect.getsource(factory):
            continue                      # a three.js view: the mouse orbits the camera
        if _drags(factory):
            out.append((name, None, True))      # drags: its pairs need not be read (nor the view built)
            continue
        pairs = point_pairs_of({k: widgets.FloatSlider() for k in _update_parameters(factory)})
        if pairs:
            out.append((name, pairs, False))
    return out


def test_the_static_reading_matches_a_built_view():
    """The parameters read from the code are the controls of the built view (for one view with
    a dropdown and point sliders, and one whose light sliders come from the light control)."""
    table = dict(factories())
    for name in ("affine.three_point_explorer", "color_intensity.shaded_sphere_view"):
        view = table[name]()
        controls = set(view.controls) - {k for k in view.controls if k.endswith("_colour")}
        assert set(_update_parameters(table[name])) - {"light0_colour", "light1_colour"} == controls
        plt.close(view.figure)


def test_every_2d_view_that_places_points_drags_them():
    found = _two_d_factories()
    missing = [(name, pairs) for name, pairs, drags in found if not drags and name not in NOT_PLACED_POINTS]
    assert not missing, f"views that place points with sliders but have no view.drag: {missing}"
    # the exclusions stay justified: each names a view that still has point pairs and no drag of its own
    undragged = {name for name, _, drags in found if not drags}
    assert set(NOT_PLACED_POINTS) <= undragged, sorted(set(NOT_PLACED_POINTS) - undragged)
    assert {"affine.three_point_explorer", "bezier.de_casteljau_explorer"} <= {name for name, _, _ in found}


def _factories(*names):
    table = dict(factories())
    return [(n, table[n]) for n in names]


#: The views made draggable for issue 18, the point each test grabs (its x and y sliders) and where
#: it takes it (a move in data units, inside the sliders' ranges from the defaults).
NEW = {
    "affine.three_point_explorer": (("x2", "y2"), (-0.7, 0.6)),
    "affine.rotation_about_point_view": (("qx", "qy"), (-1.0, 0.5)),
    "affine.transform_explorer": (("cx", "cy"), (-0.5, 0.7)),
    "mass_points.pseudoperspective_view": (("eye_z", "eye_y"), (1.0, 0.5)),
    "conformal_ifs.initial_state_view": (("x", "y"), (-0.5, -0.4)),
    "conformal_ifs.turtle_ifs_view": (("x", "y"), (0.3, 0.2)),
}


@pytest.mark.parametrize("name,factory", _factories(*NEW), ids=lambda v: v if isinstance(v, str) else "")
def test_a_mouse_drag_moves_the_point_its_sliders_and_the_drawing(name, factory, hooks):
    (xs, ys), (dx, dy) = NEW[name]
    view = factory()
    drag = view.drag
    view.figure.canvas.draw()
    before_png = figure_png(view.figure)
    start = np.array([view.values()[xs], view.values()[ys]])
    target = start + (dx, dy)
    hooks["press_at"](drag, *start)
    hooks["move_to"](drag, *(start + target) / 2)
    hooks["move_to"](drag, *target)
    hooks["release"](drag)
    assert view.last_error is None, view.last_error
    assert view.values()[xs] == pytest.approx(target[0], abs=1e-9)       # the sliders followed
    assert view.values()[ys] == pytest.approx(target[1], abs=1e-9)
    grabbed = np.asarray(drag.get_points(), float).reshape(-1, 2)
    assert np.min(np.hypot(*(grabbed - target).T)) < 1e-9                 # the point is where it was taken
    assert figure_png(view.figure) != before_png                           # and the drawing changed
    plt.close(view.figure)


def test_the_translation_drags_the_tip_of_v_and_the_other_maps_their_centre(hooks):
    (_, factory), = _factories("affine.transform_explorer")
    view = factory(kind="translation")
    view.figure.canvas.draw()
    drag = view.drag
    assert hooks["position"](drag, 0) == [1.5, 0.5]                # the tip of v = (tx, ty), where the guide ends
    hooks["press_at"](drag, 1.5, 0.5)
    hooks["move_to"](drag, -1.0, 2.0)
    hooks["release"](drag)
    assert (view.values()["tx"], view.values()["ty"]) == (-1.0, 2.0)
    assert np.allclose(view.last_result["image"][0] - view.last_result["original"][0], [-1.0, 2.0])
    view.set_values(kind="rotation")
    assert hooks["position"](drag, 0) == [view.values()["cx"], view.values()["cy"]]
    plt.close(view.figure)
