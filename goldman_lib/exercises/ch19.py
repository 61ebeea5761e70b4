"""Exercise checkers for chapter 19, simple surfaces (Goldman §19.3-19.6).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The chapter's "show that" exercises (7 and 8,
in :mod:`goldman_lib.exercises.proofs`) and the programming project do not deal.  ``SLIPS`` holds
the wrong answers each checker recognises, for the stored instance.  ``None`` or ``...`` means "not
answered yet".  Every exercise uses other rays, surfaces and points than the chapter's worked
examples.  The programming project, :func:`check_quadric_project`, runs the learner's ray-quadric
intersector against :class:`goldman_lib.simple_surfaces.Quadric` on seeded rays, degenerate ones
included.

>>> print(PROBLEMS["check_plane_parameter"])   # doctest: +ELLIPSIS
The ray P(t) = (1, 2, 3) + t (1, -1, -2) meets the plane through (0, 0, -1) with normal (1, 1, 2). ...
>>> check_plane_parameter(-2.75)
Not yet: the sign is wrong: t = N·(Q - P0) / N·d, with Q - P0 (from the ray's origin to the plane's point), not P0 - Q.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import simple_surfaces as S
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector  # shared readers
from goldman_lib.exercises.deal import Deck, integers as _ints, memo, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "DECK", "deal", "steps", "current", "deal_button", "PLANE_POINT", "PLANE_NORMAL", "PLANE_RAY", "POLYGON", "POLYGON_QUERIES",
           "SPHERE_CENTER", "SPHERE_RADIUS", "SPHERE_RAY", "CYLINDER", "CYLINDER_RAY", "TORUS", "TORUS_POINT",
           "BOUND_TORUS", "BOUND_RAYS", "check_plane_parameter", "check_polygon_inside", "check_sphere_hit",
           "check_cylinder_hit", "check_torus_normal", "check_torus_bound", "check_quadric_project",
           "quadric_project_cases"]

#: Exercise 1 (§19.3): a plane (point, normal) and a ray (origin, direction).
PLANE_POINT = (0.0, 0.0, -1.0)
PLANE_NORMAL = (1.0, 1.0, 2.0)
PLANE_RAY = ((1.0, 2.0, 3.0), (1.0, -1.0, -2.0))
#: Exercise 2 (§19.3): a U-shaped polygon in the plane z = 2 and five points of that plane.
POLYGON = ((0, 0, 2), (5, 0, 2), (5, 4, 2), (4, 4, 2), (4, 1, 2), (1, 1, 2), (1, 4, 2), (0, 4, 2))
POLYGON_QUERIES = ((0.5, 3, 2), (2.5, 3, 2), (2.5, 0.5, 2), (4.5, 2, 2), (5.5, 2, 2))
#: Exercise 3 (§19.4.1): a sphere and a ray whose direction is not a unit vector.
SPHERE_CENTER = (1.0, -2.0, 0.0)
SPHERE_RADIUS = 3.0
SPHERE_RAY = ((-4.0, 1.0, 2.0), (2.0, -1.0, -1.0))
#: Exercise 4 (§19.4.2): a capped cylinder (base, axis, radius, height) and a ray.
CYLINDER = ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0, 2.0)
CYLINDER_RAY = ((-2.0, 0.0, 4.0), (1.0, 0.0, -1.0))
#: Exercise 5 (§19.6): a torus (center, axis, R, r) and a point on it.
TORUS = ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 3.0, 2.0)
TORUS_POINT = (2.52, 3.36, 1.6)
#: Exercise 6 (§19.6.1): a torus and five rays (origin, direction).
BOUND_TORUS = ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0, 0.5)
BOUND_RAYS = (((-5, 0, 0.3), (1, 0, 0)), ((-5, 3, 0), (1, 0, 0)), ((-5, 0, 1), (1, 0, 0)), ((0, 0, 5), (0, 0, -1)),
              ((-5, 2.4, 0), (1, 0, 0)))


DECK = Deck("ch19")


def _arr(v):
    return np.asarray(v, dtype=float)


def _r6(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return fmt(np.round(np.asarray(x, dtype=float), 6) + 0.0, 6)


def _apart(tol, groups) -> bool:
    """Whether every form a checker recognises (grouped by the slip it names) is apart, by ``tol``, from the
    forms of the other groups (the answer is the first group)."""
    same = within(tol)
    groups = [[_arr(v) for v in g] for g in groups]
    return not any(same(u, v) for i, g in enumerate(groups) for h in groups[i + 1:] for u in g for v in h)


def _same_flags(a, b) -> bool:
    return [bool(x) for x in a] == [bool(x) for x in b]


def _read_flags(answer, what, n):
    if answer is None or answer is Ellipsis:
        return None, read_points(None, what, f"a list of {n} True/False")[1]
    try:
        flags = [bool(v) if isinstance(v, (bool, np.bool_)) or v in (0, 1) else None for v in answer]
    except TypeError:
        return None, wrong(f"{what} should be a list of {n} True/False values; you gave {quote(answer)}.")
    if len(flags) != n or any(f is None for f in flags):
        return None, wrong(f"{what} should be a list of {n} True/False values (or 1/0); you gave {quote(answer)}.")
    return flags, None


# -- §19.3 ---------------------------------------------------------------------------------------------

_STORED_PLANE = {"Q": PLANE_POINT, "N": PLANE_NORMAL, "P0": PLANE_RAY[0], "d": PLANE_RAY[1]}


@memo
def _plane_answers(p):
    N, Q, P0, d = (_arr(p[k]) for k in ("N", "Q", "P0", "d"))
    t = float(S.Plane(p["Q"], p["N"]).hits(p["P0"], p["d"])[0, 0])
    return t, {"P0 - Q": -t, "distance": t * float(np.linalg.norm(d)), "N·Q / N·d": float(N @ Q) / float(N @ d)}


def _plane_generate(rng) -> dict:
    while True:
        N, d = _ints(rng, -2, 2), _ints(rng, -2, 2)
        if abs(_arr(N) @ _arr(d)) >= 1:
            return {"Q": _ints(rng, -2, 2), "N": N, "P0": _ints(rng, -3, 3), "d": d}


def _plane_ok(p):
    N, Q, P0, d = (_arr(p[k]) for k in ("N", "Q", "P0", "d"))
    if abs(N @ d) < 1:
        return "the ray is parallel to the plane"
    if _plane_answers(p)[0] < 0.2:
        return "the plane is behind (or at) the ray's origin"
    return None


def _plane_statement(p) -> str:
    return (f"The ray P(t) = {fmt(p['P0'])} + t {fmt(p['d'])} meets the plane through {fmt(p['Q'])} "
            f"with normal {fmt(p['N'])}. At which parameter t? (Goldman §19.3; t in units of the direction "
            f"as given, which is not a unit vector.)")


def _plane_steps(p) -> str:
    N, Q, P0, d = (_arr(p[k]) for k in ("N", "Q", "P0", "d"))
    t = _plane_answers(p)[0]
    return (f"1. Put P0 + t d into N·(P - Q) = 0: N·(P0 - Q) + t N·d = 0, so t = N·(Q - P0) / N·d.\n"
            f"2. Q - P0 = {fmt(Q - P0)}: N·(Q - P0) = {fmt(N @ (Q - P0))}; N·d = {fmt(N @ d)}.\n"
            f"3. t = {fmt(N @ (Q - P0))} / {fmt(N @ d)} = {_r6(t)}; the hit is P0 + t d = {_r6(P0 + t * d)}.")


@DECK.exercise(stored=_STORED_PLANE, generate=_plane_generate, answer=lambda p: _plane_answers(p)[0],
               slips=lambda p: _plane_answers(p)[1], statement=_plane_statement, steps=_plane_steps,
               same=within(1e-4), well_posed=_plane_ok)
def check_plane_parameter(answer, p) -> Result:
    """Check ``t = N·(Q - P0) / N·d`` for the ray and plane of exercise 1 (Goldman §19.3).

    Recognises the sign of ``Q - P0`` reversed, the distance along the ray instead of the parameter,
    and ``N·Q / N·d`` (the origin left out).

    >>> check_plane_parameter(0.5)
    Not yet: that is N·Q / N·d: the numerator is N·(Q - P0), the plane's point minus the ray's origin.
    """
    value, err = read_number(answer, "your t")
    if err is not None:
        return err
    t, slips = _plane_answers(p)
    N, Q, P0, d = (_arr(p[k]) for k in ("N", "Q", "P0", "d"))
    if abs(value - t) <= 1e-4:
        return correct(f"t = {fmt(t)}: N·(Q - P0) = {fmt(N @ (Q - P0))}, N·d = {fmt(N @ d)}; the hit is "
                       f"{fmt(P0 + t * d)}.")
    if abs(value - slips["P0 - Q"]) <= 1e-4:
        return wrong("the sign is wrong: t = N·(Q - P0) / N·d, with Q - P0 (from the ray's origin to the plane's "
                     "point), not P0 - Q.")
    if abs(value - slips["distance"]) <= 1e-4:
        return wrong("that is the distance from the origin to the hit, |t d|; the question asks for t in units of "
                     "the direction as given (do not normalise d).")
    if abs(value - slips["N·Q / N·d"]) <= 1e-4:
        return wrong("that is N·Q / N·d: the numerator is N·(Q - P0), the plane's point minus the ray's origin.")
    return wrong(f"your t is {off_by(value, t)}; substitute P0 + t d into N·(P - Q) = 0 and solve for t.")


_STORED_POLYGON = {"polygon": POLYGON, "queries": POLYGON_QUERIES}


def _u_shape(x0, y0, z, W, H):
    return ((x0, y0, z), (x0 + W, y0, z), (x0 + W, y0 + H, z), (x0 + W - 1, y0 + H, z), (x0 + W - 1, y0 + 1, z),
            (x0 + 1, y0 + 1, z), (x0 + 1, y0 + H, z), (x0, y0 + H, z))


def _halves(rng, lo, hi) -> float:
    """A number k + 1/2 strictly between the whole numbers lo and hi."""
    return float(lo + int(rng.integers(0, hi - lo)) + 0.5)


def _polygon_generate(rng) -> dict:
    x0, y0 = (int(v) for v in rng.integers(-2, 3, size=2))
    z = int(rng.integers(-2, 4))
    W, H = int(rng.integers(4, 7)), int(rng.integers(3, 6))
    q = lambda x, y: (float(x), float(y), float(z))           # noqa: E731
    left = q(x0 + 0.5, _halves(rng, y0 + 1, y0 + H))
    notch = q(_halves(rng, x0 + 1, x0 + W - 1), _halves(rng, y0 + 1, y0 + H))
    bar = q(_halves(rng, x0, x0 + W), y0 + 0.5)
    right = q(x0 + W - 0.5, _halves(rng, y0 + 1, y0 + H))
    side = int(rng.integers(0, 4))
    outside = [q(x0 + W + 0.5, _halves(rng, y0, y0 + H)), q(x0 - 0.5, _halves(rng, y0, y0 + H)),
               q(_halves(rng, x0, x0 + W), y0 + H + 0.5), q(_halves(rng, x0, x0 + W), y0 - 0.5)][side]
    queries = [left, notch, bar, right, outside]
    order = rng.permutation(5)
    return {"polygon": _u_shape(x0, y0, z, W, H), "queries": tuple(queries[k] for k in order)}


def _hull_flags(p):
    P = _arr(p["polygon"])
    lo, hi = P.min(axis=0), P.max(axis=0)
    return [bool(np.all(_arr(x)[:2] >= lo[:2]) and np.all(_arr(x)[:2] <= hi[:2])) for x in p["queries"]]


@memo
def _polygon_answers(p):
    truth = [bool(v) for v in S.Polygon(p["polygon"]).inside(p["queries"]).tolist()]
    return truth, {"the convex hull": _hull_flags(p), "the convex edge test": [False] * len(truth),
                   "flipped": [not f for f in truth]}


def _polygon_statement(p) -> str:
    z = fmt(p["polygon"][0][2])
    return (f"The U-shaped polygon with vertices {', '.join(fmt(x) for x in p['polygon'])} lies in the plane z = {z}. "
            f"Which of the points {', '.join(fmt(x) for x in p['queries'])} lie inside it? Give a list of five "
            f"True/False (Goldman §19.3: the polygon is not convex).")


def _outside_where(p) -> str:
    P = _arr(p["polygon"])
    lo, hi = P.min(axis=0), P.max(axis=0)
    for x in p["queries"]:
        x = _arr(x)
        if x[0] > hi[0]:
            return "the one beyond the right arm"
        if x[0] < lo[0]:
            return "the one beyond the left arm"
        if x[1] > hi[1]:
            return "the one above the U"
        if x[1] < lo[1]:
            return "the one below the bar"
    return "the one outside the U"


def _polygon_steps(p) -> str:
    truth = _polygon_answers(p)[0]
    poly = S.Polygon(p["polygon"])
    lines = ["1. Cast a ray from each point in the +x direction and count the edges it crosses (odd: inside)."]
    for k, x in enumerate(p["queries"]):
        crossings = 0
        V = _arr(p["polygon"])
        for a, b in zip(V, np.roll(V, -1, axis=0)):
            if (a[1] > x[1]) != (b[1] > x[1]):
                xc = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                crossings += xc > x[0]
        lines.append(f"{k + 2}. {fmt(x)}: {crossings} crossing{'s' if crossings != 1 else ''}, "
                     f"{'inside' if truth[k] else 'outside'}.")
    lines.append(f"{len(truth) + 2}. The answer: {[bool(f) for f in poly.inside(p['queries']).tolist()]}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_POLYGON, generate=_polygon_generate, answer=lambda p: _polygon_answers(p)[0],
               slips=lambda p: _polygon_answers(p)[1], statement=_polygon_statement, steps=_polygon_steps,
               same=_same_flags)
def check_polygon_inside(answer, p) -> Result:
    """Check which query points lie inside the U-shaped polygon (Goldman §19.3).

    Recognises the convex hull's answer (the notch counted inside), the convex edge test applied to
    a non-convex polygon, and every answer flipped.

    >>> check_polygon_inside([True, True, True, True, False])
    Not yet: you counted the point in the notch of the U as inside: that is the convex hull's answer. The polygon is not convex: count how often a ray from the point crosses its edges (odd: inside).
    """
    flags, err = _read_flags(answer, "your answer", len(p["queries"]))
    if err is not None:
        return err
    truth, slips = _polygon_answers(p)
    if flags == truth:
        return correct(f"the points in the two arms and the bottom bar are inside; the one in the notch and "
                       f"{_outside_where(p)} are outside.")
    if flags == slips["the convex hull"]:
        return wrong("you counted the point in the notch of the U as inside: that is the convex hull's answer. The "
                     "polygon is not convex: count how often a ray from the point crosses its edges (odd: inside).")
    if not any(flags) and any(truth):
        return wrong("no point inside: the convex test (inside every edge's half-plane) fails for every point of "
                     "a non-convex polygon, since some edges turn the other way. Use the crossing (even-odd) test.")
    if flags == slips["flipped"]:
        return wrong("every answer is flipped: an odd number of crossings means inside, an even number outside.")
    wrong_count = sum(f != t for f, t in zip(flags, truth))
    return wrong(f"{wrong_count} of the {len(truth)} answers are wrong; draw the U and cast a ray from each point.")


# -- §19.4 ---------------------------------------------------------------------------------------------

_STORED_SPHERE = {"C": SPHERE_CENTER, "r": SPHERE_RADIUS, "P0": SPHERE_RAY[0], "d": SPHERE_RAY[1]}


def _unit_a_roots(p):
    P0, d = _arr(p["P0"]), _arr(p["d"])
    oc = P0 - _arr(p["C"])
    return np.sort(np.roots([1.0, 2 * d @ oc, oc @ oc - p["r"] ** 2]).real)


@memo
def _sphere_answers(p):
    near, far = (float(x) for x in S.Sphere(p["C"], p["r"]).hits(p["P0"], p["d"])[0])
    L = float(np.linalg.norm(p["d"]))
    return near, {"far root": far, "distance": near * L, "a = 1": float(_unit_a_roots(p)[0])}


def _sphere_generate(rng) -> dict:
    while True:
        C, r = _ints(rng, -2, 2), float(rng.integers(2, 5))
        P0 = tuple(c + w for c, w in zip(C, _ints(rng, -6, 6)))
        d = _ints(rng, -2, 2)
        p = {"C": C, "r": r, "P0": P0, "d": d}
        oc, dd = _arr(P0) - _arr(C), _arr(d)
        if dd @ dd > 1 and oc @ oc > (r + 0.5) ** 2 and dd @ oc < 0 and (dd @ oc) ** 2 - dd @ dd * (oc @ oc - r * r) > 1:
            return p


def _sphere_ok(p):
    oc, d = _arr(p["P0"]) - _arr(p["C"]), _arr(p["d"])
    disc = (d @ oc) ** 2 - (d @ d) * (oc @ oc - p["r"] ** 2)
    if disc <= 0.25 * (d @ d):
        return "the ray misses or grazes the sphere"
    if oc @ oc <= p["r"] ** 2:
        return "the ray starts inside the sphere"
    near, s = _sphere_answers(p)
    L = float(np.linalg.norm(d))
    if not _apart(1e-4, [[near], [s["far root"]], [near * L, s["far root"] * L], list(_unit_a_roots(p))]):
        return "two recognised forms coincide"
    return None


def _sphere_statement(p) -> str:
    return (f"The ray P(t) = {fmt(p['P0'])} + t {fmt(p['d'])} is aimed at the sphere with center "
            f"{fmt(p['C'])} and radius {fmt(p['r'])}. Give the parameter t of the first hit in front "
            f"of the origin, to 4 decimals (Goldman §19.4.1).")


def _sphere_steps(p) -> str:
    P0, d, C, r = _arr(p["P0"]), _arr(p["d"]), _arr(p["C"]), p["r"]
    oc = P0 - C
    a, b, c = d @ d, 2 * d @ oc, oc @ oc - r * r
    near, s = _sphere_answers(p)
    return (f"1. |P0 + t d - C|^2 = r^2 with P0 - C = {fmt(oc)}: a t^2 + b t + c = 0 with a = d·d = {fmt(a)}, "
            f"b = 2 d·(P0 - C) = {fmt(b)}, c = |P0 - C|^2 - r^2 = {fmt(c)}.\n"
            f"2. The discriminant b^2 - 4ac = {fmt(b * b - 4 * a * c)}.\n"
            f"3. t = (-b ∓ √(b^2 - 4ac)) / 2a = {_r6(near)} and {_r6(s['far root'])}; the first hit is the smaller, "
            f"t = {_r6(near)}.")


@DECK.exercise(stored=_STORED_SPHERE, generate=_sphere_generate, answer=lambda p: _sphere_answers(p)[0],
               slips=lambda p: _sphere_answers(p)[1], statement=_sphere_statement, steps=_sphere_steps,
               same=within(1e-4), well_posed=_sphere_ok)
def check_sphere_hit(answer, p) -> Result:
    """Check the first hit of the ray of exercise 3 with the sphere (Goldman §19.4.1): the smaller
    positive root of ``(d·d) t^2 + 2 d·(P0 - C) t + |P0 - C|^2 - r^2 = 0``.

    Recognises the far root, the distance instead of the parameter, and ``a = 1`` (a unit direction
    assumed).

    >>> check_sphere_hit(1.0)
    Not yet: that root comes from taking a = 1, as if d were a unit vector: here d·d is not 1, so a = d·d.
    """
    value, err = read_number(answer, "your t")
    if err is not None:
        return err
    P0, d = _arr(p["P0"]), _arr(p["d"])
    oc = P0 - _arr(p["C"])
    near, s = _sphere_answers(p)
    far = s["far root"]
    if abs(value - near) <= 1e-4:
        return correct(f"t = {fmt(near, 6)}, the smaller root of {fmt(d @ d)} t^2 + {fmt(2 * d @ oc)} t + "
                       f"{fmt(oc @ oc - p['r'] ** 2)} = 0; the ray leaves the sphere at the other root.")
    if abs(value - far) <= 1e-4:
        return wrong("that is the far root, where the ray leaves the sphere; the first hit is the smaller positive root.")
    if abs(value - near * np.linalg.norm(d)) <= 1e-4 or abs(value - far * np.linalg.norm(d)) <= 1e-4:
        return wrong("that is a distance along the ray, |t d|; t is measured in units of d as given.")
    if np.any(np.abs(_unit_a_roots(p) - value) <= 1e-4):
        return wrong("that root comes from taking a = 1, as if d were a unit vector: here d·d is not 1, so a = d·d.")
    return wrong(f"your t is {off_by(value, near)}; expand |P0 + t d - C|^2 = r^2 into a t^2 + b t + c = 0.")


_STORED_CYLINDER = {"base": CYLINDER[0], "axis": CYLINDER[1], "r": CYLINDER[2], "h": CYLINDER[3],
                    "o": CYLINDER_RAY[0], "d": CYLINDER_RAY[1]}


@memo
def _cylinder_answers(p):
    o, d = p["o"], p["d"]
    entry, leave = (float(x) for x in S.Cylinder(p["base"], p["axis"], p["r"], p["h"]).hits(o, d)[0][:2])
    wall = S.Cylinder(p["base"], p["axis"], p["r"]).hits(o, d)[0]
    t_bottom = (p["base"][2] - o[2]) / d[2]
    return entry, {"the infinite wall": float(wall[0]), "the exit": leave, "the bottom plane": float(t_bottom)}


def _cylinder_generate(rng) -> dict:
    r, h = float(rng.integers(1, 3)), float(rng.integers(2, 5))
    base = (float(rng.integers(-2, 3)), float(rng.integers(-2, 3)), float(rng.integers(-1, 2)))
    sx, dx, dz, e = float(rng.choice([-1, 1])), float(rng.integers(1, 3)), float(rng.integers(1, 3)), float(rng.integers(1, 4))
    x_top = float(rng.integers(-int(r) + 1, int(r))) if rng.random() < 0.5 else _halves(rng, -int(r), int(r))
    x0 = x_top - sx * dx * e / dz
    o = (base[0] + x0, base[1], base[2] + h + e)
    return {"base": base, "axis": (0.0, 0.0, 1.0), "r": r, "h": h, "o": o, "d": (sx * dx, 0.0, -dz)}


def _cylinder_ok(p):
    entry, s = _cylinder_answers(p)
    o, d, base = _arr(p["o"]), _arr(p["d"]), _arr(p["base"])
    top = (base[2] + p["h"] - o[2]) / d[2]
    if not (np.isfinite(entry) and abs(entry - top) < 1e-9):
        return "the ray does not enter through the top cap"
    wall_z = o[2] + s["the infinite wall"] * d[2] - base[2]
    leave_z = o[2] + s["the exit"] * d[2] - base[2]
    if not (wall_z > p["h"] + 0.1 and 0.1 < leave_z < p["h"] - 0.1):
        return "the ray must meet the infinite wall above the top and leave through the wall"
    if s["the bottom plane"] <= s["the exit"] + 0.1:
        return "the bottom cap's plane must be met outside its disc"
    return None


def _cylinder_statement(p) -> str:
    return (f"A solid cylinder has its base (bottom end) at {fmt(p['base'])}, axis {fmt(p['axis'])}, radius "
            f"{fmt(p['r'])} and height {fmt(p['h'])}, closed by its two end discs. The ray P(t) = "
            f"{fmt(p['o'])} + t {fmt(p['d'])} comes from above. Give the parameter t where it "
            f"enters the solid (Goldman §19.4.2).")


def _cylinder_steps(p) -> str:
    entry, s = _cylinder_answers(p)
    o, d, base = _arr(p["o"]), _arr(p["d"]), _arr(p["base"])
    hit = lambda t: _r6(o + t * d)        # noqa: E731
    return (f"1. The infinite wall (x - {fmt(base[0])})^2 + (y - {fmt(base[1])})^2 = {fmt(p['r'])}^2: "
            f"t = {_r6(s['the infinite wall'])} at {hit(s['the infinite wall'])}, above the top "
            f"(z > {fmt(base[2] + p['h'])}): not on the solid; t = {_r6(s['the exit'])} at {hit(s['the exit'])}, "
            f"on the wall.\n"
            f"2. The top cap z = {fmt(base[2] + p['h'])}: t = {_r6(entry)} at {hit(entry)}, inside the disc. The "
            f"bottom cap z = {fmt(base[2])}: t = {_r6(s['the bottom plane'])} at {hit(s['the bottom plane'])}, "
            f"outside the disc.\n"
            f"3. The ray enters at the smallest of the hits on the solid: t = {_r6(entry)}.")


@DECK.exercise(stored=_STORED_CYLINDER, generate=_cylinder_generate, answer=lambda p: _cylinder_answers(p)[0],
               slips=lambda p: _cylinder_answers(p)[1], statement=_cylinder_statement, steps=_cylinder_steps,
               same=within(1e-4), well_posed=_cylinder_ok)
def check_cylinder_hit(answer, p) -> Result:
    """Check where the ray of exercise 4 enters the capped cylinder (Goldman §19.4.2): the first hit
    with the wall or a cap that lies on the bounded solid.

    Recognises the infinite cylinder's wall hit, the exit (the open tube's only hit), and the plane
    of the bottom cap outside its disc.
    """
    value, err = read_number(answer, "your t")
    if err is not None:
        return err
    entry, s = _cylinder_answers(p)
    o, d = _arr(p["o"]), _arr(p["d"])
    if abs(value - entry) <= 1e-4:
        return correct(f"t = {fmt(entry)}: the ray enters through the top cap at {fmt(o + entry * d)} "
                       f"and leaves through the wall at t = {fmt(s['the exit'])}.")
    if abs(value - s["the infinite wall"]) <= 1e-4:
        return wrong("that is where the ray meets the infinite cylinder, but there the point is above the top "
                     "(z > height): the bounded cylinder's wall is not there. Check the caps.")
    if abs(value - s["the exit"]) <= 1e-4:
        return wrong("that is where the ray leaves through the wall (the only hit of an open tube); it enters "
                     "earlier, through a cap.")
    if abs(value - s["the bottom plane"]) <= 1e-4:
        return wrong("that is where the ray meets the plane of the bottom cap, but outside its disc (the point is "
                     "farther than the radius from the axis).")
    return wrong(f"your t is {off_by(value, entry)}; find the wall's hits and the caps' hits and keep those on the "
                 f"bounded solid.")


# -- §19.6 ---------------------------------------------------------------------------------------------

_STORED_TORUS = {"torus": TORUS, "P": TORUS_POINT}
_PAIRS = ((1.0, 0.0), (0.0, 1.0), (0.6, 0.8), (0.8, 0.6))


def _signed_pair(rng):
    c, s = _PAIRS[int(rng.integers(0, len(_PAIRS)))]
    return c * float(rng.choice([-1, 1])) + 0.0, s * float(rng.choice([-1, 1])) + 0.0


def _torus_generate(rng) -> dict:
    R, r = float(rng.integers(3, 6)), float(rng.choice([0.5, 1.5, 2.0, 2.5]))
    (cu, su), (cv, sv) = _signed_pair(rng), _signed_pair(rng)
    P = tuple(round(x, 9) + 0.0 for x in ((R + r * cv) * cu, (R + r * cv) * su, r * sv))
    return {"torus": ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), R, r), "P": P}


@memo
def _torus_answers(p):
    c, w, R, r = p["torus"]
    n = S.Torus(c, w, R, r).normal([p["P"]])[0]
    P = _arr(p["P"]) - _arr(c)
    return n, {"inward": -n, "not normalised": r * n, "a sphere's normal": P / np.linalg.norm(P)}


def _torus_statement(p) -> str:
    c, w, R, r = p["torus"]
    return (f"The torus with center {fmt(c)}, axis {fmt(w)}, R = {fmt(R)} and r = {fmt(r)} "
            f"passes through P = {fmt(p['P'])}. Give the unit outward normal there as [x, y, z] "
            f"(Goldman §19.6: the normal is the gradient of (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2)).")


def _torus_steps(p) -> str:
    c, w, R, r = p["torus"]
    P = _arr(p["P"])
    rho = float(np.hypot(P[0], P[1]))
    core = np.array([P[0] * R / rho, P[1] * R / rho, 0.0]) if rho > 0 else np.zeros(3)
    n = _torus_answers(p)[0]
    g = 4 * (P @ P + R * R - r * r) * P - 8 * R * R * np.array([P[0], P[1], 0.0])
    return (f"1. The gradient 4 (|P|^2 + R^2 - r^2) P - 8 R^2 (x, y, 0) at P: |P|^2 = {_r6(P @ P)}, so grad = "
            f"{_r6(g)}.\n"
            f"2. Normalise: n = grad / |grad| = {_r6(n)}.\n"
            f"3. Check: the nearest point of the core circle is R (x, y, 0)/√(x^2 + y^2) = {_r6(core)}, and "
            f"(P - it)/r = {_r6((P - core) / r)}, the same direction.")


@DECK.exercise(stored=_STORED_TORUS, generate=_torus_generate, answer=lambda p: _torus_answers(p)[0],
               slips=lambda p: _torus_answers(p)[1], statement=_torus_statement, steps=_torus_steps,
               same=within(1e-4))
def check_torus_normal(answer, p) -> Result:
    """Check the unit outward normal of the torus of exercise 5 at its point (Goldman §19.6).

    Recognises the unnormalised gradient, the unnormalised offset from the core circle, the normal
    of a sphere about the center, and the inward normal.

    >>> check_torus_normal([-0.36, -0.48, -0.8])
    Not yet: that is the inward normal; the outward one points away from the core circle of the tube.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    n, s = _torus_answers(p)
    tol = 1e-4
    if np.abs(got - n).max() <= tol:
        return correct(f"the unit normal is {fmt(n)}: along P minus the nearest point of the core circle.")
    if np.abs(got + n).max() <= tol:
        return wrong("that is the inward normal; the outward one points away from the core circle of the tube.")
    length = np.linalg.norm(got)
    if length > 0 and np.abs(got / length - n).max() <= tol:
        return wrong(f"the direction is right but its length is {fmt(length, 4)}: divide by the length to get a "
                     f"unit normal.")
    if np.abs(got - s["a sphere's normal"]).max() <= tol:
        return wrong("that is P / |P|, a sphere's normal about the center; a torus's normal points from the core "
                     "circle (radius R in the plane z = 0), not from the center.")
    return wrong(f"your normal is {far_off(got, n)} from the right one; differentiate "
                 f"(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) and normalise.")


