"""The knot-vector editor: a shared component for the B-spline chapters (27 and 28).

How a chapter reuses it
-----------------------
* The rule is a plain function: :func:`knots_from_values` maps ANY slider values (any degree,
  any preset) to a valid knot vector -- non-decreasing, at most ``max(degree, 1)`` equal interior
  knots, interior knots strictly inside the domain [0, 1] -- so an ``update`` built on it never
  raises.  :data:`RULE_TEXT` says the rule in words (the editor shows it under its sliders).
* :func:`knot_vector_editor` returns a :class:`KnotEditor`: its ``controls`` (a degree picker, a
  preset picker ``clamped / uniform / custom``, one slider per interior knot -- created for the
  largest count and hidden when the degree needs fewer -- and optionally one weight slider per
  control point), ``read(values) -> (knots, degree, weights)`` for an ``update(**values)``,
  ``arrange()`` for the control box, and ``attach(view)`` which installs the push rule on the
  sliders themselves (dragging a knot past a neighbour pushes the neighbour) and the show/hide
  of sliders when the degree changes.  Use a ``prefix`` to put two editors (u and v) in one view::

      editor = knot_vector_editor(n_ctrl=7, degree=3)
      controls = {**editor.controls, "u": float_slider("u", 0.5, 0, 1)}
      def update(u, **values):
          knots, degree, weights = editor.read(values)
          ...
      view = InteractiveView(controls=controls, update=update, arrange=editor.arrange() + [...], ...)
      editor.attach(view)

* Ready-made views: :func:`bspline_curve_editor` (matplotlib: curve, control polygon, knot marks
  on the curve, the basis functions in a panel below), :func:`nurbs_curve_editor` (the same with
  weights; starts as the exact circle) and :func:`bspline_surface_editor` (three.js: a
  tensor-product surface updated in place, with two editors for u and v).

>>> knots_from_values([0.7, 0.2, 0.9], 2, 6, "custom").tolist()
[0.0, 0.0, 0.0, 0.7, 0.7, 0.9, 1.0, 1.0, 1.0]
"""

from __future__ import annotations

import contextlib

import html

import numpy as np

from goldman_lib import bspline
from goldman_lib.bspline import KNOT_GAP as GAP, KNOT_PRESETS as PRESETS, interior_values, knots_from_values, push_knots
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders, pair_rows, point_pairs, point_sliders, points_from
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, InteractiveView
from goldman_lib.widgets.three import SceneView, grid_triangles

__all__ = ["PRESETS", "RULE_TEXT", "knots_from_values", "push_knots", "interior_values", "KnotEditor",
           "knot_vector_editor", "plot_knot_marks", "plot_basis_functions",
           "bspline_curve_editor", "nurbs_curve_editor", "bspline_surface_editor",
           "DEFAULT_POLYGON", "DEFAULT_NET"]

RULE_TEXT = ("Knots never decrease: dragging a knot past a neighbour pushes the neighbour along "
             "(a knot set below its left neighbour is raised to it). At most p interior knots may "
             "coincide (the curve stays continuous), and interior knots stay inside (0, 1). "
             "Presets: clamped = p+1 knots at each end, interior evenly spaced; uniform = all knots "
             "evenly spaced (floating ends); custom = clamped ends, interior from the sliders.")


