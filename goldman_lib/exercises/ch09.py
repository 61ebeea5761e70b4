"""Exercise checkers for chapter 9, vector geometry: points, vectors and their products without
coordinates (Goldman §9.2-9.4 and the chapter's appendices).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  The data differ from the
chapter's worked examples; the coordinate drills (a dot product, a cross product, a determinant
from coordinates) are chapter 10's.

>>> print(PROBLEMS["check_dot_from_lengths"])  # doctest: +ELLIPSIS
Two vectors have lengths |u| = 4 and |v| = 5, and |u - v| = 7. ... Goldman §9.4).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import vectors
from goldman_lib.exercises import guard_checkers, quote
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, is_unanswered, off_by,
                                   read_number, read_points, unanswered, wrong)

__all__ = ["PROBLEMS", "SLIPS", "EXPRESSIONS", "AFFINE_POINTS", "AFFINE_WEIGHTS", "DOT_LENGTHS", "CROSS_U",
           "CROSS_V_LENGTH", "CROSS_ANGLE", "DET_GIVEN", "DET_ASKED", "ASSOC_U", "ASSOC_W", "ASSOC_UV", "ASSOC_VW",
           "check_expression_types", "check_affine_point", "check_dot_from_lengths", "check_cross_from_angle",
           "check_orientation", "check_associator"]

#: Exercise 1: formal sums of the points P, Q, R, with their weights on (P, Q, R).
EXPRESSIONS = [("Q - P", (-1, 1, 0)), ("P + Q", (1, 1, 0)), ("2P - Q", (2, -1, 0)), ("(P + Q)/2", (0.5, 0.5, 0)),
               ("P - 2Q + R", (1, -2, 1)), ("P + Q - R", (1, 1, -1))]
#: Exercise 2: three points A, B, C and the weights of B and C (A's weight makes the sum affine).
AFFINE_POINTS = np.array([[1.0, 4.0], [5.0, 0.0], [-1.0, -2.0]])
AFFINE_WEIGHTS = (0.3, 0.45)
#: Exercise 3: |u|, |v| and |u - v|.
DOT_LENGTHS = (4.0, 5.0, 7.0)
#: Exercise 4: u in coordinates; v by its length and its angle from u (counterclockwise in the xy-plane).
CROSS_U = np.array([4.0, 0.0, 0.0])
CROSS_V_LENGTH = 2.5
CROSS_ANGLE = 150.0
#: Exercise 5: det(u, v, w), and the determinants asked, as coefficient rows on (u, v, w).
DET_GIVEN = 5.0
DET_ASKED = [("det(v, u, w)", [[0, 1, 0], [1, 0, 0], [0, 0, 1]]),
             ("det(w, u, v)", [[0, 0, 1], [1, 0, 0], [0, 1, 0]]),
             ("det(2u, v, -w)", [[2, 0, 0], [0, 1, 0], [0, 0, -1]]),
             ("det(u, v, u + v)", [[1, 0, 0], [0, 1, 0], [1, 1, 0]])]
#: Exercise 6: u and w in coordinates, and the dot products u · v and v · w (v itself is not given).
ASSOC_U = np.array([1.0, 0.0, 2.0])
ASSOC_W = np.array([0.0, 1.0, 1.0])
ASSOC_UV, ASSOC_VW = 3.0, -2.0

_KINDS = ("point", "vector", "undefined")
_ALIASES = {"point": "point", "a point": "point", "vector": "vector", "a vector": "vector", "undefined": "undefined",
            "illegal": "undefined", "not defined": "undefined", "meaningless": "undefined"}


def _expr_list() -> str:
    return "; ".join(f"({chr(97 + k)}) {e}" for k, (e, _) in enumerate(EXPRESSIONS))


PROBLEMS = {
    "check_expression_types": (
        f"P, Q, R are points. For each expression say whether it is a point, a vector, or undefined (depends on the "
        f"origin): {_expr_list()}. Answer with a list of {len(EXPRESSIONS)} words, e.g. [\"point\", \"vector\", ...] "
        f"(Goldman §9.3 and Chapter 9, Appendix B)."),
    "check_affine_point": (
        f"A = {fmt(AFFINE_POINTS[0])}, B = {fmt(AFFINE_POINTS[1])}, C = {fmt(AFFINE_POINTS[2])}. Give the point "
        f"a A + {fmt(AFFINE_WEIGHTS[0])} B + {fmt(AFFINE_WEIGHTS[1])} C, where the weight a of A is whatever makes it "
        f"an affine combination (Goldman §9.3)."),
    "check_dot_from_lengths": (
        f"Two vectors have lengths |u| = {fmt(DOT_LENGTHS[0])} and |v| = {fmt(DOT_LENGTHS[1])}, and "
        f"|u - v| = {fmt(DOT_LENGTHS[2])}. Without coordinates, find u · v (the law of cosines, Goldman §9.4)."),
    "check_cross_from_angle": (
        f"u = {fmt(CROSS_U)}; v lies in the xy-plane, has length {fmt(CROSS_V_LENGTH)} and makes the angle "
        f"{fmt(CROSS_ANGLE)}° with u, turning counterclockwise from u (towards +y). From the geometric definition "
        f"(length |u| |v| sin θ, perpendicular to u and v, (u, v, u × v) right-handed) give u × v as [x, y, z] "
        f"(Goldman §9.4)."),
    "check_orientation": (
        f"det(u, v, w) = {fmt(DET_GIVEN)}, so (u, v, w) is right-handed. Give "
        f"{', '.join(name for name, _ in DET_ASKED)} as a list of {len(DET_ASKED)} numbers (Goldman §9.4: the "
        f"determinant is the signed volume of the parallelepiped)."),
    "check_associator": (
        f"u = {fmt(ASSOC_U)}, w = {fmt(ASSOC_W)}, and v is a vector with u · v = {fmt(ASSOC_UV)} and "
        f"v · w = {fmt(ASSOC_VW)}. Give (u × v) × w - u × (v × w) as [x, y, z] (Goldman §9.4 and Chapter 9, "
        f"Appendix A)."),
}


# -- exercise 1 ---------------------------------------------------------------------------------

def _expected_kinds() -> list[str]:
    return [vectors.combination_kind(w) for _, w in EXPRESSIONS]


def _why(expr: str, weights, said: str, right: str) -> str:
    total = fmt(sum(weights))
    if said == "point" and right == "vector":
        return (f"{expr} is not a point: its weights add up to {total}, and a combination of points whose weights sum "
                f"to {total} is a difference of points (the origin cancels), a vector")
    if said == "undefined":
        return (f"{expr} is not undefined: its weights add up to {total}, and sums of points are legal when the weights "
                f"sum to 1 (an affine combination) or to 0 (a vector); rewrite it as a point plus vectors or as "
                f"differences of points")
    if right == "undefined":
        return (f"{expr} is undefined: its weights add up to {total}, neither 1 nor 0, so moving the origin moves the "
                f"result; only weights summing to 1 or 0 make sense for points")
    return (f"{expr}: a combination whose weights sum to 1 is a point (an affine combination), not a vector; add up "
            f"its weights again")


def check_expression_types(answer) -> Result:
    """Check the types of :data:`EXPRESSIONS` (Goldman §9.3, Appendix B): ``"point"`` when the
    weights sum to 1, ``"vector"`` when they sum to 0, ``"undefined"`` otherwise.

    Recognises: an affine combination with a negative weight (2P - Q) or a fraction ((P + Q)/2)
    called undefined; P + Q called a point; a difference (weights summing to 0) called a point.

    >>> check_expression_types(["vector", "undefined", "undefined", "point", "vector", "point"])  # doctest: +ELLIPSIS
    Not yet: 1 of the 6 is wrong. 2P - Q is not undefined: its weights add up to 1, ...
    """
    n = len(EXPRESSIONS)
    what = f"a list of {n} words (point, vector or undefined)"
    if is_unanswered(answer):
        return unanswered(what)
    if isinstance(answer, str):
        answer = [a.strip() for a in answer.replace(";", ",").split(",")]
    if not isinstance(answer, (list, tuple)) or len(answer) != n or not all(isinstance(a, str) for a in answer):
        return wrong(f"the answer should be {what}, one per expression (a) to ({chr(96 + n)}); you gave {quote(answer)}.")
    said = []
    for a in answer:
        key = _ALIASES.get(a.strip().lower())
        if key is None:
            return wrong(f"{quote(a)} is not one of point, vector, undefined; give one of these words per expression.")
        said.append(key)
    expected = _expected_kinds()
    bad = [k for k in range(n) if said[k] != expected[k]]
    if not bad:
        return correct("weights summing to 1 give a point, to 0 a vector, to anything else nothing that does not "
                       "depend on the origin.")
    k = bad[0]
    expr, weights = EXPRESSIONS[k]
    return wrong(f"{len(bad)} of the {n} {'is' if len(bad) == 1 else 'are'} wrong. "
                 f"{_why(expr, weights, said[k], expected[k])}.")


# -- exercise 2 ---------------------------------------------------------------------------------

def _affine_weights() -> np.ndarray:
    b, c = AFFINE_WEIGHTS
    return np.array([1 - b - c, b, c])


def check_affine_point(answer) -> Result:
    """Check the affine combination of :data:`AFFINE_POINTS` with weights (1 - b - c, b, c) (Goldman §9.3).

    Recognises: A's weight taken as 1 or as 0 (weights not summing to 1), the centroid (equal
    weights), and the weights given to the wrong points.
    """
    what = "the affine combination"
    got, err = read_points(answer, what, ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} is one point [x, y]; yours has shape {got.shape}.")
    w = _affine_weights()
    A = AFFINE_POINTS
    expected = vectors.affine_combination(A, w).coords
    close = lambda p: np.linalg.norm(got - p) <= 1e-4 * (1 + np.linalg.norm(p))  # noqa: E731
    if close(expected):
        return correct(f"A's weight is 1 - {fmt(AFFINE_WEIGHTS[0])} - {fmt(AFFINE_WEIGHTS[1])} = {fmt(w[0])}, and "
                       f"{fmt(w[0])} A + {fmt(w[1])} B + {fmt(w[2])} C = {fmt(expected)}, the same point whatever the "
                       f"origin.")
    for a in (1.0, 0.0):
        ws = np.array([a, *AFFINE_WEIGHTS])
        if close(ws @ A):
            return wrong(f"you gave A the weight {fmt(a)}, so the weights sum to {fmt(ws.sum())}, not 1: that sum of "
                         f"points moves when the origin moves. A's weight is what is left when B's and C's are taken "
                         f"from 1.")
    if close(A.mean(axis=0)):
        return wrong("that is the centroid, equal weights 1/3; use the weights of the statement for B and C.")
    for perm in ([0, 2, 1], [1, 0, 2], [2, 1, 0], [1, 2, 0], [2, 0, 1]):
        if close(w[perm] @ A):
            return wrong("the weights are right but sit on the wrong points: B's weight goes with B, C's with C, "
                         "and the rest with A.")
    return check_points(got, expected, what=what, tol=1e-4, hint="A's weight is 1 minus the other two; then add "
                                                                 "the weighted coordinates")


# -- exercise 3 ---------------------------------------------------------------------------------

def check_dot_from_lengths(answer) -> Result:
    """Check u · v from |u|, |v|, |u - v| (Goldman §9.4): ``(|u|² + |v|² - |u - v|²) / 2``.

    Recognises: the factor 1/2 forgotten, the sign of the law of cosines reversed, the lengths
    used without squaring them.

    >>> check_dot_from_lengths(-8)
    Not yet: that is |u|² + |v|² - |u - v|², which is 2 |u| |v| cos θ: you forgot to halve it.
    """
    a, b, c = DOT_LENGTHS
    value, err = read_number(answer, "u · v")
    if err is not None:
        return err
    expected = (a * a + b * b - c * c) / 2
    tol = 1e-4 * (1 + abs(expected))
    if abs(value - expected) <= tol:
        return correct(f"u · v = (|u|² + |v|² - |u - v|²) / 2 = ({fmt(a * a)} + {fmt(b * b)} - {fmt(c * c)}) / 2 = "
                       f"{fmt(expected)}: the angle between u and v is {'obtuse' if expected < 0 else 'acute or right'}.")
    if abs(value - 2 * expected) <= tol:
        return wrong("that is |u|² + |v|² - |u - v|², which is 2 |u| |v| cos θ: you forgot to halve it.")
    if abs(value + expected) <= tol:
        return wrong("the sign is reversed: the law of cosines says |u - v|² = |u|² + |v|² - 2 u · v, so u · v is "
                     "(|u|² + |v|² - |u - v|²) / 2, not (|u - v|² - |u|² - |v|²) / 2.")
    if abs(value - (a + b - c) / 2) <= tol:
        return wrong("you used the lengths themselves; the law of cosines works with squared lengths "
                     "|u - v|² = (u - v) · (u - v).")
    return wrong(f"u · v is {off_by(value, expected)}. Hint: expand |u - v|² = (u - v) · (u - v) = |u|² - 2 u · v + |v|².")


# -- exercise 4 ---------------------------------------------------------------------------------

def _cross_expected() -> np.ndarray:
    theta = math.radians(CROSS_ANGLE)
    v = CROSS_V_LENGTH * np.array([math.cos(theta), math.sin(theta), 0.0])
    return vectors.cross_from_geometry(CROSS_U, v, [0.0, 0.0, 1.0])


def check_cross_from_angle(answer) -> Result:
    """Check u × v from |u|, |v|, the angle and the orientation (Goldman §9.4).

    Recognises: v × u (the opposite direction), cos θ instead of sin θ, the angle's sine taken in
    radians, half the length (a triangle's area), and a vector not perpendicular to the plane of u, v.

    >>> check_cross_from_angle([0, 0, -5])
    Not yet: the length is right but the direction is reversed: that is v × u. With u along +x and v turning counterclockwise towards +y, the right-hand rule points u × v up, towards +z.
    """
    what = "u × v"
    got, err = read_points(answer, what, ask=what + " as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} is one 3D vector [x, y, z]; yours has shape {got.shape}.")
    expected = _cross_expected()
    L = float(np.linalg.norm(expected))
    tol = 1e-4 * (1 + L)
    if np.linalg.norm(got - expected) <= tol:
        return correct(f"|u × v| = |u| |v| sin {fmt(CROSS_ANGLE)}° = {fmt(L)}, perpendicular to the xy-plane, and up "
                       f"(+z) by the right-hand rule: u × v = {fmt(expected)}.")
    if abs(got[0]) > tol or abs(got[1]) > tol:
        return wrong("u × v is perpendicular to both u and v, so to the whole xy-plane: only its z-coordinate can "
                     "be nonzero.")
    z = got[2]
    lu = float(np.linalg.norm(CROSS_U))
    theta = math.radians(CROSS_ANGLE)
    if abs(z + L) <= tol:
        return wrong("the length is right but the direction is reversed: that is v × u. With u along +x and v turning "
                     "counterclockwise towards +y, the right-hand rule points u × v up, towards +z.")
    if min(abs(abs(z) - lu * CROSS_V_LENGTH * abs(math.cos(theta))), abs(z - lu * CROSS_V_LENGTH * math.cos(theta))) <= tol:
        return wrong("that length uses cos θ: |u| |v| cos θ is the dot product's size. The cross product's length "
                     "is |u| |v| sin θ, the parallelogram's area.")
    if min(abs(abs(z) - lu * CROSS_V_LENGTH * abs(math.sin(CROSS_ANGLE))), abs(z - lu * CROSS_V_LENGTH * math.sin(CROSS_ANGLE))) <= tol:
        return wrong(f"you took the sine of {fmt(CROSS_ANGLE)} radians: the angle is in degrees (set your calculator "
                     f"to degrees, or multiply by π/180).")
    if abs(abs(z) - L / 2) <= tol:
        return wrong("that is half the length, the area of the triangle on u and v; |u × v| is the area of the whole "
                     "parallelogram, |u| |v| sin θ.")
    return wrong(f"the z-coordinate is {off_by(z, expected[2])}. Hint: the length is |u| |v| sin θ, the direction "
                 f"by the right-hand rule.")


# -- exercise 5 ---------------------------------------------------------------------------------

def _det_expected() -> np.ndarray:
    # det is multilinear: det(M E) = det(M) det(E) for the coefficient rows M on (u, v, w)
    return np.array([round(float(np.linalg.det(np.array(M, float))), 12) * DET_GIVEN for _, M in DET_ASKED])


_ORDINAL = ("first", "second", "third", "fourth", "fifth", "sixth")


def check_orientation(answer) -> Result:
    """Check the determinants of :data:`DET_ASKED` from ``det(u, v, w)`` (Goldman §9.4): a swap
    changes the sign, a cyclic shift does not, factors come out of each slot, and a repeated
    direction gives a flat parallelepiped.

    Recognises: unsigned volumes (all signs dropped), a cyclic shift treated as one swap, scale
    factors left inside, and a dependent triple given a nonzero volume.

    >>> check_orientation([5, 5, 10, 0])  # doctest: +ELLIPSIS
    Not yet: those are volumes, without their signs: ...
    """
    n = len(DET_ASKED)
    what = f"the {n} determinants"
    got, err = read_points(answer, what, ask=f"a list of {n} numbers")
    if err is not None:
        return err
    if got.shape != (n,):
        return wrong(f"give {n} numbers, one per determinant asked; yours has shape {got.shape}.")
    expected = _det_expected()
    ok = np.abs(got - expected) <= 1e-6 * (1 + np.abs(expected))
    if ok.all():
        return correct("a swap reverses the orientation (the sign), a cyclic shift keeps it, each slot is linear, and "
                       "u, v, u + v span no volume.")
    if np.allclose(got, np.abs(expected)) and not np.allclose(expected, np.abs(expected)):
        return wrong("those are volumes, without their signs: det(u, v, w) is a signed volume, and exchanging two "
                     "vectors turns a right-handed triple into a left-handed one.")
    names = [name for name, _ in DET_ASKED]
    for k in np.flatnonzero(~ok):
        k = int(k)
        name, M = DET_ASKED[k]
        M = np.array(M, float)
        perm = bool(np.all((M == 0) | (M == 1)) and np.all(M.sum(0) == 1) and np.all(M.sum(1) == 1))
        scale = np.prod([abs(r[r != 0]).prod() for r in M])
        if perm and abs(got[k] + expected[k]) <= 1e-6 * (1 + abs(expected[k])):
            return wrong(f"the {_ORDINAL[k]} one, {name}: a cyclic shift (u, v, w) -> (w, u, v) is two swaps, not one, "
                         f"so it keeps the orientation.")
        if not perm and abs(expected[k]) > 0 and abs(abs(got[k]) * scale - abs(expected[k])) <= 1e-6 * (1 + abs(expected[k])):
            return wrong(f"the {_ORDINAL[k]} one, {name}: a factor in a slot comes out of the determinant (it is linear "
                         f"in each vector), sign included.")
        if expected[k] == 0:
            return wrong(f"the {_ORDINAL[k]} one, {name}: where does the third vector lie relative to the plane of "
                         f"the first two, and what volume does such a parallelepiped have?")
        return wrong(f"the {_ORDINAL[k]} one, {name}, is {off_by(got[k], expected[k])} ({int((~ok).sum())} of {n} are off). "
                     f"Hint: count the swaps that reorder the vectors, and take factors out of each slot.")
    return wrong(f"{what}: check each of {', '.join(names)}.")  # pragma: no cover - every bad entry returns above


# -- exercise 6 ---------------------------------------------------------------------------------

def check_associator(answer) -> Result:
    """Check ``(u × v) × w - u × (v × w) = (u · v) w - (v · w) u`` (Goldman §9.4, Appendix A).

    Recognises: zero (assuming the cross product is associative), the opposite sign, and the two
    dot products attached to the wrong vectors.

    >>> check_associator([0, 0, 0])  # doctest: +ELLIPSIS
    Not yet: zero would mean the cross product is associative; it is not. ...
    """
    what = "the associator"
    got, err = read_points(answer, what, ask=what + " as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} is one 3D vector [x, y, z]; yours has shape {got.shape}.")
    u, w, uv, vw = ASSOC_U, ASSOC_W, ASSOC_UV, ASSOC_VW
    expected = uv * w - vw * u
    close = lambda p: np.linalg.norm(got - p) <= 1e-6 * (1 + np.linalg.norm(p))  # noqa: E731
    if close(expected):
        return correct(f"(u × v) × w - u × (v × w) = (u · v) w - (v · w) u = {fmt(expected)}: not zero, so the cross "
                       f"product is not associative, and v itself was never needed.")
    if close(np.zeros(3)):
        return wrong("zero would mean the cross product is associative; it is not. Expand both sides with "
                     "(a × b) × c = (a · c) b - (b · c) a.")
    if close(-expected):
        return wrong("the sign is reversed: that is u × (v × w) - (u × v) × w.")
    if close(vw * w - uv * u) or close(uv * u - vw * w) or close(-vw * w + uv * u):
        return wrong("the dot products sit on the wrong vectors: in (u · v) w - (v · w) u, u · v multiplies w and "
                     "v · w multiplies u.")
    return check_points(got, expected, what=what, tol=1e-6,
                        hint="(u × v) × w = (u · w) v - (v · w) u and u × (v × w) = (u · w) v - (u · v) w")


SLIPS = {
    "check_expression_types": [["vector", "undefined", "undefined", "point", "vector", "point"],
                               ["vector", "undefined", "point", "undefined", "vector", "point"],
                               ["vector", "point", "point", "point", "vector", "point"],
                               ["point", "undefined", "point", "point", "vector", "point"],
                               ["vector", "undefined", "point", "point", "point", "point"]],
    "check_affine_point": [[2.05, 3.1], [1.05, -0.9], [5 / 3, 2 / 3], [2.2, 0.4]],
    "check_dot_from_lengths": [-8, 4, 1],
    "check_cross_from_angle": [[0, 0, -5], [0, 0, 10 * math.cos(math.radians(30))], [0, 0, 10 * math.sin(150)],
                               [0, 0, 2.5], [0, 5, 0]],
    "check_orientation": [[5, 5, 10, 0], [-5, -5, -10, 0], [-5, 5, -5, 0], [-5, 5, -10, 5]],
    "check_associator": [[0, 0, 0], [-2, -3, -7], [-3, -2, -8], [3, 2, 8]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
