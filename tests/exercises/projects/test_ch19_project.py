"""Corpus of the chapter-19 project (a ray-quadric intersector): correct solutions written from the
statement alone (vectorised a, b, c with the cancellation-free formula, a loop over rays with the
schoolbook formula and plain floats, numpy's polynomial roots per ray returning a list) must be
accepted; realistic wrong ones must be rejected with the slip named."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch19

EPS = 1e-9


def _abc(Q, o, d):
    H, D = np.c_[o, np.ones(len(o))], np.c_[d, np.zeros(len(d))]
    Q = np.asarray(Q, float)
    return (np.einsum("ij,jk,ik->i", D, Q, D), 2 * np.einsum("ij,jk,ik->i", H, Q, D),
            np.einsum("ij,jk,ik->i", H, Q, H))


# -- accepted ------------------------------------------------------------------------------------------

def vectorised(Q, origins, directions):
    a, b, c = _abc(Q, np.asarray(origins, float), np.asarray(directions, float))
    out = np.full(len(a), np.inf)
    for k in range(len(a)):
        if abs(a[k]) < 1e-12:
            roots = [] if abs(b[k]) < 1e-12 else [-c[k] / b[k]]
        else:
            disc = b[k] ** 2 - 4 * a[k] * c[k]
            if disc < 0:
                roots = []
            else:
                q = -0.5 * (b[k] + math.copysign(math.sqrt(disc), b[k]))
                roots = [q / a[k]] + ([c[k] / q] if q != 0 else [])
        front = [t for t in roots if t > EPS]
        out[k] = min(front) if front else np.inf
    return out


def schoolbook_loop(Q, origins, directions):
    """One ray at a time, the quadratic formula as in school, plain Python floats."""
    Q = [[float(v) for v in row] for row in Q]
    out = []
    for o, d in zip(origins, directions):
        h, v = list(o) + [1.0], list(d) + [0.0]
        form = lambda x, y: sum(x[i] * Q[i][j] * y[j] for i in range(4) for j in range(4))  # noqa: E731
        a, b, c = form(v, v), 2 * form(h, v), form(h, h)
        if a == 0:
            roots = [] if b == 0 else [-c / b]
        else:
            disc = b * b - 4 * a * c
            roots = [] if disc < 0 else [(-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)]
        hits = [t for t in roots if t > 1e-9]
        out.append(min(hits) if hits else math.inf)
    return out


def polynomial_roots(Q, origins, directions):
    """numpy's roots of a t^2 + b t + c (leading zeros dropped), the smallest real one in front."""
    a, b, c = _abc(Q, np.asarray(origins, float), np.asarray(directions, float))
    out = []
    for coeffs in zip(a, b, c):
        coeffs = np.array(coeffs)
        coeffs[np.abs(coeffs) < 1e-12] = 0.0
        nz = np.flatnonzero(coeffs)
        roots = np.roots(coeffs[nz[0]:]) if nz.size and nz[0] < 2 else np.array([])
        real = roots[np.abs(roots.imag) <= 1e-6 * (1 + np.abs(roots.real))].real   # a double root: imag ~ 1e-8
        hits = real[real > 1e-9]
        out.append(float(hits.min()) if hits.size else np.inf)
    return out


ACCEPTED = [vectorised, schoolbook_loop, polynomial_roots]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch19.check_quadric_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def _with(pick, linear=True, tangent=True, eps=EPS, normalise=False):
    def solve(Q, origins, directions):
        d = np.asarray(directions, float)
        if normalise:
            d = d / np.linalg.norm(d, axis=1, keepdims=True)
        a, b, c = _abc(Q, np.asarray(origins, float), d)
        out = []
        for ak, bk, ck in zip(a, b, c):
            if abs(ak) < 1e-12:
                if not linear:
                    with np.errstate(all="ignore"):
                        out.append(np.float64(-bk) / np.float64(0.0) if bk else np.nan)
                    continue
                roots = [] if abs(bk) < 1e-12 else [-ck / bk]
            else:
                disc = bk * bk - 4 * ak * ck
                if disc < 0 or (disc == 0 and not tangent):
                    roots = []
                else:
                    roots = [(-bk - math.sqrt(disc)) / (2 * ak), (-bk + math.sqrt(disc)) / (2 * ak)]
            out.append(pick(roots, eps))
        return np.array(out, dtype=float)
    return solve


def _first_in_front(roots, eps):
    hits = [t for t in roots if t > eps]
    return min(hits) if hits else np.inf


smaller_root = _with(lambda roots, eps: min(roots) if roots else np.inf)                   # the root behind
far_root = _with(lambda roots, eps: max(roots) if roots else np.inf)                       # the far root
zero_counts = _with(_first_in_front, eps=-1e-12)                                            # t = 0 is a hit
no_linear_case = _with(_first_in_front, linear=False)                                      # a = 0 not handled
tangent_misses = _with(_first_in_front, tangent=False)                                     # disc = 0 a miss
unit_directions = _with(_first_in_front, normalise=True)                                   # d normalised


REJECTED = [
    (smaller_root, "a root behind the origin"),
    (far_root, "the far root"),
    (zero_counts, "the root t = 0 is not a hit"),
    (no_linear_case, "when a = d Q d^T is 0 the equation is linear"),
    (tangent_misses, "this ray is tangent: the discriminant is 0"),
    (unit_directions, "the distance along the unit direction"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch19.check_quadric_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
