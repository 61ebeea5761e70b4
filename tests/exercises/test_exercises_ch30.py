"""Tests of the chapter-30 exercise checkers and of the programming-project checker.  Right answers
are worked by hand from the problem constants (so a bug in goldman_lib.subdivision_surfaces cannot
make a checker accept a wrong answer)."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch30

# (1 + x)^2 (1 + y)^2 = [[1,2,1],[2,4,2],[1,2,1]]; times (1 + xy): add a copy shifted one step along the diagonal
BOX = [[1, 2, 1, 0], [2, 4 + 1, 2 + 2, 1], [1, 2 + 2, 1 + 4, 2], [0, 1, 2, 1]]
# level 1: V = 10 + 15 + 7 = 32, F = 5*4 + 2*5 = 30, E = 2*15 + 30 = 60
# level 2: V = 32 + 60 + 30 = 122, F = 4*30 = 120, E = 2*60 + 120 = 240
COUNTS = [122, 240, 120]
# 3/8 ((0,0,0) + (2,0,0)) + 1/16 ((2,2,1) + (0,2,1) + (0,-2,2) + (2,-2,0)) = (0.75, 0, 0) + (0.25, 0, 0.25)
QUAD_EDGE = [1.0, 0.0, 0.25]
# 9/16 * 8 + 5 * 3/40 * 2 + 5 * 1/80 * 6 = 4.5 + 0.75 + 0.375
HEIGHT = 5.625
# 5/8 (1,1,1) + 1/8 ((1,-1,-1) + (-1,1,-1) + (-1,-1,1)) = 5/8 - 1/8 in each coordinate
TETRA = [0.5, 0.5, 0.5]
# 3/8 ((0,0,0) + (4,0,0)) + 1/8 ((2,3,1) + (2,-3,3)) = (1.5, 0, 0) + (0.5, 0, 0.5)
TRI_EDGE = [2.0, 0.0, 0.5]

CHECKERS = [
    (ch30.check_box_spline_mask, BOX),
    (ch30.check_prism_counts, COUNTS),
    (ch30.check_quad_edge_point, QUAD_EDGE),
    (ch30.check_extraordinary_height, HEIGHT),
    (ch30.check_tetrahedron_vertex, TETRA),
    (ch30.check_triangle_edge_point, TRI_EDGE),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch30.BOX_MULTIPLICITIES == (2, 2, 1)
    assert (ch30.PRISM_SIDES, ch30.PRISM_LEVELS) == (5, 2)
    assert ch30.QUAD_EDGE_POINTS.tolist() == [[0, 0, 0], [2, 0, 0], [2, 2, 1], [0, 2, 1], [0, -2, 2], [2, -2, 0]]
    assert ch30.STAR_VALENCE == 5 and ch30.STAR_HEIGHTS == (8, 2, 6)
    assert ch30.TETRA_VERTICES.tolist() == [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]
    assert ch30.EDGE_POINTS.tolist() == [[0, 0, 0], [4, 0, 0], [2, 3, 1], [2, -3, 3]]


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_box_mask_messages():
    assert "mirrored" in ch30.check_box_spline_mask(np.array(BOX)[::-1].tolist()).message
    assert "mirrored" in ch30.check_box_spline_mask(np.array(BOX)[:, ::-1].tolist()).message
    assert "weights themselves" in ch30.check_box_spline_mask((np.array(BOX) / 8).tolist()).message
    assert "without the averaging along e3" in ch30.check_box_spline_mask([[1, 2, 1], [2, 4, 2], [1, 2, 1]]).message
    assert "one factor of 1/2 too many" in ch30.check_box_spline_mask((np.array(BOX) / 2).tolist()).message
    r = ch30.check_box_spline_mask([[1, 2, 1, 0], [2, 4, 4, 1], [1, 4, 5, 2], [0, 1, 2, 1]])
    assert "yours total 31" in r.message
    r = ch30.check_box_spline_mask([[1, 2, 1, 0], [2, 5, 4, 1], [1, 4, 5, 2], [0, 1, 2, 1.01]])
    assert "should total 32" in r.message and "yours miss that total by a little" in r.message
    assert "yours total 32" not in r.message
    r = ch30.check_box_spline_mask([[1, 2, 1, 0], [2, 4, 5, 1], [1, 4, 5, 2], [0, 1, 2, 1]])
    assert "row 1, column 1" in r.message and "too small" in r.message
    assert "four by four" in ch30.check_box_spline_mask([[1, 2], [2, 1]]).message


def test_counts_messages():
    assert "after one level" in ch30.check_prism_counts([32, 60, 30]).message
    assert "leaves out the face points" in ch30.check_prism_counts([92, 240, 120]).message
    assert "not 4" in ch30.check_prism_counts([122, 240, 112]).message
    r = ch30.check_prism_counts([122, 242, 120])
    assert "V - E + F = 0" in r.message and "without changing its topology" in r.message
    assert "whole numbers" in ch30.check_prism_counts([122.5, 240, 120]).message


def test_quad_edge_messages():
    assert "midpoint of the edge" in ch30.check_quad_edge_point([1, 0, 0]).message
    assert "two old faces" in ch30.check_quad_edge_point([1, 0, 0.5]).message   # (f1 + f2)/2 with f = (1, +-1, 0.5)
    assert "equal weights" in ch30.check_quad_edge_point([1, 0, 1 / 3]).message
    assert "triangle scheme's weights" in ch30.check_quad_edge_point([1.25, 0, 0.5]).message
    assert "is off from where it should be" in ch30.check_quad_edge_point([1, 0.1, 0.25]).message


def test_extraordinary_height_messages():
    # valence-4 weights: 4.5 + 5 * 3/32 * 2 + 5 * 1/64 * 6 = 4.5 + 0.9375 + 0.46875
    assert "regular vertex (valence 4)" in ch30.check_extraordinary_height(5.90625).message
    # swapped: 4.5 + 5 * 1/80 * 2 + 5 * 3/40 * 6 = 4.5 + 0.125 + 2.25
    assert "swapped" in ch30.check_extraordinary_height(6.875).message
    assert "diagonal neighbours are missing" in ch30.check_extraordinary_height(5.25).message
    # triangle rule: 5/8 * 8 + 3/8 * 2
    assert "triangle scheme" in ch30.check_extraordinary_height(5.75).message
    # Catmull-Clark: face points (8 + 2 + 6 + 2)/4 = 4.5, edge midpoints 5: (4.5 + 2*5 + 2*8)/5 = 6.1
    assert "Catmull-Clark" in ch30.check_extraordinary_height(6.1).message
    r = ch30.check_extraordinary_height(5.5)
    assert "a little too small" in r.message and "n = 5" in r.message
    assert ch30.check_extraordinary_height(5.6251).correct


def test_tetrahedron_messages():
    assert "keeps the old vertices" in ch30.check_tetrahedron_vertex([1, 1, 1]).message
    # Warren: (1 - 9/16) (1,1,1) + 3/16 (-1,-1,-1) = 1/4
    assert "3/16" in ch30.check_tetrahedron_vertex([0.25, 0.25, 0.25]).message
    # valence 6: 10/16 - 1/16
    assert "valence-6" in ch30.check_tetrahedron_vertex([9 / 16] * 3).message
    # plain centroids: 2/3 v + 1/9 sum = 2/3 - 1/9 = 5/9
    assert "plain centroids" in ch30.check_tetrahedron_vertex([5 / 9] * 3).message
    assert "is off from where it should be" in ch30.check_tetrahedron_vertex([0.6, 0.6, 0.6]).message


def test_triangle_edge_messages():
    assert "midpoint of the edge" in ch30.check_triangle_edge_point([2, 0, 0]).message
    # plain centroids: 7/18 (v + w) + 1/9 (x + y) = (14/9 + 4/9, 0, 4/9)
    assert "7/18, 1/9" in ch30.check_triangle_edge_point([2, 0, 4 / 9]).message
    assert "quadrilateral scheme" in ch30.check_triangle_edge_point([1.75, 0, 0.25]).message


# -- the programming project --------------------------------------------------------------------------

def ring_step(v, ring):
    """The stencils written out here: 5/8 v + 3/(8n) sum, 3/8 (v + u_i) + 1/8 (u_{i-1} + u_{i+1})."""
    n = len(ring)
    out = [5 / 8 * v + 3 / (8 * n) * ring.sum(axis=0)]
    for i in range(n):
        out.append(3 / 8 * (v + ring[i]) + 1 / 8 * (ring[i - 1] + ring[(i + 1) % n]))
    return np.array(out)


def test_project_accepts_a_correct_function():
    r = ch30.check_ring_step_project(ring_step)
    assert r.correct, r
    assert "9 cases" in r.message and "valence 3" in r.message and "high valence" in r.message


def test_project_names_the_valence_3_case_for_warrens_weight():
    def warren(v, ring):
        out = ring_step(v, ring)
        if len(ring) == 3:
            out[0] = 7 / 16 * v + 3 / 16 * ring.sum(axis=0)
        return out

    r = ch30.check_ring_step_project(warren)
    assert not r.correct and r.answered
    assert "case 2 of 9 (valence 3" in r.message and "the vertex point (row 0)" in r.message


def test_project_names_shifted_edge_points():
    def shifted(v, ring):
        n = len(ring)
        out = ring_step(v, ring)
        for i in range(n):   # the edge point of edge i + 1 put in row 1 + i
            out[1 + i] = 3 / 8 * (v + ring[(i + 1) % n]) + 1 / 8 * (ring[i] + ring[(i + 2) % n])
        return out

    r = ch30.check_ring_step_project(shifted)
    assert "case 1 of 9 (valence 6" in r.message and "shifted by one place" in r.message

    def one_edge_wrong(v, ring):
        out = ring_step(v, ring)
        if len(ring) == 7:
            out[3] += 0.5
        return out

    r = ch30.check_ring_step_project(one_edge_wrong)
    assert "case 6 of 9 (valence 7" in r.message and "edge point of the edge (v, ring[2]) (row 3)" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    def crashing(v, ring):
        n = len(ring)
        return np.array([ring[i + 1] for i in range(n)])

    r = ch30.check_ring_step_project(crashing)
    assert not r.correct and r.answered
    assert "case 1 of 9" in r.message and "raised IndexError" in r.message
    assert "`return np.array([ring[i + 1] for i in range(n)])`" in r.message


def test_project_unanswered_and_wrong_shape():
    def starter(v, ring):
        """New points."""
        ...

    assert not ch30.check_ring_step_project(starter).answered
    r = ch30.check_ring_step_project(lambda v, ring: ring_step(v, ring)[1:])
    assert "return 7 points" in r.message


# -- dealt instances (issue 17 §3): the dealt answers against closed forms ----------------------------

SEEDS = range(1, 41)


def _dealt(name, seed):
    return ch30.DECK.exercises[name].instance(seed), ch30.DECK.exercises[name].answer


def _poly2(*factors):
    """The coefficient grid of a product of polynomials in x (rows) and y (columns)."""
    out = np.array([[1.0]])
    for f in factors:
        f = np.asarray(f, float)
        grid = np.zeros((out.shape[0] + f.shape[0] - 1, out.shape[1] + f.shape[1] - 1))
        for (i, j), c in np.ndenumerate(f):
            grid[i:i + out.shape[0], j:j + out.shape[1]] += c * out
        out = grid
    return out


def test_dealt_box_masks_are_products_of_direction_factors():
    for seed in SEEDS:
        p, answer = _dealt("check_box_spline_mask", seed)
        r, s, t = p["m"]
        mask = _poly2(*([[[1], [1]]] * r + [[[1, 1]]] * s + [[[1, 0], [0, 1]]] * t))
        assert np.allclose(answer(p), mask)


def test_dealt_prism_counts_follow_the_counting_rules():
    for seed in SEEDS:
        p, answer = _dealt("check_prism_counts", seed)
        n = p["n"]
        V, E, F, sizes = 2 * n, 3 * n, n + 2, 6 * n
        for _ in range(p["levels"]):
            V, E, F = V + E + F, 2 * E + sizes, sizes
            sizes = 4 * F
        assert tuple(answer(p)) == (V, E, F)


def test_dealt_stencils():
    for seed in SEEDS:
        p, answer = _dealt("check_quad_edge_point", seed)
        v, w, *others = np.array(p["points"])
        assert np.allclose(answer(p), 3 / 8 * (v + w) + sum(others) / 16)
        p, answer = _dealt("check_extraordinary_height", seed)
        zv, zu, zd = p["heights"]
        assert np.isclose(answer(p), 9 / 16 * zv + 3 / 8 * zu + 1 / 16 * zd)     # n b = 3/8, n c = 1/16
        p, answer = _dealt("check_tetrahedron_vertex", seed)
        P = np.array(p["vertices"])
        assert np.allclose(answer(p), 5 / 8 * P[0] + 1 / 8 * P[1:].sum(axis=0))
        p, answer = _dealt("check_triangle_edge_point", seed)
        v, w, x, y = np.array(p["points"])
        assert np.allclose(answer(p), 3 / 8 * (v + w) + 1 / 8 * (x + y))
