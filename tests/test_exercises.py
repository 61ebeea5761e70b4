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
    assert repr(r) == "Not yet: the perimeter should be 6, you gave 6.5 (off by 0.5). Hint: six sides."
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
    assert repr(r) == "Not yet: point 1 of the points should be (1, 1), you gave (1, 2) (1 away)."
    assert "shape (2, 2); yours has shape (3, 2)" in repr(check_points(np.zeros((3, 2)), np.zeros((2, 2)), what="P"))


def test_fmt_is_compact_and_has_no_negative_zero():
    assert fmt(-0.0) == "0" and fmt(1 / 3) == "0.3333" and fmt([2, -0.0]) == "(2, 0)"
