"""Chapter 14 views: the law of the lever with mass-points you drag, and perspective versus
pseudoperspective of a small scene seen from the side (Goldman §14.3-14.4).

Both factories return an :class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update``
is a plain function returning what it drew; all the mathematics is
:mod:`goldman_lib.mass_points`:

* :func:`lever_view`: three points with mass sliders (negative masses too; a point of mass 0 adds
  nothing), draggable with the mouse.  The sum of the mass-points is drawn: the centre of mass with
  the total mass, or -- when the masses cancel -- a vector (an arrow), with a message;
* :func:`pseudoperspective_view`: an eye, a projection plane and three objects at different
  depths in a side view (the plane ``x = 0``).  Left: the scene, lines of sight and the
  perspective images on the plane, where depth is lost.  Right: the pseudoperspective image,
  image height against pseudodepth, where depth order survives and lines stay lines.  An eye on
  the plane, a plane behind the eye and points behind the eye are messages in the status.

>>> view = lever_view()
>>> sorted(view.update(**view.values()))
['center', 'masses', 'points', 'status', 'sum', 'vector']
>>> view.last_result["center"].tolist()         # masses 3 and 1 balance a quarter of the way along
[-1.0, 0.5]
"""

from __future__ import annotations

import numpy as np
from matplotlib import ticker

from goldman_lib import mass_points as mp
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider

__all__ = ["LEVER_POINTS", "LEVER_MASSES", "SCENE", "LABELLED", "lever_view", "pseudoperspective_view"]

#: The lever view's default points and masses: the third point starts without mass (a two-point lever).
LEVER_POINTS = ((-2.0, 0.0), (2.0, 2.0), (1.0, -2.5))
LEVER_MASSES = (3.0, 1.0, 0.0)
_LEVER_BOX = (-5.0, 5.0, -4.0, 4.0)

#: The side-view scene: name -> (k, 3) polyline in the plane x = 0 (y up, z the depth axis).  From
#: the default eye (0, 1, 0) the tops of the posts A and B lie on one line of sight.
SCENE = {
    "post A": np.array([[0.0, 0.0, 4.0], [0.0, 2.0, 4.0]]),
    "post B": np.array([[0.0, 0.0, 8.0], [0.0, 3.0, 8.0]]),
    "road C": np.array([[0.0, -1.5, 5.0], [0.0, 0.5, 11.0]]),
}
#: The points whose depths and pseudodepths the status reports.
LABELLED = {"A (top of post A)": np.array([0.0, 2.0, 4.0]), "B (top of post B)": np.array([0.0, 3.0, 8.0]),
            "C (far end of the road)": np.array([0.0, 0.5, 11.0])}
_SIDE_BOX = (-3.5, 12.0, -3.0, 5.0)
_SAMPLES = 9            # points drawn along each object, mapped one by one
_NORMAL = np.array([0.0, 0.0, 1.0])
_COLOURS = {"post A": "#00798c", "post B": "#d1495b", "road C": "#5c3c92"}


def _mass_point_or_zero(P, m) -> np.ndarray:
    """The mass-point ``(m P, m)``; for ``m = 0`` the zero vector (a point of mass 0 adds nothing)."""
    if m == 0:
        return mp.scale(0.0, mp.mass_point(P, 1.0))
    return mp.mass_point(P, m)


