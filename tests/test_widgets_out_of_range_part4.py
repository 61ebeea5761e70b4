"""Out-of-range control values for the widgets of Part IV (Bezier curves to subdivision surfaces):
a value a slider cannot reach (a notebook that sets ``control.value`` by hand, a saved state, a
future slider with a wider range) must give a message in the status line -- never a hang, a
traceback of an unexpected kind, or a NaN in the drawing.

Every widget factory of the Part IV view modules, found by discovery as in
``tests/test_widget_sweeps.py``, gets for each control in turn (the others at their defaults):
integers far past both ends of an int slider, floats far past both ends (1e308, NaN, inf) of a
float slider, and an unknown option of a picker.  ``refresh`` then either shows the view (a status
string, finite arrays) or shows a ``ValueError``/``TypeError`` message in the status line.
"""

import math
import signal
from contextlib import contextmanager

import ipywidgets as widgets
import numpy as np
import pytest

from goldman_lib.views import interactive

PART4_VIEWS = ("bezier", "blossom", "bspline", "knot_editor", "knot_insertion", "subdivision",
               "subdivision_matrices", "subdivision_surfaces", "three")
TIME_LIMIT = 10  # seconds per update: generous for a loaded CI machine; a hang is minutes

FACTORIES = [pytest.param(fn, id=name) for name, fn in interactive.discover_factories()
             if name.split(".")[0] in PART4_VIEWS]


def _bad_values(w):
    if isinstance(w, (widgets.IntSlider, widgets.BoundedIntText)):
        return [w.max + 1, w.max + 10, 10 ** 6, 10 ** 12, w.min - 1, -10 ** 12]
    if isinstance(w, (widgets.FloatSlider, widgets.BoundedFloatText, widgets.FloatLogSlider)):
        span = max(w.max - w.min, 1.0)
        return [w.max + span, w.min - span, 1e150, 1e308, -1e308, math.nan, math.inf, -math.inf]
    if isinstance(w, (widgets.Dropdown, widgets.ToggleButtons, widgets.RadioButtons, widgets.SelectionSlider)):
        return ["no such option", None]
    return []


@contextmanager
def time_limit(seconds):
    def handler(signum, frame):
        raise TimeoutError(f"update took longer than {seconds} s")
    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def drawn_arrays(result):
    if isinstance(result, dict):
        for key, value in result.items():
            if key != "status":
                yield from drawn_arrays(value)
    elif isinstance(result, (list, tuple)) and not (result and np.isscalar(result[0])):
        for value in result:
            yield from drawn_arrays(value)
    elif isinstance(result, (bool, str)) or result is None:
        return
    else:
        yield np.asarray(result, dtype=float)


def test_every_part4_view_module_has_factories():
    assert {p.id.split(".")[0] for p in FACTORIES} >= {"bezier", "bspline", "knot_insertion", "subdivision",
                                                       "subdivision_surfaces"}


@pytest.mark.parametrize("factory", FACTORIES)
def test_out_of_range_values_give_a_message(factory):
    view = factory()
    view._redraw = lambda: None   # what is drawn is checked from update's result; no PNG per value
    defaults = view.values()
    problems = []
    for name, w in view.controls.items():
        for bad in _bad_values(w):
            values = {**defaults, name: bad}
            view.values = lambda values=values: values   # what refresh reads, past the slider's clamp
            try:
                with time_limit(TIME_LIMIT):
                    view.refresh()
            except TimeoutError as exc:
                problems.append(f"{name}={bad!r}: {exc}")
                continue
            if view.last_error is not None:
                kind = view.last_error.split(":")[0]
                if kind not in ("ValueError", "TypeError") or not view.status.value:
                    problems.append(f"{name}={bad!r}: {view.last_error[:160]}")
                continue
            result = view.last_result
            if not (isinstance(result.get("status"), str) and result["status"]):
                problems.append(f"{name}={bad!r}: no status line")
            for arr in drawn_arrays(result):
                if not np.all(np.isfinite(arr)):
                    problems.append(f"{name}={bad!r}: drew a non-finite value")
                    break
    assert not problems, "\n".join(problems)
