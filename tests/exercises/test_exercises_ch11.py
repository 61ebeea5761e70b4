"""Tests of the chapter-11 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.vector_geometry cannot make a checker accept a wrong answer)."""

import math

import pytest

from goldman_lib.exercises import Result, ch11

# 1. c² = 25 + 64 - 2*5*8*cos 60° = 89 - 40 = 49, c = 7
LAW = 7.0
# 2. Q - P = (1, 3, -4); (Q - P)·N = 2 - 3 - 8 = -9; |N| = sqrt(4 + 1 + 4) = 3; signed -3, distance 3
PLANE = 3.0
# 3. d1 × d2 = (1, 1, 0) × (1, 0, 1) = (1, -1, -1), |.| = sqrt 3; p2 - p1 = (-1, 2, 3); dot = -1 - 2 - 3 = -6
#    distance 6 / sqrt 3 = 2 sqrt 3
LINES = 2 * math.sqrt(3)
# 4. the xy-shadow is an L: 3x2 + 1x2 = 8; the plane z = x + y has unit normal (1, 1, -1)/sqrt 3, and the
#    shadow's area is the area times |n_z| = 1/sqrt 3, so area = 8 sqrt 3 (|N| = 16 sqrt 3)
AREA = 8 * math.sqrt(3)
# 4b. edges from P0 = (1,0,1): (2,1,0), (0,4,1), (1,1,4); det = 2(16 - 1) - 1(0 - 1) + 0 = 31; volume 31/6
VOLUME = 31 / 6
# 5. (1, 2, 3): 1 + 2 + 3 = 6; 1 - 2 + 6 = 5; 2 + 2 - 3 = 1; det = 7
POINT = [1, 2, 3]
# 6. the ray y = 3 from (3, 3) to the right crosses (5,1)-(5,5) going up and (6,0)-(6,6) going up: +1 +1
WINDING = 2
# 7. θ = 90°: sin(60°)/1 v0 + sin(30°)/1 v1 = (sqrt3/2, 1/(2 sqrt 2), 1/(2 sqrt 2))
SLERP = [math.sqrt(3) / 2, 1 / (2 * math.sqrt(2)), 1 / (2 * math.sqrt(2))]

