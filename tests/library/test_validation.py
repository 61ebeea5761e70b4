"""Argument checks: every message names the parameter and the rule, with the offending index."""

import numpy as np
import pytest

from goldman_lib.validation import as_float, as_int, as_parameter, as_points


@pytest.mark.parametrize("bad, error, message", [
    ([[0, 0], [1, np.nan]], ValueError, r"ctrl must be finite; ctrl\[1, 1\] is nan"),
    ([[0, 0], [np.inf, 1]], ValueError, r"ctrl must be finite; ctrl\[1, 0\] is inf"),
    ([0, 1, 2], ValueError, r"ctrl must have shape \(n, d\) with coordinates in the last axis; got shape \(3,\)"),
    ("0 1", TypeError, "ctrl must be numeric, not str"),
    ([[0, 0], [1]], TypeError, "ctrl must be a numeric array-like"),
    (np.zeros((0, 2)), ValueError, "ctrl must hold at least 1 point"),
])
def test_as_points_rejects(bad, error, message):
    with pytest.raises(error, match=message):
        as_points(bad, "ctrl")


def test_as_points_dimension_rule_and_copy_semantics():
    with pytest.raises(ValueError, match="must hold 2 or 3-dimensional points"):
        as_points(np.zeros((2, 4)), "points", dim=(2, 3))
    out = as_points([[1, 2]], "p", dim=2)
    assert out.dtype == float and out.shape == (1, 2)


def test_as_parameter_names_the_first_bad_entry_and_the_interval():
    with pytest.raises(ValueError, match=r"t must be finite; t\[3\] is nan"):
        as_parameter([0, 0.1, 0.2, np.nan], "t")
    with pytest.raises(ValueError, match=r"u must lie in \[0.0, 1.0\]; u\[1\] is -0.5"):
        as_parameter([0.5, -0.5], "u", low=0.0, high=1.0)
    assert as_parameter(0.25).shape == ()


@pytest.mark.parametrize("value, error, message", [
    (True, TypeError, "n must be an integer; got True"),
    ("3", TypeError, "n must be an integer; got '3'"),
    (2.5, TypeError, "n must be an integer; got 2.5"),
    (-1, ValueError, "n must be >= 0; got -1"),
    (101, ValueError, "n must be <= 100; got 101"),
])
def test_as_int_rules(value, error, message):
    with pytest.raises(error, match=message):
        as_int(value, "n", minimum=0, maximum=100)


def test_as_int_accepts_integral_values():
    assert as_int(np.int64(4), "n") == 4 and as_int(4.0, "n") == 4


def test_as_float_rules():
    assert as_float(np.float32(0.5), "step") == 0.5
    with pytest.raises(ValueError, match="step must be finite; got inf"):
        as_float(float("inf"), "step")
    with pytest.raises(ValueError, match="step must be positive; got -1.0"):
        as_float(-1, "step", positive=True)
    with pytest.raises(TypeError, match="step must be a real number; got None"):
        as_float(None, "step")
