"""Exercise checkers for chapter 18, surfaces: the general theory (Goldman §18.1-18.4).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The chapter's "show that" exercises (7 and 8,
in :mod:`goldman_lib.exercises.proofs`) ask for an expression, not a number, so they do not deal.
``SLIPS`` holds the wrong answers each checker recognises, for the stored instance.  ``None`` or
``...`` means "not answered yet".  Every exercise uses other surfaces, points and radii than the
chapter's worked examples.

>>> print(PROBLEMS["check_cylinder_curvature"])   # doctest: +ELLIPSIS
A circular cylinder has radius 2.5. ...
>>> check_cylinder_curvature([0.16, 0.4])
Not yet: those are a sphere's values: a cylinder is straight along its axis, so one of its principal curvatures vanishes; K is their product and H their average.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import surfaces as sf
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.deal import Deck, memo, within

__all__ = ["PROBLEMS", "SLIPS", "IMPLICIT_POINT", "GRAPH_UV", "DEFORM_NORMAL", "NEWTON_START", "NEWTON_ORIGIN",
           "NEWTON_DIRECTION", "CYLINDER_RADIUS", "TORUS_R", "TORUS_r", "TORUS_V", "DECK", "deal", "steps",
           "current", "deal_button",
           "check_implicit_normal", "check_parametric_normal", "check_deformed_normal", "check_newton_step",
           "check_cylinder_curvature", "check_torus_curvature"]

#: Exercise 1 (§18.2): F(x, y, z) = x^2 + 2 y^2 - z^2 - 1 at a point on it.
IMPLICIT_POINT = (1.0, 1.0, math.sqrt(2.0))
#: Exercise 2 (§18.2): X(u, v) = (u, v, u^2 v) at (u, v).
GRAPH_UV = (1.0, 2.0)
#: Exercise 3 (§18.2): A(x, y, z) = (x + 2 z, 3 y, z) and a unit normal of the surface before the map.
DEFORM_NORMAL = (1 / math.sqrt(3), 1 / math.sqrt(3), 1 / math.sqrt(3))
#: Exercise 4 (§18.3): the ray O + t d and the surface X(u, v) = (u, v, 1 - u^2 - v^2); Newton's start.
NEWTON_ORIGIN = (0.0, 0.0, 3.0)
NEWTON_DIRECTION = (0.0, 0.0, -1.0)
NEWTON_START = (1.0, 0.5, 0.5)
#: Exercise 5 (§18.4): the radius of a cylinder.
CYLINDER_RADIUS = 2.5
#: Exercise 6 (§18.4): a torus and the angle v (degrees) of the point on its tube.
TORUS_R, TORUS_r, TORUS_V = 3.0, 1.0, 120.0

DECK = Deck("ch18")


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _arr(v):
    return np.asarray(v, dtype=float)


def _r6(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return fmt(np.round(np.asarray(x, dtype=float), 6) + 0.0, 6)


def _coef(c, var, first=False) -> str:
    """``c var`` as a term of a sum: ``x^2``, ``2 y^2``, ``- z^2``, ``- 3 z^2``."""
    c = int(c)
    sign = "-" if c < 0 else ("" if first else "+")
    body = var if abs(c) == 1 else f"{abs(c)} {var}"
    return (f"{sign} {body}" if sign else body) if not (first and sign == "-") else f"-{body}"


def _sqrt_text(m) -> str:
    k = math.isqrt(int(m))
    return str(k) if k * k == int(m) else f"√{int(m)}"


def _apart(tol, groups) -> bool:
    """Whether every form a checker recognises (grouped by the slip it names) is apart, by ``tol``, from the
    forms of the other groups (the answer is the first group)."""
    same = within(tol)
    groups = [[_arr(v) for v in g] for g in groups]
    return not any(same(u, v) for i, g in enumerate(groups) for h in groups[i + 1:] for u in g for v in h)


# -- §18.2: the normal of an implicit surface ----------------------------------------------------------

_STORED_IMPLICIT = {"a": 1, "b": 2, "c": 1, "x": 1, "y": 1, "m": 2}


def _implicit_point(p):
    return np.array([p["x"], p["y"], math.sqrt(p["m"])], dtype=float)


def _implicit_grad_of(p):
    a, b, c = p["a"], p["b"], p["c"]
    return lambda P: np.stack([2 * a * P[:, 0], 2 * b * P[:, 1], -2 * c * P[:, 2]], -1)


@memo
def _implicit_answers(p):
    P = _implicit_point(p)
    g = _implicit_grad_of(p)(P[None])[0]
    n = sf.implicit_normal(_implicit_grad_of(p), P[None])[0]
    return n, {"grad F itself": g, "the other way": -n, "the z-sign lost": _unit(g * [1, 1, -1])}


def _implicit_generate(rng) -> dict:
    while True:
        a, b, c = (int(v) for v in rng.integers(1, 4, size=3))
        x, y = (int(v) for v in rng.integers(-2, 3, size=2))
        num = a * x * x + b * y * y - 1
        if num > 0 and num % c == 0:
            return {"a": a, "b": b, "c": c, "x": x, "y": y, "m": num // c}


def _implicit_F_text(p) -> str:
    return f"{_coef(p['a'], 'x^2', True)} {_coef(p['b'], 'y^2')} {_coef(-p['c'], 'z^2')} - 1"


def _implicit_statement(p) -> str:
    return (f"The point P = ({p['x']}, {p['y']}, {_sqrt_text(p['m'])}) lies on the implicit surface F(x, y, z) = "
            f"{_implicit_F_text(p)} = 0. Give the unit normal at P in the direction of grad F, [x, y, z] to 4 "
            f"decimals (Goldman §18.2).")


def _implicit_steps(p) -> str:
    n, slips = _implicit_answers(p)
    g = slips["grad F itself"]
    a, b, c = p["a"], p["b"], p["c"]
    return (f"1. grad F = ({2 * a}x, {2 * b}y, {-2 * c}z); at P = ({p['x']}, {p['y']}, {_sqrt_text(p['m'])}) it is "
            f"{_r6(g)}.\n"
            f"2. |grad F| = √{_r6(g @ g)} = {_r6(np.linalg.norm(g))}.\n"
            f"3. n = grad F / |grad F| = {_r6(n)}.")


@DECK.exercise(stored=_STORED_IMPLICIT, generate=_implicit_generate, answer=lambda p: _implicit_answers(p)[0],
               slips=lambda p: _implicit_answers(p)[1], statement=_implicit_statement, steps=_implicit_steps,
               same=within(5e-4), well_posed=lambda p: None if p["m"] > 0 else "z = 0: the z-sign slip is invisible")
def check_implicit_normal(answer, p) -> Result:
    """Check the unit normal grad F / |grad F| of the implicit surface at the given point
    (Goldman §18.2).

    Recognises the gradient left unnormalised, the opposite direction, and a lost minus sign on the
    z-derivative.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    expected, slips = _implicit_answers(p)
    a, b, c = p["a"], p["b"], p["c"]
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the unit normal is {fmt(expected)}: grad F = ({2 * a}x, {2 * b}y, {-2 * c}z) divided by its "
                       f"length.")
    if _close(got, slips["grad F itself"], tol):
        return wrong("that is grad F itself; the unit normal is grad F divided by its length |grad F|.")
    if _close(got, -expected, tol):
        return wrong("your normal points the other way: the question asks for the direction of grad F, towards "
                     "F > 0.")
    if _close(got, slips["the z-sign lost"], tol):
        zz = "-z^2 is -2z" if c == 1 else f"-{c} z^2 is -{2 * c}z"
        return wrong(f"check the sign of the z-component: the derivative of {zz}.")
    return wrong(f"your normal is {_dist(got, expected)}; differentiate F in x, y and z, evaluate at P, and "
                 f"divide by the length (your vector has length {fmt(np.linalg.norm(got), 4)}).")


