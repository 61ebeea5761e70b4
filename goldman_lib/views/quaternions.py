"""The views of chapter 15 (Goldman, complex numbers and quaternions): a complex number acting on
the plane (§15.2), the rotation ``q v q*`` of a body about an axis (§15.3.2, with the 4x4 matrix of
§15.3.6), and a key-frame animation played by slerp beside the same key frames blended linearly as
matrices (§15.3.4-15.3.5), so the distortion of the linear blend shows; the double cover (q(t) comes
back only after 720°, §15.3.2) and slerp drawn on S³ through a stereographic projection beside the
rotating body (§15.3.4).

Every number a view shows comes from :mod:`goldman_lib.quaternions`; this module only draws.

>>> view = key_frame_view()
>>> r = view.set_values(frame=0)
>>> round(r["linear_distortion"], 12), round(r["slerp_distortion"], 12)
(0.0, 0.0)
>>> view.play.value == view.controls["frame"].value        # the Play widget drives the frame slider
True
"""

from __future__ import annotations

import numpy as np

from goldman_lib import quaternions as qt
from goldman_lib.validation import as_float
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView
from goldman_lib.widgets.vectors3d import COLOURS, VectorScene

__all__ = ["complex_plane_view", "quaternion_rotation_view", "key_frame_view", "double_cover_view", "slerp_s3_view",
           "one_sided_product_plot", "FIGURE_F", "BODY_ARROWS", "KEY_SETS", "BRICK", "FRAMES", "COVER_AXIS", "S3_KEYS", "S3_MARKS"]

#: The asymmetric figure the complex numbers act on: a letter F (a closed outline), away from the origin.
FIGURE_F = np.array([[0.0, 0.0], [0.2, 0.0], [0.2, 0.4], [0.5, 0.4], [0.5, 0.6], [0.2, 0.6], [0.2, 0.8],
                     [0.6, 0.8], [0.6, 1.0], [0.0, 1.0], [0.0, 0.0]]) + [0.5, 0.2]

#: The body the rotation view turns: three arrows of different lengths (so the image shows handedness).
BODY_ARROWS = np.array([[0.9, 0.0, 0.0], [0.0, 0.6, 0.0], [0.0, 0.0, 0.35]])

#: A brick (8 corners, 12 triangles) for the key-frame animation, its long side along x.
BRICK = np.array([[x, y, z] for x in (-0.6, 0.6) for y in (-0.32, 0.32) for z in (-0.13, 0.13)])
_BRICK_TRIANGLES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
_NOSE = np.array([[0.6, 0.0, 0.0]])

#: Frames of the animation (the Play widget and the frame slider run over 0..FRAMES).
FRAMES = 96


def _turns(*axis_angles):
    """A key orientation: the quaternion of the rotations (axis, degrees) applied in order."""
    q = np.array([1.0, 0.0, 0.0, 0.0])
    for axis, angle in axis_angles:
        q = qt.multiply(qt.from_axis_angle(axis, angle), q)
    return q


#: Key orientations (unit quaternions at times 0, 1, 2, ...) of the animation.
KEY_SETS = {
    "tumble": np.stack([_turns(), _turns(([0, 0, 1], 100)), _turns(([0, 0, 1], 100), ([1, 0, 0], 110)),
                        _turns(([0, 0, 1], 100), ([1, 0, 0], 110), ([0, 1, 0], 140)), _turns(([1, 1, 1], 30))]),
    "half turns": np.stack([_turns(), _turns(([0, 0, 1], 180)), _turns(([0, 0, 1], 180), ([1, 0, 0], 180)),
                            _turns()]),
}

_OFFSET = np.array([1.3, 0.0, 0.0])


def _fmt_q(q) -> str:
    return "(" + ", ".join(f"{v + 0.0:.3f}" for v in np.asarray(q)) + ")"


def _fmt_matrix(M) -> str:
    return "[" + ", ".join("[" + ", ".join(f"{v + 0.0:.3f}" for v in row) + "]" for row in np.asarray(M)) + "]"


def _legend(items) -> "widgets.HTML":
    import ipywidgets as widgets

    return widgets.HTML(" &nbsp;".join(f"<span style='color:{c}'>&#9632; {label}</span>" for label, c in items))


# -- §15.2 ---------------------------------------------------------------------------------------------