class KnotEditor:
    """The controls of a knot-vector editor and the plain functions that read them.

    controls: ``{name: widget}`` (``degree``, ``preset``, ``k1`` .. ``kM``, optionally
    ``w0`` .. ``wn``, all with the editor's ``prefix``).  ``read(values)`` turns a dict of
    control values (e.g. the ``**values`` an ``update`` receives) into ``(knots, degree,
    weights)``, always valid.  ``attach(view)`` installs the observers (push rule, show/hide,
    presets) on an :class:`InteractiveView` built with these controls.
    """

    def __init__(self, n_ctrl: int, degree: int, max_degree: int, preset: str, interior, weights,
                 prefix: str, label: str):
        import ipywidgets as widgets

        self.n_ctrl = n_ctrl
        self.prefix = prefix
        self.max_degree = max_degree
        self.max_interior = n_ctrl - 2           # at degree 1
        self.rule_text = RULE_TEXT
        pre = prefix
        self.degree_name, self.preset_name = f"{pre}degree", f"{pre}preset"
        self.knot_names = [f"{pre}k{i + 1}" for i in range(self.max_interior)]
        self.weight_names = [f"{pre}w{i}" for i in range(n_ctrl)] if weights is not None else []
        degree_w = dropdown(f"{label}degree", list(range(1, max_degree + 1)), degree, label_width="70px", width="150px")
        preset_w = dropdown(f"{label}knots", list(PRESETS), preset, label_width="70px", width="190px")
        self.controls = {self.degree_name: degree_w, self.preset_name: preset_w}
        start = knots_from_values(interior, degree, n_ctrl, preset)
        shown = list(interior_values(start, degree))
        full = shown + list(np.linspace(0, 1, self.max_interior + 2)[1:-1][len(shown):])
        for i, name in enumerate(self.knot_names):
            m = n_ctrl - degree - 1
            s = float_slider(f"t{degree + 1 + i}" if i < m else f"k{i + 1}", float(full[i]), 0.0, 1.0, GAP)
            self.controls[name] = s
        for i, name in enumerate(self.weight_names):
            self.controls[name] = float_slider(f"w{i}", float(weights[i]), 0.1, 4.0, 0.05)
        self.rule = widgets.HTML(f"<small>{html.escape(RULE_TEXT)}</small>",
                                 layout=widgets.Layout(max_width="300px"))
        self.knots_label = widgets.HTML("", layout=widgets.Layout(max_width="300px"))
        self._view = None
        self._busy = False
        self._layout(degree, preset)
        self._show_knots(start)

    # -- the plain-function side ------------------------------------------------------------
    def read(self, values: dict):
        """``(knots, degree, weights)`` for a dict of control values (missing ones: current)."""
        get = lambda name: values[name] if name in values else self.controls[name].value  # noqa: E731
        degree = int(get(self.degree_name))
        preset = get(self.preset_name)
        if preset not in PRESETS:
            preset = "clamped"
        knots = knots_from_values([get(k) for k in self.knot_names], degree, self.n_ctrl, preset)
        weights = None
        if self.weight_names:
            w = np.array([get(k) for k in self.weight_names], dtype=float)
            weights = np.where(np.isfinite(w) & (w > 0), w, 1.0)
        return knots, min(max(degree, 0), self.n_ctrl - 1), weights

    def knots(self) -> np.ndarray:
        """The knot vector the controls show now."""
        return self.read({})[0]

    def degree(self) -> int:
        return self.read({})[1]

    def weights(self):
        return self.read({})[2]

    def arrange(self) -> list:
        """The editor's widgets in order: pickers, knot sliders, the knot vector, the rule, weights."""
        import ipywidgets as widgets

        out = [self.controls[self.degree_name], self.controls[self.preset_name]]
        out += [self.controls[k] for k in self.knot_names]
        out += [self.knots_label, self.rule]
        if self.weight_names:
            out.append(widgets.HTML("<small>weights</small>"))
            out += [self.controls[k] for k in self.weight_names]
        return out

    # -- the widget side --------------------------------------------------------------------------
    def _layout(self, degree: int, preset: str):
        m = self.n_ctrl - degree - 1
        for i, name in enumerate(self.knot_names):
            w = self.controls[name]
            w.layout.display = None if i < m else "none"
            w.description = f"t{degree + 1 + i}"
            w.disabled = preset != "custom"

    def _show_knots(self, knots):
        text = ", ".join(f"{x:g}" for x in np.round(knots, 3))
        self.knots_label.value = f"<small>knots = [{html.escape(text)}]</small>"

    def _set_sliders(self, vals):
        for name, v in zip(self.knot_names, vals):
            w = self.controls[name]
            if w.value != float(v):
                w.value = float(v)

    def attach(self, view: InteractiveView):
        """Install the observers on the sliders of ``view`` (built with :attr:`controls`)."""
        self._view = view
        self.controls[self.degree_name].observe(self._on_degree, names="value")
        self.controls[self.preset_name].observe(self._on_preset, names="value")
        for i, name in enumerate(self.knot_names):
            self.controls[name].observe(lambda change, i=i: self._on_knot(i), names="value")
        self._show_knots(self.knots())
        return view

    def _quiet(self, fn):
        """Run fn with the view's own observer muted, then refresh once."""
        if self._busy:
            return
        self._busy = True
        view = self._view
        try:
            with (view.muted() if view is not None else contextlib.nullcontext()):
                fn()
        finally:
            self._busy = False
        self._show_knots(self.knots())
        if view is not None:
            view.refresh()

    def _preset_interior(self, degree, preset):
        return interior_values(knots_from_values([], degree, self.n_ctrl,
                                                 "clamped" if preset == "custom" else preset), degree)

    def _on_degree(self, change):
        degree = int(change["new"])
        preset = self.controls[self.preset_name].value

        def go():
            self._layout(degree, preset)
            self._set_sliders(self._preset_interior(degree, preset))
        self._quiet(go)

    def _on_preset(self, change):
        preset = change["new"]
        degree = int(self.controls[self.degree_name].value)

        def go():
            self._layout(degree, preset)
            if preset != "custom":
                self._set_sliders(self._preset_interior(degree, preset))
        self._quiet(go)

    def _on_knot(self, i: int):
        if self._busy:
            return
        degree = int(self.controls[self.degree_name].value)
        m = self.n_ctrl - degree - 1
        if i >= m:
            return
        vals = [self.controls[k].value for k in self.knot_names[:m]]
        pushed = push_knots(vals, i, degree)
        if np.array_equal(pushed, vals):
            self._show_knots(self.knots())
            return
        self._quiet(lambda: self._set_sliders(pushed))


