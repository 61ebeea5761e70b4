"""Exercise checkers for chapter 10, coordinate algebra: the products of chapter 9 computed in
rectangular coordinates (Goldman §10.1-10.3).

Every exercise deals new numbers (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is
the module constants (the stored notebook), ``deal("check_...")`` or ``deal_button("check_...")``
deals another, each checker checks the current instance, ``PROBLEMS`` states it and
``steps("check_...")`` shows its worked steps.  Dealt data are small integers a learner computes
with by hand (the angle's vectors have whole lengths, the coplanar k is a whole number).
``SLIPS`` holds wrong answers of the stored instances, of the kinds each checker recognises.  The
data differ from the chapter's worked examples; the coordinate-free drills (a dot product from
lengths, a cross product from an angle, the orientation rules of the determinant) are chapter 9's.

>>> print(PROBLEMS["check_dot_product"])
Compute u · v for u = (2, -1, 3) and v = (4, 5, -2) in rectangular coordinates (Goldman §10.3).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import vectors
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import (Result, correct, fmt, off_by, read_number, read_points, wrong)
from goldman_lib.exercises.deal import Deck, integers as _ints, memo, within

__all__ = ["PROBLEMS", "SLIPS", "DOT_U", "DOT_V", "CROSS_U", "CROSS_V", "DET_ROWS", "ANGLE_U", "ANGLE_V",
           "AREA_POINTS", "COPLANAR_U", "COPLANAR_V", "COPLANAR_W", "DECK", "deal", "steps", "current",
           "deal_button", "check_dot_product", "check_cross_product", "check_determinant", "check_angle",
           "check_parallelogram_area", "check_coplanar_k"]

#: Exercise 1 (instance 0): the dot product.
DOT_U, DOT_V = np.array([2.0, -1.0, 3.0]), np.array([4.0, 5.0, -2.0])
#: Exercise 2 (instance 0): the cross product.
CROSS_U, CROSS_V = np.array([1.0, 3.0, -2.0]), np.array([2.0, -1.0, 4.0])
#: Exercise 3 (instance 0): the rows of the 3x3 determinant.
DET_ROWS = np.array([[2.0, 1.0, 3.0], [1.0, -1.0, 2.0], [4.0, 0.0, 1.0]])
#: Exercise 4 (instance 0): the angle between two vectors.
ANGLE_U, ANGLE_V = np.array([3.0, 0.0, 4.0]), np.array([1.0, 2.0, 2.0])
#: Exercise 5 (instance 0): three vertices P, Q, R of a parallelogram (the fourth is Q + R - P).
AREA_POINTS = np.array([[1.0, 0.0, 2.0], [3.0, 1.0, 2.0], [2.0, 3.0, 4.0]])
#: Exercise 6 (instance 0): u, v, and w = (k, 4, 7) with k unknown.
COPLANAR_U, COPLANAR_V = np.array([1.0, 2.0, 3.0]), np.array([2.0, 0.0, 1.0])
COPLANAR_W = (4.0, 7.0)   # the second and third coordinates of w

DECK = Deck("ch10")


def _rows(M) -> str:
    return ", ".join(fmt(r) for r in np.asarray(M))


def _vec(v) -> tuple:
    return tuple(float(x) for x in np.asarray(v, dtype=float).ravel())


def _close(value: float, target: float, rel: float = 1e-4) -> bool:
    return abs(value - target) <= rel * (1 + abs(target))


def _nonzero_ints(rng, lo, hi, size) -> tuple:
    values = [v for v in range(lo, hi + 1) if v != 0]
    return tuple(float(values[i]) for i in rng.integers(0, len(values), size=size))


def _paren(x) -> str:
    return fmt(x) if x >= 0 else "(" + fmt(x) + ")"


# -- exercise 1 ---------------------------------------------------------------------------------

_STORED_DOT = {"u": _vec(DOT_U), "v": _vec(DOT_V)}


def _dot_answer(p) -> float:
    return float(vectors.dot(np.array(p["u"]), np.array(p["v"])))


def _dot_slips(p) -> dict:
    products = np.array(p["u"]) * np.array(p["v"])
    out = {"the products not added": products, "every product added as positive": float(np.abs(products).sum())}
    for k in range(3):
        flipped = products.copy()
        flipped[k] = -flipped[k]
        out[f"the sign of product {k + 1} dropped"] = float(flipped.sum())
    return out


def _dot_generate(rng) -> dict:
    return {"u": _nonzero_ints(rng, -5, 5, 3), "v": _nonzero_ints(rng, -5, 5, 3)}


def _dot_ok(p):
    products = np.array(p["u"]) * np.array(p["v"])
    if not np.any(products < 0) or _dot_answer(p) == 0:
        return "no product is negative (a sign slip could not be told), or u · v = 0"
    return None


def _dot_statement(p) -> str:
    return f"Compute u · v for u = {fmt(p['u'])} and v = {fmt(p['v'])} in rectangular coordinates (Goldman §10.3)."


def _dot_steps(p) -> str:
    u, v = p["u"], p["v"]
    terms = " + ".join(f"{_paren(a)}·{_paren(b)}" for a, b in zip(u, v))
    products = " + ".join(_paren(a * b) for a, b in zip(u, v))
    return (f"1. Multiply matching coordinates and add: u · v = u1 v1 + u2 v2 + u3 v3 = {terms}.\n"
            f"2. = {products} = {fmt(_dot_answer(p))}.")


def _dot_sign(value: float) -> str:
    if value < 0:
        return "negative, so the angle between u and v is obtuse"
    return "positive, so the angle between u and v is acute" if value > 0 else "zero, so u and v are perpendicular"


@DECK.exercise(stored=_STORED_DOT, generate=_dot_generate, answer=_dot_answer, slips=_dot_slips,
               statement=_dot_statement, steps=_dot_steps, same=within(1e-6, relative=True), well_posed=_dot_ok)
def check_dot_product(answer, p) -> Result:
    """Check u · v for the statement's u and v (Goldman §10.3).

    Recognises: the products of coordinates left as a vector (not added up), every product added
    as positive, and a sign dropped from a negative coordinate.

    >>> check_dot_product([8, -5, -6])
    Not yet: that is the vector of products u_i v_i; the dot product is their sum, one number.
    """
    u, v = np.array(p["u"]), np.array(p["v"])
    products = u * v
    if isinstance(answer, (list, tuple, np.ndarray)):
        got, err = read_points(answer, "u · v")
        if err is not None:
            return err
        if got.shape == (3,) and np.allclose(got, products):
            return wrong("that is the vector of products u_i v_i; the dot product is their sum, one number.")
        if got.size != 1:
            return wrong("u · v is one number, not a list: multiply matching coordinates and add.")
        answer = float(got.ravel()[0])
    value, err = read_number(answer, "u · v")
    if err is not None:
        return err
    expected = float(vectors.dot(u, v))
    if _close(value, expected, 1e-9):
        terms = " + ".join(f"{fmt(a) if a >= 0 else '(' + fmt(a) + ')'}·{fmt(b) if b >= 0 else '(' + fmt(b) + ')'}"
                           for a, b in zip(u, v))
        return correct(f"u · v = {terms} = {fmt(expected)}: {_dot_sign(expected)}.")
    if _close(value, float(np.abs(products).sum()), 1e-9):
        return wrong("you added the sizes of the products u_i v_i; some are negative and must be subtracted.")
    for k in range(3):
        flipped = products.copy()
        flipped[k] = -flipped[k]
        if _close(value, float(flipped.sum()), 1e-9):
            return wrong(f"one product has the wrong sign: check u_{k + 1} v_{k + 1} (a negative coordinate times a "
                         f"positive one is negative).")
    return wrong(f"u · v is {off_by(value, expected)}. Hint: u1 v1 + u2 v2 + u3 v3.")


# -- exercise 2 ---------------------------------------------------------------------------------

_STORED_CROSS = {"u": _vec(CROSS_U), "v": _vec(CROSS_V)}


def _cross_answer(p) -> np.ndarray:
    return vectors.cross(np.array(p["u"]), np.array(p["v"]))


def _cross_slips(p) -> dict:
    u, v = np.array(p["u"]), np.array(p["v"])
    e = _cross_answer(p)
    return {"v × u": -e,
            "sums inside the minors": np.array([u[1] * v[2] + u[2] * v[1], u[2] * v[0] + u[0] * v[2],
                                                u[0] * v[1] + u[1] * v[0]]),
            "the middle sign reversed": e * np.array([1, -1, 1]),
            "the products u_i v_i": u * v}


def _cross_generate(rng) -> dict:
    return {"u": _ints(rng, -4, 4, 3), "v": _ints(rng, -4, 4, 3)}


def _cross_ok(p):
    e = _cross_answer(p)
    if e[1] == 0 or np.count_nonzero(e) < 3:
        return "u and v are parallel, or a coordinate of u × v is 0 (a sign slip could not be told)"
    return None


def _cross_statement(p) -> str:
    return (f"Compute u × v for u = {fmt(p['u'])} and v = {fmt(p['v'])} in rectangular coordinates; answer "
            f"[x, y, z] (Goldman §10.3).")


def _cross_steps(p) -> str:
    u1, u2, u3 = p["u"]
    v1, v2, v3 = p["v"]
    e = _cross_answer(p)
    return (f"1. x = u2 v3 - u3 v2 = {_paren(u2)}·{_paren(v3)} - {_paren(u3)}·{_paren(v2)} = {fmt(e[0])}.\n"
            f"2. y = u3 v1 - u1 v3 = {_paren(u3)}·{_paren(v1)} - {_paren(u1)}·{_paren(v3)} = {fmt(e[1])}.\n"
            f"3. z = u1 v2 - u2 v1 = {_paren(u1)}·{_paren(v2)} - {_paren(u2)}·{_paren(v1)} = {fmt(e[2])}.\n"
            f"4. Check: u × v = {fmt(e)} has dot product 0 with u and with v.")


@DECK.exercise(stored=_STORED_CROSS, generate=_cross_generate, answer=_cross_answer, slips=_cross_slips,
               statement=_cross_statement, steps=_cross_steps, same=within(1e-6, relative=True), well_posed=_cross_ok)
def check_cross_product(answer, p) -> Result:
    """Check u × v for the statement's u and v (Goldman §10.3).

    Recognises: v × u, plus signs inside the minors (u2 v3 + u3 v2, ...), the middle coordinate's
    sign reversed (u1 v3 - u3 v1 instead of u3 v1 - u1 v3), and the vector of products u_i v_i.

    >>> check_cross_product([14, 0, 5])  # doctest: +ELLIPSIS
    Not yet: each coordinate is a difference, not a sum: ...
    """
    what = "u × v"
    got, err = read_points(answer, what, ask=what + " as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} is one 3D vector [x, y, z]; yours has shape {got.shape}.")
    u, v = np.array(p["u"]), np.array(p["v"])
    expected = vectors.cross(u, v)
    close = lambda q: np.allclose(got, q, atol=1e-9)  # noqa: E731
    if close(expected):
        return correct(f"u × v = (u2 v3 - u3 v2, u3 v1 - u1 v3, u1 v2 - u2 v1) = {fmt(expected)}; its dot products "
                       f"with u and v are both 0.")
    if close(-expected):
        return wrong("that is v × u = -(u × v): the first coordinate is u2 v3 - u3 v2, u's coordinate first in the "
                     "positive term.")
    plus = np.array([u[1] * v[2] + u[2] * v[1], u[2] * v[0] + u[0] * v[2], u[0] * v[1] + u[1] * v[0]])
    if close(plus):
        return wrong("each coordinate is a difference, not a sum: u2 v3 - u3 v2, not u2 v3 + u3 v2 (the sign errors "
                     "of the 2x2 minors).")
    middle = expected * np.array([1, -1, 1])
    if close(middle):
        return wrong("the middle coordinate has the wrong sign: it is u3 v1 - u1 v3 (cyclic: 2-3, 3-1, 1-2), or "
                     "minus the minor u1 v3 - u3 v1 in the expansion along i, j, k.")
    if close(u * v):
        return wrong("that is the vector of products u_i v_i, not the cross product; each coordinate mixes the "
                     "other two coordinates of u and v.")
    bad = [k for k in range(3) if abs(got[k] - expected[k]) > 1e-9]
    return wrong(f"coordinate {bad[0] + 1} is {off_by(got[bad[0]], expected[bad[0]])} ({len(bad)} of 3 are off). "
                 f"Hint: (u2 v3 - u3 v2, u3 v1 - u1 v3, u1 v2 - u2 v1), and check: u × v is perpendicular to u and v.")


# -- exercise 3 ---------------------------------------------------------------------------------

_STORED_DET = {"rows": tuple(map(tuple, DET_ROWS.tolist()))}


def _det_terms(p) -> np.ndarray:
    a, b, c = np.array(p["rows"], dtype=float)
    return vectors.det_cofactor_terms(a, b, c)


def _det_answer(p) -> float:
    return float(_det_terms(p).sum())


def _det_slips(p) -> dict:
    t = _det_terms(p)
    a, b, c = np.array(p["rows"], dtype=float)
    return {"the middle term added": float(t[0] - t[1] + t[2]), "the sign reversed": -float(t.sum()),
            "forward diagonals only": float(a[0] * b[1] * c[2] + a[1] * b[2] * c[0] + a[2] * b[0] * c[1])}


def _det_generate(rng) -> dict:
    return {"rows": tuple(_ints(rng, -3, 4, 3) for _ in range(3))}


def _det_ok(p):
    if _det_answer(p) == 0 or _det_terms(p)[1] == 0:
        return "the determinant is 0, or its middle term is (a sign slip could not be told)"
    return None


def _det_statement(p) -> str:
    return (f"Compute the 3x3 determinant with rows {_rows(p['rows'])} by expanding along its first row "
            f"(Goldman §10.3).")


def _det_steps(p) -> str:
    (a1, a2, a3), (b1, b2, b3), (c1, c2, c3) = p["rows"]
    t = _det_terms(p)
    return (f"1. + a1 (b2 c3 - b3 c2) = {_paren(a1)}·({_paren(b2)}·{_paren(c3)} - {_paren(b3)}·{_paren(c2)}) "
            f"= {fmt(t[0])}.\n"
            f"2. - a2 (b1 c3 - b3 c1) = -{_paren(a2)}·({_paren(b1)}·{_paren(c3)} - {_paren(b3)}·{_paren(c1)}) "
            f"= {fmt(t[1])}.\n"
            f"3. + a3 (b1 c2 - b2 c1) = {_paren(a3)}·({_paren(b1)}·{_paren(c2)} - {_paren(b2)}·{_paren(c1)}) "
            f"= {fmt(t[2])}.\n"
            f"4. The determinant is the sum: {fmt(t[0])} + {_paren(t[1])} + {_paren(t[2])} = {fmt(t.sum())}.")


@DECK.exercise(stored=_STORED_DET, generate=_det_generate, answer=_det_answer, slips=_det_slips,
               statement=_det_statement, steps=_det_steps, same=within(1e-6, relative=True), well_posed=_det_ok)
def check_determinant(answer, p) -> Result:
    """Check the determinant of the statement's rows (Goldman §10.3).

    Recognises: the middle cofactor added instead of subtracted, the opposite sign, and the rule
    of Sarrus with the three forward diagonals only.

    >>> check_determinant(3)  # doctest: +ELLIPSIS
    Not yet: the signs of the expansion alternate + - +: ...
    """
    value, err = read_number(answer, "the determinant")
    if err is not None:
        return err
    a, b, c = np.array(p["rows"], dtype=float)
    terms = vectors.det_cofactor_terms(a, b, c)
    expected = float(terms.sum())
    if _close(value, expected, 1e-9):
        return correct(f"a1 (b2 c3 - b3 c2) - a2 (b1 c3 - b3 c1) + a3 (b1 c2 - b2 c1) = {fmt(terms[0])} + "
                       f"{fmt(terms[1])} + {fmt(terms[2])} = {fmt(expected)}.")
    if _close(value, float(terms[0] - terms[1] + terms[2]), 1e-9):
        return wrong("the signs of the expansion alternate + - +: the middle term is -a2 times its minor.")
    if _close(value, -expected, 1e-9):
        return wrong("the size is right but the sign is reversed: check the order of the products in each 2x2 "
                     "minor (b2 c3 - b3 c2, not b3 c2 - b2 c3).")
    forward = a[0] * b[1] * c[2] + a[1] * b[2] * c[0] + a[2] * b[0] * c[1]
    if _close(value, float(forward), 1e-9):
        return wrong("that is only the three forward diagonals of the rule of Sarrus; subtract the three backward "
                     "diagonals too.")
    return wrong(f"the determinant is {off_by(value, expected)}. Hint: expand along the first row with signs + - +.")


# -- exercise 4 ---------------------------------------------------------------------------------

_STORED_ANGLE = {"u": _vec(ANGLE_U), "v": _vec(ANGLE_V)}
#: vectors with whole lengths (3, 3, 5, 7, 9, 9, 11): the cosine is a fraction a learner can read.
_WHOLE = ((1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (3.0, 0.0, 4.0), (2.0, 3.0, 6.0), (1.0, 4.0, 8.0), (4.0, 4.0, 7.0),
          (2.0, 6.0, 9.0))


@memo
def _angle_answer(p) -> float:
    return float(vectors.angle_between(np.array(p["u"]), np.array(p["v"])))


@memo
def _angle_slips(p) -> dict:
    u, v = np.array(p["u"]), np.array(p["v"])
    e = _angle_answer(p)
    cos = float(vectors.dot(u, v) / (vectors.length(u) * vectors.length(v)))
    squares = float(vectors.dot(u, v) / (vectors.dot(u, u) * vectors.dot(v, v)))
    return {"radians": math.radians(e), "the cosine": cos, "the squared lengths": math.degrees(math.acos(squares)),
            "the supplementary angle": 180 - e}


def _angle_generate(rng) -> dict:
    def draw():
        base = np.array(_WHOLE[int(rng.integers(0, len(_WHOLE)))])
        return _vec(rng.permutation(base) * rng.choice([-1.0, 1.0], size=3))
    return {"u": draw(), "v": draw()}


def _angle_ok(p):
    u, v = np.array(p["u"]), np.array(p["v"])
    if vectors.dot(u, v) <= 0:
        return "u · v is not positive (the exercise's angle is acute)"
    if not 5 < _angle_answer(p) < 85:
        return "the angle is within 5 degrees of 0 or 90"
    return None


def _angle_statement(p) -> str:
    return (f"Find the angle between u = {fmt(p['u'])} and v = {fmt(p['v'])} in degrees, to 0.01° "
            f"(Goldman §10.3: cos θ = u · v / (|u| |v|)).")


def _angle_steps(p) -> str:
    u, v = np.array(p["u"]), np.array(p["v"])
    return (f"1. u · v = {fmt(vectors.dot(u, v))}, |u| = sqrt({fmt(vectors.dot(u, u))}) = {fmt(vectors.length(u))}, "
            f"|v| = sqrt({fmt(vectors.dot(v, v))}) = {fmt(vectors.length(v))}.\n"
            f"2. cos θ = u · v / (|u| |v|) = {fmt(vectors.dot(u, v))} / ({fmt(vectors.length(u))} · "
            f"{fmt(vectors.length(v))}).\n"
            f"3. θ = arccos of that, in degrees: {_angle_answer(p):.2f}°.")


@DECK.exercise(stored=_STORED_ANGLE, generate=_angle_generate, answer=_angle_answer, slips=_angle_slips,
               statement=_angle_statement, steps=_angle_steps, same=lambda a, b: abs(float(a) - float(b)) <= 0.011,
               well_posed=_angle_ok)
def check_angle(answer, p) -> Result:
    """Check the angle between the statement's u and v in degrees (Goldman §10.3), to 0.01°.

    Recognises: radians, the cosine itself, the lengths not square-rooted (|u|² |v|²), and the
    supplementary angle.

    >>> check_angle(0.7476)  # doctest: +ELLIPSIS
    Not yet: that is the angle in radians; ...
    """
    value, err = read_number(answer, "the angle", "number of degrees")
    if err is not None:
        return err
    u, v = np.array(p["u"]), np.array(p["v"])
    expected = float(vectors.angle_between(u, v))
    cos = float(vectors.dot(u, v) / (vectors.length(u) * vectors.length(v)))
    if abs(value - expected) <= 0.01:
        return correct(f"cos θ = u · v / (|u| |v|) = {fmt(vectors.dot(u, v))} / ({fmt(vectors.length(u))} · "
                       f"{fmt(vectors.length(v))}), θ = {expected:.2f}°.")
    if abs(value - math.radians(expected)) <= 2e-4:
        return wrong("that is the angle in radians; the question asks for degrees (multiply by 180/π).")
    if abs(value - cos) <= 2e-4:
        return wrong("that is cos θ; the angle is its arccosine.")
    squares = float(vectors.dot(u, v) / (vectors.dot(u, u) * vectors.dot(v, v)))
    if abs(value - math.degrees(math.acos(squares))) <= 0.01 or abs(value - squares) <= 2e-4:
        return wrong("you divided by |u|² |v|², the squared lengths: |u| = sqrt(u · u), so take the square roots.")
    if abs(value - (180 - expected)) <= 0.01:
        return wrong("that is the supplementary angle: u · v is positive here, so θ is acute.")
    return wrong(f"the angle is {off_by(value, expected)}. Hint: cos θ = u · v / (|u| |v|).")


# -- exercise 5 ---------------------------------------------------------------------------------

#: the area is asked to 4 significant digits: half a unit of the fourth digit is at most 5e-4 of it.
_AREA_REL = 6e-4
_STORED_AREA = {"points": tuple(map(tuple, AREA_POINTS.tolist()))}


def _area_cross(p) -> np.ndarray:
    P, Q, R = np.array(p["points"], dtype=float)
    return vectors.cross(Q - P, R - P)


def _area_answer(p) -> float:
    return float(vectors.length(_area_cross(p)))


def _area_slips(p) -> dict:
    P, Q, R = np.array(p["points"], dtype=float)
    c = _area_cross(p)
    return {"half (the triangle)": _area_answer(p) / 2, "the squared length": float(vectors.dot(c, c)),
            "the coordinates added": float(c.sum()), "the points' own cross product": float(vectors.length(vectors.cross(Q, R)))}


def _area_generate(rng) -> dict:
    return {"points": tuple(_ints(rng, -2, 4, 3) for _ in range(3))}


def _area_ok(p):
    a = _area_answer(p)
    if a < 1:
        return "P, Q, R are collinear (or nearly)"
    # the checker's branches, in its order: each slip must be met by its own branch only
    P, Q, R = np.array(p["points"], dtype=float)
    c = _area_cross(p)
    groups = [[a], [a / 2], [float(vectors.dot(c, c))], [float(c.sum()), float(np.abs(c).sum())],
              [float(vectors.length(vectors.cross(Q, R)))]]
    for i, g in enumerate(groups):
        for h in groups[i + 1:]:
            if any(_close(x, y, _AREA_REL) or _close(y, x, _AREA_REL) for x in g for y in h):
                return "two of the checker's slips (or a slip and the answer) meet"
    return None


def _area_statement(p) -> str:
    P, Q, R = p["points"]
    return (f"P = {fmt(P)}, Q = {fmt(Q)}, R = {fmt(R)}. Give the area of the "
            f"parallelogram with vertices P, Q, Q + R - P, R, to 4 significant digits (Goldman §10.3: the length of a "
            f"cross product).")


def _area_steps(p) -> str:
    P, Q, R = np.array(p["points"], dtype=float)
    c = _area_cross(p)
    return (f"1. The sides: Q - P = {fmt(Q - P)} and R - P = {fmt(R - P)}.\n"
            f"2. (Q - P) × (R - P) = {fmt(c)}.\n"
            f"3. The area is its length: sqrt({fmt(vectors.dot(c, c))}) = {fmt(_area_answer(p), 6)}, to 4 significant "
            f"digits {fmt(_area_answer(p))}.")


@DECK.exercise(stored=_STORED_AREA, generate=_area_generate, answer=_area_answer, slips=_area_slips,
               statement=_area_statement, steps=_area_steps, same=within(_AREA_REL, relative=True), well_posed=_area_ok)
def check_parallelogram_area(answer, p) -> Result:
    """Check the area ``|(Q - P) × (R - P)|`` of the parallelogram on the statement's points
    (Goldman §10.3).

    Recognises: half the area (the triangle PQR), the squared length (no square root), the sum of
    the cross product's coordinates, and the cross product of the points themselves.  Four
    significant digits are accepted (to 6e-4 of the value).

    >>> check_parallelogram_area(45)  # doctest: +ELLIPSIS
    Not yet: that is |(Q - P) × (R - P)|², the squared length: ...
    """
    value, err = read_number(answer, "the area")
    if err is not None:
        return err
    P, Q, R = np.array(p["points"], dtype=float)
    c = vectors.cross(Q - P, R - P)
    expected = float(vectors.length(c))
    if _close(value, expected, _AREA_REL):
        return correct(f"(Q - P) × (R - P) = {fmt(c)}, whose length sqrt({fmt(vectors.dot(c, c))}) = {expected:.4f} "
                       f"is the parallelogram's area.")
    if _close(value, expected / 2, _AREA_REL):
        return wrong("that is half the area, the triangle PQR; the parallelogram is twice the triangle, the full "
                     "length |(Q - P) × (R - P)|.")
    if _close(value, float(vectors.dot(c, c)), _AREA_REL):
        return wrong("that is |(Q - P) × (R - P)|², the squared length: take its square root.")
    if _close(value, float(c.sum()), _AREA_REL) or _close(value, float(np.abs(c).sum()), _AREA_REL):
        return wrong("you added the coordinates of the cross product; the area is its length, the square root of "
                     "the sum of their squares.")
    if _close(value, float(vectors.length(vectors.cross(Q, R))), _AREA_REL):
        return wrong("that is |Q × R| with the points' own coordinates; the sides are the vectors Q - P and R - P.")
    return wrong(f"the area is {off_by(value, expected)}. Hint: the sides are Q - P and R - P; the area is "
                 f"the length of their cross product.")


# -- exercise 6 ---------------------------------------------------------------------------------

_STORED_COPLANAR = {"u": _vec(COPLANAR_U), "v": _vec(COPLANAR_V), "w": COPLANAR_W}


def _det_of_k(p, k: float) -> float:
    return float(vectors.det(np.array(p["u"]), np.array(p["v"]), [k, *p["w"]]))


def _coplanar_answer(p) -> float:
    d0, d1 = _det_of_k(p, 0.0), _det_of_k(p, 1.0)
    return -d0 / (d1 - d0)


def _root(f):
    a0, a1 = f(0.0), f(1.0)
    return None if a1 == a0 else -a0 / (a1 - a0)


def _coplanar_roots(p):
    """The k a learner finds with the middle term's sign reversed, and with sums inside the minors."""
    u, v = p["u"], p["v"]
    w2, w3 = p["w"]
    middle = _root(lambda k: u[0] * (v[1] * w3 - v[2] * w2) + u[1] * (v[0] * w3 - v[2] * k) + u[2] * (v[0] * w2 - v[1] * k))
    plus = _root(lambda k: u[0] * (v[1] * w3 + v[2] * w2) - u[1] * (v[0] * w3 + v[2] * k) + u[2] * (v[0] * w2 + v[1] * k))
    return middle, plus


