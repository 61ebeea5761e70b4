"""Exercise checkers for chapter 25, Bezier subdivision (Goldman §25.2-25.5), and the checker of its
programming project (de Casteljau subdivision of a curve at t).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0
is the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the
current instance.  The "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) and the
programming project (already run on generated cases) do not deal.  ``SLIPS`` holds the wrong answers
of the kinds each checker recognises, for the stored instance.  The data differ from the chapter's
worked examples (its cubic (0, 0), (1, 2.5), (3, 2.5), (4, 0.5), the quartic WAVY and the patches of
§25.3) and from chapter 24's exercises (the one drill of smooth joins lives there).

>>> print(PROBLEMS["check_piece_parameter"])
A cubic C is subdivided at t = 0.4, and the right piece R is parametrised over [0, 1] again. The point C(0.7) lies on R: at which parameter s of R (Goldman §25.2)?
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, off_by, read_number, read_points,
                                   wrong)
from goldman_lib.exercises.deal import Deck, integers as _ints, plain as _tup, steps_number as _f, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "SUBDIVIDE_CTRL", "SUBDIVIDE_T", "PIECE_SPLIT_T", "PIECE_T", "FLATNESS_CTRL",
           "PATCH_NET", "PATCH_V", "BOX_A", "BOX_B", "CROSSING_CTRL", "CROSSING_LINE_Y", "ORDER_P", "ORDER_R",
           "check_subdivision_right", "check_piece_parameter", "check_flatness", "check_patch_split",
           "check_box_pairs", "check_crossing_bound", "check_join_order", "DECK", "deal", "steps", "current",
           "deal_button",
           "subdivision_project_cases", "check_subdivision_project"]

#: Exercise 1 (§25.2): the cubic split at t = 3/4; the right piece is asked for.
SUBDIVIDE_CTRL = np.array([[0.0, 4.0], [4.0, 8.0], [8.0, 0.0], [12.0, 4.0]])
SUBDIVIDE_T = 0.75
#: Exercise 2 (§25.2): split at PIECE_SPLIT_T; the original parameter PIECE_T lies on the right piece.
PIECE_SPLIT_T, PIECE_T = 0.4, 0.7
#: Exercise 3 (§25.3): a bent cubic whose flatness bound is asked for.
FLATNESS_CTRL = np.array([[0.0, 0.0], [3.0, 1.0], [3.0, -2.0], [6.0, 0.0]])
#: Exercise 4 (§25.3.2): a patch of degree (1, 2) (row index i with u, column index j with v),
#: split at v = PATCH_V.
PATCH_NET = np.array([[[0.0, 0.0, 0.0], [0.0, 2.0, 4.0], [0.0, 4.0, 0.0]],
                      [[4.0, 0.0, 0.0], [4.0, 2.0, 2.0], [4.0, 4.0, 2.0]]])
PATCH_V = 0.5
#: Exercise 5 (§25.3.1): a parabola and a segment, each halved once for the bounding-box test.
BOX_A = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0]])
BOX_B = np.array([[0.5, 1.5], [4.5, 1.5]])
#: Exercise 6 (§25.4): a quartic and the horizontal line y = CROSSING_LINE_Y.
CROSSING_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [3.0, 1.0], [4.0, 2.0]])
CROSSING_LINE_Y = 0.5
#: Exercise 7 (§25.5): two cubics over parameter intervals of equal length; the order of the join.
ORDER_P = np.array([[0.0, 0.0], [2.0, 2.0], [4.0, 2.0], [6.0, 0.0]])
ORDER_R = np.array([[6.0, 0.0], [8.0, -2.0], [10.0, -6.0], [11.0, -8.0]])


DECK = Deck("ch25")


def _net_text(net) -> str:
    return "; ".join(f"row {i}: " + fmt_points(row) for i, row in enumerate(net))


def _arr(x):
    return np.asarray(x, dtype=float)


def _apart(forms, tol=1e-3) -> bool:
    """Whether the forms a checker recognises (arrays) are pairwise apart by more than ``tol`` in
    some coordinate (forms of different shapes are apart), so that each gets its own message."""
    forms = [_arr(f) for f in forms]
    return not any(u.shape == v.shape and np.all(np.abs(u - v) <= tol)
                   for i, u in enumerate(forms) for v in forms[i + 1:])


def _same_count(a, b) -> bool:
    return a == b


# -- §25.2: the right piece -------------------------------------------------------------------------------

_STORED_RIGHT = {"ctrl": _tup(SUBDIVIDE_CTRL), "t": SUBDIVIDE_T}


def _right_answer(p):
    return bezier.subdivide(_arr(p["ctrl"]), p["t"])[1]


def _right_slips(p):
    P, t = _arr(p["ctrl"]), p["t"]
    left, right = bezier.subdivide(P, t)
    return {"reversed": right[::-1], "the left piece": left, "split at 1 - t": bezier.subdivide(P, 1 - t)[1]}


def _right_generate(rng) -> dict:
    return {"ctrl": _ints(rng, 0, 12, (4, 2)), "t": float(rng.choice([0.25, 0.75]))}


def _right_ok(p):
    P, t = _arr(p["ctrl"]), p["t"]
    left, right = bezier.subdivide(P, t)
    other = bezier.subdivide(P, 1 - t)[1]
    forms = [right, right[::-1], left, left[::-1], other, other[::-1]]
    if not _apart(forms):
        return "two polygons the checker recognises coincide"
    if np.any(np.abs(right - (1 - t)) < 1e-9):
        return "a coordinate of the answer is 1 - t, which the message of the split at 1 - t names"
    level1 = bezier.de_casteljau_steps(P, t)[1]
    if any(np.allclose(f[:3], level1, atol=1e-3) or np.allclose(f[1:], level1, atol=1e-3) for f in forms):
        return "a recognised polygon contains the first level of the pyramid"
    return None


def _right_statement(p) -> str:
    t = p["t"]
    return (f"Subdivide the cubic with control points {fmt_points(_arr(p['ctrl']))} at t = {fmt(t)} by the de "
            f"Casteljau algorithm: give the four control points of the right piece, the curve over [{fmt(t)}, 1], "
            f"in order from C({fmt(t)}) to C(1) (Goldman §25.2).")


def _right_steps(p) -> str:
    t = p["t"]
    levels = bezier.de_casteljau_steps(_arr(p["ctrl"]), t)
    lines = [f"Each new point is (1 - t) P_j + t P_(j+1) = {fmt(1 - t)} P_j + {fmt(t)} P_(j+1)."]
    lines += [f"{r}. Level {r}: " + ", ".join(_f(q) for q in level) for r, level in enumerate(levels)]
    lines.append("The right piece is the LAST point of every level, from the apex up: "
                 + ", ".join(_f(q) for q in _right_answer(p)) + ".")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_RIGHT, generate=_right_generate, answer=_right_answer, slips=_right_slips,
               statement=_right_statement, steps=_right_steps, same=within(1e-3), well_posed=_right_ok)
def check_subdivision_right(answer, p) -> Result:
    """Check the right piece of the statement's cubic split at its t (Goldman §25.2).

    answer: (4, 2).  Recognises the right piece in reverse order (read down the right edge), the
    left piece, the split at 1 - t (t and 1 - t exchanged) and the first level of the pyramid.
    """
    what = "the right piece's control points"
    got, err = read_points(answer, what, ask="the right piece's four control points as [[x0, y0], ..., [x3, y3]]")
    if err is not None:
        return err
    P, t = _arr(p["ctrl"]), p["t"]
    left, right = bezier.subdivide(P, t)
    if got.shape != right.shape:
        return wrong(f"{what} should be four points [x, y] (a piece of a cubic is a cubic); your answer has "
                     f"{len(got) if got.ndim else 'one'} entries.")
    if np.allclose(got, right, atol=1e-4):
        return correct("the right piece is the right edge of the de Casteljau pyramid, read from the apex C(t) up to P3.")
    if np.allclose(got, right[::-1], atol=1e-4):
        return wrong("these are the right points in reverse order: the right piece starts at the apex C(t) and ends "
                     "at P3 = C(1).")
    if np.allclose(got, left, atol=1e-4) or np.allclose(got, left[::-1], atol=1e-4):
        return wrong("that is the left piece (the curve over [0, t]), the left edge of the pyramid; the right piece "
                     "is its right edge, the LAST point of every level.")
    swapped = bezier.subdivide(P, 1 - t)[1]
    if np.allclose(got, swapped, atol=1e-4) or np.allclose(got, swapped[::-1], atol=1e-4):
        return wrong(f"that is the split at t = {fmt(1 - t)}: each level takes (1-t) P_j + t P_(j+1), a fraction t of "
                     f"the way from P_j to P_(j+1), not a fraction 1 - t.")
    level1 = bezier.de_casteljau_steps(P, t)[1]
    if np.allclose(got[:3], level1, atol=1e-4) or np.allclose(got[1:], level1, atol=1e-4):
        return wrong("you took the points of level 1 of the pyramid; the right piece takes the LAST point of every "
                     "level, from the apex up to P3.")
    return check_points(got, right, what=what, tol=1e-4,
                        hint="the k-th point is the last point of level 3 - k of the pyramid")


# -- §25.2: the parameter on a piece ------------------------------------------------------------------------

_STORED_PIECE = {"t0": PIECE_SPLIT_T, "t": PIECE_T}


def _piece_answer(p):
    return (p["t"] - p["t0"]) / (1 - p["t0"])


def _piece_slips(p):
    t0, t = p["t0"], p["t"]
    return {"not rescaled": t - t0, "left piece's length": (t - t0) / t0, "forward map": t0 + (1 - t0) * t,
            "left piece's formula": t / t0}


def _piece_generate(rng) -> dict:
    t0 = float(rng.choice([0.2, 0.25, 0.4, 0.5, 0.6]))
    return {"t0": t0, "t": float(rng.choice([t for t in (0.5, 0.6, 0.7, 0.75, 0.8, 0.9) if t > t0]))}


def _piece_statement(p) -> str:
    return (f"A cubic C is subdivided at t = {fmt(p['t0'])}, and the right piece R is parametrised over [0, 1] "
            f"again. The point C({fmt(p['t'])}) lies on R: at which parameter s of R (Goldman §25.2)?")


def _piece_steps(p) -> str:
    t0, t = p["t0"], p["t"]
    return (f"1. R(s) = C(t0 + (1 - t0) s) stretches [0, 1] over [{fmt(t0)}, 1], an interval of length {fmt(1 - t0)}.\n"
            f"2. Solve {fmt(t)} = {fmt(t0)} + {fmt(1 - t0)} s: s = ({fmt(t)} - {fmt(t0)})/{fmt(1 - t0)} = "
            f"{_f(_piece_answer(p))}.")


@DECK.exercise(stored=_STORED_PIECE, generate=_piece_generate, answer=_piece_answer, slips=_piece_slips,
               statement=_piece_statement, steps=_piece_steps, same=within(1e-3))
def check_piece_parameter(answer, p) -> Result:
    """Check the parameter s on the right piece of the statement's split that gives its point C(t) (Goldman §25.2).

    Recognises the shift without the division by the piece's length, the division by the left
    piece's length, the forward map t + (1 - t) s applied instead of its inverse, and the left
    piece's formula t / split.

    >>> check_piece_parameter(0.3)
    Not yet: you shifted by the split parameter but did not rescale: R(s) = C(t0 + (1 - t0) s) stretches [0, 1] over an interval of length 1 - t0, so divide by it.
    """
    t0, t = p["t0"], p["t"]
    expected = (t - t0) / (1 - t0)
    value, err = read_number(answer, "the parameter s")
    if err is not None:
        return err
    if abs(value - expected) <= 1e-4:
        return correct(f"C({fmt(t)}) is R({fmt(expected)}).")
    if abs(value - (t - t0)) <= 1e-4:
        return wrong("you shifted by the split parameter but did not rescale: R(s) = C(t0 + (1 - t0) s) stretches "
                     "[0, 1] over an interval of length 1 - t0, so divide by it.")
    if abs(value - (t - t0) / t0) <= 1e-4:
        return wrong("you divided by the length of the LEFT piece's interval [0, t0]; R covers [t0, 1], whose length "
                     "is 1 - t0.")
    if abs(value - (t0 + (1 - t0) * t)) <= 1e-4:
        return wrong("you applied the map s -> t0 + (1 - t0) s to the original parameter; here the original parameter "
                     "is given, so solve t = t0 + (1 - t0) s for s.")
    if abs(value - t / t0) <= 1e-4:
        return wrong("t / t0 is the parameter of the LEFT piece, which covers [0, t0]; the point lies beyond the "
                     "split, on the right piece.")
    return wrong(f"s is {off_by(value, expected)}. Solve t = t0 + (1 - t0) s for s.")


# -- §25.3: flatness --------------------------------------------------------------------------------------

_STORED_FLATNESS = {"ctrl": _tup(FLATNESS_CTRL)}


def _chord_distances(P):
    n = len(P) - 1
    w = (np.arange(n + 1) / n)[:, None]
    return np.linalg.norm(P - ((1 - w) * P[0] + w * P[-1]), axis=1)


def _flatness_answer(p):
    return float(bezier.flatness(_arr(p["ctrl"])))


def _flatness_slips(p):
    P = _arr(p["ctrl"])
    inner = _chord_distances(P)[1:-1]
    return {"the chord line": float(bezier.flatness(P, even=False)), "the smaller": float(inner.min()),
            "the sum": float(inner.sum())}


def _flatness_generate(rng) -> dict:
    return {"ctrl": _ints(rng, -3, 6, (4, 2))}


def _flatness_ok(p):
    P = _arr(p["ctrl"])
    if np.linalg.norm(P[-1] - P[0]) < 2:
        return "the chord is too short (P0 and P3 too close)"
    return None


def _flatness_statement(p) -> str:
    return (f"What is the flatness max_k |P_k - ((1 - k/n) P_0 + (k/n) P_n)| of the cubic with control points "
            f"{fmt_points(_arr(p['ctrl']))}, the bound on its distance from its chord that decides whether to subdivide "
            f"further (Goldman §25.3)? Four decimals are enough.")


def _flatness_steps(p) -> str:
    P = _arr(p["ctrl"])
    w = (np.arange(4) / 3)[:, None]
    L = (1 - w) * P[0] + w * P[-1]
    d = _chord_distances(P)
    return (f"1. The evenly spaced chord points L_k = (1 - k/3) P0 + (k/3) P3: L1 = {_f(L[1])}, L2 = {_f(L[2])}.\n"
            f"2. |P1 - L1| = {_f(d[1])}, |P2 - L2| = {_f(d[2])}.\n"
            f"3. The flatness is the larger: {_f(_flatness_answer(p))}.")


@DECK.exercise(stored=_STORED_FLATNESS, generate=_flatness_generate, answer=_flatness_answer, slips=_flatness_slips,
               statement=_flatness_statement, steps=_flatness_steps, same=within(3e-3), well_posed=_flatness_ok)
def check_flatness(answer, p) -> Result:
    """Check the flatness (even spacing) of the statement's cubic (Goldman §25.3).  Tolerance 1e-3.

    Recognises the distance to the chord line (not to the evenly spaced chord points), the
    smaller of the two distances (max vs min) and the sum of the distances.

    >>> check_flatness(2)
    Not yet: that is the largest distance of a control point from the chord LINE; the flatness compares P_k with the evenly spaced chord points L_k = (1 - k/n) P0 + (k/n) Pn, which also measures the uneven spacing along the chord.
    """
    P = _arr(p["ctrl"])
    expected = bezier.flatness(P)
    value, err = read_number(answer, "the flatness")
    if err is not None:
        return err
    dist = _chord_distances(P)
    if abs(value - expected) <= 1e-3:
        k = int(np.argmax(dist))
        return correct(f"the flatness is {fmt(expected)}, the distance of P{k} from the chord point L{k}.")
    if abs(value - bezier.flatness(P, even=False)) <= 1e-3:
        return wrong("that is the largest distance of a control point from the chord LINE; the flatness compares P_k "
                     "with the evenly spaced chord points L_k = (1 - k/n) P0 + (k/n) Pn, which also measures the "
                     "uneven spacing along the chord.")
    inner = dist[1:-1]
    if abs(value - inner.min()) <= 1e-3:
        return wrong("that is the SMALLER of the two distances |P1 - L1| and |P2 - L2|; the bound is the largest.")
    if abs(value - inner.sum()) <= 1e-3:
        return wrong("you added the distances; the bound is the largest of them (every C(t) - chord(t) is a convex "
                     "combination of the P_k - L_k).")
    return wrong(f"the flatness is {off_by(value, expected)}. Compute L_k = (1 - k/3) P0 + (k/3) P3 and take the largest "
                 f"|P_k - L_k|.")


# -- §25.3.2: splitting a patch ---------------------------------------------------------------------------

_STORED_PATCH = {"net": _tup(PATCH_NET), "v": PATCH_V}


def _patch_pieces(p):
    net, v = _arr(p["net"]), p["v"]
    pieces = bezier.subdivide_patch(net, 1.0, v)            # u = 1 leaves the u-direction whole
    return pieces[0, 0], pieces[0, 1], bezier.subdivide_patch(net, v, 1.0)[0, 0]


def _patch_answer(p):
    return _patch_pieces(p)[0]


def _patch_slips(p):
    lo, hi, col = _patch_pieces(p)
    return {"the other piece": hi, "rows reversed": lo[:, ::-1], "split in u": col}


def _patch_generate(rng) -> dict:
    z = rng.integers(0, 5, size=(2, 3))
    net = [[[4.0 * i, 2.0 * j, float(z[i, j])] for j in range(3)] for i in range(2)]
    return {"net": _tup(net), "v": float(rng.choice([0.25, 0.5, 0.75]))}


def _patch_ok(p):
    lo, hi, col = _patch_pieces(p)
    if not _apart([lo, hi, hi[:, ::-1], lo[:, ::-1], col]):
        return "two nets the checker recognises coincide"
    return None


def _patch_statement(p) -> str:
    v = p["v"]
    return (f"The patch P(u, v) = sum_i sum_j B_i^1(u) B_j^2(v) P_ij has the control net {_net_text(_arr(p['net']))} "
            f"(the row index i goes with u, the column index j with v). Subdivide it at v = {fmt(v)} and give the "
            f"control net of the piece over 0 <= v <= {fmt(v)}, as two rows of three points [x, y, z] (Goldman §25.3.2).")


def _patch_steps(p) -> str:
    net, v = _arr(p["net"]), p["v"]
    lo = _patch_answer(p)
    lines = [f"Each row is a quadratic in v: run de Casteljau at v = {fmt(v)} and keep the FIRST point of every level."]
    for i, row in enumerate(net):
        levels = bezier.de_casteljau_steps(row, v)
        lines.append(f"{i + 1}. Row {i}: levels " + "; ".join(", ".join(_f(q) for q in lev) for lev in levels[1:])
                     + f" -> " + ", ".join(_f(q) for q in lo[i]) + ".")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_PATCH, generate=_patch_generate, answer=_patch_answer, slips=_patch_slips,
               statement=_patch_statement, steps=_patch_steps, same=within(1e-3), well_posed=_patch_ok)
def check_patch_split(answer, p) -> Result:
    """Check the net of the statement's patch over 0 <= v <= its split parameter (Goldman §25.3.2).

    answer: (2, 3, 3).  Recognises the split taken in u (along the columns) instead of v, the
    other piece (v >= the split parameter), rows reversed, and a wrong shape.
    """
    what = "the sub-net"
    got, err = read_points(answer, what, ask="the sub-net as two rows of three points [x, y, z]")
    if err is not None:
        return err
    lo_v, hi_v, col_lo = _patch_pieces(p)
    v = p["v"]
    expected = lo_v
    if got.shape != expected.shape:
        return wrong(f"{what} should be two rows of three points [x, y, z], shape (2, 3, 3): subdividing in v keeps "
                     f"the degrees; your answer has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-4):
        return correct("the net matches: each row (a quadratic in v) is subdivided by de Casteljau, and the rows "
                       "stay rows.")
    if np.allclose(got, hi_v, atol=1e-4) or np.allclose(got, hi_v[:, ::-1], atol=1e-4):
        return wrong(f"that is the other piece, v >= {fmt(v)}: the piece over [0, v] keeps the first point of "
                     f"every level of each row's pyramid.")
    if np.allclose(got, lo_v[:, ::-1], atol=1e-4):
        return wrong("each row is in reverse order: the piece's row j = 0 point is the original P_i0, where v = 0.")
    if np.allclose(got, col_lo, atol=1e-4):
        return wrong("you split in u, along the columns: v goes with the column index j, so subdivide each ROW "
                     "(P_i0, P_i1, P_i2) as a quadratic in v.")
    bad = np.flatnonzero(np.abs(got - expected).reshape(-1, 3).max(axis=1) > 1e-4)
    k = int(bad[0])
    i, j = divmod(k, 3)
    return wrong(f"point [{i}][{j}] of {what} is {far_off(got[i, j], expected[i, j])} from where it should be ({bad.size} of 6 points are "
                 f"off). Hint: run de Casteljau at v on each row and keep the first point of every level.")


# -- §25.3.1: the bounding-box test -------------------------------------------------------------------------

_STORED_BOX = {"A": _tup(BOX_A), "B": _tup(BOX_B)}


def _box_overlaps(p):
    """The overlap margins of the control-point boxes of the 4 pairs of halves (>= 0: they overlap; a
    flat box, the segment's, overlaps another when its line lies within the other's range)."""
    margins = []
    for pa in bezier.subdivide(_arr(p["A"]), 0.5):
        for pb in bezier.subdivide(_arr(p["B"]), 0.5):
            # per axis, how far each range reaches into the other (< 0: apart by that much)
            reach = np.minimum(pa.max(axis=0) - pb.min(axis=0), pb.max(axis=0) - pa.min(axis=0))
            margins.append(float(reach.min()))
    return margins


def _box_pairs(p) -> tuple[int, int]:
    """(pairs whose control-point boxes overlap, actual crossings) after one split of each curve."""
    count = sum(m >= 0 for m in _box_overlaps(p))
    return count, len(bezier.intersect_curves(_arr(p["A"]), _arr(p["B"])))


def _box_answer(p):
    return _box_pairs(p)[0]


def _box_slips(p):
    return {"every pair": 4, "the crossings": _box_pairs(p)[1]}


def _box_generate(rng) -> dict:
    A = [[0.0, 0.0], [float(rng.integers(1, 4)), float(2 * rng.integers(1, 4))], [4.0, 0.0]]
    y = float(rng.choice([0.5, 1.0, 1.5, 2.0, 2.5]))
    x0 = float(rng.choice([-0.5, 0.5, 1.0, 1.5]))
    x1 = float(rng.choice([2.5, 3.0, 3.5, 4.5]))
    return {"A": _tup(A), "B": ((x0, y), (x1, y))}


def _box_ok(p):
    if min(abs(m) for m in _box_overlaps(p)) < 0.2:
        return "a pair of boxes nearly touches: the test would be read off too fine a margin"
    A, y = _arr(p["A"]), p["B"][0][1]
    if abs(A[1, 1] / 2 - y) < 0.3:
        return "the segment nearly touches the top of the parabola"
    if _box_pairs(p)[1] == 0:
        return "the curves do not cross"
    return None


def _box_statement(p) -> str:
    B = _arr(p["B"])
    return (f"Intersection by subdivision: the parabola with control points {fmt_points(_arr(p['A']))} and the segment "
            f"from {fmt(B[0])} to {fmt(B[1])} are each split once at t = 1/2, giving 4 pairs (half of the parabola, "
            f"half of the segment). How many pairs survive the test that the bounding boxes of their control points "
            f"overlap (Goldman §25.3.1)?")


def _box_steps(p) -> str:
    lines = ["Halve both curves at 1/2 (de Casteljau), and take the box [xmin, xmax] x [ymin, ymax] of each half's "
             "control points:"]
    names = ("parabola", "segment")
    boxes = []
    for name, key in zip(names, ("A", "B")):
        for h, half in enumerate(bezier.subdivide(_arr(p[key]), 0.5)):
            lo, hi = half.min(axis=0), half.max(axis=0)
            boxes.append((name, h, lo, hi))
            lines.append(f"- {name} half {h + 1}: x in [{_f(lo[0])}, {_f(hi[0])}], y in [{_f(lo[1])}, {_f(hi[1])}]")
    count = 0
    for (_, ha, la, ua) in boxes[:2]:
        for (_, hb, lb, ub) in boxes[2:]:
            ok = bool(np.all(np.maximum(la, lb) <= np.minimum(ua, ub)))
            count += ok
            lines.append(f"- parabola half {ha + 1} with segment half {hb + 1}: {'overlap' if ok else 'apart'}")
    lines.append(f"So {count} of the 4 pairs survive.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_BOX, generate=_box_generate, answer=_box_answer, slips=_box_slips,
               statement=_box_statement, steps=_box_steps, same=_same_count, well_posed=_box_ok)
def check_box_pairs(answer, p) -> Result:
    """Check how many of the four pairs of halves of the statement's parabola and segment keep overlapping
    boxes (Goldman §25.3.1).

    Recognises 4 (every pair kept), the number of actual intersections, and 1 (only the pairs
    that really meet counted, or one half of each curve).

    >>> check_box_pairs(4)
    Not yet: not every pair survives: compare the x-ranges of the control points of each half of the parabola with those of each half of the segment.
    """
    expected, crossings = _box_pairs(p)
    value, err = read_number(answer, "the number of pairs", "whole number")
    if err is not None:
        return err
    if value == expected:
        return correct(f"{expected} of the 4 pairs keep overlapping boxes; the curve pieces of some pairs need not "
                       f"meet at all, and further splitting discards them."
                       if p != _STORED_BOX else
                       f"{expected} of the 4 pairs keep overlapping boxes; the curve pieces of one of them do not meet "
                       f"at all, and further splitting discards it.")
    if value == 4:
        return wrong("not every pair survives: compare the x-ranges of the control points of each half of the parabola "
                     "with those of each half of the segment.")
    if value == crossings:
        return wrong("that counts the intersections of the curves; the box test is coarser: it keeps every pair whose "
                     "boxes overlap, even when the pieces inside do not meet.")
    if value < 0 or value > 4 or value != int(value):
        return wrong("the answer is a whole number of pairs between 0 and 4.")
    return wrong("that is not the number of overlapping pairs: write down the box [xmin, xmax] x [ymin, ymax] of each "
                 "half's control points, then test the 4 pairs; two boxes overlap when both their x- and y-ranges do.")


# -- §25.4: variation diminishing ---------------------------------------------------------------------------

_STORED_CROSSING = {"ctrl": _tup(CROSSING_CTRL), "y": CROSSING_LINE_Y}


def _crossing_counts(p):
    P, y = _arr(p["ctrl"]), p["y"]
    return bezier.variation_count(P, [0.0, y], [0.0, 1.0]), bezier.curve_crossings(P, [0.0, y], [0.0, 1.0])


def _crossing_answer(p):
    return _crossing_counts(p)[0]


def _crossing_slips(p):
    n = len(p["ctrl"]) - 1
    return {"control points": n + 1, "the degree": n, "the curve's crossings": _crossing_counts(p)[1]}


def _crossing_generate(rng) -> dict:
    n = int(rng.integers(3, 6))
    ys = rng.integers(-2, 4, size=n + 1)
    return {"ctrl": _tup([[float(k), float(v)] for k, v in enumerate(ys)]), "y": float(rng.choice([-0.5, 0.5, 1.5]))}


def _crossing_ok(p):
    P, y = _arr(p["ctrl"]), p["y"]
    v = bezier.de_casteljau(P, np.linspace(0, 1, 4001))[:, 1] - y
    turns = (v[1:-1] - v[:-2]) * (v[2:] - v[1:-1]) <= 0          # where the curve's height turns
    if np.any(np.abs(v[1:-1][turns]) < 0.05):
        return "the curve nearly touches the line: its crossings could not be told by eye"
    return None


def _crossing_statement(p) -> str:
    return (f"At most how many times can the line y = {fmt(p['y'])} cross the Bezier curve with control "
            f"points {fmt_points(_arr(p['ctrl']))}? Give the bound the control polygon guarantees (Goldman §25.4).")


def _crossing_steps(p) -> str:
    P, y = _arr(p["ctrl"]), p["y"]
    d = P[:, 1] - y
    signs = ", ".join("+" if v > 0 else "-" for v in d)
    return (f"1. y - {fmt(y)} at the control points: {', '.join(fmt(v) for v in d)}; the signs {signs}.\n"
            f"2. The polygon crosses the line at each sign change: {_crossing_answer(p)}.\n"
            f"3. By the variation diminishing property the curve crosses it at most that many times "
            f"(here it does {_crossing_counts(p)[1]}).")


@DECK.exercise(stored=_STORED_CROSSING, generate=_crossing_generate, answer=_crossing_answer,
               slips=_crossing_slips, statement=_crossing_statement, steps=_crossing_steps, same=_same_count,
               well_posed=_crossing_ok)
def check_crossing_bound(answer, p) -> Result:
    """Check the variation-diminishing bound for the statement's curve and line (Goldman §25.4).

    Recognises the number of control points, the degree (the bound for any polynomial curve of
    that degree) and the number of times the curve itself crosses the line.

    >>> check_crossing_bound(5)
    Not yet: 5 is the number of control points; the bound is the number of times the POLYGON crosses the line: count the sign changes of y - 0.5 along P0, ..., P4.
    """
    P, y = _arr(p["ctrl"]), p["y"]
    expected, actual = _crossing_counts(p)
    value, err = read_number(answer, "the bound", "whole number")
    if err is not None:
        return err
    words = {1: "once", 2: "twice", 3: "three times"}
    if value == expected:
        return correct(f"the control polygon crosses y = {fmt(y)} {words.get(expected, f'{expected} times')}, so the "
                       f"curve crosses it at most {expected} times (here it does {words.get(actual, f'{actual} times')}).")
    n = len(P) - 1
    if value == n + 1:
        return wrong(f"{n + 1} is the number of control points; the bound is the number of times the POLYGON crosses "
                     f"the line: count the sign changes of y - {fmt(y)} along P0, ..., P{n}.")
    if value == n:
        return wrong(f"{n} is the degree, the bound for every curve of degree {n}; the variation diminishing property "
                     f"gives a sharper one for this curve: the number of crossings of its control polygon.")
    if value == actual:
        return wrong("that is how often the curve itself crosses the line (you may have plotted it); the question asks "
                     "for the bound read off the control polygon without drawing the curve, which may be larger.")
    return wrong(f"the bound is {off_by(value, expected)}: count how often consecutive control points lie on opposite "
                 f"sides of y = {fmt(y)}.")


# -- §25.5: the order of a join ---------------------------------------------------------------------------

_STORED_ORDER = {"P": _tup(ORDER_P), "R": _tup(ORDER_R)}


def _continuation(P):
    """The control points of P's own cubic continued over the next interval of equal length."""
    return bezier.smooth_continuation(P)


