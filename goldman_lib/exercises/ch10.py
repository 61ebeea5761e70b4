"""Exercise checkers for chapter 10, coordinate algebra: the products of chapter 9 computed in
rectangular coordinates (Goldman §10.1-10.3).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  The data differ from the
chapter's worked examples; the coordinate-free drills (a dot product from lengths, a cross
product from an angle, the orientation rules of the determinant) are chapter 9's.

>>> print(PROBLEMS["check_dot_product"])
Compute u · v for u = (2, -1, 3) and v = (4, 5, -2) in rectangular coordinates (Goldman §10.3).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import vectors
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, off_by, read_number, read_points, wrong)

__all__ = ["PROBLEMS", "SLIPS", "DOT_U", "DOT_V", "CROSS_U", "CROSS_V", "DET_ROWS", "ANGLE_U", "ANGLE_V",
           "AREA_POINTS", "COPLANAR_U", "COPLANAR_V", "COPLANAR_W", "check_dot_product", "check_cross_product",
           "check_determinant", "check_angle", "check_parallelogram_area", "check_coplanar_k"]

#: Exercise 1: the dot product.
DOT_U, DOT_V = np.array([2.0, -1.0, 3.0]), np.array([4.0, 5.0, -2.0])
#: Exercise 2: the cross product.
CROSS_U, CROSS_V = np.array([1.0, 3.0, -2.0]), np.array([2.0, -1.0, 4.0])
#: Exercise 3: the rows of the 3x3 determinant.
DET_ROWS = np.array([[2.0, 1.0, 3.0], [1.0, -1.0, 2.0], [4.0, 0.0, 1.0]])
#: Exercise 4: the angle between two vectors.
ANGLE_U, ANGLE_V = np.array([3.0, 0.0, 4.0]), np.array([1.0, 2.0, 2.0])
#: Exercise 5: three vertices P, Q, R of a parallelogram (the fourth is Q + R - P).
AREA_POINTS = np.array([[1.0, 0.0, 2.0], [3.0, 1.0, 2.0], [2.0, 3.0, 4.0]])
#: Exercise 6: u, v, and w = (k, 4, 7) with k unknown.
COPLANAR_U, COPLANAR_V = np.array([1.0, 2.0, 3.0]), np.array([2.0, 0.0, 1.0])
COPLANAR_W = (4.0, 7.0)   # the second and third coordinates of w


def _rows(M) -> str:
    return ", ".join(fmt(r) for r in np.asarray(M))


PROBLEMS = {
    "check_dot_product": (
        f"Compute u · v for u = {fmt(DOT_U)} and v = {fmt(DOT_V)} in rectangular coordinates (Goldman §10.3)."),
    "check_cross_product": (
        f"Compute u × v for u = {fmt(CROSS_U)} and v = {fmt(CROSS_V)} in rectangular coordinates; answer "
        f"[x, y, z] (Goldman §10.3)."),
    "check_determinant": (
        f"Compute the 3x3 determinant with rows {_rows(DET_ROWS)} by expanding along its first row "
        f"(Goldman §10.3)."),
    "check_angle": (
        f"Find the angle between u = {fmt(ANGLE_U)} and v = {fmt(ANGLE_V)} in degrees, to 0.01° "
        f"(Goldman §10.3: cos θ = u · v / (|u| |v|))."),
    "check_parallelogram_area": (
        f"P = {fmt(AREA_POINTS[0])}, Q = {fmt(AREA_POINTS[1])}, R = {fmt(AREA_POINTS[2])}. Give the area of the "
        f"parallelogram with vertices P, Q, Q + R - P, R, to 4 significant digits (Goldman §10.3: the length of a "
        f"cross product)."),
    "check_coplanar_k": (
        f"For which number k are u = {fmt(COPLANAR_U)}, v = {fmt(COPLANAR_V)} and w = (k, {fmt(COPLANAR_W[0])}, "
        f"{fmt(COPLANAR_W[1])}) coplanar? (Goldman §10.3: three vectors are coplanar exactly when det(u, v, w) = 0.)"),
}


def _close(value: float, target: float, rel: float = 1e-4) -> bool:
    return abs(value - target) <= rel * (1 + abs(target))


# -- exercise 1 ---------------------------------------------------------------------------------

def check_dot_product(answer) -> Result:
    """Check ``DOT_U · DOT_V`` (Goldman §10.3).

    Recognises: the products of coordinates left as a vector (not added up), every product added
    as positive, and a sign dropped from a negative coordinate.

    >>> check_dot_product([8, -5, -6])
    Not yet: that is the vector of products u_i v_i; the dot product is their sum, one number.
    """
    u, v = DOT_U, DOT_V
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
        return correct(f"u · v = {terms} = {fmt(expected)}: negative, so the angle between u and v is obtuse.")
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

def check_cross_product(answer) -> Result:
    """Check ``CROSS_U × CROSS_V`` (Goldman §10.3).

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
    u, v = CROSS_U, CROSS_V
    expected = vectors.cross(u, v)
    close = lambda p: np.allclose(got, p, atol=1e-9)  # noqa: E731
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

