"""Exercise checkers for chapter 18, surfaces: the general theory (Goldman §18.1-18.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other surfaces, points and radii than the chapter's worked examples.

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
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
__all__ = ["PROBLEMS", "SLIPS", "IMPLICIT_POINT", "GRAPH_UV", "DEFORM_NORMAL", "NEWTON_START", "NEWTON_ORIGIN",
           "NEWTON_DIRECTION", "CYLINDER_RADIUS", "TORUS_R", "TORUS_r", "TORUS_V",
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


def _implicit_F(P):
    return P[:, 0] ** 2 + 2 * P[:, 1] ** 2 - P[:, 2] ** 2 - 1


def _implicit_grad(P):
    return np.stack([2 * P[:, 0], 4 * P[:, 1], -2 * P[:, 2]], -1)


def _graph(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return np.stack([u + 0 * v, v + 0 * u, u * u * v], -1)


def _dome(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return np.stack([u + 0 * v, v + 0 * u, 1 - u * u - v * v], -1)


def _shear_jacobian(P):
    return np.broadcast_to(np.array([[1.0, 0.0, 2.0], [0.0, 3.0, 0.0], [0.0, 0.0, 1.0]]), (len(P), 3, 3))


PROBLEMS = {
    "check_implicit_normal": (
        f"The point P = (1, 1, √2) lies on the implicit surface F(x, y, z) = x^2 + 2 y^2 - z^2 - 1 = 0. Give the unit "
        f"normal at P in the direction of grad F, [x, y, z] to 4 decimals (Goldman §18.2)."),
    "check_parametric_normal": (
        f"The parametric surface X(u, v) = (u, v, u^2 v). Give the unit normal X_u × X_v / |X_u × X_v| at "
        f"(u, v) = {fmt(GRAPH_UV)}, [x, y, z] to 4 decimals (Goldman §18.2)."),
    "check_deformed_normal": (
        f"A surface has the unit normal n = (1, 1, 1)/√3 at a point P. The deformation A(x, y, z) = (x + 2z, 3y, z) "
        f"maps it to a new surface. Give the unit normal of the deformed surface at A(P) (the image of n's side), "
        f"[x, y, z] to 4 decimals (Goldman §18.2)."),
    "check_newton_step": (
        f"To intersect the ray O + t d, O = {fmt(NEWTON_ORIGIN)}, d = {fmt(NEWTON_DIRECTION)}, with the parametric "
        f"surface X(u, v) = (u, v, 1 - u^2 - v^2), Newton's method solves G(t, u, v) = O + t d - X(u, v) = 0. Take "
        f"one Newton step from (t, u, v) = {fmt(NEWTON_START)}: give the new [t, u, v] (Goldman §18.3)."),
    "check_cylinder_curvature": (
        f"A circular cylinder has radius {fmt(CYLINDER_RADIUS)}. Give its Gaussian curvature K and the absolute value "
        f"of its mean curvature |H| at any point, as [K, |H|] (Goldman §18.4)."),
    "check_torus_curvature": (
        f"A torus has R = {fmt(TORUS_R)} (from its centre to the centre of the tube) and tube radius "
        f"r = {fmt(TORUS_r)}; parametrise it by ((R + r cos v) cos u, (R + r cos v) sin u, r sin v). Give its Gaussian "
        f"curvature K at the points with v = {fmt(TORUS_V)} degrees, to 4 decimals (Goldman §18.4)."),
}


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


# -- §18.2 ---------------------------------------------------------------------------------------------

def check_implicit_normal(answer) -> Result:
    """Check the unit normal grad F / |grad F| of the implicit surface at the given point
    (Goldman §18.2).

    Recognises the gradient left unnormalised, the opposite direction, and a lost minus sign on the
    z-derivative.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    P = np.array([IMPLICIT_POINT])
    g = _implicit_grad(P)[0]
    expected = sf.implicit_normal(_implicit_grad, P)[0]
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the unit normal is {fmt(expected)}: grad F = (2x, 4y, -2z) divided by its length.")
    if _close(got, g, tol):
        return wrong("that is grad F itself; the unit normal is grad F divided by its length |grad F|.")
    if _close(got, -expected, tol):
        return wrong("your normal points the other way: the question asks for the direction of grad F, towards "
                     "F > 0.")
    if _close(got, _unit(g * [1, 1, -1]), tol):
        return wrong("check the sign of the z-component: the derivative of -z^2 is -2z.")
    return wrong(f"your normal is {_dist(got, expected)}; differentiate F in x, y and z, evaluate at P, and "
                 f"divide by the length (your vector has length {fmt(np.linalg.norm(got), 4)}).")


