"""Exercise checkers for chapter 7, the fixed-point theorem and its applications (Goldman §7.2-7.3).

Every exercise uses other functions, systems, sets and maps than the chapter's worked examples, and
every checker names the slip it recognises (one Newton step instead of two, the Jacobi step when
Gauss-Seidel was asked, one direction of the Hausdorff distance, the area factor instead of the
stretch, ...).  The programming project, :func:`check_gauss_seidel_project`, runs the learner's
Gauss-Seidel sweeps against :func:`goldman_lib.fixed_point.gauss_seidel`.

All seven numeric exercises deal new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
``deal("check_newton_step")`` (or ``deal_button``) puts an exercise on a new seed, ``steps(...)``
shows the library's worked steps of the current instance, and seed 0 is the instance the module
constants below describe.  Each generator states its rule for a well-posed instance beside it
(whole-number limits, diagonally dominant systems with small whole entries, a contraction with
one-decimal entries, no power of s landing on the tolerance, ...).  The programming project does
not deal: its answer is a program, checked on its own generated cases.

>>> print(PROBLEMS["check_newton_step"])
Take two steps of Newton's method for f(x) = x^3 - 10 from x0 = 2: give x2 to 6 decimals (Goldman §7.3.1).
>>> check_newton_step(2.166667)
Not yet: that is x1, one step of Newton's method; take a second step x2 = x1 - f(x1)/f'(x1).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fixed_point as fp
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises.deal import Deck, memo, within
from goldman_lib.exercises import Result, check_number, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "LIMIT_START", "NEWTON_START", "SEIDEL_A", "SEIDEL_B", "JACOBI_A", "JACOBI_B",
           "JACOBI_X0", "JACOBI_SWEEPS", "HAUSDORFF_A", "HAUSDORFF_B", "STRETCH_L", "LEVEL_FACTORS",
           "LEVEL_START_DISTANCE", "LEVEL_TOL", "DECK", "deal", "steps", "current", "deal_button",
           "check_fixed_point_limit", "check_newton_step",
           "check_gauss_seidel_sweep", "check_jacobi_sweeps", "check_hausdorff", "check_contraction_factor",
           "check_levels_needed", "check_gauss_seidel_project", "gauss_seidel_project_cases"]


#: Exercise 1: iterate F(x) = sqrt(6 + x) from this start (instance 0).
LIMIT_START = 0.0
#: Exercise 2: Newton's method for f(x) = x^3 - 10 from this start, two steps.
NEWTON_START = 2.0
#: Exercise 3: one Gauss-Seidel sweep from zero on this 3x3 system.
SEIDEL_A = np.array([[4.0, 1.0, 1.0], [1.0, 5.0, 2.0], [2.0, 1.0, 6.0]])
SEIDEL_B = np.array([8.0, 7.0, 8.0])
#: Exercise 4: two Jacobi sweeps on this 2x2 system from JACOBI_X0.
JACOBI_A = np.array([[5.0, 2.0], [1.0, 4.0]])
JACOBI_B = np.array([9.0, 6.0])
JACOBI_X0 = np.array([1.0, 1.0])
JACOBI_SWEEPS = 2
#: Exercise 5: two finite point sets.
HAUSDORFF_A = np.array([[0.0, 0.0], [4.0, 0.0]])
HAUSDORFF_B = np.array([[0.0, 3.0], [12.0, 6.0]])
#: Exercise 6: the linear part of the map (x, y) -> (0.3 x, 0.4 x + 0.5 y) + (1, 2), row-vector convention.
STRETCH_L = np.array([[0.3, 0.4], [0.0, 0.5]])
#: Exercise 7: an IFS with these contraction factors, a start set this far from the attractor, a tolerance.
LEVEL_FACTORS = (0.6, 0.75, 0.5)
LEVEL_START_DISTANCE = 4.0
LEVEL_TOL = 0.01


def _eq(a: str) -> str:
    return a.replace("+ -", "- ").replace("1x", "x").replace("1y", "y").replace("1z", "z")


def _system_text(A, b, names) -> str:
    rows = []
    for row, rhs in zip(A, b):
        terms = " + ".join(f"{fmt(c)}{v}" for c, v in zip(row, names) if c != 0)
        rows.append(_eq(f"{terms} = {fmt(rhs)}"))
    return ", ".join(rows)


DECK = Deck("ch07")


def _matrix(rows) -> np.ndarray:
    return np.array(rows, dtype=float)


def _tuple2(M) -> tuple:
    return tuple(tuple(float(v) for v in row) for row in np.asarray(M, dtype=float))


def _r(x, digits: int = 6) -> str:
    """A number rounded for worked steps (no floating-point noise)."""
    return fmt(round(float(x), digits) + 0.0, 10)


def _decimals(answer) -> str:
    """" Decimals to 4 places are fine." for an instance whose answer is not a short decimal (the
    checker's tolerance, 1e-4, takes a 4-place rounding); nothing for one that is (instance 0)."""
    values = np.ravel(np.asarray(answer, dtype=float))
    return "" if np.allclose(values, np.round(values, 3), rtol=0, atol=1e-9) else " Decimals to 4 places are fine."


# -- §7.2 ------------------------------------------------------------------------------------------

_STORED_LIMIT = {"c": 6.0, "x0": LIMIT_START}


@memo
def _limit_answers(p):
    c, x0 = p["c"], p["x0"]
    limit, rep = fp.fixed_point_iteration(lambda x: math.sqrt(c + x), x0, full_output=True)
    k = (1 + math.sqrt(1 + 4 * c)) / 2
    x1 = math.sqrt(c + x0)
    slips = {"the negative root": -(k - 1), "x1": x1, "x2": math.sqrt(c + x1)}
    return limit, slips


def _limit_generate(rng) -> dict:
    k = int(rng.integers(2, 8))
    return {"c": float(k * (k - 1)), "x0": float(rng.integers(0, 11))}


def _limit_ok(p):
    k = (1 + math.sqrt(1 + 4 * p["c"])) / 2
    if abs(p["x0"] - k) < 0.5:
        return "the start is the fixed point (every iterate is the limit)"
    return None


def _limit_statement(p) -> str:
    return (f"Iterate x_(n+1) = F(x_n) = sqrt({fmt(p['c'])} + x_n) from x0 = {fmt(p['x0'])}. The iterates converge; "
            f"by the trivial fixed-point theorem, what is their limit L (Goldman §7.2)?")


def _limit_steps(p) -> str:
    c = p["c"]
    k = round((1 + math.sqrt(1 + 4 * c)) / 2)
    return (f"1. A limit L of x_(n+1) = F(x_n) with F continuous is a fixed point: L = sqrt({fmt(c)} + L).\n"
            f"2. Square: L^2 - L - {fmt(c)} = 0, so L = {k} or L = {-(k - 1)}.\n"
            f"3. A square root is never negative, so L = {k} (check: sqrt({fmt(c)} + {k}) = {k}); the iterates "
            f"from {fmt(p['x0'])} move monotonically towards it.")


@DECK.exercise(stored=_STORED_LIMIT, generate=_limit_generate, answer=lambda p: _limit_answers(p)[0],
               slips=lambda p: _limit_answers(p)[1], statement=_limit_statement, steps=_limit_steps,
               same=within(1e-4), well_posed=_limit_ok)
def check_fixed_point_limit(answer, p) -> Result:
    """Check the limit of x -> sqrt(c + x) from the statement's start, a fixed point L = sqrt(c + L)
    (Goldman §7.2); recognises the root of the quadratic that is not a fixed point (a square root is
    never negative) and early iterates."""
    value, problem = read_number(answer, "the limit L")
    if problem is not None:
        return problem
    limit, slips = _limit_answers(p)
    x1, x2 = slips["x1"], slips["x2"]
    neg = slips["the negative root"]
    if abs(value - neg) <= 1e-6:
        m = fmt(-neg)
        return wrong(f"{fmt(neg)} solves L^2 = {fmt(p['c'])} + L, but it is not a fixed point of F: "
                     f"sqrt({fmt(p['c'])} - {m}) is {m}, not -{m} "
                     "(a square root is never negative). Take the other root.")
    if abs(value - x1) <= 1e-4:
        return wrong("that is x1 = F(x0), the first iterate; the theorem is about the limit: solve L = F(L).")
    if abs(value - x2) <= 1e-4:
        return wrong("that is x2, an early iterate; the theorem is about the limit: solve L = F(L).")
    return check_number(value, limit, what="the limit L", tol=1e-4,
                        hint="a limit L of x_(n+1) = F(x_n) satisfies L = F(L); square both sides")


# -- §7.3.1 ----------------------------------------------------------------------------------------

def _two_steps(f, df, x0) -> float:
    """Two steps of a (slipped) Newton iteration, NaN where a step divides by zero (the library's
    ``newton_steps`` stops there, and such an instance is not dealt)."""
    try:
        h = fp.newton_steps(f, df, x0, max_iter=2).history
    except (ValueError, ZeroDivisionError, ArithmeticError):
        return math.nan
    return float(h[2]) if len(h) > 2 else math.nan


_STORED_NEWTON = {"a": 10.0, "x0": NEWTON_START}


@memo
def _newton_answers(p):
    a, x0 = p["a"], p["x0"]

    def f(x):
        return x ** 3 - a

    def df(x):
        return 3.0 * x * x

    x2 = fp.newton_steps(f, df, x0, max_iter=2).history[2]
    x1 = fp.newton_steps(f, df, x0, max_iter=1).history[1]
    plus = _two_steps(lambda x: -f(x), df, x0)
    no3 = _two_steps(f, lambda x: x * x, x0)
    root = fp.newton(f, df, x0)
    return x2, {"x1": x1, "the root": root, "x + f/f'": plus, "f' without its 3": no3}


def _newton_generate(rng) -> dict:
    a = float(rng.integers(2, 70))
    c = a ** (1 / 3)
    return {"a": a, "x0": float(rng.choice([math.floor(c), math.ceil(c)]))}


def _newton_ok(p):
    a, x0 = p["a"], p["x0"]
    if x0 < 1 or round(a ** (1 / 3)) ** 3 == a:
        return "the start is not positive, or a is a perfect cube (x0 would be the root)"
    x2, slips = _newton_answers(p)
    if not all(math.isfinite(v) for v in slips.values()) or abs(x2 - slips["the root"]) <= 2e-5:
        return "x2 is already the root to the checker's tolerance (one slip could not be told apart)"
    return None


def _newton_statement(p) -> str:
    return (f"Take two steps of Newton's method for f(x) = x^3 - {fmt(p['a'])} from x0 = {fmt(p['x0'])}: "
            f"give x2 to 6 decimals (Goldman §7.3.1).")


def _newton_steps(p) -> str:
    a, x0 = p["a"], p["x0"]
    x2, slips = _newton_answers(p)
    x1 = slips["x1"]
    return (f"1. f(x) = x^3 - {fmt(a)}, f'(x) = 3x^2; Newton's step is x - f(x)/f'(x).\n"
            f"2. x1 = {fmt(x0)} - ({fmt(x0 ** 3)} - {fmt(a)})/{fmt(3 * x0 * x0)} = {_r(x1, 8)}.\n"
            f"3. x2 = x1 - (x1^3 - {fmt(a)})/(3 x1^2) = {x2:.6f} (the cube root of {fmt(a)} is "
            f"{slips['the root']:.6f}).")


@DECK.exercise(stored=_STORED_NEWTON, generate=_newton_generate, answer=lambda p: _newton_answers(p)[0],
               slips=lambda p: _newton_answers(p)[1], statement=_newton_statement, steps=_newton_steps,
               same=within(1e-5), well_posed=_newton_ok)
def check_newton_step(answer, p) -> Result:
    """Check x2 of Newton's method on ``x^3 - a`` from the statement's start (Goldman §7.3.1).

    Recognises one step (x1), the limit (the cube root of a), the sign slip ``x + f/f'`` and the
    derivative without its factor 3.
    """
    value, problem = read_number(answer, "x2")
    if problem is not None:
        return problem
    x2, slips = _newton_answers(p)
    x1, root, plus, no3 = slips["x1"], slips["the root"], slips["x + f/f'"], slips["f' without its 3"]
    a = fmt(p["a"])
    tol = 1e-5
    if abs(value - x2) <= tol:
        near = "already within 1e-4 of" if abs(x2 - root) < 1e-4 else "closing in on"
        return correct(f"x2 is {x2:.6f}, {near} the cube root of {a}: the correct digits roughly "
                       f"double at each step.")
    if abs(value - x1) <= tol:
        return wrong("that is x1, one step of Newton's method; take a second step x2 = x1 - f(x1)/f'(x1).")
    if abs(value - root) <= tol / 10:
        return wrong(f"that is the cube root of {a} itself, the limit; the exercise asks for the second iterate, "
                     "which is not there yet.")
    if abs(value - plus) <= tol:
        return wrong("that is what x_(n+1) = x_n + f(x_n)/f'(x_n) gives: Newton's step subtracts f/f' (follow the "
                     "tangent down to the axis).")
    if abs(value - no3) <= tol:
        return wrong("that is what you get dividing f(x_n) by x_n squared: the derivative of x cubed is three times "
                     "x squared.")
    return wrong(f"x2 is {off_by(value, x2)}. Check x1 = x0 - f(x0)/f'(x0) with f'(x) three times x squared, then repeat from x1.")


# -- §7.3.2 ----------------------------------------------------------------------------------------

def _sweeps(method, A, b, x0, sweeps: int) -> np.ndarray:
    """The iterate after ``sweeps`` sweeps of the library's Jacobi or Gauss-Seidel (the history of
    its report; if it converged earlier, later sweeps change nothing beyond rounding)."""
    x0 = np.asarray(x0, dtype=float)
    if sweeps == 0:
        return x0.copy()
    _, rep = method(A, b, x0, max_iter=sweeps, full_output=True)
    return np.asarray(rep.history[min(sweeps, len(rep.history) - 1)], dtype=float)


def _backward_gauss_seidel(A, b, x0, sweeps: int) -> np.ndarray:
    """Gauss-Seidel sweeping the unknowns from last to first (the library's sweep on the reversed system)."""
    A = np.asarray(A, dtype=float)
    return _sweeps(fp.gauss_seidel, A[::-1, ::-1], np.asarray(b, dtype=float)[::-1],
                   np.asarray(x0, dtype=float)[::-1], sweeps)[::-1]


def _components_off(got, expected, names: str, what: str, hint: str) -> Result:
    """Name the components that are off and by how much (never where they should be)."""
    off = [f"{names[i]} is {off_by(got[i], expected[i])}" for i in range(len(expected))
           if abs(got[i] - expected[i]) > 1e-4]
    right = [names[i] for i in range(len(expected)) if abs(got[i] - expected[i]) <= 1e-4]
    lead = f"{' and '.join(right)} {'is' if len(right) == 1 else 'are'} right; " if right else ""
    return wrong(f"in {what}, {lead}{'; '.join(off)}. Check: {hint}.")


def _read_vector(answer, what: str, n: int):
    got, err = read_points(answer, what)
    if err is not None:
        return None, err
    if got.shape != (n,):
        return None, wrong(f"{what} is one list of {n} numbers; yours has shape {got.shape}.")
    return got, None


def _dominant_integer_system(rng, n: int):
    """A strictly diagonally dominant n x n system with small whole entries (hand-friendly)."""
    A = rng.integers(-2, 3, size=(n, n)).astype(float)
    np.fill_diagonal(A, 0.0)
    A += np.diag(np.abs(A).sum(axis=1) + rng.integers(1, 4, size=n))
    return _tuple2(A), tuple(float(v) for v in rng.integers(-9, 10, size=n))


def _sweep_formulas(A, b, names: str) -> str:
    """Each equation solved for its own unknown: "x = (9 - 2y)/5, y = (6 - x)/4"."""
    out = []
    for i, (row, rhs) in enumerate(zip(A, b)):
        num = fmt(rhs)
        for j, (c, v) in enumerate(zip(row, names)):
            if j == i or c == 0:
                continue
            term = v if abs(c) == 1 else f"{fmt(abs(c))}{v}"
            num += f" {'-' if c > 0 else '+'} {term}"
        num = f"({num})" if " " in num else num
        out.append(f"{names[i]} = {num}" + (f"/{fmt(row[i])}" if row[i] != 1 else ""))
    return ", ".join(out)


_STORED_SEIDEL = {"A": _tuple2(SEIDEL_A), "b": tuple(float(v) for v in SEIDEL_B)}


@memo
def _seidel_answers(p):
    A, b = _matrix(p["A"]), np.array(p["b"], dtype=float)
    zero = np.zeros(3)
    expected = _sweeps(fp.gauss_seidel, A, b, zero, 1)
    z_old_y = expected.copy()
    z_old_y[2] = (b[2] - A[2, 0] * expected[0]) / A[2, 2]
    slips = {"Jacobi": _sweeps(fp.jacobi, A, b, zero, 1), "z with the old y": z_old_y,
             "from z back to x": _backward_gauss_seidel(A, b, zero, 1), "the exact solution": np.linalg.solve(A, b)}
    return expected, slips


def _seidel_generate(rng) -> dict:
    A, b = _dominant_integer_system(rng, 3)
    return {"A": A, "b": b}


def _seidel_ok(p):
    A = _matrix(p["A"])
    if np.any(np.abs(np.diag(A)) <= np.abs(A).sum(axis=1) - np.abs(np.diag(A))):
        return "A is not strictly diagonally dominant"
    if not np.any(p["b"]):
        return "b is zero (every iterate is zero)"
    return None


def _seidel_statement(p) -> str:
    return (f"Do one Gauss-Seidel sweep (x, then y, then z) for {_system_text(_matrix(p['A']), p['b'], 'xyz')} "
            f"from (x, y, z) = (0, 0, 0): give the new [x, y, z] (Goldman §7.3.2).{_decimals(_seidel_answers(p)[0])}")


def _seidel_steps(p) -> str:
    A, b = _matrix(p["A"]), p["b"]
    x, y, z = _seidel_answers(p)[0]
    return (f"1. Solve each equation for its own unknown: {_sweep_formulas(A, b, 'xyz')}.\n"
            f"2. x with y = z = 0: x = {_r(x)}.\n"
            f"3. y with the new x and z = 0: y = {_r(y)}.\n"
            f"4. z with the new x and y: z = {_r(z)}.\n"
            f"So [x, y, z] = [{_r(x)}, {_r(y)}, {_r(z)}].")


@DECK.exercise(stored=_STORED_SEIDEL, generate=_seidel_generate, answer=lambda p: _seidel_answers(p)[0],
               slips=lambda p: _seidel_answers(p)[1], statement=_seidel_statement, steps=_seidel_steps,
               same=lambda a, b: bool(np.allclose(a, b, rtol=0, atol=1e-4)), well_posed=_seidel_ok)
def check_gauss_seidel_sweep(answer, p) -> Result:
    """Check one Gauss-Seidel sweep from 0 on the statement's system: x first, then y with the new
    x, then z with the new x and y (Goldman §7.3.2).

    Recognises the Jacobi step (no new value used), the new x used but not the new y, a sweep
    from the last unknown to the first, and the exact solution.
    """
    what = "the new [x, y, z]"
    got, err = _read_vector(answer, what, 3)
    if err is not None:
        return err
    expected, slips = _seidel_answers(p)
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"{what} is {fmt(expected)}: each new value is used at once.")
    if np.allclose(got, slips["Jacobi"], atol=1e-4):
        return wrong("that is the Jacobi step: every component computed from the old (0, 0, 0). Gauss-Seidel uses "
                     "each new value as soon as it is computed: the new x in the equation for y, the new x and y "
                     "in the one for z.")
    if np.allclose(got[:2], expected[:2], atol=1e-4) and not np.isclose(got[2], expected[2], atol=1e-4):
        if abs(got[2] - slips["z with the old y"][2]) <= 1e-4:
            return wrong("x and y are right, but z used the old y = 0; use the new y as well as the new x.")
        return wrong(f"x and y are right; z is {off_by(got[2], expected[2])}: solve the third equation for z "
                     f"with the new x and y.")
    if np.allclose(got, slips["from z back to x"], atol=1e-4):
        return wrong("that is a sweep from z back to x; the exercise sweeps x first, then y, then z.")
    if np.allclose(got, slips["the exact solution"], atol=1e-4):
        return wrong("that is the exact solution of the system; one sweep only gets part of the way there.")
    return _components_off(got, expected, "xyz", what,
                           "x from the first equation with y = z = 0, y from the second with the new x, "
                           "z from the third with the new x and y")


