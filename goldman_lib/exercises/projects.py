"""The programming-project checker: run a learner's function against the library on many cases and
report the first failure in words the learner can act on.

The book ends most chapters with programming projects (write a recursive turtle program, an IFS,
Newton's method, de Boor, a ray-sphere intersector, ...).  In a notebook the learner writes the
function in a starter cell; the chapter's project checker (``goldman_lib.exercises.chNN``) builds
the cases -- generated from a fixed seed, degenerate ones included -- and calls :func:`check_project`,
which

* calls the learner's function on each case, on a copy of the input (so a function that changes its
  arguments cannot spoil the next case), under a time limit per case;
* compares what it returned with what the library computes, through a ``compare`` function that
  says *what* is wrong ("point 2 is 0.3 from the curve", "4 points, expected 7");
* never crashes: anything raised inside the learner's function (an Exception, RecursionError,
  SystemExit, ...; only KeyboardInterrupt, the learner stopping the kernel, goes through) is
  reported as theirs, with its type, message and the line of their cell it came from; a result it
  cannot read (complex numbers where real ones are expected, 10**400, an object whose ``__float__``
  raises) is reported, not crashed on; a slow case is stopped and reported: the time limit is a
  :class:`ProjectTimeout`, a BaseException that the learner's ``except Exception`` does not catch,
  raised again every 50 ms until the function gives up, and a function that still returns late is
  reported as too slow;
* stops at the first failing case and reports the input, the learner's output, what was expected of
  it, and a hint; or confirms how many cases (and which kinds) passed.

A function whose body is still ``...`` returns ``None``: that is "not answered yet", not a failure.

>>> def reference(x):
...     return 2 * x
>>> cases = [Case(f"x = {x}", (x,)) for x in (0.0, 1.0, -2.5)]
>>> check_project(lambda x: 2 * x, cases, reference=reference, compare=compare_numbers(), what="doubling")
Correct: doubling passes all 3 cases.
>>> check_project(lambda x: x + x + (x < 0), cases, reference=reference, compare=compare_numbers(),
...               what="doubling", hint="no special case is needed for negative x")
Not yet: case 3 of 3 (x = -2.5): your function returned -4; it is off by 1. Hint: no special case is needed for negative x.
>>> def broken(x):
...     return x / 0
>>> print(check_project(broken, cases, reference=reference, compare=compare_numbers(), what="doubling").message)
... # doctest: +ELLIPSIS
case 1 of 3 (x = 0.0): your function raised ZeroDivisionError ('float division by zero') at line 2 of its cell: `return x / 0`.
"""

from __future__ import annotations

import copy
import linecache
import signal
import threading
import time
import traceback
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from goldman_lib.exercises import Result, Unreadable, correct, fmt, is_unanswered, plain, quote, unanswered, wrong

__all__ = ["Case", "check_project", "describe", "compare_numbers", "compare_points", "ProjectTimeout"]


@dataclass(frozen=True)
class Case:
    """One input of a project: ``label`` says it in words ("cubic (0, 0), (1, 2), (3, 2), (4, 0) at
    t = 0.25"), ``args``/``kwargs`` are what the learner's function is called with, ``kind`` names a
    family of cases ("degenerate: all control points equal") for the summary of a passing run."""

    label: str
    args: tuple = ()
    kwargs: dict = field(default_factory=dict)
    kind: str = ""


class ProjectTimeout(BaseException):
    """Raised inside a learner's function that ran past the time limit of one case.

    A BaseException, like KeyboardInterrupt, so that a learner's ``try: ... except Exception: pass``
    around the slow part does not swallow it."""


def describe(value, limit: int = 6) -> str:
    """A short, deterministic description of what a learner's function returned.

    >>> describe(np.array([[0, 0], [1, 0.5]]))
    '(0, 0), (1, 0.5)'
    >>> describe(np.zeros((40, 2)))
    'an array of shape (40, 2) starting (0, 0), (0, 0), (0, 0)'
    >>> describe("abc")
    "'abc' (a str)"
    """
    try:
        if isinstance(value, (str, bytes)) or np.iscomplexobj(value):
            raise TypeError
        arr = np.asarray(value, dtype=float)
    except Exception:  # noqa: BLE001 - anything the learner returned
        return _short_repr(value) + f" (a {type(value).__name__})"
    if arr.ndim == 0:
        return fmt(arr)
    if arr.ndim == 1 and arr.size <= limit:
        return fmt(arr)
    if arr.ndim == 2 and arr.shape[0] <= limit and arr.shape[1] <= 4:
        return ", ".join(fmt(p) for p in arr)
    head = ", ".join(fmt(p) for p in arr.reshape(arr.shape[0], -1)[:3]) if arr.ndim >= 1 else ""
    return f"an array of shape {arr.shape} starting {head}"


