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
Not yet: the perimeter is off by 0.5. Hint: a hexagon has six sides.

A wrong answer is explained, never answered: messages say how far off an answer is and what to
check, not what the answer is (``tests/test_exercises.py`` feeds every checker its recognised slips
and fails if a message gives the expected value away).  A right answer may confirm it.  Worked
solutions are not printed by code: they sit in collapsed ``<details>`` blocks of the notebook
(``tests/test_solutions.py`` runs their code and checks each one passes its checker), and the
programming projects' checker is :mod:`goldman_lib.exercises.projects`.
"""

from __future__ import annotations

import html
from dataclasses import dataclass

import numpy as np

__all__ = ["Result", "read_vector", "all_close", "distance_text", "correct", "wrong", "unanswered", "is_unanswered", "read_number", "read_points", "check_number",
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


def read_number(answer, what: str, unit: str = "number") -> tuple[float | None, Result | None]:
    """Read a learner's numeric answer: ``(value, None)`` for a finite number, otherwise
    ``(None, result)`` with the verdict to return (not answered yet, not a number, not finite).

    >>> read_number("abc", "the angle", "number of degrees")
    (None, Not yet: the angle should be a number of degrees; you gave 'abc'.)
    """
    if is_unanswered(answer):
        return None, unanswered(what)
    try:
        value = float(answer)
    except (TypeError, ValueError):
        return None, wrong(f"{what} should be a {unit}; you gave {answer!r}.")
    if not np.isfinite(value):
        return None, wrong(f"{what} should be a finite {unit}; you gave {answer!r}.")
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
        arr = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return None, wrong(f"{what} should be numbers; you gave {answer!r}.")
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
    """How far apart two answers are, as a short number for a message (2 digits).

    >>> distance_text([0, 0], [3, 4])
    '5'
    """
    return fmt(float(np.linalg.norm(np.asarray(a, float) - np.asarray(b, float))), 2)


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

    >>> check_points([[0, 0], [1, 1.1]], [[0, 0], [1, 1]], what="the control points")
    Not yet: point 1 of the control points, (1, 1.1), is 0.1 away from where it should be (1 of 2 points are off).
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
    msg = (f"point {k} of {what}, {fmt(g)}, is {fmt(np.linalg.norm(g - e), 2)} away from where it should be "
           f"({bad.size} of {err.shape[0]} points are off).")
    return wrong(msg + (f" Hint: {hint}." if hint else ""))


def off_by(value: float, expected: float) -> str:
    """How far a number is from the expected one, in words that do not give the expected value
    away: the distance to two significant digits, with no direction (and no relative error, which
    with the distance would give the expected value back).

    >>> off_by(5.5, 6.0)
    'off by 0.5'
    >>> off_by(0.3333, 1 / 3)
    'off by 3.3e-05'
    """
    return f"off by {fmt(abs(float(value) - float(expected)), 2)}"