_STORED_JACOBI = {"A": _tuple2(JACOBI_A), "b": tuple(float(v) for v in JACOBI_B),
                  "x0": tuple(float(v) for v in JACOBI_X0)}


@memo
def _jacobi_answers(p):
    A, b, x0 = _matrix(p["A"]), np.array(p["b"], dtype=float), np.array(p["x0"], dtype=float)
    expected = _sweeps(fp.jacobi, A, b, x0, JACOBI_SWEEPS)
    slips = {"Gauss-Seidel": _sweeps(fp.gauss_seidel, A, b, x0, JACOBI_SWEEPS),
             "one Gauss-Seidel sweep": _sweeps(fp.gauss_seidel, A, b, x0, 1),
             "one Jacobi sweep": _sweeps(fp.jacobi, A, b, x0, 1), "the exact solution": np.linalg.solve(A, b)}
    return expected, slips


def _jacobi_generate(rng) -> dict:
    A, b = _dominant_integer_system(rng, 2)
    return {"A": A, "b": b, "x0": tuple(float(v) for v in rng.integers(-2, 3, size=2))}


def _jacobi_ok(p):
    A = _matrix(p["A"])
    if A[0, 1] == 0 or A[1, 0] == 0:
        return "the equations are uncoupled on one side (Jacobi and Gauss-Seidel agree)"
    if np.any(np.abs(np.diag(A)) <= np.abs(A[::-1].diagonal())):
        return "A is not strictly diagonally dominant"
    return None


