"""Chapter 7 views: Newton's method step by step, Jacobi and Gauss-Seidel relaxation with their
convergence, and the fractal theorem measured level by level (Goldman §7.2-7.3).

>>> view = newton_view()
>>> view.update(**view.values())["status"].startswith("x_")
True
"""

from __future__ import annotations

import warnings

import numpy as np

from goldman_lib import fixed_point as fp
from goldman_lib import ifs
from goldman_lib.validation import as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView

__all__ = ["NEWTON_FUNCTIONS", "newton_view", "relaxation_view", "fractal_theorem_view", "START_SETS", "cobweb",
           "convergence_plot"]

#: Functions for the Newton view: name -> (f, f', x range) — one root, a cycle, divergence, a flat spot.
NEWTON_FUNCTIONS = {
    "x^2 - 2": (lambda x: x * x - 2, lambda x: 2 * x, (-0.5, 3.0)),
    "x^3 - 2x + 2 (cycles from 0)": (lambda x: x ** 3 - 2 * x + 2, lambda x: 3 * x * x - 2, (-2.5, 2.0)),
    "arctan x (diverges from |x0| > 1.39)": (np.arctan, lambda x: 1 / (1 + x * x), (-3.0, 3.0)),
    "x^3 - x (flat at ±0.577)": (lambda x: x ** 3 - x, lambda x: 3 * x * x - 1, (-1.6, 1.6)),
}


def newton_view(function: str = "x^2 - 2", x0: float = 2.5, steps: int = 1) -> InteractiveView:
    """Newton's method drawn step by step (Goldman §7.3.1): each tangent line at ``x_n`` meets the
    axis at ``x_{n+1}``.  ``update(function, x0, steps)`` returns the iterates ``xs`` and the
    tangent segments; the status names the outcome (converged, zero derivative, cycle, diverged).
    """

    if function not in NEWTON_FUNCTIONS:
        raise ValueError(f"function must be one of {list(NEWTON_FUNCTIONS)}; got {function!r}")
    fig, ax = style.new_axes(equal=False)
    curve = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2)[0]
    tangents = ax.plot([], [], color=style.PALETTE["accent"], linewidth=1.2)[0]
    drops = ax.plot([], [], ":", color="#777777", linewidth=1)[0]
    dots = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=4)[0]
    ax.axhline(0, color="#444444", linewidth=0.8)

    def update(function, x0, steps):
        f, df, (lo, hi) = NEWTON_FUNCTIONS[function]
        rep = fp.newton_steps(f, df, x0, max_iter=max(int(steps), 1))
        xs = rep.history[: int(steps) + 1]
        xs = np.clip(xs, -1e6, 1e6)
        t = np.linspace(lo, hi, 300)
        fx = np.asarray(f(t), dtype=float)
        curve.set_data(t, fx)
        seg, drop = [], []
        for a, b in zip(xs[:-1], xs[1:]):
            seg += [[a, float(f(a))], [b, 0.0], [np.nan, np.nan]]
            drop += [[b, 0.0], [b, float(f(b))], [np.nan, np.nan]]
        seg, drop = np.array(seg).reshape(-1, 2), np.array(drop).reshape(-1, 2)
        tangents.set_data(seg[:, 0], seg[:, 1])
        drops.set_data(drop[:, 0], drop[:, 1])
        dots.set_data(xs, np.zeros_like(xs))
        ax.set_xlim(lo, hi)
        ypad = 0.1 * (fx.max() - fx.min())
        ax.set_ylim(fx.min() - ypad, fx.max() + ypad)
        ax.set_title(f"Newton's method on {function.split(' (')[0]}", fontsize=10)
        shown = ", ".join(f"{v:.6g}" for v in xs[-3:])
        verdict = rep.reason if len(rep.history) <= int(steps) + 1 else "running"
        finite = lambda a: a[np.all(np.isfinite(a), axis=1)] if len(a) else np.zeros((0, 2))  # noqa: E731
        return {"xs": xs, "tangents": finite(seg), "status": f"x_{len(xs) - 1} = {xs[-1]:.10g} (... {shown}); {verdict}"
                + (f": {rep.message}" if rep.message and verdict != "running" else "")}

    controls = {"steps": int_slider("steps", steps, 0, 10),
                "x0": float_slider("x0", x0, -2.5, 3.0, 0.01),
                "function": dropdown("f", list(NEWTON_FUNCTIONS), function, label_width="initial", width="300px")}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Newton's method")


