"""Exercise checkers for chapter 30, subdivision surfaces (Goldman §30.2-30.4), and the checker of
the chapter's programming project.

Every numeric exercise deals new numbers (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below (the stored notebook), ``deal("check_...")`` or
``deal_button("check_...")`` deals another, each checker checks the current instance,
``PROBLEMS`` states it and ``steps("check_...")`` shows its worked steps, computed by the library.
The "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) and the programming project do
not deal.  ``SLIPS`` holds the wrong answers of the kinds each checker recognises, for the stored
instances.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import subdivision_surfaces as ss
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.deal import Deck, memo, plain as _tup, steps_number as _f, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "BOX_MULTIPLICITIES", "PRISM_SIDES", "PRISM_LEVELS", "QUAD_EDGE_POINTS",
           "STAR_VALENCE", "STAR_HEIGHTS", "TETRA_VERTICES", "EDGE_POINTS", "DECK", "deal", "steps", "current",
           "deal_button",
           "check_box_spline_mask", "check_prism_counts", "check_quad_edge_point", "check_extraordinary_height",
           "check_tetrahedron_vertex", "check_triangle_edge_point", "check_ring_step_project"]

#: Exercise 1: the multiplicities (r, s, t) of the directions e1, e2, e3 of the box spline.
BOX_MULTIPLICITIES = (2, 2, 1)
#: Exercise 2: the prism over a pentagon and the number of levels of the quadrilateral scheme.
PRISM_SIDES = 5
PRISM_LEVELS = 2
#: Exercise 3: the edge (v, w) and the other two vertices of each of its quadrilaterals.
QUAD_EDGE_POINTS = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0],     # v, w
                             [2.0, 2.0, 1.0], [0.0, 2.0, 1.0],     # x1, y1: face (v, w, x1, y1)
                             [0.0, -2.0, 2.0], [2.0, -2.0, 0.0]])  # y2, x2: face (w, v, y2, x2)
#: Exercise 4: a vertex of valence 5 in a quadrilateral mesh; heights (z) of the vertex, of its
#: edge neighbours and of its diagonal neighbours.
STAR_VALENCE = 5
STAR_HEIGHTS = (8.0, 2.0, 6.0)
#: Exercise 5: the regular tetrahedron (valence 3 everywhere) and the vertex asked about (row 0).
TETRA_VERTICES = np.array([[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]])
#: Exercise 6: the edge (v, w) and the opposite vertices x, y of its two triangles.
EDGE_POINTS = np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [2.0, 3.0, 1.0], [2.0, -3.0, 3.0]])

#: Relative tolerance for hand-computed decimals.
REL_TOL = 1e-4


DECK = Deck("ch30")

_WORDS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight"}
_POLYGONS = {3: ("triangle", "triangular"), 4: ("square", "square"), 5: ("pentagon", "pentagonal"),
             6: ("hexagon", "hexagonal"), 7: ("heptagon", "heptagonal"), 8: ("octagon", "octagonal")}


def _pts(P):
    return ", ".join(fmt(p) for p in P)


def _arr(v):
    return np.asarray(v, dtype=float)


def _times(k: int) -> str:
    return f"{k} time" + ("" if k == 1 else "s")


#: The checkers' tolerance (hand-computed decimals to a relative 1e-4), a little wider, and
#: answers of other shapes apart.
_same = within(REL_TOL, relative=True)


# -- reading and comparing -------------------------------------------------------------------------

def _close(got, expected) -> bool:
    exp = np.asarray(expected, dtype=float)
    return got.shape == exp.shape and bool(np.all(np.abs(got - exp) <= REL_TOL * np.maximum(1.0, np.abs(exp))))


def _point(answer, what, ask):
    got, err = read_points(answer, what, ask=ask)
    if err is not None:
        return None, err
    if got.shape != (3,):
        return None, wrong(f"{what} should be one point [x, y, z]; yours has shape {got.shape}.")
    return got, None


def _far(got, expected, what, hint) -> Result:
    return wrong(f"{what} is {far_off(got, np.asarray(expected))} from where it should be; "
                 f"{hint}.")


# -- §30.2 box splines -------------------------------------------------------------------------------

def _box_mask(multiplicities):
    delta = np.zeros((9, 9, 1))
    delta[4, 4] = 1.0
    box = ss.box_spline_split_and_average(delta, multiplicities, 1)[..., 0]
    return box[np.abs(box).sum(1) > 0][:, np.abs(box).sum(0) > 0]


def _box_scale(m) -> int:
    """The factor that makes the mask whole: 2^(r + s + t - 2)."""
    r, s, t = m
    return 2 ** (r + s + t - 2)


_STORED_BOX = {"m": tuple(BOX_MULTIPLICITIES)}
_BOXES = ((2, 2, 1), (2, 2, 2), (3, 2, 1), (2, 3, 1), (3, 3, 1), (3, 2, 2), (2, 3, 2), (3, 3, 2))


@memo
def _box_answers(p):
    m = p["m"]
    r, s, _ = m
    K = _box_scale(m)
    expected = _box_mask(m) * K
    no_e3 = np.outer([math.comb(r, i) for i in range(r + 1)], [math.comb(s, j) for j in range(s + 1)]).astype(float)
    return expected, {"mirrored": expected[::-1], "not scaled": expected / K, "no e3 factor": no_e3,
                      "halved": expected / 2}


def _size(k: int) -> str:
    return _WORDS.get(k, str(k))


def _box_statement(p) -> str:
    r, s, t = p["m"]
    K = _box_scale(p["m"])
    rows, cols = r + t + 1, s + t + 1
    return (f"On a regular grid, one level of split and average for the box spline with multiplicities "
            f"{tuple(p['m'])} for the directions e1 = (1, 0), e2 = (0, 1), e3 = (1, 1): split, then average "
            f"r - 1 = {_times(r - 1)} along e1, s - 1 = {_times(s - 1)} along e2 and t = {_times(t)} along e3. "
            f"Give its mask times {K}, as a "
            f"{rows} x {cols} list of rows laid out like the masks printed in §30.2, with the e3 diagonal running "
            f"from top left to bottom right (Goldman §30.2).")


def _box_steps(p) -> str:
    r, s, t = p["m"]
    K = _box_scale(p["m"])
    no_e3 = _box_answers(p)[1]["no e3 factor"]
    return (f"1. Splitting gives the mask (1 + x)(1 + y); each averaging along a direction multiplies it by "
            f"(1 + x)/2, (1 + y)/2 or (1 + xy)/2.\n"
            f"2. So the mask is (1 + x)^{r} (1 + y)^{s} (1 + xy)^{t} / 2^{r + s + t - 2}; times {K} it is the "
            f"polynomial multiplied out.\n"
            f"3. (1 + x)^{r} (1 + y)^{s} has the coefficients {'; '.join(_f(row) for row in no_e3)} (rows: powers of "
            f"x, columns: powers of y); each factor (1 + xy) adds a copy shifted one step down the diagonal.\n"
            f"4. The mask times {K}: {'; '.join(_f(row) for row in _box_answers(p)[0])} (the entries total {4 * K}).")


@DECK.exercise(stored=_STORED_BOX, generate=lambda rng: {"m": _BOXES[int(rng.integers(0, len(_BOXES)))]},
               answer=lambda p: _box_answers(p)[0], slips=lambda p: _box_answers(p)[1], statement=_box_statement,
               steps=_box_steps, same=_same)
def check_box_spline_mask(answer, p) -> Result:
    """Check the mask (scaled to whole numbers) of the statement's box spline (Goldman §30.2);
    recognises the mirrored layout (the e3 diagonal the other way), the mask not scaled, the
    mask without the e3 factor, and entries that do not sum to the scaled total.
    """
    got, err = read_points(answer, "your mask", ask=f"the mask times {_box_scale(p['m'])} as a list of rows")
    if err is not None:
        return err
    m = p["m"]
    r, s, t = m
    K = _box_scale(m)
    expected = _box_mask(m) * K
    no_e3 = _box_answers(p)[1]["no e3 factor"]
    if got.shape == no_e3.shape and _close(got, no_e3):
        kind = "bilinear box spline " if (r, s) == (2, 2) else "box spline "
        return wrong(f"that is the mask of the {kind}(1 + x)^{r} (1 + y)^{s}, without the averaging "
                     f"along e3; {'one averaging' if t == 1 else f'each of the {t} averagings'} along e3 multiplies "
                     f"it by (1 + xy) and shifts a copy along the diagonal.")
    if got.shape != expected.shape:
        shape = f"{_size(expected.shape[0])} by {_size(expected.shape[1])}"
        return wrong(f"the mask should be a {shape} list of rows; yours has shape {got.shape}.")
    if _close(got, expected):
        factors = f"(1 + x)^{r} (1 + y)^{s} (1 + xy)" + (f"^{t}" if t > 1 else "")
        return correct(f"the mask is {factors} / {K} multiplied out: each new point is an affine "
                       f"combination of the old ones.")
    if _close(got, expected[::-1]) or _close(got, expected[:, ::-1]):
        return wrong("that is the mask mirrored: the averaging along e3 = (1, 1) adds P[i+1, j+1] to P[i, j], so "
                     "the band of the diagonal runs from top left to bottom right, as in the masks of §30.2.")
    if _close(got, expected / K):
        return wrong(f"those are the weights themselves; the exercise asks for the mask times {K} (whole numbers).")
    if _close(got * 2, expected):
        return wrong(f"the entries should total {4 * K} (four kinds of new points, each an affine combination, times "
                     f"{K}); yours total half of that: one factor of 1/2 too many.")
    total = got.sum()
    if abs(total - 4 * K) > 1e-6:
        yours = ("total " + fmt(total) if abs(total - 4 * K) >= 0.5
                 else "miss that total by a little (an entry rounded?)")
        return wrong(f"the entries of the mask times {K} should total {4 * K} (four kinds of new points, each an "
                     f"affine combination); yours {yours}"
                     f". Multiply (1 + x)^{r} (1 + y)^{s} by (1 + xy)" + (f"^{t}" if t > 1 else "") + ".")
    bad = np.argwhere(np.abs(got - expected) > 1e-6)
    i, j = (int(x) for x in bad[0])
    return wrong(f"the entry in row {i}, column {j} is {off_by(got[i, j], expected[i, j])}; the mask is the "
                 f"product of the direction factors (1 + x)^{r} (1 + y)^{s} (1 + xy)" + (f"^{t}" if t > 1 else "")
                 + ": multiply the mask of (1 + x)^r (1 + y)^s by (1 + xy), that is, add to it a copy shifted one "
                   "step along the diagonal.")


# -- §30.3 quadrilateral meshes ----------------------------------------------------------------------

_STORED_PRISM = {"n": PRISM_SIDES, "levels": PRISM_LEVELS}


def _counts(mesh) -> tuple:
    return (mesh.n_vertices, mesh.n_edges, mesh.n_faces)


@memo
def _prism_levels(p) -> list:
    """[V, E, F] of the prism after 0, 1, ..., levels levels (the library's meshes)."""
    mesh = ss.prism(p["n"])
    return [_counts(mesh)] + [_counts(ss.centroid_averaging(mesh, k)) for k in range(1, p["levels"] + 1)]


@memo
def _prism_answers(p):
    counts = _prism_levels(p)
    L, F0 = p["levels"], counts[0][2]
    (V, E, F), (V1, E1, _) = counts[L], counts[L - 1]
    slips = {"one level short": counts[L - 1], "face points left out": (V1 + E1, E, F),
             "F = 4F": (V, E, 4 ** L * F0), "V - E + F not 2": (V, E + 2, F)}
    return counts[L], slips


def _prism_generate(rng) -> dict:
    """The notebook's exercise counts two levels: the prism's polygon deals, the levels stay."""
    return {"n": int(rng.choice([3, 5, 6, 7, 8])), "levels": PRISM_LEVELS}


def _prism_statement(p) -> str:
    n = p["n"]
    V, E, F = _prism_levels(p)[0]
    name = _POLYGONS[n][0]
    return (f"The prism over a {name} has V = {V} vertices, E = {E} edges and F = {F} faces ({_WORDS[n]} "
            f"quadrilaterals and two {name}s). After {p['levels']} levels of quadrilateral centroid averaging, how "
            f"many vertices, edges and faces are there? Give [V, E, F] (Goldman §30.3).")


def _prism_steps(p) -> str:
    counts = _prism_levels(p)
    n = p["n"]
    lines = [f"1. Each level: V' = V + E + F (old vertices, edge points, face points), E' = 2E + (sum of face "
             f"sizes), F' = sum of face sizes (a k-gon becomes k quadrilaterals); the averaging moves points only."]
    for k in range(1, len(counts)):
        sizes = 2 * n + 4 * n if k == 1 else 4 * counts[k - 1][2]
        lines.append(f"{k + 1}. Level {k}: the face sizes sum to {sizes}; V, E, F = {counts[k]} "
                     f"(V - E + F = {counts[k][0] - counts[k][1] + counts[k][2]}).")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_PRISM, generate=_prism_generate, answer=lambda p: _prism_answers(p)[0],
               slips=lambda p: _prism_answers(p)[1], statement=_prism_statement, steps=_prism_steps,
               same=within(1e-9))
