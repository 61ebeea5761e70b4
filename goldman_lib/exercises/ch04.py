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
from goldman_lib.exercises.deal import Deck, integers as _ints, memo
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_points, unanswered, wrong

__all__ = ["PROBLEMS", "SLIPS", "ROTATE_P", "ROTATE_Q", "ROTATE_ANGLE", "COMPOSE_ANGLE", "COMPOSE_SCALE",
           "COMPOSE_CENTER", "COMMUTE_PAIRS", "COORD_MATRIX", "COORD_POINT", "COORD_VECTOR", "PV_POINT",
           "PV_VECTORS", "PV_IMAGE_POINT", "PV_IMAGE_VECTORS", "DIR_FACTOR", "DIR_DIRECTION", "DIR_CENTER",
           "SRC_POINTS", "DST_POINTS", "DECK", "deal", "steps", "current", "deal_button",
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


DECK = Deck("ch04")


def _matrix_text(M) -> str:
    return ", ".join(fmt(r) for r in np.asarray(M, dtype=float))


def _steps_matrix(M) -> str:
    return "rows " + "; ".join(fmt(np.round(r, 6) + 0.0) for r in np.asarray(M, dtype=float))


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


# -- exercise 4.1: rotate P about Q ----------------------------------------------------------------

_STORED_ROTATE = {"P": ROTATE_P, "Q": ROTATE_Q, "angle": ROTATE_ANGLE}


@memo
def _rotate_answers(p):
    P, Q, angle = np.array(p["P"]), np.array(p["Q"]), p["angle"]
    right = affine.apply(P, affine.rotation(angle, Q))
    slips = {
        "is P rotated about the origin; rotate about Q: move Q to the origin (P - Q), rotate, then add Q back.":
            affine.apply(P, affine.rotation(angle)),
        "is the clockwise rotation about Q; a positive angle turns counterclockwise, (x, y) -> (-y, x).":
            affine.apply(P, affine.rotation(-angle, Q)),
        "is P - Q rotated: that is where the vector from Q goes; add Q back to get the point.":
            affine.apply(P - Q, affine.rotation(angle)),
        "is P + Q rotated minus Q: the conjugation T(-Q) R T(Q) moves Q to the origin first, so subtract Q "
        "before rotating and add it after.":
            affine.apply(P + Q, affine.rotation(angle)) - Q,
    }
    return right, slips


def _rotate_generate(rng) -> dict:
    return {"P": _ints(rng, -5, 5, 2), "Q": _ints(rng, -4, 4, 2), "angle": 90.0}


def _rotate_statement(p) -> str:
    return (f"Where does the rotation by {fmt(p['angle'])} degrees (counterclockwise) about Q = {_p(p['Q'])} send "
            f"P = {_p(p['P'])}? Answer with the point [x, y] (Goldman §4.2.2, §4.4).")


def _rotate_steps(p) -> str:
    P, Q = np.array(p["P"]), np.array(p["Q"])
    d = P - Q
    r = affine.apply(d, affine.rotation(p["angle"]))
    return (f"1. Move Q to the origin: P - Q = {fmt(d)}.\n"
            f"2. Rotate by {fmt(p['angle'])} degrees, (x, y) -> (-y, x): {fmt(np.round(r, 9) + 0.0)}.\n"
            f"3. Add Q back: {fmt(np.round(r + Q, 9) + 0.0)}.")


@DECK.exercise(stored=_STORED_ROTATE, generate=_rotate_generate, answer=lambda p: _rotate_answers(p)[0],
               slips=lambda p: _rotate_answers(p)[1], statement=_rotate_statement, steps=_rotate_steps,
               same=_close, well_posed=lambda p: None if p["P"] != p["Q"] else "P is the centre")
def check_rotate_about_point(answer, p) -> Result:
    """Exercise 4.1: the image of P under the rotation by the statement's angle about Q
    (Goldman §4.2.2, §4.4).  answer: ``[x, y]``.

    >>> print(check_rotate_about_point([-3, 2]).message)
    (-3, 2) is P - Q rotated: that is where the vector from Q goes; add Q back to get the point.
    """
    right, slips = _rotate_answers(p)
    return _check_point(answer, f"the image of P = {_p(p['P'])}", "the image of P as a point [x, y]", right, slips)


# -- exercise 4.2: a composite matrix --------------------------------------------------------------

_STORED_COMPOSE = {"angle": COMPOSE_ANGLE, "scale": COMPOSE_SCALE, "center": COMPOSE_CENTER}


@memo
def _composite_answers(p):
    angle, scale, center = p["angle"], p["scale"], p["center"]
    R = affine.rotation(angle)
    S = affine.scaling(scale, center)
    first = fmt(np.round(R[0], 9) + 0.0)
    slips = {
        'is "scale, then rotate": with row vectors the map applied first is the LEFT factor, so the '
        "matrix is R S, not S R.": S @ R,
        "scales about the origin; the scaling is about the given point, S(s, C) = T(-C) S(s) T(C), which "
        "adds a translation.": R @ affine.scaling(scale),
        "is the column-vector form (the transpose): in the book's convention points are row vectors, "
        "Q = P M, so the translation goes in the last row and the last column is two zeros above a one.": (R @ S).T,
        f"is the clockwise rotation followed by the scaling; a positive angle turns counterclockwise, so "
        f"the first row of R({fmt(angle)}) is {first}, the image of (1, 0).": affine.rotation(-angle) @ S,
    }
    return R @ S, slips


def _composite_generate(rng) -> dict:
    return {"angle": float(rng.choice([90.0, 270.0])), "scale": float(rng.choice([2.0, 3.0, 4.0, 0.5])),
            "center": _ints(rng, -3, 3, 2)}


def _composite_statement(p) -> str:
    return (f"Write the 3x3 matrix (row-vector convention, translation in the last row) of the map: first rotate by "
            f"{fmt(p['angle'])} degrees about the origin, then scale by {fmt(p['scale'])} about the point "
            f"{_p(p['center'])} (Goldman §4.3, §4.5).")


def _composite_steps(p) -> str:
    R, S = affine.rotation(p["angle"]), affine.scaling(p["scale"], p["center"])
    return (f"1. R({fmt(p['angle'])}) about the origin: {_steps_matrix(R)}.\n"
            f"2. S({fmt(p['scale'])}, C) = T(-C) S({fmt(p['scale'])}) T(C): {_steps_matrix(S)} (the last row is "
            f"C - {fmt(p['scale'])} C).\n"
            f"3. With row vectors the map applied first is the left factor: R S = {_steps_matrix(R @ S)}.")


def _composite_ok(p):
    return None if any(p["center"]) else "the centre is the origin"


@DECK.exercise(stored=_STORED_COMPOSE, generate=_composite_generate, answer=lambda p: _composite_answers(p)[0],
               slips=lambda p: _composite_answers(p)[1], statement=_composite_statement, steps=_composite_steps,
               same=_close, well_posed=_composite_ok)
def check_composite_matrix(answer, p) -> Result:
    """Exercise 4.2: the matrix of "rotate about the origin, then scale about a point" of the
    statement (Goldman §4.3, §4.5).  answer: 3x3 rows.
    """
    right, slips = _composite_answers(p)
    return _check_matrix(answer, "the composite matrix", right, slips,
                         f"write R({fmt(p['angle'])}) and S({fmt(p['scale'])}, C) = T(-C) S({fmt(p['scale'])}) T(C) "
                         f"separately, then multiply them in the order the maps are applied, R S")


# -- exercise 4.4: the image of a point and of a vector ---------------------------------------------

_STORED_COORD = {"M": tuple(map(tuple, COORD_MATRIX.tolist())), "P": COORD_POINT, "v": COORD_VECTOR}


@memo
def _coord_answers(p):
    M = np.array(p["M"], dtype=float)
    P = np.array([*p["P"], 1.0]) @ M
    v = np.array([*p["v"], 0.0]) @ M
    right = np.array([P[:2], v[:2]])
    col_P, col_v = M @ np.array([*p["P"], 1.0]), M @ np.array([*p["v"], 0.0])
    slips = {
        "translates the vector: a vector has affine coordinates (x, y, 0), so the last row (the translation) "
        "does not act on it.": np.array([P[:2], P[:2]]),
        "leaves the vector unchanged; the translation does not act on a vector, but the linear part (the "
        "upper-left 2x2 block) does.": np.array([P[:2], p["v"]]),
        "multiplies M by a column (M p): in the book's convention the point is a row vector on the left, "
        "(x, y, 1) M.": np.array([col_P[:2], col_v[:2]]),
    }
    return right, slips


def _coord_generate(rng) -> dict:
    L = rng.integers(-2, 4, size=(2, 2)).astype(float)
    t = _ints(rng, -3, 3, 2)
    M = ((L[0, 0], L[0, 1], 0.0), (L[1, 0], L[1, 1], 0.0), (t[0], t[1], 1.0))
    return {"M": M, "P": _ints(rng, -3, 3, 2), "v": _ints(rng, -3, 3, 2)}


def _coord_ok(p):
    M = np.array(p["M"])
    if abs(np.linalg.det(M[:2, :2])) < 0.5 or not np.any(M[2, :2]) or not np.any(p["v"]):
        return "the map is singular, has no translation, or the vector is zero"
    right, _ = _coord_answers(p)
    if _close(right[0], right[1]):
        return "the two images are equal (a swap could not be told)"
    return None


def _coord_statement(p) -> str:
    rows = ", ".join(fmt(r) for r in np.array(p["M"], dtype=float))
    return (f"The affine map M has the rows {rows} (row-vector convention). Give the image "
            f"of the point P = {_p(p['P'])} and the image of the vector v = {_p(p['v'])}, as "
            f"[[image of P], [image of v]] (Goldman §4.5: affine coordinates).")


def _coord_steps(p) -> str:
    right, _ = _coord_answers(p)
    return (f"1. The point has affine coordinates ({fmt(p['P'])[1:-1]}, 1): (x, y, 1) M = "
            f"{fmt(np.append(right[0], 1))}, the translation (last row) included.\n"
            f"2. The vector has affine coordinates ({fmt(p['v'])[1:-1]}, 0): (x, y, 0) M = "
            f"{fmt(np.append(right[1], 0))}, no translation.\n"
            f"3. Answer [[{fmt(right[0])[1:-1]}], [{fmt(right[1])[1:-1]}]].")


@DECK.exercise(stored=_STORED_COORD, generate=_coord_generate, answer=lambda p: _coord_answers(p)[0],
               slips=lambda p: _coord_answers(p)[1], statement=_coord_statement, steps=_coord_steps, same=_close,
               well_posed=_coord_ok)
def check_point_and_vector_image(answer, p) -> Result:
    """Exercise 4.4: the images of the point P (coordinates ``(x, y, 1)``) and of the vector v
    (coordinates ``(x, y, 0)``) under the statement's matrix M (Goldman §4.5).
    answer: ``[[image of P], [image of v]]``.
    """
    what = "the images of P and v"
    got, problem = _read(answer, what, (2, 2), "the images as [[image of P], [image of v]]")
    if problem is not None:
        return problem
    right, slips = _coord_answers(p)
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


# -- exercise 4.5: the map of a point and two vectors -----------------------------------------------

_STORED_PV = {"P": PV_POINT, "Q": PV_IMAGE_POINT, "V": PV_VECTORS, "W": PV_IMAGE_VECTORS}


@memo
def _pv_answers(p):
    right = affine.affine_from_point_and_vectors(p["P"], p["V"], p["Q"], p["W"])
    W = np.array(p["W"])
    naive = np.eye(3)
    naive[:2, :2] = W
    naive[2, :2] = np.array(p["Q"]) - np.array(p["P"]) @ W
    no_shift = right.copy()
    no_shift[2, :2] = p["Q"]
    v2 = "v2 is not (0, 1)" if p == _STORED_PV else "v1, v2 are not (1, 0), (0, 1)"
    slips = {
        "writes the images w1, w2 as the rows of the linear part, as if v1, v2 were (1, 0) and (0, 1); here "
        f"{v2}: solve V L = W with the inverse of V.": naive,
        "puts the image point in the last row; the last row is the image of the ORIGIN, t = Q - P L.": no_shift,
    }
    return right, slips


def _pv_generate(rng) -> dict:
    V = rng.integers(-2, 3, size=(2, 2)).astype(float)
    W = rng.integers(-2, 3, size=(2, 2)).astype(float)
    return {"P": _ints(rng, -3, 3, 2), "Q": _ints(rng, -3, 3, 2), "V": tuple(map(tuple, V.tolist())),
            "W": tuple(map(tuple, W.tolist()))}


def _pv_ok(p):
    dV, dW = np.linalg.det(np.array(p["V"])), np.linalg.det(np.array(p["W"]))
    if round(abs(dV)) not in (1, 2) or abs(dW) < 0.5:
        return "v1, v2 (or their images) are dependent, or det V is not 1 or 2 (hand-friendly)"
    if not np.any(p["P"]):
        return "P is the origin (the image point would be the last row)"
    return None


def _pv_statement(p) -> str:
    return (f"Write the 3x3 matrix of the affine map that sends the point P = {_p(p['P'])} to {_p(p['Q'])}, "
            f"the vector v1 = {_p(p['V'][0])} to {_p(p['W'][0])} and the vector v2 = {_p(p['V'][1])} "
            f"to {_p(p['W'][1])} (Goldman §4.7.1).")


def _pv_steps(p) -> str:
    V, W = np.array(p["V"]), np.array(p["W"])
    L = np.linalg.solve(V, W)
    t = np.array(p["Q"]) - np.array(p["P"]) @ L
    return (f"1. The linear part L sends v1, v2 to w1, w2: V L = W with V = {_steps_matrix(V)}, W = "
            f"{_steps_matrix(W)}.\n"
            f"2. L = V^-1 W = {_steps_matrix(L)}.\n"
            f"3. The last row is the image of the origin: t = Q - P L = {fmt(np.round(t, 9) + 0.0)}.\n"
            f"4. M = {_steps_matrix(_pv_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_PV, generate=_pv_generate, answer=lambda p: _pv_answers(p)[0],
               slips=lambda p: _pv_answers(p)[1], statement=_pv_statement, steps=_pv_steps, same=_close,
               well_posed=_pv_ok)
def check_point_and_vectors_map(answer, p) -> Result:
    """Exercise 4.5: the matrix of the map sending a point and two vectors to their images
    (Goldman §4.7.1): ``L = V^-1 W``, translation ``Q - P L``.  answer: 3x3 rows.
    """
    right, slips = _pv_answers(p)
    hint = ("the first row is the image of (1, 0) = v1; the image of (0, 1) = v2 - v1 is w2 - w1; the last row is "
            "Q - P L" if p == _STORED_PV else
            "the rows of V are v1, v2 and those of W their images: L = V^-1 W; the last row is Q - P L")
    return _check_matrix(answer, "the matrix of the map", right, slips, hint)


# -- exercise 4.6: a directional scaling ------------------------------------------------------------

_STORED_DIR = {"factor": DIR_FACTOR, "direction": DIR_DIRECTION, "center": DIR_CENTER}
_DIRECTIONS = ((3.0, 4.0), (4.0, 3.0), (5.0, 12.0), (12.0, 5.0), (-3.0, 4.0), (4.0, -3.0), (1.0, 1.0), (1.0, 2.0),
               (2.0, -1.0), (-5.0, 12.0))


@memo
def _dir_answers(p):
    s, d, C = p["factor"], p["direction"], np.array(p["center"])
    right = affine.directional_scaling(s, d, C)
    w = np.array(d)
    L = np.eye(2) + (s - 1) * np.outer(w, w)
    raw = np.eye(3)
    raw[:2, :2], raw[2, :2] = L, C - C @ L
    perp = (-d[1], d[0])
    slips = {
        f"uses the direction {_p(d)} as it is; the formula needs the UNIT vector w along it: divide {_p(d)} by "
        f"its length first.": raw,
        "scales about the origin; about the point C the translation is C - C L (the last row is not zero).":
            affine.directional_scaling(s, d),
        f"scales every direction (uniform scaling); only the direction {_p(d)} should stretch, the perpendicular "
        f"direction {_p(perp)} keeps its length.": affine.scaling(s, C),
    }
    return right, slips


def _dir_generate(rng) -> dict:
    return {"factor": float(rng.choice([2.0, 3.0, 0.5, 4.0])), "direction": _DIRECTIONS[int(rng.integers(0, 10))],
            "center": _ints(rng, -3, 3, 2)}


def _dir_statement(p) -> str:
    return (f"Write the 3x3 matrix of the nonuniform scaling by {fmt(p['factor'])} along the direction "
            f"{_p(p['direction'])} about the point {_p(p['center'])} (Goldman §4.7.2). Decimals to 4 places are "
            f"fine.")


def _dir_steps(p) -> str:
    s, d = p["factor"], np.array(p["direction"])
    w = d / np.linalg.norm(d)
    L = np.eye(2) + (s - 1) * np.outer(w, w)
    C = np.array(p["center"])
    return (f"1. The unit vector along {_p(d)}: w = {fmt(w)}.\n"
            f"2. L = I + (s - 1) w^T w = {_steps_matrix(L)}.\n"
            f"3. The centre stays fixed: t = C - C L = {fmt(np.round(C - C @ L, 9) + 0.0)}.\n"
            f"4. M = {_steps_matrix(_dir_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_DIR, generate=_dir_generate, answer=lambda p: _dir_answers(p)[0],
               slips=lambda p: _dir_answers(p)[1], statement=_dir_statement, steps=_dir_steps, same=_close,
               well_posed=lambda p: None if any(p["center"]) else "the centre is the origin")
def check_directional_scaling(answer, p) -> Result:
    """Exercise 4.6: the matrix of the scaling by a factor along a direction about a point, as the
    statement gives them (Goldman §4.7.2): ``L = I + (s - 1) w^T w`` with ``w`` the unit vector,
    translation ``C - C L``.  answer: 3x3 rows, decimals to about 1e-4.
    """
    right, slips = _dir_answers(p)
    return _check_matrix(answer, "the scaling matrix", right, slips,
                         "with the unit vector w, L is the identity plus (s minus one) times the outer product "
                         "w^T w, and the centre C stays fixed: t = C - C L")


# -- exercise 4.7: the map of three points --------------------------------------------------------

_STORED_THREE = {"src": SRC_POINTS, "dst": DST_POINTS}


@memo
def _three_answers(p):
    right = affine.affine_from_points(p["src"], p["dst"])
    A, B = np.array(p["src"]), np.array(p["dst"])
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


def _three_generate(rng) -> dict:
    return {"src": tuple(_ints(rng, -2, 3, 2) for _ in range(3)), "dst": tuple(_ints(rng, -3, 3, 2) for _ in range(3))}


def _three_ok(p):
    A, B = np.array(p["src"]), np.array(p["dst"])
    dA, dB = np.linalg.det(A[1:] - A[0]), np.linalg.det(B[1:] - B[0])
    if round(abs(dA)) not in (1, 2) or abs(dB) < 0.5:
        return "the points are collinear (or the source triangle is not hand-friendly: det 1 or 2)"
    if not np.any(A[0]) or np.array_equal(A[2] - A[0], [0.0, 1.0]):
        return "P1 is the origin or P3 - P1 is (0, 1): a slip would be right"
    return None


def _three_statement(p) -> str:
    return (f"Write the 3x3 matrix of the affine map sending P1, P2, P3 = {', '.join(_p(q) for q in p['src'])} to "
            f"Q1, Q2, Q3 = {', '.join(_p(q) for q in p['dst'])} (Goldman §4.7.3).")


def _three_steps(p) -> str:
    A, B = np.array(p["src"]), np.array(p["dst"])
    D, E = A[1:] - A[0], B[1:] - B[0]
    L = np.linalg.solve(D, E)
    return (f"1. The vectors P2 - P1, P3 - P1 = {fmt(D[0])}, {fmt(D[1])} go to Q2 - Q1, Q3 - Q1 = {fmt(E[0])}, "
            f"{fmt(E[1])}.\n"
            f"2. So L solves D L = E: L = D^-1 E = {_steps_matrix(L)}.\n"
            f"3. t = Q1 - P1 L = {fmt(np.round(B[0] - A[0] @ L, 9) + 0.0)}.\n"
            f"4. M = {_steps_matrix(_three_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_THREE, generate=_three_generate, answer=lambda p: _three_answers(p)[0],
               slips=lambda p: _three_answers(p)[1], statement=_three_statement, steps=_three_steps, same=_close,
               well_posed=_three_ok)
def check_three_points_map(answer, p) -> Result:
    """Exercise 4.7: the matrix of the affine map sending the statement's P1, P2, P3 to Q1, Q2, Q3
    (Goldman §4.7.3).  answer: 3x3 rows.
    """
    right, slips = _three_answers(p)
    return _check_matrix(answer, "the matrix of the map", right, slips,
                         "P2 - P1 and P3 - P1 go to Q2 - Q1 and Q3 - Q1; find the images of (1, 0) and (0, 1) from "
                         "them, then t = Q1 - P1 L")


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



#: Deal another instance of an exercise (``deal("check_rotate_about_point")``, or with ``seed=``; 0
#: is the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Exercise 4.3 is a table of five chosen pairs, each commuting or not for its own reason: it does
#: not deal.
PROBLEMS = DECK.problems({"check_commuting_pairs": (
    "Which pairs of maps commute (M N = N M)? Answer with a dict {label: True or False} for the pairs "
    + "; ".join(f"({k}) {d}" for k, (d, _, _) in COMMUTE_PAIRS.items()) + " (Goldman §4.3, §4.4).")})


#: Wrong answers of the kinds each checker recognises (tests feed them and check the message).
SLIPS = {
    "check_rotate_about_point": [v.tolist() for v in _rotate_answers(_STORED_ROTATE)[1].values()],
    "check_composite_matrix": [v.tolist() for v in _composite_answers(_STORED_COMPOSE)[1].values()],
    "check_commuting_pairs": [{"a": True, "b": True, "c": False, "d": True, "e": False},
                              {"a": False, "b": False, "c": False, "d": True, "e": False},
                              {"a": False, "b": True, "c": True, "d": True, "e": False},
                              {"a": False, "b": True, "c": False, "d": False, "e": False},
                              {"a": False, "b": True, "c": False, "d": True, "e": True}],
    "check_point_and_vector_image": [v.tolist() for v in _coord_answers(_STORED_COORD)[1].values()],
    "check_point_and_vectors_map": [v.tolist() for v in _pv_answers(_STORED_PV)[1].values()],
    "check_directional_scaling": [v.tolist() for v in _dir_answers(_STORED_DIR)[1].values()],
    "check_three_points_map": [v.tolist() for v in _three_answers(_STORED_THREE)[1].values()],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