def _order_answer(p):
    return bezier.join_order(_arr(p["P"]), _arr(p["R"]))


def _order_slips(p):
    k = _order_answer(p)
    return {"the degree": 3, "one step off": 1 if k == 2 else 2, "no join": 0}


def _order_generate(rng) -> dict:
    P = rng.integers(-2, 7, size=(4, 2)).astype(float)
    Q = bezier.smooth_continuation(P)
    k = int(rng.choice([1, 2]))
    R = Q.copy()
    R[k + 1:] += rng.integers(-2, 3, size=(3 - k, 2))
    return {"P": _tup(P), "R": _tup(R)}


def _order_ok(p):
    if _order_answer(p) not in (1, 2):
        return "the join is not C1 or C2 (the changed points happened to agree)"
    return None


def _order_statement(p) -> str:
    return (f"The cubics P with control points {fmt_points(_arr(p['P']))} and R with control points "
            f"{fmt_points(_arr(p['R']))} run over parameter intervals of equal length. Give the largest k for which "
            f"they meet with C^k continuity, by comparing R with the control points of P's own polynomial continued "
            f"past its end (Goldman §25.5).")


def _order_steps(p) -> str:
    P, R = _arr(p["P"]), _arr(p["R"])
    Q = bezier.smooth_continuation(P)
    k = _order_answer(p)
    rows = [f"- Q{j} = {_f(Q[j])}, R{j} = {fmt(R[j])}: {'equal' if np.allclose(Q[j], R[j]) else 'different'}"
            for j in range(4)]
    return ("Continue P past its end (extrapolating subdivision): Q0 = P3, Q1 = 2 P3 - P2, Q2 = P1 - 4 P2 + 4 P3, "
            "Q3 = -P0 + 6 P1 - 12 P2 + 8 P3.\n\n" + "\n".join(rows)
            + f"\n\nR0, ..., R{k} agree with the continuation and R{k + 1} does not: the join is C{k}.")


