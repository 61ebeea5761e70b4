"""Exercise checkers: every exercise of every chapter is checked by a function that says right or
wrong *and why*.

A checker takes the learner's answer and returns a :class:`Result`.  A ``Result`` renders in a
notebook as a green or red box with the reason ("your point is 0.03 from the curve at t=0.4"), and
as one line of plain text everywhere else, so nbval compares it.  The chapter checkers live beside
this module, one module a chapter (``goldman_lib.exercises.ch01``, ``...ch24``); they are built from
the small helpers here so that every chapter's feedback reads alike.

A learner who has not answered yet (the answer is ``None`` or ``...``) is told so, not failed:

>>> check_number(None, 2.0, what="the perimeter")
Not answered yet: replace None with the perimeter.
>>> check_number(6.0, 6.0, what="the perimeter")
Correct: the perimeter is 6.
>>> check_number(5.5, 6.0, what="the perimeter", hint="a hexagon has six sides")
Not yet: the perimeter is too small. Hint: a hexagon has six sides.

Any object can be given as an answer.  Every chapter checker reads it through one layer here
(:func:`answer_checker`, applied to each chapter's checkers by :func:`guard_checkers`):
:func:`plain` turns the answer into bounded plain data (numbers, text, lists, arrays; complex numbers
only where a chapter computes with them) or says why it cannot ("I could not read your answer ...
as ...: it is nested more than 32 levels deep"), and :func:`quote` shows at most a short prefix of
it in a message, without calling the answer's own ``__repr__``.  :func:`read_number`,
:func:`read_points` and :func:`read_vector` go through the same layer.

A wrong answer is explained, never answered: messages name the slip, or say which way an answer
is off and roughly how much in words ("a little too large"), never the gap in digits, nor what the
answer is (``tests/exercises/test_exercises.py`` feeds every checker its recognised slips
and fails if a message gives the expected value away).  A right answer may confirm it.  Worked
solutions are not printed by code: they sit in collapsed ``<details>`` blocks of the notebook
(``tests/exercises/test_solutions.py`` runs their code and checks each one passes its checker), and the
programming projects' checker is :mod:`goldman_lib.exercises.projects`.

Numeric exercises deal new instances (issue 17 §3): a chapter registers them on a
:class:`goldman_lib.exercises.deal.Deck`, whose module-level checkers check the current instance;
``chNN.deal("check_...")`` deals another, ``chNN.steps("check_...")`` shows its worked steps, and seed 0
is the stored instance.
"""

from __future__ import annotations

import functools
import html
from dataclasses import dataclass

import numpy as np

__all__ = ["Result", "Unreadable", "quote", "clip", "plain", "unreadable", "answer_checker", "guard_checkers", "far_off",
           "read_vector", "all_close", "distance_text", "correct", "wrong", "unanswered", "is_unanswered", "read_number", "read_points", "check_number",
           "check_points", "fmt", "fmt_points", "off_by"]


def fmt(x, digits: int = 4) -> str:
    """Format a number or small array compactly and deterministically for feedback messages.

    >>> fmt(0.30000000000000004), fmt(2.0), fmt([1, 0.5])
    ('0.3', '2', '(1, 0.5)')
    """
    arr = np.asarray(x, dtype=float)
    if arr.ndim == 0:
        v = float(arr)
        if v == 0:
            v = 0.0
        return f"{v:.{digits}g}"
    return "(" + ", ".join(fmt(v, digits) for v in arr.ravel()) + ")"


def fmt_points(points, digits: int = 4) -> str:
    """Format a list of points (a control polygon) for feedback messages.

    >>> fmt_points([[0, 0], [1, 0.5]])
    '(0, 0), (1, 0.5)'
    """
    return ", ".join(fmt(p, digits) for p in np.asarray(points, dtype=float))