def complex_plane_view(re: float = 0.9, im: float = 0.5) -> InteractiveView:
    """Multiplication by a complex number z = re + i im on the plane (Goldman §15.2): the letter F
    in grey and its image z·F in blue; the point z (red, draggable with the mouse, or set by its
    sliders) is the image of 1.  Multiplying by z rotates the plane about the origin by ``arg z``
    and scales it by ``|z|`` (:func:`goldman_lib.quaternions.complex_polar`).

    ``update(re, im)`` returns ``{"image" (n, 2), "z" (2,), "scale", "angle", "status"}``.

    >>> r = complex_plane_view().set_values(re=0.0, im=1.5)
    >>> r["scale"], r["angle"]
    (1.5, 90.0)
    """
    re, im = as_float(re, "re"), as_float(im, "im")
    controls = {"re": float_slider("Re z", re, -1.6, 1.6, 0.05), "im": float_slider("Im z", im, -1.6, 1.6, 0.05)}
    fig, ax = style.new_axes()
    ax.set_xlim(-2.6, 2.6), ax.set_ylim(-2.6, 2.6)
    circle = np.exp(1j * np.linspace(0, 2 * np.pi, 121))
    ax.plot(circle.real, circle.imag, color="#c8c8c8", linewidth=0.8, linestyle="--")
    ax.axhline(0, color="#bbbbbb", linewidth=0.6), ax.axvline(0, color="#bbbbbb", linewidth=0.6)
    ax.plot(*FIGURE_F.T, color="#9a9a9a", linewidth=1.6, label="F")
    (image_line,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.0, label="z·F")
    (one_to_z,) = ax.plot([], [], color=style.PALETTE["point"], linewidth=1.0)
    ax.plot([1.0], [0.0], "o", color="#444444", markersize=5)
    ax.annotate("1", (1.0, 0.0), textcoords="offset points", xytext=(4, -12), fontsize=9)
    (z_dot,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=8, label="z (drag me)")
    ax.legend(loc="lower left", fontsize=8)
    title = ax.set_title("", fontsize=10)

    def update(re, im):
        z = complex(re, im)
        image = qt.complex_multiply(FIGURE_F, z)
        scale, angle = qt.complex_polar(z)
        image_line.set_data(image[:, 0], image[:, 1])
        one_to_z.set_data([0.0, re], [0.0, im])
        z_dot.set_data([re], [im])
        if scale == 0:
            title.set_text("z = 0: the whole plane collapses to the origin")
            status = "z = 0: multiplying by 0 sends every point to the origin; there is no rotation (arg 0 is undefined)"
        else:
            title.set_text(f"z = {re:.2f} {'+' if im >= 0 else '-'} {abs(im):.2f} i")
            status = (f"z = {re:.2f} {'+' if im >= 0 else '-'} {abs(im):.2f} i:  |z| = {scale:.3f},  arg z = "
                      f"{angle:.1f}°  —  multiplying by z rotates F by {angle:.1f}° about the origin and scales it "
                      f"by {scale:.3f}; 1 goes to z")
        return {"image": image, "z": np.array([re, im]), "scale": scale, "angle": angle, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§15.2 multiplying by a complex number z", side=True)
    drag_sliders(view, ax, [("re", "im")])
    return view


# -- §15.3.2 and §15.3.6 --------------------------------------------------------------------------------

def quaternion_rotation_view(ax: float = 1.0, ay: float = 1.0, az: float = 0.5, angle: float = 110.0,
                  size: float = 1.0) -> InteractiveView:
    """The conformal map ``v -> q v q*`` of the quaternion ``q = size (cos(θ/2), sin(θ/2) u)``, u
    the unit vector along the axis (ax, ay, az) (Goldman §15.3.2): the axis in orange, a body of
    three arrows (blue) and its image (pink), the path of the long arrow's tip under the rotation
    ``q/|q|`` (grey).  With ``size = |q| = 1`` the map is the rotation by θ about the axis; otherwise
    it also scales every length by ``|q|^2``.  The status gives q and the 4x4 matrix of its rotation
    in the book's row convention (:func:`goldman_lib.quaternions.to_matrix`, §15.3.6).

    ``update(ax, ay, az, angle, size)`` returns ``{"q" (4,), "image" (3, 3), "matrix" (4, 4),
    "scale", "status"}``.  A zero axis shows a message and leaves the body unmoved.

    >>> r = quaternion_rotation_view().set_values(ax=0.0, ay=0.0, az=1.0, angle=90.0, size=1.0)
    >>> (np.round(r["image"][0], 12) + 0.0).tolist()
    [0.0, 0.9, 0.0]
    """
    values = {k: as_float(v, k) for k, v in dict(ax=ax, ay=ay, az=az, angle=angle, size=size).items()}
    controls = {
        "ax": float_slider("axis x", values["ax"], -1.0, 1.0, 0.05, label_width="56px"),
        "ay": float_slider("axis y", values["ay"], -1.0, 1.0, 0.05, label_width="56px"),
        "az": float_slider("axis z", values["az"], -1.0, 1.0, 0.05, label_width="56px"),
        "angle": float_slider("θ", values["angle"], -180.0, 180.0, 1.0, readout=".0f", label_width="56px"),
        "size": float_slider("|q|", values["size"], 0.5, 1.4, 0.05, label_width="56px"),
    }
    scene = VectorScene(camera_position=(3.4, -4.0, 2.6))
    zero = np.zeros((1, 3))
    steps = np.linspace(0.0, 1.0, 33)
    scene.add_segments("path", np.repeat(BODY_ARROWS[:1], 33, axis=0), [[i, i + 1] for i in range(32)],
                       color="#9a9a9a", width=1.2)
    scene.add_arrows("axis", zero, [[0.0, 0.0, 1.4]], color=COLOURS["cross"])
    scene.add_arrows("body", zero, BODY_ARROWS, color=COLOURS["u"])
    scene.add_arrows("image", zero, BODY_ARROWS, color=COLOURS["image"])

    def update(ax, ay, az, angle, size):
        axis = np.array([ax, ay, az], dtype=float)
        if not np.any(axis):
            scene.set_arrows("axis", zero, np.zeros((1, 3)))
            scene.set_arrows("image", zero, BODY_ARROWS)
            scene.set_segments("path", np.repeat(BODY_ARROWS[:1], 33, axis=0))
            return {"q": np.array([size, 0.0, 0.0, 0.0]), "image": BODY_ARROWS.copy(), "matrix": np.eye(4),
                    "scale": size * size,
                    "status": "the axis (0, 0, 0) has no direction: choose a nonzero axis to rotate about"}
        unit = qt.from_axis_angle(axis, angle)
        q = size * unit
        image = qt.conformal_map(q, BODY_ARROWS)
        M = qt.to_matrix(q)
        n = float(qt.norm(q))
        path = qt.rotate(qt.from_axis_angle(axis, steps * angle), BODY_ARROWS[0])
        scene.set_arrows("axis", zero, 1.4 * axis[None] / np.linalg.norm(axis))
        scene.set_arrows("image", zero, image)
        scene.set_segments("path", path)
        scale = n * n
        what = (f"rotation by {angle:.0f}° about the axis" if abs(scale - 1) < 1e-9 else
                f"rotation by {angle:.0f}° about the axis, then scaling by |q|² = {scale:.3f}")
        status = (f"q = {_fmt_q(q)}, |q| = {n:.3f}: q v q* is the {what};  4x4 matrix of the rotation "
                  f"(row convention, v' = v M): {_fmt_matrix(M)}")
        return {"q": q, "image": image, "matrix": M, "scale": scale, "status": status}

    legend = _legend([("axis", COLOURS["cross"]), ("body v", COLOURS["u"]), ("image q v q*", COLOURS["image"]),
                      ("path of the tip", "#9a9a9a")])
    view = InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="§15.3.2 the rotation q v q*", side=True)
    view.scene = scene
    return view


