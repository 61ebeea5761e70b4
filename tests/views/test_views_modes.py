"""A control that does not act in the current mode is disabled (issue 18 §1: the radiosity view's
Jacobi and Gauss-Seidel sliders changed nothing while progressive refinement was shown).

For every widget factory, for every value of every mode control (a dropdown, toggle or checkbox),
set as a learner would (so the views' own hide/disable rules run), every slider still enabled and
visible is moved from its default to its minimum and to its maximum: at least one of the two must
change what ``update`` returns (its status line aside).  Measured, not assumed.
"""

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np
import pytest

from goldman_lib.views import factories
from goldman_lib.widgets.interactive import InteractiveView, dropdown, int_slider

MODES = (widgets.Dropdown, widgets.ToggleButtons, widgets.RadioButtons, widgets.Checkbox, widgets.ToggleButton)
SLIDERS = (widgets.FloatSlider, widgets.IntSlider)

#: (view, mode control or "*", slider): sliders that act although update's return does not show it
#: in that mode, each with the reason.
ACTS_UNSEEN = {
    # the light moves the three.js scene's lamp and its shading, drawn by the browser, not returned
    **{("simple_surfaces.surface_scene_view", "*", k): "three.js light"
       for k in ("light0_x", "light0_y", "light0_z", "light0_I")},
    # lift moves the drawn vertex (the red dot, scene.set_points); on these solids the faces stay
    # planar, so the readout update returns is unchanged -- which is what the slider shows
    ("solid_modeling.brep_view", "solid", "lift"): "moves the drawn vertex; the readout is the lesson",
    # scaling along d = (1, 0, 0.6) about c does not depend on c's y coordinate (only c . d counts);
    # cy acts for a direction with a y component, and always for uniform scaling
    ("transforms.scaling_view", "kind", "cy"): "c . d does not involve cy for the default direction",
    # the chaos game's probabilities and point count act on the embedded editor's drawing (view.editor),
    # not on Tao's program, which is what tao_view's own update returns
    **{("conformal_ifs.tao_view", "*", f"p{i}"): "acts on view.editor's drawing" for i in range(8)},
    ("conformal_ifs.tao_view", "*", "points"): "acts on view.editor's drawing",
}


def _same(a, b) -> bool:
    if isinstance(a, dict) and isinstance(b, dict):
        keys = (set(a) | set(b)) - {"status"}
        return all(k in a and k in b and _same(a[k], b[k]) for k in keys)
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        A, B = np.asarray(a), np.asarray(b)
        return A.shape == B.shape and bool(np.array_equal(A, B, equal_nan=A.dtype.kind in "fc"))
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001 - objects without a truthy ==
        return a is b


def _options(w):
    if isinstance(w, (widgets.Checkbox, widgets.ToggleButton)):
        return [False, True]
    opts = w.options
    return [o[1] if isinstance(o, tuple) else o for o in (opts.items() if hasattr(opts, "items") else opts)]


def _visible(widget, out=None) -> set:
    """The ids of the widgets shown under ``widget``: a box hidden with ``layout.display = "none"``
    (the IFS editor's rows of other maps, the knot editor's unused knots) hides what it holds."""
    out = set() if out is None else out
    layout = getattr(widget, "layout", None)
    if layout is not None and layout.display == "none":
        return out
    out.add(id(widget))
    for child in getattr(widget, "children", ()) or ():
        if isinstance(child, widgets.Widget):
            _visible(child, out)
    return out


def _dead_sliders(view):
    """[(mode, value, slider)] for every enabled, visible slider that moving to its ends leaves unchanged."""
    defaults = view.values()
    dead = []
    for mode, w in view.controls.items():
        if not isinstance(w, MODES):
            continue
        for value in _options(w):
            view.set_values(**{**defaults, mode: value})
            base = view.values()
            before = view.update(**base)
            shown = _visible(view)
            for name, s in view.controls.items():
                if not isinstance(s, SLIDERS) or s.disabled or id(s) not in shown:
                    continue
                ends = [v for v in (s.min, s.max) if v != base[name]]
                if ends and all(_same(before, view.update(**{**base, name: v})) for v in ends):
                    dead.append((mode, value, name))
        view.set_values(**defaults)
    return dead


FACTORIES = [(name, f) for name, f in factories()]


@pytest.mark.parametrize("name,factory", FACTORIES, ids=[n for n, _ in FACTORIES])
def test_every_enabled_slider_acts_in_every_mode(name, factory):
    view = factory()
    if not any(isinstance(w, MODES) for w in view.controls.values()):
        pytest.skip("no mode control")
    dead = [(m, v, s) for m, v, s in _dead_sliders(view)
            if (name, m, s) not in ACTS_UNSEEN and (name, "*", s) not in ACTS_UNSEEN]
    if view.figure is not None:
        plt.close(view.figure)
    assert not dead, f"{name}: sliders enabled where they change nothing (mode, value, slider): {dead}"


def test_the_radiosity_steps_act_only_for_their_solver():
    (_, factory), = [(n, f) for n, f in FACTORIES if n == "radiosity.radiosity_view"]
    view = factory()
    steps = {"progressive": "shots", "jacobi": "jacobi_k", "gauss_seidel": "gs_k"}
    for solver, slider in steps.items():
        view.controls["solver"].value = solver          # as a learner picks it
        assert {k: view.controls[k].disabled for k in steps.values()} == {k: k != slider for k in steps.values()}
    plt.close(view.figure)


def test_acts_disables_and_re_enables_and_names_its_rules():
    calls = []
    controls = {"mode": dropdown("mode", ["a", "b", "c"]), "k": int_slider("k", 1, 0, 5),
                "j": int_slider("j", 1, 0, 5), "free": int_slider("free", 1, 0, 5)}
    view = InteractiveView(controls=controls, views=[], update=lambda **v: calls.append(v) or {},
                           acts={"k": {"mode": ["b", "c"]}, "j": lambda v: v["mode"] == "c"})
    state = lambda: {n: view.controls[n].disabled for n in ("k", "j", "free")}
    assert state() == {"k": True, "j": True, "free": False}
    controls["mode"].value = "b"
    assert state() == {"k": False, "j": True, "free": False}
    controls["mode"].value = "c"
    assert state() == {"k": False, "j": False, "free": False}
    view.set_values(mode="a")
    assert state() == {"k": True, "j": True, "free": False}
    assert view.acting({"mode": "c"}) == {"mode": True, "k": True, "j": True, "free": True}
    with pytest.raises(KeyError, match="nope"):
        InteractiveView(controls=controls, views=[], update=lambda **v: {}, acts={"nope": {"mode": ["a"]}})
    with pytest.raises(KeyError, match="mood"):
        InteractiveView(controls=controls, views=[], update=lambda **v: {}, acts={"k": {"mood": ["a"]}})
