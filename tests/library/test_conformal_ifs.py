"""Chapter 8: recursive turtle programs and conformal IFS (Goldman §8.2-8.5).

References: coordinates worked out by hand in the tests; the turtle of chapter 1
(goldman_lib.turtle, which knows nothing of IFS); the standard systems of goldman_lib.ifs and its
deterministic algorithm; scipy's directed Hausdorff distance; the fractal theorem as a property.
"""

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.spatial.distance import directed_hausdorff

from goldman_lib import affine, fractals, ifs, turtle
from goldman_lib import conformal_ifs as cf

R2 = 1 / math.sqrt(2)
SQ3 = math.sqrt(3)
TRIANGLE = np.array([[0, 0], [1, 0], [0.5, SQ3 / 2], [0, 0]])
UNIT = np.array([[0.0, 0.0], [1.0, 0.0]])


def _copies(system, level, start):
    """The deterministic algorithm of goldman_lib.ifs, as strokes: the copies of ``start``."""
    start = np.asarray(start, dtype=float)
    return list(ifs.deterministic(ifs.IFS(system.maps), level, start=start).reshape(-1, len(start), 2))


# ---------------------------------------------------------------------------------------------
# §8.2 changing the turtle's initial state
# ---------------------------------------------------------------------------------------------

def test_state_map_by_hand():
    # w = (0, 2): rotate by 90 degrees, scale by 2; P = (2, 1): translate.  (x, y) -> (2 - 2y, 1 + 2x)
    M = cf.state_map([2, 1], [0, 2])
    assert np.allclose(affine.apply([[0, 0], [1, 0], [0, 1], [3, 4]], M),
                       [[2, 1], [2, 3], [0, 1], [-6, 7]])


def test_changing_the_initial_state_of_koch_level_1_by_hand():
    # Koch level 1 from ((0,0),(1,0)): (0,0) (1/3,0) (1/2, sqrt3/6) (2/3,0) (1,0).
    # From P=(1,2), w=(0,2) the map is (x, y) -> (1 - 2y, 2 + 2x):
    expected = [[1, 2], [1, 2 + 2 / 3], [1 - SQ3 / 3, 3], [1, 2 + 4 / 3], [1, 4]]
    (drawn,) = fractals.koch_curve_program().polylines(1, point=(1, 2), direction=(0, 2))
    assert np.allclose(drawn, expected, atol=1e-12)
    (standard,) = fractals.koch_curve_program().polylines(1)
    M = cf.initial_state_map([0, 0], [1, 0], [1, 2], [0, 2])
    assert np.allclose(affine.apply(standard, M), expected, atol=1e-12)


def test_initial_state_map_between_two_arbitrary_states_by_hand():
    # From ((1,0),(1,0)) to ((0,1),(0,-1)): translate by -(1,0), rotate by -90 degrees, translate by (0,1):
    # (x, y) -> (y, 1 - (x - 1)) = (y, 2 - x).
    M = cf.initial_state_map([1, 0], [1, 0], [0, 1], [0, -1])
    assert np.allclose(affine.apply([[1, 0], [2, 0], [3, 5]], M), [[0, 1], [0, 0], [5, -1]])
    p, w = cf.state_after(M, [1, 0], [1, 0])
    assert np.allclose(p, [0, 1]) and np.allclose(w, [0, -1])


programs = st.lists(st.tuples(st.sampled_from(["FORWARD", "MOVE", "TURN", "RESIZE"]),
                              st.floats(-3, 3).filter(lambda v: abs(v) > 0.05)), min_size=1, max_size=12)
states = st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-180, 180), st.floats(0.2, 3))


@settings(max_examples=60, deadline=None)
@given(programs, states, states)
def test_changing_the_initial_state_moves_the_drawing_by_the_similarity(cmds, s1, s2):
    """§8.2 as a property: a program run from a second state draws the first drawing mapped by
    initial_state_map; the reference is the chapter 1 turtle."""
    text = " ".join(f"{c} {v!r}" for c, v in cmds)
    (x1, y1, a1, r1), (x2, y2, a2, r2) = s1, s2
    w1 = r1 * np.array([math.cos(math.radians(a1)), math.sin(math.radians(a1))])
    w2 = r2 * np.array([math.cos(math.radians(a2)), math.sin(math.radians(a2))])
    first = turtle.run(text, point=(x1, y1), direction=w1)
    second = turtle.run(text, point=(x2, y2), direction=w2)
    M = cf.initial_state_map((x1, y1), w1, (x2, y2), w2)
    mapped = cf.transform_polylines(first, M)
    assert len(mapped) == len(second)
    for a, b in zip(mapped, second):
        assert np.allclose(a, b, atol=1e-8 * max(1.0, np.abs(b).max()))


