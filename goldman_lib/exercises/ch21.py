"""Exercise checkers for chapter 21, shading (Goldman §21.1-21.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other polygons, normals, triangles and intensities than the chapter's worked
examples.  The programming project, :func:`check_gouraud_project`, runs the learner's Gouraud
shader for one triangle against :func:`goldman_lib.shading.gouraud_triangle` on seeded triangles,
slivers, edge-on and degenerate ones included.

Screen coordinates: x to the right, y down the rows; pixel (row i, column j) is centred at
(j + 0.5, i + 0.5).

>>> print(PROBLEMS["check_forward_differences"])   # doctest: +ELLIPSIS
Along one scan line fast Phong shading evaluates a quadratic ...
>>> check_pixels_covered(64)
Not yet: that is every pixel of the bounding box; the box only limits the candidates, each of which must still pass the three edge tests.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import shading
from goldman_lib import vector_geometry as vg
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "NEWELL_QUAD", "FACE_VECTORS", "COVER_TRIANGLE", "GOURAUD_TRIANGLE",
           "GOURAUD_INTENSITIES", "GOURAUD_PIXEL", "PHONG_NA", "PHONG_NB", "PHONG_T", "PHONG_L", "QUADRATIC",
           "QUADRATIC_X0", "NLERP_ANGLE", "NLERP_T", "check_newell_normal", "check_vertex_normal",
           "check_pixels_covered", "check_gouraud_pixel", "check_phong_diffuse", "check_forward_differences",
           "check_lerp_angle", "check_gouraud_project", "gouraud_project_cases"]

#: Exercise 1 (§21.1): a non-planar quadrilateral.
NEWELL_QUAD = ((0.0, 0.0, 0.0), (3.0, 0.0, 1.0), (3.0, 2.0, 2.0), (0.0, 1.0, 0.0))
#: Exercise 2 (§21.1): the Newell vectors (twice the area vectors) of the three faces around a vertex.
FACE_VECTORS = ((0.0, 0.0, 6.0), (2.0, 0.0, 0.0), (0.0, -1.0, 1.0))
#: Exercise 3 (§21.2): a triangle in screen coordinates.
COVER_TRIANGLE = ((1.2, 0.3), (8.7, 2.6), (2.1, 7.4))
#: Exercise 4 (§21.3): a triangle, its vertex intensities and the pixel (row, column).
GOURAUD_TRIANGLE = ((0.0, 0.0), (8.0, 0.0), (0.0, 6.0))
GOURAUD_INTENSITIES = (0.9, 0.3, 0.5)
GOURAUD_PIXEL = (2, 3)
#: Exercise 5 (§21.4.1): the normals at the two ends of a scan-line span, the pixel's place t and the light.
PHONG_NA = (0.0, 0.6, 0.8)
PHONG_NB = (0.8, 0.0, 0.6)
PHONG_T = 0.3
PHONG_L = (1 / 3, 2 / 3, 2 / 3)
#: Exercise 6 (§21.4.2): f(X) = a X^2 + b X + c along a scan line, from X = x0.
QUADRATIC = (0.004, -0.05, 0.9)
QUADRATIC_X0 = 12
#: Exercise 7 (§21.4.4): two unit normals this many degrees apart, and the parameter.
NLERP_ANGLE = 120.0
NLERP_T = 0.25


PROBLEMS = {
    "check_newell_normal": (
        f"The quadrilateral with vertices {', '.join(fmt(p) for p in NEWELL_QUAD)} (in this order) is not planar. "
        f"Give its unit normal by Newell's formula, N_x = Σ (y_i - y_(i+1))(z_i + z_(i+1)) and cyclically, "
        f"normalised, as [x, y, z] to 4 decimals (Goldman §21.1)."),
    "check_vertex_normal": (
        f"Three triangles meet at a vertex; their Newell vectors (normals whose length is twice the area) are "
        f"{', '.join(fmt(p) for p in FACE_VECTORS)}. Give the vertex normal as the book builds it for Gouraud and "
        f"Phong shading: the average of the faces' unit normals, normalised. [x, y, z] to 4 decimals "
        f"(Goldman §21.1)."),
    "check_pixels_covered": (
        f"A triangle has screen vertices {', '.join(fmt(p) for p in COVER_TRIANGLE)} (x right, y down). A pixel "
        f"(row i, column j) is drawn when its centre (j + 0.5, i + 0.5) lies inside the triangle. How many pixels "
        f"does scan conversion draw? (Goldman §21.2)"),
    "check_gouraud_pixel": (
        f"Gouraud shading: a triangle has screen vertices {', '.join(fmt(p) for p in GOURAUD_TRIANGLE)} with "
        f"intensities {', '.join(fmt(c) for c in GOURAUD_INTENSITIES)}. Give the intensity at the pixel in row "
        f"{GOURAUD_PIXEL[0]}, column {GOURAUD_PIXEL[1]} (the intensities interpolated linearly at its centre), "
        f"to 4 decimals (Goldman §21.3)."),
    "check_phong_diffuse": (
        f"Phong shading: on a scan line the normals at the two ends of a span are N_a = {fmt(PHONG_NA)} and "
        f"N_b = {fmt(PHONG_NB)}. At the pixel a fraction t = {fmt(PHONG_T)} of the way from a to b, give the "
        f"diffuse cosine L·N for the unit light direction L = (1/3, 2/3, 2/3), with N the interpolated normal "
        f"made unit length, to 4 decimals (Goldman §21.4.1)."),
    "check_forward_differences": (
        f"Along one scan line fast Phong shading evaluates a quadratic f(X) = {fmt(QUADRATIC[0])} X^2 "
        f"{QUADRATIC[1]:+g} X + {fmt(QUADRATIC[2])} by forward differences, starting at X = {QUADRATIC_X0}. Give "
        f"[f({QUADRATIC_X0}), Δf({QUADRATIC_X0}), Δ²f] with Δf(X) = f(X + 1) - f(X) and Δ²f = Δf(X + 1) - Δf(X), "
        f"to 4 decimals: then each next pixel costs two additions (Goldman §21.4.2)."),
    "check_lerp_angle": (
        f"Two unit vertex normals are {fmt(NLERP_ANGLE)} degrees apart. Phong shading interpolates them linearly "
        f"and normalises: N(t) = ((1 - t) N0 + t N1) / |(1 - t) N0 + t N1|. At t = {fmt(NLERP_T)}, how many degrees "
        f"is N(t) from N0? Give it to 2 decimals; slerp (§21.4.4) would move at constant speed (Goldman §21.4)."),
}


# -- reading answers ---------------------------------------------------------------------------------

def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


# -- §21.1 -------------------------------------------------------------------------------------------

def check_newell_normal(answer) -> Result:
    """Check Newell's unit normal of :data:`NEWELL_QUAD` (Goldman §21.1).

    Recognises the cross product of the first two edges (one corner's normal, not Newell's), the
    vector left unnormalised, and the opposite orientation.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    P = np.array(NEWELL_QUAD)
    expected = shading.newell_normal(P)
    Q = np.roll(P, -1, axis=0)
    raw = np.array([((P[:, 1] - Q[:, 1]) * (P[:, 2] + Q[:, 2])).sum(), ((P[:, 2] - Q[:, 2]) * (P[:, 0] + Q[:, 0])).sum(),
                    ((P[:, 0] - Q[:, 0]) * (P[:, 1] + Q[:, 1])).sum()])
    tol = 2e-4
    if _close(got, expected, tol):
        return correct("that is Newell's normal: each coordinate is twice the signed area of the polygon's "
                       "projection on a coordinate plane, so every vertex contributes, even off a plane.")
    corner = _unit(np.cross(P[1] - P[0], P[2] - P[1]))
    if _close(got, corner, tol):
        return wrong("that is the normal of the first corner alone, (P1 - P0) × (P2 - P1): for a non-planar polygon "
                     "each corner gives another normal; Newell's formula averages over all edges.")
    if _close(got, -expected, tol):
        return wrong("your normal points the other way: the vertices go counterclockwise around Newell's normal; "
                     "check the sign of (y_i - y_(i+1))(z_i + z_(i+1)).")
    if _close(got, raw, 1e-3) or _close(got, raw / 2, 1e-3):
        return wrong("that is Newell's vector before normalising; divide it by its length.")
    return wrong(f"your normal is {_dist(got, expected)} from Newell's; sum the three coordinates over the "
                 f"four edges (wrapping from the last vertex to the first), then normalise.")