# -- §18.2: the normal of a parametric surface ---------------------------------------------------------

_STORED_GRAPH = {"c": 1, "u": GRAPH_UV[0], "v": GRAPH_UV[1]}


def _graph_of(c):
    def X(u, v):
        u, v = np.asarray(u, float), np.asarray(v, float)
        return np.stack([u + 0 * v, v + 0 * u, c * u * u * v], -1)
    return X


def _graph_text(c) -> str:
    return "(u, v, u^2 v)" if c == 1 else f"(u, v, {c} u^2 v)"


@memo
def _graph_answers(p):
    c, u, v = p["c"], p["u"], p["v"]
    n = sf.parametric_normal(_graph_of(c), u, v)
    cross = np.cross([1.0, 0.0, 2 * c * u * v], [0.0, 1.0, c * u * u])
    return n, {"X_v × X_u": -n, "not normalised": cross, "middle sign": _unit(cross * [1, -1, 1])}


def _graph_generate(rng) -> dict:
    return {"c": int(rng.integers(1, 4)), "u": float(rng.choice([-2.0, -1.0, 1.0, 2.0])),
            "v": float(rng.choice([-2.0, -1.0, 1.0, 2.0]))}


def _graph_statement(p) -> str:
    return (f"The parametric surface X(u, v) = {_graph_text(p['c'])}. Give the unit normal X_u × X_v / |X_u × X_v| at "
            f"(u, v) = {fmt((p['u'], p['v']))}, [x, y, z] to 4 decimals (Goldman §18.2).")


