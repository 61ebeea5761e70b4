"""Exercise checkers for chapter 22, hidden surfaces (Goldman §22.2-22.7).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) and the programming project do not deal.  ``SLIPS`` holds the
wrong answers each checker recognises, for the stored instance.  ``None`` or ``...`` means "not
answered yet".  Every exercise uses other polygons, depths, planes and trees than the chapter's
worked examples.  The programming project, :func:`check_bsp_project`, runs the learner's
back-to-front traversal of a BSP tree against :func:`goldman_lib.hidden_surfaces.bsp_back_to_front`
on seeded scenes (coplanar polygons, an eye in a polygon's plane, cyclic overlap, a single polygon,
an empty tree).

>>> check_painter_order([2, 0, 1, 3])
Not yet: that is nearest first; the painter paints the farthest polygon first, so nearer ones cover it.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import hidden_surfaces as hs
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_points, wrong
from goldman_lib.exercises import read_vector as _read_list  # the shared reader
from goldman_lib.exercises.deal import Deck, plain as _tup
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "PAINTER_DEPTHS", "FRAGMENTS", "SCAN_POLYGON", "SCAN_ROW", "SPLIT_TRIANGLE",
           "SPLIT_POINT", "SPLIT_NORMAL", "BSP_EYE", "DECK", "deal", "steps", "current", "deal_button",
           "check_painter_order", "check_z_buffer_pixel",
           "check_scan_line_span", "check_split_points", "check_bsp_order", "check_bsp_project", "bsp_project_cases",
           "exercise_bsp_tree"]

#: Exercise 1 (§22.2): the depths (distances along the view direction) of each polygon's vertices.
#: Chosen so that sorting by the farthest vertex (3, 1, 0, 2), the nearest vertex (2, 0, 3, 1) and the
#: average depth (3, 2, 0, 1) give three different orders, so the checker can tell each slip apart.
PAINTER_DEPTHS = ((3.0, 5.0, 4.0), (6.0, 1.0, 2.0), (4.5, 4.6, 4.0), (2.0, 7.0, 4.5))
#: Exercise 2 (§22.3): fragments arriving at one pixel, in order: (polygon, depth); the buffer starts at 1.
FRAGMENTS = ((3, 0.8), (1, 0.6), (2, 0.75), (0, 0.35), (4, 0.35), (2, 0.5))
#: Exercise 3 (§22.4): a polygon in screen coordinates and the scan line (row).
SCAN_POLYGON = ((1.0, 0.5), (9.0, 2.0), (7.0, 7.5), (2.0, 6.0))
SCAN_ROW = 3
#: Exercise 4 (§22.6): a triangle and the plane that splits it.
SPLIT_TRIANGLE = ((0.0, 0.0, 0.0), (6.0, 0.0, 0.0), (0.0, 4.0, 0.0))
SPLIT_POINT = (1.0, 1.0, 0.0)
SPLIT_NORMAL = (1.0, 2.0, 0.0)
#: Exercise 5 (§22.7): the eye for the tree of :func:`exercise_bsp_tree`.
BSP_EYE = (-1.0, 0.0, 2.0)

DECK = Deck("ch22")


#: The stored tree of exercise 5: which polygon sits where, on which side of the root the node hangs,
#: the root's normal (+z or -z), the node's plane x = c and its normal (+x or -x).
_STORED_BSP = {"labels": (0, 1, 2, 3, 4), "node_side": "front", "root_sign": 1, "node_c": 1.0, "node_sign": 1,
               "eye": BSP_EYE}


def _bsp_tree(p) -> hs.BSPNode:
    """The BSP tree of an instance of exercise 5 (see :func:`exercise_bsp_tree` for the stored one)."""
    r, n, f, b, leaf = p["labels"]
    sr, c, sn = float(p["root_sign"]), float(p["node_c"]), float(p["node_sign"])
    zn = sr if p["node_side"] == "front" else -sr             # the z side of the root the node hangs on
    A = lambda pts: np.array(pts, dtype=float)  # noqa: E731
    root = hs.BSPNode(A([0, 0, 0]), A([0, 0, sr]), [(r, A([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]))])
    node = hs.BSPNode(A([c, 0, zn]), A([sn, 0, 0]),
                      [(n, A([[c, 0, zn * 0.5], [c, 1, zn * 0.5], [c, 1, zn * 1.5], [c, 0, zn * 1.5]]))])
    node.front = hs.BSPNode(A([c + sn, 0, zn]), A([0, 0, 1]), [(f, A([[c + sn, 0, zn], [c + 2 * sn, 0, zn], [c + 2 * sn, 1, zn]]))])
    node.back = hs.BSPNode(A([c - sn, 0, 2 * zn]), A([0, 0, 1]),
                           [(b, A([[c - sn, 0, 2 * zn], [c - 0.5 * sn, 0, 2 * zn], [c - 0.5 * sn, 1, 2 * zn]]))])
    other = hs.BSPNode(A([0, 0, -zn]), A([0, 0, 1]), [(leaf, A([[0, 0, -zn], [1, 0, -zn], [0, 1, -zn]]))])
    if p["node_side"] == "front":
        root.front, root.back = node, other
    else:
        root.front, root.back = other, node
    return root


def exercise_bsp_tree() -> hs.BSPNode:
    """The BSP tree of exercise 5 (the stored instance): root polygon 0 in the plane z = 0 (normal +z);
    in front of it node polygon 1 in the plane x = 1 (normal +x) with polygon 2 in front and polygon 3
    behind; behind the root, polygon 4."""
    sq = lambda pts: np.array(pts, dtype=float)  # noqa: E731
    leaf = lambda k, pts: hs.BSPNode(sq(pts)[0], hs.shading.unit_newell_normal(sq(pts)), [(k, sq(pts))])  # noqa: E731
    root = leaf(0, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    node = leaf(1, [[1, 0, 0.5], [1, 1, 0.5], [1, 1, 1.5], [1, 0, 1.5]])
    node.front = leaf(2, [[2, 0, 1], [3, 0, 1], [3, 1, 1]])
    node.back = leaf(3, [[0, 0, 2], [0.5, 0, 2], [0.5, 1, 2]])
    root.front = node
    root.back = leaf(4, [[0, 0, -1], [1, 0, -1], [0, 1, -1]])
    return root


# -- §22.2 -------------------------------------------------------------------------------------------

def _painter_orders(p):
    D = p["depths"]
    key = lambda values: sorted(range(len(values)), key=lambda k: -values[k])  # noqa: E731
    far = key([max(d) for d in D])
    return far, {"nearest first": far[::-1], "nearest vertex": key([min(d) for d in D]),
                 "average": key([sum(d) / len(d) for d in D])}


def _painter_generate(rng) -> dict:
    return {"depths": _tup(rng.integers(10, 80, size=(4, 3)) / 10)}


def _painter_ok(p):
    D = np.array(p["depths"])
    for values in (D.max(1), D.min(1), D.mean(1)):
        v = np.sort(values)
        if np.min(np.diff(v)) < 0.05:
            return "two polygons tie (or nearly) on a sort key"
    return None


def _painter_statement(p) -> str:
    return ("The heedless painter sorts polygons by their farthest vertex. Polygons 0-3 have vertices at the depths "
            + "; ".join(f"{k}: {', '.join(fmt(d) for d in ds)}" for k, ds in enumerate(p["depths"]))
            + " (distance from the eye along the view direction). Give the painting order as a list of polygon "
              "numbers, first painted first (Goldman §22.2).")


def _painter_steps(p) -> str:
    far, _ = _painter_orders(p)
    return ("1. Each polygon's farthest vertex: " + ", ".join(f"{k}: {fmt(max(d))}" for k, d in enumerate(p["depths"]))
            + f".\n2. Farthest first: {far}.")


@DECK.exercise(stored={"depths": PAINTER_DEPTHS}, generate=_painter_generate, answer=lambda p: _painter_orders(p)[0],
               slips=lambda p: _painter_orders(p)[1], statement=_painter_statement, steps=_painter_steps,
               same=lambda a, b: list(a) == list(b), well_posed=_painter_ok)
def check_painter_order(answer, p) -> Result:
    """Check the heedless painter's order, farthest vertex first (Goldman §22.2).

    Recognises nearest first (the reverse), a sort by each polygon's nearest vertex and a sort by its
    average depth.
    """
    D = p["depths"]
    got, err = _read_list(answer, "your order", len(D), "the painting order as a list of polygon numbers")
    if err is not None:
        return err
    if np.any(got != np.round(got)):
        return wrong("polygon numbers are whole numbers 0-3; list each once.")
    got = [int(v) for v in got]
    expected, s = _painter_orders(p)
    if got == expected:
        return correct("farthest first: each polygon is painted over the ones behind it (which is right only when "
                       "no polygon reaches in front of one painted later).")
    if got == expected[::-1]:
        return wrong("that is nearest first; the painter paints the farthest polygon first, so nearer ones cover it.")
    if got == s["nearest vertex"]:
        return wrong("you sorted by each polygon's nearest vertex; the heedless painter sorts by the farthest one.")
    if got == s["average"]:
        return wrong("you sorted by each polygon's average depth (its centroid); the heedless painter sorts by the "
                     "farthest vertex.")
    if sorted(got) != list(range(len(D))):
        return wrong("list each polygon number 0-3 exactly once.")
    return wrong("that order is not sorted by the farthest vertex: find each polygon's largest depth, then paint "
                 "from the largest to the smallest.")


# -- §22.3 -------------------------------------------------------------------------------------------

def _z_run(fragments, strict=True):
    depth, shown, writes = 1.0, None, 0
    for k, d in fragments:
        if d < depth or (not strict and d <= depth):
            depth, shown, writes = d, k, writes + 1
    return shown, writes


def _z_slips(p) -> dict:
    F = p["fragments"]
    shown, writes = _z_run(F)
    return {"ties overwrite": list(_z_run(F, strict=False)), "every fragment": [shown, len(F)],
            "last fragment": [F[-1][0], writes]}


def _z_generate(rng) -> dict:
    n = int(rng.integers(5, 8))
    polys = [int(v) for v in rng.integers(0, 5, size=n)]
    depths = [float(v) for v in rng.integers(6, 19, size=n) * 0.05]
    i = int(np.argmin(depths))
    j = int(rng.integers(i + 1, n)) if i < n - 1 else None
    if j is not None:                       # an equally near fragment arrives later
        depths[j] = depths[i]
        while polys[j] == polys[i]:
            polys[j] = int(rng.integers(0, 5))
    return {"fragments": tuple((k, round(d, 2)) for k, d in zip(polys, depths))}


def _z_ok(p):
    F = p["fragments"]
    shown, writes = _z_run(F)
    if _z_run(F, strict=False) == (shown, writes):
        return "no tie decides anything"
    if F[-1][0] == shown:
        return "the last fragment is the one shown"
    if writes < 2:
        return "the first fragment is the nearest"
    return None


def _z_statement(p) -> str:
    return ("A z-buffer pixel starts with depth 1 (the far plane) and the background colour. Fragments arrive in this "
            "order as (polygon, depth): " + ", ".join(f"({k}, {fmt(d)})" for k, d in p["fragments"])
            + ". A fragment is written only if it is strictly nearer than the stored depth. Give [the polygon shown "
              "at the end, the number of times the pixel was written] (Goldman §22.3).")


def _z_steps(p) -> str:
    depth, lines, writes = 1.0, [], 0
    for k, d in p["fragments"]:
        if d < depth:
            writes += 1
            lines.append(f"   ({k}, {fmt(d)}): {fmt(d)} < {fmt(depth)}, written (write {writes}); the pixel shows {k}")
            depth = d
        else:
            lines.append(f"   ({k}, {fmt(d)}): not nearer than {fmt(depth)}, skipped")
    shown, writes = _z_run(p["fragments"])
    return "1. Follow the stored depth, from 1:\n" + "\n".join(lines) + f"\n2. [{shown}, {writes}]."


@DECK.exercise(stored={"fragments": FRAGMENTS}, generate=_z_generate, answer=lambda p: list(_z_run(p["fragments"])),
               slips=_z_slips, statement=_z_statement, steps=_z_steps, same=lambda a, b: list(a) == list(b),
               well_posed=_z_ok)
def check_z_buffer_pixel(answer, p) -> Result:
    """Check [final polygon, writes] for the statement's fragments (Goldman §22.3).

    Recognises the <= test (ties overwrite), counting every fragment, and the last fragment (a painter).
    """
    got, err = _read_list(answer, "your answer", 2, "[the polygon shown, the number of writes]")
    if err is not None:
        return err
    F = p["fragments"]
    shown, writes = _z_run(F)
    if got[0] == shown and got[1] == writes:
        return correct("only strictly nearer fragments are written; the equally near one that comes later is not.")
    shown2, writes2 = _z_run(F, strict=False)
    if got[0] == shown2 and got[1] == writes2:
        return wrong("you let an equally near fragment overwrite (<=); the test is strictly nearer, so the first of "
                     "two equal depths stays.")
    if got[1] == len(F):
        return wrong("not every fragment is written: each is compared with the stored depth first.")
    if got[0] == F[-1][0]:
        return wrong("that is the last fragment to arrive, as a painter would show; the z-buffer keeps the nearest.")
    if got[0] == shown:
        return wrong(f"the polygon is right; the number of writes is {off_by(got[1], writes)}: count the fragments "
                     f"strictly nearer than the depth stored when they arrive.")
    return wrong("follow the stored depth: start at 1, and for each fragment in turn replace it if the fragment is "
                 "strictly nearer.")


# -- §22.4 -------------------------------------------------------------------------------------------

def _span(P, y):
    P = np.asarray(P, dtype=float)
    xs = []
    for i in range(len(P)):
        a, b = P[i], P[(i + 1) % len(P)]
        if (a[1] - y) * (b[1] - y) < 0:
            xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
    return np.array(sorted(xs))


def _scan_slips(p) -> dict:
    P = np.array(p["polygon"])
    expected = _span(P, p["row"] + 0.5)
    return {"top of the pixels": _span(P, float(p["row"])), "swapped": expected[::-1],
            "bounding box": np.array([P[:, 0].min(), P[:, 0].max()])}


def _scan_generate(rng) -> dict:
    angles = np.sort(rng.uniform(0, 2 * np.pi, 4))
    r = rng.uniform(3, 4.5, 4)
    P = np.round((np.c_[5 + r * np.cos(angles), 4.5 + 0.9 * r * np.sin(angles)]) * 2) / 2
    lo, hi = int(np.ceil(P[:, 1].min())), int(np.floor(P[:, 1].max())) - 1
    return {"polygon": _tup(P), "row": int(rng.integers(lo, max(lo, hi) + 1))}


def _scan_ok(p):
    P = np.array(p["polygon"])
    y0, y1 = float(p["row"]), p["row"] + 0.5
    if np.any(np.abs(P[:, 1][:, None] - np.array([y0, y1])) < 0.1):
        return "a vertex lies on the scan line or on the pixels' top"
    d = np.roll(P, -1, axis=0) - P
    cross = d[:, 0] * np.roll(d, -1, axis=0)[:, 1] - d[:, 1] * np.roll(d, -1, axis=0)[:, 0]
    if not (np.all(cross > 0.5) or np.all(cross < -0.5)):
        return "the polygon is not (strictly) convex"
    if len(_span(P, y1)) != 2 or len(_span(P, y0)) != 2:
        return "the scan line does not cross two edges"
    e = _span(P, y1)
    s = _scan_slips(p)
    if e[1] - e[0] < 1.5:
        return "the span is too short"
    for name in ("top of the pixels", "bounding box"):
        v = np.asarray(s[name])
        if min(np.max(np.abs(v - e)), np.max(np.abs(v - e[::-1]))) < 0.05:
            return "a recognised slip (nearly) gives the span"
    return None


def _scan_statement(p) -> str:
    row = p["row"]
    return (f"A polygon has screen vertices {', '.join(fmt(q) for q in p['polygon'])} (x right, y down). On scan line "
            f"(row) {row}, sampled at the pixel centres' height y = {row} + 0.5, the active edge list holds the "
            f"two edges it crosses. Give the span [x_left, x_right] where the scan line is inside the polygon, to 4 "
            f"decimals (Goldman §22.4).")


def _scan_steps(p) -> str:
    P = np.array(p["polygon"])
    y = p["row"] + 0.5
    lines = []
    for i in range(len(P)):
        a, b = P[i], P[(i + 1) % len(P)]
        if (a[1] - y) * (b[1] - y) < 0:
            x = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            lines.append(f"   edge {fmt(a)}–{fmt(b)}: x = {fmt(a[0])} + ({fmt(y)} - {fmt(a[1])})·{fmt(b[0] - a[0])}/"
                         f"{fmt(b[1] - a[1])} = {fmt(np.round(x, 6), 6)}")
    return (f"1. The scan line y = {fmt(y)} crosses the two edges whose y-ranges contain it:\n" + "\n".join(lines)
            + f"\n2. The span is [{', '.join(fmt(np.round(x, 6), 6) for x in _span(P, y))}] (smaller first).")


@DECK.exercise(stored={"polygon": SCAN_POLYGON, "row": SCAN_ROW}, generate=_scan_generate,
               answer=lambda p: _span(p["polygon"], p["row"] + 0.5), slips=_scan_slips, statement=_scan_statement,
               steps=_scan_steps, same=lambda a, b: np.shape(a) == np.shape(b) and bool(np.allclose(a, b, atol=1e-3, rtol=0)),
               well_posed=_scan_ok)
def check_scan_line_span(answer, p) -> Result:
    """Check the span of the statement's polygon on its row at y = row + 0.5 (Goldman §22.4).

    Recognises the span at y = row (the pixel's top, not its centre), the ends swapped, and the
    bounding box's x-range.
    """
    got, err = _read_list(answer, "your span", 2, "the span as [x_left, x_right]")
    if err is not None:
        return err
    P = np.array(p["polygon"])
    row = p["row"]
    expected = _span(P, row + 0.5)
    tol = 1e-3
    if np.allclose(got, expected, atol=tol):
        return correct("the two active edges cross the scan line there; the pixels whose centres lie between "
                       "the ends are drawn.")
    if np.allclose(got, _span(P, float(row)), atol=tol):
        return wrong("that is the span at y = row, the top of the pixels; scan lines are sampled at the pixel "
                     "centres, y = row + 0.5.")
    if np.allclose(got, expected[::-1], atol=tol):
        return wrong("your ends are swapped: x_left is the smaller.")
    if np.allclose(got, [P[:, 0].min(), P[:, 0].max()], atol=tol):
        return wrong("that is the x-range of the whole polygon; on one scan line only the crossings of the two "
                     "active edges bound the span.")
    return wrong(f"your span is {far_off(got, expected)} at one end; find the two edges whose "
                 f"y-range contains the scan line and intersect each with it.")


# -- §22.6 -------------------------------------------------------------------------------------------

def _split_parts(p):
    T = np.array(p["triangle"])
    front, back = hs.split_polygon(T, p["point"], p["normal"])
    cut = np.array([q for q in front if min(np.linalg.norm(T - q, axis=1)) > 1e-9])
    s = (T - np.array(p["point"])) @ np.array(p["normal"])
    crossing = [(i, (i + 1) % 3) for i in range(3) if s[i] * s[(i + 1) % 3] < 0]
    mids = np.array([(T[i] + T[j]) / 2 for i, j in crossing])
    alone = T[int(np.argmax([np.sign(s[i]) != np.sign(s[(i + 1) % 3]) and np.sign(s[i]) != np.sign(s[(i + 2) % 3])
                             for i in range(3)]))]
    return T, cut, s, mids, alone


def _split_same(a, b) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and (bool(np.allclose(a, b, atol=1e-3, rtol=0)) or bool(np.allclose(a, b[::-1], atol=1e-3, rtol=0)))


def _split_slips(p) -> dict:
    T, cut, s, mids, alone = _split_parts(p)
    return {"midpoints": mids, "a vertex": np.array([alone, cut[1]])}


def _split_generate(rng) -> dict:
    a, b = int(rng.integers(3, 9)), int(rng.integers(3, 9))
    T = np.array([[0, 0, 0], [a, 0, 0], [0, b, 0]], dtype=float) + np.r_[rng.integers(-2, 3, size=2), 0]
    N = np.r_[rng.integers(-2, 3, size=2), 0].astype(float)
    Q = np.r_[rng.integers(0, 4, size=2), 0].astype(float) + T[0]
    return {"triangle": _tup(T), "point": _tup(Q), "normal": _tup(N)}


def _split_ok(p):
    N = np.array(p["normal"])
    if not np.any(N):
        return "the normal is zero"
    T = np.array(p["triangle"])
    s = (T - np.array(p["point"])) @ N / np.linalg.norm(N)
    if np.min(np.abs(s)) < 0.3:
        return "a vertex lies (nearly) on the plane"
    if np.all(s > 0) or np.all(s < 0):
        return "the plane misses the triangle"
    T, cut, s, mids, alone = _split_parts(p)
    if len(cut) != 2 or np.linalg.norm(cut[0] - cut[1]) < 0.5:
        return "the cut is too short"
    return None


def _split_statement(p) -> str:
    return (f"Depth sort and BSP trees split polygons by planes. The plane through {fmt(p['point'])} with normal "
            f"{fmt(p['normal'])} cuts the triangle {', '.join(fmt(q) for q in p['triangle'])}. Give the two points "
            f"where it crosses the triangle's edges, [[x, y, z], [x, y, z]] in either order (Goldman §22.6).")


def _split_steps(p) -> str:
    T, cut, s, mids, alone = _split_parts(p)
    lines = []
    for i in range(3):
        j = (i + 1) % 3
        if s[i] * s[j] < 0:
            t = s[i] / (s[i] - s[j])
            lines.append(f"   edge {fmt(T[i])}–{fmt(T[j])}: t = {fmt(s[i])}/({fmt(s[i])} - ({fmt(s[j])})) = "
                         f"{fmt(np.round(t, 6), 6)}, the point {fmt(np.round(T[i] + t * (T[j] - T[i]), 6), 6)}")
    return (f"1. The signed distances s = (P - Q)·N at the vertices: {', '.join(fmt(v) for v in s)}.\n"
            "2. The plane cuts the two edges whose ends have opposite signs, at the fraction s_a / (s_a - s_b):\n"
            + "\n".join(lines))


@DECK.exercise(stored={"triangle": SPLIT_TRIANGLE, "point": SPLIT_POINT, "normal": SPLIT_NORMAL},
               generate=_split_generate, answer=lambda p: _split_parts(p)[1], slips=_split_slips,
               statement=_split_statement, steps=_split_steps, same=_split_same, well_posed=_split_ok)
def check_split_points(answer, p) -> Result:
    """Check where the plane cuts the triangle's edges (Goldman §22.6).

    Recognises the midpoints of the two cut edges and a vertex of the triangle given as a cut point.
    """
    got, err = read_points(answer, "your points", ask="[[x, y, z], [x, y, z]]")
    if err is not None:
        return err
    if got.shape != (2, 3):
        return wrong(f"give two points of three coordinates, shape (2, 3); yours has shape {got.shape}.")
    T, cut, s, mids, alone = _split_parts(p)
    tol = 1e-3

    def same(a, b):
        return np.allclose(a, b, atol=tol) or np.allclose(a, b[::-1], atol=tol)

    if same(got, cut):
        return correct("each cut point divides its edge in the ratio of the vertices' signed distances to the "
                       "plane, s_a / (s_a - s_b).")
    if len(mids) == 2 and same(got, mids):
        return wrong("those are the midpoints of the two cut edges; the plane cuts each edge where the signed "
                     "distance (P - Q)·N changes sign, at the fraction s_a / (s_a - s_b) along it.")
    if any(min(np.linalg.norm(T - q, axis=1)) < tol for q in got):
        return wrong("one of your points is a vertex of the triangle; no vertex lies on the plane here.")
    near = cut if np.abs(got - cut).max() <= np.abs(got - cut[::-1]).max() else cut[::-1]
    return wrong(f"your points are {far_off(got, near)}; compute s = (P - Q)·N at each vertex and interpolate along "
                 f"the two edges whose ends have opposite signs.")


# -- §22.7 -------------------------------------------------------------------------------------------

def _bsp_in_order(node) -> list:
    """Back subtree, node, front subtree at every node, whatever the eye."""
    if node is None:
        return []
    return _bsp_in_order(node.back) + [k for k, _ in node.pieces] + _bsp_in_order(node.front)


def _bsp_answer(p) -> list:
    return [k for k, _ in hs.bsp_back_to_front(_bsp_tree(p), p["eye"])]


def _bsp_slips(p) -> dict:
    return {"front to back": _bsp_answer(p)[::-1], "always back first": _bsp_in_order(_bsp_tree(p))}


def _bsp_generate(rng) -> dict:
    eye = (float(rng.choice([-3, -2, -1, 2, 3, 4])), float(rng.integers(-2, 3)), float(rng.choice([-3, -2, -1, 1, 2, 3])))
    return {"labels": tuple(int(v) for v in rng.permutation(5)), "node_side": str(rng.choice(["front", "back"])),
            "root_sign": int(rng.choice([-1, 1])), "node_c": float(rng.integers(0, 2)),
            "node_sign": int(rng.choice([-1, 1])), "eye": eye}


def _bsp_ok(p):
    if abs(p["eye"][0] - p["node_c"]) < 0.5 or abs(p["eye"][2]) < 0.5:
        return "the eye lies in a node's plane"
    return None


def _side_text(sign, axis, front=True) -> str:
    op = ">" if (sign > 0) == front else "<"
    return f"{axis} {op} 0"


def _bsp_statement(p) -> str:
    r, n, f, b, leaf = p["labels"]
    sr, sn, c = p["root_sign"], p["node_sign"], p["node_c"]
    node_front = p["node_side"] == "front"
    first = "in front of it" if node_front else "behind it"
    other = "behind the root" if node_front else "in front of the root"
    return (f"A BSP tree: the root holds polygon {r} in the plane z = 0 (normal {'+' if sr > 0 else '-'}z); {first} "
            f"({_side_text(sr, 'z', node_front)}) a node holds polygon {n} in the plane x = {fmt(c)} (normal "
            f"{'+' if sn > 0 else '-'}x), with polygon {f} in front of that plane and polygon {b} behind it; {other} "
            f"({_side_text(sr, 'z', not node_front)}) a leaf holds polygon {leaf}. Give the back-to-front order for the "
            f"eye at {fmt(p['eye'])} as a list of polygon numbers (Goldman §22.7).")


def _bsp_steps(p) -> str:
    r, n, f, b, leaf = p["labels"]
    tree = _bsp_tree(p)
    eye = np.array(p["eye"])
    s_root = float((eye - tree.point) @ tree.normal)
    node = tree.front if p["node_side"] == "front" else tree.back
    s_node = float((eye - node.point) @ node.normal)
    far_root = "back" if s_root >= 0 else "front"
    far_node = "back" if s_node >= 0 else "front"
    return (f"1. At the root (polygon {r}): (eye - point)·normal = {fmt(s_root)}, so the eye is "
            f"{'in front' if s_root >= 0 else 'behind'}; its {far_root} subtree is farther and comes first.\n"
            f"2. At the node (polygon {n}): (eye - point)·normal = {fmt(s_node)}, so the eye is "
            f"{'in front' if s_node >= 0 else 'behind'}; its {far_node} subtree comes first.\n"
            f"3. Far side, node, near side at every node: {_bsp_answer(p)}.")


@DECK.exercise(stored=_STORED_BSP, generate=_bsp_generate, answer=_bsp_answer, slips=_bsp_slips,
               statement=_bsp_statement, steps=_bsp_steps, same=lambda a, b: list(a) == list(b), well_posed=_bsp_ok)
def check_bsp_order(answer, p) -> Result:
    """Check the back-to-front order of the statement's BSP tree for its eye (Goldman §22.7).

    Recognises front-to-back (the reverse) and a fixed in-order traversal (back, node, front) that
    ignores the eye's side.
    """
    got, err = _read_list(answer, "your order", 5, "the order as a list of polygon numbers")
    if err is not None:
        return err
    if np.any(got != np.round(got)):
        return wrong("polygon numbers are whole numbers 0-4; list each once.")
    got = [int(v) for v in got]
    tree = _bsp_tree(p)
    expected = _bsp_answer(p)
    if got == expected:
        return correct("at each node the side away from the eye first, then the node, then the eye's side.")
    if got == expected[::-1]:
        return wrong("that is front to back; back to front paints the subtree on the far side of each plane first.")
    if got == _bsp_in_order(tree):
        eye = np.array(p["eye"])
        node = tree.front if p["node_side"] == "front" else tree.back
        for nd, axis, value, c in ((tree, "z", eye[2], 0.0), (node, "x", eye[0], p["node_c"])):
            if float((eye - nd.point) @ nd.normal) < 0:
                break
        return wrong(f"that always takes the back subtree first; which side is 'back' depends on the eye: at the "
                     f"node of plane {axis} = {fmt(c)} the eye ({axis} = {fmt(value)}) is behind the plane, so its "
                     "front subtree is farther.")
    if sorted(got) != list(range(5)):
        return wrong("list each polygon number 0-4 exactly once.")
    return wrong("that order breaks the rule at some node: test on which side of each node's plane the eye lies, "
                 "and go to the other side first.")


#: Deal another instance of an exercise (``deal("check_bsp_order")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


# -- the programming project -------------------------------------------------------------------------

def bsp_project_cases(seed: int = 22) -> list[Case]:
    """The cases of :func:`check_bsp_project`: BSP trees built by :func:`goldman_lib.hidden_surfaces.build_bsp`
    from seeded scenes, with eyes around them -- random triangles, coplanar polygons (several at one
    node), an eye in the plane of a polygon, the chapter's cyclic bars and piercing triangles, a single
    polygon and an empty tree.

    >>> cases = bsp_project_cases()
    >>> len(cases), cases[0].kind, cases[-1].kind
    (11, 'random triangles', 'empty tree')
    """
    rng = np.random.default_rng(seed)
    cases: list[Case] = []

    def add(polys, eye, kind, label):
        eye = np.round(np.asarray(eye, float), 3)
        cases.append(Case(f"{label}, eye {fmt(eye)}", (hs.build_bsp(polys), eye), kind=kind))

    for n in (4, 6, 8):
        polys = [rng.uniform(-2, 2, 3) + rng.uniform(-1, 1, (3, 3)) for _ in range(n)]
        add(polys, rng.uniform(-6, 6, 3), "random triangles", f"{n} random triangles")
    tri = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    coplanar = [tri, tri + [2, 0, 0], tri + [0, 0, 1], tri + [0, 2, 0], tri + [1, 1, -1]]
    add(coplanar, [0.3, 0.2, 4], "coplanar polygons", "five triangles, three in the plane z = 0")
    add(coplanar, [0.3, 0.2, -4], "coplanar polygons", "the same, seen from below")
    wall = [np.array([[0, -1, -1], [0, 1, -1], [0, 1, 1], [0, -1, 1]], float), tri + [1, 0, 0], tri - [2, 0, 0]]
    add(wall, [0, 3, 0.5], "eye in a polygon's plane", "a wall in the plane x = 0 and a triangle on each side")
    polygons, _ = hs.default_scene()
    add(polygons, hs.default_camera().eye, "cyclic overlap", "the chapter's three cyclic bars and two piercing triangles")
    add(polygons, [3, 6, -2], "cyclic overlap", "the chapter's scene from behind")
    add(polygons[:3], [0, -7, 5], "cyclic overlap", "the three cyclic bars from above")
    add([tri], [0, 0, 3], "a single polygon", "one triangle")
    cases.append(Case("no polygons (the tree is None), eye (0, 0, 1)", (None, np.array([0.0, 0.0, 1.0])),
                      kind="empty tree"))
    return cases


def _side(node, eye) -> float:
    """(eye - point)·normal, set to 0 when the eye lies in the node's plane to rounding (a tie)."""
    s = float((eye - node.point) @ node.normal)
    scale = float(np.linalg.norm(node.normal)) * (1.0 + float(np.linalg.norm(eye - node.point)))
    return 0.0 if abs(s) <= 1e-9 * scale else s


def _count(node) -> int:
    return 0 if node is None else node.count()


def _same_piece(a, b, indices_only: bool) -> bool:
    if a[0] != b[0]:
        return False
    if indices_only:
        return True
    return a[1].shape == np.shape(b[1]) and bool(np.allclose(a[1], b[1], atol=1e-9))


def _fits(node, seq, eye, sides: str, place: str, indices_only: bool = False) -> bool:
    """Whether ``seq`` (a list of (index, vertices)) lists the pieces of ``node``'s tree in an order of
    the given kind.  sides: "far" (the rule: the subtree away from the eye first; either subtree first
    when the eye lies in the node's plane), "near" (the eye's side first), "back"/"front" (always that
    subtree first, whatever the eye).  place: where the node's own pieces go ("middle", "first", "last").
    Pieces of one node may come in any order among themselves (they lie in one plane)."""
    if node is None:
        return not seq
    if len(seq) != node.count():
        return False
    s = _side(node, eye)
    if sides in ("far", "near"):
        eye_front = (s >= 0) if sides == "far" else (s < 0)
        options = [(node.back, node.front) if eye_front else (node.front, node.back)]
        if s == 0:
            options = [(node.back, node.front), (node.front, node.back)]
    else:
        options = [(node.back, node.front) if sides == "back" else (node.front, node.back)]
    here = len(node.pieces)
    for first, second in options:
        n1, n2 = _count(first), _count(second)
        if place == "middle":
            a, mid, b = seq[:n1], seq[n1:n1 + here], seq[n1 + here:]
        elif place == "first":
            mid, a, b = seq[:here], seq[here:here + n1], seq[here + n1:]
        else:
            a, b, mid = seq[:n1], seq[n1:n1 + n2], seq[n1 + n2:]
        left = list(node.pieces)
        ok = True
        for piece in mid:
            j = next((j for j, q in enumerate(left) if _same_piece(piece, q, indices_only)), None)
            if j is None:
                ok = False
                break
            left.pop(j)
        if ok and _fits(first, a, eye, sides, place, indices_only) and _fits(second, b, eye, sides, place, indices_only):
            return True
    return False


def _compare_bsp(got, expected, case) -> str | None:
    try:
        items = list(got)
        seq = [(int(k), np.asarray(P, dtype=float)) for k, P in items]
    except (TypeError, ValueError):
        return "it should be a list of (polygon index, vertices) pairs, the pieces stored at the nodes"
    exp_k = [k for k, _ in expected]
    if len(seq) != len(exp_k):
        return f"it lists {len(seq)} pieces; the tree holds {len(exp_k)} (every node's pieces, each once)"
    tree, eye = case.args
    eye = np.asarray(eye, dtype=float)
    if sorted(k for k, _ in seq) != sorted(exp_k):
        return (f"it lists the polygons {sorted(k for k, _ in seq)}; the tree's pieces belong to the polygons "
                f"{sorted(exp_k)} (every node's pieces, each once)")
    if _fits(tree, seq, eye, "far", "middle"):
        return None
    if _fits(tree, seq, eye, "far", "middle", indices_only=True):
        return "the pieces' vertices differ from the tree's: return the pieces as they are stored at the nodes"
    order = f" (one right order of the polygon numbers: {exp_k})"
    if _fits(tree, seq, eye, "near", "middle", indices_only=True):
        return "it is front to back: the reverse of the painting order" + order
    for sides in ("back", "front"):
        if _fits(tree, seq, eye, sides, "middle", indices_only=True):
            return (f"it always lists the {sides} subtree first, whatever the eye: which side is farther depends on "
                    f"the side of the node's plane the eye is on" + order)
    for place, where in (("first", "before both subtrees"), ("last", "after both subtrees")):
        for sides in ("far", "near"):
            if _fits(tree, seq, eye, sides, place, indices_only=True):
                return (f"it lists each node's pieces {where}; they belong between the far subtree and the near "
                        f"one" + order)
    return ("that order breaks the rule at some node: at each node the subtree on the eye's far side comes first, "
            "then the node's pieces, then the subtree on the eye's side" + order)


def check_bsp_project(function) -> Result:
    """Check the learner's ``back_to_front(tree, eye)`` -- the pieces ``(polygon index, vertices)`` of a
    BSP tree (:class:`goldman_lib.hidden_surfaces.BSPNode`: ``point``, ``normal``, ``pieces``,
    ``front``, ``back``; None for an empty subtree) in back-to-front order from ``eye`` -- against
    :func:`goldman_lib.hidden_surfaces.bsp_back_to_front` on :func:`bsp_project_cases` (Goldman §22.7).
    Any order among the pieces of one node is accepted (they lie in one plane and cannot hide each
    other), and either subtree first when the eye lies in a node's plane (nothing on one side can
    hide anything on the other); the list may hold tuples or lists, the vertices lists or arrays.

    >>> def in_order(tree, eye):
    ...     if tree is None:
    ...         return []
    ...     return in_order(tree.back, eye) + list(tree.pieces) + in_order(tree.front, eye)
    >>> print(check_bsp_project(in_order).message)   # doctest: +ELLIPSIS
    case ...: your function returned ...; it always lists the back subtree first, whatever the eye: ... Hint: ...
    """
    return check_project(function, bsp_project_cases(), reference=hs.bsp_back_to_front, compare=_compare_bsp,
                         what="back-to-front traversal of a BSP tree",
                         hint="if (eye - node.point)·node.normal >= 0 the eye is in front: list the back subtree, "
                              "then node.pieces, then the front subtree; otherwise the other way round")


SLIPS = {
    "check_painter_order": [[2, 0, 1, 3], [2, 0, 3, 1], [3, 2, 0, 1]],
    "check_z_buffer_pixel": [[4, 4], [0, 6], [2, 3]],
    "check_scan_line_span": [[1.4545, 8.6364], [8.4545, 1.5455], [1.0, 9.0]],
    "check_split_points": [[[3, 0, 0], [0, 2, 0]]],
    "check_bsp_order": [[3, 1, 2, 0, 4], [4, 0, 3, 1, 2]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
