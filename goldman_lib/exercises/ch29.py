"""Exercise checkers for chapter 29, subdivision matrices and iterated function systems
(Goldman §29.2-29.4), and the checker of the chapter's programming project.

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
from fractions import Fraction

import numpy as np

from goldman_lib import affine
from goldman_lib import subdivision_matrices as sm
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, fmt_points, off_by, read_points, wrong
from goldman_lib.exercises.deal import Deck, memo, plain as _tup, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "SPLIT_T", "BSPLINE_CTRL", "COMPOSED_CTRL", "NORMAL_DEGREE", "NORMAL_T",
           "FRACTAL_CTRL", "FRACTAL_MIDDLE", "DECK", "deal", "steps", "current", "deal_button",
           "check_left_matrix_at_t", "check_bspline_right_half", "check_composed_fixed_point",
           "check_normal_curve_point", "check_fractal_joint", "check_fractal_quarter_joint",
           "check_subdivision_matrices_project"]

#: Exercise 1: the split parameter of the quadratic's left subdivision matrix.
SPLIT_T = 1 / 3
#: Exercise 2: one segment of a uniform cubic B-spline, subdivided at its middle.
BSPLINE_CTRL = np.array([[0.0, 0.0], [2.0, 6.0], [6.0, 6.0], [8.0, 2.0]])
#: Exercise 3: the quadratic whose IFS map "first M_L, then M_R" is asked about.
COMPOSED_CTRL = np.array([[0.0, 0.0], [3.0, 6.0], [9.0, 0.0]])
#: Exercise 4: the degree and parameter of the normal-curve point.
NORMAL_DEGREE = 4
NORMAL_T = 1 / 3
#: Exercises 5 and 6: the control points and middle weight of the fractal curve.
FRACTAL_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0]])
FRACTAL_MIDDLE = -0.5

#: Relative tolerance for hand-computed decimals (1/81 typed as 0.01235 is right).
REL_TOL = 1e-4

DECK = Deck("ch29")


def _arr(v):
    return np.asarray(v, dtype=float)


def _cross2(a, b) -> float:
    """The 2D cross product a_x b_y - a_y b_x (zero for parallel vectors)."""
    return float(a[0] * b[1] - a[1] * b[0])


def _q(x) -> str:
    """A parameter as the statement writes it: 1/3, 3/4, 1/2."""
    q = Fraction(float(x)).limit_denominator(12)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def _f(x) -> str:
    """Numbers of the worked steps, rounded to 6 digits (no floating-point noise)."""
    x = np.round(np.asarray(x, dtype=float), 6) + 0.0
    return fmt_points(x, 6) if x.ndim > 1 else fmt(x, 6)


#: The split parameters and normal-curve parameters dealt (not 1/2: the chapter's matrices).
_PARAMS = (1 / 5, 1 / 4, 1 / 3, 2 / 5, 3 / 5, 2 / 3, 3 / 4, 4 / 5)

#: The checkers' tolerance (hand-computed decimals to a relative 1e-4), a little wider, and
#: answers of other shapes apart.
_same = within(REL_TOL, relative=True)


# -- reading and comparing -------------------------------------------------------------------------

def _close(got, expected) -> bool:
    exp = np.asarray(expected, dtype=float)
    return got.shape == exp.shape and bool(np.all(np.abs(got - exp) <= REL_TOL * np.maximum(1.0, np.abs(exp))))


def _read(answer, what, ask, shape):
    got, err = read_points(answer, what, ask=ask)
    if err is not None:
        return None, err
    if got.shape != shape:
        return None, wrong(f"{what} should have shape {shape}; yours has shape {got.shape}. "
                           f"Check what the exercise asks for.")
    return got, None


def _far(got, expected, what, hint) -> Result:
    """The generic verdict: which entry or point is off and by how much, never where it should be."""
    exp = np.asarray(expected, dtype=float)
    if got.ndim == 1:
        if exp.size <= 4 and got.size == exp.size and exp.ndim == 1 and exp.size != 2:
            k = int(np.argmax(np.abs(got - exp)))
            return wrong(f"coordinate x{k + 1} of {what} is {off_by(got[k], exp[k])}; {hint}.")
        return wrong(f"{what} is {far_off(got, exp)} from where it should be; {hint}.")
    err = np.linalg.norm((got - exp).reshape(len(exp), -1), axis=1)
    bad = np.flatnonzero(err > REL_TOL * np.maximum(1.0, np.abs(exp).reshape(len(exp), -1).max(axis=1)))
    k = int(bad[0])
    others = "the only point that is off" if bad.size == 1 else f"one of {bad.size} points off"
    return wrong(f"point {k} of {what} is {far_off(got[k], exp[k])} from where it should be ({others}); {hint}.")


def _matrix_entry(got, expected, name, hint) -> Result:
    bad = np.argwhere(np.abs(got - expected) > REL_TOL * np.maximum(1.0, np.abs(expected)))
    i, j = (int(x) for x in bad[0])
    return wrong(f"the entry in row {i}, column {j} of {name} is {off_by(got[i, j], expected[i, j])}; {hint}.")


# -- §29.2 ------------------------------------------------------------------------------------------

_STORED_SPLIT = {"t": SPLIT_T}


@memo
def _split_answers(p):
    t = p["t"]
    L, R = sm.bezier_subdivision_matrices(2, t)
    return L, {"transpose": L.T, "R": R, "1 - t": sm.bezier_subdivision_matrices(2, 1 - t)[0],
               "t = 1/2": sm.bezier_subdivision_matrices(2, 0.5)[0]}


def _split_statement(p) -> str:
    t = _q(p["t"])
    return (f"Subdivide a quadratic Bezier curve at t = {t} instead of 1/2. Give the left subdivision matrix L "
            f"(3x3, a list of rows) such that L @ P are the control points of the piece over [0, {t}]; "
            f"fractions or 4-digit decimals are fine (Goldman §29.2).")


def _split_steps(p) -> str:
    t = p["t"]
    L, _ = sm.bezier_subdivision_matrices(2, t)
    return (f"1. The de Casteljau triangle at t = {_q(t)}: level 0 is P0, P1, P2; each step takes "
            f"(1 - t) of the left point and t of the right one.\n"
            f"2. Its left edge is P0, (1 - t) P0 + t P1, (1 - t)^2 P0 + 2t(1 - t) P1 + t^2 P2: row i of L holds "
            f"B_j^i(t), j = 0..i.\n"
            f"3. L = [{'; '.join(_f(row) for row in L)}] (rows sum to 1).")


@DECK.exercise(stored=_STORED_SPLIT, generate=lambda rng: {"t": float(rng.choice(_PARAMS))},
               answer=lambda p: _split_answers(p)[0], slips=lambda p: _split_answers(p)[1],
               statement=_split_statement, steps=_split_steps, same=_same)
def check_left_matrix_at_t(answer, p) -> Result:
    """Check L of a quadratic Bezier curve split at the statement's t (Goldman §29.2); recognises the
    transpose, R, the matrix at 1 - t (t and 1 - t swapped), the matrix at 1/2, and rows that do not
    sum to one.
    """
    got, err = _read(answer, "L", "L as a list of rows", (3, 3))
    if err is not None:
        return err
    t = p["t"]
    L, R = sm.bezier_subdivision_matrices(2, t)
    if _close(got, L):
        return correct(f"row i of L is the left edge of the de Casteljau triangle at t = {_q(t)}: "
                       f"(B_0^i, ..., B_i^i)({_q(t)}).")
    if _close(got, L.T):
        return wrong("that is the transpose of L: with points as rows, each new control point is a row of L, "
                     "and the rows (not the columns) sum to 1.")
    if _close(got, R):
        return wrong(f"that is R, whose rows control the piece over [{_q(t)}, 1]; L starts at P0, so its first row "
                     f"is (1, 0, 0).")
    if _close(got, sm.bezier_subdivision_matrices(2, 1 - t)[0]):
        return wrong(f"t and 1 - t are swapped: that is L at t = {_q(1 - t)}. The first de Casteljau step gives "
                     f"(1 - t) P0 + t P1, so P1 gets the weight t.")
    if _close(got, sm.bezier_subdivision_matrices(2, 0.5)[0]):
        return wrong(f"that is L at t = 1/2, the matrix of the chapter; here the split is at t = {_q(t)}.")
    sums = got.sum(axis=1)
    if not np.allclose(sums, 1, atol=1e-3):
        k = int(np.flatnonzero(np.abs(sums - 1) > 1e-3)[0])
        return wrong(f"every row of L must sum to 1 (each new control point is an affine combination); "
                     f"row {k} sums to {fmt(sums[k])}.")
    return _matrix_entry(got, L, "L", "row i holds the Bernstein values B_j^i(t), j = 0..i, then zeros")


_STORED_RIGHT = {"ctrl": _tup(BSPLINE_CTRL)}


@memo
def _right_answers(p):
    P = _arr(p["ctrl"])
    Lb, Rb = sm.bspline_subdivision_matrices(3)
    return Rb @ P, {"the whole refined polygon": np.vstack([Lb @ P, (Rb @ P)[-1:]]), "L @ P": Lb @ P,
                    "Bezier R @ P": sm.bezier_subdivision_matrices(3)[1] @ P, "R transposed": Rb.T @ P}


def _right_ok(p):
    P = _arr(p["ctrl"])
    if abs(_cross2(P[1] - P[0], P[2] - P[0])) + abs(_cross2(P[2] - P[1], P[3] - P[1])) == 0:
        return "the control points lie on a line"
    return None


def _right_statement(p) -> str:
    return (f"One segment of a uniform cubic B-spline has control points {fmt_points(p['ctrl'])}. Halving the knot "
            f"spacing splits it in two; give the four control points R @ P of the right half, as [[x, y], ...] "
            f"(Goldman §29.2).")


def _right_steps(p) -> str:
    P = _arr(p["ctrl"])
    Lb, Rb = sm.bspline_subdivision_matrices(3)
    return (f"1. The rows of 8R are (1, 6, 1, 0), (0, 4, 4, 0), (0, 1, 6, 1), (0, 0, 4, 4): the cubic mask "
            f"1/8 (1, 6, 1) at an old point, 1/2 (1, 1) at a midpoint.\n"
            f"2. R = [{'; '.join(_f(row) for row in Rb)}].\n"
            f"3. R @ P = {_f(Rb @ P)}.")


@DECK.exercise(stored=_STORED_RIGHT, generate=lambda rng: {"ctrl": _tup(rng.integers(0, 9, size=(4, 2)))},
               answer=lambda p: _right_answers(p)[0], slips=lambda p: _right_answers(p)[1],
               statement=_right_statement, steps=_right_steps, same=_same, well_posed=_right_ok)
def check_bspline_right_half(answer, p) -> Result:
    """Check R @ P for the statement's uniform cubic B-spline segment (Goldman §29.2);
    recognises L @ P, the Bezier R @ P, the transposed matrix and the whole refined polygon.
    """
    got, err = read_points(answer, "your points", ask="the four points as [[x, y], ...]")
    if err is not None:
        return err
    P = _arr(p["ctrl"])
    Lb, Rb = sm.bspline_subdivision_matrices(3)
    expected = Rb @ P
    if got.shape == (5, 2):
        return wrong("those are five points: the refined polygon of the whole segment. Each half of a cubic "
                     "segment is again a cubic segment, with four control points; keep the last four.")
    if got.shape != (4, 2):
        return wrong(f"give four points [x, y]; yours has shape {got.shape}.")
    if _close(got, expected):
        return correct("R @ P uses the cubic mask 1/8 (1, 6, 1) at the old points and 1/2 (1, 1) at the "
                       "midpoints: the four points match.")
    if _close(got, Lb @ P):
        return wrong("that is L @ P, the left half: it starts at the midpoint of P0 and P1. The right half ends "
                     "at the midpoint of P2 and P3.")
    if _close(got, sm.bezier_subdivision_matrices(3)[1] @ P):
        return wrong("that is the Bezier R @ P: it ends at P3. A B-spline segment does not pass through its "
                     "control points; use the B-spline matrices of §29.2 (the Lane-Riesenfeld mask).")
    if _close(got, Rb.T @ P):
        return wrong("that is R transposed applied to P: each new point is a row of R times P, so its weights "
                     "are a row (summing to 1), not a column.")
    return _far(got, expected, "R @ P", "each new point is a row of R times P; the rows of 8R are printed "
                                        "in §29.2")


# -- §29.3 ------------------------------------------------------------------------------------------

def _bezier_point(ctrl, t):
    from goldman_lib import bezier
    return bezier.de_casteljau(ctrl, t)


_STORED_COMPOSED = {"ctrl": _tup(COMPOSED_CTRL)}


@memo
def _composed_answers(p):
    P = _arr(p["ctrl"])
    maps, _ = sm.curve_ifs(P)
    slips = {"M_R then M_L": affine.fixed_point(maps[1] @ maps[0]), "P0": P[0], "P2": P[-1],
             "C(1/2)": _bezier_point(P, 0.5), "the parameter": 2 / 3}
    return affine.fixed_point(maps[0] @ maps[1]), slips


def _composed_ok(p):
    P = _arr(p["ctrl"])
    if _cross2(P[1] - P[0], P[2] - P[0]) == 0:
        return "the control points lie on a line: the IFS is not defined"
    return None


def _composed_statement(p) -> str:
    return (f"The quadratic Bezier curve with control points {fmt_points(p['ctrl'])} is the attractor of its IFS "
            f"{{M_L, M_R}} = {{P^-1 L P, P^-1 R P}}. Which point does the composite map X -> X M_L M_R (first M_L, then "
            f"M_R; points are row vectors) leave fixed? Give [x, y] to 4 decimal places (Goldman §29.3).")


def _composed_steps(p) -> str:
    P = _arr(p["ctrl"])
    maps, _ = sm.curve_ifs(P)
    return (f"1. M_L sends the curve point C(t) to C(t/2) and M_R sends C(s) to C((1 + s)/2).\n"
            f"2. First M_L, then M_R: C(t) -> C(t/2) -> C((1 + t/2)/2) = C(1/2 + t/4).\n"
            f"3. The fixed parameter solves t = 1/2 + t/4: t = 2/3.\n"
            f"4. C(2/3) = (1/9) P0 + (4/9) P1 + (4/9) P2 = {_f(_bezier_point(P, 2 / 3))}; the fixed point of the "
            f"matrix M_L M_R is the same point, {_f(affine.fixed_point(maps[0] @ maps[1]))}.")


@DECK.exercise(stored=_STORED_COMPOSED, generate=lambda rng: {"ctrl": _tup(rng.integers(0, 10, size=(3, 2)))},
               answer=lambda p: _composed_answers(p)[0], slips=lambda p: _composed_answers(p)[1],
               statement=_composed_statement, steps=_composed_steps, same=_same, well_posed=_composed_ok)
def check_composed_fixed_point(answer, p) -> Result:
    """Check the fixed point of ``X -> X M_L M_R`` for the statement's quadratic (Goldman §29.3); recognises
    the maps taken in the other order, the fixed points of M_L and M_R alone, C(1/2), and the
    parameter typed instead of the point.
    """
    got, err = read_points(answer, "your point", ask="the fixed point as [x, y]")
    if err is not None:
        return err
    if got.size == 1:
        return wrong("give the point [x, y], not a parameter: find the t whose curve point the composite map "
                     "leaves in place, then evaluate the curve there.")
    if got.shape != (2,):
        return wrong(f"the fixed point should be one point [x, y]; yours has shape {got.shape}.")
    P = _arr(p["ctrl"])
    maps, _ = sm.curve_ifs(P)
    expected = affine.fixed_point(maps[0] @ maps[1])
    if _close(got, expected):
        return correct("M_L sends C(t) to C(t/2) and M_R sends C(s) to C((1 + s)/2), so the composite sends C(t) "
                       "to C(1/2 + t/4) and fixes C(2/3).")
    if _close(got, affine.fixed_point(maps[1] @ maps[0])):
        return wrong("that is the fixed point of M_R followed by M_L: with row vectors, X M_L M_R applies M_L "
                     "first. Follow a curve point C(t) through M_L, then through M_R.")
    if _close(got, P[0]):
        return wrong("P0 is the fixed point of M_L alone; after M_L the map M_R moves it into the right half.")
    if _close(got, P[-1]):
        return wrong("P2 is the fixed point of M_R alone, but M_L first sends it to C(1/2), and M_R does not "
                     "bring that back to P2.")
    if _close(got, _bezier_point(P, 0.5)):
        return wrong("C(1/2) is where the two halves meet, but the composite moves it (M_L sends it to C(1/4)). "
                     "Solve t = where the composite sends C(t).")
    return _far(got, expected, "your point", "write where M_L, then M_R send the curve point C(t) as a parameter, "
                                            "solve for the t that stays, and evaluate the curve there")


_STORED_NORMAL = {"n": NORMAL_DEGREE, "t": NORMAL_T}


def _bern(n, t) -> np.ndarray:
    return np.array([math.comb(n, k) * t ** k * (1 - t) ** (n - k) for k in range(n + 1)])


@memo
def _normal_answers(p):
    n, t = p["n"], p["t"]
    return sm.normal_curve(n, t), {"with B_0": _bern(n, t), "1 - t": sm.normal_curve(n, 1 - t),
                                   "no binomials": np.array([t ** k * (1 - t) ** (n - k) for k in range(1, n + 1)])}


def _normal_generate(rng) -> dict:
    """The notebook's exercise is the normal quartic: the parameter deals, the degree stays 4."""
    return {"n": NORMAL_DEGREE, "t": float(rng.choice(_PARAMS))}


