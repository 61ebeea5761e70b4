"""Chapter 6 checkers: hand-worked right answers pass, each recognised slip gets its reason, other
wrong answers say how far off; the grid-fractal project passes a right function (in any map order),
and names the failing case for a subtly wrong one (swapped index, transposed matrix, maps composed
the wrong way round) and for one that crashes."""

import numpy as np
import pytest

from goldman_lib import ifs
from goldman_lib.exercises import ch06


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_problems_and_slips_listed():
    names = {"check_iterate_map", "check_carpet_points", "check_fixed_point", "check_chaos_game_steps",
             "check_tree_branches"}
    assert set(ch06.PROBLEMS) == names == set(ch06.SLIPS)
    assert "check_grid_fractal_project" in ch06.__all__ and "check_grid_fractal_project" not in ch06.PROBLEMS


def test_iterate_map():
    # (8, 0) -> (0, 4) -> (-2, 0) -> (0, -1)
    assert ch06.check_iterate_map([0, -1]).correct
    _assert_wrong(ch06.check_iterate_map([0, 1]), "clockwise")          # (8,0) -> (0,-4) -> (-2,0) -> (0,1)
    _assert_wrong(ch06.check_iterate_map([0, -8]), "does not halve")
    _assert_wrong(ch06.check_iterate_map([1, 0]), "does not turn")
    _assert_wrong(ch06.check_iterate_map([-2, 0]), "one step short")
    _assert_wrong(ch06.check_iterate_map([0.5, 0]), "one step too many")
    _assert_wrong(ch06.check_iterate_map([0, -2]), "is well off")
    _assert_wrong(ch06.check_iterate_map([0, -1, 0]), "one point")


def test_carpet_points():
    assert ch06.check_carpet_points(2560).correct                     # 5 * 8^3
    _assert_wrong(ch06.check_carpet_points(512), "copies of the square")
    _assert_wrong(ch06.check_carpet_points(2048), "4 corners")
    _assert_wrong(ch06.check_carpet_points(120), "multiplies by 8")
    _assert_wrong(ch06.check_carpet_points(2925), "every level")      # 5 (1 + 8 + 64 + 512)
    _assert_wrong(ch06.check_carpet_points(320), "one level short")
    _assert_wrong(ch06.check_carpet_points(2561), "too large")
    _assert_wrong(ch06.check_carpet_points("many"), "should be a number")


def test_fixed_point():
    # x = -y/2 + 5, y = x/2 -> x = 4, y = 2
    assert ch06.check_fixed_point([4, 2]).correct
    _assert_wrong(ch06.check_fixed_point([5, 0]), "applied once to the origin")
    _assert_wrong(ch06.check_fixed_point([5, -2.5]), "INVERSE")       # (5, 0)(I - L) = (5, 0) - (0, 5/2)
    _assert_wrong(ch06.check_fixed_point([10, 0]), "ignores the turn")
    _assert_wrong(ch06.check_fixed_point([4, -2]), "clockwise")
    _assert_wrong(ch06.check_fixed_point([0, 0]), "w moves your point by 5")


def test_chaos_game_steps():
    # (0,0) -> (2,0) -> (1,2) -> (0.5,3) -> (0.25,1.5)
    assert ch06.check_chaos_game_steps([0.25, 1.5]).correct
    _assert_wrong(ch06.check_chaos_game_steps([2, 1.5]), "reverse order")   # maps 1, 3, 3, 2
    _assert_wrong(ch06.check_chaos_game_steps([0.5, 3]), "one step short")
    _assert_wrong(ch06.check_chaos_game_steps([0, 0]), "HALFWAY")
    _assert_wrong(ch06.check_chaos_game_steps([1, 2]), "averages the corners")
    _assert_wrong(ch06.check_chaos_game_steps([0.25, 2.5]), "is well off")


def test_tree_branches():
    assert ch06.check_tree_branches(121).correct                      # 1 + 3 + 9 + 27 + 81
    _assert_wrong(ch06.check_tree_branches(81), "newest")
    _assert_wrong(ch06.check_tree_branches(243), "add the copies level by level")
    _assert_wrong(ch06.check_tree_branches(40), "one level short")
    _assert_wrong(ch06.check_tree_branches(364), "one level too many")
    _assert_wrong(ch06.check_tree_branches(31), "2 maps")
    _assert_wrong(ch06.check_tree_branches(100), "too small")


# -- the programming project ------------------------------------------------------------------------

