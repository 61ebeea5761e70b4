"""Exercise checkers for chapter 29, subdivision matrices and iterated function systems
(Goldman §29.2-29.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> check_normal_curve_point([3 / 8, 3 / 8, 1 / 8])
Correct: N(1/2) = (B_1^3, B_2^3, B_3^3)(1/2) = (0.375, 0.375, 0.125).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import subdivision_matrices as sm
from goldman_lib.exercises import fmt_points, Result, check_points, correct, fmt, read_points, wrong

__all__ = ["PROBLEMS", "FIXED_CTRL", "FRACTAL_CTRL", "FRACTAL_MIDDLE",
           "check_quadratic_left_matrix", "check_chaikin_right_matrix", "check_normal_curve_point",
           "check_right_map_fixed_point", "check_fractal_joint"]

#: Exercise 4: the quadratic whose map P^-1 R P is asked about.
FIXED_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [6.0, 2.0]])
#: Exercise 5: the control points and middle weight of the fractal curve.
FRACTAL_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0]])
FRACTAL_MIDDLE = -0.5


PROBLEMS = {
    "check_quadratic_left_matrix": (
        "Give the left subdivision matrix L of a quadratic Bezier curve at t = 1/2, as a 3x3 list of rows: "
        "L @ P are the control points of the half on [0, 1/2] (Goldman §29.2)."),
    "check_chaikin_right_matrix": (
        "Give the right subdivision matrix R of one segment of a uniform quadratic B-spline (three control "
        "points), as a 3x3 list of rows (Goldman §29.2)."),
    "check_normal_curve_point": (
        "Give the point N(1/2) of the normal curve of degree 3, whose control points are the origin and "
        "the unit points e1, e2, e3 of 3-space (Goldman §29.3)."),
    "check_right_map_fixed_point": (
        f"For the quadratic Bezier curve with control points {fmt_points(FIXED_CTRL)}, which point does the map "
        f"P^-1 R P of its IFS leave fixed? Give [x, y] (Goldman §29.3)."),
    "check_fractal_joint": (
        f"With L = [[1, 0, 0], [1/2, 1/2, 0], [u, v, u]] and R = [[u, v, u], [0, 1/2, 1/2], [0, 0, 1]], "
        f"v = {fmt(FRACTAL_MIDDLE)} and rows summing to one, the two halves of the fractal with control points "
        f"{fmt_points(FRACTAL_CTRL)} meet at one point. Give it as [x, y] (Goldman §29.4)."),
}


def _matrix(answer, what, shape=(3, 3)):
    got, err = read_points(answer, what, ask=what + " as a list of rows")
    if err is not None:
        return None, err
    if got.shape != shape:
        return None, wrong(f"{what} should be a {shape[0]}x{shape[1]} matrix; yours has shape {got.shape}.")
    return got, None


def check_quadratic_left_matrix(answer) -> Result:
    """Check L of the quadratic Bezier curve (Goldman §29.2); recognises R and the transpose of L.

    >>> check_quadratic_left_matrix([[1, 0, 0], [0.5, 0.5, 0], [0.25, 0.5, 0.25]])
    Correct: L is the left edge of the de Casteljau triangle: row i holds B_j^i(1/2).
    >>> check_quadratic_left_matrix([[1, 0.5, 0.25], [0, 0.5, 0.5], [0, 0, 0.25]])
    Not yet: that is the transpose of L: with points as rows, each new control point is a row of L, and the rows (not the columns) sum to 1.
    """
    got, err = _matrix(answer, "L")
    if err is not None:
        return err
    L, R = sm.bezier_subdivision_matrices(2)
    if np.allclose(got, L, atol=1e-9):
        return correct("L is the left edge of the de Casteljau triangle: row i holds B_j^i(1/2).")
    if np.allclose(got, L.T, atol=1e-9):
        return wrong("that is the transpose of L: with points as rows, each new control point is a row of L, and "
                     "the rows (not the columns) sum to 1.")
    if np.allclose(got, R, atol=1e-9):
        return wrong("that is R, the right half; L starts at P0: its first row is (1, 0, 0).")
    sums = got.sum(axis=1)
    if not np.allclose(sums, 1, atol=1e-9):
        k = int(np.flatnonzero(np.abs(sums - 1) > 1e-9)[0])
        return wrong(f"every row of L must sum to 1 (each new control point is an affine combination); row {k} sums to {fmt(sums[k])}.")
    return check_points(got, L, what="the rows of L", tol=1e-9, hint="row i is (B_0^i, ..., B_i^i)(1/2), then zeros")


def check_chaikin_right_matrix(answer) -> Result:
    """Check R of a uniform quadratic B-spline segment (Goldman §29.2); recognises L and the Bezier R.

    >>> check_chaikin_right_matrix([[0.25, 0.75, 0], [0, 0.75, 0.25], [0, 0.25, 0.75]])
    Correct: R holds Chaikin's weights 3/4, 1/4: the right half of the segment is controlled by the cuts near P1 and P2.
    """
    got, err = _matrix(answer, "R")
    if err is not None:
        return err
    L, R = sm.bspline_subdivision_matrices(2)
    if np.allclose(got, R, atol=1e-9):
        return correct("R holds Chaikin's weights 3/4, 1/4: the right half of the segment is controlled by the cuts "
                       "near P1 and P2.")
    if np.allclose(got, L, atol=1e-9):
        return wrong("that is L, the left half; R uses the cuts of the legs P0P1 and P1P2 nearer to P2's side.")
    if np.allclose(got, sm.bezier_subdivision_matrices(2)[1], atol=1e-9):
        return wrong("that is the Bezier R; a B-spline segment is subdivided by Chaikin's corner cutting "
                     "(weights 3/4 and 1/4), and does not pass through its end control points.")
    return check_points(got, R, what="the rows of R", tol=1e-9, hint="every row is 3/4 of one point plus 1/4 of a neighbour")


def check_normal_curve_point(answer) -> Result:
    """Check N(1/2) for the normal curve of degree 3 (Goldman §29.3); recognises the answer with B_0.

    >>> check_normal_curve_point([1 / 8, 3 / 8, 3 / 8, 1 / 8])
    Not yet: the normal curve lives in 3-space: its coordinates are B_1, B_2, B_3; B_0 is the weight of the origin and adds nothing.
    """
    got, err = read_points(answer, "your point", ask="the point as [x, y, z]")
    if err is not None:
        return err
    expected = sm.normal_curve(3, 0.5)
    if got.shape == (4,) and np.allclose(got, [1 / 8, 3 / 8, 3 / 8, 1 / 8], atol=1e-9):
        return wrong("the normal curve lives in 3-space: its coordinates are B_1, B_2, B_3; B_0 is the weight of "
                     "the origin and adds nothing.")
    if got.shape != (3,):
        return wrong(f"N(1/2) should be one point [x, y, z]; yours has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-9):
        return correct(f"N(1/2) = (B_1^3, B_2^3, B_3^3)(1/2) = {fmt(expected)}.")
    return check_points(got, expected, what="N(1/2)", tol=1e-9, hint="B_k^3(1/2) = C(3, k) / 8")


def check_right_map_fixed_point(answer) -> Result:
    """Check the fixed point of ``P^-1 R P`` for ``FIXED_CTRL`` (Goldman §29.3); recognises P0 (the
    fixed point of the left map) and the curve point at t = 1/2.

    >>> check_right_map_fixed_point([6, 2])
    Correct: the right map sends the whole curve to its right half and keeps the end P2 = (6, 2) where it is.
    """
    got, err = read_points(answer, "your point", ask="the fixed point as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the fixed point should be one point [x, y]; yours has shape {got.shape}.")
    maps, P = sm.curve_ifs(FIXED_CTRL)
    M = maps[1]
    expected = np.linalg.solve((np.eye(3) - M)[:2, :2].T, M[2, :2])  # x (I - A) = t for x -> x A + t
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"the right map sends the whole curve to its right half and keeps the end P2 = {fmt(expected)} where it is.")
    if np.allclose(got, FIXED_CTRL[0], atol=1e-6):
        return wrong("P0 is the fixed point of the left map P^-1 L P; the right map fixes the other end.")
    mid = (FIXED_CTRL[0] + 2 * FIXED_CTRL[1] + FIXED_CTRL[2]) / 4
    if np.allclose(got, mid, atol=1e-6):
        return wrong("C(1/2) is where the halves meet, but the right map moves it (to C(3/4)); a fixed point of a "
                     "map onto the right half is an end that the half shares with the whole curve.")
    return check_points(got, expected, what="the fixed point", tol=1e-6, hint="R's last row is (0, 0, 1)")


def check_fractal_joint(answer) -> Result:
    """Check the point where the halves of the fractal meet (Goldman §29.4); recognises the Bezier
    midpoint C(1/2) and weights that do not sum to one.

    >>> check_fractal_joint([2, -2])
    Correct: the joint is u P0 + v P1 + u P2 with v = -0.5 and u = (1 - v)/2 = 0.75: (2, -2).
    """
    got, err = read_points(answer, "your point", ask="the joint as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the joint should be one point [x, y]; yours has shape {got.shape}.")
    v = FRACTAL_MIDDLE
    u = (1 - v) / 2
    P = FRACTAL_CTRL
    expected = u * P[0] + v * P[1] + u * P[2]
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"the joint is u P0 + v P1 + u P2 with v = {fmt(v)} and u = (1 - v)/2 = {fmt(u)}: {fmt(expected)}.")
    if np.allclose(got, (P[0] + 2 * P[1] + P[2]) / 4, atol=1e-6):
        return wrong("that is the Bezier midpoint C(1/2) (v = 1/2); here the middle weight is "
                     f"{fmt(v)}, so u = (1 - v)/2 = {fmt(u)}.")
    for uu in (0.5, (1 + v) / 2, 0.25):
        if np.allclose(got, uu * P[0] + v * P[1] + uu * P[2], atol=1e-6):
            return wrong(f"the weights must sum to one (an affine combination): u + v + u = 1 gives u = {fmt(u)}, "
                         f"not {fmt(uu)}.")
    return check_points(got, expected, what="the joint", tol=1e-6,
                        hint="it is the last row of L (the first of R) applied to the control points")
