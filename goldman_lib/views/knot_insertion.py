"""Chapter 28 views: knot insertion step by step (Boehm, Oslo), subdivision level by level
(Lane-Riesenfeld, Schaefer) and knot insertion on a knot vector set with the shared knot-vector
editor (Goldman §28.3-28.4).

Plot functions take ``ax=None`` and return their artists; widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function.

>>> view = bspline_subdivision_view()
>>> sorted(view.update(**view.values()))
['curve', 'distance', 'labels', 'polygon', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bspline
from goldman_lib import knot_insertion as ki
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import (
    InteractiveView,
    dropdown,
    figure_widget,
    float_slider,
    int_slider,
)

__all__ = ["DEFAULT_POLYGON", "DEFAULT_KNOTS", "DEFAULT_DEGREE", "plot_bspline", "plot_polygon",
           "plot_knot_points", "plot_bezier_pieces", "boehm_view", "oslo_view", "bspline_subdivision_view",
           "insertion_editor", "render_view", "DEFAULT_SECOND"]

#: The cubic B-spline of the chapter: seven control points, clamped, three interior knots.
DEFAULT_POLYGON = np.array([[0.0, 0.0], [0.6, 2.4], [2.2, 3.0], [3.2, 0.6], [4.6, 0.2], [5.4, 2.6], [6.8, 2.0]])
DEFAULT_DEGREE = 3
DEFAULT_KNOTS = np.array([0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1], dtype=float)

#: The quadratic B-spline the chapter's curve is intersected with: ``(ctrl, knots, degree)``.
DEFAULT_SECOND = (np.array([[-0.5, 1.8], [1.5, 0.2], [3.0, 2.6], [4.5, 0.8], [7.2, 1.4]]),
                  np.array([0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1], dtype=float), 2)

_SAMPLES = 200
_MARKER_LIMIT = 150     # polygons with more points are drawn without markers (keeps a redraw under 50 ms)


def _curve_points(ctrl, knots, degree, samples=_SAMPLES):
    t = np.asarray(knots, dtype=float)
    lo, hi = t[degree], t[t.size - degree - 1]
    return bspline.de_boor(ctrl, t, degree, np.linspace(lo, hi, samples))


def _knot_points(ctrl, knots, degree):
    t = np.asarray(knots, dtype=float)
    lo, hi = t[degree], t[t.size - degree - 1]
    inner = np.unique(t[(t >= lo) & (t <= hi)])
    return bspline.de_boor(ctrl, t, degree, inner)


_LABEL_LIMIT = 16      # more points than this get no blossom labels (they would overlap)


def _label_text(label) -> str:
    """``b(0.25, 0.5, 0.5)``: a blossom label as the book writes it (arguments to 3 digits)."""
    return "b(" + ", ".join(f"{float(x):.3g}" for x in label) + ")"


def _put_labels(ax, store: list, points, labels, colour, offset=(5, 5), ha="left"):
    """Write the blossom labels beside the points (appending the texts to ``store``)."""
    for q, lab in zip(np.asarray(points, dtype=float).reshape(-1, 2), labels):
        store.append(ax.annotate(_label_text(lab), (float(q[0]), float(q[1])), textcoords="offset points",
                                 xytext=offset, fontsize=6.5, color=colour, ha=ha, zorder=6))


def _clear_labels(store: list):
    for text in store:
        text.remove()
    store.clear()


def _limits(ax, pts, pad=0.4):
    ax.set_xlim(pts[:, 0].min() - pad, pts[:, 0].max() + pad)
    ax.set_ylim(pts[:, 1].min() - pad, pts[:, 1].max() + pad)
    ax.set_aspect("equal", adjustable="box")


# -- static plots -------------------------------------------------------------------------------
def plot_bspline(ctrl, knots, degree, ax=None, samples: int = _SAMPLES, color=None, **kwargs):
    """Draw the B-spline curve over its domain (Goldman §27.2); returns the line."""
    ctrl = as_points(ctrl, "ctrl", dim=2)
    ax = style.get_axes(ax)
    pts = _curve_points(ctrl, knots, int(degree), samples)
    kw = dict(linewidth=2.2)
    kw.update(kwargs)
    (line,) = ax.plot(pts[:, 0], pts[:, 1], color=color or style.PALETTE["curve"], **kw)
    return line


def plot_polygon(ctrl, ax=None, color=None, marker="o", labels: bool = False, **kwargs):
    """Draw a control polygon with its points (labelled P0, P1, ... if ``labels``); returns the line."""
    ctrl = as_points(ctrl, "ctrl", dim=2)
    ax = style.get_axes(ax)
    kw = dict(markersize=5, linewidth=1)
    kw.update(kwargs)
    (line,) = ax.plot(ctrl[:, 0], ctrl[:, 1], marker=marker, linestyle="--",
                      color=color or style.PALETTE["control"], **kw)
    if labels:
        for k, p in enumerate(ctrl):
            ax.annotate(f"$P_{{{k}}}$", p, textcoords="offset points", xytext=(5, 5), fontsize=9)
    return line


def plot_knot_points(ctrl, knots, degree, ax=None, **kwargs):
    """Mark the curve points at the distinct knots of the domain (where the pieces meet); returns the line."""
    ax = style.get_axes(ax)
    pts = _knot_points(as_points(ctrl, "ctrl", dim=2), knots, int(degree))
    (line,) = ax.plot(pts[:, 0], pts[:, 1], "|", color="#222222", markersize=12, markeredgewidth=2, **kwargs)
    return line


def plot_bezier_pieces(ctrl, knots, degree, ax=None):
    """Draw the Bezier control polygons of the pieces of a B-spline (Goldman §28.3.3), one colour
    a piece; returns the lines."""
    ax = style.get_axes(ax)
    pieces, _ = ki.to_piecewise_bezier(ctrl, knots, degree)
    lines = []
    for j, piece in enumerate(pieces):
        (ln,) = ax.plot(piece[:, 0], piece[:, 1], "s-", color=style.level_colour(j + 1), markersize=4,
                        linewidth=1.3)
        lines.append(ln)
    return lines


# -- widgets ------------------------------------------------------------------------------------
def boehm_view(ctrl=DEFAULT_POLYGON, knots=DEFAULT_KNOTS, degree: int = DEFAULT_DEGREE, u: float = 0.4,
               times: int = 1) -> InteractiveView:
    """Step through Boehm's algorithm (Goldman §28.3.1): pick the knot ``u`` to insert and how
    many times; the view shows the old polygon, the new one, the p-1 old points that are replaced
    (crossed out) and the p new points on the old legs.  The curve does not move.
    Beside the new points stand their blossom labels (the new knots ``tau_{i+1..i+p}``), beside
    the replaced points their old labels.

    ``update(u, times)`` returns the new polygon, the replaced and the new points with their labels,
    and the curve.
    Inserting more often than the multiplicity rule allows (at most degree+1 equal knots) stops
    at the limit and says so.
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    p = as_int(degree, "degree", minimum=1)
    knots = bspline.check_knots(knots, p, len(ctrl))
    lo, hi = knots[p], knots[knots.size - p - 1]
    fig, ax = style.new_axes()
    crv = _curve_points(ctrl, knots, p)
    plot_polygon(ctrl, ax, alpha=0.55, label="old polygon")
    ax.plot(crv[:, 0], crv[:, 1], color=style.PALETTE["curve"], linewidth=2.2, label="curve (unchanged)")
    (new_poly,) = ax.plot([], [], "o-", color=style.PALETTE["accent"], markersize=5, linewidth=1.5,
                          label="new polygon")
    (replaced,) = ax.plot([], [], "x", color=style.PALETTE["point"], markersize=11, markeredgewidth=2.2,
                          label="replaced")
    (fresh,) = ax.plot([], [], "o", color=style.PALETTE["good"], markersize=8, label="new points")
    (at_u,) = ax.plot([], [], "|", color="#222222", markersize=14, markeredgewidth=2)
    ax.legend(loc="lower right", fontsize=7, frameon=False)
    _limits(ax, np.vstack([ctrl, crv]))
    ax.set_title("Boehm's algorithm", fontsize=10)
    texts: list = []

    def update(u, times):
        u = float(min(max(u, lo), hi))
        s = int(np.count_nonzero(knots == u))
        allowed = max(0, min(int(times), p + 1 - s))
        steps = ki.boehm_steps(ctrl, knots, p, u, allowed)
        last = steps[-1]
        prev = steps[-2]["ctrl"] if allowed else ctrl
        Q = last["ctrl"]
        gone = prev[last["replaced"]] if allowed else np.zeros((0, 2))
        new = Q[last["new"]] if allowed else np.zeros((0, 2))
        new_poly.set_data(Q[:, 0], Q[:, 1])
        replaced.set_data(gone[:, 0], gone[:, 1])
        fresh.set_data(new[:, 0], new[:, 1])
        c = bspline.de_boor(ctrl, knots, p, u)
        at_u.set_data([c[0]], [c[1]])
        _clear_labels(texts)
        new_labels = [bspline.control_point_labels(last["knots"], p)[i] for i in last["new"]] if allowed else []
        old_labels = [bspline.control_point_labels(steps[-2]["knots"], p)[i] for i in last["replaced"]] if allowed else []
        _put_labels(ax, texts, new, new_labels, style.PALETTE["good"], (9, -3))
        _put_labels(ax, texts, gone, old_labels, style.PALETTE["point"], (-9, -3), ha="right")
        note = "" if allowed == int(times) else f" (u already has multiplicity {s}: at most {p + 1 - s} more)"
        alphas = ", ".join(f"{a:.2f}" for a in last["alphas"]) if allowed else "-"
        status = (f"insert u = {u:.2f} x{allowed}{note}: {len(ctrl)} -> {len(Q)} points; "
                  f"last step replaced {len(gone)} point(s) by {len(new)}, weights a_i = [{alphas}]")
        return {"polygon": Q, "replaced": gone, "new": new, "curve": crv, "knots": last["knots"], "status": status,
                "new_labels": new_labels, "replaced_labels": old_labels}

    controls = {"u": float_slider("u", u, float(lo), float(hi), 0.01),
                "times": int_slider("times", times, 0, p + 1)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Boehm's knot insertion, step by step")


def oslo_view(ctrl=DEFAULT_POLYGON, knots=DEFAULT_KNOTS, degree: int = DEFAULT_DEGREE, count: int = 4,
              step: int = 3) -> InteractiveView:
    """Step through the Oslo algorithm (Goldman §28.3.2): ``count`` new knots (evenly spaced in
    the domain) are inserted at once; the step slider picks the new control point ``Q_j`` and the
    view draws its de Boor pyramid with the new knots as arguments (the blossom
    ``b(tau_{j+1}, ..., tau_{j+p})``), the new points computed so far, and the old polygon.

    Every point of the pyramid carries its blossom label (from
    :func:`goldman_lib.knot_insertion.oslo_steps`): the old points their knots, each level one more
    new knot.

    ``update(count, step)`` returns the new polygon, the points done so far, the pyramid levels
    with their labels and the label of ``Q_j``.
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    p = as_int(degree, "degree", minimum=1)
    knots = bspline.check_knots(knots, p, len(ctrl))
    lo, hi = knots[p], knots[knots.size - p - 1]
    max_count = 8
    fig, ax = style.new_axes()
    crv = _curve_points(ctrl, knots, p)
    plot_polygon(ctrl, ax, alpha=0.55)
    ax.plot(crv[:, 0], crv[:, 1], color=style.PALETTE["curve"], linewidth=2.0, alpha=0.8)
    (new_poly,) = ax.plot([], [], "-", color=style.PALETTE["accent"], linewidth=1.2, alpha=0.6)
    (done,) = ax.plot([], [], "o", color=style.PALETTE["accent"], markersize=6)
    levels = [ax.plot([], [], "o-", color=style.level_colour(r), markersize=4, linewidth=1.1)[0]
              for r in range(1, p + 1)]
    (current,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=10, zorder=5)
    _limits(ax, np.vstack([ctrl, crv]))
    ax.set_title("the Oslo algorithm: every new point is a blossom value", fontsize=10)
    texts: list = []

    def new_knots(count):
        extra = lo + (hi - lo) * (np.arange(1, count + 1) / (count + 1))
        return np.sort(np.concatenate([knots, extra]))

    def update(count, step):
        count = int(min(max(count, 1), max_count))
        tau = new_knots(count)
        steps = ki.oslo_steps(ctrl, knots, p, tau)
        j = int(min(max(step, 0), len(steps) - 1))
        Q = np.array([s["point"] for s in steps])
        new_poly.set_data(Q[:, 0], Q[:, 1])
        done.set_data(Q[:j + 1, 0], Q[:j + 1, 1])
        pyramid = steps[j]["levels"]
        for r, line in enumerate(levels, start=1):
            pts = pyramid[r - 1] if r - 1 < len(pyramid) else np.zeros((0, 2))
            line.set_data(pts[:, 0], pts[:, 1])
        q = steps[j]["point"]
        current.set_data([q[0]], [q[1]])
        _clear_labels(texts)
        # Q_j first, then the old points, then the levels between; a label whose point crowds one
        # already labelled is left out of the picture (it stays in update()["labels"])
        placed = []
        room = 0.06 * float(np.ptp(ax.get_xlim()))
        for r in [p] + list(range(p)):
            colour = "#555555" if r == 0 else style.PALETTE["point"] if r == p else style.level_colour(r)
            offset, ha = ((9, 6), "left") if r == p else ((-7, 5), "right") if r % 2 else ((7, -8), "left")
            for pt, lab in zip(pyramid[r], steps[j]["labels"][r]):
                if all(np.hypot(*(pt - o)) > room for o in placed):
                    placed.append(pt)
                    _put_labels(ax, texts, pt, [lab], colour, offset, ha)
        label = ", ".join(f"{x:.2f}" for x in steps[j]["label"])
        status = (f"{count} new knots: {len(ctrl)} -> {len(Q)} points. Q_{j} = b({label}) "
                  f"from P_{steps[j]['span'] - p}..P_{steps[j]['span']} = ({q[0]:.3f}, {q[1]:.3f})")
        return {"polygon": Q, "done": Q[:j + 1], "levels": pyramid, "point": q, "label": steps[j]["label"],
                "labels": steps[j]["labels"], "knots": tau, "status": status}

    n_max = len(ctrl) + max_count - 1
    controls = {"count": int_slider("knots", count, 1, max_count),
                "step": int_slider("point", step, 0, n_max)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Oslo algorithm, one new control point at a time")


_ALGORITHMS = ("Lane-Riesenfeld (uniform)", "Lane-Riesenfeld (closed)", "Schaefer (clamped)")


def bspline_subdivision_view(ctrl=DEFAULT_POLYGON, degree: int = DEFAULT_DEGREE, level: int = 1, rnd: int | None = None,
                     algorithm: str = "Schaefer (clamped)", max_level: int = 6, max_degree: int = 5) -> InteractiveView:
    """An insertion-level slider for Lane-Riesenfeld and Schaefer subdivision (Goldman §28.4).

    ``level`` halvings of every knot interval; the ``round`` slider shows the last level part way:
    round 0 is the doubled polygon, round r after r averaging steps (round = degree is the level
    finished).  Three algorithms: Lane-Riesenfeld on an open uniform curve, on a closed (periodic)
    one, and Schaefer's on the clamped curve with uniform interior knots.  The status line shows
    the distance of the polygon to the curve (§28.4.3), which drops by about 4 per level.  For
    Schaefer's algorithm every point drawn is a blossom value of the curve, and while there are at
    most 16 points its label stands beside it (:func:`goldman_lib.knot_insertion.schaefer_labels`).

    ``update(algorithm, degree, level, round)`` returns the polygon drawn, the curve, the distance
    and the labels (empty for Lane-Riesenfeld).
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    max_degree = as_int(max_degree, "max_degree", minimum=1, maximum=len(ctrl) - 1)
    max_level = as_int(max_level, "max_level", minimum=1, maximum=8)
    degree = as_int(degree, "degree", minimum=1, maximum=max_degree)
    if algorithm not in _ALGORITHMS:
        raise ValueError(f"algorithm must be one of {_ALGORITHMS}; got {algorithm!r}")

    fig, ax = style.new_axes()
    plot_polygon(ctrl, ax, alpha=0.45)
    (curve,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.4, alpha=0.85, label="curve")
    (poly,) = ax.plot([], [], "o-", color=style.PALETTE["accent"], markersize=3.5, linewidth=1.2,
                      label="refined polygon")
    ax.legend(loc="lower right", fontsize=7, frameon=False)
    _limits(ax, ctrl)
    ax.set_title("subdivision = inserting every midpoint", fontsize=10)
    cache: dict = {}
    texts: list = []

    def curve_of(alg, p):
        key = ("curve", alg, p)
        if key not in cache:
            if alg.endswith("(closed)"):
                ext, t = ki.closed_curve(ctrl, p)
                cache[key] = (bspline.de_boor(ext, t, p, np.linspace(*bspline.domain(t, p), 240)), ext, t)
            elif alg.startswith("Lane"):
                t = np.arange(len(ctrl) + p + 1, dtype=float)
                cache[key] = (bspline.de_boor(ctrl, t, p, np.linspace(p, len(ctrl), 240)), ctrl, t)
            else:
                t = bspline.clamped_knots(len(ctrl), p)
                cache[key] = (bspline.de_boor(ctrl, t, p, np.linspace(0, 1, 240)), ctrl, t)
        return cache[key]

    def update(algorithm, degree, level, round):
        alg = algorithm if algorithm in _ALGORITHMS else _ALGORITHMS[0]
        p = int(min(max(degree, 1), max_degree))
        L = int(min(max(level, 0), max_level))
        r = p if round is None else int(min(max(round, 0), p))
        crv, _, t = curve_of(alg, p)
        closed = alg.endswith("(closed)")
        if alg.startswith("Lane"):
            before = ki.lane_riesenfeld(ctrl, p, max(L - 1, 0), closed=closed)
            rounds = ki.lane_riesenfeld_steps(before, p, 1, closed=closed)[0] if L >= 1 else [before]
            knots_now = None if closed else ki.lane_riesenfeld_knots(len(ctrl), p, L)
        else:
            before, tk = ki.schaefer(ctrl, t, p, max(L - 1, 0))
            if L >= 1:
                steps = ki.schaefer_steps(before, tk, p)
                rounds, knots_now = steps["rounds"], steps["knots"]
                round_labels = steps["labels"]
            else:
                rounds, knots_now = [before], tk
                round_labels = [bspline.control_point_labels(tk, p)]
        P = rounds[min(r, len(rounds) - 1)]
        labels = round_labels[min(r, len(rounds) - 1)] if not alg.startswith("Lane") else []
        _clear_labels(texts)
        if len(labels) <= _LABEL_LIMIT:
            for k, (pt, lab) in enumerate(zip(P, labels)):
                _put_labels(ax, texts, pt, [lab], "#7a4a00", (4, 5) if k % 2 else (4, -10))
        finished = rounds[-1]
        shown = np.vstack([P, P[:1]]) if closed else P
        poly.set_data(shown[:, 0], shown[:, 1])
        poly.set_marker("o" if len(P) <= _MARKER_LIMIT else "None")   # hundreds of markers cost Agg time
        curve.set_data(crv[:, 0], crv[:, 1])
        # distance of the finished level's control points from the curve at their Greville abscissae
        d = ki.control_polygon_distance(finished, knots_now, p, closed=closed, skip_outside=True)
        if L >= 1 and r < p:
            dist_text = (f"showing round {r} of {p} (doubled, then {r} averaging step{'s' if r != 1 else ''}); "
                         f"finished polygon {d:.4f} from the curve")
        else:
            dist_text = f"farthest control point {d:.4f} from the curve"
        status = f"{alg}, degree {p}, level {L}: {len(P)} points; {dist_text}"
        return {"polygon": P, "curve": crv, "distance": d, "status": status, "labels": labels}

    controls = {"algorithm": dropdown("algorithm", list(_ALGORITHMS), algorithm, label_width="70px", width="290px"),
                "degree": int_slider("degree", degree, 1, max_degree),
                "level": int_slider("level", level, 0, max_level),
                "round": int_slider("round", degree if rnd is None else rnd, 0, max_degree)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Lane-Riesenfeld and Schaefer subdivision", side=True)


def insertion_editor(ctrl=DEFAULT_POLYGON, degree: int = DEFAULT_DEGREE, u: float = 0.6, times: int = 1) -> InteractiveView:
    """Knot insertion on a knot vector you set (Goldman §28.3): the shared knot-vector editor
    (:mod:`goldman_lib.widgets.knot_editor`) sets the degree and the knots, and two more sliders
    pick the knot ``u`` to insert and how many times.  The view draws the curve, the old and new
    polygons, and the Bezier polygons of the pieces once every knot has multiplicity p (§28.3.3)
    when ``bezier`` is ticked.

    ``update(u, times, bezier, **editor values)`` returns the new polygon and knots.
    """
    import ipywidgets as widgets

    from goldman_lib.widgets.knot_editor import knot_vector_editor

    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=3)
    editor = knot_vector_editor(n_ctrl=len(ctrl), degree=degree, max_degree=min(5, len(ctrl) - 1))
    fig, ax = style.new_axes()
    plot_polygon(ctrl, ax, alpha=0.5)
    (curve,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.2)
    (marks,) = ax.plot([], [], "|", color="#222222", markersize=12, markeredgewidth=2)
    (new_poly,) = ax.plot([], [], "o-", color=style.PALETTE["accent"], markersize=5, linewidth=1.4)
    (at_u,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=8, zorder=5)
    piece_lines = [ax.plot([], [], "s-", color=style.level_colour(j + 1), markersize=3, linewidth=1.0)[0]
                   for j in range(len(ctrl))]
    _limits(ax, ctrl)
    ax.set_title("knot insertion on your knot vector", fontsize=10)

    def update(u, times, bezier, **values):
        knots, p, _ = editor.read(values)
        lo, hi = knots[p], knots[knots.size - p - 1]
        x = float(min(max(u, lo), hi))
        s = int(np.count_nonzero(knots == x))
        k = max(0, min(int(times), p + 1 - s))
        Q, tau = ki.boehm_insert(ctrl, knots, p, x, k)
        crv = _curve_points(ctrl, knots, p)
        curve.set_data(crv[:, 0], crv[:, 1])
        kp = _knot_points(ctrl, knots, p)
        marks.set_data(kp[:, 0], kp[:, 1])
        new_poly.set_data(Q[:, 0], Q[:, 1])
        c = bspline.de_boor(ctrl, knots, p, x)
        at_u.set_data([c[0]], [c[1]])
        pieces = ki.to_piecewise_bezier(ctrl, knots, p)[0] if bezier else np.zeros((0, p + 1, 2))
        for j, line in enumerate(piece_lines):
            if j < len(pieces):
                line.set_data(pieces[j][:, 0], pieces[j][:, 1])
            else:
                line.set_data([], [])
        knot_text = ", ".join(f"{v:g}" for v in np.round(tau, 2))
        status = (f"degree {p}; insert u = {x:.2f} x{k}: {len(ctrl)} -> {len(Q)} control points; "
                  f"new knots [{knot_text}]")
        return {"polygon": Q, "knots": tau, "curve": crv, "pieces": pieces, "status": status}

    controls = {**editor.controls,
                "u": float_slider("insert u", u, 0.0, 1.0, 0.01, label_width="70px"),
                "times": int_slider("times", times, 0, 6, label_width="70px"),
                "bezier": widgets.Checkbox(value=False, description="Bezier pieces", indent=False)}
    arrange = [controls["u"], controls["times"], controls["bezier"]] + editor.arrange()
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="knot insertion with the knot-vector editor", arrange=arrange, side=True)
    editor.attach(view)
    return view


