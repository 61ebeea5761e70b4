"""Time every widget callback at its chapter's default size (target: under 50 ms a slider move).

For a matplotlib view the cost of a slider move is ``update`` (the library call and the in-place
``set_data``) plus one full Agg redraw of the figure, which is what ipympl does before sending the
picture; both are printed.  For a three.js view it is ``update`` alone (the browser renders).
Each callback is timed while cycling through values from its own slider ranges, so no cache of
a single position flatters it.

Absolute times move about 2x between machines, so each callback is also printed as a multiple of
an empty 560x420 Agg figure redraw timed in the same run (target: at most 3x, on a loaded machine
too).

How the multiple is measured, so that a loaded machine gives the multiple an idle one does: the
callback (update + redraw) and the empty redraw alternate call by call for :data:`ROUNDS` rounds,
each call timed in CPU time of this process (``time.process_time``), and each side keeps its *best*
(shortest) round.  CPU time leaves out the time the process waits for a core while other processes
run (most of what load adds to wall time on a shared 2-core machine); what load still adds (caches,
memory bandwidth) only ever adds, and in bursts, so the best of many short interleaved rounds is
each side's least-disturbed cost, and alternating exposes both sides to the same load.  The median
was rejected: under load it measures the load, more for the callback (three or four times longer,
so more often hit by a burst) than for the empty redraw, which biases the multiple upwards.
"""

from __future__ import annotations

import itertools
import pathlib
import runpy
import time

import matplotlib

matplotlib.use("Agg")

from benchmarks.timing import best_time, fmt_time  # noqa: E402
from goldman_lib.views import factories  # noqa: E402

#: The sweep of a view's controls the view tests use (test machinery, kept with the tests).
_SWEEPS = runpy.run_path(str(pathlib.Path(__file__).resolve().parents[1] / "tests" / "views" / "sweeps.py"))
sweep_values = _SWEEPS["sweep_values"]

TARGET = 0.050  # seconds
#: Each callback (update + redraw) at most this multiple of an empty 560x420 Agg redraw, same run.
REDRAW_TARGET = 3.0
#: Interleaved rounds of one call each (a callback is >= 10 ms): many short rounds, so that some
#: fall between the bursts of a loaded machine.
ROUNDS = 21


def empty_figure():
    """An empty 560x420 figure (5.6 x 4.2 inches at 100 dpi, one axes) whose Agg redraw is the unit."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(5.6, 4.2), dpi=100)
    fig.add_subplot()
    return fig


def best_cpu_times(*fns, rounds: int = ROUNDS) -> list[float]:
    """CPU seconds of one call of each ``fn()``: the best of ``rounds`` rounds in which the functions
    are called once each, in turn (after one warm-up call each)."""
    for fn in fns:
        fn()
    best = [float("inf")] * len(fns)
    for _ in range(rounds):
        for i, fn in enumerate(fns):
            start = time.process_time()
            fn()
            best[i] = min(best[i], time.process_time() - start)
    return best


def _factories():
    """Every widget factory a chapter displays (:func:`goldman_lib.views.factories`)."""
    return factories()


def time_callback(view, empty=None) -> tuple[float, float | None, float | None]:
    """(seconds per update, seconds per update + full redraw or None for three.js views, seconds
    per redraw of the ``empty`` figure timed in interleaved rounds with the callback, or None).
    With ``empty``, all three are CPU times from the same interleaved rounds."""
    values = itertools.cycle(sweep_values(view, n=5)[:50] or [view.values()])
    update = lambda: view.update(**next(values))  # noqa: E731
    if view.figure is None:
        if empty is None:
            return best_time(update, repeat=5), None, None
        alone, base = best_cpu_times(update, empty.canvas.draw)
        return alone, None, base

    def update_and_draw():
        update()
        view.figure.canvas.draw()

    if empty is None:
        return best_time(update, repeat=5), best_time(update_and_draw, repeat=5), None
    return tuple(best_cpu_times(update, update_and_draw, empty.canvas.draw))


def main(only: str | None = None):
    import matplotlib.pyplot as plt

    worst = 0.0
    empty = empty_figure()
    print(f"unit: an empty 560x420 Agg redraw, timed in {ROUNDS} rounds interleaved call by call with each callback, "
          f"CPU time, best round of each side (target {REDRAW_TARGET:g}x)")
    ratios = {}
    for name, factory in _factories():
        if only and only not in name:
            continue
        view = factory()
        alone, drawn, base = time_callback(view, empty)
        total = drawn if drawn is not None else alone
        worst = max(worst, total)
        base = base or best_time(empty.canvas.draw, repeat=5)
        ratios[name] = total / base
        drawn_text = f"update + redraw {fmt_time(drawn):>10}" if drawn is not None else "(rendered by the browser)"
        verdict = "ok" if total < TARGET else "OVER 50 ms"
        multiple = (f"{total / base:5.1f}x redraw ({fmt_time(base)}) "
                    f"{'met' if total / base <= REDRAW_TARGET else 'MISSED'}")
        print(f"{name:<36} update {fmt_time(alone):>10}   {drawn_text}   {verdict}   {multiple}")
        if view.figure is not None:  # one figure at a time: a benchmark of 40+ views must not pile them up
            plt.close(view.figure)
    plt.close(empty)
    print(f"slowest callback: {fmt_time(worst)} (target {fmt_time(TARGET)})")
    missed = sorted((r, n) for n, r in ratios.items() if r > REDRAW_TARGET)
    print(f"target every callback <= {REDRAW_TARGET:g}x an empty redraw: "
          + ("met" if not missed else "MISSED by " + ", ".join(f"{n} ({r:.1f}x)" for r, n in reversed(missed))))
    return ratios


if __name__ == "__main__":
    main()
