"""No answer is one keystroke away (issue 17 §2): over every answer checker of every chapter, a
wrong answer's message never gives the expected value, nor the gap between the learner's answer and
it to two significant digits ("off by 0.033" with the learner's own 1.2 gives 1.233 back), and the
checker's docstring (what Shift+Tab shows inside ``chNN.check_...(``) never states the value.

Each checker's right answer comes from its worked solution in the chapter's notebook (the argument
of the solution's last call, as ``tests/exercises/test_solutions.py`` finds it); the wrong answers fed are the
right one shifted up and down (all entries, and one entry alone, by amounts that are not round), a
wrong type, and each slip the chapter recognises (``SLIPS``).
"""

from __future__ import annotations

import ast
import functools
import inspect
import json
import re

import numpy as np
import pytest

import goldman_lib.exercises as exercises
from goldman_lib.exercises import Result, fmt, quote
from test_solutions import EXERCISES, leaked, numbers_in, run_solution, solution_cells, solution_code

#: Shifts (relative to the answer's size) chosen so that their two-digit roundings are not numbers a
#: statement or hint would print by chance.
SHIFTS = (0.0371, -0.0529, 0.283, -0.417, 1.37)


@functools.lru_cache(maxsize=None)
def _answer(path, index):
    cell = dict(solution_cells(path))[index]
    namespace, last, _ = run_solution(solution_code(cell))
    return eval(compile(ast.Expression(last.args[0]), "<solution>", "eval"), namespace)


def _numeric(answer):
    try:
        arr = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return None
    if arr.dtype == bool or arr.size == 0 or isinstance(answer, (bool, str)) or not np.all(np.isfinite(arr)):
        return None
    if isinstance(answer, (list, tuple)) and any(isinstance(a, (bool, str)) for a in np.ravel(np.array(answer, dtype=object))):
        return None
    return arr


def shifted(answer) -> list:
    """The right answer moved up and down: every entry, and the first entry alone."""
    arr = _numeric(answer)
    if arr is None:
        return []
    scale = max(1.0, float(np.abs(arr).max()))
    out = []
    for k, s in enumerate(SHIFTS):
        moved = arr + s * scale
        out.append(moved)
        one = arr.copy().ravel()
        one[0] += s * scale * (1 if k % 2 else 0.5)
        out.append(one.reshape(arr.shape))
    return [float(a) if a.ndim == 0 else a.tolist() for a in out]


def gaps(wrong, answer) -> list[float]:
    """Every gap a message could print: per entry, per point, in all, and relative to the answer."""
    got, exp = np.asarray(wrong, dtype=float), np.asarray(answer, dtype=float)
    if got.shape != exp.shape:
        return []
    d = got - exp
    out = [abs(float(x)) for x in d.ravel()]
    out.append(float(np.linalg.norm(d)))
    if d.ndim >= 2:
        out += [float(x) for x in np.linalg.norm(d.reshape(-1, d.shape[-1]), axis=1)]
    size = float(np.linalg.norm(exp))
    if size > 0:
        out += [float(np.linalg.norm(d)) / size, 100 * float(np.linalg.norm(d)) / size]
    return [g for g in out if g > 1e-9]


def gap_leaks(message: str, wrong, answer, given: str) -> list[float]:
    """Numbers in ``message``, written with two significant digits or more, that are a gap between
    ``wrong`` and ``answer`` rounded to those digits (and not a number the learner was given)."""
    known = [v for v, _ in numbers_in(given)]
    out = []
    message = message.replace(quote(wrong), "")   # the learner's own answer, quoted (perhaps cut short)
    for written, digits in numbers_in(message, drop_counters=True):
        if digits < 2 or any(abs(written - k) <= 1e-9 or float(f"{k:.{digits}g}") == written for k in known):
            continue
        for g in gaps(wrong, answer):
            if float(f"{g:.{digits}g}") == abs(written):
                out.append(written)
                break
    return out


CHECKED = [p for p in EXERCISES]
#: Checkers whose messages print a number computed from the learner's answer alone, which a shift
#: can make equal to the gap by chance (not a leak: the learner could compute it from their answer).
GAP_FREE = {
    "check_highlight_exponent": "names the angle at which the learner's own exponent halves the highlight",
}