# -- §15.3.4-15.3.5 -------------------------------------------------------------------------------------

def key_frame_view(keys: str = "tumble", frame: int = FRAMES // 8) -> InteractiveView:
    """Key-frame animation (Goldman §15.3.5): a brick moved through the key orientations
    :data:`KEY_SETS` ``[keys]`` (at times 0, 1, 2, ...) by slerp (left, blue,
    :func:`goldman_lib.quaternions.key_frames`), beside the same brick moved by the linear blend of
    the key orientations' matrices (right, red, :func:`goldman_lib.quaternions.matrix_key_frames`).
    Press the Play button (it drives the frame slider) or move the slider: between keys the linear
    blend is no rotation, and the brick shrinks and shears (§15.3.4).  The grey curves are the paths
    of the bricks' noses over the whole animation; the status gives ``matrix_distortion`` of both
    (0 for slerp).

    ``update(keys, frame)`` returns ``{"time", "slerp" (4,), "linear" (4, 4), "slerp_distortion",
    "linear_distortion", "status"}``.  The Play widget is ``view.play`` (CSS class
    ``goldman-play``), linked to the control ``frame``.

    >>> r = key_frame_view("half turns").set_values(frame=FRAMES // 6)   # halfway between two keys
    >>> round(r["linear_distortion"], 9)
    1.0
    """
    import ipywidgets as widgets

    if keys not in KEY_SETS:
        raise ValueError(f"keys must be one of {sorted(KEY_SETS)}; got {keys!r}")
    frame = int(round(as_float(frame, "frame")))
    if not 0 <= frame <= FRAMES:
        raise ValueError(f"frame must be in [0, {FRAMES}]; got {frame}")
    controls = {
        "keys": dropdown("keys", list(KEY_SETS), keys, label_width="48px", width="290px"),
        "frame": int_slider("frame", frame, 0, FRAMES, width="240px"),
    }
    play = widgets.Play(value=frame, min=0, max=FRAMES, step=1, interval=60, description="play",
                        layout=widgets.Layout(width="110px"))
    play.add_class("goldman-play")
    widgets.link((play, "value"), (controls["frame"], "value"))

    scene = VectorScene(width=460, height=320, camera_position=(0.6, -5.2, 2.4), axes=0.0)
    fine = np.linspace(0.0, 1.0, FRAMES + 1)
    scene.add_segments("slerp:path", np.zeros((FRAMES + 1, 3)), [[i, i + 1] for i in range(FRAMES)],
                       color="#9a9a9a", width=1.0)
    scene.add_segments("linear:path", np.zeros((FRAMES + 1, 3)), [[i, i + 1] for i in range(FRAMES)],
                       color="#9a9a9a", width=1.0)
    scene.add_mesh("slerp:brick", BRICK - _OFFSET, _BRICK_TRIANGLES, color=COLOURS["u"])
    scene.add_mesh("linear:brick", BRICK + _OFFSET, _BRICK_TRIANGLES, color=COLOURS["v"])
    scene.add_points("noses", np.concatenate([_NOSE - _OFFSET, _NOSE + _OFFSET]), color="#222222", size=0.09)
    shown = {"keys": None}

    def set_paths(name):
        orientations = KEY_SETS[name]
        times = np.arange(len(orientations), dtype=float)
        t = fine * times[-1]
        slerp_nose = qt.rotate(qt.key_frames(orientations, times, t), _NOSE[0])
        linear_nose = _NOSE[0] @ qt.matrix_key_frames(orientations, times, t)[..., :3, :3]
        scene.set_segments("slerp:path", slerp_nose - _OFFSET)
        scene.set_segments("linear:path", linear_nose + _OFFSET)
        shown["keys"] = name

    def update(keys, frame):
        orientations = KEY_SETS[keys]
        if shown["keys"] != keys:
            set_paths(keys)
        times = np.arange(len(orientations), dtype=float)
        t = float(frame) / FRAMES * times[-1]
        q = qt.key_frames(orientations, times, t)
        M_slerp = qt.to_matrix(q)
        M_linear = qt.matrix_key_frames(orientations, times, t)
        scene.set_mesh("slerp:brick", BRICK @ M_slerp[:3, :3] - _OFFSET)
        scene.set_mesh("linear:brick", BRICK @ M_linear[:3, :3] + _OFFSET)
        scene.set_points("noses", np.concatenate([_NOSE @ M_slerp[:3, :3] - _OFFSET,
                                                  _NOSE @ M_linear[:3, :3] + _OFFSET]))
        d_slerp = float(qt.matrix_distortion(M_slerp))
        d_linear = float(qt.matrix_distortion(M_linear))
        key = min(int(t), len(orientations) - 2)
        where = (f"at key {int(round(t))}" if abs(t - round(t)) < 1e-9 else f"between keys {key} and {key + 1}")
        status = (f"time {t:.3f} ({where}):  matrix_distortion of the slerp brick {d_slerp:.3f} (a rotation), "
                  f"of the linearly blended brick {d_linear:.3f}"
                  + ("  (collapsed: the blend is singular here)" if d_linear > 0.999 else ""))
        return {"time": t, "slerp": q, "linear": M_linear, "slerp_distortion": d_slerp,
                "linear_distortion": d_linear, "status": status}

    legend = _legend([("slerp of the key quaternions", COLOURS["u"]),
                      ("linear blend of the key matrices", COLOURS["v"])])
    view = InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="§15.3.5 key-frame animation: slerp (left) and linear matrices (right)",
                           arrange=[controls["keys"], widgets.HBox([play, controls["frame"]])])
    view.play, view.scene = play, scene
    return view


