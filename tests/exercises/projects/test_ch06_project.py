"""Corpus of the chapter-6 project (the IFS of a grid fractal): correct solutions written from the
statement alone (matrices written out by hand, a composition translate-scale-translate, nested
lists, a numpy stack in another order of the maps) must be accepted; realistic wrong ones must be
rejected with the slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch06


# -- accepted ------------------------------------------------------------------------------------------

def by_hand(corner, side, cells):
    """P -> P/3 + corner*2/3 + (i, j) side/3, written as 3x3 row-convention matrices (nested lists)."""
    cx, cy = corner
    return [[[1 / 3, 0, 0], [0, 1 / 3, 0], [2 * cx / 3 + i * side / 3, 2 * cy / 3 + j * side / 3, 1]]
            for i, j in cells]


def _T(v):
    M = np.eye(3)
    M[2, :2] = v
    return M


def composed(corner, side, cells):
    """Move the corner to the origin, shrink, move to the cell's corner; maps in reverse order."""
    S = np.diag([1 / 3, 1 / 3, 1.0])
    c = np.asarray(corner, float)
    return [_T(-c) @ S @ _T(c + np.array([i, j]) * side / 3) for i, j in reversed(cells)]


def stacked(corner, side, cells):
    """One (k, 3, 3) array built at once."""
    ij = np.asarray(cells, float)
    out = np.zeros((len(ij), 3, 3))
    out[:, 0, 0] = out[:, 1, 1] = 1 / 3
    out[:, 2, 2] = 1
    out[:, 2, :2] = np.asarray(corner, float) * 2 / 3 + ij * side / 3
    return out


ACCEPTED = [by_hand, composed, stacked]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch06.check_grid_fractal_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def swapped_indices(corner, side, cells):        # (j, i) for (i, j)
    return by_hand(corner, side, [(j, i) for i, j in cells])


def corner_forgotten(corner, side, cells):       # scales about (0, 0) and never adds the corner
    return [[[1 / 3, 0, 0], [0, 1 / 3, 0], [i * side / 3, j * side / 3, 1]] for i, j in cells]


def whole_corner(corner, side, cells):           # scales about (0, 0), then adds the whole corner
    return [[[1 / 3, 0, 0], [0, 1 / 3, 0], [corner[0] + i * side / 3, corner[1] + j * side / 3, 1]]
            for i, j in cells]


def translate_then_scale(corner, side, cells):   # the wrong order of the factors
    S = np.diag([1 / 3, 1 / 3, 1.0])
    c = np.asarray(corner, float)
    return [_T(np.array([i, j]) * side / 3) @ _T(-c) @ S @ _T(c) for i, j in cells]


def column_convention(corner, side, cells):      # the column-vector matrices
    return [np.asarray(M).T for M in by_hand(corner, side, cells)]


def linear_parts_only(corner, side, cells):      # 2x2 matrices, the translation lost
    return [np.eye(2) / 3 for _ in cells]


def one_map_for_all(corner, side, cells):        # a single map
    return by_hand(corner, side, cells[:1])


REJECTED = [
    (swapped_indices, "mirrored in the diagonal"),
    (corner_forgotten, "sits on the square with corner (0, 0)"),
    (whole_corner, "translate by the whole corner"),
    (translate_then_scale, "translate first and then scale"),
    (column_convention, "column-vector matrix, transposed"),
    (linear_parts_only, "2x2 linear parts"),
    (one_map_for_all, "each needs its own map"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch06.check_grid_fractal_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
