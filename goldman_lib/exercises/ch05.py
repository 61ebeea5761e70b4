"""Exercise checkers for chapter 5, the CODO language (Goldman §5.1-5.2).

Answers are CODO programs or expressions (strings), numbers, or a table of types.  A program that
does not run is answered with the interpreter's own message (line, column, token).  ``None`` or
``...`` means "not answered yet".

>>> exercise_one_third("P + (Q - P)/3")
Correct: P + (Q - P)/3 is the point one third of the way from P to Q, for every P and Q.
>>> exercise_one_third("P + Q/3")
Not yet: P + Q/3 does not run: line 1, column 3, at '+': P + Q/3 is neither a point nor a vector: its weights add up to 1.33333. Adding points or scaling a point is legal only in an affine combination whose weights sum to 1 (a point, e.g. (P + Q)/2 or 0.25*P + 0.75*Q) or 0 (a vector, e.g. P - Q).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import codo
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_number, unanswered, wrong

__all__ = ["PROBLEMS", "TYPE_EXPRESSIONS", "exercise_hexagon_program", "exercise_one_third",
           "exercise_expression_types", "exercise_image_program", "exercise_sheared_turn", "segments_of"]

PROBLEMS = {
    "exercise_hexagon_program": ("a CODO program drawing the regular hexagon with centre (0, 0) and a vertex at (1, 0) "
                                 "(Goldman §5.2.2)"),
    "exercise_one_third": "a CODO expression for the point one third of the way from P to Q (Goldman §5.2.1)",
    "exercise_expression_types": "for each expression, 'point', 'vector' or 'illegal' (Goldman §5.2.1)",
    "exercise_image_program": "a CODO program drawing the image of the unit square under the map sending "
                              "(0, 0), (1, 0), (0, 1) to (1, 0), (3, 1), (2, 2) (Goldman §5.2, §4.7.3)",
    "exercise_sheared_turn": "the turtle's first TURN angle for the sheared square (Goldman §5.1)",
}


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


def _run(answer, what) -> tuple[list | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered(what)
    if not isinstance(answer, str):
        return None, wrong(f"the answer should be a CODO program in quotes; you gave {type(answer).__name__} "
                           f"{answer!r}.")
    try:
        return codo.run(answer), None
    except codo.CodoError as exc:
        return None, wrong(f"the program does not run: {exc}.")


def _polygon_segments(vertices) -> set:
    V = np.asarray(vertices, dtype=float)
    return segments_of([np.vstack([V, V[:1]])])


def _compare(drawn: set, expected: set, name: str) -> Result:
    if drawn == expected:
        return correct(f"your drawing is {name}: its {len(expected)} sides and nothing else.")
    missing, extra = expected - drawn, drawn - expected
    if not drawn:
        return wrong("your program draws nothing: use CONNECT (or DRAW a figure).")
    if missing and not extra:
        a, b = sorted(missing)[0]
        return wrong(f"{len(missing)} of the {len(expected)} sides {'is' if len(missing) == 1 else 'are'} missing, "
                     f"e.g. the side from {fmt(a)} to "
                     f"{fmt(b)}.")
    if len(drawn) != len(expected):
        ok = len(drawn & expected)
        return wrong(f"you drew {len(drawn)} different segment{'s' * (len(drawn) != 1)}, {ok} of them sides of "
                     f"{name}; {name} has "
                     f"{len(expected)} sides.")
    a, b = sorted(extra)[0]
    if not drawn & expected:
        return wrong(f"you drew {len(drawn)} segments but none of them is a side of {name} (e.g. {fmt(a)} to "
                     f"{fmt(b)}): check the position and size of your figure.")
    return wrong(f"you drew a segment from {fmt(a)} to {fmt(b)}, which is not a side of {name}"
                 + (f"; {len(missing)} sides are missing." if missing else "."))


def exercise_hexagon_program(answer) -> Result:
    """Exercise 5.1: a CODO program that draws the regular hexagon with centre ``(0, 0)`` and a
    vertex at ``(1, 0)`` (Goldman §5.2.2).  answer: program text.  Checks the set of segments drawn.

    >>> exercise_hexagon_program(codo.SAMPLES["regular pentagon"].replace("72", "60").replace("5", "6"))
    Correct: your drawing is the regular hexagon: its 6 sides and nothing else.
    >>> exercise_hexagon_program(codo.SAMPLES["regular pentagon"])
    Not yet: you drew 5 different segments, 0 of them sides of the regular hexagon; the regular hexagon has 6 sides.
    """
    lines, problem = _run(answer, "a CODO program (in quotes) for the hexagon")
    if problem is not None:
        return problem
    a = np.radians(60.0 * np.arange(6))
    return _compare(segments_of(lines), _polygon_segments(np.column_stack([np.cos(a), np.sin(a)])),
                    "the regular hexagon")


_PAIRS = [((1.0, 2.0), (7.0, 5.0)), ((-3.0, 0.5), (2.0, -4.0))]


def exercise_one_third(answer) -> Result:
    """Exercise 5.2: a CODO expression in ``P`` and ``Q`` for the point one third of the way from
    ``P`` to ``Q`` (Goldman §5.2.1: affine combinations).  answer: expression text.  Evaluated for
    two different pairs ``P, Q``.

    >>> exercise_one_third("(P + Q)/3")
    Not yet: (P + Q)/3 does not run: line 1, column 8, at '/': (P + Q)/3 is neither a point nor a vector: its weights add up to 0.666667. Adding points or scaling a point is legal only in an affine combination whose weights sum to 1 (a point, e.g. (P + Q)/2 or 0.25*P + 0.75*Q) or 0 (a vector, e.g. P - Q).
    """
    if is_unanswered(answer):
        return unanswered("a CODO expression (in quotes) such as \"P + ...\"")
    if not isinstance(answer, str):
        return wrong(f"the answer should be a CODO expression in quotes; you gave {answer!r}.")
    expr = " ".join(answer.split())
    for k, (P, Q) in enumerate(_PAIRS):
        setup = f"P = point({P[0]!r}, {P[1]!r}); Q = point({Q[0]!r}, {Q[1]!r})\n"
        try:
            X = codo.execute(setup + "X = " + answer).variables["X"]
        except codo.CodoError as exc:
            # report the message for the learner's own line, numbered as they wrote it
            msg = str(exc).replace(f"line {exc.line},", "line 1,", 1).replace(
                f"column {exc.column},", f"column {exc.column - 4 if exc.line == 2 else exc.column},", 1)
            return wrong(f"{expr} does not run: {msg}.")
        if not isinstance(X, codo.Point):
            return wrong(f"{expr} is {'a vector' if isinstance(X, codo.Vector) else type(X).__name__}, not a point: "
                         f"add it to P (a point plus a vector is a point).")
        P_, Q_ = np.array(P), np.array(Q)
        want = P_ + (Q_ - P_) / 3
        got = np.array(X)
        if np.allclose(got, want, atol=1e-9):
            continue
        if np.allclose(got, P_ + 2 * (Q_ - P_) / 3, atol=1e-9):
            return wrong(f"{expr} is two thirds of the way from P to Q (one third from Q); start at P.")
        if k == 1:
            return wrong(f"{expr} gives the right point for P = {fmt(_PAIRS[0][0])}, Q = {fmt(_PAIRS[0][1])} but not "
                         f"for P = {fmt(P)}, Q = {fmt(Q)}: write it in terms of P and Q.")
        return wrong(f"for P = {fmt(P)} and Q = {fmt(Q)}, {expr} is {fmt(got)}; one third of the way is {fmt(want)}.")
    return correct(f"{expr} is the point one third of the way from P to Q, for every P and Q.")


#: The expressions of exercise 5.3 (P, Q, R points; v a vector).
TYPE_EXPRESSIONS = ("P - Q", "P + v", "P + Q", "(P + Q + R)/3", "P - 2*Q + R", "2*P - Q", "3*v - P")


def _type_of(expression: str) -> tuple[str, str]:
    """The type of an expression by the CODO interpreter and, if illegal, its reason."""
    setup = "P = point(1, 2); Q = point(-3, 4); R = point(5, -1); v = vector(2, 7)\n"
    try:
        X = codo.execute(setup + "X = " + expression).variables["X"]
    except codo.CodoTypeError as exc:
        return "illegal", str(exc).split(": ", 1)[1]
    return ("point" if isinstance(X, codo.Point) else "vector"), ""


def exercise_expression_types(answer) -> Result:
    """Exercise 5.3: for each expression of :data:`TYPE_EXPRESSIONS`, is it a ``"point"``, a
    ``"vector"``, or ``"illegal"``?  (Goldman §5.2.1.)  answer: a dict expression -> word.

    The rule: the weights of the points must sum to 1 (a point) or 0 (a vector).

    >>> exercise_expression_types({"P - Q": "vector", "P + v": "point", "P + Q": "illegal", "(P + Q + R)/3": "point",
    ...     "P - 2*Q + R": "vector", "2*P - Q": "point", "3*v - P": "illegal"})
    Correct: all 7 types are right: the weights of the points sum to 1 (point), 0 (vector) or something else (illegal).
    """
    if is_unanswered(answer):
        return unanswered("a dict giving 'point', 'vector' or 'illegal' for each expression")
    if not isinstance(answer, dict):
        return wrong(f"the answer should be a dict like {{\"P - Q\": \"vector\", ...}}; you gave {type(answer).__name__}.")
    missing = [e for e in TYPE_EXPRESSIONS if e not in answer]
    if missing:
        return wrong(f"give a type for every expression; {missing[0]!r} is missing.")
    for e in TYPE_EXPRESSIONS:
        given = str(answer[e]).strip().lower()
        if given not in ("point", "vector", "illegal"):
            return wrong(f"the type of {e!r} should be 'point', 'vector' or 'illegal'; you gave {answer[e]!r}.")
        kind, why = _type_of(e)
        if given != kind:
            if kind == "illegal":
                return wrong(f"{e} is illegal: {why.split('. Adding')[0]}.")
            weights = "1" if kind == "point" else "0"
            return wrong(f"{e} is a {kind}: the weights of its points add up to {weights}.")
    return correct(f"all {len(TYPE_EXPRESSIONS)} types are right: the weights of the points sum to 1 (point), "
                   f"0 (vector) or something else (illegal).")


def exercise_image_program(answer) -> Result:
    """Exercise 5.4: a CODO program that draws the image of the unit square
    ``(0, 0), (1, 0), (1, 1), (0, 1)`` under the affine map sending ``(0, 0), (1, 0), (0, 1)`` to
    ``(1, 0), (3, 1), (2, 2)`` (Goldman §5.2, §4.7.3).  answer: program text.

    >>> exercise_image_program('''M = affine(point(0,0), point(1,0), point(0,1), point(1,0), point(3,1), point(2,2))
    ... DRAW M(polygon(point(0,0), point(1,0), point(1,1), point(0,1)))''')
    Correct: your drawing is the image of the square: its 4 sides and nothing else.
    """
    lines, problem = _run(answer, "a CODO program (in quotes) that draws the image of the square")
    if problem is not None:
        return problem
    drawn = segments_of(lines)
    expected = _polygon_segments([[1, 0], [3, 1], [4, 3], [2, 2]])
    if drawn == _polygon_segments([[0, 0], [1, 0], [1, 1], [0, 1]]):
        return wrong("that is the square itself: apply the map to it, as M(F) for a figure F.")
    if drawn == _polygon_segments([[1, 0], [3, 1], [3, 3], [2, 2]]) or drawn == _polygon_segments(
            [[1, 0], [3, 1], [2, 2], [1, 0]]):
        return wrong("the image of (1, 1) is not a corner you can read off: it is Q1 + (Q2 - Q1) + (Q3 - Q1) = (4, 3), "
                     "since an affine map keeps the square a parallelogram.")
    return _compare(drawn, expected, "the image of the square")


def exercise_sheared_turn(answer) -> Result:
    """Exercise 5.5: the turtle draws the unit square with ``REPEAT 4 [FORWARD 1 TURN 90]``.  Its
    image under the shear ``(x, y) -> (x + y, y)`` is the parallelogram ``(0, 0), (1, 0), (2, 1),
    (1, 1)``.  By how many degrees must a turtle TURN at ``(1, 0)`` to draw it?  (Goldman §5.1.)

    >>> exercise_sheared_turn(45)
    Correct: the turtle turns by 45 degrees at (1, 0): the side (1, 0) -> (2, 1) points at 45 degrees. The program itself must change, not only the turtle's initial state: affine maps do not preserve angles.
    >>> exercise_sheared_turn(90)
    Not yet: 90 degrees is the square's turn; the shear changes the angles, which is exactly why the turtle program has to change: the side from (1, 0) to (2, 1) points at 45 degrees.
    """
    what = "the turning angle at (1, 0)"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    r = a % 360.0
    if min(abs(r - 45.0), 360.0 - abs(r - 45.0)) <= 0.01:
        return correct("the turtle turns by 45 degrees at (1, 0): the side (1, 0) -> (2, 1) points at 45 degrees. "
                       "The program itself must change, not only the turtle's initial state: affine maps do not "
                       "preserve angles.")
    if abs(r - 90.0) <= 0.01:
        return wrong("90 degrees is the square's turn; the shear changes the angles, which is exactly why the turtle "
                     "program has to change: the side from (1, 0) to (2, 1) points at 45 degrees.")
    if abs(r - 135.0) <= 0.01:
        return wrong("135 degrees is the interior angle of the parallelogram at (1, 0); the turtle turns by the "
                     "exterior angle, 180 - 135.")
    if abs(r - 315.0) <= 0.01:
        return wrong("a negative TURN turns clockwise; the parallelogram is drawn counterclockwise, like the square.")
    return wrong(f"{what} should be 45 degrees, you gave {fmt(a)}. Hint: the turtle heads along (1, 0); the next "
                 f"side goes from (1, 0) to (2, 1).")