# -- why a sandwich (§15.3.2) --------------------------------------------------------------------------

def one_sided_product_plot(axis, v, ax=None):
    """The scalar parts of ``q v`` and of ``q v q*`` for ``q = (cos(θ/2), sin(θ/2) u)``, u along
    ``axis``, over θ from -360 to 360 degrees (Goldman §15.3.2): the one-sided product has the
    scalar part ``-sin(θ/2) u·v``, so it leaves the vectors (the mass-points of mass 0) unless θ is 0
    or 360, while the sandwich's scalar part stays 0.  Draws on ``ax`` (a new figure if None) and
    returns the axes.

    >>> ax = one_sided_product_plot([1, 1, 1], [0.3, -1.2, 2.0])
    >>> [line.get_label() for line in ax.get_lines()[:2]]
    ['scalar part of q v', 'scalar part of q v q*']
    """
    ax = style.get_axes(ax, equal=False)
    theta = np.linspace(-360.0, 360.0, 241)
    q = qt.from_axis_angle(axis, theta)
    v4 = qt.pure(v)
    one_sided = qt.multiply(q, v4)[:, 0]
    sandwich = qt.multiply(qt.multiply(q, v4), qt.conjugate(q))[:, 0]
    ax.plot(theta, one_sided, color=style.PALETTE["point"], linewidth=1.8, label="scalar part of q v")
    ax.plot(theta, sandwich, color=style.PALETTE["curve"], linewidth=1.8, label="scalar part of q v q*")
    ax.axhline(0.0, color="#cccccc", linewidth=0.6)
    ax.set_xlim(-360.0, 360.0)
    ax.set_xticks([-360, -180, 0, 180, 360])
    ax.set_xlabel("θ, the angle of q (degrees)", fontsize=9)
    ax.set_ylabel("mass (scalar part)", fontsize=9)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title("q v leaves the vectors; q v q* stays among them", fontsize=10)
    ax.figure.tight_layout()
    return ax


