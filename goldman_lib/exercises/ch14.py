"""Exercise checkers for chapter 14, projective space and the universal space of mass-points
(Goldman §14.2-14.4).

Each checker recognises the usual slips (adding the points without their masses, dividing by the
wrong mass, dropping the sign of a negative mass, forgetting that masses which cancel give a
vector, a vector counted with mass 1, projective equality confused with equality of coordinates,
depth and pseudodepth order reversed) and names the misconception; it says how far off an answer is,
never what the answer is.  ``None`` or ``...`` means "not answered yet".

>>> print(PROBLEMS["check_point_at_infinity"])
In homogeneous coordinates (x, y, w) the line 3x + 2y = 11 of the plane is 3x + 2y - 11w = 0. Give its point at infinity as [x, y, w] (any nonzero multiple will do) (Goldman §14.2).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import mass_points as mp
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, off_by, read_points, unanswered, is_unanswered, wrong

__all__ = ["PROBLEMS", "SLIPS", "LEVER_POINTS", "LEVER_MASSES", "COMBO_MASSES", "COMBINATIONS", "TUPLE_PAIRS",
           "LINE", "PERSPECTIVE_EYE", "PERSPECTIVE_PLANE", "PERSPECTIVE_POINT", "DEPTH_EYE", "DEPTH_PLANE",
           "DEPTH_POINTS", "ORDER_EYE", "ORDER_PLANE", "ORDER_POINTS",
           "check_center_of_mass", "check_point_or_vector", "check_same_projective_point", "check_point_at_infinity",
           "check_perspective_by_lever", "check_pseudodepth", "check_depth_order"]

#: Exercise 1: three points with masses (one negative).
LEVER_POINTS = ((2.0, 1.0), (5.0, -2.0), (0.0, 4.0))
LEVER_MASSES = (3.0, -1.0, 2.0)
#: Exercise 2: the masses of the mass-points A, B, C; v is a vector (mass 0).
COMBO_MASSES = {"A": 2, "B": 1, "C": 3, "v": 0}
#: Exercise 2: combinations as {name: coefficient}.
COMBINATIONS = (
    ("A - 2B", {"A": 1, "B": -2}),
    ("A - B", {"A": 1, "B": -1}),
    ("2B - C", {"B": 2, "C": -1}),
    ("3B - C + v", {"B": 3, "C": -1, "v": 1}),
    ("A - B - v", {"A": 1, "B": -1, "v": -1}),
    ("C - A - B + v", {"C": 1, "A": -1, "B": -1, "v": 1}),
)
#: Exercise 3: pairs of homogeneous tuples (x, y, z, w).
TUPLE_PAIRS = (
    ((2, -4, 6, 2), (-1, 2, -3, -1)),
    ((1, 2, 3, 1), (2, 4, 6, 1)),
    ((4, 2, 0, 0), (-2, -1, 0, 0)),
    ((3, 6, 9, 3), (1, 2, 3, 1)),
    ((1, 0, 2, 0), (1, 0, 2, 1)),
)
#: Exercise 4: the line a x + b y = d, as (a, b, d).
LINE = (3.0, 2.0, 11.0)
#: Exercise 5: eye, plane (point, normal) and the point projected.
PERSPECTIVE_EYE = (0.0, 1.0, -2.0)
PERSPECTIVE_PLANE = ((0.0, 0.0, 2.0), (0.0, 0.0, 1.0))
PERSPECTIVE_POINT = (6.0, 7.0, 10.0)
#: Exercise 6: the eye looks down the z-axis at the plane z = -3.
DEPTH_EYE = (0.0, 0.0, 1.0)
DEPTH_PLANE = ((0.0, 0.0, -3.0), (0.0, 0.0, -1.0))
DEPTH_POINTS = {"A": (2.0, 1.0, -7.0), "B": (0.0, 3.0, -15.0), "C": (1.0, 1.0, -4.0)}
#: Exercise 7: a tilted plane; two of the points share a line of sight.
ORDER_EYE = (0.0, 0.0, 0.0)
ORDER_PLANE = ((2.0, 0.0, 0.0), (1.0, 1.0, 0.0))
ORDER_POINTS = {"A": (3.0, 1.0, 5.0), "B": (1.0, 2.0, -1.0), "C": (6.0, 2.0, 0.0), "D": (2.0, 4.0, -2.0)}


def _tuple(t) -> str:
    return "(" + ", ".join(fmt(v) for v in t) + ")"


def _combo(coeffs) -> str:
    return " ".join(f"{'+' if c > 0 else '-'} {abs(c) if abs(c) != 1 else ''}{k}" for k, c in coeffs.items()).lstrip("+ ")


PROBLEMS = {
    "check_center_of_mass": (
        "Add the mass-points of the points " + ", ".join(
            f"P{i + 1} = {_tuple(P)} with mass {fmt(m)}" for i, (P, m) in enumerate(zip(LEVER_POINTS, LEVER_MASSES)))
        + ". The sum is a mass-point (M P, M): give its point P, the centre of mass, and its total mass M as "
          "[x, y, M] (Goldman §14.3)."),
    "check_point_or_vector": (
        "A, B, C are mass-points with masses " + ", ".join(f"{k} = {COMBO_MASSES[k]}" for k in "ABC")
        + ", and v is a vector. For each combination " + ", ".join(name for name, _ in COMBINATIONS)
        + ", is the result a point (a mass-point) or a vector? Answer a list of six words 'point' or 'vector', "
          "in this order (Goldman §14.3)."),
    "check_same_projective_point": (
        "Are these pairs of homogeneous coordinates (x, y, z, w) the same point of projective space? "
        + "; ".join(f"({k + 1}) {_tuple(a)} and {_tuple(b)}" for k, (a, b) in enumerate(TUPLE_PAIRS))
        + ". Answer a list of five True/False (Goldman §14.2)."),
    "check_point_at_infinity": (
        f"In homogeneous coordinates (x, y, w) the line {fmt(LINE[0])}x + {fmt(LINE[1])}y = {fmt(LINE[2])} of the "
        f"plane is {fmt(LINE[0])}x + {fmt(LINE[1])}y - {fmt(LINE[2])}w = 0. Give its point at infinity as [x, y, w] "
        f"(any nonzero multiple will do) (Goldman §14.2)."),
    "check_perspective_by_lever": (
        f"The eye is E = {_tuple(PERSPECTIVE_EYE)} and the plane of projection passes through Q = "
        f"{_tuple(PERSPECTIVE_PLANE[0])} with normal N = {_tuple(PERSPECTIVE_PLANE[1])}. With c = (Q - E)·N and "
        f"s = (P - E)·N, the perspective image of P = {_tuple(PERSPECTIVE_POINT)} is the sum of the mass-points "
        f"(cP, c) and ((s - c)E, s - c), written (mP, m) as in §14.3: mass c at P, mass s - c at E. Compute it "
        f"by the law of the lever and give the image point [x, y, z] (Goldman §14.4)."),
    "check_pseudodepth": (
        f"The eye is E = {_tuple(DEPTH_EYE)}, looking at the plane through Q = {_tuple(DEPTH_PLANE[0])} with "
        f"normal N = {_tuple(DEPTH_PLANE[1])} (towards the plane). With c = (Q - E)·N and s = (P - E)·N, the "
        f"pseudodepth of a point P in front of the eye is 1 - c/s. Give the pseudodepths of "
        + ", ".join(f"{k} = {_tuple(P)}" for k, P in DEPTH_POINTS.items())
        + " as [dA, dB, dC] (Goldman §14.4)."),
    "check_depth_order": (
        f"The eye is E = {_tuple(ORDER_EYE)} and the plane of projection passes through Q = {_tuple(ORDER_PLANE[0])} "
        f"with normal N = {_tuple(ORDER_PLANE[1])} (not a unit vector; c/s does not care). Order the points "
        + ", ".join(f"{k} = {_tuple(P)}" for k, P in ORDER_POINTS.items())
        + " by pseudodepth, from nearest the eye to farthest, as a string of letters such as 'ABCD' "
          "(Goldman §14.4)."),
}


# -- exercise 1: the sum of three mass-points --------------------------------------------------------

def _lever_sum(masses, points=LEVER_POINTS) -> np.ndarray:
    total = mp.mass_point(points[0], masses[0])
    for P, m in zip(points[1:], masses[1:]):
        total = mp.add(total, mp.mass_point(P, m))
    return total


def _lever_answers():
    pts = np.array(LEVER_POINTS)
    total = _lever_sum(LEVER_MASSES)
    right = np.append(mp.point_of(total), mp.mass_of(total))
    wp, M = total[:2], mp.mass_of(total)
    abs_sum = _lever_sum([abs(m) for m in LEVER_MASSES])
    slips = {
        "drops the sign of the negative mass: a mass of -1 pushes instead of pulls, so P2 enters the sum as "
        "-1 · P2 and the total mass counts -1.": np.append(mp.point_of(abs_sum), mp.mass_of(abs_sum)),
        "adds the points without their masses: the centre of mass is (sum of m_i P_i) / (sum of m_i), every point "
        "weighted by its mass.": np.append(pts.mean(axis=0), M),
        "divides by the number of points; divide the weighted sum by the TOTAL MASS.": np.append(wp / len(pts), M),
        "divides by the sum of the sizes of the masses; the total mass keeps their signs.":
            np.append(wp / sum(abs(m) for m in LEVER_MASSES), M),
        "gives the first coordinates of the summed mass-point, (M P, M); the point P is found by dividing by the "
        "mass M.": np.append(wp, M),
    }
    return right, slips


def check_center_of_mass(answer) -> Result:
    """Exercise 1: the sum of the mass-points of :data:`LEVER_POINTS` with :data:`LEVER_MASSES`:
    the centre of mass and the total mass, ``[x, y, M]`` (Goldman §14.3).
    """
    got, problem = read_points(answer, "your answer", ask="the centre of mass and the total mass as [x, y, M]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three numbers [x, y, M], the centre of mass and the total mass; yours has shape "
                     f"{got.shape}.")
    right, slips = _lever_answers()
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"the sum is the mass-point at {fmt(right[:2])} with total mass {fmt(right[2])}.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your answer {why}")
    if np.allclose(got, np.r_[right[2], right[:2]], atol=1e-6, rtol=1e-4) and not np.allclose(got, right):
        return wrong("your numbers are in the order [M, x, y]: the answer is [x, y, M], the centre of mass first "
                     "and the total mass last.")
    for why, value in slips.items():          # the same slip in the point, with another mass
        if np.allclose(got[:2], value[:2], atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    if np.isclose(got[2], sum(abs(m) for m in LEVER_MASSES), atol=1e-6):
        return wrong("your total mass drops the sign of the negative mass: the total mass is the sum of the masses "
                     "WITH their signs (a negative mass counts negatively).")
    if not np.isclose(got[2], right[2], atol=1e-6):
        return wrong(f"the total mass M is {off_by(got[2], right[2])}. Hint: M is the sum of the masses, with "
                     f"their signs.")
    return wrong(f"the mass is right; your centre of mass is {far_off(got[:2], right[:2])}"
                 f". Hint: add the mass-points (m P, m) coordinate by coordinate, then divide by the "
                 f"total mass.")


# -- exercise 2: point or vector ---------------------------------------------------------------------

def _classify(masses) -> list[str]:
    return ["vector" if sum(c * masses[k] for k, c in coeffs.items()) == 0 else "point" for _, coeffs in COMBINATIONS]


def _kinds():
    right = _classify(COMBO_MASSES)
    coefficient_sum = ["vector" if sum(coeffs.values()) == 0 else "point" for _, coeffs in COMBINATIONS]
    vector_as_point = _classify({**COMBO_MASSES, "v": 1})
    negative_not_point = ["vector" if sum(c * COMBO_MASSES[k] for k, c in coeffs.items()) <= 0 else "point"
                          for _, coeffs in COMBINATIONS]
    slips = {
        "you summed the coefficients, not the masses: the mass of c1 A + c2 B + ... is c1 mA + c2 mB + ..., "
        "and a combination is a vector exactly when that total mass is 0.": coefficient_sum,
        "you gave the vector v a mass of 1: a vector is a mass-point of mass 0, (v, 0); adding it changes the "
        "position, not the mass.": vector_as_point,
        "you took a negative total mass for a vector: a mass-point may have a negative mass and is still a point; "
        "only a total mass of exactly 0 gives a vector.": negative_not_point,
    }
    return right, slips


def _read_words(answer, n) -> tuple[list[str] | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered("a list of six words 'point' or 'vector'")
    if isinstance(answer, str) or not isinstance(answer, (list, tuple)):
        return None, wrong(f"the answer is a list of {n} words, each 'point' or 'vector'; you gave {quote(answer)}.")
    words = [w.strip().lower() if isinstance(w, str) else None for w in answer]
    if len(words) != n or any(w not in ("point", "vector") for w in words):
        return None, wrong(f"the answer is a list of {n} words, each 'point' or 'vector', one per combination; you "
                           f"gave {quote(answer)}.")
    return words, None


def check_point_or_vector(answer) -> Result:
    """Exercise 2: which combinations of :data:`COMBINATIONS` are points and which vectors: a
    vector exactly when the total mass is 0 (Goldman §14.3).
    """
    words, problem = _read_words(answer, len(COMBINATIONS))
    if problem is not None:
        return problem
    right, slips = _kinds()
    if words == right:
        masses = [sum(c * COMBO_MASSES[k] for k, c in coeffs.items()) for _, coeffs in COMBINATIONS]
        return correct(f"the total masses are {', '.join(str(m) for m in masses)}: a vector exactly where the masses "
                       f"cancel (a negative mass is still a point).")
    for why, value in slips.items():
        if words == value:
            return wrong(why)
    bad = sum(w != r for w, r in zip(words, right))
    checks = ["did you sum the coefficients instead of the masses?", "did you give the vector v a mass?",
              "did you take a negative total mass for a vector?"]
    hints = [check for check, value in zip(checks, slips.values())
             if any(w == v != r for w, v, r in zip(words, value, right))]
    return wrong(f"answers not right: {bad} of {len(right)}. Hint: for each combination add up coefficient × mass "
                 f"(a vector has mass 0); total 0 means a vector." + (" Check: " + " ".join(hints) if hints else ""))


# -- exercise 3: the same projective point? ----------------------------------------------------------

def _same_answers():
    right = [bool(mp.same_projective_point(a, b)) for a, b in TUPLE_PAIRS]
    positive_only = [bool(mp.same_projective_point(a, b)) and float(np.dot(a, b)) > 0 for a, b in TUPLE_PAIRS]
    ignore_w = [bool(mp.same_projective_point(a[:3], b[:3])) for a, b in TUPLE_PAIRS]
    identical = [tuple(a) == tuple(b) for a, b in TUPLE_PAIRS]
    # the mass-point reading of w = 0: two vectors, equal only if identical (not the projective reading)
    vectors_apart = [bool(mp.same_projective_point(a, b)) if a[3] != 0 or b[3] != 0 else tuple(a) == tuple(b)
                     for a, b in TUPLE_PAIRS]
    slips = {
        "you allowed only positive scale factors: (x, y, z, w) and c (x, y, z, w) are the same projective point "
        "for EVERY c ≠ 0, negative too (a mass-point with mass -1 is the same point as with mass 1).": positive_only,
        "you compared x, y, z and ignored w: two tuples are the same point only if ALL four coordinates are "
        "proportional, with the same factor (divide by w first when w ≠ 0).": ignore_w,
        "you asked for equal coordinates: that is equality in the space of mass-points (same point AND same mass); "
        "projective space forgets the mass, so proportional tuples are one point.": identical,
        "you compared the tuples with w = 0 as mass-points, that is as vectors, which are equal only when they are "
        "identical; in projective space a tuple with w = 0 is a point at infinity, and the same rule holds there: "
        "proportional tuples (any nonzero factor) are one point.": vectors_apart,
    }
    return right, slips


def check_same_projective_point(answer) -> Result:
    """Exercise 3: for each pair of :data:`TUPLE_PAIRS`, whether the tuples are proportional, the
    same projective point (Goldman §14.2).  answer: five booleans.
    """
    if is_unanswered(answer):
        return unanswered("a list of five True/False")
    n = len(TUPLE_PAIRS)
    if not isinstance(answer, (list, tuple)) or len(answer) != n or not all(isinstance(a, (bool, np.bool_))
                                                                             for a in answer):
        return wrong(f"the answer is a list of {n} booleans True/False, one per pair; you gave {quote(answer)}.")
    got = [bool(a) for a in answer]
    right, slips = _same_answers()
    if got == right:
        return correct("pairs 1, 3 and 4 are proportional (factors -1/2, -1/2, 1/3); pairs 2 and 5 are not.")
    for why, value in slips.items():
        if got == value:
            return wrong(why)
    bad = sum(g != r for g, r in zip(got, right))
    return wrong(f"answers not right: {bad} of {n}. Hint: two tuples are one projective point when one is a "
                 f"nonzero multiple (any sign) of the other, in all four coordinates.")


# -- exercise 4: the point at infinity of a line -----------------------------------------------------

def check_point_at_infinity(answer) -> Result:
    """Exercise 4: the point at infinity of the line :data:`LINE`: ``w = 0`` and ``(x, y)`` a
    direction of the line, up to a nonzero factor (Goldman §14.2).

    >>> print(check_point_at_infinity([3, 2, 0]).message)
    (3, 2, 0) has w = 0, but (3, 2) is the line's NORMAL (the coefficients of x and y), perpendicular to the line: a point at infinity of a line is the direction along it.
    """
    got, problem = read_points(answer, "your point", ask="the point at infinity as [x, y, w]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three homogeneous coordinates [x, y, w]; yours has shape {got.shape}.")
    if not np.any(got):
        return wrong("(0, 0, 0) is no point of projective space: the coordinates of a point are never all 0.")
    a, b, d = LINE
    direction = np.array([b, -a, 0.0])
    said = fmt(got)
    if bool(mp.same_projective_point(got, direction, tol=1e-8)):
        return correct(f"{said} is the line's point at infinity: w = 0 and (x, y) is a direction of the line.")
    if bool(mp.same_projective_point(got, [a, b, -d], tol=1e-8)) or bool(mp.same_projective_point(got, [a, b, d],
                                                                                                  tol=1e-8)):
        return wrong(f"{said} holds the line's coefficients: they describe the line (a point of the DUAL plane), not "
                     f"a point on it. A point on the line satisfies the equation; at infinity w = 0.")
    if abs(got[2]) > 1e-12 and np.any(got[:2]) and bool(mp.same_projective_point(got[:2], direction[:2], tol=1e-8)):
        return wrong(f"{said} has the right direction but w ≠ 0: that is an affine point (x/w, y/w), not a point "
                     f"at infinity. Points at infinity are the tuples with w = 0 (the vectors, mass 0).")
    if abs(got[2]) <= 1e-12 and bool(mp.same_projective_point(got[:2], [a, b], tol=1e-8)):
        return wrong(f"{said} has w = 0, but ({fmt(got[0])}, {fmt(got[1])}) is the line's NORMAL (the coefficients "
                     f"of x and y), perpendicular to the line: a point at infinity of a line is the direction along it.")
    if abs(got[2]) > 1e-12:
        on_line = abs(a * got[0] + b * got[1] - d * got[2]) <= 1e-8 * (1 + np.abs(got).max())
        where = "a point of the line, but an affine one" if on_line else "not even on the line"
        return wrong(f"{said} has w ≠ 0, so it is {where}; the point at infinity has w = 0. Hint: put w = 0 into "
                     f"the line's equation.")
    return wrong(f"{said} has w = 0, but it does not satisfy the line's equation with w = 0. Hint: solve "
                 f"{fmt(a)}x + {fmt(b)}y = 0 for a nonzero (x, y).")


# -- exercise 5: perspective by the law of the lever -------------------------------------------------

def _perspective_answers():
    E, (Q, N), P = np.array(PERSPECTIVE_EYE), PERSPECTIVE_PLANE, np.array(PERSPECTIVE_POINT)
    image = mp.perspective_mass(P, E, Q, N)
    right = mp.point_of(image)
    s, c = float(mp.mass_of(image)), float(mp.mass_of(mp.perspective_mass(Q, E, Q, N)))
    s0, c0 = float(P @ np.array(N)), float(np.array(Q) @ np.array(N))
    slips = {
        "swaps the masses: the mass c belongs at P and s - c at E (the heavier mass pulls the balance point towards "
        "it; here the eye is nearer the plane, so the eye gets the larger mass).":
            mp.point_of(mp.add(mp.mass_point(P, s - c), mp.mass_point(E, c))),
        "is the first three coordinates of the summed mass-point (c P + (s - c) E, s); divide by its mass to get "
        "the point.": image[:3],
        "divides by c, the mass at P; the sum's mass is the TOTAL mass c + (s - c) = s.": image[:3] / c,
        "divides by s - c, the mass at E; the sum's mass is the TOTAL mass c + (s - c) = s.": image[:3] / (s - c),
        "is the midpoint of P and E: that gives both points the same mass; here the masses are c and s - c.":
            (P + E) / 2,
        "gives E the mass c - s: the sign is wrong. The masses c and s - c add up to s, the depth of P.":
            mp.point_of(mp.add(mp.mass_point(P, c), mp.mass_point(E, c - s))),
        "measures depths from the origin: s and c are depths from the EYE, (P - E)·N and (Q - E)·N.":
            mp.point_of(mp.add(mp.mass_point(P, c0), mp.mass_point(E, s0 - c0))),
    }
    return right, slips


def check_perspective_by_lever(answer) -> Result:
    """Exercise 5: the perspective image of :data:`PERSPECTIVE_POINT` as the sum of the
    mass-points ``(cP, c)`` and ``((s - c)E, s - c)`` (Goldman §14.4).  answer: ``[x, y, z]``.
    """
    got, problem = read_points(answer, "your point", ask="the image point as [x, y, z]")
    if problem is not None:
        return problem
    right, slips = _perspective_answers()
    if got.shape == (4,) and got[3] != 0 and bool(mp.same_projective_point(got, np.append(right, 1.0), tol=1e-8)):
        return wrong("you gave a mass-point (four numbers) of the image, and it is the right one: now divide by its "
                     "mass and give the point [x, y, z].")
    if got.shape != (3,):
        return wrong(f"the image is one point [x, y, z]; yours has shape {got.shape}.")
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"the image is {fmt(right)}, on the plane and on the line EP.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    (Q, N) = PERSPECTIVE_PLANE
    off_plane = abs(float((got - np.array(Q)) @ np.array(N)))
    where = "it is not on the plane of projection" if off_plane > 1e-6 else "it is on the plane, but not on the line EP"
    return wrong(f"your point is {far_off(got, right)}; {where}. Hint: compute c and s "
                 f"first, then (c P + (s - c) E) / s.")


# -- exercise 6: pseudodepth -------------------------------------------------------------------------

def _depth_answers():
    E, (Q, N) = np.array(DEPTH_EYE), DEPTH_PLANE
    P = np.array(list(DEPTH_POINTS.values()))
    right = mp.pseudodepth(P, E, Q, N)
    s = mp.mass_of(mp.perspective_mass(P, E, Q, N))
    c = float(mp.mass_of(mp.perspective_mass(Q, E, Q, N)))
    s0, c0 = P @ np.array(N), float(np.array(Q) @ np.array(N))
    slips = {
        "are c/s, the perspective scale factor: it SHRINKS with depth (reversing the depth order); pseudodepth is "
        "1 - c/s, which grows with depth.": c / s,
        "measure depth from the origin: s and c are depths from the EYE, (P - E)·N and (Q - E)·N.": 1 - c0 / s0,
        "are s/c, the ratio upside down; pseudodepth is 1 - c/s, between 0 (on the plane) and 1 (at infinity).": s / c,
        "are the depths s themselves; pseudodepth is 1 - c/s, between 0 (on the plane) and 1 (at infinity).": s,
        "are 1 - s/c, with the ratio upside down; pseudodepth is 1 - c/s.": 1 - s / c,
    }
    return right, slips


def check_pseudodepth(answer) -> Result:
    """Exercise 6: the pseudodepths ``1 - c/s`` of :data:`DEPTH_POINTS` (Goldman §14.4).
    answer: ``[dA, dB, dC]``.
    """
    got, problem = read_points(answer, "your pseudodepths", ask="the three pseudodepths as [dA, dB, dC]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three numbers [dA, dB, dC]; yours has shape {got.shape}.")
    right, slips = _depth_answers()
    if np.allclose(got, right, atol=1e-4, rtol=1e-4):
        return correct(f"the pseudodepths are {fmt(right)}: C is nearest, then A, then B, the order of the depths s.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-4, rtol=1e-4):
            return wrong(f"your values {why}")
    names = list(DEPTH_POINTS)
    k = int(np.argmax(np.abs(got - right) > 1e-4))
    return wrong(f"the pseudodepth of {names[k]} is {off_by(got[k], right[k])}. Hint: s = (P - E)·N is the depth of "
                 f"P in front of the eye, c = (Q - E)·N that of the plane; then 1 - c/s.")


# -- exercise 7: depth order by pseudodepth ----------------------------------------------------------

def _order_answers():
    E, (Q, N) = np.array(ORDER_EYE), ORDER_PLANE
    names = list(ORDER_POINTS)
    P = np.array(list(ORDER_POINTS.values()))

    def order(keys):
        return "".join(names[i] for i in np.argsort(keys, kind="stable"))

    right = order(mp.pseudodepth(P, E, Q, N))
    slips = {
        order(-mp.pseudodepth(P, E, Q, N)): "that is the order from FARTHEST to nearest (or the order of c/s, which "
                                            "shrinks with depth); pseudodepth 1 - c/s grows with depth, and the "
                                            "nearest point comes first.",
        order(np.linalg.norm(P - E, axis=1)): "that is the order of the distances |P - E| from the eye; depth, and so "
                                             "pseudodepth, is measured along the normal N of the plane: s = (P - E)·N.",
        order(P[:, 2]): "that orders the points by z; here the eye looks along N = (1, 1, 0), so depth is "
                        "s = (P - E)·N, not a coordinate.",
    }
    return right, slips


def check_depth_order(answer) -> Result:
    """Exercise 7: the points of :data:`ORDER_POINTS` from nearest to farthest by pseudodepth
    (Goldman §14.4).  answer: a string of letters such as ``"ABCD"``.
    """
    if is_unanswered(answer):
        return unanswered("the order as a string of letters such as 'ABCD'")
    if isinstance(answer, (list, tuple)) and all(isinstance(a, str) for a in answer):
        answer = "".join(answer)
    if not isinstance(answer, str):
        return wrong(f"the answer is a string of the four letters, nearest first, such as 'ABCD'; you gave {quote(answer)}.")
    letters = "".join(ch for ch in answer.upper() if ch.isalpha())
    if sorted(letters) != sorted(ORDER_POINTS):
        return wrong(f"the answer names each of the points {', '.join(ORDER_POINTS)} once, nearest first; you gave "
                     f"{quote(answer)}.")
    right, slips = _order_answers()
    if letters == right:
        return correct(f"{', '.join(right)} by pseudodepth, the order of the depths; B and D share a line of sight "
                       f"(perspective sends them to one point), and pseudodepth still tells them apart.")
    if letters in slips:
        return wrong(slips[letters])
    place = sum(a != b for a, b in zip(letters, right))
    return wrong(f"points in the wrong place: {place} of 4. Hint: compute s = (P - E)·N for each point; "
                 f"1 - c/s grows with s, so the order of the pseudodepths is the order of the depths.")


SLIPS = {
    "check_center_of_mass": [[11 / 6, 1.5, 6], [7 / 3, 1.0, 4], [1 / 3, 13 / 3, 4], [1 / 6, 13 / 6, 4], [1, 13, 4],
                             [0.25, 3.25, 6], [4, 0.25, 3.25]],
    "check_point_or_vector": [["point", "vector", "point", "point", "point", "vector"],
                              ["vector", "point", "point", "point", "vector", "point"],
                              ["vector", "point", "vector", "vector", "point", "vector"],
                              ["point", "point", "point", "vector", "point", "vector"]],
    "check_same_projective_point": [[False, False, False, True, False], [True, True, True, True, True],
                                    [False, False, False, False, False], [True, False, False, True, False]],
    "check_point_at_infinity": [[3, 2, 0], [2, -3, 1], [3, 2, -11], [1, 4, 1], [0, 0, 0], [1, 1, 0]],
    "check_perspective_by_lever": [[4, 5, 6], [24, 36, 24], [6, 9, 6], [3, 4.5, 3], [3, 4, 4], [-6, -5, -14],
                                   [1.2, 2.2, 0.4], [2, 3, 2, 1]],
    "check_pseudodepth": [[0.5, 0.25, 0.8], [4 / 7, 0.8, 0.25], [2, 4, 1.25], [8, 16, 5], [-1, -3, -0.25]],
    "check_depth_order": ["CDAB", "BDAC", "DBCA", "ABCD"],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
