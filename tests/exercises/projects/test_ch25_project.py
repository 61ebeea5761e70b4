"""Corpus of the chapter-25 project (de Casteljau subdivision): correct solutions written from the
statement alone (the pyramid level by level, recursion on the level, the closed form through
Bernstein weights, nested lists returned as a tuple or a list) must be accepted; realistic wrong ones
must be rejected with the slip named."""

from math import comb

import numpy as np
import pytest

from goldman_lib.exercises import ch25


# -- accepted ------------------------------------------------------------------------------------------

def pyramid(ctrl, t):
    level = np.asarray(ctrl, float)
    left, right = [level[0]], [level[-1]]
    while len(level) > 1:
        level = (1 - t) * level[:-1] + t * level[1:]
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right[::-1])


def recursive(ctrl, t):
    """Returns lists of lists, in a list."""
    pts = [list(map(float, p)) for p in ctrl]
    if len(pts) == 1:
        return [pts, pts]
    nxt = [[(1 - t) * a + t * b for a, b in zip(p, q)] for p, q in zip(pts, pts[1:])]
    left, right = recursive(nxt, t)
    return [[pts[0]] + left, right + [pts[-1]]]


def bernstein(ctrl, t):
    """Left point k = sum_j C(k, j) (1-t)^(k-j) t^j P_j; right point k from the reversed polygon at 1 - t."""
    P = np.asarray(ctrl, float)
    n = len(P) - 1

    def firsts(Q, s):
        return np.array([sum(comb(k, j) * (1 - s) ** (k - j) * s ** j * Q[j] for j in range(k + 1))
                         for k in range(n + 1)])
    return firsts(P, t), firsts(P[::-1], 1 - t)[::-1]


ACCEPTED = [pyramid, recursive, bernstein]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch25.check_subdivision_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def right_reversed(ctrl, t):                     # the last points read bottom-up
    left, right = pyramid(ctrl, t)
    return left, right[::-1]


def exchanged(ctrl, t):
    left, right = pyramid(ctrl, t)
    return right, left


def one_minus_t(ctrl, t):                        # t P_j + (1 - t) P_(j+1)
    return pyramid(ctrl, 1 - t)


def always_midpoints(ctrl, t):                   # the midpoint split of §25.3, whatever t
    return pyramid(ctrl, 0.5)


def apex_missing(ctrl, t):                       # one level short: the apex left out
    left, right = pyramid(ctrl, t)
    return left[:-1], right[1:]


REJECTED = [
    (right_reversed, "your right polygon is in reverse order"),
    (exchanged, "the two polygons are exchanged"),
    (one_minus_t, "the split at 1 - t"),
    (always_midpoints, "the split at t = 1/2"),
    (apex_missing, "as many points as the curve has control points"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch25.check_subdivision_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
