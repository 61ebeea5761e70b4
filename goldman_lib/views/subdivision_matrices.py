"""Chapter 29 views: curves drawn as attractors of their subdivision IFS, and fractals with control
points whose sliders reshape the fractal (Goldman §29.3-29.4).

>>> view = fractal_editor()
>>> sorted(view.update(**view.values()))
['fractal', 'joint', 'polygon', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier, ifs
from goldman_lib import subdivision_matrices as sm
from goldman_lib.subdivision_matrices import barycentric_attractor  # noqa: F401  (moved to the library)
from goldman_lib.validation import (as_float, as_float_array, as_int, as_points, check_finite, finite_result,
                                     within_budget)
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider, int_slider

__all__ = ["DEFAULT_TRIANGLE", "DEFAULT_CUBIC", "plot_attractor_levels",
           "curve_attractor_view", "fractal_editor"]

#: The three control points of the fractal editor.
DEFAULT_TRIANGLE = np.array([[0.0, 0.0], [1.5, 2.5], [4.0, 0.0]])
#: The cubic of the attractor view.
DEFAULT_CUBIC = np.array([[0.0, 0.0], [1.0, 2.5], [3.0, 2.5], [4.0, 0.0]])


def plot_attractor_levels(ctrl, levels=(0, 1, 2, 4), ax=None, kind: str = "bezier"):
    """Draw the sets of the deterministic algorithm for the curve's IFS, starting from the control
    polygon (Goldman §29.3): level k is the 2^k control polygons of the pieces.  Returns the lines."""
    P = as_points(ctrl, "ctrl", dim=2)
    ax = style.get_axes(ax)
    lines = []
    for j, k in enumerate(levels):
        pts = sm.curve_as_attractor(P, k, kind)
        blocks = pts.reshape(-1, len(P), 2)
        sep = np.concatenate([blocks, np.full((len(blocks), 1, 2), np.nan)], axis=1).reshape(-1, 2)
        colour = style.PALETTE["control"] if k == 0 else style.level_colour(j)
        (ln,) = ax.plot(sep[:, 0], sep[:, 1], "-", color=colour, linewidth=1.2, label=f"level {k}")
        lines.append(ln)
    return lines


def curve_attractor_view(ctrl=DEFAULT_CUBIC, levels: int = 2, max_levels: int = 8) -> InteractiveView:
    """A level slider for the deterministic algorithm of the IFS ``{P^-1 L P, P^-1 R P}`` started
    from the control polygon (Goldman §29.3), with a Bezier / B-spline picker: the 2^k polygons
    converge to the curve.  ``update(kind, levels)`` returns the polygons and their distance to the curve.
    """
    import ipywidgets as widgets

    P = as_points(ctrl, "ctrl", dim=2, min_count=2)
    max_levels = as_int(max_levels, "max_levels", minimum=1, maximum=12)
    fig, ax = style.new_axes()
    ax.plot(P[:, 0], P[:, 1], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1, label="control polygon")
    (polys,) = ax.plot([], [], "-", color=style.PALETTE["accent"], linewidth=1.4, label="level-k sets")
    (curve,) = ax.plot([], [], "-", color=style.PALETTE["curve"], linewidth=2.2, alpha=0.6, label="the curve")
    ax.legend(loc="lower center", fontsize=8, frameon=False, ncol=3)
    pad = 0.4
    ax.set_xlim(P[:, 0].min() - pad, P[:, 0].max() + pad)
    ax.set_ylim(P[:, 1].min() - pad, P[:, 1].max() + pad)
    dense = {kind: sm.curve_as_attractor(P, 8, kind).reshape(-1, len(P), 2).mean(1) for kind in ("bezier", "bspline")}

    def update(kind, levels):
        levels = as_int(levels, "levels", minimum=0, maximum=max_levels)
        pts = sm.curve_as_attractor(P, levels, kind)
        blocks = pts.reshape(-1, len(P), 2)
        sep = np.concatenate([blocks, np.full((len(blocks), 1, 2), np.nan)], axis=1).reshape(-1, 2)
        polys.set_data(sep[:, 0], sep[:, 1])
        c = dense[kind]
        curve.set_data(c[:, 0], c[:, 1])
        # flatness: how far each piece's control points stray from the chord of their piece
        flat = float(bezier.flatness(blocks, even=False).max())
        return {"polygons": pts, "flatness": flat,
                "status": f"{kind}: {len(blocks)} polygons after {levels} level(s); each within {flat:.4f} of its chord"}

    controls = {"kind": widgets.ToggleButtons(options=["bezier", "bspline"], value="bezier", description="curve",
                                              style={"description_width": "48px", "button_width": "80px"}),
                "levels": int_slider("levels", as_int(levels, "levels", minimum=0, maximum=max_levels), 0, max_levels)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="a curve as the attractor of its IFS")


def fractal_editor(ctrl=DEFAULT_TRIANGLE, middle: float = -0.3, levels: int = 10,
                   box=(-1.0, 5.0, -2.0, 4.0)) -> InteractiveView:
    """Control-point sliders reshaping a fractal curve (Goldman §29.4).

    The matrices of :func:`~goldman_lib.subdivision_matrices.fractal_matrices` (rows summing to one;
    ``middle`` is the weight of ``P1`` where the two pieces meet, 1/2 for the Bezier parabola)
    are conjugated by the control points, ``P^-1 L P`` and ``P^-1 R P``, and the attractor is drawn
    with ``ifs.deterministic`` from the end points; the control points can be dragged with the
    mouse (``view.drag``).  ``update(middle, levels, x0, y0, ...)``
    returns the fractal polyline, the control polygon and the joint ``u P0 + v P1 + w P2``.
    Collinear control points have no ``P^-1``; the view then draws the same attractor from
    barycentric coordinates and says so.
    """
    P0 = as_points(ctrl, "ctrl", dim=2)
    if len(P0) != 3:
        raise ValueError(f"ctrl must hold 3 control points; got {len(P0)}")
    xmin, xmax, ymin, ymax = box
    fig, ax = style.new_axes()
    ax.set_xlim(xmin, xmax)
    ax.set_ylim(ymin, ymax)
    (polygon,) = ax.plot(*P0.T, "o--", color=style.PALETTE["control"], markersize=6, linewidth=1)
    (fractal,) = ax.plot([], [], "-", color=style.PALETTE["curve"], linewidth=1.2)
    (joint,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=6)
    ax.set_title("a fractal with control points", fontsize=10)

    controls = {"middle": float_slider("middle", middle, -1.0, 1.0, 0.05),
                "levels": int_slider("levels", levels, 1, 13)}
    for k, (x, y) in enumerate(P0):
        controls[f"x{k}"] = float_slider(f"x{k}", float(x), xmin, xmax, 0.1)
        controls[f"y{k}"] = float_slider(f"y{k}", float(y), ymin, ymax, 0.1)

    def update(middle, levels, **coords):
        P = np.array([[as_float(coords[f"x{k}"], f"x{k}"), as_float(coords[f"y{k}"], f"y{k}")] for k in range(3)])
        middle = as_float(middle, "middle")
        levels = as_int(levels, "levels", minimum=0, maximum=16)
        mats = sm.fractal_matrices(middle)
        try:
            system = sm.control_point_ifs(P, mats)
            pts = ifs.deterministic(system, levels, start=P[[0, 2]])
            how = "ifs.deterministic on {P^-1 L P, P^-1 R P}"
        except ValueError:
            pts = sm.barycentric_attractor(mats, levels) @ P
            how = "control points collinear (no P^-1): drawn from barycentric coordinates"
        finite_result(pts, "middle", middle, why="is too far from [-1, 1]")
        u = (1 - middle) / 2
        J = u * P[0] + middle * P[1] + u * P[2]
        polygon.set_data(P[:, 0], P[:, 1])
        fractal.set_data(pts[:, 0], pts[:, 1])
        joint.set_data([J[0]], [J[1]])
        return {"fractal": pts, "polygon": P, "joint": J,
                "status": f"middle weight {middle:.2f} ({'the Bezier parabola' if abs(middle - 0.5) < 1e-9 else 'a fractal curve'}); "
                          f"{len(pts) // 2} pieces; {how}"}

    import ipywidgets as widgets

    arrange = [controls["middle"], controls["levels"], widgets.HTML("<small>control points</small>")]
    arrange += [controls[f"{a}{k}"] for k in range(3) for a in "xy"]
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="fractal with control points", arrange=arrange, side=True)
    # the control points are also dragged with the mouse; a drag sets their sliders
    from goldman_lib.widgets.drag import drag_sliders, point_pairs

    view.ax = ax
    drag_sliders(view, ax, point_pairs(3))
    return view
