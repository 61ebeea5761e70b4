"""Tests of the chapter-28 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.knot_insertion cannot make a checker accept a wrong answer)."""

import pytest

from goldman_lib.exercises import Result, ch28

# Quadratic, P = (0,0),(2,4),(4,4),(6,0), knots 0,0,0,1,2,2,2; labels P0=b(0,0), P1=b(0,1), P2=b(1,2), P3=b(2,2).
# Boehm, u = 0.5 in [t2, t3) = [0, 1): a1 = (0.5-0)/(1-0) = 1/2, a2 = (0.5-0)/(2-0) = 1/4
# Q1 = P0/2 + P1/2 = (1, 2); Q2 = 3/4 P1 + 1/4 P2 = (2.5, 4)
BOEHM = [[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]]
# Oslo, new knots 0,0,0,.5,1,1.5,2,2,2: b(0,0), b(0,.5), b(.5,1), b(1,1.5), b(1.5,2), b(2,2)
# b(0,.5) = (P0+P1)/2 = (1,2); b(.5,1) = 3/4 P1 + 1/4 P2 = (2.5,4); b(1,1.5) = 1/4 P1 + 3/4 P2 = (3.5,4);
# b(1.5,2) = (P2+P3)/2 = (5,2)
OSLO = [[0, 0], [1, 2], [2.5, 4], [3.5, 4], [5, 2], [6, 0]]
# pieces: [b(0,0), b(0,1), b(1,1)] and [b(1,1), b(1,2), b(2,2)], b(1,1) = (P1+P2)/2 = (3,4)
PIECES = [[[0, 0], [2, 4], [3, 4]], [[3, 4], [4, 4], [6, 0]]]
# Chaikin on the open polygon (0,0),(4,0),(4,4),(0,4): 1/4 and 3/4 of each leg
CHAIKIN = [[1, 0], [3, 0], [4, 1], [4, 3], [3, 4], [1, 4]]
FACTOR = 4
# y - 1 along (0,0),(1,3),(2,-1),(3,3),(4,-1),(5,0): -, +, -, +, -, -  -> 4 sign changes
CROSSINGS = 4

CHECKERS = [
    (ch28.check_boehm_insert, BOEHM),
    (ch28.check_oslo, OSLO),
    (ch28.check_bezier_pieces, PIECES),
    (ch28.check_chaikin, CHAIKIN),
    (ch28.check_convergence_factor, FACTOR),
    (ch28.check_crossing_bound, CROSSINGS),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch28.QUAD_CTRL.tolist() == [[0, 0], [2, 4], [4, 4], [6, 0]]
    assert ch28.QUAD_KNOTS.tolist() == [0, 0, 0, 1, 2, 2, 2] and ch28.QUAD_DEGREE == 2 and ch28.BOEHM_U == 0.5
    assert ch28.OSLO_NEW_KNOTS.tolist() == [0, 0, 0, 0.5, 1, 1.5, 2, 2, 2]
    assert ch28.CHAIKIN_CTRL.tolist() == [[0, 0], [4, 0], [4, 4], [0, 4]]
    assert ch28.CROSSING_CTRL.tolist() == [[0, 0], [1, 3], [2, -1], [3, 3], [4, -1], [5, 0]]
    assert ch28.CROSSING_LINE_Y == 1.0


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_boehm_messages():
    assert "weights are swapped" in ch28.check_boehm_insert([[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]]).message
    assert "old polygon" in ch28.check_boehm_insert(ch28.QUAD_CTRL.tolist()).message
    assert "should be 5 points" in ch28.check_boehm_insert([[0, 0], [1, 2], [6, 0]]).message
    r = ch28.check_boehm_insert([[0, 0], [1, 2], [2.5, 3.5], [4, 4], [6, 0]])
    assert not r and "point 2" in r.message


def test_oslo_messages():
    assert "inserting 0.5 alone" in ch28.check_oslo(BOEHM).message
    # 1.5 alone: in [1, 2): a2 = (1.5-0)/(2-0) = 3/4, a3 = (1.5-1)/(2-1) = 1/2
    assert "inserting 1.5 alone" in ch28.check_oslo([[0, 0], [2, 4], [3.5, 4], [5, 2], [6, 0]]).message
    r = ch28.check_oslo([[0, 0], [1, 2], [3, 4], [3, 4], [5, 2], [6, 0]])
    assert not r and "point 2" in r.message and "blossom" in r.message


def test_bezier_pieces_messages():
    r = ch28.check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]])
    assert "meet at the curve point C(1)" in r.message
    assert "shape (2, 3, 2)" in ch28.check_bezier_pieces([[0, 0], [2, 4], [3, 4], [4, 4], [6, 0]]).message
    r = ch28.check_bezier_pieces([[[0, 0], [2, 3], [3, 4]], [[3, 4], [4, 4], [6, 0]]])
    assert not r and "point 1" in r.message


def test_chaikin_messages():
    midpoints = [[0, 0], [2, 0], [4, 0], [4, 2], [4, 4], [2, 4], [0, 4]]
    assert "one averaging round" in ch28.check_chaikin(midpoints).message
    closed = CHAIKIN + [[0, 3], [0, 1]]
    assert "closed" in ch28.check_chaikin(closed).message
    doubled = [[0, 0], [0, 0], [4, 0], [4, 0], [4, 4], [4, 4], [0, 4], [0, 4]]
    assert "doubled polygon only" in ch28.check_chaikin(doubled).message


def test_convergence_messages():
    assert "knot spacing" in ch28.check_convergence_factor(2).message
    assert "inverse" in ch28.check_convergence_factor(0.25).message
    assert "about 4" in ch28.check_convergence_factor(8).message


def test_crossing_messages():
    assert "number of legs" in ch28.check_crossing_bound(5).message
    assert "too small" in ch28.check_crossing_bound(2).message
    assert "more than the bound" in ch28.check_crossing_bound(6).message
