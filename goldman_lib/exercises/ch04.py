"""Exercise checkers for chapter 4, affine transformations (Goldman §4.2-4.7).

Answers are points ``[x, y]``, pairs of points, a table of yes/no answers, or 3x3 matrices in the
book's row-vector convention (``Q = P M``, translation in the last row, last column ``(0, 0, 1)``).
Each checker recognises the usual slips (rotating about the origin, composing in the wrong order,
the column-vector matrix, translating a vector, a direction that is not a unit vector, the images
of the points written as rows) and names the misconception; it says how far off an answer is, never
what the answer is.  Hand-computed decimals are accepted to about 1e-4 (relative).  ``None`` or
``...`` means "not answered yet".

>>> print(check_rotate_about_point([-2, 4]).message)
(-2, 4) is P rotated about the origin; rotate about Q: move Q to the origin (P - Q), rotate, then add Q back.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_points, unanswered, wrong

__all__ = ["PROBLEMS", "SLIPS", "ROTATE_P", "ROTATE_Q", "ROTATE_ANGLE", "COMPOSE_ANGLE", "COMPOSE_SCALE",
           "COMPOSE_CENTER", "COMMUTE_PAIRS", "COORD_MATRIX", "COORD_POINT", "COORD_VECTOR", "PV_POINT",
           "PV_VECTORS", "PV_IMAGE_POINT", "PV_IMAGE_VECTORS", "DIR_FACTOR", "DIR_DIRECTION", "DIR_CENTER",
           "SRC_POINTS", "DST_POINTS",
           "check_rotate_about_point", "check_composite_matrix", "check_commuting_pairs",
           "check_point_and_vector_image", "check_point_and_vectors_map", "check_directional_scaling",
           "check_three_points_map"]

#: Exercise 4.1: rotate P by ROTATE_ANGLE degrees about Q.
ROTATE_P, ROTATE_Q, ROTATE_ANGLE = (4.0, 2.0), (2.0, -1.0), 90.0
#: Exercise 4.2: rotate by COMPOSE_ANGLE about the origin, then scale by COMPOSE_SCALE about COMPOSE_CENTER.
COMPOSE_ANGLE, COMPOSE_SCALE, COMPOSE_CENTER = 90.0, 3.0, (1.0, 0.0)
#: Exercise 4.3: the pairs of maps (label -> (description, M, N)).
COMMUTE_PAIRS = {
    "a": ("the translation by (2, 1) and the uniform scaling by 3 about the origin",
          affine.translation([2, 1]), affine.scaling(3)),
    "b": ("the scaling by 2 about (1, 1) and the rotation by 90 degrees about (1, 1)",
          affine.scaling(2, [1, 1]), affine.rotation(90, [1, 1])),
    "c": ("the scaling by 2 about the origin and the scaling by 3 about (1, 0)",
          affine.scaling(2), affine.scaling(3, [1, 0])),
    "d": ("the mirror in the x-axis and the mirror in the y-axis",
          affine.mirror([0, 0], [1, 0]), affine.mirror([0, 0], [0, 1])),
    "e": ("the nonuniform scaling (x, y) -> (2x, y) and the rotation by 90 degrees about the origin",
          affine.scaling([2, 1]), affine.rotation(90)),
}
#: Exercise 4.4: a matrix, a point and a vector.
COORD_MATRIX = np.array([[2.0, 1.0, 0.0], [0.0, 1.0, 0.0], [3.0, -1.0, 1.0]])
COORD_POINT, COORD_VECTOR = (1.0, 2.0), (1.0, 2.0)
#: Exercise 4.5: the map sending the point PV_POINT to PV_IMAGE_POINT and the vectors PV_VECTORS to PV_IMAGE_VECTORS.
PV_POINT, PV_IMAGE_POINT = (1.0, 1.0), (2.0, 3.0)
PV_VECTORS, PV_IMAGE_VECTORS = ((1.0, 0.0), (1.0, 1.0)), ((0.0, 2.0), (1.0, 1.0))
#: Exercise 4.6: scale by DIR_FACTOR along DIR_DIRECTION about DIR_CENTER.
DIR_FACTOR, DIR_DIRECTION, DIR_CENTER = 2.0, (3.0, 4.0), (1.0, 0.0)
#: Exercise 4.7: the map sending SRC_POINTS to DST_POINTS.
SRC_POINTS = ((1.0, 1.0), (2.0, 1.0), (1.0, 3.0))
DST_POINTS = ((0.0, 0.0), (2.0, 2.0), (-2.0, 2.0))


def _p(v) -> str:
    return fmt(v)


PROBLEMS = {
    "check_rotate_about_point": (
        f"Where does the rotation by {fmt(ROTATE_ANGLE)} degrees (counterclockwise) about Q = {_p(ROTATE_Q)} send "
        f"P = {_p(ROTATE_P)}? Answer with the point [x, y] (Goldman §4.2.2, §4.4)."),
    "check_composite_matrix": (
        f"Write the 3x3 matrix (row-vector convention, translation in the last row) of the map: first rotate by "
        f"{fmt(COMPOSE_ANGLE)} degrees about the origin, then scale by {fmt(COMPOSE_SCALE)} about the point "
        f"{_p(COMPOSE_CENTER)} (Goldman §4.3, §4.5)."),
    "check_commuting_pairs": (
        "Which pairs of maps commute (M N = N M)? Answer with a dict {label: True or False} for the pairs "
        + "; ".join(f"({k}) {d}" for k, (d, _, _) in COMMUTE_PAIRS.items()) + " (Goldman §4.3, §4.4)."),
    "check_point_and_vector_image": (
        f"The affine map M has the rows (2, 1, 0), (0, 1, 0), (3, -1, 1) (row-vector convention). Give the image "
        f"of the point P = {_p(COORD_POINT)} and the image of the vector v = {_p(COORD_VECTOR)}, as "
        f"[[image of P], [image of v]] (Goldman §4.5: affine coordinates)."),
    "check_point_and_vectors_map": (
        f"Write the 3x3 matrix of the affine map that sends the point P = {_p(PV_POINT)} to {_p(PV_IMAGE_POINT)}, "
        f"the vector v1 = {_p(PV_VECTORS[0])} to {_p(PV_IMAGE_VECTORS[0])} and the vector v2 = {_p(PV_VECTORS[1])} "
        f"to {_p(PV_IMAGE_VECTORS[1])} (Goldman §4.7.1)."),
    "check_directional_scaling": (
        f"Write the 3x3 matrix of the nonuniform scaling by {fmt(DIR_FACTOR)} along the direction "
        f"{_p(DIR_DIRECTION)} about the point {_p(DIR_CENTER)} (Goldman §4.7.2). Decimals to 4 places are fine."),
    "check_three_points_map": (
        f"Write the 3x3 matrix of the affine map sending P1, P2, P3 = {', '.join(_p(p) for p in SRC_POINTS)} to "
        f"Q1, Q2, Q3 = {', '.join(_p(q) for q in DST_POINTS)} (Goldman §4.7.3)."),
}


# -- expected answers and the slips each checker recognises --------------------------------------

def _rotate_answers():
    P, Q = np.array(ROTATE_P), np.array(ROTATE_Q)
    right = affine.apply(P, affine.rotation(ROTATE_ANGLE, Q))
    slips = {
        "is P rotated about the origin; rotate about Q: move Q to the origin (P - Q), rotate, then add Q back.":
            affine.apply(P, affine.rotation(ROTATE_ANGLE)),
        "is the clockwise rotation about Q; a positive angle turns counterclockwise, (x, y) -> (-y, x).":
            affine.apply(P, affine.rotation(-ROTATE_ANGLE, Q)),
        "is P - Q rotated: that is where the vector from Q goes; add Q back to get the point.":
            affine.apply(P - Q, affine.rotation(ROTATE_ANGLE)),
        "is P + Q rotated minus Q: the conjugation T(-Q) R T(Q) moves Q to the origin first, so subtract Q "
        "before rotating and add it after.":
            affine.apply(P + Q, affine.rotation(ROTATE_ANGLE)) - Q,
    }
    return right, slips


def _composite_answers():
    R = affine.rotation(COMPOSE_ANGLE)
    S = affine.scaling(COMPOSE_SCALE, COMPOSE_CENTER)
    slips = {
        'is "scale, then rotate": with row vectors the map applied first is the LEFT factor, so the '
        "matrix is R S, not S R.": S @ R,
        "scales about the origin; the scaling is about the given point, S(s, C) = T(-C) S(s) T(C), which "
        "adds a translation.": R @ affine.scaling(COMPOSE_SCALE),
        "is the column-vector form (the transpose): in the book's convention points are row vectors, "
        "Q = P M, so the translation goes in the last row and the last column is two zeros above a one.": (R @ S).T,
        "is the clockwise rotation followed by the scaling; a positive angle turns counterclockwise, so "
        "the first row of R(90) is (0, 1, 0), the image of (1, 0).": affine.rotation(-COMPOSE_ANGLE) @ S,
    }
    return R @ S, slips


def _coord_answers():
    M = COORD_MATRIX
    P = np.array([*COORD_POINT, 1.0]) @ M
    v = np.array([*COORD_VECTOR, 0.0]) @ M
    right = np.array([P[:2], v[:2]])
    col_P, col_v = M @ np.array([*COORD_POINT, 1.0]), M @ np.array([*COORD_VECTOR, 0.0])
    slips = {
        "translates the vector: a vector has affine coordinates (x, y, 0), so the last row (the translation) "
        "does not act on it.": np.array([P[:2], P[:2]]),
        "leaves the vector unchanged; the translation does not act on a vector, but the linear part (the "
        "upper-left 2x2 block) does.": np.array([P[:2], COORD_VECTOR]),
        "multiplies M by a column (M p): in the book's convention the point is a row vector on the left, "
        "(x, y, 1) M.": np.array([col_P[:2], col_v[:2]]),
    }
    return right, slips


def _pv_answers():
    right = affine.affine_from_point_and_vectors(PV_POINT, PV_VECTORS, PV_IMAGE_POINT, PV_IMAGE_VECTORS)
    W = np.array(PV_IMAGE_VECTORS)
    naive = np.eye(3)
    naive[:2, :2] = W
    naive[2, :2] = np.array(PV_IMAGE_POINT) - np.array(PV_POINT) @ W
    no_shift = right.copy()
    no_shift[2, :2] = PV_IMAGE_POINT
    slips = {
        "writes the images w1, w2 as the rows of the linear part, as if v1, v2 were (1, 0) and (0, 1); here "
        "v2 is not (0, 1): solve V L = W with the inverse of V.": naive,
        "puts the image point in the last row; the last row is the image of the ORIGIN, t = Q - P L.": no_shift,
    }
    return right, slips


def _dir_answers():
    right = affine.directional_scaling(DIR_FACTOR, DIR_DIRECTION, DIR_CENTER)
    w = np.array(DIR_DIRECTION)
    L = np.eye(2) + (DIR_FACTOR - 1) * np.outer(w, w)
    C = np.array(DIR_CENTER)
    raw = np.eye(3)
    raw[:2, :2], raw[2, :2] = L, C - C @ L
    slips = {
        "uses the direction (3, 4) as it is; the formula needs the UNIT vector w along it: divide (3, 4) by "
        "its length first.": raw,
        "scales about the origin; about the point C the translation is C - C L (the last row is not zero).":
            affine.directional_scaling(DIR_FACTOR, DIR_DIRECTION),
        "scales every direction (uniform scaling); only the direction (3, 4) should stretch, the perpendicular "
        "direction (-4, 3) keeps its length.": affine.scaling(DIR_FACTOR, DIR_CENTER),
    }
    return right, slips


def _three_answers():
    right = affine.affine_from_points(SRC_POINTS, DST_POINTS)
    A, B = np.array(SRC_POINTS), np.array(DST_POINTS)
    points_as_rows = np.eye(3)
    points_as_rows[:2, :2] = B[1:]
    differences = np.eye(3)
    differences[:2, :2] = B[1:] - B[0]
    differences[2, :2] = B[0] - A[0] @ differences[:2, :2]
    q1_last = right.copy()
    q1_last[2, :2] = B[0]
    slips = {
        "writes the points Q2 and Q3 as rows; the rows of the linear part are the images of the vectors "
        "(1, 0) and (0, 1), and the last row is the image of the origin.": points_as_rows,
        "uses Q2 - Q1 and Q3 - Q1 as the images of (1, 0) and (0, 1); they are the images of P2 - P1 and "
        "P3 - P1, and P3 - P1 is not (0, 1): solve for the images of (1, 0) and (0, 1) first.": differences,
        "puts Q1 in the last row; Q1 is the image of P1, not of the origin: t = Q1 - P1 L.": q1_last,
    }
    return right, slips


# -- shared reading and comparing --------------------------------------------------------------

def _close(got, expected, rel: float = 1e-4) -> bool:
    got, expected = np.asarray(got, float), np.asarray(expected, float)
    return got.shape == expected.shape and bool(np.all(np.abs(got - expected) <= rel * np.maximum(1.0, np.abs(expected))))


def _read(answer, what, shape, ask) -> tuple[np.ndarray | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered(ask)
    got, problem = read_points(answer, what)
    if problem is not None:
        return None, problem
    if got.shape != shape:
        want = "two numbers [x, y]" if shape == (2,) else (
            "a 3x3 matrix (three rows of three numbers)" if shape == (3, 3) else "two points [[x, y], [x, y]]")
        return None, wrong(f"{what} should be {want}; yours has shape {got.shape}.")
    return got, None


def _check_point(answer, what, ask, right, slips) -> Result:
    got, problem = _read(answer, what, (2,), ask)
    if problem is not None:
        return problem
    if _close(got, right):
        return correct(f"{what} is {fmt(right)}.")
    for why, value in slips.items():
        if _close(got, value):
            return wrong(f"{fmt(got)} {why}")
    return wrong(f"{what} is {far_off(got, right)}; check each step: "
                 f"P - Q, the rotation (x, y) -> (-y, x), then add Q back.")


_ROWS = ("first", "second", "third")


def _check_matrix(answer, what, right, slips, hint) -> Result:
    got, problem = _read(answer, what, (3, 3), f"{what}, a 3x3 matrix as a list of three rows")
    if problem is not None:
        return problem
    right = np.asarray(right, dtype=float)
    if _close(got, right):
        return correct(f"{what} is " + ", ".join(fmt(r) for r in right) + " (rows).")
    for why, value in slips.items():
        if _close(got, value):
            return wrong(f"your matrix {why}")
    if _close(got.T, right):
        return wrong("your matrix is the column-vector form (the transpose): in the book's convention points are "
                     "row vectors, Q = P M, so the translation goes in the last row and the last column is two zeros above a one.")
    if not _close(got[:, 2], [0, 0, 1]):
        return wrong("the last column of an affine matrix is two zeros above a one in the row-vector convention; "
                     f"yours is {fmt(got[:, 2])}.")
    bad = [k for k in range(3) if not _close(got[k], right[k])]
    k = bad[0]
    part = "the translation (the image of the origin)" if k == 2 else f"the image of the vector e{k + 1}"
    also = f" (also off: {', '.join('row ' + str(j + 1) for j in bad[1:])})" if len(bad) > 1 else ""
    return wrong(f"the {_ROWS[k]} row of your matrix, {part}, is {far_off(got[k], right[k])}"
                 f"{also}. Hint: {hint}.")


# -- the checkers -------------------------------------------------------------------------------

def check_rotate_about_point(answer) -> Result:
    """Exercise 4.1: the image of ``ROTATE_P`` under the rotation by ``ROTATE_ANGLE`` degrees about
    ``ROTATE_Q`` (Goldman §4.2.2, §4.4).  answer: ``[x, y]``.

    >>> print(check_rotate_about_point([-3, 2]).message)
    (-3, 2) is P - Q rotated: that is where the vector from Q goes; add Q back to get the point.
    """
    right, slips = _rotate_answers()
    return _check_point(answer, f"the image of P = {_p(ROTATE_P)}", "the image of P as a point [x, y]", right, slips)


def check_composite_matrix(answer) -> Result:
    """Exercise 4.2: the matrix of "rotate by ``COMPOSE_ANGLE`` about the origin, then scale by
    ``COMPOSE_SCALE`` about ``COMPOSE_CENTER``" (Goldman §4.3, §4.5).  answer: 3x3 rows.
    """
    right, slips = _composite_answers()
    return _check_matrix(answer, "the composite matrix", right, slips,
                         "write R(90) and S(3, C) = T(-C) S(3) T(C) separately, then multiply them in the order "
                         "the maps are applied, R S")


def check_commuting_pairs(answer) -> Result:
    """Exercise 4.3: which pairs of :data:`COMMUTE_PAIRS` commute (Goldman §4.3, §4.4).  answer: a
    dict ``{label: bool}`` (also ``"yes"``/``"no"``).
    """
    if is_unanswered(answer):
        return unanswered("a dict {label: True or False} for the pairs a to e")
    if not isinstance(answer, dict):
        return wrong(f"the answer should be a dict like {{'a': True, ...}}; you gave {type(answer).__name__}.")
    words = {"true": True, "yes": True, "false": False, "no": False}
    reasons = {
        "a": "a translation does not commute with a scaling about the origin: scaling after translating scales "
             "the translation too (try the origin: one order sends it to (2, 1), the other further).",
        "b": "maps about the SAME point commute when their linear parts do: a uniform scaling commutes with "
             "every rotation, and both fix (1, 1).",
        "c": "scalings about different centres do not commute: each order fixes a different point (check where "
             "the origin goes in each order).",
        "d": "both mirrors fix the origin and their linear parts, diag(1, -1) and diag(-1, 1), are diagonal, so "
             "they commute: either order is the rotation by 180 degrees.",
        "e": "a nonuniform scaling does not commute with a rotation by 90 degrees: check where (1, 0) goes in "
             "each order.",
    }
    for label, (_, M, N) in COMMUTE_PAIRS.items():
        if label not in answer:
            return wrong(f"give an answer for every pair; pair ({label}) is missing.")
        given = answer[label]
        if isinstance(given, str):
            given = words.get(given.strip().lower(), given)
        if not isinstance(given, (bool, np.bool_)):
            return wrong(f"the answer for pair ({label}) should be True or False; you gave {quote(answer[label])}.")
        if bool(given) != affine.commute(M, N):
            return wrong(f"pair ({label}): {reasons[label]}")
    return correct(f"all {len(COMMUTE_PAIRS)} answers are right: maps commute when they fix the same point and "
                   f"their linear parts commute (or both are translations).")


def check_point_and_vector_image(answer) -> Result:
    """Exercise 4.4: the images of the point ``COORD_POINT`` (coordinates ``(x, y, 1)``) and of the
    vector ``COORD_VECTOR`` (coordinates ``(x, y, 0)``) under ``COORD_MATRIX`` (Goldman §4.5).
    answer: ``[[image of P], [image of v]]``.

    >>> print(check_point_and_vector_image([[5, 2], [5, 2]]).message)
    your answer translates the vector: a vector has affine coordinates (x, y, 0), so the last row (the translation) does not act on it.
    """
    what = "the images of P and v"
    got, problem = _read(answer, what, (2, 2), "the images as [[image of P], [image of v]]")
    if problem is not None:
        return problem
    right, slips = _coord_answers()
    if _close(got, right):
        return correct(f"the point goes to {fmt(right[0])} and the vector to {fmt(right[1])}.")
    for why, value in slips.items():
        if _close(got, value):
            return wrong(f"your answer {why}")
    if _close(got[::-1], right):
        return wrong("the two images are swapped: give the image of the point first, then of the vector.")
    k = 0 if not _close(got[0], right[0]) else 1
    name = ("the image of the point P: (x, y, 1) M, translation included" if k == 0
            else "the image of the vector v: (x, y, 0) M, no translation")
    return wrong(f"{name}, is {far_off(got[k], right[k])}; multiply the row of "
                 f"affine coordinates by M, column by column.")


def check_point_and_vectors_map(answer) -> Result:
    """Exercise 4.5: the matrix of the map sending a point and two vectors to their images
    (Goldman §4.7.1): ``L = V^-1 W``, translation ``Q - P L``.  answer: 3x3 rows.
    """
    right, slips = _pv_answers()
    return _check_matrix(answer, "the matrix of the map", right, slips,
                         "the first row is the image of (1, 0) = v1; the image of (0, 1) = v2 - v1 is w2 - w1; the "
                         "last row is Q - P L")


def check_directional_scaling(answer) -> Result:
    """Exercise 4.6: the matrix of the scaling by ``DIR_FACTOR`` along ``DIR_DIRECTION`` about
    ``DIR_CENTER`` (Goldman §4.7.2): ``L = I + (s - 1) w^T w`` with ``w`` the unit vector, translation
    ``C - C L``.  answer: 3x3 rows, decimals to about 1e-4.
    """
    right, slips = _dir_answers()
    return _check_matrix(answer, "the scaling matrix", right, slips,
                         "with the unit vector w, L is the identity plus (s minus one) times the outer product "
                         "w^T w, and the centre C stays fixed: t = C - C L")


def check_three_points_map(answer) -> Result:
    """Exercise 4.7: the matrix of the affine map sending ``SRC_POINTS`` to ``DST_POINTS``
    (Goldman §4.7.3).  answer: 3x3 rows.
    """
    right, slips = _three_answers()
    return _check_matrix(answer, "the matrix of the map", right, slips,
                         "P2 - P1 and P3 - P1 go to Q2 - Q1 and Q3 - Q1; find the images of (1, 0) and (0, 1) from "
                         "them, then t = Q1 - P1 L")


#: Wrong answers of the kinds each checker recognises (tests feed them and check the message).
SLIPS = {
    "check_rotate_about_point": [v.tolist() for v in _rotate_answers()[1].values()],
    "check_composite_matrix": [v.tolist() for v in _composite_answers()[1].values()],
    "check_commuting_pairs": [{"a": True, "b": True, "c": False, "d": True, "e": False},
                              {"a": False, "b": False, "c": False, "d": True, "e": False},
                              {"a": False, "b": True, "c": True, "d": True, "e": False},
                              {"a": False, "b": True, "c": False, "d": False, "e": False},
                              {"a": False, "b": True, "c": False, "d": True, "e": True}],
    "check_point_and_vector_image": [v.tolist() for v in _coord_answers()[1].values()],
    "check_point_and_vectors_map": [v.tolist() for v in _pv_answers()[1].values()],
    "check_directional_scaling": [v.tolist() for v in _dir_answers()[1].values()],
    "check_three_points_map": [v.tolist() for v in _three_answers()[1].values()],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
