"""Exercise checkers for chapter 21, shading (Goldman §21.1-21.4).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) and the programming project do not deal.  ``SLIPS`` holds the
wrong answers each checker recognises, for the stored instance.  ``None`` or ``...`` means "not
answered yet".  Every exercise uses other polygons, normals, triangles and intensities than the
chapter's worked examples.  The programming project, :func:`check_gouraud_project`, runs the
learner's Gouraud shader for one triangle against :func:`goldman_lib.rasteriser.gouraud_triangle` on
seeded triangles, slivers, edge-on and degenerate ones included.

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

from goldman_lib import rasteriser, shading
from goldman_lib import vector_geometry as vg
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.deal import Deck, plain as _tup, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "NEWELL_QUAD", "FACE_VECTORS", "COVER_TRIANGLE", "GOURAUD_TRIANGLE",
           "GOURAUD_INTENSITIES", "GOURAUD_PIXEL", "PHONG_NA", "PHONG_NB", "PHONG_T", "PHONG_L", "QUADRATIC",
           "QUADRATIC_X0", "NLERP_ANGLE", "NLERP_T", "DECK", "deal", "steps", "current", "deal_button",
           "check_newell_normal", "check_vertex_normal",
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

DECK = Deck("ch21")


def _arr(v) -> np.ndarray:
    return np.asarray(v, dtype=float)


def _r(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return np.round(np.asarray(x, dtype=float), 6) + 0.0


def _apart(values, tol) -> bool:
    """Whether every pair of ``values`` (numbers or arrays) differs by more than ``tol`` somewhere."""
    same = within(tol)
    return not any(same(a, b) for i, a in enumerate(values) for b in values[i + 1:])


# -- reading answers ---------------------------------------------------------------------------------

def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


# -- §21.1 -------------------------------------------------------------------------------------------

def _newell_raw(P) -> np.ndarray:
    Q = np.roll(P, -1, axis=0)
    return np.array([((P[:, 1] - Q[:, 1]) * (P[:, 2] + Q[:, 2])).sum(), ((P[:, 2] - Q[:, 2]) * (P[:, 0] + Q[:, 0])).sum(),
                     ((P[:, 0] - Q[:, 0]) * (P[:, 1] + Q[:, 1])).sum()])


def _newell_slips(p) -> dict:
    P = _arr(p["quad"])
    return {"first corner": _unit(np.cross(P[1] - P[0], P[2] - P[1])), "opposite": -shading.unit_newell_normal(P),
            "unnormalised": _newell_raw(P)}


def _newell_generate(rng) -> dict:
    quad = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]) * rng.integers(2, 5, size=3)
    quad[:, 2] = rng.integers(-1, 3, size=4)                       # a bent quadrilateral: heights off a plane
    quad += rng.integers(-1, 2, size=(4, 3)) * np.array([1, 1, 0])   # and a jittered outline
    axes = rng.permutation(3)
    return {"quad": _tup(quad[:, axes])}


def _newell_ok(p):
    P = _arr(p["quad"])
    if min(np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1)) < 0.5:
        return "two consecutive vertices coincide"
    raw = _newell_raw(P)
    if np.linalg.norm(raw) < 3:
        return "the polygon is nearly degenerate (Newell's vector is short)"
    if np.linalg.norm(np.cross(P[1] - P[0], P[2] - P[1])) < 0.5:
        return "the first corner is straight: its cross product vanishes"
    if abs(float(np.linalg.det(np.array([P[1] - P[0], P[2] - P[0], P[3] - P[0]])))) < 0.5:
        return "the quadrilateral is planar: every corner gives Newell's normal"
    n = shading.unit_newell_normal(P)
    corner = _unit(np.cross(P[1] - P[0], P[2] - P[1]))
    if np.degrees(np.arccos(np.clip(n @ corner, -1, 1))) < 3:
        return "the first corner's normal is within 3 degrees of Newell's"
    forms = [n, corner, -n, raw, raw / 2]
    if not _apart(forms, 2e-3):
        return "two recognised forms coincide"
    return None


def _newell_statement(p) -> str:
    return (f"The quadrilateral with vertices {', '.join(fmt(q) for q in p['quad'])} (in this order) is not planar. "
            f"Give its unit normal by Newell's formula, N_x = Σ (y_i - y_(i+1))(z_i + z_(i+1)) and cyclically, "
            f"normalised, as [x, y, z] to 4 decimals (Goldman §21.1).")


def _newell_steps(p) -> str:
    P = _arr(p["quad"])
    raw = _newell_raw(P)
    lines = []
    for i in range(4):
        a, b = P[i], P[(i + 1) % 4]
        term = np.array([(a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1])])
        lines.append(f"   edge {i} → {(i + 1) % 4}: {fmt(term)}")
    return ("1. For each edge i → i+1 (the last wraps to vertex 0) the terms (y_i - y_(i+1))(z_i + z_(i+1)), "
            "(z_i - z_(i+1))(x_i + x_(i+1)), (x_i - x_(i+1))(y_i + y_(i+1)):\n" + "\n".join(lines) + "\n"
            f"2. Their sum is Newell's vector N = {fmt(raw)}, of length √{fmt(raw @ raw)} = {fmt(_r(np.linalg.norm(raw)), 6)}.\n"
            f"3. The unit normal N/|N| = {fmt(_r(shading.unit_newell_normal(P)), 6)}.")


@DECK.exercise(stored={"quad": _tup(NEWELL_QUAD)}, generate=_newell_generate,
               answer=lambda p: shading.unit_newell_normal(_arr(p["quad"])), slips=_newell_slips,
               statement=_newell_statement, steps=_newell_steps, same=within(2e-4), well_posed=_newell_ok)
def check_newell_normal(answer, p) -> Result:
    """Check Newell's unit normal of the statement's quadrilateral (Goldman §21.1).

    Recognises the cross product of the first two edges (one corner's normal, not Newell's), the
    vector left unnormalised, and the opposite orientation.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    P = _arr(p["quad"])
    expected = shading.unit_newell_normal(P)
    raw = _newell_raw(P)
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