def check_determinant(answer) -> Result:
    """Check the determinant of ``DET_ROWS`` (Goldman §10.3).

    Recognises: the middle cofactor added instead of subtracted, the opposite sign, and the rule
    of Sarrus with the three forward diagonals only.

    >>> check_determinant(3)  # doctest: +ELLIPSIS
    Not yet: the signs of the expansion alternate + - +: ...
    """
    value, err = read_number(answer, "the determinant")
    if err is not None:
        return err
    a, b, c = DET_ROWS
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

def check_angle(answer) -> Result:
    """Check the angle between ``ANGLE_U`` and ``ANGLE_V`` in degrees (Goldman §10.3), to 0.01°.

    Recognises: radians, the cosine itself, the lengths not square-rooted (|u|² |v|²), and the
    supplementary angle.

    >>> check_angle(0.7476)  # doctest: +ELLIPSIS
    Not yet: that is the angle in radians; ...
    """
    value, err = read_number(answer, "the angle", "number of degrees")
    if err is not None:
        return err
    u, v = ANGLE_U, ANGLE_V
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

def check_parallelogram_area(answer) -> Result:
    """Check the area ``|(Q - P) × (R - P)|`` of the parallelogram on ``AREA_POINTS`` (Goldman §10.3).

    Recognises: half the area (the triangle PQR), the squared length (no square root), the sum of
    the cross product's coordinates, and the cross product of the points themselves.

    >>> check_parallelogram_area(45)  # doctest: +ELLIPSIS
    Not yet: that is |(Q - P) × (R - P)|², the squared length: ...
    """
    value, err = read_number(answer, "the area")
    if err is not None:
        return err
    P, Q, R = AREA_POINTS
    c = vectors.cross(Q - P, R - P)
    expected = float(vectors.length(c))
    if _close(value, expected):
        return correct(f"(Q - P) × (R - P) = {fmt(c)}, whose length sqrt({fmt(vectors.dot(c, c))}) = {expected:.4f} "
                       f"is the parallelogram's area.")
    if _close(value, expected / 2):
        return wrong("that is half the area, the triangle PQR; the parallelogram is twice the triangle, the full "
                     "length |(Q - P) × (R - P)|.")
    if _close(value, float(vectors.dot(c, c))):
        return wrong("that is |(Q - P) × (R - P)|², the squared length: take its square root.")
    if _close(value, float(c.sum())) or _close(value, float(np.abs(c).sum())):
        return wrong("you added the coordinates of the cross product; the area is its length, the square root of "
                     "the sum of their squares.")
    if _close(value, float(vectors.length(vectors.cross(Q, R)))):
        return wrong("that is |Q × R| with the points' own coordinates; the sides are the vectors Q - P and R - P.")
    return wrong(f"the area is {off_by(value, expected)}. Hint: the sides are Q - P and R - P; the area is "
                 f"the length of their cross product.")


# -- exercise 6 ---------------------------------------------------------------------------------

def _det_of_k(k: float) -> float:
    return float(vectors.det(COPLANAR_U, COPLANAR_V, [k, *COPLANAR_W]))


def check_coplanar_k(answer) -> Result:
    """Check the k that makes ``COPLANAR_U``, ``COPLANAR_V``, ``(k, 4, 7)`` coplanar (Goldman §10.3):
    ``det(u, v, w)`` is affine in k, and zero at one k.

    Recognises: the middle cofactor's sign reversed and plus signs inside the minors; any other
    wrong k is told the sign of the determinant it gives.

    >>> check_coplanar_k(-4)  # doctest: +ELLIPSIS
    Not yet: with k = -4 the determinant is not 0 (it is negative), ...
    """
    value, err = read_number(answer, "k")
    if err is not None:
        return err
    d0, d1 = _det_of_k(0.0), _det_of_k(1.0)
    expected = -d0 / (d1 - d0)
    if _close(value, expected, 1e-6):
        return correct(f"det(u, v, w) = {fmt(d1 - d0)} k + ({fmt(d0)}) vanishes at k = {fmt(expected)}: w is a "
                       f"combination of u and v, so the three lie in one plane.")
    u, v = COPLANAR_U, COPLANAR_V
    w2, w3 = COPLANAR_W

    def root(f):
        a0, a1 = f(0.0), f(1.0)
        return None if a1 == a0 else -a0 / (a1 - a0)

    middle = root(lambda k: u[0] * (v[1] * w3 - v[2] * w2) + u[1] * (v[0] * w3 - v[2] * k) + u[2] * (v[0] * w2 - v[1] * k))
    plus = root(lambda k: u[0] * (v[1] * w3 + v[2] * w2) - u[1] * (v[0] * w3 + v[2] * k) + u[2] * (v[0] * w2 + v[1] * k))
    if middle is not None and _close(value, middle, 1e-6):
        return wrong("the middle term of the expansion has the wrong sign: det = u1 (v2 w3 - v3 w2) - u2 (v1 w3 - "
                     "v3 w1) + u3 (v1 w2 - v2 w1).")
    if plus is not None and _close(value, plus, 1e-6):
        return wrong("the 2x2 minors are differences (v2 w3 - v3 w2), not sums: check the signs inside them.")
    # det is affine in k: its sign at the learner's k from d0 and d1 (no overflow error at k = 1e308)
    sign = "positive" if d0 + value * (d1 - d0) > 0 else "negative"
    return wrong(f"with k = {fmt(value)} the determinant is not 0 (it is {sign}), so u, v, w span a solid. "
                 f"Hint: det(u, v, w) is linear in k; expand it and solve det = 0.")


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