def check_prism_counts(answer, p) -> Result:
    """Check [V, E, F] of the statement's prism after its levels of the quadrilateral scheme
    (Goldman §30.3); recognises the counts one level short, face points left out, F = 4F (as if all
    faces were quadrilaterals), and an answer whose V - E + F is not 2.

    >>> check_prism_counts([32, 60, 30])
    Not yet: those are the counts after one level; apply the rules V' = V + E + F, E' = 2E + (sum of face sizes), F' = sum of face sizes once more (now every face is a quadrilateral).
    """
    what = "[V, E, F]"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} should be three numbers; yours has shape {got.shape}.")
    if not np.allclose(got, np.round(got)):
        return wrong("V, E and F count vertices, edges and faces: they are whole numbers.")
    if np.abs(got).max() > 1e6:
        return wrong("each level multiplies the counts of a small prism by about four, not by millions; count "
                     "each level with V' = V + E + F.")
    V, E, F = (int(round(x)) for x in got)
    counts = _prism_levels(p)
    L, n = p["levels"], p["n"]
    F0 = counts[0][2]
    expected = counts[L]
    if (V, E, F) == expected:
        return correct(f"{_WORDS[L]} levels take the {_POLYGONS[n][1]} prism to V, E, F = {expected}, and "
                       f"V - E + F = 2 at every level.")
    if (V, E, F) == counts[L - 1]:
        levels = "one level" if L == 2 else f"{_WORDS[L - 1]} levels"
        return wrong(f"those are the counts after {levels}; apply the rules V' = V + E + F, E' = 2E + (sum of "
                     "face sizes), F' = sum of face sizes once more (now every face is a quadrilateral).")
    if V == counts[L - 1][0] + counts[L - 1][1]:
        return wrong("V leaves out the face points: the bilinear split adds a point at every edge and at every "
                     "face, V' = V + E + F.")
    if F == 4 * F0 or F == 4 ** L * F0:
        return wrong(f"a k-gon is cut into k quadrilaterals, not 4: the two {_POLYGONS[n][0]}s give {_WORDS[n]} "
                     f"each, so at the first level F' is the sum of the face sizes.")
    chi = V - E + F
    if chi != 2:
        return wrong(f"your counts give V - E + F = {chi}, but subdivision refines the mesh without changing its "
                     f"topology, so V - E + F stays what it was for the prism. Count each level with V' = V + E + F, "
                     f"E' = 2E + (sum of face sizes), F' = sum of face sizes.")
    return wrong("V - E + F is right but the counts are not; count each level with V' = V + E + F, "
                 "E' = 2E + (sum of face sizes), F' = sum of face sizes.")


