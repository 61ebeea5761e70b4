"""Exercise checkers for chapter 5, turtle shortcomings and the CODO language (Goldman §5.1-5.2).

Answers are CODO programs or expressions (strings, parsed and run by :mod:`goldman_lib.codo`, never
by Python's ``eval``), numbers, or a table of types.  A program that does not run is answered with
the interpreter's own message (line, column, token).  Drawings are compared segment by segment
within a tolerance, so decimals to about four places (``0.86603``) are as good as ``sqrt(3)/2``.
Messages name the slip and how far off an answer is, never the expected numbers.  ``None`` or
``...`` means "not answered yet".

>>> print(check_parallelogram_vertex("A + C").message)
A + C does not run: line 1, column 3, at '+': A + C is neither a point nor a vector: its weights add up to 2.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from goldman_lib import codo
from goldman_lib.exercises import far_off, guard_checkers, quote, clip
from goldman_lib.exercises.deal import Deck, integers as _ints, memo
from goldman_lib.exercises import (Result, correct, fmt, is_unanswered, off_by, read_number, read_points,
                                   unanswered, wrong)

__all__ = ["PROBLEMS", "SLIPS", "HEXAGON_SIDES", "PARALLELOGRAM_TRIPLES", "TYPE_EXPRESSIONS", "IMAGE_SRC",
           "IMAGE_DST", "UNIT_SQUARE", "TURTLE_DOTS", "SEGMENT_TOL", "DECK", "deal", "steps", "current", "deal_button",
           "check_hexagon_program", "check_parallelogram_vertex", "check_expression_types",
           "check_image_program", "check_sheared_turn", "check_turtle_through_dots", "segments_of"]

#: Tolerance on the dots of a drawing (hand-typed decimals such as 0.86603 pass).
SEGMENT_TOL = 1e-4
#: Exercise 1: the regular hexagon with centre (0, 0) and a vertex at (1, 0).
HEXAGON_SIDES = 6
#: Exercise 2: triples (A, B, C) the learner's expression is evaluated on.
PARALLELOGRAM_TRIPLES = (((1.0, 2.0), (4.0, 1.0), (6.0, 5.0)), ((-2.0, 0.5), (3.0, -3.0), (0.0, 4.0)))
#: Exercise 3: the expressions to classify (P, Q, R points; v a vector).
TYPE_EXPRESSIONS = ("Q - 2*P", "P + v", "(P + Q + R)/3", "P - 2*Q + R", "2*P - Q", "3*v - P", "(P - Q)/2 + R",
                    "0.5*P + 0.5*v")
#: Exercise 4: the map sending IMAGE_SRC to IMAGE_DST, applied to UNIT_SQUARE.
IMAGE_SRC = ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))
IMAGE_DST = ((1.0, 0.0), (3.0, 1.0), (2.0, 2.0))
UNIT_SQUARE = ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0))
#: Exercise 6: the dots a turtle at the first one, heading (1, 0), must connect.
TURTLE_DOTS = ((1.0, 1.0), (-3.0, 4.0), (-3.0, 0.0))


def _pts(points) -> str:
    return ", ".join(fmt(p) for p in points)




# -- drawings, compared segment by segment within a tolerance ------------------------------------

def segments_of(polylines, digits: int = 6) -> set:
    """The segments of a drawing as a set of unordered pairs of rounded points (orientation and
    order of drawing forgotten; zero-length segments dropped).

    >>> sorted(segments_of([np.array([[0, 0], [1, 0], [0, 0]])]))
    [((0.0, 0.0), (1.0, 0.0))]
    """
    out = set()
    for p in polylines:
        q = np.round(np.asarray(p, dtype=float), digits) + 0.0
        for a, b in zip(q[:-1], q[1:]):
            a, b = tuple(a.tolist()), tuple(b.tolist())
            if a != b:
                out.add((min(a, b), max(a, b)))
    return out


def _segment_list(polylines) -> list[np.ndarray]:
    """The drawing's segments as (2, 2) arrays, zero-length ones and repeats (within the tolerance) dropped."""
    out: list[np.ndarray] = []
    for p in polylines:
        q = np.asarray(p, dtype=float)
        for a, b in zip(q[:-1], q[1:]):
            s = np.array([a, b])
            if np.abs(a - b).max() <= SEGMENT_TOL:
                continue
            if not any(_gap(s, t) <= SEGMENT_TOL for t in out):
                out.append(s)
    return out