def check_parametric_normal(answer) -> Result:
    """Check the unit normal X_u × X_v / |X_u × X_v| of the parametric surface at the given (u, v)
    (Goldman §18.2).

    Recognises X_v × X_u (the opposite normal), the unnormalised cross product, and a sign slip in
    the middle component.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    u, v = GRAPH_UV
    expected = sf.parametric_normal(_graph, u, v)
    Xu, Xv = np.array([1.0, 0.0, 2 * u * v]), np.array([0.0, 1.0, u * u])
    cross = np.cross(Xu, Xv)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"X_u × X_v = {fmt(cross)}, of length {fmt(np.linalg.norm(cross), 4)}: the unit normal is "
                       f"{fmt(expected)}.")
    if _close(got, -expected, tol):
        return wrong("that is X_v × X_u, the opposite normal: the order of the factors sets the orientation; the "
                     "question asks for X_u × X_v.")
    if _close(got, cross, tol):
        return wrong("that is X_u × X_v itself; divide it by its length to get the unit normal.")
    if _close(got, _unit(cross * [1, -1, 1]), tol):
        return wrong("check the middle component of the cross product: (a × b)_y = a_z b_x - a_x b_z.")
    return wrong(f"your normal is {_dist(got, expected)}; X_u = (1, 0, 2uv) and X_v = (0, 1, u^2) at the given "
                 f"(u, v), then their cross product, normalised.")


def check_deformed_normal(answer) -> Result:
    """Check the unit normal of the deformed surface, J^{-T} n normalised, for the Jacobian J of the
    deformation (Goldman §18.2).

    Recognises J n (the normal moved like a tangent), J^{-1} n (the inverse without the transpose),
    J^T n (the transpose without the inverse), and the unnormalised J^{-T} n.
    """
    got, err = _read_vector(answer, "your normal", 3, "the unit normal as [x, y, z]")
    if err is not None:
        return err
    n = np.array([DEFORM_NORMAL])
    J = _shear_jacobian(n)
    expected = sf.deformed_normals(J, n)[0]
    M = J[0]
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the deformed normal is {fmt(expected)}: J^(-T) n is perpendicular to every mapped tangent "
                       f"J t, since (J^(-T) n)·(J t) = n·t = 0.")
    if _close(got, -expected, tol):
        return wrong("your normal points to the other side; J^(-T) n keeps the side of n.")
    if _close(got, _unit(M @ n[0]), tol):
        return wrong("that is J n: you moved the normal like a tangent vector. Normals map by the inverse transpose "
                     "J^(-T) of the Jacobian.")
    if _close(got, _unit(np.linalg.solve(M, n[0])), tol):
        return wrong("that is J^(-1) n: the inverse, but not transposed; normals map by J^(-T) = (J^(-1))^T.")
    if _close(got, _unit(M.T @ n[0]), tol):
        return wrong("that is J^T n: the transpose, but not inverted; normals map by J^(-T) = (J^T)^(-1).")
    if _close(got, np.linalg.solve(M.T, n[0]), tol) or _close(got, np.linalg.solve(M.T, [1, 1, 1]), tol):
        return wrong("that is J^(-T) n before normalising: divide it by its length.")
    return wrong(f"your normal is {_dist(got, expected)}; the Jacobian of A is [[1, 0, 2], [0, 3, 0], [0, 0, 1]]; "
                 f"solve J^T m = n for m and normalise it.")


# -- §18.3 ---------------------------------------------------------------------------------------------

def _newton(start, sign_xu=-1.0, add=False):
    O, d = np.array(NEWTON_ORIGIN), np.array(NEWTON_DIRECTION)
    t, u, v = start
    G = O + t * d - _dome(u, v)
    Xu, Xv = np.array([1.0, 0.0, -2 * u]), np.array([0.0, 1.0, -2 * v])
    J = np.stack([d, sign_xu * Xu, sign_xu * Xv], axis=-1)
    step = np.linalg.solve(J, G)
    return np.array([t, u, v]) + (step if add else -step)


def check_newton_step(answer) -> Result:
    """Check one Newton step on G = O + t d - X(u, v) from the given start, with the Jacobian
    J = [d, -X_u, -X_v] (Goldman §18.3).

    Recognises the step added instead of subtracted, +X_u and +X_v in the Jacobian, and the
    converged intersection (2, 0, 0) instead of one step.
    """
    got, err = _read_vector(answer, "your (t, u, v)", 3, "the new [t, u, v]")
    if err is not None:
        return err
    expected = _newton(NEWTON_START)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"one step lands on {fmt(expected)}: (u, v) is already the hit point's, and the next step "
                       f"corrects t.")
    if _close(got, [2.0, 0.0, 0.0], tol):
        return wrong("that is where Newton's method converges (the intersection itself); the exercise asks for the "
                     "point after one step.")
    if _close(got, _newton(NEWTON_START, add=True), tol):
        return wrong("you added the step: Newton's update is (t, u, v) - J^(-1) G.")
    if _close(got, _newton(NEWTON_START, sign_xu=1.0), tol):
        return wrong("the Jacobian of G = O + t d - X(u, v) has the columns d, -X_u and -X_v (the minus from -X).")
    return wrong(f"your point is {_dist(got, expected)}; evaluate G and its Jacobian [d, -X_u, -X_v] at the start, "
                 f"solve J s = G and subtract s.")


# -- §18.4 ---------------------------------------------------------------------------------------------

def check_cylinder_curvature(answer) -> Result:
    """Check [K, |H|], the Gauss and mean curvature of the cylinder of the exercise (Goldman §18.4).

    Recognises the sphere's values (1/r^2, 1/r), |H| = 1/r (a principal curvature, not the mean),
    K = 1/r^2 with the right H, and a negative |H| (an absolute value is never negative: rejected,
    naming the rule, even when its size is right).
    """
    got, err = _read_vector(answer, "your [K, |H|]", 2, "[K, |H|]")
    if err is not None:
        return err
    r = CYLINDER_RADIUS
    c = sf.parametric_cylinder(r)
    H, K = c.curvature(0.3, 0.1)
    expected = np.array([float(K), abs(float(H))])
    tol = 1e-4
    if got[1] < 0:
        return wrong("|H| is an absolute value, so it cannot be negative: H itself has a sign that depends on the "
                     "choice of normal, |H| does not.")
    if _close(got, expected, tol):
        return correct("K = 0 and |H| = 1/(2r): the principal curvatures are 1/r around the cylinder and 0 along it; "
                       "K is their product, H their average.")
    if _close(got, [1 / r ** 2, 1 / r], tol):
        return wrong("those are a sphere's values: a cylinder is straight along its axis, so one of its principal "
                     "curvatures vanishes; K is their product and H their average.")
    if _close(got, [0.0, 1 / r], tol):
        return wrong("K is right, but |H| = 1/r is the curvature around the cylinder alone; H is the average of the two "
                     "principal curvatures (the one along the axis vanishes).")
    if _close(got, [1 / r ** 2, 1 / (2 * r)], tol):
        return wrong("H is right, but K is the product of the principal curvatures, and the one along the axis "
                     "vanishes (the axis is a straight line).")
    bad = "K" if abs(got[0] - expected[0]) > tol else "|H|"
    return wrong(f"your {bad} is off; the principal curvatures are 1/r around the cylinder and none along its "
                 f"straight axis: K is their product, H their average.")


def check_torus_curvature(answer) -> Result:
    """Check the Gauss curvature K = cos v / (r (R + r cos v)) of the torus at the given v (Goldman
    §18.4).

    Recognises the lost sign, (R + r) in place of (R + r cos v), and v taken in radians.
    """
    value, err = read_number(answer, "K")
    if err is not None:
        return err
    R, r, v = TORUS_R, TORUS_r, math.radians(TORUS_V)
    _, K = sf.parametric_torus(R, r).curvature(0.0, v)
    expected = float(K)
    tol = 5e-4
    if abs(value - expected) <= tol:
        return correct(f"K = {fmt(expected)}: negative, as on every point of the inner half of the tube "
                       f"(cos v < 0), where the surface is saddle-shaped.")
    if abs(value + expected) <= tol:
        return wrong("you lost the sign: at v = 120 degrees cos v < 0, the inner side of the tube, where the torus is "
                     "saddle-shaped and K < 0.")
    if abs(value - math.cos(v) / (r * (R + r))) <= tol:
        return wrong("the distance from the axis is R + r cos v, not R + r: use the same v in both places.")
    if abs(value - math.cos(TORUS_V) / (r * (R + r * math.cos(TORUS_V)))) <= tol:
        return wrong("you took v = 120 in radians; the angle is 120 degrees.")
    return wrong(f"your K is {off_by(value, expected)}; use K = cos v / (r (R + r cos v)).")


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
