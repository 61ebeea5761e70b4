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
from goldman_lib.angles import cos_sin_degrees
from goldman_lib.validation import (MAX_ITEMS, as_float, as_int, as_points, as_tolerance, largest_within,
                                    within_budget)

__all__ = [
    "RECURSE", "MAX_LEVEL", "RecursiveTurtleProgram",
    "koch_curve_program", "koch_snowflake_program", "sierpinski_gasket_program",
    "sierpinski_carpet_program", "polygon_gasket_program", "c_curve_program", "dragon_program",
    "quadratic_koch_program", "quadratic_koch",
    "tree_program", "bush_program", "PROGRAMS",
    "koch_curve", "koch_snowflake", "sierpinski_gasket", "sierpinski_carpet", "polygon_gasket",
    "c_curve", "dragon", "tree", "bush",
    "state_change", "Loop", "loop_analysis", "loop_period", "repeat_closes",
    "similarity_dimension", "recursion_scales", "program_dimension",
    "ink_length", "chord_angles", "difference_quotients", "headings_at",
    "BASE_CASES", "points_on", "base_case_distances", "as_commands",
]

#: The name of the recursive call in a program's ``body``.
RECURSE = "RECURSE"
#: The highest level any recursive turtle program is run, counted or measured at: a program
#: whose command count does not grow (one RECURSE) still does work per level, and 200 levels
#: is far past any visible difference.  Programs that grow are bounded much lower by the
#: command budget :data:`goldman_lib.turtle.MAX_COMMANDS` (the Koch curve at level 8).
MAX_LEVEL = 200
_CODES = {name: code for code, name in enumerate(turtle.COMMANDS)}


# ---------------------------------------------------------------------------------------------
# Recursive turtle programs (§2.3)
# ---------------------------------------------------------------------------------------------

def as_commands(seq, name: str, *, allow_recurse: bool) -> tuple:
    """A recursive turtle program's commands (Goldman §2.3): a sequence of ``(command, value)`` pairs
    checked (known commands, finite values, RECURSE only where ``allow_recurse``) and returned as a
    tuple of tuples with upper-case commands; TypeError/ValueError naming ``name`` otherwise.

    >>> as_commands([("forward", 1), ("TURN", 60)], "base", allow_recurse=False)
    (('FORWARD', 1.0), ('TURN', 60.0))
    """
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
        value = turtle.command_value(value, f"{name}[{i}] value")
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
            parts.append(f"{c} {turtle.format_number(v)}")
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
        self.body = as_commands(body, "body", allow_recurse=True)
        self.base = as_commands(base, "base", allow_recurse=False)
        if not any(c == RECURSE for c, _ in self.body):
            raise ValueError("body must RECURSE at least once (otherwise the program is not recursive)")
        if not isinstance(name, str):
            raise TypeError(f"name must be a string; got {type(name).__name__}")
        self.name = name
        default = ((RECURSE, None),)
        self.start = default if start is None else as_commands(start, "start", allow_recurse=True)
        self._mirrored = any(c == RECURSE and v == -1 for c, v in self.body + self.start)

    # -- sizes ---------------------------------------------------------------------------------
    def count(self, level: int) -> int:
        """How many turtle commands level ``level`` executes (an exact int; nothing is built).
        level: 0 <= level <= :data:`MAX_LEVEL`.

        >>> koch_curve_program().count(8)
        174761
        """
        level = _level(level)
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
        max_commands = as_int(max_commands, "max_commands", minimum=1, maximum=MAX_ITEMS)
        best = largest_within(lambda v: self._sizes(v)[-1] if v <= MAX_LEVEL else max_commands + 1,
                              max_commands)
        return max(best, 0)

    # -- expansion -----------------------------------------------------------------------------
    def expand(self, level: int, *, max_commands: int = MAX_COMMANDS) -> tuple[np.ndarray, np.ndarray]:
        """The flat program that level ``level`` executes (Goldman §2.3), as
        :func:`goldman_lib.turtle.expand` returns it.

        level: int >= 0.  Returns ``(codes, values)``, two ``(m,)`` arrays (int8 codes of
        FORWARD/MOVE/TURN/RESIZE, float values).  Each level is built from the one below by
        concatenating numpy arrays.  Raises ValueError if the drawing would execute more than
        ``max_commands`` commands (default :data:`goldman_lib.turtle.MAX_COMMANDS`, at most
        :data:`goldman_lib.validation.MAX_ITEMS`), naming the highest level that fits
        (:meth:`max_level`; never above :data:`MAX_LEVEL`).

        >>> codes, values = koch_curve_program().expand(1)
        >>> codes.tolist()
        [3, 0, 2, 0, 2, 0, 2, 0, 3]
        >>> koch_curve_program().expand(9)
        Traceback (most recent call last):
        ...
        ValueError: level 9 of the Koch curve would execute 699,049 turtle commands, more than the limit of 200,000; the highest level that fits is 8
        """
        level = as_int(level, "level", minimum=0)
        max_commands = as_int(max_commands, "max_commands", minimum=1, maximum=MAX_ITEMS)
        highest = self.max_level(max_commands)
        if level > highest:
            label = f"the {self.name}" if self.name else "this program"
            over = highest + 1
            if over > MAX_LEVEL:
                raise ValueError(f"level must be <= {MAX_LEVEL} (the highest level any recursive program is run "
                                 f"at); got {level}")
            total = self._sizes(over)[-1]
            if level == over:
                raise ValueError(f"level {level} of {label} would execute {total:,} turtle commands, more than "
                                 f"the limit of {max_commands:,}; the highest level that fits is {highest}")
            raise ValueError(f"level {level} of {label} would execute far more than {max_commands:,} turtle "
                             f"commands, the limit (level {over} already executes {total:,}); the highest "
                             f"level that fits is {highest}")
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
        p0, w0 = turtle.as_state(point, direction)
        codes, values = self.expand(level, max_commands=max_commands)
        return turtle.trace_arrays(codes, values, p0, w0)

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

