"""Tests of the chapter-25 exercise checkers and of its programming-project checker.  Right answers
are worked by hand from the problem constants (so a bug in goldman_lib.bezier cannot make a checker
accept a wrong answer), and each recognised slip gets its own message."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch25

# -- hand-worked answers ---------------------------------------------------------------------------
# (0,4),(4,8),(8,0),(12,4) at t = 3/4 (each step 1/4 P_j + 3/4 P_j+1):
#   level 1 (3,7),(7,2),(11,3); level 2 (6,3.25),(10,2.75); level 3 (9,2.875)
LEFT = [[0, 4], [3, 7], [6, 3.25], [9, 2.875]]
RIGHT = [[9, 2.875], [10, 2.75], [11, 3], [12, 4]]
# C(0.7) on the right piece of a split at 0.4: s = (0.7 - 0.4) / 0.6
PIECE_S = 0.5
# chord points L1 = (2,0), L2 = (4,0): |(1,1)| = sqrt 2, |(-1,-2)| = sqrt 5
FLAT = 5 ** 0.5
# rows (quadratics in v) split at 1/2: row 0 (0,0,0),(0,2,4),(0,4,0) -> (0,0,0),(0,1,2),(0,2,2)
#                                      row 1 (4,0,0),(4,2,2),(4,4,2) -> (4,0,0),(4,1,1),(4,2,1.5)
PATCH = [[[0, 0, 0], [0, 1, 2], [0, 2, 2]], [[4, 0, 0], [4, 1, 1], [4, 2, 1.5]]]
# parabola halves: (0,0),(1,2),(2,2) box [0,2]x[0,2]; (2,2),(3,2),(4,0) box [2,4]x[0,2]
# segment halves: x in [0.5,2.5] and [2.5,4.5], y = 1.5: all pairs but (left parabola, right segment)
BOXES = 3
# y - 0.5 along the quartic: -0.5, 2.5, -1.5, 0.5, 1.5: three sign changes
CROSS = 3
# continuation of (0,0),(2,2),(4,2),(6,0): Q1 = 2P3 - P2 = (8,-2), Q2 = P1 - 4P2 + 4P3 = (10,-6),
# Q3 = -P0 + 6P1 - 12P2 + 8P3 = (12,-12); R = (6,0),(8,-2),(10,-6),(11,-8): C2, not C3
ORDER = 2

CHECKERS = [
    (ch25.check_subdivision_right, RIGHT),
    (ch25.check_piece_parameter, PIECE_S),
    (ch25.check_flatness, FLAT),
    (ch25.check_patch_split, PATCH),
    (ch25.check_box_pairs, BOXES),
    (ch25.check_crossing_bound, CROSS),
    (ch25.check_join_order, ORDER),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch25.SUBDIVIDE_CTRL.tolist() == [[0, 4], [4, 8], [8, 0], [12, 4]] and ch25.SUBDIVIDE_T == 0.75
    assert (ch25.PIECE_SPLIT_T, ch25.PIECE_T) == (0.4, 0.7)
    assert ch25.FLATNESS_CTRL.tolist() == [[0, 0], [3, 1], [3, -2], [6, 0]]
    assert ch25.PATCH_NET.tolist() == [[[0, 0, 0], [0, 2, 4], [0, 4, 0]], [[4, 0, 0], [4, 2, 2], [4, 4, 2]]]
    assert ch25.PATCH_V == 0.5
    assert ch25.BOX_A.tolist() == [[0, 0], [2, 4], [4, 0]] and ch25.BOX_B.tolist() == [[0.5, 1.5], [4.5, 1.5]]
    assert ch25.CROSSING_CTRL.tolist() == [[0, 0], [1, 3], [2, -1], [3, 1], [4, 2]] and ch25.CROSSING_LINE_Y == 0.5
    assert ch25.ORDER_P.tolist() == [[0, 0], [2, 2], [4, 2], [6, 0]]
    assert ch25.ORDER_R.tolist() == [[6, 0], [8, -2], [10, -6], [11, -8]]


def test_no_join_construction_drill_repeats_chapter_24():
    assert not any("C1" in name or "c2" in name for name in ch25.PROBLEMS)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r
    assert "Correct" in repr(r) and "Correct" in r._repr_html_()


def test_hand_decimals_are_accepted():
    assert ch25.check_flatness(2.2361).correct
    assert not ch25.check_flatness(2.25).correct


@pytest.mark.parametrize("answer,reason", [
    (RIGHT[::-1], "reverse order"),
    (LEFT, "that is the left piece"),
    ([[3, 7], [7, 2], [11, 3], [12, 4]], "level 1 of the pyramid"),
    ([[9, 2.875], [10, 2.75], [11, 3]], "four points"),
    ([[9, 2.875], [10, 2.75], [11, 3.5], [12, 4]], "point 2"),
])
def test_subdivision_wrong_answers_say_why(answer, reason):
    r = ch25.check_subdivision_right(answer)
    assert not r.correct and reason in r.message, r


def test_the_split_at_one_minus_t_is_what_the_slip_assumes():
    # (0,4),(4,8),(8,0),(12,4) at 1/4: level 1 (1,5),(5,6),(9,1); level 2 (2,5.25),(6,4.75); level 3 (3,5.125)
    r = ch25.check_subdivision_right([[3, 5.125], [6, 4.75], [9, 1], [12, 4]])
    assert "split at t = 0.25" in r.message


@pytest.mark.parametrize("answer,reason", [
    (0.3, "did not rescale"), (0.75, "LEFT piece's interval"), (0.82, "solve t = t0"),
    (1.75, "parameter of the LEFT piece"), (0.6, "too large"),
])
def test_piece_parameter_wrong_answers_say_why(answer, reason):
    r = ch25.check_piece_parameter(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [
    (2.0, "chord LINE"), (2 ** 0.5, "SMALLER"), (2 ** 0.5 + 5 ** 0.5, "added the distances"), (1.0, "much too small"),
])
def test_flatness_wrong_answers_say_why(answer, reason):
    r = ch25.check_flatness(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [
    ([[[0, 2, 2], [0, 3, 2], [0, 4, 0]], [[4, 2, 1.5], [4, 3, 2], [4, 4, 2]]], "other piece"),
    ([[[0, 0, 0], [0, 2, 4], [0, 4, 0]], [[2, 0, 0], [2, 2, 3], [2, 4, 1]]], "split in u"),
    ([[[0, 2, 2], [0, 1, 2], [0, 0, 0]], [[4, 2, 1.5], [4, 1, 1], [4, 0, 0]]], "reverse order"),
    ([[0, 0, 0], [0, 1, 2], [0, 2, 2]], "shape (2, 3, 3)"),
    ([[[0, 0, 0], [0, 1, 2], [0, 2, 2]], [[4, 0, 0], [4, 1, 1], [4, 2, 2]]], "point [1][2]"),
])
def test_patch_split_wrong_answers_say_why(answer, reason):
    r = ch25.check_patch_split(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(4, "not every pair"), (2, "intersections of the curves"),
                                           (7, "between 0 and 4"), (1, "test the 4 pairs")])
def test_box_pairs_wrong_answers_say_why(answer, reason):
    r = ch25.check_box_pairs(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(5, "number of control points"), (4, "is the degree"),
                                           (1, "curve itself crosses"), (2, "too small")])
def test_crossing_wrong_answers_say_why(answer, reason):
    r = ch25.check_crossing_bound(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(3, "compare R3"), (1, "compare R2"), (0, "do meet"),
                                           (-1, "do meet"), (5, "between 0 and the degree")])
def test_join_order_wrong_answers_say_why(answer, reason):
    r = ch25.check_join_order(answer)
    assert not r.correct and reason in r.message, r


def test_every_checker_has_a_problem_statement_and_slips():
    assert set(ch25.PROBLEMS) == {c.__name__ for c, _ in CHECKERS} == set(ch25.SLIPS)
    assert all("Goldman §25." in text for text in ch25.PROBLEMS.values())
    np.testing.assert_allclose(LEFT[-1], RIGHT[0])


# -- the programming project ------------------------------------------------------------------------

def subdivide_by_hand(ctrl, t):
    """A learner's correct solution: keep the first and last point of every level of the pyramid."""
    level = [np.asarray(p, dtype=float) for p in ctrl]
    left, right = [level[0]], [level[-1]]
    while len(level) > 1:
        level = [(1 - t) * a + t * b for a, b in zip(level, level[1:])]
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right[::-1])