def _vertex_forms(p):
    F = _arr(p["faces"])
    units = F / np.linalg.norm(F, axis=1, keepdims=True)
    return F, units, _unit(units.sum(0))


def _vertex_slips(p) -> dict:
    F, units, _ = _vertex_forms(p)
    return {"area-weighted": _unit(F.sum(0)), "not normalised": units.mean(0), "raw average": F.mean(0)}


def _vertex_generate(rng) -> dict:
    faces = []
    for _ in range(3):
        v = rng.integers(-1, 3, size=3)
        v[rng.integers(0, 3)] = rng.integers(1, 3)
        faces.append(v * rng.integers(1, 4))
    return {"faces": _tup(np.array(faces)[:, rng.permutation(3)])}


def _vertex_ok(p):
    F, units, expected = _vertex_forms(p)
    if np.any(np.linalg.norm(F, axis=1) < 0.5):
        return "a face vector is zero"
    if np.linalg.norm(units.sum(0)) < 1.0 or np.linalg.norm(F.sum(0)) < 1.0:
        return "the faces' normals nearly cancel"
    for i in range(3):
        for j in range(i + 1, 3):
            if np.linalg.norm(np.cross(units[i], units[j])) < 0.2 or units[i] @ units[j] < -0.2:
                return "two faces are (nearly) parallel or fold back on each other"
    s = _vertex_slips(p)
    if not _apart([expected, s["area-weighted"], s["not normalised"], units.sum(0), s["raw average"]], 2e-3):
        return "two recognised forms coincide"
    return None


def _vertex_statement(p) -> str:
    return (f"Three triangles meet at a vertex; their Newell vectors (normals whose length is twice the area) are "
            f"{', '.join(fmt(q) for q in p['faces'])}. Give the vertex normal as the book builds it for Gouraud and "
            f"Phong shading: the average of the faces' unit normals, normalised. [x, y, z] to 4 decimals "
            f"(Goldman §21.1).")