# -- the double cover: q and -q (§15.3.2) ----------------------------------------------------------------

#: The axis of the double-cover view: (2, 3, 6)/7, so the four components of q(t) are four different curves.
COVER_AXIS = np.array([2.0, 3.0, 6.0]) / 7.0

_COMPONENT_COLOURS = {"w": "#222222", "x": style.PALETTE["point"], "y": style.PALETTE["good"], "z": style.PALETTE["curve"]}


def _body_lines(ax3, colour, style_="-", width=2.0):
    lines = [ax3.plot([0, 0], [0, 0], [0, 0], style_, color=colour, linewidth=width)[0] for _ in BODY_ARROWS]
    tips = ax3.plot([], [], [], "o", color=colour, markersize=4)[0]
    return lines, tips


def _set_body(lines, tips, arrows):
    for line, tip in zip(lines, arrows):
        line.set_data_3d([0.0, tip[0]], [0.0, tip[1]], [0.0, tip[2]])
    tips.set_data_3d(arrows[:, 0], arrows[:, 1], arrows[:, 2])


def _body_axes(fig, position, title):
    ax3 = fig.add_subplot(*position, projection="3d")
    ax3.set_xlim(-0.8, 0.8), ax3.set_ylim(-0.8, 0.8), ax3.set_zlim(-0.8, 0.8)
    ax3.set_box_aspect((1, 1, 1))
    ax3.set_axis_off()               # (the panes and ticks of a 3D axes are most of its redraw)
    for k, name in enumerate("xyz"):  # faint coordinate axes instead
        end = np.eye(3)[k] * 0.8
        ax3.plot(*np.stack([-end, end]).T, color="#d0d0d0", linewidth=0.8)
        ax3.text(*(end * 1.08), name, color="#9a9a9a", fontsize=8)
    ax3.view_init(elev=22, azim=-60)
    ax3.set_title(title, fontsize=9)
    return ax3


