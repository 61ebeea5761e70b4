"""Exercise checkers for chapter 25, Bezier subdivision (Goldman §25.2-25.5).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> print(PROBLEMS["check_reparametrised_parameter"])
The cubic is subdivided at t = 0.25 and the right piece is parametrised over [0, 1] again. Which parameter t of the original curve does the parameter s = 0.5 of the right piece correspond to (Goldman §25.2)?
>>> check_reparametrised_parameter(0.625)
Correct: s = 0.5 of the right piece is t = 0.625 of the original curve.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib.exercises import (fmt_points, Result, check_number, check_points, correct, fmt, read_number, read_points,
                                   wrong)

__all__ = ["PROBLEMS", "SUBDIVIDE_CTRL", "REPARAM_T", "REPARAM_S", "FLATNESS_CTRL", "CROSSING_CTRL",
           "CROSSING_LINE_Y", "C2_CTRL", "check_subdivision_left", "check_reparametrised_parameter",
           "check_flatness", "check_crossing_bound", "check_c2_continuation"]

#: Exercise 1: the cubic to subdivide at t = 1/2 by hand.
SUBDIVIDE_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [6.0, 4.0], [8.0, 0.0]])
#: Exercise 2: the split parameter and the parameter of the right piece.
REPARAM_T, REPARAM_S = 0.25, 0.5
#: Exercise 3: a straight but unevenly parametrised quadratic.
FLATNESS_CTRL = np.array([[0.0, 0.0], [3.0, 0.0], [4.0, 0.0]])
#: Exercise 4: the cubic and the horizontal line y = CROSSING_LINE_Y.
CROSSING_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [2.0, -3.0], [3.0, 1.0]])
CROSSING_LINE_Y = 0.5
#: Exercise 5: the cubic that a second cubic continues with C2 continuity.
C2_CTRL = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]])


PROBLEMS = {
    "check_subdivision_left": (
        f"Subdivide the cubic with control points {fmt_points(SUBDIVIDE_CTRL)} at t = 1/2 by the de Casteljau algorithm: "
        f"give the four control points of the left piece (the curve over [0, 1/2]) (Goldman §25.2)."),
    "check_reparametrised_parameter": (
        f"The cubic is subdivided at t = {fmt(REPARAM_T)} and the right piece is parametrised over [0, 1] again. "
        f"Which parameter t of the original curve does the parameter s = {fmt(REPARAM_S)} of the right piece "
        f"correspond to (Goldman §25.2)?"),
    "check_flatness": (
        f"The quadratic with control points {fmt_points(FLATNESS_CTRL)} is a straight segment. What is its flatness "
        f"max_k |P_k - ((1 - k/n) P_0 + (k/n) P_n)|, the bound used to stop subdividing (Goldman §25.3)?"),
    "check_crossing_bound": (
        f"At most how many times can the line y = {fmt(CROSSING_LINE_Y)} cross the Bezier curve with control "
        f"points {fmt_points(CROSSING_CTRL)}? Give the bound the control polygon guarantees (Goldman §25.4)."),
    "check_c2_continuation": (
        f"A second cubic Q continues the cubic with control points {fmt_points(C2_CTRL)} over a parameter interval of "
        f"the same length. Give Q0, Q1, Q2 so that the join is C2 (Goldman §25.5)."),
}


def check_subdivision_left(answer) -> Result:
    """Check the left piece of ``SUBDIVIDE_CTRL`` subdivided at 1/2 (Goldman §25.2).

    answer: (4, 2).  Recognises the right piece, the left piece in reverse, and the first level
    of the pyramid taken for the answer.

    >>> check_subdivision_left([[0, 0], [1, 2], [2.5, 3], [4, 3]])
    Correct: the left piece is the left edge of the de Casteljau pyramid: (0, 0), (1, 2), (2.5, 3), (4, 3).
    >>> check_subdivision_left([[4, 3], [5.5, 3], [7, 2], [8, 0]])
    Not yet: that is the right piece (the curve over [1/2, 1]), read up the right edge of the pyramid; the left piece starts at P0.
    """
    what = "the left piece's control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    left, right = bezier.subdivide(SUBDIVIDE_CTRL, 0.5)
    if got.shape != left.shape:
        return wrong(f"{what} should be four points, shape {left.shape} (a piece of a cubic is a cubic); "
                     f"yours has shape {got.shape}.")
    if np.allclose(got, left, atol=1e-6):
        return correct(f"the left piece is the left edge of the de Casteljau pyramid: {fmt_points(left)}.")
    if np.allclose(got, right, atol=1e-6):
        return wrong("that is the right piece (the curve over [1/2, 1]), read up the right edge of the pyramid; "
                     "the left piece starts at P0.")
    if np.allclose(got, left[::-1], atol=1e-6):
        return wrong("these are the right points in reverse order: the left piece starts at P0 = C(0) and ends at "
                     "C(1/2).")
    level1 = bezier.de_casteljau_steps(SUBDIVIDE_CTRL, 0.5)[1]
    if np.allclose(got[1:], level1, atol=1e-6):
        return wrong("you took the midpoints of the control polygon (level 1 of the pyramid); the left piece takes "
                     "the FIRST point of every level: P0, P0^1, P0^2, P0^3.")
    return check_points(got, left, what=what, hint="take the first point of each level of the pyramid at t = 1/2")


def check_reparametrised_parameter(answer) -> Result:
    """Check the original parameter of ``s = REPARAM_S`` on the right piece of a split at ``REPARAM_T`` (Goldman §25.2).

    Recognises the left piece's formula ``t s``.

    >>> check_reparametrised_parameter(0.125)
    Not yet: t s = 0.125 is the formula of the LEFT piece, which covers [0, t]; the right piece covers [t, 1]: t + (1 - t) s.
    """
    t, s = REPARAM_T, REPARAM_S
    expected = t + (1 - t) * s
    value, err = read_number(answer, "the parameter")
    if err is not None:
        return err
    if abs(value - expected) <= 1e-9:
        return correct(f"s = {fmt(s)} of the right piece is t = {fmt(expected)} of the original curve.")
    if abs(value - t * s) <= 1e-9:
        return wrong(f"t s = {fmt(t * s)} is the formula of the LEFT piece, which covers [0, t]; the right piece "
                     f"covers [t, 1]: t + (1 - t) s.")
    return check_number(value, expected, what="the parameter", tol=1e-9,
                        hint="the right piece maps [0, 1] onto [t, 1], so s goes to t + (1 - t) s")


def check_flatness(answer) -> Result:
    """Check the flatness of the straight, unevenly parametrised ``FLATNESS_CTRL`` (Goldman §25.3).

    Recognises 0 (straightness alone) and explains why the spacing matters.

    >>> check_flatness(1.0)
    Correct: the flatness is 1: P1 = (3, 0) is 1 away from the evenly spaced point (2, 0).
    >>> check_flatness(0)
    Not yet: the control points are collinear, so the polygon is straight (distance 0 from the chord), but they are not evenly spaced: P1 = (3, 0) should be at (2, 0) for the curve to run along the chord at constant speed. The flatness measures |P1 - (P0 + P2)/2|.
    """
    P = FLATNESS_CTRL
    expected = bezier.flatness(P)
    value, err = read_number(answer, "the flatness")
    if err is not None:
        return err
    mid = (P[0] + P[-1]) / 2
    if abs(value - expected) <= 1e-9:
        return correct(f"the flatness is {fmt(expected)}: P1 = {fmt(P[1])} is {fmt(expected)} away from the evenly "
                       f"spaced point {fmt(mid)}.")
    if abs(value) <= 1e-9:
        return wrong(f"the control points are collinear, so the polygon is straight (distance 0 from the chord), "
                     f"but they are not evenly spaced: P1 = {fmt(P[1])} should be at {fmt(mid)} for the curve to run "
                     f"along the chord at constant speed. The flatness measures |P1 - (P0 + P2)/2|.")
    return check_number(value, expected, what="the flatness", tol=1e-9,
                        hint="compare P1 with the midpoint of P0 and P2")


def check_crossing_bound(answer) -> Result:
    """Check the variation-diminishing bound for ``CROSSING_CTRL`` and the line y = ``CROSSING_LINE_Y`` (Goldman §25.4).

    Recognises the number of control points (or of legs) given instead of the crossings.

    >>> check_crossing_bound(3)
    Correct: the control polygon crosses y = 0.5 three times, so the curve crosses it at most 3 times (here it does 3 times).
    >>> check_crossing_bound(4)
    Not yet: 4 is the number of control points; the bound is the number of times the POLYGON crosses the line: count the sign changes of y - 0.5 along P0, ..., P3.
    """
    P = CROSSING_CTRL
    y = CROSSING_LINE_Y
    expected = bezier.variation_count(P, [0.0, y], [0.0, 1.0])
    actual = bezier.curve_crossings(P, [0.0, y], [0.0, 1.0])
    value, err = read_number(answer, "the bound", "whole number")
    if err is not None:
        return err
    if value == expected:
        words = {1: "once", 2: "twice", 3: "three times"}.get(expected, f"{expected} times")
        return correct(f"the control polygon crosses y = {fmt(y)} {words}, so the curve crosses it at most "
                       f"{expected} times (here it does {actual} times).")
    if value == len(P):
        return wrong(f"{len(P)} is the number of control points; the bound is the number of times the POLYGON "
                     f"crosses the line: count the sign changes of y - {fmt(y)} along P0, ..., P{len(P) - 1}.")
    if value == len(P) - 1:
        return wrong(f"{len(P) - 1} is the degree (the most a cubic can cross any line); the variation diminishing "
                     f"property gives a sharper bound: the number of crossings of the control polygon.")
    return wrong(f"the bound should be {expected}, you gave {fmt(value)}: count how often consecutive control points "
                 f"lie on opposite sides of y = {fmt(y)}.")


def check_c2_continuation(answer) -> Result:
    """Check Q0, Q1, Q2 of a cubic continuing ``C2_CTRL`` with C2 continuity (Goldman §25.5).

    answer: (3, 2).  Says which order of continuity the answer does reach (C0, C1) and recognises
    Q2 taken as the reflection of P1 through P3.

    >>> check_c2_continuation([[4, 2], [5, 1], [5, -2]])
    Correct: Q0, Q1, Q2 are the first three control points of the curve's own continuation, so the join is C2.
    >>> check_c2_continuation([[4, 2], [5, 1], [7, 2]])
    Not yet: the join is C1 but not C2: Q2 should be (5, -2). Reflecting P1 through P3 is not the rule; the C2 rule is Q2 = P1 - 4 P2 + 4 P3 (continue the de Casteljau construction past t = 1).
    """
    what = "Q0, Q1, Q2"
    got, err = read_points(answer, what, ask=what + " as [[x0, y0], [x1, y1], [x2, y2]]")
    if err is not None:
        return err
    if got.shape != (3, 2):
        return wrong(f"{what} should be three points, shape (3, 2); yours has shape {got.shape}.")
    P = C2_CTRL
    cont = bezier.smooth_continuation(P, 1.0)
    trial = cont.copy()
    trial[:3] = got
    order = bezier.join_order(P, trial)
    if order >= 2:
        return correct("Q0, Q1, Q2 are the first three control points of the curve's own continuation, so the join "
                       "is C2.")
    if order < 0:
        return wrong(f"the curves do not even meet: Q0 should be P3 = {fmt(P[-1])}.")
    if order == 0:
        return wrong(f"the curves meet (C0) but the tangents differ: Q1 should be 2 P3 - P2 = {fmt(cont[1])}.")
    reflect = 2 * P[-1] - P[1]
    extra = ""
    if np.allclose(got[2], reflect, atol=1e-6):
        extra = " Reflecting P1 through P3 is not the rule;"
    return wrong(f"the join is C1 but not C2: Q2 should be {fmt(cont[2])}.{extra} the C2 rule is "
                 f"Q2 = P1 - 4 P2 + 4 P3 (continue the de Casteljau construction past t = 1).")
