"""The exercise framework: verdicts, their rendering, and the shared numeric/point checkers."""

import numpy as np

from goldman_lib.exercises import Result, check_number, check_points, fmt, read_number


def test_result_verdicts_render_as_text_and_html():
    ok, bad, todo = Result(True, "fine."), Result(False, "off."), Result(False, "replace None.", answered=False)
    assert (bool(ok), bool(bad), bool(todo)) == (True, False, False)
    assert [repr(r) for r in (ok, bad, todo)] == ["Correct: fine.", "Not yet: off.", "Not answered yet: replace None."]
    assert "&#10004; Correct:" in ok._repr_html_() and "&#10008; Not yet:" in bad._repr_html_()
    assert "<b>" not in Result(False, "<b>")._repr_html_().split("</b>", 1)[1]  # the message is escaped


def test_check_number_says_how_far_off():
    assert check_number(6.0000001, 6, what="x").correct
    r = check_number(6.5, 6, what="the perimeter", hint="six sides")
    assert repr(r) == "Not yet: the perimeter is too large. Hint: six sides."
    assert repr(check_number(6.1, 6, what="x")) == "Not yet: x is a little too large."
    assert repr(check_number(-6, 6, what="x")) == "Not yet: x is far too small."
    assert "6" not in repr(check_number(6.5, 6, what="x")), "neither the expected value nor the gap is given"
    assert repr(check_number("six", 6, what="x")) == "Not yet: x should be a number; you gave 'six'."
    assert repr(check_number(float("nan"), 6, what="x")) == "Not yet: x should be a finite number; you gave nan."
    assert not check_number(None, 6, what="x").answered and not check_number(..., 6, what="x").answered


def test_read_number():
    assert read_number("2.5", "x") == (2.5, None)
    value, problem = read_number([1, 2], "x")
    assert value is None and not problem


def test_check_points_names_the_first_point_that_is_off():
    assert check_points([[0, 0], [1, 1]], np.array([[0, 0], [1, 1]]), what="P").correct
    r = check_points([[0, 0], [1, 2]], [[0, 0], [1, 1]], what="the points")
    assert repr(r) == ("Not yet: point 1 of the points, (1, 2), is well off from where it should be "
                       "(1 of 2 points are off).")
    assert "shape (2, 2); yours has shape (3, 2)" in repr(check_points(np.zeros((3, 2)), np.zeros((2, 2)), what="P"))


def test_fmt_is_compact_and_has_no_negative_zero():
    assert fmt(-0.0) == "0" and fmt(1 / 3) == "0.3333" and fmt([2, -0.0]) == "(2, 0)"


# -- every chapter's checkers, found by discovery -------------------------------------------------
# Each chapter module ``goldman_lib.exercises.chNN`` has ``PROBLEMS`` (checker name -> statement)
# and the checkers themselves.  Whatever the chapter, a checker must treat ``None`` (and ``...``) as
# "not answered yet", answer garbage with a message rather than an exception, and have a problem
# statement that cites its chapter.  Chapter test files check right and wrong answers.

import importlib  # noqa: E402
import pkgutil  # noqa: E402

import pytest  # noqa: E402

import goldman_lib.exercises as exercises_pkg  # noqa: E402


def _chapter_checkers():
    found = []
    for info in pkgutil.iter_modules(exercises_pkg.__path__):
        if not info.name.startswith("ch"):
            continue
        module = importlib.import_module(f"goldman_lib.exercises.{info.name}")
        for name in module.PROBLEMS:
            found.append(pytest.param(module, name, id=f"{info.name}.{name}"))
    return found


CHAPTER_CHECKERS = _chapter_checkers()
GARBAGE = ("abc", [[1, 2], [3]], [[1, "x"]], np.nan, np.inf, [np.nan, 1.0], {"a": 1}, [1.0, 2.0],
           [1.0, 2.0, 3.0, 4.0, 5.0])