_STORED_QUAD_EDGE = {"points": _tup(QUAD_EDGE_POINTS)}


@memo
def _quad_edge_answers(p):
    v, w, x1, y1, y2, x2 = _arr(p["points"])
    others = x1 + y1 + y2 + x2
    ea, eb = ss.quad_edge_stencil()
    mid = (v + w) / 2
    f1, f2 = (v + w + x1 + y1) / 4, (w + v + y2 + x2) / 4
    slips = {"midpoint": mid, "old face centroids": (f1 + f2) / 2, "equal weights": (mid + f1 + f2) / 3,
             "triangle weights": 3 / 8 * (v + w) + 1 / 8 * others}
    return ea * (v + w) + eb * others, slips


def _quad_edge_generate(rng) -> dict:
    return {"points": _tup(rng.integers(-2, 3, size=(6, 3)) * 2)}


def _quad_edge_ok(p):
    v, w, x1, y1, y2, x2 = _arr(p["points"])
    if np.allclose(v, w) or not np.any(np.cross(w - v, x1 - v)) or not np.any(np.cross(w - v, x2 - v)):
        return "a degenerate edge or face"
    return None


def _quad_edge_statement(p) -> str:
    P = _arr(p["points"])
    return (f"An edge of a quadrilateral mesh runs from v = {fmt(P[0])} to w = {fmt(P[1])}. "
            f"Its two faces are (v, w, {fmt(P[2])}, {fmt(P[3])}) and "
            f"(w, v, {fmt(P[4])}, {fmt(P[5])}). Where is the new edge point after one "
            f"level of quadrilateral centroid averaging? Give [x, y, z] (Goldman §30.3).")


