"""Checks of the values a widget's ``update`` receives (issue 10): a control's value may come from
a learner's code (``view.update(level=10**12)``) rather than from the slider, so each update
checks its values here and raises a ValueError/TypeError naming the control, which the view
shows in its status line (:class:`goldman_lib.views.interactive.InteractiveView`).
"""

from __future__ import annotations

from goldman_lib.validation import as_float, as_int


def option(options, value, name: str):
    """``value`` if it is one of ``options`` (a mapping's keys or a sequence), else ValueError."""
    keys = list(options)
    try:
        ok = value in keys
    except TypeError:
        ok = False
    if not ok or (isinstance(value, float) and value != value):
        shown = repr(value)
        shown = shown if len(shown) <= 60 else shown[:57] + "..."
        listed = ", ".join(repr(k) for k in keys[:12]) + (", ..." if len(keys) > 12 else "")
        raise ValueError(f"{name} must be one of {listed}; got {shown}")
    return value


def integer(value, name: str, low: int, high: int) -> int:
    """An integer control's value within its slider's range ``[low, high]``."""
    return as_int(value, name, minimum=low, maximum=high)


def number(value, name: str, low: float | None = None, high: float | None = None) -> float:
    """A float control's value: a finite real number, inside ``[low, high]`` if given."""
    x = as_float(value, name)
    if (low is not None and x < low) or (high is not None and x > high):
        raise ValueError(f"{name} must lie in [{low:g}, {high:g}]; got {x:g}")
    return x