def _vertex_steps(p) -> str:
    F, units, expected = _vertex_forms(p)
    lines = "\n".join(f"   {fmt(f)} / {fmt(_r(np.linalg.norm(f)), 6)} = {fmt(_r(u), 6)}" for f, u in zip(F, units))
    return (f"1. Normalise each face vector:\n{lines}\n"
            f"2. Their sum is {fmt(_r(units.sum(0)), 6)} (the average is a third of it: the same direction).\n"
            f"3. Normalise: {fmt(_r(expected), 6)}.")


@DECK.exercise(stored={"faces": _tup(FACE_VECTORS)}, generate=_vertex_generate,
               answer=lambda p: _vertex_forms(p)[2], slips=_vertex_slips, statement=_vertex_statement,
               steps=_vertex_steps, same=within(2e-4), well_posed=_vertex_ok)
def check_vertex_normal(answer, p) -> Result:
    """Check the average of the statement's faces' unit normals, normalised (Goldman §21.1).

    Recognises the area-weighted normal (the raw vectors summed), the average left unnormalised and
    the raw average.
    """
    got, err = _read_vector(answer, "your vertex normal", 3, "the vertex normal as [x, y, z]")
    if err is not None:
        return err
    F, units, expected = _vertex_forms(p)
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

def _cover_count(p) -> int:
    return int((rasteriser.gouraud_triangle(_arr(p["tri"]), [1, 1, 1], 12, 12) > 0).sum())


def _cover_area(x) -> float:
    d1, d2 = x[1] - x[0], x[2] - x[0]
    return 0.5 * abs(d1[0] * d2[1] - d1[1] * d2[0])


def _cover_box(x) -> int:
    lo, hi = np.floor(x.min(0)), np.ceil(x.max(0))
    return int((hi - lo).prod())


def _cover_slips(p) -> dict:
    x = _arr(p["tri"])
    return {"area": round(_cover_area(x)), "bounding box": _cover_box(x)}


def _cover_generate(rng) -> dict:
    return {"tri": _tup(np.round(rng.uniform(0.2, 11.8, size=(3, 2)), 1))}


def _cover_ok(p):
    x = _arr(p["tri"])
    area = _cover_area(x)
    if not 10 <= area <= 45:
        return "the triangle is too small or too big to count by hand"
    edges = [np.linalg.norm(x[i] - x[(i + 1) % 3]) for i in range(3)]
    if min(edges) < 3 or 2 * area / max(edges) < 2:
        return "the triangle is a sliver"
    jj, ii = np.meshgrid(np.arange(12) + 0.5, np.arange(12) + 0.5)
    q = np.stack([jj.ravel(), ii.ravel()], 1)
    for i in range(3):
        a, b = x[i], x[(i + 1) % 3]
        d = b - a
        dist = np.abs(d[0] * (q[:, 1] - a[1]) - d[1] * (q[:, 0] - a[0])) / np.linalg.norm(d)
        along = ((q - a) @ d) / (d @ d)
        if np.any((dist < 0.02) & (along > -0.05) & (along < 1.05)):
            return "a pixel centre lies (nearly) on an edge: inside or outside is a matter of rounding"
    expected = _cover_count(p)
    others = [round(area), _corner_count(x)]
    if expected in others or _cover_box(x) in others + [expected]:
        return "a recognised slip gives the answer's count"
    return None


def _cover_statement(p) -> str:
    return (f"A triangle has screen vertices {', '.join(fmt(q) for q in p['tri'])} (x right, y down). A pixel "
            f"(row i, column j) is drawn when its centre (j + 0.5, i + 0.5) lies inside the triangle. How many pixels "
            f"does scan conversion draw? (Goldman §21.2)")


def _cover_steps(p) -> str:
    x = _arr(p["tri"])
    image = rasteriser.gouraud_triangle(x, [1, 1, 1], 12, 12) > 0
    rows = [f"   row {i} (y = {fmt(i + 0.5)}): columns {int(np.flatnonzero(r)[0])}-{int(np.flatnonzero(r)[-1])}, "
            f"{int(r.sum())} pixel{'s' if r.sum() != 1 else ''}" for i, r in enumerate(image) if r.any()]
    return ("1. In each row i take the scan line y = i + 0.5 and find where it crosses the triangle's left and right "
            "edges; the columns j whose centres j + 0.5 lie between them are drawn:\n" + "\n".join(rows) + "\n"
            f"2. In all {int(image.sum())} pixels (the triangle's area is {fmt(_cover_area(x))}: close, but the count "
            "is of centres).")