def _level(level, name: str = "level") -> int:
    """A level for counting and measuring: an int in [0, MAX_LEVEL]."""
    level = as_int(level, name, minimum=0)
    if level > MAX_LEVEL:
        raise ValueError(f"{name} must be <= {MAX_LEVEL} (the highest level any recursive program is run, "
                         f"counted or measured at); got {level}")
    return level


def _levels(program: RecursiveTurtleProgram, levels) -> list[int]:
    """A list of levels, each drawable and all together at most MAX_ITEMS commands."""
    if isinstance(levels, (str, bytes)):
        raise TypeError(f"levels must be an int or a sequence of ints; got {type(levels).__name__}")
    arr = np.atleast_1d(np.asarray(levels, dtype=object))
    if arr.ndim != 1 or arr.size == 0:
        raise ValueError(f"levels must be an int or a non-empty 1-D sequence of ints; got shape {arr.shape}")
    if arr.size > MAX_LEVEL + 1:
        raise ValueError(f"levels must hold at most {MAX_LEVEL + 1} entries; got {arr.size}")
    highest = program.max_level()
    out = []
    for i, n in enumerate(arr):
        n = as_int(n, f"levels[{i}]", minimum=0)
        if n > highest:
            try:
                program.expand(n)   # raises, naming the level that fits
            except ValueError as exc:
                shown = f"{n:,}" if n < 10 ** 15 else f"{float(n):.3g}"
                reason = str(exc).replace(f"level {n} ", f"level {shown} ", 1)
                raise ValueError(f"levels[{i}] must be <= {highest}: {reason}") from None
        out.append(n)
    total = sum(program.count(n) for n in out)
    if total > MAX_ITEMS:
        raise ValueError(f"levels would draw {total:,} turtle commands in all, over the limit of {MAX_ITEMS:,}; "
                         f"ask for fewer levels")
    return out


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