def knot_vector_editor(n_ctrl: int = 7, degree: int = 3, max_degree: int = 5, preset: str = "custom",
                       interior=None, weights=None, prefix: str = "", label: str = "") -> KnotEditor:
    """Build the controls of a knot-vector editor for ``n_ctrl`` control points (Goldman §27.2-27.4).

    degree: the starting degree, in 1 .. max_degree (max_degree is cut to n_ctrl - 1).  preset:
    ``clamped``, ``uniform`` or ``custom``.  interior: starting interior knots (custom preset;
    default evenly spaced).  weights: (n_ctrl,) starting weights to add weight sliders (NURBS),
    or None.  prefix/label: put in front of every control name / description (two editors in one view).
    Raises ValueError for a bad count, degree or preset.

    >>> ed = knot_vector_editor(n_ctrl=5, degree=2)
    >>> sorted(ed.controls)
    ['degree', 'k1', 'k2', 'k3', 'preset']
    >>> ed.read({"degree": 2, "k1": 0.8, "k2": 0.3}) [0].tolist()
    [0.0, 0.0, 0.0, 0.8, 0.8, 1.0, 1.0, 1.0]
    """
    n_ctrl = as_int(n_ctrl, "n_ctrl", minimum=2)
    max_degree = min(as_int(max_degree, "max_degree", minimum=1), n_ctrl - 1)
    degree = as_int(degree, "degree", minimum=1, maximum=max_degree)
    if preset not in PRESETS:
        raise ValueError(f"preset must be one of {PRESETS}; got {preset!r}")
    if weights is not None:
        weights = np.asarray(weights, dtype=float)
        if weights.shape != (n_ctrl,) or not np.all(weights > 0):
            raise ValueError(f"weights must hold {n_ctrl} positive numbers; got {weights.tolist()}")
    return KnotEditor(n_ctrl, degree, max_degree, preset, interior, weights, prefix, label)


# -- static plots -----------------------------------------------------------------------------
def plot_knot_marks(ctrl, knots, degree, ax=None, weights=None):
    """Mark the curve points ``C(t_i)`` at the distinct knots of the domain (Goldman §27.2); returns the marker line."""
    ax = style.get_axes(ax)
    pts = _knot_points(np.asarray(ctrl, float), np.asarray(knots, float), int(degree), weights)
    (marks,) = ax.plot(pts[:, 0], pts[:, 1], "D", color=style.PALETTE["accent"], markersize=6,
                       markeredgecolor="#333333", zorder=4, label="knots on the curve")
    return marks


def _knot_points(ctrl, knots, degree, weights=None):
    lo, hi = bspline.domain(knots, degree)
    at = np.unique(knots[(knots >= lo) & (knots <= hi)])
    if weights is None:
        return bspline.de_boor(ctrl, knots, degree, at)
    return bspline.nurbs_curve(ctrl, weights, knots, degree, at)