def check_vertex_normal(answer) -> Result:
    """Check the average of the unit normals of :data:`FACE_VECTORS`, normalised (Goldman §21.1).

    Recognises the area-weighted normal (the raw vectors summed), the average left unnormalised and
    the raw average.
    """
    got, err = _read_vector(answer, "your vertex normal", 3, "the vertex normal as [x, y, z]")
    if err is not None:
        return err
    F = np.array(FACE_VECTORS)
    units = F / np.linalg.norm(F, axis=1, keepdims=True)
    expected = _unit(units.sum(0))
    tol = 2e-4
    if _close(got, expected, tol):
        return correct("each face counts once, whatever its size: the unit normals averaged, then normalised.")
    if _close(got, _unit(F.sum(0)), tol):
        return wrong("that weights each face by its area (you summed the Newell vectors as they are); the book "
                     "averages the faces' unit normals, so normalise each one first.")
    if _close(got, units.mean(0), tol) or _close(got, units.sum(0), tol):
        return wrong("that is the average (or sum) of the unit normals before normalising; a normal for shading "
                     "must have length 1.")
    if _close(got, F.mean(0), tol):
        return wrong("that is the plain average of the Newell vectors: normalise each first, then normalise "
                     "their average.")
    return wrong(f"your vertex normal is {_dist(got, expected)}; normalise each face vector, add the three, "
                 f"and normalise the sum.")