def _jacobi_statement(p) -> str:
    return (f"Do {JACOBI_SWEEPS} Jacobi sweeps for {_system_text(_matrix(p['A']), p['b'], 'xy')} from "
            f"(x, y) = {fmt(p['x0'])}: give [x, y] after the second sweep (Goldman §7.3.2)."
            f"{_decimals(_jacobi_answers(p)[0])}")


def _jacobi_steps(p) -> str:
    A, b = _matrix(p["A"]), p["b"]
    first = _jacobi_answers(p)[1]["one Jacobi sweep"]
    second = _jacobi_answers(p)[0]
    return (f"1. Solve each equation for its own unknown: {_sweep_formulas(A, b, 'xy')}.\n"
            f"2. Sweep 1, both from (x, y) = {fmt(p['x0'])}: [{_r(first[0])}, {_r(first[1])}].\n"
            f"3. Sweep 2, both from the first sweep's values: [{_r(second[0])}, {_r(second[1])}].")


@DECK.exercise(stored=_STORED_JACOBI, generate=_jacobi_generate, answer=lambda p: _jacobi_answers(p)[0],
               slips=lambda p: _jacobi_answers(p)[1], statement=_jacobi_statement, steps=_jacobi_steps,
               same=lambda a, b: bool(np.allclose(a, b, rtol=0, atol=1e-4)), well_posed=_jacobi_ok)