def _graph_partials_text(c) -> str:
    return ("X_u = (1, 0, 2uv) and X_v = (0, 1, u^2)" if c == 1
            else f"X_u = (1, 0, {2 * c}uv) and X_v = (0, 1, {c}u^2)")


def _graph_steps(p) -> str:
    c, u, v = p["c"], p["u"], p["v"]
    n, slips = _graph_answers(p)
    cross = slips["not normalised"]
    return (f"1. {_graph_partials_text(c)}; at (u, v) = {fmt((u, v))}: X_u = {fmt((1, 0, 2 * c * u * v))}, "
            f"X_v = {fmt((0, 1, c * u * u))}.\n"
            f"2. X_u × X_v = {fmt(cross)}, of length √{_r6(cross @ cross)} = {_r6(np.linalg.norm(cross))}.\n"
            f"3. n = {_r6(n)}.")


@DECK.exercise(stored=_STORED_GRAPH, generate=_graph_generate, answer=lambda p: _graph_answers(p)[0],
               slips=lambda p: _graph_answers(p)[1], statement=_graph_statement, steps=_graph_steps,
               same=within(5e-4))
def check_parametric_normal(answer, p) -> Result:
    """Check the unit normal X_u × X_v / |X_u × X_v| of the parametric surface at the given (u, v)
    (Goldman §18.2).

    Recognises X_v × X_u (the opposite normal), the unnormalised cross product, and a sign slip in
    the middle component.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    expected, slips = _graph_answers(p)
    cross = slips["not normalised"]
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"X_u × X_v = {fmt(cross)}, of length {fmt(np.linalg.norm(cross), 4)}: the unit normal is "
                       f"{fmt(expected)}.")
    if _close(got, -expected, tol):
        return wrong("that is X_v × X_u, the opposite normal: the order of the factors sets the orientation; the "
                     "question asks for X_u × X_v.")
    if _close(got, cross, tol):
        return wrong("that is X_u × X_v itself; divide it by its length to get the unit normal.")
    if _close(got, slips["middle sign"], tol):
        return wrong("check the middle component of the cross product: (a × b)_y = a_z b_x - a_x b_z.")
    return wrong(f"your normal is {_dist(got, expected)}; {_graph_partials_text(p['c'])} at the given "
                 f"(u, v), then their cross product, normalised.")


# -- §18.2: the normal of a deformed surface -----------------------------------------------------------

_STORED_DEFORM = {"M": ((1.0, 0.0, 2.0), (0.0, 3.0, 0.0), (0.0, 0.0, 1.0)), "m": (1.0, 1.0, 1.0)}


def _map_text(M) -> str:
    rows = []
    for row in M:
        terms = [(int(c), var) for c, var in zip(row, "xyz") if c != 0]
        text = ""
        for k, (c, var) in enumerate(terms):
            body = var if abs(c) == 1 else f"{abs(c)}{var}"
            text += (("-" if c < 0 else "") + body) if k == 0 else (f" - {body}" if c < 0 else f" + {body}")
        rows.append(text)
    return "(" + ", ".join(rows) + ")"


def _normal_text(m) -> str:
    m = np.asarray(m, dtype=float)
    s = int(round(float(m @ m)))
    if s == 1:
        return fmt(m)
    k = math.isqrt(s)
    return f"{fmt(m)}/{k}" if k * k == s else f"{fmt(m)}/√{s}"


@memo
def _deform_answers(p):
    M, m = _arr(p["M"]), _arr(p["m"])
    n = _unit(m)
    expected = sf.deformed_normals(M[None], n[None])[0]
    return expected, {"the other side": -expected, "J n": _unit(M @ n), "J^-1 n": _unit(np.linalg.solve(M, n)),
                      "J^T n": _unit(M.T @ n), "not normalised": np.linalg.solve(M.T, m)}


def _deform_generate(rng) -> dict:
    while True:
        M = np.diag(rng.integers(1, 4, size=3).astype(float))
        cells = [(i, j) for i in range(3) for j in range(3) if i != j]
        for k in rng.choice(len(cells), size=2, replace=False):
            M[cells[k]] = float(rng.choice([-2, -1, 1, 2]))
        m = rng.integers(-2, 3, size=3).astype(float)
        if abs(np.linalg.det(M)) >= 1 and m @ m > 0:
            return {"M": tuple(tuple(float(x) for x in row) for row in M), "m": tuple(float(x) for x in m)}


def _deform_ok(p):
    M, m = _arr(p["M"]), _arr(p["m"])
    if np.allclose(M, M.T):
        return "a symmetric J: J^-1 n and J^-T n coincide"
    expected, s = _deform_answers(p)
    if not _apart(5e-4, [[expected], [s["the other side"]], [s["J n"]], [s["J^-1 n"]], [s["J^T n"]],
                         [s["not normalised"], np.linalg.solve(M.T, _unit(m))]]):
        return "two recognised forms coincide"
    return None


def _deform_statement(p) -> str:
    return (f"A surface has the unit normal n = {_normal_text(p['m'])} at a point P. The deformation A(x, y, z) = "
            f"{_map_text(p['M'])} maps it to a new surface. Give the unit normal of the deformed surface at A(P) "
            f"(the image of n's side), [x, y, z] to 4 decimals (Goldman §18.2).")


def _jacobian_text(M) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(x) for x in row) + "]" for row in M) + "]"


def _deform_steps(p) -> str:
    M, m = _arr(p["M"]), _arr(p["m"])
    expected, s = _deform_answers(p)
    w = s["not normalised"]
    return (f"1. The Jacobian of A is J = {_jacobian_text(M)} (row i: the coefficients of component i).\n"
            f"2. Normals map by J^(-T): solve J^T w = {fmt(m)} (n up to its length): w = {_r6(w)}.\n"
            f"3. Normalise: n' = w / |w| = {_r6(expected)} (the positive factor keeps n's side).")


@DECK.exercise(stored=_STORED_DEFORM, generate=_deform_generate, answer=lambda p: _deform_answers(p)[0],
               slips=lambda p: _deform_answers(p)[1], statement=_deform_statement, steps=_deform_steps,
               same=within(5e-4), well_posed=_deform_ok)
def check_deformed_normal(answer, p) -> Result:
    """Check the unit normal of the deformed surface, J^{-T} n normalised, for the Jacobian J of the
    deformation (Goldman §18.2).

    Recognises J n (the normal moved like a tangent), J^{-1} n (the inverse without the transpose),
    J^T n (the transpose without the inverse), and the unnormalised J^{-T} n.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    M, m = _arr(p["M"]), _arr(p["m"])
    expected, s = _deform_answers(p)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the deformed normal is {fmt(expected)}: J^(-T) n is perpendicular to every mapped tangent "
                       f"J t, since (J^(-T) n)·(J t) = n·t = 0.")
    if _close(got, -expected, tol):
        return wrong("your normal points to the other side; J^(-T) n keeps the side of n.")
    if _close(got, s["J n"], tol):
        return wrong("that is J n: you moved the normal like a tangent vector. Normals map by the inverse transpose "
                     "J^(-T) of the Jacobian.")
    if _close(got, s["J^-1 n"], tol):
        return wrong("that is J^(-1) n: the inverse, but not transposed; normals map by J^(-T) = (J^(-1))^T.")
    if _close(got, s["J^T n"], tol):
        return wrong("that is J^T n: the transpose, but not inverted; normals map by J^(-T) = (J^T)^(-1).")
    if _close(got, np.linalg.solve(M.T, _unit(m)), tol) or _close(got, s["not normalised"], tol):
        return wrong("that is J^(-T) n before normalising: divide it by its length.")
    return wrong(f"your normal is {_dist(got, expected)}; the Jacobian of A is {_jacobian_text(M)}; "
                 f"solve J^T m = n for m and normalise it.")