@DECK.exercise(stored=_STORED_ORDER, generate=_order_generate, answer=_order_answer, slips=_order_slips,
               statement=_order_statement, steps=_order_steps, same=_same_count, well_posed=_order_ok)
def check_join_order(answer, p) -> Result:
    """Check the order of continuity of the join of the statement's cubics P and R (Goldman §25.5).

    Recognises the order found by comparing tangents only (1) or one point too many (2), the degree
    (3) and answers that deny the curves meet.

    >>> check_join_order(3)
    Not yet: C3 would need all four control points of R to be those of P's continuation, and then R would be P's own polynomial; compare R3 with -P0 + 6 P1 - 12 P2 + 8 P3.
    """
    expected = _order_answer(p)
    value, err = read_number(answer, "k", "whole number")
    if err is not None:
        return err
    if value == expected:
        agree = ", ".join(f"R{j}" for j in range(expected + 1))
        count = {2: "two", 3: "three"}[expected + 1]
        return correct(f"{agree} are the first {count} control points of P's continuation and R{expected + 1} is not, "
                       f"so the join is C{expected} but not C{expected + 1}.")
    if value == 3:
        return wrong("C3 would need all four control points of R to be those of P's continuation, and then R would be "
                     "P's own polynomial; compare R3 with -P0 + 6 P1 - 12 P2 + 8 P3.")
    if value == 1:
        return wrong("the tangents agree (R1 = 2 P3 - P2), but look one step further: compare R2 with "
                     "P1 - 4 P2 + 4 P3, the next control point of P's continuation.")
    if value == 2:
        return wrong("C2 needs R2 to be P1 - 4 P2 + 4 P3 as well, the third control point of P's continuation: "
                     "compute it and compare.")
    if value in (0, -1):
        return wrong("the curves do meet (R0 = P3) and more: continue P past its end by extrapolating subdivision and "
                     "count how many of R's control points agree with the continuation.")
    return wrong("k is a whole number between 0 and the degree 3: the join is C^k when R0, ..., Rk are the first "
                 "k + 1 control points of P's continuation.")