def _quad_edge_steps(p) -> str:
    v, w, x1, y1, y2, x2 = _arr(p["points"])
    ea, eb = ss.quad_edge_stencil()
    return (f"1. After the split the edge's midpoint lies in four small quadrilaterals; the average of their "
            f"centroids gives the stencil {_f(ea)} (v + w) + {_f(eb)} (the four other corners) (§30.3).\n"
            f"2. v + w = {fmt(v + w)}; the other corners sum to {fmt(x1 + y1 + y2 + x2)}.\n"
            f"3. The edge point = {_f(_quad_edge_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_QUAD_EDGE, generate=_quad_edge_generate, answer=lambda p: _quad_edge_answers(p)[0],
               slips=lambda p: _quad_edge_answers(p)[1], statement=_quad_edge_statement, steps=_quad_edge_steps,
               same=_same, well_posed=_quad_edge_ok)
def check_quad_edge_point(answer, p) -> Result:
    """Check the edge point of the quadrilateral scheme for the statement's edge (Goldman §30.3);
    recognises the midpoint, the average of the two face centroids, the triangle weights, and the
    midpoint averaged with the face centroids with equal weights.
    """
    got, err = _point(answer, "the edge point", "the edge point as [x, y, z]")
    if err is not None:
        return err
    v, w, x1, y1, y2, x2 = _arr(p["points"])
    others = x1 + y1 + y2 + x2
    ea, eb = ss.quad_edge_stencil()
    expected = ea * (v + w) + eb * others
    if _close(got, expected):
        return correct("the edge point is 3/8 (v + w) + 1/16 (the four other corners of its two faces): the "
                       "average of the centroids of the four small quadrilaterals around the edge's midpoint.")
    mid = (v + w) / 2
    f1, f2 = (v + w + x1 + y1) / 4, (w + v + y2 + x2) / 4
    if _close(got, mid):
        return wrong("that is the midpoint of the edge, where the bilinear split puts the new point; the averaging "
                     "step then moves it to the centroid of the centroids of its four small faces.")
    if _close(got, (f1 + f2) / 2):
        return wrong("that is the average of the centroids of the two old faces; the edge point lies in four "
                     "small quadrilaterals of the split mesh, and their centroids are what is averaged.")
    if _close(got, (mid + f1 + f2) / 3):
        return wrong("you averaged the midpoint and the two face centroids with equal weights; average instead the "
                     "centroids of the four small quadrilaterals (midpoint, an end's half, a face centroid, ...) "
                     "around the midpoint.")
    if _close(got, 3 / 8 * (v + w) + 1 / 8 * others):
        return wrong("those are the triangle scheme's weights 3/8, 1/8; in a quadrilateral mesh the edge has four "
                     "other corners and each gets 1/16 (the weights must sum to one).")
    return _far(got, expected, "the edge point", "average the centroids of the four small quadrilaterals around the "
                                                 "midpoint of the edge")