@DECK.exercise(stored={"tri": _tup(COVER_TRIANGLE)}, generate=_cover_generate, answer=_cover_count,
               slips=_cover_slips, statement=_cover_statement, steps=_cover_steps, same=within(0.5),
               well_posed=_cover_ok)
def check_pixels_covered(answer, p) -> Result:
    """Check the number of pixel centres inside the statement's triangle (Goldman §21.2).

    Recognises the area (rounded), the count of integer points (pixel corners) instead of centres,
    and the count of pixels the bounding box holds.
    """
    value, err = read_number(answer, "your count", "whole number")
    if err is not None:
        return err
    x = _arr(p["tri"])
    expected = _cover_count(p)
    if value == expected:
        return correct("every centre that passes the three edge tests (all barycentric coordinates >= 0) is drawn.")
    area = _cover_area(x)
    box = _cover_box(x)
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

def _gouraud_at(p, x, y) -> float:
    """The linear interpolation of the instance's intensities at (x, y) (inside the triangle or not)."""
    P = _arr(p["tri"])
    c = _arr(p["I"])
    d1, d2 = P[1] - P[0], P[2] - P[0]
    a = d1[0] * d2[1] - d1[1] * d2[0]
    q = np.array([x, y]) - P[0]
    l1 = (q[0] * d2[1] - q[1] * d2[0]) / a
    l2 = (d1[0] * q[1] - d1[1] * q[0]) / a
    return float((1 - l1 - l2) * c[0] + l1 * c[1] + l2 * c[2])


def _gouraud_answer(p) -> float:
    i, j = p["pixel"]
    P = _arr(p["tri"])
    W, H = max(8, int(np.ceil(P[:, 0].max()))), max(6, int(np.ceil(P[:, 1].max())))
    return float(rasteriser.gouraud_triangle(P, p["I"], W, H)[i, j])


def _gouraud_slips(p) -> dict:
    i, j = p["pixel"]
    P, c = _arr(p["tri"]), _arr(p["I"])
    lam = _bary(P, j + 0.5, i + 0.5)
    return {"corner": _gouraud_at(p, j, i), "swapped": _gouraud_at(p, i + 0.5, j + 0.5), "average": float(c.mean()),
            "nearest vertex": float(c[int(np.argmax(lam))])}


def _bary(P, x, y) -> np.ndarray:
    d1, d2 = P[1] - P[0], P[2] - P[0]
    a = d1[0] * d2[1] - d1[1] * d2[0]
    q = np.array([x, y]) - P[0]
    l1 = (q[0] * d2[1] - q[1] * d2[0]) / a
    l2 = (d1[0] * q[1] - d1[1] * q[0]) / a
    return np.array([1 - l1 - l2, l1, l2])


def _gouraud_generate(rng) -> dict:
    P = rng.integers(0, [11, 9], size=(3, 2)).astype(float)
    I = rng.choice(np.arange(1, 10), size=3, replace=False) / 10
    inside = [(i, j) for i in range(9) for j in range(11)
              if _cover_area(P) > 0 and _bary(P, j + 0.5, i + 0.5).min() >= 0.05]
    i, j = inside[int(rng.integers(0, len(inside)))] if inside else (0, 0)
    return {"tri": _tup(P), "I": _tup(I), "pixel": (i, j)}


def _gouraud_ok(p):
    P, c = _arr(p["tri"]), _arr(p["I"])
    i, j = p["pixel"]
    if _cover_area(P) < 12:
        return "the triangle is too small"
    lam = _bary(P, j + 0.5, i + 0.5)
    if lam.min() < 0.05:
        return "the pixel's centre is outside the triangle or on an edge"
    if i == j:
        return "row and column are equal: swapping them is no slip"
    if abs(_gouraud_answer(p) - 0.5) < 1e-3:
        return "the answer is 0.5, a number every hint about pixel centres shows"
    s = _gouraud_slips(p)
    values = [_gouraud_answer(p), s["corner"], s["swapped"], s["average"]] + list(c)   # (the nearest is one of c)
    if not _apart(values, 5e-3):
        return "two recognised forms coincide"
    return None


