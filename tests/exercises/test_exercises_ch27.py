"""Chapter 27 exercise checkers: right answers (worked by hand here, not by the library) pass, each
recognised slip gets its own explanation, and no message gives the answer away (the generic
checks of every checker are in tests/exercises/test_exercises.py and tests/exercises/test_solutions.py)."""

import numpy as np
import pytest
from scipy.interpolate import BSpline

from goldman_lib.exercises import Result, ch27

# Exercise 1: knots 0,0,0,1,3,4,4,4, u = 2 in [t3, t4) = [1, 3): P1 = (1, 3), P2 = (4, 6), P3 = (7, 0).
# level 1: node 2, a = (2 - t2)/(t4 - t2) = 2/3 -> (1, 3) + 2/3 (3, 3) = (3, 5)
#          node 3, a = (2 - t3)/(t5 - t3) = 1/3 -> (4, 6) + 1/3 (3, -6) = (5, 4)
# level 2: node 3, a = (2 - t3)/(t4 - t3) = 1/2 -> (4, 4.5)
DE_BOOR = [4.0, 4.5]
# Exercise 2: u = 2.5: N_3,0 = 1; N_2,1 = (3 - 2.5)/2 = 1/4, N_3,1 = (2.5 - 1)/2 = 3/4;
# N_1,2 = (3 - 2.5)/3 * 1/4 = 1/24; N_2,2 = 2.5/3 * 1/4 + (4 - 2.5)/3 * 3/4 = 7/12; N_3,2 = 1.5/3 * 3/4 = 3/8.
BASIS = [1 / 24, 7 / 12, 3 / 8]
# Exercise 3: quartic, multiplicities 1, 2, 3, 4 -> C^(4 - m).
ORDERS = [3, 2, 1, 0]
# Exercise 4: blossoms b1(u1, u2) = (u1 + u2) - u1 u2 of 2u - u^2, b2 = 0.5 + (u1 + u2)/2 - u1 u2 / 2:
# P0 = b1(0, 0) = 0, P1 = b1(0, 1) = 1, P2 = b1(1, 3) = 4 - 3 = 1 = b2(1, 3) = 0.5 + 2 - 1.5, P3 = b2(3, 3) = -1.
SPLINE = [0.0, 1.0, 1.0, -1.0]
# Exercise 5: u = 1.5: rows 1, 2 weigh 1/2; v = 0.5: Bernstein 1/4, 1/2, 1/4.
# row 1 heights 2, 4, 2 -> 3; row 2 heights 4, 0, 6 -> 2.5; z = 2.75; x = 1.5, y = 1.
SURFACE = [1.5, 1.0, 2.75]
# Exercise 6: N_1,2(1.5) = 1/8, N_2,2 = 5/8, N_3,2 = 1/4; weighted 2/8, 5/8, 6/8, sum 13/8;
# numerator 1/4 (1, 2) + 5/8 (3, 2) + 3/4 (4, 0) = (41/8, 14/8) -> (41/13, 14/13).
NURBS = [41 / 13, 14 / 13]

