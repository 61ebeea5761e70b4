"""Every widget of the course (found by discovery, as the in-range sweep finds them) at values its
controls cannot reach: NaN, infinities, 1e308, 10**12, wrong types, unknown options, values just
past a slider's ends, hostile programs.  ``update`` either draws (finite arrays and a status) or raises
a ValueError/TypeError, and the view then shows that message in its status line; nothing hangs
(issue 10: every input gets bounded work and a clear answer).

The in-range sweep is tests/views/test_widget_sweeps.py.
"""

import re
import time

import ipywidgets as widgets
import numpy as np
import pytest

from goldman_lib.views import factories
from goldman_lib.widgets import interactive
from goldman_lib.widgets.interactive import InteractiveView

FACTORIES = [pytest.param(fn, id=name) for name, fn in factories()]
#: Seconds one update may take at a hostile value (the budgets make most fail in milliseconds).
LIMIT = 3.0

NUMBERS = [float("nan"), float("inf"), -float("inf"), 1e308, -1e308, 10 ** 12, -(10 ** 12), "x", None, 1 + 2j]
INTEGERS = [10 ** 12, -(10 ** 12), 10 ** 400, 2.5, float("nan"), float("inf"), "3", None]
OPTIONS = ["no such option", None, 42, float("nan")]
PROGRAMS = [
    "REPEAT 20000 [ REPEAT 20000 [ ] ]",
    "REPEAT 1e300 [ FORWARD 1 ]",
    "REPEAT 1 [ " * 500 + "]" * 500,
    "P = " + "(" * 500 + "1" + ")" * 500,
    "P = " + "-" * 2000 + "1",
    "FORWARD " + "a" * 1_000_000,
    "x" * 1_000_000,
    "TURN 1e308 TURN 1e308",
    "",
    None,
    42,
]


class _Hostile:
    """A value whose comparisons, conversions and repr all raise."""

    def __eq__(self, other):
        raise RuntimeError("__eq__ raised")

    __hash__ = object.__hash__

    def __repr__(self):
        raise RuntimeError("__repr__ raised")

    def __float__(self):
        raise RuntimeError("__float__ raised")

    def __index__(self):
        raise RuntimeError("__index__ raised")


def _nested(depth=100_000):
    out = []
    for _ in range(depth):
        out = [out]
    return out


#: Values of the wrong kind for every kind of control (issue 20): the framework refuses each with a
#: short message naming the control, before the view's own code sees it.
HOSTILE = [np.array([1.0, 2.0]), np.array(["a", "b"]), np.zeros((2, 2), dtype=bool), [1, 2], {"a": 1},
           "x" * 10_000_000, _nested(), _Hostile(), b"bytes", object()]
COLOURS = ["notacolour", "", " ", "#12345", "#gggggg", "rgb(1, 2)", "#ff0000" + "0" * 10_000_000, 42, None,
           (1.0, 0.0, 0.0), ["#ff0000"]]
BOOLEANS = [None, "yes", "True", 1, 0, 2.5, float("nan")]


def _bad_values(w):
    if isinstance(w, (widgets.IntSlider, widgets.BoundedIntText)):
        return INTEGERS + [w.min - 1, w.max + 1, w.max + 10]
    if isinstance(w, (widgets.FloatSlider, widgets.BoundedFloatText, widgets.FloatLogSlider)):
        span = max(w.max - w.min, 1.0)
        return NUMBERS + [w.min - 1e6, w.max + 1e6, w.min - span, w.max + span, 1e150]
    if isinstance(w, (widgets.Dropdown, widgets.ToggleButtons, widgets.RadioButtons, widgets.SelectionSlider)):
        return OPTIONS
    if isinstance(w, (widgets.Textarea, widgets.Text)):
        return PROGRAMS
    if isinstance(w, (widgets.Checkbox, widgets.ToggleButton)):
        return BOOLEANS
    if isinstance(w, widgets.ColorPicker):
        return COLOURS
    return [None]


def _swept(controls):
    """The controls to try: all of them, but only the first map's sliders of an 8-map editor."""
    out = []
    for name in controls:
        m = re.fullmatch(r"[a-z]+(\d+)", name)
        if m and int(m.group(1)) > 0:
            continue
        out.append(name)
    return out


def _finite(result):
    if isinstance(result, dict):
        for k, v in result.items():
            if k != "status":
                yield from _finite(v)
    elif isinstance(result, (list, tuple)) and not (result and np.isscalar(result[0])):
        for v in result:
            yield from _finite(v)
    elif isinstance(result, (bool, str)) or result is None:
        return
    else:
        yield np.asarray(result, dtype=float)