def _short_repr(value, limit: int = 80) -> str:
    """``repr`` cut to ``limit`` characters: built-in data through the bounded
    :func:`~goldman_lib.exercises.quote` (never deep, never long), an object of a class of its own
    by its ``repr`` (a chapter may wrap results to describe them), guarded against one that raises."""
    if isinstance(value, (str, bytes, int, float, complex, list, tuple, dict, set, frozenset, np.ndarray, np.generic)):
        return quote(value, limit)
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - the learner's __repr__
        return quote(value, limit)
    if not isinstance(text, str):
        return quote(value, limit)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def compare_numbers(tol: float = 1e-6) -> Callable[[Any, Any, Case], str | None]:
    """A ``compare`` for functions returning one number: the problem in words, or None if within ``tol``."""

    def compare(got, expected, case):
        value = float(np.asarray(got, dtype=float))
        if not np.isfinite(value):
            return f"it should be a finite number"
        if abs(value - float(expected)) > tol:
            return f"it is off by {fmt(abs(value - float(expected)), 2)}"
        return None

    return compare


def compare_points(tol: float = 1e-6, what: str = "point") -> Callable[[Any, Any, Case], str | None]:
    """A ``compare`` for functions returning an array of points: checks the shape, then names the
    first point that is off and by how much (and how many are off)."""

    def compare(got, expected, case):
        arr = np.asarray(got, dtype=float)
        exp = np.asarray(expected, dtype=float)
        if arr.shape != exp.shape:
            return f"it has shape {arr.shape}; the expected result has shape {exp.shape}"
        if not np.all(np.isfinite(arr)):
            return "it contains NaN or infinite values"
        if exp.ndim == 0:
            return compare_numbers(tol)(arr, exp, case)
        err = np.abs(arr - exp).reshape(-1, exp.shape[-1]).max(axis=1)
        bad = np.flatnonzero(err > tol)
        if bad.size == 0:
            return None
        k = int(bad[0])
        dist = float(np.linalg.norm((arr - exp).reshape(-1, exp.shape[-1])[k]))
        return (f"{what} {k} is {fmt(dist, 2)} from where it should be, expected "
                f"{fmt(exp.reshape(-1, exp.shape[-1])[k])} ({bad.size} of {err.size} off)")

    return compare


def _learner_line(exc: BaseException, function) -> str:
    """'at line N of its cell: `source`' for the deepest frame of the learner's own code."""
    code = getattr(function, "__code__", None)
    filename = code.co_filename if code is not None else None
    where = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if frame.f_code.co_filename == filename:
            where = (lineno, frame.f_code.co_filename)
    if where is None:
        return ""
    lineno, fname = where
    first = code.co_firstlineno
    text = linecache.getline(fname, lineno).strip()
    rel = lineno if fname.startswith("<") or "ipykernel" in fname else lineno - first + 1
    return f" at line {rel} of its cell" + (f": `{text}`" if text else "")


#: After the time limit, ProjectTimeout is raised again every this many seconds until the learner's
#: function gives up (a loop that catches it and carries on gets it again at its next step).
RETRY_INTERVAL = 0.05


def _call_with_limit(function, args, kwargs, time_limit: float):
    """Call ``function`` with a wall-clock limit: a SIGALRM timer where possible (the main thread
    of a POSIX process, as in a Jupyter kernel), raising :class:`ProjectTimeout` at the limit and
    every ``RETRY_INTERVAL`` after it; in any case, a call that returns after the limit raises
    ProjectTimeout too (a function that caught the limit and returned anyway is still too slow)."""
    use_alarm = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    start = time.perf_counter()
    if not use_alarm:
        out = function(*args, **kwargs)
        if time.perf_counter() - start > time_limit:
            raise ProjectTimeout
        return out

    active = [True]

    def on_alarm(signum, frame):
        if active[0]:
            raise ProjectTimeout

    previous = signal.signal(signal.SIGALRM, on_alarm)
    signal.setitimer(signal.ITIMER_REAL, time_limit, RETRY_INTERVAL)
    try:
        out = function(*args, **kwargs)
    finally:
        active[0] = False
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    if time.perf_counter() - start > time_limit:
        raise ProjectTimeout
    return out