def _gouraud_statement(p) -> str:
    return (f"Gouraud shading: a triangle has screen vertices {', '.join(fmt(q) for q in p['tri'])} with "
            f"intensities {', '.join(fmt(c) for c in p['I'])}. Give the intensity at the pixel in row "
            f"{p['pixel'][0]}, column {p['pixel'][1]} (the intensities interpolated linearly at its centre), "
            f"to 4 decimals (Goldman §21.3).")


def _gouraud_steps(p) -> str:
    P, c = _arr(p["tri"]), _arr(p["I"])
    i, j = p["pixel"]
    lam = _bary(P, j + 0.5, i + 0.5)
    return (f"1. The pixel in row {i}, column {j} is centred at ({fmt(j + 0.5)}, {fmt(i + 0.5)}).\n"
            f"2. Its barycentric coordinates in the triangle (ratios of signed areas) are {fmt(_r(lam), 6)}.\n"
            f"3. The intensity is {' + '.join(f'{fmt(w, 6)}·{fmt(v)}' for w, v in zip(_r(lam), c))} = "
            f"{fmt(_r(_gouraud_answer(p)), 6)}.")


@DECK.exercise(stored={"tri": _tup(GOURAUD_TRIANGLE), "I": _tup(GOURAUD_INTENSITIES), "pixel": GOURAUD_PIXEL},
               generate=_gouraud_generate, answer=_gouraud_answer, slips=_gouraud_slips,
               statement=_gouraud_statement, steps=_gouraud_steps, same=within(1e-4), well_posed=_gouraud_ok)
def check_gouraud_pixel(answer, p) -> Result:
    """Check the Gouraud intensity at the statement's pixel (Goldman §21.3).

    Recognises the pixel's corner used instead of its centre, rows and columns swapped, the average
    of the three intensities (the centroid's) and the nearest vertex's intensity (uniform shading).
    """
    value, err = read_number(answer, "your intensity")
    if err is not None:
        return err
    i, j = p["pixel"]
    intensities = _arr(p["I"])
    expected = _gouraud_answer(p)
    tol = 1e-4
    if abs(value - expected) <= tol:
        return correct("the three vertex intensities weighted by the pixel centre's barycentric coordinates, "
                       "as the scan line interpolates them along the edges and then across.")
    if abs(value - _gouraud_at(p, j, i)) <= tol:
        return wrong("you interpolated at the pixel's corner (j, i); the pixel is sampled at its centre "
                     "(j + 0.5, i + 0.5).")
    if abs(value - _gouraud_at(p, i + 0.5, j + 0.5)) <= tol:
        return wrong("you swapped row and column: x is the column j, y is the row i.")
    if abs(value - float(np.mean(intensities))) <= tol:
        return wrong("that is the average of the three intensities, the value at the centroid only; weight each "
                     "by the pixel's barycentric coordinate.")
    if any(abs(value - c) <= tol for c in intensities):
        return wrong("that is one vertex's intensity, as uniform shading would give; Gouraud interpolates the "
                     "three across the face.")
    return wrong(f"your intensity is {off_by(value, expected)}; find the barycentric coordinates of "
                 f"(j + 0.5, i + 0.5) and weight the intensities by them.")


# -- §21.4 Phong ---------------------------------------------------------------------------------------

#: unit normals with short decimals (3-4-5 triangles), and unit light directions written as fractions
_NORMALS = tuple(tuple(float(v) for v in n) for n in
                 [(0, 0.6, 0.8), (0.8, 0, 0.6), (0.6, 0.8, 0), (0, 0.8, 0.6), (0.6, 0, 0.8), (0.8, 0.6, 0),
                  (0, 0, 1), (0, 1, 0), (1, 0, 0), (0, -0.6, 0.8), (-0.6, 0, 0.8), (0.6, -0.8, 0), (-0.8, 0, 0.6)])
