"""Hidden surfaces (Goldman chapter 22): six ways to draw only what the eye sees, on one scene.

A scene is a list of planar convex polygons (each ``(k, 3)`` vertices in order) seen by a
:class:`goldman_lib.camera.Camera`.  Every algorithm returns a :class:`Rendering`: ``ids`` (h, w),
the index of the polygon seen at each pixel (-1 for none), and ``order``, what it drew in the order
it drew it, for the step-through of the views.

* :func:`heedless_painter` (§22.2): paint polygons back to front, sorted by their farthest point,
  each over the last -- wrong where polygons interpenetrate or overlap cyclically;
* :func:`z_buffer` (§22.3): the depth buffer of :func:`goldman_lib.rasteriser.rasterise_triangles`, the
  one scan conversion of the course;
* :func:`scan_line` (§22.4): an edge table and an active edge list per scan line; on each scan line
  the spans of the active polygons, the nearest polygon kept at each pixel;
* :func:`ray_casting` (§22.5): the first polygon hit by the ray through each pixel
  (:class:`goldman_lib.simple_surfaces.Polygon`);
* :func:`depth_sort` (§22.6): Newell, Newell and Sancha's depth sort: sort by depth, resolve
  ambiguous pairs by the extent and plane tests, reorder, and split polygons by planes
  (:func:`split_polygon`) to break cycles; then paint;
* :func:`bsp_render` (§22.7): a BSP tree (:func:`build_bsp`) traversed back to front from the eye
  (:func:`bsp_back_to_front`); then paint.

All but the heedless painter produce the same ``ids`` up to pixels on the edges of polygons (and on
the lines where polygons cross); the painters scan convert with the same rule.  Every algorithm draws
the same part of each polygon: the part at or beyond the camera's near plane, clipped once for all
(:meth:`goldman_lib.camera.Camera.clip_polygon`, with a guard band of :data:`GUARD` image sizes), so
a polygon reaching behind the eye, or one nearer than the near plane, is one picture in all six.
The work is bounded before any pixel is drawn: the polygons' screen extents summed (their overdraw;
polygons x pixels for ray casting) by :data:`MAX_PIXEL_TESTS`, the depth sort's pairs of polygons
overlapping in depth by :data:`MAX_PAIR_TESTS`.  :func:`shade`
colours an ``ids`` image by uniform shading (one :func:`goldman_lib.lighting.intensity` per polygon).

>>> polygons, colours = default_scene()
>>> camera = default_camera(40, 30)
>>> a, b = z_buffer(polygons, camera), bsp_render(polygons, camera)
>>> bool((a.ids == b.ids).mean() > 0.97)
True
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from goldman_lib import lighting, rasteriser, shading
from goldman_lib.camera import Camera
from goldman_lib.kernels import meshes, polygons
from goldman_lib.simple_surfaces import Polygon
from goldman_lib.validation import (MAX_ITEMS, as_colour, as_float, as_float_array, as_points, check_finite,
                                    finite_result, within_budget)

__all__ = ["Rendering", "default_scene", "default_camera", "split_polygon", "heedless_painter", "z_buffer",
           "scan_line", "ray_casting", "depth_sort", "BSPNode", "build_bsp", "bsp_back_to_front", "bsp_render",
           "ALGORITHMS", "frames", "shade", "edge_pixels"]

#: Polygons (pieces included) an algorithm may handle: splitting can multiply them.
MAX_POLYGONS = 2000
#: The most pixel candidates one rendering may examine: the polygons' screen extents summed (their
#: overdraw) for the scan-converting algorithms, polygons x pixels for ray casting.
MAX_PIXEL_TESTS = MAX_ITEMS
#: The guard band of the clip (:meth:`goldman_lib.camera.Camera.clip_polygon`): polygons are cut
#: to the view frustum widened this many times, so screen coordinates stay within a few image sizes.
GUARD = 4.0
#: The most pairs of pieces the depth sort may compare (its tests 1-4 on one pair are one).
MAX_PAIR_TESTS = 400_000


class Rendering(NamedTuple):
    """What a hidden-surface algorithm produced: ``ids`` (h, w) the polygon seen at each pixel (-1:
    none) and ``order`` the drawing steps in order -- polygon indices (painters, z-buffer), pieces
    ``(polygon index, piece vertices)`` (depth sort, BSP), spans ``(row, first column, last column,
    polygon index)`` (scan line) or rows (ray casting)."""

    ids: np.ndarray
    order: list


# -- the scene -------------------------------------------------------------------------------------

def default_scene():
    """The chapter's scene (Goldman §22.1): three bars that overlap cyclically (each lies over the next
    at one end and under it at the other, so no order of whole polygons is right) and two triangles
    that pass through each other.  Returns ``(polygons, colours)``: a list of (4, 3) and (3, 3)
    arrays and an (5, 3) array of RGB colours.

    >>> polygons, colours = default_scene()
    >>> [len(p) for p in polygons], colours.shape
    ([4, 4, 4, 3, 3], (5, 3))
    """
    polygons = []
    corners = [np.array([np.cos(a), np.sin(a)]) * 1.2 for a in np.radians([90, 210, 330])]
    for k in range(3):
        a, b = corners[k], corners[(k + 1) % 3]
        u = (b - a) / np.linalg.norm(b - a)
        p = np.array([-u[1], u[0]]) * 0.22
        s, e = a - 0.45 * u, b + 0.45 * u
        y0, y1 = -0.5, 0.5                           # near at its start, far at its end
        quad = [(s - p, y0), (e - p, y1), (e + p, y1), (s + p, y0)]
        polygons.append(np.array([[x, y, z + 0.3] for (x, z), y in quad]))
    polygons.append(np.array([[-1.9, -0.6, -1.3], [-0.2, 0.6, -1.5], [-1.0, 0.0, -0.3]]))
    polygons.append(np.array([[-1.8, 0.5, -0.6], [-0.3, -0.5, -0.9], [-1.2, 0.1, -1.7]]))
    colours = np.array([[0.85, 0.3, 0.25], [0.25, 0.6, 0.3], [0.25, 0.4, 0.85], [0.9, 0.7, 0.2], [0.6, 0.35, 0.75]])
    return polygons, colours


def default_camera(width: int = 160, height: int = 120) -> Camera:
    """The camera of the chapter's scene: on the -y side, looking at it along +y.

    >>> default_camera().eye
    (0.0, -7.0, 0.6)
    """
    return Camera(eye=(0.0, -7.0, 0.6), target=(0.0, 0.0, 0.1), up=(0.0, 0.0, 1.0), fov=36.0,
                          width=width, height=height)


def _polygons(polygons) -> list[np.ndarray]:
    if isinstance(polygons, np.ndarray) and polygons.ndim == 2:
        raise TypeError("polygons must be a sequence of (k, 3) vertex arrays, not one array")
    try:
        items = list(polygons)
    except TypeError:
        raise TypeError(f"polygons must be a sequence of (k, 3) vertex arrays; got {type(polygons).__name__}") from None
    if len(items) > MAX_POLYGONS:
        raise ValueError(f"polygons must hold at most {MAX_POLYGONS} polygons; got {len(items)}")
    out = []
    for k, p in enumerate(items):
        P = as_points(p, f"polygons[{k}]", dim=3, min_count=3)
        if len(P) < 3:
            raise ValueError(f"polygons[{k}] must have at least 3 vertices; got {len(P)}")
        if np.abs(P).max() > 1e6:
            raise ValueError(f"polygons[{k}] must have coordinates within 1e6")
        out.append(P)
    return out


def _camera(camera) -> Camera:
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a goldman_lib.camera.Camera; got {type(camera).__name__}")
    return camera


def _visible(camera, polys) -> list:
    """``(index, part)`` of every polygon with a part at or beyond the camera's near plane and
    within the guard band (:meth:`goldman_lib.camera.Camera.clip_polygon`, ``guard=GUARD``): the
    one clip all six algorithms share, so a polygon reaching behind the eye, or one nearer than the
    near plane, is the same picture (or none) in each, and no vertex projects far off the image."""
    out = []
    frame, slopes = camera.frame, camera.frustum_slopes(GUARD)
    for k, P in enumerate(polys):
        C = polygons.clip_to_view(P, *frame, camera.near, slopes)
        if C is not None:
            out.append((k, C))
    return out


def _screens(camera, polys) -> list:
    """The screen coordinates ``(k, 4)`` of each polygon's vertices (one projection for all)."""
    if not polys:
        return []
    S = camera.project(np.vstack(polys))
    return np.split(S, np.cumsum([len(P) for P in polys])[:-1])


