"""Exercise checkers for chapter 20, solid modeling (Goldman §20.2-20.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other solids, rays and counts than the chapter's worked examples.  The
programming project, :func:`check_csg_classifier_project`, runs the learner's interval classifier
``classify(first, second, operation)`` against
:func:`goldman_lib.solid_modeling.combine_intervals` on seeded interval lists, touching, empty,
nested, identical and unbounded ones included.

>>> print(PROBLEMS["check_genus"])   # doctest: +ELLIPSIS
A block with two square holes drilled through it has V = 24 vertices, ...
>>> check_genus(0)
Not yet: 0 is V - E + F read as twice (S - G) without the rings: the top and bottom faces each have two inner loops, so L - F = 4 must be subtracted first (the Euler-Poincare formula V - E + F - (L - F) = twice (S - G)).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import solid_modeling as sm
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_number, read_points, unanswered, wrong
from goldman_lib.exercises.projects import Case, check_project, describe
from goldman_lib.simple_surfaces import Sphere

__all__ = ["PROBLEMS", "SLIPS", "BALL_A", "BALL_B", "RAY_ORIGIN", "RAY_DIRECTION", "PRISM_SIDES", "HOLES_COUNTS",
           "SLAB_TOP", "OCTREE_DEPTH", "TREE_INTERVALS", "TREE_RESULT", "TREE_OPTIONS", "PYRAMID_VERTICES",
           "PYRAMID_FACES", "check_csg_difference", "check_which_tree", "check_euler_counts", "check_genus",
           "check_flipped_face", "check_octree_counts", "check_csg_classifier_project", "csg_project_cases"]

#: Exercise 1 (§20.2): two balls (centre, radius) and a ray along the x-axis.
BALL_A = ((0.0, 0.0, 0.0), 2.0)
BALL_B = ((1.5, 0.0, 0.0), 1.0)
RAY_ORIGIN = (-5.0, 0.0, 0.0)
RAY_DIRECTION = (1.0, 0.0, 0.0)
#: Exercise 2 (§20.2): the inside intervals of three primitives along one ray, and a result.
TREE_INTERVALS = {"A": [(1.0, 5.0)], "B": [(3.0, 8.0)], "C": [(4.0, 6.0)]}
TREE_RESULT = [(1.0, 4.0), (6.0, 8.0)]
TREE_OPTIONS = {"a": "A ∪ (B − C)", "b": "(A − C) ∪ B", "c": "(A ∪ B) − C", "d": "(A ∩ B) ∪ C"}
#: Exercise 3 (§20.3): a prism over a regular polygon with this many sides.
PRISM_SIDES = 6
#: Exercise 4 (§20.3): the counts of a block with two square through-holes.
HOLES_COUNTS = {"V": 24, "E": 36, "F": 14, "L": 18, "S": 1}
#: Exercise 5 (§20.3): a square pyramid whose face list has one face inside out.
PYRAMID_VERTICES = ((0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (2.0, 2.0, 0.0), (0.0, 2.0, 0.0), (1.0, 1.0, 1.5))
PYRAMID_FACES = ((0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (3, 2, 4), (3, 0, 4))
#: Exercise 6 (§20.4): the half-space z <= SLAB_TOP in the root cube [-1, 1]^3, to this depth.
SLAB_TOP = 0.6
OCTREE_DEPTH = 2


def _iv_text(ivs) -> str:
    return ", ".join(f"[{fmt(a)}, {fmt(b)}]" for a, b in ivs)


PROBLEMS = {
    "check_csg_difference": (
        f"Ball A has centre {BALL_A[0]} and radius {fmt(BALL_A[1])}; ball B has centre {BALL_B[0]} and radius "
        f"{fmt(BALL_B[1])}. Along the ray P(t) = {RAY_ORIGIN} + t {RAY_DIRECTION}, find the intervals of t where "
        "the ray is inside the CSG solid A − B (Goldman §20.2: classify each primitive's intervals, then combine "
        "them). Give a list of [start, end] intervals."),
    "check_which_tree": (
        f"Along one ray the primitives' inside intervals are A: {_iv_text(TREE_INTERVALS['A'])}, "
        f"B: {_iv_text(TREE_INTERVALS['B'])}, C: {_iv_text(TREE_INTERVALS['C'])}. The solid drawn is inside on "
        f"{_iv_text(TREE_RESULT)}. Which CSG tree gives it? "
        + "; ".join(f"({k}) {v}" for k, v in TREE_OPTIONS.items()) + ". Give the letter (Goldman §20.2)."),
    "check_euler_counts": (
        f"Count the vertices, edges and faces of a prism over a regular {PRISM_SIDES}-gon (a hexagonal prism) "
        "and check Euler's formula V - E + F = 2. Give [V, E, F] (Goldman §20.3)."),
    "check_genus": (
        f"A block with two square holes drilled through it has V = {HOLES_COUNTS['V']} vertices, "
        f"E = {HOLES_COUNTS['E']} edges, F = {HOLES_COUNTS['F']} faces, L = {HOLES_COUNTS['L']} loops (its top and "
        f"bottom faces each have two rings) and S = {HOLES_COUNTS['S']} shell. What is its genus G by the "
        "Euler-Poincare formula (Goldman §20.3)?"),
    "check_flipped_face": (
        f"A square pyramid has vertices {', '.join(str(v) for v in PYRAMID_VERTICES)} (0-3 the base, 4 the apex) "
        f"and faces {', '.join(f'{k}: {list(f)}' for k, f in enumerate(PYRAMID_FACES))}. One face is listed inside "
        "out (clockwise seen from outside). Which one? Give its index (Goldman §20.3: a shared edge must be "
        "traversed in opposite directions by its two faces)."),
    "check_octree_counts": (
        f"Build the octree of the half-space z <= {fmt(SLAB_TOP)} in the root cube [-1, 1]^3 to depth "
        f"{OCTREE_DEPTH}, classifying a cell full if its 8 corners and centre are all inside, empty if none is, "
        "partial otherwise, and splitting only partial cells. How many leaf cells are full, partial and empty? "
        "Give [full, partial, empty] (Goldman §20.4)."),
}


# -- reading answers ---------------------------------------------------------------------------------

def _read_intervals(answer, what: str):
    got, err = read_points(answer, what, ask="a list of [start, end] intervals")
    if err is not None:
        return None, err
    if got.size == 0:
        return np.zeros((0, 2)), None
    if got.ndim == 1 and got.shape == (2,):
        got = got[None]
    if got.ndim != 2 or got.shape[1] != 2:
        return None, wrong(f"{what} should be a list of [start, end] pairs; yours has shape {got.shape}.")
    if np.any(got[:, 0] > got[:, 1]):
        return None, wrong(f"{what} has an interval whose start is after its end; write each as [start, end].")
    return got[np.argsort(got[:, 0], kind="stable")], None


def _same(got, ivs, tol=1e-4) -> bool:
    exp = np.asarray(ivs, dtype=float).reshape(-1, 2)
    return got.shape == exp.shape and bool(np.all(np.abs(got - exp) <= tol))


def _ball_intervals(ball):
    return sm.intervals(Sphere(*ball), RAY_ORIGIN, RAY_DIRECTION)[0]


def _finite(iv):
    return iv[np.isfinite(iv[:, 0])]


# -- §20.2 ---------------------------------------------------------------------------------------------

def check_csg_difference(answer) -> Result:
    """Check the inside intervals of A − B along the ray, in the ray's parameter t (Goldman §20.2).

    Recognises the union, the intersection, B − A, A's interval alone, the symmetric difference and
    the answer in x instead of t.
    """
    got, err = _read_intervals(answer, "your intervals")
    if err is not None:
        return err
    ia, ib = _finite(_ball_intervals(BALL_A)), _finite(_ball_intervals(BALL_B))
    expected = sm.combine_intervals(ia, ib, "difference")
    if _same(got, expected):
        return correct(f"A − B is inside for t in {_iv_text(expected)}: A's interval minus B's; the ray enters A "
                       "and leaves the result where it enters B (there the result's normal is B's, reversed).")
    slips = [
        (sm.combine_intervals(ia, ib, "union"), "that is A ∪ B, the part of the ray inside either ball"),
        (sm.combine_intervals(ia, ib, "intersection"), "that is A ∩ B, the part of the ray inside both balls; "
                                                       "A − B keeps the part of A's interval that is not in B's"),
        (sm.combine_intervals(ib, ia, "difference"), "that is B − A: subtract B from A, not A from B"),
        (ia, "that is A's interval alone: B has not been subtracted from it"),
        (sm.combine_intervals(sm.combine_intervals(ia, ib, "union"), sm.combine_intervals(ia, ib, "intersection"),
                              "difference"),
         "that is the symmetric difference (inside exactly one ball): B's part outside A is not in A − B"),
        (expected + np.array(RAY_ORIGIN[0]), "those are x-coordinates of the ends; the question asks for the ray "
                                             "parameter t, with x = -5 + t"),
    ]
    for ivs, why in slips:
        if _same(got, ivs):
            return wrong(why + ".")
    if len(got) != len(expected):
        return wrong(f"you gave {len(got)} interval(s); A − B along this ray is a different number. Find where the "
                     "ray enters and leaves each ball (solve |P(t) - C|^2 = r^2), then keep what is in A and not in B.")
    k = int(np.argmax(np.abs(got - expected).max(axis=1)))
    return wrong(f"interval {k} is {far_off(got[k], expected[k])} at one end. Solve "
                 "|P(t) - C|^2 = r^2 for each ball and combine the two intervals.")


def _tree_result(letter: str) -> np.ndarray:
    A, B, C = (np.array(TREE_INTERVALS[k], dtype=float) for k in "ABC")
    c = sm.combine_intervals
    return {"a": lambda: c(A, c(B, C, "difference"), "union"),
            "b": lambda: c(c(A, C, "difference"), B, "union"),
            "c": lambda: c(c(A, B, "union"), C, "difference"),
            "d": lambda: c(c(A, B, "intersection"), C, "union")}[letter]()


def check_which_tree(answer) -> Result:
    """Check which CSG tree turns the intervals A [1, 5], B [3, 8], C [4, 6] into [1, 4], [6, 8]
    (Goldman §20.2).

    Explains what each other tree keeps or loses.
    """
    if is_unanswered(answer):
        return unanswered("a letter, e.g. \"a\"")
    if not isinstance(answer, str) or answer.strip().strip("()").lower() not in TREE_OPTIONS:
        return wrong(f"give one of the letters {', '.join(TREE_OPTIONS)} as a string; you gave {quote(answer)}.")
    letter = answer.strip().strip("()").lower()
    if _same(_tree_result(letter), TREE_RESULT, 1e-12):
        return correct(f"({letter}) {TREE_OPTIONS[letter]}: A ∪ B covers one interval, and subtracting C cuts the "
                       "gap out of it; the tree is evaluated bottom up, one interval combination per node.")
    why = {
        "a": "A ∪ (B − C) subtracts C from B only, so the part of A inside C survives and the gap is too short",
        "b": "(A − C) ∪ B subtracts C from A only; B then fills C's interval back in, so the result has no gap",
        "d": "(A ∩ B) ∪ C keeps only the overlap of A and B and adds C: it starts where B starts, not where A does",
        "c": "",
    }[letter]
    return wrong(why + ".")


# -- §20.3 ---------------------------------------------------------------------------------------------

def check_euler_counts(answer) -> Result:
    """Check [V, E, F] of a hexagonal prism (Goldman §20.3).

    Recognises edges counted once per face (each edge lies in two faces), the caps left out, and the
    counts of the hexagon's pyramid.
    """
    got, err = read_points(answer, "your counts", ask="[V, E, F]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"give three counts [V, E, F]; yours has shape {got.shape}.")
    n = PRISM_SIDES
    V, E, F = 2 * n, 3 * n, n + 2
    if np.array_equal(got, [V, E, F]):
        return correct(f"V = {V}, E = {E}, F = {F}: V - E + F = {V - E + F}, Euler's formula for a simple "
                       "polyhedron.")
    if np.array_equal(got, [V, 2 * E, F]):
        return wrong("you counted each edge once for every face it lies in: in a closed polyhedron every edge "
                     "lies in exactly two faces, so halve the sum over the faces.")
    if np.array_equal(got, [V, E, n]):
        return wrong("you left out the two caps (top and bottom faces); with them V - E + F = 2.")
    if np.array_equal(got, [n + 1, 2 * n, n + 1]):
        return wrong("those are the counts of a pyramid over the hexagon; a prism has two hexagons joined by "
                     "rectangles.")
    if np.abs(got).max() > 1e6:
        return wrong("a hexagonal prism has a few vertices, edges and faces, not millions; count them.")
    chi = int(got[0] - got[1] + got[2])
    if chi != 2:
        return wrong(f"your counts give V - E + F = {chi}, but a prism is a simple polyhedron (Euler: 2). Count "
                     "the top and bottom hexagons' vertices, their edges plus the vertical ones, and the faces.")
    return wrong("your counts satisfy Euler's formula but are not the prism's: count the vertices of the two "
                 "hexagons, the edges of both hexagons and the vertical edges, and the rectangles plus two caps.")


def check_genus(answer) -> Result:
    """Check the genus of the block with holes, from V - E + F - (L - F) = 2(S - G) (Goldman §20.3).

    Recognises the rings left out, the factor 2 forgotten, and the sign of the genus reversed.
    """
    value, err = read_number(answer, "your genus")
    if err is not None:
        return err
    c = HOLES_COUNTS
    chi = c["V"] - c["E"] + c["F"] - (c["L"] - c["F"])
    G = c["S"] - chi // 2
    if value == G:
        return correct(f"V - E + F - (L - F) = {chi} = 2(S - G) gives G = {G}: one handle per hole drilled "
                       "through the block.")
    chi0 = c["V"] - c["E"] + c["F"]
    if value == c["S"] - chi0 // 2:
        return wrong(f"{fmt(value)} is V - E + F read as twice (S - G) without the rings: the top and bottom faces each "
                     f"have two inner loops, so L - F = {c['L'] - c['F']} must be subtracted first (the "
                     "Euler-Poincare formula V - E + F - (L - F) = twice (S - G)).")
    if value == c["S"] - chi:
        return wrong("you set V - E + F - (L - F) equal to S - G: the formula has twice (S - G) on the right; halve it.")
    if value == chi // 2 - c["S"]:
        return wrong("the sign is reversed: twice (S - G) is V - E + F - (L - F), so G is S minus half of V - E + F - (L - F), "
                     "and a genus is never negative.")
    if value < 0 or value != int(value):
        return wrong("a genus counts handles: a whole number >= 0. Use G = S minus half of V - E + F - (L - F).")
    return wrong(f"your genus is {off_by(value, G)}. Use G = S minus half of V - E + F - (L - F), with the counts given.")


def check_flipped_face(answer) -> Result:
    """Check which face of the pyramid is inside out: the one that runs a shared edge the same way
    as its neighbour (Goldman §20.3).

    Recognises the faces that share an edge with the flipped face.
    """
    value, err = read_number(answer, "your face index", "face index")
    if err is not None:
        return err
    if value != int(value) or not 0 <= value < len(PYRAMID_FACES):
        return wrong(f"give a face index from 0 to {len(PYRAMID_FACES) - 1}; you gave {quote(answer)}.")
    k = int(value)
    brep = sm.BRep(PYRAMID_VERTICES, [list(f) for f in PYRAMID_FACES])
    bad_edges = [p for p in brep.problems() if "opposite directions" in p]
    flipped = [f for f in range(len(PYRAMID_FACES))
               if all(any(f"face {f}" in p and f"({min(a, b)}, {max(a, b)})" in p for p in bad_edges)
                      for a, b in zip(PYRAMID_FACES[f], PYRAMID_FACES[f][1:] + PYRAMID_FACES[f][:1]))]
    if flipped and k == flipped[0]:
        fixed = [list(f) if i != k else list(f)[::-1] for i, f in enumerate(PYRAMID_FACES)]
        ok = sm.BRep(PYRAMID_VERTICES, fixed).is_valid()
        return correct(f"face {k}: each of its edges runs the same way as in its neighbour; reversing it makes the "
                       f"pyramid {'valid' if ok else 'consistent'} (every shared edge traversed once each way).")
    if any(f"face {k}" in p for p in bad_edges):
        return wrong(f"face {k} shares an edge with the flipped face, so that edge runs the same way in both; but "
                     f"face {k}'s other edges run opposite to their neighbours'. Find the face all of whose edges "
                     "disagree.")
    return wrong(f"face {k}'s edges all run opposite to its neighbours', as they should. For each edge (a, b) of "
                 "a face look for (b, a) in the face across it.")


# -- §20.4 ---------------------------------------------------------------------------------------------

def check_octree_counts(answer) -> Result:
    """Check [full, partial, empty] leaves of the octree of the half-space z <= 0.6 at depth 2
    (Goldman §20.4).

    Recognises full cells split as well (a uniform grid), the tree stopped a level early, the
    depth-1 full cells left out, and partial and empty swapped.
    """
    got, err = read_points(answer, "your counts", ask="[full, partial, empty]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"give three counts [full, partial, empty]; yours has shape {got.shape}.")
    tree = sm.Octree.build(lambda P: P[:, 2] <= SLAB_TOP, size=2.0, depth=OCTREE_DEPTH)
    c = tree.counts()
    exp = np.array([c["full"], c["partial"], c["empty"]])
    if np.array_equal(got, exp):
        return correct(f"{c['full']} full, {c['partial']} partial, {c['empty']} empty leaves; the full cells' volume "
                       f"{fmt(tree.volume(0.0))} and full + partial {fmt(tree.volume(1.0))} bracket the true "
                       f"{fmt(4 * (1 + SLAB_TOP))}.")
    uniform = sm.Octree.build(lambda P: P[:, 2] <= SLAB_TOP, size=2.0, depth=1).counts()
    fine = 8 ** OCTREE_DEPTH
    cells = (np.arange(2 ** OCTREE_DEPTH) + 0.5) * 2 / 2 ** OCTREE_DEPTH - 1
    lo, hi = cells - 1 / 2 ** OCTREE_DEPTH, cells + 1 / 2 ** OCTREE_DEPTH
    layers_full = int(np.sum(hi <= SLAB_TOP)) * 4 ** OCTREE_DEPTH
    layers_partial = int(np.sum((lo <= SLAB_TOP) & (hi > SLAB_TOP))) * 4 ** OCTREE_DEPTH
    if np.array_equal(got, [layers_full, layers_partial, fine - layers_full - layers_partial]):
        return wrong(f"you split every cell down to depth {OCTREE_DEPTH} (a uniform grid of {fine} cells): an "
                     "octree splits only partial cells, so a full octant at depth 1 stays one leaf.")
    if np.array_equal(got, [uniform["full"], uniform["partial"], uniform["empty"]]):
        return wrong(f"you stopped at depth 1: the partial octants are split once more (depth {OCTREE_DEPTH}).")
    if np.array_equal(got, [exp[0] - uniform["full"], exp[1], exp[2]]):
        return wrong("you counted only the cells of the last level: the full octants of depth 1 are leaves too.")
    if np.array_equal(got, [exp[0], exp[2], exp[1]]):
        return wrong("partial and empty are swapped: a cell with some samples inside and some outside is partial.")
    return wrong(f"{int(got.sum())} leaves in all; classify the 8 octants first (which lie wholly below "
                 f"z = {fmt(SLAB_TOP)}?), then split only the partial ones into 8 and classify again.")


# -- programming project ---------------------------------------------------------------------------

def _reference(first, second, operation):
    a = np.asarray(first, dtype=float).reshape(-1, 2)
    b = np.asarray(second, dtype=float).reshape(-1, 2)
    return sm.combine_intervals(a, b, operation).tolist()


def csg_project_cases(seed: int = 20) -> list[Case]:
    """The cases of :func:`check_csg_classifier_project`, from a fixed seed: random lists under each
    operation, touching intervals (a union merges them, an intersection is empty), an empty list,
    nested and identical intervals, lists that never meet, and unbounded intervals (a half-space,
    ``-inf``/``inf`` ends).

    >>> cases = csg_project_cases()
    >>> len(cases), cases[0].kind
    (22, 'random lists')
    """
    rng = np.random.default_rng(seed)
    cases: list[Case] = []

    def add(a, b, op, kind):
        a = [[float(s), float(e)] for s, e in a]
        b = [[float(s), float(e)] for s, e in b]
        label = f"{op} of first = {a} and second = {b}"
        cases.append(Case(label, (a, b, op), kind=kind))

    def random_list(k):
        ends = np.sort(rng.choice(np.arange(0, 40), size=2 * k, replace=False)) / 4
        return ends.reshape(-1, 2)

    for op in ("union", "intersection", "difference"):
        for k1, k2 in ((2, 2), (3, 1)):
            add(random_list(k1), random_list(k2), op, "random lists")
    for op in ("union", "intersection", "difference"):
        add([[0, 1]], [[1, 2]], op, "touching intervals")
        add([[0, 1], [2, 3]], [[1, 2]], op, "touching on both sides")
        add([], [[0.5, 2]], op, "an empty list")
        add([[0, 5]], [[1, 2], [3, 4]], op, "nested")
    for op in ("union", "difference"):
        add([[1, 3], [4, 6]], [[1, 3], [4, 6]], op, "identical lists")
    add([[-np.inf, 2]], [[1, np.inf]], "intersection", "unbounded (half-spaces)")
    add([[0, 3]], [[-np.inf, 1]], "difference", "unbounded (half-spaces)")
    return cases


def _compare(got, expected, case) -> str | None:
    try:
        arr = np.asarray(got, dtype=float)
    except (TypeError, ValueError):
        return f"it should be a list of [start, end] pairs; it is {describe(got)}"
    exp = np.asarray(expected, dtype=float).reshape(-1, 2)
    if arr.size == 0:
        arr = arr.reshape(0, 2)
    if arr.ndim != 2 or arr.shape[1] != 2:
        return f"it should be a list of [start, end] pairs; it has shape {arr.shape}"
    if np.isnan(arr).any():
        return "it contains NaN"
    op = case.args[2]
    if len(arr) != len(exp):
        if op == "difference":
            other = np.asarray(_reference(case.args[1], case.args[0], op), dtype=float).reshape(-1, 2)
            if other.shape == arr.shape and np.allclose(arr, other, atol=1e-9, rtol=0):
                return ("that is second minus first; the difference is first minus second (the part of first "
                        "outside second)")
        why = ""
        if len(arr) > len(exp):
            touching = np.any(arr[1:, 0] <= arr[:-1, 1]) if len(arr) > 1 else False
            zero = np.any(arr[:, 1] <= arr[:, 0])
            if zero:
                why = " (an interval of zero length -- a single touching point -- is dropped)"
            elif touching:
                why = " (intervals that touch or overlap merge into one)"
        return (f"it has {len(arr)} interval(s); the {op} has {len(exp)}: expected {exp.tolist()}{why}")
    if len(arr) and np.any(arr[1:, 0] < arr[:-1, 0]):
        return "its intervals are not sorted by their start"
    if not np.allclose(arr, exp, atol=1e-9, rtol=0):
        if op == "difference":
            other = np.asarray(_reference(case.args[1], case.args[0], op), dtype=float).reshape(-1, 2)
            if other.shape == arr.shape and np.allclose(arr, other, atol=1e-9, rtol=0):
                return "that is second minus first; the difference is first minus second (the part of first outside second)"
        k = int(np.flatnonzero(~np.all(np.isclose(arr, exp, atol=1e-9, rtol=0), axis=1))[0])
        return f"interval {k} is {arr[k].tolist()}; expected {exp[k].tolist()}"
    return None


def check_csg_classifier_project(function) -> Result:
    """Check the learner's CSG interval classifier ``classify(first, second, operation)`` (lists of
    ``[start, end]`` pairs, sorted and disjoint; ``operation`` "union", "intersection" or
    "difference") against :func:`goldman_lib.solid_modeling.combine_intervals` on
    :func:`csg_project_cases` (Goldman §20.2).  The result must be sorted, disjoint, with touching
    pieces merged and zero-length pieces dropped.

    >>> def naive(first, second, operation):
    ...     return first + second if operation == "union" else first
    >>> print(check_csg_classifier_project(naive).message)   # doctest: +ELLIPSIS
    case 1 of 22 (union of first = ...): your function returned ...; it has 4 interval(s); the union has 2: ... (intervals that touch or overlap merge into one). Hint: ...
    """
    return check_project(function, csg_project_cases(), reference=_reference, compare=_compare,
                         what="the CSG classifier",
                         hint="cut the line at every end of both lists, decide for each piece whether it lies in "
                              "first and in second, keep it if the operation says so, and merge kept pieces that "
                              "touch")


SLIPS = {
    "check_csg_difference": [[[3, 7.5]], [[5.5, 7]], [[7, 7.5]], [[3, 7]], [[3, 5.5], [7, 7.5]], [[-2, 0.5]]],
    "check_which_tree": ["a", "b", "d"],
    "check_euler_counts": [[12, 36, 8], [12, 18, 6], [7, 12, 7]],
    "check_genus": [0, 3, -2],
    "check_flipped_face": [2, 4, 0],
    "check_octree_counts": [[48, 16, 0], [4, 4, 0], [16, 16, 0], [20, 0, 16]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