def _coords(n) -> str:
    return ", ".join(f"x{k}" for k in range(1, n + 1))


def _normal_statement(p) -> str:
    n, t = p["n"], p["t"]
    return (f"Give the point N({_q(t)}) of the normal curve of degree {n}, whose control points are the origin "
            f"and the unit points e1, ..., e{n} of {n}-space, as [{_coords(n)}] (fractions or 4-digit decimals; "
            f"Goldman §29.3).")


def _normal_steps(p) -> str:
    n, t = p["n"], p["t"]
    B = _bern(n, t)
    q = Fraction(float(t)).limit_denominator(12)
    a, b = q.numerator, q.denominator
    rows = ", ".join(f"B_{k}^{n} = C({n}, {k}) {a}^{k} {b - a}^{n - k} / {b}^{n} = {_f(B[k])}" for k in range(1, n + 1))
    return (f"1. N(t) = sum_k B_k^{n}(t) e_k: the coordinates are B_1^{n}(t), ..., B_{n}^{n}(t) (the origin's weight "
            f"B_0 adds nothing).\n"
            f"2. With t = {a}/{b}, 1 - t = {b - a}/{b}: {rows}.\n"
            f"3. N({_q(t)}) = {_f(sm.normal_curve(n, t))}.")


@DECK.exercise(stored=_STORED_NORMAL, generate=_normal_generate, answer=lambda p: _normal_answers(p)[0],
               slips=lambda p: _normal_answers(p)[1], statement=_normal_statement, steps=_normal_steps, same=_same)