def lever_view(points=LEVER_POINTS, masses=LEVER_MASSES) -> InteractiveView:
    """Archimedes' law of the lever as a sum of mass-points (Goldman §14.3).

    Three points (drag them, or use the x, y sliders) with masses ``m0, m1, m2`` in [-3, 3]: the
    sum ``(m0 P0, m0) + (m1 P1, m1) + (m2 P2, m2)`` is drawn as the centre of mass (the black dot,
    its size the total mass).  A negative mass pushes instead of pulls (the centre leaves the
    segment); masses that sum to 0 give a vector ``(v, 0)``, drawn as an arrow from P0, with a
    message: a point at infinity, no centre.

    ``update(x0, y0, m0, ..., x2, y2, m2)`` returns the points, masses, the summed mass-point, and
    the centre (None for a vector) or the vector (None for a point).
    """
    from matplotlib.patches import FancyArrowPatch

    P0 = np.asarray(points, dtype=float)
    M0 = np.asarray(masses, dtype=float)
    if P0.shape != (3, 2) or M0.shape != (3,):
        raise ValueError("points must be three 2D points and masses three numbers")
    fig, ax = style.new_axes()
    x0, x1, y0, y1 = _LEVER_BOX
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_title("the sum of mass-points: centre of mass and total mass", fontsize=10)
    (bar,) = ax.plot([], [], "-", color=style.PALETTE["control"], linewidth=2.5, alpha=0.6, zorder=1)
    (line,) = ax.plot([], [], ":", color=style.PALETTE["control"], linewidth=1, zorder=1)
    dots = [ax.plot([], [], "o", markersize=8, zorder=3)[0] for _ in range(3)]
    labels = [ax.annotate("", (0, 0), textcoords="offset points", xytext=(-6, 9), ha="right", fontsize=9)
              for _ in range(3)]
    (centre,) = ax.plot([], [], "o", color="black", zorder=4)
    centre_label = ax.annotate("", (0, 0), textcoords="offset points", xytext=(7, -14), fontsize=9)
    arrow = FancyArrowPatch((0, 0), (0, 0), arrowstyle="-|>", mutation_scale=16, color=style.PALETTE["accent"],
                            linewidth=2, zorder=4)
    ax.add_patch(arrow)
    names = [("x0", "y0", "m0"), ("x1", "y1", "m1"), ("x2", "y2", "m2")]

    def update(x0, y0, m0, x1, y1, m1, x2, y2, m2):
        pts = np.array([[x0, y0], [x1, y1], [x2, y2]], dtype=float)
        ms = np.array([m0, m1, m2], dtype=float)
        total = _mass_point_or_zero(pts[0], ms[0])
        for P, m in zip(pts[1:], ms[1:]):
            total = mp.add(total, _mass_point_or_zero(P, m))
        mass = mp.mass_of(total)
        active = [k for k in range(3) if ms[k] != 0]
        for k, (dot, label) in enumerate(zip(dots, labels)):
            m = ms[k]
            colour = style.PALETTE["curve"] if m > 0 else style.PALETTE["point"] if m < 0 else "#b0b0b0"
            dot.set_data([pts[k, 0]], [pts[k, 1]])
            dot.set_color(colour)
            dot.set_markersize(5 + 3 * abs(m))
            dot.set_markerfacecolor(colour if m > 0 else "white")
            label.xy = pts[k]
            label.set_text(f"P{k}, m = {m:g}")
            label.set_color(colour)
        ends = pts[active] if len(active) >= 2 else pts[:0]
        bar.set_data(ends[:, 0], ends[:, 1])
        centre_pt, vec = None, None
        masses_text = " + ".join(f"({m:g})" for m in ms)
        if mass != 0:
            centre_pt = mp.point_of(total)
            centre.set_data([centre_pt[0]], [centre_pt[1]])
            centre.set_markersize(5 + 1.5 * min(abs(mass), 6))
            centre.set_markerfacecolor("black" if mass > 0 else "white")
            centre_label.xy = centre_pt
            centre_label.set_text(f"centre, M = {mass:g}")
            arrow.set_visible(False)
            outside = not (_LEVER_BOX[0] <= centre_pt[0] <= _LEVER_BOX[1]
                           and _LEVER_BOX[2] <= centre_pt[1] <= _LEVER_BOX[3])
            where = " (outside the picture)" if outside else ""
            status = (f"total mass M = {masses_text} = {mass:g}: the sum is the mass-point at the centre of mass "
                      f"({centre_pt[0]:.2f}, {centre_pt[1]:.2f}){where} with mass {mass:g}")
            if mass < 0:
                status += "; a negative total mass: still a point, drawn hollow"
            # the lever's line: through the two points with mass, where a two-point centre must lie
            if len(active) == 2:
                a, b = pts[active[0]], pts[active[1]]
                far = np.array([a + 20 * (b - a), a - 20 * (b - a)])
                line.set_data(far[:, 0], far[:, 1])
            else:
                line.set_data([], [])
        else:
            vec = total[:2]
            centre.set_data([], [])
            centre_label.set_text("")
            line.set_data([], [])
            base = pts[active[0]] if active else pts[0]
            arrow.set_positions(tuple(base), tuple(base + vec))
            arrow.set_visible(bool(np.any(vec != 0)))
            if np.any(vec != 0):
                status = (f"total mass M = {masses_text} = 0: the masses cancel and the sum is the VECTOR "
                          f"({vec[0]:.2f}, {vec[1]:.2f}) -- a point at infinity, no centre of mass (arrow drawn "
                          f"from P{active[0] if active else 0})")
            else:
                status = (f"total mass M = {masses_text} = 0 and the weighted points cancel too: the sum is "
                          f"the zero vector, no point at all")
        return {"points": pts, "masses": ms, "sum": total, "center": centre_pt, "vector": vec, "status": status}

    controls = {}
    for (xn, yn, mn), P, m in zip(names, P0, M0):
        controls[xn] = float_slider(xn, float(P[0]), -4.0, 4.0, 0.1)
        controls[yn] = float_slider(yn, float(P[1]), -3.5, 3.5, 0.1)
        controls[mn] = float_slider(mn, float(m), -3.0, 3.0, 0.5)
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="the law of the lever: drag the points, set the masses", side=True)
    drag_sliders(view, ax, [(xn, yn) for xn, yn, _ in names])
    return view


