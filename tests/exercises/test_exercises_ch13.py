"""Tests of the chapter-13 exercise checkers and of the programming-project checker.  Right answers
are worked by hand from the problem constants (so a bug in goldman_lib.transforms cannot make a
checker accept a wrong answer)."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch13

# 90 degrees about y: rows are the images of e1, e2, e3: w × e1 = (0, 0, -1), e2, w × e3 = (1, 0, 0)
BLOCK = [[0, 0, -1], [0, 1, 0], [1, 0, 0]]
# Q - Q L with Q = (1, 0, 2): Q L = 1 (0, 0, -1) + 2 (1, 0, 0) = (2, 0, -1)
ROW = [-1, 0, 3]
# n = (1, 1, 0)/√2: I - 2 nᵀn swaps x and y with a minus sign; 2 (Q·n) n = 2 (2/√2)(1, 1, 0)/√2 = (2, 2, 0)
MIRROR = [[0, -1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [2, 2, 0, 1]]
# T R: block of R (x -> y, y -> -x), last row (1, 2, 0) R = (0, 1, 0) + 2 (-1, 0, 0) = (-2, 1, 0)
COMPOSITE = [[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [-2, 1, 0, 1]]
# the line from (0, 0, 5) through (2, 4, 3) meets z = 0 at t = 5/2: (5, 10, 0)
PERSPECTIVE = [5, 10, 0]
# (1, 2, 3) L = (0, 1, 0) + 2 (-1, 0, 0) + 3 (0, 0, 1) = (-2, 1, 3); the point adds (2, -1, 3)
POINT_AND_VECTOR = [[0, 0, 6], [-2, 1, 3]]
# the frame: V = rows P_i - P0 = (1, 0, 0), (0, 1, 1), (0, 0, 1); W = rows Q_i - Q0 = (0, 1, 0), (-2, 0, 1), (0, 0, 2).
# V L = W: row 1 of L = (0, 1, 0); row 2 + row 3 = (-2, 0, 1) with row 3 = (0, 0, 2), so row 2 = (-2, 0, -1).
# t = Q0 - P0 L = (2, 0, 1) - [(0, 1, 0) + (-2, 0, -1)] = (4, -1, 2)
FRAME = [[0, 1, 0, 0], [-2, 0, -1, 0], [0, 0, 2, 0], [4, -1, 2, 1]]
# R: 90° about x through (0, 1, 1), block rows (1, 0, 0), (0, 0, 1), (0, -1, 0), row t = Q - Q R = (0, 2, 0);
# R⁻¹: block Rᵀ, row -t Rᵀ = (0, 0, 2); S⁻¹ R⁻¹ halves the block rows and keeps the last row
INVERSE = [[0.5, 0, 0, 0], [0, 0, -0.5, 0], [0, 0.5, 0, 0], [0, 0, 2, 1]]

CHECKERS = [
    (ch13.check_rotation_block, BLOCK),
    (ch13.check_translation_row, ROW),
    (ch13.check_mirror_matrix, MIRROR),
    (ch13.check_composite_matrix, COMPOSITE),
    (ch13.check_perspective_image, PERSPECTIVE),
    (ch13.check_point_and_vector, POINT_AND_VECTOR),
    (ch13.check_frame_matrix, FRAME),
    (ch13.check_inverse_matrix, INVERSE),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch13.ROT_AXIS.tolist() == [0, 1, 0] and ch13.ROT_ANGLE == 90 and ch13.ROT_POINT.tolist() == [1, 0, 2]
    assert ch13.MIRROR_PLANE_POINT.tolist() == [2, 0, 0] and ch13.MIRROR_NORMAL.tolist() == [1, 1, 0]
    assert ch13.COMPOSE_SHIFT.tolist() == [1, 2, 0] and ch13.COMPOSE_ANGLE == 90
    assert (ch13.PERSP_EYE.tolist(), ch13.PERSP_PLANE_POINT.tolist(), ch13.PERSP_NORMAL.tolist(),
            ch13.PERSP_POINT.tolist()) == ([0, 0, 5], [0, 0, 0], [0, 0, 1], [2, 4, 3])
    assert ch13.AFFINE_COORDS.tolist() == [1, 2, 3]
    # the printed perspective matrix: c = (Q - E)·N = -5; c I + NᵀE; N; -(Q·N) E = 0; -E·N = -5
    assert "[[-5, 0, 0, 0], [0, -5, 0, 0], [0, 0, 0, 1], [0, 0, 0, -5]]" in ch13.PROBLEMS["check_perspective_image"]


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_rotation_slips():
    assert "column convention" in ch13.check_rotation_block(np.array(BLOCK).T.tolist()).message
    assert "another coordinate axis" in ch13.check_rotation_block([[1, 0, 0], [0, 0, 1], [0, -1, 0]]).message
    m = lambda a: ch13.check_translation_row(a).message  # noqa: E731
    assert "sign is wrong" in m([1, 0, -3])
    assert "through the origin" in m([0, 0, 0])
    assert "not ±Q" in m([1, 0, 2]) and "not ±Q" in m([-1, 0, -2])
    assert "transposed block" in m([3, 0, 1])


def test_mirror_slips():
    m = lambda a: ch13.check_mirror_matrix(a).message  # noqa: E731
    assert "column convention" in m(np.array(MIRROR).T.tolist())
    assert "orthogonal projection" in m([[0.5, -0.5, 0, 0], [-0.5, 0.5, 0, 0], [0, 0, 1, 0], [1, 1, 0, 1]])
    assert "length √2" in m([[-1, -2, 0, 0], [-2, -1, 0, 0], [0, 0, 1, 0], [4, 4, 0, 1]])
    assert "wrong sign" in m([[0, -1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [-2, -2, 0, 1]])
    assert "through the origin" in m([[0, -1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def test_composition_slips():
    m = lambda a: ch13.check_composite_matrix(a).message  # noqa: E731
    assert "first rotate, then translate" in m([[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [1, 2, 0, 1]])
    assert "column convention" in m(np.array(COMPOSITE).T.tolist())
    assert "clockwise" in m([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [2, -1, 0, 1]])


def test_perspective_and_vector_slips():
    m = lambda a: ch13.check_perspective_image(a).message  # noqa: E731
    assert "dividing them by the fourth" in m([-10, -20, 0])
    assert "by w itself" in m([-5, -10, 0])
    assert "transpose" in m([2, 4, -0.2])
    v = lambda a: ch13.check_point_and_vector(a).message  # noqa: E731
    assert "vector was translated" in v([[0, 0, 6], [0, 0, 6]])
    assert "point was not translated" in v([[-2, 1, 3], [-2, 1, 3]])
    assert "swapped" in v([[-2, 1, 3], [0, 0, 6]])
    assert "block L still acts" in v([[0, 0, 6], [1, 2, 3]])
    assert "column convention" in v([[4, -2, 6], [2, -1, 3]])


def test_frame_matrix_by_lstsq_and_slips():
    P, Q = ch13.FRAME_SOURCES, ch13.FRAME_IMAGES
    H = np.c_[P, np.ones(4)]
    X = np.linalg.lstsq(H, np.c_[Q, np.ones(4)], rcond=None)[0]      # an independent reference
    assert np.allclose(X, FRAME)
    m = lambda a: ch13.check_frame_matrix(a).message  # noqa: E731
    assert "column convention" in m(np.array(FRAME).T.tolist())
    inverse = np.linalg.lstsq(np.c_[Q, np.ones(4)], H, rcond=None)[0]
    assert "inverse of the map" in m(inverse.tolist())
    row = [r[:] for r in FRAME]
    row[3] = [2, 0, 1, 1]
    assert "not Q0" in m(row)
    row[3] = [1, -1, 1, 1]
    assert "before L acts" in m(row)
    assert "as if P_i - P0 were the unit vectors" in m([[0, 1, 0, 0], [-2, 0, 1, 0], [0, 0, 2, 0], [4, -1, 0, 1]])


def test_inverse_matrix_against_numpy_and_slips():
    M = np.linalg.inv(INVERSE)                                         # M = R S, by numpy
    R = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 2, 0, 1]])
    assert np.allclose(M, R @ np.diag([2, 2, 2, 1]))
    m = lambda a: ch13.check_inverse_matrix(a).message  # noqa: E731
    same_order = np.linalg.inv(R) @ np.diag([0.5, 0.5, 0.5, 1])
    assert "same order" in m(same_order.tolist())
    assert "transpose of M" in m(M.T.tolist())
    negated = np.array(INVERSE, float)
    negated[3, :3] = -M[3, :3]
    assert "not just -t" in m(negated.tolist())


def test_dealt_instances_are_checked_on_their_own_numbers():
    try:
        ch13.deal("check_frame_matrix", seed=5)
        _, p = ch13.current("check_frame_matrix")
        P, Q = np.array(p["P"]), np.array(p["Q"])
        X = np.linalg.lstsq(np.c_[P, np.ones(4)], np.c_[Q, np.ones(4)], rcond=None)[0]
        assert ch13.check_frame_matrix(X.tolist()).correct
        assert not ch13.check_frame_matrix(FRAME).correct or np.allclose(X, FRAME)
        assert np.linalg.cond(P[1:] - P[0]) <= ch13.FRAME_MAX_CONDITION
        ch13.deal("check_inverse_matrix", seed=9)
        _, p = ch13.current("check_inverse_matrix")
        R = ch13.transforms.rotation(p["axis"], p["angle"], point=p["Q"])
        M = R @ np.diag([p["s"], p["s"], p["s"], 1.0])
        assert ch13.check_inverse_matrix(np.linalg.inv(M).tolist()).correct
    finally:
        ch13.DECK.reset()


# -- the programming project (its corpus of right and wrong solutions: tests/exercises/projects/test_ch13_project.py) --

def test_project_reports_a_crash_with_the_learners_line():
    def broken(sources, images):
        M = np.zeros((4, 4))
        M[:3, 3] = np.append(sources[0], 1.0)
        return M

    r = ch13.check_projective_map_project(broken)
    assert not r.correct and "your function raised ValueError" in r.message
    assert "M[:3, 3] = np.append(sources[0], 1.0)" in r.message


def test_project_unanswered_and_wrong_shape():
    def starter(sources, images):
        """Return the matrix."""
        ...

    assert not ch13.check_projective_map_project(starter).answered
    r = ch13.check_projective_map_project(lambda p, q: np.eye(3))
    assert not r.correct and "a 4x4 matrix is expected" in r.message
