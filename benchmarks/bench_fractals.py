"""goldman_lib.fractals against the book's recursion run literally, timed in the same run.

- Koch curve at level 8 (65,536 segments, 174,761 turtle commands): ``koch_curve(8)`` (level by
  level with numpy concatenation, then the vectorised turtle) against a plain recursive Python
  turtle (one call per command, as Goldman §2.3 describes the recursion); target: well under a
  second, and many times faster than the reference.
- dragon at level 14 (16,384 segments, the mirror-program recursion), same comparison.
- similarity dimension of 12 unequal scales: ``similarity_dimension`` against
  ``scipy.optimize.brentq`` on the same equation.

The drawings are checked to agree before anything is timed; ours and the reference are timed in
interleaved rounds (best of several).

>>> callable(main)
True
"""

from __future__ import annotations

import math

import numpy as np

from benchmarks.timing import best_times, report
from goldman_lib import fractals


def naive_polylines(program, level):
    """The recursion run literally: one Python call per turtle command (the reference)."""
    x = y = h = 0.0
    s = 1.0
    strokes, down = [], False

    def cmd(c, v):
        nonlocal x, y, h, s, down
        if c == "TURN":
            h += v
        elif c == "RESIZE":
            s *= v
        else:
            nx = x + v * s * math.cos(math.radians(h))
            ny = y + v * s * math.sin(math.radians(h))
            if c == "FORWARD":
                if not down:
                    strokes.append([(x, y)])
                    down = True
                strokes[-1].append((nx, ny))
            else:
                down = False
            x, y = nx, ny

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
    return [np.array(p) for p in strokes]


def _agree(a, b):
    assert len(a) == len(b) and all(np.allclose(p, q, atol=1e-9) for p, q in zip(a, b))


def main():
    for name, level in [("Koch curve", 8), ("dragon curve", 14)]:
        prog = fractals.PROGRAMS[name]()
        _agree(prog.polylines(level), naive_polylines(prog, level))
        ours, ref = best_times(lambda: prog.polylines(level), lambda: naive_polylines(prog, level),
                               repeat=3, budget=1.0)
        report(f"{name} level {level}", ours, ref, "recursive Python")

    from scipy.optimize import brentq

    scales = np.random.default_rng(0).uniform(0.05, 0.6, 12)
    f = lambda d: float(np.sum(scales ** d)) - 1  # noqa: E731
    ref_d = brentq(f, 0, 100, xtol=1e-15)
    assert abs(fractals.similarity_dimension(scales) - ref_d) < 1e-10
    ours, ref = best_times(lambda: fractals.similarity_dimension(scales), lambda: brentq(f, 0, 100, xtol=1e-15))
    report("similarity_dimension (12 scales)", ours, ref, "scipy brentq")


if __name__ == "__main__":
    main()
