"""The camera (Goldman §13.6.2, §17.2): the one place where a pixel becomes a ray, and a point a pixel.

A :class:`Camera` is a pinhole: an eye, the point it looks at, an up direction, a vertical field of
view and an image size.  Like pbrt's ``Camera::GenerateRay``, it is the only code of the course that
turns pixels into rays (:meth:`Camera.pixel_directions`, :meth:`Camera.rays`, :meth:`Camera.ray`):
the ray tracer (chapter 17, :mod:`goldman_lib.ray_tracing`), the ray-cast pictures of chapter 16
(:mod:`goldman_lib.views.color_intensity`) and ray casting among the hidden-surface algorithms
(chapter 22, :mod:`goldman_lib.hidden_surfaces`) all ask it.  The other way, :meth:`Camera.project`
maps points to screen coordinates and depths by the perspective matrix of §13.6.2 for the
rasteriser (:mod:`goldman_lib.rasteriser`: chapters 21 and 22), and :meth:`Camera.clip_polygon`
cuts polygons at the near plane.  Both maps share one pixel convention: pixel (i, j) -- row i from
the top, column j from the left -- is centred at screen coordinates ``(j + 0.5, i + 0.5)``, so the
ray of a pixel projects back onto the pixel's centre.

>>> cam = Camera(eye=(0, -5, 0), target=(0, 0, 0), width=4, height=4)
>>> o, d = cam.ray(1, 2)
>>> cam.project([o + 3 * d])[0, :2].tolist()      # back to the centre of pixel (column 1, row 2)
[1.5, 2.5]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from goldman_lib import transforms
from goldman_lib.kernels.polygons import clip_to_view
from goldman_lib.validation import (as_float, as_float_array, as_int, as_points, check_finite, finite_result,
                                    within_budget)

__all__ = ["Camera", "ViewFrame", "image_size"]


class ViewFrame(NamedTuple):
    """A camera's frame (Goldman §17.2): the ``eye`` and three orthonormal directions, ``view`` (from
    the eye towards the target), ``right`` and ``up`` (across the screen), each ``(3,)``."""

    eye: np.ndarray
    view: np.ndarray
    right: np.ndarray
    up: np.ndarray


def image_size(width, height) -> tuple[int, int]:
    """A checked image size (Goldman §17.1, raster graphics): ``(width, height)`` whole numbers >= 1, their
    product within the work budget (:func:`goldman_lib.validation.within_budget`).

    >>> image_size(160, 120)
    (160, 120)
    """
    height = within_budget(height, "height", cost=lambda h: h, what="the image's height", unit="pixels",
                           minimum=1)
    width = within_budget(width, "width", cost=lambda w: w * height, what="the image", unit="pixels", minimum=1)
    return width, height


@dataclass(frozen=True)
class Camera:
    """A pinhole camera (Goldman §17.2, §13.6.2): ``eye``, the point ``target`` it looks at, the ``up``
    direction (only its direction across the view counts), the vertical field of view ``fov`` in
    degrees, the image ``width`` x ``height`` in pixels and the ``near`` distance.  The screen is the
    plane one unit in front of the eye; pixel (i, j) (row i from the top, column j from the left) is
    centred at screen coordinates ``(j + 0.5, i + 0.5)`` (x to the right, y down the rows).

    Both ways between pixels and space live here: :meth:`pixel_directions`, :meth:`rays` and
    :meth:`ray` send a ray from the eye through a pixel's centre (the ray tracer of chapter 17, ray
    casting in chapters 16 and 22); :meth:`project` maps points to the screen by the perspective matrix
    of §13.6.2 (:func:`goldman_lib.transforms.perspective`) for the rasteriser (chapters 21 and 22).
    Each projected vertex gets a depth ``z = 1 - near / w`` with ``w`` its distance along the view
    direction: z grows with distance and is *linear in screen space* across a triangle (``1/w`` is),
    so the rasteriser may interpolate it with screen barycentrics.

    >>> cam = Camera(eye=(0, -5, 0), target=(0, 0, 0), width=8, height=6)
    >>> cam.project([[0, 0, 0]]).round(6).tolist()
    [[4.0, 3.0, 0.98, 5.0]]
    >>> o, d = Camera((0, -5, 0), (0, 0, 0), fov=90, width=2, height=2).rays()
    >>> d[0, 0].round(4).tolist()    # top-left pixel: left, forward, up (the screen's half-height is tan 45 = 1)
    [-0.4082, 0.8165, 0.4082]
    """

    eye: tuple = (0.0, -6.0, 2.0)
    target: tuple = (0.0, 0.0, 0.0)
    up: tuple = (0.0, 0.0, 1.0)
    fov: float = 30.0
    width: int = 256
    height: int = 256
    near: float = 0.1

    def __post_init__(self):
        E = as_points(self.eye, "eye", ndim=1, dim=3)
        T = as_points(self.target, "target", ndim=1, dim=3)
        U = as_points(self.up, "up", ndim=1, dim=3)
        fov = as_float(self.fov, "fov")
        if not 0 < fov < 180:
            raise ValueError(f"fov must be in (0, 180) degrees; got {fov}")
        width, height = image_size(self.width, self.height)
        near = as_float(self.near, "near", positive=True)
        with np.errstate(over="ignore", invalid="ignore"):
            d = finite_result(T - E, "target", why="is too far from eye")
            dist = finite_result(np.linalg.norm(d), "target", why="is too far from eye")
        if dist <= 1e-12 * (1 + np.abs(E).max()):
            raise ValueError("target must differ from eye: the camera needs a direction to look in")
        n = d / dist
        with np.errstate(over="ignore", invalid="ignore"):
            right = np.cross(n, U / np.abs(U).max() if np.abs(U).max() > 1e150 else U)   # only up's direction counts
            rl = np.linalg.norm(right)
        if not np.isfinite(rl) or rl <= 1e-9 * max(np.linalg.norm(U), 1e-300):
            raise ValueError("up must not be parallel to the view direction (target - eye)")
        right = right / rl
        for name, value in (("eye", E), ("target", T), ("up", U)):
            object.__setattr__(self, name, tuple(float(v) for v in value))
        object.__setattr__(self, "fov", fov)
        object.__setattr__(self, "width", width)
        object.__setattr__(self, "height", height)
        object.__setattr__(self, "near", near)
        object.__setattr__(self, "_frame", ViewFrame(E, n, right, np.cross(right, n)))

    @classmethod
    def framing(cls, eye, target, half_height, **kwargs) -> "Camera":
        """The camera at ``eye`` looking at ``target`` whose image spans ``[-half_height, half_height]``
        vertically in the plane through ``target`` square to the view (Goldman §17.2): its field of
        view is ``2 atan(half_height / |target - eye|)``.  Other keywords (``up``, ``width``,
        ``height``, ``near``) go to the camera as they are.

        >>> round(Camera.framing((0, 0, 6), (0, 0, 0), 6.0, up=(0, 1, 0)).fov, 9)
        90.0
        """
        E = as_points(eye, "eye", ndim=1, dim=3)
        T = as_points(target, "target", ndim=1, dim=3)
        half = as_float(half_height, "half_height", positive=True)
        with np.errstate(over="ignore", invalid="ignore"):
            distance = finite_result(np.linalg.norm(T - E), "target", why="is too far from eye")
        return cls(E, T, fov=float(np.degrees(2 * np.arctan2(half, distance))), **kwargs)

    @property
    def frame(self) -> ViewFrame:
        """The eye and the unit ``view``, ``right`` and ``up`` directions (read-only arrays are not
        enforced: treat them as constants).

        >>> Camera(eye=(0, -5, 0), target=(0, 0, 0)).frame.view.tolist()
        [0.0, 1.0, 0.0]
        """
        return self._frame

    def frustum_slopes(self, guard=1.0) -> tuple[float, float]:
        """``(tx, ty)``: a point at distance ``w`` along the view direction is inside the view frustum
        widened ``guard`` times when ``|x| <= tx w`` and ``|y| <= ty w`` across the screen (Goldman
        §22.1's guard band; ``guard = 1`` is the image's own frustum).

        >>> [round(t, 12) for t in Camera(eye=(0, -5, 0), target=(0, 0, 0), fov=90, width=2, height=4).frustum_slopes(2)]
        [1.0, 2.0]
        """
        guard = as_float(guard, "guard")
        if not 1 <= guard <= 1e6:
            raise ValueError(f"guard must be in [1, 1e6] (image sizes kept around the image); got {guard}")
        tx, ty = guard * 0.5 * self.width / self.scale, guard * 0.5 * self.height / self.scale
        return float(tx), float(ty)

    @property
    def scale(self) -> float:
        """Pixels per unit on the projection plane one unit in front of the eye."""
        return 0.5 * self.height / np.tan(np.radians(self.fov) / 2)

    def project(self, points) -> np.ndarray:
        """Screen coordinates of points (Goldman §13.6.2): ``(n, 4)`` rows ``(x, y, z, w)``, x and y in
        pixels, ``z = 1 - near / w`` the depth the rasteriser compares and ``w`` the distance along
        the view direction (``z < 0`` in front of the near plane, which the rasteriser clips)."""
        P = as_points(points, "points", dim=3)
        E, n, right, up = self._frame
        H = transforms.homogeneous(P, transforms.perspective(E, E + n, n))
        w = H[:, 3]
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            Q = H[:, :3] / w[:, None] - (E + n)           # the projected point, from the plane's centre
            x = 0.5 * self.width + self.scale * (Q @ right)
            y = 0.5 * self.height - self.scale * (Q @ up)
            z = 1.0 - self.near / w
        bad = w <= 0
        out = np.stack([x, y, z, w], axis=1)
        out[bad, :3] = [0.0, 0.0, -1.0]                    # behind the eye: clipped by the rasteriser
        return finite_result(out, "points", why="are too far from the camera")

    def view_depth(self, points) -> np.ndarray:
        """The distance ``w`` of points along the view direction (negative behind the eye): ``(n,)``.

        >>> Camera(eye=(0, -5, 0), target=(0, 0, 0)).view_depth([[0, 0, 0], [3, -6, 1]]).tolist()
        [5.0, -1.0]
        """
        P = as_points(points, "points", dim=3)
        E, n, _, _ = self._frame
        with np.errstate(over="ignore", invalid="ignore"):
            return finite_result((P - E) @ n, "points", why="are too far from the camera")

    def clip_polygon(self, polygon, guard=None):
        """The part of a convex polygon at or beyond the near plane ``w = near`` (Sutherland and
        Hodgman's clipping against one plane, Goldman §22.1's near plane): ``(k', 3)`` vertices in
        the polygon's order, or None if nothing of it is that far.  A vertex nearer than ``near``
        (or behind the eye) is replaced by the points where its edges cross the plane, so every
        vertex of the result projects in front of the eye; the one home of the near plane of the
        hidden-surface algorithms (chapter 22), so that all of them draw the same part.  guard: if
        given (>= 1), the polygon is also clipped to the view frustum widened ``guard`` times
        (guard-band clipping: what is cut away lies far outside the image, and the screen
        coordinates of what is left stay within ``guard`` image sizes of it).

        >>> cam = Camera(eye=(0, 0, 0), target=(0, 1, 0), near=1.0)
        >>> cam.clip_polygon([[0, -1, 0], [1, 3, 0], [-1, 3, 0]]).tolist()
        [[0.5, 1.0, 0.0], [1.0, 3.0, 0.0], [-1.0, 3.0, 0.0], [-0.5, 1.0, 0.0]]
        >>> cam.clip_polygon([[0, -1, 0], [1, 0.5, 0], [-1, 0.5, 0]]) is None
        True
        """
        P = as_points(polygon, "polygon", dim=3, min_count=3)
        if len(P) < 3:
            raise ValueError(f"polygon must have at least 3 vertices; got {len(P)}")
        E, n, _, _ = self._frame
        with np.errstate(over="ignore", invalid="ignore"):
            finite_result((P - E) @ n, "polygon", why="is too far from the camera")
        slopes = None if guard is None else self.frustum_slopes(guard)
        return clip_to_view(P, *self._frame, self.near, slopes)

    def pixel_directions(self, columns, rows) -> np.ndarray:
        """Unit directions from the eye through the centres of pixels ``(rows, columns)`` (arrays of
        one shape; column from the left, row from the top, fractions allowed): shape
        ``columns.shape + (3,)``.  The one place where a pixel becomes a ray: :meth:`rays`,
        :meth:`ray`, the ray tracer of chapter 17, ray casting in chapters 16 and 22 all ask here.

        >>> Camera(eye=(0, -5, 0), target=(0, 0, 0), fov=90, width=2, height=2).pixel_directions(1.5, 0.5).round(4).tolist()
        [0.7071, 0.7071, 0.0]
        """
        E, n, right, up = self._frame
        columns = check_finite(as_float_array(columns, "columns"), "columns")
        rows = check_finite(as_float_array(rows, "rows"), "rows")
        if columns.shape != rows.shape:
            raise ValueError(f"columns and rows must have one shape; got {columns.shape} and {rows.shape}")
        for arr, name, size in ((columns, "columns", self.width), (rows, "rows", self.height)):
            if arr.size and (arr.min() < -1 or arr.max() > size):
                raise ValueError(f"{name} must lie within the image (0 to {size - 1}); got {arr.min():g} to {arr.max():g}")
        j = (columns + 0.5 - 0.5 * self.width) / self.scale
        i = (0.5 * self.height - rows - 0.5) / self.scale
        D = n + j[..., None] * right + i[..., None] * up
        return D / np.linalg.norm(D, axis=-1, keepdims=True)

    def rays(self):
        """The ray through the centre of every pixel (Goldman §17.2; §22.5's ray casting):
        ``(origin (3,), directions (height, width, 3))``, the eye and unit directions, row 0 at the top.

        >>> o, d = Camera(eye=(0, -5, 0), target=(0, 0, 0), width=3, height=3).rays()
        >>> o.tolist(), d.shape, d[1, 1].tolist()
        ([0.0, -5.0, 0.0], (3, 3, 3), [0.0, 1.0, 0.0])
        """
        rows, columns = np.mgrid[0:self.height, 0:self.width]
        return np.array(self._frame[0]), self.pixel_directions(columns, rows)

    def ray(self, px: int, py: int) -> tuple[np.ndarray, np.ndarray]:
        """The ray of one pixel (Goldman §17.2), column ``px`` from the left and row ``py`` from the top:
        ``(origin (3,), unit direction (3,))``.

        >>> Camera(eye=(0, -5, 0), target=(0, 0, 0), width=3, height=3).ray(1, 1)[1].tolist()
        [0.0, 1.0, 0.0]
        """
        px = as_int(px, "px", minimum=0, maximum=self.width - 1)
        py = as_int(py, "py", minimum=0, maximum=self.height - 1)
        return np.array(self._frame[0]), self.pixel_directions(px, py)
