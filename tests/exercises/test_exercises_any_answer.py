"""Every answer checker returns a Result for *any* answer (issue 20 §1).

A learner can pass anything: complex numbers, 10**400, a list nested 100,000 deep, a string of ten
megabytes, an object whose ``__float__``, ``__array__``, ``__repr__`` or ``__iter__`` raises.  Each
answer checker of every chapter (every public ``check_*`` of ``goldman_lib.exercises.chNN`` but the
project checkers, which take functions) is fed the whole battery: each call must return a Result
that is not Correct, within a time bound, with a message under 500 characters that quotes at most a
short prefix of the answer.  The checkers run with ``exercises.STRICT`` set, so a checker that only
survives through the layer's last-resort "I could not check your answer" fails here.

The project checker's own promises (the learner's SystemExit, a result of 10**400, a complex result,
a loop that swallows the time limit) are at the end.
"""

from __future__ import annotations

import importlib
import pkgutil
import signal
import time

import numpy as np
import pytest

import goldman_lib.exercises as exercises
from goldman_lib.exercises import Result, plain, quote, read_number, read_points, Unreadable


# -- the battery -----------------------------------------------------------------------------------

class RaisingFloat:
    def __float__(self):
        raise RuntimeError("__float__ raised")


class RaisingArray:
    def __array__(self, *args, **kwargs):
        raise RuntimeError("__array__ raised")


class RaisingRepr:
    def __repr__(self):
        raise RuntimeError("__repr__ raised")


class RaisingIter:
    def __iter__(self):
        raise RuntimeError("__iter__ raised")

    def __len__(self):
        return 3

    def __getitem__(self, i):
        raise RuntimeError("__getitem__ raised")


class RaisingEverything(RaisingFloat, RaisingArray, RaisingRepr, RaisingIter):
    pass


def nested(depth: int):
    x = [1.0]
    for _ in range(depth):
        x = [x]
    return x


HOSTILE = {
    "complex": 1 + 2j,
    "complex array": np.array([1 + 1j, 2, 3]),
    "complex in a list": [1j, 2.0, 3.0],
    "complex matrix": [[1, 2j], [3, 4]],
    "nested 100,000 deep": nested(100_000),
    "10**400": 10 ** 400,
    "-10**400 in a list": [-(10 ** 400), 1, 2],
    "10**5000 (no str())": 10 ** 5000,
    "raising __float__": RaisingFloat(),
    "raising __array__": RaisingArray(),
    "raising __repr__": RaisingRepr(),
    "raising __iter__": RaisingIter(),
    "raising everything": RaisingEverything(),
    "raising objects in a list": [RaisingRepr(), RaisingFloat(), 1.0],
    "10 MB string": "x" * 10_000_000,
    "10 MB of digits": "1" * 10_000_000,
    "NaN": float("nan"),
    "-inf": float("-inf"),
    "1e308": 1e308,
    "-1e308 in a list": [-1e308, 1e308, 0.0],
    "1e-320": 1e-320,
    "'1e400'": "1e400",
    "True": True,
    "empty list": [],
    "[[]]": [[]],
    "ragged": [[1, 2], [3]],
    "dict": {"a": [1, 2]},
    "set": {1, 2},
    "bytes": b"abc",
    "a million numbers": list(range(1_000_000)),
    "a 2000 x 2000 array": np.zeros((2000, 2000)),
    "an object array": np.array([1, "x", None], dtype=object),
    "a function": len,
    "a generator": (i for i in range(3)),
    "NUL bytes": "\x00" * 100,
    # texts a program or expression checker parses: deep, long, huge numbers, endless loops
    "5000 open brackets": "(" * 5000,
    "nested calls": "point(" * 1500,
    "9,999 letters": "a" * 9999,
    "a 5000-digit number": "FORWARD " + "9" * 5000,
    "a loop of 10**10 steps": "REPEAT 99999 [ REPEAT 99999 [ FORWARD 1 ] ]",
    "1/0": "1/0",
}


def _answer_checkers():
    found = []
    for info in pkgutil.iter_modules(exercises.__path__):
        if not info.name.startswith("ch"):
            continue
        module = importlib.import_module(f"goldman_lib.exercises.{info.name}")
        for name, f in sorted(vars(module).items()):
            if (name.startswith("check_") and not name.endswith("_project") and callable(f)
                    and getattr(f, "__module__", "") == module.__name__):
                found.append(pytest.param(module, name, id=f"{info.name}.{name}"))
    return found


