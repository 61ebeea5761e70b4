"""Chapter 5, the CODO language: the §5.2.2 sample programs draw figures whose vertices are written
here, the type rules of affine geometry, maps against closed forms, one test per error class
checking the line, column and token of the message, and the two shortcomings of turtle graphics
(§5.1) against an independent least-squares solve."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from goldman_lib import affine, codo, turtle

SETTINGS = settings(max_examples=40, deadline=None)


def circle_points(angles, radius=1.0):
    a = np.radians(angles)
    return radius * np.column_stack([np.cos(a), np.sin(a)])


# --- the sample programs of §5.2.2 -----------------------------------------------------------------

def test_pentagon_sample():
    lines = codo.run(codo.SAMPLES["regular pentagon"])
    P = circle_points(72.0 * np.arange(6))
    assert len(lines) == 5
    for k, seg in enumerate(lines):
        np.testing.assert_allclose(seg, P[k:k + 2], atol=1e-14)


def test_star_sample():
    lines = codo.run(codo.SAMPLES["five-pointed star"])
    P = circle_points(90.0 + 144.0 * np.arange(6))
    for k, seg in enumerate(lines):
        np.testing.assert_allclose(seg, P[k:k + 2], atol=1e-14)
    np.testing.assert_allclose(lines[-1][-1], [0, 1], atol=1e-14)   # the star closes


def test_nested_squares_sample():
    lines = codo.run(codo.SAMPLES["nested squares"])
    assert len(lines) == 5
    np.testing.assert_allclose(lines[0], [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]])
    np.testing.assert_allclose(lines[1], [[0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5], [0.5, 0]])
    np.testing.assert_allclose(lines[2], [[0.75, 0.25], [0.75, 0.75], [0.25, 0.75], [0.25, 0.25], [0.75, 0.25]])
    # each square has half the area of the one before
    for k, sq in enumerate(lines):
        side = np.linalg.norm(sq[1] - sq[0])
        assert side ** 2 == pytest.approx(0.5 ** k)


def test_spiral_sample():
    lines = codo.run(codo.SAMPLES["spiral"])
    k = np.arange(61)
    P = circle_points(20.0 * k) * (0.95 ** k)[:, None]
    assert len(lines) == 60
    np.testing.assert_allclose(np.array([s[0] for s in lines]), P[:-1], atol=1e-12)
    np.testing.assert_allclose(lines[-1][1], P[-1], atol=1e-12)


def test_rosette_sample():
    lines = codo.run(codo.SAMPLES["rosette of squares"])
    assert len(lines) == 12
    np.testing.assert_allclose(lines[0], [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]])
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    np.testing.assert_allclose(lines[1], [[0, 0], [c, s], [c - s, s + c], [-s, c], [0, 0]], atol=1e-14)
    np.testing.assert_allclose(lines[3][1], [0, 1], atol=1e-14)


def test_affine_image_of_a_house_sample():
    house, image, sheared = codo.run(codo.SAMPLES["affine image of a house"])
    np.testing.assert_allclose(house, [[0, 0], [1, 0], [1, 1], [0.5, 1.5], [0, 1], [0, 0]])
    np.testing.assert_allclose(image, [[2, 0], [3.5, 0.5], [4, 1.5], [3.5, 1.75], [2.5, 1], [2, 0]], atol=1e-14)
    np.testing.assert_allclose(sheared, [[4.5, 0], [5.5, 0], [6.1, 1], [5.9, 1.5], [5.1, 1], [4.5, 0]], atol=1e-14)


# --- the type rules of affine geometry (§5.2.1) -----------------------------------------------------

def test_points_and_vectors_type_rules():
    v = codo.execute("""P = point(1, 2); Q = point(4, 6); u = vector(1, 1)