_STORED_STAR = {"n": STAR_VALENCE, "heights": tuple(STAR_HEIGHTS)}


def _star_slips(p):
    n = p["n"]
    zv, zu, zd = p["heights"]
    face = (zv + 2 * zu + zd) / 4
    return {
        "valence 4": 9 / 16 * zv + n * 3 / 32 * zu + n * 1 / 64 * zd,
        "swapped": 9 / 16 * zv + n * 1 / (16 * n) * zu + n * 3 / (8 * n) * zd,
        "no diagonals": 9 / 16 * zv + n * 3 / (8 * n) * zu,
        "triangle": 5 / 8 * zv + n * 3 / (8 * n) * zu,
        "catmull-clark": (face + 2 * (zv + zu) / 2 + (n - 3) * zv) / n,
    }


def _star_answer(p) -> float:
    n = p["n"]
    a, b, c = ss.quad_vertex_stencil(n)
    zv, zu, zd = p["heights"]
    return a * zv + n * b * zu + n * c * zd


def _star_generate(rng) -> dict:
    """The notebook's exercise is the vertex of valence 5: the heights deal, the valence stays."""
    return {"n": STAR_VALENCE, "heights": tuple(float(z) for z in rng.choice(np.arange(0, 10), 3, replace=False))}


def _star_statement(p) -> str:
    n, (zv, zu, zd) = p["n"], p["heights"]
    return (f"In a quadrilateral mesh, a vertex v of valence {n} is at height z = {fmt(zv)}; its "
            f"{n} edge neighbours are at z = {fmt(zu)} and its {n} diagonal neighbours "
            f"(the far corners of its faces) at z = {fmt(zd)}. At what height is its new vertex point after "
            f"one level of quadrilateral centroid averaging? Give z to 4 decimal places (Goldman §30.3).")


def _star_steps(p) -> str:
    n, (zv, zu, zd) = p["n"], p["heights"]
    a, b, c = ss.quad_vertex_stencil(n)
    return (f"1. The vertex stencil of §30.3 at valence n = {n}: a = 9/16, b = 3/(8n) = {_f(b)}, "
            f"c = 1/(16n) = {_f(c)}.\n"
            f"2. z' = a z_v + b (sum of the {n} edge neighbours) + c (sum of the {n} diagonal neighbours) = "
            f"9/16·{fmt(zv)} + {n}·{_f(b)}·{fmt(zu)} + {n}·{_f(c)}·{fmt(zd)}.\n"
            f"3. z' = {_f(_star_answer(p))}.")


@DECK.exercise(stored=_STORED_STAR, generate=_star_generate, answer=_star_answer, slips=_star_slips,
               statement=_star_statement, steps=_star_steps, same=_same)
def check_extraordinary_height(answer, p) -> Result:
    """Check the height of the new vertex point of the statement's extraordinary vertex in a
    quadrilateral mesh (Goldman §30.3); recognises the valence-4 weights, the edge and diagonal weights
    swapped, the diagonal neighbours left out, the triangle rule, and Catmull-Clark's vertex rule.
    """
    value, err = read_number(answer, "the height")
    if err is not None:
        return err
    n = p["n"]
    expected = _star_answer(p)
    close = lambda x: abs(value - x) <= REL_TOL * max(1.0, abs(x))  # noqa: E731
    if close(expected):
        return correct(f"9/16 of the vertex, 3/(8n) of each edge neighbour and 1/(16n) of each diagonal neighbour, "
                       f"with n = {n}.")
    slips = _star_slips(p)
    if close(slips["valence 4"]):
        return wrong(f"you used the weights of a regular vertex (valence 4); this vertex has {_WORDS[n]} neighbours "
                     f"of each kind, so the weights of the neighbours are shared among n = {n}, and only the vertex's "
                     f"own weight stays the same.")
    if close(slips["swapped"]):
        return wrong("the edge and diagonal weights are swapped: the edge neighbours are the nearer ones and get "
                     "the larger weight.")
    if close(slips["no diagonals"]):
        return wrong("the diagonal neighbours are missing: they are corners of the faces around v, so they enter "
                     "through the face centroids (and without them the weights do not sum to one).")
    if close(slips["triangle"]):
        return wrong("that is the triangle scheme's vertex rule; in a quadrilateral mesh the face centroids bring "
                     "in the diagonal neighbours, and the vertex keeps 9/16 of its own position.")
    if close(slips["catmull-clark"]):
        return wrong("that is Catmull-Clark's vertex rule, whose own weight depends on the valence; centroid "
                     "averaging keeps 9/16 at every valence and shares the rest among the neighbours.")
    return wrong(f"the height is {off_by(value, expected)}. Hint: a v + b (sum of the edge neighbours) + c (sum of "
                 f"the diagonal neighbours), with the weights of §30.3 for n = {n}.")


# -- §30.4 triangle meshes ---------------------------------------------------------------------------

_STORED_TETRA = {"vertices": _tup(TETRA_VERTICES)}