CHECKERS = [
    (ch27.check_local_de_boor, DE_BOOR),
    (ch27.check_basis_values, BASIS),
    (ch27.check_continuity_orders, ORDERS),
    (ch27.check_spline_control_points, SPLINE),
    (ch27.check_surface_point, SURFACE),
    (ch27.check_nurbs_point, NURBS),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch27.CURVE_CTRL.tolist() == [[0, 0], [1, 3], [4, 6], [7, 0], [9, 2]]
    assert ch27.CURVE_KNOTS.tolist() == [0, 0, 0, 1, 3, 4, 4, 4] and ch27.CURVE_DEGREE == 2
    assert (ch27.DE_BOOR_U, ch27.BASIS_U) == (2.0, 2.5)
    assert ch27.CONT_DEGREE == 4 and ch27.CONT_KNOTS.tolist() == [0] * 5 + [1] + [2] * 2 + [3] * 3 + [4] * 4 + [5] * 5
    assert ch27.SURF_HEIGHTS.tolist() == [[0, 2, 0], [2, 4, 2], [4, 0, 6]] and ch27.SURF_UV == (1.5, 0.5)
    assert ch27.NURBS_WEIGHTS.tolist() == [1, 2, 1, 3] and ch27.NURBS_U == 1.5


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_hand_answers_agree_with_scipy():
    assert np.allclose(BSpline(ch27.CURVE_KNOTS, ch27.CURVE_CTRL, 2)(2.0), DE_BOOR)
    assert np.allclose(BSpline.design_matrix([2.5], ch27.CURVE_KNOTS, 2).toarray()[0, 1:4], BASIS)
    knots = [0, 0, 0, 1, 3, 3, 3]
    spline = BSpline(knots, SPLINE, 2)
    u = np.linspace(0, 3, 13)
    assert np.allclose(spline(u), np.where(u <= 1, 2 * u - u ** 2, 0.5 + u - u ** 2 / 2))


def test_local_de_boor_slips():
    assert "de Casteljau's weight" in ch27.check_local_de_boor([4, 3.75]).message
    assert "level 1" in ch27.check_local_de_boor([3, 5]).message
    assert "level 1" in ch27.check_local_de_boor([5, 4]).message
    assert "P0..P2, the points of another span" in ch27.check_local_de_boor([4, 4]).message
    assert "P2..P4" in ch27.check_local_de_boor([5, 10]).message
    assert "is well off from C(2)" in ch27.check_local_de_boor([0, 0]).message
    assert "one point" in ch27.check_local_de_boor([1, 2, 3]).message


def test_basis_values_slips():
    assert ch27.check_basis_values([0.0417, 0.5833, 0.375]).correct        # 4 decimals are enough
    assert "Bernstein" in ch27.check_basis_values([0.0625, 0.375, 0.5625]).message
    assert "reverse order" in ch27.check_basis_values(BASIS[::-1]).message
    assert "sum to 0.9" in ch27.check_basis_values([0.1, 0.5, 0.3]).message
    assert "N_1,2 is too large" in ch27.check_basis_values([0.05, 0.575, 0.375]).message
    assert "three basis functions" in ch27.check_basis_values([0.2, 0.8]).message


def test_continuity_orders_slips():
    assert "multiplicities" in ch27.check_continuity_orders([1, 2, 3, 4]).message
    assert "one too low" in ch27.check_continuity_orders([2, 1, 0, -1]).message
    assert "simple knot only" in ch27.check_continuity_orders([3, 3, 3, 3]).message
    assert "at u = 3 is not right" in ch27.check_continuity_orders([3, 2, 0, 0]).message
    assert "each of the 4 interior knots" in ch27.check_continuity_orders([3, 2, 1]).message


def test_spline_control_points_slips():
    assert "values of the spline" in ch27.check_spline_control_points([0, 0.75, 0.5, -1]).message
    assert "second piece" in ch27.check_spline_control_points([0, 1, 1, -3]).message
    assert "P2 is much too large" in ch27.check_spline_control_points([0, 1, 2, -1]).message
    assert "has 4 control points" in ch27.check_spline_control_points([0, 1, -1]).message


def test_surface_point_slips():
    assert "u knots along j" in ch27.check_surface_point([1, 1.5, 2.5]).message
    assert "row 1 alone" in ch27.check_surface_point([1, 1, 3]).message
    assert "row 2 alone" in ch27.check_surface_point([2, 1, 2.5]).message
    assert "height is too large" in ch27.check_surface_point([1.5, 1, 3]).message
    assert "one point" in ch27.check_surface_point([1.5, 1]).message


def test_nurbs_point_slips():
    assert ch27.check_nurbs_point([3.154, 1.077]).correct                 # 3 decimals are enough
    assert "polynomial B-spline" in ch27.check_nurbs_point([3, 1.5]).message
    assert "forgot to divide" in ch27.check_nurbs_point([5.125, 1.75]).message
    assert "sum of the weights" in ch27.check_nurbs_point([5.125 / 7, 1.75 / 7]).message
    assert "divided by the weights" in ch27.check_nurbs_point([2.9459, 1.7838]).message
    assert "off from C(1.5)" in ch27.check_nurbs_point([3, 1]).message


def test_slips_are_all_recognised_as_wrong():
    for name, slips in ch27.SLIPS.items():
        for slip in slips:
            r = getattr(ch27, name)(slip)
            assert r.answered and not r.correct, (name, slip, r)


# -- Exercise 7 (§27.5), worked by hand: knots 0,0,0,1,2,4,5,5,5, p = 2, node (r, i) = (1, 3):
#    label (u, t_4) = (u, 2); spans k = 3, 4; interval [t_3, t_5] = [1, 4]
def test_pyramid_node_interval_by_hand_and_its_slips():
    assert ch27.PYRAMID_KNOTS.tolist() == [0, 0, 0, 1, 2, 4, 5, 5, 5] and ch27.PYRAMID_DEGREE == 2
    assert ch27.PYRAMID_NODE == (1, 3)
    assert ch27.check_pyramid_node_interval([1, 4]).correct
    assert "support of the basis function" in ch27.check_pyramid_node_interval([1, 5]).message
    assert "single knot span" in ch27.check_pyramid_node_interval([1, 2]).message
    assert "wrong knot" in ch27.check_pyramid_node_interval([0, 2]).message
    assert not ch27.check_pyramid_node_interval([0, 1]).correct


# -- dealt instances (issue 17 §3): the library's answer of every dealt instance agrees with scipy ----

SEEDS = range(1, 41)


def _dealt(name, seed):
    return ch27.DECK.exercises[name].instance(seed), ch27.DECK.exercises[name].answer


def test_dealt_de_boor_and_basis_agree_with_scipy():
    for seed in SEEDS:
        p, answer = _dealt("check_local_de_boor", seed)
        assert np.allclose(answer(p), BSpline(p["knots"], np.array(p["ctrl"]), 2)(p["u"]), atol=1e-12)
        p, answer = _dealt("check_basis_values", seed)
        assert np.allclose(answer(p), BSpline.design_matrix([p["u"]], p["knots"], 2).toarray()[0, 1:4], atol=1e-12)


def test_dealt_continuity_orders_are_degree_minus_multiplicity():
    for seed in SEEDS:
        p, answer = _dealt("check_continuity_orders", seed)
        assert list(answer(p)) == [p["degree"] - list(p["knots"]).count(x) for x in p["at"]]


def test_dealt_spline_control_points_reproduce_the_pieces():
    for seed in SEEDS:
        p, answer = _dealt("check_spline_control_points", seed)
        (c0, c1), (a, b, e) = p["pieces"], p["breaks"]
        spline = BSpline([a, a, a, b, e, e, e], np.asarray(answer(p)), 2)
        u = np.linspace(a, e, 17)
        pieces = np.where(u <= b, np.polyval(c0[::-1], u), np.polyval(c1[::-1], u))
        assert np.allclose(spline(u), pieces, atol=1e-12)


def test_dealt_surface_and_nurbs_points_agree_with_scipy():
    for seed in SEEDS:
        p, answer = _dealt("check_surface_point", seed)
        u, v = p["uv"]
        Nu = BSpline.design_matrix([u], ch27.SURF_KNOTS_U, 1).toarray()[0]
        Nv = BSpline.design_matrix([v], ch27.SURF_KNOTS_V, 2).toarray()[0]
        assert np.allclose(answer(p), [Nu @ [0, 1, 2], Nv @ [0, 1, 2], Nu @ np.array(p["heights"]) @ Nv])
        p, answer = _dealt("check_nurbs_point", seed)
        w, P = np.array(p["weights"]), np.array(p["ctrl"])
        hom = BSpline(ch27.NURBS_KNOTS, np.column_stack([w[:, None] * P, w]), 2)(p["u"])
        assert np.allclose(answer(p), hom[:2] / hom[2], atol=1e-12)


def test_dealt_pyramid_interval_is_t_i_to_t_i_plus_p_plus_1_minus_r():
    for seed in SEEDS:
        p, answer = _dealt("check_pyramid_node_interval", seed)
        (r, i), deg, t = p["node"], p["degree"], p["knots"]
        assert list(answer(p)) == [t[i], t[i + deg + 1 - r]]


def test_dealt_steps_print_and_the_stored_instance_comes_back():
    for name in ch27.DECK.exercises:
        ch27.deal(name, seed=3)
        assert "seed 3" in repr(ch27.steps(name))
        ch27.deal(name, seed=0)
    assert ch27.check_local_de_boor(DE_BOOR).correct
