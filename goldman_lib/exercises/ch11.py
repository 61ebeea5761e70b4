"""Exercise checkers for chapter 11, applications of vector geometry (Goldman §11.2-11.7).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.

>>> print(PROBLEMS["check_law_of_cosines"])
A triangle has sides a = 5 and b = 8 with the angle γ = 60° between them. Give the third side c (Goldman §11.2).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import vector_geometry as vg
from goldman_lib import vectors
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, fmt_points, off_by, read_number, read_points, wrong

__all__ = ["PROBLEMS", "SLIPS", "TRIANGLE", "PLANE_POINT", "PLANE_NORMAL", "QUERY_POINT", "LINE1", "LINE2",
           "POLYGON_3D", "TETRAHEDRON", "PLANES", "WINDING_POLYGON", "WINDING_QUERY", "SLERP_V0", "SLERP_V1", "SLERP_T",
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


PROBLEMS = {
    "check_law_of_cosines": (
        f"A triangle has sides a = {fmt(TRIANGLE[0])} and b = {fmt(TRIANGLE[1])} with the angle γ = {fmt(TRIANGLE[2])}° "
        f"between them. Give the third side c (Goldman §11.2)."),
    "check_point_plane_distance": (
        f"Give the distance from the point Q = {fmt(QUERY_POINT)} to the plane through P = {fmt(PLANE_POINT)} with "
        f"normal N = {fmt(PLANE_NORMAL)} (Goldman §11.4). A distance is not negative."),
    "check_line_line_distance": (
        f"Give the distance between the lines L1 = {fmt(LINE1[0])} + s {fmt(LINE1[1])} and "
        f"L2 = {fmt(LINE2[0])} + t {fmt(LINE2[1])} (Goldman §11.4), to 3 decimals or better."),
    "check_newell_area": (
        f"The hexagon with vertices {fmt_points(POLYGON_3D)} (in this order) lies in the plane z = x + y. "
        f"Give its area by Newell's formula (Goldman §11.4), to 3 decimals or better."),
    "check_tetrahedron_volume": (
        f"Give the volume of the tetrahedron with vertices {fmt_points(TETRAHEDRON)} (Goldman §11.4), to 3 decimals "
        f"or better."),
    "check_three_planes": (
        "Give the point where the three planes " + ", ".join(_plane_text(N, c) for N, c in PLANES)
        + " meet, as [x, y, z] (Goldman §11.5)."),
    "check_winding_number": (
        f"The closed polygon {fmt_points(WINDING_POLYGON)} crosses itself. Give its winding number about the point "
        f"Q = {fmt(WINDING_QUERY)} (Goldman §11.7): counterclockwise turns count positive."),
    "check_slerp": (
        "v0 = (1, 0, 0) and v1 = (0, 1/√2, 1/√2) are unit vectors 90° apart. Give slerp(v0, v1, t) at t = 1/3 as "
        "[x, y, z] to 3 decimals or better (Goldman §11.6)."),
}


def _is(value, target, tol=_TOL) -> bool:
    return abs(float(value) - float(target)) <= tol * max(1.0, abs(float(target)))


# -- §11.2 ------------------------------------------------------------------------------------------
def check_law_of_cosines(answer) -> Result:
    """Check the third side of the triangle ``TRIANGLE`` (Goldman §11.2).  Recognises the sign of
    the cosine term flipped, c² given instead of c, and the angle taken in radians."""
    what = "the third side c"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    a, b, g = TRIANGLE
    expected = vg.law_of_cosines(a, b, g)
    if _is(value, expected):
        return correct(f"c² = a² + b² - 2ab cos γ gives {what} = {fmt(expected)}.")
    if _is(value, np.sqrt(a * a + b * b + 2 * a * b * np.cos(np.radians(g)))):
        return wrong("the cosine term has the wrong sign: |u - v|² = |u|² + |v|² - 2 u·v, so c² = a² + b² - 2ab cos γ; "
                     "an angle below 90° makes c shorter than the hypotenuse of a right triangle.")
    if _is(value, expected ** 2):
        return wrong("that is c², not c: take the square root.")
    if _is(value, np.sqrt(max(a * a + b * b - 2 * a * b * np.cos(g), 0))):
        return wrong(f"your calculator took γ = {fmt(g)} in radians; set it to degrees.")
    return wrong(f"{what} is {off_by(value, expected)}. Check c² = a² + b² - 2ab cos γ with cos {fmt(g)}°.")


# -- §11.4 ------------------------------------------------------------------------------------------
def check_point_plane_distance(answer) -> Result:
    """Check the distance from ``QUERY_POINT`` to the plane (Goldman §11.4).  Recognises the signed
    distance, (Q - P)·N not divided by |N|, a division by |N|² and the distance |Q - P| to P."""
    what = "the distance"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    Q, P, N = QUERY_POINT, PLANE_POINT, PLANE_NORMAL
    expected = vg.point_plane_distance(Q, P, N)
    signed = vg.point_plane_distance(Q, P, N, signed=True)
    raw = float((Q - P) @ N)
    if _is(value, expected):
        return correct(f"|(Q - P)·N| / |N| = {fmt(expected)}; Q lies on the side the normal points away from.")
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


def check_line_line_distance(answer) -> Result:
    """Check the distance between ``LINE1`` and ``LINE2`` (Goldman §11.4).  Recognises
    |(p2 - p1)·(d1 × d2)| without dividing by |d1 × d2|, a division by |d1 × d2|², a division by
    |d1| |d2|, the distance between the two given points and a negative (signed) answer."""
    what = "the distance between the lines"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    (p1, d1), (p2, d2) = LINE1, LINE2
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


def check_newell_area(answer) -> Result:
    """Check the area of ``POLYGON_3D`` (Goldman §11.4).  Recognises |N| without the 1/2, the area
    of the shadow on the xy-plane (|N_z| / 2 or |N_z|) and the sum of the projected areas."""
    what = "the area"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    N = vg.newell_normal(POLYGON_3D)
    expected = vg.polygon_area(POLYGON_3D)
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


def check_tetrahedron_volume(answer) -> Result:
    """Check the volume of ``TETRAHEDRON`` (Goldman §11.4).  Recognises the parallelepiped's volume
    (the 1/6 left out), the factor 1/2 of a triangle's area, the factor 1/3 of a pyramid over the
    parallelogram, and a negative (signed) volume."""
    what = "the volume"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    P0, P1, P2, P3 = TETRAHEDRON
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
def check_three_planes(answer) -> Result:
    """Check the common point of ``PLANES`` (Goldman §11.5).  Recognises the point not divided by
    det(N1, N2, N3), the wrong sign of the determinant, and a point on some planes but not all (it
    names the planes it misses)."""
    what = "the common point"
    got, problem = read_points(answer, what, ask="the point [x, y, z]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"{what} should be one point [x, y, z]; yours has shape {got.shape}.")
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
def check_slerp(answer) -> Result:
    """Check slerp(SLERP_V0, SLERP_V1, 1/3) (Goldman §11.6).  Recognises linear interpolation,
    normalised linear interpolation, and the weights swapped (slerp at 1 - t)."""
    what = "slerp(v0, v1, 1/3)"
    got, problem = read_points(answer, what, ask="the vector [x, y, z]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"{what} should be one vector [x, y, z]; yours has shape {got.shape}.")
    v0, v1, t = SLERP_V0, SLERP_V1, SLERP_T
    expected = vg.slerp(v0, v1, t)
    lerp = (1 - t) * v0 + t * v1
    if np.allclose(got, expected, atol=_TOL):
        return correct(f"{what} is a unit vector a third of the way along the arc: 30° from v0 and 60° from v1.")
    if np.allclose(got, lerp, atol=_TOL):
        return wrong("that is linear interpolation (1 - t) v0 + t v1: it runs along the chord, inside the sphere "
                     "(its length is below 1). Slerp weights v0 and v1 by sin((1 - t)θ)/sin θ and sin(tθ)/sin θ.")
    if np.allclose(got, vg.nlerp(v0, v1, t), atol=_TOL):
        return wrong("that is linear interpolation pushed out to the sphere (normalised): a unit vector on the right "
                     "arc, but at the wrong place, since the chord is not cut in equal angles. Use the sine weights "
                     "of slerp.")
    if np.allclose(got, vg.slerp(v0, v1, 1 - t), atol=_TOL):
        return wrong("the weights are swapped: sin((1 - t)θ)/sin θ goes with v0, so at t = 1/3 the result stays "
                     "closer to v0.")
    length = float(np.linalg.norm(got))
    hint = "" if abs(length - 1) < 1e-2 else " Slerp of unit vectors is a unit vector; yours is not."
    return wrong(f"{what} is {far_off(got, expected)} from your vector.{hint} "
                 "Find θ from v0·v1, then the weights sin((1 - t)θ)/sin θ and sin(tθ)/sin θ.")


# -- §11.7 ------------------------------------------------------------------------------------------
def check_winding_number(answer) -> Result:
    """Check the winding number of ``WINDING_POLYGON`` about ``WINDING_QUERY`` (Goldman §11.7).
    Recognises the even-odd verdict given as a number, the orientation reversed, an inside/outside
    answer given as True/False, and the crossings counted without their signs."""
    what = "the winding number"
    if isinstance(answer, (bool, np.bool_)):
        return wrong("that is an inside/outside verdict; the winding number is an integer: add +1 for each edge "
                     "crossing a ray from Q upward and -1 for each crossing downward.")
    value, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    expected = int(vg.winding_number(WINDING_POLYGON, WINDING_QUERY))
    crossings, signs = vg.ray_crossings(WINDING_POLYGON, WINDING_QUERY)
    if value != round(value):
        return wrong(f"{what} is an integer (a count of turns); you gave {fmt(value)}.")
    value = int(round(value))
    if value == expected:
        return correct(f"{what} about Q is {expected}: the polygon winds around Q that many times counterclockwise, "
                       f"so Q is inside by the nonzero rule, though an even number of crossings puts it outside by "
                       f"the even-odd rule.")
    if value == -expected:
        return wrong("the sign is reversed: this polygon turns counterclockwise around Q, which counts positive "
                     "(an edge crossing the rightward ray from Q going up counts +1).")
    if value == len(signs) % 2 and value != expected:
        return wrong("that is the even-odd (ray casting) verdict, inside = 1 and outside = 0: the parity of the "
                     "number of crossings. The winding number adds the crossings with signs, +1 up, -1 down.")
    if value == 1 and expected > 1:
        return wrong("the winding number counts how many times the polygon goes around Q, not only whether it does: "
                     "follow the edges and count every counterclockwise turn about Q.")
    return wrong(f"{what} is {off_by(value, expected)}. Cast a ray from Q to the right and add +1 for each edge "
                 "crossing it upward, -1 for each crossing downward.")


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