# -- §18.3: one Newton step ----------------------------------------------------------------------------

_STORED_NEWTON = {"O": NEWTON_ORIGIN, "d": NEWTON_DIRECTION, "start": NEWTON_START}


def _dome(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return np.stack([u + 0 * v, v + 0 * u, 1 - u * u - v * v], -1)


def _newton(p, sign_xu=-1.0, add=False):
    O, d = _arr(p["O"]), _arr(p["d"])
    t, u, v = p["start"]
    G = O + t * d - _dome(u, v)
    Xu, Xv = np.array([1.0, 0.0, -2 * u]), np.array([0.0, 1.0, -2 * v])
    J = np.stack([d, sign_xu * Xu, sign_xu * Xv], axis=-1)
    step = np.linalg.solve(J, G)
    return np.array([t, u, v]) + (step if add else -step)


def _newton_limit(p):
    """Where the vertical ray meets the dome: (u, v) = (O_x, O_y), and t from the heights."""
    O, d = _arr(p["O"]), _arr(p["d"])
    a, b = O[0], O[1]
    return np.array([(O[2] - (1 - a * a - b * b)) / -d[2], a, b])


@memo
def _newton_answers(p):
    return _newton(p), {"converged": _newton_limit(p), "step added": _newton(p, add=True),
                        "+X_u, +X_v": _newton(p, sign_xu=1.0)}


_HALVES = [-1.0, -0.5, 0.0, 0.5, 1.0]


def _newton_generate(rng) -> dict:
    a, b = (float(rng.choice(_HALVES)) for _ in range(2))
    h = float(rng.integers(2, 5))
    start = (float(rng.choice([0.5, 1.0, 1.5, 2.0, 2.5])), float(rng.choice(_HALVES)), float(rng.choice(_HALVES)))
    return {"O": (a, b, h), "d": NEWTON_DIRECTION, "start": start}


def _newton_statement(p) -> str:
    return (f"To intersect the ray O + t d, O = {fmt(p['O'])}, d = {fmt(p['d'])}, with the parametric "
            f"surface X(u, v) = (u, v, 1 - u^2 - v^2), Newton's method solves G(t, u, v) = O + t d - X(u, v) = 0. Take "
            f"one Newton step from (t, u, v) = {fmt(p['start'])}: give the new [t, u, v] (Goldman §18.3).")


def _newton_steps(p) -> str:
    O, d = _arr(p["O"]), _arr(p["d"])
    t, u, v = p["start"]
    G = O + t * d - _dome(u, v)
    J = np.stack([d, -np.array([1.0, 0.0, -2 * u]), -np.array([0.0, 1.0, -2 * v])], axis=-1)
    s = np.linalg.solve(J, G)
    return (f"1. G({fmt(p['start'])}) = O + t d - X(u, v) = {_r6(G)}.\n"
            f"2. X_u = (1, 0, -2u) = {fmt((1, 0, -2 * u))}, X_v = (0, 1, -2v) = {fmt((0, 1, -2 * v))}; "
            f"J = [d, -X_u, -X_v] = {_jacobian_text(J)}.\n"
            f"3. Solve J s = G: s = {_r6(s)}.\n"
            f"4. (t, u, v) - s = {_r6(_newton_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_NEWTON, generate=_newton_generate, answer=lambda p: _newton_answers(p)[0],
               slips=lambda p: _newton_answers(p)[1], statement=_newton_statement, steps=_newton_steps,
               same=within(5e-4))
def check_newton_step(answer, p) -> Result:
    """Check one Newton step on G = O + t d - X(u, v) from the given start, with the Jacobian
    J = [d, -X_u, -X_v] (Goldman §18.3).

    Recognises the step added instead of subtracted, +X_u and +X_v in the Jacobian, and the
    converged intersection instead of one step.
    """
    got, err = _read_vector(answer, "your (t, u, v)", 3, "the new [t, u, v]")
    if err is not None:
        return err
    expected, slips = _newton_answers(p)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"one step lands on {fmt(expected)}: (u, v) is already the hit point's, and the next step "
                       f"corrects t.")
    if _close(got, slips["converged"], tol):
        return wrong("that is where Newton's method converges (the intersection itself); the exercise asks for the "
                     "point after one step.")
    if _close(got, slips["step added"], tol):
        return wrong("you added the step: Newton's update is (t, u, v) - J^(-1) G.")
    if _close(got, slips["+X_u, +X_v"], tol):
        return wrong("the Jacobian of G = O + t d - X(u, v) has the columns d, -X_u and -X_v (the minus from -X).")
    return wrong(f"your point is {_dist(got, expected)}; evaluate G and its Jacobian [d, -X_u, -X_v] at the start, "
                 f"solve J s = G and subtract s.")