def _side(points) -> np.ndarray:
    """The side-view coordinates (z, y) of points in the plane x = 0."""
    return np.asarray(points)[..., [2, 1]]


def pseudoperspective_view(eye_y: float = 1.0, eye_z: float = 0.0, plane_z: float = 2.0) -> InteractiveView:
    """Perspective versus pseudoperspective of a scene, seen from the side (Goldman §14.4).

    The eye ``E = (0, eye_y, eye_z)`` looks along +z at the plane ``z = plane_z`` (normal
    ``N = (0, 0, 1)``); the scene :data:`SCENE` holds two posts and a road at different depths.
    Left: the scene, lines of sight, and the perspective images on the plane -- the tops of the
    posts A and B share a line of sight from the default eye, and perspective sends them to the
    same image.  Right: pseudoperspective, image height against pseudodepth ``δ = 1 - c/s``
    (``s`` the depth of a point in front of the eye, ``c`` that of the plane): the posts stay
    apart in depth order and every object stays straight.  (The pseudoperspective image proper is
    ``persp(P) + c δ N``; the right panel draws its height and δ, an affine rescaling of it.)

    ``update(eye_y, eye_z, plane_z)`` returns the scene, the perspective images, the
    pseudoperspective pairs ``(δ, height)`` and the labelled points' depths and pseudodepths.
    Degenerate positions give messages, never exceptions.  The eye can be dragged with the mouse in
    the left panel (``view.drag``).
    """
    fig = style.new_figure(figsize=style.WIDE_FIGSIZE)
    left = style.style_axes(fig.add_subplot(1, 2, 1), equal=False)
    right = style.style_axes(fig.add_subplot(1, 2, 2), equal=False)
    z0, z1, y0, y1 = _SIDE_BOX
    left.set_xlim(z0, z1)
    left.set_ylim(y0, y1)
    left.set_xlabel("depth axis z", fontsize=9)
    left.set_ylabel("y", fontsize=9)
    left.set_title("the scene and its perspective image on the plane", fontsize=10)
    right.set_xlim(-0.05, 1.05)
    right.set_ylim(y0, y1)
    # heights every 2 units, δ at 0, 1/2, 1: tick labels are most of a redraw (each is laid out and
    # rendered at every slider move), and these read the picture as well as twice as many
    for axes in (left, right):
        axes.yaxis.set_major_locator(ticker.MultipleLocator(2))
    right.set_xticks([0, 0.5, 1])
    right.set_xlabel("pseudodepth δ = 1 - c/s", fontsize=9)
    right.set_title("pseudoperspective: height on the plane vs δ", fontsize=10)
    t = np.linspace(0.0, 1.0, _SAMPLES)[:, None]
    samples = {name: (seg[0] + t * (seg[-1] - seg[0])) for name, seg in SCENE.items()}
    for name, seg in SCENE.items():
        left.plot(*_side(seg).T, "-", color=_COLOURS[name], linewidth=3, label=name)
    (eye,) = left.plot([], [], "o", color="black", markersize=8)
    eye_label = left.annotate("eye E", (0, 0), textcoords="offset points", xytext=(-12, 8), fontsize=9)
    (plane,) = left.plot([], [], "-", color=style.PALETTE["good"], linewidth=1.5)
    sights = {name: left.plot([], [], "-", color=_COLOURS[name], linewidth=0.6, alpha=0.5)[0] for name in SCENE}
    # different marker sizes, so that images which collide on the plane stay visible one behind the other
    images = {name: left.plot([], [], "o-", color=_COLOURS[name], markersize=size, linewidth=2, alpha=0.85)[0]
              for name, size in zip(SCENE, (7, 4, 3))}
    pseudo = {name: right.plot([], [], "o-", color=_COLOURS[name], markersize=3, linewidth=2, label=name)[0]
              for name in SCENE}
    (plane_r,) = right.plot([0, 0], [y0, y1], "-", color=style.PALETTE["good"], linewidth=1.5)
    left.legend(fontsize=8, loc="upper left", frameon=False)
    fig.tight_layout()
    empty = np.zeros((0, 2))

    def clear():
        for art in list(sights.values()) + list(images.values()) + list(pseudo.values()):
            art.set_data([], [])

    def update(eye_y, eye_z, plane_z):
        E = np.array([0.0, eye_y, eye_z])
        Q = np.array([0.0, 0.0, plane_z])
        eye.set_data([eye_z], [eye_y])
        eye_label.xy = (eye_z, eye_y)
        plane.set_data([plane_z, plane_z], [y0, y1])
        clear()
        drawn = {"scene": {n: _side(s) for n, s in samples.items()}, "images": {}, "pseudo": {}, "labelled": {}}
        try:
            c = mp.mass_of(mp.perspective_mass(Q, E, Q, _NORMAL))      # the depth of the plane from the eye
        except ValueError:
            drawn["status"] = (f"the eye (z = {eye_z:.2f}) lies on the projection plane z = {plane_z:.2f}: every "
                               f"line of sight from E meets the plane only at E -- no perspective, no pseudodepth. "
                               f"Move the plane or the eye.")
            return drawn
        if c < 0:
            drawn["status"] = (f"the plane z = {plane_z:.2f} is behind the eye (z = {eye_z:.2f}), while the scene is "
                               f"in front: the book's picture needs the plane between the eye and the scene's side "
                               f"(c = {c:.2f} < 0). Move the plane in front of the eye.")
            return drawn
        behind = []
        for name, pts in samples.items():
            s = mp.mass_of(mp.perspective_mass(pts, E, Q, _NORMAL))   # depth of each sample in front of the eye
            front = s > 1e-9
            if not np.all(front):
                behind.append(name)
            if not np.any(front):
                drawn["images"][name] = empty
                drawn["pseudo"][name] = empty
                continue
            P = pts[front]
            img = mp.point_of(mp.perspective_mass(P, E, Q, _NORMAL))
            delta = mp.pseudodepth(P, E, Q, _NORMAL)
            images[name].set_data(*_side(img).T)
            pseudo[name].set_data(delta, img[:, 1])
            far = np.array([E, P[-1]]) if s[front][-1] >= c else np.array([E, img[-1]])
            near = np.array([E, P[0]]) if s[front][0] >= c else np.array([E, img[0]])
            line = np.concatenate([far, [[np.nan] * 3], near])
            sights[name].set_data(line[:, 2], line[:, 1])
            drawn["images"][name] = _side(img)
            drawn["pseudo"][name] = np.column_stack([delta, img[:, 1]])
        rows = []
        front_labels = {}
        for label, P in LABELLED.items():
            s = float(mp.mass_of(mp.perspective_mass(P, E, Q, _NORMAL)))
            short = label.split()[0]
            if s <= 1e-9:
                rows.append(f"{short}: behind the eye")
                continue
            d = float(mp.pseudodepth(P, E, Q, _NORMAL))
            h = float(mp.point_of(mp.perspective_mass(P, E, Q, _NORMAL))[1])
            front_labels[short] = (s, d, h)
            drawn["labelled"][short] = np.array([s, d, h])
            rows.append(f"{short}: depth s = {s:.2f}, δ = {d:.3f}")
        order_s = sorted(front_labels, key=lambda k: front_labels[k][0])
        order_d = sorted(front_labels, key=lambda k: front_labels[k][1])
        parts = [f"c = {c:.2f}; " + "; ".join(rows)]
        if len(order_s) >= 2:
            same = "the same" if order_s == order_d else "NOT the same"
            parts.append(f"depth order {' < '.join(order_s)}, pseudodepth order {' < '.join(order_d)}: {same}")
        keys = list(front_labels)
        for i in range(len(keys)):
            for j in range(i + 1, len(keys)):
                a, b = front_labels[keys[i]], front_labels[keys[j]]
                if abs(a[2] - b[2]) < 0.02:
                    parts.append(f"{keys[i]} and {keys[j]} are on one line of sight: perspective sends both to "
                                 f"height {a[2]:.2f} (depth lost), pseudoperspective keeps them apart")
        if behind:
            parts.append(f"part of {', '.join(behind)} is behind the eye: not drawn (no perspective image there)")
        drawn["status"] = "; ".join(parts)
        return drawn

    controls = {"eye_y": float_slider("eye y", eye_y, -2.0, 4.0, 0.1),
                "eye_z": float_slider("eye z", eye_z, -3.0, 6.0, 0.1),
                "plane_z": float_slider("plane z", plane_z, -3.0, 10.0, 0.1)}
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="perspective versus pseudoperspective (side view)")
    drag_sliders(view, left, [("eye_z", "eye_y")])     # drag the eye in the side view (z across, y up)
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    for axes in (left, right):  # axes, legend and titles stay as they are: rendered once, pasted at each redraw
        style.freeze_axes_decorations(axes, axes.title)
    return view
