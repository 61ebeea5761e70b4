"""Exercise checkers for chapter 6, fractals from iterated function systems (Goldman §6.1-6.4),
and the checker of its programming project (write the IFS of a grid fractal).

Each checker recognises the usual slips (turning the wrong way, one level too many or too few,
counting copies instead of points, the maps in reverse order, forgetting the condensation set's
earlier copies) and names the misconception; it says how far off an answer is, never what the
answer is.  ``None`` or ``...`` means "not answered yet".

>>> print(PROBLEMS["check_fixed_point"])
The map w(P) = P L + (5, 0), where L turns by 90 degrees counterclockwise and halves, (x, y) L = (-y/2, x/2), is a contraction. Find its fixed point P = w(P) as [x, y] (Goldman §6.2).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import affine, ifs
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, memo
from goldman_lib.exercises.projects import Case, check_project
from goldman_lib.fixed_point import hausdorff_distance

__all__ = ["PROBLEMS", "SLIPS", "HALF_TURN", "ITERATE_START", "ITERATE_STEPS", "CARPET_LEVEL", "FIXED_POINT_MAP",
           "CHAOS_CORNERS", "CHAOS_START", "CHAOS_SEQUENCE", "TREE_MAPS", "TREE_LEVEL", "PROJECT_SEED", "DECK", "deal", "steps", "current", "deal_button",
           "check_iterate_map", "check_carpet_points", "check_fixed_point", "check_chaos_game_steps",
           "check_tree_branches", "check_grid_fractal_project", "grid_fractal_cases"]

#: Exercises 1 and 3: the linear map "turn by 90 degrees counterclockwise and halve", (x, y) -> (-y/2, x/2).
HALF_TURN = affine.rotation(90) @ affine.scaling(0.5)
#: Exercise 1: iterate HALF_TURN this many times from this point.
ITERATE_START, ITERATE_STEPS = (8.0, 0.0), 3
#: Exercise 2: the Sierpinski carpet's deterministic algorithm from the unit square's closed polyline.
CARPET_LEVEL = 3
#: Exercise 3: w(P) = P L + (5, 0) with L = HALF_TURN.
FIXED_POINT_MAP = HALF_TURN @ affine.translation([5.0, 0.0])
#: Exercise 4: the chaos game on the gasket with these corners; map i (1-based) halves the way to corner i.
CHAOS_CORNERS = ((0.0, 0.0), (4.0, 0.0), (0.0, 4.0))
CHAOS_START, CHAOS_SEQUENCE = (0.0, 0.0), (2, 3, 3, 1)
#: Exercise 5: a tree with a trunk as condensation set and this many maps; trunk copies in A_TREE_LEVEL.
TREE_MAPS, TREE_LEVEL = 3, 4

DECK = Deck("ch06")

_TIMES = {1: "once", 2: "twice", 3: "three times", 4: "four times", 5: "five times", 6: "six times"}


def _close(a, b) -> bool:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and bool(np.allclose(a, b, atol=1e-6, rtol=1e-4))


def _equal(a, b) -> bool:
    return float(a) == float(b)


def _read_point(answer, what, ask) -> tuple[np.ndarray | None, Result | None]:
    got, problem = read_points(answer, "your point", ask=ask)
    if problem is not None:
        return None, problem
    if got.shape != (2,):
        return None, wrong(f"{what} is one point [x, y]; yours has shape {got.shape}.")
    return got, None


def _check_point(answer, what, right, slips, hint) -> Result:
    got, problem = _read_point(answer, what, f"{what} as [x, y]")
    if problem is not None:
        return problem
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"{what} is {fmt(right)}.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    return wrong(f"{what} is {far_off(got, right)}. Hint: {hint}.")


# -- exercise answers and slips ---------------------------------------------------------------------

def _iterate(M, P, n) -> np.ndarray:
    return ifs.iterate_map(M, [P], n)[-1, 0]


_STORED_ITERATE = {"start": ITERATE_START, "steps": ITERATE_STEPS}


@memo
def _iterate_answers(p):
    P, n = np.array(p["start"]), p["steps"]
    right = _iterate(HALF_TURN, P, n)
    clockwise = affine.rotation(-90) @ affine.scaling(0.5)
    slips = {
        "turns clockwise; a positive angle turns counterclockwise: (x, y) -> (-y, x) before halving.":
            _iterate(clockwise, P, n),
        "turns but does not halve: each step also shrinks the distance to the origin by half.":
            _iterate(affine.rotation(90), P, n),
        "halves but does not turn: each step also turns by 90 degrees.": _iterate(affine.scaling(0.5), P, n),
        f"is one step short: w^{n} applies w {_TIMES[n]} (count the arrows P -> w(P) -> ...).":
            _iterate(HALF_TURN, P, n - 1),
        f"is one step too many: w^{n} applies w {_TIMES[n]}.": _iterate(HALF_TURN, P, n + 1),
    }
    return right, slips


def _iterate_generate(rng) -> dict:
    n = int(rng.integers(2, 6))
    return {"start": tuple(float(v) * 2 ** n for v in rng.integers(-2, 3, size=2)), "steps": n}


def _nested(n: int) -> str:
    return "w(" * n + "P" + ")" * n


def _iterate_statement(p) -> str:
    n = p["steps"]
    return (f"The map w turns every point by 90 degrees counterclockwise about the origin and halves it: "
            f"w(x, y) = (-y/2, x/2). Where is w^{n}(P) = {_nested(n)} for P = {fmt(p['start'])}? "
            f"Answer [x, y] (Goldman §6.1).")


def _iterate_steps(p) -> str:
    P, n = np.array(p["start"]), p["steps"]
    pts = ifs.iterate_map(HALF_TURN, [P], n)[:, 0]
    chain = " -> ".join(fmt(np.round(q, 9) + 0.0) for q in pts)
    return (f"1. One step: (x, y) -> (-y/2, x/2).\n"
            f"2. Apply it {_TIMES[n]}: {chain}.\n"
            f"3. (Or at once: w^{n} turns by {90 * n} degrees and scales by 1/{2 ** n}.)")


@DECK.exercise(stored=_STORED_ITERATE, generate=_iterate_generate, answer=lambda p: _iterate_answers(p)[0],
               slips=lambda p: _iterate_answers(p)[1], statement=_iterate_statement, steps=_iterate_steps,
               same=_close, well_posed=lambda p: None if any(p["start"]) else "P is the fixed point")
def check_iterate_map(answer, p) -> Result:
    """Exercise 1: ``w^n(P)`` for the half turn ``w(x, y) = (-y/2, x/2)`` and the statement's P and n
    (Goldman §6.1).  answer: ``[x, y]``.
    """
    right, slips = _iterate_answers(p)
    n = p["steps"]
    return _check_point(answer, f"w^{n}(P)", right, slips,
                        f"apply w {_TIMES[n]}, one step at a time: (x, y) -> (-y/2, x/2)")


# -- exercise 2: the carpet's points ------------------------------------------------------------------

def _carpet_slips(p) -> dict:
    n = p["level"]
    return {
        "counts the copies of the square; each copy has 5 points (a closed polyline repeats its first point).":
            8 ** n,
        "counts 4 corners a copy; the closed polyline has 5 points (it repeats its first point), and every point is "
        "copied.": 4 * 8 ** n,
        "adds the maps level by level; each level applies all 8 maps to EVERY point, so the count multiplies by 8 "
        "each level.": 5 * 8 * n,
        "counts every level's points together; without a condensation set the algorithm keeps only the last level.":
            5 * sum(8 ** j for j in range(n + 1)),
        "is one level short: level 0 is the square itself, level 1 its 8 copies.": 5 * 8 ** (n - 1),
    }


def _carpet_statement(p) -> str:
    return (f"The deterministic algorithm draws the Sierpinski carpet (8 maps) starting from the unit square as a closed "
            f"polyline of 5 points, (0, 0), (1, 0), (1, 1), (0, 1), (0, 0). How many points does it return at level "
            f"{p['level']} (no condensation set) (Goldman §6.1, §6.3)?")


def _carpet_steps(p) -> str:
    n = p["level"]
    return (f"1. Level 0 is the start polyline: 5 points.\n"
            f"2. Each level applies all 8 maps to every point of the level before: the count is multiplied by 8.\n"
            f"3. Level {n}: 5 * 8^{n} = {5 * 8 ** n} points (only the last level is kept).")


@DECK.exercise(stored={"level": CARPET_LEVEL}, generate=lambda rng: {"level": int(rng.integers(2, 6))},
               answer=lambda p: 5 * 8 ** p["level"], slips=_carpet_slips, statement=_carpet_statement,
               steps=_carpet_steps, same=_equal)
def check_carpet_points(answer, p) -> Result:
    """Exercise 2: points returned by the deterministic algorithm for the carpet at the statement's
    level from the 5-point square (Goldman §6.1, §6.3): each level applies every map to every point.
    """
    value, problem = read_number(answer, "the number of points")
    if problem is not None:
        return problem
    right = 5 * 8 ** p["level"]
    if value == right:
        return correct(f"the number of points is {right}.")
    slips = {v: why for why, v in _carpet_slips(p).items()}
    if value in slips:
        return wrong(f"{fmt(value)} {slips[value]}")
    return wrong(f"the number of points is {off_by(value, right)}. Hint: level n holds 8^n copies of the start "
                 f"polyline.")


# -- exercise 3: a fixed point ----------------------------------------------------------------------

def _fixed_map(p) -> np.ndarray:
    return HALF_TURN @ affine.translation(list(p["t"]))


@memo
def _fixed_answers(p):
    M = _fixed_map(p)
    right = affine.fixed_point(M)
    t = M[2, :2]
    L = M[:2, :2]
    slips = {
        "is w applied once to the origin, the first step of the iteration; the fixed point is its limit: solve "
        "P = P L + t, i.e. P (I - L) = t.": t,
        "is t (I - L); the fixed point solves P (I - L) = t, so multiply t by the INVERSE of (I - L).": t @ (np.eye(2) - L),
        "ignores the turn: with L = I/2 the fixed point would be t / (1 - 1/2), but L also turns by 90 degrees.": 2 * t,
        "solves the equation with the clockwise turn (the transposed L, as if points were column vectors); "
        "(x, y) L = (-y/2, x/2).": t @ np.linalg.inv(np.eye(2) - L.T),
    }
    return right, slips


def _plus(v: float) -> str:
    return "" if v == 0 else f" {'+' if v > 0 else '-'} {fmt(abs(v))}"


def _fixed_statement(p) -> str:
    return (f"The map w(P) = P L + {fmt(p['t'])}, where L turns by 90 degrees counterclockwise and halves, "
            f"(x, y) L = (-y/2, x/2), is a contraction. Find its fixed point P = w(P) as [x, y] (Goldman §6.2).")


def _fixed_steps(p) -> str:
    t = np.array(p["t"])
    right = _fixed_answers(p)[0]
    return (f"1. P = w(P) reads x = -y/2{_plus(t[0])} and y = x/2{_plus(t[1])}, that is P (I - L) = t with "
            f"t = {fmt(t)}.\n"
            f"2. I - L has rows (1, -1/2), (1/2, 1), determinant 5/4; P = t (I - L)^-1.\n"
            f"3. P = {fmt(np.round(right, 9) + 0.0)} (check: w moves it by nothing).")


@DECK.exercise(stored={"t": (5.0, 0.0)}, generate=lambda rng: {"t": _ints(rng, -5, 5, 2)},
               answer=lambda p: _fixed_answers(p)[0], slips=lambda p: _fixed_answers(p)[1],
               statement=_fixed_statement, steps=_fixed_steps, same=_close,
               well_posed=lambda p: None if any(p["t"]) else "t = 0: the fixed point is the origin")
def check_fixed_point(answer, p) -> Result:
    """Exercise 3: the fixed point of ``w(P) = P L + t`` with ``L`` the half turn and the statement's
    t (Goldman §6.2): solve ``P (I - L) = t``.  answer: ``[x, y]``.

    >>> print(check_fixed_point([5, 0]).message)
    your point is w applied once to the origin, the first step of the iteration; the fixed point is its limit: solve P = P L + t, i.e. P (I - L) = t.
    """
    right, slips = _fixed_answers(p)
    got, problem = _read_point(answer, "the fixed point of w", "the fixed point of w as [x, y]")
    if problem is not None:
        return problem
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"the fixed point of w is {fmt(right)}.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    t = p["t"]
    moved = np.linalg.norm(affine.apply(got, _fixed_map(p)) - got)
    return wrong(f"w moves your point by {fmt(moved, 2)}, so it is not fixed. Hint: write P = (x, y); "
                 f"P = w(P) gives x = -y/2{_plus(t[0])} and y = x/2{_plus(t[1])}, two equations for x and y.")


# -- exercise 4: the chaos game by hand ----------------------------------------------------------------

_STORED_CHAOS = {"start": CHAOS_START, "sequence": CHAOS_SEQUENCE}


@memo
def _chaos_answers(p):
    C = np.array(CHAOS_CORNERS)
    sequence = tuple(p["sequence"])

    def play(seq, start=p["start"]):
        P = np.array(start, dtype=float)
        for i in seq:
            P = (P + C[i - 1]) / 2
        return P

    right = play(sequence)
    slips = {
        "is the point after the maps in reverse order; the first map picked is applied first.": play(sequence[::-1]),
        "is one step short: apply all the maps picked, the last one too.": play(sequence[:-1]),
        "jumps to the corner; each map moves the point only HALFWAY to its corner, to the midpoint of P and the "
        "corner.":
            C[sequence[-1] - 1],
        "averages the corners picked; each step halves the way from the CURRENT point to the corner.":
            C[[i - 1 for i in sequence]].mean(axis=0),
    }
    return right, slips


def _chaos_generate(rng) -> dict:
    start = tuple(float(v) for v in rng.integers(0, 3, size=2))
    return {"start": start, "sequence": tuple(int(i) for i in rng.integers(1, 4, size=int(rng.integers(3, 6))))}


def _chaos_statement(p) -> str:
    seq = p["sequence"]
    return (f"The chaos game on the Sierpinski gasket with corners {', '.join(fmt(c) for c in CHAOS_CORNERS)}: map i "
            f"moves a point halfway to corner i (i = 1, 2, 3). Starting at {fmt(p['start'])}, the game picks the maps "
            f"{', '.join(str(i) for i in seq)}, in that order. Where is the point after these "
            f"{len(seq)} steps? Answer [x, y] (Goldman §6.3).")


def _chaos_steps(p) -> str:
    C = np.array(CHAOS_CORNERS)
    P = np.array(p["start"], dtype=float)
    lines = []
    for k, i in enumerate(p["sequence"], 1):
        Q = (P + C[i - 1]) / 2
        lines.append(f"{k}. map {i}: the midpoint of {fmt(P)} and {fmt(C[i - 1])} is {fmt(Q)}.")
        P = Q
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_CHAOS, generate=_chaos_generate, answer=lambda p: _chaos_answers(p)[0],
               slips=lambda p: _chaos_answers(p)[1], statement=_chaos_statement, steps=_chaos_steps, same=_close)
def check_chaos_game_steps(answer, p) -> Result:
    """Exercise 4: the chaos game by hand on the gasket :data:`CHAOS_CORNERS` with the statement's
    start and maps (Goldman §6.3).  answer: ``[x, y]``.
    """
    right, slips = _chaos_answers(p)
    return _check_point(answer, f"the point after the {len(p['sequence'])} steps", right, slips,
                        "each step replaces the point P by the midpoint of P and the corner of the map picked")


# -- exercise 5: a tree's trunks ------------------------------------------------------------------------

def _tree_total(k, level):
    return sum(k ** j for j in range(level + 1))


def _tree_slips(p) -> dict:
    k, n = p["maps"], p["level"]
    return {
        f"counts only the newest, smallest trunks ({k}^{n}); the condensation set keeps a copy of every "
        f"earlier level too.": k ** n,
        f"is {k}^{n + 1}: the trunks do not multiply like the points of a fractal without condensation; "
        f"add the copies level by level.": k ** (n + 1),
        "is one level short: A_0 is the trunk alone and each level adds a new generation of smaller "
        "trunks.": _tree_total(k, n - 1),
        "is one level too many: A_0 is the trunk alone (one trunk).": _tree_total(k, n + 1),
        f"is the count for a tree with 2 maps; this tree has {k} maps, so each generation has {k} times "
        f"as many trunks as the one before.": 2 ** (n + 1) - 1,
    }


def _tree_statement(p) -> str:
    k, n = p["maps"], p["level"]
    union = " ∪ ".join(f"w_{i}(A_n)" for i in range(1, k + 1))
    return (f"A tree has a trunk as condensation set C and {k} maps, each shrinking the tree onto a branch: "
            f"A_0 = C and A_(n+1) = C ∪ {union}. How many copies of the trunk does "
            f"A_{n} hold (Goldman §6.4)?")


def _tree_steps(p) -> str:
    k, n = p["maps"], p["level"]
    terms = " + ".join(f"{k}^{j}" for j in range(n + 1))
    return (f"1. A_0 is one trunk. Each level keeps the trunk C and maps the whole tree by each of the {k} maps.\n"
            f"2. So generation j adds {k}^j trunks, and A_{n} holds {terms}.\n"
            f"3. = ({k}^{n + 1} - 1)/({k} - 1) = {_tree_total(k, n)}.")


@DECK.exercise(stored={"maps": TREE_MAPS, "level": TREE_LEVEL},
               generate=lambda rng: {"maps": int(rng.integers(3, 6)), "level": int(rng.integers(2, 7))},
               answer=lambda p: _tree_total(p["maps"], p["level"]), slips=_tree_slips, statement=_tree_statement,
               steps=_tree_steps, same=_equal)
def check_tree_branches(answer, p) -> Result:
    """Exercise 5: trunk copies in ``A_n`` of a tree with the statement's number of maps and a trunk
    as condensation set (Goldman §6.4): each generation adds the images of the last one.
    """
    value, problem = read_number(answer, "the number of trunks")
    if problem is not None:
        return problem
    k, n = p["maps"], p["level"]
    right = _tree_total(k, n)
    if value == right:
        return correct(f"the number of trunks is {right}.")
    slips = {v: why for why, v in _tree_slips(p).items()}
    if value in slips:
        return wrong(f"{fmt(value)} {slips[value]}")
    return wrong(f"the number of trunks is {off_by(value, right)}. Hint: generation j adds {k}^j trunks.")


#: Deal another instance of an exercise (``deal("check_fixed_point")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems()


# -- the programming project: the IFS of a grid fractal -----------------------------------------------

#: The seed of the project's generated cases.
PROJECT_SEED = 6
_BOX = [(0, 0), (2, 0), (1, 1), (0, 2), (2, 2)]
_CARPET = [(i, j) for i in range(3) for j in range(3) if (i, j) != (1, 1)]
_ELL = [(0, 0), (1, 0), (2, 0), (0, 1)]


def grid_fractal_cases() -> list[Case]:
    """The project's cases: the box fractal, the carpet, an uneven "L" (asymmetric in the
    diagonal, so it tells (i, j) from (j, i)), squares away from the origin and of other sizes, and the degenerate patterns (one cell:
    the attractor is a point; all nine cells: the whole square); then random squares and patterns
    from :data:`PROJECT_SEED`."""
    rng = np.random.default_rng(PROJECT_SEED)

    def case(corner, side, cells, kind):
        corner = tuple(float(c) for c in corner)
        cells = [tuple(int(v) for v in c) for c in cells]
        return Case(f"corner {fmt(corner)}, side {fmt(side)}, cells {cells}", (corner, float(side), cells), kind=kind)

    cases = [case((0, 0), 1, _BOX, "the box fractal on the unit square"),
             case((2, 1), 3, _CARPET, "the carpet away from the origin"),
             case((0, 0), 1, _ELL, "an asymmetric pattern"),
             case((-1.5, 2), 0.75, [(2, 1), (0, 1), (1, 2), (0, 0)], "an asymmetric pattern"),
             case((3, -2), 2, [(1, 2)], "degenerate: one cell (the attractor is a point)"),
             case((-4, -4), 9, [(i, j) for i in range(3) for j in range(3)], "degenerate: all nine cells"),
             case((0.5, 0.25), 1e-3, _ELL[::-1], "a tiny square")]
    all_cells = [(i, j) for i in range(3) for j in range(3)]
    for _ in range(5):
        k = int(rng.integers(2, 9))
        pick = sorted(rng.choice(9, size=k, replace=False).tolist())
        corner = np.round(rng.uniform(-5, 5, size=2), 2)
        side = round(float(rng.uniform(0.5, 4.0)), 2)
        cases.append(case(corner, side, [all_cells[p] for p in pick], "random squares and patterns"))
    return cases


def _reference(corner, side, cells):
    return list(ifs.grid_fractal(cells, corner=corner, side=side).maps)


def _level(k: int) -> int:
    """The deterministic level compared: as deep as about 2000 points allow."""
    return 1 if k == 1 else min(10, int(math.log(2000) / math.log(k)))


def _compare_ifs(got, expected, case) -> str | None:
    corner, side, cells = case.args
    arr = got.maps if isinstance(got, ifs.IFS) else np.asarray(got, dtype=float)
    exp = np.asarray(expected, dtype=float)
    if arr.ndim != 3 or arr.shape[1:] != (3, 3):
        return (f"it should be a list of 3x3 matrices, one per kept cell; it has shape {arr.shape}"
                + (" (a list of 2x2 linear parts? the translation needs the 3x3 matrix)" if arr.shape[1:] == (2, 2)
                   else ""))
    if len(arr) != len(exp):
        return f"it has {len(arr)} maps; {len(exp)} cells are kept, and each needs its own map"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite entries"
    for i, M in enumerate(arr):
        if not np.allclose(M[:, 2], [0, 0, 1], atol=1e-9):
            return (f"map {i} has last column {fmt(M[:, 2])}; in the row-vector convention the last column is "
                    f"(0, 0, 1) and the translation is the last row (is it the column-vector matrix, transposed?)")
    factors = np.linalg.svd(arr[:, :2, :2], compute_uv=False)[:, 0]
    if np.any(factors >= 1):
        i = int(np.argmax(factors >= 1))
        return (f"map {i} stretches distances by up to {fmt(factors[i], 3)}; every map of an IFS must shrink "
                f"(factor below 1), and these should shrink the square by 1/3")
    level = _level(len(exp))
    tol = 3.0 * side * 3.0 ** -level
    mine = ifs.deterministic(ifs.IFS(arr), level)
    target = ifs.deterministic(ifs.IFS(exp), level)
    h = hausdorff_distance(mine, target)
    if h <= tol:
        return None
    swapped = ifs.deterministic(ifs.grid_fractal([(j, i) for i, j in cells], corner=corner, side=side), level)
    if hausdorff_distance(mine, swapped) <= tol:
        return ("its attractor is the fractal mirrored in the diagonal: cell (i, j) is column i (x) and row j (y), "
                "so its map translates by (i, j) * side/3, not (j, i) * side/3")
    about_origin = ifs.deterministic(ifs.grid_fractal(cells, corner=(0.0, 0.0), side=side), level)
    if hausdorff_distance(mine, about_origin) <= tol:
        return ("its attractor sits on the square with corner (0, 0): the maps must scale about the square's corner "
                f"{fmt(corner)} (or translate by the corner's share, corner * 2/3, too)")
    full_corner = ifs.deterministic(ifs.IFS([affine.scaling(1.0 / 3.0) @ affine.translation(
        np.asarray(corner, float) + np.array([i, j]) * side / 3.0) for i, j in cells]), level)
    if hausdorff_distance(mine, full_corner) <= tol:
        return ("its maps scale about (0, 0) and then translate by the whole corner: the scaling has moved the "
                "corner to corner/3 already, so the translation is corner * 2/3 + (i, j) * side/3 (or scale about "
                "the corner itself)")
    shrink = affine.scaling(1.0 / 3.0, center=corner)
    translate_first = ifs.deterministic(ifs.IFS([affine.translation(np.array([i, j]) * side / 3.0) @ shrink
                                                 for i, j in cells]), level)
    if hausdorff_distance(mine, translate_first) <= tol:
        return ("its maps translate first and then scale, so the translation shrinks by 1/3 too: with row vectors "
                "the map applied first is the LEFT factor, scaling @ translation")
    from goldman_lib.fixed_point import directed_hausdorff
    far = directed_hausdorff(mine, target)
    if far > tol:
        d = np.min(np.linalg.norm(mine[:, None, :] - target[None, :: max(1, len(target) // 500), :], axis=2), axis=1)
        p = mine[int(np.argmax(d))]
        return (f"its attractor is {fmt(h, 2)} from the fractal (Hausdorff distance, level {level}; up to "
                f"{fmt(tol, 2)} is drawing error): your point {fmt(p)} is {fmt(far, 2)} from the fractal")
    return (f"its attractor misses part of the fractal: it is {fmt(h, 2)} from it (Hausdorff distance, level "
            f"{level}; up to {fmt(tol, 2)} is drawing error): check that every kept cell gets its own map")


def check_grid_fractal_project(function) -> Result:
    """The programming project: ``function(corner, side, cells)`` returns the IFS of the grid fractal
    of :func:`goldman_lib.ifs.grid_fractal` as a list of 3x3 matrices (row-vector convention, one
    per kept cell).  Checked on :func:`grid_fractal_cases`: the shape, the number of maps, the last
    column ``(0, 0, 1)``, that each map is a contraction, and that the attractor (the deterministic
    algorithm's points at a fixed level) is within drawing error of the target's (Hausdorff
    distance).  Any maps with that attractor are right, in any order.

    >>> def linear_only(corner, side, cells):
    ...     return [np.eye(2) / 3 for _ in cells]
    >>> print(check_grid_fractal_project(linear_only).message)   # doctest: +ELLIPSIS
    case 1 of 12 (...): ... (a list of 2x2 linear parts? the translation needs the 3x3 matrix). Hint: ...
    """
    return check_project(function, grid_fractal_cases(), reference=_reference, compare=_compare_ifs,
                         what="the grid-fractal IFS",
                         hint="the map for cell (i, j) scales by 1/3 about the square's corner, then translates by "
                              "(i, j) * side/3; with row vectors the map applied first is the left factor")


#: Wrong answers of the kinds each checker recognises (tests feed them and check the message).
SLIPS = {
    "check_iterate_map": [v.tolist() for v in _iterate_answers(_STORED_ITERATE)[1].values()],
    "check_carpet_points": [8 ** 3, 4 * 8 ** 3, 5 * 8 * 3, 5 * (1 + 8 + 64 + 512), 5 * 64],
    "check_fixed_point": [v.tolist() for v in _fixed_answers({"t": (5.0, 0.0)})[1].values()],
    "check_chaos_game_steps": [v.tolist() for v in _chaos_answers(_STORED_CHAOS)[1].values()],
    "check_tree_branches": [81, 243, 40, 364, 31],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