def test_state_validation():
    with pytest.raises(ValueError, match="direction must be a nonzero vector"):
        cf.state_map([0, 0], [0, 0])
    with pytest.raises(ValueError, match="new_direction must be a nonzero vector"):
        cf.initial_state_map([0, 0], [1, 0], [1, 1], [0, 0])
    with pytest.raises(ValueError, match="point must"):
        cf.state_map([0, 0, 0], [1, 0])
    with pytest.raises(ValueError, match="must be finite"):
        cf.state_map([np.nan, 0], [1, 0])


# ---------------------------------------------------------------------------------------------
# §8.4 Ron's algorithm
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("program, system", [
    (fractals.koch_curve_program, ifs.koch),
    (fractals.c_curve_program, ifs.c_curve),
    (fractals.dragon_program, ifs.dragon),
])
def test_rons_algorithm_gives_the_standard_systems(program, system):
    conv = cf.rons_algorithm(program())
    assert conv.maps.shape == system().maps.shape
    assert np.allclose(conv.maps, system().maps, atol=1e-12)
    assert conv.condensation == ()
    assert len(conv.base) == 1 and np.allclose(conv.base[0], UNIT)


def test_rons_algorithm_sierpinski_maps_by_hand():
    # RESIZE 1/2, RECURSE, RESIZE 2, MOVE 1, TURN 120, three times: calls at (0,0) heading 0,
    # (1,0) heading 120, (1/2, sqrt3/2) heading 240, each with scale 1/2.
    conv = cf.rons_algorithm(fractals.sierpinski_gasket_program())
    expected = [affine.similarity(0.5, 0), affine.similarity(0.5, 120, (1, 0)),
                affine.similarity(0.5, 240, (0.5, SQ3 / 2))]
    assert np.allclose(conv.maps, expected, atol=1e-12)
    assert conv.condensation == ()
    assert np.allclose(conv.base[0], TRIANGLE, atol=1e-12)


def test_rons_algorithm_tree_condensation_by_hand():
    conv = cf.rons_algorithm(fractals.tree_program(30, 0.6))
    assert np.allclose(conv.maps, [affine.similarity(0.6, 30, (1, 0)), affine.similarity(0.6, -30, (1, 0))])
    assert len(conv.condensation) == 1 and np.allclose(conv.condensation[0], UNIT)
    assert np.allclose(conv.ifs.condensation, UNIT)


def test_dragon_mirror_is_the_half_turn_about_the_chord_midpoint():
    conv = cf.rons_algorithm(fractals.dragon_program())
    # z -> 1 - z
    assert np.allclose(conv.mirror, [[-1, 0, 0], [0, -1, 0], [1, 0, 1]], atol=1e-12)


@pytest.mark.parametrize("name", sorted(fractals.PROGRAMS))
def test_turtle_and_ifs_draw_the_same_segments(name):
    """The equivalence theorem (§8.3) for every fractal of chapter 2: identical segment sets."""
    program = fractals.PROGRAMS[name]()
    conv = cf.rons_algorithm(program)
    for level in range(4):
        assert cf.same_drawing(program.polylines(level), conv.polylines(level)), (name, level)
    assert cf.equivalence_distance(program, 3) < 1e-9


@pytest.mark.parametrize("name", ["Koch curve", "C-curve", "dragon curve", "Sierpinski gasket"])
def test_turtle_level_equals_ifs_deterministic_from_the_base(name):
    """Against goldman_lib.ifs.deterministic directly: the copies of the base polyline."""
    program = fractals.PROGRAMS[name]()
    conv = cf.rons_algorithm(program)
    (base,) = conv.base
    for level in (2, 4):
        copies = _copies(conv.ifs, level, base)
        assert cf.same_drawing(program.polylines(level), copies)
        turtle_pts = np.concatenate(program.polylines(level))
        ifs_pts = np.concatenate(copies)
        h = max(directed_hausdorff(turtle_pts, ifs_pts)[0], directed_hausdorff(ifs_pts, turtle_pts)[0])
        assert h < 1e-9


