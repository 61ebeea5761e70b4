"""Chapter 27 exercise checkers: right answers pass, typical wrong answers fail with the right
explanation, None is "unanswered".  Expected values are hand-computed here or by scipy."""

import math

import numpy as np
import pytest
from scipy.interpolate import BSpline

from goldman_lib.exercises import ch27


def test_every_checker_has_a_problem_and_handles_none():
    for name in ch27.PROBLEMS:
        res = getattr(ch27, name)(None)
        assert not res.answered and not res.correct and "replace None" in res.message


def test_span_control_points():
    assert ch27.check_span_control_points([1, 2, 3]).correct
    assert ch27.check_span_control_points((3, 1, 2)).correct          # order does not matter
    assert "ending at P_k" in ch27.check_span_control_points([3, 4, 5]).message
    assert "p+1 = 3 control points" in ch27.check_span_control_points([1, 2]).message
    assert not ch27.check_span_control_points([0, 1, 2]).correct


def test_de_boor_point_against_scipy():
    ref = BSpline(ch27.DE_BOOR_KNOTS, ch27.DE_BOOR_CTRL, 2)(ch27.DE_BOOR_U)
    np.testing.assert_allclose(ref, [4.25, 1.0])
    assert ch27.check_de_boor_point(ref).correct
    assert "first level" in ch27.check_de_boor_point([3.5, 1]).message
    # de Casteljau's weights on the span [1, 2] with s = 0.5 over P1, P2, P3
    bez = 0.25 * np.array([2, 4]) + 0.5 * np.array([4, 0]) + 0.25 * np.array([6, 2])
    assert "de Casteljau's weights" in ch27.check_de_boor_point(bez).message
    assert "one point" in ch27.check_de_boor_point([1, 2, 3]).message
    assert "from C(1.5)" in ch27.check_de_boor_point([0, 0]).message


def test_basis_value_against_scipy():
    N = BSpline.design_matrix([ch27.BASIS_U], ch27.DE_BOOR_KNOTS, 2).toarray()[0]
    assert ch27.check_basis_value(N[1]).correct and N[1] == pytest.approx(0.625)
    assert "Bernstein" in ch27.check_basis_value(0.5).message
    assert "neighbouring" in ch27.check_basis_value(N[0]).message
    assert "should be 0.625" in ch27.check_basis_value(0.9).message
    assert "number" in ch27.check_basis_value("x").message


def test_continuity():
    assert ch27.check_continuity(1).correct
    assert "simple knot" in ch27.check_continuity(2).message
    assert "one order too few" in ch27.check_continuity(0).message
    assert "C^(p - m)" in ch27.check_continuity(3).message


def test_circle_weight():
    assert ch27.check_circle_weight(math.sqrt(2) / 2).correct
    assert ch27.check_circle_weight(0.70711).correct
    assert "parabola" in ch27.check_circle_weight(1).message
    assert "1/cos 45" in ch27.check_circle_weight(math.sqrt(2)).message
    assert "positive" in ch27.check_circle_weight(-1).message
    assert "inside the circle" in ch27.check_circle_weight(0.5).message