#: Deal another instance of an exercise (``deal("check_flatness")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_subdivision_right": [[[12, 4], [11, 3], [10, 2.75], [9, 2.875]], [[0, 4], [3, 7], [6, 3.25], [9, 2.875]],
                                [[3, 5.125], [6, 4.75], [9, 1], [12, 4]], [[9, 2.875], [10, 2.75], [11, 3]]],
    "check_piece_parameter": [0.3, 0.75, 0.82, 1.75],
    "check_flatness": [2.0, 2 ** 0.5, 2 ** 0.5 + 5 ** 0.5],
    "check_patch_split": [
        [[[0, 2, 2], [0, 3, 2], [0, 4, 0]], [[4, 2, 1.5], [4, 3, 2], [4, 4, 2]]],
        [[[0, 0, 0], [0, 2, 4], [0, 4, 0]], [[2, 0, 0], [2, 2, 3], [2, 4, 1]]],
        [[[0, 2, 2], [0, 1, 2], [0, 0, 0]], [[4, 2, 1.5], [4, 1, 1], [4, 0, 0]]],
    ],
    "check_box_pairs": [4, 2],
    "check_crossing_bound": [5, 4, 1],
    "check_join_order": [3, 1, 0],
}


# -- the programming project: de Casteljau subdivision ---------------------------------------------

