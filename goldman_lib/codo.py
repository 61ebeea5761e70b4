"""Affine graphics and the CODO (connect-the-dots) language (Goldman §5.1-5.2).

Turtle graphics has two shortcomings (§5.1), both measured by functions here:

1. **The turtle cannot simply connect two dots.**  It knows no coordinates, so to draw the
   segment from ``P`` to ``Q`` it must be told a distance and an angle, computed with square roots
   and arc tangents (:func:`turtle_program_through`).
2. **The turtle cannot draw the affine image of its own drawing.**  Changing its initial state
   ``(P, w)`` moves, rotates and scales the drawing uniformly (a similarity), nothing more: the
   image under a nonuniform scaling or a shear is out of reach (:func:`closest_turtle_state`
   measures how far out).

CODO fixes both: its objects are **points**, **vectors** and **affine maps**, and it draws by
connecting dots.  A CODO program is a list of statements, one a line (or separated by ``;``)::

    C = point(0, 0)              # a point
    P = C + vector(1, 0)         # point + vector = point
    R = rotate(C, 72)            # the rotation by 72 degrees about C
    REPEAT 5 [
        Q = R(P)                 # apply a map to a point (or a vector, or a figure)
        CONNECT P, Q             # draw the segment P-Q: connect the dots
        P = Q
    ]

**Statements.**  ``name = expression``; ``CONNECT P, Q, ...`` (a polyline through two or more
points); ``DRAW F`` (draw a figure); ``REPEAT n [ ... ]`` (the body ``n`` times, nested freely).

**Expressions.**  Numbers, names, ``+ - * /``, parentheses and calls.  The type rules of affine
geometry (§5.2.1, §4.3) are enforced: point + vector = point, point - point = vector,
vector +- vector = vector, number * vector = vector; a point times a number or a sum of points is
legal only inside an **affine combination** whose weights sum to 1 (a point, as in
``(P + Q)/2`` or ``0.25*P + 0.75*Q``) or to 0 (a vector, as in ``P - Q``).  ``P + Q`` alone is an
error.  Maps compose with ``*`` in the book's row-vector order: ``M * N`` applies ``M`` first,
then ``N`` (points are row vectors, ``P M N``), so ``(M * N)(P)`` is ``N(M(P))``: the call
notation reads right to left, the product left to right.  Figures (from ``polyline``, ``polygon`` or a map applied to a figure) combine with
``+``.

**Built-in functions** (case-insensitive): ``point(x, y)``, ``vector(x, y)``, ``translate(v)``,
``rotate(C, angle)``, ``scale(C, s)``, ``scale(C, w, s)`` (nonuniform, by ``s`` along ``w``),
``mirror(C, w)`` (reflection in the line through C along w), ``affine(P1, P2, P3, Q1, Q2, Q3)``
(the map of three points), ``affine(P, u, v, Q, u', v')`` (the map of a point and two vectors),
``identity()``, ``polyline(P, Q, ...)``, ``polygon(P, Q, ...)`` (closed), ``sqrt(x)``,
``sin(a)``, ``cos(a)`` (degrees), ``length(v)``, ``dist(P, Q)``.  Keywords and built-ins ignore
case; variable names do not (``P`` and ``p`` differ).  ``#`` starts a comment.

Every error is a :class:`CodoError` (a ValueError) whose message starts with the line, the
column and the token: ``line 3, column 9, at '+': ...``.

>>> [p.round(12).tolist() for p in run("A = point(0, 0)\\nB = A + vector(2, 0)\\nCONNECT A, B, (A + B)/2 + vector(0, 1), A")]
[[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [0.0, 0.0]]]

Importing this module imports numpy only.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from goldman_lib import affine, turtle
from goldman_lib.angles import cos_sin_degrees
from goldman_lib.validation import MAX_ITEMS, MAX_ITERATIONS, as_float_array, as_int, as_points, check_finite

__all__ = ["CodoError", "CodoSyntaxError", "CodoTypeError", "CodoRuntimeError", "Point", "Vector", "Figure",
           "Drawing", "parse", "execute", "run", "SAMPLES", "KEYWORDS", "BUILTINS", "MAX_STEPS", "MAX_POINTS",
           "MAX_NESTING", "MAX_WORK", "MAX_LENGTH", "MAX_STROKES",
           "turtle_program_through", "TurtleFit", "closest_turtle_state", "turtle_image_gap", "vertices"]

#: The most statements one program may execute (REPEATs counted out).
MAX_STEPS = 20_000
#: The most points a program may draw or hold in one figure.
MAX_POINTS = 200_000
#: The deepest nesting the parser accepts: of REPEAT blocks, parentheses, unary signs and calls
#: together, and of the expression tree (``1 + 1 + ... + 1`` with 51 terms is 50 deep).  Deeper
#: programs are a :class:`CodoSyntaxError` at the token that goes too deep, never a RecursionError.
MAX_NESTING = 50
#: The most work one program may do on figures (maps applied to figures, figures joined, drawn),
#: counted as the points moved plus :data:`_STROKE_WORK` per polyline (each costs a numpy call):
#: :data:`goldman_lib.validation.MAX_ITEMS`, about a second.
MAX_WORK = MAX_ITEMS
_STROKE_WORK = 500
#: The most polylines one figure may hold (each is a numpy array that every map and check visits).
MAX_STROKES = 10_000
#: The longest program text :func:`parse` reads: 20,000 characters, several hundred lines (a
#: fraction of a second of parsing; a program that draws more repeats its statements with REPEAT).
MAX_LENGTH = 20_000
#: How many characters of a token a message quotes.
_QUOTE = 60
#: The statement keywords (case-insensitive).
KEYWORDS = ("CONNECT", "DRAW", "REPEAT")
_TOL = 1e-9


# ---------------------------------------------------------------------------------------------
# Errors
# ---------------------------------------------------------------------------------------------

class CodoError(ValueError):
    """A CODO program that does not parse or cannot run.

    The message starts with ``line L, column C, at 'token':``; ``line``, ``column`` (1-based)
    and ``token`` are also attributes.
    """

    def __init__(self, message: str, line: int, column: int, token: str):
        where = "at end of program" if token == "" else f"at {_quote(token)}"
        super().__init__(f"line {line}, column {column}, {where}: {message}")
        self.line, self.column, self.token = line, column, token


def _short(text: str) -> str:
    """A token as written, at most about 60 characters of it."""
    return text if len(text) <= _QUOTE else text[:_QUOTE] + "..."


def _quote(text: str) -> str:
    """``repr`` of a token, at most about 60 characters of it."""
    if len(text) <= _QUOTE:
        return repr(text)
    return repr(text[:_QUOTE]) + f"... ({len(text):,} characters)"


class CodoSyntaxError(CodoError):
    """The text is not a CODO program: an unknown character, a missing bracket, a statement that
    does not start with a name or keyword..."""


class CodoTypeError(CodoError):
    """A rule of affine geometry is broken (``P + Q``, a vector where a point is needed, ...)."""


class CodoRuntimeError(CodoError):
    """The program parses and its types are right, but running it fails: an undefined name,
    collinear points for ``affine``, a division by zero, too many steps."""


# ---------------------------------------------------------------------------------------------
# Values a program computes
# ---------------------------------------------------------------------------------------------

class Point(NamedTuple):
    """A point of the plane (a variable's value, as :func:`execute` reports it)."""

    x: float
    y: float


class Vector(NamedTuple):
    """A vector of the plane (a variable's value, as :func:`execute` reports it)."""

    x: float
    y: float


@dataclass(frozen=True)
class Figure:
    """A figure: polylines, each a ``(k, 2)`` array.  Maps apply to all its points; ``+`` joins."""

    polylines: tuple

    def __len__(self) -> int:
        return len(self.polylines)


class _Mass:
    """A point (weight 1), a vector (weight 0), or an unfinished affine combination (other weights)."""

    __slots__ = ("x", "y", "w")

    def __init__(self, x: float, y: float, w: float):
        self.x, self.y, self.w = x, y, w


def _describe(v) -> str:
    if isinstance(v, float):
        return "a number"
    if isinstance(v, _Mass):
        if abs(v.w - 1) <= _TOL:
            return "a point"
        if abs(v.w) <= _TOL:
            return "a vector"
        return f"a sum of points with weights adding to {v.w:.6g}"
    if isinstance(v, np.ndarray):
        return "a map"
    if isinstance(v, Figure):
        return "a figure"
    return type(v).__name__


# ---------------------------------------------------------------------------------------------
# Tokens and the syntax tree
# ---------------------------------------------------------------------------------------------

class Token(NamedTuple):
    kind: str      # name, number, op, newline, end
    text: str
    offset: int


_TOKEN = re.compile(r"(?P<space>[ \t\r\f\v]+)|(?P<comment>#[^\n]*)|(?P<newline>[\n;])"
                    r"|(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z_][A-Za-z_0-9]*)"
                    r"|(?P<op>[-+*/=(),\[\]])")


def _position(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _tokens(text: str) -> list[Token]:
    """The tokens of a program; newlines inside parentheses are dropped (a call may span lines)."""
    toks: list[Token] = []
    depth = 0
    pos, n = 0, len(text)
    while pos < n:
        m = _TOKEN.match(text, pos)
        if m is None:
            line, col = _position(text, pos)
            ch = text[pos]
            raise CodoSyntaxError(f"unexpected character {ch!r}; CODO uses names, numbers, + - * / = ( ) , [ ] "
                                  f"and # comments", line, col, ch)
        kind = m.lastgroup
        tok = m.group()
        if kind == "op":
            depth += tok == "("
            depth = max(0, depth - (tok == ")"))
        if kind in ("name", "number", "op") or (kind == "newline" and depth == 0):
            toks.append(Token(kind, tok, m.start()))
        pos = m.end()
    toks.append(Token("end", "", n))
    return toks


# expression nodes: (kind, token, start, end, payload...)
class Node(NamedTuple):
    kind: str          # num, name, call, apply, binop, neg
    tok: Token
    start: int
    end: int
    args: tuple = ()
    value: float = 0.0
    depth: int = 1


class Statement(NamedTuple):
    kind: str          # assign, connect, draw, repeat
    tok: Token
    target: str = ""
    args: tuple = ()
    body: tuple = ()


@dataclass(frozen=True)
class Program:
    """A parsed CODO program: its statements and its source ``text`` (for messages)."""

    statements: tuple
    text: str = ""


BUILTINS = ("point", "vector", "translate", "rotate", "scale", "mirror", "affine", "identity", "polyline",
            "polygon", "sqrt", "sin", "cos", "length", "dist")


class _Parser:
    def __init__(self, text: str):
        self.text = text
        self.toks = _tokens(text)
        self.i = 0
        self.nesting = 0

    def enter(self, tok: Token | None = None):
        """One level deeper (a REPEAT block, a parenthesis, a sign, a call): at most MAX_NESTING."""
        self.nesting += 1
        if self.nesting > MAX_NESTING:
            self.fail(f"the program is nested more than {MAX_NESTING} deep (REPEAT blocks, parentheses, signs and "
                      f"calls inside one another); split it into several statements", tok)

    def node(self, kind: str, tok: Token, start: int, end: int, args: tuple, **kw) -> Node:
        """An expression node whose tree is at most MAX_NESTING deep (evaluation recurses along it)."""
        depth = 1 + max((a.depth for a in args), default=0)
        if depth > MAX_NESTING:
            self.fail(f"this expression is nested more than {MAX_NESTING} deep (operations inside one another); "
                      f"split it into several assignments", tok)
        return Node(kind, tok, start, end, args, depth=depth, **kw)

    # -- helpers -------------------------------------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.i]

    def fail(self, message: str, tok: Token | None = None, cls=CodoSyntaxError):
        tok = tok or self.tok
        line, col = _position(self.text, tok.offset)
        raise cls(message, line, col, "" if tok.kind == "end" else ("end of line" if tok.text == "\n" else tok.text))

    @staticmethod
    def found(tok: Token) -> str:
        if tok.kind == "end":
            return "end of program"
        if tok.kind == "newline":
            return "end of line" if tok.text == "\n" else "';'"
        if tok.kind == "number":
            return f"the number {tok.text}"
        return _quote(tok.text)

    def expect(self, text: str, what: str) -> Token:
        tok = self.tok
        if tok.text != text or tok.kind not in ("op",):
            self.fail(f"expected {what}, found {self.found(tok)}")
        self.i += 1
        return tok

    def skip_separators(self):
        while self.tok.kind == "newline":
            self.i += 1

    # -- statements ----------------------------------------------------------------------------
    def program(self) -> Program:
        body = self.block(top=True)
        return Program(body, self.text)

    def block(self, top: bool, opener: Token | None = None) -> tuple:
        out = []
        while True:
            self.skip_separators()
            tok = self.tok
            if tok.kind == "end":
                if not top:
                    line, col = _position(self.text, opener.offset)
                    self.fail(f"expected ']' to close the REPEAT at line {line}, column {col}, found end of program")
                return tuple(out)
            if tok.kind == "op" and tok.text == "]":
                if top:
                    self.fail("found ']' with no REPEAT [ to close")
                return tuple(out)
            out.append(self.statement())
            nxt = self.tok
            if nxt.kind not in ("newline", "end") and not (nxt.kind == "op" and nxt.text == "]"):
                self.fail(f"expected the end of the statement (a new line or ';'), found {self.found(nxt)}")

    def statement(self) -> Statement:
        tok = self.tok
        if tok.kind != "name":
            self.fail(f"expected a statement (name = ..., CONNECT, DRAW or REPEAT), found {self.found(tok)}")
        word = tok.text.upper()
        if word == "CONNECT":
            self.i += 1
            args = [self.expr()]
            while self.tok.kind == "op" and self.tok.text == ",":
                self.i += 1
                args.append(self.expr())
            if len(args) < 2:
                self.fail("CONNECT needs at least two points separated by commas, found only one", tok,
                          cls=CodoSyntaxError)
            return Statement("connect", tok, args=tuple(args))
        if word == "DRAW":
            self.i += 1
            return Statement("draw", tok, args=(self.expr(),))
        if word == "REPEAT":
            self.i += 1
            count = self.expr()
            opener = self.tok
            if not (opener.kind == "op" and opener.text == "["):
                self.fail(f"expected '[' after REPEAT {self.text[count.start:count.end]}, found {self.found(opener)}")
            self.i += 1
            self.enter(tok)
            body = self.block(top=False, opener=tok)
            self.nesting -= 1
            self.i += 1   # the ']'
            return Statement("repeat", tok, args=(count,), body=body)
        nxt = self.toks[self.i + 1]
        if not (nxt.kind == "op" and nxt.text == "="):
            close = difflib.get_close_matches(word, KEYWORDS, n=1, cutoff=0.6) if len(word) <= 20 else []
            hint = f" (did you mean {close[0]}?)" if close else ""
            self.fail(f"expected '=' after the name {tok.text} (or a statement: CONNECT, DRAW, REPEAT), "
                      f"found {self.found(nxt)}{hint}", nxt if not close else tok)
        if tok.text.lower() in BUILTINS:
            self.fail(f"cannot assign to {_quote(tok.text)}: it is a built-in function; choose another name", tok)
        self.i += 2
        return Statement("assign", tok, target=tok.text, args=(self.expr(),))

    # -- expressions ---------------------------------------------------------------------------
    def expr(self) -> Node:
        left = self.term()
        while self.tok.kind == "op" and self.tok.text in "+-":
            op = self.tok
            self.i += 1
            right = self.term()
            left = self.node("binop", op, left.start, right.end, (left, right))
        return left

    def term(self) -> Node:
        left = self.unary()
        while self.tok.kind == "op" and self.tok.text in "*/":
            op = self.tok
            self.i += 1
            right = self.unary()
            left = self.node("binop", op, left.start, right.end, (left, right))
        return left

    def unary(self) -> Node:
        tok = self.tok
        if tok.kind == "op" and tok.text in "+-":
            self.i += 1
            self.enter(tok)
            operand = self.unary()
            self.nesting -= 1
            if tok.text == "+":
                return operand._replace(start=tok.offset)
            return self.node("neg", tok, tok.offset, operand.end, (operand,))
        return self.postfix()

    def postfix(self) -> Node:
        node = self.primary()
        while self.tok.kind == "op" and self.tok.text == "(":
            open_tok = self.tok
            args, end = self.arguments()
            node = self.node("apply", open_tok, node.start, end, (node, *args))
        return node

    def arguments(self) -> tuple[list, int]:
        open_tok = self.expect("(", "'('")
        self.enter(open_tok)
        try:
            return self._arguments(open_tok)
        finally:
            self.nesting -= 1

    def _arguments(self, open_tok: Token) -> tuple[list, int]:
        args = []
        if self.tok.kind == "op" and self.tok.text == ")":
            self.i += 1
            return args, self.toks[self.i - 1].offset + 1
        while True:
            args.append(self.expr())
            tok = self.tok
            if tok.kind == "op" and tok.text == ",":
                self.i += 1
                continue
            if tok.kind == "op" and tok.text == ")":
                self.i += 1
                return args, tok.offset + 1
            if tok.kind == "end":
                line, col = _position(self.text, open_tok.offset)
                self.fail(f"expected ')' to close the '(' at line {line}, column {col}, found end of program")
            hint = ""
            if self.text.count("\n", open_tok.offset, tok.offset):
                line, col = _position(self.text, open_tok.offset)
                hint = f" (is the '(' at line {line}, column {col} closed?)"
            self.fail(f"expected ',' or ')' in the argument list, found {self.found(tok)}{hint}")

    def primary(self) -> Node:
        tok = self.tok
        if tok.kind == "number":
            self.i += 1
            value = float(tok.text)
            if not math.isfinite(value):
                self.fail(f"the number {tok.text} is too large", tok)
            return Node("num", tok, tok.offset, tok.offset + len(tok.text), value=value)
        if tok.kind == "name":
            word = tok.text.upper()
            if word in KEYWORDS:
                self.fail(f"{word} is a statement and cannot appear inside an expression", tok)
            self.i += 1
            if tok.text.lower() in BUILTINS:
                if not (self.tok.kind == "op" and self.tok.text == "("):
                    self.fail(f"expected '(' after the function {tok.text}, found {self.found(self.tok)}")
                args, end = self.arguments()
                return self.node("call", tok, tok.offset, end, tuple(args))
            return Node("name", tok, tok.offset, tok.offset + len(tok.text))
        if tok.kind == "op" and tok.text == "(":
            self.i += 1
            self.enter(tok)
            inner = self.expr()
            self.nesting -= 1
            close = self.tok
            if not (close.kind == "op" and close.text == ")"):
                if close.kind == "op" and close.text == ",":
                    self.fail("found ',' inside parentheses: write a point as point(x, y), a vector as vector(x, y)")
                self.fail(f"expected ')' to close the '(' at column {_position(self.text, tok.offset)[1]}, "
                          f"found {self.found(close)}")
            self.i += 1
            return inner._replace(start=tok.offset, end=close.offset + 1)
        self.fail(f"expected a number, a name or '(' to start an expression, found {self.found(tok)}")


def parse(program: str) -> Program:
    """Parse a CODO program into its statements (Goldman §5.2.1).

    program: the program text (see the module docstring for the language).  Returns a
    :class:`Program`.  Raises TypeError if ``program`` is not a string, ValueError if it is longer
    than :data:`MAX_LENGTH` characters, and :class:`CodoSyntaxError` naming the line, column and
    token where parsing failed.

    >>> len(parse("P = point(0, 0)\\nREPEAT 3 [ P = P + vector(1, 0) ]").statements)
    2
    >>> parse("P = point(0, 0\\nCONNECT P, P")
    Traceback (most recent call last):
    ...
    goldman_lib.codo.CodoSyntaxError: line 2, column 1, at 'CONNECT': expected ',' or ')' in the argument list, found 'CONNECT' (is the '(' at line 1, column 10 closed?)
    """
    if not isinstance(program, str):
        raise TypeError(f"program must be a string of CODO statements; got {type(program).__name__}")
    if len(program) > MAX_LENGTH:
        raise ValueError(f"program must be at most {MAX_LENGTH:,} characters long (a fraction of a second of "
                         f"parsing); got {len(program):,} characters: use REPEAT instead of writing statements out")
    return _Parser(program).program()


# ---------------------------------------------------------------------------------------------
# Running a program
# ---------------------------------------------------------------------------------------------

@dataclass
class Drawing:
    """What running a CODO program produced (see :func:`execute`).

    polylines: list of ``(k, 2)`` arrays, in drawing order.  variables: the final value of each
    variable (:class:`Point`, :class:`Vector`, a float, a 3x3 map, a :class:`Figure`).  steps: how
    many statements ran.
    """

    polylines: list = field(default_factory=list)
    variables: dict = field(default_factory=dict)
    steps: int = 0


class _Interpreter:
    def __init__(self, program: Program, max_steps: int):
        self.text = program.text
        self.program = program
        self.env: dict = {}
        self.lines: list = []
        self.points = 0
        self.steps = 0
        self.max_steps = max_steps
        self.repeats: list[Token] = []
        self.rounds = 0      # rounds of REPEATs with an empty body: steps too, though no statement runs
        self.work = 0        # figure points moved (maps applied to figures, figures joined, drawn)

    def count_step(self, tok: Token, rounds: int = 0):
        """One more statement (or ``rounds`` more rounds of an empty loop) against ``max_steps``."""
        if rounds:
            self.rounds += rounds
        else:
            self.steps += 1
        if self.steps + self.rounds > self.max_steps:
            if self.repeats:
                where = self.repeats[0]
                line, col = _position(self.text, where.offset)
                self.fail(f"this program runs more than {self.max_steps:,} statements (the REPEAT at line {line}, "
                          f"column {col} is the outermost loop; a round of an empty loop counts as a statement); "
                          f"use fewer repetitions so the drawing stays quick", where)
            self.fail(f"this program runs more than {self.max_steps:,} statements (the limit max_steps); "
                      f"write a shorter program", tok)

    def touch(self, polylines, tok: Token):
        """Count the work of moving these polylines (points + _STROKE_WORK each) against MAX_WORK."""
        self.work += sum(len(p) for p in polylines) + _STROKE_WORK * len(polylines)
        if self.work > MAX_WORK:
            self.fail(f"this program does more than {MAX_WORK:,} units of work on figures (a point moved is "
                      f"one, a polyline {_STROKE_WORK}: maps applied to figures, figures joined or drawn); use smaller "
                      f"figures or fewer repetitions", tok)

    def fail(self, message: str, tok: Token, cls=CodoRuntimeError):
        line, col = _position(self.text, tok.offset)
        raise cls(message, line, col, tok.text)

    def snippet(self, node: Node) -> str:
        s = " ".join(self.text[node.start:node.end].split())
        return s if len(s) <= 40 else s[:37] + "..."

    # -- statements ----------------------------------------------------------------------------
    def run(self, statements):
        for st in statements:
            self.count_step(st.tok)
            kind = st.kind
            if kind == "assign":
                self.env[st.target] = self.settle(self.eval(st.args[0]), st.args[0])
            elif kind == "connect":
                pts = [self.want_point(a, "CONNECT") for a in st.args]
                self.add([np.array(pts)], st.tok)
            elif kind == "draw":
                v = self.settle(self.eval(st.args[0]), st.args[0])
                if not isinstance(v, Figure):
                    self.fail(f"DRAW needs a figure (from polyline, polygon or a map applied to a figure); "
                              f"{self.snippet(st.args[0])} is {_describe(v)}", st.args[0].tok, CodoTypeError)
                self.add(list(v.polylines), st.tok)
            else:
                n = self.want_number(st.args[0], "the REPEAT count")
                if not (n >= 0 and n == int(n)):
                    self.fail(f"the REPEAT count must be a whole number >= 0; got {n:g}",
                              st.args[0].tok, CodoTypeError)
                if n > self.max_steps:
                    self.fail(f"REPEAT {n:g} is more than the limit of {self.max_steps:,} statements", st.tok)
                self.repeats.append(st.tok)
                if not st.body:
                    self.count_step(st.tok, rounds=int(n))
                else:
                    for _ in range(int(n)):
                        self.run(st.body)
                self.repeats.pop()

    def add(self, polylines, tok):
        self.touch(polylines, tok)
        for p in polylines:
            self.points += len(p)
        if self.points > MAX_POINTS:
            self.fail(f"this program draws more than {MAX_POINTS:,} points; draw less", tok)
        self.lines.extend(polylines)

    # -- values --------------------------------------------------------------------------------
    def settle(self, v, node: Node):
        """A value at a boundary (assignment, argument): a sum of points must have weights 1 or 0."""
        if isinstance(v, _Mass):
            if abs(v.w - 1) <= _TOL:
                v.w = 1.0
            elif abs(v.w) <= _TOL:
                v.w = 0.0
            else:
                example = "(P + Q)/2 or 0.25*P + 0.75*Q"
                self.fail(f"{self.snippet(node)} is neither a point nor a vector: its weights add up to {v.w:.6g}. "
                          f"Adding points or scaling a point is legal only in an affine combination whose "
                          f"weights sum to 1 (a point, e.g. {example}) or 0 (a vector, e.g. P - Q)",
                          node.tok, CodoTypeError)
            if not (math.isfinite(v.x) and math.isfinite(v.y)):
                self.fail(f"{self.snippet(node)} overflows (its coordinates are not finite)", node.tok)
        elif isinstance(v, np.ndarray) and not np.all(np.isfinite(v)):
            self.fail(f"{self.snippet(node)} overflows (the map has non-finite entries)", node.tok)
        elif isinstance(v, Figure) and not all(np.isfinite(p).all() for p in v.polylines):
            self.fail(f"{self.snippet(node)} overflows (the figure has non-finite points)", node.tok)
        return v

    def want(self, node: Node, kinds: tuple, what: str):
        v = self.settle(self.eval(node), node)
        if _describe(v) not in kinds:
            self.fail(f"{what} must be {' or '.join(kinds)}; {self.snippet(node)} is {_describe(v)}", node.tok,
                      CodoTypeError)
        return v

    def want_point(self, node, where):
        v = self.want(node, ("a point",), f"each argument of {where}")
        return (v.x, v.y)

    def want_number(self, node, what):
        return self.want(node, ("a number",), what)

    def eval(self, node: Node):
        kind = node.kind
        if kind == "num":
            return node.value
        if kind == "name":
            try:
                v = self.env[node.tok.text]
            except KeyError:
                names = list(self.env)
                word = node.tok.text
                close = difflib.get_close_matches(word, names, n=1, cutoff=0.6) if len(word) <= 40 else []
                if not close:
                    close = [k for k in names if k.lower() == word.lower()]
                hint = f" (did you mean {_short(close[0])}?)" if close else ""
                self.fail(f"the name {_short(word)} has no value yet; give it one first "
                          f"({_short(word)} = ...){hint}", node.tok)
            return _Mass(v.x, v.y, v.w) if isinstance(v, _Mass) else v
        if kind == "binop":
            return self.binop(node)
        if kind == "neg":
            v = self.eval(node.args[0])
            if isinstance(v, float):
                return -v
            if isinstance(v, _Mass):
                return _Mass(-v.x, -v.y, -v.w)
            self.fail(f"cannot negate {_describe(v)}", node.tok, CodoTypeError)
        if kind == "call":
            return self.call(node)
        return self.apply(node)

    def binop(self, node: Node):
        op = node.tok.text
        a = self.eval(node.args[0])
        b = self.eval(node.args[1])
        fa, fb = isinstance(a, float), isinstance(b, float)
        ma, mb = isinstance(a, _Mass), isinstance(b, _Mass)
        if fa and fb:
            if op == "+":
                r = a + b
            elif op == "-":
                r = a - b
            elif op == "*":
                r = a * b
            else:
                if b == 0:
                    self.fail(f"division by zero in {self.snippet(node)}", node.tok)
                r = a / b
            if not math.isfinite(r):
                self.fail(f"{self.snippet(node)} overflows", node.tok)
            return r
        if op in "+-" and ma and mb:
            s = 1.0 if op == "+" else -1.0
            return _Mass(a.x + s * b.x, a.y + s * b.y, a.w + s * b.w)
        if op == "*" and (fa and mb or ma and fb):
            k, m = (a, b) if fa else (b, a)
            return _Mass(k * m.x, k * m.y, k * m.w)
        if op == "/" and ma and fb:
            if b == 0:
                self.fail(f"division by zero in {self.snippet(node)}", node.tok)
            return _Mass(a.x / b, a.y / b, a.w / b)
        if op == "*" and isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
            with np.errstate(over="ignore", invalid="ignore"):   # overflow is reported by settle
                return a @ b
        if op == "+" and isinstance(a, Figure) and isinstance(b, Figure):
            if len(a.polylines) + len(b.polylines) > MAX_STROKES:
                self.fail(f"the figure {self.snippet(node)} would hold more than {MAX_STROKES:,} polylines", node.tok)
            if sum(len(p) for p in a.polylines + b.polylines) > MAX_POINTS:
                self.fail(f"the figure {self.snippet(node)} would hold more than {MAX_POINTS:,} points", node.tok)
            self.touch(a.polylines + b.polylines, node.tok)
            return Figure(a.polylines + b.polylines)
        da, db = _describe(a), _describe(b)
        verb = {"+": "add", "-": "subtract", "*": "multiply", "/": "divide"}[op]
        hint = ""
        if op == "*" and "a map" in (da, db) and da != db:
            hint = "; to apply a map M to X write M(X)"
        elif op in "*/" and ma and mb:
            hint = "; points and vectors are multiplied only by numbers"
        elif op in "+-" and (fa or fb):
            hint = "; numbers and points or vectors do not add"
        self.fail(f"cannot {verb} {da} and {db} in {self.snippet(node)}{hint}", node.tok, CodoTypeError)

    # -- functions and maps --------------------------------------------------------------------
    def call(self, node: Node):
        name = node.tok.text.lower()
        args = node.args
        n = len(args)

        def arity(*allowed, signature):
            if n not in allowed:
                self.fail(f"{name} takes {signature}; got {n} argument{'s' * (n != 1)}", node.tok, CodoTypeError)

        if name in ("point", "vector"):
            arity(2, signature=f"two numbers: {name}(x, y)")
            x = self.want_number(args[0], f"the x coordinate of {name}")
            y = self.want_number(args[1], f"the y coordinate of {name}")
            return _Mass(x, y, 1.0 if name == "point" else 0.0)
        if name in ("sqrt", "sin", "cos"):
            arity(1, signature=f"one number: {name}(x)")
            x = self.want_number(args[0], f"the argument of {name}")
            if name == "sqrt":
                if x < 0:
                    self.fail(f"sqrt of a negative number ({x:g})", args[0].tok)
                return math.sqrt(x)
            c, s = cos_sin_degrees(x)
            return c if name == "cos" else s
        if name == "length":
            arity(1, signature="one vector: length(v)")
            v = self.want(args[0], ("a vector",), "the argument of length")
            return math.hypot(v.x, v.y)
        if name == "dist":
            arity(2, signature="two points: dist(P, Q)")
            (px, py), (qx, qy) = (self.want_point(a, "dist") for a in args)
            return math.hypot(qx - px, qy - py)
        if name == "identity":
            arity(0, signature="no arguments: identity()")
            return affine.identity()
        if name in ("polyline", "polygon"):
            if n < 2:
                self.fail(f"{name} takes two or more points; got {n}", node.tok, CodoTypeError)
            pts = [self.want_point(a, name) for a in args]
            if name == "polygon":
                pts.append(pts[0])
            return Figure((np.array(pts, dtype=float),))
        if name == "translate":
            arity(1, signature="one vector: translate(v)")
            v = self.want(args[0], ("a vector",), "the argument of translate")
            return affine.translation([v.x, v.y])
        if name == "rotate":
            arity(2, signature="a point and an angle in degrees: rotate(C, angle)")
            c = self.want_point(args[0], "rotate (the centre)")
            a = self.want_number(args[1], "the angle of rotate")
            return affine.rotation(a, center=c)
        if name == "scale":
            arity(2, 3, signature="a centre and a factor, scale(C, s), or a centre, a direction and a factor, "
                                  "scale(C, w, s)")
            c = self.want_point(args[0], "scale (the centre)")
            if n == 2:
                return affine.scaling(self.want_number(args[1], "the factor of scale"), center=c)
            w = self.want(args[1], ("a vector",), "the direction of scale(C, w, s)")
            s = self.want_number(args[2], "the factor of scale")
            if w.x == 0 and w.y == 0:
                self.fail("the direction of scale(C, w, s) must be a nonzero vector", args[1].tok)
            return affine.directional_scaling(s, [w.x, w.y], center=c)
        if name == "mirror":
            arity(2, signature="a point and a direction: mirror(C, w)")
            c = self.want_point(args[0], "mirror (a point of the line)")
            w = self.want(args[1], ("a vector",), "the direction of mirror(C, w)")
            if w.x == 0 and w.y == 0:
                self.fail("the direction of mirror(C, w) must be a nonzero vector", args[1].tok)
            return affine.mirror(c, [w.x, w.y])
        # affine
        arity(6, signature="three points and their images, affine(P1, P2, P3, Q1, Q2, Q3), or a point, two "
                           "vectors and their images, affine(P, u, v, Q, u2, v2)")
        vals = [self.settle(self.eval(a), a) for a in args]
        kinds = [_describe(v) for v in vals]
        if kinds == ["a point"] * 6:
            src = [(v.x, v.y) for v in vals[:3]]
            dst = [(v.x, v.y) for v in vals[3:]]
            try:
                return affine.affine_from_points(src, dst)
            except ValueError:
                self.fail(f"the three points {', '.join(self.snippet(a) for a in args[:3])} are collinear: "
                          f"no affine map is fixed by them (choose a triangle)", node.tok)
        want = ["a point", "a vector", "a vector"] * 2
        if kinds == want:
            try:
                return affine.affine_from_point_and_vectors(
                    (vals[0].x, vals[0].y), [(v.x, v.y) for v in vals[1:3]],
                    (vals[3].x, vals[3].y), [(v.x, v.y) for v in vals[4:6]])
            except ValueError:
                self.fail(f"the vectors {self.snippet(args[1])} and {self.snippet(args[2])} are parallel: "
                          f"no affine map is fixed by them", node.tok)
        k = next(i for i, (a, b) in enumerate(zip(kinds, want if kinds[1] == "a vector" else ["a point"] * 6))
                 if a != b)
        expected = (want if kinds[1] == "a vector" else ["a point"] * 6)[k]
        self.fail(f"argument {k + 1} of affine must be {expected.split()[1]} here; {self.snippet(args[k])} is {kinds[k]}",
                  args[k].tok, CodoTypeError)

    def apply(self, node: Node):
        target, *args = node.args
        if target.kind == "name" and target.tok.text not in self.env:
            close = (difflib.get_close_matches(target.tok.text.lower(), BUILTINS, n=1, cutoff=0.6)
                     if len(target.tok.text) <= 40 else [])
            if close:
                self.fail(f"there is no function {_short(target.tok.text)} (did you mean {close[0]}?)", target.tok)
        M = self.settle(self.eval(target), target)
        if not isinstance(M, np.ndarray):
            self.fail(f"{self.snippet(target)} is {_describe(M)}, not a map: only maps can be applied, as in "
                      f"R(P)", node.tok, CodoTypeError)
        if len(args) != 1:
            self.fail(f"a map is applied to one point, vector or figure; got {len(args)} arguments", node.tok,
                      CodoTypeError)
        x = self.settle(self.eval(args[0]), args[0])
        if isinstance(x, _Mass):
            (a, b, _), (c, d, _), (e, f, _) = M.tolist()
            return _Mass(x.x * a + x.y * c + x.w * e, x.x * b + x.y * d + x.w * f, x.w)
        if isinstance(x, Figure):
            self.touch(x.polylines, node.tok)
            with np.errstate(over="ignore", invalid="ignore"):   # overflow is reported by settle
                return Figure(tuple(p @ M[:2, :2] + M[2, :2] for p in x.polylines))
        self.fail(f"a map applies to a point, a vector or a figure; {self.snippet(args[0])} is {_describe(x)}",
                  args[0].tok, CodoTypeError)


def _public(v):
    if isinstance(v, _Mass):
        return Point(v.x, v.y) if v.w == 1.0 else Vector(v.x, v.y)
    return v


def execute(program, *, max_steps: int = MAX_STEPS) -> Drawing:
    """Run a CODO program; return its drawing and its variables (Goldman §5.2).

    program: program text or a parsed :class:`Program`.  max_steps: the most statements it may
    execute (each round of a REPEAT with an empty body counts as one), an int from 0 to
    :data:`goldman_lib.validation.MAX_ITERATIONS` (1,000,000: about a minute of interpreting).
    A program may also do at most :data:`MAX_WORK` work on figures and nest at most
    :data:`MAX_NESTING` deep.  Returns a :class:`Drawing`.  Raises TypeError for a program that is not a string,
    :class:`CodoSyntaxError`, :class:`CodoTypeError` or :class:`CodoRuntimeError` (all
    ValueErrors) naming the line, column and token.

    >>> d = execute("P = point(1, 2)\\nv = P - point(0, 0)\\nM = scale(P, 2)")
    >>> d.variables["P"], d.variables["v"]
    (Point(x=1.0, y=2.0), Vector(x=1.0, y=2.0))
    >>> execute("P = point(1, 2)\\nQ = P + P")
    Traceback (most recent call last):
    ...
    goldman_lib.codo.CodoTypeError: line 2, column 7, at '+': P + P is neither a point nor a vector: its weights add up to 2. Adding points or scaling a point is legal only in an affine combination whose weights sum to 1 (a point, e.g. (P + Q)/2 or 0.25*P + 0.75*Q) or 0 (a vector, e.g. P - Q)
    """
    prog = program if isinstance(program, Program) else parse(program)
    if not isinstance(program, (str, Program)):
        raise TypeError(f"program must be a string of CODO statements or a parsed Program; got {type(program).__name__}")
    max_steps = as_int(max_steps, "max_steps", minimum=0, maximum=MAX_ITERATIONS)
    interp = _Interpreter(prog, max_steps)
    interp.run(prog.statements)
    return Drawing(interp.lines, {k: _public(v) for k, v in interp.env.items()}, interp.steps)


def run(program) -> list[np.ndarray]:
    """Run a CODO program; return its polylines, one ``(k, 2)`` array per CONNECT or figure line
    drawn (Goldman §5.2).  Raises as :func:`execute`.

    >>> run("C = point(0, 0); P = point(1, 0); R = rotate(C, 90)\\nREPEAT 4 [ CONNECT P, R(P); P = R(P) ]")[1]
    array([[ 0.,  1.],
           [-1.,  0.]])
    """
    return execute(program).polylines


def vertices(polylines) -> np.ndarray:
    """All the points of a drawing in one ``(n, 2)`` array (the dots, in drawing order).

    >>> vertices([np.zeros((2, 2)), np.ones((1, 2))]).shape
    (3, 2)
    """
    if isinstance(polylines, np.ndarray) and polylines.ndim >= 1:
        polylines = list(polylines)
    if not isinstance(polylines, (list, tuple)):
        raise TypeError(f"polylines must be a list of (k, 2) arrays of points; got {type(polylines).__name__}")
    if not polylines:
        return np.zeros((0, 2))
    out = []
    for i, p in enumerate(polylines):
        name = f"polylines[{i}]"
        arr = check_finite(as_float_array(p, name), name)
        if arr.size % 2:
            raise ValueError(f"{name} must hold 2D points (x, y); got shape {arr.shape}")
        out.append(arr.reshape(-1, 2))
    return np.concatenate(out)


# ---------------------------------------------------------------------------------------------
# The sample programs of §5.2.2
# ---------------------------------------------------------------------------------------------

#: Sample CODO programs (Goldman §5.2.2): name -> program text.
SAMPLES = {
    "regular pentagon": """# a regular pentagon: rotate a vertex about the centre, connect the dots
C = point(0, 0)
P = point(1, 0)
R = rotate(C, 72)
REPEAT 5 [
  Q = R(P)
  CONNECT P, Q
  P = Q
]
""",
    "five-pointed star": """# the star {5/2}: the same loop, rotating by 144 degrees
C = point(0, 0)
P = point(0, 1)
R = rotate(C, 144)
REPEAT 5 [
  CONNECT P, R(P)
  P = R(P)
]
""",
    "nested squares": """# connect the midpoints of a square's sides, again and again
A = point(0, 0); B = point(1, 0); C = point(1, 1); D = point(0, 1)
REPEAT 5 [
  CONNECT A, B, C, D, A
  A1 = (A + B)/2; B1 = (B + C)/2; C1 = (C + D)/2; D1 = (D + A)/2
  A = A1; B = B1; C = C1; D = D1
]
""",
    "spiral": """# rotate and shrink about a centre: a polygonal spiral
C = point(0, 0)
P = point(1, 0)
M = rotate(C, 20) * scale(C, 0.95)
REPEAT 60 [
  CONNECT P, M(P)
  P = M(P)
]
""",
    "rosette of squares": """# a figure and its images under repeated rotation
C = point(0, 0)
F = polygon(C, point(1, 0), point(1, 1), point(0, 1))
R = rotate(C, 30)
REPEAT 12 [
  DRAW F
  F = R(F)
]
""",
    "affine image of a house": """# a house, its image under the map of three points, and its shear
house = polygon(point(0, 0), point(1, 0), point(1, 1), point(0.5, 1.5), point(0, 1))
DRAW house
M = affine(point(0, 0), point(1, 0), point(0, 1), point(2, 0), point(3.5, 0.5), point(2.5, 1))
DRAW M(house)
DRAW affine(point(0, 0), vector(1, 0), vector(0, 1), point(4.5, 0), vector(1, 0), vector(0.6, 1))(house)
""",
}


# ---------------------------------------------------------------------------------------------
# §5.1: the two shortcomings of turtle graphics, measured
# ---------------------------------------------------------------------------------------------

def turtle_program_through(points) -> str:
    """The turtle program that draws the polyline through ``points`` (Goldman §5.1, shortcoming 1).

    The turtle starts at ``points[0]`` heading ``(1, 0)``; to reach each next dot it must TURN by
    the angle between its heading and the next segment (an arc tangent) and go FORWARD by the
    segment's length (a square root).  CODO just says ``CONNECT P0, P1, ...``.  points: (k, 2),
    k >= 2, consecutive points distinct.  Raises ValueError for repeated consecutive points.

    >>> turtle_program_through([[0, 0], [3, 4]])
    'TURN 53.13010235415598 FORWARD 5'
    """
    P = as_points(points, "points", dim=2, min_count=2)
    seg = np.diff(P, axis=0)
    lens = np.hypot(seg[:, 0], seg[:, 1])
    if np.any(lens == 0):
        k = int(np.flatnonzero(lens == 0)[0])
        raise ValueError(f"points must not repeat consecutively; points[{k}] == points[{k + 1}]")
    headings = np.degrees(np.arctan2(seg[:, 1], seg[:, 0]))
    turns = np.diff(np.concatenate([[0.0], headings]))
    turns = (turns + 180.0) % 360.0 - 180.0
    out = []
    for a, d in zip(turns, lens):
        if a != 0:
            out.append(f"TURN {turtle.format_number(a)}")
        out.append(f"FORWARD {turtle.format_number(d)}")
    return " ".join(out)


class TurtleFit(NamedTuple):
    """The initial turtle state whose drawing comes closest to a target (see
    :func:`closest_turtle_state`): ``point`` and ``direction`` ``(2,)``, the state that minimises the
    largest distance; ``residual`` that smallest largest distance between a drawn vertex and its
    target (each distinct vertex counted once); ``rms`` the smallest root-mean-square distance any
    state achieves (the least-squares state, in general a different one)."""

    point: np.ndarray
    direction: np.ndarray
    residual: float
    rms: float


def _distinct_pairs(z: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop repeated (drawn vertex, target) pairs, so a closed polygon's closing vertex, which the
    turtle draws twice, counts once (up to round-off: 9 significant digits of the figure's size)."""
    scale = max(float(np.abs(z).max()), float(np.abs(y).max()), 1e-300)
    keys = np.round(np.column_stack([z.real, z.imag, y.real, y.imag]) / scale, 9) + 0.0
    _, first = np.unique(keys, axis=0, return_index=True)
    first = np.sort(first)
    return z[first], y[first]


def _minimax_similarity(z: np.ndarray, y: np.ndarray, *, rel_gap: float = 1e-9, max_sweeps: int = 20000):
    """``min over w, p of max_i |w z_i + p - y_i|`` (complex), by Lawson's algorithm: weighted least
    squares whose weights grow where the error is largest.  Each sweep gives an upper bound (the
    largest error of the current state) and a lower bound (the weighted least-squares error: for
    weights summing to 1 it is at most the largest error of *any* state); stop when they agree to
    ``rel_gap``.  Returns ``(w, p, upper, lower)``."""
    A = np.column_stack([z, np.ones_like(z)])
    n = len(z)
    weights = np.full(n, 1.0 / n)
    best = None
    lower = 0.0
    for _ in range(max_sweeps):
        r = np.sqrt(weights)
        x, *_ = np.linalg.lstsq(A * r[:, None], y * r, rcond=None)
        err = np.abs(A @ x - y)
        lower = max(lower, float(np.sqrt(np.sum(weights * err ** 2))))
        if best is None or err.max() < best[2]:
            best = (x[0], x[1], float(err.max()))
        if best[2] - lower <= rel_gap * max(best[2], 1e-300) or best[2] <= 1e-14 * max(1.0, np.abs(y).max()):
            break
        weights = weights * err
        total = weights.sum()
        if total == 0:
            break
        weights = weights / total
    return best[0], best[1], best[2], lower


def closest_turtle_state(program, target) -> TurtleFit:
    """The initial state ``(P, w)`` from which a turtle program draws closest to ``target``
    (Goldman §5.1, shortcoming 2): the state whose largest vertex distance is smallest.

    Started at ``P`` heading ``w`` instead of ``(0, 0)``, ``(1, 0)``, the turtle draws the image
    of its standard drawing under ``z -> w z + P`` (complex numbers): a rotation, a uniform
    scaling and a translation.  So the best state solves a small minimax problem in the complex
    unknowns ``w`` and ``P``: minimise ``max_i |w z_i + P - y_i|`` over the distinct vertices (a
    closed polygon's closing vertex is counted once).  It is solved by Lawson's algorithm, which
    brackets the minimum between a lower and an upper bound and stops when they agree to 1e-9
    (relative).  ``rms`` is reported too: the smallest root-mean-square distance, which linear
    least squares gives.  A zero residual means the target is a state change away; the image
    under a nonuniform scaling, a shear or a mirror is not.

    program: a turtle program.  target: polylines with the same shapes as ``turtle.run(program)``
    (one ``(k, 2)`` array or a list).  Raises ValueError if the shapes differ or the program draws
    fewer than two distinct points.

    >>> from goldman_lib import affine
    >>> sq = "REPEAT 4 [FORWARD 1 TURN 90]"
    >>> fit = closest_turtle_state(sq, [affine.apply(p, affine.rotation(30, [2, 1])) for p in turtle.run(sq)])
    >>> round(fit.residual, 12)
    0.0
    >>> fit = closest_turtle_state(sq, [affine.apply(p, affine.scaling([2, 1])) for p in turtle.run(sq)])
    >>> round(fit.residual, 4), round(fit.rms, 4)
    (0.3536, 0.3536)
    """
    drawn = turtle.run(program)
    if not isinstance(target, (np.ndarray, list, tuple)):
        raise TypeError(f"target must be polylines: one (k, 2) array of points or a list of them; "
                        f"got {type(target).__name__}")
    if isinstance(target, np.ndarray) or (isinstance(target, (list, tuple)) and target and np.ndim(target[0]) == 1):
        target = [target]
    tgt = [as_points(t, f"target[{i}]", dim=2) for i, t in enumerate(target)]
    if [p.shape for p in drawn] != [t.shape for t in tgt]:
        raise ValueError(f"target must have the shapes of the program's strokes {[p.shape for p in drawn]}; "
                         f"got {[t.shape for t in tgt]}")
    z = vertices(drawn) @ np.array([1.0, 1.0j])
    y = vertices(tgt) @ np.array([1.0, 1.0j])
    if z.size == 0 or np.ptp(z.real) + np.ptp(z.imag) == 0:
        raise ValueError("the program must draw at least two distinct points")
    z, y = _distinct_pairs(z, y)
    A = np.column_stack([z, np.ones_like(z)])
    x_ls, *_ = np.linalg.lstsq(A, y, rcond=None)
    rms = float(np.sqrt(np.mean(np.abs(A @ x_ls - y) ** 2)))
    w, p, largest, _ = _minimax_similarity(z, y)
    return TurtleFit(np.array([p.real, p.imag]), np.array([w.real, w.imag]), largest, rms)


def turtle_image_gap(program, M) -> TurtleFit:
    """How close a turtle comes to drawing the image of its drawing under the map ``M`` by
    changing its initial state only (Goldman §5.1): :func:`closest_turtle_state` of the image.

    Zero for translations, rotations and uniform scalings; positive for nonuniform scalings,
    shears and mirrors of any figure that is not a straight line.  M: (3, 3).

    >>> from goldman_lib import affine
    >>> round(turtle_image_gap("REPEAT 3 [FORWARD 1 TURN 120]", affine.shear(1)).residual, 3)
    0.289
    """
    M = affine.as_affine(M)
    return closest_turtle_state(program, [affine.apply(p, M) for p in turtle.run(program)])