def quadratic_koch_program() -> RecursiveTurtleProgram:
    """The quadratic Koch curve (Goldman §2.3, bump fractals; the "square bump" curve): each
    segment replaced by five segments one third as long -- forward, up, forward, down, forward --
    with the square bump on the turtle's left.

    level 0: ``FORWARD 1``; level n: ``RESIZE 1/3 Q TURN 90 Q TURN -90 Q TURN -90 Q TURN 90 Q
    RESIZE 3``.  From ``(0, 0)`` heading ``(1, 0)`` it ends at ``(1, 0)``; level n draws ``5**n``
    segments of length ``3**-n``.  (Chapter 2's programming project asks the learner to write it.)

    >>> quadratic_koch_program().polylines(1)[0].round(6) + 0.0
    array([[0.      , 0.      ],
           [0.333333, 0.      ],
           [0.333333, 0.333333],
           [0.666667, 0.333333],
           [0.666667, 0.      ],
           [1.      , 0.      ]])
    """
    body = _cmds(("RESIZE", 1 / 3), _R, ("TURN", 90), _R, ("TURN", -90), _R, ("TURN", -90), _R,
                 ("TURN", 90), _R, ("RESIZE", 3))
    return RecursiveTurtleProgram(body, _cmds(("FORWARD", 1)), "quadratic Koch curve")


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
    if not 1 / turtle.MAX_VALUE <= scale < 1:
        raise ValueError(f"scale must lie in [1e-06, 1) (its inverse is a RESIZE factor, at most "
                         f"{turtle.MAX_VALUE:g}); got {scale}")
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
    if not 1 / turtle.MAX_VALUE <= scale < 1:
        raise ValueError(f"scale must lie in [1e-06, 1) (its inverse is a RESIZE factor, at most "
                         f"{turtle.MAX_VALUE:g}); got {scale}")
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

    level: 0 <= level <= 8, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> koch_curve(1)[0][2].round(6)
    array([0.5     , 0.288675])
    """
    return koch_curve_program().polylines(level)


def koch_snowflake(level: int) -> list[np.ndarray]:
    """The strokes of the Koch snowflake at ``level`` (Goldman §2.3).

    level: 0 <= level <= 7, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> turtle.closes(koch_snowflake(3)[0])
    True
    """
    return koch_snowflake_program().polylines(level)


def sierpinski_gasket(level: int) -> list[np.ndarray]:
    """The 3**level triangles of the Sierpinski gasket at ``level`` (Goldman §2.3).

    level: 0 <= level <= 8, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(sierpinski_gasket(4))
    81
    """
    return sierpinski_gasket_program().polylines(level)


def sierpinski_carpet(level: int) -> list[np.ndarray]:
    """The 8**level squares of the Sierpinski carpet at ``level`` (Goldman §2.3).

    level: 0 <= level <= 4, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(sierpinski_carpet(1))
    8
    """
    return sierpinski_carpet_program().polylines(level)


def polygon_gasket(level: int, sides: int = 5) -> list[np.ndarray]:
    """The sides**level polygons of the n-gon gasket at ``level`` (Goldman §2.3).

    level: 0 <= level <= 5 for 5 or 6 sides (lower for more sides), the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(polygon_gasket(2, 5))
    25
    """
    return polygon_gasket_program(sides).polylines(level)


def c_curve(level: int) -> list[np.ndarray]:
    """The C-curve at ``level`` from (0, 0) to (1, 0): one stroke of 2**level segments (Goldman §2.3).

    level: 0 <= level <= 15, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(c_curve(10)[0])
    1025
    """
    return c_curve_program().polylines(level)


def quadratic_koch(level: int) -> list[np.ndarray]:
    """The strokes of the quadratic Koch curve at ``level`` from (0, 0) to (1, 0) (Goldman §2.3).

    >>> len(quadratic_koch(3)[0]) - 1
    125
    """
    return quadratic_koch_program().polylines(level)


def dragon(level: int) -> list[np.ndarray]:
    """The Heighway dragon at ``level`` from (0, 0) to (1, 0): 2**level segments (Goldman §2.3).

    level: 0 <= level <= 15, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(dragon(10)[0])
    1025
    """
    return dragon_program().polylines(level)


def tree(level: int, angle: float = 30.0, scale: float = 0.6) -> list[np.ndarray]:
    """The fractal tree at ``level``, growing along +x from (0, 0) (Goldman §2.3).

    level: 0 <= level <= 14, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(tree(4))
    16
    """
    return tree_program(angle, scale).polylines(level)


def bush(level: int, angle: float = 25.0, scale: float = 0.5) -> list[np.ndarray]:
    """The fractal bush at ``level``, growing along +x from (0, 0) (Goldman §2.3).

    level: 0 <= level <= 9, the highest level whose drawing runs at most
    :data:`goldman_lib.turtle.MAX_COMMANDS` (200,000) turtle commands; beyond it a ValueError
    names the level that fits (:meth:`RecursiveTurtleProgram.max_level`).

    >>> len(bush(1))
    3
    """
    return bush_program(angle, scale).polylines(level)


# ---------------------------------------------------------------------------------------------
# The looping lemmas (§2.2)
# ---------------------------------------------------------------------------------------------

def _flat_program(program, name: str = "program") -> tuple[np.ndarray, np.ndarray]:
    """Codes and values of a turtle program: text, a parsed Program, or (command, value) pairs."""
    if isinstance(program, (str, turtle.Program)):
        return turtle.expand(program)
    commands = as_commands(program, name, allow_recurse=False)
    return _flat(commands, 1.0)


def state_change(program) -> tuple[float, float, np.ndarray]:
    """What one run of a (non-recursive) turtle program does to the turtle's state (Goldman §2.2).

    program: turtle-language text, a parsed :class:`goldman_lib.turtle.Program`, or a sequence
    of ``(command, value)`` pairs.  Returns ``(T, S, d)``: the total turning ``T`` (degrees), the
    total RESIZE factor ``S`` and the displacement ``d`` ``(2,)`` of a turtle that starts at the
    origin heading ``(1, 0)``.  From any state ``(P, w)`` the program ends in
    ``(P + d_1 w + d_2 w_perp, S rot_T(w))``, ``w_perp`` being ``w`` turned 90 degrees.

    >>> T, S, d = state_change("FORWARD 1 TURN 90 FORWARD 1 RESIZE 2")
    >>> T, S, d
    (90.0, 2.0, array([1., 1.]))
    """
    codes, values = _flat_program(program)
    t = turtle.trace_arrays(codes, values, np.zeros(2), np.array([1.0, 0.0]))
    scale = float(np.prod(values[codes == RESIZE])) if codes.size else 1.0
    return t.total_turning, scale, t.point


def loop_period(angle: float, *, max_period: int = 10_000) -> int | None:
    """The least ``k >= 1`` with ``k * angle`` a multiple of 360 (Goldman §2.2), or None.

    angle: degrees.  If ``angle = 360 p/q`` in lowest terms the answer is ``q``; an angle that
    is not such a rational multiple of 360 with ``q <= max_period`` (up to rounding in the
    ninth decimal) gives None: the turtle never returns to its heading.

    >>> loop_period(144), loop_period(360 / 7), loop_period(720), loop_period(2 ** 0.5)
    (5, 7, 1, None)
    """
    angle = as_float(angle, "angle")
    max_period = as_int(max_period, "max_period", minimum=1)
    frac = Fraction(angle / 360.0).limit_denominator(max_period)
    if abs(float(frac) * 360.0 - angle) > 1e-9 * max(1.0, abs(angle)):
        return None
    return frac.denominator


@dataclass(frozen=True)
class Loop:
    """What repeating a turtle program does (see :func:`loop_analysis`).

    total_turning, scale, displacement: the state change of one pass (:func:`state_change`).
    period: the least number of passes after which the turtle is back in its initial state, or
    None if it never is.  winding: ``period * total_turning / 360``, how many times the closed
    figure winds around its centre (None if it never closes).  center: ``(2,)`` the point the
    figure turns about (the fixed point of one pass; None for a pure translation).  kind: one of
    ``"polygon"``, ``"star"``, ``"retrace"`` (closes after one pass), ``"drift"`` (moves off in a
    straight line), ``"spiral"`` (RESIZE != 1), ``"never closes"`` (turning not a rational
    multiple of 360).
    """

    total_turning: float
    scale: float
    displacement: np.ndarray
    period: int | None
    winding: int | None
    center: np.ndarray | None
    kind: str


def loop_analysis(program, *, tol: float = 1e-9) -> Loop:
    """The looping lemmas (Goldman §2.2): whether and when ``REPEAT k [program]`` closes.

    One pass of a program turns the turtle by ``T``, resizes it by ``S`` and moves it by ``d``
    (:func:`state_change`).  With ``S = 1``:

    * if ``T`` is not a multiple of 360, repeating the program ``k`` times returns the turtle to
      its initial state **if and only if** ``k T`` is a multiple of 360; the least such ``k`` is
      the period ``q`` of ``T = 360 p/q``.  Every pass is the previous one rotated by ``T`` about
      one centre ``c = d / (1 - e^{iT})``, so the figure has ``q``-fold rotational symmetry: for
      ``FORWARD s TURN a`` it is the regular polygon (``p = 1``) or star polygon ``{q/p}``;
    * if ``T`` is a multiple of 360 each pass is the previous one translated by ``d``: the path
      closes only if ``d = 0``, and otherwise drifts off in a straight line.

    With ``S != 1`` every pass is the previous one turned by ``T`` and scaled by ``S`` about a
    centre: a spiral that never closes (unless ``d = 0``).  program: text, a parsed Program or
    ``(command, value)`` pairs.  tol: tolerance on ``|d|`` and ``|S - 1|``.  Returns a
    :class:`Loop`.

    >>> L = loop_analysis("FORWARD 1 TURN 144")
    >>> L.period, L.winding, L.kind
    (5, 2, 'star')
    >>> loop_analysis("FORWARD 1 TURN 360").kind
    'drift'
    """
    tol = as_tolerance(tol)
    T, S, d = state_change(program)
    c_, s_ = cos_sin_degrees(np.array([T]))
    rot = complex(c_[0], s_[0]) * S
    dz = complex(d[0], d[1])
    center = None
    if abs(1 - rot) > tol:
        cz = dz / (1 - rot)
        center = np.array([cz.real, cz.imag])
    moved = abs(dz) > tol
    if abs(S - 1) > tol:
        return Loop(T, S, d, 1 if not moved else None, None, center, "spiral" if moved else "retrace")
    if loop_period(T) == 1 or abs(1 - rot) <= tol:
        if moved:
            return Loop(T, S, d, None, None, None, "drift")
        return Loop(T, S, d, 1, round(T / 360), None, "retrace")
    q = loop_period(T)
    if q is None:
        return Loop(T, S, d, None, None, center, "never closes")
    winding = int(round(q * T / 360))
    if not moved:
        return Loop(T, S, d, 1, None, center, "retrace")
    kind = "polygon" if abs(winding) == 1 else "star"
    return Loop(T, S, d, q, winding, center, kind)


def repeat_closes(program, k: int, *, tol: float = 1e-9) -> bool:
    """Run ``REPEAT k [program]`` with the turtle and say whether it ends in its initial state
    (position and heading within ``tol``) -- the direct numerical check of the looping lemmas
    (Goldman §2.2).

    program: text, a parsed Program or ``(command, value)`` pairs.  k >= 1, with ``k`` times the
    program's commands at most :data:`goldman_lib.turtle.MAX_COMMANDS`.  tol > 0.

    >>> repeat_closes("FORWARD 1 TURN 144", 5), repeat_closes("FORWARD 1 TURN 144", 4)
    (True, False)
    """
    tol = as_tolerance(tol)
    codes, values = _flat_program(program)
    k = within_budget(k, "k", cost=lambda v: v * codes.size, what=f"REPEAT k of {codes.size} commands",
                      unit="commands", limit=MAX_COMMANDS, minimum=1)
    t = turtle.trace_arrays(np.tile(codes, k), np.tile(values, k), np.zeros(2), np.array([1.0, 0.0]))
    return bool(np.hypot(*t.point) <= tol and np.hypot(*(t.direction - [1.0, 0.0])) <= tol)


# ---------------------------------------------------------------------------------------------
# Fractal dimension (§3.2)
# ---------------------------------------------------------------------------------------------

def similarity_dimension(scales) -> float:
    """The similarity dimension ``D`` of a fractal made of copies of itself scaled by ``s_i``:
    the root of ``sum_i s_i**D = 1`` (Goldman §3.2.1).

    scales: ``(N,)`` the scale factors, each in (0, 1).  Equal scales give the closed form
    ``D = log N / log(1/s)``; unequal ones are solved by Newton's method safeguarded by
    bisection inside the bracket ``[log N / log(1/min s), log N / log(1/max s)]``.  Raises
    ValueError if the list is empty or a scale is not in (0, 1): then no ``D >= 0`` solves the
    equation (a scale >= 1 keeps the sum above 1; a scale 0 is a point, leave it out).

    >>> round(similarity_dimension([1/3] * 4), 12)  # the Koch curve: log 4 / log 3
    1.261859507143
    >>> similarity_dimension([0.5, 0.25, 0.25])
    1.0
    >>> similarity_dimension([0.5, 1.0])
    Traceback (most recent call last):
    ...
    ValueError: no dimension D solves sum(s_i**D) = 1: scales[1] = 1.0 is not < 1, so the sum is at least 1 + 0.5**D > 1 for every D >= 0 (every copy must be smaller than the whole)
    """
    if isinstance(scales, (str, bytes)):
        raise TypeError("scales must be a sequence of numbers, not a string")
    from goldman_lib.validation import MAX_ITERATIONS, as_float_array
    s = as_float_array(scales, "scales")
    if s.ndim > 1:
        raise ValueError(f"scales must be a flat list of scale factors; got shape {s.shape}")
    if s.size == 0:
        raise ValueError("scales must hold at least one scale factor")
    if s.size > MAX_ITERATIONS:
        raise ValueError(f"scales must hold at most {MAX_ITERATIONS:,} scale factors (each Newton step sums them "
                         f"all); got {s.size:,}")
    s = as_points(s.reshape(-1, 1), "scales", ndim=2, dim=1)[:, 0]
    bad = np.flatnonzero(s <= 0)
    if bad.size:
        i = int(bad[0])
        raise ValueError(f"scales must be > 0; scales[{i}] = {s[i]} (a copy of scale 0 is a point: leave it out; "
                         f"use the absolute value for a reflected copy)")
    big = np.flatnonzero(s >= 1)
    if big.size:
        i = int(big[0])
        rest = [f"{turtle.format_number(x)}**D" for j, x in enumerate(s[:5]) if j != i]
        others = " + ".join(rest[:3]) + (" + ..." if s.size > 4 else "") if rest else "0"
        raise ValueError(f"no dimension D solves sum(s_i**D) = 1: scales[{i}] = {s[i]} is not < 1, so the sum "
                         f"is at least 1 + {others} > 1 for every D >= 0 (every copy must be smaller than "
                         f"the whole)")
    n = s.size
    if n == 1:
        return 0.0
    if np.all(s == s[0]):
        return math.log(n) / math.log(1 / s[0])
    logs = np.log(s)
    lo = math.log(n) / -float(logs.min())
    hi = math.log(n) / -float(logs.max())
    D = 0.5 * (lo + hi)
    for _ in range(200):
        terms = np.exp(D * logs)
        f = float(terms.sum()) - 1.0
        if f > 0:
            lo = D
        else:
            hi = D
        if f == 0 or hi - lo <= 4e-16 * hi:
            break
        fp = float((terms * logs).sum())
        step = D - f / fp
        D = step if lo < step < hi else 0.5 * (lo + hi)
    return float(D)


def _net_scales(program: RecursiveTurtleProgram, level: int) -> list[float]:
    """The total RESIZE factor of one run of the program at levels 0..level."""
    plain = [v for c, v in program.body if c == "RESIZE"]
    calls = sum(1 for c, _ in program.body if c == RECURSE)
    f = float(np.prod(plain)) if plain else 1.0
    nets = [float(np.prod([v for c, v in program.base if c == "RESIZE"])) if program.base else 1.0]
    for _ in range(level):
        try:
            nets.append(f * nets[-1] ** calls)
        except OverflowError:
            nets.append(math.inf)
    return nets


def _as_program(program) -> RecursiveTurtleProgram:
    if not isinstance(program, RecursiveTurtleProgram):
        raise TypeError(f"program must be a RecursiveTurtleProgram; got {type(program).__name__}")
    return program


def recursion_scales(program) -> np.ndarray:
    """The scale factor of each recursive call of a recursive turtle program (Goldman §3.2.2).

    Each RECURSE in the body draws a copy of the fractal scaled by the product of the RESIZE
    factors in force at that moment (absolute value).  program: a :class:`RecursiveTurtleProgram`
    whose body and base each leave the turtle's step size as they found it (total RESIZE 1),
    as the book's programs do.  Returns ``(N,)``, one scale per RECURSE.  Raises TypeError for
    another type and ValueError for a program that changes the step size.

    >>> recursion_scales(sierpinski_gasket_program())
    array([0.5, 0.5, 0.5])
    """
    program = _as_program(program)
    for part, cmds in (("body", program.body), ("base", program.base)):
        f = float(np.prod([v for c, v in cmds if c == "RESIZE"])) if cmds else 1.0
        if abs(f - 1) > 1e-9:
            raise ValueError(f"the {part} of the program must restore the turtle's step size (total RESIZE 1) "
                             f"for the copies to be similar; its RESIZE factors multiply to {f:.6g}")
    scale, out = 1.0, []
    for c, v in program.body:
        if c == "RESIZE":
            scale *= v
        elif c == RECURSE:
            out.append(abs(scale))
    return np.array(out)


def program_dimension(program) -> float:
    """The similarity dimension of the fractal a recursive turtle program draws (Goldman §3.2.2):
    :func:`similarity_dimension` of its :func:`recursion_scales`.

    This is the fractal's dimension when the copies do not overlap too much (the gaskets, the
    Koch curve, the C-curve and the dragon; a tree's branches also add its trunk, dimension 1).
    Raises as the two functions it calls.

    >>> round(program_dimension(koch_curve_program()), 12), round(program_dimension(dragon_program()), 12)
    (1.261859507143, 2.0)
    """
    return similarity_dimension(recursion_scales(program))


# ---------------------------------------------------------------------------------------------
# Length (§3.2) and non-differentiability (§3.3)
# ---------------------------------------------------------------------------------------------

def ink_length(program, level: int, *, step: float = 1.0) -> float:
    """The length of the strokes level ``level`` of a recursive turtle program draws, from the
    recursion ``L_n = (FORWARD length of the body) + sum_i s_i L_{n-1}`` without drawing anything
    (Goldman §3.2: the Koch curve's length ``(4/3)**n`` grows without bound).

    program: a :class:`RecursiveTurtleProgram`; 0 <= level <= :data:`MAX_LEVEL`; step: ``|w|`` at
    the start, > 0.  Counts overlapping strokes as often as they are drawn.  Raises ValueError
    naming ``level`` if the length overflows a float (a length that grows like ``(4/3)**n``
    does beyond level 2,466, so the bound :data:`MAX_LEVEL` keeps it finite for the book's fractals).

    >>> round(ink_length(koch_curve_program(), 3), 12), round((4 / 3) ** 3, 12)
    (2.37037037037, 2.37037037037)
    """
    program = _as_program(program)
    level = _level(level)
    step = as_float(step, "step", positive=True)
    with np.errstate(over="ignore", invalid="ignore"):
        length = step * _ink_length(program, level)
    if not math.isfinite(length):
        raise ValueError(f"step is too large: the ink length at step {step:g} overflows a float; use a smaller step")
    return length


def _ink_length(program, level: int) -> float:
    nets = _net_scales(program, level)

    def run(cmds, sub_len, sub_net):
        scale, total = 1.0, 0.0
        for c, v in cmds:
            if c == "RESIZE":
                scale *= v
            elif c == "FORWARD":
                total += abs(v * scale)
            elif c == RECURSE:
                total += abs(scale) * sub_len
                scale *= sub_net
        return total

    L = run(program.base, 0.0, 1.0)
    for n in range(1, level + 1):
        L = run(program.body, L, nets[n - 1])
    L = run(program.start, L, nets[level])
    if not math.isfinite(L):
        raise ValueError(f"level {level} is too high for this program: its ink length overflows a float "
                         f"(the strokes or RESIZE factors grow too fast); use a lower level")
    return L


def chord_angles(polyline, anchor: int, offsets) -> np.ndarray:
    """Directions (degrees, in (-180, 180]) of the chords from ``polyline[anchor]`` to
    ``polyline[anchor + h]`` for each ``h`` in ``offsets`` (Goldman §3.3).

    A curve with a tangent at the anchor has chord directions that converge as ``h -> 0``; the
    Koch curve's do not.  polyline: ``(k, 2)``.  anchor: an index.  offsets: nonzero ints with
    ``anchor + h`` inside the polyline.  Returns ``(len(offsets),)``.  Raises ValueError naming
    an offset that leaves the polyline or is 0.

    >>> chord_angles(koch_curve(2)[0], 0, [16, 8, 4, 2]).round(6) + 0.0
    array([ 0., 30.,  0., 30.])
    """
    p, anchor, offs = _chord_args(polyline, anchor, offsets)
    v = p[anchor + offs] - p[anchor]
    ang = np.degrees(np.arctan2(v[:, 1], v[:, 0]))
    ang[ang == -180.0] = 180.0
    return ang


def _chord_args(polyline, anchor, offsets):
    p = as_points(polyline, "polyline", ndim=2, dim=2, min_count=2)
    anchor = as_int(anchor, "anchor", minimum=0, maximum=len(p) - 1)
    try:
        offs = np.asarray(offsets)
    except (TypeError, ValueError):
        raise TypeError("offsets must be a non-empty 1-D sequence of integers") from None
    if offs.ndim != 1 or offs.size == 0 or not np.issubdtype(offs.dtype, np.integer):
        raise TypeError("offsets must be a non-empty 1-D sequence of integers")
    for i, h in enumerate(offs):
        if h == 0 or not 0 <= anchor + h < len(p):
            raise ValueError(f"offsets[{i}] = {int(h)}: anchor + offset must be another index of the polyline "
                             f"(0..{len(p) - 1}); got {anchor + int(h)}")
    return p, anchor, offs.astype(int)


def difference_quotients(polyline, anchor: int, offsets) -> np.ndarray:
    """``|P(t + h) - P(t)| / |h|`` along a polyline whose vertices sit at the parameters
    ``t = index / (k - 1)`` (Goldman §3.3).

    For the Koch curve at level n the vertices are equally spaced along the curve, so these are
    the difference quotients of its arc-fraction parametrisation; at ``t = 0`` with
    ``h = 4**-j`` they equal ``(4/3)**j``: no derivative.  Arguments as :func:`chord_angles`.

    >>> difference_quotients(koch_curve(3)[0], 0, [64, 16, 4, 1]).round(6)
    array([1.      , 1.333333, 1.777778, 2.37037 ])
    """
    p, anchor, offs = _chord_args(polyline, anchor, offsets)
    h = offs / (len(p) - 1)
    return np.hypot(*(p[anchor + offs] - p[anchor]).T) / np.abs(h)


def headings_at(program, t: float, levels) -> np.ndarray:
    """The turtle's heading (degrees, in (-180, 180]) when it has drawn the fraction ``t`` of
    the level-n curve, for each n in ``levels`` (Goldman §3.3).

    For a smooth limit curve these headings would converge (to the tangent's direction); for
    the Koch curve they keep jumping by multiples of 60 degrees.  program: a
    :class:`RecursiveTurtleProgram` that draws one stroke; t in [0, 1); levels: ints >= 0, each
    at most the program's :meth:`~RecursiveTurtleProgram.max_level`, and all of them together
    drawing at most :data:`goldman_lib.validation.MAX_ITEMS` turtle commands.

    >>> headings_at(koch_curve_program(), 0.4, [0, 1, 2, 3, 4]).round(6) + 0.0
    array([ 0., 60.,  0., 60.,  0.])
    """
    program = _as_program(program)
    t = as_float(t, "t")
    if not 0 <= t < 1:
        raise ValueError(f"t must lie in [0, 1); got {t}")
    levels = _levels(program, levels)
    out = []
    for n in levels:
        polys = program.polylines(n)
        if len(polys) != 1:
            raise ValueError(f"headings_at needs a program that draws one stroke; level {int(n)} draws {len(polys)}")
        seg = np.diff(polys[0], axis=0)
        lens = np.hypot(seg[:, 0], seg[:, 1])
        cum = np.cumsum(lens)
        i = int(np.searchsorted(cum, t * cum[-1], side="right"))
        i = min(i, len(seg) - 1)
        ang = math.degrees(math.atan2(seg[i, 1], seg[i, 0]))
        out.append(180.0 if ang == -180.0 else ang)
    return np.array(out)


# ---------------------------------------------------------------------------------------------
# Attraction: the base case does not matter (§3.4)
# ---------------------------------------------------------------------------------------------

#: Alternative base cases (name -> commands) for two fractals; each changes the turtle's state
#: exactly as the book's base case does, so all converge to the same fractal (Goldman §3.4).
BASE_CASES = {
    "Koch curve": {
        "segment (the book's)": (("FORWARD", 1.0),),
        "tent": (("TURN", 60.0), ("FORWARD", 1.0), ("TURN", -120.0), ("FORWARD", 1.0), ("TURN", 60.0)),
        "square bump": (("FORWARD", 1 / 3), ("TURN", 90.0), ("FORWARD", 1 / 3), ("TURN", -90.0),
                        ("FORWARD", 1 / 3), ("TURN", -90.0), ("FORWARD", 1 / 3), ("TURN", 90.0),
                        ("FORWARD", 1 / 3)),
        "dip below": (("TURN", -45.0), ("FORWARD", math.sqrt(0.5)), ("TURN", 90.0),
                      ("FORWARD", math.sqrt(0.5)), ("TURN", -45.0)),
        "zigzag": (("TURN", 30.0),) + (("FORWARD", 1 / (4 * math.cos(math.pi / 6))), ("TURN", -60.0),
                                        ("FORWARD", 1 / (4 * math.cos(math.pi / 6))), ("TURN", 60.0)) * 2
                   + (("TURN", -30.0),),
    },
    "Sierpinski gasket": {
        "triangle (the book's)": (("FORWARD", 1.0), ("TURN", 120.0)) * 3,
        "square": (("FORWARD", 1.0), ("TURN", 90.0)) * 4,
        "five-pointed star": (("FORWARD", 1.0), ("TURN", 144.0)) * 5,
        "stick": (("FORWARD", 1.0), ("MOVE", -1.0)),
        "hexagon": (("FORWARD", 0.5), ("TURN", 60.0)) * 6,
    },
}


def points_on(polylines, per_segment: int = 4) -> np.ndarray:
    """Points along strokes: every vertex plus ``per_segment - 1`` equally spaced points inside
    each segment, so the Hausdorff distance between two drawings is measured between the
    curves, not only their corners (Goldman §3.4).

    polylines: a ``(k, 2)`` array or a non-empty list of them.  per_segment >= 1, with the result's
    ``m`` points at most :data:`goldman_lib.validation.MAX_ITEMS`.  Returns ``(m, 2)``.

    >>> points_on([np.array([[0, 0], [1, 0]])], 4)[:, 0]
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    per_segment = as_int(per_segment, "per_segment", minimum=1)
    polys = turtle.as_polylines(polylines)
    if not polys:
        raise ValueError("polylines must hold at least one polyline; got an empty list")
    segments, ends = sum(len(p) - 1 for p in polys), len(polys)
    per_segment = within_budget(per_segment, "per_segment", cost=lambda v: v * segments + ends,
                                what="the points", minimum=1)
    t = np.arange(per_segment) / per_segment
    parts = []
    for p in polys:
        a, b = p[:-1], p[1:]
        parts.append((a[:, None, :] + t[None, :, None] * (b - a)[:, None, :]).reshape(-1, 2))
        parts.append(p[-1:])
    return np.concatenate(parts)


def base_case_distances(program, bases, levels, *, per_segment: int = 2) -> np.ndarray:
    """Hausdorff distances between the drawings of one recursive program run with different
    base cases (Goldman §3.4): at level n they shrink like ``s**n`` (the largest recursion
    scale), because the fractal does not depend on the base case.

    program: a :class:`RecursiveTurtleProgram`.  bases: a list of base cases (sequences of
    ``(command, value)`` pairs); each is compared with the program's own base.  levels: ints
    >= 0.  Returns ``(len(bases), len(levels))``.  Cost: quadratic in the points drawn, keep
    levels small (Koch <= 5, gasket <= 5).  Raises ValueError if a base draws nothing.

    >>> d = base_case_distances(koch_curve_program(), [BASE_CASES["Koch curve"]["tent"]], [0, 1, 2])
    >>> (d[0, 1:] / d[0, :-1]).round(2)
    array([0.33, 0.33])
    """
    from goldman_lib.fixed_point import hausdorff_distance

    program = _as_program(program)
    per_segment = as_int(per_segment, "per_segment", minimum=1)
    levels = _levels(program, levels)
    if isinstance(bases, (str, bytes)) or not hasattr(bases, "__len__"):
        raise TypeError(f"bases must be a list of base cases; got {type(bases).__name__}")
    others = [program.with_base(as_commands(b, f"bases[{i}]", allow_recurse=False)) for i, b in enumerate(bases)]
    out = np.zeros((len(others), len(levels)))
    for j, n in enumerate(levels):
        ref_polys = program.polylines(n)
        if not ref_polys:
            raise ValueError("the program's own base draws nothing")
        ref = points_on(ref_polys, per_segment)
        for i, q in enumerate(others):
            polys = q.polylines(n)
            if not polys:
                raise ValueError(f"bases[{i}] draws nothing (only MOVE and TURN): there is no drawing to compare")
            out[i, j] = hausdorff_distance(ref, points_on(polys, per_segment))
    return out


__all__ += ["program_text", "program_codes"]


def program_text(commands) -> str:
    """A recursive turtle program's commands as one line of text (Goldman §2.3): ``FORWARD 1 TURN 60
    RECURSE ...``, a mirrored recursion (``("RECURSE", -1)``) written ``RECURSE(mirror)``.

    commands: ``(command, value)`` pairs, e.g. a :class:`RecursiveTurtleProgram`'s ``body``.

    >>> program_text([("FORWARD", 1.0), ("TURN", 60.0), ("RECURSE", None), ("RECURSE", -1)])
    'FORWARD 1 TURN 60 RECURSE RECURSE(mirror)'
    """
    return _text(as_commands(commands, "commands", allow_recurse=True))


def program_codes(program) -> tuple[np.ndarray, np.ndarray]:
    """The command codes and values of a (non-recursive) turtle program, ready for
    :func:`goldman_lib.turtle.trace_arrays` (Goldman §2.2).

    program: turtle-language text, a parsed :class:`goldman_lib.turtle.Program`, or ``(command,
    value)`` pairs.  Returns ``(codes int8 (k,), values (k,))``.

    >>> codes, values = program_codes([("FORWARD", 1.0), ("TURN", 90.0)])
    >>> values.tolist()
    [1.0, 90.0]
    """
    return _flat_program(program, "program")