def check_jacobi_sweeps(answer, p) -> Result:
    """Check two Jacobi sweeps on the statement's 2x2 system from its start (Goldman §7.3.2).

    Recognises the Gauss-Seidel iterate, one sweep only, and the exact solution.
    """
    what = "[x, y] after two sweeps"
    got, err = _read_vector(answer, what, 2)
    if err is not None:
        return err
    expected, slips = _jacobi_answers(p)
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"{what} is {fmt(expected)}.")
    if np.allclose(got, slips["Gauss-Seidel"], atol=1e-4):
        return wrong("that is the Gauss-Seidel iterate: you used the new x at once in the equation for y. Jacobi "
                     "computes both components of a sweep from the previous iterate only.")
    if np.allclose(got, slips["one Gauss-Seidel sweep"], atol=1e-4):
        return wrong("that is one Gauss-Seidel sweep (the new x used for y); Jacobi uses only the previous "
                     "iterate, and the exercise asks for two sweeps.")
    if np.allclose(got, slips["one Jacobi sweep"], atol=1e-4):
        return wrong("that is the iterate after one Jacobi sweep; do a second sweep from it.")
    if np.allclose(got, slips["the exact solution"], atol=1e-4):
        return wrong("that is the exact solution of the system; two sweeps only get part of the way there.")
    return _components_off(got, expected, "xy", what,
                           f"a Jacobi sweep is {_sweep_formulas(_matrix(p['A']), p['b'], 'xy')} with the previous "
                           f"x and y on the right")


