"""Time every widget callback at its chapter's default size (target: under 50 ms a slider move).

For a matplotlib view the cost of a slider move is ``update`` (the library call and the in-place
``set_data``) plus one full Agg redraw of the figure, which is what ipympl does before sending the
picture; both are printed.  For a three.js view it is ``update`` alone (the browser renders).
Each callback is timed while cycling through values from its own slider ranges, so no cache of
a single position flatters it.

Absolute times move about 2x between machines, so each callback is also printed as a multiple of
an empty 560x420 Agg figure redraw timed in the same run (target: at most 4x).
"""

from __future__ import annotations

import itertools
import pathlib
import runpy

import matplotlib

matplotlib.use("Agg")

from benchmarks.timing import best_time, best_times, fmt_time  # noqa: E402
from goldman_lib.views import factories  # noqa: E402

#: The sweep of a view's controls the view tests use (test machinery, kept with the tests).
_SWEEPS = runpy.run_path(str(pathlib.Path(__file__).resolve().parents[1] / "tests" / "views" / "sweeps.py"))
sweep_values = _SWEEPS["sweep_values"]

TARGET = 0.050  # seconds
#: Each callback (update + redraw) at most this multiple of an empty 560x420 Agg redraw, same run.
REDRAW_TARGET = 4.0


def empty_figure():
    """An empty 560x420 figure (5.6 x 4.2 inches at 100 dpi, one axes) whose Agg redraw is the unit."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(5.6, 4.2), dpi=100)
    fig.add_subplot()
    return fig


def _factories():
    """Every widget factory a chapter displays (:func:`goldman_lib.views.factories`)."""
    return factories()


def time_callback(view, empty=None) -> tuple[float, float | None, float | None]:
    """(seconds per update, seconds per update + full redraw or None for three.js views, seconds
    per redraw of the ``empty`` figure timed in interleaved rounds with the callback, or None)."""
    values = itertools.cycle(sweep_values(view, n=5)[:50] or [view.values()])
    update = lambda: view.update(**next(values))  # noqa: E731
    alone = best_time(update, repeat=5)
    if view.figure is None:
        return alone, None, None

    def update_and_draw():
        update()
        view.figure.canvas.draw()

    if empty is None:
        return alone, best_time(update_and_draw, repeat=5), None
    drawn, base = best_times(update_and_draw, empty.canvas.draw, repeat=5)
    return alone, drawn, base


def main(only: str | None = None):
    import matplotlib.pyplot as plt

    worst = 0.0
    empty = empty_figure()
    print(f"unit: an empty 560x420 Agg redraw, timed in rounds interleaved with each callback (target {REDRAW_TARGET:g}x)")
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