def check_normal_curve_point(answer, p) -> Result:
    """Check N(t) on the statement's normal curve (Goldman §29.3); recognises the answer with
    B_0, t and 1 - t swapped, and the binomial coefficients left out.

    >>> check_normal_curve_point([16 / 81, 32 / 81, 24 / 81, 8 / 81, 1 / 81])
    Not yet: the normal curve lives in 4-space: its coordinates are B_1, ..., B_4; B_0 is the weight of the origin and adds nothing.
    """
    n, t = p["n"], p["t"]
    got, err = read_points(answer, "your point", ask=f"the point as [{_coords(n)}]")
    if err is not None:
        return err
    if got.shape == (n + 1,) and _close(got, _bern(n, t)):
        return wrong(f"the normal curve lives in {n}-space: its coordinates are B_1, ..., B_{n}; B_0 is the weight "
                     f"of the origin and adds nothing.")
    if got.shape != (n,):
        return wrong(f"N({_q(t)}) should be one point of {n}-space [{_coords(n)}]; yours has shape {got.shape}.")
    expected = sm.normal_curve(n, t)
    if _close(got, expected):
        return correct(f"N({_q(t)}) = ({', '.join(f'B_{k}^{n}' for k in range(1, n + 1))})({_q(t)}) = {fmt(expected)}.")
    if _close(got, sm.normal_curve(n, 1 - t)):
        smallest = f", the smallest for t = {_q(t)}" if t < 0.5 else ""
        return wrong(f"t and 1 - t are swapped: that is N({_q(1 - t)}). B_k^{n}(t) = C({n}, k) t^k (1 - t)^({n} - k), "
                     f"so the last coordinate is t^{n}{smallest}.")
    if _close(got, [t ** k * (1 - t) ** (n - k) for k in range(1, n + 1)]):
        binomials = ", ".join(str(math.comb(n, k)) for k in range(1, n + 1))
        return wrong(f"the binomial coefficients C({n}, k) = {binomials} are missing: "
                     f"B_k^{n}(t) = C({n}, k) t^k (1 - t)^({n} - k).")
    q = Fraction(float(t)).limit_denominator(12)
    a, b = q.numerator, q.denominator
    power = f"{b - a}^({n} - k)" if a == 1 else f"{a}^k {b - a}^({n} - k)"
    return _far(got, expected, f"N({_q(t)})", f"B_k^{n}({_q(t)}) = C({n}, k) {power} / {b ** n}")


