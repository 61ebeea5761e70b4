"""Exercise checkers for chapter 20, solid modeling (Goldman §20.2-20.4).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) and the programming project do not deal.  ``SLIPS`` holds the
wrong answers each checker recognises, for the stored instance.  ``None`` or ``...`` means "not
answered yet".  Every exercise uses other solids, rays and counts than the chapter's worked
examples.  The programming project, :func:`check_csg_classifier_project`, runs the learner's
interval classifier ``classify(first, second, operation)`` against
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
from goldman_lib.exercises.deal import Deck
from goldman_lib.exercises.projects import Case, check_project, describe
from goldman_lib.simple_surfaces import Sphere

__all__ = ["PROBLEMS", "SLIPS", "BALL_A", "BALL_B", "RAY_ORIGIN", "RAY_DIRECTION", "PRISM_SIDES", "HOLES_COUNTS",
           "SLAB_TOP", "OCTREE_DEPTH", "TREE_INTERVALS", "TREE_RESULT", "TREE_OPTIONS", "PYRAMID_VERTICES",
           "PYRAMID_FACES", "DECK", "deal", "steps", "current", "deal_button",
           "check_csg_difference", "check_which_tree", "check_euler_counts", "check_genus",
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

DECK = Deck("ch20")

#: names of the polygons and counts the dealt instances use
_ADJECTIVE = {3: "triangular", 4: "square", 5: "pentagonal", 6: "hexagonal", 7: "heptagonal", 8: "octagonal",
              9: "nonagonal", 10: "decagonal", 12: "dodecagonal"}
_NOUN = {3: "triangle", 4: "square", 5: "pentagon", 6: "hexagon", 7: "heptagon", 8: "octagon", 9: "nonagon",
         10: "decagon", 12: "dodecagon"}
_WORD = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}


def _iv_text(ivs) -> str:
    return ", ".join(f"[{fmt(a)}, {fmt(b)}]" for a, b in ivs)


def _ivs(a) -> np.ndarray:
    return np.asarray(a, dtype=float).reshape(-1, 2)


def _same_ivs(a, b, tol=1e-4) -> bool:
    """Two interval lists are one answer when they have as many intervals, each end within tol."""
    a, b = _ivs(a), _ivs(b)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol))


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


def _finite(iv):
    return iv[np.isfinite(iv[:, 0])]


# -- §20.2 ---------------------------------------------------------------------------------------------

def _ball_iv(p, which):
    return _finite(sm.intervals(Sphere(*p[which]), p["origin"], p["direction"])[0])


def _csg_forms(p):
    ia, ib = _ball_iv(p, "A"), _ball_iv(p, "B")
    c = sm.combine_intervals
    expected = c(ia, ib, "difference")
    slips = {"union": c(ia, ib, "union"), "intersection": c(ia, ib, "intersection"), "B - A": c(ib, ia, "difference"),
             "A alone": ia, "symmetric": c(c(ia, ib, "union"), c(ia, ib, "intersection"), "difference"),
             "x for t": expected + np.array(p["origin"][0])}
    return expected, slips


def _csg_generate(rng) -> dict:
    a = float(rng.integers(-2, 3)) / 2
    ra = float(rng.choice([1.5, 2.0, 2.5, 3.0]))
    b = a + float(rng.choice([-1, 1])) * float(rng.integers(1, 7)) / 2
    rb = float(rng.choice([0.5, 1.0, 1.5, 2.0]))
    return {"A": ((a, 0.0, 0.0), ra), "B": ((b, 0.0, 0.0), rb), "origin": (float(rng.integers(-7, -4)), 0.0, 0.0),
            "direction": (1.0, 0.0, 0.0)}


def _csg_ok(p):
    (a, _, _), ra = p["A"]
    (b, _, _), rb = p["B"]
    if p["origin"][0] >= min(a - ra, b - rb):
        return "the ray starts inside a ball"
    overlap = min(a + ra, b + rb) - max(a - ra, b - rb)
    if overlap < 0.5:
        return "the balls hardly overlap: A − B is A"
    if abs(a + ra - (b + rb)) < 0.25 or abs(a - ra - (b - rb)) < 0.25:
        return "the balls' ends (nearly) coincide"
    return None


def _csg_statement(p) -> str:
    return (f"Ball A has centre {p['A'][0]} and radius {fmt(p['A'][1])}; ball B has centre {p['B'][0]} and radius "
            f"{fmt(p['B'][1])}. Along the ray P(t) = {p['origin']} + t {p['direction']}, find the intervals of t where "
            "the ray is inside the CSG solid A − B (Goldman §20.2: classify each primitive's intervals, then combine "
            "them). Give a list of [start, end] intervals.")


def _csg_steps(p) -> str:
    ia, ib = _ball_iv(p, "A"), _ball_iv(p, "B")
    x0 = p["origin"][0]
    lines = []
    for name, iv in (("A", ia), ("B", ib)):
        (c, _, _), r = p[name]
        lines.append(f"   ball {name}: x from {fmt(c)} - {fmt(r)} to {fmt(c)} + {fmt(r)}, so t in {_iv_text(iv)}")
    return (f"1. On the ray x = {fmt(x0)} + t, y = z = 0, so each ball is crossed where |x - centre| <= radius:\n"
            + "\n".join(lines) + "\n"
            f"2. A − B keeps the part of A's interval outside B's: {_iv_text(_csg_forms(p)[0]) or 'nothing'} "
            f"(sm.combine_intervals(A, B, 'difference')).")


@DECK.exercise(stored={"A": BALL_A, "B": BALL_B, "origin": RAY_ORIGIN, "direction": RAY_DIRECTION},
               generate=_csg_generate, answer=lambda p: _csg_forms(p)[0], slips=lambda p: _csg_forms(p)[1],
               statement=_csg_statement, steps=_csg_steps, same=_same_ivs, well_posed=_csg_ok)
def check_csg_difference(answer, p) -> Result:
    """Check the inside intervals of A − B along the ray, in the ray's parameter t (Goldman §20.2).

    Recognises the union, the intersection, B − A, A's interval alone, the symmetric difference and
    the answer in x instead of t.
    """
    got, err = _read_intervals(answer, "your intervals")
    if err is not None:
        return err
    expected, s = _csg_forms(p)
    if _same(got, expected):
        return correct(f"A − B is inside for t in {_iv_text(expected)}: A's interval minus B's; the ray enters A "
                       "and leaves the result where it enters B (there the result's normal is B's, reversed).")
    slips = [
        (s["union"], "that is A ∪ B, the part of the ray inside either ball"),
        (s["intersection"], "that is A ∩ B, the part of the ray inside both balls; "
                            "A − B keeps the part of A's interval that is not in B's"),
        (s["B - A"], "that is B − A: subtract B from A, not A from B"),
        (s["A alone"], "that is A's interval alone: B has not been subtracted from it"),
        (s["symmetric"], "that is the symmetric difference (inside exactly one ball): B's part outside A is not in A − B"),
        (s["x for t"], "those are x-coordinates of the ends; the question asks for the ray "
                       f"parameter t, with x = {fmt(p['origin'][0])} + t"),
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


def _tree_result(p, letter: str) -> np.ndarray:
    A, B, C = (_ivs(p["intervals"][k]) for k in "ABC")
    c = sm.combine_intervals
    return {"a": lambda: c(A, c(B, C, "difference"), "union"),
            "b": lambda: c(c(A, C, "difference"), B, "union"),
            "c": lambda: c(c(A, B, "union"), C, "difference"),
            "d": lambda: c(c(A, B, "intersection"), C, "union")}[letter]()


_STORED_TREE = {"intervals": {k: tuple(tuple(iv) for iv in v) for k, v in TREE_INTERVALS.items()},
                "result": tuple(TREE_RESULT)}


def _tree_answer(p) -> str:
    return next(k for k in TREE_OPTIONS if _same(_tree_result(p, k), p["result"], 1e-12))


def _tree_generate(rng) -> dict:
    ends = rng.choice(np.arange(0, 11), size=6, replace=False).reshape(3, 2)    # six different ends
    ivs = {k: ((float(min(e)), float(max(e))),) for k, e in zip("ABC", ends)}
    letter = "abcd"[int(rng.integers(0, 4))]
    p = {"intervals": ivs, "result": ()}
    return {"intervals": ivs, "result": tuple(tuple(float(x) for x in iv) for iv in _tree_result(p, letter))}


def _tree_ok(p):
    results = [_tree_result(p, k) for k in TREE_OPTIONS]
    if not len(p["result"]):
        return "the solid drawn is empty along the ray"
    if any(_same_ivs(r, q) for i, r in enumerate(results) for q in results[i + 1:]):
        return "two trees give the same intervals"
    ends = [x for v in p["intervals"].values() for iv in v for x in iv]
    if len(set(ends)) < len(ends):
        return "two primitives share an end (a touching case, not this exercise's point)"
    return None


def _tree_statement(p) -> str:
    ivs = p["intervals"]
    return (f"Along one ray the primitives' inside intervals are A: {_iv_text(ivs['A'])}, "
            f"B: {_iv_text(ivs['B'])}, C: {_iv_text(ivs['C'])}. The solid drawn is inside on "
            f"{_iv_text(p['result'])}. Which CSG tree gives it? "
            + "; ".join(f"({k}) {v}" for k, v in TREE_OPTIONS.items()) + ". Give the letter (Goldman §20.2).")


def _tree_steps(p) -> str:
    lines = [f"   ({k}) {v}: {_iv_text(_tree_result(p, k)) or 'empty'}" for k, v in TREE_OPTIONS.items()]
    return ("1. Evaluate each tree bottom up, one interval combination per node (sm.combine_intervals):\n"
            + "\n".join(lines) + f"\n2. Only ({_tree_answer(p)}) gives {_iv_text(p['result'])}.")


@DECK.exercise(stored=_STORED_TREE, generate=_tree_generate, answer=_tree_answer,
               slips=lambda p: {k: k for k in TREE_OPTIONS if k != _tree_answer(p)}, statement=_tree_statement,
               steps=_tree_steps, same=lambda a, b: a == b, well_posed=_tree_ok)
def check_which_tree(answer, p) -> Result:
    """Check which CSG tree turns the statement's intervals A, B, C into the solid drawn
    (Goldman §20.2).

    Explains what each other tree keeps or loses.
    """
    if is_unanswered(answer):
        return unanswered("a letter, e.g. \"a\"")
    if not isinstance(answer, str) or answer.strip().strip("()").lower() not in TREE_OPTIONS:
        return wrong(f"give one of the letters {', '.join(TREE_OPTIONS)} as a string; you gave {quote(answer)}.")
    letter = answer.strip().strip("()").lower()
    if _same(_tree_result(p, letter), p["result"], 1e-12):
        if p == _STORED_TREE:
            return correct(f"({letter}) {TREE_OPTIONS[letter]}: A ∪ B covers one interval, and subtracting C cuts the "
                           "gap out of it; the tree is evaluated bottom up, one interval combination per node.")
        return correct(f"({letter}) {TREE_OPTIONS[letter]}: the tree is evaluated bottom up, one interval "
                       "combination per node.")
    if p == _STORED_TREE:
        why = {
            "a": "A ∪ (B − C) subtracts C from B only, so the part of A inside C survives and the gap is too short",
            "b": "(A − C) ∪ B subtracts C from A only; B then fills C's interval back in, so the result has no gap",
            "d": "(A ∩ B) ∪ C keeps only the overlap of A and B and adds C: it starts where B starts, not where A does",
            "c": "",
        }[letter]
        return wrong(why + ".")
    got = _tree_result(p, letter)
    return wrong(f"({letter}) {TREE_OPTIONS[letter]} gives {_iv_text(got) or 'nothing'} along the ray, not the solid "
                 "drawn: evaluate each tree bottom up, one combination per node.")


# -- §20.3 ---------------------------------------------------------------------------------------------

def _prism_counts(p):
    n = p["n"]
    return 2 * n, 3 * n, n + 2


def _prism_slips(p) -> dict:
    n = p["n"]
    V, E, F = _prism_counts(p)
    return {"edges twice": [V, 2 * E, F], "no caps": [V, E, n], "pyramid": [n + 1, 2 * n, n + 1]}


def _prism_statement(p) -> str:
    return (f"Count the vertices, edges and faces of a prism over a regular {p['n']}-gon (a {_ADJECTIVE[p['n']]} prism) "
            "and check Euler's formula V - E + F = 2. Give [V, E, F] (Goldman §20.3).")


def _prism_steps(p) -> str:
    n = p["n"]
    V, E, F = _prism_counts(p)
    return (f"1. V: two {_NOUN[n]}s of {n} vertices, {V}.\n"
            f"2. E: {n} edges on each {_NOUN[n]} and {n} vertical ones, {E} (or: each of the {F} faces' edges, "
            f"{2 * E} in all, counts every edge twice).\n"
            f"3. F: {n} rectangles and the two caps, {F}.  V - E + F = {V - E + F}.")


@DECK.exercise(stored={"n": PRISM_SIDES}, generate=lambda rng: {"n": int(rng.choice(list(_ADJECTIVE)))},
               answer=lambda p: list(_prism_counts(p)), slips=_prism_slips, statement=_prism_statement,
               steps=_prism_steps, same=lambda a, b: list(a) == list(b))
def check_euler_counts(answer, p) -> Result:
    """Check [V, E, F] of the statement's prism (Goldman §20.3).

    Recognises edges counted once per face (each edge lies in two faces), the caps left out, and the
    counts of the polygon's pyramid.
    """
    got, err = read_points(answer, "your counts", ask="[V, E, F]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"give three counts [V, E, F]; yours has shape {got.shape}.")
    n = p["n"]
    V, E, F = _prism_counts(p)
    if np.array_equal(got, [V, E, F]):
        return correct(f"V = {V}, E = {E}, F = {F}: V - E + F = {V - E + F}, Euler's formula for a simple "
                       "polyhedron.")
    if np.array_equal(got, [V, 2 * E, F]):
        return wrong("you counted each edge once for every face it lies in: in a closed polyhedron every edge "
                     "lies in exactly two faces, so halve the sum over the faces.")
    if np.array_equal(got, [V, E, n]):
        return wrong("you left out the two caps (top and bottom faces); with them V - E + F = 2.")
    if np.array_equal(got, [n + 1, 2 * n, n + 1]):
        return wrong(f"those are the counts of a pyramid over the {_NOUN[n]}; a prism has two {_NOUN[n]}s joined by "
                     "rectangles.")
    if np.abs(got).max() > 1e6:
        return wrong(f"a {_ADJECTIVE[n]} prism has a few vertices, edges and faces, not millions; count them.")
    chi = int(got[0] - got[1] + got[2])
    if chi != 2:
        return wrong(f"your counts give V - E + F = {chi}, but a prism is a simple polyhedron (Euler: 2). Count "
                     f"the top and bottom {_NOUN[n]}s' vertices, their edges plus the vertical ones, and the faces.")
    return wrong(f"your counts satisfy Euler's formula but are not the prism's: count the vertices of the two "
                 f"{_NOUN[n]}s, the edges of both {_NOUN[n]}s and the vertical edges, and the rectangles plus two caps.")


def _genus_parts(p):
    c = p["counts"]
    chi = c["V"] - c["E"] + c["F"] - (c["L"] - c["F"])
    return c, chi, c["S"] - chi // 2


def _genus_slips(p) -> dict:
    c, chi, _ = _genus_parts(p)
    return {"no rings": c["S"] - (c["V"] - c["E"] + c["F"]) // 2, "not halved": c["S"] - chi,
            "sign": chi // 2 - c["S"]}


def _genus_generate(rng) -> dict:
    h, k = int(rng.integers(2, 7)), int(rng.choice([3, 4, 5, 6]))
    return {"holes": h, "shape": _NOUN[k] if k != 4 else "square", "sides": k,
            "counts": {"V": 8 + 2 * k * h, "E": 12 + 3 * k * h, "F": 6 + k * h, "L": 6 + k * h + 2 * h, "S": 1}}


def _genus_statement(p) -> str:
    c, h = p["counts"], p["holes"]
    shape = {"square": "square", "triangle": "triangular", "pentagon": "pentagonal", "hexagon": "hexagonal"}[p["shape"]]
    return (f"A block with {_WORD[h]} {shape} holes drilled through it has V = {c['V']} vertices, "
            f"E = {c['E']} edges, F = {c['F']} faces, L = {c['L']} loops (its top and "
            f"bottom faces each have {_WORD[h]} rings) and S = {c['S']} shell. What is its genus G by the "
            "Euler-Poincare formula (Goldman §20.3)?")


def _genus_steps(p) -> str:
    c, chi, G = _genus_parts(p)
    return (f"1. V - E + F - (L - F) = {c['V']} - {c['E']} + {c['F']} - ({c['L']} - {c['F']}) = {chi}.\n"
            f"2. The formula sets it to 2(S - G) = 2({c['S']} - G), so S - G = {chi // 2} and G = {G}: one handle "
            f"per hole.")


@DECK.exercise(stored={"holes": 2, "shape": "square", "sides": 4, "counts": dict(HOLES_COUNTS)},
               generate=_genus_generate, answer=lambda p: _genus_parts(p)[2], slips=_genus_slips,
               statement=_genus_statement, steps=_genus_steps, same=lambda a, b: a == b)
def check_genus(answer, p) -> Result:
    """Check the genus of the block with holes, from V - E + F - (L - F) = 2(S - G) (Goldman §20.3).

    Recognises the rings left out, the factor 2 forgotten, and the sign of the genus reversed.
    """
    value, err = read_number(answer, "your genus")
    if err is not None:
        return err
    c, chi, G = _genus_parts(p)
    if value == G:
        return correct(f"V - E + F - (L - F) = {chi} = 2(S - G) gives G = {G}: one handle per hole drilled "
                       "through the block.")
    chi0 = c["V"] - c["E"] + c["F"]
    if value == c["S"] - chi0 // 2:
        return wrong(f"{fmt(value)} is V - E + F read as twice (S - G) without the rings: the top and bottom faces each "
                     f"have {_WORD[p['holes']]} inner loops, so L - F = {c['L'] - c['F']} must be subtracted first (the "
                     "Euler-Poincare formula V - E + F - (L - F) = twice (S - G)).")
    if value == c["S"] - chi:
        return wrong("you set V - E + F - (L - F) equal to S - G: the formula has twice (S - G) on the right; halve it.")
    if value == chi // 2 - c["S"]:
        return wrong("the sign is reversed: twice (S - G) is V - E + F - (L - F), so G is S minus half of V - E + F - (L - F), "
                     "and a genus is never negative.")
    if value < 0 or value != int(value):
        return wrong("a genus counts handles: a whole number >= 0. Use G = S minus half of V - E + F - (L - F).")
    return wrong(f"your genus is {off_by(value, G)}. Use G = S minus half of V - E + F - (L - F), with the counts given.")


#: convex base polygons with whole coordinates, counterclockwise seen from above
_BASES = {3: ((0.0, 0.0), (3.0, 0.0), (0.0, 3.0)), 4: ((0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)),
          5: ((0.0, 0.0), (2.0, 0.0), (3.0, 2.0), (1.0, 3.0), (-1.0, 2.0)),
          6: ((1.0, 0.0), (3.0, 0.0), (4.0, 2.0), (3.0, 4.0), (1.0, 4.0), (0.0, 2.0))}


def _pyramid_bad(p):
    faces = [list(f) for f in p["faces"]]
    brep = sm.BRep(p["vertices"], faces)
    bad_edges = [q for q in brep.problems() if "opposite directions" in q]
    flipped = [f for f in range(len(faces))
               if all(any(f"face {f}" in q and f"({min(a, b)}, {max(a, b)})" in q for q in bad_edges)
                      for a, b in zip(faces[f], faces[f][1:] + faces[f][:1]))]
    return bad_edges, flipped


def _pyramid_answer(p) -> int:
    return _pyramid_bad(p)[1][0]


def _pyramid_slips(p) -> dict:
    bad, flipped = _pyramid_bad(p)      # (every neighbour gets the same message: one stands for them)
    return {"a neighbour": next(k for k in range(len(p["faces"])) if k != flipped[0] and any(f"face {k}" in q for q in bad))}


def _pyramid_generate(rng) -> dict:
    n = int(rng.choice(list(_BASES)))
    base = np.array(_BASES[n])
    base = np.roll(base, int(rng.integers(0, n)), axis=0) + rng.integers(-1, 2, size=2)
    apex = np.r_[np.round(base.mean(0)), float(rng.integers(1, 4))]
    vertices = [(float(x), float(y), 0.0) for x, y in base] + [tuple(float(v) for v in apex)]
    faces = [tuple(int(i) for i in np.roll(np.arange(n)[::-1], int(rng.integers(0, n))))]
    faces += [(i, (i + 1) % n, n) for i in range(n)]
    flip = int(rng.integers(0, n + 1))
    faces[flip] = faces[flip][::-1]
    order = rng.permutation(n + 1)
    faces = [tuple(int(v) for v in np.roll(faces[k], int(rng.integers(0, len(faces[k]))))) for k in order]
    return {"vertices": tuple(vertices), "faces": tuple(faces)}


def _pyramid_ok(p):
    bad, flipped = _pyramid_bad(p)
    if len(flipped) != 1:
        return "not exactly one face is inside out"
    return None


def _pyramid_statement(p) -> str:
    n = len(p["vertices"]) - 1
    return (f"A {_ADJECTIVE[n]} pyramid has vertices {', '.join(str(v) for v in p['vertices'])} (0-{n - 1} the base, "
            f"{n} the apex) and faces {', '.join(f'{k}: {list(f)}' for k, f in enumerate(p['faces']))}. One face is "
            "listed inside out (clockwise seen from outside). Which one? Give its index (Goldman §20.3: a shared edge "
            "must be traversed in opposite directions by its two faces).")


def _pyramid_steps(p) -> str:
    bad, flipped = _pyramid_bad(p)
    lines = "\n".join(f"   {q}" for q in bad)
    return ("1. List each face's directed edges (a → b, the last back to the first) and look for the reverse b → a "
            "in the face across the edge. BRep.problems() reports the edges run the same way twice:\n"
            f"{lines}\n2. Face {flipped[0]} is in every report: all its edges disagree with its neighbours', so it "
            "is the one inside out (each neighbour has only the one edge it shares with it).")


@DECK.exercise(stored={"vertices": PYRAMID_VERTICES, "faces": PYRAMID_FACES}, generate=_pyramid_generate,
               answer=_pyramid_answer, slips=_pyramid_slips, statement=_pyramid_statement, steps=_pyramid_steps,
               same=lambda a, b: a == b, well_posed=_pyramid_ok)
def check_flipped_face(answer, p) -> Result:
    """Check which face of the pyramid is inside out: the one that runs a shared edge the same way
    as its neighbour (Goldman §20.3).

    Recognises the faces that share an edge with the flipped face.
    """
    value, err = read_number(answer, "your face index", "face index")
    if err is not None:
        return err
    faces = p["faces"]
    if value != int(value) or not 0 <= value < len(faces):
        return wrong(f"give a face index from 0 to {len(faces) - 1}; you gave {quote(answer)}.")
    k = int(value)
    bad_edges, flipped = _pyramid_bad(p)
    if flipped and k == flipped[0]:
        fixed = [list(f) if i != k else list(f)[::-1] for i, f in enumerate(faces)]
        ok = sm.BRep(p["vertices"], fixed).is_valid()
        return correct(f"face {k}: each of its edges runs the same way as in its neighbour; reversing it makes the "
                       f"pyramid {'valid' if ok else 'consistent'} (every shared edge traversed once each way).")
    if any(f"face {k}" in q for q in bad_edges):
        return wrong(f"face {k} shares an edge with the flipped face, so that edge runs the same way in both; but "
                     f"face {k}'s other edges run opposite to their neighbours'. Find the face all of whose edges "
                     "disagree.")
    return wrong(f"face {k}'s edges all run opposite to its neighbours', as they should. For each edge (a, b) of "
                 "a face look for (b, a) in the face across it.")


# -- §20.4 ---------------------------------------------------------------------------------------------

_AXIS = {"x": 0, "y": 1, "z": 2}


def _octree(p, depth):
    ax, top = _AXIS[p["axis"]], p["top"]
    return sm.Octree.build(lambda P: P[:, ax] <= top, size=2.0, depth=depth)


def _octree_forms(p):
    depth, top = p["depth"], p["top"]
    c = _octree(p, depth).counts()
    exp = np.array([c["full"], c["partial"], c["empty"]])
    uniform = _octree(p, 1).counts()
    fine = 8 ** depth
    cells = (np.arange(2 ** depth) + 0.5) * 2 / 2 ** depth - 1
    lo, hi = cells - 1 / 2 ** depth, cells + 1 / 2 ** depth
    layers_full = int(np.sum(hi <= top)) * 4 ** depth
    layers_partial = int(np.sum((lo <= top) & (hi > top))) * 4 ** depth
    slips = {"uniform grid": np.array([layers_full, layers_partial, fine - layers_full - layers_partial]),
             "depth 1": np.array([uniform["full"], uniform["partial"], uniform["empty"]]),
             "last level only": np.array([exp[0] - uniform["full"], exp[1], exp[2] - uniform["empty"]]),
             "swapped": np.array([exp[0], exp[2], exp[1]])}
    return exp, slips, uniform


def _octree_generate(rng) -> dict:
    top = float(rng.choice([-0.9, -0.8, -0.7, -0.6, -0.4, -0.3, -0.2, -0.1, 0.1, 0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9]))
    return {"axis": "xyz"[int(rng.integers(0, 3))], "top": top, "depth": int(rng.choice([2, 3]))}


def _octree_statement(p) -> str:
    return (f"Build the octree of the half-space {p['axis']} <= {fmt(p['top'])} in the root cube [-1, 1]^3 to depth "
            f"{p['depth']}, classifying a cell full if its 8 corners and centre are all inside, empty if none is, "
            "partial otherwise, and splitting only partial cells. How many leaf cells are full, partial and empty? "
            "Give [full, partial, empty] (Goldman §20.4).")


def _octree_steps(p) -> str:
    lines = []
    for d in range(1, p["depth"] + 1):
        c = _octree(p, d).counts()
        lines.append(f"   to depth {d} (cells of edge {fmt(2 / 2 ** d)}): {c['full']} full, {c['partial']} partial, "
                     f"{c['empty']} empty leaves")
    return (f"1. The plane {p['axis']} = {fmt(p['top'])} cuts only the cells whose {p['axis']}-range contains it; "
            "cells wholly below are full, wholly above empty.\n"
            "2. Split only the partial cells, level by level (sm.Octree.build(...).counts()):\n" + "\n".join(lines)
            + f"\n3. Full leaves of every level count: the answer is the last line.")


@DECK.exercise(stored={"axis": "z", "top": SLAB_TOP, "depth": OCTREE_DEPTH}, generate=_octree_generate,
               answer=lambda p: _octree_forms(p)[0], slips=lambda p: _octree_forms(p)[1],
               statement=_octree_statement, steps=_octree_steps, same=lambda a, b: np.array_equal(a, b))
def check_octree_counts(answer, p) -> Result:
    """Check [full, partial, empty] leaves of the octree of the statement's half-space at its depth
    (Goldman §20.4).

    Recognises full cells split as well (a uniform grid), the tree stopped a level early, the
    depth-1 full (or empty) cells left out, and partial and empty swapped.
    """
    got, err = read_points(answer, "your counts", ask="[full, partial, empty]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"give three counts [full, partial, empty]; yours has shape {got.shape}.")
    depth, top = p["depth"], p["top"]
    tree = _octree(p, depth)
    exp, s, uniform = _octree_forms(p)
    if np.array_equal(got, exp):
        return correct(f"{exp[0]} full, {exp[1]} partial, {exp[2]} empty leaves; the full cells' volume "
                       f"{fmt(tree.volume(0.0))} and full + partial {fmt(tree.volume(1.0))} bracket the true "
                       f"{fmt(4 * (1 + top))}.")
    if np.array_equal(got, s["uniform grid"]):
        return wrong(f"you split every cell down to depth {depth} (a uniform grid of {8 ** depth} cells): an "
                     "octree splits only partial cells, so a full octant at depth 1 stays one leaf.")
    if np.array_equal(got, s["depth 1"]):
        return wrong(f"you stopped at depth 1: the partial octants are split once more (depth {depth}).")
    if np.array_equal(got, s["last level only"]):
        which = "full" if uniform["empty"] == 0 else "empty" if uniform["full"] == 0 else "full and empty"
        return wrong(f"you counted only the cells of the last level: the {which} octants of depth 1 are leaves too.")
    if np.array_equal(got, s["swapped"]):
        return wrong("partial and empty are swapped: a cell with some samples inside and some outside is partial.")
    return wrong(f"{int(got.sum())} leaves in all; classify the 8 octants first (which lie wholly below "
                 f"{p['axis']} = {fmt(top)}?), then split only the partial ones into 8 and classify again.")


#: Deal another instance of an exercise (``deal("check_genus")``, or with ``seed=``; 0 is the stored
#: one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


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