_DEGREE_WORDS = {1: "segment", 2: "quadratic", 3: "cubic", 4: "quartic", 5: "quintic"}


def _label(P: np.ndarray, t: float) -> str:
    return f"the {len(P[0])}D {_DEGREE_WORDS.get(len(P) - 1, f'degree-{len(P) - 1} curve')} {fmt_points(P, 3)} at t = {fmt(t)}"


def subdivision_project_cases() -> list[Case]:
    """The cases of :func:`check_subdivision_project`: degrees 1 to 5 in 2D and 3D with random
    control points and parameters (a fixed seed), then degenerate ones: all control points equal,
    t = 0, t = 1, collinear unevenly spaced points, a repeated control point."""
    rng = np.random.default_rng(2025)
    cases = []
    for d in (2, 3):
        for n in range(1, 6):
            P = np.round(rng.uniform(-5, 5, size=(n + 1, d)), 2)
            t = float(np.round(rng.uniform(0.1, 0.9), 2))
            cases.append(Case(_label(P, t), (P, t), kind=f"random {d}D"))
    P = np.tile([1.5, -2.0], (4, 1))
    cases.append(Case(_label(P, 0.3), (P, 0.3), kind="all control points equal"))
    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]])
    cases.append(Case(_label(P, 0.0), (P, 0.0), kind="t = 0"))
    P = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 1.0], [3.0, 1.0, -1.0], [4.0, 0.0, 2.0], [5.0, 1.0, 0.0]])
    cases.append(Case(_label(P, 1.0), (P, 1.0), kind="t = 1"))
    P = np.array([[0.0, 0.0], [2.7, 0.9], [3.0, 1.0], [6.0, 2.0]])
    cases.append(Case(_label(P, 0.6), (P, 0.6), kind="collinear points"))
    P = np.array([[0.0, 0.0, 0.0], [2.0, 1.0, 0.0], [2.0, 1.0, 0.0], [4.0, 0.0, 3.0]])
    cases.append(Case(_label(P, 0.35), (P, 0.35), kind="a repeated control point"))
    return cases


