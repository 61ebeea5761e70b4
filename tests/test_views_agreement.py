"""goldman_lib.views.agreement: a check printed as the values it compares (issue 18, part 5)."""

import numpy as np
import pytest

from goldman_lib.views import agreement


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