@memo
def _tetra_answers(p):
    P = _arr(p["vertices"])
    v, nbrs = P[0], P[1:]
    a, b = ss.triangle_vertex_stencil(3)
    a3, b3 = ss.triangle_vertex_stencil(3, self_weight=1 / 3)
    slips = {"not moved": v, "Warren's 3/16": (1 - 3 * 3 / 16) * v + 3 / 16 * nbrs.sum(axis=0),
             "valence-6 weights": 10 / 16 * v + 1 / 16 * nbrs.sum(axis=0),
             "plain centroids": a3 * v + b3 * nbrs.sum(axis=0)}
    return a * v + b * nbrs.sum(axis=0), slips


def _tetra_generate(rng) -> dict:
    return {"vertices": _tup(rng.integers(-4, 5, size=(4, 3)))}


def _tetra_ok(p):
    P = _arr(p["vertices"])
    if abs(float(np.linalg.det(P[1:] - P[0]))) < 6:
        return "the tetrahedron is flat or tiny"
    return None


def _tetra_statement(p) -> str:
    P = _arr(p["vertices"])
    return (f"The tetrahedron with vertices {_pts(P)} is a triangle mesh whose vertices all have valence 3. "
            f"Where does the vertex {fmt(P[0])} go after one level of the triangle scheme (weighted "
            f"centroids 1/4, 3/8, 3/8)? Give [x, y, z] (Goldman §30.4).")


def _tetra_steps(p) -> str:
    P = _arr(p["vertices"])
    a, b = ss.triangle_vertex_stencil(3)
    return (f"1. The vertex stencil of the triangle scheme: 5/8 v + 3/(8n) (sum of the n neighbours); here "
            f"n = 3: a = {_f(a)}, b = {_f(b)}.\n"
            f"2. v = {fmt(P[0])}; its neighbours (the other three vertices) sum to {fmt(P[1:].sum(axis=0))}.\n"
            f"3. The new vertex = {_f(_tetra_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_TETRA, generate=_tetra_generate, answer=lambda p: _tetra_answers(p)[0],
               slips=lambda p: _tetra_answers(p)[1], statement=_tetra_statement, steps=_tetra_steps, same=_same,
               well_posed=_tetra_ok)
def check_tetrahedron_vertex(answer, p) -> Result:
    """Check where the statement's tetrahedron's vertex goes after one level of the triangle scheme
    (Goldman §30.4); recognises Loop's (Warren's) valence-3 weight 3/16, the regular (valence 6)
    weights, plain centroids, and the vertex left where it was.
    """
    got, err = _point(answer, "the new vertex", "the new vertex as [x, y, z]")
    if err is not None:
        return err
    P = _arr(p["vertices"])
    v, nbrs = P[0], P[1:]
    a, b = ss.triangle_vertex_stencil(3)
    expected = a * v + b * nbrs.sum(axis=0)
    if _close(got, expected):
        return correct("5/8 v + 3/(8n) (sum of its neighbours) with n = 3. At valence 3 every level shrinks the "
                       "corner and its ring by 1/4 in every direction at once, so the corner keeps its shape: a cone "
                       "point (see the eigenvalues in §30.4).")
    if _close(got, v):
        return wrong("the midpoint split keeps the old vertices where they are, but the averaging step then moves "
                     "each one to the average of the weighted centroids of its triangles.")
    if _close(got, (1 - 3 * 3 / 16) * v + 3 / 16 * nbrs.sum(axis=0)):
        return wrong("that is Loop's vertex rule with Warren's valence-3 weight 3/16; the chapter's scheme averages "
                     "weighted centroids, which gives each neighbour 3/(8n) at every valence.")
    if _close(got, 10 / 16 * v + 1 / 16 * nbrs.sum(axis=0)):
        return wrong("you used the regular weight 1/16 of a valence-6 vertex; here n = 3, and the neighbours share "
                     "3/8 among themselves.")
    a3, b3 = ss.triangle_vertex_stencil(3, self_weight=1 / 3)
    if _close(got, a3 * v + b3 * nbrs.sum(axis=0)):
        return wrong("those are plain centroids (1/3, 1/3, 1/3); the scheme weights each triangle's corner v by "
                     "1/4 and the other two by 3/8.")
    return _far(got, expected, "the new vertex", "average over the three triangles at v their weighted centroids "
                                                "1/4 v + 3/8 a + 3/8 b")


_STORED_TRI_EDGE = {"points": _tup(EDGE_POINTS)}


@memo
def _tri_edge_answers(p):
    v, w, x, y = _arr(p["points"])
    ea, eb = ss.triangle_edge_stencil()
    pa, pb = ss.triangle_edge_stencil(1 / 3)
    slips = {"midpoint": (v + w) / 2, "plain centroids": pa * (v + w) + pb * (x + y),
             "quadrilateral weights": 3 / 8 * (v + w) + 1 / 16 * (x + y)}
    return ea * (v + w) + eb * (x + y), slips


def _tri_edge_generate(rng) -> dict:
    return {"points": _tup(rng.integers(-4, 5, size=(4, 3)))}