# -- §18.4: curvature of a cylinder and of a torus --------------------------------------------------------

_RADII = (0.5, 0.8, 1.0, 1.25, 1.6, 2.0, 2.5, 4.0, 5.0, 8.0)


@memo
def _cylinder_answers(p):
    r = p["r"]
    H, K = sf.parametric_cylinder(r).curvature(0.3, 0.1)
    return np.array([float(K), abs(float(H))]), {"a sphere's": [1 / r ** 2, 1 / r], "1/r as H": [0.0, 1 / r],
                                                 "K = 1/r^2": [1 / r ** 2, 1 / (2 * r)],
                                                 "negative |H|": [0.0, -1 / (2 * r)]}


def _cylinder_statement(p) -> str:
    return (f"A circular cylinder has radius {fmt(p['r'])}. Give its Gaussian curvature K and the absolute value "
            f"of its mean curvature |H| at any point, as [K, |H|] (Goldman §18.4).")


def _cylinder_steps(p) -> str:
    r = p["r"]
    return (f"1. The principal curvatures: 1/r = 1/{fmt(r)} = {_r6(1 / r)} around the cylinder, 0 along its "
            f"straight axis.\n"
            f"2. K = their product = 0.\n"
            f"3. |H| = their average = 1/(2r) = {_r6(1 / (2 * r))}.")