# -- §21.2 scan conversion ---------------------------------------------------------------------------

def check_pixels_covered(answer) -> Result:
    """Check the number of pixel centres inside :data:`COVER_TRIANGLE` (Goldman §21.2).

    Recognises the area (rounded), the count of integer points (pixel corners) instead of centres,
    and the count of pixels the bounding box holds.
    """
    value, err = read_number(answer, "your count", "whole number")
    if err is not None:
        return err
    x = np.array(COVER_TRIANGLE)
    expected = int((shading.gouraud_triangle(x, [1, 1, 1], 12, 12) > 0).sum())
    if value == expected:
        return correct("every centre that passes the three edge tests (all barycentric coordinates >= 0) is drawn.")
    d1, d2 = x[1] - x[0], x[2] - x[0]
    area = 0.5 * abs(d1[0] * d2[1] - d1[1] * d2[0])
    lo, hi = np.floor(x.min(0)), np.ceil(x.max(0))
    box = int((hi - lo).prod())
    if value in (round(area), math.floor(area), math.ceil(area)) or value == _corner_count(x):
        return wrong("that is the triangle's area (or the number of integer points, the pixels' corners, inside "
                     "it); scan conversion tests each pixel's centre (j + 0.5, i + 0.5).")
    if value == box:
        return wrong("that is every pixel of the bounding box; the box only limits the candidates, each of which "
                     "must still pass the three edge tests.")
    return wrong(f"your count is {off_by(value, expected)}; list the rows the triangle spans and, in each, the "
                 f"columns whose centres lie between its left and right edges.")


def _corner_count(x) -> int:
    jj, ii = np.meshgrid(np.arange(13), np.arange(13))
    pts = np.stack([jj.ravel(), ii.ravel(), np.zeros(jj.size)], 1)
    S = np.c_[x, np.full(3, 0.5)]
    count = 0
    for p in pts:  # the barycentric test at integer points (the pixel corners)
        a = np.cross(np.r_[S[1, :2] - S[0, :2], 0], np.r_[S[2, :2] - S[0, :2], 0])[2]
        l1 = np.cross(np.r_[p[:2] - S[0, :2], 0], np.r_[S[2, :2] - S[0, :2], 0])[2] / a
        l2 = np.cross(np.r_[S[1, :2] - S[0, :2], 0], np.r_[p[:2] - S[0, :2], 0])[2] / a
        count += int(l1 >= 0 and l2 >= 0 and l1 + l2 <= 1)
    return count