_STORED_BOUND = {"torus": BOUND_TORUS, "rays": BOUND_RAYS}


def _tenths(rng, lo, hi) -> float:
    """A number with one decimal strictly between lo and hi."""
    k = int(rng.integers(int(round(lo * 10)) + 1, int(round(hi * 10))))
    return k / 10


def _bound_generate(rng) -> dict:
    R, r = float(rng.integers(2, 5)), float(rng.choice([0.5, 1.0]))
    S_ = R + r
    far = float(math.ceil(S_) + 2)
    sgn = lambda: float(rng.choice([-1, 1]))             # noqa: E731
    through = ((-far, _tenths(rng, -(R - r), R - r), _tenths(rng, -r, r)), (1.0, 0.0, 0.0))
    beside = ((-far, sgn() * _tenths(rng, S_, S_ + 1.5), _tenths(rng, -r, r)), (1.0, 0.0, 0.0))
    above = ((-far, _tenths(rng, -1.0, 1.0), sgn() * _tenths(rng, r, min(S_ - 0.2, r + 1.5))), (1.0, 0.0, 0.0))
    hole = ((_tenths(rng, -(R - r) / 2, (R - r) / 2), _tenths(rng, -(R - r) / 2, (R - r) / 2), far), (0.0, 0.0, -1.0))
    tube = ((-far, sgn() * _tenths(rng, R - r, S_), 0.0), (1.0, 0.0, 0.0))
    rays = [through, beside, above, hole, tube]
    rays = [((o[1], o[0], o[2]), (d[1], d[0], d[2])) if rng.random() < 0.3 else (o, d) for o, d in rays]   # some along y
    order = rng.permutation(5)
    return {"torus": ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), R, r), "rays": tuple(rays[k] for k in order)}


