"""Exercise checkers for chapter 11, applications of vector geometry (Goldman §11.2-11.7).

Every exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is
the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow
the current instance. The chapter's "show that" exercises (9 and 10, in
:mod:`goldman_lib.exercises.proofs`) ask for an identity, not a number, so they do not deal.
``SLIPS`` holds the wrong answers of the kinds each checker recognises, for the stored instance.

>>> print(PROBLEMS["check_law_of_cosines"])
A triangle has sides a = 5 and b = 8 with the angle γ = 60° between them. Give the third side c (Goldman §11.2).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import vector_geometry as vg
from goldman_lib import vectors
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, fmt_points, off_by, read_number, read_points, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, memo, plain as _tup

__all__ = ["PROBLEMS", "SLIPS", "TRIANGLE", "PLANE_POINT", "PLANE_NORMAL", "QUERY_POINT", "LINE1", "LINE2",
           "POLYGON_3D", "TETRAHEDRON", "PLANES", "WINDING_POLYGON", "WINDING_QUERY", "SLERP_V0", "SLERP_V1", "SLERP_T",
           "DECK", "deal", "steps", "current", "deal_button",
           "check_law_of_cosines", "check_point_plane_distance", "check_line_line_distance", "check_newell_area",
           "check_tetrahedron_volume", "check_three_planes", "check_winding_number", "check_slerp"]

#: Exercise 1: sides a, b and the angle γ between them (degrees).
TRIANGLE = (5.0, 8.0, 60.0)
#: Exercise 2: the plane through PLANE_POINT with normal PLANE_NORMAL, and the point QUERY_POINT.
PLANE_POINT = np.array([1.0, 0.0, 0.0])
PLANE_NORMAL = np.array([2.0, -1.0, 2.0])
QUERY_POINT = np.array([2.0, 3.0, -4.0])
#: Exercise 3: the lines p1 + s d1 and p2 + t d2, each as (point, direction).
LINE1 = (np.array([1.0, 0.0, 0.0]), np.array([1.0, 1.0, 0.0]))
LINE2 = (np.array([0.0, 2.0, 3.0]), np.array([1.0, 0.0, 1.0]))
#: Exercise 4: an L-shaped hexagon in the plane z = x + y.
POLYGON_3D = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 3.0], [3.0, 2.0, 5.0], [1.0, 2.0, 3.0], [1.0, 4.0, 5.0],
                       [0.0, 4.0, 4.0]])
#: Exercise 5: the vertices P0, P1, P2, P3 of a tetrahedron.
TETRAHEDRON = np.array([[1.0, 0.0, 1.0], [3.0, 1.0, 1.0], [1.0, 4.0, 2.0], [2.0, 1.0, 5.0]])
#: Exercise 6: three planes N·X = c as (N, c).
PLANES = ((np.array([1.0, 1.0, 1.0]), 6.0), (np.array([1.0, -1.0, 2.0]), 5.0), (np.array([2.0, 1.0, -1.0]), 1.0))
#: Exercise 7: a self-intersecting octagon that winds twice around its middle, and the query point.
WINDING_POLYGON = np.array([[0.0, 0.0], [6.0, 0.0], [6.0, 6.0], [1.0, 6.0], [1.0, 1.0], [5.0, 1.0], [5.0, 5.0],
                            [0.0, 5.0]])
WINDING_QUERY = np.array([3.0, 3.0])
#: Exercise 8: slerp between two unit vectors 90° apart, at t = 1/3.
SLERP_V0 = np.array([1.0, 0.0, 0.0])
SLERP_V1 = np.array([0.0, 1.0, 1.0]) / np.sqrt(2)
SLERP_T = 1 / 3

_TOL = 1e-3   # answers worked with a calculator to four decimals are accepted

DECK = Deck("ch11")


def _plane_text(N, c) -> str:
    terms = []
    for coef, var in zip(N, "xyz"):
        if coef == 0:
            continue
        sign = "-" if coef < 0 else "+"
        mag = "" if abs(coef) == 1 else fmt(abs(coef))
        terms.append((sign, f"{mag}{var}"))
    text = ("-" if terms[0][0] == "-" else "") + terms[0][1]
    for sign, term in terms[1:]:
        text += f" {sign} {term}"
    return f"{text} = {fmt(c)}"


def _as_point_plane(N, c):
    """(a point, the normal) of the plane N·X = c: the point c N / N·N."""
    return c * N / float(N @ N), N


def _is(value, target, tol=_TOL) -> bool:
    return abs(float(value) - float(target)) <= tol * max(1.0, abs(float(target)))


def _same_number(a, b) -> bool:
    return _is(a, b)


def _same_point(a, b) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, atol=_TOL))


def _arr(v):
    return np.asarray(v, dtype=float)


def _f6(x) -> str:
    """A number of the worked steps, to six digits (enough for the checker's tolerance)."""
    return fmt(x, 6)


def _r(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return np.round(np.asarray(x, dtype=float), 6) + 0.0


# -- §11.2 ------------------------------------------------------------------------------------------
_STORED_LAW = {"a": TRIANGLE[0], "b": TRIANGLE[1], "gamma": TRIANGLE[2]}


@memo
def _law_answers(p):
    a, b, g = p["a"], p["b"], p["gamma"]
    expected = vg.law_of_cosines(a, b, g)
    slips = {"sign": float(np.sqrt(a * a + b * b + 2 * a * b * np.cos(np.radians(g)))),
             "c squared": float(expected ** 2),
             "radians": float(np.sqrt(max(a * a + b * b - 2 * a * b * np.cos(g), 0)))}
    return float(expected), slips


def _law_generate(rng) -> dict:
    return {"a": float(rng.integers(2, 13)), "b": float(rng.integers(2, 13)),
            "gamma": float(rng.choice([30.0, 45.0, 60.0, 120.0, 135.0, 150.0]))}


def _law_statement(p) -> str:
    return (f"A triangle has sides a = {fmt(p['a'])} and b = {fmt(p['b'])} with the angle γ = {fmt(p['gamma'])}° "
            f"between them. Give the third side c (Goldman §11.2).")


def _law_steps(p) -> str:
    a, b, g = p["a"], p["b"], p["gamma"]
    c2 = a * a + b * b - 2 * a * b * np.cos(np.radians(g))
    return (f"1. cos {fmt(g)}° = {_f6(_r(np.cos(np.radians(g))))}.\n"
            f"2. c² = a² + b² - 2ab cos γ = {fmt(a * a)} + {fmt(b * b)} - {fmt(2 * a * b)} cos γ = {_f6(_r(c2))}.\n"
            f"3. c = √c² = {_f6(_r(np.sqrt(c2)))}.")


@DECK.exercise(stored=_STORED_LAW, generate=_law_generate, answer=lambda p: _law_answers(p)[0],
               slips=lambda p: _law_answers(p)[1], statement=_law_statement, steps=_law_steps,
               same=_same_number, well_posed=lambda p: None if p["gamma"] != 90 else "a right angle: the cosine "
               "term vanishes and its sign could not be told")
def check_law_of_cosines(answer, p) -> Result:
    """Check the third side of the statement's triangle (Goldman §11.2).  Recognises the sign of
    the cosine term flipped, c² given instead of c, and the angle taken in radians."""
    what = "the third side c"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    a, b, g = p["a"], p["b"], p["gamma"]
    expected = vg.law_of_cosines(a, b, g)
    if _is(value, expected):
        return correct(f"c² = a² + b² - 2ab cos γ gives {what} = {fmt(expected)}.")
    if _is(value, np.sqrt(a * a + b * b + 2 * a * b * np.cos(np.radians(g)))):
        if g < 90:
            return wrong("the cosine term has the wrong sign: |u - v|² = |u|² + |v|² - 2 u·v, so c² = a² + b² - 2ab "
                         "cos γ; an angle below 90° makes c shorter than the hypotenuse of a right triangle.")
        return wrong("the cosine term has the wrong sign: |u - v|² = |u|² + |v|² - 2 u·v, so c² = a² + b² - 2ab "
                     "cos γ; an angle above 90° makes c longer than the hypotenuse of a right triangle.")
    if _is(value, expected ** 2):
        return wrong("that is c², not c: take the square root.")
    if _is(value, np.sqrt(max(a * a + b * b - 2 * a * b * np.cos(g), 0))):
        return wrong(f"your calculator took γ = {fmt(g)} in radians; set it to degrees.")
    return wrong(f"{what} is {off_by(value, expected)}. Check c² = a² + b² - 2ab cos γ with cos {fmt(g)}°.")


# -- §11.4 ------------------------------------------------------------------------------------------
_STORED_PLANE = {"Q": _tup(QUERY_POINT), "P": _tup(PLANE_POINT), "N": _tup(PLANE_NORMAL)}
#: normals of whole length (hand-friendly |N|), none a unit vector
_NORMALS = ((1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (2.0, 2.0, 1.0), (2.0, 3.0, 6.0), (3.0, 6.0, 2.0), (6.0, 2.0, 3.0),
            (1.0, 4.0, 8.0), (4.0, 4.0, 7.0), (0.0, 3.0, 4.0), (4.0, 0.0, 3.0))


@memo
def _plane_answers(p):
    Q, P, N = _arr(p["Q"]), _arr(p["P"]), _arr(p["N"])
    expected = float(vg.point_plane_distance(Q, P, N))
    raw = float((Q - P) @ N)
    slips = {"signed": float(vg.point_plane_distance(Q, P, N, signed=True)), "not divided": abs(raw),
             "divided by N·N": abs(raw) / float(N @ N), "to the point": float(np.linalg.norm(Q - P))}
    return expected, slips


def _plane_generate(rng) -> dict:
    N = np.array(_NORMALS[int(rng.integers(0, len(_NORMALS)))]) * rng.choice([-1.0, 1.0], size=3)
    return {"Q": _ints(rng, -5, 5, 3), "P": _ints(rng, -3, 3, 3), "N": _tup(N)}


def _plane_ok(p):
    if vg.point_plane_distance(_arr(p["Q"]), _arr(p["P"]), _arr(p["N"]), signed=True) >= 0:
        return "Q lies on the side N points to (or on the plane): the signed distance would be right"
    return None


def _plane_statement(p) -> str:
    return (f"Give the distance from the point Q = {fmt(p['Q'])} to the plane through P = {fmt(p['P'])} with "
            f"normal N = {fmt(p['N'])} (Goldman §11.4). A distance is not negative.")


def _plane_steps(p) -> str:
    Q, P, N = _arr(p["Q"]), _arr(p["P"]), _arr(p["N"])
    raw = float((Q - P) @ N)
    return (f"1. Q - P = {fmt(Q - P)}.\n"
            f"2. (Q - P)·N = {fmt(raw)}.\n"
            f"3. |N| = √(N·N) = √{fmt(N @ N)} = {_f6(_r(np.linalg.norm(N)))}.\n"
            f"4. The signed distance is {fmt(raw)} / {_f6(_r(np.linalg.norm(N)))} = "
            f"{_f6(_r(raw / np.linalg.norm(N)))}; the distance is its absolute value.")


@DECK.exercise(stored=_STORED_PLANE, generate=_plane_generate, answer=lambda p: _plane_answers(p)[0],
               slips=lambda p: _plane_answers(p)[1], statement=_plane_statement, steps=_plane_steps,
               same=_same_number, well_posed=_plane_ok)
def check_point_plane_distance(answer, p) -> Result:
    """Check the distance from the statement's point Q to its plane (Goldman §11.4).  Recognises
    the signed distance, (Q - P)·N not divided by |N|, a division by |N|² and the distance |Q - P| to P."""
    what = "the distance"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    Q, P, N = _arr(p["Q"]), _arr(p["P"]), _arr(p["N"])
    expected = vg.point_plane_distance(Q, P, N)
    signed = vg.point_plane_distance(Q, P, N, signed=True)
    raw = float((Q - P) @ N)
    side = "away from" if signed < 0 else "towards"
    if _is(value, expected):
        return correct(f"|(Q - P)·N| / |N| = {fmt(expected)}; Q lies on the side the normal points {side}.")
    if _is(value, signed):
        return wrong("that is the signed distance (Q - P)·N / |N|: its sign says which side of the plane Q is on "
                     "(here the side away from N). A distance is its absolute value.")
    if _is(abs(value), abs(raw)):
        return wrong("you did not divide by |N|: (Q - P)·N is the distance times the length of the normal, and this "
                     "N is not a unit vector.")
    if _is(abs(value), abs(raw) / float(N @ N)):
        return wrong("you divided by |N|² = N·N; divide (Q - P)·N by the length |N| once.")
    if _is(value, float(np.linalg.norm(Q - P))):
        return wrong("that is the distance from Q to the point P; the plane comes closer. Project Q - P on the unit "
                     "normal: (Q - P)·N / |N|.")
    return wrong(f"{what} is {off_by(value, expected)}. Check Q - P and its dot product with N, then divide by |N|.")


_STORED_LINES = {"p1": _tup(LINE1[0]), "d1": _tup(LINE1[1]), "p2": _tup(LINE2[0]), "d2": _tup(LINE2[1])}


@memo
def _lines_answers(p):
    p1, d1, p2, d2 = (_arr(p[k]) for k in ("p1", "d1", "p2", "d2"))
    expected = float(vg.line_line_distance(p1, d1, p2, d2))
    c = vectors.cross(d1, d2)
    triple = abs(float((p2 - p1) @ c))
    slips = {"negative": -expected, "not normalised": triple, "divided by |c|²": triple / float(c @ c),
             "divided by |d1| |d2|": triple / float(np.linalg.norm(d1) * np.linalg.norm(d2)),
             "between the points": float(np.linalg.norm(p2 - p1))}
    return expected, slips


def _lines_generate(rng) -> dict:
    return {"p1": _ints(rng, -3, 3, 3), "d1": _ints(rng, -2, 2, 3), "p2": _ints(rng, -3, 3, 3),
            "d2": _ints(rng, -2, 2, 3)}


def _lines_ok(p):
    d1, d2 = _arr(p["d1"]), _arr(p["d2"])
    c = vectors.cross(d1, d2)
    if float(c @ c) < 0.5:
        return "the lines are parallel (or a direction is zero)"
    if abs(float((_arr(p["p2"]) - _arr(p["p1"])) @ c)) < 0.5:
        return "the lines meet: the distance would be 0"
    return None


def _lines_statement(p) -> str:
    return (f"Give the distance between the lines L1 = {fmt(p['p1'])} + s {fmt(p['d1'])} and "
            f"L2 = {fmt(p['p2'])} + t {fmt(p['d2'])} (Goldman §11.4), to 3 decimals or better.")


def _lines_steps(p) -> str:
    p1, d1, p2, d2 = (_arr(p[k]) for k in ("p1", "d1", "p2", "d2"))
    c = vectors.cross(d1, d2)
    dot = float((p2 - p1) @ c)
    return (f"1. The common perpendicular: d1 × d2 = {fmt(c)}, |d1 × d2| = √{fmt(c @ c)}.\n"
            f"2. p2 - p1 = {fmt(p2 - p1)}; (p2 - p1)·(d1 × d2) = {fmt(dot)}.\n"
            f"3. The distance is |{fmt(dot)}| / √{fmt(c @ c)} = {_f6(_r(abs(dot) / np.sqrt(c @ c)))}.")


@DECK.exercise(stored=_STORED_LINES, generate=_lines_generate, answer=lambda p: _lines_answers(p)[0],
               slips=lambda p: _lines_answers(p)[1], statement=_lines_statement, steps=_lines_steps,
               same=_same_number, well_posed=_lines_ok)
def check_line_line_distance(answer, p) -> Result:
    """Check the distance between the statement's lines L1 and L2 (Goldman §11.4).  Recognises
    |(p2 - p1)·(d1 × d2)| without dividing by |d1 × d2|, a division by |d1 × d2|², a division by
    |d1| |d2|, the distance between the two given points and a negative (signed) answer."""
    what = "the distance between the lines"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    p1, d1, p2, d2 = (_arr(p[k]) for k in ("p1", "d1", "p2", "d2"))
    expected = vg.line_line_distance(p1, d1, p2, d2)
    c = vectors.cross(d1, d2)
    triple = abs(float((p2 - p1) @ c))
    if _is(value, expected):
        return correct(f"{what} is |(p2 - p1)·(d1 × d2)| / |d1 × d2| = {fmt(expected)}.")
    if _is(value, -expected):
        return wrong("a distance is not negative: take the absolute value of (p2 - p1)·(d1 × d2).")
    if _is(abs(value), triple):
        return wrong("you did not normalise: d1 × d2 is perpendicular to both lines but not a unit vector, so divide "
                     "(p2 - p1)·(d1 × d2) by |d1 × d2|.")
    if _is(abs(value), triple / float(c @ c)):
        return wrong("you divided by |d1 × d2|²; the unit normal is (d1 × d2) / |d1 × d2|, one division by the "
                     "length.")
    if _is(abs(value), triple / float(np.linalg.norm(d1) * np.linalg.norm(d2))):
        return wrong("you divided by |d1| |d2|; |d1 × d2| = |d1| |d2| sin θ, and these directions are not "
                     "perpendicular. Divide by the length of the cross product.")
    if _is(value, float(np.linalg.norm(p2 - p1))):
        return wrong("that is the distance between the two given points p1 and p2, not between the lines; project "
                     "p2 - p1 on the common perpendicular d1 × d2.")
    return wrong(f"{what} is {off_by(value, expected)}. Check d1 × d2, then (p2 - p1)·(d1 × d2) and |d1 × d2|.")


def _z_plane_text(a, b, c) -> str:
    terms = [(coef, var) for coef, var in ((a, "x"), (b, "y")) if coef != 0]
    text = ""
    for coef, var in terms:
        mag = "" if abs(coef) == 1 else fmt(abs(coef))
        if not text:
            text = ("-" if coef < 0 else "") + f"{mag}{var}"
        else:
            text += f" {'-' if coef < 0 else '+'} {mag}{var}"
    if c:
        text = f"{text} {'-' if c < 0 else '+'} {fmt(abs(c))}" if text else fmt(c)
    return f"z = {text or '0'}"


_STORED_NEWELL = {"polygon": _tup(POLYGON_3D), "plane": (1.0, 1.0, 0.0)}


@memo
def _newell_answers(p):
    poly = _arr(p["polygon"])
    N = vg.newell_normal(poly)
    expected = float(vg.polygon_area(poly))
    slips = {"|N|": 2 * expected, "the shadow": abs(float(N[2])) / 2, "the components added": float(np.abs(N).sum()) / 2}
    return expected, slips


def _newell_generate(rng) -> dict:
    w, h = int(rng.integers(2, 6)), int(rng.integers(3, 6))
    k, h1 = int(rng.integers(1, w)), int(rng.integers(1, h))
    x0, y0 = _ints(rng, -2, 2, 2)
    xy = [(0, 0), (w, 0), (w, h1), (k, h1), (k, h), (0, h)]
    if rng.integers(0, 2):
        xy = xy[::-1]
    a, b = (float(v) for v in rng.integers(-2, 3, size=2))
    c = float(rng.integers(-2, 3))
    pts = tuple((x0 + x, y0 + y, a * (x0 + x) + b * (y0 + y) + c) for x, y in xy)
    return {"polygon": tuple(tuple(float(v) for v in q) for q in pts), "plane": (a, b, c)}


def _newell_ok(p):
    a, b, _ = p["plane"]
    if (a, b) == (0, 0):
        return "the plane is horizontal: the polygon is its own shadow"
    N = np.abs(vg.newell_normal(_arr(p["polygon"])))
    forms = [np.linalg.norm(N) / 2, np.linalg.norm(N), N[2] / 2, N[2], N.sum() / 2, N.sum()]
    if any(_is(u, v) for i, u in enumerate(forms) for v in forms[i + 1:]):
        return "two of the recognised forms (the shadow, the summed components, with or without 1/2) coincide"
    return None


def _newell_statement(p) -> str:
    return (f"The hexagon with vertices {fmt_points(p['polygon'])} (in this order) lies in the plane "
            f"{_z_plane_text(*p['plane'])}. Give its area by Newell's formula (Goldman §11.4), to 3 decimals or better.")


def _newell_steps(p) -> str:
    poly = _arr(p["polygon"])
    N = vg.newell_normal(poly)
    return (f"1. Newell's normal N = Σ P_i × P_(i+1), the last edge back to the first vertex included: "
            f"N = {_f6(_r(N))}.\n"
            f"2. |N| = √(N·N) = √{_f6(_r(N @ N))} = {_f6(_r(np.linalg.norm(N)))}.\n"
            f"3. The area is |N| / 2 = {_f6(_r(np.linalg.norm(N) / 2))}.")


@DECK.exercise(stored=_STORED_NEWELL, generate=_newell_generate, answer=lambda p: _newell_answers(p)[0],
               slips=lambda p: _newell_answers(p)[1], statement=_newell_statement, steps=_newell_steps,
               same=_same_number, well_posed=_newell_ok)
def check_newell_area(answer, p) -> Result:
    """Check the area of the statement's polygon in space (Goldman §11.4).  Recognises |N| without the 1/2, the area
    of the shadow on the xy-plane (|N_z| / 2 or |N_z|) and the sum of the projected areas."""
    what = "the area"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    poly = _arr(p["polygon"])
    N = vg.newell_normal(poly)
    expected = vg.polygon_area(poly)
    if _is(value, expected):
        return correct(f"N = Σ P_i × P_(i+1) = {fmt(N)} and {what} is |N| / 2 = {fmt(expected)}.")
    if _is(value, 2 * expected):
        return wrong("that is |N|, twice the area: Newell's sum adds cross products, each twice a triangle's area; "
                     "halve it.")
    if _is(value, abs(N[2]) / 2) or _is(value, abs(N[2])):
        return wrong("that is (up to the factor 1/2) the area of the polygon's shadow on the xy-plane, the z "
                     "component of N alone; the polygon is tilted, so use all three components: |N| / 2.")
    if _is(value, np.abs(N).sum() / 2) or _is(value, np.abs(N).sum()):
        return wrong("you added the three components of N; the area is half the length of N, "
                     "sqrt(N_x² + N_y² + N_z²) / 2 (the projected areas combine like the sides of a box's "
                     "diagonal, not by adding).")
    return wrong(f"{what} is {off_by(value, expected)}. Check each component of Σ P_i × P_(i+1) "
                 f"(N_x = Σ (y_i z_(i+1) - z_i y_(i+1)), and so on), including the last edge back to the first vertex.")


_STORED_TET = {"T": _tup(TETRAHEDRON)}


@memo
def _tet_answers(p):
    P0, P1, P2, P3 = _arr(p["T"])
    expected = float(vg.tetrahedron_volume(P0, P1, P2, P3))
    box = float(vg.parallelepiped_volume(P1 - P0, P2 - P0, P3 - P0))
    return expected, {"signed": -expected, "the box": box, "halved": box / 2, "a third": box / 3}


def _tet_generate(rng) -> dict:
    return {"T": tuple(_ints(rng, -1, 4, 3) for _ in range(4))}


def _tet_ok(p):
    P0, P1, P2, P3 = _arr(p["T"])
    return None if abs(vectors.det(P1 - P0, P2 - P0, P3 - P0)) >= 1 else "the four points lie in one plane"


def _tet_statement(p) -> str:
    return (f"Give the volume of the tetrahedron with vertices {fmt_points(p['T'])} (Goldman §11.4), to 3 decimals "
            f"or better.")


def _tet_steps(p) -> str:
    P0, P1, P2, P3 = _arr(p["T"])
    d = float(vectors.det(P1 - P0, P2 - P0, P3 - P0))
    return (f"1. The edges from P0: P1 - P0 = {fmt(P1 - P0)}, P2 - P0 = {fmt(P2 - P0)}, P3 - P0 = {fmt(P3 - P0)}.\n"
            f"2. det(P1 - P0, P2 - P0, P3 - P0) = ((P1 - P0) × (P2 - P0))·(P3 - P0) = {_f6(_r(d))}.\n"
            f"3. The volume is |det| / 6 = {_f6(_r(abs(d) / 6))}.")


@DECK.exercise(stored=_STORED_TET, generate=_tet_generate, answer=lambda p: _tet_answers(p)[0],
               slips=lambda p: _tet_answers(p)[1], statement=_tet_statement, steps=_tet_steps,
               same=_same_number, well_posed=_tet_ok)
def check_tetrahedron_volume(answer, p) -> Result:
    """Check the volume of the statement's tetrahedron (Goldman §11.4).  Recognises the parallelepiped's volume
    (the 1/6 left out), the factor 1/2 of a triangle's area, the factor 1/3 of a pyramid over the
    parallelogram, and a negative (signed) volume."""
    what = "the volume"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    P0, P1, P2, P3 = _arr(p["T"])
    expected = vg.tetrahedron_volume(P0, P1, P2, P3)
    box = vg.parallelepiped_volume(P1 - P0, P2 - P0, P3 - P0)
    if _is(value, expected):
        return correct(f"{what} is |det(P1 - P0, P2 - P0, P3 - P0)| / 6 = {fmt(expected)}.")
    if _is(value, -expected):
        return wrong("a volume is not negative: det(P1 - P0, P2 - P0, P3 - P0) is a signed volume (its sign says "
                     "whether the edges are right- or left-handed); take its absolute value.")
    if _is(abs(value), box):
        return wrong("that is the volume of the parallelepiped on the three edges from P0; the tetrahedron fills "
                     "one sixth of it.")
    if _is(abs(value), box / 2):
        return wrong("you halved the determinant as for a triangle's area; in 3D the tetrahedron is one sixth of "
                     "the parallelepiped (a third of a prism that is half the box).")
    if _is(abs(value), box / 3):
        return wrong("one third of base times height is right for a pyramid, but the base here is the triangle "
                     "P0 P1 P2, half of the parallelogram whose area |(P1 - P0) × (P2 - P0)| measures: divide the "
                     "determinant by 6.")
    return wrong(f"{what} is {off_by(value, expected)}. Check the three edge vectors from P0 and the determinant "
                 "(P1 - P0) × (P2 - P0) · (P3 - P0).")


# -- §11.5 ------------------------------------------------------------------------------------------
_STORED_PLANES = {"planes": tuple((_tup(N), float(c)) for N, c in PLANES)}


def _planes_of(p):
    return [(_arr(N), float(c)) for N, c in p["planes"]]


@memo
def _planes_answers(p):
    planes = _planes_of(p)
    expected = vg.intersect_three_planes(*[_as_point_plane(N, c) for N, c in planes])
    d = float(vectors.det(*(N for N, _ in planes)))
    return expected, {"not divided": d * expected, "sign": -expected}


def _planes_generate(rng) -> dict:
    X = np.array(_ints(rng, -3, 3, 3))
    Ns = rng.integers(-2, 3, size=(3, 3)).astype(float)
    return {"planes": tuple((_tup(N), float(N @ X)) for N in Ns)}


def _planes_ok(p):
    M = np.array([N for N, _ in _planes_of(p)])
    if any(not np.any(N) for N in M) or abs(np.linalg.det(M)) < 1.5 or np.linalg.cond(M) > 30:
        return "the normals are (nearly) dependent, or det(N1, N2, N3) is ±1 (a slip would be right)"
    return None


def _planes_statement(p) -> str:
    return ("Give the point where the three planes " + ", ".join(_plane_text(N, c) for N, c in _planes_of(p))
            + " meet, as [x, y, z] (Goldman §11.5).")


def _planes_steps(p) -> str:
    (N1, c1), (N2, c2), (N3, c3) = _planes_of(p)
    d = float(vectors.det(N1, N2, N3))
    num = c1 * np.cross(N2, N3) + c2 * np.cross(N3, N1) + c3 * np.cross(N1, N2)
    return (f"1. N2 × N3 = {fmt(np.cross(N2, N3))}, N3 × N1 = {fmt(np.cross(N3, N1))}, "
            f"N1 × N2 = {fmt(np.cross(N1, N2))}.\n"
            f"2. det(N1, N2, N3) = (N1 × N2)·N3 = {fmt(d)}.\n"
            f"3. c1 (N2 × N3) + c2 (N3 × N1) + c3 (N1 × N2) = {fmt(num)}.\n"
            f"4. Divide by the determinant: X = {_f6(_r(num / d))}; check it in each equation.")


@DECK.exercise(stored=_STORED_PLANES, generate=_planes_generate, answer=lambda p: _planes_answers(p)[0],
               slips=lambda p: _planes_answers(p)[1], statement=_planes_statement, steps=_planes_steps,
               same=_same_point, well_posed=_planes_ok)
def check_three_planes(answer, p) -> Result:
    """Check the common point of the statement's three planes (Goldman §11.5).  Recognises the point not divided by
    det(N1, N2, N3), the wrong sign of the determinant, and a point on some planes but not all (it
    names the planes it misses)."""
    what = "the common point"
    got, problem = read_points(answer, what, ask="the point [x, y, z]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"{what} should be one point [x, y, z]; yours has shape {got.shape}.")
    PLANES = _planes_of(p)
    planes = [_as_point_plane(N, c) for N, c in PLANES]
    expected = vg.intersect_three_planes(*planes)
    N1, N2, N3 = (N for N, _ in PLANES)
    d = float(vectors.det(N1, N2, N3))
    if np.allclose(got, expected, atol=_TOL):
        return correct(f"{what} lies on all three planes.")
    if np.allclose(got, d * expected, atol=_TOL):
        return wrong("you left out the division by det(N1, N2, N3): the numerator "
                     "c1 (N2 × N3) + c2 (N3 × N1) + c3 (N1 × N2) is det times the point.")
    if np.allclose(got, -expected, atol=_TOL):
        return wrong("the sign is flipped: check the sign of det(N1, N2, N3) = (N1 × N2)·N3, and the cyclic order "
                     "N2 × N3, N3 × N1, N1 × N2 in the numerator.")
    names = ["first", "second", "third"]
    misses = [names[k] for k, (N, c) in enumerate(PLANES) if abs(float(N @ got) - c) > _TOL * max(1.0, abs(c))]
    if len(misses) < 3:
        return wrong(f"your point lies on {['no', 'one', 'two'][len(PLANES) - len(misses)]} of the planes but not on the "
                     f"{' and '.join(misses)} ({', '.join(_plane_text(*PLANES[names.index(m)]) for m in misses)}); "
                     f"it must satisfy all three equations.")
    return wrong(f"your point is {far_off(got, expected)} from the common point and lies on "
                 "none of the planes. Check the cross products N2 × N3, N3 × N1, N1 × N2 and det(N1, N2, N3).")


# -- §11.6 ------------------------------------------------------------------------------------------
_STORED_SLERP = {"v0": _tup(SLERP_V0), "v1": _tup(SLERP_V1), "t": SLERP_T, "v0_text": "(1, 0, 0)",
                 "v1_text": "(0, 1/√2, 1/√2)", "t_text": "1/3", "theta": 90.0}
_T_TEXT = {"1/4": 0.25, "1/3": 1 / 3, "2/3": 2 / 3, "3/4": 0.75}
_T_WORDS = {"1/4": "a quarter", "1/3": "a third", "2/3": "two thirds", "3/4": "three quarters"}
#: cos and sin of the angles dealt, written exactly
_TRIG = {60.0: ("1/2", "√3/2"), 90.0: ("0", "1"), 120.0: ("-1/2", "√3/2"), 45.0: ("1/√2", "1/√2"),
         135.0: ("-1/√2", "1/√2")}


@memo
def _slerp_answers(p):
    v0, v1, t = _arr(p["v0"]), _arr(p["v1"]), p["t"]
    expected = vg.slerp(v0, v1, t)
    return expected, {"lerp": (1 - t) * v0 + t * v1, "nlerp": vg.nlerp(v0, v1, t), "swapped": vg.slerp(v0, v1, 1 - t)}


def _slerp_generate(rng) -> dict:
    theta = float(rng.choice(list(_TRIG)))
    t_text = str(rng.choice(list(_T_TEXT)))
    i, j = (int(k) for k in rng.permutation(3)[:2])
    s0, s1 = (float(s) for s in rng.choice([-1.0, 1.0], size=2))
    v0, e1 = np.zeros(3), np.zeros(3)
    v0[i], e1[j] = s0, s1
    cos_text, sin_text = _TRIG[theta]
    v1 = np.cos(np.radians(theta)) * v0 + np.sin(np.radians(theta)) * e1
    t0 = ["0"] * 3
    t0[i] = "1" if s0 > 0 else "-1"
    t1 = ["0"] * 3
    t1[i] = cos_text if s0 > 0 else (cos_text[1:] if cos_text.startswith("-") else "-" + cos_text)
    t1[j] = sin_text if s1 > 0 else "-" + sin_text
    t1 = [x if x not in ("-0",) else "0" for x in t1]
    return {"v0": _tup(v0), "v1": _tup(np.round(v1, 15) + 0.0), "t": _T_TEXT[t_text],
            "v0_text": "(" + ", ".join(t0) + ")", "v1_text": "(" + ", ".join(t1) + ")", "t_text": t_text,
            "theta": theta}


def _slerp_statement(p) -> str:
    return (f"v0 = {p['v0_text']} and v1 = {p['v1_text']} are unit vectors {fmt(p['theta'])}° apart. Give "
            f"slerp(v0, v1, t) at t = {p['t_text']} as [x, y, z] to 3 decimals or better (Goldman §11.6).")


def _slerp_steps(p) -> str:
    th, t = p["theta"], p["t"]
    w0, w1 = np.sin(np.radians((1 - t) * th)) / np.sin(np.radians(th)), np.sin(np.radians(t * th)) / np.sin(np.radians(th))
    return (f"1. cos θ = v0·v1 = {_f6(_r(np.cos(np.radians(th))))}, so θ = {fmt(th)}°.\n"
            f"2. The weights: sin((1 - t)θ)/sin θ = sin {_f6(_r((1 - t) * th))}° / sin {fmt(th)}° = {_f6(_r(w0))}, "
            f"sin(tθ)/sin θ = sin {_f6(_r(t * th))}° / sin {fmt(th)}° = {_f6(_r(w1))}.\n"
            f"3. slerp = {_f6(_r(w0))} v0 + {_f6(_r(w1))} v1 = {_f6(_r(_slerp_answers(p)[0]))}, a unit vector.")


@DECK.exercise(stored=_STORED_SLERP, generate=_slerp_generate, answer=lambda p: _slerp_answers(p)[0],
               slips=lambda p: _slerp_answers(p)[1], statement=_slerp_statement, steps=_slerp_steps,
               same=_same_point)
def check_slerp(answer, p) -> Result:
    """Check slerp(v0, v1, t) for the statement's unit vectors and t (Goldman §11.6).  Recognises linear interpolation,
    normalised linear interpolation, and the weights swapped (slerp at 1 - t)."""
    what = f"slerp(v0, v1, {p['t_text']})"
    got, problem = read_points(answer, what, ask="the vector [x, y, z]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"{what} should be one vector [x, y, z]; yours has shape {got.shape}.")
    v0, v1, t = _arr(p["v0"]), _arr(p["v1"]), p["t"]
    expected = vg.slerp(v0, v1, t)
    lerp = (1 - t) * v0 + t * v1
    if np.allclose(got, expected, atol=_TOL):
        return correct(f"{what} is a unit vector {_T_WORDS[p['t_text']]} of the way along the arc: "
                       f"{fmt(t * p['theta'])}° from v0 and {fmt((1 - t) * p['theta'])}° from v1.")
    if np.allclose(got, lerp, atol=_TOL):
        return wrong("that is linear interpolation (1 - t) v0 + t v1: it runs along the chord, inside the sphere "
                     "(its length is below 1). Slerp weights v0 and v1 by sin((1 - t)θ)/sin θ and sin(tθ)/sin θ.")
    if np.allclose(got, vg.nlerp(v0, v1, t), atol=_TOL):
        return wrong("that is linear interpolation pushed out to the sphere (normalised): a unit vector on the right "
                     "arc, but at the wrong place, since the chord is not cut in equal angles. Use the sine weights "
                     "of slerp.")
    if np.allclose(got, vg.slerp(v0, v1, 1 - t), atol=_TOL):
        near = "v0" if t < 0.5 else "v1"
        return wrong(f"the weights are swapped: sin((1 - t)θ)/sin θ goes with v0, so at t = {p['t_text']} the result "
                     f"stays closer to {near}.")
    length = float(np.linalg.norm(got))
    hint = "" if abs(length - 1) < 1e-2 else " Slerp of unit vectors is a unit vector; yours is not."
    return wrong(f"{what} is {far_off(got, expected)} from your vector.{hint} "
                 "Find θ from v0·v1, then the weights sin((1 - t)θ)/sin θ and sin(tθ)/sin θ.")


# -- §11.7 ------------------------------------------------------------------------------------------
_STORED_WINDING = {"polygon": _tup(WINDING_POLYGON), "query": _tup(WINDING_QUERY)}


@memo
def _winding_answers(p):
    expected = int(vg.winding_number(_arr(p["polygon"]), _arr(p["query"])))
    slips = {"reversed": -expected, "even-odd": 0}
    if expected > 1:
        slips["inside only"] = 1
    return expected, slips


def _winding_generate(rng) -> dict:
    W, H = int(rng.integers(6, 10)), int(rng.integers(6, 10))
    a, b, a2, b2 = (int(v) for v in rng.integers(1, 3, size=4))
    poly = np.array([(0, 0), (W, 0), (W, H), (a, H), (a, b), (W - a2, b), (W - a2, H - b2), (0, H - b2)], dtype=float)
    q = np.array([rng.integers(a + 1, W - a2), rng.integers(b + 1, H - b2)], dtype=float)
    # one of the eight symmetries of the square grid (the reflections turn the polygon clockwise), then a shift
    M = [np.eye(2), np.array([[0.0, -1.0], [1.0, 0.0]])][int(rng.integers(0, 2))]
    if rng.integers(0, 2):
        M = M @ np.diag([-1.0, 1.0])
    M = M * float(rng.choice([-1.0, 1.0]))
    shift = np.array(_ints(rng, -3, 3, 2))
    return {"polygon": _tup(poly @ M + shift), "query": _tup(q @ M + shift)}


def _winding_ok(p):
    w = int(vg.winding_number(_arr(p["polygon"]), _arr(p["query"])))
    return None if abs(w) == 2 else "the query point is not where the polygon winds twice"


def _winding_statement(p) -> str:
    return (f"The closed polygon {fmt_points(p['polygon'])} crosses itself. Give its winding number about the point "
            f"Q = {fmt(p['query'])} (Goldman §11.7): counterclockwise turns count positive.")


def _winding_steps(p) -> str:
    poly, q = _arr(p["polygon"]), _arr(p["query"])
    crossings, signs = vg.ray_crossings(poly, q)
    parts = ", ".join(f"at {fmt(c)} ({'+1, going up' if s > 0 else '-1, going down'})"
                      for c, s in zip(crossings, np.ravel(signs)))
    return (f"1. Cast the ray from Q = {fmt(q)} to the right (y = {fmt(q[1])}, x > {fmt(q[0])}).\n"
            f"2. The edges cross it {parts or 'none'}.\n"
            f"3. The winding number is the sum of the signs: {int(np.sum(signs))}.")


@DECK.exercise(stored=_STORED_WINDING, generate=_winding_generate, answer=lambda p: _winding_answers(p)[0],
               slips=lambda p: _winding_answers(p)[1], statement=_winding_statement, steps=_winding_steps,
               same=lambda a, b: float(a) == float(b), well_posed=_winding_ok)
def check_winding_number(answer, p) -> Result:
    """Check the winding number of the statement's polygon about its point Q (Goldman §11.7).
    Recognises the even-odd verdict given as a number, the orientation reversed, an inside/outside
    answer given as True/False, and the crossings counted without their signs."""
    what = "the winding number"
    if isinstance(answer, (bool, np.bool_)):
        return wrong("that is an inside/outside verdict; the winding number is an integer: add +1 for each edge "
                     "crossing a ray from Q upward and -1 for each crossing downward.")
    value, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    poly, q = _arr(p["polygon"]), _arr(p["query"])
    expected = int(vg.winding_number(poly, q))
    crossings, signs = vg.ray_crossings(poly, q)
    if value != round(value):
        return wrong(f"{what} is an integer (a count of turns); you gave {fmt(value)}.")
    value = int(round(value))
    if value == expected:
        turns = "counterclockwise" if expected > 0 else "clockwise"
        return correct(f"{what} about Q is {expected}: the polygon winds around Q that many times {turns}, "
                       f"so Q is inside by the nonzero rule, though an even number of crossings puts it outside by "
                       f"the even-odd rule.")
    if value == -expected:
        if expected > 0:
            return wrong("the sign is reversed: this polygon turns counterclockwise around Q, which counts positive "
                         "(an edge crossing the rightward ray from Q going up counts +1).")
        return wrong("the sign is reversed: this polygon turns clockwise around Q, which counts negative "
                     "(an edge crossing the rightward ray from Q going down counts -1).")
    if value == len(signs) % 2 and value != expected:
        return wrong("that is the even-odd (ray casting) verdict, inside = 1 and outside = 0: the parity of the "
                     "number of crossings. The winding number adds the crossings with signs, +1 up, -1 down.")
    if value == 1 and expected > 1:
        return wrong("the winding number counts how many times the polygon goes around Q, not only whether it does: "
                     "follow the edges and count every counterclockwise turn about Q.")
    return wrong(f"{what} is {off_by(value, expected)}. Cast a ray from Q to the right and add +1 for each edge "
                 "crossing it upward, -1 for each crossing downward.")


#: Deal another instance of an exercise (``deal("check_slerp")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})

SLIPS = {
    "check_law_of_cosines": [float(np.sqrt(129)), 49.0, float(np.sqrt(89 - 80 * np.cos(60)))],
    "check_point_plane_distance": [-3.0, 9.0, -9.0, 1.0, float(np.sqrt(26))],
    "check_line_line_distance": [6.0, 2.0, 3.0, float(np.sqrt(14)), -float(2 * np.sqrt(3))],
    "check_newell_area": [float(16 * np.sqrt(3)), 8.0, 16.0, 24.0],
    "check_tetrahedron_volume": [31.0, 15.5, 31 / 3, -31 / 6],
    "check_three_planes": [[7.0, 14.0, 21.0], [-1.0, -2.0, -3.0], [4.0, 1.0, 1.0], [2.0, 3.0, 1.0], [1.0, 2.0, 4.0]],
    "check_winding_number": [0, -2, 1, True],
    "check_slerp": [[2 / 3, 1 / (3 * np.sqrt(2)), 1 / (3 * np.sqrt(2))],
                    [2 / np.sqrt(5), 1 / np.sqrt(10), 1 / np.sqrt(10)],
                    [0.5, np.sqrt(3) / (2 * np.sqrt(2)), np.sqrt(3) / (2 * np.sqrt(2))]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