def relaxation_view(method: str = "Jacobi", steps: int = 6, diagonal: float = 3.0) -> InteractiveView:
    """Jacobi and Gauss-Seidel on the 2x2 system ``[[d, 1], [2, d]] x = (1, 2)`` (Goldman §7.3.2):
    left, the two lines and the iterates walking to their intersection; right, the residual per
    iteration (log scale).  For ``d <= 2`` the matrix is not diagonally dominant, and for
    ``d < sqrt 2`` the iteration diverges.  ``update(method, steps, diagonal)`` returns the
    iterates and residuals.
    """
    import ipywidgets as widgets

    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax, axr = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    style.style_axes(ax, equal=False)
    style.style_axes(axr, equal=False)
    line1 = ax.plot([], [], color=style.PALETTE["curve"], linewidth=1.5, label="row 1")[0]
    line2 = ax.plot([], [], color=style.PALETTE["good"], linewidth=1.5, label="row 2")[0]
    path = ax.plot([], [], "o-", color=style.PALETTE["point"], markersize=3, linewidth=1)[0]
    ax.legend(fontsize=8, loc="upper right", frameon=False)
    res_line = axr.semilogy([1], [1], "o-", color=style.PALETTE["point"], markersize=3)[0]
    for a in (ax, axr):
        style.few_ticks(a)        # tick labels are most of a redraw: a few, and decades without minor ticks
    axr.set_xlabel("iteration")
    axr.set_ylabel("residual ||b - A x||")
    b = np.array([1.0, 2.0])

    def update(method, steps, diagonal):
        A = np.array([[diagonal, 1.0], [2.0, diagonal]])
        solve = fp.jacobi if method == "Jacobi" else fp.gauss_seidel
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            _, rep = solve(A, b, max_iter=max(int(steps), 1), tol=1e-300, full_output=True)
        hist = rep.history[: int(steps) + 1]
        hist = np.clip(hist, -1e6, 1e6)
        res = np.clip(rep.residuals[: int(steps) + 1], 1e-17, 1e12)
        exact = np.linalg.solve(A, b)
        t = np.linspace(-3, 3, 2)
        # row 1: d x + y = 1  ->  y = 1 - d x;  row 2: 2 x + d y = 2  ->  x = (2 - d y) / 2
        line1.set_data(t, 1 - diagonal * t)
        line2.set_data((2 - diagonal * t) / 2, t)
        path.set_data(hist[:, 0], hist[:, 1])
        span = max(1.5, float(np.abs(hist).max()) * 1.1) if np.abs(hist).max() < 50 else 50
        ax.set_xlim(exact[0] - span, exact[0] + span)
        ax.set_ylim(exact[1] - span, exact[1] + span)
        res_line.set_data(np.arange(len(res)), res)
        axr.set_xlim(-0.5, max(int(steps), 1) + 0.5)
        # the axis follows the data, so the slope (the rate, a factor per step) is visible
        axr.set_ylim(max(float(res.min()) / 4, 1e-17), max(float(res.max()) * 4, 1e-15))
        dominant = fp.is_diagonally_dominant(A)
        ax.set_title(f"{method}, d = {diagonal:.2f} ({'' if dominant else 'not '}diagonally dominant)", fontsize=10, y=1.0)
        return {"iterates": hist, "residuals": res, "solution": exact,
                "status": f"step {len(hist) - 1}: x = ({hist[-1][0]:.6g}, {hist[-1][1]:.6g}), residual {res[-1]:.2e}; "
                          f"exact solution ({exact[0]:.6g}, {exact[1]:.6g})"}

    controls = {"steps": int_slider("steps", steps, 0, 30),
                "diagonal": float_slider("d", diagonal, 1.0, 5.0, 0.05),
                "method": widgets.ToggleButtons(options=["Jacobi", "Gauss-Seidel"], value=method,
                                                style={"button_width": "100px"})}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="relaxation: Jacobi and Gauss-Seidel")


