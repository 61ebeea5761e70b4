"""Corpus of the chapter-30 project (one level of the triangle scheme's stencils around a vertex):
correct solutions written from the statement alone (np.roll, a loop with indices mod n and lists,
the (n+1) x (n+1) stencil matrix built by hand) must be accepted; realistic wrong ones must be
rejected with the slip named."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch30


# -- accepted ------------------------------------------------------------------------------------------

def rolled(v, ring):
    v, ring = np.asarray(v, float), np.asarray(ring, float)
    n = len(ring)
    edges = 3 / 8 * (v + ring) + 1 / 8 * (np.roll(ring, 1, axis=0) + np.roll(ring, -1, axis=0))
    return np.vstack([5 / 8 * v + 3 / (8 * n) * ring.sum(axis=0), edges])


def loop_lists(v, ring):
    v = [float(x) for x in v]
    ring = [[float(x) for x in u] for u in ring]
    n = len(ring)
    out = [[5 / 8 * v[c] + 3 / (8 * n) * sum(u[c] for u in ring) for c in range(3)]]
    for i in range(n):
        a, b = ring[(i - 1) % n], ring[(i + 1) % n]
        out.append([3 / 8 * (v[c] + ring[i][c]) + 1 / 8 * (a[c] + b[c]) for c in range(3)])
    return out


def stencil_matrix(v, ring):
    n = len(ring)
    S = np.zeros((n + 1, n + 1))
    S[0, 0], S[0, 1:] = 5 / 8, 3 / (8 * n)
    for i in range(n):
        S[1 + i, 0] += 3 / 8
        S[1 + i, 1 + i] += 3 / 8
        S[1 + i, 1 + (i - 1) % n] += 1 / 8
        S[1 + i, 1 + (i + 1) % n] += 1 / 8
    return S @ np.vstack([v, ring])


ACCEPTED = [rolled, loop_lists, stencil_matrix]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch30.check_ring_step_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def edges_shifted(v, ring):                      # row 1 + i holds the edge point of ring[i + 1]
    out = rolled(v, ring)
    out[1:] = np.roll(out[1:], -1, axis=0)
    return out


def loops_beta(v, ring):                         # Loop's cosine beta for the vertex point
    out = rolled(v, ring)
    n = len(ring)
    beta = (5 / 8 - (3 / 8 + math.cos(2 * math.pi / n) / 4) ** 2) / n
    out[0] = (1 - n * beta) * np.asarray(v, float) + beta * np.asarray(ring, float).sum(axis=0)
    return out


def warren_at_three(v, ring):                    # 3/16 at valence 3
    out = rolled(v, ring)
    n = len(ring)
    beta = 3 / 16 if n == 3 else 3 / (8 * n)
    out[0] = (1 - n * beta) * np.asarray(v, float) + beta * np.asarray(ring, float).sum(axis=0)
    return out


def midpoints(v, ring):                          # edge points without the opposite vertices
    out = rolled(v, ring)
    out[1:] = (np.asarray(v, float) + np.asarray(ring, float)) / 2
    return out


def no_modulo(v, ring):                          # ring[i + 1] past the end
    v, ring = np.asarray(v, float), np.asarray(ring, float)
    n = len(ring)
    out = [5 / 8 * v + 3 / (8 * n) * ring.sum(axis=0)]
    for i in range(n):
        out.append(3 / 8 * (v + ring[i]) + 1 / 8 * (ring[i - 1] + ring[i + 1]))
    return np.array(out)


def edge_points_only(v, ring):                   # the vertex point forgotten
    return rolled(v, ring)[1:]


REJECTED = [
    (edges_shifted, "shifted by one place"),
    (loops_beta, "Loop's vertex rule"),
    (warren_at_three, "Warren's vertex rule"),
    (midpoints, "the midpoints of the edges"),
    (no_modulo, "IndexError"),
    (edge_points_only, "return 7 points: the vertex point, then one edge point per neighbour"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch30.check_ring_step_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
