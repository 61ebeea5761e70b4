"""goldman_lib.fractals: recursive turtle programs (Goldman §2.2-2.3) and fractal strangeness
(§3.2-3.4).

References are independent of the code under test: a naive recursive turtle interpreter written
here (one Python call per command, math.cos/sin), closed forms (log 3 / log 2, (4/3)**n, the
snowflake's area, the paper-folding sequence), exact integer arithmetic for the looping lemmas,
hand-solved dimension equations and scipy.optimize.brentq."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from goldman_lib import fractals, turtle
from goldman_lib.fractals import RecursiveTurtleProgram

SQ3 = math.sqrt(3)


# -- an independent reference: the recursion run literally, one command at a time ---------------

def naive_polylines(program, level, point=(0.0, 0.0), heading=0.0, step=1.0):
    """Run a RecursiveTurtleProgram by plain recursion, as the book describes it."""
    x, y = point
    state = {"x": x, "y": y, "h": heading, "s": step, "strokes": [], "down": False}

    def cmd(c, v):
        if c == "TURN":
            state["h"] += v
        elif c == "RESIZE":
            state["s"] *= v
        else:
            nx = state["x"] + v * state["s"] * math.cos(math.radians(state["h"]))
            ny = state["y"] + v * state["s"] * math.sin(math.radians(state["h"]))
            if c == "FORWARD":
                if not state["down"]:
                    state["strokes"].append([(state["x"], state["y"])])
                    state["down"] = True
                state["strokes"][-1].append((nx, ny))
            else:
                state["down"] = False
            state["x"], state["y"] = nx, ny

    def run(n, sign):
        for c, v in (program.body if n > 0 else program.base):
            if c == "RECURSE":
                run(n - 1, -1 if v == -1 else 1)
            else:
                cmd(c, sign * v if c == "TURN" else v)

    for c, v in program.start:
        if c == "RECURSE":
            run(level, -1 if v == -1 else 1)
        else:
            cmd(c, v)
    return [np.array(s) for s in state["strokes"]]


def assert_same_drawing(a, b, atol=1e-9):
    assert len(a) == len(b)
    for p, q in zip(a, b):
        np.testing.assert_allclose(p, q, atol=atol)


# -- the data structure --------------------------------------------------------------------------

def test_program_is_plain_data():
    k = fractals.koch_curve_program()
    assert isinstance(k.body, tuple) and isinstance(k.base, tuple) and k.name == "Koch curve"
    assert k.base == (("FORWARD", 1.0),)
    assert [c for c, _ in k.body] == ["RESIZE", "RECURSE", "TURN", "RECURSE", "TURN", "RECURSE", "TURN",
                                      "RECURSE", "RESIZE"]
    assert all(v is None for c, v in k.body if c == "RECURSE")
    assert set(fractals.PROGRAMS) >= {"Sierpinski gasket", "Koch curve", "Koch snowflake", "C-curve",
                                      "dragon curve", "fractal tree", "fractal bush"}


@pytest.mark.parametrize("name", list(fractals.PROGRAMS))
@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_vectorised_expansion_matches_naive_recursion(name, level):
    prog = fractals.PROGRAMS[name]()
    assert_same_drawing(prog.polylines(level), naive_polylines(prog, level))


def test_initial_state_is_respected():
    prog = fractals.c_curve_program()
    got = prog.polylines(4, point=(2, -1), direction=(0, 2))
    assert_same_drawing(got, naive_polylines(prog, 4, point=(2, -1), heading=90, step=2))


def test_expand_codes_match_turtle_expand_of_the_written_out_program():
    prog = fractals.sierpinski_gasket_program()
    text = ("REPEAT 3 [RESIZE 0.5 REPEAT 3 [FORWARD 1 TURN 120] RESIZE 2 MOVE 1 TURN 120]")
    c1, v1 = prog.expand(1)
    c2, v2 = turtle.expand(text)
    np.testing.assert_array_equal(c1, c2)
    np.testing.assert_allclose(v1, v2)


def test_count_is_exact_and_too_many_commands_is_a_clear_error():
    k = fractals.koch_curve_program()
    # n_0 = 1, n_k = 5 + 4 n_(k-1)
    n = 1
    for level in range(1, 10):
        n = 5 + 4 * n
        assert k.count(level) == n
    assert k.expand(8)[0].size == 174761
    with pytest.raises(ValueError, match="level 9 of the Koch curve would execute 699,049 .* highest level that fits is 8"):
        k.expand(9)
    assert k.expand(9, max_commands=10**6)[0].size == 699049


def test_koch_level_8_has_65536_segments():
    (p,) = fractals.koch_curve(8)
    assert p.shape == (4**8 + 1, 2)
    np.testing.assert_allclose(p[-1], [1, 0], atol=1e-12)


@pytest.mark.parametrize("body, base, match", [
    ([("FORWARD", 1)], [("FORWARD", 1)], "RECURSE at least once"),
    ([("RECURSE", None)], [("RECURSE", None)], "base case may not RECURSE"),
    ([("JUMP", 1), ("RECURSE", None)], [("FORWARD", 1)], "unknown command 'JUMP'"),
    ([("RESIZE", 0), ("RECURSE", None)], [("FORWARD", 1)], "RESIZE 0"),
    ([("RECURSE", 2)], [("FORWARD", 1)], "RECURSE takes None, 1"),
    ([("TURN", float("nan")), ("RECURSE", None)], [("FORWARD", 1)], "finite"),
])
def test_bad_programs_name_the_rule(body, base, match):
    with pytest.raises(ValueError, match=match):
        RecursiveTurtleProgram(body, base)


def test_bad_program_types():
    with pytest.raises(TypeError, match="body must be a sequence"):
        RecursiveTurtleProgram("FORWARD 1", [("FORWARD", 1)])
    with pytest.raises(TypeError, match=r"body\[0\] must be a \(command, value\) pair"):
        RecursiveTurtleProgram([("FORWARD",)], [("FORWARD", 1)])
    with pytest.raises(ValueError, match="level must be >= 0"):
        fractals.koch_curve(-1)
    with pytest.raises(TypeError, match="level must be an integer"):
        fractals.koch_curve(1.5)
    with pytest.raises(ValueError, match="direction"):
        fractals.koch_curve_program().polylines(1, direction=(1, 2, 3))


def test_with_base_and_equality():
    k = fractals.koch_curve_program()
    assert k.with_base([("FORWARD", 1)]) == k
    assert k.with_base([("MOVE", 1)]) != k


# -- the fractals of §2.3, against closed forms --------------------------------------------------

def test_koch_level_1_vertices():
    (p,) = fractals.koch_curve(1)
    np.testing.assert_allclose(p, [[0, 0], [1 / 3, 0], [1 / 2, SQ3 / 6], [2 / 3, 0], [1, 0]], atol=1e-15)


@pytest.mark.parametrize("n", range(7))
def test_koch_length_is_four_thirds_to_the_n(n):
    expected = (4 / 3) ** n
    assert turtle.length(fractals.koch_curve(n)) == pytest.approx(expected, rel=1e-12)
    assert fractals.ink_length(fractals.koch_curve_program(), n) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("n", range(6))
def test_snowflake_perimeter_and_area(n):
    (p,) = fractals.koch_snowflake(n)
    assert len(p) - 1 == 3 * 4**n
    assert turtle.closes(p, 1e-12)
    assert turtle.length(p) == pytest.approx(3 * (4 / 3) ** n, rel=1e-12)
    x, y = p[:, 0], p[:, 1]
    area = 0.5 * abs(np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1]))
    a0 = SQ3 / 4
    assert area == pytest.approx(a0 * (8 / 5 - 3 / 5 * (4 / 9) ** n), rel=1e-12)


@pytest.mark.parametrize("n", range(6))
def test_sierpinski_gasket_triangles(n):
    tris = fractals.sierpinski_gasket(n)
    assert len(tris) == 3**n
    side = 0.5**n
    area = 0.0
    for t in tris:
        assert t.shape == (4, 2)
        np.testing.assert_allclose(t[0], t[-1], atol=1e-12)
        np.testing.assert_allclose(np.hypot(*np.diff(t, axis=0).T), side, rtol=1e-12)
        x, y = t[:, 0], t[:, 1]
        area += 0.5 * (np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1]))
        # inside the big triangle (0,0), (1,0), (1/2, sqrt3/2)
        assert (t[:, 1] >= -1e-12).all() and (SQ3 * t[:, 0] - t[:, 1] >= -1e-12).all()
        assert (SQ3 * (1 - t[:, 0]) - t[:, 1] >= -1e-12).all()
    assert area == pytest.approx(SQ3 / 4 * 0.75**n, rel=1e-12)


def test_polygon_gasket_scale_is_the_touching_ratio():
    # pentagon: r = 1 / (2 (1 + cos 72)) = (3 - sqrt 5) / 2 by hand
    assert fractals.polygon_gasket_program(5).body[0][1] == pytest.approx((3 - math.sqrt(5)) / 2, rel=1e-14)
    assert fractals.polygon_gasket_program(6).body[0][1] == pytest.approx(1 / 3, rel=1e-14)
    assert fractals.polygon_gasket_program(3).body[0][1] == pytest.approx(1 / 2, rel=1e-14)
    assert len(fractals.polygon_gasket(3, 5)) == 125
    with pytest.raises(ValueError, match="sides must be >= 3"):
        fractals.polygon_gasket_program(2)


def test_carpet_has_no_square_in_the_middle_ninth():
    squares = fractals.sierpinski_carpet(2)
    assert len(squares) == 64
    centres = np.array([s[:-1].mean(axis=0) for s in squares])
    assert centres.min() > 0 and centres.max() < 1
    middle = (np.abs(centres - 0.5) < 1 / 6).all(axis=1)
    assert not middle.any()
    assert len({tuple(c) for c in np.round(centres, 9)}) == 64


@pytest.mark.parametrize("n", range(1, 9))
def test_c_curve_headings_count_the_bits(n):
    # first half = level n-1 turned +45, second half turned -45: heading(k) = 45 (n - 2 popcount(k))
    (p,) = fractals.c_curve(n)
    seg = np.diff(p, axis=0)
    heading = np.degrees(np.arctan2(seg[:, 1], seg[:, 0]))
    expected = np.array([45 * (n - 2 * bin(k).count("1")) for k in range(2**n)], dtype=float)
    np.testing.assert_allclose(np.mod(heading - expected + 180, 360) - 180, 0, atol=1e-9)


@pytest.mark.parametrize("n", range(1, 11))
def test_dragon_turns_follow_the_paper_folding_sequence(n):
    (p,) = fractals.dragon(n)
    turns = turtle.turning_angles(p)
    expected = []
    for k in range(1, 2**n):
        m = k
        while m % 2 == 0:
            m //= 2
        expected.append(-90.0 if m % 4 == 1 else 90.0)
    np.testing.assert_allclose(turns, expected, atol=1e-7)
    np.testing.assert_allclose(p[-1], [1, 0], atol=1e-12)


def test_dragon_never_draws_a_segment_twice():
    (p,) = fractals.dragon(12)
    q = np.round(p * 2**6, 6)  # level 12: a grid of spacing 2**-6
    edges = {tuple(sorted((tuple(a), tuple(b)))) for a, b in zip(q[:-1], q[1:])}
    assert len(edges) == 2**12


def test_mirror_program_of_the_dragon_is_the_dragon_backwards():
    d = fractals.dragon_program()
    mirror = RecursiveTurtleProgram(d.body, d.base, start=[("RECURSE", -1)])
    for n in range(6):
        (m,) = mirror.polylines(n)
        (p,) = d.polylines(n)
        np.testing.assert_allclose(m, np.array([1.0, 0.0]) - p[::-1], atol=1e-12)


def test_trees_return_the_turtle_home():
    for prog in (fractals.tree_program(), fractals.bush_program(40, 0.45)):
        for n in range(5):
            t = prog.trace(n)
            np.testing.assert_allclose(t.point, [0, 0], atol=1e-12)
            np.testing.assert_allclose(t.direction, [1, 0], atol=1e-12)
    # a binary tree of level n has 2**(n+1) - 1 branches of lengths 0.6**k
    assert turtle.length(fractals.tree(5)) == pytest.approx(sum(2**k * 0.6**k for k in range(6)), rel=1e-12)
    with pytest.raises(ValueError, match="scale must lie in"):
        fractals.tree_program(30, 1.2)
    with pytest.raises(ValueError, match="angle must lie in"):
        fractals.bush_program(200)


@pytest.mark.parametrize("name", list(fractals.PROGRAMS))
def test_ink_length_recursion_equals_the_measured_length(name):
    prog = fractals.PROGRAMS[name]()
    for n in range(4):
        assert fractals.ink_length(prog, n) == pytest.approx(turtle.length(prog.polylines(n)), rel=1e-12)


# -- the looping lemmas (§2.2) ------------------------------------------------------------------

@settings(max_examples=80, deadline=None)
@given(a=st.integers(1, 359), k=st.integers(1, 60), step=st.sampled_from([0.5, 1.0, 2.0]))
def test_looping_lemma_closes_iff_k_a_is_a_multiple_of_360(a, k, step):
    prog = f"FORWARD {step} TURN {a}"
    assert fractals.repeat_closes(prog, k) == ((k * a) % 360 == 0)


@settings(max_examples=60, deadline=None)
@given(a=st.integers(1, 359))
def test_looping_lemma_polygon_or_star(a):
    g = math.gcd(a, 360)
    loop = fractals.loop_analysis(f"FORWARD 1 TURN {a}")
    assert loop.period == 360 // g
    assert loop.winding == a // g
    assert loop.kind == ("polygon" if a // g == 1 else "star")
    # every vertex is on one circle about the centre, and the path is the {q/p} star polygon
    (p,) = turtle.run(f"REPEAT {loop.period} [FORWARD 1 TURN {a}]")
    r = np.hypot(*(p - loop.center).T)
    np.testing.assert_allclose(r, r[0], rtol=1e-9)
    expected_r = 1 / (2 * math.sin(math.pi * loop.winding / loop.period))  # circumradius of {q/p}, side 1
    assert r[0] == pytest.approx(expected_r, rel=1e-9)
    assert turtle.total_turning(f"REPEAT {loop.period} [FORWARD 1 TURN {a}]") == pytest.approx(360 * loop.winding)


def test_looping_lemma_compound_programs_and_the_other_cases():
    loop = fractals.loop_analysis("FORWARD 1 TURN 90 FORWARD 2 TURN 45")  # T = 135 = 360 * 3/8
    assert (loop.period, loop.winding, loop.kind) == (8, 3, "star")
    assert fractals.repeat_closes("FORWARD 1 TURN 90 FORWARD 2 TURN 45", 8)
    assert not any(fractals.repeat_closes("FORWARD 1 TURN 90 FORWARD 2 TURN 45", k) for k in range(1, 8))
    drift = fractals.loop_analysis("FORWARD 1 TURN 90 FORWARD 1 TURN -90")
    assert (drift.kind, drift.period) == ("drift", None)
    assert not any(fractals.repeat_closes("FORWARD 1 TURN 90 FORWARD 1 TURN -90", k) for k in range(1, 50))
    assert fractals.loop_analysis("FORWARD 1 TURN 180 FORWARD 1 TURN 180").kind == "retrace"
    spiral = fractals.loop_analysis("FORWARD 1 TURN 90 RESIZE 0.5")
    assert spiral.kind == "spiral" and spiral.period is None
    # the spiral converges to its centre: c = d / (1 - S e^{iT}) = 1 / (1 - 0.5 i)
    c = 1 / (1 - 0.5j)
    np.testing.assert_allclose(spiral.center, [c.real, c.imag], atol=1e-12)
    (p,) = turtle.run("REPEAT 60 [FORWARD 1 TURN 90 RESIZE 0.5]")
    np.testing.assert_allclose(p[-1], spiral.center, atol=1e-12)
    assert fractals.loop_analysis("FORWARD 1 TURN 137.50776405").kind == "never closes"
    assert fractals.loop_period(360 / 7) == 7
    assert fractals.loop_period(-90) == 4
    assert fractals.state_change([("FORWARD", 2), ("TURN", 30), ("RESIZE", 3)])[:2] == (30.0, 3.0)


# -- similarity dimension (§3.2) -----------------------------------------------------------------

@pytest.mark.parametrize("scales, expected", [
    ([1 / 2] * 3, math.log(3) / math.log(2)),            # Sierpinski gasket
    ([1 / 3] * 4, math.log(4) / math.log(3)),            # Koch curve
    ([1 / 3] * 8, math.log(8) / math.log(3)),            # Sierpinski carpet
    ([1 / 3] * 2, math.log(2) / math.log(3)),            # Cantor set
    ([math.sqrt(0.5)] * 2, 2.0),                         # C-curve, dragon
    ([0.5, 0.25, 0.25], 1.0),                            # x + 2x^2 = 1 with x = 2^-D: x = 1/2
    ([0.5, 0.25], math.log((1 + math.sqrt(5)) / 2) / math.log(2)),  # x + x^2 = 1: x = 1/golden ratio
    ([0.9], 0.0),                                        # one copy: s^D = 1 only at D = 0
])
def test_similarity_dimension_closed_forms(scales, expected):
    assert fractals.similarity_dimension(scales) == pytest.approx(expected, rel=1e-13, abs=1e-15)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.01, 0.95), min_size=2, max_size=12))
def test_similarity_dimension_matches_brentq(scales):
    D = fractals.similarity_dimension(scales)
    ref = brentq(lambda d: sum(s**d for s in scales) - 1, 0, 1e3, xtol=1e-15, rtol=1e-15)
    assert D == pytest.approx(ref, rel=1e-10, abs=1e-12)
    assert sum(s**D for s in scales) == pytest.approx(1, rel=1e-12)


@pytest.mark.parametrize("scales, exc, match", [
    ([], ValueError, "at least one"),
    ([0.5, 1.0], ValueError, "no dimension D solves"),
    ([1.5], ValueError, "no dimension D solves"),
    ([0.5, 0.0], ValueError, "must be > 0"),
    ([0.5, -0.5], ValueError, "must be > 0"),
    ([0.5, float("nan")], ValueError, "finite"),
    ("0.5", TypeError, "not a string"),
    ([[0.5, 0.5], [0.5, 0.5]], ValueError, "flat list"),
])
def test_similarity_dimension_errors(scales, exc, match):
    with pytest.raises(exc, match=match):
        fractals.similarity_dimension(scales)


@pytest.mark.parametrize("name, expected", [
    ("Sierpinski gasket", math.log(3) / math.log(2)),
    ("Koch curve", math.log(4) / math.log(3)),
    ("Koch snowflake", math.log(4) / math.log(3)),
    ("Sierpinski carpet", math.log(8) / math.log(3)),
    ("pentagonal gasket", math.log(5) / math.log(2 / (3 - math.sqrt(5)))),
    ("hexagonal gasket", math.log(6) / math.log(3)),
    ("C-curve", 2.0),
    ("dragon curve", 2.0),
    ("fractal tree", math.log(2) / math.log(1 / 0.6)),
    ("fractal bush", math.log(3) / math.log(2)),
])
def test_dimension_from_the_recursive_program(name, expected):
    assert fractals.program_dimension(fractals.PROGRAMS[name]()) == pytest.approx(expected, rel=1e-12)


def test_recursion_scales_need_a_program_that_restores_the_step():
    bad = RecursiveTurtleProgram([("RESIZE", 0.5), ("RECURSE", None)], [("FORWARD", 1)])
    with pytest.raises(ValueError, match="restore the turtle's step size"):
        fractals.recursion_scales(bad)
    with pytest.raises(TypeError, match="RecursiveTurtleProgram"):
        fractals.program_dimension("FORWARD 1")
    unequal = RecursiveTurtleProgram([("RESIZE", 0.5), ("RECURSE", None), ("RESIZE", 0.5), ("RECURSE", None),
                                      ("RECURSE", None), ("RESIZE", 4)], [("FORWARD", 1)])
    np.testing.assert_allclose(fractals.recursion_scales(unequal), [0.5, 0.25, 0.25])
    assert fractals.program_dimension(unequal) == pytest.approx(1.0, rel=1e-14)


# -- non-differentiability (§3.3) ---------------------------------------------------------------

def test_koch_difference_quotients_blow_up_at_the_start():
    n = 8
    (p,) = fractals.koch_curve(n)
    offsets = [4 ** (n - j) for j in range(n + 1)]  # h = 4**-j: P(h) = (3**-j, 0)
    q = fractals.difference_quotients(p, 0, offsets)
    np.testing.assert_allclose(q, [(4 / 3) ** j for j in range(n + 1)], rtol=1e-12)


def test_koch_chord_directions_keep_swinging():
    n = 8
    (p,) = fractals.koch_curve(n)
    to_third = [4 ** (n - j) for j in range(1, n)]        # (3**-j, 0): direction 0
    to_tip = [2 * 4 ** (n - j) for j in range(1, n)]      # the tip of the first bump: direction 30
    np.testing.assert_allclose(fractals.chord_angles(p, 0, to_third), 0, atol=1e-9)
    np.testing.assert_allclose(fractals.chord_angles(p, 0, to_tip), 30, atol=1e-9)
    with pytest.raises(ValueError, match=r"offsets\[0\] = 0"):
        fractals.chord_angles(p, 0, [0])
    with pytest.raises(ValueError, match="another index"):
        fractals.difference_quotients(p, 0, [-1])


@pytest.mark.parametrize("m", [3, 1000, 12345, 40000, 65000])
def test_koch_headings_follow_the_base_4_digits(m):
    # t = (m + 1/2) / 4**8: its base-4 digits d_1 d_2 ... pick sub-curves; digit 1 turns +60,
    # digit 2 turns -60, digits 0 and 3 keep the heading.
    t = (m + 0.5) / 4**8
    digits = [(m // 4 ** (7 - i)) % 4 for i in range(8)]
    expected = [sum({0: 0, 1: 60, 2: -60, 3: 0}[d] for d in digits[:n]) for n in range(9)]
    got = fractals.headings_at(fractals.koch_curve_program(), t, range(9))
    np.testing.assert_allclose(got, expected, atol=1e-9)


# -- attraction: the base case does not matter (§3.4) ---------------------------------------------

@pytest.mark.parametrize("fractal, book_base", [("Koch curve", "segment (the book's)"),
                                                ("Sierpinski gasket", "triangle (the book's)")])
def test_alternative_bases_change_the_state_as_the_book_base_does(fractal, book_base):
    bases = fractals.BASE_CASES[fractal]
    T0, S0, d0 = fractals.state_change(bases[book_base])
    for name, base in bases.items():
        T, S, d = fractals.state_change(base)
        assert (T - T0) % 360 == pytest.approx(0, abs=1e-9), name
        assert S == pytest.approx(S0), name
        np.testing.assert_allclose(d, d0, atol=1e-12, err_msg=name)


@pytest.mark.parametrize("fractal, ratio", [("Koch curve", 1 / 3), ("Sierpinski gasket", 1 / 2)])
def test_different_bases_converge_to_one_fractal(fractal, ratio):
    prog = fractals.PROGRAMS[fractal]()
    bases = list(fractals.BASE_CASES[fractal].values())
    levels = [0, 1, 2, 3, 4]
    d = fractals.base_case_distances(prog, bases, levels)
    assert d.shape == (len(bases), len(levels))
    # the book's own base (goldman_lib.fixed_point squares distances: ~1e-8 of rounding)
    np.testing.assert_allclose(d[0], 0, atol=1e-7)
    # the Hausdorff metric contracts by the recursion scale: d_n <= s * d_(n-1) (+ sampling)
    for row in d[1:]:
        assert (row[1:] <= ratio * row[:-1] * (1 + 1e-9) + 1e-7).all(), row
        assert row[-1] <= ratio**4 * row[0] + 1e-7
    # against an independent computation of the Hausdorff distance (scipy)
    from scipy.spatial.distance import directed_hausdorff
    a = fractals.points_on(prog.polylines(2), 2)
    b = fractals.points_on(prog.with_base(bases[1]).polylines(2), 2)
    ref = max(directed_hausdorff(a, b)[0], directed_hausdorff(b, a)[0])
    assert d[1, 2] == pytest.approx(ref, abs=1e-7)


def test_base_that_draws_nothing_is_an_error():
    with pytest.raises(ValueError, match=r"bases\[0\] draws nothing"):
        fractals.base_case_distances(fractals.koch_curve_program(), [[("MOVE", 1)]], [1])


def test_points_on_subdivides_each_segment():
    pts = fractals.points_on([np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]])], 2)
    np.testing.assert_allclose(pts, [[0, 0], [0.5, 0], [1, 0], [1, 1], [1, 2]])


def test_quadratic_koch_curve_closed_forms():
    """Level 1 is forward, up, forward, down, forward in thirds; level n has 5**n segments of length
    3**-n, ends at (1, 0), and the curve's dimension is log 5 / log 3 (five copies at scale 1/3)."""
    (p1,) = fractals.quadratic_koch(1)
    third = 1 / 3
    np.testing.assert_allclose(p1, [[0, 0], [third, 0], [third, third], [2 * third, third], [2 * third, 0], [1, 0]],
                               atol=1e-12)
    for n in range(5):
        (p,) = fractals.quadratic_koch(n)
        assert len(p) - 1 == 5 ** n
        np.testing.assert_allclose(p[-1], [1, 0], atol=1e-12)
        assert turtle.length(p) == pytest.approx((5 / 3) ** n, rel=1e-12)
    assert fractals.program_dimension(fractals.quadratic_koch_program()) == pytest.approx(math.log(5) / math.log(3))