def double_cover_view(t: float = 200.0) -> InteractiveView:
    """The double cover (Goldman §15.3.2): the unit quaternion ``q(t) = (cos(t/2), sin(t/2) u)`` of the
    rotation by ``t`` degrees about ``u =`` :data:`COVER_AXIS`, for ``t`` from 0 to 720.  Left, top: the
    four components of q(t) (:func:`goldman_lib.quaternions.from_axis_angle`), with a marker at the
    slider's t; below: how far q(t) is from q(0) = 1 (blue) and the angle of the rotation it performs
    (orange, :func:`goldman_lib.quaternions.to_axis_angle`, 0 to 180° about ±u).  The rotation comes
    back at 360°, where q(360°) = -1 is the other quaternion of the same rotation; q comes back only
    at 720°.
    Right: the body of three arrows turned by q(t) (blue), the axis u (orange) and the body at rest
    (grey).

    ``update(t)`` returns ``{"q" (4,), "image" (3, 3), "matrix" (4, 4), "status"}``.

    >>> r = double_cover_view().set_values(t=360.0)
    >>> (np.round(r["q"], 12) + 0.0).tolist(), bool(np.allclose(r["image"], BODY_ARROWS))
    ([-1.0, 0.0, 0.0, 0.0], True)
    """
    t = as_float(t, "t")
    controls = {"t": float_slider("t (°)", t, 0.0, 720.0, 5.0, readout=".0f")}
    fig = style.new_figure(figsize=(8.4, 3.9))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.35, 1.0), height_ratios=(1.6, 1.0))
    ax = fig.add_subplot(grid[0, 0])
    ax_dist = fig.add_subplot(grid[1, 0], sharex=ax)
    ts = np.linspace(0.0, 720.0, 289)
    qs = qt.from_axis_angle(COVER_AXIS, ts)
    for k, name in enumerate("wxyz"):
        ax.plot(ts, qs[:, k], color=_COMPONENT_COLOURS[name], linewidth=1.5, label=name)
    for a in (ax, ax_dist):
        for mark in (360.0, 720.0):
            a.axvline(mark, color="#9a9a9a", linewidth=0.8, linestyle="--")
        a.tick_params(labelsize=8)
    ax.axhline(0.0, color="#cccccc", linewidth=0.6)
    ax.set_ylim(-1.1, 1.1)
    ax.set_ylabel("components of q(t)", fontsize=8)
    ax.legend(loc="lower left", fontsize=7, ncol=2)
    ax.annotate("q(360°) = −1", (360.0, -1.0), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.annotate("q(720°) = 1", (720.0, 1.0), textcoords="offset points", xytext=(-58, -12), fontsize=8)
    away_q = np.linalg.norm(qs - qs[0], axis=1)
    ax_dist.plot(ts, away_q, color=style.PALETTE["curve"], linewidth=1.5, label="|q(t) − 1|")
    ax_dist.set_ylim(0.0, 2.2)
    ax_dist.set_ylabel("|q(t) − 1|", fontsize=8, color=style.PALETTE["curve"])
    ax_angle = ax_dist.twinx()
    ax_angle.plot(ts, qt.to_axis_angle(qs)[1], color=style.PALETTE["accent"], linewidth=1.5)
    ax_angle.set_ylim(0.0, 198.0)
    ax_angle.set_yticks([0, 90, 180])
    ax_angle.tick_params(labelsize=8)
    ax_angle.set_ylabel("rotation angle (°)", fontsize=8, color=style.PALETTE["accent"])
    ax_dist.set_xlim(0.0, 720.0)
    ax_dist.set_xticks([0, 180, 360, 540, 720])
    ax_dist.set_xlabel("t, the angle turned (degrees)", fontsize=8)
    cursor = [a.axvline(t, color=style.PALETTE["point"], linewidth=1.0) for a in (ax, ax_dist)]
    (dots,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=5)
    ax3 = _body_axes(fig, (grid[:, 1],), "the body turned by q(t)")
    _set_body(*_body_lines(ax3, "#b5b5b5", width=1.2), BODY_ARROWS)
    ax3.plot(*np.stack([-COVER_AXIS, COVER_AXIS]).T, color=COLOURS["cross"], linewidth=1.5)
    body = _body_lines(ax3, COLOURS["u"])
    fig.tight_layout()
    style.pin_layout(fig)            # fixed limits: titles and labels need no new placing at each move
    # axes, legend, titles and notes stay as they are at every move: rendered once, pasted at each redraw
    for a in fig.axes:
        style.freeze_axes_decorations(a, a.title, *a.texts)

    def update(t):
        q = qt.from_axis_angle(COVER_AXIS, t)
        image = qt.rotate(q, BODY_ARROWS)
        M = qt.to_matrix(q)
        for line in cursor:
            line.set_xdata([t, t])
        dots.set_data([t] * 4, q)
        _set_body(*body, image)
        turned = t % 360.0
        if np.isclose(t, 360.0):
            where = "q(360°) = −1: the body is back where it started, but q is the other quaternion of that rotation"
        elif np.isclose(t, 720.0) or np.isclose(t, 0.0):
            where = "q = 1: the body and the quaternion are both back where they started"
        elif t > 360.0:
            where = (f"the body looks as it did at t = {turned:.0f}°, and q(t) = −q({turned:.0f}°): q and −q give "
                     f"the same rotation")
        else:
            where = "the first turn: q runs through half of its circle"
        status = f"t = {t:.0f}°: q(t) = {_fmt_q(np.round(q, 6) + 0.0)};  {where}"
        return {"q": q, "image": image, "matrix": M, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§15.3.2 the double cover: q(t) comes back only after 720°")
    return view


# -- slerp drawn on S³ (§15.3.4) ------------------------------------------------------------------------

#: Key pairs of the S³ view: (q0, q1), unit quaternions on one side (q0·q1 > 0).
S3_KEYS = {
    "150° about x to 150° about y": (qt.from_axis_angle([1.0, 0.0, 0.0], 150.0), qt.from_axis_angle([0.0, 1.0, 0.0], 150.0)),
    "90° about x to 90° about y": (qt.from_axis_angle([1.0, 0.0, 0.0], 90.0), qt.from_axis_angle([0.0, 1.0, 0.0], 90.0)),
    "a twist and a tilt": (_turns(([0, 0, 1], -60)), _turns(([1, 0, 0], 120), ([0, 0, 1], 60))),
}

#: Equal steps of t at which the S³ view marks slerp and nlerp.
S3_MARKS = np.linspace(0.0, 1.0, 11)


def slerp_s3_view(keys: str = "150° about x to 150° about y", t: float = 0.3) -> InteractiveView:
    """Slerp drawn on S³ (Goldman §15.3.4): left, the unit quaternions seen in 3-space through the
    stereographic projection from -1 (:func:`goldman_lib.quaternions.stereographic`: 1 at the origin,
    the rotation by θ about u at tan(θ/4) u; the box is fitted to the arc).  The great
    circle through the keys q0 and q1 :data:`S3_KEYS` ``[keys]`` (grey) carries both the slerp arc and the
    normalised chord of nlerp (:func:`goldman_lib.quaternions.nlerp`); the markers at equal steps of t
    (:data:`S3_MARKS`) are evenly spaced for slerp (blue); for nlerp (red) they bunch near the keys and
    spread out in the middle, where the normalised chord runs fastest.
    Middle: the fraction of the turn from q0 to q1 done at t (the angle of ``q q0*``,
    :func:`goldman_lib.quaternions.to_axis_angle`): t itself for slerp, an S-curve for nlerp.  Right:
    the body turned by slerp(t) (blue) and by nlerp(t) (red, dashed).

    ``update(keys, t)`` returns ``{"slerp" (4,), "nlerp" (4,), "slerp_point" (3,), "nlerp_point" (3,),
    "slerp_turned", "nlerp_turned", "total", "status"}``, the angles in degrees turned from q0.

    >>> r = slerp_s3_view().set_values(t=0.5)
    >>> bool(np.allclose(r["slerp"], r["nlerp"])), round(r["slerp_turned"] / r["total"], 9)
    (True, 0.5)
    """

    if keys not in S3_KEYS:
        raise ValueError(f"keys must be one of {sorted(S3_KEYS)}; got {keys!r}")
    t = as_float(t, "t")
    controls = {
        "keys": dropdown("keys", list(S3_KEYS), keys, label_width="48px", width="290px"),
        "t": float_slider("t", t, 0.0, 1.0, 0.01),
    }
    fig = style.new_figure(figsize=(10.4, 3.7))
    grid = fig.add_gridspec(1, 3, width_ratios=(1.25, 0.95, 1.0))
    ax = fig.add_subplot(grid[0, 0], projection="3d")
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()                # (the panes and ticks of a 3D axes are most of its redraw)
    ax.view_init(elev=72, azim=45)
    ax.set_title("unit quaternions, stereographic view from −1", fontsize=9)
    (circle,) = ax.plot([], [], [], color="#9a9a9a", linewidth=1.0)
    (arc,) = ax.plot([], [], [], color=style.PALETTE["curve"], linewidth=2.0)
    (slerp_marks,) = ax.plot([], [], [], "o", color=style.PALETTE["curve"], markersize=6, label="slerp, t = 0, 0.1, ..., 1")
    (nlerp_marks,) = ax.plot([], [], [], "x", color=style.PALETTE["point"], markersize=8, mew=1.6,
                             label="nlerp, the same t")
    (keys_dots,) = ax.plot([], [], [], "s", color="#222222", markersize=5)
    (slerp_now,) = ax.plot([], [], [], "o", color=style.PALETTE["curve"], markersize=9, markerfacecolor="none")
    (nlerp_now,) = ax.plot([], [], [], "o", color=style.PALETTE["point"], markersize=12, markerfacecolor="none")
    labels = [ax.text(0, 0, 0, name, fontsize=9) for name in ("q0", "q1")]
    ax.legend(loc="upper left", fontsize=7)
    ax_turn = fig.add_subplot(grid[0, 1])
    ax_turn.plot([0, 1], [0, 1], color="#cccccc", linewidth=0.8)
    (slerp_turn,) = ax_turn.plot([], [], color=style.PALETTE["curve"], linewidth=1.8, label="slerp")
    (nlerp_turn,) = ax_turn.plot([], [], color=style.PALETTE["point"], linewidth=1.8, linestyle="--", label="nlerp")
    (turn_now,) = ax_turn.plot([], [], "o", color="#222222", markersize=4)
    ax_turn.set_xlim(0, 1), ax_turn.set_ylim(0, 1)
    ax_turn.set_xlabel("t", fontsize=8)
    ax_turn.set_title("fraction of the turn from q0 to q1", fontsize=9)
    ax_turn.tick_params(labelsize=7)
    ax_turn.legend(loc="upper left", fontsize=7)
    ax3 = _body_axes(fig, (grid[0, 2],), "the body turned by slerp(t) and nlerp(t)")
    slerp_body = _body_lines(ax3, COLOURS["u"])
    nlerp_body = _body_lines(ax3, style.PALETTE["point"], "--", 1.4)
    fig.tight_layout()
    style.pin_layout(fig)            # the 2D panel's limits are fixed; the 3D panels show no ticks
    # axes, legends, titles and the body's axis names stay as they are at a move of t (the S³ box is
    # fitted again only with new keys): rendered once, pasted at each redraw
    for a in (ax, ax_turn):
        style.freeze_axes_decorations(a, a.title)
    style.freeze_axes_decorations(ax3, ax3.title, *ax3.texts)
    shown = {"keys": None}
    fine = np.linspace(0.0, 1.0, 61)

    def set_keys(name):
        q0, q1 = S3_KEYS[name]
        # the great circle through q0 and q1, a little beyond the keys; the box fits it
        P = qt.stereographic(qt.slerp(q0, q1, np.linspace(-0.35, 1.35, 69)))
        circle.set_data_3d(P[:, 0], P[:, 1], P[:, 2])
        style.equal_3d_limits(ax, P)
        A = qt.stereographic(qt.slerp(q0, q1, fine))
        arc.set_data_3d(A[:, 0], A[:, 1], A[:, 2])
        S = qt.stereographic(qt.slerp(q0, q1, S3_MARKS))
        N = qt.stereographic(qt.nlerp(q0, q1, S3_MARKS))
        slerp_marks.set_data_3d(S[:, 0], S[:, 1], S[:, 2])
        nlerp_marks.set_data_3d(N[:, 0], N[:, 1], N[:, 2])
        back = qt.conjugate(q0)
        total = float(qt.to_axis_angle(qt.multiply(q1, back))[1])
        slerp_turn.set_data(fine, qt.to_axis_angle(qt.multiply(qt.slerp(q0, q1, fine), back))[1] / total)
        nlerp_turn.set_data(fine, qt.to_axis_angle(qt.multiply(qt.nlerp(q0, q1, fine), back))[1] / total)
        K = qt.stereographic(np.stack([q0, q1]))
        keys_dots.set_data_3d(K[:, 0], K[:, 1], K[:, 2])
        for label, point in zip(labels, K):
            label.set_position((point[0], point[1]))
            label.set_3d_properties(point[2], "z")
        shown["keys"] = name

    def update(keys, t):
        if shown["keys"] != keys:
            set_keys(keys)
        q0, q1 = S3_KEYS[keys]
        qs, qn = qt.slerp(q0, q1, t), qt.nlerp(q0, q1, t)
        ps, pn = qt.stereographic(qs), qt.stereographic(qn)
        slerp_now.set_data_3d([ps[0]], [ps[1]], [ps[2]])
        nlerp_now.set_data_3d([pn[0]], [pn[1]], [pn[2]])
        _set_body(*slerp_body, qt.rotate(qs, BODY_ARROWS))
        _set_body(*nlerp_body, qt.rotate(qn, BODY_ARROWS))
        back = qt.conjugate(q0)
        total = float(qt.to_axis_angle(qt.multiply(q1, back))[1])
        turned_s = float(qt.to_axis_angle(qt.multiply(qs, back))[1])
        turned_n = float(qt.to_axis_angle(qt.multiply(qn, back))[1])
        turn_now.set_data([t, t], [turned_s / total, turned_n / total])
        status = (f"t = {t:.2f}: slerp has turned {turned_s:.1f}° of the {total:.1f}° from q0 to q1 "
                  f"({turned_s / total:.0%}, always t), nlerp {turned_n:.1f}° ({turned_n / total:.0%}): the chord "
                  f"pushed onto the sphere moves slowly near the keys and fast in the middle")
        return {"slerp": qs, "nlerp": qn, "slerp_point": ps, "nlerp_point": pn, "slerp_turned": turned_s,
                "nlerp_turned": turned_n, "total": total, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§15.3.4 slerp on S³: equal steps of t, evenly spaced (slerp) or bunched (nlerp)")
    return view