def test_rons_algorithm_with_a_changed_initial_state():
    P, w = (1.0, -2.0), (0.6, 0.8)
    program = fractals.c_curve_program()
    conv = cf.rons_algorithm(program, P, w)
    S = cf.state_map(P, w)
    assert np.allclose(conv.maps, [np.linalg.inv(S) @ M @ S for M in ifs.c_curve().maps], atol=1e-12)
    assert cf.same_drawing(program.polylines(5, P, w), conv.polylines(5))


def test_snowflake_driver_places_three_koch_curves():
    conv = cf.rons_algorithm(fractals.koch_snowflake_program())
    assert len(conv.placements) == 3
    # the driver walks the triangle clockwise: corners (0,0), (1,0), (1/2, -sqrt3/2)
    assert np.allclose(conv.placements[:, 2, :2], [[0, 0], [1, 0], [0.5, -SQ3 / 2]], atol=1e-12)


def test_rons_algorithm_errors():
    with pytest.raises(TypeError, match="RecursiveTurtleProgram"):
        cf.rons_algorithm("FORWARD 1")
    # Koch without the final RESIZE 3: level 1 ends with step 1/3, the base case with step 1
    body = fractals.koch_curve_program().body[:-1]
    bad = fractals.RecursiveTurtleProgram(body, [("FORWARD", 1)], "broken Koch")
    with pytest.raises(ValueError, match="the broken Koch: the base case leaves the turtle at .* level 1 leaves it"):
        cf.rons_algorithm(bad)
    mixed = fractals.RecursiveTurtleProgram(
        [("RESIZE", 0.5), ("RECURSE", None), ("TURN", 30), ("RECURSE", -1), ("TURN", -30), ("RESIZE", 2)],
        [("FORWARD", 1), ("MOVE", -1)])
    with pytest.raises(ValueError, match="mirror program.*graph-directed"):
        cf.rons_algorithm(mixed)
    with pytest.raises(ValueError, match="direction must be a nonzero vector"):
        cf.rons_algorithm(fractals.koch_curve_program(), (0, 0), (0, 0))


# ---------------------------------------------------------------------------------------------
# §8.4 Tao's algorithm
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("system, base", [(ifs.koch, UNIT), (ifs.c_curve, UNIT), (ifs.dragon, UNIT),
                                          (ifs.sierpinski, TRIANGLE), (ifs.cantor, UNIT)])
def test_tao_program_draws_the_ifs(system, base):
    s = system()
    program = cf.tao_algorithm(s, base)
    for level in range(5):
        assert cf.same_drawing(program.polylines(level), _copies(s, level, base)), level
    # the body returns the turtle to where it started
    t = program.trace(2)
    assert np.allclose(t.point, [0, 0], atol=1e-12) and np.allclose(t.direction, [1, 0], atol=1e-12)


def test_tao_program_with_condensation_draws_the_tree():
    s = ifs.tree()
    trunk = s.condensation
    program = cf.tao_algorithm(s, base=trunk)
    for level in range(4):
        expected = ifs.deterministic(s, level, start=trunk).reshape(-1, 2, 2)
        assert cf.same_drawing(program.polylines(level), list(expected)), level


@pytest.mark.parametrize("name", ["koch", "c_curve", "dragon", "sierpinski", "tree"])
def test_round_trips_give_the_same_maps(name):
    s = getattr(ifs, name)()
    once = cf.rons_algorithm(cf.tao_algorithm(s))
    assert np.allclose(once.maps, s.maps, atol=1e-12, rtol=0)
    twice = cf.rons_algorithm(cf.tao_algorithm(once))
    assert np.allclose(twice.maps, s.maps, atol=1e-12, rtol=0)