@memo
def _bound_answers(p):
    c, w, R, r = p["torus"]
    T = S.Torus(c, w, R, r)
    solve, hit = [], []
    for o, d in p["rays"]:
        hit.append(bool(np.isfinite(T.intersect(o, d)[0])))
        solve.append(T.quartics_solved == 1)
    sphere = [bool(np.linalg.norm(np.cross(np.subtract(c, o), d)) / np.linalg.norm(d) <= R + r) for o, d in p["rays"]]
    return solve, {"hits the torus": hit, "the sphere alone": sphere, "flipped": [not f for f in solve]}


def _bound_ok(p):
    solve, s = _bound_answers(p)
    if sum(solve) != 3:
        return "three rays must pass the bound"
    return None


def _bound_statement(p) -> str:
    c, w, R, r = p["torus"]
    return (f"Bounding test for the torus with center {fmt(c)}, axis {fmt(w)}, "
            f"R = {fmt(R)}, r = {fmt(r)} (Goldman §19.6.1): the torus lies inside the "
            f"sphere of radius R + r about its center and inside the slab |z| <= r; a ray whose line misses the "
            f"sphere, or meets the sphere only outside the slab, skips the quartic. For the rays (origin, "
            f"direction) " + "; ".join(f"{fmt(o)}, {fmt(d)}" for o, d in p["rays"])
            + ", which must solve the quartic? Give five True/False.")