# -- §29.4 ------------------------------------------------------------------------------------------

_STORED_FRACTAL = {"ctrl": _tup(FRACTAL_CTRL), "v": FRACTAL_MIDDLE}
#: the middle weights dealt (not 1/2: the Bezier curve)
_MIDDLES = (-1.0, -0.5, -0.25, 0.25, 0.75, 1.5)


def _fractal(p):
    L, R = sm.fractal_matrices(p["v"])
    return L, R, _arr(p["ctrl"])


def _fractal_generate(rng) -> dict:
    return {"ctrl": _tup(2 * rng.integers(0, 5, size=(3, 2))), "v": float(rng.choice(_MIDDLES))}


def _fractal_ok(p):
    P = _arr(p["ctrl"])
    if _cross2(P[1] - P[0], P[2] - P[0]) == 0:
        return "the control points lie on a line"
    return None


def _wrong_us(v):
    u = (1 - v) / 2
    return [uu for uu in (0.5, (1 + v) / 2, 0.25, 1.0) if abs(uu - u) > 1e-9]


@memo
def _joint_answers(p):
    L, R, P = _fractal(p)
    v = p["v"]
    slips = {"Bezier midpoint": (P[0] + 2 * P[1] + P[2]) / 4}
    for uu in _wrong_us(v):
        slips[f"u = {fmt(uu)}"] = uu * P[0] + v * P[1] + uu * P[2]
    return L[2] @ P, slips


