"""The widget pattern: InteractiveView calls a plain update function, never shows a traceback,
and carries a static PNG fallback in its display bundle."""

import ipywidgets as widgets
import numpy as np
import pytest

from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, figure_png
from sweeps import control_grid, covering_corners, sweep_values

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def make_view():
    fig, ax = style.new_axes()
    (line,) = ax.plot([], [])
    calls = []

    def update(a, b):
        if b < 0:
            raise ValueError("b must be >= 0; got %s" % b)
        x = np.linspace(0, 1, 5)
        line.set_data(x, a * x + b)
        calls.append((a, b))
        return {"y": a * x + b, "status": f"a={a}, b={b}"}

    view = InteractiveView(controls={"a": widgets.FloatSlider(value=1, min=-2, max=2),
                                     "b": widgets.IntSlider(value=0, min=-1, max=3)},
                           views=[], update=update, figure=fig, title="line")
    return view, calls, line


def test_update_runs_at_construction_and_on_every_slider_change():
    view, calls, line = make_view()
    assert calls == [(1.0, 0)]
    view.controls["a"].value = 2.0
    assert calls[-1] == (2.0, 0)
    np.testing.assert_allclose(line.get_ydata(), [0, 0.5, 1, 1.5, 2])
    assert view.status.value == "a=2.0, b=0"


def test_error_is_a_message_not_a_traceback_and_the_last_drawing_stays():
    view, calls, line = make_view()
    view.controls["b"].value = -1  # update raises; refresh must swallow it
    assert view.last_error == "ValueError: b must be >= 0; got -1"
    assert "b must be &gt;= 0" in view.status.value and "Traceback" not in view.status.value
    np.testing.assert_allclose(line.get_ydata(), [0, 0.25, 0.5, 0.75, 1])
    view.controls["b"].value = 1
    assert view.last_error is None


def test_set_values_updates_once_and_returns_the_drawing():
    view, calls, _ = make_view()
    result = view.set_values(a=-2.0, b=3)
    assert calls[-1] == (-2.0, 3) and len(calls) == 2
    np.testing.assert_allclose(result["y"], [3, 2.5, 2, 1.5, 1])
    with pytest.raises(KeyError, match="no control named 'c'"):
        view.set_values(c=1)


def test_sweep_values_cover_every_corner():
    view, _, _ = make_view()
    combos = sweep_values(view, n=3)
    assert {(c["a"], c["b"]) for c in combos} >= {(-2.0, -1), (-2.0, 3), (2.0, -1), (2.0, 3)}


def test_control_grid_for_many_controls_stays_bounded_and_keeps_extremes():
    controls = {f"s{i}": widgets.FloatSlider(value=0, min=-1, max=1) for i in range(9)}
    combos = control_grid(controls, n=3, max_full=50)
    assert len(combos) < 3 ** 9
    assert {k: -1.0 for k in controls} in combos and {k: 1.0 for k in controls} in combos
    assert all(set(c) == set(controls) for c in combos)


def test_display_bundle_has_widget_view_png_fallback_and_short_text():
    view, _, _ = make_view()
    bundle = view._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    import base64
    assert base64.b64decode(bundle["image/png"]).startswith(PNG_MAGIC)
    assert bundle["text/plain"] == "[interactive view: line; run the notebook to use it]"
    assert figure_png(view.figure).startswith(PNG_MAGIC)


def test_covering_corners_meet_every_three_controls_in_every_combination():
    import itertools

    import numpy as np


    for k in (3, 5, 9, 17):
        for strength in (2, 3):
            rows = covering_corners(k, strength)
            assert rows.shape[1] == k and set(np.unique(rows)) <= {0, 1}
            for group in itertools.combinations(range(k), strength):
                assert len({tuple(r[list(group)]) for r in rows}) == 2 ** strength, (k, strength, group)
    # few rows: far fewer than the 2**17 corners, and deterministic
    assert len(covering_corners(17)) < 40
    assert (covering_corners(17) == covering_corners.__wrapped__(17)).all()


def test_covering_corners_refuse_bad_sizes():
    import pytest


    for bad in (-1, 2.5, True):
        with pytest.raises(ValueError, match="k must be"):
            covering_corners(bad)
    with pytest.raises(ValueError, match="strength must be"):
        covering_corners(5, 7)


def test_the_sweep_of_a_view_with_many_controls_reaches_every_triple_of_extremes():
    import itertools

    import ipywidgets as widgets

    controls = {f"c{i}": widgets.FloatSlider(value=0.5, min=0.0, max=1.0) for i in range(12)}
    combos = control_grid(controls, n=3)
    assert len(combos) < 400
    for group in itertools.combinations(controls, 3):
        seen = {tuple(c[name] for name in group) for c in combos if all(c[name] in (0.0, 1.0) for name in group)}
        assert len(seen) == 8, group