_LIGHTS = {(1 / 3, 2 / 3, 2 / 3): "(1/3, 2/3, 2/3)", (2 / 3, 1 / 3, 2 / 3): "(2/3, 1/3, 2/3)",
           (2 / 3, 2 / 3, 1 / 3): "(2/3, 2/3, 1/3)", (2 / 7, 3 / 7, 6 / 7): "(2/7, 3/7, 6/7)",
           (6 / 7, 2 / 7, 3 / 7): "(6/7, 2/7, 3/7)", (3 / 7, 6 / 7, 2 / 7): "(3/7, 6/7, 2/7)"}


def _phong_parts(p):
    return _arr(p["Na"]), _arr(p["Nb"]), _arr(p["L"]), p["t"]


def _phong_answer(p) -> float:
    a, b, L, t = _phong_parts(p)
    return float(L @ _unit((1 - t) * a + t * b))


def _phong_slips(p) -> dict:
    a, b, L, t = _phong_parts(p)
    return {"Gouraud": float((1 - t) * (L @ a) + t * (L @ b)), "other end": float(L @ _unit(t * a + (1 - t) * b))}


def _phong_generate(rng) -> dict:
    k = rng.choice(len(_NORMALS), size=2, replace=False)
    L = list(_LIGHTS)[int(rng.integers(0, len(_LIGHTS)))]
    return {"Na": _NORMALS[k[0]], "Nb": _NORMALS[k[1]], "t": float(rng.choice([0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8])),
            "L": L}


def _phong_ok(p):
    a, b, L, t = _phong_parts(p)
    if a @ b < 0.2:
        return "the end normals are more than about 80 degrees apart"
    if min(L @ a, L @ b) <= 0.05:
        return "the light is behind one end of the span"
    values = [_phong_answer(p)] + list(_phong_slips(p).values())
    if not _apart(values, 2e-3):
        return "two recognised forms coincide"
    return None


def _phong_statement(p) -> str:
    return (f"Phong shading: on a scan line the normals at the two ends of a span are N_a = {fmt(p['Na'])} and "
            f"N_b = {fmt(p['Nb'])}. At the pixel a fraction t = {fmt(p['t'])} of the way from a to b, give the "
            f"diffuse cosine L·N for the unit light direction L = {_LIGHTS.get(tuple(p['L']), fmt(p['L']))}, with N "
            f"the interpolated normal made unit length, to 4 decimals (Goldman §21.4.1).")


def _phong_steps(p) -> str:
    a, b, L, t = _phong_parts(p)
    N = (1 - t) * a + t * b
    return (f"1. N = (1 - t) N_a + t N_b = {fmt(1 - t)}·{fmt(a)} + {fmt(t)}·{fmt(b)} = {fmt(_r(N), 6)}.\n"
            f"2. |N| = √{fmt(_r(N @ N), 6)} = {fmt(_r(np.linalg.norm(N)), 6)}; the unit normal is "
            f"{fmt(_r(_unit(N)), 6)}.\n"
            f"3. L·N = {fmt(_r(_phong_answer(p)), 6)}.")


@DECK.exercise(stored={"Na": _tup(PHONG_NA), "Nb": _tup(PHONG_NB), "t": PHONG_T, "L": _tup(PHONG_L)},
               generate=_phong_generate, answer=_phong_answer, slips=_phong_slips, statement=_phong_statement,
               steps=_phong_steps, same=within(1e-4), well_posed=_phong_ok)
def check_phong_diffuse(answer, p) -> Result:
    """Check L·N at t along the span, N the normalised linear interpolation of the end normals
    (Goldman §21.4.1).

    Recognises Gouraud's answer (the end cosines interpolated), the normal left unnormalised, and
    t measured from the other end.
    """
    value, err = read_number(answer, "your cosine")
    if err is not None:
        return err
    a, b, L, t = _phong_parts(p)
    expected = _phong_answer(p)
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


def _fd_answer(p) -> np.ndarray:
    a, b, c = p["abc"]
    values = shading.forward_differences([c, b, 0, a, 0, 0], p["x0"], 0, 3)
    return np.array([values[0], values[1] - values[0], values[2] - 2 * values[1] + values[0]])


