"""Exercise checkers for chapter 28, knot insertion (Goldman §28.3-28.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> print(PROBLEMS["check_convergence_factor"])
Each level of subdivision halves the knot spacing h. By what factor does the distance from the control polygon to the curve shrink per level, for a smooth curve of degree >= 2 (Goldman §28.4.3)?
>>> check_convergence_factor(4)
Correct: the distance shrinks by a factor of about 4 per level: it is O(h^2).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib import knot_insertion as ki
from goldman_lib.exercises import (fmt_points, 
    Result,
    check_points,
    correct,
    fmt,
    read_number,
    read_points,
    wrong,
)

__all__ = ["PROBLEMS", "QUAD_CTRL", "QUAD_KNOTS", "QUAD_DEGREE", "BOEHM_U", "OSLO_NEW_KNOTS", "CHAIKIN_CTRL",
           "CROSSING_CTRL", "CROSSING_KNOTS", "CROSSING_LINE_Y",
           "check_boehm_insert", "check_oslo", "check_bezier_pieces", "check_chaikin", "check_convergence_factor",
           "check_crossing_bound"]

#: Exercises 1-3: the quadratic B-spline with knots 0, 0, 0, 1, 2, 2, 2 (two polynomial pieces).
QUAD_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 4.0], [6.0, 0.0]])
QUAD_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])
QUAD_DEGREE = 2
#: Exercise 1: the knot inserted once by Boehm's algorithm.
BOEHM_U = 0.5
#: Exercise 2: the refined knot vector of the Oslo algorithm (0.5 and 1.5 inserted at once).
OSLO_NEW_KNOTS = np.array([0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.0, 2.0])
#: Exercise 4: the open polygon refined by one level of Lane-Riesenfeld of degree 2 (Chaikin).
CHAIKIN_CTRL = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]])
#: Exercise 6: a cubic B-spline and a horizontal line y = CROSSING_LINE_Y.
CROSSING_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [3.0, 3.0], [4.0, -1.0], [5.0, 0.0]])
CROSSING_KNOTS = np.array([0.0, 0.0, 0.0, 0.0, 1 / 3, 2 / 3, 1.0, 1.0, 1.0, 1.0])
CROSSING_LINE_Y = 1.0


def _knots(t) -> str:
    return ", ".join(fmt(x) for x in np.asarray(t))


PROBLEMS = {
    "check_boehm_insert": (
        f"The quadratic B-spline with control points {fmt_points(QUAD_CTRL)} and knots {_knots(QUAD_KNOTS)}: insert the "
        f"knot u = {fmt(BOEHM_U)} once by Boehm's algorithm and give the five new control points (Goldman §28.3.1)."),
    "check_oslo": (
        f"For the same quadratic B-spline, give the control points over the refined knot vector "
        f"{_knots(OSLO_NEW_KNOTS)} (the knots 0.5 and 1.5 inserted at once): each new control point is the blossom "
        f"at two consecutive new knots (Goldman §28.3.2)."),
    "check_bezier_pieces": (
        "Convert the same quadratic B-spline to piecewise Bezier form: give the two Bezier control polygons, "
        "[[piece 1: 3 points], [piece 2: 3 points]] (Goldman §28.3.3)."),
    "check_chaikin": (
        f"Apply one level of the Lane-Riesenfeld algorithm of degree 2 (double every point, then average "
        f"neighbours twice) to the open polygon {fmt_points(CHAIKIN_CTRL)}: give the refined polygon (Goldman §28.4.1)."),
    "check_convergence_factor": (
        "Each level of subdivision halves the knot spacing h. By what factor does the distance from the control "
        "polygon to the curve shrink per level, for a smooth curve of degree >= 2 (Goldman §28.4.3)?"),
    "check_crossing_bound": (
        f"The cubic B-spline with control points {fmt_points(CROSSING_CTRL)} (clamped, uniform interior knots): without "
        f"drawing the curve, what is the largest number of times it can cross the line y = {fmt(CROSSING_LINE_Y)}? "
        f"(Goldman §28.3.4)"),
}


def check_boehm_insert(answer) -> Result:
    """Check the five control points after inserting ``BOEHM_U`` into the quadratic (Goldman §28.3.1).

    answer: (5, 2).  Recognises the weights a_i and 1 - a_i swapped, the old polygon returned
    unchanged, and a wrong number of points.

    >>> check_boehm_insert([[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]])
    Correct: the new control points match.
    >>> check_boehm_insert([[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]])
    Not yet: the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i with a_i = (u - t_i) / (t_(i+p) - t_i), so a_2 = 0.25 goes with P_2.
    """
    what = "the new control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t, p, u = QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, BOEHM_U
    expected, _ = ki.boehm_insert(P, t, p, u)
    if got.shape == P.shape and np.allclose(got, P):
        return wrong("that is the old polygon: inserting a knot adds one control point (5 here) and replaces "
                     f"p - 1 = {p - 1} old point by p = {p} new ones on the legs.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (one more than the {len(P)} old ones); "
                     f"yours has shape {got.shape}.")
    k = 2
    i = np.arange(k - p + 1, k + 1)
    a = ((u - t[i]) / (t[i + p] - t[i]))[:, None]
    swapped = expected.copy()
    swapped[i] = a * P[i - 1] + (1 - a) * P[i]
    if not np.allclose(swapped, expected) and np.allclose(got, swapped, atol=1e-6):
        return wrong("the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i with a_i = (u - t_i) / (t_(i+p) - t_i), "
                     f"so a_2 = {fmt(a[1, 0])} goes with P_2.")
    return check_points(got, expected, what=what,
                        hint="u = 0.5 lies in [t_2, t_3) = [0, 1); a_1 = (0.5 - t_1)/(t_3 - t_1), a_2 = (0.5 - t_2)/(t_4 - t_2)")


def check_oslo(answer) -> Result:
    """Check the six control points over ``OSLO_NEW_KNOTS`` (Goldman §28.3.2).

    answer: (6, 2).  Recognises only one of the two knots inserted (Boehm once), and the midpoints
    of the old legs (the weights of uniform subdivision, wrong for these knots).

    >>> check_oslo([[0, 0], [1, 2], [2.5, 4], [3.5, 4], [5, 2], [6, 0]])
    Correct: the refined control points match.
    >>> check_oslo([[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]])
    Not yet: these are the points after inserting 0.5 alone; the Oslo algorithm inserts 0.5 and 1.5 together, giving 6 points.
    """
    what = "the refined control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    expected = ki.oslo(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, OSLO_NEW_KNOTS)
    for u in (0.5, 1.5):
        one, _ = ki.boehm_insert(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, u)
        if got.shape == one.shape and np.allclose(got, one, atol=1e-6):
            return wrong(f"these are the points after inserting {fmt(u)} alone; the Oslo algorithm inserts 0.5 and "
                         f"1.5 together, giving {len(expected)} points.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (two knots inserted into {len(QUAD_CTRL)} points); "
                     f"yours has shape {got.shape}.")
    labels = ", ".join(f"b({fmt(OSLO_NEW_KNOTS[j + 1])}, {fmt(OSLO_NEW_KNOTS[j + 2])})" for j in range(len(expected)))
    return check_points(got, expected, what=what,
                        hint=f"the new points are the blossom values {labels}; b(x, 1) runs from P_1 = b(0, 1) to "
                             f"P_2 = b(2, 1) as x goes from 0 to 2")


def check_bezier_pieces(answer) -> Result:
    """Check the two Bezier polygons of the quadratic (Goldman §28.3.3).

    answer: (2, 3, 2).  Recognises the old control points cut into pieces without computing the
    junction point, and a junction that is not the curve point at the knot.

    >>> check_bezier_pieces([[[0, 0], [2, 4], [3, 4]], [[3, 4], [4, 4], [6, 0]]])
    Correct: the Bezier pieces match.
    >>> check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]])
    Not yet: the pieces must meet at the curve point C(1) = b(1, 1) = (3, 4), the midpoint of P1 and P2 here: insert the knot 1 once more so that it has multiplicity p = 2.
    """
    what = "the Bezier pieces"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    expected, _ = ki.to_piecewise_bezier(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE)
    if got.shape != expected.shape:
        return wrong(f"{what} should be 2 quadratic Bezier polygons of 3 points each, shape (2, 3, 2); yours has "
                     f"shape {got.shape}.")
    junction = expected[0, -1]
    if not (np.allclose(got[0, -1], junction, atol=1e-6) and np.allclose(got[1, 0], junction, atol=1e-6)):
        return wrong(f"the pieces must meet at the curve point C(1) = b(1, 1) = {fmt(junction)}, the midpoint of "
                     f"P1 and P2 here: insert the knot 1 once more so that it has multiplicity p = 2.")
    return check_points(got.reshape(-1, 2), expected.reshape(-1, 2), what=what,
                        hint="the Bezier points of the piece over [a, b] are b(a, a), b(a, b), b(b, b)")


def check_chaikin(answer) -> Result:
    """Check one Lane-Riesenfeld level of degree 2 on ``CHAIKIN_CTRL`` (Goldman §28.4.1).

    answer: (6, 2).  Recognises a single averaging round (degree 1: the midpoints inserted), the
    closed-polygon answer (8 points) and the polygon after doubling only.

    >>> check_chaikin([[1, 0], [3, 0], [4, 1], [4, 3], [3, 4], [1, 4]])
    Correct: the points of the refined polygon match.
    >>> check_chaikin([[0, 0], [2, 0], [4, 0], [4, 2], [4, 4], [2, 4], [0, 4]])
    Not yet: that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice, giving the points 1/4 and 3/4 along each leg.
    """
    what = "the points of the refined polygon"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = CHAIKIN_CTRL
    expected = ki.lane_riesenfeld(P, 2, 1)
    once = ki.lane_riesenfeld(P, 1, 1)
    if got.shape == once.shape and np.allclose(got, once, atol=1e-6):
        return wrong("that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice, "
                     "giving the points 1/4 and 3/4 along each leg.")
    closed = ki.lane_riesenfeld(P, 2, 1, closed=True)
    if got.shape == closed.shape and all(np.any(np.linalg.norm(closed - g, axis=1) < 1e-6) for g in got):
        return wrong("that treats the polygon as closed (the leg from the last point back to the first is cut too); "
                     "the polygon is open, so the refined one has 2 * 4 - 2 = 6 points.")
    if got.shape == (8, 2) and np.allclose(got, np.repeat(P, 2, axis=0), atol=1e-6):
        return wrong("that is the doubled polygon only; now average neighbours twice.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points: doubling gives 8, and each of the 2 averaging "
                     f"rounds drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what=what, hint="each leg P_i P_(i+1) gives 3/4 P_i + 1/4 P_(i+1) and "
                                                        "1/4 P_i + 3/4 P_(i+1)")


def check_convergence_factor(answer) -> Result:
    """Check the per-level convergence factor of subdivision (Goldman §28.4.3): about 4.

    Recognises 2 (the factor for the knot spacing, not the distance) and 8.

    >>> check_convergence_factor(2)
    Not yet: 2 is the factor by which the knot spacing h shrinks; the distance from the control polygon to the curve is O(h^2), so it shrinks by 2^2 = 4.
    """
    what = "the factor"
    value, err = read_number(answer, what)
    if err is not None:
        return err
    if abs(value - 4.0) <= 0.25:
        return correct("the distance shrinks by a factor of about 4 per level: it is O(h^2).")
    if abs(value - 2.0) <= 0.25:
        return wrong("2 is the factor by which the knot spacing h shrinks; the distance from the control polygon "
                     "to the curve is O(h^2), so it shrinks by 2^2 = 4.")
    if abs(value - 0.25) <= 0.03:
        return wrong("0.25 is the ratio new distance / old distance; the factor it shrinks by is its inverse, 4.")
    return wrong(f"{what} should be about 4, you gave {fmt(value)}: a control point sits O(h^2) from the curve, and "
                 f"halving h divides h^2 by 4. Try the convergence study of §28.4.3.")


def check_crossing_bound(answer) -> Result:
    """Check the variation-diminishing bound for ``CROSSING_CTRL`` and the line y = 1 (Goldman §28.3.4).

    The bound is the number of times the control polygon crosses the line.  Recognises the
    number of control points below/above the line and the number of legs.

    >>> check_crossing_bound(4)
    Correct: the control polygon crosses y = 1 four times, so the curve crosses it at most 4 times (variation diminishing).
    """
    what = "the largest number of crossings"
    value, err = read_number(answer, what, unit="whole number")
    if err is not None:
        return err
    bound = bezier.variation_count(CROSSING_CTRL, [0.0, CROSSING_LINE_Y], [0.0, 1.0])
    words = {3: "three", 4: "four", 5: "five"}
    if abs(value - bound) < 1e-9:
        return correct(f"the control polygon crosses y = {fmt(CROSSING_LINE_Y)} {words.get(bound, bound)} times, so "
                       f"the curve crosses it at most {bound} times (variation diminishing).")
    if abs(value - (len(CROSSING_CTRL) - 1)) < 1e-9 and bound != len(CROSSING_CTRL) - 1:
        return wrong("that is the number of legs; count only the legs whose end points lie on opposite sides of the line.")
    if value < bound:
        return wrong(f"{fmt(value)} is too small: the bound is the number of crossings of the control polygon with the "
                     f"line (count the sign changes of y - {fmt(CROSSING_LINE_Y)} along the control points); the "
                     f"curve may reach it.")
    return wrong(f"{fmt(value)} is more than the bound: the curve crosses a line no more often than its control polygon "
                 f"does; count the sign changes of y - {fmt(CROSSING_LINE_Y)} along the control points.")