# -- §7.3.3 ----------------------------------------------------------------------------------------

def _set_text(points) -> str:
    return "{" + ", ".join(fmt(q) for q in points) + "}"


_STORED_HAUSDORFF = {"A": _tuple2(HAUSDORFF_A), "B": _tuple2(HAUSDORFF_B)}


@memo
def _hausdorff_answers(p):
    A, B = _matrix(p["A"]), _matrix(p["B"])
    expected = fp.hausdorff_distance(A, B)
    a_to_b, b_to_a = fp.directed_hausdorff(A, B), fp.directed_hausdorff(B, A)
    pair = np.linalg.norm(A[:, None, :] - B[None, :, :], axis=-1)
    slips = {"one direction": min(a_to_b, b_to_a), "the closest pair": float(pair.min()),
             "the farthest pair": float(pair.max())}
    return expected, slips


def _hausdorff_generate(rng) -> dict:
    pts = rng.integers(-6, 13, size=(4, 2)).astype(float)
    return {"A": _tuple2(pts[:2]), "B": _tuple2(pts[2:])}


def _hausdorff_ok(p):
    A, B = _matrix(p["A"]), _matrix(p["B"])
    if np.array_equal(A[0], A[1]) or np.array_equal(B[0], B[1]):
        return "a set has the same point twice"
    return None


def _hausdorff_statement(p) -> str:
    return (f"Compute the Hausdorff distance h(A, B) between A = {_set_text(p['A'])} and "
            f"B = {_set_text(p['B'])} (Goldman §7.3.3).{_decimals(_hausdorff_answers(p)[0])}")


def _nearest_lines(X, Y, x_name, y_name) -> str:
    d = np.linalg.norm(X[:, None, :] - Y[None, :, :], axis=-1)
    parts = [f"{fmt(q)} is {_r(d[i].min(), 4)} from {fmt(Y[int(d[i].argmin())])}" for i, q in enumerate(X)]
    return f"From {x_name} to {y_name}: " + "; ".join(parts) + f"; the larger is {_r(d.min(axis=1).max(), 4)}."


def _hausdorff_steps(p) -> str:
    A, B = _matrix(p["A"]), _matrix(p["B"])
    return (f"1. {_nearest_lines(A, B, 'A', 'B')}\n"
            f"2. {_nearest_lines(B, A, 'B', 'A')}\n"
            f"3. h(A, B) is the larger of the two directions: {_r(_hausdorff_answers(p)[0], 4)}.")


@DECK.exercise(stored=_STORED_HAUSDORFF, generate=_hausdorff_generate, answer=lambda p: _hausdorff_answers(p)[0],
               slips=lambda p: _hausdorff_answers(p)[1], statement=_hausdorff_statement, steps=_hausdorff_steps,
               same=within(1e-4), well_posed=_hausdorff_ok)
def check_hausdorff(answer, p) -> Result:
    """Check the Hausdorff distance h(A, B) of the statement's two sets: the larger of the two
    one-sided distances (Goldman §7.3.3).

    Recognises one direction only, the closest pair, and the farthest pair.
    """
    value, problem = read_number(answer, "the Hausdorff distance")
    if problem is not None:
        return problem
    A, B = _matrix(p["A"]), _matrix(p["B"])
    expected, slips = _hausdorff_answers(p)
    if abs(value - expected) <= 1e-4:
        for X, Y, x_name, y_name in ((B, A, "B", "A"), (A, B, "A", "B")):
            d = np.linalg.norm(X[:, None, :] - Y[None, :, :], axis=-1).min(axis=1)
            if abs(d.max() - expected) <= 1e-12:
                far = X[int(d.argmax())]
                break
        return correct(f"the Hausdorff distance is {fmt(expected)}: the point {fmt(far)} of {x_name} is that far "
                       f"from {y_name}.")
    if abs(value - slips["one direction"]) <= 1e-4:
        short, long = ("A", "B") if fp.directed_hausdorff(A, B) <= fp.directed_hausdorff(B, A) else ("B", "A")
        return wrong(f"that is only the distance from {short} to {long} (how far a point of {short} is from its "
                     f"nearest point of {long}); the Hausdorff distance is the larger of the two directions: measure "
                     f"from {long} to {short} too.")
    if abs(value - slips["the closest pair"]) <= 1e-4:
        return wrong("that is the distance between the closest two points of A and B; the Hausdorff distance asks "
                     "how far the worst point of each set is from the nearest point of the other.")
    if abs(value - slips["the farthest pair"]) <= 1e-4:
        return wrong("that is the largest distance between any two points; the Hausdorff distance uses the "
                     "distance to the *nearest* point of the other set.")
    return check_number(value, expected, what="the Hausdorff distance", tol=1e-4,
                        hint="for each point, find its nearest point in the other set; take the largest of these")


_STORED_STRETCH = {"L": _tuple2(STRETCH_L), "t": (1.0, 2.0)}


@memo
def _stretch_answers(p):
    L = _matrix(p["L"])
    s = fp.contraction_factor(L)
    slips = {"the square": s * s, "the eigenvalue": float(max(abs(np.linalg.eigvals(L)))),
             "the determinant": abs(float(np.linalg.det(L))), "the Frobenius norm": float(np.linalg.norm(L)),
             "a column": float(np.linalg.norm(L, axis=0).max())}
    return s, slips