@pytest.fixture(autouse=True)
def strict_checkers(monkeypatch):
    """A checker's own failure on a readable answer raises here (instead of the learner's "I could
    not check your answer"), so that these tests see it."""
    monkeypatch.setattr(exercises, "STRICT", True)


@pytest.mark.parametrize("path,index,module,name", CHECKED)
def test_wrong_answers_give_neither_the_answer_nor_the_gap(path, index, module, name):
    answer = _answer(path, index)
    checker = getattr(module, name)
    statement = module.PROBLEMS[name]
    assert checker(answer).correct, f"{name}: the worked solution's answer should pass"
    tries = shifted(answer) + list(module.SLIPS.get(name, [])) + ["abc", {"answer": 1}, [answer, answer]]
    for wrong in tries:
        r = checker(wrong)
        assert isinstance(r, Result), (name, wrong, r)
        if r.correct:
            continue          # a shift the checker's tolerance or an accepted form takes: nothing to leak
        given = statement + " " + json.dumps(wrong, default=str)
        assert not leaked(r.message, answer, given), (
            f"{name}({quote(wrong)}) gives the answer away (prints {leaked(r.message, answer, given)}): {r}")
        if _numeric(wrong) is not None and _numeric(answer) is not None and name not in GAP_FREE:
            found = gap_leaks(r.message, wrong, answer, given)
            assert not found, f"{name}({quote(wrong)}) gives the gap to the answer ({found}): {r}"


@pytest.mark.parametrize("path,index,module,name", CHECKED)
def test_docstring_does_not_state_the_answer(path, index, module, name):
    """Shift+Tab inside ``chNN.check_...(`` shows this docstring: it says what is checked, never
    the value (nor a doctest that shows a correct answer; those live in tests/)."""
    answer = _answer(path, index)
    doc = inspect.getdoc(getattr(module, name)) or ""
    assert "Correct:" not in doc, f"{name}'s docstring shows a correct answer; keep that example in tests/"
    given = module.PROBLEMS[name]
    found = [e for e in leaked(doc, answer, given) if not _small_int(e) or _stated(doc, e)]
    assert not found, f"{name}'s docstring states the expected value ({found}):\n{doc}"
    arr = _numeric(answer)
    if arr is not None and 2 <= arr.size <= 16:
        written = ", ".join(fmt(v) for v in arr.ravel())
        assert written not in doc.replace("[", "(").replace("]", ")"), (
            f"{name}'s docstring states the expected value ({written}):\n{doc}")


def _small_int(value: float) -> bool:
    return float(value).is_integer() and abs(value) <= 12


def _stated(doc: str, value: float) -> bool:
    """A small whole number (a count, a degree, a coordinate such as 0 or 1 appears in any formula)
    states the answer only where the docstring says it is one: "= 3", "is 3", "gives 3", "so 3"."""
    text = f"{value:g}"
    return bool(re.search(rf"(?:=|\bis|\bgives|\bso|\banswer)\s*\(?{re.escape(text)}(?![\d.(\w])", doc))


# -- the helpers above can fail ---------------------------------------------------------------------

def test_gap_leaks_finds_a_two_digit_gap_and_ignores_words():
    assert gap_leaks("the perimeter is off by 0.5.", 5.5, 6.0, "") == []          # one digit is not two
    assert gap_leaks("the side is off by 0.033.", 1.2, 1.233, "") == [0.033]
    assert gap_leaks("the side is off by 0.033; yours is 1.2.", 1.2, 1.233, "") == [0.033]
    assert gap_leaks("yours is (0.06084, 1).", [0.060844, 1.0], [0.0, 1.0], "[0.060844, 1.0]") == []
    assert gap_leaks("your point is 0.41 away.", [1.0, 1.0], [1.3, 1.28], "") == [0.41]
    assert gap_leaks("the side is a little too small.", 1.2, 1.233, "") == []
    assert gap_leaks("off by 3.3%.", 1.2, 1.241, "") == [3.3]


def test_shifted_moves_every_entry_and_one_entry():
    moved = shifted([1.0, 2.0])
    assert len(moved) == 2 * len(SHIFTS) and all(m != [1.0, 2.0] for m in moved)
    assert shifted("abc") == [] and shifted([True, False]) == []