CHECKERS = [
    (ch11.check_law_of_cosines, LAW),
    (ch11.check_point_plane_distance, PLANE),
    (ch11.check_line_line_distance, LINES),
    (ch11.check_newell_area, AREA),
    (ch11.check_tetrahedron_volume, VOLUME),
    (ch11.check_three_planes, POINT),
    (ch11.check_winding_number, WINDING),
    (ch11.check_slerp, SLERP),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch11.TRIANGLE == (5.0, 8.0, 60.0)
    assert ch11.QUERY_POINT.tolist() == [2, 3, -4] and ch11.PLANE_POINT.tolist() == [1, 0, 0]
    assert ch11.PLANE_NORMAL.tolist() == [2, -1, 2]
    assert [x.tolist() for x in ch11.LINE1] == [[1, 0, 0], [1, 1, 0]]
    assert [x.tolist() for x in ch11.LINE2] == [[0, 2, 3], [1, 0, 1]]
    assert ch11.POLYGON_3D.tolist() == [[0, 0, 0], [3, 0, 3], [3, 2, 5], [1, 2, 3], [1, 4, 5], [0, 4, 4]]
    assert ch11.TETRAHEDRON.tolist() == [[1, 0, 1], [3, 1, 1], [1, 4, 2], [2, 1, 5]]
    assert [(N.tolist(), c) for N, c in ch11.PLANES] == [([1, 1, 1], 6), ([1, -1, 2], 5), ([2, 1, -1], 1)]
    assert ch11.WINDING_POLYGON.tolist() == [[0, 0], [6, 0], [6, 6], [1, 6], [1, 1], [5, 1], [5, 5], [0, 5]]
    assert ch11.WINDING_QUERY.tolist() == [3, 3]
    assert ch11.SLERP_T == pytest.approx(1 / 3)


def test_every_checker_has_a_statement_citing_its_section_and_slips():
    assert set(ch11.PROBLEMS) == set(IDS) == set(ch11.SLIPS)
    for name, text in ch11.PROBLEMS.items():
        assert "§11." in text, name
        assert len(ch11.SLIPS[name]) >= 2, name


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_hand_precision_is_accepted(checker, answer):
    rounded = round(answer, 4) if isinstance(answer, float) else [round(x, 4) for x in answer] \
        if isinstance(answer, list) else answer
    assert checker(rounded).correct


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_unanswered_and_garbage(checker, answer):
    assert not checker(None).answered and not checker(...).answered
    for junk in ("abc", [1, "x"], float("nan"), {"a": 1}):
        r = checker(junk)
        assert isinstance(r, Result) and not r.correct and r.answered, (junk, r)


def test_law_of_cosines_slips():
    assert "wrong sign" in ch11.check_law_of_cosines(math.sqrt(89 + 40)).message
    assert "c², not c" in ch11.check_law_of_cosines(49).message
    assert "radians" in ch11.check_law_of_cosines(math.sqrt(89 - 80 * math.cos(60))).message
    assert "c is too large" in ch11.check_law_of_cosines(8).message


def test_point_plane_distance_slips():
    assert "signed distance" in ch11.check_point_plane_distance(-3).message
    assert "did not divide by |N|" in ch11.check_point_plane_distance(9).message
    assert "did not divide by |N|" in ch11.check_point_plane_distance(-9).message
    assert "|N|²" in ch11.check_point_plane_distance(1).message
    assert "to the point P" in ch11.check_point_plane_distance(math.sqrt(26)).message


def test_line_line_distance_slips():
    assert "did not normalise" in ch11.check_line_line_distance(6).message
    assert "|d1 × d2|²" in ch11.check_line_line_distance(2).message
    assert "|d1| |d2|" in ch11.check_line_line_distance(3).message        # 6 / (sqrt2 sqrt2)
    assert "two given points" in ch11.check_line_line_distance(math.sqrt(14)).message
    assert "not negative" in ch11.check_line_line_distance(-LINES).message


def test_newell_area_slips():
    assert "twice the area" in ch11.check_newell_area(16 * math.sqrt(3)).message
    assert "shadow on the xy-plane" in ch11.check_newell_area(8).message
    assert "added the three components" in ch11.check_newell_area(24).message   # (16 + 16 + 16) / 2


def test_tetrahedron_volume_slips():
    assert "parallelepiped" in ch11.check_tetrahedron_volume(31).message
    assert "halved" in ch11.check_tetrahedron_volume(15.5).message
    assert "pyramid" in ch11.check_tetrahedron_volume(31 / 3).message
    assert "not negative" in ch11.check_tetrahedron_volume(-31 / 6).message
    assert "volume is too large" in ch11.check_tetrahedron_volume(31 / 6 + 1).message


def test_three_planes_slips():
    assert "division by det" in ch11.check_three_planes([7, 14, 21]).message
    assert "sign is flipped" in ch11.check_three_planes([-1, -2, -3]).message
    # (4, 1, 1) = (1, 2, 3) + (3, -1, -2), along N1 × N2: on the first two planes (6, 5), not the third (8 != 1)
    m = ch11.check_three_planes([4, 1, 1]).message
    assert "two of the planes" in m and "the third" in m
    assert "should be one point" in ch11.check_three_planes([1, 2]).message


def test_winding_number_slips():
    assert "even-odd" in ch11.check_winding_number(0).message           # two crossings: even
    assert "sign is reversed" in ch11.check_winding_number(-2).message
    assert "how many times" in ch11.check_winding_number(1).message
    assert "inside/outside verdict" in ch11.check_winding_number(True).message
    assert "integer" in ch11.check_winding_number(2.5).message
    assert "much too large" in ch11.check_winding_number(3).message


def test_slerp_slips():
    lerp = [2 / 3, 1 / (3 * math.sqrt(2)), 1 / (3 * math.sqrt(2))]
    assert "linear interpolation (1 - t)" in ch11.check_slerp(lerp).message
    n = math.sqrt(sum(x * x for x in lerp))
    assert "normalised" in ch11.check_slerp([x / n for x in lerp]).message
    swapped = [0.5, math.sqrt(3) / (2 * math.sqrt(2)), math.sqrt(3) / (2 * math.sqrt(2))]
    assert "swapped" in ch11.check_slerp(swapped).message
    assert "not" in ch11.check_slerp([1, 1, 1]).message and "unit vector" in ch11.check_slerp([1, 1, 1]).message
