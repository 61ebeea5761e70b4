"""Every use of pythreejs in the course goes through this module.

pythreejs 2.4 (three.js r97) is unmaintained upstream; keeping it behind :class:`SceneView` means
the 3D back end can be replaced in one place.  A ``SceneView`` builds its renderer, camera, orbit
controls, lights and axes **once**; afterwards the geometry of each named primitive (a mesh, line
segments, points) is updated in place by assigning a new ``BufferAttribute.array``, which is all a
slider callback has to do.  It also keeps a numpy copy of every primitive, so it can draw a static
fallback picture of itself with matplotlib (:meth:`SceneView.to_png`) for pages without a kernel.

The scene is z-up, as the book's pictures of patches are.

>>> view = SceneView(width=200, height=150)
>>> view.add_points("p", [[0, 0, 0], [1, 1, 1]])
>>> view.set_points("p", [[0, 0, 1], [1, 1, 0]])
>>> view.data("p")["positions"].shape
(2, 3)
"""

from __future__ import annotations

import io

import numpy as np

from goldman_lib import lighting, shading
from goldman_lib.shading import vertex_normals
from goldman_lib.validation import as_points, within_budget
from goldman_lib.widgets import style

__all__ = ["SceneView", "grid_triangles", "vertex_normals"]


def grid_triangles(rows: int, cols: int) -> np.ndarray:
    """Triangle indices ``(2*(rows-1)*(cols-1), 3)`` of a ``rows x cols`` grid of vertices stored
    row by row (as ``grid.reshape(-1, 3)`` stores them).

    rows, cols >= 2, with the ``6 (rows-1)(cols-1)`` indices at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).

    >>> grid_triangles(2, 2).tolist()
    [[0, 2, 1], [1, 2, 3]]
    """
    rows = within_budget(rows, "rows", cost=lambda v: 6 * (v - 1), what="the triangle grid", unit="indices",
                         minimum=2)
    cols = within_budget(cols, "cols", cost=lambda v: 6 * (rows - 1) * (v - 1), what="the triangle grid",
                         unit="indices", minimum=2)
    r, c = np.meshgrid(np.arange(rows - 1), np.arange(cols - 1), indexing="ij")
    a = (r * cols + c).ravel()
    b, d, e = a + 1, a + cols, a + cols + 1
    return np.concatenate([np.stack([a, d, b], 1), np.stack([b, d, e], 1)]).reshape(2, -1, 3).transpose(1, 0, 2).reshape(-1, 3)


