"""goldman_lib.widgets.agreement: a check printed as the values it compares (issue 18, part 5)."""

import numpy as np
import pytest

from goldman_lib.widgets import agreement


def test_a_gap_within_the_bound_prints_the_bound_not_the_noise():
    assert agreement.gap(2.7755575615628914e-17, 1e-12) == "< 1e-12"
    assert agreement.gap(0.0, 1e-9) == "< 1e-9"


def test_a_gap_over_the_bound_is_shown_and_named():
    assert agreement.gap(3e-3, 1e-3) == "0.003 (over the bound 0.001)"
    text = agreement.side_by_side([0, 1], [1.0, 2.0], [1.0, 2.5], bound=1e-6)
    assert text.splitlines()[-1] == "largest gap over all 2: 0.5 (over the bound 1e-6)"


@pytest.mark.parametrize("x, shown", [(-1e-17, "0"), (-0.0, "0"), (1 / 3, "0.3333"), (-2.5, "-2.5"),
                                      (12.0, "12"), (0.90625 + 2e-16, "0.9062"), (0.90625 - 2e-16, "0.9062"),
                                      (float("nan"), "nan")])
def test_numbers_are_rounded_portably(x, shown):
    assert agreement.number(x) == shown


def test_side_by_side_spreads_its_rows_over_all_and_reports_the_largest_gap():
    t = np.linspace(0, 1, 101)
    ours = np.c_[t, t ** 2]
    ref = ours.copy()
    ref[37] += [0, 1e-13]                       # not a shown row: the last line must still see it
    ref[50] += [2e-3, 0]                        # a shown row over the bound
    lines = agreement.side_by_side(t, ours, ref, bound=1e-3).splitlines()
    assert [line.split("|")[0].strip() for line in lines[1:-1]] == ["0", "0.25", "0.5", "0.75", "1"]
    assert lines[3].split("|")[3].strip() == "0.002 (over the bound 0.001)"
    assert lines[-1] == "largest gap over all 101: 0.002 (over the bound 0.001)"
    assert len({line.index("|") for line in lines[:-1]}) == 1       # the columns line up


def test_side_by_side_refuses_mismatched_input():
    with pytest.raises(ValueError, match="same shape"):
        agreement.side_by_side([0, 1], [[0, 0], [1, 1]], [0, 1], bound=1e-12)
    with pytest.raises(ValueError, match="one label per row"):
        agreement.side_by_side([0], [0, 1], [0, 1], bound=1e-12)


def test_the_same_infinity_is_no_gap_but_a_miss_against_a_hit_is():
    text = agreement.side_by_side(["ray 0", "ray 1"], [[1.0, np.inf], [np.inf, np.inf]],
                                  [[1.0, np.inf], [np.inf, np.inf]], bound=1e-9)
    assert text.splitlines()[-1] == "largest gap over all 2: < 1e-9"
    text = agreement.side_by_side(["ray 0"], [[1.0, np.inf]], [[1.0, 2.0]], bound=1e-9)
    assert text.splitlines()[-1] == "largest gap over all 1: inf (over the bound 1e-9)"


# -- value and agreement_table (the notebooks of chapters 07-17 print these) --------------------------------

FLOAT_NOISE = __import__("re").compile(r"(?<![\w.])(?:\d\.\d+e-(?:1\d|[2-9]\d|\d{3})|0(?:\.0+)?e[+-]00)(?![\w.])")


def test_values_are_rounded_to_the_digits_that_matter():
    assert agreement.value(2 / 3) == "0.6667"
    assert agreement.value([-1e-17, 0.1 + 0.2]) == "(0, 0.3)"
    assert agreement.value(np.array([[1.0, 2.0], [3.0, 4.0]])) == "((1, 2), (3, 4))"
    assert agreement.value(np.ones((500, 3)), max_items=6) == "(1, 1, 1), … (500 x 3)"
    assert agreement.value(np.arange(9.0), max_items=6) == "0, … (9 values)"
    assert agreement.value(1 / 7, digits=2) == "0.14"
    assert agreement.value([True, False]) == "(True, False)" and agreement.value("a label") == "a label"
    assert agreement.value(0.2 + 1.4j) == "(0.2, 1.4)"