A = P + u
w = Q - P
s = u + w - vector(0, 1)
t = 2*u
M = (P + Q)/2
B = 0.25*P + 0.75*Q
C = P - Q + Q
D = P + (Q - P)/2
d = dist(P, Q)
n = length(w)
k = -u
""").variables
    assert v["A"] == codo.Point(2, 3) and isinstance(v["A"], codo.Point)
    assert v["w"] == codo.Vector(3, 4) and isinstance(v["w"], codo.Vector)
    assert v["s"] == codo.Vector(4, 4)
    assert v["t"] == codo.Vector(2, 2)
    assert v["M"] == codo.Point(2.5, 4)
    assert v["B"] == codo.Point(3.25, 5)
    assert v["C"] == codo.Point(1, 2)
    assert v["D"] == codo.Point(2.5, 4)
    assert v["d"] == 5.0 and v["n"] == 5.0
    assert v["k"] == codo.Vector(-1, -1)


def test_numbers_and_functions():
    v = codo.execute("a = 2 + 3*4 - 6/3\nb = -(1 + 1)\nc = sqrt(2)*sqrt(2)\nd = cos(60) + sin(30)\ne = cos(90)").variables
    assert v["a"] == 12 and v["b"] == -2 and v["c"] == pytest.approx(2) and v["d"] == pytest.approx(1) and v["e"] == 0


@pytest.mark.parametrize("program, expected", [
    ("X = rotate(point(1, 1), 90)(point(3, 1))", (1, 3)),
    ("X = rotate(point(0, 0), 30)(point(2, 0))", (math.sqrt(3), 1)),
    ("X = scale(point(1, 1), 3)(point(2, 2))", (4, 4)),
    ("X = scale(point(0, 0), vector(1, 0), 2)(point(3, 5))", (6, 5)),
    ("X = scale(point(0, 0), vector(1, 1), 3)(point(1, 0))", (2, 1)),
    ("X = mirror(point(0, 1), vector(1, 0))(point(3, 5))", (3, -3)),
    ("X = translate(vector(2, -1))(point(1, 1))", (3, 0)),
    ("X = affine(point(0,0), point(1,0), point(0,1), point(1,1), point(3,1), point(1,4))(point(1, 1))", (3, 4)),
    ("X = affine(point(0,0), vector(1,0), vector(0,1), point(1,1), vector(0,1), vector(-1,0))(point(2, 0))", (1, 3)),
    ("X = (rotate(point(0, 0), 90) * translate(vector(1, 0)))(point(1, 0))", (1, 1)),   # rotate first
    ("X = (translate(vector(1, 0)) * rotate(point(0, 0), 90))(point(1, 0))", (0, 2)),   # translate first
    ("X = identity()(point(7, 8))", (7, 8)),
])
def test_maps_on_points_closed_forms(program, expected):
    X = codo.execute(program).variables["X"]
    assert isinstance(X, codo.Point)
    np.testing.assert_allclose(X, expected, atol=1e-14)


def test_maps_on_vectors_ignore_translation_and_maps_on_figures():
    v = codo.execute("""u = translate(vector(5, 5))(vector(1, 0))
r = rotate(point(3, 3), 90)(vector(1, 0))
F = polyline(point(0, 0), point(1, 0)) + polygon(point(0, 0), point(1, 0), point(0, 1))
G = translate(vector(0, 2))(F)
M = rotate(point(0, 0), 90)
""").variables
    assert v["u"] == codo.Vector(1, 0)
    np.testing.assert_allclose(v["r"], (0, 1), atol=1e-15)
    assert len(v["F"]) == 2 and v["F"].polylines[1].shape == (4, 2)
    np.testing.assert_allclose(v["G"].polylines[1], [[0, 2], [1, 2], [0, 3], [0, 2]])
    np.testing.assert_array_equal(v["M"], [[0, 1, 0], [-1, 0, 0], [0, 0, 1]])


@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), min_size=3, max_size=3),
       st.lists(st.floats(-2, 2), min_size=2, max_size=2))
@SETTINGS
def test_affine_combinations_in_codo_match_the_weighted_sum(pts, w):
    c = [w[0], w[1], 1 - w[0] - w[1]]
    prog = "\n".join(f"P{i} = point({x!r}, {y!r})" for i, (x, y) in enumerate(pts))
    prog += f"\nX = {c[0]!r}*P0 + {c[1]!r}*P1 + {c[2]!r}*P2"
    X = codo.execute(prog).variables["X"]
    np.testing.assert_allclose(X, np.array(c) @ np.array(pts), atol=1e-9)


def test_repeat_nesting_and_comments():
    lines = codo.run("""# a grid of unit segments
