"""Corpus of the chapter-28 project (Boehm's knot insertion): correct solutions written from the
statement alone (the span by searchsorted, the first span instead of the last when u is already a
knot and Python lists, the insertion as a matrix) must be accepted; realistic wrong ones must be rejected with the slip named."""

import bisect

import numpy as np
import pytest

from goldman_lib.exercises import ch28


# -- accepted ------------------------------------------------------------------------------------------

def boehm(ctrl, knots, degree, u):
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.vstack([P[:k - p + 1], np.zeros((p, P.shape[1])), P[k:]])
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def first_span_lists(ctrl, knots, degree, u):
    """The span with t_k < u <= t_(k+1) (the first one when u is already a knot); lists throughout."""
    P = [list(map(float, q)) for q in ctrl]
    t = [float(x) for x in knots]
    p, n = degree, len(P) - 1
    k = max(bisect.bisect_left(t, u) - 1, p)
    k = min(k, n)
    out = P[:k - p + 1]
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        out.append([(1 - a) * x + a * y for x, y in zip(P[i - 1], P[i])])
    return out + P[k:]


def insertion_matrix(ctrl, knots, degree, u):
    """The (n+2) x (n+1) matrix A with Q = A P: identity rows above and below, two weights per new row."""
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    A = np.zeros((n + 2, n + 1))
    for i in range(n + 2):
        if i <= k - p:
            A[i, i] = 1
        elif i > k:
            A[i, i - 1] = 1
        else:
            a = (u - t[i]) / (t[i + p] - t[i])
            A[i, i - 1], A[i, i] = 1 - a, a
    return A @ P


ACCEPTED = [boehm, first_span_lists, insertion_matrix]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch28.check_boehm_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def swapped_weights(ctrl, knots, degree, u):
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.vstack([P[:k - p + 1], np.zeros((p, P.shape[1])), P[k:]])
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = a * P[i - 1] + (1 - a) * P[i]
    return Q


def wrong_knot_gap(ctrl, knots, degree, u):     # t_(i+p+1) - t_i: the de Boor gap of the wrong level
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.vstack([P[:k - p + 1], np.zeros((p, P.shape[1])), P[k:]])
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[min(i + p + 1, len(t) - 1)] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def span_one_late(ctrl, knots, degree, u):      # searchsorted(...) without the - 1
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")), n + 1)
    Q = np.vstack([P[:k - p + 1], np.zeros((p, P.shape[1])), P[k:]])[:n + 2]
    for i in range(k - p + 1, min(k, n) + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def replaces_instead_of_inserting(ctrl, knots, degree, u):   # n+1 points: the old count
    return boehm(ctrl, knots, degree, u)[:-1]


def span_one_early(ctrl, knots, degree, u):     # the new points one index too early
    P, t, p = np.asarray(ctrl, float), np.asarray(knots, float), degree
    n = len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n) - 1
    lo = max(k - p + 1, 1)
    Q = np.vstack([P[:lo], np.zeros((k - lo + 1, P.shape[1])), P[k:]])
    for i in range(lo, k + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


REJECTED = [
    (swapped_weights, "the weights are swapped"),
    (wrong_knot_gap, "divides by the wrong knot gap"),
    (span_one_late, "one index too late"),
    (span_one_early, "one index too early"),
    (replaces_instead_of_inserting, "inserting one knot adds one control point"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch28.check_boehm_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
