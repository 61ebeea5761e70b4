"""Timing helpers shared by the benchmark modules.

>>> t = best_time(lambda: sum(range(100)), repeat=3, number=10)
>>> t > 0
True
>>> line = report("sum", 2e-3, 1e-3, "builtin")   # doctest: +NORMALIZE_WHITESPACE
sum  ours  2.00 ms  builtin  1.00 ms  ours/reference = 2.0x
"""

from __future__ import annotations

import time

__all__ = ["best_time", "best_times", "report", "fmt_time", "CLOCK"]

#: The clock every ratio is timed by: the CPU time of this process (all its threads), not the wall
#: clock.  On a shared machine (CI beside two browsers, a laptop with other work) the wall clock
#: also counts the time the scheduler gave to others, which swung same-code ratios by 30% and more
#: at load 5-10 on 2 cores; CPU time counts only the work both sides do.  On an idle machine the
#: two agree for single-threaded code, so an absolute target in milliseconds (a slider callback
#: under 50 ms) is what an idle machine's wall clock would show; the benchmarks that also print
#: wall-clock times (ray tracing, shading, radiosity, hidden surfaces) time them with
#: ``time.perf_counter`` and say so.
CLOCK = time.process_time


def best_time(fn, repeat: int = 7, number: int = 0, budget: float = 0.2, clock=None) -> float:
    """Seconds per call of ``fn()``: the best of ``repeat`` rounds of ``number`` calls each.

    ``number=0`` picks it so that one round takes about ``budget / repeat`` seconds (at least one
    call).  The best round, not the mean, is reported: it is the least disturbed by other load.
    Timed by :data:`CLOCK` (CPU time), or by ``clock`` if given (``time.perf_counter`` for a wall-clock time).
    """
    clock = CLOCK if clock is None else clock
    fn()  # warm up (imports, caches, allocations)
    if number <= 0:
        start = clock()
        fn()
        once = max(clock() - start, 1e-7)
        number = max(1, int(budget / repeat / once))
    best = float("inf")
    for _ in range(repeat):
        start = clock()
        for _ in range(number):
            fn()
        best = min(best, (clock() - start) / number)
    return best


def best_times(*fns, repeat: int = 9, budget: float = 0.3) -> list[float]:
    """Seconds per call of each ``fn()``, measured in interleaved rounds (best of ``repeat``).

    Alternating the functions round by round exposes them to the same machine load, so their
    ratio is steadier than from two separate :func:`best_time` calls on a shared machine.

    >>> a, b = best_times(lambda: sum(range(10)), lambda: sum(range(1000)), repeat=3)
    >>> a < b
    True
    """
    numbers = []
    for fn in fns:
        fn()
        start = CLOCK()
        fn()
        once = max(CLOCK() - start, 1e-7)
        numbers.append(max(1, int(budget / len(fns) / repeat / once)))
    best = [float("inf")] * len(fns)
    for _ in range(repeat):
        for i, (fn, number) in enumerate(zip(fns, numbers)):
            start = CLOCK()
            for _ in range(number):
                fn()
            best[i] = min(best[i], (CLOCK() - start) / number)
    return best


def fmt_time(seconds: float) -> str:
    """Format a duration with a unit that suits it: ``12.3 us``, ``4.56 ms``, ``1.20 s``."""
    if seconds < 1e-3:
        return f"{seconds * 1e6:.1f} us"
    if seconds < 1:
        return f"{seconds * 1e3:.2f} ms"
    return f"{seconds:.2f} s"


def report(name: str, ours: float, ref: float | None = None, ref_name: str = "reference") -> str:
    """Print and return one line: our time, the reference's time and ``ours/reference = R x``.

    With ``ref=None`` only our time is printed (for callbacks that have no reference library).
    """
    if ref is None:
        line = f"{name:<44} ours {fmt_time(ours):>10}"
    else:
        line = (f"{name:<44} ours {fmt_time(ours):>10}   {ref_name} {fmt_time(ref):>10}   "
                f"ours/reference = {ours / ref:.1f}x")
    print(line, flush=True)
    return line


def report_targets(ratios: dict[str, float], targets: dict[str, float]) -> None:
    """Print whether each ratio (ours / reference, measured in this run) meets its target."""
    for name, limit in targets.items():
        verdict = "met" if ratios[name] <= limit else "MISSED"
        print(f"target {name} <= {limit:g}x reference: {verdict} ({ratios[name]:.2f}x)")