def _exception_text(exc: BaseException) -> str:
    """The learner's exception message, short, whatever its ``__str__`` does."""
    try:
        message = str(exc)
    except Exception:  # noqa: BLE001
        message = "its message could not be shown"
    return message if len(message) <= 120 else message[:117] + "..."


def _has_complex(value) -> bool:
    try:
        return bool(np.iscomplexobj(value)) or (isinstance(value, (list, tuple)) and any(_has_complex(v) for v in value[:50]))
    except Exception:  # noqa: BLE001
        return False


def check_project(function, cases, *, reference: Callable, compare: Callable, what: str,
                  hint: str | None = None, time_limit: float = 2.0) -> Result:
    """Run the learner's ``function`` on every case and compare with ``reference`` (the library).

    function: the learner's callable (``None`` or ``...`` means not answered yet).
    cases: a sequence of :class:`Case`.  reference: called with the same arguments, gives the
    expected result.  compare(got, expected, case) -> None if ``got`` is right, otherwise what is
    wrong with it, in words (it may name the expected value of *this case*: the learner's answer is
    the function, not the value).  what: the project's name in messages.  hint: one sentence said
    with the first failure.  time_limit: seconds per case.

    Returns a :class:`~goldman_lib.exercises.Result`; never raises because of the learner's code.
    """
    if is_unanswered(function):
        return unanswered(f"your function for {what} (define it in the starter cell, then pass it here)")
    if not callable(function):
        return wrong(f"pass your function itself (not its result): got {describe(function)}.")
    cases = list(cases)
    total = len(cases)
    suffix = f" Hint: {hint}." if hint else ""
    for i, case in enumerate(cases, start=1):
        head = f"case {i} of {total} ({case.label})"
        expected = reference(*copy.deepcopy(case.args), **copy.deepcopy(case.kwargs))
        try:
            got = _call_with_limit(function, copy.deepcopy(case.args), copy.deepcopy(case.kwargs), time_limit)
        except ProjectTimeout:
            return wrong(f"{head}: your function ran longer than {fmt(time_limit)} s and was stopped "
                         f"(an endless loop or recursion without a base case?).{suffix}")
        except RecursionError as exc:
            return wrong(f"{head}: your function recursed too deeply{_learner_line(exc, function)} "
                         f"(is the base case reached?).{suffix}")
        except KeyboardInterrupt:
            raise                        # the learner stopped the kernel: not a verdict
        except BaseException as exc:     # noqa: BLE001 - the learner's own error (SystemExit too), reported as theirs
            return wrong(f"{head}: your function raised {type(exc).__name__} ({_exception_text(exc)!r})"
                         f"{_learner_line(exc, function)}.{suffix}")
        if got is None:
            if i == 1:
                return Result(False, f"your function for {what} returns None: write its body "
                                     f"(it must return its result).", answered=False)
            return wrong(f"{head}: your function returned None (a path without a return?).{suffix}")
        try:
            plain(got, complex_ok=_has_complex(expected), max_items=10 ** 7, max_text=10 ** 6)
        except Unreadable as exc:
            reason = str(exc)
            if not reason.endswith("not numbers or text"):   # an object of its own kind: compare decides
                return wrong(f"{head}: your function returned {quote(got)}; I could not read it: {reason}.{suffix}")
        try:
            problem = compare(got, expected, case)
        except Exception as exc:  # noqa: BLE001 - whatever the learner's result does to the comparison
            problem = f"it is not of the expected kind ({type(exc).__name__}: {_exception_text(exc)})"
        if problem is not None:
            return wrong(f"{head}: your function returned {describe(got)}; {problem}.{suffix}")
    kinds = sorted({c.kind for c in cases if c.kind})
    extra = f", including {', '.join(kinds)}" if kinds else ""
    return correct(f"{what} passes all {total} cases{extra}.")