def _joint_ok(p):
    why = _fractal_ok(p)
    if why:
        return why
    # a wrong u named in a message must not be a coordinate of the answer (it would read as a hint)
    answer = _joint_answers(p)[0]
    if any(abs(uu - a) < 1e-9 for uu in _wrong_us(p["v"]) for a in answer):
        return "a wrong weight named in a message equals a coordinate of the answer"
    return None


def _joint_statement(p) -> str:
    return (f"With L = [[1, 0, 0], [1/2, 1/2, 0], [u, v, u]] and R = [[u, v, u], [0, 1/2, 1/2], [0, 0, 1]], "
            f"v = {fmt(p['v'])} and rows summing to one, the two halves of the fractal with control points "
            f"{fmt_points(p['ctrl'])} meet at one point. Give it as [x, y] (Goldman §29.4).")


def _joint_steps(p) -> str:
    L, R, P = _fractal(p)
    v = p["v"]
    return (f"1. The rows sum to one: u + v + u = 1, so u = (1 - v)/2 = {fmt((1 - v) / 2)}.\n"
            f"2. The halves L @ P and R @ P share the point of the last row of L, which is the first row of R.\n"
            f"3. The joint u P0 + v P1 + u P2 = {_f(L[2] @ P)}.")


@DECK.exercise(stored=_STORED_FRACTAL, generate=_fractal_generate, answer=lambda p: _joint_answers(p)[0],
               slips=lambda p: _joint_answers(p)[1], statement=_joint_statement, steps=_joint_steps, same=_same,
               well_posed=_joint_ok)
