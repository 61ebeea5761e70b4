"""views.agreement prints a check as ours | reference | gap: the gap is '< bound' when it holds (the
same text on every CPU), and a gap outside the bound is shown and flagged, so the stored notebook
output changes where the claim fails.  Expected strings are written out by hand."""

import numpy as np
import pytest

from goldman_lib.views.agreement import agreement_table, gap_text, shown_value


def test_values_are_rounded_to_the_digits_that_matter():
    assert shown_value(2 / 3) == "0.6667"
    assert shown_value(-1e-17) == "0"                       # no '-0' from rounding noise
    assert shown_value(5.0) == "5"
    assert shown_value([0.5, -1.0, 4.0]) == "(0.5, -1, 4)"
    assert shown_value(np.array([[1.0, 2.0], [3.0, 4.0]])) == "((1, 2), (3, 4))"
    assert shown_value(np.ones((500, 3))) == "(1, 1, 1), … (500 items)"
    assert shown_value(True) == "True" and shown_value("a label") == "a label"


def test_gap_inside_the_bound_is_printed_as_the_bound_and_outside_it_is_flagged():
    assert gap_text(0.0, 1e-12) == "< 1e-12" and gap_text(9.9e-13, 1e-12) == "< 1e-12"
    assert gap_text(1e-12, 1e-12) == "1e-12 > 1e-12 (fails)"
    assert gap_text(0.5, 1e-8) == "0.5 > 1e-8 (fails)"


def test_table_takes_the_largest_gap_over_a_batch():
    a = np.zeros(500)
    b = a.copy()
    b[321] = 1e-3                                            # one pair of 500 off by 1e-3
    text = agreement_table([("batch", a, b), ("same", [1.0, 2.0], [1.0, 2.0 + 1e-15])])
    lines = text.splitlines()
    assert lines[0].split() == ["claim", "ours", "reference", "gap"]
    assert lines[1].startswith("batch") and lines[1].endswith("0.001 > 1e-12 (fails)")
    assert lines[2].startswith("same") and lines[2].endswith("< 1e-12")
    nan = agreement_table([("nan", [np.nan], [1.0])])
    assert "fails" in nan                                    # a NaN never passes as agreement


@pytest.mark.parametrize("rows, bound, err, match", [
    ([], 1e-12, ValueError, "at least one"),
    ([("x", 1.0)], 1e-12, ValueError, r"rows\[0\] must be a triple"),
    ([("x", [1.0, 2.0], [1.0, 2.0, 3.0])], 1e-12, ValueError, "shape"),
    ([("x", "one", 1.0)], 1e-12, TypeError, "numbers or arrays"),
    ([("x", 1.0, 1.0)], 0.0, ValueError, "bound must be a positive number"),
    ([("x", 1.0, 1.0)], True, ValueError, "bound must be a positive number"),
])
def test_bad_input_names_the_parameter_and_the_rule(rows, bound, err, match):
    with pytest.raises(err, match=match):
        agreement_table(rows, bound=bound)