#: Start sets for the fractal theorem view: any compact set converges to the attractor.
START_SETS = {
    "a far-away point": np.array([[2.5, 2.0]]),
    "unit square": ifs.UNIT_SQUARE[:4].copy(),
    "circle": np.c_[0.5 + 1.2 * np.cos(np.linspace(0, 2 * np.pi, 12, endpoint=False)),
                    0.3 + 1.2 * np.sin(np.linspace(0, 2 * np.pi, 12, endpoint=False))],
    "random cloud": np.random.default_rng(7).uniform(-1, 2, (20, 2)),
}


def fractal_theorem_view(system: str = "Sierpinski gasket", start: str = "unit square", level: int = 3) -> InteractiveView:
    """The fractal theorem measured (Goldman §7.3.3): left, ``W^n(A_0)`` over the attractor; right,
    ``h(W^n(A_0), A)`` per level against the bound ``s^n h(A_0, A)`` (log scale).

    ``update(system, start, level)`` returns the iterate and the distances and bounds.
    """

    names = ["Sierpinski gasket", "Koch curve", "dragon", "C-curve", "Cantor set", "Barnsley fern"]
    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax, axh = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    style.style_axes(ax)
    style.style_axes(axh, equal=False)
    attractor = ax.plot([], [], ",", color="#aaaaaa")[0]
    iterate = ax.plot([], [], ".", color=style.PALETTE["point"], markersize=2)[0]
    dist_line = axh.semilogy([0], [1], "o-", color=style.PALETTE["curve"], label="h(W^n(A0), A)")[0]
    bound_line = axh.semilogy([0], [1], "--", color=style.PALETTE["accent"], label="s^n h(A0, A)")[0]
    for a in (ax, axh):
        style.few_ticks(a)        # tick labels are most of a redraw: a few, and decades without minor ticks
    now = axh.axvline(0, color="#999999", linewidth=0.8)
    axh.set_xlabel("level n")
    axh.legend(fontsize=8, frameon=False)
    cache = {}

    def measure(system, start):
        key = (system, start)
        if key not in cache:
            s = ifs.STANDARD[system]()
            A0 = START_SETS[start]
            levels = 0
            while levels < 8 and len(A0) * len(s) ** (levels + 1) <= 20_000:
                levels += 1
            cache[key] = fp.fractal_theorem(s, A0, levels, attractor_points=3000)
        return cache[key]

    def update(system, start, level):
        r = measure(system, start)
        n = min(int(level), len(r.sets) - 1)
        S = r.sets[n]
        attractor.set_data(r.attractor[:, 0], r.attractor[:, 1])
        iterate.set_data(S[:, 0], S[:, 1])
        allp = np.concatenate([r.attractor, S])
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.05 * (hi - lo).max()
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        ks = np.arange(len(r.distances))
        dist_line.set_data(ks, np.maximum(r.distances, 1e-6))
        bound_line.set_data(ks, np.maximum(r.bounds, 1e-6))
        now.set_xdata([n, n])
        axh.set_xlim(-0.3, ks[-1] + 0.3)
        axh.set_ylim(max(1e-4, float(np.maximum(r.distances, 1e-6).min()) / 2), float(r.bounds[0]) * 2)
        ax.set_title(f"W^{n}(A0), {len(S):,} points", fontsize=10, y=1.0)
        axh.set_title(f"contraction factor s = {r.factor:.3f}", fontsize=10, y=1.0)
        capped = f" (level {level} capped at {n})" if n < level else ""
        return {"iterate": S, "distances": r.distances, "bounds": r.bounds,
                "status": f"level {n}{capped}: h(W^n(A0), A) = {r.distances[n]:.4f} <= s^n h(A0, A) = "
                          f"{r.bounds[n]:.4f}"}

    controls = {"level": int_slider("level", as_int(level, "level", minimum=0, maximum=8), 0, 8),
                "system": dropdown("IFS", names, system, label_width="initial", width="260px"),
                "start": dropdown("A0", list(START_SETS), start, label_width="initial", width="260px")}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="the fractal theorem")