def plot_basis_functions(knots, degree, ax=None, samples: int = 300):
    """Draw every basis function ``N_{k,p}`` over the domain (Goldman §27.3); returns the lines."""
    t = bspline.check_knots(knots, degree)
    p = int(degree)
    ax = style.get_axes(ax, equal=False)
    u = np.linspace(*bspline.domain(t, p), samples)
    lines = ax.plot(u, bspline.basis(t, p, u), linewidth=1.5)
    ax.set_ylim(-0.03, 1.05)
    ax.set_xlabel("u")
    return lines


# -- the curve views ----------------------------------------------------------------------------
#: The default control polygon of the curve editor: 7 points, a wave.
DEFAULT_POLYGON = np.array([[0.0, 0.0], [0.8, 2.2], [2.0, 2.6], [3.0, 0.4], [4.2, 0.2], [5.0, 2.4], [6.0, 1.6]])


def _curve_figure(ctrl, n_basis):
    from matplotlib.gridspec import GridSpec
    from matplotlib.ticker import FixedLocator, MaxNLocator

    fig = style.new_figure(figsize=(5.6, 5.4))
    gs = GridSpec(2, 1, height_ratios=[2.2, 1], hspace=0.3, figure=fig)
    ax = fig.add_subplot(gs[0])
    style.style_axes(ax)
    axb = fig.add_subplot(gs[1])
    style.style_axes(axb, equal=False)
    pad = 0.5
    lo, hi = ctrl.min(0), ctrl.max(0)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    (polygon,) = ax.plot(ctrl[:, 0], ctrl[:, 1], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1)
    (curve,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.2)
    (marks,) = ax.plot([], [], "D", color=style.PALETTE["accent"], markersize=6, markeredgecolor="#333333", zorder=4)
    lines = [axb.plot([], [], linewidth=1.5)[0] for _ in range(n_basis)]
    (ticks,) = axb.plot([], [], "|", color="#333333", markersize=12, markeredgewidth=1.5)
    axb.set_xlim(-0.02, 1.02)
    axb.set_ylim(-0.05, 1.08)
    axb.set_xlabel("u", labelpad=1)
    # few ticks, no grid and plain-text titles below: a redraw is mostly text, and it must stay fast
    ax.xaxis.set_major_locator(MaxNLocator(5))
    ax.yaxis.set_major_locator(MaxNLocator(4))
    axb.xaxis.set_major_locator(FixedLocator([0.0, 0.25, 0.5, 0.75, 1.0]))
    axb.yaxis.set_major_locator(FixedLocator([0.0, 0.5, 1.0]))
    axb.grid(False)
    axb.set_title("basis functions N_k,p(u); knots marked |", fontsize=9)
    return fig, ax, axb, polygon, curve, marks, lines, ticks


def _continuity_text(knots, degree):
    t = np.asarray(knots)
    inner = interior_values(t, degree)
    vals, counts = np.unique(inner, return_counts=True)
    multi = [f"C^{degree - c} at {v:g}" for v, c in zip(vals, counts) if c > 1]
    return ("; ".join(multi) + " (repeated knots)") if multi else f"C^{degree - 1} at every interior knot"