def _stretch_generate(rng) -> dict:
    a, b, d = (float(rng.integers(1, 10)) / 10 for _ in range(3))
    b *= float(rng.choice([-1.0, 1.0]))
    return {"L": ((a, b), (0.0, d)), "t": tuple(float(v) for v in rng.integers(-3, 4, size=2))}


def _stretch_ok(p):
    L = _matrix(p["L"])
    s = _stretch_answers(p)[0]
    if s >= 0.95:
        return "the map is not a contraction (or barely: the factor is 0.95 or more)"
    if abs(float(np.sqrt(abs(np.linalg.det(L)))) - s) <= 1e-4:
        return "the square root of the area factor equals the stretch"
    if any(abs(v - s) < 0.01 for v in _stretch_answers(p)[1].values()):
        return "a named slip lies within 0.01 of the answer (a wrong try would nearly give it)"
    if any(abs(float(np.sqrt(abs(np.linalg.det(L)))) - v) <= 1e-4 for v in _stretch_answers(p)[1].values()):
        return "the square root of the area factor equals a named slip"
    return None


def _map_text(p) -> str:
    (a, b), (_, d) = p["L"]
    second = f"{fmt(abs(b))} x {'+' if d >= 0 else '-'} {fmt(abs(d))} y"
    second = ("-" if b < 0 else "") + second
    return f"(x, y) -> ({fmt(a)} x, {second}) + {fmt(p['t'])}"


def _stretch_statement(p) -> str:
    (a, b), (c, d) = p["L"]
    return (f"The affine map {_map_text(p)} has linear part L = [[{fmt(a)}, {fmt(b)}], [{fmt(c)}, {fmt(d)}]] "
            "(rows: Q = P L). Give its contraction factor, the most it stretches any distance, max |v L| / |v|, "
            "to 4 decimals (Goldman §7.3.3).")


def _stretch_steps(p) -> str:
    L = _matrix(p["L"])
    G = L @ L.T
    tr, det = float(np.trace(G)), float(np.linalg.det(G))
    lam = (tr + math.sqrt(max(tr * tr - 4 * det, 0.0))) / 2
    return (f"1. The translation changes no distance; with row vectors |v L|^2 = v (L L^T) v^T, and L L^T = "
            f"[[{_r(G[0, 0])}, {_r(G[0, 1])}], [{_r(G[1, 0])}, {_r(G[1, 1])}]] (L^T L has the same eigenvalues).\n"
            f"2. Its largest eigenvalue, from trace {_r(tr)} and determinant {_r(det)}: "
            f"(trace + sqrt(trace^2 - 4 det))/2 = {_r(lam)}.\n"
            f"3. The contraction factor is its square root: {_stretch_answers(p)[0]:.4f}.")


@DECK.exercise(stored=_STORED_STRETCH, generate=_stretch_generate, answer=lambda p: _stretch_answers(p)[0],
               slips=lambda p: _stretch_answers(p)[1], statement=_stretch_statement, steps=_stretch_steps,
               same=within(1e-4), well_posed=_stretch_ok)
def check_contraction_factor(answer, p) -> Result:
    """Check the contraction factor of the statement's linear part L: the square root of the
    largest eigenvalue of L^T L (Goldman §7.3.3).

    Recognises the eigenvalue (the diagonal of a triangular L), the area factor (determinant),
    the Frobenius norm, the largest column length and a forgotten square root.
    """
    value, problem = read_number(answer, "the contraction factor")
    if problem is not None:
        return problem
    s, slips = _stretch_answers(p)
    tol = 1e-4
    if abs(value - s) <= tol:
        return correct(f"the contraction factor is {s:.4f}, more than either diagonal entry: a shearing map "
                       f"stretches some direction more than its eigenvalues say.")
    if abs(value - s * s) <= tol:
        return wrong(f"{fmt(value)} is the largest eigenvalue of L^T L, the square of the stretch; take its square root.")
    if abs(value - slips["the eigenvalue"]) <= tol:
        return wrong(f"{fmt(value)} is the largest eigenvalue of L (the diagonal of a triangular matrix); the stretch "
                     f"is the largest singular value, the square root of the largest eigenvalue of L^T L.")
    det = slips["the determinant"]
    if abs(value - det) <= tol or abs(value - math.sqrt(det)) <= tol:
        return wrong(f"{fmt(value)} comes from the determinant, the area factor; the contraction factor is the most "
                     f"the map stretches one distance.")
    if abs(value - slips["the Frobenius norm"]) <= tol:
        return wrong(f"{fmt(value)} is the Frobenius norm (root of the sum of squared entries), only an upper bound on "
                     f"the stretch; compute the largest eigenvalue of L^T L.")
    if abs(value - slips["a column"]) <= tol:
        return wrong(f"{fmt(value)} is the length of a column of L, the image of no vector; with Q = P L the images of "
                     f"(1, 0) and (0, 1) are the rows, and the most stretched direction is neither.")
    return check_number(value, s, what="the contraction factor", tol=tol,
                        hint="the square root of the largest eigenvalue of L^T L (trace and determinant give it)")


def _levels(s: float, h0: float, tol: float) -> int:
    """The smallest n with s^n h0 <= tol."""
    n = max(0, math.ceil(math.log(tol / h0) / math.log(s)))
    while s ** n * h0 > tol:
        n += 1
    while n > 0 and s ** (n - 1) * h0 <= tol:
        n -= 1
    return n


_STORED_LEVELS = {"factors": LEVEL_FACTORS, "h0": LEVEL_START_DISTANCE, "tol": LEVEL_TOL}


@memo
def _levels_answers(p):
    f, h0, tol = p["factors"], p["h0"], p["tol"]
    n = _levels(max(f), h0, tol)
    slips = {"the smallest factor": _levels(min(f), h0, tol), "the average factor": _levels(sum(f) / len(f), h0, tol),
             "h(A0, A) forgotten": _levels(max(f), 1.0, tol), "one too few": n - 1, "one too many": n + 1}
    return n, slips


def _levels_generate(rng) -> dict:
    factors = tuple(float(v) for v in rng.choice([0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.75, 0.8], size=3,
                                                   replace=False))
    return {"factors": factors, "h0": float(rng.integers(2, 11)), "tol": float(rng.choice([0.1, 0.05, 0.01, 0.001]))}