@dataclass(frozen=True)
class Result:
    """The verdict of a checker: ``correct`` (bool), ``message`` (why), ``answered`` (bool).

    ``bool(result)`` is ``result.correct``: a wrong ``Result`` is falsy, so a helper returning
    "a Result or None" must be tested with ``is not None``, not truthiness.  Renders as a coloured box in JupyterLab and as one
    line of text (``Correct: ...`` / ``Not yet: ...``) in plain-text outputs.
    """

    correct: bool
    message: str
    answered: bool = True

    def __bool__(self) -> bool:
        return self.correct

    @property
    def verdict(self) -> str:
        if not self.answered:
            return "Not answered yet"
        return "Correct" if self.correct else "Not yet"

    def __repr__(self) -> str:
        return f"{self.verdict}: {self.message}"

    def _repr_html_(self) -> str:
        colour, mark = (("#1b7f3b", "&#10004;") if self.correct else
                        ("#8a6d00", "&#9998;") if not self.answered else ("#b3261e", "&#10008;"))
        return (f'<div style="border-left:4px solid {colour};padding:4px 10px;margin:4px 0;">'
                f'<b style="color:{colour}">{mark} {self.verdict}:</b> {html.escape(self.message)}</div>')


def correct(message: str) -> Result:
    """A right answer, with what makes it right."""
    return Result(True, message)


def wrong(message: str) -> Result:
    """A wrong answer, with what is wrong about it."""
    return Result(False, message)


def unanswered(what: str) -> Result:
    """The learner has not replaced the ``None`` (or ``...``) in the exercise cell yet."""
    return Result(False, f"replace None with {what}.", answered=False)


def is_unanswered(answer) -> bool:
    """True for the stand-ins an exercise cell starts with: ``None`` and ``...``."""
    return answer is None or answer is Ellipsis


# -- reading any answer ---------------------------------------------------------------------------
# A learner can pass anything to a checker: a number, a list, an array, a string of ten megabytes,
# a list nested 100,000 deep, 10**400, a complex number, an object whose ``__float__`` or
# ``__repr__`` raises.  Every checker reads its answer through this layer, so whatever comes in, a
# checker returns a Result, and a message quotes at most a short prefix of the answer.

#: The most characters of the answer a message quotes.
QUOTE_LIMIT = 60
#: The longest text answer read (a CODO program, an expression); longer texts are refused.
MAX_TEXT = 10_000
#: The most entries (numbers, strings, list items) an answer may hold, and its deepest nesting.
MAX_ITEMS = 100_000
MAX_DEPTH = 32


class _Full(Exception):
    """The quote has reached its length."""


def _int_text(v: int) -> str:
    if v.bit_length() <= 64:
        return repr(v)
    digits = int(v.bit_length() * 0.30103) + 1
    return f"{'-' if v < 0 else ''}<an integer of about {digits} digits>"


def quote(answer, limit: int = QUOTE_LIMIT) -> str:
    """A short, safe text for an answer in a message: like ``repr`` for numbers, strings, lists,
    tuples, dicts and arrays, cut to ``limit`` characters, nested levels beyond the fourth shown as
    ``...``; any other object is named by its type (its own ``__repr__`` is never called).  Never
    raises, and its cost does not grow with the size or depth of the answer.

    >>> quote([[0, 1], [2, 'x']])
    "[[0, 1], [2, 'x']]"
    >>> quote('x' * 100, limit=12)
    "'xxxxxxxx..."
    >>> quote(10 ** 400)
    '<an integer of about 401 digits>'
    """
    out: list[str] = []
    size = [0]

    def emit(s: str) -> None:
        out.append(s)
        size[0] += len(s)
        if size[0] > limit:
            raise _Full

    def walk(v, depth: int) -> None:
        if v is None or v is Ellipsis or isinstance(v, (bool, np.bool_)):
            emit(repr(bool(v)) if isinstance(v, np.bool_) else repr(v))
        elif isinstance(v, (int, np.integer)):
            emit(_int_text(int(v)))
        elif isinstance(v, (float, np.floating)):
            emit(repr(float(v)))
        elif isinstance(v, (complex, np.complexfloating)):
            emit(repr(complex(v)))
        elif isinstance(v, (str, bytes)):
            emit(repr(v[: limit + 2]))
        elif isinstance(v, (list, tuple, np.ndarray, dict, set, frozenset)):
            if depth >= 4:
                emit("...")
                return
            if isinstance(v, np.ndarray) and v.ndim == 0:
                walk(v[()], depth)
                return
            opener, closer = (("[", "]") if isinstance(v, (list, np.ndarray)) else ("(", ")") if isinstance(v, tuple)
                              else ("{", "}"))
            if isinstance(v, np.ndarray):
                emit("array(")
            emit(opener)
            items = v.items() if isinstance(v, dict) else v
            for i, item in enumerate(items):
                if i:
                    emit(", ")
                if i >= limit:
                    emit("...")
                    break
                if isinstance(v, dict):
                    walk(item[0], depth + 1)
                    emit(": ")
                    walk(item[1], depth + 1)
                else:
                    walk(item, depth + 1)
            if isinstance(v, tuple) and len(v) == 1:
                emit(",")
            emit(closer)
            if isinstance(v, np.ndarray):
                emit(")")
        else:
            emit(f"<a {type(v).__name__}>")

    try:
        walk(answer, 0)
    except _Full:
        pass
    except Exception:  # noqa: BLE001 - a container that cannot even be iterated
        return f"<a {type(answer).__name__}>"
    text = "".join(out)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def clip(text, limit: int = 80) -> str:
    """A text (an expression the learner wrote, an error message about it) cut to ``limit``
    characters for a message.

    >>> clip("A + B - C"), clip("x" * 100, 10)
    ('A + B - C', 'xxxxxxx...')
    """
    text = str(text)
    return text if len(text) <= limit else text[: limit - 3] + "..."