def _curve_editor(ctrl, degree, max_degree, preset, interior, weights, samples, title) -> InteractiveView:
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=3)
    n_ctrl = len(ctrl)
    max_degree = min(as_int(max_degree, "max_degree", minimum=1), n_ctrl - 1)
    degree = min(as_int(degree, "degree", minimum=1), max_degree)
    editor = knot_vector_editor(n_ctrl, degree, max_degree, preset, interior, weights)
    fig, ax, axb, polygon, curve, marks, lines, ticks = _curve_figure(ctrl, n_ctrl)
    rational = weights is not None
    if rational:
        axb.set_title("rational basis R_k(u) = w_k N_k,p(u) / sum_j w_j N_j,p(u)", fontsize=9)
    ax.set_title("NURBS curve: curve, control polygon, knots" if rational else
                 "B-spline curve: curve, control polygon, knots", fontsize=10)
    u = np.linspace(0.0, 1.0, samples)
    # the control points: x/y sliders over the figure's box, and dragged with the mouse
    points = point_sliders(ctrl, (*ax.get_xlim(), *ax.get_ylim()), width="200px", label_width="24px")

    def update(**values):
        knots, p, w = editor.read(values)
        ctrl = points_from(values, n_ctrl)
        polygon.set_data(ctrl[:, 0], ctrl[:, 1])
        if rational:
            pts = bspline.nurbs_curve(ctrl, w, knots, p, u)
            N = bspline.rational_basis(knots, p, w, u)
        else:
            pts = bspline.de_boor(ctrl, knots, p, u)
            N = bspline.basis(knots, p, u)
        curve.set_data(pts[:, 0], pts[:, 1])
        kp = _knot_points(ctrl, knots, p, w)
        marks.set_data(kp[:, 0], kp[:, 1])
        for k, line in enumerate(lines):
            line.set_data(u, N[:, k])
        inside = knots[(knots >= 0) & (knots <= 1)]
        ticks.set_data(inside, np.zeros_like(inside))
        status = f"degree {p}, {n_ctrl} control points, {len(knots)} knots; {_continuity_text(knots, p)}"
        return {"curve": pts, "knots": knots, "knot_points": kp, "basis": N, "polygon": ctrl,
                "weights": w if rational else np.ones(n_ctrl), "status": status}

    import ipywidgets as widgets

    view = InteractiveView(controls={**editor.controls, **points}, views=[figure_widget(fig)], update=update,
                           figure=fig, title=title, side=True,
                           arrange=editor.arrange() + [widgets.HTML("<small>control points (or drag them)</small>")]
                           + pair_rows(points, n_ctrl))
    editor.attach(view)
    view.editor = editor
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n_ctrl))
    style.pin_layout(fig)        # fixed limits: titles and labels placed once; axes and titles rendered once
    for a in (ax, axb):
        style.freeze_axes_decorations(a, a.title)
    return view


def bspline_curve_editor(ctrl=DEFAULT_POLYGON, degree: int = 3, max_degree: int = 5, preset: str = "custom",
                         interior=None, samples: int = 240) -> InteractiveView:
    """The knot-vector editor on a planar B-spline curve (Goldman §27.3-27.4, §27.7).

    A degree picker, a preset picker and one slider per interior knot (they never let the knots
    decrease); the figure shows the curve, its control polygon, the curve points at the knots,
    and below it every basis function ``N_{k,p}`` with the knots marked.  The control points have
    x/y sliders and can be dragged with the mouse (``view.drag``).  ``update(**values)``
    returns the curve, the knot vector, the knot points and the basis values.
    """
    return _curve_editor(ctrl, degree, max_degree, preset, interior, None, samples, "knot-vector editor")


def _circle_default():
    ctrl, w, knots, p = bspline.nurbs_circle()
    return ctrl, w, interior_values(knots, p)


_CIRCLE_CTRL, _CIRCLE_W, _CIRCLE_INTERIOR = _circle_default()


def nurbs_curve_editor(ctrl=_CIRCLE_CTRL, weights=_CIRCLE_W, degree: int = 2, max_degree: int = 4,
                       preset: str = "custom", interior=_CIRCLE_INTERIOR, samples: int = 240) -> InteractiveView:
    """The knot-vector editor with a weight slider per control point: a NURBS curve (Goldman §27.9).

    It starts as the exact circle (9 control points on a square, weights 1 and sqrt(2)/2, double
    interior knots).  Raising a weight pulls the curve towards its control point; the panel below
    shows the rational basis ``R_k = w_k N_k / sum_j w_j N_j``.
    """
    weights = np.asarray(weights, dtype=float)
    return _curve_editor(ctrl, degree, max_degree, preset, interior, weights, samples, "NURBS editor")


# -- the surface view ---------------------------------------------------------------------------
def _default_net(m: int = 6, n: int = 6) -> np.ndarray:
    i, j = np.meshgrid(np.linspace(0, 3, m), np.linspace(0, 3, n), indexing="ij")
    z = 0.9 * np.sin(1.3 * i) * np.cos(1.1 * j) + 0.4
    z[0, :] = z[:, 0] = 0.0
    return np.stack([i, j, z], -1)


#: The default 6 x 6 control net of the surface editor.
DEFAULT_NET = _default_net()