def _extent_pixels(camera, S) -> int:
    """The pixels of the image inside the screen extent (bounding box) of a clipped polygon's screen
    vertices S: what its scan conversion examines."""
    x0 = min(max(np.ceil(S[:, 0].min() - 0.5), 0), camera.width)
    x1 = min(max(np.floor(S[:, 0].max() - 0.5), -1), camera.width - 1)
    y0 = min(max(np.ceil(S[:, 1].min() - 0.5), 0), camera.height)
    y1 = min(max(np.floor(S[:, 1].max() - 0.5), -1), camera.height - 1)
    return int(max(x1 - x0 + 1, 0) * max(y1 - y0 + 1, 0))


def _check_work(camera, items, ray_cast=False) -> None:
    """The work budget of a rendering (:data:`MAX_PIXEL_TESTS`), checked before any pixel is drawn:
    polygons x covered pixels (the overdraw), or polygons x pixels for ray casting."""
    if ray_cast:
        cost = len(items) * camera.width * camera.height
        rule = f"ray casting tests every polygon against every pixel: {len(items)} x {camera.width * camera.height:,}"
    else:
        cost = sum(_extent_pixels(camera, S) for S in _screens(camera, [P for _, P in items]))
        rule = "the polygons' screen extents, summed (each pixel once per polygon that may cover it: the overdraw)"
    if cost > MAX_PIXEL_TESTS:
        raise ValueError(f"polygons must cover at most {MAX_PIXEL_TESTS:,} pixels in all at this camera's "
                         f"{camera.width}x{camera.height} image; {rule} come to {cost:,}: use fewer or smaller "
                         "polygons, or a smaller image")


