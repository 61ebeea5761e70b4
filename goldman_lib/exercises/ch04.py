"""Exercise checkers for chapter 4, affine transformations (Goldman §4.2-4.7).

Answers are points ``(x, y)``, vectors, or 3x3 matrices in the book's row-vector convention
(translation in the last row).  Each checker recognises the usual slips (rotating about the
origin, composing in the wrong order, writing the column-vector matrix, translating a vector)
and says which one it was.  ``None`` or ``...`` means "not answered yet".

>>> exercise_rotate_point((1, 3))
Correct: the image of P = (3, 1) is (1, 3).
>>> exercise_rotate_point((-1, 3))
Not yet: (-1, 3) is the rotation of P about the origin; rotate about Q = (1, 1): move Q to the origin, rotate, move back.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_points, unanswered, wrong

__all__ = ["PROBLEMS", "exercise_rotate_point", "exercise_compose_matrix", "exercise_three_points",
           "exercise_vector_image", "exercise_nonuniform_scaling"]

#: The problems, by checker name (the notebook states them in full).
PROBLEMS = {
    "exercise_rotate_point": "the image of P = (3, 1) under the rotation by 90 degrees about Q = (1, 1) (Goldman §4.2.2, §4.4)",
    "exercise_compose_matrix": "the 3x3 matrix of: translate by (2, -1), then scale by 2 about the origin (Goldman §4.3, §4.5)",
    "exercise_three_points": ("the 3x3 matrix of the affine map sending (0, 0), (1, 0), (0, 1) to (1, 1), (3, 2), (0, 3) "
                              "(Goldman §4.7.3)"),
    "exercise_vector_image": ("the image of the vector v = (1, 1) under: translate by (5, 2), then rotate by 90 degrees "
                              "(Goldman §4.5)"),
    "exercise_nonuniform_scaling": "the 3x3 matrix of the scaling by 3 along the direction (1, 1) about the origin (Goldman §4.7.2)",
}

_TOL = 1e-6


def _point(answer, what) -> tuple[np.ndarray | None, Result | None]:
    got, problem = read_points(answer, what)
    if problem is not None:
        return None, problem
    if got.shape != (2,):
        return None, wrong(f"{what} should be two numbers (x, y); you gave shape {got.shape}.")
    return got, None


def _close(a, b) -> bool:
    return bool(np.all(np.abs(np.asarray(a, float) - np.asarray(b, float)) <= _TOL))


def _slip(got, slips: dict, expected, what) -> Result:
    if _close(got, expected):
        return correct(f"{what} is {fmt(expected)}.")
    for why, value in slips.items():
        if _close(got, value):
            return wrong(f"{fmt(got)} {why}")
    return wrong(f"{what} should be {fmt(expected)}; you gave {fmt(got)}.")


def exercise_rotate_point(answer) -> Result:
    """Exercise 4.1: the image of ``P = (3, 1)`` under the rotation by 90 degrees about
    ``Q = (1, 1)`` (Goldman §4.2.2, §4.4).  answer: ``(x, y)``.

    >>> exercise_rotate_point((0, 2))
    Not yet: (0, 2) is P - Q rotated about the origin: after T(-Q) and R, translate back by Q.
    """
    what = "the image of P = (3, 1)"
    if is_unanswered(answer):
        return unanswered(f"{what} as a point (x, y)")
    got, problem = _point(answer, what)
    if problem is not None:
        return problem
    slips = {
        "is the rotation of P about the origin; rotate about Q = (1, 1): move Q to the origin, rotate, move back.":
            (-1, 3),
        "is the clockwise rotation; a positive angle turns counterclockwise.": (1, -1),
        "is P - Q rotated about the origin: after T(-Q) and R, translate back by Q.": (0, 2),
    }
    return _slip(got, slips, (1, 3), what)


def _matrix(answer, what) -> tuple[np.ndarray | None, Result | None]:
    got, problem = read_points(answer, what)
    if problem is not None:
        return None, problem
    if got.shape != (3, 3):
        return None, wrong(f"{what} should be a 3x3 matrix (three rows of three numbers); you gave shape {got.shape}.")
    return got, None


def _check_matrix(answer, expected, what, slips: dict) -> Result:
    if is_unanswered(answer):
        return unanswered(f"{what}, a 3x3 matrix as a list of three rows")
    got, problem = _matrix(answer, what)
    if problem is not None:
        return problem
    expected = np.asarray(expected, dtype=float)
    if _close(got, expected):
        return correct(f"{what} is {fmt(expected[0])}, {fmt(expected[1])}, {fmt(expected[2])} (rows).")
    if _close(got, expected.T):
        return wrong("that is the column-vector form (the transpose): in the book's convention points are row "
                     "vectors, Q = P M, so the translation goes in the last row and the last column is (0, 0, 1).")
    for why, value in slips.items():
        if _close(got, value):
            return wrong(why)
    if not _close(got[:, 2], [0, 0, 1]):
        return wrong(f"the last column of an affine matrix is (0, 0, 1); yours is {fmt(got[:, 2])}.")
    rows = ["first", "second", "third"]
    k = int(np.flatnonzero(np.abs(got - expected).max(axis=1) > _TOL)[0])
    part = "the translation (the image of the origin)" if k == 2 else f"the image of the vector e{k + 1}"
    return wrong(f"the {rows[k]} row, {part}, should be {fmt(expected[k])}; yours is {fmt(got[k])}.")


def exercise_compose_matrix(answer) -> Result:
    """Exercise 4.2: the matrix of "translate by (2, -1), then scale by 2 about the origin"
    (Goldman §4.3, §4.5).  answer: 3x3 rows.

    >>> exercise_compose_matrix([[2, 0, 0], [0, 2, 0], [4, -2, 1]])
    Correct: the composite matrix is (2, 0, 0), (0, 2, 0), (4, -2, 1) (rows).
    >>> exercise_compose_matrix([[2, 0, 0], [0, 2, 0], [2, -1, 1]])
    Not yet: that is "scale, then translate": with row vectors the map applied first is the left factor, T(2, -1) S(2), so the translation is scaled too: (4, -2).
    """
    T, S = affine.translation([2, -1]), affine.scaling(2)
    return _check_matrix(answer, T @ S, "the composite matrix", {
        'that is "scale, then translate": with row vectors the map applied first is the left factor, '
        "T(2, -1) S(2), so the translation is scaled too: (4, -2).": S @ T,
        "that is the translation alone; the scaling by 2 is missing.": T,
    })


def exercise_three_points(answer) -> Result:
    """Exercise 4.3: the matrix of the affine map sending ``(0, 0), (1, 0), (0, 1)`` to
    ``(1, 1), (3, 2), (0, 3)`` (Goldman §4.7.3).  answer: 3x3 rows.

    >>> exercise_three_points([[2, 1, 0], [-1, 2, 0], [1, 1, 1]])
    Correct: the matrix of the map is (2, 1, 0), (-1, 2, 0), (1, 1, 1) (rows).
    >>> exercise_three_points([[3, 2, 0], [0, 3, 0], [1, 1, 1]])
    Not yet: the rows of the linear part are the images of the vectors e1 = (1, 0) and e2 = (0, 1): Q2 - Q1 and Q3 - Q1, not the points Q2 and Q3.
    """
    src = [[0, 0], [1, 0], [0, 1]]
    dst = [[1, 1], [3, 2], [0, 3]]
    M = affine.affine_from_points(src, dst)
    naive = np.array([[3, 2, 0], [0, 3, 0], [1, 1, 1]], dtype=float)
    return _check_matrix(answer, M, "the matrix of the map", {
        "the rows of the linear part are the images of the vectors e1 = (1, 0) and e2 = (0, 1): Q2 - Q1 and "
        "Q3 - Q1, not the points Q2 and Q3.": naive,
        "the translation (last row) is the image of the origin, Q1 = (1, 1).": np.vstack([M[:2], [0, 0, 1]]),
    })


def exercise_vector_image(answer) -> Result:
    """Exercise 4.4: the image of the vector ``v = (1, 1)`` under "translate by (5, 2), then
    rotate by 90 degrees about the origin" (Goldman §4.5: vectors have affine coordinates
    ``(a, b, 0)``).  answer: ``(x, y)``.

    >>> exercise_vector_image((-1, 1))
    Correct: the image of v is (-1, 1).
    >>> exercise_vector_image((-3, 6))
    Not yet: (-3, 6) is what happens to the point (1, 1); a vector has last coordinate 0, so translations do not move it.
    """
    what = "the image of v"
    if is_unanswered(answer):
        return unanswered(f"{what} as a vector (x, y)")
    got, problem = _point(answer, what)
    if problem is not None:
        return problem
    slips = {
        "is what happens to the point (1, 1); a vector has last coordinate 0, so translations do not move it.":
            (-3, 6),
        "is v itself; the translation does not move a vector, but the rotation does turn it.": (1, 1),
        "is v rotated clockwise; positive angles turn counterclockwise.": (1, -1),
    }
    return _slip(got, slips, (-1, 1), what)


def exercise_nonuniform_scaling(answer) -> Result:
    """Exercise 4.5: the matrix of the scaling by 3 along the direction (1, 1) about the origin
    (Goldman §4.7.2): ``v -> v + (s - 1)(v . w) w`` with ``w`` the *unit* vector.  answer: 3x3 rows.

    >>> exercise_nonuniform_scaling([[2, 1, 0], [1, 2, 0], [0, 0, 1]])
    Correct: the scaling matrix is (2, 1, 0), (1, 2, 0), (0, 0, 1) (rows).
    >>> exercise_nonuniform_scaling([[3, 2, 0], [2, 3, 0], [0, 0, 1]])
    Not yet: the formula v + (s - 1)(v . w) w needs the unit vector w = (1, 1)/sqrt(2); with w = (1, 1) the scaling factor comes out 5, not 3.
    """
    M = affine.directional_scaling(3, [1, 1])
    return _check_matrix(answer, M, "the scaling matrix", {
        "the formula v + (s - 1)(v . w) w needs the unit vector w = (1, 1)/sqrt(2); with w = (1, 1) the scaling "
        "factor comes out 5, not 3.": [[3, 2, 0], [2, 3, 0], [0, 0, 1]],
        "that scales every direction by 3 (uniform scaling); only the direction (1, 1) should stretch, the "
        "perpendicular direction (1, -1) stays fixed.": affine.scaling(3),
        "that scales along the x-axis; the direction is (1, 1).": affine.scaling([3, 1]),
    })