def _levels_ok(p):
    f, h0, tol = p["factors"], p["h0"], p["tol"]
    s = max(f)
    for k in range(0, 60):   # a power of s times h0 lying on the tolerance makes rounding decide
        if abs(s ** k * h0 - tol) <= 1e-9 * tol:
            return "s^n h(A0, A) hits the tolerance exactly for some n (rounding would decide)"
    if _levels(s, h0, tol) < 2:
        return "fewer than two levels are needed"
    return None


def _levels_statement(p) -> str:
    return (f"An IFS has three maps with contraction factors {', '.join(fmt(s) for s in p['factors'])}, and the start "
            f"set A0 is at Hausdorff distance {fmt(p['h0'])} from the attractor A. By the fractal theorem, "
            f"what is the smallest number of levels n that guarantees h(W^n(A0), A) <= {fmt(p['tol'])} "
            f"(Goldman §7.3.3)?")


def _levels_steps(p) -> str:
    f, h0, tol = p["factors"], p["h0"], p["tol"]
    s = max(f)
    n = _levels(s, h0, tol)
    x = math.log(tol / h0) / math.log(s)
    return (f"1. W contracts by the largest factor, s = {fmt(s)}: h(W^n(A0), A) <= s^n h(A0, A) = {fmt(s)}^n x {fmt(h0)}.\n"
            f"2. Solve {fmt(s)}^n x {fmt(h0)} <= {fmt(tol)}: n >= log({fmt(tol)}/{fmt(h0)}) / log({fmt(s)}) = {_r(x, 3)}.\n"
            f"3. Round up: n = {n} ({fmt(s)}^{n} x {fmt(h0)} = {s ** n * h0:.4g}, while {fmt(s)}^{n - 1} x {fmt(h0)} "
            f"= {s ** (n - 1) * h0:.4g}).")


@DECK.exercise(stored=_STORED_LEVELS, generate=_levels_generate, answer=lambda p: _levels_answers(p)[0],
               slips=lambda p: _levels_answers(p)[1], statement=_levels_statement, steps=_levels_steps,
               same=lambda a, b: a == b, well_posed=_levels_ok)
def check_levels_needed(answer, p) -> Result:
    """Check the smallest n with s^n h(A0, A) <= the statement's tolerance, s the largest factor of
    the maps (Goldman §7.3.3).

    Recognises the smallest or average factor used instead of the largest, the distance h(A0, A)
    forgotten, and a count one too small or too large.
    """
    value, problem = read_number(answer, "n")
    if problem is not None:
        return problem
    f, h0, tol = p["factors"], p["h0"], p["tol"]
    if value != int(value):
        return wrong(f"n counts levels, a whole number; you gave {fmt(value)}. Round up the n that solves "
                     f"s^n h(A0, A) = {fmt(tol)}.")
    v = int(value)
    if v < 0:
        return wrong(f"n counts levels, a whole number 0 or more; you gave {fmt(value)}.")
    s = max(f)
    n, slips = _levels_answers(p)
    if v == n:
        return correct(f"n is {n}: s = {fmt(s)} (the largest factor), and {fmt(s)}^{n} x {fmt(h0)} <= {fmt(tol)} "
                       f"while one level fewer is not enough.")
    if v == slips["the smallest factor"]:
        return wrong(f"{v} levels is what the smallest factor, {fmt(min(f))}, would need; the theorem's s "
                     f"is the largest factor of the maps (the slowest map sets the pace).")
    if v == slips["the average factor"]:
        return wrong(f"{v} levels is what the average factor would need; the theorem's s is the largest factor of "
                     f"the maps.")
    if v == slips["h(A0, A) forgotten"]:
        return wrong(f"{v} levels would do if A0 started at distance 1; the bound is s^n h(A0, A) with "
                     f"h(A0, A) = {fmt(h0)}.")
    if v < n:
        return wrong(f"with {v} levels the bound s^n h(A0, A) = {s ** v * h0:.4g} is still above {fmt(tol)}; "
                     f"{'one more level is' if v == n - 1 else 'more levels are'} needed.")
    return wrong(f"{v} levels are enough but not the fewest; find the smallest n with s^n h(A0, A) <= "
                 f"{fmt(tol)} (a logarithm, then round up).")


#: Deal another instance of an exercise (``deal("check_newton_step")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Every exercise of the chapter deals; the programming project (a function the learner writes,
#: checked on its own generated cases) has no number to deal.
PROBLEMS = DECK.problems()


# -- the programming project: Gauss-Seidel sweeps (§7.3.2) -------------------------------------------

def _dominant_system(rng, n: int, *, negative: bool = False):
    """A strictly diagonally dominant n x n system with small decimal entries."""
    A = np.round(rng.uniform(-2, 2, (n, n)), 1)
    np.fill_diagonal(A, 0.0)
    diag = np.abs(A).sum(axis=1) + np.round(rng.uniform(1, 3, n), 1)
    if negative:
        diag = diag * np.where(rng.uniform(size=n) < 0.5, -1.0, 1.0)
    A = A + np.diag(diag)
    b = np.round(rng.uniform(-9, 9, n), 1)
    return A, b