def test_every_chapter_with_a_notebook_has_checkers():
    chapters = {p.id.split(".")[0] for p in CHAPTER_CHECKERS}
    assert {"ch01", "ch02", "ch06", "ch24", "ch27", "ch30"} <= chapters


@pytest.mark.parametrize("module,name", CHAPTER_CHECKERS)
def test_checker_has_a_statement_citing_its_chapter(module, name):
    chapter = int(module.__name__.rsplit("ch", 1)[1])
    assert callable(getattr(module, name, None)), f"PROBLEMS names {name}, which the module does not define"
    assert f"§{chapter}." in module.PROBLEMS[name], f"the statement of {name} cites no section of chapter {chapter}"


@pytest.mark.parametrize("module,name", CHAPTER_CHECKERS)
def test_unanswered_is_not_failed(module, name):
    for blank in (None, ...):
        r = getattr(module, name)(blank)
        assert isinstance(r, Result) and not r.answered and not r.correct
        assert repr(r).startswith("Not answered yet: replace None with"), repr(r)


@pytest.mark.parametrize("module,name", CHAPTER_CHECKERS)
def test_garbage_gets_a_message_not_an_exception(module, name):
    for bad in GARBAGE:
        r = getattr(module, name)(bad)
        assert isinstance(r, Result) and not r.correct and r.answered and r.message, (bad, r)


# -- the programming-project checker --------------------------------------------------------------

from goldman_lib.exercises.projects import Case, check_project, compare_numbers, compare_points  # noqa: E402

SQUARE_CASES = [Case(f"x = {x}", (x,), kind="negative" if x < 0 else "") for x in (0.0, 1.5, -2.0, 3.0)]


def _square(x):
    return x * x


def test_project_checker_accepts_a_correct_function_and_names_the_case_kinds():
    r = check_project(lambda x: x ** 2, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="squaring")
    assert r.correct and repr(r) == "Correct: squaring passes all 4 cases, including negative."


def test_project_checker_reports_the_first_wrong_case_with_input_output_and_hint():
    r = check_project(lambda x: x * abs(x), SQUARE_CASES, reference=_square, compare=compare_numbers(),
                      what="squaring", hint="the sign")
    assert not r.correct and r.answered
    assert repr(r) == ("Not yet: case 3 of 4 (x = -2.0): your function returned -4; it is off by 8. "
                       "Hint: the sign.")


def test_project_checker_reports_the_learners_exception_with_their_line():
    def broken(x):
        y = x + 1
        return [y][2]

    r = check_project(broken, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="squaring")
    assert not r.correct and r.answered
    assert "case 1 of 4 (x = 0.0): your function raised IndexError ('list index out of range')" in r.message
    assert "line 3 of its cell: `return [y][2]`" in r.message


def test_project_checker_stops_endless_loops_and_recursion():
    def forever(x):
        while True:
            x += 1

    def recurse(x):
        return recurse(x)

    r = check_project(forever, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="s", time_limit=0.2)
    assert not r.correct and "longer than 0.2 s" in r.message
    r = check_project(recurse, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="s")
    assert not r.correct and "recursed too deeply" in r.message


def test_project_checker_unanswered_and_not_callable():
    assert not check_project(None, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="s").answered

    def starter(x):
        """Square x."""
        ...

    assert not check_project(starter, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="s").answered
    r = check_project(4.0, SQUARE_CASES, reference=_square, compare=compare_numbers(), what="s")
    assert r.answered and not r.correct and "pass your function itself" in r.message


def test_project_checker_does_not_let_a_function_spoil_its_input():
    import numpy as np

    cases = [Case("points", (np.array([[0.0, 0.0], [1.0, 1.0]]),))] * 2

    def mutate(p):
        p += 1
        return p

    r = check_project(mutate, cases, reference=lambda p: p + 1, compare=compare_points(), what="shift")
    assert r.correct, r
    r = check_project(lambda p: p[:1], cases, reference=lambda p: p + 1, compare=compare_points(), what="shift")
    assert "shape (1, 2); the expected result has shape (2, 2)" in r.message