def check_fractal_joint(answer, p) -> Result:
    """Check the point where the halves of the statement's fractal meet (Goldman §29.4); recognises the
    Bezier midpoint C(1/2) and weights that do not sum to one.
    """
    got, err = read_points(answer, "your point", ask="the joint as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the joint should be one point [x, y]; yours has shape {got.shape}.")
    L, R, P = _fractal(p)
    v = p["v"]
    u = (1 - v) / 2
    expected = L[2] @ P
    if _close(got, expected):
        return correct(f"the joint is the last row of L (the first of R) applied to the control points: "
                       f"u P0 + v P1 + u P2 = {fmt(expected)}.")
    if _close(got, (P[0] + 2 * P[1] + P[2]) / 4):
        return wrong("that is the Bezier midpoint C(1/2) (v = 1/2); here the middle weight is "
                     f"{fmt(v)}, and u follows from it.")
    for uu in (0.5, (1 + v) / 2, 0.25, 1.0):
        if abs(uu - u) > 1e-9 and _close(got, uu * P[0] + v * P[1] + uu * P[2]):
            return wrong(f"the weights must sum to one (an affine combination): u + v + u = 1 fixes u, and "
                         f"u = {fmt(uu)} does not satisfy it.")
    return _far(got, expected, "the joint", "it is the last row of L (the first of R) applied to the control points")


_STORED_QUARTER = dict(_STORED_FRACTAL)


@memo
def _quarter_answers(p):
    L, R, P = _fractal(p)
    slips = {"the right half's joint": (L @ R @ P)[2], "the halves' joint": (L @ P)[2],
             "Bezier C(1/4)": _bezier_point(P, 0.25), "midpoint of P0 and the joint": ((L @ P)[0] + (L @ P)[2]) / 2}
    return (L @ L @ P)[2], slips


def _quarter_statement(p) -> str:
    same = "Same fractal" if p == _STORED_QUARTER else "The same kind of fractal"
    return (f"{same} (v = {fmt(p['v'])}, control points {fmt_points(p['ctrl'])}). Its left half is "
            f"itself a copy of the fractal, with control points L @ P, and is made of two quarters. Where do the first "
            f"and the second quarter meet? Give [x, y] (Goldman §29.4).")


def _quarter_steps(p) -> str:
    L, R, P = _fractal(p)
    v = p["v"]
    return (f"1. u = (1 - v)/2 = {fmt((1 - v) / 2)}; the left half's control points L @ P = P0, (P0 + P1)/2 and the "
            f"joint: {_f(L @ P)}.\n"
            f"2. The left half is a copy of the fractal: its two quarters meet at its own joint, u, v, u applied to "
            f"those three points.\n"
            f"3. (L @ L @ P)[2] = {_f((L @ L @ P)[2])}.")


@DECK.exercise(stored=_STORED_QUARTER, generate=_fractal_generate, answer=lambda p: _quarter_answers(p)[0],
               slips=lambda p: _quarter_answers(p)[1], statement=_quarter_statement, steps=_quarter_steps,
               same=_same, well_posed=_fractal_ok)