# -- §21.3 Gouraud -----------------------------------------------------------------------------------

def _gouraud_at(x, y) -> float:
    P = np.array(GOURAUD_TRIANGLE)
    c = np.array(GOURAUD_INTENSITIES)
    d1, d2 = P[1] - P[0], P[2] - P[0]
    a = d1[0] * d2[1] - d1[1] * d2[0]
    q = np.array([x, y]) - P[0]
    l1 = (q[0] * d2[1] - q[1] * d2[0]) / a
    l2 = (d1[0] * q[1] - d1[1] * q[0]) / a
    return float((1 - l1 - l2) * c[0] + l1 * c[1] + l2 * c[2])


def check_gouraud_pixel(answer) -> Result:
    """Check the Gouraud intensity at :data:`GOURAUD_PIXEL` (Goldman §21.3).

    Recognises the pixel's corner used instead of its centre, rows and columns swapped, the average
    of the three intensities (the centroid's) and the nearest vertex's intensity (uniform shading).
    """
    value, err = read_number(answer, "your intensity")
    if err is not None:
        return err
    i, j = GOURAUD_PIXEL
    image = shading.gouraud_triangle(GOURAUD_TRIANGLE, GOURAUD_INTENSITIES, 8, 6)
    expected = float(image[i, j])
    tol = 1e-4
    if abs(value - expected) <= tol:
        return correct("the three vertex intensities weighted by the pixel centre's barycentric coordinates, "
                       "as the scan line interpolates them along the edges and then across.")
    if abs(value - _gouraud_at(j, i)) <= tol:
        return wrong("you interpolated at the pixel's corner (j, i); the pixel is sampled at its centre "
                     "(j + 0.5, i + 0.5).")
    if abs(value - _gouraud_at(i + 0.5, j + 0.5)) <= tol:
        return wrong("you swapped row and column: x is the column j, y is the row i.")
    if abs(value - float(np.mean(GOURAUD_INTENSITIES))) <= tol:
        return wrong("that is the average of the three intensities, the value at the centroid only; weight each "
                     "by the pixel's barycentric coordinate.")
    if any(abs(value - c) <= tol for c in GOURAUD_INTENSITIES):
        return wrong("that is one vertex's intensity, as uniform shading would give; Gouraud interpolates the "
                     "three across the face.")
    return wrong(f"your intensity is {off_by(value, expected)}; find the barycentric coordinates of "
                 f"(j + 0.5, i + 0.5) and weight the intensities by them.")


# -- §21.4 Phong ---------------------------------------------------------------------------------------

def check_phong_diffuse(answer) -> Result:
    """Check L·N at t along the span, N the normalised linear interpolation of the end normals
    (Goldman §21.4.1).

    Recognises Gouraud's answer (the end cosines interpolated), the normal left unnormalised, and
    t measured from the other end.
    """
    value, err = read_number(answer, "your cosine")
    if err is not None:
        return err
    a, b, L, t = np.array(PHONG_NA), np.array(PHONG_NB), np.array(PHONG_L), PHONG_T
    expected = float(L @ _unit((1 - t) * a + t * b))
    tol = 1e-4
    if abs(value - expected) <= tol:
        return correct("the normal is interpolated, renormalised and lit at the pixel: Phong shading.")
    if abs(value - ((1 - t) * (L @ a) + t * (L @ b))) <= tol:
        return wrong("that is the end cosines interpolated, Gouraud's answer -- the same as L·N with the "
                     "interpolated normal left unnormalised: it is shorter than 1 (it cuts the chord of the "
                     "sphere), so normalise it before the dot product.")
    if abs(value - float(L @ _unit(t * a + (1 - t) * b))) <= tol:
        return wrong("you measured t from the other end: at t = 0 the normal is N_a.")
    return wrong(f"your cosine is {off_by(value, expected)}; form (1 - t) N_a + t N_b, divide by its length, "
                 f"then dot with L.")