@DECK.exercise(stored={"r": CYLINDER_RADIUS}, generate=lambda rng: {"r": float(rng.choice(_RADII))},
               answer=lambda p: _cylinder_answers(p)[0], slips=lambda p: _cylinder_answers(p)[1],
               statement=_cylinder_statement, steps=_cylinder_steps, same=within(1e-4))
def check_cylinder_curvature(answer, p) -> Result:
    """Check [K, |H|], the Gauss and mean curvature of the cylinder of the exercise (Goldman §18.4).

    Recognises the sphere's values (1/r^2, 1/r), |H| = 1/r (a principal curvature, not the mean),
    K = 1/r^2 with the right H, and a negative |H| (an absolute value is never negative: rejected,
    naming the rule, even when its size is right).
    """
    got, err = _read_vector(answer, "your [K, |H|]", 2, "[K, |H|]")
    if err is not None:
        return err
    r = p["r"]
    expected, slips = _cylinder_answers(p)
    tol = 1e-4
    if got[1] < 0:
        return wrong("|H| is an absolute value, so it cannot be negative: H itself has a sign that depends on the "
                     "choice of normal, |H| does not.")
    if _close(got, expected, tol):
        return correct("K = 0 and |H| = 1/(2r): the principal curvatures are 1/r around the cylinder and 0 along it; "
                       "K is their product, H their average.")
    if _close(got, slips["a sphere's"], tol):
        return wrong("those are a sphere's values: a cylinder is straight along its axis, so one of its principal "
                     "curvatures vanishes; K is their product and H their average.")
    if _close(got, slips["1/r as H"], tol):
        return wrong("K is right, but |H| = 1/r is the curvature around the cylinder alone; H is the average of the two "
                     "principal curvatures (the one along the axis vanishes).")
    if _close(got, slips["K = 1/r^2"], tol):
        return wrong("H is right, but K is the product of the principal curvatures, and the one along the axis "
                     "vanishes (the axis is a straight line).")
    bad = "K" if abs(got[0] - expected[0]) > tol else "|H|"
    return wrong(f"your {bad} is off; the principal curvatures are 1/r around the cylinder and none along its "
                 f"straight axis: K is their product, H their average.")


_STORED_TORUS = {"R": TORUS_R, "r": TORUS_r, "v": TORUS_V}
_TORUS_ANGLES = (30.0, 45.0, 60.0, 120.0, 135.0, 150.0, 210.0, 225.0, 240.0, 300.0, 315.0, 330.0)