def _coplanar_slips(p) -> dict:
    middle, plus = _coplanar_roots(p)
    return {"the middle term's sign reversed": math.nan if middle is None else middle,
            "sums inside the minors": math.nan if plus is None else plus}


def _coplanar_generate(rng) -> dict:
    # w = a u + b v with whole a, b: coplanar at a whole k = a u1 + b v1, which the learner finds
    u, v = np.array(_ints(rng, -3, 4, 3)), np.array(_ints(rng, -3, 4, 3))
    a, b = _nonzero_ints(rng, -2, 2, 2)
    w = a * u + b * v
    return {"u": _vec(u), "v": _vec(v), "w": (float(w[1]), float(w[2]))}


def _coplanar_ok(p):
    d0, d1 = _det_of_k(p, 0.0), _det_of_k(p, 1.0)
    if abs(d1 - d0) < 0.5:
        return "det(u, v, w) does not depend on k (no k, or every k)"
    k = _coplanar_answer(p)
    if abs(2 * k - round(2 * k)) > 1e-9 or abs(k) > 20 or max(abs(x) for x in p["w"]) > 12:
        return "k is not a whole or half number up to 20, or w's coordinates exceed 12 (hand-friendly)"
    if None in _coplanar_roots(p):
        return "a slip's determinant does not depend on k"
    return None


