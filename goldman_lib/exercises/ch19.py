"""Exercise checkers for chapter 19, simple surfaces (Goldman §19.3-19.6).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other rays, surfaces and points than the chapter's worked examples.  The
programming project, :func:`check_quadric_project`, runs the learner's ray-quadric intersector
against :class:`goldman_lib.simple_surfaces.Quadric` on seeded rays, degenerate ones included.

>>> print(PROBLEMS["check_plane_parameter"])   # doctest: +ELLIPSIS
The ray P(t) = (1, 2, 3) + t (1, -1, -2) meets the plane through (0, 0, -1) with normal (1, 1, 2). ...
>>> check_plane_parameter(-2.75)
Not yet: the sign is wrong: t = N·(Q - P0) / N·d, with Q - P0 (from the ray's origin to the plane's point), not P0 - Q.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import simple_surfaces as S
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector  # shared readers
from goldman_lib.exercises.projects import Case, check_project, describe

__all__ = ["PROBLEMS", "SLIPS", "PLANE_POINT", "PLANE_NORMAL", "PLANE_RAY", "POLYGON", "POLYGON_QUERIES",
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


PROBLEMS = {
    "check_plane_parameter": (
        f"The ray P(t) = {fmt(PLANE_RAY[0])} + t {fmt(PLANE_RAY[1])} meets the plane through {fmt(PLANE_POINT)} "
        f"with normal {fmt(PLANE_NORMAL)}. At which parameter t? (Goldman §19.3; t in units of the direction "
        f"as given, which is not a unit vector.)"),
    "check_polygon_inside": (
        f"The U-shaped polygon with vertices {', '.join(fmt(p) for p in POLYGON)} lies in the plane z = 2. "
        f"Which of the points {', '.join(fmt(p) for p in POLYGON_QUERIES)} lie inside it? Give a list of five "
        f"True/False (Goldman §19.3: the polygon is not convex)."),
    "check_sphere_hit": (
        f"The ray P(t) = {fmt(SPHERE_RAY[0])} + t {fmt(SPHERE_RAY[1])} is aimed at the sphere with center "
        f"{fmt(SPHERE_CENTER)} and radius {fmt(SPHERE_RADIUS)}. Give the parameter t of the first hit in front "
        f"of the origin, to 4 decimals (Goldman §19.4.1)."),
    "check_cylinder_hit": (
        f"A solid cylinder has its base (bottom end) at {fmt(CYLINDER[0])}, axis {fmt(CYLINDER[1])}, radius "
        f"{fmt(CYLINDER[2])} and height {fmt(CYLINDER[3])}, closed by its two end discs. The ray P(t) = "
        f"{fmt(CYLINDER_RAY[0])} + t {fmt(CYLINDER_RAY[1])} comes from above. Give the parameter t where it "
        f"enters the solid (Goldman §19.4.2)."),
    "check_torus_normal": (
        f"The torus with center {fmt(TORUS[0])}, axis {fmt(TORUS[1])}, R = {fmt(TORUS[2])} and r = {fmt(TORUS[3])} "
        f"passes through P = {fmt(TORUS_POINT)}. Give the unit outward normal there as [x, y, z] "
        f"(Goldman §19.6: the normal is the gradient of (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2))."),
    "check_torus_bound": (
        f"Bounding test for the torus with center {fmt(BOUND_TORUS[0])}, axis {fmt(BOUND_TORUS[1])}, "
        f"R = {fmt(BOUND_TORUS[2])}, r = {fmt(BOUND_TORUS[3])} (Goldman §19.6.1): the torus lies inside the "
        f"sphere of radius R + r about its center and inside the slab |z| <= r; a ray whose line misses the "
        f"sphere, or meets the sphere only outside the slab, skips the quartic. For the rays (origin, "
        f"direction) " + "; ".join(f"{fmt(o)}, {fmt(d)}" for o, d in BOUND_RAYS)
        + ", which must solve the quartic? Give five True/False."),
}


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

def _plane_t() -> float:
    return float(S.Plane(PLANE_POINT, PLANE_NORMAL).hits(*PLANE_RAY)[0, 0])


def check_plane_parameter(answer) -> Result:
    """Check ``t = N·(Q - P0) / N·d`` for the ray and plane of exercise 1 (Goldman §19.3).

    Recognises the sign of ``Q - P0`` reversed, the distance along the ray instead of the parameter,
    and ``N·Q / N·d`` (the origin left out).

    >>> check_plane_parameter(0.5)
    Not yet: that is N·Q / N·d: the numerator is N·(Q - P0), the plane's point minus the ray's origin.
    """
    value, err = read_number(answer, "your t")
    if err is not None:
        return err
    t = _plane_t()
    N, Q, (P0, d) = (np.array(x, float) for x in (PLANE_NORMAL, PLANE_POINT, PLANE_RAY))
    if abs(value - t) <= 1e-4:
        return correct(f"t = {fmt(t)}: N·(Q - P0) = {fmt(N @ (Q - P0))}, N·d = {fmt(N @ d)}; the hit is "
                       f"{fmt(P0 + t * d)}.")
    if abs(value + t) <= 1e-4:
        return wrong("the sign is wrong: t = N·(Q - P0) / N·d, with Q - P0 (from the ray's origin to the plane's "
                     "point), not P0 - Q.")
    if abs(value - t * np.linalg.norm(d)) <= 1e-4:
        return wrong("that is the distance from the origin to the hit, |t d|; the question asks for t in units of "
                     "the direction as given (do not normalise d).")
    if abs(value - (N @ Q) / (N @ d)) <= 1e-4:
        return wrong("that is N·Q / N·d: the numerator is N·(Q - P0), the plane's point minus the ray's origin.")
    return wrong(f"your t is {off_by(value, t)}; substitute P0 + t d into N·(P - Q) = 0 and solve for t.")


def check_polygon_inside(answer) -> Result:
    """Check which query points lie inside the U-shaped polygon (Goldman §19.3).

    Recognises the convex hull's answer (the notch counted inside), the convex edge test applied to
    a non-convex polygon, and every answer flipped.

    >>> check_polygon_inside([True, True, True, True, False])
    Not yet: you counted the point in the notch of the U as inside: that is the convex hull's answer. The polygon is not convex: count how often a ray from the point crosses its edges (odd: inside).
    """
    flags, err = _read_flags(answer, "your answer", len(POLYGON_QUERIES))
    if err is not None:
        return err
    truth = S.Polygon(POLYGON).inside(POLYGON_QUERIES).tolist()
    if flags == truth:
        return correct("the points in the two arms and the bottom bar are inside; the one in the notch and the one "
                       "beyond the right arm are outside.")
    hull = [bool(p[0] <= 5 and p[1] <= 4 and p[0] >= 0 and p[1] >= 0) for p in POLYGON_QUERIES]
    if flags == hull:
        return wrong("you counted the point in the notch of the U as inside: that is the convex hull's answer. The "
                     "polygon is not convex: count how often a ray from the point crosses its edges (odd: inside).")
    if not any(flags) and any(truth):
        return wrong("no point inside: the convex test (inside every edge's half-plane) fails for every point of "
                     "a non-convex polygon, since some edges turn the other way. Use the crossing (even-odd) test.")
    if flags == [not f for f in truth]:
        return wrong("every answer is flipped: an odd number of crossings means inside, an even number outside.")
    wrong_count = sum(f != t for f, t in zip(flags, truth))
    return wrong(f"{wrong_count} of the {len(truth)} answers are wrong; draw the U and cast a ray from each point.")


# -- §19.4 ---------------------------------------------------------------------------------------------

def check_sphere_hit(answer) -> Result:
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
    P0, d = (np.array(x, float) for x in SPHERE_RAY)
    oc = P0 - np.array(SPHERE_CENTER)
    near, far = S.Sphere(SPHERE_CENTER, SPHERE_RADIUS).hits(P0, d)[0]
    if abs(value - near) <= 1e-4:
        return correct(f"t = {fmt(near, 6)}, the smaller root of {fmt(d @ d)} t^2 + {fmt(2 * d @ oc)} t + "
                       f"{fmt(oc @ oc - SPHERE_RADIUS ** 2)} = 0; the ray leaves the sphere at the other root.")
    if abs(value - far) <= 1e-4:
        return wrong("that is the far root, where the ray leaves the sphere; the first hit is the smaller positive root.")
    if abs(value - near * np.linalg.norm(d)) <= 1e-4 or abs(value - far * np.linalg.norm(d)) <= 1e-4:
        return wrong("that is a distance along the ray, |t d|; t is measured in units of d as given.")
    roots = np.roots([1.0, 2 * d @ oc, oc @ oc - SPHERE_RADIUS ** 2])
    if np.any(np.abs(roots.real - value) <= 1e-4):
        return wrong("that root comes from taking a = 1, as if d were a unit vector: here d·d is not 1, so a = d·d.")
    return wrong(f"your t is {off_by(value, near)}; expand |P0 + t d - C|^2 = r^2 into a t^2 + b t + c = 0.")


def check_cylinder_hit(answer) -> Result:
    """Check where the ray of exercise 4 enters the capped cylinder (Goldman §19.4.2): the first hit
    with the wall or a cap that lies on the bounded solid.

    Recognises the infinite cylinder's wall hit, the exit (the open tube's only hit), and the plane
    of the bottom cap outside its disc.
    """
    value, err = read_number(answer, "your t")
    if err is not None:
        return err
    base, axis, radius, height = CYLINDER
    o, d = CYLINDER_RAY
    entry, leave = S.Cylinder(base, axis, radius, height).hits(o, d)[0]
    wall = S.Cylinder(base, axis, radius).hits(o, d)[0]
    if abs(value - entry) <= 1e-4:
        return correct(f"t = {fmt(entry)}: the ray enters through the top cap at {fmt(np.add(o, entry * np.array(d)))} "
                       f"and leaves through the wall at t = {fmt(leave)}.")
    if abs(value - wall[0]) <= 1e-4:
        return wrong("that is where the ray meets the infinite cylinder, but there the point is above the top "
                     "(z > height): the bounded cylinder's wall is not there. Check the caps.")
    if abs(value - leave) <= 1e-4:
        return wrong("that is where the ray leaves through the wall (the only hit of an open tube); it enters "
                     "earlier, through a cap.")
    t_bottom = (base[2] - o[2]) / d[2]
    if abs(value - t_bottom) <= 1e-4:
        return wrong("that is where the ray meets the plane of the bottom cap, but outside its disc (the point is "
                     "farther than the radius from the axis).")
    return wrong(f"your t is {off_by(value, entry)}; find the wall's hits and the caps' hits and keep those on the "
                 f"bounded solid.")


# -- §19.6 ---------------------------------------------------------------------------------------------

def check_torus_normal(answer) -> Result:
    """Check the unit outward normal of the torus of exercise 5 at its point (Goldman §19.6).

    Recognises the unnormalised gradient, the unnormalised offset from the core circle, the normal
    of a sphere about the center, and the inward normal.

    >>> check_torus_normal([-0.36, -0.48, -0.8])
    Not yet: that is the inward normal; the outward one points away from the core circle of the tube.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    c, w, R, r = TORUS
    n = S.Torus(c, w, R, r).normal([TORUS_POINT])[0]
    P = np.array(TORUS_POINT)
    tol = 1e-4
    if np.abs(got - n).max() <= tol:
        return correct(f"the unit normal is {fmt(n)}: along P minus the nearest point of the core circle.")
    if np.abs(got + n).max() <= tol:
        return wrong("that is the inward normal; the outward one points away from the core circle of the tube.")
    length = np.linalg.norm(got)
    if length > 0 and np.abs(got / length - n).max() <= tol:
        return wrong(f"the direction is right but its length is {fmt(length, 4)}: divide by the length to get a "
                     f"unit normal.")
    if np.abs(got - P / np.linalg.norm(P)).max() <= tol:
        return wrong("that is P / |P|, a sphere's normal about the center; a torus's normal points from the core "
                     "circle (radius R in the plane z = 0), not from the center.")
    return wrong(f"your normal is {far_off(got, n)} from the right one; differentiate "
                 f"(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) and normalise.")