def _tri_edge_ok(p):
    v, w, x, y = _arr(p["points"])
    if np.linalg.norm(np.cross(w - v, x - v)) == 0 or np.linalg.norm(np.cross(w - v, y - v)) == 0:
        return "a degenerate triangle"
    return None


def _tri_edge_statement(p) -> str:
    P = _arr(p["points"])
    return (f"An edge of a triangle mesh runs from v = {fmt(P[0])} to w = {fmt(P[1])}; its two "
            f"triangles have opposite vertices x = {fmt(P[2])} and y = {fmt(P[3])}. Where is the new "
            f"edge point after one level of the triangle scheme (weighted centroids 1/4, 3/8, 3/8)? Give [x, y, z] "
            f"(Goldman §30.4).")


def _tri_edge_steps(p) -> str:
    v, w, x, y = _arr(p["points"])
    ea, eb = ss.triangle_edge_stencil()
    return (f"1. The edge stencil of the triangle scheme: {_f(ea)} (v + w) + {_f(eb)} (x + y) (§30.4).\n"
            f"2. v + w = {fmt(v + w)}, x + y = {fmt(x + y)}.\n"
            f"3. The edge point = {_f(_tri_edge_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_TRI_EDGE, generate=_tri_edge_generate, answer=lambda p: _tri_edge_answers(p)[0],
               slips=lambda p: _tri_edge_answers(p)[1], statement=_tri_edge_statement, steps=_tri_edge_steps,
               same=_same, well_posed=_tri_edge_ok)
def check_triangle_edge_point(answer, p) -> Result:
    """Check the edge point of the triangle scheme for the statement's edge (Goldman §30.4); recognises
    the midpoint, plain centroids, and the quadrilateral scheme's weights.
    """
    got, err = _point(answer, "the edge point", "the edge point as [x, y, z]")
    if err is not None:
        return err
    v, w, x, y = _arr(p["points"])
    ea, eb = ss.triangle_edge_stencil()
    expected = ea * (v + w) + eb * (x + y)
    if _close(got, expected):
        return correct("the edge point is 3/8 (v + w) + 1/8 (x + y).")
    if _close(got, (v + w) / 2):
        return wrong("that is the midpoint of the edge, where the split puts the new point; the averaging step then "
                     "pulls it towards the opposite vertices x and y.")
    pa, pb = ss.triangle_edge_stencil(1 / 3)
    if _close(got, pa * (v + w) + pb * (x + y)):
        return wrong("these are the weights 7/18, 1/9 of plain centroids; the scheme here weights each corner "
                     "by 1/4 in its own triangle's centroid and the other two by 3/8.")
    if _close(got, 3 / 8 * (v + w) + 1 / 16 * (x + y)):
        return wrong("1/16 is the quadrilateral scheme's weight, for four other corners; a triangle edge has two "
                     "opposite vertices (and the weights must sum to one).")
    return _far(got, expected, "the edge point", "average, over the small triangles around the edge's midpoint, "
                                                "their weighted centroids")


#: Deal another instance of an exercise (``deal("check_prism_counts")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_box_spline_mask": [
        [[0, 1, 2, 1], [1, 4, 5, 2], [2, 5, 4, 1], [1, 2, 1, 0]],          # mirrored
        [[1 / 8, 2 / 8, 1 / 8, 0], [2 / 8, 5 / 8, 4 / 8, 1 / 8], [1 / 8, 4 / 8, 5 / 8, 2 / 8], [0, 1 / 8, 2 / 8, 1 / 8]],
        [[1, 2, 1], [2, 4, 2], [1, 2, 1]],                                    # no e3 factor
        [[0.5, 1, 0.5, 0], [1, 2.5, 2, 0.5], [0.5, 2, 2.5, 1], [0, 0.5, 1, 0.5]],  # halved
    ],
    "check_prism_counts": [
        [32, 60, 30],      # one level
        [92, 240, 120],    # face points left out at the second level
        [122, 240, 112],   # F = 4F at the first level
        [122, 242, 120],   # V - E + F = 0
    ],
    "check_quad_edge_point": [
        [1, 0, 0],         # midpoint
        [1, 0, 0.5],       # average of the two face centroids
        [1, 0, 1 / 3],     # midpoint and face centroids, equal weights
        [1.25, 0, 0.5],    # triangle weights
    ],
    "check_extraordinary_height": [
        189 / 32,          # valence-4 weights
        6.875,             # edge and diagonal weights swapped
        5.25,              # diagonals left out
        5.75,              # triangle rule
        6.1,               # Catmull-Clark
    ],
    "check_tetrahedron_vertex": [
        [1, 1, 1],                 # not moved
        [0.25, 0.25, 0.25],        # Warren's 3/16
        [9 / 16, 9 / 16, 9 / 16],  # valence-6 weights
        [5 / 9, 5 / 9, 5 / 9],     # plain centroids
    ],
    "check_triangle_edge_point": [
        [2, 0, 0],         # midpoint
        [2, 0, 4 / 9],     # plain centroids
        [1.75, 0, 0.25],   # the quadrilateral weight 1/16
    ],
}


# -- the programming project -------------------------------------------------------------------------