def _fan(k: int) -> np.ndarray:
    return np.stack([np.zeros(k - 2, np.intp), np.arange(1, k - 1), np.arange(2, k)], 1)


def _view_depth(camera, P) -> np.ndarray:
    E, n, _, _ = camera.frame
    return (P - E) @ n


# -- §22.6 splitting a polygon by a plane -----------------------------------------------------------

def split_polygon(polygon, plane_point, normal, eps: float = 1e-9):
    """Split a convex polygon by a plane (Goldman §22.6-22.7): ``(front, back)``, the parts on the
    side ``normal`` points to and on the other side, each a (k, 3) array or None if empty.  Vertices
    within ``eps`` of the plane belong to both parts; a polygon in the plane is returned as front.

    >>> f, b = split_polygon([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], [1, 0, 0], [1, 0, 0])
    >>> f.tolist(), b.tolist()
    ([[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.0], [1.0, 1.0, 0.0]], [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]])
    """
    P = as_points(polygon, "polygon", dim=3, min_count=3)
    if len(P) < 3:
        raise ValueError(f"polygon must have at least 3 vertices; got {len(P)}")
    Q = as_points(plane_point, "plane_point", ndim=1, dim=3)
    N = as_points(normal, "normal", ndim=1, dim=3)
    if not np.any(N != 0):
        raise ValueError("normal must be a nonzero vector")
    eps = _eps(eps)
    with np.errstate(over="ignore", invalid="ignore"):
        N = lighting.unit_rows(N / np.abs(N).max(), "normal")
        s = finite_result((P - Q) @ N, "polygon and plane_point", why="are too far apart")
    return _split(P, s, eps)


def _eps(eps) -> float:
    e = as_float(eps, "eps")
    if not 0 <= e <= 1e-3:
        raise ValueError(f"eps must be in [0, 1e-3] (a tolerance for lying on a plane); got {e}")
    return e


def _split(P, s, eps):
    if np.all(s >= -eps):
        return P, None
    if np.all(s <= eps):
        return None, P
    front, back = [], []
    k = len(P)
    for i in range(k):
        a, b, sa, sb = P[i], P[(i + 1) % k], s[i], s[(i + 1) % k]
        if sa >= -eps:
            front.append(a)
        if sa <= eps:
            back.append(a)
        if (sa > eps and sb < -eps) or (sa < -eps and sb > eps):
            x = a + (sa / (sa - sb)) * (b - a)
            front.append(x)
            back.append(x)
    f = np.array(front) if len(front) >= 3 else None
    b = np.array(back) if len(back) >= 3 else None
    return f, b


def _plane(P):
    """(point, unit Newell normal) of a polygon; a zero normal for a degenerate one."""
    return P[0], shading.unit_newell_normal(P)


# -- painting through the shared scan conversion ----------------------------------------------------

def _cover(camera, P, S=None) -> np.ndarray:
    """The pixels whose centres the projected polygon covers (the rasteriser's rule): (h, w) bool.
    S: its screen vertices, if already projected."""
    S = camera.project(P) if S is None else S
    if np.any(S[:, 3] <= 0):                             # (clipped by _visible before it gets here)
        return np.zeros((camera.height, camera.width), bool)
    S = S[:, :3].copy()
    S[:, 2] = 0.5
    if np.abs(S[:, :2]).max() > 1e9:
        raise ValueError("polygons must project within 1e9 pixels of the image (move them away from the eye's plane)")
    return meshes.rasterise(S, _fan(len(P)), camera.width, camera.height)[0] >= 0


def _paint(camera, pieces, keep_frames=False):
    """Paint (polygon index, vertices) pieces in order, each over the last."""
    ids = np.full((camera.height, camera.width), -1, dtype=np.intp)
    frames = []
    for (k, P), S in zip(pieces, _screens(camera, [P for _, P in pieces])):
        ids[_cover(camera, P, S)] = k
        if keep_frames:
            frames.append(ids.copy())
    return ids, frames


# -- §22.2 the heedless painter ---------------------------------------------------------------------

def _painter_order(items, camera):
    far = {k: float(_view_depth(camera, P).max()) for k, P in items}
    return sorted(far, key=lambda k: -far[k])