def test_project_accepts_a_correct_function_and_names_the_degenerate_kinds():
    r = ch25.check_subdivision_project(subdivide_by_hand)
    assert r.correct, r
    for kind in ("all control points equal", "t = 0", "t = 1", "collinear points", "random 2D", "random 3D"):
        assert kind in r.message


def test_project_cases_cover_degrees_one_to_five_in_two_and_three_dimensions():
    cases = ch25.subdivision_project_cases()
    shapes = {(len(c.args[0]) - 1, c.args[0].shape[1]) for c in cases}
    assert {(n, d) for n in range(1, 6) for d in (2, 3)} <= shapes
    assert {c.args[1] for c in cases} >= {0.0, 1.0}
    assert [c.label for c in cases] == [c.label for c in ch25.subdivision_project_cases()]  # a fixed seed


def test_project_names_a_reversed_right_polygon_and_the_failing_case():
    def reversed_right(ctrl, t):
        left, right = subdivide_by_hand(ctrl, t)
        return left, right[::-1]

    r = ch25.check_subdivision_project(reversed_right)
    assert not r.correct and r.answered
    assert r.message.startswith("case 1 of 15 (the 2D segment")
    assert "right polygon is in reverse order" in r.message


def test_project_names_t_and_one_minus_t_exchanged():
    r = ch25.check_subdivision_project(lambda ctrl, t: subdivide_by_hand(ctrl, 1 - t))
    assert not r.correct and "split at 1 - t" in r.message and "case 1 of 15" in r.message


def test_project_names_the_first_point_that_is_off():
    def one_level_short(ctrl, t):
        left, right = subdivide_by_hand(ctrl, t)
        left = left.copy()
        left[-1] = left[-2]   # forgot the apex on the left
        return left, right

    r = ch25.check_subdivision_project(one_level_short)
    assert not r.correct
    assert "your left polygon's point 1 is" in r.message and "from where it should be" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    def crashing(ctrl, t):
        n = len(ctrl)
        return ctrl[n], ctrl

    r = ch25.check_subdivision_project(crashing)
    assert not r.correct and r.answered
    assert "raised IndexError" in r.message and "`return ctrl[n], ctrl`" in r.message


def test_project_wrong_shapes_and_unanswered():
    r = ch25.check_subdivision_project(lambda ctrl, t: (ctrl, ctrl[:-1]))
    assert "right polygon has shape" in r.message
    r = ch25.check_subdivision_project(lambda ctrl, t: subdivide_by_hand(ctrl, t)[0])
    assert "two control polygons, (left, right), each" in r.message
    assert ch25.check_subdivision_project(lambda ctrl, t: np.stack(subdivide_by_hand(ctrl, t))).correct

    def starter(ctrl, t):
        """Not written yet."""
        ...

    assert not ch25.check_subdivision_project(starter).answered
    assert not ch25.check_subdivision_project(None).answered