@pytest.mark.parametrize("name", ["Koch curve", "dragon curve", "Sierpinski gasket", "fractal tree", "fractal bush"])
def test_program_to_ifs_to_program_draws_the_same(name):
    program = fractals.PROGRAMS[name]()
    conv = cf.rons_algorithm(program)
    again = cf.tao_algorithm(conv)
    assert np.allclose(cf.rons_algorithm(again).maps, conv.maps, atol=1e-12, rtol=0)
    for level in range(4):
        assert cf.same_drawing(again.polylines(level), program.polylines(level)), level


def test_tao_from_another_initial_state():
    P, w = (2.0, 1.0), (-0.5, 1.5)
    s = ifs.koch()
    program = cf.tao_algorithm(s, point=P, direction=w)
    base = np.array([P, np.add(P, w)])
    for level in range(4):
        assert cf.same_drawing(program.polylines(level, P, w), _copies(s, level, base))


maps_strategy = st.lists(st.tuples(st.floats(0.15, 0.7), st.floats(-180, 180), st.floats(-1, 1), st.floats(-1, 1)),
                         min_size=1, max_size=4)


@settings(max_examples=40, deadline=None)
@given(maps_strategy, states)
# Two copies 1e-8 apart in one grid cell: drawing_distance must pair each point with its nearest.
@example(params=[(0.5, 0.0, 0.0, 0.0), (0.5, 4.4463032999835184e-07, 0.0, 0.0)], state=(0.0, 0.0, 0.0, 3.0))
def test_tao_then_ron_is_the_identity_on_conformal_ifs(params, state):
    maps = [affine.similarity(r, a, (x, y)) for r, a, x, y in params]
    x0, y0, a0, r0 = state
    w0 = r0 * np.array([math.cos(math.radians(a0)), math.sin(math.radians(a0))])
    program = cf.tao_algorithm(maps, point=(x0, y0), direction=w0)
    back = cf.rons_algorithm(program, (x0, y0), w0)
    assert np.allclose(back.maps, maps, atol=1e-9 * max(1.0, abs(x0), abs(y0)), rtol=0)
    base = np.array([[x0, y0], [x0 + w0[0], y0 + w0[1]]])
    drawn = program.polylines(2, (x0, y0), w0)
    expected = ifs.deterministic(ifs.IFS(maps), 2, start=base)
    assert cf.drawing_distance(drawn, [expected]) < 1e-8


def test_tao_rejects_non_conformal_maps_naming_them():
    with pytest.raises(ValueError, match=r"maps\[0\] is not conformal"):
        cf.tao_algorithm(ifs.barnsley_fern())
    maps = [affine.similarity(0.5, 0), affine.scaling([0.5, 0.25])]
    with pytest.raises(ValueError, match=r"maps\[1\] is not conformal"):
        cf.tao_algorithm(maps)
    with pytest.raises(ValueError, match=r"maps\[1\] reverses orientation"):
        cf.tao_algorithm([affine.similarity(0.5, 0), affine.similarity(0.5, 30, reflect=True)])
    with pytest.raises(ValueError, match=r"maps\[0\] has scale 0"):
        cf.tao_algorithm([affine.scaling(0.0)])
    with pytest.raises(ValueError, match=r"maps\[0\] must have last column"):
        cf.tao_algorithm([[[1, 0, 1], [0, 1, 0], [0, 0, 1]]])


def test_move_commands_reach_the_target_state():
    cmds = cf.move_commands([1, 1], [0, 2], [-2, 3], [1.5, -0.5])
    text = " ".join(f"{c} {v!r}" for c, v in cmds)
    assert "FORWARD" not in text
    p, w = turtle.final_state(text, point=(1, 1), direction=(0, 2))
    assert np.allclose(p, [-2, 3]) and np.allclose(w, [1.5, -0.5])


def test_polyline_commands_draw_and_come_home():
    poly = np.array([[0.5, 0.5], [1, 0.5], [1, 2], [-1, 0]])
    text = " ".join(f"{c} {v!r}" for c, v in cf.polyline_commands(poly))
    t = turtle.trace(text)
    assert len(t.polylines) == 1 and np.allclose(t.polylines[0], poly)
    assert np.allclose(t.point, [0, 0], atol=1e-12) and np.allclose(t.direction, [1, 0], atol=1e-12)