# ---------------------------------------------------------------------------------------------
# Static pictures of §7.2-7.3 (added for the cobweb and the convergence plots)
# ---------------------------------------------------------------------------------------------

def cobweb(F, starts, steps: int, interval, ax=None, title: str = ""):
    """The cobweb picture of ``x_{n+1} = F(x_n)`` (Goldman §7.2-7.3): the graph of ``F``, the
    diagonal ``y = x``, and for each start the path ``(x_0, x_0) -> (x_0, x_1) -> (x_1, x_1) ->
    (x_1, x_2) -> ...`` (up to the graph, across to the diagonal).  Where ``|F'| <= s < 1`` the
    path closes in on the fixed point (a staircase if ``F' > 0``, a spiral if ``F' < 0``); where
    ``|F'| > 1`` it moves away.  The iterates come from
    :func:`goldman_lib.fixed_point.fixed_point_iteration`.

    F: a function of a float.  starts: numbers.  steps: iterations per start (1..200).
    interval: ``(a, b)``, the x-range drawn.  ax: a matplotlib Axes (a new figure if None).
    Returns the Axes; ``ax.lines[2:]`` are the paths, one per start.

    >>> import math
    >>> ax = cobweb(math.cos, [0.0], 5, (0, 1.2))
    >>> ax.lines[2].get_xydata().shape
    (11, 2)
    """
    steps = as_int(steps, "steps", minimum=1, maximum=200)
    a, b = (float(v) for v in interval)
    if not a < b:
        raise ValueError(f"interval must be (a, b) with a < b; got {interval!r}")
    if ax is None:
        ax = style.new_figure().add_subplot()
    style.style_axes(ax)
    t = np.linspace(a, b, 400)
    with np.errstate(all="ignore"):
        ax.plot(t, [F(float(x)) for x in t], color=style.PALETTE["curve"], linewidth=1.5, label="y = F(x)")
    ax.plot([a, b], [a, b], color=style.PALETTE["control"], linewidth=1, linestyle="--", label="y = x")
    colours = [style.PALETTE["point"], style.PALETTE["good"], style.PALETTE["accent"]]
    for k, x0 in enumerate(starts):
        _, rep = fp.fixed_point_iteration(F, float(x0), max_iter=steps, tol=1e-300, full_output=True)
        h = rep.history
        xs = np.repeat(h, 2)[:-1]      # x0, x0, x1, x1, ..., x_n
        ys = np.repeat(h, 2)[1:]       # x0, x1, x1, x2, ..., x_n: up to the graph, across to the diagonal
        ax.plot(xs, ys, "-", color=colours[k % len(colours)], linewidth=1, marker="o", markersize=2,
                label=f"x0 = {float(x0):g}")
    ax.set_xlim(a, b)
    ax.set_ylim(a, b)
    ax.legend(fontsize=8, loc="upper left", frameon=False)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def convergence_plot(errors: dict, ax=None, ylabel: str = "error", title: str = ""):
    """Errors against the iteration number on a logarithmic axis (Goldman §7.3): a straight line
    is linear convergence (its slope is the factor per step), a curve bending down ever more
    steeply is quadratic.  errors: name -> sequence of nonnegative numbers (zeros are not drawn).
    Returns the Axes, one line per name.

    >>> convergence_plot({"halving": [1, 0.5, 0.25]}).lines[0].get_xydata().tolist()
    [[0.0, 1.0], [1.0, 0.5], [2.0, 0.25]]
    """
    if ax is None:
        ax = style.new_figure().add_subplot()
    style.style_axes(ax, equal=False)
    for name, e in errors.items():
        e = np.asarray(e, dtype=float)
        n = np.arange(len(e))
        keep = e > 0
        ax.semilogy(n[keep], e[keep], "o-", markersize=3, linewidth=1, label=name)
    ax.set_xlabel("iteration n")
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8, frameon=False)
    if title:
        ax.set_title(title, fontsize=10)
    return ax