@pytest.mark.parametrize("factory", FACTORIES)
def test_out_of_range_values_give_a_status_message(factory):
    """Out-of-range values of each control's own kind (this loop), then values of the wrong kind for
    every control (:func:`_check_values_of_the_wrong_kind`)."""
    view = factory()
    assert isinstance(view, InteractiveView) and view.last_error is None, view.last_error
    defaults = view.values()
    for name in _swept(view.controls):
        for bad in _bad_values(view.controls[name]):
            values = {**defaults, name: bad}
            start = time.process_time()     # CPU time: the suite runs beside two browsers
            raised = False
            try:
                result = view.update(**values)
            except (ValueError, TypeError) as exc:
                raised = True
                message = str(exc)
                assert message and len(message) < 1000, (name, bad, message[:200])
            else:
                assert isinstance(result, dict) and result.get("status"), (name, bad)
                for arr in _finite(result):
                    assert np.all(np.isfinite(arr)), f"{name}={bad!r} drew a non-finite value"
            elapsed = time.process_time() - start
            assert elapsed < LIMIT, f"update({name}={str(bad)[:40]!r}) took {elapsed:.2f} s"
            huge = isinstance(bad, (int, float)) and not isinstance(bad, bool) and abs(bad) >= 1e6
            if raised or huge:
                # what the learner sees: the view's refresh shows the message in the status line, or
                # redraws (a huge drawing must not break the figure's ticks either)
                view.values = lambda values=values: values
                view.refresh()
                if raised:
                    assert view.last_error is not None and "&#9888;" in view.status.value, (name, bad)
                    assert len(view.status.value) < 2000
                del view.values
    view.set_values(**defaults)
    assert view.last_error is None, view.last_error
    _check_values_of_the_wrong_kind(view)


#: The kinds of control the 79 factories use, each with its rule in ``check_control_values``.
KINDS = (widgets.IntSlider, widgets.FloatSlider, widgets.Dropdown, widgets.ToggleButtons, widgets.Checkbox,
         widgets.ColorPicker, widgets.Textarea)


def _check_values_of_the_wrong_kind(view):
    """Arrays, a 10 MB string, a list nested 100,000 deep, an object whose __eq__ and __repr__ raise,
    and (for a colour picker) strings that are no colour: a ValueError/TypeError naming the control,
    under 300 characters (it quotes at most a short prefix), from the framework's one check
    (``check_control_values``), and the view shows it in its status line.  Every control is of a
    kind the framework has a rule for (:data:`KINDS`): a new kind (a date picker, a file upload)
    gets its rule there before a factory uses it."""
    defaults = view.values()
    unknown = {type(w).__name__ for w in view.controls.values() if not isinstance(w, KINDS)}
    assert not unknown, f"controls of kinds the framework has no rule for (give them one): {sorted(unknown)}"
    for name, w in view.controls.items():
        bad_values = HOSTILE + (COLOURS if isinstance(w, widgets.ColorPicker) else [])
        for bad in bad_values:
            if isinstance(w, (widgets.Textarea, widgets.Text)) and isinstance(bad, str):
                continue      # any string is a text field's value: its reader (a language) bounds it
            with pytest.raises((ValueError, TypeError)) as info:
                interactive.check_control_values(view.controls, {name: bad})
            message = str(info.value)
            assert name in message and len(message) < 300, (name, message[:300])
            assert "truth value" not in message and "Traceback" not in message
            with pytest.raises((ValueError, TypeError)) as through_update:
                view.update(**{**defaults, name: bad})
            assert str(through_update.value) == message
    view.values = lambda: {**defaults, next(iter(view.controls)): HOSTILE[0]} if view.controls else {}
    view.refresh()
    if view.controls:
        assert view.last_error is not None and "&#9888;" in view.status.value and len(view.status.value) < 1000
    del view.values
    view.set_values(**defaults)
    assert view.last_error is None, view.last_error


def test_the_issue_reproducers():
    """'notacolour' gave matplotlib's raw message, a 10 MB value a 10 MB message; a dropdown given an
    array leaked numpy's "truth value of an array is ambiguous"."""
    from goldman_lib.views import color_intensity, knot_insertion

    view = color_intensity.rgb_mixing_view()
    for bad, rule in (("notacolour", "must be a colour"), ("#" + "f" * 10_000_000, "must be a colour")):
        with pytest.raises(ValueError, match=rf"^wall {rule}") as info:
            view.update(**{**view.values(), "wall": bad})
        assert len(str(info.value)) < 200
    from goldman_lib.views import affine

    view = affine.transform_explorer()
    assert isinstance(view.controls["kind"], widgets.Dropdown)
    with pytest.raises(ValueError, match=r"^kind must be one of .*; got an array of shape \(2,\)$"):
        view.update(**{**view.values(), "kind": np.array([1, 2])})
    view = knot_insertion.insertion_editor()
    with pytest.raises(TypeError, match=r"^bezier must be True or False; got an array of shape \(2,\)$"):
        view.update(**{**view.values(), "bezier": np.array([True, False])})