class Unreadable(Exception):
    """An answer that cannot be read: the reason, in words."""


def plain(answer, *, complex_ok: bool = False, max_items: int = MAX_ITEMS, max_text: int = MAX_TEXT):
    """The answer as plain data -- ``None``, ``...``, bool, int, float, complex (only if
    ``complex_ok``), str, list, tuple, dict, set and numpy arrays of numbers or text -- copied, so a
    checker cannot change the learner's objects, and bounded: at most ``max_items`` entries,
    ``MAX_DEPTH`` levels and texts of ``MAX_TEXT`` characters.  A complex number whose imaginary
    part is 0 is read as its real part.  Other objects are read through ``__array__``, ``__float__``,
    ``__index__`` or ``__iter__``, each guarded.  Raises :class:`Unreadable` saying why it cannot.

    >>> plain((1, [2.5, np.float32(0.5)]))
    (1, [2.5, 0.5])
    >>> plain([1 + 2j])
    Traceback (most recent call last):
    ...
    goldman_lib.exercises.Unreadable: it should be real numbers; (1+2j) has an imaginary part
    """
    count = [0]

    def tick(n: int = 1) -> None:
        count[0] += n
        if count[0] > max_items:
            raise Unreadable(f"it has more than {max_items:,} entries; the answer is much smaller")

    def number(v):
        if isinstance(v, complex):
            if v.imag == 0:
                return v.real
            if complex_ok:
                return v
            raise Unreadable(f"it should be real numbers; {quote(v)} has an imaginary part")
        return v

    def walk(v, depth: int):
        if depth > MAX_DEPTH:
            raise Unreadable(f"it is nested more than {MAX_DEPTH} levels deep")
        tick()
        if v is None or v is Ellipsis or type(v) in (bool, float, str):
            if type(v) is str and len(v) > max_text:
                raise Unreadable(f"it is a text of {len(v):,} characters; the answer is far shorter")
            return v
        if isinstance(v, (bool, np.bool_)):
            return bool(v)
        if isinstance(v, (int, np.integer)):
            v = int(v)
            if v.bit_length() > 1000:
                raise Unreadable(f"{quote(v)} is too large a number to compute with")
            return v
        if isinstance(v, (float, np.floating)):
            return float(v)
        if isinstance(v, (complex, np.complexfloating)):
            return number(complex(v))
        if isinstance(v, str):
            return walk(str.__str__(v), depth)
        if isinstance(v, bytes):
            raise Unreadable("it is bytes, not numbers or text")
        if isinstance(v, np.ndarray):
            return array(v, depth)
        if isinstance(v, (list, tuple)):
            tick(len(v))
            items = [walk(x, depth + 1) for x in v]
            return items if isinstance(v, list) else tuple(items)
        if isinstance(v, dict):
            tick(len(v))
            return {key(k, depth): walk(x, depth + 1) for k, x in v.items()}
        if isinstance(v, (set, frozenset)):
            tick(len(v))
            items = [key(x, depth) for x in v]
            return frozenset(items) if isinstance(v, frozenset) else set(items)
        return other(v, depth)

    def key(k, depth: int):
        k = walk(k, depth + 1)
        try:
            hash(k)
        except TypeError:
            raise Unreadable("one of its keys is not a number or a text") from None
        return k

    def array(a: np.ndarray, depth: int):
        if a.size > max_items:
            raise Unreadable(f"it is an array of {a.size:,} entries; the answer is much smaller")
        tick(a.size)
        kind = a.dtype.kind
        if kind in "biuf":
            return np.array(a, dtype=float if kind == "f" else a.dtype, copy=True)
        if kind == "c":
            if not np.any(a.imag != 0):
                return np.array(a.real, dtype=float, copy=True)
            if complex_ok:
                return np.array(a, copy=True)
            first = a.ravel()[np.flatnonzero(a.ravel().imag != 0)[0]]
            raise Unreadable(f"it should be real numbers; {quote(complex(first))} has an imaginary part")
        if kind in "US":
            if a.dtype.itemsize * a.size > 40 * max_text:
                raise Unreadable("its texts are far longer than the answer")
            return np.array(a, copy=True)
        if kind == "O":
            if a.ndim == 0:
                return walk(a[()], depth + 1)
            return walk(a.tolist(), depth)
        raise Unreadable(f"it is an array of {a.dtype} values, not numbers")

    def other(v, depth: int):
        name = type(v).__name__
        try:
            if hasattr(type(v), "__array__") or hasattr(v, "__array_interface__"):
                return array(np.asarray(v), depth)
            if hasattr(type(v), "__float__") or hasattr(type(v), "__complex__"):
                try:
                    return number(complex(v)) if not hasattr(type(v), "__float__") else float(v)
                except OverflowError:
                    raise Unreadable(f"it is a {name} too large to compute with") from None
            if hasattr(type(v), "__index__"):
                return walk(int(v.__index__()), depth)
            if hasattr(type(v), "__iter__") and not callable(v):
                items = []
                for x in iter(v):
                    items.append(x)
                    tick()
                return walk(items, depth)
        except Unreadable:
            raise
        except Exception as exc:  # noqa: BLE001 - the learner's object failed to give its value
            raise Unreadable(f"reading a {name} raised {type(exc).__name__}") from None
        raise Unreadable(f"it is a {name}, not numbers or text")

    try:
        return walk(answer, 0)
    except RecursionError:
        raise Unreadable("it is nested too deeply") from None