def check_forward_differences(answer) -> Result:
    """Check [f(x0), Δf(x0), Δ²f] for the quadratic :data:`QUADRATIC` (Goldman §21.4.2).

    Recognises the derivative f'(x0) in place of the first difference, a in place of the second
    difference 2a, and the backward difference f(x0) - f(x0 - 1).
    """
    got, err = _read_vector(answer, "your answer", 3, "[f(x0), Δf(x0), Δ²f]")
    if err is not None:
        return err
    a, b, c = QUADRATIC
    x0 = QUADRATIC_X0
    values = shading.forward_differences([c, b, 0, a, 0, 0], x0, 0, 3)
    expected = np.array([values[0], values[1] - values[0], values[2] - 2 * values[1] + values[0]])
    tol = 1e-4
    if _close(got, expected, tol):
        return correct("start from f(x0); each pixel adds the first difference, and the first difference grows "
                       "by the constant second difference 2a: two additions per pixel.")
    if abs(got[0] - expected[0]) > tol:
        return wrong(f"your f(x0) is {off_by(got[0], expected[0])}: evaluate a X^2 + b X + c at the start.")
    if abs(got[2] - a) <= tol:
        return wrong("your second difference is a, the X^2 coefficient; the second difference of a X^2 + b X + c "
                     "is 2a (f(X+2) - 2 f(X+1) + f(X)).")
    if abs(got[1] - (2 * a * x0 + b)) <= tol:
        return wrong("your first difference is the derivative f'(x0) = 2a x0 + b; the forward difference "
                     "f(x0 + 1) - f(x0) is 2a x0 + a + b.")
    if abs(got[1] - (2 * a * x0 - a + b)) <= tol:
        return wrong("that is the backward difference f(x0) - f(x0 - 1); the forward difference looks one pixel "
                     "ahead, f(x0 + 1) - f(x0).")
    return wrong(f"your answer is {_dist(got, expected)}; compute f(x0), f(x0 + 1) and f(x0 + 2) and take "
                 f"differences.")


def check_lerp_angle(answer) -> Result:
    """Check the angle from N0 of the normalised linear interpolation at t (Goldman §21.4, §21.4.4).

    Recognises t θ (what slerp gives), (1 - t) θ (the angle from N1) and the angle of the
    interpolation measured from the other normal.
    """
    value, err = read_number(answer, "your angle", "number of degrees")
    if err is not None:
        return err
    theta = math.radians(NLERP_ANGLE)
    n0, n1 = np.array([1.0, 0.0]), np.array([math.cos(theta), math.sin(theta)])
    t = NLERP_T
    got_n = vg.nlerp(n0, n1, t)
    expected = math.degrees(math.atan2(got_n[1], got_n[0]))
    tol = 0.01
    if abs(value - expected) <= tol:
        return correct(f"less than t θ: normalised linear interpolation lags near the ends and rushes through the "
                       f"middle; slerp (§21.4.4) moves at constant speed.")
    if abs(value - t * NLERP_ANGLE) <= tol:
        return wrong("that is t θ, where slerp would be; linear interpolation followed by normalising does not "
                     "move at constant angular speed. Compute the angle of (1 - t) N0 + t N1.")
    if abs(value - (1 - t) * NLERP_ANGLE) <= tol or abs(value - (NLERP_ANGLE - expected)) <= tol:
        return wrong("that is the angle from N1; the question asks how far N(t) is from N0.")
    return wrong(f"your angle is {off_by(value, expected)}; put N0 = (1, 0) and N1 = (cos θ, sin θ), form "
                 f"(1 - t) N0 + t N1, and take its angle with atan2.")


# -- the programming project -------------------------------------------------------------------------