def test_agreeing_rows_print_the_bound_not_the_noise():
    text = agreement.agreement_table([("sum", np.array([0.1 + 0.2, 1.0]), [0.3, 1.0])])
    assert text.splitlines()[1].split() == ["sum", "(0.3,", "1)", "(0.3,", "1)", "<", "1e-12"]
    assert not FLOAT_NOISE.search(text)


def test_the_table_takes_the_largest_gap_over_a_batch_and_a_failed_claim_shows():
    a = np.zeros(500)
    b = a.copy()
    b[321] = 1e-3                                    # one pair of 500 off by 1e-3: not the row shown
    lines = agreement.agreement_table([("batch", a, b), ("same", [1.0, 2.0], [1.0, 2.0 + 1e-15])],
                                      headers=("claim", "ours", "reference", "gap")).splitlines()
    assert lines[0].split() == ["claim", "ours", "reference", "gap"]
    assert lines[1].startswith("batch") and lines[1].endswith("0.001 (over the bound 1e-12)")
    assert lines[2].startswith("same") and lines[2].endswith("< 1e-12")
    assert "over the bound" in agreement.agreement_table([("nan", [np.nan], [1.0])])   # NaN never agrees
    differ = agreement.agreement_table([("differ", [0.0], [2.0], {"relation": ">", "bound": 0.1}),
                                        ("same", [0.0], [0.0], {"relation": ">", "bound": 0.1})]).splitlines()
    assert differ[1].endswith("2 > 0.1") and differ[2].endswith("0 NOT > 0.1")


def test_a_wide_table_puts_each_label_on_its_own_line():
    text = agreement.agreement_table([("a long label " * 5, np.zeros((5, 3)), np.zeros((5, 3)))], width=60)
    lines = text.splitlines()
    assert lines[1] == "a long label " * 5 and lines[2].strip().startswith("(0, 0, 0), … (5 x 3)")
    assert lines[2].rstrip().endswith("< 1e-12")


@pytest.mark.parametrize("rows, kw, err, match", [
    ([], {}, ValueError, "at least one"),
    ([("x", 1.0)], {}, ValueError, r"rows\[0\] must be"),
    ([("x", [1.0, 2.0], [1.0, 2.0, 3.0])], {}, ValueError, "same shape"),
    ([("x", "one", 1.0)], {}, TypeError, "numbers or arrays"),
    ([("x", 1.0, 1.0)], {"bound": 0.0}, ValueError, "bound must be a positive finite"),
    ([("x", 1.0, 1.0)], {"bound": True}, ValueError, "bound must be a positive finite"),
    ([("x", 1.0, 1.0, {"bound": float("nan")})], {}, ValueError, "bound must be a positive finite"),
    ([("x", 1.0, 1.0, {"relation": "="})], {}, ValueError, "relation must be"),
    ([("x", 1.0, 1.0, {"tolerance": 1})], {}, ValueError, "options may hold"),
    ([("x", 1.0, 1.0)], {"headers": ("a", "b")}, ValueError, "headers must name four"),
    ([("x", 1.0, 1.0)], {"digits": -1}, ValueError, "digits must be"),
])
def test_bad_input_names_the_parameter_and_the_rule(rows, kw, err, match):
    with pytest.raises(err, match=match):
        agreement.agreement_table(rows, **kw)


def test_bad_values_are_refused():
    with pytest.raises(TypeError, match="value must be a number"):
        agreement.value(object())
    with pytest.raises(ValueError, match="relation must be"):
        agreement.gap(1.0, 0.1, "=")