def _show(p) -> str:
    """A drawn point for a message, round-off (1e-16) cleared."""
    return fmt(np.round(np.asarray(p, dtype=float), 9) + 0.0)


def _gap(s: np.ndarray, t: np.ndarray) -> float:
    """How far apart two segments' end points are, either way round."""
    return float(min(np.abs(s - t).max(), np.abs(s - t[::-1]).max()))


def _polygon(vertices) -> list[np.ndarray]:
    V = np.asarray(vertices, dtype=float)
    return [np.array([V[i], V[(i + 1) % len(V)]]) for i in range(len(V))]


def _run(answer, ask) -> tuple[list | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered(ask)
    if not isinstance(answer, str):
        return None, wrong(f"the answer should be a CODO program in quotes; you gave {type(answer).__name__} "
                           f"{quote(answer)}.")
    try:
        return codo.run(answer), None
    except codo.CodoError as exc:
        return None, wrong(f"the program does not run: {clip(exc, 200)}.")


def _compare(polylines, expected: list[np.ndarray], name: str, hint: str) -> Result:
    drawn = _segment_list(polylines)
    n = len(expected)
    if not drawn:
        return wrong("your program draws nothing: use CONNECT (or DRAW a figure).")
    missing = [e for e in expected if not any(_gap(e, d) <= SEGMENT_TOL for d in drawn)]
    extra = [d for d in drawn if not any(_gap(d, e) <= SEGMENT_TOL for e in expected)]
    if not missing and not extra:
        return correct(f"your drawing is {name}: its {n} sides and nothing else.")
    if extra:
        d = extra[0]
        near = min(_gap(d, e) for e in expected)
        if near <= 0.05:
            return wrong(f"your segment from {_show(d[0])} to {_show(d[1])} is nearly a side of {name} but "
                         f"slightly off: type more decimals (four places) or exact values such as sqrt(3)/2.")
        if not any(_gap(d, e) <= SEGMENT_TOL for d in drawn for e in expected):
            return wrong(f"none of your {len(drawn)} segments is a side of {name} (e.g. {_show(d[0])} to {_show(d[1])}): "
                         f"{hint}.")
        return wrong(f"your segment from {_show(d[0])} to {_show(d[1])} is not a side of {name}"
                     + (f", and {len(missing)} of its {n} sides are missing" if missing else "") + f": {hint}.")
    return wrong(f"{len(missing)} of the {n} sides of {name} {'is' if len(missing) == 1 else 'are'} missing: "
                 f"{hint}.")


def _hexagon() -> list[np.ndarray]:
    a = np.radians(360.0 / HEXAGON_SIDES * np.arange(HEXAGON_SIDES))
    return _polygon(np.column_stack([np.cos(a), np.sin(a)]))


def check_hexagon_program(answer) -> Result:
    """Exercise 1: a CODO program that draws the regular hexagon with centre ``(0, 0)`` and a
    vertex at ``(1, 0)`` (Goldman §5.2.2).  answer: program text.  Compares the segments drawn,
    each end within :data:`SEGMENT_TOL`.

    >>> print(check_hexagon_program(codo.SAMPLES["regular pentagon"]).message)
    none of your 5 segments is a side of the regular hexagon (e.g. (1, 0) to (0.309, 0.9511)): the hexagon turns by 360/6 degrees at the centre from one vertex to the next.
    """
    lines, problem = _run(answer, "a CODO program (in quotes) for the hexagon")
    if problem is not None:
        return problem
    return _compare(lines, _hexagon(), "the regular hexagon",
                    "the hexagon turns by 360/6 degrees at the centre from one vertex to the next")


def _one_expression(answer, names, setup_values, ask):
    """Evaluate a learner's CODO expression with the named points set up; (value, None) or (None, Result)."""
    if is_unanswered(answer):
        return None, unanswered(ask)
    if not isinstance(answer, str):
        return None, wrong(f"the answer should be a CODO expression in quotes; you gave {quote(answer)}.")
    if "\n" in answer.strip() or ";" in answer:
        return None, wrong("write one expression (no statements, no ';'), e.g. \"A + ...\".")
    setup = "; ".join(f"{n} = point({x!r}, {y!r})" for n, (x, y) in zip(names, setup_values)) + "\n"
    try:
        return codo.execute(setup + "X = " + answer.strip()).variables["X"], None
    except codo.CodoError as exc:
        # the message for the learner's own line, numbered as they wrote it
        msg = str(exc).replace(f"line {exc.line},", "line 1,", 1).replace(
            f"column {exc.column},", f"column {exc.column - 4 if exc.line == 2 else exc.column},", 1)
        return None, wrong(f"{clip(' '.join(answer.split()))} does not run: {clip(msg.split('. Adding')[0], 200)}.")


def check_parallelogram_vertex(answer) -> Result:
    """Exercise 2: a CODO expression in ``A, B, C`` for the fourth vertex ``D`` of the
    parallelogram ``ABCD`` (Goldman §5.2.1).  answer: expression text, evaluated by the CODO
    interpreter for the triples :data:`PARALLELOGRAM_TRIPLES`.

    >>> print(check_parallelogram_vertex("B + C - A").message)
    B + C - A is the vertex opposite A, which makes ABDC a parallelogram with B and C next to each other; in ABCD the vertex D is next to A and to C, opposite B.
    """
    expr = clip(" ".join(answer.split())) if isinstance(answer, str) else ""
    for k, (A, B, C) in enumerate(PARALLELOGRAM_TRIPLES):
        X, problem = _one_expression(answer, "ABC", (A, B, C), "a CODO expression (in quotes) in A, B and C")
        if problem is not None:
            return problem
        if isinstance(X, codo.Vector):
            return wrong(f"{expr} is a vector (its weights add up to 0), not a point: a vertex is a point, e.g. a "
                         f"point plus a vector.")
        if not isinstance(X, codo.Point):
            return wrong(f"{expr} is a {type(X).__name__}, not a point.")
        A_, B_, C_ = (np.array(p) for p in (A, B, C))
        got, want = np.array(X), A_ + C_ - B_
        if np.allclose(got, want, atol=1e-9):
            continue
        if np.allclose(got, B_ + C_ - A_, atol=1e-9):
            return wrong(f"{expr} is the vertex opposite A, which makes ABDC a parallelogram with B and C next to "
                         f"each other; in ABCD the vertex D is next to A and to C, opposite B.")
        if np.allclose(got, A_ + B_ - C_, atol=1e-9):
            return wrong(f"{expr} is the vertex opposite C; in ABCD the vertex D is next to A and to C, opposite B.")
        if np.allclose(got, (A_ + C_) / 2, atol=1e-9):
            return wrong(f"{expr} is the centre of the parallelogram (where the diagonals cross), not a vertex: D is "
                         f"as far beyond the centre as B is before it.")
        if k == 1:
            return wrong(f"{expr} gives D for the first triple A, B, C = {_pts(PARALLELOGRAM_TRIPLES[0])} but not "
                         f"for A, B, C = {_pts((A, B, C))}: write it in terms of A, B and C, not numbers.")
        return wrong(f"for A, B, C = {_pts((A, B, C))}, {expr} is {far_off(got, want)} from D. "
                     f"Hint: opposite sides of a parallelogram are the same vector, D - A = C - B.")
    return correct(f"{expr} is the fourth vertex D of the parallelogram ABCD, for every A, B, C.")


def _type_of(expression: str) -> tuple[str, str]:
    """The type of an expression by the CODO interpreter and, if illegal, its reason."""
    setup = "P = point(1, 2); Q = point(-3, 4); R = point(5, -1); v = vector(2, 7)\n"
    try:
        X = codo.execute(setup + "X = " + expression).variables["X"]
    except codo.CodoTypeError as exc:
        return "illegal", str(exc).split(": ", 1)[1]
    return ("point" if isinstance(X, codo.Point) else "vector"), ""


def check_expression_types(answer) -> Result:
    """Exercise 3: for each expression of :data:`TYPE_EXPRESSIONS`, is it a ``"point"``, a
    ``"vector"``, or ``"illegal"``?  (Goldman §5.2.1.)  answer: a dict expression -> word.
    The rule: the weights of the points must sum to 1 (a point) or 0 (a vector).

    >>> print(check_expression_types({e: "point" for e in TYPE_EXPRESSIONS}).message)
    Q - 2*P is illegal: Q - 2*P is neither a point nor a vector: its weights add up to -1.
    """
    if is_unanswered(answer):
        return unanswered("a dict giving 'point', 'vector' or 'illegal' for each expression")
    if not isinstance(answer, dict):
        return wrong(f"the answer should be a dict like {{\"P + v\": \"point\", ...}}; you gave {type(answer).__name__}.")
    missing = [e for e in TYPE_EXPRESSIONS if e not in answer]
    if missing:
        return wrong(f"give a type for every expression; {quote(missing[0])} is missing.")
    for e in TYPE_EXPRESSIONS:
        given = str(answer[e]).strip().lower()
        if given not in ("point", "vector", "illegal"):
            return wrong(f"the type of {quote(e)} should be 'point', 'vector' or 'illegal'; you gave {quote(answer[e])}.")
        kind, why = _type_of(e)
        if given != kind:
            if kind == "illegal":
                return wrong(f"{e} is illegal: {why.split('. Adding')[0]}.")
            if "v" in e and given == "illegal":
                return wrong(f"{e} is a {kind}: a vector may be added to anything, and does not count in the "
                             f"weights; only the points' weights must sum to 1 or 0.")
            weights = "1" if kind == "point" else "0"
            return wrong(f"{e} is a {kind}: the weights of its points add up to {weights}.")
    return correct(f"all {len(TYPE_EXPRESSIONS)} types are right: the weights of the points sum to 1 (point), "
                   f"0 (vector) or something else (illegal).")


DECK = Deck("ch05")


def _connect(points) -> str:
    """A CODO program that connects ``points`` and closes the polygon."""
    pts = [tuple(float(c) for c in q) for q in points]
    return "CONNECT " + ", ".join(f"point({fmt(x, 12)}, {fmt(y, 12)})" for x, y in pts + pts[:1])


@functools.lru_cache(maxsize=1024)
def _program_segments(text: str) -> tuple:
    return tuple(_segment_list(codo.run(text)))


def _same_drawing(a: str, b: str) -> bool:
    """Whether two CODO programs draw the same segments (within SEGMENT_TOL), both ways."""
    da, db = _program_segments(a), _program_segments(b)
    return len(da) == len(db) and all(any(_gap(e, d) <= SEGMENT_TOL for d in db) for e in da)


# -- exercise 4: the image of the unit square -----------------------------------------------------

_STORED_IMAGE = {"dst": IMAGE_DST}


@memo
def _image_square(p) -> np.ndarray:
    from goldman_lib import affine
    return affine.apply(np.array(UNIT_SQUARE), affine.affine_from_points(IMAGE_SRC, p["dst"]))


def _image_guess(dst) -> np.ndarray:
    dst = np.array(dst, dtype=float)
    return np.array([dst[0], dst[1], np.array([dst[1][0], dst[2][1]]), dst[2]])


def _image_slips(p) -> dict:
    return {"the square itself": _connect(UNIT_SQUARE), "the image of the triangle": _connect(p["dst"]),
            "the fourth corner read off": _connect(_image_guess(p["dst"]))}


def _image_generate(rng) -> dict:
    return {"dst": tuple(_ints(rng, -3, 4, 2) for _ in range(3))}


def _image_ok(p):
    B = np.array(p["dst"])
    if abs(np.linalg.det(B[1:] - B[0])) < 0.5:
        return "the image points are collinear: the map is singular"
    return None


def _image_statement(p) -> str:
    return (f"Write a CODO program that draws the image of the unit square {_pts(UNIT_SQUARE)} under the affine map "
            f"sending {_pts(IMAGE_SRC)} to {_pts(p['dst'])} (Goldman §5.2, §4.7.3).")


def _image_steps(p) -> str:
    Q = np.array(p["dst"])
    four = Q[1] + Q[2] - Q[0]
    return (f"1. The map sends (0, 0), (1, 0), (0, 1) to Q1, Q2, Q3 = {_pts(Q)}.\n"
            f"2. (1, 1) = (1, 0) + (0, 1) - (0, 0) is an affine combination, so its image is Q2 + Q3 - Q1 = "
            f"{fmt(four)}.\n"
            f"3. One program: `{_connect([Q[0], Q[1], four, Q[2]])}` (or in CODO: M = affine(...); DRAW M(square)).")


@DECK.exercise(stored=_STORED_IMAGE, generate=_image_generate, answer=lambda p: _connect(_image_square(p)),
               slips=_image_slips, statement=_image_statement, steps=_image_steps, same=_same_drawing,
               well_posed=_image_ok)
def check_image_program(answer, p) -> Result:
    """Exercise 4: a CODO program that draws the image of :data:`UNIT_SQUARE` under the affine map
    sending :data:`IMAGE_SRC` to the statement's three points (Goldman §5.2, §4.7.3).  answer:
    program text.
    """
    lines, problem = _run(answer, "a CODO program (in quotes) that draws the image of the square")
    if problem is not None:
        return problem
    drawn = _segment_list(lines)

    def same(vertices):
        exp = _polygon(vertices)      # both ways: a degenerate guess's segments may all be sides of the answer
        return (all(any(_gap(e, d) <= SEGMENT_TOL for d in drawn) for e in exp)
                and all(any(_gap(d, e) <= SEGMENT_TOL for e in exp) for d in drawn))

    dst = np.array(p["dst"])
    if same(UNIT_SQUARE):
        return wrong("that is the square itself: apply the map to it, as M(F) for a figure F.")
    if same(dst):
        return wrong("that is the image of the triangle (0, 0), (1, 0), (0, 1); the square has a fourth corner, "
                     "(1, 1), and its image is needed too.")
    if same(_image_guess(dst)):
        return wrong("the image of (1, 1) is not a corner you can read off: an affine map keeps the square a "
                     "parallelogram, so it is Q1 + (Q2 - Q1) + (Q3 - Q1).")
    return _compare(lines, _polygon(_image_square(p)), "the image of the square",
                    "the images of (0, 0), (1, 0), (0, 1) are given; (1, 1) = (1, 0) + (0, 1) - (0, 0) goes to the "
                    "same combination of the images")


# -- exercise 5: the turn of a sheared square -----------------------------------------------------

def _shear_text(k: float) -> str:
    if k == 1:
        return "x + y"
    if k == -1:
        return "x - y"
    return f"x {'+' if k > 0 else '-'} {fmt(abs(k))}y"


def _corner(k: float) -> str:
    return f"({fmt(1 + k)}, 1)"


def _shear_answer(p) -> float:
    return math.degrees(math.atan2(1.0, p["k"]))


def _shear_slips(p) -> dict:
    right = _shear_answer(p)
    return {"the square's turn": 90.0, "the interior angle": 180.0 - right, "clockwise": -right,
            "radians": math.radians(right)}


def _same_turn(a, b) -> bool:
    d = (float(a) - float(b)) % 360.0
    return min(d, 360.0 - d) <= 0.01 or abs(float(a) - float(b)) <= 1e-3


def _shear_statement(p) -> str:
    k = p["k"]
    return (f"The turtle draws the unit square with REPEAT 4 [FORWARD 1 TURN 90]. Its image under the shear "
            f"(x, y) -> ({_shear_text(k)}, y) is the parallelogram (0, 0), (1, 0), {_corner(k)}, ({fmt(k)}, 1). By "
            f"how many degrees must a turtle that has just drawn the side from (0, 0) to (1, 0) TURN at (1, 0) to "
            f"draw the next side (Goldman §5.1)?")


def _shear_steps(p) -> str:
    k = p["k"]
    return (f"1. The next side goes from (1, 0) to {_corner(k)}: its direction is ({fmt(k)}, 1).\n"
            f"2. The turtle arrives heading along (1, 0), at 0 degrees; the new heading is atan2(1, {fmt(k)}) = "
            f"{fmt(_shear_answer(p))} degrees.\n"
            f"3. TURN is the change of heading: {fmt(_shear_answer(p))} degrees (counterclockwise).")


@DECK.exercise(stored={"k": 1.0}, generate=lambda rng: {"k": float(rng.choice([2.0, 3.0, 0.5, -1.0, -2.0, -0.5, 1.0]))},
               answer=_shear_answer, slips=_shear_slips, statement=_shear_statement, steps=_shear_steps,
               same=_same_turn)
def check_sheared_turn(answer, p) -> Result:
    """Exercise 5: the turtle's TURN at ``(1, 0)`` for the sheared square (Goldman §5.1: the
    turtle cannot draw the affine image of its drawing by changing only its initial state).

    >>> print(check_sheared_turn(90).message)
    90 degrees is the square's turn; the shear changes the angles, which is exactly why the turtle program has to change: find the direction of the side from (1, 0) to (2, 1).
    """
    what = "the turning angle at (1, 0)"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    r = a % 360.0
    right = _shear_answer(p)
    corner = _corner(p["k"])

    def near(x):
        d = (r - x) % 360.0
        return min(d, 360.0 - d) <= 0.01

    if near(right):
        return correct(f"the turtle turns by {fmt(right)} degrees at (1, 0). The program itself must change, not only "
                       f"the turtle's initial state: affine maps do not preserve angles.")
    if near(90.0):
        return wrong(f"90 degrees is the square's turn; the shear changes the angles, which is exactly why the turtle "
                     f"program has to change: find the direction of the side from (1, 0) to {corner}.")
    if near(180.0 - right):
        return wrong(f"{fmt(a)} degrees is the interior angle of the parallelogram at (1, 0); the turtle turns by the "
                     f"exterior angle, 180 minus the interior one.")
    if near(-right):
        return wrong("a negative TURN turns clockwise; the parallelogram is drawn counterclockwise, like the square.")
    if abs(a - math.radians(right)) <= 1e-3:
        return wrong(f"{fmt(a)} looks like radians; TURN takes degrees.")
    return wrong(f"{what} is {off_by(r if r <= 180 else r - 360, right)}. Hint: the turtle arrives heading "
                 f"along (1, 0); it must turn to the direction of the side from (1, 0) to {corner}.")


# -- exercise 6: turtle commands through three dots ------------------------------------------------

_STORED_DOTS = {"dots": TURTLE_DOTS}


@memo
def _turtle_answer(p) -> np.ndarray:
    P = np.array(p["dots"])
    seg = np.diff(P, axis=0)
    headings = np.degrees(np.arctan2(seg[:, 1], seg[:, 0]))
    turns = np.diff(np.concatenate([[0.0], headings]))
    turns = (turns + 180.0) % 360.0 - 180.0
    return np.array([turns[0], np.hypot(*seg[0]), turns[1], np.hypot(*seg[1])])


def _dots_slips(p) -> dict:
    right = _turtle_answer(p)
    seg = np.diff(np.array(p["dots"]), axis=0)
    d = seg[0]
    heading2 = math.degrees(math.atan2(seg[1][1], seg[1][0]))

    def with_(k, v):
        out = right.copy()
        out[k] = v
        return out
    return {"atan of |dy/dx|": with_(0, math.degrees(math.atan(abs(d[1] / d[0])))),
            "atan(dy/dx)": with_(0, math.degrees(math.atan(d[1] / d[0]))),
            "radians": with_(0, math.radians(right[0])),
            "|dx| + |dy|": with_(1, abs(d[0]) + abs(d[1])),
            "the squared length": with_(1, float(d @ d)),
            "the heading, not the turn": with_(2, heading2),
            "the turn the wrong way": with_(2, -right[2])}


def _same_commands(a, b) -> bool:
    a, b = np.asarray(a, float), np.asarray(b, float)

    def angle_ok(x, y):
        d = (x - y) % 360.0
        return min(d, 360.0 - d) <= 0.01 or abs(x - y) <= 1e-3
    return (angle_ok(a[0], b[0]) and angle_ok(a[2], b[2]) and abs(a[1] - b[1]) <= 1e-3
            and abs(a[3] - b[3]) <= 1e-3)


def _dots_generate(rng) -> dict:
    P0 = _ints(rng, -3, 3, 2)
    d1 = (-float(rng.integers(1, 6)), float(rng.integers(1, 6)))
    d2 = _ints(rng, -5, 5, 2)
    P1 = (P0[0] + d1[0], P0[1] + d1[1])
    return {"dots": (P0, P1, (P1[0] + d2[0], P1[1] + d2[1]))}


def _dots_ok(p):
    t2 = _turtle_answer(p)[2]
    if not 20 <= t2 <= 160:
        return "the second turn is not a clear left bend (the messages say the polyline bends left)"
    return None


def _dots_statement(p) -> str:
    dots = p["dots"]
    return (f"A turtle stands at {fmt(dots[0])} heading along (1, 0). Which TURN and FORWARD commands make it "
            f"draw the polyline {_pts(dots)}? Answer [turn 1, forward 1, turn 2, forward 2], angles in degrees "
            f"counterclockwise, to 0.01 degree (Goldman §5.1).")


def _dots_steps(p) -> str:
    P = np.array(p["dots"])
    seg = np.diff(P, axis=0)
    h = np.degrees(np.arctan2(seg[:, 1], seg[:, 0]))
    r = _turtle_answer(p)
    return (f"1. The segments are {fmt(seg[0])} and {fmt(seg[1])}; their headings are atan2(dy, dx) = "
            f"{fmt(h[0])} and {fmt(h[1])} degrees.\n"
            f"2. turn 1 = {fmt(h[0])} - 0 = {fmt(r[0])}; forward 1 = sqrt(dx^2 + dy^2) = {fmt(r[1])}.\n"
            f"3. turn 2 = {fmt(h[1])} - {fmt(h[0])} = {fmt(r[2])} (mod 360, between -180 and 180); forward 2 = "
            f"{fmt(r[3])}.")


@DECK.exercise(stored=_STORED_DOTS, generate=_dots_generate, answer=_turtle_answer, slips=_dots_slips,
               statement=_dots_statement, steps=_dots_steps, same=_same_commands, well_posed=_dots_ok)
def check_turtle_through_dots(answer, p) -> Result:
    """Exercise 6: the turtle commands ``[turn 1, forward 1, turn 2, forward 2]`` that draw the
    polyline of the statement from its first dot, heading ``(1, 0)`` (Goldman §5.1: the turtle
    needs arc tangents and square roots to connect dots).  Turns are compared modulo 360 to 0.01
    degree, distances to 1e-3.
    """
    what = "the four numbers [turn 1, forward 1, turn 2, forward 2]"
    got, problem = read_points(answer, "your commands", ask=what)
    if problem is not None:
        return problem
    if got.shape != (4,):
        return wrong(f"give four numbers [turn 1, forward 1, turn 2, forward 2]; yours has shape {got.shape}.")
    right = _turtle_answer(p)
    P = np.array(p["dots"])
    seg = np.diff(P, axis=0)
    headings = np.degrees(np.arctan2(seg[:, 1], seg[:, 0]))

    def angle_ok(a, b):
        d = (a - b) % 360.0
        return min(d, 360.0 - d) <= 0.01

    turns_ok = [angle_ok(got[0], right[0]), angle_ok(got[2], right[2])]
    dist_ok = [abs(got[1] - right[1]) <= 1e-3, abs(got[3] - right[3]) <= 1e-3]
    if all(turns_ok) and all(dist_ok):
        return correct("those commands draw the polyline: each TURN is an arc tangent, each FORWARD a square root. "
                       "In CODO it is one CONNECT of the three dots.")
    if not all(dist_ok):
        k = 0 if not dist_ok[0] else 1
        d = seg[k]
        if abs(got[2 * k + 1] - (abs(d[0]) + abs(d[1]))) <= 1e-3:
            return wrong(f"forward {k + 1} adds |dx| + |dy|; the turtle walks straight along the segment, "
                         f"its length is sqrt(dx^2 + dy^2).")
        if abs(got[2 * k + 1] - float(d @ d)) <= 1e-3:
            return wrong(f"forward {k + 1} is the squared length; take the square root.")
        return wrong(f"forward {k + 1} is {off_by(got[2 * k + 1], right[2 * k + 1])}: it is the length of the "
                     f"segment from dot {k + 1} to dot {k + 2}.")
    if not turns_ok[0]:
        d = seg[0]
        if angle_ok(got[0], math.degrees(math.atan(abs(d[1] / d[0])))):
            return wrong(f"turn 1 is the arc tangent of {fmt(abs(d[1]))}/{fmt(abs(d[0]))} without its quadrant: the "
                         f"segment goes left (x decreases), so its heading is between 90 and 180 degrees; use "
                         f"atan2(dy, dx).")
        if angle_ok(got[0], math.degrees(math.atan(d[1] / d[0]))):
            return wrong("turn 1 is atan(dy/dx), which loses the quadrant: the segment goes left and up; use "
                         "atan2(dy, dx).")
        if abs(got[0] - math.radians(right[0])) <= 1e-3:
            return wrong("turn 1 looks like radians; TURN takes degrees.")
        return wrong(f"turn 1 is {off_by(right[0] + (got[0] - right[0] + 180) % 360 - 180, right[0])}: the "
                     f"turtle heads along (1, 0) and must turn to the direction of the first segment.")
    if angle_ok(got[2], headings[1]):
        return wrong("turn 2 is the heading of the second segment; TURN is relative: subtract the heading the turtle "
                     "already has (the first segment's).")
    if angle_ok(got[2], -right[2]):
        return wrong("turn 2 goes the wrong way: a positive TURN is counterclockwise; the polyline bends to the left "
                     "at the second dot.")
    return wrong(f"turn 2 is {off_by(right[2] + (got[2] - right[2] + 180) % 360 - 180, right[2])}: it is "
                 f"the change of heading at the second dot, from the first segment's direction to the second's.")




#: Deal another instance of an exercise (``deal("check_sheared_turn")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Exercises 1-3 ask for a program, an expression and a table of types, fixed by design (exercise 2
#: is already checked on two triples of points): they do not deal.
PROBLEMS = DECK.problems({
    "check_hexagon_program": (
        f"Write a CODO program that draws the regular hexagon with centre (0, 0) and a vertex at (1, 0): its "
        f"{HEXAGON_SIDES} sides and nothing else (Goldman §5.2.2). Dots are compared to 1e-4, so sqrt(3)/2 or "
        f"decimals to four places are both fine."),
    "check_parallelogram_vertex": (
        "A, B, C are three consecutive vertices of the parallelogram ABCD. Write a CODO expression in A, B and C "
        "for the fourth vertex D (Goldman §5.2.1: affine combinations)."),
    "check_expression_types": (
        "P, Q, R are points and v is a vector. For each expression say whether it is a 'point', a 'vector' or "
        "'illegal': " + ", ".join(TYPE_EXPRESSIONS) + ". Answer with a dict {expression: word} (Goldman §5.2.1)."),
})


#: Wrong answers of the kinds each checker recognises (tests feed them and check the message).
SLIPS = {
    "check_hexagon_program": [codo.SAMPLES["regular pentagon"],
                              "C = point(0, 0); P = point(1, 0); R = rotate(C, 60)\nREPEAT 5 [ CONNECT P, R(P); P = R(P) ]",
                              "CONNECT point(1, 0), point(0.5, 0.87), point(-0.5, 0.87), point(-1, 0), "
                              "point(-0.5, -0.87), point(0.5, -0.87), point(1, 0)",
                              "P = point(0, 0)\nCONNECT P, P + P"],
    "check_parallelogram_vertex": ["B + C - A", "A + B - C", "(A + C)/2", "C - B", "A + C"],
    "check_expression_types": [
        {**dict.fromkeys(TYPE_EXPRESSIONS, "point"), "Q - 2*P": "vector"},
        {"Q - 2*P": "illegal", "P + v": "illegal", "(P + Q + R)/3": "point", "P - 2*Q + R": "vector",
         "2*P - Q": "point", "3*v - P": "illegal", "(P - Q)/2 + R": "point", "0.5*P + 0.5*v": "illegal"},
        {"Q - 2*P": "illegal", "P + v": "point", "(P + Q + R)/3": "point", "P - 2*Q + R": "illegal",
         "2*P - Q": "point", "3*v - P": "illegal", "(P - Q)/2 + R": "point", "0.5*P + 0.5*v": "illegal"},
        {"Q - 2*P": "illegal", "P + v": "point", "(P + Q + R)/3": "point", "P - 2*Q + R": "vector",
         "2*P - Q": "point", "3*v - P": "illegal", "(P - Q)/2 + R": "point", "0.5*P + 0.5*v": "point"},
    ],
    "check_image_program": ["CONNECT point(0,0), point(1,0), point(1,1), point(0,1), point(0,0)",
                            "CONNECT point(1,0), point(3,1), point(2,2), point(1,0)",
                            "CONNECT point(1,0), point(3,1), point(3,2), point(2,2), point(1,0)",
                            "M = affine(point(0, 0), point(1, 0), point(2, 0), point(1, 0), point(3, 1), point(2, 2))"],
    "check_sheared_turn": [90, 135, -45, 0.7854],
    "check_turtle_through_dots": [[36.87, 5, 126.87, 4], [-36.87, 5, 126.87, 4], [143.13, 7, 126.87, 4],
                                  [143.13, 5, 270, 4], [143.13, 5, -126.87, 4], [143.13, 25, 126.87, 4]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