def check_fractal_quarter_joint(answer, p) -> Result:
    """Check where the first two quarters of the statement's fractal meet (Goldman §29.4): the joint of
    the left half, ``(L @ L @ P)[2]``; recognises the right half's joint, the Bezier point C(1/4), the
    joint of the whole curve, and the midpoint of P0 and the joint.
    """
    got, err = read_points(answer, "your point", ask="the point as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the point should be one point [x, y]; yours has shape {got.shape}.")
    L, R, P = _fractal(p)
    expected = (L @ L @ P)[2]
    if _close(got, expected):
        return correct(f"the left half has control points L @ P = P0, (P0 + P1)/2 and the joint, and its own joint "
                       f"is u, v, u applied to those: {fmt(expected)}.")
    if _close(got, (L @ R @ P)[2]) or _close(got, (R @ R @ P)[0]):
        return wrong("that is where the third and fourth quarters meet, in the right half; the first two "
                     "quarters make up the left half, with control points L @ P.")
    if _close(got, (L @ P)[2]):
        return wrong("that is the joint of the two halves; the quarters of the left half meet at the joint of "
                     "the left half, whose control points are L @ P.")
    if _close(got, _bezier_point(P, 0.25)):
        return wrong("that is the Bezier point C(1/4) (middle weight 1/2); the fractal's weights u, v, u with "
                     f"v = {fmt(p['v'])} apply to the left half's control points.")
    if _close(got, ((L @ P)[0] + (L @ P)[2]) / 2):
        return wrong("that is the midpoint of P0 and the joint: the left half is a copy of the fractal, not a "
                     "segment; apply u, v, u to its three control points L @ P.")
    return _far(got, expected, "your point", "compute L @ P (three points), then apply the row (u, v, u) to them")


#: Deal another instance of an exercise (``deal("check_fractal_joint")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_left_matrix_at_t": [
        [[1, 2 / 3, 4 / 9], [0, 1 / 3, 4 / 9], [0, 0, 1 / 9]],           # transposed
        [[4 / 9, 4 / 9, 1 / 9], [0, 2 / 3, 1 / 3], [0, 0, 1]],           # R
        [[1, 0, 0], [1 / 3, 2 / 3, 0], [1 / 9, 4 / 9, 4 / 9]],           # t and 1 - t swapped
        [[1, 0, 0], [0.5, 0.5, 0], [0.25, 0.5, 0.25]],                   # t = 1/2
        [[1, 0, 0], [2 / 3, 1 / 3, 0], [4 / 9, 2 / 9, 1 / 9]],           # binomial 2 forgotten
    ],
    "check_bspline_right_half": [
        [[1, 3], [2.25, 5.25], [4, 6], [5.75, 5.5]],                      # L @ P
        [[4, 4.75], [5.5, 5], [7, 4], [8, 2]],                            # Bezier R @ P
        [[0, 0], [1.75, 3.75], [9.5, 8.5], [4.75, 1.75]],                 # R^T @ P
        [[1, 3], [2.25, 5.25], [4, 6], [5.75, 5.5], [7, 4]],              # the whole refined polygon
    ],
    "check_composed_fixed_point": [
        [7 / 3, 8 / 3],        # M_R then M_L: C(1/3)
        [0, 0], [9, 0],        # fixed points of M_L, M_R alone
        [3.75, 3],             # C(1/2)
        2 / 3,                 # the parameter, not the point
    ],
    "check_normal_curve_point": [
        [16 / 81, 32 / 81, 24 / 81, 8 / 81, 1 / 81],   # with B_0
        [8 / 81, 24 / 81, 32 / 81, 16 / 81],           # N(2/3)
        [8 / 81, 4 / 81, 2 / 81, 1 / 81],              # no binomials
    ],
    "check_fractal_joint": [
        [2, 2],      # Bezier midpoint
        [1, -2],     # u = 1/2
        [0, -2],     # u = 1/4
    ],
    "check_fractal_quarter_joint": [
        [3, -2.5],   # the right half's joint
        [2, -2],     # the joint of the halves
        [1, 1.5],    # Bezier C(1/4)
        [1, -1],     # midpoint of P0 and the joint
    ],
}


# -- the programming project ------------------------------------------------------------------------

def _project_cases():
    rng = np.random.default_rng(2929)
    cases = [Case("degree 1, a segment, at t = 1/2", (1,), {"t": 0.5}, kind="degree 1 (a segment)")]
    cases += [Case(f"degree {n} at t = 1/2", (n,), {"t": 0.5}, kind="degrees 2-6 at t = 1/2") for n in range(2, 7)]
    for n, t in zip(rng.integers(2, 7, size=4), rng.uniform(0.1, 0.9, size=4)):
        t = round(float(t), 3)
        cases.append(Case(f"degree {int(n)} at t = {t}", (int(n),), {"t": t}, kind="random t"))
    cases.append(Case("degree 3 at t = 0 (the left piece is the point P0)", (3,), {"t": 0.0},
                      kind="degenerate t = 0 and t = 1"))
    cases.append(Case("degree 2 at t = 1 (the right piece is the point P2)", (2,), {"t": 1.0},
                      kind="degenerate t = 0 and t = 1"))
    return cases


