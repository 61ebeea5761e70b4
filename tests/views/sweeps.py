"""Value combinations that sweep a view's controls over their ranges, corners included: how the
view tests (``test_widget_sweeps.py`` and the chapters' tests) and the callback benchmark
(``benchmarks/bench_callbacks.py``) move every control of every factory.  Test machinery, kept with
the tests (issue 19 §3), reading only a view's public ``controls``.

The view tests import it by name (``from sweeps import sweep_values``: pytest puts this folder on
the path); the benchmark loads it with ``runpy.run_path``.
"""

from __future__ import annotations

import functools
import itertools
import math
from typing import Mapping

import ipywidgets as widgets
import numpy as np


def options(w) -> list:
    """A picker's options as ``(label, value)`` pairs."""
    opts = w.options
    if isinstance(opts, Mapping):
        return list(opts.items())
    return [(o, o) if not isinstance(o, tuple) else o for o in opts]


def control_values(w: widgets.Widget, n: int) -> list:
    """``n`` values spread over a control's range, ends included (all options of a picker)."""
    if isinstance(w, (widgets.IntSlider, widgets.BoundedIntText)):
        vals = np.linspace(w.min, w.max, min(n, w.max - w.min + 1))
        return sorted({int(round(v)) for v in vals})
    if isinstance(w, (widgets.FloatSlider, widgets.BoundedFloatText, widgets.FloatLogSlider)):
        return [float(v) for v in np.linspace(w.min, w.max, n)]
    if isinstance(w, (widgets.Dropdown, widgets.ToggleButtons, widgets.RadioButtons, widgets.SelectionSlider)):
        return [value for _, value in options(w)]
    if isinstance(w, widgets.Checkbox):
        return [False, True]
    return [w.value]


@functools.lru_cache(maxsize=64)
def covering_corners(k: int, strength: int = 3, seed: int = 0) -> np.ndarray:
    """Rows of 0s and 1s (a control at its minimum or its maximum) over ``k`` controls in which every
    ``strength`` controls meet in each of their ``2**strength`` combinations: a covering array of
    that strength, built greedily (each row the best of 64 seeded random candidates, one of them
    made to cover a combination still missing), so it is the same on every run.

    A fault that needs three controls at their extremes at once shows in some row, and the rows are
    few: about 20-40 for 10-30 controls, where all the corners would be 2**k.

    >>> rows = covering_corners(6)
    >>> import itertools
    >>> all(len({tuple(r[list(c)]) for r in rows}) == 8 for c in itertools.combinations(range(6), 3))
    True
    >>> len(rows) < 2 ** 6
    True
    """
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
        raise ValueError(f"k must be a whole number of controls >= 0; got {k!r}")
    if isinstance(strength, bool) or not isinstance(strength, (int, np.integer)) or not 1 <= strength <= 4:
        raise ValueError(f"strength must be 1, 2, 3 or 4; got {strength!r}")
    if k <= strength:
        out = np.array(list(itertools.product((0, 1), repeat=k)), dtype=np.int8).reshape(-1, k)
        out.flags.writeable = False     # cached: shared by every caller
        return out
    groups = np.array(list(itertools.combinations(range(k), strength)))
    weights = 1 << np.arange(strength)[::-1]
    missing = np.ones((len(groups), 2 ** strength), dtype=bool)
    everyone = np.arange(len(groups))
    rng = np.random.default_rng(seed)
    rows = []
    while missing.any():
        candidates = rng.integers(0, 2, size=(64, k))
        g, combo = np.argwhere(missing)[0]
        candidates[0, groups[g]] = (combo >> np.arange(strength)[::-1]) & 1
        codes = (candidates[:, groups] * weights).sum(axis=-1)
        best = candidates[int(np.argmax(missing[everyone, codes].sum(axis=1)))]
        missing[everyone, (best[groups] * weights).sum(axis=-1)] = False
        rows.append(best)
    out = np.array(rows, dtype=np.int8)
    out.flags.writeable = False     # cached: shared by every caller
    return out


def control_grid(controls: Mapping[str, widgets.Widget], n: int = 3, max_full: int = 400, seed: int = 0) -> list[dict]:
    """Value combinations covering each control's range, corners included.

    If the full grid has at most ``max_full`` points it is returned whole.  Otherwise: every
    control swept over its ``n`` values with the others at their defaults, at their minima and at
    their maxima; the two all-min / all-max corners; and the corners of :func:`covering_corners`,
    in which every three controls meet at each of their eight min/max combinations.
    """
    names = list(controls)
    axes = [control_values(controls[k], n) for k in names]
    total = math.prod(len(a) for a in axes)  # exact: np.prod would wrap round in int64 for ~40+ controls
    if total <= max_full:
        return [dict(zip(names, combo)) for combo in itertools.product(*axes)]
    default = {k: controls[k].value for k in names}
    lows = {k: a[0] for k, a in zip(names, axes)}
    highs = {k: a[-1] for k, a in zip(names, axes)}
    combos = [lows, highs]
    for base in (default, lows, highs):
        for k, a in zip(names, axes):
            for v in a:
                combos.append({**base, k: v})
    for row in covering_corners(len(names), 3, seed):
        combos.append({k: (a[-1] if bit else a[0]) for k, a, bit in zip(names, axes, row)})
    return combos


def sweep_values(view, n: int = 3, max_full: int = 400) -> list[dict]:
    """Value combinations over every control of ``view``, corners included (:func:`control_grid`)."""
    return control_grid(view.controls, n=n, max_full=max_full)
