"""Recursive turtle programs and fractals (Goldman Ch. 2-3): the looping lemmas, fractal gaskets
and bump fractals drawn by recursion, their similarity dimension, length, non-differentiability
and independence of the base case.

A *recursive turtle program* (Goldman §2.3) has a **base case**, run at level 0, and a **body**,
run at every level ``n > 0``, in which each ``RECURSE`` runs the whole program again at level
``n - 1`` from the turtle's state at that moment.  The Koch curve is::

    KOCH   level 0:  FORWARD 1
           level n:  RESIZE 1/3  KOCH  TURN 60  KOCH  TURN -120  KOCH  TURN 60  KOCH  RESIZE 3

In this module a program is plain data, a :class:`RecursiveTurtleProgram` holding ``body`` and
``base``: tuples of ``(command, value)`` pairs with ``command`` one of ``"FORWARD"``, ``"MOVE"``,
``"TURN"``, ``"RESIZE"`` (:data:`goldman_lib.turtle.COMMANDS`) or ``"RECURSE"``.

>>> koch = koch_curve_program()
>>> koch.body[:3]
(('RESIZE', 0.3333333333333333), ('RECURSE', None), ('TURN', 60.0))
>>> [p.shape for p in koch.polylines(2)]
[(17, 2)]

Two small extensions of the book's single recursion keep every fractal of Ch. 2 in this one
data structure:

* ``("RECURSE", -1)`` runs the **mirror program** at level ``n - 1``: the program with the sign
  of every TURN of its own body and base reversed (its own RECURSE entries keep their kinds).
  ``("RECURSE", None)`` and ``("RECURSE", 1)`` run the program itself.  So a program with a
  ``-1`` call is a pair of mutually recursive programs, like the left and right dragons
  ``LDRAGON``/``RDRAGON`` of turtle geometry; the Heighway dragon (:func:`dragon_program`)
  needs it.  For the dragon the mirror program draws the same curve traversed backwards.
* ``start`` (default ``(("RECURSE", None),)``: just run the program) is a driver run once at
  the top, whose RECURSE entries run the program at the *requested* level.  The Koch snowflake
  is the driver ``REPEAT 3 [KOCH TURN -120]`` around the Koch curve
  (:func:`koch_snowflake_program`).

Expansion is vectorised: level ``n`` is built from level ``n - 1`` by concatenating numpy arrays
(one piece per body entry), never by a Python loop over commands, and the turtle then runs the
flat program with :mod:`goldman_lib.turtle`'s cumulative sums.  Level 8 of the Koch curve
(65,536 segments, 174,761 commands) draws in milliseconds.

Importing this module imports numpy only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from goldman_lib import turtle
from goldman_lib.turtle import FORWARD, MOVE, RESIZE, TURN, MAX_COMMANDS
from goldman_lib.validation import as_float, as_int, as_points

__all__ = [
    "RECURSE", "RecursiveTurtleProgram",
    "koch_curve_program", "koch_snowflake_program", "sierpinski_gasket_program",
    "sierpinski_carpet_program", "polygon_gasket_program", "c_curve_program", "dragon_program",
    "tree_program", "bush_program", "PROGRAMS",
    "koch_curve", "koch_snowflake", "sierpinski_gasket", "sierpinski_carpet", "polygon_gasket",
    "c_curve", "dragon", "tree", "bush",
]

#: The name of the recursive call in a program's ``body``.
RECURSE = "RECURSE"
_CODES = {name: code for code, name in enumerate(turtle.COMMANDS)}


# ---------------------------------------------------------------------------------------------
# Recursive turtle programs (§2.3)
# ---------------------------------------------------------------------------------------------

def _fmt(x) -> str:
    return turtle.format_number(x)


def _as_commands(seq, name: str, *, allow_recurse: bool) -> tuple:
    """Validate a sequence of ``(command, value)`` pairs; return them as a tuple of tuples."""
    if isinstance(seq, (str, bytes)) or not hasattr(seq, "__iter__"):
        raise TypeError(f"{name} must be a sequence of (command, value) pairs; got {type(seq).__name__}")
    out = []
    for i, item in enumerate(seq):
        if not isinstance(item, (tuple, list)) or len(item) != 2:
            raise TypeError(f"{name}[{i}] must be a (command, value) pair; got {item!r}")
        cmd, value = item
        if not isinstance(cmd, str):
            raise TypeError(f"{name}[{i}]: the command must be a string; got {cmd!r}")
        cmd = cmd.upper()
        if cmd == RECURSE:
            if not allow_recurse:
                raise ValueError(f"{name}[{i}]: the base case may not RECURSE (it is what level 0 draws)")
            if value is not None and not (not isinstance(value, bool) and value in (1, -1)):
                raise ValueError(f"{name}[{i}]: RECURSE takes None, 1 (the program) or -1 (its mirror "
                                 f"program); got {value!r}")
            out.append((RECURSE, None if value in (None, 1) else -1))
            continue
        if cmd not in _CODES:
            raise ValueError(f"{name}[{i}]: unknown command {cmd!r}; use FORWARD, MOVE, TURN, RESIZE "
                             f"or RECURSE")
        value = as_float(value, f"{name}[{i}] value")
        if cmd == "RESIZE" and value == 0:
            raise ValueError(f"{name}[{i}]: RESIZE 0 would shrink the turtle's step to nothing")
        out.append((cmd, value))
    return tuple(out)


def _flat(commands, sign: float) -> tuple[np.ndarray, np.ndarray]:
    """Codes and values of RECURSE-free commands, TURN angles multiplied by ``sign``."""
    codes = np.array([_CODES[c] for c, _ in commands], dtype=np.int8)
    values = np.array([v for _, v in commands], dtype=float)
    if sign < 0:
        values = np.where(codes == TURN, -values, values)
    return codes, values


def _text(commands) -> str:
    parts = []
    for c, v in commands:
        if c == RECURSE:
            parts.append("RECURSE" if v is None else "RECURSE(mirror)")
        else:
            parts.append(f"{c} {_fmt(v)}")
    return " ".join(parts)


class RecursiveTurtleProgram:
    """A recursive turtle program (Goldman §2.3): at level 0 run ``base``; at level n > 0 run
    ``body``, where each ``("RECURSE", None)`` entry runs the program at level n - 1 (with the
    turtle state current at that moment).

    body: sequence of ``(command, value)`` pairs, command in FORWARD, MOVE, TURN, RESIZE (with a
    finite number) or RECURSE (value None, or -1 for the mirror program: every TURN of body and
    base negated).  base: the same without RECURSE.  name: a label.  start: an optional driver
    run once at the top whose RECURSE entries run the program at the requested level (default:
    just the program).  Attributes ``body``, ``base``, ``start`` are tuples, ``name`` a string.
    Raises TypeError/ValueError naming the entry that breaks a rule.

    >>> p = RecursiveTurtleProgram([("RESIZE", 0.5), ("RECURSE", None), ("MOVE", 1),
    ...                             ("RECURSE", None), ("RESIZE", 2)], [("FORWARD", 1)], "Cantor")
    >>> p.count(3), len(p.polylines(3))
    (29, 8)
    """

    def __init__(self, body, base, name: str = "", start=None):
        self.body = _as_commands(body, "body", allow_recurse=True)
        self.base = _as_commands(base, "base", allow_recurse=False)
        if not any(c == RECURSE for c, _ in self.body):
            raise ValueError("body must RECURSE at least once (otherwise the program is not recursive)")
        if not isinstance(name, str):
            raise TypeError(f"name must be a string; got {type(name).__name__}")
        self.name = name
        default = ((RECURSE, None),)
        self.start = default if start is None else _as_commands(start, "start", allow_recurse=True)
        self._mirrored = any(c == RECURSE and v == -1 for c, v in self.body + self.start)

    # -- sizes ---------------------------------------------------------------------------------
    def count(self, level: int) -> int:
        """How many turtle commands level ``level`` executes (an exact int; nothing is built).

        >>> koch_curve_program().count(8)
        174761
        """
        level = as_int(level, "level", minimum=0)
        sizes = self._sizes(level)
        return sizes[-1]

    def _sizes(self, level: int) -> list[int]:
        """Exact command counts of the program at levels 0..level, then of the whole drawing."""
        plain = sum(1 for c, _ in self.body if c != RECURSE)
        calls = sum(1 for c, _ in self.body if c == RECURSE)
        sizes = [len(self.base)]
        for _ in range(level):
            sizes.append(plain + calls * sizes[-1])
        s_plain = sum(1 for c, _ in self.start if c != RECURSE)
        s_calls = sum(1 for c, _ in self.start if c == RECURSE)
        return sizes + [s_plain + s_calls * sizes[-1]]

    def max_level(self, max_commands: int = MAX_COMMANDS) -> int:
        """The highest level whose drawing executes at most ``max_commands`` commands.

        >>> koch_curve_program().max_level()
        8
        """
        max_commands = as_int(max_commands, "max_commands", minimum=1)
        level = 0
        while level < 200 and self._sizes(level + 1)[-1] <= max_commands:
            level += 1
        return level

    # -- expansion -----------------------------------------------------------------------------
    def expand(self, level: int, *, max_commands: int = MAX_COMMANDS) -> tuple[np.ndarray, np.ndarray]:
        """The flat program that level ``level`` executes (Goldman §2.3), as
        :func:`goldman_lib.turtle.expand` returns it.

        level: int >= 0.  Returns ``(codes, values)``, two ``(m,)`` arrays (int8 codes of
        FORWARD/MOVE/TURN/RESIZE, float values).  Each level is built from the one below by
        concatenating numpy arrays.  Raises ValueError if the drawing would execute more than
        ``max_commands`` commands, naming the highest level that fits.

        >>> codes, values = koch_curve_program().expand(1)
        >>> codes.tolist()
        [3, 0, 2, 0, 2, 0, 2, 0, 3]
        >>> koch_curve_program().expand(9)
        Traceback (most recent call last):
        ...
        ValueError: level 9 of the Koch curve would execute 699,049 turtle commands, more than the limit of 200,000; the highest level that fits is 8
        """
        level = as_int(level, "level", minimum=0)
        max_commands = as_int(max_commands, "max_commands", minimum=1)
        total = self._sizes(level)[-1]
        if total > max_commands:
            label = f"the {self.name}" if self.name else "this program"
            raise ValueError(f"level {level} of {label} would execute {total:,} turtle commands, more than "
                             f"the limit of {max_commands:,}; the highest level that fits is "
                             f"{self.max_level(max_commands)}")
        pos = _flat(self.base, 1.0)
        neg = _flat(self.base, -1.0) if self._mirrored else pos
        body_pos = [(c, v) for c, v in self.body]
        for _ in range(level):
            new_pos = self._substitute(body_pos, pos, neg, 1.0)
            if self._mirrored:
                neg = self._substitute(body_pos, pos, neg, -1.0)
            pos = new_pos
            if not self._mirrored:
                neg = pos
        return self._substitute(list(self.start), pos, neg, 1.0)

    @staticmethod
    def _substitute(entries, pos, neg, sign):
        """Concatenate the entries, RECURSE replaced by ``pos`` (or ``neg`` for -1); TURNs of the
        plain entries multiplied by ``sign``."""
        parts_c, parts_v = [], []
        run: list = []
        for c, v in entries:
            if c == RECURSE:
                if run:
                    rc, rv = _flat(run, sign)
                    parts_c.append(rc)
                    parts_v.append(rv)
                    run = []
                sub = neg if v == -1 else pos
                parts_c.append(sub[0])
                parts_v.append(sub[1])
            else:
                run.append((c, v))
        if run:
            rc, rv = _flat(run, sign)
            parts_c.append(rc)
            parts_v.append(rv)
        if not parts_c:
            return np.zeros(0, dtype=np.int8), np.zeros(0)
        return np.concatenate(parts_c), np.concatenate(parts_v)

    def trace(self, level: int, point=(0, 0), direction=(1, 0), *,
              max_commands: int = MAX_COMMANDS) -> turtle.Trace:
        """Run level ``level`` and return the :class:`goldman_lib.turtle.Trace` (strokes and
        final state).  point, direction: ``(2,)`` the turtle's initial state.

        >>> t = koch_curve_program().trace(3)
        >>> t.point.round(12) + 0.0, t.direction
        (array([1., 0.]), array([1., 0.]))
        """
        p0, w0 = turtle._as_state(point, direction)
        codes, values = self.expand(level, max_commands=max_commands)
        return turtle._trace_arrays(codes, values, p0, w0)

    def polylines(self, level: int, point=(0, 0), direction=(1, 0)) -> list[np.ndarray]:
        """The strokes level ``level`` draws: a list of ``(k, 2)`` arrays (Goldman §2.3).

        point, direction: ``(2,)`` the turtle's initial state (``|direction|`` is the step).
        Raises ValueError for a negative level or one beyond :data:`goldman_lib.turtle.MAX_COMMANDS`,
        TypeError/ValueError naming a bad ``point``/``direction``.

        >>> sierpinski_gasket_program().polylines(1)[1].round(6) + 0.0
        array([[1.      , 0.      ],
               [0.75    , 0.433013],
               [0.5     , 0.      ],
               [1.      , 0.      ]])
        """
        return self.trace(level, point, direction).polylines

    # -- variants ------------------------------------------------------------------------------
    def with_base(self, base, name: str | None = None) -> "RecursiveTurtleProgram":
        """The same program with another base case (Goldman §3.4: the limit does not change).

        >>> koch_curve_program().with_base([("MOVE", 1)]).polylines(3)
        []
        """
        return RecursiveTurtleProgram(self.body, base, self.name if name is None else name, self.start)

    def text(self) -> str:
        """The program in the book's notation, one line per case.

        >>> print(c_curve_program().text())
        C-curve
          level 0: FORWARD 1
          level n: TURN 45 RESIZE 0.7071067811865476 RECURSE TURN -90 RECURSE TURN 45 RESIZE 1.4142135623730951
        """
        lines = [self.name or "recursive turtle program",
                 f"  level 0: {_text(self.base)}", f"  level n: {_text(self.body)}"]
        if self.start != ((RECURSE, None),):
            lines.append(f"  drawn by: {_text(self.start)}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        extra = "" if self.start == ((RECURSE, None),) else f", start={self.start!r}"
        return f"RecursiveTurtleProgram(body={self.body!r}, base={self.base!r}, name={self.name!r}{extra})"

    def __eq__(self, other) -> bool:
        if not isinstance(other, RecursiveTurtleProgram):
            return NotImplemented
        return (self.body, self.base, self.start) == (other.body, other.base, other.start)

    __hash__ = None


# ---------------------------------------------------------------------------------------------
# The programs of §2.3
# ---------------------------------------------------------------------------------------------

def _cmds(*pairs):
    return tuple((c, None if c == RECURSE else float(v)) for c, v in pairs)


_R = (RECURSE, None)


def koch_curve_program() -> RecursiveTurtleProgram:
    """The Koch curve (Goldman §2.3, bump fractals): a segment whose middle third is replaced by
    the two sides of an equilateral bump.

    level 0: ``FORWARD 1``; level n: ``RESIZE 1/3 KOCH TURN 60 KOCH TURN -120 KOCH TURN 60 KOCH
    RESIZE 3``.  From ``(0, 0)`` heading ``(1, 0)`` it ends at ``(1, 0)`` with the bump above.

    >>> len(koch_curve_program().polylines(8)[0]) - 1
    65536
    """
    body = _cmds(("RESIZE", 1 / 3), _R, ("TURN", 60), _R, ("TURN", -120), _R, ("TURN", 60), _R,
                 ("RESIZE", 3))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1)), "Koch curve")


def koch_snowflake_program() -> RecursiveTurtleProgram:
    """The Koch snowflake (Goldman §2.3): three Koch curves around a triangle, bumps outward.

    The Koch curve's program, driven by ``REPEAT 3 [KOCH TURN -120]`` (the ``start``); the
    turtle walks the triangle clockwise so each bump (on its left) points out.

    >>> koch_snowflake_program().start[:2]
    (('RECURSE', None), ('TURN', -120.0))
    >>> len(koch_snowflake_program().polylines(2)[0]) - 1
    48
    """
    k = koch_curve_program()
    start = _cmds(_R, ("TURN", -120)) * 3
    return RecursiveTurtleProgram(k.body, k.base, "Koch snowflake", start)


def sierpinski_gasket_program() -> RecursiveTurtleProgram:
    """The Sierpinski gasket (Goldman §2.3, fractal gaskets): three half-size gaskets at the
    corners of a triangle.

    level 0: ``REPEAT 3 [FORWARD 1 TURN 120]`` (a triangle); level n: ``REPEAT 3 [RESIZE 1/2
    SIERP RESIZE 2 MOVE 1 TURN 120]``.  The turtle ends in its initial state.

    >>> len(sierpinski_gasket_program().polylines(5))
    243
    """
    body = _cmds(("RESIZE", 0.5), _R, ("RESIZE", 2), ("MOVE", 1), ("TURN", 120)) * 3
    base = _cmds(("FORWARD", 1), ("TURN", 120)) * 3
    return RecursiveTurtleProgram(body, base, "Sierpinski gasket")


def polygon_gasket_program(sides: int = 5) -> RecursiveTurtleProgram:
    """The n-gon gasket (Goldman §2.3, fractal gaskets): ``sides`` copies of the gasket, scaled
    so neighbouring copies touch, at the corners of a regular polygon.

    sides >= 3 (3 gives the Sierpinski gasket; 5 the pentagonal gasket).  The scale is
    ``r = 1 / (2 (1 + sum_{k=1}^{floor(sides/4)} cos(360 k / sides)))`` (1/2, 1/2, 0.382, 1/3
    for 3, 4, 5, 6 sides).  level 0: the polygon; level n: ``REPEAT sides [RESIZE r RECURSE
    RESIZE 1/r MOVE 1 TURN 360/sides]``.  Raises TypeError/ValueError naming ``sides``.

    >>> round(polygon_gasket_program(5).body[0][1], 6)
    0.381966
    """
    sides = as_int(sides, "sides", minimum=3, maximum=24)
    r = 1.0 / (2.0 * (1.0 + sum(math.cos(2 * math.pi * k / sides) for k in range(1, sides // 4 + 1))))
    turn = 360.0 / sides
    body = _cmds(("RESIZE", r), _R, ("RESIZE", 1 / r), ("MOVE", 1), ("TURN", turn)) * sides
    base = _cmds(("FORWARD", 1), ("TURN", turn)) * sides
    names = {3: "Sierpinski gasket", 4: "square gasket", 5: "pentagonal gasket", 6: "hexagonal gasket"}
    return RecursiveTurtleProgram(body, base, names.get(sides, f"{sides}-gon gasket"))


def sierpinski_carpet_program() -> RecursiveTurtleProgram:
    """The Sierpinski carpet (Goldman §2.3, fractal gaskets): eight third-size carpets around
    the border of a square (the middle ninth removed).

    level 0: ``REPEAT 4 [FORWARD 1 TURN 90]``; level n: ``REPEAT 4 [RESIZE 1/3 CARPET MOVE 1
    CARPET MOVE 2 RESIZE 3 TURN 90]``.

    >>> len(sierpinski_carpet_program().polylines(2))
    64
    """
    body = _cmds(("RESIZE", 1 / 3), _R, ("MOVE", 1), _R, ("MOVE", 2), ("RESIZE", 3), ("TURN", 90)) * 4
    base = _cmds(("FORWARD", 1), ("TURN", 90)) * 4
    return RecursiveTurtleProgram(body, base, "Sierpinski carpet")


def c_curve_program() -> RecursiveTurtleProgram:
    """The C-curve (Goldman §2.3, bump fractals): each segment replaced by the two legs of a
    right isosceles triangle, always on the same side.

    level 0: ``FORWARD 1``; level n: ``TURN 45 RESIZE 1/sqrt2 C TURN -90 C TURN 45 RESIZE sqrt2``.

    >>> c_curve_program().polylines(1)[0].round(6) + 0.0
    array([[0. , 0. ],
           [0.5, 0.5],
           [1. , 0. ]])
    """
    s = math.sqrt(0.5)
    body = _cmds(("TURN", 45), ("RESIZE", s), _R, ("TURN", -90), _R, ("TURN", 45), ("RESIZE", math.sqrt(2)))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1)), "C-curve")


def dragon_program() -> RecursiveTurtleProgram:
    """The Heighway dragon (Goldman §2.3, bump fractals): like the C-curve, but the bumps
    alternate sides.

    Two mutually recursive programs, the dragon and its mirror (``("RECURSE", -1)``, every TURN
    of body and base reversed)::

        DRAGON  level n: TURN 45 RESIZE 1/sqrt2 DRAGON TURN -90 MIRROR TURN 45 RESIZE sqrt2
        MIRROR  level n: TURN -45 RESIZE 1/sqrt2 DRAGON TURN 90 MIRROR TURN -45 RESIZE sqrt2
        both    level 0: FORWARD 1

    The mirror program draws the dragon traversed backwards, so level n's turns follow the
    paper-folding sequence: fold a strip of paper in half n times and open every fold to 90
    degrees.

    >>> [round(a) for a in turtle.turning_angles(dragon_program().polylines(3)[0])]
    [-90, -90, 90, -90, -90, 90, 90]
    """
    s = math.sqrt(0.5)
    body = _cmds(("TURN", 45), ("RESIZE", s), _R, ("TURN", -90)) + ((RECURSE, -1),) + \
        _cmds(("TURN", 45), ("RESIZE", math.sqrt(2)))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1)), "dragon curve")


def tree_program(angle: float = 30.0, scale: float = 0.6) -> RecursiveTurtleProgram:
    """A binary fractal tree (Goldman §2.3): a trunk with two smaller trees at its top.

    level 0: ``FORWARD 1 MOVE -1`` (a stick); level n: ``FORWARD 1 TURN angle RESIZE scale TREE
    RESIZE 1/scale TURN -2angle RESIZE scale TREE RESIZE 1/scale TURN angle MOVE -1``.  The
    turtle ends where it started.  angle in (0, 180) degrees; scale in (0, 1).  Raises
    TypeError/ValueError naming the parameter.

    >>> len(tree_program().polylines(3))  # one stroke from the root to each of the 2**3 tips
    8
    """
    angle = as_float(angle, "angle")
    scale = as_float(scale, "scale")
    if not 0 < angle < 180:
        raise ValueError(f"angle must lie in (0, 180) degrees; got {angle}")
    if not 0 < scale < 1:
        raise ValueError(f"scale must lie in (0, 1); got {scale}")
    body = _cmds(("FORWARD", 1), ("TURN", angle), ("RESIZE", scale), _R, ("RESIZE", 1 / scale),
                 ("TURN", -2 * angle), ("RESIZE", scale), _R, ("RESIZE", 1 / scale), ("TURN", angle),
                 ("MOVE", -1))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1), ("MOVE", -1)), "fractal tree")


def bush_program(angle: float = 25.0, scale: float = 0.5) -> RecursiveTurtleProgram:
    """A fractal bush (Goldman §2.3): a stem with a smaller bush to the left half-way up, one to
    the right at the top, and one straight on.

    level 0: ``FORWARD 1 MOVE -1``; level n: ``FORWARD 1/2, TURN angle, RESIZE scale, BUSH, RESIZE
    1/scale, TURN -angle, FORWARD 1/2, TURN -angle, RESIZE scale, BUSH, RESIZE 1/scale, TURN angle,
    RESIZE scale, BUSH, RESIZE 1/scale, MOVE -1``.  angle in (0, 180); scale in (0, 1).

    >>> len(bush_program().polylines(2))  # one stroke per tip
    9
    """
    angle = as_float(angle, "angle")
    scale = as_float(scale, "scale")
    if not 0 < angle < 180:
        raise ValueError(f"angle must lie in (0, 180) degrees; got {angle}")
    if not 0 < scale < 1:
        raise ValueError(f"scale must lie in (0, 1); got {scale}")
    inv = 1 / scale
    body = _cmds(("FORWARD", 0.5), ("TURN", angle), ("RESIZE", scale), _R, ("RESIZE", inv),
                 ("TURN", -angle), ("FORWARD", 0.5), ("TURN", -angle), ("RESIZE", scale), _R,
                 ("RESIZE", inv), ("TURN", angle), ("RESIZE", scale), _R, ("RESIZE", inv), ("MOVE", -1))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1), ("MOVE", -1)), "fractal bush")


#: The fractals of §2.3 by name: name -> constructor taking no arguments.
PROGRAMS = {
    "Sierpinski gasket": sierpinski_gasket_program,
    "pentagonal gasket": lambda: polygon_gasket_program(5),
    "hexagonal gasket": lambda: polygon_gasket_program(6),
    "Sierpinski carpet": sierpinski_carpet_program,
    "Koch curve": koch_curve_program,
    "Koch snowflake": koch_snowflake_program,
    "C-curve": c_curve_program,
    "dragon curve": dragon_program,
    "fractal tree": tree_program,
    "fractal bush": bush_program,
}


def koch_curve(level: int) -> list[np.ndarray]:
    """The strokes of the Koch curve at ``level`` from (0, 0) to (1, 0) (Goldman §2.3).

    >>> koch_curve(1)[0][2].round(6)
    array([0.5     , 0.288675])
    """
    return koch_curve_program().polylines(level)


def koch_snowflake(level: int) -> list[np.ndarray]:
    """The strokes of the Koch snowflake at ``level`` (Goldman §2.3).

    >>> turtle.closes(koch_snowflake(3)[0])
    True
    """
    return koch_snowflake_program().polylines(level)


def sierpinski_gasket(level: int) -> list[np.ndarray]:
    """The 3**level triangles of the Sierpinski gasket at ``level`` (Goldman §2.3).

    >>> len(sierpinski_gasket(4))
    81
    """
    return sierpinski_gasket_program().polylines(level)


def sierpinski_carpet(level: int) -> list[np.ndarray]:
    """The 8**level squares of the Sierpinski carpet at ``level`` (Goldman §2.3).

    >>> len(sierpinski_carpet(1))
    8
    """
    return sierpinski_carpet_program().polylines(level)


def polygon_gasket(level: int, sides: int = 5) -> list[np.ndarray]:
    """The sides**level polygons of the n-gon gasket at ``level`` (Goldman §2.3).

    >>> len(polygon_gasket(2, 5))
    25
    """
    return polygon_gasket_program(sides).polylines(level)


def c_curve(level: int) -> list[np.ndarray]:
    """The C-curve at ``level`` from (0, 0) to (1, 0): one stroke of 2**level segments (Goldman §2.3).

    >>> len(c_curve(10)[0])
    1025
    """
    return c_curve_program().polylines(level)


def dragon(level: int) -> list[np.ndarray]:
    """The Heighway dragon at ``level`` from (0, 0) to (1, 0): 2**level segments (Goldman §2.3).

    >>> len(dragon(10)[0])
    1025
    """
    return dragon_program().polylines(level)


def tree(level: int, angle: float = 30.0, scale: float = 0.6) -> list[np.ndarray]:
    """The fractal tree at ``level``, growing along +x from (0, 0) (Goldman §2.3).

    >>> len(tree(4))
    16
    """
    return tree_program(angle, scale).polylines(level)


def bush(level: int, angle: float = 25.0, scale: float = 0.5) -> list[np.ndarray]:
    """The fractal bush at ``level``, growing along +x from (0, 0) (Goldman §2.3).

    >>> len(bush(1))
    3
    """
    return bush_program(angle, scale).polylines(level)
