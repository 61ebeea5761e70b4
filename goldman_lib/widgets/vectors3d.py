"""The shared three.js view of Part II (Goldman chapters 9-15): points, arrows, planes and polygons
in one :class:`VectorScene`, built once and updated in place; and the chapter-9/10 widget that
shows two vectors with their sum, cross product and parallelogram.

Every number a view shows (a product, an area, an angle) comes from the library
(:mod:`goldman_lib.vectors`, :mod:`goldman_lib.vector_geometry`); this module only draws.  An arrow
is a shaft (line segments) and a cone head (a small mesh); a plane is a square patch of given size
centred at its point; a polygon is a filled fan with its outline.

>>> scene = VectorScene()
>>> scene.add_arrows("u", [[0, 0, 0]], [[1, 0, 0]])
>>> scene.set_arrows("u", [[0, 0, 0]], [[0, 2, 0]])
>>> scene.data("u:head")["positions"][0].tolist()   # the tip of the cone
[0.0, 2.0, 0.0]
>>> view = vector_products_view()
>>> sorted(view.update(**view.values()))
['angle', 'area', 'cross', 'dot', 'status', 'sum', 'triple']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import vector_geometry, vectors
from goldman_lib.validation import as_points
from goldman_lib.widgets.interactive import InteractiveView, float_slider
from goldman_lib.widgets.three import SceneView

__all__ = ["VectorScene", "vector_products_view", "COLOURS"]

#: The colours of Part II's pictures: the same object has the same colour in every chapter.
COLOURS = {"u": "#1f77b4", "v": "#d62728", "w": "#2ca02c", "sum": "#9467bd", "cross": "#ff7f0e",
           "normal": "#ff7f0e", "plane": "#9ecae1", "polygon": "#c7e9c0", "point": "#222222", "image": "#e377c2"}

_CONE_SIDES = 12


def _frame(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors perpendicular to each row of ``d`` and to each other (for drawing only)."""
    length = np.linalg.norm(d, axis=1, keepdims=True)
    unit = np.divide(d, length, out=np.tile([0.0, 0.0, 1.0], (len(d), 1)), where=length > 1e-12)
    helper = np.where(np.abs(unit[:, [0]]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    e1 = vectors.cross(unit, helper)
    e1 /= np.linalg.norm(e1, axis=1, keepdims=True)
    e2 = vectors.cross(unit, e1)
    return e1, e2


class VectorScene(SceneView):
    """A :class:`~goldman_lib.widgets.three.SceneView` that also draws arrows, planes and polygons.

    Each compound object is made of primitives named ``"<name>:<part>"`` (``u:shaft``, ``u:head``,
    ``P:fill``, ...), updated in place by the ``set_*`` methods with the same number of items.
    """

    def __init__(self, width: int = 420, height: int = 340, camera_position=(3.2, -4.2, 2.8), target=(0, 0, 0),
                 axes: float = 1.0):
        super().__init__(width=width, height=height, camera_position=camera_position, target=target, axes=axes)
        self._head = {}

    # -- arrows ------------------------------------------------------------------------------
    def _arrow_geometry(self, name, origins, vecs):
        O = as_points(origins, "origins", dim=3)
        V = as_points(vecs, "vectors", dim=3)
        O, V = np.broadcast_arrays(O, V)
        n = len(V)
        tips = O + V
        length = np.linalg.norm(V, axis=1)
        h = np.minimum(0.18, 0.35 * length)[:, None]
        r = 0.45 * h
        unit = np.divide(V, length[:, None], out=np.zeros_like(V), where=length[:, None] > 1e-12)
        base = tips - h * unit
        e1, e2 = _frame(V)
        ang = np.linspace(0, 2 * np.pi, _CONE_SIDES, endpoint=False)
        ring = base[:, None, :] + r[:, None, :] * (np.cos(ang)[None, :, None] * e1[:, None, :]
                                                   + np.sin(ang)[None, :, None] * e2[:, None, :])
        verts = np.concatenate([tips[:, None, :], ring], axis=1).reshape(-1, 3)
        shaft = np.stack([O, base], axis=1).reshape(-1, 3)
        k = np.arange(_CONE_SIDES)
        one = np.stack([np.zeros(_CONE_SIDES, int), 1 + k, 1 + (k + 1) % _CONE_SIDES], axis=1)
        tris = (one[None] + (np.arange(n) * (_CONE_SIDES + 1))[:, None, None]).reshape(-1, 3)
        segs = np.arange(2 * n).reshape(n, 2)
        return shaft, segs, verts, tris

    def add_arrows(self, name: str, origins, vectors_, color: str = "#1f77b4"):
        """Arrows from ``origins`` (k, 3) (or one origin) along ``vectors_`` (k, 3)."""
        shaft, segs, verts, tris = self._arrow_geometry(name, origins, vectors_)
        self.add_segments(f"{name}:shaft", shaft, segs, color=color, width=2.0)
        self.add_mesh(f"{name}:head", verts, tris, color=color)

    def set_arrows(self, name: str, origins, vectors_):
        """New origins and vectors (same count) for the arrows ``name``."""
        shaft, _, verts, _ = self._arrow_geometry(name, origins, vectors_)
        self.set_segments(f"{name}:shaft", shaft)
        self.set_mesh(f"{name}:head", verts)

    # -- planes and polygons ---------------------------------------------------------------------
    @staticmethod
    def _plane_corners(point, normal, size):
        P = as_points(point, "point", ndim=1, dim=3)
        N = as_points(normal, "normal", ndim=1, dim=3)
        e1, e2 = _frame(N[None])
        s = float(size) / 2
        return np.array([P + s * (a * e1[0] + b * e2[0]) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))])

    def add_plane(self, name: str, point, normal, size: float = 2.0, color: str = "#9ecae1", opacity: float = 0.45):
        """A translucent square of side ``size`` centred at ``point`` perpendicular to ``normal``."""
        self.add_mesh(f"{name}:fill", self._plane_corners(point, normal, size), [[0, 1, 2], [0, 2, 3]],
                      color=color, opacity=opacity)

    def set_plane(self, name: str, point, normal, size: float = 2.0):
        """Move the plane ``name``."""
        self.set_mesh(f"{name}:fill", self._plane_corners(point, normal, size))

    def add_polygon(self, name: str, vertices, color: str = "#c7e9c0", edge_color: str = "#2b6b2b",
                    opacity: float = 0.6):
        """A filled polygon (a fan from its first vertex) with its outline; vertices (n, 3)."""
        V = as_points(vertices, "vertices", dim=3, min_count=3)
        n = len(V)
        fan = [[0, i, i + 1] for i in range(1, n - 1)]
        self.add_mesh(f"{name}:fill", V, fan, color=color, opacity=opacity)
        self.add_segments(f"{name}:edges", V, [[i, (i + 1) % n] for i in range(n)], color=edge_color, width=1.6)

    def set_polygon(self, name: str, vertices):
        """New vertices (same count) for the polygon ``name``."""
        V = as_points(vertices, "vertices", dim=3, min_count=3)
        self.set_mesh(f"{name}:fill", V)
        self.set_segments(f"{name}:edges", V)


