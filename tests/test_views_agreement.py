"""The agreement table that replaces "claim: True" in the notebooks: values rounded to the digits
that matter, the gap as a portable bound, a failed claim visible, bad rows refused."""

import re

import numpy as np
import pytest

from goldman_lib.views.agreement import agreement_table, shown_values

# the course check's pattern for a residual printed to its last bits
FLOAT_NOISE = re.compile(r"(?<![\w.])(?:\d\.\d+e-(?:1\d|[2-9]\d|\d{3})|0(?:\.0+)?e[+-]00)(?![\w.])")


def test_shown_values_rounds_and_drops_negative_zero():
    assert shown_values(2 / 3) == "0.6667"
    assert shown_values([-1e-17, 0.1 + 0.2]) == "[0.0, 0.3]"
    assert shown_values(np.array([[1, 2], [3, 4]])) == "[[1, 2], [3, 4]]"
    assert shown_values(np.arange(30.0).reshape(10, 3)) == "[0.0, 1.0, 2.0] ... (10 x 3)"
    assert shown_values(np.arange(9.0)) == "[0.0, 1.0, 2.0, 3.0, 4.0, 5.0] ... (9)"
    assert shown_values(1 / 7, digits=2) == "0.14"
    assert shown_values([True, False]) == "[True, False]"


def test_agreeing_rows_print_the_bound_not_the_noise():
    ours = np.array([0.1 + 0.2, 1.0])           # 0.30000000000000004
    text = agreement_table([("sum", ours, [0.3, 1.0])])
    assert text.splitlines() == ["     ours        reference   largest gap",
                                 "sum  [0.3, 1.0]  [0.3, 1.0]  < 1e-12"]
    assert not FLOAT_NOISE.search(text)


def test_a_failed_claim_shows_its_gap():
    text = agreement_table([("off", [1.0, 2.0], [1.0, 2.5])], bound=1e-6)
    assert text.splitlines()[1].endswith("0.5 NOT < 1e-06")
    differ = agreement_table([("differ", [0.0], [2.0], {"relation": ">", "bound": 0.1}),
                              ("same", [0.0], [0.0], {"relation": ">", "bound": 0.1})])
    assert differ.splitlines()[1].endswith("2 > 0.1") and differ.splitlines()[2].endswith("0 NOT > 0.1")


def test_a_wide_table_puts_each_label_on_its_own_line():
    text = agreement_table([("a long label " * 5, np.zeros((5, 3)), np.zeros((5, 3)))], width=60)
    lines = text.splitlines()
    assert lines[1] == ("a long label " * 5) and lines[2].startswith("  [0.0, 0.0, 0.0] ... (5 x 3)")
    assert lines[2].rstrip().endswith("< 1e-12")


@pytest.mark.parametrize("rows, match", [
    ([], "at least one"),
    ([("x", 1.0)], r"rows\[0\] must be"),
    ([("x", [1.0, 2.0], [1.0, 2.0, 3.0])], "same shape"),
    ([("x", 1.0, 1.0, {"bound": -1})], "bound must be a positive finite"),
    ([("x", 1.0, 1.0, {"bound": float("nan")})], "bound must be a positive finite"),
    ([("x", 1.0, 1.0, {"relation": "="})], "relation must be"),
    ([("x", 1.0, 1.0, {"tolerance": 1})], "options may hold"),
])
def test_bad_rows_are_refused(rows, match):
    with pytest.raises(ValueError, match=match):
        agreement_table(rows)


def test_bad_values_are_refused():
    with pytest.raises(TypeError, match="value must be a number"):
        shown_values(object())
    with pytest.raises(ValueError, match="digits must be"):
        shown_values(1.0, digits=-1)