def unreadable(answer, what: str, reason: str) -> Result:
    """The verdict on an answer :func:`plain` could not read: what was asked, a short quote, why."""
    return wrong(f"I could not read your answer {quote(answer)} as {what}: {reason}.")


#: Tests set this to True so that a checker's own failure on a readable answer raises instead of
#: being reported as "I could not check your answer" (the sweep in tests/ proves none happens).
STRICT = False


def _asked(function) -> str:
    """What a checker asks for, in the words of its "not answered yet" message."""
    asked = getattr(function, "_asked", None)
    if asked is None:
        try:
            message = function(None).message
        except Exception:  # noqa: BLE001
            message = ""
        prefix = "replace None with "
        asked = message[len(prefix):].rstrip(".") if message.startswith(prefix) else "the answer asked for"
        function._asked = asked
    return asked


def answer_checker(function=None, *, complex_ok: bool = False):
    """Wrap an exercise checker so that it returns a Result for *any* answer: the answer is read
    by :func:`plain` first (an unreadable one is told why, quoting at most a short prefix), the
    checker gets the plain copy, and should the checker still fail on it, the learner is told the
    answer is not in the form asked for (with ``STRICT`` set, the failure is raised, for tests).
    ``complex_ok`` lets complex numbers through, for a chapter that computes with them."""
    if function is None:
        return functools.partial(answer_checker, complex_ok=complex_ok)
    if getattr(function, "_answer_checker", False):
        return function

    @functools.wraps(function)
    def checker(answer, *args, **kwargs):
        if is_unanswered(answer):
            return function(answer, *args, **kwargs)
        try:
            value = plain(answer, complex_ok=complex_ok)
        except Unreadable as exc:
            return unreadable(answer, _asked(function), str(exc))
        try:
            with np.errstate(all="ignore"):   # 1e308 squared is refused by the checker, not warned about
                return function(value, *args, **kwargs)
        except Exception as exc:
            if STRICT:
                raise
            return wrong(f"I could not check your answer {quote(answer)} as {_asked(function)}: it is not in the "
                         f"form asked for ({type(exc).__name__}).")

    checker._answer_checker = True
    return checker


