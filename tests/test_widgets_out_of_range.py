"""Every widget of the course (found by discovery, as the in-range sweep finds them) at values its
controls cannot reach: NaN, infinities, 1e308, 10**12, wrong types, unknown options, values just
past a slider's ends, hostile programs.  ``update`` either draws (finite arrays and a status) or raises
a ValueError/TypeError, and the view then shows that message in its status line; nothing hangs
(issue 10: every input gets bounded work and a clear answer).

The in-range sweep is tests/test_widget_sweeps.py.
"""

import re
import time

import ipywidgets as widgets
import numpy as np
import pytest

from goldman_lib.views import interactive
from goldman_lib.views.interactive import InteractiveView

FACTORIES = [pytest.param(fn, id=name) for name, fn in interactive.discover_factories()]
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
    if isinstance(w, widgets.Checkbox):
        return [None, "yes"]
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
    view = factory()
    assert isinstance(view, InteractiveView) and view.last_error is None, view.last_error
    defaults = view.values()
    for name in _swept(view.controls):
        for bad in _bad_values(view.controls[name]):
            values = {**defaults, name: bad}
            start = time.perf_counter()
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
            elapsed = time.perf_counter() - start
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