def _bound_steps(p) -> str:
    c, w, R, r = p["torus"]
    solve, s = _bound_answers(p)
    lines = [f"1. The bound: the sphere of radius R + r = {fmt(R + r)} about {fmt(c)}, and the slab |z| <= {fmt(r)}."]
    for k, ((o, d), ok) in enumerate(zip(p["rays"], solve)):
        dist = float(np.linalg.norm(np.cross(np.subtract(c, o), d)) / np.linalg.norm(d))
        if dist > R + r:
            why = f"its line passes {_r6(dist)} from the center: it misses the sphere, skip"
        elif not ok:
            why = f"it meets the sphere (distance {_r6(dist)}) but only where |z| > {fmt(r)}: skip"
        else:
            why = (f"it meets the sphere (distance {_r6(dist)}) inside the slab: solve the quartic "
                   f"({'it hits the torus' if s['hits the torus'][k] else 'no real root: it misses'})")
        lines.append(f"{k + 2}. {fmt(o)}, {fmt(d)}: {why}.")
    lines.append(f"{len(solve) + 2}. The answer: {solve}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_BOUND, generate=_bound_generate, answer=lambda p: _bound_answers(p)[0],
               slips=lambda p: _bound_answers(p)[1], statement=_bound_statement, steps=_bound_steps,
               same=_same_flags, well_posed=_bound_ok)
