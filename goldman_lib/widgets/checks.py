"""Checks of the values a widget's ``update`` receives (issue 10): a control's value may come from
a learner's code (``view.update(level=10**12)``) rather than from the slider, so each update
checks its values here and raises a ValueError/TypeError naming the control, which the view
shows in its status line (:class:`goldman_lib.widgets.interactive.InteractiveView`).

One check per kind of control (issue 20): sliders (:func:`number`, :func:`integer`), pickers
(:func:`option`), checkboxes and toggles (:func:`boolean`), colour pickers (:func:`colour`) and
text fields (:func:`text`).  Whatever the value -- an array, a 10 MB string, a list nested 100,000
deep, an object whose ``__eq__`` or ``__repr__`` raises -- the message is short, names the control
and says the rule; it quotes at most a short prefix of the value (:func:`shown`).
"""

from __future__ import annotations

import numbers
import reprlib

import numpy as np

from goldman_lib.validation import as_float, as_int

#: The longest colour a colour picker holds: a CSS name or code (``'rgba(255, 255, 255, 0.5)'``).
MAX_COLOUR = 64

_REPR = reprlib.Repr()
_REPR.maxstring = 40
_REPR.maxother = 40
_REPR.maxlevel = 2
_REPR.maxlist = _REPR.maxtuple = _REPR.maxdict = _REPR.maxset = 4


def shown(value) -> str:
    """A short, safe ``repr`` of any value for a message: at most about 60 characters, never a
    recursion or an exception of the value's own ``__repr__``.

    >>> shown("x" * 10_000_000)
    "'xxxxxxxxxxxxxxxxx...xxxxxxxxxxxxxxxxxx'"
    """
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape}"
    try:
        text = _REPR.repr(value)
    except Exception:  # noqa: BLE001 - a value whose repr raises is named by its type
        text = f"a {type(value).__name__}"
    return text if len(text) <= 60 else text[:57] + "..."


def _same(a, b) -> bool:
    """``a == b`` as one bool, False for anything that is not a plain answer (an array's
    element-wise comparison, an ``__eq__`` that raises)."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return False
    try:
        result = a == b
    except Exception:  # noqa: BLE001
        return False
    return result if isinstance(result, bool) else bool(result) if isinstance(result, np.bool_) else False


def option(options, value, name: str):
    """``value`` if it is one of ``options`` (a mapping's keys or a sequence), else ValueError.

    >>> option(["a", "b"], np.array(["a", "b"]), "kind")
    Traceback (most recent call last):
    ...
    ValueError: kind must be one of 'a', 'b'; got an array of shape (2,)
    """
    keys = list(options)
    ok = any(_same(value, k) and isinstance(value, bool) == isinstance(k, bool) for k in keys)   # True is not 1
    if not ok or (isinstance(value, float) and value != value):
        listed = ", ".join(shown(k) for k in keys[:12]) + (", ..." if len(keys) > 12 else "")
        raise ValueError(f"{name} must be one of {listed}; got {shown(value)}")
    return value


def integer(value, name: str, low: int, high: int) -> int:
    """An integer control's value within its slider's range ``[low, high]``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be an integer in [{low}, {high}]; got {shown(value)}")
    return as_int(value, name, minimum=low, maximum=high)


def number(value, name: str, low: float | None = None, high: float | None = None) -> float:
    """A float control's value: a finite real number, inside ``[low, high]`` if given."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number; got {shown(value)}")
    x = as_float(value, name)
    if (low is not None and x < low) or (high is not None and x > high):
        raise ValueError(f"{name} must lie in [{low:g}, {high:g}]; got {x:g}")
    return x


def boolean(value, name: str) -> bool:
    """A checkbox's or toggle's value: True or False.

    >>> boolean(np.array([True, False]), "bezier")
    Traceback (most recent call last):
    ...
    TypeError: bezier must be True or False; got an array of shape (2,)
    """
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False; got {shown(value)}")
    return bool(value)


def text(value, name: str) -> str:
    """A text field's value: a string (its length is the reader's business: a program editor's
    language bounds it)."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string (the text of the field); got {shown(value)}")
    return value


def colour(value, name: str) -> str:
    """A colour picker's value: a colour name or code that matplotlib draws (``'red'``,
    ``'#ff8800'``, ``'#f80'``).

    >>> colour("notacolour", "wall")
    Traceback (most recent call last):
    ...
    ValueError: wall must be a colour: a name such as 'red' or a code such as '#ff8800'; got 'notacolour'
    """
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a colour (a string such as '#ff8800'); got {shown(value)}")
    from matplotlib.colors import is_color_like

    if len(value) > MAX_COLOUR or not value.strip() or not is_color_like(value):
        raise ValueError(f"{name} must be a colour: a name such as 'red' or a code such as '#ff8800'; "
                         f"got {shown(value)}")
    return value


def same_kind(value, current, name: str):
    """The value of a control of another kind: of the type of its current value."""
    if current is not None and not isinstance(value, type(current)):
        raise TypeError(f"{name} must be a {type(current).__name__} like its control's value; got {shown(value)}")
    return value