P = point(0, 0)
REPEAT 3 [           # rows
  REPEAT 2 [ CONNECT P, P + vector(1, 0); P = P + vector(1, 0) ]
  P = P + vector(-2, 1)
]
REPEAT 0 [ CONNECT P, P ]
""")
    assert len(lines) == 6
    np.testing.assert_allclose(lines[-1], [[1, 2], [2, 2]])


def test_case_rules_and_multiline_calls():
    v = codo.execute("p = POINT(1,\n  2)\nP = Point(3, 4)\nrepeat 2 [ connect p, P ]").variables
    assert v["p"] == codo.Point(1, 2) and v["P"] == codo.Point(3, 4)


# --- errors: every class names the line, the column and the token -----------------------------------

ERRORS = [
    # (program, error class, line, column, token, fragment of the message)
    ("P = point(0, 0) £", codo.CodoSyntaxError, 1, 17, "£", "unexpected character"),
    ("P = (1, 2)", codo.CodoSyntaxError, 1, 7, ",", "write a point as point(x, y)"),
    ("P = point(0, 0)\nQ = P Q", codo.CodoSyntaxError, 2, 7, "Q", "expected the end of the statement"),
    ("CONECT P, Q", codo.CodoSyntaxError, 1, 1, "CONECT", "did you mean CONNECT?"),
    ("P = point(0, 0)\nCONNECT P", codo.CodoSyntaxError, 2, 1, "CONNECT", "at least two points"),
    ("REPEAT 3 CONNECT", codo.CodoSyntaxError, 1, 10, "CONNECT", "expected '[' after REPEAT 3"),
    ("P = point(0, 0)\nREPEAT 3 [\n  CONNECT P, P\n", codo.CodoSyntaxError, 4, 1, "",
     "expected ']' to close the REPEAT at line 2, column 1"),
    ("P = point(0, 0)\n]", codo.CodoSyntaxError, 2, 1, "]", "no REPEAT [ to close"),
    ("x = 3 * (2 + 1", codo.CodoSyntaxError, 1, 15, "", "expected ')' to close the '('"),
    ("P = point(0, 0\nCONNECT P, P", codo.CodoSyntaxError, 2, 1, "CONNECT", "is the '(' at line 1, column 10 closed?"),
    ("x = 3 +", codo.CodoSyntaxError, 1, 8, "", "expected a number, a name or '('"),
    ("rotate = 3", codo.CodoSyntaxError, 1, 1, "rotate", "it is a built-in function"),
    ("P = CONNECT", codo.CodoSyntaxError, 1, 5, "CONNECT", "cannot appear inside an expression"),
    ("x = 1e400", codo.CodoSyntaxError, 1, 5, "1e400", "too large"),
    ("M = rotate", codo.CodoSyntaxError, 1, 11, "", "expected '(' after the function rotate"),
    ("P = point(1, 2)\nQ = point(3, 4)\nM = P + Q", codo.CodoTypeError, 3, 7, "+", "weights add up to 2"),
    ("P = point(1, 2)\nQ = 2*P", codo.CodoTypeError, 2, 6, "*", "weights add up to 2"),
    ("P = point(1, 2)\nQ = 0.5*P + 0.3*P", codo.CodoTypeError, 2, 11, "+", "weights add up to 0.8"),
    ("P = point(1, 2)*point(1, 1)", codo.CodoTypeError, 1, 16, "*", "multiplied only by numbers"),
    ("x = 1 + point(0, 0)", codo.CodoTypeError, 1, 7, "+", "cannot add a number and a point"),
    ("M = identity()\nQ = M * point(1, 1)", codo.CodoTypeError, 2, 7, "*", "write M(X)"),
    ("P = point(0, 0)\nCONNECT P, vector(1, 0)", codo.CodoTypeError, 2, 12, "vector", "must be a point"),
    ("P = point(0, 0)\nDRAW P", codo.CodoTypeError, 2, 6, "P", "DRAW needs a figure"),
    ("P = point(0, 0)\nQ = P(P)", codo.CodoTypeError, 2, 6, "(", "not a map"),
    ("M = rotate(point(0, 0))", codo.CodoTypeError, 1, 5, "rotate", "rotate takes a point and an angle"),
    ("M = rotate(vector(0, 0), 30)", codo.CodoTypeError, 1, 12, "vector", "must be a point"),
    ("M = translate(point(1, 0))", codo.CodoTypeError, 1, 15, "point", "must be a vector"),
    ("REPEAT 2.5 [ ]", codo.CodoTypeError, 1, 8, "2.5", "whole number"),
    ("M = affine(point(0,0), vector(1,0), point(0,1), point(0,0), point(1,0), point(0,1))", codo.CodoTypeError,
     1, 37, "point", "argument 3 of affine must be vector"),
    ("CONNECT P, Q", codo.CodoRuntimeError, 1, 9, "P", "has no value yet"),
    ("p = point(0, 0)\nQ = P", codo.CodoRuntimeError, 2, 5, "P", "did you mean p?"),
    ("P = rotat(point(0, 0), 3)", codo.CodoRuntimeError, 1, 5, "rotat", "did you mean rotate?"),
    ("x = 1/0", codo.CodoRuntimeError, 1, 6, "/", "division by zero"),
    ("P = point(0, 0)\nX = affine(P, point(1, 1), point(2, 2), P, P, P)", codo.CodoRuntimeError, 2, 5, "affine",
     "collinear"),
    ("M = scale(point(0, 0), vector(0, 0), 2)", codo.CodoRuntimeError, 1, 24, "vector", "nonzero vector"),
    ("x = sqrt(-1)", codo.CodoRuntimeError, 1, 10, "-", "negative"),
    ("P = point(0, 0)\nREPEAT 1000 [ REPEAT 1000 [ P = P ] ]", codo.CodoRuntimeError, 2, 1, "REPEAT",
     "more than 20,000 statements"),
    ("REPEAT 100000 [ ]", codo.CodoRuntimeError, 1, 1, "REPEAT", "more than the limit"),
    ("F = polygon(point(0, 0), point(1, 0))\nREPEAT 30 [ F = F + F ]", codo.CodoRuntimeError, 2, 19, "+",
     "more than 10,000 polylines"),
    ("x = 1e300 * 1e300", codo.CodoRuntimeError, 1, 11, "*", "overflows"),
    ("C = point(0, 0)\nF = polygon(C, point(1, 0), point(0, 1))\nM = scale(C, 1e200)\nDRAW M(M(F))",
     codo.CodoRuntimeError, 4, 7, "(", "the figure has non-finite points"),
]


@pytest.mark.parametrize("program, cls, line, column, token, fragment", ERRORS,
                         ids=[f"{e[1].__name__}-{i}" for i, e in enumerate(ERRORS)])
def test_error_names_line_column_and_token(program, cls, line, column, token, fragment):
    with pytest.raises(cls) as info:
        codo.run(program)
    err = info.value
    assert isinstance(err, ValueError) and isinstance(err, codo.CodoError)
    assert (err.line, err.column, err.token) == (line, column, token), str(err)
    where = "at end of program" if token == "" else f"at {token!r}"
    assert str(err).startswith(f"line {line}, column {column}, {where}: "), str(err)
    assert fragment in str(err), str(err)


def test_program_must_be_a_string():
    with pytest.raises(TypeError, match="program must be a string"):
        codo.run(42)


def test_empty_program_draws_nothing():
    assert codo.run("") == [] and codo.run("# nothing\n\n;") == []


# --- §5.1: the two shortcomings of turtle graphics ----------------------------------------------------

points = st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)), min_size=2, max_size=8, unique=True)


@given(points)
@SETTINGS
def test_turtle_needs_trigonometry_to_connect_dots(pts):
    P = np.array(pts, dtype=float)
    seg = np.diff(P, axis=0)
    if np.any(np.hypot(*seg.T) == 0):
        return
    program = codo.turtle_program_through(P)
    (path,) = turtle.run(program, point=P[0])
    np.testing.assert_allclose(path, P, atol=1e-9)


def test_turtle_program_through_closed_form_and_errors():
    assert codo.turtle_program_through([[0, 0], [1, 0], [1, 1]]) == "FORWARD 1 TURN 90 FORWARD 1"
    assert codo.turtle_program_through([[0, 0], [1, 1]]) == f"TURN 45 FORWARD {math.sqrt(2)!r}"
    with pytest.raises(ValueError, match="must not repeat consecutively"):
        codo.turtle_program_through([[0, 0], [0, 0], [1, 1]])


def reference_state_fit(z, y):
    """Least squares for x' = a x - b y + p, y' = b x + a y + q (real unknowns a, b, p, q)."""
    n = len(z)
    A = np.zeros((2 * n, 4))
    A[0::2] = np.column_stack([z[:, 0], -z[:, 1], np.ones(n), np.zeros(n)])
    A[1::2] = np.column_stack([z[:, 1], z[:, 0], np.zeros(n), np.ones(n)])
    sol, *_ = np.linalg.lstsq(A, y.reshape(-1), rcond=None)
    err = np.linalg.norm((A @ sol - y.reshape(-1)).reshape(-1, 2), axis=1)
    return sol, err.max()


SQUARE = "REPEAT 4 [FORWARD 1 TURN 90]"


@given(st.floats(-180, 180), st.floats(0.2, 4), st.tuples(st.floats(-5, 5), st.floats(-5, 5)))
@SETTINGS
def test_similarities_are_a_change_of_turtle_state(a, s, t):
    M = affine.similarity(s, a, t)
    fit = codo.turtle_image_gap(turtle.star(5, 2), M)
    assert fit.residual < 1e-9
    # the state found draws the image
    (drawn,) = turtle.run(turtle.star(5, 2), point=fit.point, direction=fit.direction)
    np.testing.assert_allclose(drawn, affine.apply(turtle.run(turtle.star(5, 2))[0], M), atol=1e-9)


@pytest.mark.parametrize("M", [affine.scaling([2, 1]), affine.shear(1), affine.directional_scaling(0.3, [1, 2]),
                               affine.mirror([0, 0], [1, 0])])
@pytest.mark.parametrize("program", [SQUARE, "FORWARD 2 TURN 90 FORWARD 1 TURN 135 FORWARD 1.4142135623730951"])
def test_nonuniform_maps_and_mirrors_are_not_a_change_of_state(M, program):
    (z,) = turtle.run(program)
    y = affine.apply(z, M)
    fit = codo.closest_turtle_state(program, [y])
    # each distinct vertex once: the square's closing vertex is its first one
    distinct = z[:-1] if program == SQUARE else z
    sol, ls_largest = reference_state_fit(distinct, affine.apply(distinct, M))
    ls_err = np.linalg.norm(affine.apply(distinct, M) - (distinct @ np.array([[sol[0], sol[1]], [-sol[1], sol[0]]]) + sol[2:]), axis=1)
    assert fit.rms == pytest.approx(np.sqrt(np.mean(ls_err ** 2)), rel=1e-9)
    # the state found attains the residual it reports ...
    (drawn,) = turtle.run(program, point=fit.point, direction=fit.direction)
    assert np.linalg.norm(drawn - y, axis=1).max() == pytest.approx(fit.residual, rel=1e-9)
    # ... which is no larger than least squares' largest distance, and at least the smallest RMS
    assert fit.rms - 1e-12 <= fit.residual <= ls_largest + 1e-12
    # and no state does better: an independent minimax solve (SLSQP on the epigraph form)
    optimize = pytest.importorskip("scipy.optimize")
    Z = distinct

    def gaps(v):
        return np.linalg.norm(affine.apply(Z, M) - (Z @ np.array([[v[0], v[1]], [-v[1], v[0]]]) + v[2:4]), axis=1)

    x0 = np.concatenate([sol, [ls_largest]])
    r = optimize.minimize(lambda v: v[4], x0, method="SLSQP",
                          constraints=[{"type": "ineq", "fun": lambda v: v[4] ** 2 - gaps(v) ** 2}],
                          options={"ftol": 1e-14, "maxiter": 500})
    assert fit.residual <= gaps(r.x).max() + 1e-7
    assert fit.residual > 0.1


def test_closing_vertex_counted_once():
    # a square scaled by (2, 1): four distinct vertices, each 1/2 * sqrt(1/2) from the best square
    fit = codo.turtle_image_gap(SQUARE, affine.scaling([2, 1]))
    assert fit.residual == pytest.approx(np.sqrt(2) / 4, rel=1e-9)
    assert fit.rms == pytest.approx(np.sqrt(2) / 4, rel=1e-9)


def test_closest_turtle_state_errors():
    with pytest.raises(ValueError, match="shapes of the program's strokes"):
        codo.closest_turtle_state(SQUARE, [np.zeros((3, 2))])
    with pytest.raises(ValueError, match="at least two distinct points"):
        codo.closest_turtle_state("MOVE 1 FORWARD 0", [np.zeros((2, 2))])