def gouraud_project_cases(seed: int = 21) -> list[Case]:
    """The cases of :func:`check_gouraud_project`, generated from a fixed seed: random triangles in both
    orientations, slivers, triangles partly off the image, edges through pixel centres, edge-on
    (collinear) and degenerate (one point) triangles.

    >>> cases = gouraud_project_cases()
    >>> len(cases), cases[0].kind, cases[-1].kind
    (14, 'random triangle', 'degenerate: all three vertices equal')
    """
    rng = np.random.default_rng(seed)
    W, H = 16, 12
    cases: list[Case] = []

    def add(tri, c, kind):
        tri = np.round(np.asarray(tri, float), 3)
        c = np.round(np.asarray(c, float), 3)
        label = f"vertices {', '.join(fmt(p) for p in tri)}, intensities {fmt(c)}, image {W}x{H}"
        cases.append(Case(label, (tri, c, W, H), kind=kind))

    for _ in range(3):
        add(rng.uniform([0, 0], [W, H], (3, 2)), rng.uniform(0, 1, 3), "random triangle")
    tri = rng.uniform([0, 0], [W, H], (3, 2))
    add(tri[::-1], rng.uniform(0, 1, 3), "random triangle, the other orientation")
    add([[0.3, 0.4], [15.7, 11.2], [0.9, 1.6]], rng.uniform(0, 1, 3), "sliver (long and thin)")
    add([[2.2, 10.5], [14.1, 1.3], [14.6, 1.9]], rng.uniform(0, 1, 3), "sliver (long and thin)")
    add([[-5.0, -3.0], [22.0, 4.0], [6.0, 19.0]], rng.uniform(0, 1, 3), "partly off the image")
    add([[-3.0, 2.0], [8.0, -6.0], [9.0, 20.0]], rng.uniform(0, 1, 3), "partly off the image")
    add([[2.5, 1.5], [9.5, 1.5], [2.5, 8.5]], [1.0, 0.2, 0.5], "edges through pixel centres")
    add([[12.5, 9.5], [4.5, 9.5], [12.5, 3.5]], [0.1, 0.9, 0.4], "edges through pixel centres")
    add([[1.0, 1.0], [7.0, 4.0], [13.0, 7.0]], [0.2, 0.4, 0.6], "edge-on: three collinear vertices")
    add([[3.0, 9.0], [3.0, 2.0], [3.0, 5.0]], [0.5, 0.5, 0.5], "edge-on: three collinear vertices")
    add([[4.0, 4.0], [10.0, 8.0], [10.0, 8.0]], [0.3, 0.6, 0.9], "degenerate: two vertices equal")
    add([[6.0, 5.0], [6.0, 5.0], [6.0, 5.0]], [1.0, 1.0, 1.0], "degenerate: all three vertices equal")
    return cases


def _centre_weights(tri, W, H):
    """Barycentric coordinates of every pixel centre (H, W, 3), or None for a degenerate triangle."""
    P = np.asarray(tri, float)
    d1, d2 = P[1] - P[0], P[2] - P[0]
    a = d1[0] * d2[1] - d1[1] * d2[0]
    if abs(a) < 1e-12:
        return None
    jj, ii = np.meshgrid(np.arange(W) + 0.5, np.arange(H) + 0.5)
    qx, qy = jj - P[0, 0], ii - P[0, 1]
    l1 = (qx * d2[1] - qy * d2[0]) / a
    l2 = (d1[0] * qy - d1[1] * qx) / a
    return np.stack([1 - l1 - l2, l1, l2], -1)