def _fd_slips(p) -> dict:
    a, b, c = p["abc"]
    x0 = p["x0"]
    f = _fd_answer(p)
    return {"a for 2a": np.array([f[0], f[1], a]), "derivative": np.array([f[0], 2 * a * x0 + b, f[2]]),
            "backward": np.array([f[0], 2 * a * x0 - a + b, f[2]])}


def _fd_generate(rng) -> dict:
    a = float(rng.integers(2, 10)) / 1000
    b = float(rng.integers(-9, 10)) / 100
    c = float(rng.integers(5, 11)) / 10
    return {"abc": (a, b, c), "x0": int(rng.integers(4, 21))}


def _fd_ok(p):
    a, b, c = p["abc"]
    if b == 0:
        return "b = 0 (the quadratic is even: too special)"
    values = [_fd_answer(p)] + list(_fd_slips(p).values())
    if not _apart(values, 1e-3):
        return "two recognised forms coincide"
    return None


def _fd_statement(p) -> str:
    a, b, c = p["abc"]
    x0 = p["x0"]
    return (f"Along one scan line fast Phong shading evaluates a quadratic f(X) = {fmt(a)} X^2 "
            f"{b:+g} X + {fmt(c)} by forward differences, starting at X = {x0}. Give "
            f"[f({x0}), Δf({x0}), Δ²f] with Δf(X) = f(X + 1) - f(X) and Δ²f = Δf(X + 1) - Δf(X), "
            f"to 4 decimals: then each next pixel costs two additions (Goldman §21.4.2).")


def _fd_steps(p) -> str:
    a, b, c = p["abc"]
    x0 = p["x0"]
    v = shading.forward_differences([c, b, 0, a, 0, 0], x0, 0, 3)
    f = _fd_answer(p)
    return (f"1. f({x0}) = {fmt(_r(v[0]), 6)}, f({x0 + 1}) = {fmt(_r(v[1]), 6)}, f({x0 + 2}) = {fmt(_r(v[2]), 6)}.\n"
            f"2. Δf({x0}) = f({x0 + 1}) - f({x0}) = {fmt(_r(f[1]), 6)} (= 2a·{x0} + a + b).\n"
            f"3. Δ²f = f({x0 + 2}) - 2 f({x0 + 1}) + f({x0}) = {fmt(_r(f[2]), 6)} = 2a, the same at every pixel.")


@DECK.exercise(stored={"abc": _tup(QUADRATIC), "x0": QUADRATIC_X0}, generate=_fd_generate, answer=_fd_answer,
               slips=_fd_slips, statement=_fd_statement, steps=_fd_steps, same=within(1e-4), well_posed=_fd_ok)
def check_forward_differences(answer, p) -> Result:
    """Check [f(x0), Δf(x0), Δ²f] for the statement's quadratic (Goldman §21.4.2).

    Recognises the derivative f'(x0) in place of the first difference, a in place of the second
    difference 2a, and the backward difference f(x0) - f(x0 - 1).
    """
    got, err = _read_vector(answer, "your answer", 3, "[f(x0), Δf(x0), Δ²f]")
    if err is not None:
        return err
    a, b, c = p["abc"]
    x0 = p["x0"]
    expected = _fd_answer(p)
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


def _lerp_answer(p) -> float:
    theta = math.radians(p["angle"])
    n0, n1 = np.array([1.0, 0.0]), np.array([math.cos(theta), math.sin(theta)])
    got_n = vg.nlerp(n0, n1, p["t"])
    return math.degrees(math.atan2(got_n[1], got_n[0]))


def _lerp_slips(p) -> dict:
    return {"slerp": p["t"] * p["angle"], "from N1": p["angle"] - _lerp_answer(p)}


def _lerp_generate(rng) -> dict:
    return {"angle": float(rng.choice([60.0, 80.0, 90.0, 100.0, 120.0, 135.0, 150.0])),
            "t": float(rng.choice([0.1, 0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8, 0.9]))}