# ---------------------------------------------------------------------------------------------
# §8.3 equivalence: base-case independence and the fractal theorem
# ---------------------------------------------------------------------------------------------

def test_contraction_ratio():
    assert cf.contraction_ratio(ifs.koch()) == pytest.approx(1 / 3)
    assert cf.contraction_ratio(cf.rons_algorithm(fractals.tree_program(30, 0.6))) == pytest.approx(0.6)
    with pytest.raises(ValueError, match=r"maps\[1\] is not conformal"):
        cf.contraction_ratio(ifs.barnsley_fern().maps[[0, 1]][::-1])


@pytest.mark.parametrize("name, other", [
    ("C-curve", [("TURN", 90), ("FORWARD", 0.5), ("TURN", -90), ("FORWARD", 1), ("TURN", -90),
                 ("FORWARD", 0.5), ("TURN", 90)]),
    ("Koch curve", [("TURN", 30), ("FORWARD", 1 / SQ3), ("TURN", -60), ("FORWARD", 1 / SQ3), ("TURN", 30)]),
    ("Sierpinski gasket", [("FORWARD", 1), ("MOVE", -1)]),
])
def test_base_case_gaps_shrink_by_the_contraction_ratio(name, other):
    """The fractal theorem: h(W^n(A), W^n(B)) <= s^n h(A, B)."""
    program = fractals.PROGRAMS[name]()
    gaps = cf.base_case_gaps(program, other, 5)
    s = cf.contraction_ratio(cf.rons_algorithm(program))
    assert gaps[0] > 0.1
    assert np.all(gaps <= gaps[0] * s ** np.arange(6) + 1e-12)


def test_base_case_gaps_need_the_same_state_change():
    with pytest.raises(ValueError, match="change the turtle's state differently"):
        cf.base_case_gaps(fractals.koch_curve_program(), [("FORWARD", 2)], 2)


# ---------------------------------------------------------------------------------------------
# §8.5 bump fractals
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bump, system", [("Koch curve", ifs.koch), ("C-curve", ifs.c_curve), ("dragon", ifs.dragon)])
def test_bump_ifs_are_the_standard_systems(bump, system):
    assert np.allclose(cf.bump_ifs(*cf.BUMPS[bump]).maps, system().maps, atol=1e-12)


@pytest.mark.parametrize("bump, program", [("Koch curve", fractals.koch_curve_program),
                                           ("C-curve", fractals.c_curve_program),
                                           ("dragon", fractals.dragon_program)])
def test_bump_programs_draw_the_chapter_2_fractals(bump, program):
    mine = cf.bump_program(*cf.BUMPS[bump])
    for level in range(5):
        assert cf.same_drawing(mine.polylines(level), program().polylines(level)), level


@pytest.mark.parametrize("bump", sorted(cf.BUMPS))
def test_bump_fractals_both_ways(bump):
    poly, rev = cf.BUMPS[bump]
    system = cf.bump_ifs(poly, rev)
    program = cf.bump_program(poly, rev)
    assert np.allclose(cf.rons_algorithm(program).maps, system.maps, atol=1e-12)
    for level in range(4):
        assert cf.same_drawing(program.polylines(level), _copies(system, level, UNIT)), level
    back, back_rev = cf.bump_of(system)
    assert np.allclose(back, poly, atol=1e-12) and back_rev == tuple(rev)


def test_bump_level_1_is_the_bump():
    poly, _ = cf.BUMPS["square Koch curve"]
    (drawn,) = cf.bump_program(poly).polylines(1)
    assert np.allclose(drawn, poly, atol=1e-12)


def test_cesaro_bump_has_four_equal_sides_and_its_apex_angle():
    poly, _ = cf.BUMPS["Cesàro curve (80°)"]
    sides = np.hypot(*np.diff(poly, axis=0).T)
    assert np.allclose(sides, sides[0])
    u, v = poly[1] - poly[2], poly[3] - poly[2]
    apex = math.degrees(math.acos(u @ v / (np.hypot(*u) * np.hypot(*v))))
    assert apex == pytest.approx(180 - 2 * 80)