ANSWER_CHECKERS = _answer_checkers()


def test_discovery_finds_every_answer_checker_and_each_reads_through_the_layer():
    assert len(ANSWER_CHECKERS) >= 184
    for p in ANSWER_CHECKERS:
        module, name = p.values
        assert name in module.PROBLEMS, f"{module.__name__}.{name} has no statement in PROBLEMS"
        assert getattr(getattr(module, name), "_answer_checker", False), (
            f"{module.__name__}.{name} does not read its answer through goldman_lib.exercises.answer_checker")


class _TooSlow(Exception):
    pass


def _bounded(call, seconds: float = 5.0):
    """Run ``call()``; fail (instead of hanging) if it takes longer than ``seconds``."""
    def on_alarm(signum, frame):
        raise _TooSlow

    previous = signal.signal(signal.SIGALRM, on_alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        return call()
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


@pytest.fixture
def strict(monkeypatch):
    monkeypatch.setattr(exercises, "STRICT", True)


@pytest.mark.parametrize("module,name", ANSWER_CHECKERS)
def test_any_answer_gets_a_short_result(module, name, strict):
    checker = getattr(module, name)
    for label, answer in HOSTILE.items():
        try:
            r = _bounded(lambda: checker(answer))
        except _TooSlow:
            pytest.fail(f"{name}({label}) did not return within 5 s")
        assert isinstance(r, Result), f"{name}({label}) returned {type(r).__name__}"
        assert r.answered and not r.correct, f"{name}({label}): {quote(r.message, 200)}"
        assert 10 < len(r.message) < 500, f"{name}({label}): a message of {len(r.message)} characters"


# -- the layer itself --------------------------------------------------------------------------------

def test_quote_is_short_and_never_calls_a_raising_repr():
    assert quote([[0, 1], [2, "x"]]) == "[[0, 1], [2, 'x']]"
    assert quote(RaisingRepr()) == "<a RaisingRepr>"
    assert len(quote("x" * 10_000_000)) <= 60 and len(quote(nested(100_000))) <= 60
    assert quote(10 ** 400) == "<an integer of about 401 digits>"
    assert quote(np.array([1.5, 2.0])) == "array([1.5, 2.0])"
    big = list(range(1_000_000))
    start = time.process_time()     # CPU time: the suite runs beside two browsers
    quote(big)
    assert time.process_time() - start < 0.1, "quoting stops at the limit, whatever the answer's size"


def test_plain_reads_what_it_can_and_says_why_not():
    assert plain((1, [2.5, np.float32(0.5)])) == (1, [2.5, 0.5])
    assert plain(3 + 0j) == 3.0 and plain(np.array([1 + 0j, 2])).dtype == float
    assert plain(2 + 1j, complex_ok=True) == 2 + 1j
    from fractions import Fraction
    assert plain(Fraction(1, 4)) == 0.25
    original = [[1.0, 2.0]]
    copy = plain(original)
    copy[0][0] = 9.0
    assert original == [[1.0, 2.0]], "the checker gets a copy"
    for bad, why in [(1 + 2j, "imaginary part"), (nested(100), "nested more than"), (10 ** 400, "too large"),
                     (RaisingFloat(), "raised RuntimeError"), (RaisingIter(), "raised RuntimeError"),
                     ("x" * 20_000, "20,000 characters"), (np.zeros(200_000), "200,000 entries"),
                     (len, "not numbers or text")]:
        with pytest.raises(Unreadable, match=why):
            plain(bad)


def test_read_number_and_read_points_never_raise():
    for label, answer in HOSTILE.items():
        value, problem = read_number(answer, "x")
        assert (value is None) == isinstance(problem, Result), label
        assert problem is None or len(problem.message) < 500, label
        got, problem = read_points(answer, "the points")
        assert (got is None) == (problem is not None), label
    assert read_number(np.float32(2.5), "x") == (2.5, None)
    assert read_number(" 2.5 ", "x") == (2.5, None)
    assert read_number(np.array([2.5]), "x") == (2.5, None)


# -- the reproducers of issue 20 §1 ----------------------------------------------------------------

def test_issue20_a_complex_answer_is_not_marked_correct():
    from goldman_lib.exercises import ch11

    r = ch11.check_three_planes(np.array([1 + 1j, 2, 3]))
    assert not r.correct and r.answered and "should be real numbers" in r.message and "(1+1j)" in r.message
    assert ch11.check_three_planes(np.array([1 + 0j, 2, 3])).correct, "a zero imaginary part is read as real"


def test_issue17_ch15_reads_a_python_complex_answer():
    from goldman_lib.exercises import ch15

    assert ch15.check_complex_factor(0.2 + 1.4j).correct
    assert ch15.check_complex_factor([0.2, 1.4]).correct
    r = ch15.check_complex_factor(-5 + 5j)
    assert not r.correct and "the product" in r.message, "a complex slip is named like the same pair"
    assert repr(ch15.check_complex_factor(None)).startswith("Not answered yet: replace None with z as [Re z, Im z]")


def test_issue20_huge_nested_long_and_raising_answers(strict):
    from goldman_lib.exercises import ch01, ch05, ch11

    for answer, why in [(10 ** 400, "too large a number"), (nested(100_000), "nested"),
                        (RaisingFloat(), "raised RuntimeError"), (RaisingRepr(), "not numbers or text"),
                        ("x" * 10_000_000, "10,000,000 characters")]:
        r = ch11.check_law_of_cosines(answer)
        assert not r.correct and why in r.message and len(r.message) < 300, r
    # ch05 raised ValueError on a program over 20,000 characters
    for name in ch05.PROBLEMS:
        r = getattr(ch05, name)("FORWARD 1 " * 3_000)
        assert isinstance(r, Result) and not r.correct and len(r.message) < 500, (name, r)
    r = ch01.check_final_state("x" * 10_000_000)
    assert len(r.message) < 200


# -- the project checker ----------------------------------------------------------------------------

from goldman_lib.exercises.projects import Case, ProjectTimeout, check_project, compare_numbers  # noqa: E402

CASES = [Case(f"x = {x}", (x,)) for x in (0.0, 1.0)]


def _run(function, **kwargs):
    return check_project(function, CASES, reference=lambda x: 2 * x, compare=compare_numbers(), what="doubling",
                         **kwargs)


def test_project_checker_reports_whatever_the_learners_function_does():
    def exits(x):
        raise SystemExit(3)

    def runtime(x):
        raise RuntimeError("boom")

    class Unprintable(Exception):
        def __str__(self):
            raise RuntimeError

    def unprintable(x):
        raise Unprintable

    def deep(x):
        return deep(x)

    # built here, not inside the timed call: making 100,000 nested lists in a long-lived test worker
    # can set off full garbage collections that, beside two browsers, once took over the 2 s limit
    deeply_nested = nested(100_000)

    for f, says in [(exits, "raised SystemExit ('3')"), (runtime, "raised RuntimeError ('boom')"),
                    (unprintable, "raised Unprintable"), (deep, "recursed too deeply"),
                    (lambda x: 10 ** 400, "too large a number"), (lambda x: 2 * x + 1j, "imaginary part"),
                    (lambda x: RaisingFloat(), "raised RuntimeError"), (lambda x: "x" * 10_000_000, "characters"),
                    (lambda x: deeply_nested, "nested")]:
        r = _run(f)
        assert not r.correct and r.answered and says in r.message and len(r.message) < 500, (says, r)


def test_project_checker_lets_keyboard_interrupt_through():
    def interrupted(x):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        _run(interrupted)


def test_issue20_the_slerp_project_rejects_a_complex_slerp():
    from goldman_lib import quaternions as qt
    from goldman_lib.exercises import ch15

    r = ch15.check_slerp_project(lambda q0, q1, t: qt.slerp(q0, q1, t) + 5j)
    assert not r.correct and "should be real numbers" in r.message and "5j" in r.message
    assert ch15.check_slerp_project(lambda q0, q1, t: qt.slerp(q0, q1, t)).correct


def test_issue20_the_time_limit_cannot_be_swallowed():
    assert not issubclass(ProjectTimeout, Exception), "a learner's `except Exception` must not catch it"

    def swallows(x):
        while True:
            try:
                time.sleep(0.01)
            except Exception:  # noqa: BLE001 - the learner's code under test
                pass

    def catches_and_returns(x):
        try:
            while True:
                time.sleep(0.01)
        except BaseException:  # noqa: BLE001 - the learner's code under test
            return 2 * x

    for f in (swallows, catches_and_returns):
        start = time.perf_counter()
        r = _bounded(lambda: _run(f, time_limit=0.3), seconds=10)
        assert time.perf_counter() - start < 5.0     # wall time (it sleeps), on a loaded machine
        assert not r.correct and "ran longer than 0.3 s and was stopped" in r.message, r