def check_torus_bound(answer, p) -> Result:
    """Check which rays of exercise 6 pass the bounding test and solve the quartic (Goldman §19.6.1).

    Recognises "does the ray hit the torus" answered instead, the sphere test without the slab, and
    every answer flipped.

    >>> check_torus_bound([True, False, False, False, True])
    Not yet: you answered whether each ray hits the torus; the bound only rules rays out. A ray down the hole passes the bound and must solve the quartic (which then has no real root).
    """
    flags, err = _read_flags(answer, "your answer", len(p["rays"]))
    if err is not None:
        return err
    solve, s = _bound_answers(p)
    if flags == solve:
        return correct("three rays pass the bound; the one beside the sphere and the one above the slab skip the "
                       "quartic. The ray down the hole passes it and finds no root.")
    if flags == s["hits the torus"]:
        return wrong("you answered whether each ray hits the torus; the bound only rules rays out. A ray down the "
                     "hole passes the bound and must solve the quartic (which then has no real root).")
    if flags == s["the sphere alone"]:
        return wrong("that is the bounding sphere alone: a ray that meets the sphere only where |z| > r cannot "
                     "meet the torus either (the slab is part of the bound).")
    if flags == s["flipped"]:
        return wrong("every answer is flipped: True means the ray must solve the quartic (it passed the bound).")
    return wrong(f"{sum(f != x for f, x in zip(flags, solve))} of the {len(solve)} answers are wrong; for each ray "
                 f"find its distance from the center and where it crosses the slab |z| <= r.")