def _vector_sliders(prefix: str, value, low=-2.0, high=2.0):
    return {f"{prefix}{axis}": float_slider(f"{prefix}{axis}", float(v), low, high, 0.1, width="220px", label_width="28px")
            for axis, v in zip("xyz", value)}


def vector_products_view(u=(1.5, 0.2, 0.0), v=(0.4, 1.2, 0.3)) -> InteractiveView:
    """Two vectors u and v from the origin with their sum (the parallelogram rule, Goldman §9.2),
    the parallelogram they span, and their cross product u × v (Goldman §9.4), perpendicular to
    both with length equal to the parallelogram's area.  The status line gives u · v, the angle,
    |u × v| and the parallelogram's area computed independently (Goldman §11.4), and
    det(u, v, u × v) = |u × v|² > 0 (the frame is right-handed).
    """
    scene = VectorScene()
    zero = np.zeros((1, 3))
    u0, v0 = np.array(u, float)[None], np.array(v, float)[None]
    scene.add_polygon("parallelogram", np.concatenate([zero, u0, u0 + v0, v0]), color=COLOURS["plane"],
                      edge_color="#7aa6c2", opacity=0.35)
    scene.add_arrows("u", zero, u0, color=COLOURS["u"])
    scene.add_arrows("v", zero, v0, color=COLOURS["v"])
    scene.add_arrows("sum", zero, u0 + v0, color=COLOURS["sum"])
    scene.add_arrows("cross", zero, vectors.cross(u0, v0), color=COLOURS["cross"])
    controls = {**_vector_sliders("u", u), **_vector_sliders("v", v)}

    def update(ux, uy, uz, vx, vy, vz):
        a, b = np.array([[ux, uy, uz]]), np.array([[vx, vy, vz]])
        c = vectors.cross(a, b)
        scene.set_polygon("parallelogram", np.concatenate([zero, a, a + b, b]))
        scene.set_arrows("u", zero, a)
        scene.set_arrows("v", zero, b)
        scene.set_arrows("sum", zero, a + b)
        scene.set_arrows("cross", zero, c)
        dot = vectors.dot(a[0], b[0])
        cross_len = float(vectors.length(c[0]))
        area = 2 * float(vector_geometry.triangle_area(np.zeros(3), a[0], b[0]))
        triple = float(vectors.det(a[0], b[0], c[0]))
        if vectors.length(a[0]) == 0 or vectors.length(b[0]) == 0:
            angle, angle_text = None, "undefined (a zero vector has no direction)"
        else:
            angle = float(vectors.angle_between(a[0], b[0]))
            angle_text = f"{angle:.1f}°"
        status = (f"u·v = {dot:.3f};  angle = {angle_text};  |u×v| = {cross_len:.3f} = parallelogram area "
                  f"{area:.3f};  det(u, v, u×v) = {triple:.3f}")
        return {"sum": (a + b)[0], "cross": c[0], "dot": dot, "angle": angle, "area": area, "triple": triple,
                "status": status}

    legend = ("<span style='color:%s'>&#9632; u</span> &nbsp;<span style='color:%s'>&#9632; v</span> &nbsp;"
              "<span style='color:%s'>&#9632; u + v</span> &nbsp;<span style='color:%s'>&#9632; u × v</span>"
              % (COLOURS["u"], COLOURS["v"], COLOURS["sum"], COLOURS["cross"]))
    import ipywidgets as widgets

    return InteractiveView(controls=controls, views=[scene.widget, widgets.HTML(legend)], update=update,
                           static=scene.to_png, title="vectors, their sum and cross product", side=True)