def _compare_split(got, expected, case) -> str | None:
    P, t = case.args
    left, right = (np.asarray(x, dtype=float) for x in expected)
    if not isinstance(got, (tuple, list, np.ndarray)) or len(got) != 2:
        return "it should return two control polygons, (left, right)"
    try:
        gl, gr = (np.asarray(x, dtype=float) for x in got)
    except (TypeError, ValueError):
        return "the two polygons should be arrays of numbers"
    if gl.ndim != 2 or gr.ndim != 2:
        return ("it should return two control polygons, (left, right), each an (n+1, d) array of points; "
                "yours are not two arrays of points")
    for name, g, e in (("left", gl, left), ("right", gr, right)):
        if g.shape != e.shape:
            return (f"your {name} polygon has shape {g.shape}; it should have shape {e.shape}, as many points as "
                    f"the curve has control points")
        if not np.all(np.isfinite(g)):
            return f"your {name} polygon contains NaN or infinite values"
    tol = 1e-9 * max(1.0, float(np.abs(P).max()))
    if np.allclose(gl, left, atol=tol) and np.allclose(gr, right, atol=tol):
        return None
    if np.allclose(gl, left, atol=tol) and np.allclose(gr, right[::-1], atol=tol):
        return ("your right polygon is in reverse order: it should start at C(t), the apex of the pyramid, and end "
                "at the last control point")
    if np.allclose(gl, right, atol=tol) and np.allclose(gr, left, atol=tol):
        return "the two polygons are exchanged: the left one (the curve over [0, t]) starts at the first control point"
    other = bezier.subdivide(P, 1.0 - t)
    if np.allclose(gl, other[0], atol=tol) and np.allclose(gr, other[1], atol=tol):
        return (f"these are the polygons of the split at 1 - t = {fmt(1 - t)}: each level should take "
                f"(1 - t) P_j + t P_(j+1), a fraction t of the way from P_j to P_(j+1)")
    half = bezier.subdivide(P, 0.5)
    if abs(t - 0.5) > 1e-9 and np.allclose(gl, half[0], atol=tol) and np.allclose(gr, half[1], atol=tol):
        return (f"these are the polygons of the split at t = 1/2 (midpoints at every level); split at the t given, "
                f"t = {fmt(t)}")
    for name, g, e in (("left", gl, left), ("right", gr, right)):
        err = np.linalg.norm(g - e, axis=1)
        bad = np.flatnonzero(err > tol)
        if bad.size:
            k = int(bad[0])
            return (f"your {name} polygon's point {k} is {fmt(err[k], 2)} from where it should be, {fmt(e[k])} "
                    f"({bad.size} of {len(e)} points are off)")
    return None


def check_subdivision_project(function) -> Result:
    """Run the learner's ``function(ctrl, t) -> (left, right)`` on :func:`subdivision_project_cases` and
    compare with :func:`goldman_lib.bezier.subdivide` (Goldman §25.2).

    Says which case fails first and how: polygons of the wrong shape, the right polygon reversed,
    the two exchanged, t and 1 - t exchanged, or the first point that is off and by how much.

    >>> def exchanged(ctrl, t):
    ...     left, right = bezier.subdivide(ctrl, t)
    ...     return right, left
    >>> print(check_subdivision_project(exchanged).message)   # doctest: +ELLIPSIS
    case 1 of 15 (...): ...; the two polygons are exchanged: ... Hint: ...
    """
    return check_project(function, subdivision_project_cases(), reference=bezier.subdivide, compare=_compare_split,
                         what="de Casteljau subdivision",
                         hint="the left polygon is the first point of every level of the pyramid, the right polygon "
                              "the last point of every level, from the apex to P_n")


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