_RENDER_METHODS = {"Bezier pieces (28.3.5)": "bezier", "subdivision (28.4.4)": "subdivision"}


def render_view(ctrl=DEFAULT_POLYGON, knots=DEFAULT_KNOTS, degree: int = DEFAULT_DEGREE, second=DEFAULT_SECOND,
                digits: int = 2, shift: float = 0.0) -> InteractiveView:
    """Rendering and intersecting a B-spline by knot insertion (Goldman §28.3.5, §28.4.4).

    The curve is drawn as the polyline :func:`goldman_lib.knot_insertion.render_by_subdivision` returns for the
    tolerance ``10^-digits``: the chords of flat Bezier pieces, or the subdivided control polygon.
    A second B-spline, moved up or down by ``shift``, is intersected with it
    (:func:`goldman_lib.knot_insertion.intersect`) and the crossings are marked.

    ``update(method, digits, shift)`` returns the polyline, the intersection points and parameters.
    """

    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    p = as_int(degree, "degree", minimum=1)
    knots = bspline.check_knots(knots, p, len(ctrl))
    q_ctrl = as_points(second[0], "second[0]", dim=2, min_count=2)
    q_deg = as_int(second[2], "second[2]", minimum=1)
    q_knots = bspline.check_knots(second[1], q_deg, len(q_ctrl), name="second[1]")
    fig, ax = style.new_axes()
    crv = _curve_points(ctrl, knots, p)
    ax.plot(crv[:, 0], crv[:, 1], color=style.PALETTE["curve"], linewidth=6, alpha=0.18, label="the curve")
    (drawn,) = ax.plot([], [], "o-", color=style.PALETTE["curve"], markersize=2.5, linewidth=1.1,
                       label="rendered polyline")
    (other,) = ax.plot([], [], color=style.PALETTE["good"], linewidth=1.8, label="second B-spline")
    (hits,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=9, zorder=5, label="intersections")
    ax.legend(loc="lower right", fontsize=7, frameon=False)
    other_base = _curve_points(q_ctrl, q_knots, q_deg)
    _limits(ax, np.vstack([ctrl, crv, other_base + [0, 1.2], other_base - [0, 1.2]]))
    ax.set_title("render and intersect by knot insertion", fontsize=10)

    def update(method, digits, shift):
        how = _RENDER_METHODS.get(method, "bezier")
        tol = 10.0 ** -int(min(max(digits, 1), 4))
        pts, levels = ki.render_by_subdivision(ctrl, knots, p, tol=tol, method=how)
        drawn.set_data(pts[:, 0], pts[:, 1])
        drawn.set_marker("o" if len(pts) <= _MARKER_LIMIT else "None")
        moved = q_ctrl + np.array([0.0, float(shift)])
        oc = other_base + np.array([0.0, float(shift)])
        other.set_data(oc[:, 0], oc[:, 1])
        params, xs = ki.intersect((ctrl, knots, p), (moved, q_knots, q_deg))
        hits.set_data(xs[:, 0], xs[:, 1])
        status = (f"tolerance {tol:.0e}: {len(pts)} points after {levels} halving level{'s' if levels != 1 else ''}; "
                  f"{len(xs)} intersection{'s' if len(xs) != 1 else ''}")
        return {"polyline": pts, "points": xs, "params": params, "status": status}

    controls = {"method": dropdown("method", list(_RENDER_METHODS), list(_RENDER_METHODS)[0], label_width="60px", width="290px"),
                "digits": int_slider("tol 1e-", digits, 1, 4),
                "shift": float_slider("shift", shift, -1.2, 1.2, 0.05)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="rendering and intersecting by knot insertion")