def guard_checkers(namespace: dict, complex_ok=()) -> None:
    """Wrap every checker a chapter module lists in its ``PROBLEMS`` with :func:`answer_checker`
    (called at the end of each ``chNN`` module with ``globals()``); ``complex_ok`` names the
    checkers that read complex numbers."""
    for name in namespace["PROBLEMS"]:
        namespace[name] = answer_checker(namespace[name], complex_ok=name in complex_ok)


def read_number(answer, what: str, unit: str = "number") -> tuple[float | None, Result | None]:
    """Read a learner's numeric answer: ``(value, None)`` for a finite real number (or a text that
    writes one), otherwise ``(None, result)`` with the verdict to return (not answered yet, not a
    number, not finite, complex, unreadable).  Any object can be given; the message quotes at most
    a short prefix of it.

    >>> read_number("abc", "the angle", "number of degrees")
    (None, Not yet: the angle should be a number of degrees; you gave 'abc'.)
    """
    if is_unanswered(answer):
        return None, unanswered(what)
    try:
        value = plain(answer)
    except Unreadable as exc:
        return None, unreadable(answer, what, str(exc))
    if isinstance(value, np.ndarray) and value.size == 1 and value.dtype.kind in "biuf":
        value = value.reshape(())[()]
    if isinstance(value, (list, tuple, dict, set, frozenset, np.ndarray)) or value is None or value is Ellipsis:
        return None, wrong(f"{what} should be a {unit}; you gave {quote(answer)}.")
    try:
        value = float(value.strip() if isinstance(value, str) else value)
    except (TypeError, ValueError, OverflowError):
        return None, wrong(f"{what} should be a {unit}; you gave {quote(answer)}.")
    if not np.isfinite(value):
        return None, wrong(f"{what} should be a finite {unit}; you gave {quote(answer)}.")
    return value, None


def read_points(answer, what: str, ask: str | None = None) -> tuple[np.ndarray | None, Result | None]:
    """Read a learner's array answer (points, vectors): ``(array, None)`` if it is finite numbers,
    otherwise ``(None, result)`` with the verdict to return.  ``ask`` is what the "not answered
    yet" message asks for (default ``what``).

    >>> read_points([[0, 1], [2, "x"]], "the control points")
    (None, Not yet: the control points should be numbers; you gave [[0, 1], [2, 'x']].)
    """
    if is_unanswered(answer):
        return None, unanswered(ask or what)
    try:
        value = plain(answer)
    except Unreadable as exc:
        return None, unreadable(answer, what, str(exc))
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        return None, wrong(f"{what} should be numbers; you gave {quote(answer)}.")
    if not np.all(np.isfinite(arr)):
        return None, wrong(f"{what} contain a NaN or infinite value.")
    return arr, None


def read_vector(answer, what: str, n: int, ask: str | None = None) -> tuple[np.ndarray | None, Result | None]:
    """Read one vector of ``n`` numbers: ``(vector, None)``, or ``(None, result)`` saying what is wrong
    with the answer (not answered, not numbers, the wrong shape).

    >>> read_vector([1, 2, 3], "N", 3)[0].tolist()
    [1.0, 2.0, 3.0]
    """
    got, err = read_points(answer, what, ask=ask)
    if err is not None:
        return None, err
    if got.shape != (n,):
        return None, wrong(f"{what} should be {n} numbers; yours has shape {got.shape}.")
    return got, None