def _compare_gouraud(got, expected, case) -> str | None:
    tri, c, W, H = case.args
    arr = np.asarray(got, dtype=float)
    if arr.shape != (H, W):
        return f"it has shape {arr.shape}; the image is {H} rows by {W} columns, shape ({H}, {W})"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinity (a degenerate triangle has zero area: draw nothing rather than divide by it)"
    lam = _centre_weights(tri, W, H)
    strict = case.kind == "edges through pixel centres"
    if lam is None:
        check = np.ones((H, W), bool)
    else:
        # centres within rounding of an edge may go either way, except where the case is about them
        check = np.ones((H, W), bool) if strict else np.abs(lam).min(-1) > 1e-9
    bad = check & (np.abs(arr - expected) > 1e-6)
    if not bad.any():
        return None
    i, j = map(int, np.argwhere(bad)[0])
    where = f"pixel (row {i}, column {j}), centre ({fmt(j + 0.5)}, {fmt(i + 0.5)})"
    if lam is not None:
        P = np.asarray(tri, float)
        signed = (P[1, 0] - P[0, 0]) * (P[2, 1] - P[0, 1]) - (P[1, 1] - P[0, 1]) * (P[2, 0] - P[0, 0])
        if signed < 0 and not np.any(arr) and np.any(expected):
            return (f"{where} is 0, and your image is empty: this triangle has the other orientation (negative "
                    f"signed area), so all three barycentric coordinates come out with the other sign unless you "
                    f"divide by the signed area")
        corners = shading.gouraud_triangle(P + 0.5, c, W, H)    # sampling at (j, i) = the centres of the shifted image
        if np.allclose(arr, corners, atol=1e-6) and not np.allclose(corners, expected, atol=1e-6):
            return (f"{where} is {fmt(arr[i, j])}: you sampled the pixel at its corner (j, i), not at its centre "
                    f"(j + 0.5, i + 0.5)")
    inside = lam is not None and lam[i, j].min() >= 0
    if lam is None:
        return f"{where} is {fmt(arr[i, j])}, but the triangle has zero area and covers no pixel"
    if not inside and arr[i, j] != 0:
        return f"{where} is {fmt(arr[i, j])}, but its centre lies outside the triangle (it should stay 0)"
    if inside and arr[i, j] == 0 and expected[i, j] != 0:
        side = " on an edge (it counts as inside)" if lam[i, j].min() < 1e-9 else " inside the triangle"
        return f"{where} is 0, but its centre lies{side}; expected {fmt(expected[i, j])}"
    if abs(arr[i, j] - c[np.argmax(lam[i, j])]) < 1e-9 and abs(expected[i, j] - arr[i, j]) > 1e-6:
        return (f"{where} is {fmt(arr[i, j])}, the nearest vertex's intensity (uniform shading); expected "
                f"{fmt(expected[i, j])}")
    return f"{where} is {fmt(arr[i, j])}; expected {fmt(expected[i, j])} ({int(bad.sum())} pixels are off)"


def check_gouraud_project(function) -> Result:
    """Check the learner's ``shade_triangle(screen, intensities, width, height)`` -- Gouraud shading of
    one triangle: (height, width) intensities interpolated at the covered pixel centres, 0 elsewhere --
    against :func:`goldman_lib.shading.gouraud_triangle` on :func:`gouraud_project_cases`
    (Goldman §21.3).

    >>> def flat(screen, intensities, width, height):
    ...     return np.full((height, width), float(np.mean(intensities)))
    >>> print(check_gouraud_project(flat).message)   # doctest: +ELLIPSIS
    case 1 of 14 (vertices ...): your function returned ...; pixel (row 0, column 0), ... lies outside the triangle (it should stay 0). Hint: ...
    """
    return check_project(function, gouraud_project_cases(), reference=shading.gouraud_triangle,
                         compare=_compare_gouraud, what="Gouraud shading of a triangle",
                         hint="for each pixel centre compute the barycentric coordinates (a, b, c) from the signed "
                              "areas; draw it when all three are >= 0, with intensity a I0 + b I1 + c I2")


SLIPS = {
    "check_newell_normal": [[-0.2857, -0.4286, 0.8571], [0.3885, 0.2914, -0.8742], [-4.0, -3.0, 9.0]],
    "check_vertex_normal": [[0.2722, -0.1361, 0.9526], [0.3333, -0.2357, 0.569], [0.6667, -0.3333, 2.3333]],
    "check_pixels_covered": [26, 64],
    "check_gouraud_pixel": [0.5417, 0.4792, 0.5667, 0.9],
    "check_phong_diffuse": [0.8533, 0.8446],
    "check_forward_differences": [[0.876, 0.05, 0.004], [0.876, 0.046, 0.008], [0.876, 0.042, 0.008]],
    "check_lerp_angle": [30.0, 90.0, 100.89],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
