"""Turtle graphics (Goldman §1.1-1.3): the turtle's state, its four commands, turtle programs
and a small turtle-program language.

The turtle's state is a point ``P`` (where it is) and a vector ``w`` (where it is heading; the
length of ``w`` is its step size).  The four commands of Goldman §1.2 change that state:

========== ===================================================================
FORWARD d  draw a line from ``P`` to ``P + d*w``; then ``P <- P + d*w``
MOVE d     the same without drawing (the pen is lifted): a new stroke starts
TURN a     rotate ``w`` by ``a`` degrees counterclockwise (``a < 0``: clockwise)
RESIZE s   ``w <- s*w``: every later FORWARD and MOVE goes ``s`` times as far
========== ===================================================================

A program in the course's turtle language is a sequence of these commands and of
``REPEAT n [ ... ]`` blocks (nested freely).  Commands are case-insensitive, numbers may be
negative or decimal (``-1.5``, ``2e-3``), ``#`` starts a comment that runs to the end of the
line, and line breaks are ordinary white space.

>>> run("REPEAT 4 [FORWARD 1 TURN 90]  # a unit square")
[array([[0., 0.],
       [1., 0.],
       [1., 1.],
       [0., 1.],
       [0., 0.]])]

A program runs in three vectorised steps: :func:`parse` builds the command tree, :func:`expand`
flattens it into arrays of command codes and values (REPEAT becomes ``numpy.tile``), and
:func:`trace` turns those arrays into points with cumulative sums of the turning angles and
cumulative products of the RESIZE factors.  No Python loop runs per command, so a program of
100,000 commands draws in milliseconds.  A program may execute at most :data:`MAX_COMMANDS`
commands, so that ``REPEAT 1000 [REPEAT 1000 [...]]`` typed into a widget fails at once with a
message instead of hanging it.

Importing this module imports numpy only.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from goldman_lib.angles import cos_sin_degrees
from goldman_lib.validation import MAX_ITEMS, MAX_ITERATIONS, as_float, as_int, as_points, as_tolerance, within_budget

__all__ = ["FORWARD", "MOVE", "TURN", "RESIZE", "COMMANDS", "MAX_COMMANDS", "MAX_DEPTH", "MAX_VALUE", "MAX_REPEAT",
           "TurtleSyntaxError", "Command", "Repeat", "Program", "Trace", "Turtle",
           "parse", "expand", "trace", "run", "final_state", "total_turning", "closes",
           "closing_gap", "length", "perimeter", "turning_angles",
           "polygon", "star", "spiral", "circle", "rosette", "format_number", "command_value"]

#: Codes of the four commands in the flat arrays of :func:`expand`.
FORWARD, MOVE, TURN, RESIZE = 0, 1, 2, 3
#: The command names of the language, by code.
COMMANDS = ("FORWARD", "MOVE", "TURN", "RESIZE")
_CODE = {name: code for code, name in enumerate(COMMANDS)}

#: The most commands one program may execute (REPEATs counted out).
MAX_COMMANDS = 200_000
#: The deepest nesting of REPEAT blocks the parser accepts.
MAX_DEPTH = 64
#: The largest magnitude of a FORWARD, MOVE, TURN or RESIZE number (in a program, a :class:`Turtle`
#: command or a program built here): a million steps or degrees is far beyond any drawing, and
#: products and sums of such numbers over :data:`MAX_COMMANDS` commands stay finite.
MAX_VALUE = 1e6
#: The largest REPEAT count (:data:`goldman_lib.validation.MAX_ITERATIONS`); with at most
#: :data:`MAX_DEPTH` nested REPEATs the command count of any program stays a modest Python int.
MAX_REPEAT = MAX_ITERATIONS
#: How many characters of an offending token a message quotes.
_QUOTE = 60


def _quote(text: str) -> str:
    """``repr`` of a token, at most about 60 characters of it (a 1 MB word is not echoed back)."""
    if len(text) <= _QUOTE:
        return repr(text)
    return repr(text[:_QUOTE]) + f"... ({len(text):,} characters)"


def _short(text: str) -> str:
    """A token as written, at most about 60 characters of it."""
    return text if len(text) <= _QUOTE else text[:_QUOTE] + "..."


def _big(n: int) -> str:
    """An exact count for a message: with thousands separators, or as a power of ten when huge."""
    if n < 10 ** 18:
        return f"{n:,}"
    return f"about 10^{len(str(n)) - 1}"


def command_value(value: float, name: str) -> float:
    """A command's number (Goldman §1.2): finite and at most :data:`MAX_VALUE` in magnitude, else a
    ValueError naming ``name``; used by every module that builds turtle commands.

    >>> command_value(90, "angle")
    90.0
    """
    value = as_float(value, name)
    if abs(value) > MAX_VALUE:
        raise ValueError(f"{name} must be at most {MAX_VALUE:g} in magnitude (a turtle step, angle or "
                         f"factor beyond that overflows a drawing); got {value:g}")
    return value


# ---------------------------------------------------------------------------------------------
# The language: tokens, syntax errors, the command tree
# ---------------------------------------------------------------------------------------------

class TurtleSyntaxError(ValueError):
    """A turtle program that does not parse or cannot run.

    The message starts with ``line L, column C:`` and names what was expected and what was
    found.  ``line`` and ``column`` (1-based) are also attributes.
    """

    def __init__(self, message: str, line: int, column: int):
        super().__init__(f"line {line}, column {column}: {message}")
        self.line = line
        self.column = column


class Command(NamedTuple):
    """One of FORWARD, MOVE, TURN, RESIZE with its number; ``offset`` is where it starts in the
    program text."""

    name: str
    value: float
    offset: int = 0


class Repeat(NamedTuple):
    """``REPEAT count [body]``; ``offset`` is where the word REPEAT starts in the program text."""

    count: int
    body: tuple
    offset: int = 0


@dataclass(frozen=True)
class Program:
    """A parsed turtle program: the command tree ``items`` and the source ``text`` (for messages)."""

    items: tuple
    text: str = ""

    def position(self, offset: int) -> tuple[int, int]:
        """``(line, column)``, both 1-based, of a character offset in the source text."""
        return _position(self.text, offset)

    def count(self) -> int:
        """How many commands the program executes, REPEATs counted out (an exact Python int)."""
        return _count(self.items)


_TOKEN = re.compile(r"[^\s,;\[\]#]+|[\[\]]|#[^\n]*")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_WORD = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")


def _kind(tok: str) -> str:
    """The kind of a raw token: word, number, open, close, comment or other."""
    if tok == "[":
        return "open"
    if tok == "]":
        return "close"
    if tok[0] == "#":
        return "comment"
    if _WORD.fullmatch(tok):
        return "word"
    if _NUMBER.fullmatch(tok):
        return "number"
    return "other"


def _position(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    start = text.rfind("\n", 0, offset) + 1
    return line, offset - start + 1


def _describe(kind: str, text: str) -> str:
    if kind == "end":
        return "end of program"
    if kind == "number":
        return f"the number {_short(text)}"
    return _quote(text)


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """``(kind, text, offset)`` of each token, then an ``("end", "", offset)`` token.

    White space, commas and semicolons separate tokens; a ``#`` comment runs to the end of the
    line.  The kinds of repeated token texts are looked up once (most programs repeat a few
    words and numbers many times), which keeps long programs quick to read.
    """
    kinds: dict[str, str] = {}
    toks = []
    for m in _TOKEN.finditer(text):
        tok = m.group()
        kind = kinds.get(tok)
        if kind is None:
            kind = kinds[tok] = _kind(tok)
        if kind == "other":
            # split off the first character that cannot start a word or a number
            bad = _NUMBER.match(tok) or _WORD.match(tok)
            if bad:
                toks.append(("number" if _NUMBER.match(tok) else "word", bad.group(), m.start()))
                toks.append(("other", tok[bad.end()], m.start() + bad.end()))
            else:
                toks.append(("other", tok[0], m.start()))
            continue
        if kind != "comment":
            toks.append((kind, tok, m.start()))
    end = toks[-1][2] + len(toks[-1][1]) if toks else 0
    toks.append(("end", "", end))
    return toks


def parse(program: str) -> Program:
    """Parse a turtle program into its command tree (Goldman §1.3 programs, §1.2 commands).

    program: text such as ``"REPEAT 5 [FORWARD 1 TURN 144]"``.  Grammar::

        program := item*
        item    := ("FORWARD" | "MOVE" | "TURN" | "RESIZE") number
                 | "REPEAT" count "[" item* "]"

    Words are case-insensitive; numbers may be signed and decimal; ``#`` comments to the end of
    a line; white space (and commas or semicolons) separate freely.  Returns a :class:`Program`.
    Raises TypeError if ``program`` is not a string and :class:`TurtleSyntaxError` (a
    ValueError) naming the line, the column, the token expected and the token found.

    >>> parse("repeat 2 [forward 1.5 turn -90]").items
    (Repeat(count=2, body=(Command(name='FORWARD', value=1.5, offset=10), Command(name='TURN', value=-90.0, offset=22)), offset=0),)
    >>> parse("REPEAT 5 [\\n FORWARD")
    Traceback (most recent call last):
    ...
    goldman_lib.turtle.TurtleSyntaxError: line 2, column 9: expected a number after FORWARD, found end of program
    """
    if not isinstance(program, str):
        raise TypeError(f"program must be a string of turtle commands; got {type(program).__name__}")
    text = program
    toks = _tokens(text)

    def fail(message, offset):
        line, col = _position(text, offset)
        raise TurtleSyntaxError(message, line, col)

    # An explicit stack instead of recursion: nesting depth cannot overflow Python's stack.
    stack: list[tuple[list, int, int]] = []   # (items of the enclosing block, repeat count, offset)
    items: list = []
    i = 0
    n = len(toks)
    while True:
        kind, tok, off = toks[i]
        if kind == "end":
            if stack:
                _, _, ropen = stack[-1]
                line, col = _position(text, ropen)
                fail(f"expected ']' to close REPEAT opened at line {line}, column {col}, found end of program", off)
            break
        if kind == "close":
            if not stack:
                fail("found ']' with no REPEAT [ to close", off)
            outer, count, ropen = stack.pop()
            outer.append(Repeat(count, tuple(items), ropen))
            items = outer
            i += 1
            continue
        if kind != "word":
            what = "'['" if kind == "open" else _describe(kind, tok)
            fail(f"expected a command (FORWARD, MOVE, TURN, RESIZE or REPEAT), found {what}", off)
        word = tok.upper()
        if word in _CODE:
            nkind, ntok, noff = toks[i + 1]
            if nkind != "number":
                fail(f"expected a number after {word}, found {_describe(nkind, ntok)}", noff)
            value = float(ntok)
            if not math.isfinite(value):
                fail(f"the number after {word} must be finite; {_short(ntok)} is too large", noff)
            if abs(value) > MAX_VALUE:
                fail(f"the number after {word} must be at most {MAX_VALUE:g} in magnitude (over the limit); "
                     f"found {_short(ntok)}", noff)
            items.append(Command(word, value, off))
            i += 2
            continue
        if word == "REPEAT":
            nkind, ntok, noff = toks[i + 1]
            if nkind != "number":
                fail(f"expected a repeat count (a whole number) after REPEAT, found {_describe(nkind, ntok)}", noff)
            value = float(ntok)
            if not (math.isfinite(value) and value >= 0 and value == int(value)):
                fail(f"the REPEAT count must be a non-negative whole number, found {_short(ntok)}", noff)
            if value > MAX_REPEAT:
                fail(f"the REPEAT count must be at most {MAX_REPEAT:,} (over the limit of the language), "
                     f"found {_short(ntok)}", noff)
            bkind, btok, boff = toks[i + 2]
            if bkind != "open":
                fail(f"expected '[' after REPEAT {int(value)}, found {_describe(bkind, btok)}", boff)
            if len(stack) >= MAX_DEPTH:
                fail(f"REPEAT blocks are nested more than {MAX_DEPTH} deep", off)
            stack.append((items, int(value), off))
            items = []
            i += 3
            continue
        close = (difflib.get_close_matches(word, list(COMMANDS) + ["REPEAT"], n=1, cutoff=0.6)
                 if len(word) <= 20 else [])
        hint = f" (did you mean {close[0]}?)" if close else ""
        fail(f"expected a command (FORWARD, MOVE, TURN, RESIZE or REPEAT), found {_quote(tok)}{hint}", off)
    assert i == n - 1
    return Program(tuple(items), text)


def _count(items) -> int:
    total = 0
    for it in items:
        total += 1 if isinstance(it, Command) else it.count * _count(it.body)
    return total


def _as_program(program, name: str = "program") -> Program:
    if isinstance(program, Program):
        return program
    if isinstance(program, str):
        return parse(program)
    raise TypeError(f"{name} must be a turtle program (a string) or a parsed Program; "
                    f"got {type(program).__name__}")


def _biggest_repeat(items):
    """The REPEAT whose expansion is largest (to name it in the too-many-commands message)."""
    best = None
    pending = list(items)
    while pending:
        it = pending.pop()
        if isinstance(it, Repeat):
            size = it.count * _count(it.body)
            if best is None or size > best[0]:
                best = (size, it)
            pending.extend(it.body)
    return best


def expand(program, *, max_commands: int = MAX_COMMANDS) -> tuple[np.ndarray, np.ndarray]:
    """Flatten a turtle program into the commands it executes, in order (Goldman §1.3).

    program: a program string or a parsed :class:`Program`.  Returns ``(codes, values)``: two
    ``(m,)`` arrays, ``codes`` (int8) holding :data:`FORWARD`, :data:`MOVE`, :data:`TURN` or
    :data:`RESIZE`, ``values`` (float) their numbers.  REPEAT bodies are tiled with numpy.
    Raises TurtleSyntaxError if the program does not parse, or if it would execute more than
    ``max_commands`` commands (naming the REPEAT responsible).  max_commands: at most
    :data:`goldman_lib.validation.MAX_ITEMS` (10,000,000: the flat arrays and the points they draw
    would take gigabytes beyond that).

    >>> codes, values = expand("REPEAT 2 [FORWARD 1 TURN 90]")
    >>> codes.tolist(), values.tolist()
    ([0, 2, 0, 2], [1.0, 90.0, 1.0, 90.0])
    """
    prog = _as_program(program)
    max_commands = as_int(max_commands, "max_commands", minimum=0, maximum=MAX_ITEMS)
    total = prog.count()
    if total > max_commands:
        big = _biggest_repeat(prog.items)
        what = ""
        line, col = 1, 1
        if big is not None:
            line, col = prog.position(big[1].offset)
            what = (f" (this REPEAT runs its body of {_big(_count(big[1].body))} commands "
                    f"{big[1].count:,} times)")
        raise TurtleSyntaxError(
            f"this program would execute {_big(total)} commands, more than the limit of {max_commands:,}"
            f"{what}; use fewer repetitions so the drawing stays quick", line, col)
    return _expand(prog.items)


def _expand(items) -> tuple[np.ndarray, np.ndarray]:
    parts_c, parts_v = [], []
    run_c, run_v = [], []
    for it in items:
        if isinstance(it, Command):
            run_c.append(_CODE[it.name])
            run_v.append(it.value)
            continue
        if it.count == 0:
            continue
        bc, bv = _expand(it.body)
        if bc.size == 0:
            continue
        if run_c:
            parts_c.append(np.array(run_c, dtype=np.int8))
            parts_v.append(np.array(run_v, dtype=float))
            run_c, run_v = [], []
        parts_c.append(np.tile(bc, it.count))
        parts_v.append(np.tile(bv, it.count))
    if run_c:
        parts_c.append(np.array(run_c, dtype=np.int8))
        parts_v.append(np.array(run_v, dtype=float))
    if not parts_c:
        return np.zeros(0, dtype=np.int8), np.zeros(0, dtype=float)
    if len(parts_c) == 1:
        return parts_c[0], parts_v[0]
    return np.concatenate(parts_c), np.concatenate(parts_v)


# ---------------------------------------------------------------------------------------------
# Running a program: the vectorised turtle
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Trace:
    """What running a program produced (see :func:`trace`).

    polylines: list of ``(k, 2)`` arrays, one per pen-down stroke.  point, direction: the final
    state ``P`` and ``w`` (``(2,)`` arrays).  total_turning: sum of the TURN angles (degrees).
    commands: the number of commands executed.  first_draws / last_draws: whether the first /
    last FORWARD-or-MOVE of the program was a FORWARD (None if it has neither).
    """

    polylines: list
    point: np.ndarray
    direction: np.ndarray
    total_turning: float
    commands: int
    first_draws: bool | None = None
    last_draws: bool | None = None


def as_state(point, direction):
    """The turtle's state ``(P, w)`` (Goldman §1.2) as two validated 2-vectors.

    >>> as_state((0, 0), (1, 0))
    (array([0., 0.]), array([1., 0.]))
    """
    p = as_points(point, "point", ndim=1, dim=2)
    w = as_points(direction, "direction", ndim=1, dim=2)
    return p, w


def trace_arrays(codes: np.ndarray, values: np.ndarray, p0: np.ndarray, w0: np.ndarray) -> Trace:
    """Run flat command arrays (as :func:`expand` returns them) from the state ``(p0, w0)``
    (Goldman §1.2), vectorised: headings are cumulative sums of the turns, step sizes cumulative
    products of the RESIZE factors.  Recursive programs (``goldman_lib.fractals``) expand to such
    arrays and draw through here.  No validation: use :func:`trace` for programs from users.

    >>> codes, values = expand("FORWARD 1 TURN 90 FORWARD 1")
    >>> trace_arrays(codes, values, np.zeros(2), np.array([1.0, 0.0])).polylines[0].tolist()
    [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
    """
    turns = np.where(codes == TURN, values, 0.0)
    factors = np.where(codes == RESIZE, values, 1.0)
    total_turn = float(turns.sum())
    moving = codes <= MOVE
    # Heading and scale in force *at* each command: exclusive cumulative sum / product.
    cum_turn = np.cumsum(turns) - turns
    with np.errstate(over="ignore", invalid="ignore"):
        cum_scale = np.cumprod(factors)
    total_scale = float(cum_scale[-1]) if cum_scale.size else 1.0
    scale_before = np.concatenate(([1.0], cum_scale[:-1]))
    th = cum_turn[moving]
    c, s = cos_sin_degrees(th)
    with np.errstate(over="ignore", invalid="ignore"):
        d = values[moving] * scale_before[moving]
        steps = np.empty((th.size, 2))
        steps[:, 0] = d * (c * w0[0] - s * w0[1])
        steps[:, 1] = d * (s * w0[0] + c * w0[1])
        pts = np.empty((th.size + 1, 2))
        pts[0] = p0
        np.cumsum(steps, axis=0, out=pts[1:])
        pts[1:] += p0
        cf, sf = cos_sin_degrees(np.array([total_turn]))
        w_end = total_scale * np.array([cf[0] * w0[0] - sf[0] * w0[1], sf[0] * w0[0] + cf[0] * w0[1]])
    if not (np.isfinite(pts).all() and np.isfinite(w_end).all() and math.isfinite(total_turn)):
        raise ValueError("the turtle's path overflowed (a coordinate became infinite or undefined): "
                         "use smaller steps or RESIZE factors")
    draws = codes[moving] == FORWARD
    edges = np.diff(np.concatenate(([0], draws.view(np.int8), [0])))
    starts = np.flatnonzero(edges == 1)
    ends = np.flatnonzero(edges == -1)
    polylines = [pts[a:b + 1].copy() for a, b in zip(starts, ends)]
    return Trace(polylines, pts[-1].copy(), w_end, total_turn, int(codes.size),
                 bool(draws[0]) if draws.size else None, bool(draws[-1]) if draws.size else None)


def trace(program, *, point=(0, 0), direction=(1, 0), max_commands: int = MAX_COMMANDS) -> Trace:
    """Run a turtle program and return its strokes and the turtle's final state (Goldman §1.2).

    program: a program string or parsed :class:`Program`.  point: ``(2,)`` the initial ``P``.
    direction: ``(2,)`` the initial ``w`` (its length is the step size).  Returns a
    :class:`Trace`.  Raises TypeError/ValueError naming a bad ``point``/``direction``,
    TurtleSyntaxError for a program that does not parse or is too long, and ValueError if the
    path overflows.

    >>> t = trace("FORWARD 2 TURN 90 RESIZE 0.5 FORWARD 2")
    >>> t.point, t.direction, t.total_turning
    (array([2., 1.]), array([0. , 0.5]), 90.0)
    """
    p0, w0 = as_state(point, direction)
    codes, values = expand(program, max_commands=max_commands)
    return trace_arrays(codes, values, p0, w0)


def run(program, *, point=(0, 0), direction=(1, 0)) -> list[np.ndarray]:
    """Run a turtle program; return one ``(k, 2)`` float polyline per pen-down stroke (Goldman §1.2-1.3).

    program: a program string (see :func:`parse`) or a parsed :class:`Program`.  point: ``(2,)``
    the turtle's initial position ``P``; direction: ``(2,)`` its initial heading ``w`` (whose
    length is the step size).  FORWARD extends the current stroke; MOVE ends it, and the next
    FORWARD starts a new one.  A program that never draws returns ``[]``.  Raises TypeError for
    a program that is not a string, TurtleSyntaxError (a ValueError) naming line, column and
    expected token, ValueError if it would execute more than :data:`MAX_COMMANDS` commands or
    its path overflows, and TypeError/ValueError naming ``point`` or ``direction``.

    >>> run("FORWARD 1 TURN 90 FORWARD 1")
    [array([[0., 0.],
           [1., 0.],
           [1., 1.]])]
    >>> len(run("FORWARD 1 MOVE 1 FORWARD 1"))
    2
    """
    return trace(program, point=point, direction=direction).polylines


def final_state(program, *, point=(0, 0), direction=(1, 0)) -> tuple[np.ndarray, np.ndarray]:
    """The turtle's state ``(P, w)`` after running a program (Goldman §1.2).

    Same parameters and errors as :func:`run`; returns two ``(2,)`` arrays.

    >>> final_state("TURN 90 RESIZE 2 FORWARD 1")
    (array([0., 2.]), array([0., 2.]))
    """
    t = trace(program, point=point, direction=direction)
    return t.point, t.direction


def total_turning(program) -> float:
    """The total turning of a program: the sum of the angles of all the TURNs it executes, in
    degrees (Goldman §1.3).

    program: a program string or parsed :class:`Program`.  Raises as :func:`expand`.  A turtle
    that walks once around a simple closed polygon counterclockwise turns 360 degrees; one that
    returns to its initial state turns a multiple of 360.

    >>> total_turning("REPEAT 5 [FORWARD 1 TURN 144]")
    720.0
    """
    codes, values = expand(program)
    with np.errstate(over="ignore"):
        total = float(values[codes == TURN].sum())
    if not math.isfinite(total):
        raise ValueError("program: the sum of its TURN angles overflows; use smaller angles")
    return total


# ---------------------------------------------------------------------------------------------
# Measuring paths
# ---------------------------------------------------------------------------------------------

def _as_polyline(polyline, name: str = "polyline") -> np.ndarray:
    return as_points(polyline, name, ndim=2, dim=2)


def as_polylines(polylines, name: str = "polylines") -> list[np.ndarray]:
    """A drawing (Goldman §1.3) as a list of validated ``(m, 2)`` polylines: one polyline or a list
    of them.  Raises ValueError naming the polyline at fault.

    >>> [p.shape for p in as_polylines([[0, 0], [1, 0]])]
    [(2, 2)]
    """
    if isinstance(polylines, np.ndarray) and polylines.ndim == 2:
        return [_as_polyline(polylines, name)]
    if isinstance(polylines, (list, tuple)) and polylines and np.ndim(polylines[0]) == 1:
        return [_as_polyline(polylines, name)]
    if not isinstance(polylines, (list, tuple)):
        return [_as_polyline(polylines, name)]
    return [_as_polyline(p, f"{name}[{i}]") for i, p in enumerate(polylines)]


def closing_gap(polyline) -> float:
    """Distance from a polyline's last point back to its first (Goldman §1.3).

    polyline: ``(k, 2)`` points, ``k >= 1``.  Raises TypeError/ValueError naming ``polyline``.

    >>> closing_gap([[0, 0], [3, 0], [3, 4]])
    5.0
    """
    p = _as_polyline(polyline)
    return float(np.hypot(*(p[-1] - p[0])))


def closes(polyline, tol: float = 1e-9) -> bool:
    """Whether a path closes: its last point is within ``tol`` of its first (Goldman §1.3).

    polyline: ``(k, 2)`` points.  tol: absolute tolerance, >= 0.  Raises TypeError/ValueError
    naming the parameter.

    >>> closes(run("REPEAT 6 [FORWARD 1 TURN 60]")[0])
    True
    >>> closes([[0, 0], [1, 0]], tol=0.5)
    False
    """
    tol = as_float(tol, "tol")
    if tol < 0:
        raise ValueError(f"tol must be >= 0; got {tol}")
    return closing_gap(polyline) <= tol


def length(polylines) -> float:
    """Total length of a polyline ``(k, 2)`` or of a list of polylines (the turtle's ink).

    Raises TypeError/ValueError naming ``polylines``.

    >>> length(run("FORWARD 3 TURN 90 FORWARD 4 MOVE 1 FORWARD 2"))
    9.0
    """
    return float(sum(np.hypot(*np.diff(p, axis=0).T).sum() for p in as_polylines(polylines)))


def perimeter(polyline, tol: float = 1e-9) -> float:
    """Perimeter of a closed polyline ``(k, 2)`` (first and last points within ``tol``).

    Raises ValueError if the polyline does not close, saying how far apart its ends are.

    >>> perimeter(run("REPEAT 4 [FORWARD 2 TURN 90]")[0])
    8.0
    """
    p = _as_polyline(polyline)
    tol = as_tolerance(tol, "tol")
    gap = closing_gap(p)
    if gap > tol:
        raise ValueError(f"polyline must be closed to have a perimeter; its ends are {gap:.3g} apart")
    return length(p)


def turning_angles(polyline) -> np.ndarray:
    """Signed turning angles (degrees, counterclockwise positive, in (-180, 180]) at the interior
    vertices of a polyline: the TURNs a turtle tracing it would make (Goldman §1.3).

    polyline: ``(k, 2)``; zero-length segments are skipped.  Returns ``(j,)``.

    >>> turning_angles([[0, 0], [1, 0], [1, 1], [0, 1]])
    array([90., 90.])
    """
    p = _as_polyline(polyline)
    seg = np.diff(p, axis=0)
    seg = seg[np.hypot(seg[:, 0], seg[:, 1]) > 0]
    if len(seg) < 2:
        return np.zeros(0)
    a, b = seg[:-1], seg[1:]
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    dot = (a * b).sum(axis=1)
    ang = np.degrees(np.arctan2(cross, dot))
    ang[ang == -180.0] = 180.0
    return ang


# ---------------------------------------------------------------------------------------------
# Turtle programs of §1.3
# ---------------------------------------------------------------------------------------------

def format_number(x: float) -> str:
    """A number as the turtle language writes it: integers without a point, others in full.

    >>> format_number(72.0), format_number(360 / 7), format_number(-0.5)
    ('72', '51.42857142857143', '-0.5')
    """
    x = as_float(x, "x")
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def _sides(n, name: str, *, minimum: int, per: int, extra: int = 0) -> int:
    """A count of repetitions whose program executes ``per * n + extra`` commands, bounded so that
    it runs: at most :data:`MAX_COMMANDS` commands."""
    return within_budget(n, name, cost=lambda v: per * v + extra, what="the program", unit="commands",
                         limit=MAX_COMMANDS, minimum=minimum)


def polygon(n: int, step: float = 1.0) -> str:
    """The program of a regular n-gon: ``REPEAT n [FORWARD step TURN 360/n]`` (Goldman §1.3).

    n: number of sides, 3 <= n <= 100,000 (the program runs ``2n`` commands, at most
    :data:`MAX_COMMANDS`).  step: side length (in units of ``|w|``), 0 < step <= :data:`MAX_VALUE`.

    >>> polygon(6, 2)
    'REPEAT 6 [FORWARD 2 TURN 60]'
    """
    n = _sides(n, "n", minimum=3, per=2)
    step = command_value(as_float(step, "step", positive=True), "step")
    return f"REPEAT {n} [FORWARD {format_number(step)} TURN {format_number(360 / n)}]"


def star(n: int, k: int, step: float = 1.0) -> str:
    """The program of the star polygon {n/k}: ``REPEAT n [FORWARD step TURN 360k/n]`` (Goldman §1.3).

    The turtle visits every k-th of n points evenly spaced on a circle; it closes after n steps
    having turned ``360k`` degrees.  2 <= n <= 100,000 points (``2n`` commands, at most
    :data:`MAX_COMMANDS`); 1 <= k < n (k = 1 is the regular polygon; if gcd(n, k) = g > 1 the
    path retraces the {n/g / k/g} polygon g times); 0 < step <= :data:`MAX_VALUE`.

    >>> star(5, 2)
    'REPEAT 5 [FORWARD 1 TURN 144]'
    """
    n = _sides(n, "n", minimum=2, per=2)
    k = as_int(k, "k", minimum=1, maximum=n - 1)
    step = command_value(as_float(step, "step", positive=True), "step")
    return f"REPEAT {n} [FORWARD {format_number(step)} TURN {format_number(360 * k / n)}]"


def spiral(n: int, angle: float = 90.0, step: float = 1.0, *, factor: float | None = None,
           increment: float | None = None) -> str:
    """The program of a spiral of ``n`` steps turning ``angle`` each time (Goldman §1.3).

    With ``factor`` (the default, 1.1): ``REPEAT n [FORWARD step TURN angle RESIZE factor]``, a
    spiral whose steps grow geometrically.  With ``increment``: the steps grow arithmetically,
    ``step, step + increment, ...`` (written out command by command).  Give at most one of the
    two.  n: 0 <= n <= 66,666 (``3n`` commands, at most :data:`MAX_COMMANDS`); angle, step,
    factor: at most :data:`MAX_VALUE` in magnitude, and so must the last step
    ``step + (n - 1) increment`` be.  Raises ValueError/TypeError naming the parameter.

    >>> spiral(3, 90, 1, factor=2)
    'REPEAT 3 [FORWARD 1 TURN 90 RESIZE 2]'
    >>> spiral(3, 90, 1, increment=1)
    'FORWARD 1 TURN 90\\nFORWARD 2 TURN 90\\nFORWARD 3 TURN 90'
    """
    n = _sides(n, "n", minimum=0, per=3)
    angle = command_value(angle, "angle")
    step = command_value(step, "step")
    if factor is not None and increment is not None:
        raise ValueError("give factor or increment, not both")
    a = format_number(angle)
    if increment is not None:
        increment = command_value(increment, "increment")
        last = step + (n - 1) * increment if n else step
        if abs(last) > MAX_VALUE:
            raise ValueError(f"increment is too large for n = {n}: the last step step + (n - 1)*increment = "
                             f"{last:g} is over {MAX_VALUE:g} in magnitude")
        return "\n".join(f"FORWARD {format_number(step + i * increment)} TURN {a}" for i in range(n))
    factor = 1.1 if factor is None else command_value(as_float(factor, "factor", nonzero=True), "factor")
    return f"REPEAT {n} [FORWARD {format_number(step)} TURN {a} RESIZE {format_number(factor)}]"


def circle(radius: float = 1.0, n: int = 36) -> str:
    """The program of a circle of ``radius`` approximated by a regular n-gon inscribed in it
    (Goldman §1.3).

    The turtle starts on the circle heading along the tangent (the centre is on its left, at
    ``P + radius * w`` rotated by 90 degrees for ``|w| = 1``), walks ``n`` chords of length
    ``2 radius sin(180/n)`` and ends in its initial state.  0 < radius <= :data:`MAX_VALUE` / 2
    (a chord is at most a diameter, and the language's numbers are at most :data:`MAX_VALUE`);
    3 <= n <= 99,999 (``2n + 2`` commands, at most :data:`MAX_COMMANDS`).

    >>> circle(1, 4)
    'TURN 45 REPEAT 4 [FORWARD 1.414213562373095 TURN 90] TURN -45'
    """
    radius = as_float(radius, "radius", positive=True)
    if radius > MAX_VALUE / 2:
        raise ValueError(f"radius must be at most {MAX_VALUE / 2:g} (its chords, up to a diameter, must be at most "
                         f"{MAX_VALUE:g}, the largest number of the turtle language); got {radius:g}")
    n = _sides(n, "n", minimum=3, per=2, extra=2)
    chord = 2 * radius * math.sin(math.pi / n)
    half = format_number(180 / n)
    return (f"TURN {half} REPEAT {n} [FORWARD {format_number(chord)} TURN {format_number(360 / n)}] "
            f"TURN -{half}")


def rosette(n: int = 12, sides: int = 6, step: float = 1.0) -> str:
    """The program of a rosette: a regular polygon drawn ``n`` times, turning 360/n between
    copies (Goldman §1.3).

    n >= 1 copies; sides >= 3; step > 0; the program's ``n (2 sides + 1)`` commands at most
    :data:`MAX_COMMANDS` (so sides <= 99,999 and n <= 200,000 / (2 sides + 1)).

    >>> rosette(4, 4)
    'REPEAT 4 [REPEAT 4 [FORWARD 1 TURN 90] TURN 90]'
    """
    sides = _sides(sides, "sides", minimum=3, per=2, extra=1)
    n = _sides(n, "n", minimum=1, per=2 * sides + 1)
    return f"REPEAT {n} [{polygon(sides, step)} TURN {format_number(360 / n)}]"


# ---------------------------------------------------------------------------------------------
# The object layer
# ---------------------------------------------------------------------------------------------

class Turtle:
    """A turtle with state ``(P, w)`` that executes commands one at a time (Goldman §1.2).

    point: ``(2,)`` initial position.  direction: ``(2,)`` initial heading vector, whose length
    is the step size.  Every command method returns the turtle, so commands chain.
    :meth:`polylines` returns the strokes drawn so far; :meth:`run` executes a program text.

    >>> t = Turtle().forward(1).turn(90).forward(1).move(1).forward(2)
    >>> t.point, t.heading
    (array([1., 4.]), 90.0)
    >>> [p.shape for p in t.polylines()]
    [(3, 2), (2, 2)]
    """

    def __init__(self, point=(0, 0), direction=(1, 0)):
        p, w = as_state(point, direction)
        self._p0, self._w0 = p.copy(), w.copy()
        self.point, self.direction = p.copy(), w.copy()
        self._codes: list[np.ndarray] = []
        self._values: list[np.ndarray] = []
        self._turning = 0.0

    def _do(self, code: int, value, name: str):
        value = command_value(value, name)
        t = trace_arrays(np.array([code], dtype=np.int8), np.array([value]), self.point, self.direction)
        self.point, self.direction = t.point, t.direction
        self._turning += t.total_turning
        self._codes.append(np.array([code], dtype=np.int8))
        self._values.append(np.array([value]))
        return self

    def forward(self, distance: float) -> "Turtle":
        """FORWARD distance: draw from ``P`` to ``P + distance*w`` and move there."""
        return self._do(FORWARD, distance, "distance")

    def move(self, distance: float) -> "Turtle":
        """MOVE distance: go to ``P + distance*w`` without drawing (a new stroke starts)."""
        return self._do(MOVE, distance, "distance")

    def turn(self, angle: float) -> "Turtle":
        """TURN angle: rotate ``w`` by ``angle`` degrees counterclockwise."""
        return self._do(TURN, angle, "angle")

    def resize(self, factor: float) -> "Turtle":
        """RESIZE factor: ``w <- factor*w`` (later steps are ``factor`` times as long)."""
        return self._do(RESIZE, factor, "factor")

    def run(self, program) -> "Turtle":
        """Execute a turtle program (string or :class:`Program`) from the current state."""
        codes, values = expand(program)
        t = trace_arrays(codes, values, self.point, self.direction)
        self.point, self.direction = t.point, t.direction
        self._turning += t.total_turning
        self._codes.append(codes)
        self._values.append(values)
        return self

    @property
    def heading(self) -> float:
        """The direction of ``w`` in degrees, counterclockwise from the x-axis, in (-180, 180]."""
        h = math.degrees(math.atan2(self.direction[1], self.direction[0]))
        return 180.0 if h == -180.0 else h + 0.0

    @property
    def step(self) -> float:
        """The step size ``|w|``."""
        return float(np.hypot(*self.direction))

    @property
    def total_turning(self) -> float:
        """The sum of all the angles this turtle has turned, in degrees."""
        return self._turning

    def polylines(self) -> list[np.ndarray]:
        """The strokes drawn so far: a list of ``(k, 2)`` arrays, one per pen-down stroke."""
        if not self._codes:
            return []
        codes, values = np.concatenate(self._codes), np.concatenate(self._values)
        return trace_arrays(codes, values, self._p0, self._w0).polylines

    def __repr__(self) -> str:
        p, w = self.point, self.direction
        return f"Turtle(point=({p[0]:.6g}, {p[1]:.6g}), direction=({w[0]:.6g}, {w[1]:.6g}))"