#: Deal another instance of an exercise (``deal("check_sphere_hit")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button


# -- the programming project: a ray-quadric intersector (§19.5) ----------------------------------------

def _q(coeffs) -> np.ndarray:
    A, B, C, D, E, F, G, H, I, J = (float(v) for v in coeffs)
    return np.array([[A, D / 2, E / 2, G / 2], [D / 2, B, F / 2, H / 2], [E / 2, F / 2, C, I / 2],
                     [G / 2, H / 2, I / 2, J]])


def quadric_project_cases() -> list[Case]:
    """The cases of the ray-quadric project: a quadric ``Q`` (4x4) and a batch of rays, seeded, with the
    degenerate ones labelled by ``kind``: rays from outside, from inside, tangent, parallel to a
    cylinder's axis (``a = 0, b = 0``), parallel to a paraboloid's axis (``a = 0``: one root), through a
    cone's apex, starting on the surface, missing, and a rotated ellipsoid given with cross terms."""
    rng = np.random.default_rng(1919)
    cases = []

    def add(name, Q, o, d, kind):
        o, d = np.asarray(o, float).reshape(-1, 3), np.asarray(d, float).reshape(-1, 3)
        cases.append(Case(f"{name}, {len(o)} ray(s)", (np.asarray(Q, float), o, d), kind=kind))

    sphere = _q([1, 1, 1, 0, 0, 0, 0, 0, 0, -1])
    o = rng.normal(size=(8, 3))
    o = 4 * o / np.linalg.norm(o, axis=1, keepdims=True)
    add("unit sphere x^2 + y^2 + z^2 = 1", sphere, o, -o + rng.normal(size=(8, 3)) * 0.3, "rays from outside")
    ell = _q([1 / 4, 1, 4, 0, 0, 0, 0, 0, 0, -1])
    add("ellipsoid x^2/4 + y^2 + 4 z^2 = 1", ell, rng.normal(size=(6, 3)) * 0.2, rng.normal(size=(6, 3)),
        "rays starting inside (one root behind)")
    add("unit sphere", sphere, [[-2, 1, 0], [0, -3, 1]], [[1, 0, 0], [0, 2, 0]], "tangent rays (a double root)")
    cyl = _q([1, 1, 0, 0, 0, 0, 0, 0, 0, -1])
    add("cylinder x^2 + y^2 = 1", cyl, [[0.5, 0, -2], [3, 0, 0], [-3, 0.2, 1]], [[0, 0, 1], [0, 0, -1], [1, 0, 0]],
        "parallel to the cylinder's axis (a = 0, b = 0)")
    par = _q([1, 1, 0, 0, 0, 0, 0, 0, -1, 0])
    add("paraboloid z = x^2 + y^2", par, [[0.5, 0.5, -3], [1, 0, 5]], [[0, 0, 1], [0, 0, -2]],
        "parallel to the paraboloid's axis (a = 0: one root)")
    cone = _q([1, 1, -1, 0, 0, 0, 0, 0, 0, 0])
    add("double cone x^2 + y^2 = z^2", cone, [[-1, -1, -1], [0, 0, -3], [-2, 0, 1]], [[1, 1, 1], [0, 0, 1], [1, 0, 0]],
        "through the cone's apex")
    add("unit sphere", sphere, [[1, 0, 0], [0.6, 0.8, 0], [0, 0, -1]], [[-1, 0.2, 0], [1, 1, 0], [0, 1, 1]],
        "starting on the surface (t = 0 does not count)")
    hyp = _q([1, 1, -1, 0, 0, 0, 0, 0, 0, -1])
    add("hyperboloid x^2 + y^2 - z^2 = 1", hyp, [[0, 0, -5], [-5, 3, 0], [-5, 0, 2]], [[0, 0, 1], [1, 0, 0], [1, 0, 0]],
        "missing rays and a ray along the axis")
    R = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    A = R.T @ np.diag([1.0, 1 / 4, 1 / 9]) @ R
    Q = np.zeros((4, 4))
    Q[:3, :3] = A
    Q[3, 3] = -1.0
    o = rng.normal(size=(10, 3)) * 4
    add("a rotated ellipsoid (cross terms)", Q, o, -o + rng.normal(size=(10, 3)), "general quadric with cross terms")
    return cases