def heedless_painter(polygons, camera) -> Rendering:
    """The heedless painter's algorithm (Goldman §22.2): sort the polygons by the depth of their
    farthest vertex and paint them back to front, each over what is already there.  Wrong when a
    farther-starting polygon reaches in front of a nearer one, or polygons pierce or overlap
    cyclically.  ``order``: polygon indices in painting order.

    >>> r = heedless_painter(*default_scene()[:1], default_camera(32, 24))
    >>> r.order
    [3, 0, 4, 1, 2]
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items)
    order = _painter_order(items, camera)
    part = dict(items)
    ids, _ = _paint(camera, [(k, part[k]) for k in order])
    return Rendering(ids, order)


# -- §22.3 the z-buffer ------------------------------------------------------------------------------

def _zbuffer(camera, items, upto=None):
    V, T, owner = [], [], []
    base = 0
    for k, P in items[:upto]:
        V.append(P)
        T.append(_fan(len(P)) + base)
        owner.append(np.full(len(P) - 2, k))
        base += len(P)
    if not V:
        return np.full((camera.height, camera.width), -1, dtype=np.intp)
    S = camera.project(np.vstack(V))[:, :3]
    f = rasteriser.rasterise_triangles(S, np.vstack(T), camera.width, camera.height)
    owner = np.concatenate(owner)
    return np.where(f.triangle >= 0, owner[np.maximum(f.triangle, 0)], -1)


def z_buffer(polygons, camera) -> Rendering:
    """The z-buffer (Goldman §22.3): scan convert every polygon (as a fan of triangles) with a depth
    per pixel and keep the nearest -- :func:`goldman_lib.rasteriser.rasterise_triangles`, whose depth is
    ``1 - near / w``, linear in screen space.  The polygons may come in any order; ``order`` is the
    order given.

    >>> r = z_buffer(*default_scene()[:1], default_camera(32, 24))
    >>> r.order, int((r.ids >= 0).sum()) > 100
    ([0, 1, 2, 3, 4], True)
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items)
    return Rendering(_zbuffer(camera, items), [k for k, _ in items])


# -- §22.4 scan line ----------------------------------------------------------------------------------

def _screen_planes(camera, polys):
    """Per (clipped) polygon: screen vertices (k, 3) and the plane z = a x + b y + c in screen space."""
    out = []
    for P in polys:
        S = camera.project(P)[:, :3]
        n = shading.unit_newell_normal(S) if len(S) >= 3 else np.zeros(3)
        if abs(n[2]) < 1e-12:
            out.append((S, None))                       # edge-on: covers no pixel centre
            continue
        a, b = -n[0] / n[2], -n[1] / n[2]
        c = S[0, 2] - a * S[0, 0] - b * S[0, 1]
        out.append((S, (a, b, c)))
    return out