def all_close(a, b, tol) -> bool:
    """Whether every entry of ``a`` is within ``tol`` of the matching entry of ``b``.

    >>> all_close([1.0, 2.0], [1.0, 2.00004], 1e-4)
    True
    """
    return bool(np.all(np.abs(np.asarray(a, float) - np.asarray(b, float)) <= tol))


def distance_text(a, b) -> str:
    """How far apart two answers are, in words for a message ("a little off", "off", "well off",
    "far off"): never the distance in digits, which with the learner's answer could give the
    expected one away.  The same as :func:`far_off`.

    >>> distance_text([0, 0], [3, 4])
    'well off'
    """
    return far_off(a, b)


def check_number(answer, expected: float, *, what: str, tol: float = 1e-6, hint: str | None = None) -> Result:
    """Check a single number against ``expected`` within ``tol`` (absolute)."""
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    if abs(value - expected) <= tol:
        return correct(f"{what} is {fmt(expected)}.")
    return wrong(f"{what} is {off_by(value, expected)}." + (f" Hint: {hint}." if hint else ""))


def check_points(answer, expected, *, what: str, tol: float = 1e-6, hint: str | None = None) -> Result:
    """Check an array of points against ``expected`` (same shape) within ``tol`` per coordinate,
    naming the first point that is off and how far, without saying where it should be.

    >>> check_points([[0, 0], [1, 3]], [[0, 0], [1, 1]], what="the control points")
    Not yet: point 1 of the control points, (1, 3), is well off from where it should be (1 of 2 points are off).
    """
    got, problem = read_points(answer, what)
    if problem is not None:
        return problem
    exp = np.asarray(expected, dtype=float)
    if got.shape != exp.shape:
        return wrong(f"{what} should have shape {exp.shape}; yours has shape {got.shape}.")
    err = np.abs(got - exp).reshape(-1, exp.shape[-1]) if exp.ndim else np.abs(got - exp).reshape(1, 1)
    bad = np.flatnonzero(err.max(axis=1) > tol)
    if bad.size == 0:
        return correct(f"{what} match.")
    k = int(bad[0])
    g, e = got.reshape(err.shape)[k], exp.reshape(err.shape)[k]
    msg = (f"point {k} of {what}, {fmt(g)}, is {far_off(g, e)} from where it should be "
           f"({bad.size} of {err.shape[0]} points are off).")
    return wrong(msg + (f" Hint: {hint}." if hint else ""))


def _size_word(gap: float, scale: float) -> str:
    r = abs(gap) / scale if scale > 0 else abs(gap)
    return "a little " if r < 0.05 else "" if r < 0.5 else "much " if r < 2 else "far "


def off_by(value: float, expected: float) -> str:
    """Which way a number is off and roughly how much, in words that do not give the expected value
    away (no gap in digits: "off by 0.033" with the learner's own value gives the answer back).
    Below 5% of the expected value's size the answer is "a little" off, up to 50% plainly off, up
    to twice its size "much", beyond that "far".

    >>> off_by(6.1, 6.0), off_by(5.0, 6.0), off_by(-6.0, 6.0)
    ('a little too large', 'too small', 'far too small')
    """
    value, expected = float(value), float(expected)
    gap = value - expected
    if gap == 0 or not np.isfinite(gap):
        return "off"
    return f"{_size_word(gap, abs(expected))}too {'large' if gap > 0 else 'small'}"


def far_off(got, expected) -> str:
    """How far a point (or any array) is from the expected one, in words that neither give the
    distance in digits nor the direction: "a little off", "off", "well off" or "far off", measured
    against the size of the expected point.

    >>> far_off([1.0, 2.02], [1.0, 2.0]), far_off([0, 0], [3, 4])
    ('a little off', 'well off')
    """
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    dist = float(np.linalg.norm(got - expected))
    scale = float(np.linalg.norm(expected))
    word = _size_word(dist, scale if scale > 0 else 1.0)
    return {"a little ": "a little off", "": "off", "much ": "well off", "far ": "far off"}[word]