def _reference(Q, origins, directions):
    return S.Quadric(Q).intersect(origins, directions)


def _compare_quadric(got, expected, case) -> str | None:
    Q, o, d = case.args
    try:
        arr = np.asarray(got, dtype=float)
    except (TypeError, ValueError):
        return "it should be an array of N parameters, one per ray"
    if arr.shape != expected.shape:
        return f"it has shape {arr.shape}; with {len(expected)} rays the result is {len(expected)} numbers, shape {expected.shape}"
    if np.any(np.isnan(arr)):
        k = int(np.flatnonzero(np.isnan(arr))[0])
        return (f"ray {k} gives NaN: when a = d Q d^T is 0 the equation is linear (b t + c = 0), and when b is 0 "
                f"too there is no root (return inf)")
    for k in range(len(expected)):
        g, e = arr[k], expected[k]
        if (np.isinf(e) and g == np.inf) or (np.isfinite(e) and np.isfinite(g) and abs(g - e) <= 1e-6 * (1 + abs(e))):
            continue
        ray = f"ray {k} (origin {fmt(o[k])}, direction {fmt(d[k])})"
        if np.isinf(e):
            why = "; a root at t <= 1e-9 (behind the origin, or where it starts) is not a hit" if g <= 1e-6 else ""
            return f"{ray}: you returned {fmt(g)}, but this ray misses the quadric in front of its origin{why}"
        if not np.isfinite(g):
            H, D = np.r_[o[k], 1.0], np.r_[d[k], 0.0]
            a, b, c = D @ Q @ D, 2 * H @ Q @ D, H @ Q @ H
            scale = max(abs(b) ** 2, abs(4 * a * c), 1e-300)
            if abs(a) <= 1e-12 * max(1.0, abs(b), abs(c)):
                why = "here a = 0 the equation is linear, b t + c = 0, with the root t = -c/b"
            elif abs(b * b - 4 * a * c) <= 1e-9 * scale:
                why = "this ray is tangent: the discriminant is 0 and the double root t = -b/(2a) is a hit"
            else:
                why = "if a = 0 the equation is linear, and a tangent ray has a double root (discriminant 0)"
            return f"{ray}: you returned {fmt(g)}, but it hits at t = {fmt(e)}; {why}"
        if abs(g) <= 1e-9:
            return (f"{ray}: you returned {fmt(g)}: the ray starts on the surface, and the root t = 0 is not a hit "
                    f"(keep only t > 1e-9); the first hit in front is {fmt(e)}")
        h = S.Quadric(Q).hits(o[k], d[k])[0]
        if np.any(np.abs(h - g) <= 1e-6 * (1 + np.abs(g))) and g < e:
            return f"{ray}: you returned {fmt(g)}, a root behind the origin (or at t = 0); the first hit in front is {fmt(e)}"
        if np.any(np.abs(h - g) <= 1e-6 * (1 + np.abs(g))):
            return f"{ray}: you returned {fmt(g)}, the far root; the first hit in front of the origin is {fmt(e)}"
        length = float(np.linalg.norm(d[k]))
        if abs(length - 1) > 1e-6 and abs(g - e * length) <= 1e-6 * (1 + abs(e * length)):
            return (f"{ray}: you returned {fmt(g)}, the distance along the unit direction; t is the parameter of "
                    f"the direction as given (P0 + t d with d not normalised), here {fmt(e)}")
        return f"{ray}: you returned {fmt(g)}, expected {fmt(e)}"
    return None