def _scan_line(camera, items, keep_frames=False):
    W, H = camera.width, camera.height
    index = np.array([k for k, _ in items] + [-1], dtype=np.intp)      # position -> polygon (-1: none)
    planes = _screen_planes(camera, [P for _, P in items])
    # the edge table: every non-horizontal edge, bucketed by the first scan line (row) it crosses
    rows_first, edges = [], []
    for k, (S, plane) in enumerate(planes):
        if plane is None:
            continue
        for i in range(len(S)):
            p, q = S[i], S[(i + 1) % len(S)]
            if p[1] == q[1]:
                continue
            top, bottom = (p, q) if p[1] < q[1] else (q, p)
            first = int(np.ceil(top[1] - 0.5))           # the first centre y = row + 0.5 >= top
            last = int(np.ceil(bottom[1] - 0.5)) - 1      # half-open: centres below the bottom end
            if last < max(first, 0) or first >= H:
                continue
            dxdy = (bottom[0] - top[0]) / (bottom[1] - top[1])
            edges.append((first, last, top[0] + (first + 0.5 - top[1]) * dxdy, dxdy, k))
    table: dict[int, list] = {}
    for e in edges:
        table.setdefault(max(e[0], 0), []).append(e)
    ids = np.full((H, W), -1, dtype=np.intp)
    order, frames = [], []
    active = np.zeros((0, 4))                             # rows: last row, x, dx/dy, polygon
    for row in range(H):
        new = table.get(row, [])
        if new:
            add = np.array([[e[1], e[2] + (row - e[0]) * e[3], e[3], e[4]] for e in new])
            active = np.vstack([active, add])
        if len(active):
            # spans: the active edges of each polygon, sorted by x, paired
            srt = np.lexsort((active[:, 1], active[:, 3]))
            crossings = active[srt]
            poly = crossings[:, 3].astype(np.intp)
            starts = np.flatnonzero(np.r_[True, poly[1:] != poly[:-1]])
            xs_left, xs_right, span_poly = [], [], []
            for s, e in zip(starts, np.r_[starts[1:], len(poly)]):
                xs = crossings[s:e, 1]
                xs_left.extend(xs[0::2])
                xs_right.extend(xs[1::2][: len(xs[0::2])])
                span_poly.extend([poly[s]] * (len(xs) // 2))
            xs_left, xs_right = np.array(xs_left[: len(span_poly)]), np.array(xs_right)
            j0 = np.clip(np.ceil(xs_left - 0.5), 0, W).astype(np.intp)
            j1 = np.clip(np.floor(xs_right - 0.5), -1, W - 1).astype(np.intp)
            count = np.maximum(j1 - j0 + 1, 0)
            if count.sum():
                which = np.repeat(np.arange(len(count)), count)
                j = j0[which] + np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
                k = np.array(span_poly)[which]
                abc = np.array([planes[m][1] for m in k])
                z = abc[:, 0] * (j + 0.5) + abc[:, 1] * (row + 0.5) + abc[:, 2]
                keep = (z >= 0) & (z < 1)
                j, k, z = j[keep], k[keep], z[keep]
                sel = np.lexsort((k, z, j))
                first = np.r_[True, j[sel][1:] != j[sel][:-1]]
                ids[row, j[sel][first]] = index[k[sel][first]]
                line = ids[row]
                change = np.flatnonzero(np.r_[True, line[1:] != line[:-1]])
                for a, b in zip(change, np.r_[change[1:], W]):
                    if line[a] >= 0:
                        order.append((row, int(a), int(b - 1), int(line[a])))
            # the active edge list for the next scan line: drop finished edges, step x by dx/dy
            active = active[active[:, 0] > row]
            active[:, 1] += active[:, 2]
        if keep_frames:
            frames.append(ids.copy())
    return ids, order, frames


def scan_line(polygons, camera) -> Rendering:
    """The scan-line algorithm (Goldman §22.4): an edge table holds each edge under the first scan
    line it crosses; going down the image, an active edge list gains the edges that start, loses the
    edges that end and steps each edge's x by dx/dy.  On each scan line the active edges of each
    polygon, sorted by x and paired, give its spans; at each pixel of the spans the polygon whose
    plane is nearest (depth linear in x and y) is kept.  ``order``: the visible spans
    ``(row, first column, last column, polygon)`` in the order drawn.

    >>> r = scan_line(*default_scene()[:1], default_camera(32, 24))
    >>> r.order[0][0] >= 0 and all(span[1] <= span[2] for span in r.order)
    True
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items)
    ids, order, _ = _scan_line(camera, items)
    return Rendering(ids, order)


# -- §22.5 ray casting -------------------------------------------------------------------------------

def _ray_casting(camera, items, keep_frames=False):
    o, d = camera.rays()
    D = d.reshape(-1, 3)
    O = np.broadcast_to(o, D.shape)
    best = np.full(len(D), np.inf)
    ids = np.full(len(D), -1, dtype=np.intp)
    for k, P in items:
        try:
            surface = Polygon(P)
        except ValueError:
            continue                                     # a degenerate polygon is hit by no ray
        t = surface.intersect(O, D)
        closer = t < best
        best[closer] = t[closer]
        ids[closer] = k
    ids = ids.reshape(camera.height, camera.width)
    frames = []
    if keep_frames:
        for row in range(camera.height):
            frame = np.full_like(ids, -1)
            frame[: row + 1] = ids[: row + 1]
            frames.append(frame)
    return ids, frames


def ray_casting(polygons, camera) -> Rendering:
    """Ray casting (Goldman §22.5): for the ray from the eye through each pixel centre, the first
    polygon it hits (:class:`goldman_lib.simple_surfaces.Polygon`, the ray-polygon intersection of
    chapter 19), vectorised over all rays, one polygon at a time.  ``order``: the rows, top to bottom
    (each pixel is found independently).

    >>> r = ray_casting(*default_scene()[:1], default_camera(32, 24))
    >>> r.order[:3], r.ids.shape
    ([0, 1, 2], (24, 32))
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items, ray_cast=True)
    ids, _ = _ray_casting(camera, items)
    return Rendering(ids, list(range(camera.height)))


# -- §22.6 depth sort ------------------------------------------------------------------------------

@dataclass
class _Piece:
    polygon: int
    P: np.ndarray
    near: float
    far: float
    box: np.ndarray         # screen x0, x1, y0, y1
    point: np.ndarray       # its plane: a point and the Newell normal (zero for a degenerate piece)
    normal: np.ndarray
    eye_side: float         # the sign of the eye's side of that plane
    moved: bool = False
    id: int = -1            # its row in the depth sort's table of boxes and planes


def _piece(camera, k, P, S=None):
    w = _view_depth(camera, P)
    S = camera.project(P) if S is None else S
    point, normal = _plane(P)
    return _Piece(k, P, float(w.min()), float(w.max()), np.array([S[:, 0].min(), S[:, 0].max(), S[:, 1].min(),
                                                                  S[:, 1].max()]),
                  point, normal, float(np.sign((np.asarray(camera.eye) - point) @ normal)))


def _side_of(P, plane, eye, eps):
    """+1 if every vertex of P is on the eye's side of the plane (or on it), -1 if every vertex is on
    the far side (or on it), 0 otherwise."""
    Q, N = plane
    s = (P - Q) @ N * np.sign((eye - Q) @ N)
    if np.all(s >= -eps):
        return 1
    if np.all(s <= eps):
        return -1
    return 0


def _pair_tests(near, far, eps) -> int:
    """The pairs of pieces whose depth ranges overlap (sorted by far depth, each P against the Q after
    it that reach nearer than P's near end): the pairs the depth sort compares at least once."""
    order = np.argsort(-far, kind="stable")
    near, far = near[order], far[order]
    # far is non-increasing: the Q after P overlapping it in depth are those with far > P.near + eps
    reach = np.searchsorted(-far, -(near + eps), side="left")
    return int(np.maximum(reach - np.arange(len(far)) - 1, 0).sum())


def _depth_sort(camera, items, eps=1e-9):
    eye = np.asarray(camera.eye)
    depths = [_view_depth(camera, P) for _, P in items]
    pairs = _pair_tests(np.array([w.min() for w in depths]), np.array([w.max() for w in depths]), eps)
    if pairs > MAX_PAIR_TESTS:
        raise ValueError(f"polygons must overlap in depth in at most {MAX_PAIR_TESTS:,} pairs for the depth sort "
                         f"(each such pair is compared by the extent and plane tests); these {len(items)} polygons "
                         f"overlap in depth in {pairs:,} pairs")
    screens = _screens(camera, [P for _, P in items])
    pieces = sorted((_piece(camera, k, P, S) for (k, P), S in zip(items, screens)), key=lambda p: -p.far)
    # a table of every piece's box and plane, so a piece is compared with many at once
    table = {"box": [], "point": [], "normal": [], "side": []}

    def enter(new):
        base = len(table["side"])
        for i, p in enumerate(new):
            p.id = base + i
        rows = {"box": [p.box for p in new], "point": [p.point for p in new], "normal": [p.normal for p in new],
                "side": [p.eye_side for p in new]}
        for key, value in rows.items():
            table[key] = np.concatenate([np.asarray(table[key], float).reshape((-1,) + np.shape(value)[1:]),
                                         np.asarray(value, float)])

    enter(pieces)
    out = []
    budget = 50 * (len(items) + 1) ** 2
    pairs = 0
    while pieces:
        budget -= 1
        if budget < 0 or len(pieces) + len(out) > MAX_POLYGONS:
            raise ValueError("polygons need more reordering or splitting than the depth sort's budget allows")
        P = pieces[0]
        blocker = None
        # the Q after P that overlap it in depth: the list is sorted by far depth (but for the pieces
        # moved to its front), so they run up to the first Q that lies wholly nearer than P's near end
        candidates = []
        for idx in range(1, len(pieces)):
            if pieces[idx].far <= P.near + eps:
                break
            candidates.append(idx)
        pairs += len(candidates)
        if pairs > MAX_PAIR_TESTS:
            raise ValueError(f"polygons need more than {MAX_PAIR_TESTS:,} pair tests in the depth sort (pieces "
                             "overlapping in depth, compared by the extent and plane tests)")
        if candidates:
            # tests 1-2, for all candidates at once: the screen extents are disjoint
            ids = np.array([pieces[i].id for i in candidates])
            box = table["box"][ids]
            overlap = ~((box[:, 0] >= P.box[1]) | (P.box[0] >= box[:, 1]) | (box[:, 2] >= P.box[3])
                        | (P.box[2] >= box[:, 3]))
            near = [candidates[j] for j in np.flatnonzero(overlap)]
            ids = ids[overlap]
        else:
            near = []
        if near:
            # test 3, for all of them at once: P lies behind Q's plane (every vertex on the far side
            # or on it, seen from the eye); P in Q's plane (coplanar pieces) hides nothing of Q nor
            # Q of P, so test 4 passes for it without being made
            point, normal, side = table["point"][ids], table["normal"][ids], table["side"][ids]
            sv = np.einsum("vqj,qj->vq", P.P[:, None, :] - point[None], normal) * side
            behind = np.all(sv <= eps, axis=0) & ~np.all(sv >= -eps, axis=0)
            coplanar = np.all(np.abs(sv) <= eps, axis=0) & np.any(normal != 0, axis=1) & bool(np.any(P.normal))
            for j in np.flatnonzero(~behind & ~coplanar):
                Q = pieces[near[j]]
                if _side_of(Q.P, (P.point, P.normal), eye, eps) == 1:
                    continue                             # test 4: Q lies in front of P's plane
                blocker = near[j]
                break
        if blocker is None:
            out.append(pieces.pop(0))                    # nothing in front of P needs drawing first
            continue
        Q = pieces[blocker]
        if not Q.moved:
            Q.moved = True                               # try Q first: move it to the front of the list
            pieces.insert(0, pieces.pop(blocker))
            continue
        # Q was moved before: a cycle (or interpenetration). Split P by Q's plane.
        point, normal = Q.point, Q.normal
        front, back = _split(P.P, (P.P - point) @ normal, eps)
        if front is None or back is None:                # P does not cross Q's plane: split Q by P's
            point, normal = P.point, P.normal
            front, back = _split(Q.P, (Q.P - point) @ normal, eps)
            if front is None or back is None:
                out.append(pieces.pop(0))                # nothing to split: accept the order (touching)
                continue
            pieces.pop(blocker)
            parent = Q.polygon
        else:
            pieces.pop(0)
            parent = P.polygon
        new = [_piece(camera, parent, front), _piece(camera, parent, back)]
        enter(new)
        pieces.extend(new)
        pieces.sort(key=lambda p: -p.far)
    return [(p.polygon, p.P) for p in out]


def depth_sort(polygons, camera) -> Rendering:
    """Depth sort with polygon splitting (Goldman §22.6, after Newell, Newell and Sancha): sort the
    polygons by their farthest depth; before painting the farthest, P, compare it with every Q whose
    depth range overlaps P's: Q cannot hide P if their screen extents are disjoint (x, then y), if P
    lies wholly behind Q's plane, or if Q lies wholly in front of P's plane (seen from the eye).  If
    all tests fail, Q moves to the front of the list and is tried first; a Q that must move twice is
    in a cycle (or pierces P), and P is split by Q's plane (or Q by P's) and the pieces re-sorted.
    ``order``: the pieces ``(polygon index, vertices)`` in painting order.  (The book's fifth test,
    whether the projections overlap at all, is left out: it only saves moves.)  Coplanar pieces hide
    nothing of each other and pass without test 4; more than :data:`MAX_PAIR_TESTS` pairs overlapping
    in depth are refused before sorting.

    >>> r = depth_sort(*default_scene()[:1], default_camera(32, 24))
    >>> len(r.order) > 5        # the cycle and the piercing triangles force splits
    True
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items)
    order = _depth_sort(camera, items)
    ids, _ = _paint(camera, order)
    return Rendering(ids, order)


# -- §22.7 BSP trees ---------------------------------------------------------------------------------

@dataclass
class BSPNode:
    """A node of a BSP tree (Goldman §22.7): the plane of its first polygon, the pieces ``(polygon
    index, vertices)`` that lie in that plane, and the subtrees in front of it (where its normal
    points) and behind it."""

    point: np.ndarray
    normal: np.ndarray
    pieces: list
    front: "BSPNode | None" = None
    back: "BSPNode | None" = None

    def count(self) -> int:
        """The number of pieces in the tree."""
        return len(self.pieces) + (self.front.count() if self.front else 0) + (self.back.count() if self.back else 0)


def build_bsp(polygons, eps: float = 1e-9) -> BSPNode | None:
    """Build a BSP tree (Goldman §22.7): the first polygon's plane splits the others
    (:func:`split_polygon`) into those in front and those behind, and each side is built the same
    way.  Polygons in the plane stay at the node.  Returns the root (None for no polygons).

    >>> tree = build_bsp(default_scene()[0])
    >>> tree.count() >= 5
    True
    """
    polys = _polygons(polygons)
    eps = _eps(eps)
    items = [(k, P) for k, P in enumerate(polys)]
    return _build(items, eps, [0])


def _build(items, eps, count):
    if not items:
        return None
    count[0] += len(items)
    if count[0] > 50 * MAX_POLYGONS:
        raise ValueError("polygons split into more pieces than the BSP tree's budget allows")
    k, P = items[0]
    point, normal = _plane(P)
    if not np.any(normal):
        node = BSPNode(point, normal, [(k, P)])
        node.front = _build(items[1:], eps, count)
        return node
    here, front, back = [(k, P)], [], []
    for j, Q in items[1:]:
        s = (Q - point) @ normal
        if np.all(np.abs(s) <= eps):
            here.append((j, Q))
            continue
        f, b = _split(Q, s, eps)
        if f is not None:
            front.append((j, f))
        if b is not None:
            back.append((j, b))
    return BSPNode(point, normal, here, _build(front, eps, count), _build(back, eps, count))


def bsp_back_to_front(tree: BSPNode | None, eye) -> list:
    """The pieces of a BSP tree in back-to-front order for an eye (Goldman §22.7): at each node, if
    the eye is in front of the node's plane, first the back subtree, then the node's pieces, then the
    front subtree; otherwise the other way round.

    >>> tree = build_bsp([[[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]])
    >>> [k for k, _ in bsp_back_to_front(tree, [0, 0, 5])], [k for k, _ in bsp_back_to_front(tree, [0, 0, -5])]
    ([0, 1], [1, 0])
    """
    if tree is not None and not isinstance(tree, BSPNode):
        raise TypeError(f"tree must be a BSPNode (from build_bsp) or None; got {type(tree).__name__}")
    E = as_points(eye, "eye", ndim=1, dim=3)
    out: list = []
    stack = [(tree, False)]
    while stack:
        node, emit = stack.pop()
        if node is None:
            continue
        if emit:
            out.extend(node.pieces)
            continue
        in_front = (E - node.point) @ node.normal >= 0
        first, last = (node.back, node.front) if in_front else (node.front, node.back)
        stack.extend([(last, False), (node, True), (first, False)])
    return out


def bsp_render(polygons, camera) -> Rendering:
    """Hidden surfaces by a BSP tree (Goldman §22.7): build the tree, list its pieces back to front
    from the camera's eye, and paint them in that order.  ``order``: the pieces ``(polygon index,
    vertices)`` in painting order.

    >>> r = bsp_render(*default_scene()[:1], default_camera(32, 24))
    >>> sorted({k for k, _ in r.order})
    [0, 1, 2, 3, 4]
    """
    polys, camera = _polygons(polygons), _camera(camera)
    items = _visible(camera, polys)
    _check_work(camera, items)
    order = bsp_back_to_front(_build(items, 1e-9, [0]), camera.eye)
    ids, _ = _paint(camera, order)
    return Rendering(ids, order)


#: The algorithms by name, with their sections.
ALGORITHMS = {"heedless painter": (heedless_painter, "§22.2"), "z-buffer": (z_buffer, "§22.3"),
              "scan line": (scan_line, "§22.4"), "ray casting": (ray_casting, "§22.5"),
              "depth sort": (depth_sort, "§22.6"), "BSP tree": (bsp_render, "§22.7")}


def frames(algorithm: str, polygons, camera) -> np.ndarray:
    """The image after each drawing step of an algorithm (for the step-through): (steps, h, w) polygon
    indices -- after each polygon or piece painted (painters, depth sort, BSP), each polygon added to
    the z-buffer, each scan line, each row of rays.

    >>> frames("z-buffer", *default_scene()[:1], default_camera(16, 12)).shape
    (5, 12, 16)
    """
    if not isinstance(algorithm, str) or algorithm not in ALGORITHMS:
        raise ValueError(f"algorithm must be one of {sorted(ALGORITHMS)}; got {algorithm!r}")
    polys, camera = _polygons(polygons), _camera(camera)
    hw = camera.width * camera.height
    if algorithm in ("scan line", "ray casting"):
        within_budget(camera.height, "camera", cost=lambda h: h * hw, what="the frames", unit="pixels")
    else:
        within_budget(len(polys), "polygons", cost=lambda n: n * hw * 8, what="the frames", unit="pixels")
    items = _visible(camera, polys)
    if algorithm == "scan line":
        _check_work(camera, items)
        return np.array(_scan_line(camera, items, keep_frames=True)[2])
    if algorithm == "ray casting":
        _check_work(camera, items, ray_cast=True)
        return np.array(_ray_casting(camera, items, keep_frames=True)[1])
    if algorithm == "z-buffer":
        _check_work(camera, items)
        extent = sum(_extent_pixels(camera, S) for S in _screens(camera, [P for _, P in items]))
        within_budget(len(items), "polygons", cost=lambda n: n * extent,
                      what="the z-buffer's frames (each drawn afresh)", unit="pixel tests", limit=MAX_PIXEL_TESTS)
        return np.array([_zbuffer(camera, items, upto=k + 1) for k in range(len(items))])
    order = ALGORITHMS[algorithm][0](polys, camera).order
    part = dict(items)
    pieces = [(k, part[k]) for k in order] if algorithm == "heedless painter" else order
    return np.array(_paint(camera, pieces, keep_frames=True)[1])


def shade(ids, polygons, colours, camera, lights=None, background=(1.0, 1.0, 1.0)) -> np.ndarray:
    """Colour an ``ids`` image (Goldman §22.1, with chapter 21's uniform shading): each polygon's
    pixels get :func:`goldman_lib.lighting.intensity` at its centroid with its Newell normal (turned
    towards the eye), its colour the material's; lights: default one light beside the eye.
    Returns (h, w, 3) in [0, 1].

    >>> p, c = default_scene()
    >>> cam = default_camera(16, 12)
    >>> shade(z_buffer(p, cam).ids, p, c, cam).shape
    (12, 16, 3)
    """
    polys, camera = _polygons(polygons), _camera(camera)
    C = as_points(colours, "colours", dim=3)
    if len(C) != len(polys) or np.any(C < 0) or np.any(C > 1):
        raise ValueError(f"colours must hold one RGB colour in [0, 1] per polygon of polygons ({len(polys)})")
    I = _ids(ids)
    if I.shape != (camera.height, camera.width):
        raise ValueError(f"ids must be an integer image of shape {(camera.height, camera.width)}")
    if I.size and (I.min() < -1 or I.max() >= len(polys)):
        raise ValueError("ids must hold polygon indices (or -1 for none)")
    eye = np.asarray(camera.eye)
    lights = (lighting.Light(tuple(eye + [2.0, 0.0, 3.0])),) if lights is None else lights
    table = np.zeros((len(polys) + 1, 3))
    table[-1] = as_colour(background, "background")
    for k, P in enumerate(polys):
        centroid = P.mean(0, keepdims=True)
        n = shading.unit_newell_normal(P)[None]
        material = lighting.Material(colour=tuple(C[k]), ambient=1.0, diffuse=0.7, specular=0.1, exponent=10)
        table[k] = lighting.to_image(lighting.intensity(centroid, n, eye, lights, material, 0.35, two_sided=True))[0]
    return table[np.where(I >= 0, I, len(polys))]


def _ids(ids) -> np.ndarray:
    I = as_float_array(ids, "ids")
    check_finite(I, "ids")
    if np.any(I != np.round(I)):
        raise ValueError("ids must hold integer polygon indices")
    return I.astype(np.intp)


def edge_pixels(ids) -> np.ndarray:
    """Pixels on an edge of what an ``ids`` image shows (a 4-neighbour shows another polygon): the
    pixels where two correct hidden-surface algorithms may disagree by rounding (Goldman §22.1).

    >>> edge_pixels(np.array([[0, 0, 1], [0, 0, 1]])).astype(int).tolist()
    [[0, 1, 1], [0, 1, 1]]
    """
    I = _ids(ids)
    if I.ndim != 2:
        raise ValueError(f"ids must be a 2D image; got shape {I.shape}")
    e = np.zeros(I.shape, bool)
    e[:, 1:] |= I[:, 1:] != I[:, :-1]
    e[:, :-1] |= I[:, 1:] != I[:, :-1]
    e[1:] |= I[1:] != I[:-1]
    e[:-1] |= I[1:] != I[:-1]
    return e