@memo
def _torus_answers(p):
    R, r, v = p["R"], p["r"], p["v"]
    _, K = sf.parametric_torus(R, r).curvature(0.0, math.radians(v))
    K = float(K)
    c = math.cos(math.radians(v))
    return K, {"lost sign": -K, "R + r": c / (r * (R + r)),
               "radians": math.cos(v) / (r * (R + r * math.cos(v)))}


def _torus_generate(rng) -> dict:
    R = float(rng.integers(2, 6))
    return {"R": R, "r": float(rng.choice([0.5, 1.0, 1.5])), "v": float(rng.choice(_TORUS_ANGLES))}


def _torus_statement(p) -> str:
    return (f"A torus has R = {fmt(p['R'])} (from its centre to the centre of the tube) and tube radius "
            f"r = {fmt(p['r'])}; parametrise it by ((R + r cos v) cos u, (R + r cos v) sin u, r sin v). Give its "
            f"Gaussian curvature K at the points with v = {fmt(p['v'])} degrees, to 4 decimals (Goldman §18.4).")


def _torus_steps(p) -> str:
    R, r, v = p["R"], p["r"], p["v"]
    c = math.cos(math.radians(v))
    return (f"1. cos {fmt(v)}° = {_r6(c)}.\n"
            f"2. R + r cos v = {fmt(R)} + {fmt(r)} · {_r6(c)} = {_r6(R + r * c)}.\n"
            f"3. K = cos v / (r (R + r cos v)) = {_r6(c)} / {_r6(r * (R + r * c))} = {_r6(_torus_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_TORUS, generate=_torus_generate, answer=lambda p: _torus_answers(p)[0],
               slips=lambda p: _torus_answers(p)[1], statement=_torus_statement, steps=_torus_steps,
               same=within(5e-4))
def check_torus_curvature(answer, p) -> Result:
    """Check the Gauss curvature K = cos v / (r (R + r cos v)) of the torus at the given v (Goldman
    §18.4).

    Recognises the lost sign, (R + r) in place of (R + r cos v), and v taken in radians.
    """
    value, err = read_number(answer, "K")
    if err is not None:
        return err
    v = p["v"]
    expected, slips = _torus_answers(p)
    inner = math.cos(math.radians(v)) < 0
    tol = 5e-4
    if abs(value - expected) <= tol:
        if inner:
            return correct(f"K = {fmt(expected)}: negative, as on every point of the inner half of the tube "
                           f"(cos v < 0), where the surface is saddle-shaped.")
        return correct(f"K = {fmt(expected)}: positive, as on every point of the outer half of the tube "
                       f"(cos v > 0), where the surface is egg-shaped.")
    if abs(value - slips["lost sign"]) <= tol:
        if inner:
            return wrong(f"you lost the sign: at v = {fmt(v)} degrees cos v < 0, the inner side of the tube, where the "
                         f"torus is saddle-shaped and K < 0.")
        return wrong(f"you lost the sign: at v = {fmt(v)} degrees cos v > 0, the outer side of the tube, where the "
                     f"torus is egg-shaped and K > 0.")
    if abs(value - slips["R + r"]) <= tol:
        return wrong("the distance from the axis is R + r cos v, not R + r: use the same v in both places.")
    if abs(value - slips["radians"]) <= tol:
        return wrong(f"you took v = {fmt(v)} in radians; the angle is {fmt(v)} degrees.")
    return wrong(f"your K is {off_by(value, expected)}; use K = cos v / (r (R + r cos v)).")


#: Deal another instance of an exercise (``deal("check_torus_curvature")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_implicit_normal": [[2, 4, -2 * math.sqrt(2)], [-0.37796, -0.75593, 0.53452], [0.37796, 0.75593, 0.53452]],
    "check_parametric_normal": [[0.94281, 0.2357, -0.2357], [-4, -1, 1], [-0.94281, 0.2357, 0.2357]],
    "check_deformed_normal": [[0.68825, 0.68825, 0.22942], [-0.68825, 0.22942, 0.68825], [0.22942, 0.68825, 0.68825],
                              [1, 1 / 3, -1]],
    "check_newton_step": [[2, 0, 0], [0.5, 1, 1], [1.5, 1, 1]],
    "check_cylinder_curvature": [[0.16, 0.4], [0, 0.4], [0.16, 0.2], [0, -0.2]],
    "check_torus_curvature": [0.2, -0.125, 0.2135],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