class _Returned:
    """What the learner's function returned, described briefly ("(L, R), two 4 x 4 matrices") so that
    a failing case does not print whole matrices; the comparison looks at ``value``."""

    def __init__(self, value):
        self.value = value

    def __repr__(self):
        v = self.value
        if isinstance(v, (tuple, list)) and len(v) == 2:
            shapes = [np.shape(m) for m in v]
            if all(len(sh) == 2 for sh in shapes):
                if shapes[0] == shapes[1]:
                    return f"(L, R), two {shapes[0][0]} x {shapes[0][1]} matrices"
                return f"(L, R) with L of shape {shapes[0]} and R of shape {shapes[1]}"
        text = repr(v)
        return text if len(text) <= 60 else text[:57] + "..."


class _Learner:
    """Calls the learner's function and wraps what it returns in :class:`_Returned`; carries the
    function's ``__code__`` so that the project checker reports an exception at the learner's line."""

    def __init__(self, function):
        self.function = function
        self.__code__ = getattr(function, "__code__", None)

    def __call__(self, *args, **kwargs):
        value = self.function(*args, **kwargs)
        if value is None:
            return None
        named = type(type(value).__name__, (_Returned,), {})  # describe() says "(a tuple)", "(a list)"
        return named(value)


def _compare_matrices(got, expected, case):
    got = got.value if isinstance(got, _Returned) else got
    if not isinstance(got, (tuple, list)) or len(got) != 2:
        return "it should be a pair (L, R) of matrices"
    try:
        L, R = (np.asarray(m, dtype=float) for m in got)
    except (TypeError, ValueError):
        return "L and R should be arrays of numbers"
    EL, ER = expected
    if L.shape != EL.shape or R.shape != ER.shape:
        return (f"for degree {len(EL) - 1} both L and R should have shape {EL.shape}, one row per control point "
                f"of a piece and one column per control point of the curve")
    if not (np.all(np.isfinite(L)) and np.all(np.isfinite(R))):
        return "it contains NaN or infinite values"
    ok = lambda a, b: bool(np.allclose(a, b, atol=1e-9))  # noqa: E731
    if ok(L, EL) and ok(R, ER):
        return None
    if ok(L, ER) and ok(R, EL):
        return "L and R are swapped: L @ P should control the piece over [0, t], which starts at P0"
    if ok(L, EL.T) or ok(R, ER.T):
        which = "L" if ok(L, EL.T) else "R"
        return (f"{which} is transposed: with control points as rows, each new control point is a row of {which} "
                f"times P, so the rows (not the columns) sum to 1")
    if ok(L, EL) and ok(R, ER[::-1]):
        return ("the rows of R are in reverse order: R @ P controls the piece over [t, 1], which starts at C(t) "
                "(the apex of the triangle) and ends at the last control point")
    n, t = len(EL) - 1, float(case.kwargs.get("t", 0.5))
    for s_, why in ((1.0 - t, f"these are the matrices of the split at 1 - t = {fmt(1 - t)}: each step of the "
                              f"triangle is (1 - t) P_j + t P_(j+1)"),
                    (0.5, "these are the matrices of the split at t = 1/2: use the t given")):
        if abs(s_ - t) > 1e-12:
            AL, AR = sm.bezier_subdivision_matrices(n, s_)
            if ok(L, AL) and ok(R, AR):
                return why
    for name, M, E in (("L", L, EL), ("R", R, ER)):
        bad = np.argwhere(np.abs(M - E) > 1e-9)
        if bad.size:
            i, j = (int(x) for x in bad[0])
            return (f"{name}[{i}, {j}] (row {i}, column {j}) is {fmt(M[i, j])}, expected {fmt(E[i, j])} "
                    f"(entries of {name} off: {len(bad)} of {E.size})")
    return None


def check_subdivision_matrices_project(function) -> Result:
    """Run the learner's ``function(n, t=0.5) -> (L, R)`` against
    :func:`goldman_lib.subdivision_matrices.bezier_subdivision_matrices` for degrees 1 to 6 at t = 1/2,
    at random t (fixed seed) and at the degenerate t = 0 and t = 1 (Goldman §29.2, programming project).

    >>> def swapped(n, t=0.5):
    ...     L, R = sm.bezier_subdivision_matrices(n, t)
    ...     return R, L
    >>> print(check_subdivision_matrices_project(swapped).message)   # doctest: +ELLIPSIS
    case 1 of 12 (...): ...; L and R are swapped: ... Hint: ...
    """
    learner = _Learner(function) if callable(function) else function
    return check_project(learner, _project_cases(), reference=sm.bezier_subdivision_matrices,
                         compare=_compare_matrices, what="subdivision_matrices(n, t)",
                         hint="L[i, j] = B_j^i(t) (the left edge of the de Casteljau triangle) and "
                              "R[i, j] = B_{j-i}^{n-i}(t) (its right edge)")


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