def _coplanar_statement(p) -> str:
    w2, w3 = p["w"]
    return (f"For which number k are u = {fmt(p['u'])}, v = {fmt(p['v'])} and w = (k, {fmt(w2)}, "
            f"{fmt(w3)}) coplanar? (Goldman §10.3: three vectors are coplanar exactly when det(u, v, w) = 0.)")


def _coplanar_steps(p) -> str:
    d0, d1 = _det_of_k(p, 0.0), _det_of_k(p, 1.0)
    return (f"1. Expand det(u, v, w) along the row of u: u1 (v2 w3 - v3 w2) - u2 (v1 w3 - v3 k) + u3 (v1 w2 - v2 k).\n"
            f"2. It is linear in k: det = {fmt(d1 - d0)} k + ({fmt(d0)}).\n"
            f"3. Set it to 0: k = {fmt(_coplanar_answer(p))}.")


@DECK.exercise(stored=_STORED_COPLANAR, generate=_coplanar_generate, answer=_coplanar_answer, slips=_coplanar_slips,
               statement=_coplanar_statement, steps=_coplanar_steps, same=within(1e-6, relative=True), well_posed=_coplanar_ok)
def check_coplanar_k(answer, p) -> Result:
    """Check the k that makes the statement's u, v and w = (k, w2, w3) coplanar (Goldman §10.3):
    ``det(u, v, w)`` is affine in k, and zero at one k.

    Recognises: the middle cofactor's sign reversed and plus signs inside the minors; any other
    wrong k is told the sign of the determinant it gives.

    >>> check_coplanar_k(-4)  # doctest: +ELLIPSIS
    Not yet: with k = -4 the determinant is not 0 (it is negative), ...
    """
    value, err = read_number(answer, "k")
    if err is not None:
        return err
    d0, d1 = _det_of_k(p, 0.0), _det_of_k(p, 1.0)
    expected = -d0 / (d1 - d0)
    if _close(value, expected, 1e-6):
        return correct(f"det(u, v, w) = {fmt(d1 - d0)} k + ({fmt(d0)}) vanishes at k = {fmt(expected)}: w is a "
                       f"combination of u and v, so the three lie in one plane.")
    middle, plus = _coplanar_roots(p)
    if middle is not None and _close(value, middle, 1e-6):
        return wrong("the middle term of the expansion has the wrong sign: det = u1 (v2 w3 - v3 w2) - u2 (v1 w3 - "
                     "v3 w1) + u3 (v1 w2 - v2 w1).")
    if plus is not None and _close(value, plus, 1e-6):
        return wrong("the 2x2 minors are differences (v2 w3 - v3 w2), not sums: check the signs inside them.")
    # det is affine in k: its sign at the learner's k from d0 and d1 (no overflow error at k = 1e308)
    sign = "positive" if d0 + value * (d1 - d0) > 0 else "negative"
    return wrong(f"with k = {fmt(value)} the determinant is not 0 (it is {sign}), so u, v, w span a solid. "
                 f"Hint: det(u, v, w) is linear in k; expand it and solve det = 0.")


#: Deal another instance of an exercise (``deal("check_dot_product")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems()


SLIPS = {
    "check_dot_product": [[8, -5, -6], 19, 7],
    "check_cross_product": [[-10, 8, 7], [14, 0, 5], [10, 8, -7], [2, -3, -8]],
    "check_determinant": [3, -17, 6],
    "check_angle": [0.7476, 0.7333, 87.197, 137.17],
    "check_parallelogram_area": [3.3541, 45, 3, 11, 10.8167],
    "check_coplanar_k": [24, 0, -4],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