def bspline_surface_editor(ctrl=DEFAULT_NET, degree_u: int = 3, degree_v: int = 2, max_degree: int = 4,
                           resolution: int = 30, width: int = 480, height: int = 360) -> InteractiveView:
    """Two knot-vector editors (u and v) on a three.js tensor-product B-spline surface (Goldman §27.8).

    The surface ``S(u, v) = sum N_i(u) N_j(v) P_ij`` is evaluated on a ``resolution^2`` grid as
    basis matrices ``N(u) P N(v)^T`` and the mesh is updated in place; the control net, and the
    isoparametric curves at the interior knots (the seams between the polynomial patches), are
    drawn too.  ``update(**values)`` returns the surface grid, both knot vectors and the seams.
    """
    net = as_points(ctrl, "ctrl", ndim=3, dim=3, min_count=3)
    m1, n1 = net.shape[:2]
    resolution = as_int(resolution, "resolution", minimum=4, maximum=120)
    max_degree = as_int(max_degree, "max_degree", minimum=1)
    ed_u = knot_vector_editor(m1, min(degree_u, m1 - 1), min(max_degree, m1 - 1), prefix="u_", label="u ")
    ed_v = knot_vector_editor(n1, min(degree_v, n1 - 1), min(max_degree, n1 - 1), prefix="v_", label="v ")
    grid = np.linspace(0.0, 1.0, resolution)
    ii, jj = np.meshgrid(np.arange(m1), np.arange(n1), indexing="ij")
    idx = ii * n1 + jj
    net_segments = np.concatenate([np.stack([idx[:, :-1].ravel(), idx[:, 1:].ravel()], 1),
                                   np.stack([idx[:-1, :].ravel(), idx[1:, :].ravel()], 1)])
    # seams: one polyline of `resolution` points per possible interior knot in each direction
    n_seams = ed_u.max_interior + ed_v.max_interior
    seg = np.arange(resolution - 1)
    seam_segments = np.concatenate([np.stack([s * resolution + seg, s * resolution + seg + 1], 1) for s in range(n_seams)])
    center = net.reshape(-1, 3).mean(0)
    scene = SceneView(width=width, height=height, target=tuple(center),
                      camera_position=tuple(center + np.array([3.6, -4.6, 3.8])), axes=1.0)
    flat = np.zeros((resolution * resolution, 3))
    scene.add_mesh("surface", flat, grid_triangles(resolution, resolution), color=style.PALETTE["surface"])
    scene.add_segments("net", net.reshape(-1, 3), net_segments, color="#555555")
    scene.add_points("control points", net.reshape(-1, 3), color="#333333", size=0.1)
    scene.add_segments("seams", np.zeros((n_seams * resolution, 3)), seam_segments, color=style.PALETTE["point"])

    def update(**values):
        tu, pu, _ = ed_u.read(values)
        tv, pv, _ = ed_v.read(values)
        surf = bspline.surface_grid(net, tu, tv, pu, pv, grid, grid)
        seams = []
        for a in interior_values(tu, pu):
            seams.append(bspline.surface_grid(net, tu, tv, pu, pv, [a], grid)[0])
        for b in interior_values(tv, pv):
            seams.append(bspline.surface_grid(net, tu, tv, pu, pv, grid, [b])[:, 0])
        drawn = np.concatenate(seams) if seams else np.zeros((0, 3))
        filler = np.broadcast_to(surf[0, 0], (n_seams * resolution - len(drawn), 3))
        scene.set_mesh("surface", surf.reshape(-1, 3))
        scene.set_segments("seams", np.concatenate([drawn, filler]))
        patches = (len(np.unique(tu[pu:len(tu) - pu])) - 1) * (len(np.unique(tv[pv:len(tv) - pv])) - 1)
        return {"surface": surf, "knots_u": tu, "knots_v": tv, "seams": drawn,
                "status": f"bidegree ({pu}, {pv}), {m1}x{n1} control points, {patches} polynomial patches; drag to orbit"}

    controls = {**ed_u.controls, **ed_v.controls}
    arrange = ed_u.arrange()[:-1] + ed_v.arrange()          # the rule text once, at the end
    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="B-spline surface: knot vectors in u and v", side=True, arrange=arrange)
    ed_u.attach(view)
    ed_v.attach(view)
    view.scene = scene
    view.editors = (ed_u, ed_v)
    return view