def check_quadric_project(function) -> Result:
    """Check the learner's ``intersect_quadric(Q, origins, directions)`` -> the nearest parameter
    ``t > 1e-9`` per ray, ``inf`` on a miss, for the quadric ``[P 1] Q [P 1]^T = 0`` (Goldman §19.5),
    against :class:`goldman_lib.simple_surfaces.Quadric` on :func:`quadric_project_cases`.

    >>> def smaller_root(Q, o, d):
    ...     H, D = np.c_[o, np.ones(len(o))], np.c_[d, np.zeros(len(d))]
    ...     a, b, c = (np.einsum("ij,jk,ik->i", X, Q, Y) for X, Y in ((D, D), (H, D), (H, H)))
    ...     return (-2 * b - np.sqrt(4 * b * b - 4 * a * c)) / (2 * a)
    >>> print(check_quadric_project(smaller_root).message)   # doctest: +ELLIPSIS
    case 2 of 9 (ellipsoid ...): your function returned ...; ray 0 (...): you returned ..., a root behind the origin ...
    """
    return check_project(function, quadric_project_cases(), reference=_reference, compare=_compare_quadric,
                         what="the ray-quadric intersector",
                         hint="with a = [d 0] Q [d 0]^T, b = 2 [P0 1] Q [d 0]^T, c = [P0 1] Q [P0 1]^T, keep the "
                              "smallest root t > 1e-9; treat a = 0 (linear) and a negative discriminant (miss)")


PROBLEMS = DECK.problems({})


SLIPS = {
    "check_plane_parameter": [-2.75, 2.75 * 6 ** 0.5, 0.5, 3.0],
    "check_polygon_inside": [[True, True, True, True, False], [False] * 5, [False, True, False, False, True]],
    "check_sphere_hit": [(30 + 204 ** 0.5) / 12, (30 - 204 ** 0.5) / 12 * 6 ** 0.5, 1.0, 2.0],
    "check_cylinder_hit": [1.0, 3.0, 4.0, 2.5],
    "check_torus_normal": [[-0.36, -0.48, -0.8], [0.72, 0.96, 1.6], [2.52 / 4.4944, 3.36 / 4.4944, 1.6 / 4.4944],
                           [0.6, 0.8, 0.0]],
    "check_torus_bound": [[True, False, False, False, True], [True, False, True, True, True],
                          [False, True, True, False, False]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