def gauss_seidel_project_cases() -> list[Case]:
    """The project's cases, generated from a fixed seed: sizes 1 to 6, zero and nonzero starts,
    zero, one and several sweeps, a negative diagonal, b = 0 and a start at the solution."""
    rng = np.random.default_rng(7)
    cases: list[Case] = []

    def add(A, b, x0, sweeps, kind, note=""):
        n = len(b)
        label = (f"{n}x{n} system{note}, {sweeps} sweep{'s' if sweeps != 1 else ''} from "
                 f"x0 = {fmt(x0)}")
        if n <= 3:
            label += f", A = [{'; '.join(fmt(r) for r in A)}], b = {fmt(b)}"
        cases.append(Case(label, (A, b, x0, sweeps), kind=kind))

    A, b = _dominant_system(rng, 3)
    add(A, b, np.zeros(3), 3, "")
    A, b = _dominant_system(rng, 2)
    add(A, b, np.zeros(2), 1, "")
    for n in (4, 5, 6):
        A, b = _dominant_system(rng, n)
        add(A, b, np.round(rng.uniform(-3, 3, n), 1), int(rng.integers(2, 6)), "")
    A, b = _dominant_system(rng, 1)
    add(A, b, np.zeros(1), 1, "1x1 systems")
    add(A, b, np.array([5.0]), 4, "1x1 systems")
    A, b = _dominant_system(rng, 3)
    add(A, b, np.array([1.0, -1.0, 2.0]), 0, "no sweeps (x0 returned)")
    A, b = _dominant_system(rng, 4, negative=True)
    add(A, b, np.zeros(4), 3, "negative diagonal entries", " with negative diagonal entries")
    A, _ = _dominant_system(rng, 3)
    add(A, np.zeros(3), np.array([2.0, -1.0, 0.5]), 3, "b = 0", " with b = 0")
    A = np.array([[4.0, -1.0, 0.0], [-1.0, 4.0, -1.0], [0.0, -1.0, 4.0]])
    add(A, A @ np.array([1.0, 2.0, 3.0]), np.array([1.0, 2.0, 3.0]), 2, "start at the solution",
        " started at its solution")
    A, b = _dominant_system(rng, 5)
    add(A, b, np.zeros(5), 25, "many sweeps")
    return cases


def _gauss_seidel_reference(A, b, x0, sweeps):
    return _sweeps(fp.gauss_seidel, A, b, x0, sweeps)


def _compare_gauss_seidel(got, expected, case) -> str | None:
    A, b, x0, sweeps = case.args
    arr = np.asarray(got, dtype=float)
    n = len(b)
    if arr.shape != (n,):
        return f"it should be one vector x of shape ({n},), like b; yours has shape {arr.shape}"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite values"
    tol = 1e-8 * (1.0 + float(np.abs(expected).max()))
    diff = float(np.abs(arr - expected).max())
    if diff <= tol:
        return None
    head = f"after {sweeps} sweep{'s' if sweeps != 1 else ''} your x differs from Gauss-Seidel's by {fmt(diff, 2)}"
    if sweeps >= 1 and np.allclose(arr, _sweeps(fp.jacobi, A, b, x0, sweeps), rtol=0, atol=tol):
        return f"{head} -- it matches the Jacobi iterate: use the new values as soon as they are computed"
    if sweeps >= 1 and np.allclose(arr, _sweeps(fp.gauss_seidel, A, b, x0, sweeps - 1), rtol=0, atol=tol):
        return f"{head} -- it matches the iterate after {sweeps - 1} sweep{'s' if sweeps - 1 != 1 else ''}: one sweep too few"
    if np.allclose(arr, _sweeps(fp.gauss_seidel, A, b, x0, sweeps + 1), rtol=0, atol=tol):
        return f"{head} -- it matches the iterate after {sweeps + 1} sweep{'s' if sweeps + 1 != 1 else ''}: one sweep too many"
    if sweeps >= 1 and np.allclose(arr, _backward_gauss_seidel(A, b, x0, sweeps), rtol=0, atol=tol):
        return f"{head} -- it matches sweeps from the last unknown to the first: update x[0] first, then x[1] and so on"
    A_, b_ = np.asarray(A, dtype=float), np.asarray(b, dtype=float)
    with_diagonal = np.array(x0, dtype=float)
    for _ in range(sweeps):
        for i in range(n):
            with_diagonal[i] = (b_[i] - A_[i] @ with_diagonal) / A_[i, i]
    if sweeps >= 1 and np.all(np.isfinite(with_diagonal)) and np.allclose(arr, with_diagonal, rtol=0, atol=tol):
        return f"{head} -- your sum includes the diagonal term a_ii x_i: the sum is over j != i only"
    exact = np.linalg.solve(A_, b_)
    if sweeps < 25 and np.allclose(arr, exact, rtol=0, atol=tol):
        return (f"{head} -- it is the exact solution of A x = b: return the iterate after exactly {sweeps} "
                f"sweep{'s' if sweeps != 1 else ''}, not the limit")
    k = int(np.argmax(np.abs(arr - expected) > tol))
    return (f"{head}; the first wrong component is x[{k}], expected {fmt(expected, 6)}; "
            f"x[i] = (b[i] - sum of A[i, j] x[j] over j != i) / A[i, i]")


def check_gauss_seidel_project(function) -> Result:
    """Check the learner's ``gauss_seidel(A, b, x0, sweeps)`` against the library's Gauss-Seidel
    (:func:`goldman_lib.fixed_point.gauss_seidel`) on :func:`gauss_seidel_project_cases`: the x
    after exactly ``sweeps`` sweeps (Goldman §7.3.2).

    >>> def lazy(A, b, x0, sweeps):
    ...     return x0
    >>> print(check_gauss_seidel_project(lazy).message)   # doctest: +ELLIPSIS
    case 1 of 12 (3x3 system, 3 sweeps from x0 = (0, 0, 0), ...): your function returned (0, 0, 0); after 3 sweeps your x differs from Gauss-Seidel's by ...
    """
    return check_project(function, gauss_seidel_project_cases(), reference=_gauss_seidel_reference,
                         compare=_compare_gauss_seidel, what="gauss_seidel",
                         hint="sweep i = 0, 1, ..., n-1 and overwrite x[i] in place, so later rows see it")


SLIPS = {
    "check_fixed_point_limit": [-2, math.sqrt(6), math.sqrt(6 + math.sqrt(6))],
    "check_newton_step": [13 / 6, 10 ** (1 / 3), 1.6],
    "check_gauss_seidel_sweep": [[2, 1.4, 4 / 3], [2, 1, 2 / 3], [1.45, 13 / 15, 4 / 3]],
    "check_jacobi_sweeps": [[1.34, 1.165], [1.4, 1.25], [1.4, 1.15], [4 / 3, 7 / 6]],
    "check_hausdorff": [5, 3, math.hypot(12, 6)],
    "check_contraction_factor": [0.45, 0.5, 0.15, math.sqrt(0.5), math.hypot(0.4, 0.5)],
    "check_levels_needed": [9, 13, 17, 20, 22],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