def _lerp_ok(p):
    values = [_lerp_answer(p), p["t"] * p["angle"], p["angle"] - _lerp_answer(p), (1 - p["t"]) * p["angle"]]
    if not _apart(values, 0.1):
        return "two recognised forms coincide"
    return None


def _lerp_statement(p) -> str:
    return (f"Two unit vertex normals are {fmt(p['angle'])} degrees apart. Phong shading interpolates them linearly "
            f"and normalises: N(t) = ((1 - t) N0 + t N1) / |(1 - t) N0 + t N1|. At t = {fmt(p['t'])}, how many degrees "
            f"is N(t) from N0? Give it to 2 decimals; slerp (§21.4.4) would move at constant speed (Goldman §21.4).")


def _lerp_steps(p) -> str:
    th, t = p["angle"], p["t"]
    n1 = np.array([math.cos(math.radians(th)), math.sin(math.radians(th))])
    N = (1 - t) * np.array([1.0, 0.0]) + t * n1
    return (f"1. Put N0 = (1, 0) and N1 = (cos {fmt(th)}°, sin {fmt(th)}°) = {fmt(_r(n1), 6)} in their plane.\n"
            f"2. (1 - t) N0 + t N1 = {fmt(_r(N), 6)} (its length {fmt(_r(np.linalg.norm(N)), 6)} does not change "
            f"its direction).\n"
            f"3. Its angle is atan2({fmt(_r(N[1]), 6)}, {fmt(_r(N[0]), 6)}) = {fmt(_r(_lerp_answer(p)), 6)}°, "
            f"against t θ = {fmt(t * th)}° for slerp.")


@DECK.exercise(stored={"angle": NLERP_ANGLE, "t": NLERP_T}, generate=_lerp_generate, answer=_lerp_answer,
               slips=_lerp_slips, statement=_lerp_statement, steps=_lerp_steps, same=within(0.01),
               well_posed=_lerp_ok)
def check_lerp_angle(answer, p) -> Result:
    """Check the angle from N0 of the normalised linear interpolation at t (Goldman §21.4, §21.4.4).

    Recognises t θ (what slerp gives), (1 - t) θ (the angle from N1) and the angle of the
    interpolation measured from the other normal.
    """
    value, err = read_number(answer, "your angle", "number of degrees")
    if err is not None:
        return err
    angle, t = p["angle"], p["t"]
    expected = _lerp_answer(p)
    tol = 0.01
    if abs(value - expected) <= tol:
        return correct(f"{'less' if t < 0.5 else 'more'} than t θ: normalised linear interpolation lags near the "
                       f"ends and rushes through the middle; slerp (§21.4.4) moves at constant speed.")
    if abs(value - t * angle) <= tol:
        return wrong("that is t θ, where slerp would be; linear interpolation followed by normalising does not "
                     "move at constant angular speed. Compute the angle of (1 - t) N0 + t N1.")
    if abs(value - (1 - t) * angle) <= tol or abs(value - (angle - expected)) <= tol:
        return wrong("that is the angle from N1; the question asks how far N(t) is from N0.")
    return wrong(f"your angle is {off_by(value, expected)}; put N0 = (1, 0) and N1 = (cos θ, sin θ), form "
                 f"(1 - t) N0 + t N1, and take its angle with atan2.")


#: Deal another instance of an exercise (``deal("check_gouraud_pixel")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


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
        corners = rasteriser.gouraud_triangle(P + 0.5, c, W, H)    # sampling at (j, i) = the centres of the shifted image
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
    against :func:`goldman_lib.rasteriser.gouraud_triangle` on :func:`gouraud_project_cases`
    (Goldman §21.3).

    >>> def flat(screen, intensities, width, height):
    ...     return np.full((height, width), float(np.mean(intensities)))
    >>> print(check_gouraud_project(flat).message)   # doctest: +ELLIPSIS
    case 1 of 14 (vertices ...): your function returned ...; pixel (row 0, column 0), ... lies outside the triangle (it should stay 0). Hint: ...
    """
    return check_project(function, gouraud_project_cases(), reference=rasteriser.gouraud_triangle,
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