def third(corner):
    """Scaling by 1/3 about ``corner``, written out: P -> corner + (P - corner)/3."""
    x0, y0 = corner
    return np.array([[1 / 3, 0, 0], [0, 1 / 3, 0], [2 * x0 / 3, 2 * y0 / 3, 1]])


def shift(dx, dy):
    return np.array([[1, 0, 0], [0, 1, 0], [dx, dy, 1.0]])


def right(corner, side, cells):
    return [third(corner) @ shift(i * side / 3, j * side / 3) for i, j in cells]


def test_project_accepts_a_right_function_in_any_map_order_and_an_ifs():
    r = ch06.check_grid_fractal_project(right)
    assert r.correct and "passes all 12 cases" in r.message and "degenerate: one cell" in r.message, r
    assert ch06.check_grid_fractal_project(lambda c, s, cells: right(c, s, cells)[::-1]).correct
    assert ch06.check_grid_fractal_project(lambda c, s, cells: ifs.IFS(right(c, s, cells))).correct


def test_project_names_the_case_of_a_swapped_index():
    def swapped(corner, side, cells):
        return [third(corner) @ shift(j * side / 3, i * side / 3) for i, j in cells]

    r = ch06.check_grid_fractal_project(swapped)
    # the box fractal and the carpet are symmetric in the diagonal: the uneven "L" is the first to fail
    _assert_wrong(r, "case 3 of 12 (corner (0, 0), side 1, cells [(0, 0), (1, 0), (2, 0), (0, 1)])",
                  "mirrored in the diagonal")


def test_project_names_a_transposed_matrix_and_the_wrong_order_of_composition():
    r = ch06.check_grid_fractal_project(lambda c, s, cells: [M.T for M in right(c, s, cells)])
    _assert_wrong(r, "case 1 of 12", "map 1 has last column", "transposed")
    r = ch06.check_grid_fractal_project(lambda c, s, cells: [shift(i * s / 3, j * s / 3) @ third(c) for i, j in cells])
    _assert_wrong(r, "case 1 of 12", "translate first and then scale")
    r = ch06.check_grid_fractal_project(lambda c, s, cells: [third((0, 0)) @ shift(i * s / 3, j * s / 3)
                                                             for i, j in cells])
    _assert_wrong(r, "case 2 of 12 (corner (2, 1)", "scale about the square's corner")


def test_project_reports_counts_shapes_contractions_and_distances():
    _assert_wrong(ch06.check_grid_fractal_project(lambda c, s, cells: right(c, s, cells)[1:]),
                  "case 1 of 12", "it has 4 maps; 5 cells are kept")
    _assert_wrong(ch06.check_grid_fractal_project(lambda c, s, cells: [M[:2, :2] for M in right(c, s, cells)]),
                  "3x3 matrices", "2x2 linear parts")
    _assert_wrong(ch06.check_grid_fractal_project(lambda c, s, cells: [np.diag([3.0, 3.0, 1.0])] * len(cells)),
                  "map 0 stretches distances by up to 3")

    def half(corner, side, cells):
        x0, y0 = corner
        h = np.array([[0.5, 0, 0], [0, 0.5, 0], [x0 / 2, y0 / 2, 1]])
        return [h @ shift(i * side / 3, j * side / 3) for i, j in cells]

    _assert_wrong(ch06.check_grid_fractal_project(half), "case 1 of 12", "Hausdorff distance", "your point")


def test_project_reports_a_crash_with_the_learners_line():
    def crashing(corner, side, cells):
        maps = []
        for i, j in cells:
            maps.append(third(corner) @ shift(i * side[0] / 3, j))
        return maps

    r = ch06.check_grid_fractal_project(crashing)
    _assert_wrong(r, "case 1 of 12", "raised TypeError", "maps.append(third(corner) @ shift(i * side[0] / 3, j))")


def test_project_unanswered():
    def grid_fractal_ifs(corner, side, cells):
        """The starter."""
        ...

    assert not ch06.check_grid_fractal_project(grid_fractal_ifs).answered
    assert not ch06.check_grid_fractal_project(None).answered


def test_project_cases_are_fixed_and_cover_the_degenerate_patterns():
    cases = ch06.grid_fractal_cases()
    assert [c.label for c in cases] == [c.label for c in ch06.grid_fractal_cases()]
    kinds = {c.kind for c in cases}
    assert {"degenerate: one cell (the attractor is a point)", "degenerate: all nine cells", "a tiny square",
            "an asymmetric pattern"} <= kinds
    assert any(sorted(c.args[2]) != sorted((j, i) for i, j in c.args[2]) for c in cases[:3])