def _ring_reference(v, ring):
    pts = np.vstack([np.asarray(v, dtype=float)[None], np.asarray(ring, dtype=float)])
    return ss.local_subdivision_matrix(len(ring), "triangle") @ pts


def _regular_ring(n, radius=1.0, height=0.0, rng=None):
    ang = 2 * np.pi * np.arange(n) / n
    ring = np.column_stack([radius * np.cos(ang), radius * np.sin(ang), np.full(n, height)])
    if rng is not None:
        ring = ring + rng.normal(scale=0.2, size=ring.shape)
    return ring


def _project_cases():
    rng = np.random.default_rng(3030)
    cases = [Case("valence 6, a flat regular hexagon around v = (0, 0, 0)", (np.zeros(3), _regular_ring(6)),
                  kind="regular (valence 6)")]
    for n in (3, 3, 4, 5, 7):
        v = rng.normal(size=3) + [0, 0, 1]
        cases.append(Case(f"valence {n}, v and a jittered ring drawn from the seed", (v, _regular_ring(n, rng=rng)),
                          kind="valence 3" if n == 3 else "valences 4, 5, 7"))
    for n in (12, 20):
        cases.append(Case(f"valence {n}, a jittered ring", (rng.normal(size=3), _regular_ring(n, 2.0, rng=rng)),
                          kind="high valence (12, 20)"))
    p = np.array([1.0, -2.0, 0.5])
    cases.append(Case("valence 5, all points at (1, -2, 0.5)", (p.copy(), np.tile(p, (5, 1))),
                      kind="degenerate: all points equal"))
    return cases


def _compare_ring(got, expected, case):
    arr = np.asarray(got, dtype=float)
    exp = np.asarray(expected, dtype=float)
    n = len(exp) - 1
    if arr.shape != exp.shape:
        return (f"it has shape {arr.shape}; for a vertex of valence {n} return {n + 1} points: the vertex point, "
                f"then one edge point per neighbour")
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite values"
    err = np.linalg.norm(arr - exp, axis=1)
    bad = np.flatnonzero(err > 1e-9)
    if bad.size == 0:
        return None
    for shift in (1, -1):
        if np.allclose(arr[1:], np.roll(exp[1:], shift, axis=0), atol=1e-9):
            return ("the edge points are shifted by one place: row 1 + i should be the edge point of the edge "
                    "(v, ring[i]), whose opposite vertices are ring[i - 1] and ring[i + 1]")
    k = int(bad[0])
    v, ring = (np.asarray(a, dtype=float) for a in case.args)
    if np.allclose(arr[1:], (v + ring) / 2, atol=1e-9) and not np.allclose(exp[1:], (v + ring) / 2, atol=1e-9):
        return ("the edge points are the midpoints of the edges: the edge stencil is 3/8 (v + ring[i]) + 1/8 "
                "(ring[i - 1] + ring[i + 1]), the two opposite vertices included")
    if k == 0:
        beta_loop = (5 / 8 - (3 / 8 + np.cos(2 * np.pi / n) / 4) ** 2) / n
        beta_warren = 3 / 16 if n == 3 else 3 / (8 * n)
        names = [name for beta, name in ((beta_loop, "Loop's vertex rule (beta from the cosine formula)"),
                                         (beta_warren, "Warren's vertex rule (3/16 at valence 3)"))
                 if np.allclose(arr[0], (1 - n * beta) * v + beta * ring.sum(axis=0), atol=1e-9)]
        if names:
            return (f"the vertex point (row 0) follows {' and '.join(names)}; this chapter's centroid rule is "
                    f"5/8 v + 3/(8n) times the sum of the ring, at every valence")
        return f"the vertex point (row 0) is {fmt(err[0], 2)} from where it should be, expected {fmt(exp[0])}"
    return (f"the edge point of the edge (v, ring[{k - 1}]) (row {k}) is {fmt(err[k], 2)} from where it should be, "
            f"expected {fmt(exp[k])}")


def check_ring_step_project(function) -> Result:
    """Run the learner's ``function(v, ring) -> (n+1, 3)`` (one level of the triangle scheme's stencils
    around a vertex of valence n: its new vertex point and the new edge points of its n edges) against
    :func:`goldman_lib.subdivision_surfaces.local_subdivision_matrix` on generated rings (fixed seed):
    the regular valence 6, valence 3, valences 4, 5 and 7, the high valences 12 and 20, and a
    degenerate ring whose points all coincide (Goldman §30.4, programming project).

    >>> def midpoints(v, ring):
    ...     return np.vstack([v, (np.asarray(v) + np.asarray(ring)) / 2])
    >>> print(check_ring_step_project(midpoints).message)   # doctest: +ELLIPSIS
    case 2 of 9 (...): ...; the edge points are the midpoints of the edges: ... Hint: ...
    """
    return check_project(function, _project_cases(), reference=_ring_reference, compare=_compare_ring,
                         what="ring_step(v, ring)",
                         hint="the chapter's vertex rule 5/8, 3/(8n) holds at every valence, n = 3 included, and the "
                              "edge (v, ring[i]) has the opposite vertices ring[i - 1] and ring[i + 1], indices mod n")


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