def _bound_answers():
    c, w, R, r = BOUND_TORUS
    T = S.Torus(c, w, R, r)
    solve, hit = [], []
    for o, d in BOUND_RAYS:
        hit.append(bool(np.isfinite(T.intersect(o, d)[0])))
        solve.append(T.quartics_solved == 1)
    return solve, hit


def check_torus_bound(answer) -> Result:
    """Check which rays of exercise 6 pass the bounding test and solve the quartic (Goldman §19.6.1).

    Recognises "does the ray hit the torus" answered instead, the sphere test without the slab, and
    every answer flipped.

    >>> check_torus_bound([True, False, False, False, True])
    Not yet: you answered whether each ray hits the torus; the bound only rules rays out. A ray down the hole passes the bound and must solve the quartic (which then has no real root).
    """
    flags, err = _read_flags(answer, "your answer", len(BOUND_RAYS))
    if err is not None:
        return err
    solve, hit = _bound_answers()
    if flags == solve:
        return correct("three rays pass the bound; the one beside the sphere and the one above the slab skip the "
                       "quartic. The ray down the hole passes it and finds no root.")
    if flags == hit:
        return wrong("you answered whether each ray hits the torus; the bound only rules rays out. A ray down the "
                     "hole passes the bound and must solve the quartic (which then has no real root).")
    c, w, R, r = BOUND_TORUS
    sphere = [bool(np.linalg.norm(np.cross(np.subtract(c, o), d)) / np.linalg.norm(d) <= R + r) for o, d in BOUND_RAYS]
    if flags == sphere:
        return wrong("that is the bounding sphere alone: a ray that meets the sphere only where |z| > r cannot "
                     "meet the torus either (the slab is part of the bound).")
    if flags == [not f for f in solve]:
        return wrong("every answer is flipped: True means the ray must solve the quartic (it passed the bound).")
    return wrong(f"{sum(f != s for f, s in zip(flags, solve))} of the {len(solve)} answers are wrong; for each ray "
                 f"find its distance from the center and where it crosses the slab |z| <= r.")


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