class SceneView:
    """A three.js view built once, with named primitives updated in place.

    width, height: canvas size in pixels.  camera_position: where the camera starts (it looks at
    ``target`` and orbits around it with the mouse).  axes: draw x (red), y (green), z (blue) axes
    of length ``axes`` (0 for none).  lights: point lights (:class:`goldman_lib.lighting.Light`,
    default :func:`~goldman_lib.lighting.default_lights`) fixed in the scene, and ambient_light the
    ambient intensity: the live view and its static picture (:meth:`to_png`) are lit by the same
    lights, and :meth:`set_lights` moves them in place (the light-position control does).
    """

    def __init__(self, width: int = 480, height: int = 360, camera_position=(3.0, -4.0, 3.0),
                 target=(0.0, 0.0, 0.0), axes: float = 1.0, background: str = "#ffffff", lights=None,
                 ambient_light: float = 0.35):
        import pythreejs as p3

        self._p3 = p3
        self._items: dict[str, dict] = {}
        self.target = tuple(float(v) for v in target)
        self.camera_position = tuple(float(v) for v in camera_position)
        self.lights = self._check_lights(lighting.default_lights() if lights is None else lights)
        self.ambient_light = float(ambient_light)
        # Each light gets its shadow object from here: left "uninitialized", pythreejs's front end
        # makes one itself and a state update of the light can then reach its change listener
        # before the new model is resolved ("Error setting state: t.on is not a function", logged
        # once or twice by every three.js chapter under ipywidgets 8).  No shadow is ever cast.
        self._light_objects = [p3.PointLight(color=self._hex(light.colour), intensity=light.intensity,
                                             position=list(light.position), distance=0, decay=0,
                                             shadow=p3.LightShadow(camera=p3.PerspectiveCamera(fov=90, aspect=1,
                                                                                              near=0.5, far=500)))
                               for light in self.lights]
        self.camera = p3.PerspectiveCamera(position=list(self.camera_position), up=[0, 0, 1],
                                           aspect=width / height, fov=40)
        children = [self.camera, p3.AmbientLight(color="#ffffff", intensity=self.ambient_light),
                    *self._light_objects]
        if axes:
            children.append(p3.AxesHelper(size=float(axes)))
        self.scene = p3.Scene(children=children, background=background)
        self.controls = p3.OrbitControls(controlling=self.camera, target=list(self.target))
        self.renderer = p3.Renderer(camera=self.camera, scene=self.scene, controls=[self.controls],
                                    width=width, height=height, antialias=True)
        self.camera.lookAt(list(self.target))

    # -- lights ----------------------------------------------------------------------------------
    @staticmethod
    def _hex(rgb) -> str:
        return "#" + "".join(f"{int(round(255 * c)):02x}" for c in rgb)

    @staticmethod
    def _check_lights(lights) -> tuple:
        lights = (lights,) if isinstance(lights, lighting.Light) else tuple(lights)
        if not all(isinstance(light, lighting.Light) for light in lights):
            raise TypeError("lights must be a sequence of goldman_lib.lighting.Light")
        return lights

    def set_lights(self, lights):
        """Move and recolour the scene's lights in place (as many as it was built with)."""
        lights = self._check_lights(lights)
        if len(lights) != len(self._light_objects):
            raise ValueError(f"lights must hold {len(self._light_objects)} lights (as the scene was built); "
                             f"got {len(lights)}")
        for obj, light in zip(self._light_objects, lights):
            obj.position = tuple(light.position)
            obj.color = self._hex(light.colour)
            obj.intensity = light.intensity
        self.lights = lights

    # -- building ------------------------------------------------------------------------------
    def _attr(self, arr, dtype=np.float32):
        return self._p3.BufferAttribute(array=np.ascontiguousarray(arr, dtype=dtype), normalized=False)

    def add_mesh(self, name: str, positions, triangles, color: str = "#66a3d2", opacity: float = 1.0,
                 colors=None, lit: bool = True):
        """A shaded triangle mesh: positions ``(n, 3)``, triangles ``(k, 3)`` vertex indices.

        colors: optional per-vertex RGB ``(n, 3)`` in [0, 1] (three.js vertex colours, interpolated
        over each triangle; the static picture gives each face the mean of its vertices' colours).
        lit: False shows the colours as they are, unshaded (a radiosity solution, a curvature map);
        True lets the scene's lights shade them.
        """
        p3 = self._p3
        pos = as_points(positions, "positions", dim=3)
        tri = np.asarray(triangles, dtype=np.uint32)
        if tri.ndim != 2 or tri.shape[1] != 3 or (tri.size and tri.max() >= len(pos)):
            raise ValueError(f"triangles must have shape (k, 3) with indices below {len(pos)}; got shape {tri.shape}")
        attributes = {"position": self._attr(pos), "normal": self._attr(vertex_normals(pos, tri)),
                      "index": self._attr(tri.ravel(), np.uint32)}
        col = None if colors is None else self._colors(colors, len(pos))
        if col is not None:
            attributes["color"] = self._attr(col)
        geom = p3.BufferGeometry(attributes=attributes)
        common = dict(side="DoubleSide", transparent=opacity < 1, opacity=opacity,
                      vertexColors="VertexColors" if col is not None else "NoColors")
        if lit:
            material = p3.MeshPhongMaterial(color="#ffffff" if col is not None else color, shininess=40, **common)
        else:
            material = p3.MeshBasicMaterial(color="#ffffff" if col is not None else color, **common)
        obj = p3.Mesh(geometry=geom, material=material)
        self._add(name, obj, geom, kind="mesh", positions=pos, triangles=tri, color=color, opacity=float(opacity),
                  colors=col, lit=bool(lit))

    @staticmethod
    def _colors(colors, count: int) -> np.ndarray:
        col = as_points(colors, "colors", dim=3)
        if len(col) != count:
            raise ValueError(f"colors must hold one RGB colour per vertex ({count}); got shape {col.shape}")
        if col.min() < 0 or col.max() > 1:
            raise ValueError("colors must hold RGB values in [0, 1]")
        return col

    def set_colors(self, name: str, colors):
        """New per-vertex colours ``(n, 3)`` in [0, 1] for mesh ``name`` (built with ``colors``), in place."""
        item = self._item(name, "mesh")
        if item.get("colors") is None:
            raise ValueError(f"mesh {name!r} was built without per-vertex colors; pass colors= to add_mesh")
        col = self._colors(colors, len(item["positions"]))
        item["colors"] = col
        item["geometry"].attributes["color"].array = col.astype(np.float32)

    def set_color(self, name: str, color: str):
        """A new single colour (``"#rrggbb"``) for mesh ``name``, in place (a picker that swaps one surface
        for another); the static picture uses it too."""
        item = self._item(name, "mesh")
        from matplotlib.colors import to_hex

        try:
            color = to_hex(color)
        except ValueError:
            raise ValueError(f"color must be a colour such as '#66a3d2'; got {color!r}") from None
        item["color"] = color
        if item.get("colors") is None:
            item["object"].material.color = color

    def add_segments(self, name: str, positions, segments, color: str = "#7a7a7a", width: float = 1.2):
        """Line segments between ``positions[segments[:, 0]]`` and ``positions[segments[:, 1]]``.

        width: the line width of the static picture (WebGL draws every line 1 pixel wide)."""
        pos = as_points(positions, "positions", dim=3)
        seg = np.asarray(segments, dtype=np.int64)
        if seg.ndim != 2 or seg.shape[1] != 2 or (seg.size and seg.max() >= len(pos)):
            raise ValueError(f"segments must have shape (k, 2) with indices below {len(pos)}; got shape {seg.shape}")
        geom = self._p3.BufferGeometry(attributes={"position": self._attr(pos[seg].reshape(-1, 3))})
        obj = self._p3.LineSegments(geometry=geom, material=self._p3.LineBasicMaterial(color=color, linewidth=2))
        self._add(name, obj, geom, kind="segments", positions=pos, segments=seg, color=color, width=float(width))

    def add_points(self, name: str, positions, color: str = "#d1495b", size: float = 0.12):
        """Round-ish dots of world size ``size`` at ``positions`` ``(n, 3)``."""
        pos = as_points(positions, "positions", dim=3)
        geom = self._p3.BufferGeometry(attributes={"position": self._attr(pos)})
        obj = self._p3.Points(geometry=geom, material=self._p3.PointsMaterial(color=color, size=size))
        self._add(name, obj, geom, kind="points", positions=pos, color=color)

    def _add(self, name, obj, geom, **data):
        if name in self._items:
            raise ValueError(f"name {name!r} is already used in this scene")
        self._items[name] = {"object": obj, "geometry": geom, **data}
        self.scene.children = tuple(self.scene.children) + (obj,)

    # -- updating in place ---------------------------------------------------------------------
    def _item(self, name, kind):
        if name not in self._items or self._items[name]["kind"] != kind:
            raise KeyError(f"no {kind} named {name!r} in this scene")
        return self._items[name]

    def _same_shape(self, name, old, new):
        if new.shape != old.shape:
            raise ValueError(f"positions for {name!r} must keep shape {old.shape}; got {new.shape}")

    def set_mesh(self, name: str, positions):
        """New vertex positions (same count) for mesh ``name``; normals are recomputed."""
        item = self._item(name, "mesh")
        pos = as_points(positions, "positions", dim=3)
        self._same_shape(name, item["positions"], pos)
        item["positions"] = pos
        attrs = item["geometry"].attributes
        attrs["normal"].array = vertex_normals(pos, item["triangles"]).astype(np.float32)
        attrs["position"].array = pos.astype(np.float32)

    def set_segments(self, name: str, positions):
        """New endpoint positions (same count) for the segments ``name``."""
        item = self._item(name, "segments")
        pos = as_points(positions, "positions", dim=3)
        self._same_shape(name, item["positions"], pos)
        item["positions"] = pos
        item["geometry"].attributes["position"].array = pos[item["segments"]].reshape(-1, 3).astype(np.float32)

    def set_points(self, name: str, positions):
        """New positions (same count) for the points ``name``."""
        item = self._item(name, "points")
        pos = as_points(positions, "positions", dim=3)
        self._same_shape(name, item["positions"], pos)
        item["positions"] = pos
        item["geometry"].attributes["position"].array = pos.astype(np.float32)

    def replace_mesh(self, name: str, positions, triangles):
        """New geometry of any size for mesh ``name``: positions ``(n, 3)`` and triangles ``(k, 3)``.

        For views whose mesh changes its vertex count (a subdivision level slider).  The mesh keeps
        its ``BufferGeometry`` and ``BufferAttribute`` widgets; their arrays are replaced.  three.js
        r97 (pythreejs 2.4) re-uploads a non-dynamic attribute with ``bufferData`` and updates its
        ``count`` in ``setArray``, so an array of a new length is drawn whole.  The positions go first
        and the indices last, so no index ever points past the vertices it is drawn with.  Frustum
        culling is switched off for the mesh, since its bounding sphere was computed for the first
        geometry.
        """
        item = self._item(name, "mesh")
        pos = as_points(positions, "positions", dim=3)
        tri = np.asarray(triangles, dtype=np.uint32)
        if tri.ndim != 2 or tri.shape[1] != 3 or (tri.size and tri.max() >= len(pos)):
            raise ValueError(f"triangles must have shape (k, 3) with indices below {len(pos)}; got shape {tri.shape}")
        item["positions"], item["triangles"] = pos, tri
        item["object"].frustumCulled = False
        attrs = item["geometry"].attributes
        attrs["position"].array = pos.astype(np.float32)
        attrs["normal"].array = vertex_normals(pos, tri).astype(np.float32)
        attrs["index"].array = np.ascontiguousarray(tri.ravel())

    def replace_segments(self, name: str, positions, segments):
        """New endpoints and index pairs of any size for the segments ``name`` (see :meth:`replace_mesh`)."""
        item = self._item(name, "segments")
        pos = as_points(positions, "positions", dim=3)
        seg = np.asarray(segments, dtype=np.int64)
        if seg.ndim != 2 or seg.shape[1] != 2 or (seg.size and seg.max() >= len(pos)):
            raise ValueError(f"segments must have shape (k, 2) with indices below {len(pos)}; got shape {seg.shape}")
        item["positions"], item["segments"] = pos, seg
        item["object"].frustumCulled = False
        item["geometry"].attributes["position"].array = pos[seg].reshape(-1, 3).astype(np.float32)

    def __contains__(self, name: str) -> bool:
        """Whether the scene has a primitive called ``name``."""
        return name in self._items

    def data(self, name: str) -> dict:
        """The numpy data behind primitive ``name`` (``positions`` and, for meshes, ``triangles``)."""
        return {k: v for k, v in self._items[name].items() if k not in ("object", "geometry")}

    @property
    def widget(self):
        """The ipywidget to display (the three.js renderer)."""
        return self.renderer

    # -- the static fallback -------------------------------------------------------------------
    def to_png(self, figsize=(4.8, 3.6), dpi: int = 100) -> bytes:
        """PNG bytes of the scene drawn by matplotlib from the camera's starting direction.

        Meshes are shaded by the scene's own lights (:func:`goldman_lib.lighting.shade_faces`; translucent if their opacity is below 1); segments and points are drawn
        over them, since matplotlib's depth sorting of polygons against lines would bury a control
        net lying on its surface.  Degenerate triangles and zero-length segments (the padding of a
        view whose geometry shrank) are left out.  Axes have equal scales.
        """
        from matplotlib.colors import to_rgb
        from matplotlib.figure import Figure
        from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

        fig = Figure(figsize=figsize, dpi=dpi)
        ax = fig.add_subplot(1, 1, 1, projection="3d", computed_zorder=False)
        d = np.subtract(self.camera_position, self.target)
        ax.view_init(elev=np.degrees(np.arctan2(d[2], np.hypot(d[0], d[1]))), azim=np.degrees(np.arctan2(d[1], d[0])))
        everything = []
        for order, item in enumerate(self._items.values()):
            pos = item["positions"]
            if item["kind"] == "mesh":
                tris = pos[item["triangles"]]
                normals = shading.face_normals(pos, item["triangles"])
                keep = np.linalg.norm(normals, axis=1) > 1e-12
                if not keep.any():
                    continue
                tris, normals = tris[keep], normals[keep]
                if item.get("colors") is not None:
                    face_colours = item["colors"][item["triangles"]].mean(axis=1)[keep]
                else:
                    face_colours = to_rgb(item["color"])
                if item.get("lit", True):
                    colors = lighting.shade_faces(tris.mean(axis=1), normals, self.camera_position, face_colours,
                                                  self.lights, self.ambient_light)
                else:
                    colors = np.broadcast_to(face_colours, tris.shape[:1] + (3,))
                ax.add_collection3d(Poly3DCollection(tris, facecolors=colors, edgecolors="none",
                                                     alpha=min(1.0, item["opacity"] + 0.15), zorder=order))
                everything.append(tris.reshape(-1, 3))
            elif item["kind"] == "segments":
                segs = pos[item["segments"]]
                segs = segs[np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1) > 1e-12]
                if len(segs):
                    ax.add_collection3d(Line3DCollection(segs, colors=item["color"], linewidths=item["width"],
                                                         zorder=100 + order))
                    everything.append(segs.reshape(-1, 3))
            else:
                ax.scatter(*pos.T, color=item["color"], s=18, depthshade=False, zorder=200 + order)
                everything.append(pos)
        if everything:
            style.equal_3d_limits(ax, np.concatenate(everything))
        ax.set_box_aspect((1, 1, 1))
        ax.set_xlabel("x"), ax.set_ylabel("y"), ax.set_zlabel("z")
        buf = io.BytesIO()
        fig.savefig(buf, format="png", metadata={"Software": None})
        return buf.getvalue()