def test_bump_validation():
    with pytest.raises(ValueError, match="bump must end away from where it starts"):
        cf.bump_ifs([[0, 0], [1, 1], [0, 0]])
    with pytest.raises(ValueError, match="bump segment 1 has length 0"):
        cf.bump_program([[0, 0], [0.5, 0.5], [0.5, 0.5], [1, 0]])
    with pytest.raises(ValueError, match="reverse entry must be <= 1"):
        cf.bump_ifs([[0, 0], [0.5, 0.5], [1, 0]], reverse=(2,))
    with pytest.raises(ValueError, match="at least 2 point"):
        cf.bump_ifs([[0, 0]])
    # the gasket's first two maps chain (0,0)-(1/2,0)-(1,0); the third leaves the chain
    with pytest.raises(ValueError, match=r"maps\[2\] does not continue the chain"):
        cf.bump_of(ifs.sierpinski())


def test_bump_of_a_non_bump_ending_elsewhere():
    with pytest.raises(ValueError, match="not at \\(1, 0\\)"):
        cf.bump_of([affine.similarity(0.5, 0)])


# ---------------------------------------------------------------------------------------------
# comparing drawings
# ---------------------------------------------------------------------------------------------

def test_drawing_distance_against_scipy():
    rng = np.random.default_rng(3)
    A = [rng.normal(size=(7, 2)), rng.normal(size=(5, 2))]
    B = [rng.normal(size=(9, 2))]
    a, b = np.concatenate(A), np.concatenate(B)
    expected = max(directed_hausdorff(a, b)[0], directed_hausdorff(b, a)[0])
    assert cf.drawing_distance(A, B) == pytest.approx(expected, rel=1e-7)
    with pytest.raises(ValueError, match="both drawings must draw something"):
        cf.drawing_distance([], B)


def test_drawing_distance_is_precise_for_coinciding_sets():
    pts = np.random.default_rng(0).random((50, 2))
    assert cf.drawing_distance([pts], [pts[::-1] + 1e-15]) < 1e-14


def test_same_drawing_ignores_order_and_direction():
    a = [np.array([[0, 0], [1, 0], [1, 1]])]
    b = [np.array([[1, 1], [1, 0]]), np.array([[1, 0], [0, 0]])]
    assert cf.same_drawing(a, b)
    assert not cf.same_drawing(a, [np.array([[0, 0], [1, 0]])])
    assert cf.segment_set([]).shape == (0, 4)


def test_drawing_distance_of_many_strokes_is_checked_at_once_and_still_names_a_bad_stroke():
    # thousands of 2-point strokes (a level-8 bump drawing) take one finiteness check; a bad stroke
    # among them is still named by its index
    rng = np.random.default_rng(0)
    strokes = [rng.uniform(0, 1, (2, 2)) for _ in range(5000)]
    assert cf.drawing_distance(strokes, strokes) == 0.0
    bad = list(strokes)
    bad[1234] = np.array([[0.0, 0.0], [np.nan, 1.0]])
    with pytest.raises(ValueError, match=r"first\[1234\]"):
        cf.drawing_distance(bad, strokes)
    bad[1234] = np.zeros((0, 2))
    with pytest.raises(ValueError, match=r"first\[1234\]"):
        cf.drawing_distance(bad, strokes)


def test_shared_segments_counts_each_segment_once_whatever_its_direction():
    # worked by hand: the square's four sides drawn as one stroke, and as four reversed strokes
    # plus the diagonal and a repeat; the first has 4, the second 5, and they share the 4 sides
    square = [[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]]
    pieces = [[[1, 0], [0, 0]], [[1, 1], [1, 0]], [[0, 1], [1, 1]], [[0, 0], [0, 1]], [[0, 0], [1, 1]],
              [[1, 0], [0, 0]]]
    assert cf.shared_segments(square, pieces) == (4, 5, 4)
    assert cf.shared_segments(pieces, square) == (5, 4, 4)
    nudged = [[[0, 0], [1, 0], [1, 1], [0, 1], [0, 1e-6]]]      # the last side ends 1e-6 off
    assert cf.shared_segments(square, nudged) == (4, 4, 3)
    assert cf.shared_segments(square, nudged, decimals=4) == (4, 4, 4)
    with pytest.raises(TypeError):
        cf.shared_segments(square, square, decimals=1.5)
