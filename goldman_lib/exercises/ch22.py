"""Exercise checkers for chapter 22, hidden surfaces (Goldman §22.2-22.7).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other polygons, depths, planes and trees than the chapter's worked examples.  The
programming project, :func:`check_bsp_project`, runs the learner's back-to-front traversal of a BSP
tree against :func:`goldman_lib.hidden_surfaces.bsp_back_to_front` on seeded scenes (coplanar
polygons, an eye in a polygon's plane, cyclic overlap, a single polygon, an empty tree).

>>> check_painter_order([2, 0, 1, 3])
Not yet: that is nearest first; the painter paints the farthest polygon first, so nearer ones cover it.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import hidden_surfaces as hs
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_points, wrong
from goldman_lib.exercises import read_vector as _read_list  # the shared reader
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "PAINTER_DEPTHS", "FRAGMENTS", "SCAN_POLYGON", "SCAN_ROW", "SPLIT_TRIANGLE",
           "SPLIT_POINT", "SPLIT_NORMAL", "BSP_EYE", "check_painter_order", "check_z_buffer_pixel",
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


def exercise_bsp_tree() -> hs.BSPNode:
    """The BSP tree of exercise 5: root polygon 0 in the plane z = 0 (normal +z); in front of it node
    polygon 1 in the plane x = 1 (normal +x) with polygon 2 in front and polygon 3 behind; behind the
    root, polygon 4."""
    sq = lambda pts: np.array(pts, dtype=float)  # noqa: E731
    leaf = lambda k, pts: hs.BSPNode(sq(pts)[0], hs.shading.newell_normal(sq(pts)), [(k, sq(pts))])  # noqa: E731
    root = leaf(0, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    node = leaf(1, [[1, 0, 0.5], [1, 1, 0.5], [1, 1, 1.5], [1, 0, 1.5]])
    node.front = leaf(2, [[2, 0, 1], [3, 0, 1], [3, 1, 1]])
    node.back = leaf(3, [[0, 0, 2], [0.5, 0, 2], [0.5, 1, 2]])
    root.front = node
    root.back = leaf(4, [[0, 0, -1], [1, 0, -1], [0, 1, -1]])
    return root


PROBLEMS = {
    "check_painter_order": (
        "The heedless painter sorts polygons by their farthest vertex. Polygons 0-3 have vertices at the depths "
        + "; ".join(f"{k}: {', '.join(fmt(d) for d in ds)}" for k, ds in enumerate(PAINTER_DEPTHS))
        + " (distance from the eye along the view direction). Give the painting order as a list of polygon "
          "numbers, first painted first (Goldman §22.2)."),
    "check_z_buffer_pixel": (
        "A z-buffer pixel starts with depth 1 (the far plane) and the background colour. Fragments arrive in this "
        "order as (polygon, depth): " + ", ".join(f"({k}, {fmt(d)})" for k, d in FRAGMENTS)
        + ". A fragment is written only if it is strictly nearer than the stored depth. Give [the polygon shown "
          "at the end, the number of times the pixel was written] (Goldman §22.3)."),
    "check_scan_line_span": (
        f"A polygon has screen vertices {', '.join(fmt(p) for p in SCAN_POLYGON)} (x right, y down). On scan line "
        f"(row) {SCAN_ROW}, sampled at the pixel centres' height y = {SCAN_ROW} + 0.5, the active edge list holds the "
        f"two edges it crosses. Give the span [x_left, x_right] where the scan line is inside the polygon, to 4 "
        f"decimals (Goldman §22.4)."),
    "check_split_points": (
        f"Depth sort and BSP trees split polygons by planes. The plane through {fmt(SPLIT_POINT)} with normal "
        f"{fmt(SPLIT_NORMAL)} cuts the triangle {', '.join(fmt(p) for p in SPLIT_TRIANGLE)}. Give the two points "
        f"where it crosses the triangle's edges, [[x, y, z], [x, y, z]] in either order (Goldman §22.6)."),
    "check_bsp_order": (
        "A BSP tree: the root holds polygon 0 in the plane z = 0 (normal +z); in front of it (z > 0) a node holds "
        "polygon 1 in the plane x = 1 (normal +x), with polygon 2 in front of that plane and polygon 3 behind it; "
        f"behind the root (z < 0) a leaf holds polygon 4. Give the back-to-front order for the eye at {fmt(BSP_EYE)} "
        "as a list of polygon numbers (Goldman §22.7)."),
}


# -- §22.2 -------------------------------------------------------------------------------------------

def check_painter_order(answer) -> Result:
    """Check the heedless painter's order, farthest vertex first (Goldman §22.2).

    Recognises nearest first (the reverse), a sort by each polygon's nearest vertex and a sort by its
    average depth.
    """
    got, err = _read_list(answer, "your order", len(PAINTER_DEPTHS), "the painting order as a list of polygon numbers")
    if err is not None:
        return err
    if np.any(got != np.round(got)):
        return wrong("polygon numbers are whole numbers 0-3; list each once.")
    got = [int(v) for v in got]
    far = [max(d) for d in PAINTER_DEPTHS]
    expected = sorted(range(len(far)), key=lambda k: -far[k])
    if got == expected:
        return correct("farthest first: each polygon is painted over the ones behind it (which is right only when "
                       "no polygon reaches in front of one painted later).")
    if got == expected[::-1]:
        return wrong("that is nearest first; the painter paints the farthest polygon first, so nearer ones cover it.")
    near = [min(d) for d in PAINTER_DEPTHS]
    if got == sorted(range(len(near)), key=lambda k: -near[k]):
        return wrong("you sorted by each polygon's nearest vertex; the heedless painter sorts by the farthest one.")
    mean = [sum(d) / len(d) for d in PAINTER_DEPTHS]
    if got == sorted(range(len(mean)), key=lambda k: -mean[k]):
        return wrong("you sorted by each polygon's average depth (its centroid); the heedless painter sorts by the "
                     "farthest vertex.")
    if sorted(got) != list(range(len(far))):
        return wrong("list each polygon number 0-3 exactly once.")
    return wrong("that order is not sorted by the farthest vertex: find each polygon's largest depth, then paint "
                 "from the largest to the smallest.")


# -- §22.3 -------------------------------------------------------------------------------------------

def check_z_buffer_pixel(answer) -> Result:
    """Check [final polygon, writes] for the fragments :data:`FRAGMENTS` (Goldman §22.3).

    Recognises the <= test (ties overwrite), counting every fragment, and the last fragment (a painter).
    """
    got, err = _read_list(answer, "your answer", 2, "[the polygon shown, the number of writes]")
    if err is not None:
        return err
    depth, shown, writes = 1.0, None, 0
    for k, d in FRAGMENTS:
        if d < depth:
            depth, shown, writes = d, k, writes + 1
    if got[0] == shown and got[1] == writes:
        return correct("only strictly nearer fragments are written; the equally near one that comes later is not.")
    depth2, shown2, writes2 = 1.0, None, 0
    for k, d in FRAGMENTS:
        if d <= depth2:
            depth2, shown2, writes2 = d, k, writes2 + 1
    if got[0] == shown2 and got[1] == writes2:
        return wrong("you let an equally near fragment overwrite (<=); the test is strictly nearer, so the first of "
                     "two equal depths stays.")
    if got[1] == len(FRAGMENTS):
        return wrong("not every fragment is written: each is compared with the stored depth first.")
    if got[0] == FRAGMENTS[-1][0]:
        return wrong("that is the last fragment to arrive, as a painter would show; the z-buffer keeps the nearest.")
    if got[0] == shown:
        return wrong(f"the polygon is right; the number of writes is {off_by(got[1], writes)}: count the fragments "
                     f"strictly nearer than the depth stored when they arrive.")
    return wrong("follow the stored depth: start at 1, and for each fragment in turn replace it if the fragment is "
                 "strictly nearer.")


# -- §22.4 -------------------------------------------------------------------------------------------

def _span(y):
    P = np.array(SCAN_POLYGON)
    xs = []
    for i in range(len(P)):
        a, b = P[i], P[(i + 1) % len(P)]
        if (a[1] - y) * (b[1] - y) < 0:
            xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
    return np.array(sorted(xs))


def check_scan_line_span(answer) -> Result:
    """Check the span of :data:`SCAN_POLYGON` on row :data:`SCAN_ROW` at y = row + 0.5 (Goldman §22.4).

    Recognises the span at y = row (the pixel's top, not its centre), the ends swapped, and the
    bounding box's x-range.
    """
    got, err = _read_list(answer, "your span", 2, "the span as [x_left, x_right]")
    if err is not None:
        return err
    expected = _span(SCAN_ROW + 0.5)
    tol = 1e-3
    if np.allclose(got, expected, atol=tol):
        return correct("the two active edges cross the scan line there; the pixels whose centres lie between "
                       "the ends are drawn.")
    if np.allclose(got, _span(float(SCAN_ROW)), atol=tol):
        return wrong("that is the span at y = row, the top of the pixels; scan lines are sampled at the pixel "
                     "centres, y = row + 0.5.")
    if np.allclose(got, expected[::-1], atol=tol):
        return wrong("your ends are swapped: x_left is the smaller.")
    P = np.array(SCAN_POLYGON)
    if np.allclose(got, [P[:, 0].min(), P[:, 0].max()], atol=tol):
        return wrong("that is the x-range of the whole polygon; on one scan line only the crossings of the two "
                     "active edges bound the span.")
    return wrong(f"your span is {far_off(got, expected)} at one end; find the two edges whose "
                 f"y-range contains the scan line and intersect each with it.")


# -- §22.6 -------------------------------------------------------------------------------------------

def check_split_points(answer) -> Result:
    """Check where the plane cuts the triangle's edges (Goldman §22.6).

    Recognises the midpoints of the two cut edges and a vertex of the triangle given as a cut point.
    """
    got, err = read_points(answer, "your points", ask="[[x, y, z], [x, y, z]]")
    if err is not None:
        return err
    if got.shape != (2, 3):
        return wrong(f"give two points of three coordinates, shape (2, 3); yours has shape {got.shape}.")
    T = np.array(SPLIT_TRIANGLE)
    front, back = hs.split_polygon(T, SPLIT_POINT, SPLIT_NORMAL)
    cut = np.array([p for p in front if min(np.linalg.norm(T - p, axis=1)) > 1e-9])
    tol = 1e-3

    def same(a, b):
        return np.allclose(a, b, atol=tol) or np.allclose(a, b[::-1], atol=tol)

    if same(got, cut):
        return correct("each cut point divides its edge in the ratio of the vertices' signed distances to the "
                       "plane, s_a / (s_a - s_b).")
    N = np.array(SPLIT_NORMAL)
    s = (T - np.array(SPLIT_POINT)) @ N
    crossing = [(i, (i + 1) % 3) for i in range(3) if s[i] * s[(i + 1) % 3] < 0]
    mids = np.array([(T[i] + T[j]) / 2 for i, j in crossing])
    if len(mids) == 2 and same(got, mids):
        return wrong("those are the midpoints of the two cut edges; the plane cuts each edge where the signed "
                     "distance (P - Q)·N changes sign, at the fraction s_a / (s_a - s_b) along it.")
    if any(min(np.linalg.norm(T - p, axis=1)) < tol for p in got):
        return wrong("one of your points is a vertex of the triangle; no vertex lies on the plane here.")
    near = cut if np.abs(got - cut).max() <= np.abs(got - cut[::-1]).max() else cut[::-1]
    return wrong(f"your points are {far_off(got, near)}; compute s = (P - Q)·N at each vertex and interpolate along "
                 f"the two edges whose ends have opposite signs.")


# -- §22.7 -------------------------------------------------------------------------------------------

def check_bsp_order(answer) -> Result:
    """Check the back-to-front order of :func:`exercise_bsp_tree` for :data:`BSP_EYE` (Goldman §22.7).

    Recognises front-to-back (the reverse) and a fixed in-order traversal (back, node, front) that
    ignores the eye's side.
    """
    got, err = _read_list(answer, "your order", 5, "the order as a list of polygon numbers")
    if err is not None:
        return err
    if np.any(got != np.round(got)):
        return wrong("polygon numbers are whole numbers 0-4; list each once.")
    got = [int(v) for v in got]
    expected = [k for k, _ in hs.bsp_back_to_front(exercise_bsp_tree(), BSP_EYE)]
    if got == expected:
        return correct("at each node the side away from the eye first, then the node, then the eye's side.")
    if got == expected[::-1]:
        return wrong("that is front to back; back to front paints the subtree on the far side of each plane first.")
    if got == [4, 0, 3, 1, 2]:
        return wrong("that always takes the back subtree first; which side is 'back' depends on the eye: at the "
                     "node of plane x = 1 the eye (x = -1) is behind the plane, so its front subtree is farther.")
    if sorted(got) != list(range(5)):
        return wrong("list each polygon number 0-4 exactly once.")
    return wrong("that order breaks the rule at some node: test on which side of each node's plane the eye lies, "
                 "and go to the other side first.")


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
