"""Exercise checkers for chapter 9, vector geometry: points, vectors and their products without
coordinates (Goldman §9.2-9.4 and the chapter's appendices).

Exercises 2-6 deal new numbers (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is the
module constants (the stored notebook), ``deal("check_...")`` or ``deal_button("check_...")``
deals another, each checker checks the current instance, ``PROBLEMS`` states it and
``steps("check_...")`` shows its worked steps.  Exercise 1 (which formal sums of points are legal)
is a table of chosen expressions, each legal or not for its own reason, and an answer of words: it
stays fixed.  ``SLIPS`` holds wrong answers of the stored instances, of the kinds each checker
recognises.  The data differ from the chapter's worked examples; the coordinate drills (a dot
product, a cross product, a determinant from coordinates) are chapter 10's.

>>> print(PROBLEMS["check_dot_from_lengths"])  # doctest: +ELLIPSIS
Two vectors have lengths |u| = 4 and |v| = 5, and |u - v| = 7. ... Goldman §9.4).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import vectors
from goldman_lib.exercises import guard_checkers, quote
from goldman_lib.exercises.deal import Deck, memo, within
from goldman_lib.exercises import (Result, check_points, correct, fmt, is_unanswered, off_by,
                                   read_number, read_points, unanswered, wrong)

__all__ = ["PROBLEMS", "SLIPS", "EXPRESSIONS", "AFFINE_POINTS", "AFFINE_WEIGHTS", "DOT_LENGTHS", "CROSS_U",
           "CROSS_V_LENGTH", "CROSS_ANGLE", "DET_GIVEN", "DET_ASKED", "ASSOC_U", "ASSOC_W", "ASSOC_UV", "ASSOC_VW",
           "DECK", "deal", "steps", "current", "deal_button",
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
#: Exercise 5 (instance 0): det(u, v, w), and the determinants asked, as coefficient rows on (u, v, w).
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


_EXPRESSIONS_PROBLEM = (
    f"P, Q, R are points. For each expression say whether it is a point, a vector, or undefined (depends on the "
    f"origin): {_expr_list()}. Answer with a list of {len(EXPRESSIONS)} words, e.g. [\"point\", \"vector\", ...] "
    f"(Goldman §9.3 and Chapter 9, Appendix B).")

DECK = Deck("ch09")


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

_STORED_AFFINE = {"points": tuple(map(tuple, AFFINE_POINTS.tolist())), "weights": AFFINE_WEIGHTS}


def _affine_weights(p) -> np.ndarray:
    b, c = p["weights"]
    return np.array([1 - b - c, b, c])


@memo
def _affine_answers(p):
    A = np.array(p["points"], dtype=float)
    w = _affine_weights(p)
    right = vectors.affine_combination(A, w).coords
    slips = {}
    for a in (1.0, 0.0):
        ws = np.array([a, *p["weights"]])
        slips[f"A's weight taken as {fmt(a)}"] = ws @ A
    slips["the centroid"] = A.mean(axis=0)
    slips["B's and C's weights swapped"] = w[[0, 2, 1]] @ A
    return right, slips


def _affine_generate(rng) -> dict:
    points = tuple(tuple(float(v) for v in rng.integers(-5, 6, size=2)) for _ in range(3))
    b, c = (float(k) / 20 for k in rng.integers(2, 13, size=2))   # multiples of 0.05 in [0.1, 0.6]
    return {"points": points, "weights": (b, c)}


def _affine_ok(p):
    A = np.array(p["points"], dtype=float)
    if abs(np.linalg.det(A[1:] - A[0])) < 0.5:
        return "A, B, C are collinear (the weights would not be seen in the point)"
    a = _affine_weights(p)[0]
    if abs(a) < 1e-9 or abs(a - 1) < 1e-9 or a < -0.3:
        return "A's weight is 0 or 1 (a slip would be right) or below -0.3"
    b, c = p["weights"]
    if any(abs(x - s) < 1e-6 for x in _affine_answers(p)[0] for s in (b + c, 1 + b + c)):
        return "a coordinate of the answer is a sum of weights a slip's message prints"
    return None


def _affine_statement(p) -> str:
    A = p["points"]
    b, c = p["weights"]
    return (f"A = {fmt(A[0])}, B = {fmt(A[1])}, C = {fmt(A[2])}. Give the point "
            f"a A + {fmt(b)} B + {fmt(c)} C, where the weight a of A is whatever makes it "
            f"an affine combination (Goldman §9.3).")


def _affine_steps(p) -> str:
    w = _affine_weights(p)
    A = np.array(p["points"], dtype=float)
    right, _ = _affine_answers(p)
    terms = " + ".join(f"{fmt(w[k])}·{fmt(A[k])}" for k in range(3))
    return (f"1. The weights must sum to 1: a = 1 - {fmt(w[1])} - {fmt(w[2])} = {fmt(w[0])}.\n"
            f"2. Add the weighted coordinates: {terms} = {fmt(right)}.\n"
            f"3. The result does not depend on the origin, because the weights sum to 1.")


def _same_point(a, b, rel: float = 1e-4) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.linalg.norm(a - b) <= rel * (1 + np.linalg.norm(b)))


@DECK.exercise(stored=_STORED_AFFINE, generate=_affine_generate, answer=lambda p: _affine_answers(p)[0],
               slips=lambda p: _affine_answers(p)[1], statement=_affine_statement, steps=_affine_steps,
               same=lambda a, b: _same_point(a, b) or _same_point(b, a), well_posed=_affine_ok)
def check_affine_point(answer, p) -> Result:
    """Check the affine combination of the statement's A, B, C with weights (1 - b - c, b, c)
    (Goldman §9.3).

    Recognises: A's weight taken as 1 or as 0 (weights not summing to 1), the centroid (equal
    weights), and the weights given to the wrong points.
    """
    what = "the affine combination"
    got, err = read_points(answer, what, ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} is one point [x, y]; yours has shape {got.shape}.")
    w = _affine_weights(p)
    A = np.array(p["points"], dtype=float)
    b, c = p["weights"]
    expected = vectors.affine_combination(A, w).coords
    close = lambda q: np.linalg.norm(got - q) <= 1e-4 * (1 + np.linalg.norm(q))  # noqa: E731
    if close(expected):
        return correct(f"A's weight is 1 - {fmt(b)} - {fmt(c)} = {fmt(w[0])}, and "
                       f"{fmt(w[0])} A + {fmt(w[1])} B + {fmt(w[2])} C = {fmt(expected)}, the same point whatever the "
                       f"origin.")
    for a in (1.0, 0.0):
        ws = np.array([a, b, c])
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

_STORED_DOT = {"lengths": DOT_LENGTHS}


def _dot_value(p) -> float:
    a, b, c = p["lengths"]
    return (a * a + b * b - c * c) / 2


def _dot_slips(p) -> dict:
    a, b, c = p["lengths"]
    e = _dot_value(p)
    return {"not halved": 2 * e, "the sign reversed": -e, "the lengths not squared": (a + b - c) / 2}


def _dot_generate(rng) -> dict:
    a, b = (float(v) for v in rng.integers(2, 10, size=2))
    c = float(rng.integers(abs(a - b) + 1, a + b))      # a strict triangle: |a - b| < c < a + b
    return {"lengths": (a, b, c)}


def _dot_ok(p):
    a, b, c = p["lengths"]
    if not abs(a - b) < c < a + b:
        return "the three lengths make no triangle"
    if _dot_value(p) == 0:
        return "u and v are perpendicular (the sign could not be told)"
    return None


def _dot_statement(p) -> str:
    a, b, c = p["lengths"]
    return (f"Two vectors have lengths |u| = {fmt(a)} and |v| = {fmt(b)}, and "
            f"|u - v| = {fmt(c)}. Without coordinates, find u · v (the law of cosines, Goldman §9.4).")


def _dot_steps(p) -> str:
    a, b, c = p["lengths"]
    e = _dot_value(p)
    return (f"1. |u - v|² = (u - v) · (u - v) = |u|² - 2 u · v + |v|².\n"
            f"2. So u · v = (|u|² + |v|² - |u - v|²) / 2 = ({fmt(a * a)} + {fmt(b * b)} - {fmt(c * c)}) / 2 "
            f"= {fmt(e)}.\n"
            f"3. The sign says the angle between u and v is {'obtuse' if e < 0 else 'acute'}.")


@DECK.exercise(stored=_STORED_DOT, generate=_dot_generate, answer=_dot_value, slips=_dot_slips,
               statement=_dot_statement, steps=_dot_steps, same=within(1e-4, relative=True), well_posed=_dot_ok)
def check_dot_from_lengths(answer, p) -> Result:
    """Check u · v from |u|, |v|, |u - v| (Goldman §9.4): ``(|u|² + |v|² - |u - v|²) / 2``.

    Recognises: the factor 1/2 forgotten, the sign of the law of cosines reversed, the lengths
    used without squaring them.

    >>> check_dot_from_lengths(-8)
    Not yet: that is |u|² + |v|² - |u - v|², which is 2 |u| |v| cos θ: you forgot to halve it.
    """
    a, b, c = p["lengths"]
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

_STORED_CROSS = {"u": tuple(CROSS_U.tolist()), "v_length": CROSS_V_LENGTH, "angle": CROSS_ANGLE}


@memo
def _cross_expected(p) -> np.ndarray:
    theta = math.radians(p["angle"])
    v = p["v_length"] * np.array([math.cos(theta), math.sin(theta), 0.0])
    return vectors.cross_from_geometry(np.array(p["u"]), v, [0.0, 0.0, 1.0])


@memo
def _cross_slips(p) -> dict:
    L = float(np.linalg.norm(_cross_expected(p)))
    lu, lv, angle = float(np.linalg.norm(p["u"])), p["v_length"], p["angle"]
    return {"v × u": np.array([0.0, 0.0, -L]),
            "cos θ": np.array([0.0, 0.0, lu * lv * math.cos(math.radians(angle))]),
            "the sine in radians": np.array([0.0, 0.0, lu * lv * math.sin(angle)]),
            "half the length": np.array([0.0, 0.0, L / 2]),
            "in the plane of u and v": np.array([0.0, L, 0.0])}


def _cross_generate(rng) -> dict:
    return {"u": (float(rng.integers(1, 7)), 0.0, 0.0), "v_length": float(rng.choice([1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0])),
            "angle": float(rng.choice([30.0, 150.0]))}   # sin θ = 1/2: an exact answer by hand


def _cross_ok(p):
    # the checker tells the cos and radian slips by the size of the z-coordinate: keep them apart
    s = _cross_slips(p)
    zs = [abs(v[2]) for v in s.values()] + [abs(_cross_expected(p)[2])]
    tol = 1e-4 * (1 + zs[-1])
    if any(abs(zs[i] - zs[j]) <= tol for i in (1, 2, 3, 5) for j in (1, 2, 3, 5) if i < j):
        return "two slips have z-coordinates of the same size"
    return None


def _cross_statement(p) -> str:
    return (f"u = {fmt(p['u'])}; v lies in the xy-plane, has length {fmt(p['v_length'])} and makes the angle "
            f"{fmt(p['angle'])}° with u, turning counterclockwise from u (towards +y). From the geometric definition "
            f"(length |u| |v| sin θ, perpendicular to u and v, (u, v, u × v) right-handed) give u × v as [x, y, z] "
            f"(Goldman §9.4).")


def _cross_steps(p) -> str:
    e = _cross_expected(p)
    lu = float(np.linalg.norm(p["u"]))
    return (f"1. Length: |u| |v| sin θ = {fmt(lu)} · {fmt(p['v_length'])} · sin {fmt(p['angle'])}° = "
            f"{fmt(np.linalg.norm(e))}.\n"
            f"2. Direction: perpendicular to the xy-plane, where u and v lie; u along +x and v turning counterclockwise "
            f"towards +y make u × v point to +z (right-hand rule).\n"
            f"3. u × v = {fmt(e)}.")


@DECK.exercise(stored=_STORED_CROSS, generate=_cross_generate, answer=_cross_expected, slips=_cross_slips,
               statement=_cross_statement, steps=_cross_steps,
               same=lambda a, b: _same_point(a, b) or _same_point(b, a), well_posed=_cross_ok)
def check_cross_from_angle(answer, p) -> Result:
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
    expected = _cross_expected(p)
    angle, v_length = p["angle"], p["v_length"]
    L = float(np.linalg.norm(expected))
    tol = 1e-4 * (1 + L)
    if np.linalg.norm(got - expected) <= tol:
        return correct(f"|u × v| = |u| |v| sin {fmt(angle)}° = {fmt(L)}, perpendicular to the xy-plane, and up "
                       f"(+z) by the right-hand rule: u × v = {fmt(expected)}.")
    if abs(got[0]) > tol or abs(got[1]) > tol:
        return wrong("u × v is perpendicular to both u and v, so to the whole xy-plane: only its z-coordinate can "
                     "be nonzero.")
    z = got[2]
    lu = float(np.linalg.norm(p["u"]))
    theta = math.radians(angle)
    if abs(z + L) <= tol:
        return wrong("the length is right but the direction is reversed: that is v × u. With u along +x and v turning "
                     "counterclockwise towards +y, the right-hand rule points u × v up, towards +z.")
    if min(abs(abs(z) - lu * v_length * abs(math.cos(theta))), abs(z - lu * v_length * math.cos(theta))) <= tol:
        return wrong("that length uses cos θ: |u| |v| cos θ is the dot product's size. The cross product's length "
                     "is |u| |v| sin θ, the parallelogram's area.")
    if min(abs(abs(z) - lu * v_length * abs(math.sin(angle))), abs(z - lu * v_length * math.sin(angle))) <= tol:
        return wrong(f"you took the sine of {fmt(angle)} radians: the angle is in degrees (set your calculator "
                     f"to degrees, or multiply by π/180).")
    if abs(abs(z) - L / 2) <= tol:
        return wrong("that is half the length, the area of the triangle on u and v; |u × v| is the area of the whole "
                     "parallelogram, |u| |v| sin θ.")
    return wrong(f"the z-coordinate is {off_by(z, expected[2])}. Hint: the length is |u| |v| sin θ, the direction "
                 f"by the right-hand rule.")


# -- exercise 5 ---------------------------------------------------------------------------------

#: the triples Exercise 5 draws from: one exchange, one cyclic shift, one repeated direction.
_SWAPS = (("det(v, u, w)", [[0, 1, 0], [1, 0, 0], [0, 0, 1]]), ("det(u, w, v)", [[1, 0, 0], [0, 0, 1], [0, 1, 0]]),
          ("det(w, v, u)", [[0, 0, 1], [0, 1, 0], [1, 0, 0]]))
_CYCLES = (("det(w, u, v)", [[0, 0, 1], [1, 0, 0], [0, 1, 0]]), ("det(v, w, u)", [[0, 1, 0], [0, 0, 1], [1, 0, 0]]))
_FLATS = (("det(u, v, u + v)", [[1, 0, 0], [0, 1, 0], [1, 1, 0]]), ("det(u, w, u - w)", [[1, 0, 0], [0, 0, 1], [1, 0, -1]]),
          ("det(v, w, 2v + w)", [[0, 1, 0], [0, 0, 1], [0, 2, 1]]))
_STORED_DET = {"det": DET_GIVEN, "swap": 0, "cycle": 0, "scale": (2.0, -1.0), "flat": 0}


def _slot(k: float, name: str) -> str:
    return name if k == 1 else ("-" + name if k == -1 else fmt(k) + name)


def _det_asked(p) -> list:
    s1, s3 = p["scale"]
    scaled = (f"det({_slot(s1, 'u')}, v, {_slot(s3, 'w')})", [[s1, 0, 0], [0, 1, 0], [0, 0, s3]])
    return [_SWAPS[p["swap"]], _CYCLES[p["cycle"]], scaled, _FLATS[p["flat"]]]


def _det_expected(p) -> np.ndarray:
    # det is multilinear: det(M E) = det(M) det(E) for the coefficient rows M on (u, v, w)
    return np.array([round(float(np.linalg.det(np.array(M, float))), 12) * p["det"] for _, M in _det_asked(p)])


def _det_slips(p) -> dict:
    e = _det_expected(p)
    s1, s3 = p["scale"]
    out = {"volumes without signs": np.abs(e)}
    for k, why in ((0, "a swap keeping the sign"), (1, "a cyclic shift as one swap")):
        s = e.copy()
        s[k] = -s[k]
        out[why] = s
    s = e.copy()
    s[2] = e[2] / abs(s1 * s3)
    out["the factors left inside"] = s
    s = e.copy()
    s[3] = p["det"]
    out["a flat triple with a volume"] = s
    return out


def _det_generate(rng) -> dict:
    return {"det": float(rng.integers(2, 10)), "swap": int(rng.integers(0, 3)), "cycle": int(rng.integers(0, 2)),
            "scale": (float(rng.integers(2, 5)), -float(rng.integers(1, 4))), "flat": int(rng.integers(0, 3))}


def _det_statement(p) -> str:
    asked = _det_asked(p)
    return (f"det(u, v, w) = {fmt(p['det'])}, so (u, v, w) is right-handed. Give "
            f"{', '.join(name for name, _ in asked)} as a list of {len(asked)} numbers (Goldman §9.4: the "
            f"determinant is the signed volume of the parallelepiped).")


def _det_steps(p) -> str:
    asked, e = _det_asked(p), _det_expected(p)
    s1, s3 = p["scale"]
    return (f"1. {asked[0][0]}: one exchange of two vectors reverses the orientation: {fmt(e[0])}.\n"
            f"2. {asked[1][0]}: a cyclic shift is two exchanges, the orientation is kept: {fmt(e[1])}.\n"
            f"3. {asked[2][0]}: the factors {fmt(s1)} and {fmt(s3)} come out of their slots: "
            f"{fmt(s1)} · ({fmt(s3)}) · {fmt(p['det'])} = {fmt(e[2])}.\n"
            f"4. {asked[3][0]}: the third vector lies in the plane of the first two, so the parallelepiped is flat: "
            f"{fmt(e[3])}.")


def _same_dets(a, b) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= 1e-6 * (1 + np.maximum(np.abs(a), np.abs(b)))))


_ORDINAL = ("first", "second", "third", "fourth", "fifth", "sixth")


@DECK.exercise(stored=_STORED_DET, generate=_det_generate, answer=_det_expected, slips=_det_slips,
               statement=_det_statement, steps=_det_steps, same=_same_dets)
def check_orientation(answer, p) -> Result:
    """Check the determinants the statement asks for, from ``det(u, v, w)`` (Goldman §9.4): a swap
    changes the sign, a cyclic shift does not, factors come out of each slot, and a repeated
    direction gives a flat parallelepiped.

    Recognises: unsigned volumes (all signs dropped), a swap that keeps the sign, a cyclic shift
    treated as one swap, scale factors left inside, and a dependent triple given a nonzero volume.

    >>> check_orientation([5, 5, 10, 0])  # doctest: +ELLIPSIS
    Not yet: those are volumes, without their signs: ...
    """
    asked = _det_asked(p)
    n = len(asked)
    what = f"the {n} determinants"
    got, err = read_points(answer, what, ask=f"a list of {n} numbers")
    if err is not None:
        return err
    if got.shape != (n,):
        return wrong(f"give {n} numbers, one per determinant asked; yours has shape {got.shape}.")
    expected = _det_expected(p)
    ok = np.abs(got - expected) <= 1e-6 * (1 + np.abs(expected))
    if ok.all():
        return correct("a swap reverses the orientation (the sign), a cyclic shift keeps it, each slot is linear, and "
                       f"{asked[3][0][4:-1]} span no volume.")
    if np.allclose(got, np.abs(expected)) and not np.allclose(expected, np.abs(expected)):
        return wrong("those are volumes, without their signs: det(u, v, w) is a signed volume, and exchanging two "
                     "vectors turns a right-handed triple into a left-handed one.")
    names = [name for name, _ in asked]
    for k in np.flatnonzero(~ok):
        k = int(k)
        name, M = asked[k]
        M = np.array(M, float)
        perm = bool(np.all((M == 0) | (M == 1)) and np.all(M.sum(0) == 1) and np.all(M.sum(1) == 1))
        scale = np.prod([abs(r[r != 0]).prod() for r in M])
        if perm and abs(got[k] + expected[k]) <= 1e-6 * (1 + abs(expected[k])):
            if np.linalg.det(M) < 0:
                return wrong(f"the {_ORDINAL[k]} one, {name}: exchanging two vectors reverses the orientation, so "
                             f"one swap changes the sign.")
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

_STORED_ASSOC = {"u": tuple(ASSOC_U.tolist()), "w": tuple(ASSOC_W.tolist()), "uv": ASSOC_UV, "vw": ASSOC_VW}


def _assoc_expected(p) -> np.ndarray:
    return p["uv"] * np.array(p["w"]) - p["vw"] * np.array(p["u"])


def _assoc_slips(p) -> dict:
    u, w, uv, vw = np.array(p["u"]), np.array(p["w"]), p["uv"], p["vw"]
    return {"zero": np.zeros(3), "the sign reversed": -_assoc_expected(p),
            "the dot products on the wrong vectors": vw * w - uv * u}


def _assoc_generate(rng) -> dict:
    nonzero = [-3.0, -2.0, -1.0, 1.0, 2.0, 3.0, 4.0]
    return {"u": tuple(float(v) for v in rng.integers(-2, 4, size=3)),
            "w": tuple(float(v) for v in rng.integers(-2, 4, size=3)),
            "uv": float(rng.choice(nonzero)), "vw": float(rng.choice(nonzero))}


def _assoc_ok(p):
    if np.linalg.norm(np.cross(p["u"], p["w"])) < 0.5:
        return "u and w are parallel (or zero): no room for v, and the associator would not show the rule"
    return None


def _assoc_statement(p) -> str:
    return (f"u = {fmt(p['u'])}, w = {fmt(p['w'])}, and v is a vector with u · v = {fmt(p['uv'])} and "
            f"v · w = {fmt(p['vw'])}. Give (u × v) × w - u × (v × w) as [x, y, z] (Goldman §9.4 and Chapter 9, "
            f"Appendix A).")


def _assoc_steps(p) -> str:
    return ("1. (u × v) × w = (u · w) v - (v · w) u and u × (v × w) = (u · w) v - (u · v) w.\n"
            "2. Subtract: the terms in v cancel, so (u × v) × w - u × (v × w) = (u · v) w - (v · w) u, and v "
            "itself is never needed.\n"
            f"3. {fmt(p['uv'])} · {fmt(p['w'])} - ({fmt(p['vw'])}) · {fmt(p['u'])} = {fmt(_assoc_expected(p))}.")


def _same_assoc(a, b) -> bool:
    return _same_point(a, b, 1e-6) or _same_point(b, a, 1e-6)


@DECK.exercise(stored=_STORED_ASSOC, generate=_assoc_generate, answer=_assoc_expected, slips=_assoc_slips,
               statement=_assoc_statement, steps=_assoc_steps, same=_same_assoc, well_posed=_assoc_ok)
def check_associator(answer, p) -> Result:
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
    u, w, uv, vw = np.array(p["u"]), np.array(p["w"]), p["uv"], p["vw"]
    expected = uv * w - vw * u
    close = lambda q: np.linalg.norm(got - q) <= 1e-6 * (1 + np.linalg.norm(q))  # noqa: E731
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


#: Deal another instance of an exercise (``deal("check_dot_from_lengths")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Exercise 1 is a table of chosen expressions, each legal or not for its own reason: it does not deal.
PROBLEMS = DECK.problems({"check_expression_types": _EXPRESSIONS_PROBLEM})


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
