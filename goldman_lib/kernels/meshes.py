"""Meshes: polyhedra as vertex and face tables, their edges and fans, and scan conversion of
triangle meshes (Goldman §20.3, §21.2-21.3, §22.2, §30.4), unchecked.

The polygon meshes of the library are vertex tables ``(V, d)`` and faces as vertex loops, stored
flat as ``corners`` (every face's vertex indices, face after face) and ``sizes`` (vertices per
face).  Two classes hold them, each for what the other cannot do:
``subdivision_surfaces.Mesh`` (a validated manifold mesh in any dimension with cached adjacency,
what subdivision rewrites, §30) and ``solid_modeling.BRep`` (a boundary representation whose
faces may have holes, rings, and whose faults are described rather than refused, with counts,
shells, volume and the Euler-Poincare formula, §20.3); ``BRep.from_mesh`` and ``Mesh.from_brep``
convert.  What they share lives here, once:

- :data:`CUBE_VERTICES`, :data:`CUBE_FACES`, :data:`TETRAHEDRON_VERTICES`, :data:`TETRAHEDRON_FACES`:
  the cube ``[-1, 1]^3`` and the regular tetrahedron at alternate corners of it, faces counterclockwise
  seen from outside (read-only): ``subdivision_surfaces.cube``, ``tetrahedron`` and
  ``solid_modeling.cube``, ``tetrahedron``, scaled;
- :func:`flatten`: loops to ``(corners, sizes)``; :func:`edge_table`: the distinct edges and the
  edge of each corner; :func:`same_direction_edges`: the orientation test (edges two loops run the
  same way); :func:`fan_triangles`: every face fanned from its first vertex:
  ``Mesh.edges``/``triangulate``/its orientation check and ``BRep.edges``/``triangles``/``problems``.

:func:`rasterise` is the one scan conversion of chapters 21 and 22: ``rasteriser.rasterise_triangles``
and ``rasteriser.gouraud_triangle`` (checked), the shading modes of ``shading.render`` and
``hidden_surfaces``' painter's coverage run it.  Nothing here checks its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rasterise", "BATCH", "CUBE_VERTICES", "CUBE_FACES", "TETRAHEDRON_VERTICES", "TETRAHEDRON_FACES",
           "flatten", "edge_table", "same_direction_edges", "fan_triangles"]


def _frozen(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


#: The cube ``[-1, 1]^3`` (Goldman §20.3, §30.4): vertex ``k`` has coordinates ``2 b - 1`` for the bits
#: ``b = (k & 1, k >> 1 & 1, k >> 2 & 1)`` (x changes fastest); valence 3 everywhere.
CUBE_VERTICES = _frozen(np.array([[(k >> 0) & 1, (k >> 1) & 1, (k >> 2) & 1] for k in range(8)], dtype=float) * 2 - 1)
#: The cube's six quadrilaterals, counterclockwise seen from outside: z = -1, z = 1, y = -1, y = 1, x = -1, x = 1.
CUBE_FACES = _frozen(np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]],
                              dtype=np.int64))
#: The regular tetrahedron with vertices at alternate corners of the cube ``[-1, 1]^3``.
TETRAHEDRON_VERTICES = _frozen(np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float))
#: Its four triangles, counterclockwise seen from outside.
TETRAHEDRON_FACES = _frozen(np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], dtype=np.int64))


def flatten(loops) -> tuple[np.ndarray, np.ndarray]:
    """Vertex loops (a list of index sequences, or an ``(F, k)`` array) as ``(corners, sizes)``: every
    loop's indices one after another ``(sum k,)`` and the length of each ``(F,)``, both int64.

    >>> [a.tolist() for a in flatten([[0, 1, 2], [0, 2, 3, 4]])]
    [[0, 1, 2, 0, 2, 3, 4], [3, 4]]
    """
    if isinstance(loops, np.ndarray) and loops.ndim == 2:
        return loops.astype(np.int64).ravel(), np.full(len(loops), loops.shape[1], dtype=np.int64)
    sizes = np.array([len(f) for f in loops], dtype=np.int64)
    corners = np.fromiter((v for f in loops for v in f), dtype=np.int64, count=int(sizes.sum()))
    return corners, sizes


def _next_corner(sizes: np.ndarray) -> np.ndarray:
    offsets = np.cumsum(sizes) - sizes
    nxt = np.arange(int(sizes.sum())) + 1
    nxt[offsets + sizes - 1] = offsets
    return nxt


def edge_table(corners: np.ndarray, sizes: np.ndarray, n_vertices: int, nxt=None) -> tuple[np.ndarray, np.ndarray]:
    """The distinct edges of faces given as ``(corners, sizes)`` (Goldman §20.3): ``(E, 2)`` vertex
    pairs ``(i < j)`` sorted, and for each corner the index of the edge from it to the next corner of
    its face ``(sum k,)``.  nxt: that next corner of each corner, if the caller has it.

    >>> e, of = edge_table(*flatten([[0, 1, 2], [0, 2, 3]]), 4)
    >>> e.tolist(), of.tolist()
    ([[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]], [0, 3, 1, 1, 4, 2])
    """
    a = corners
    b = corners[_next_corner(sizes) if nxt is None else nxt]
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    keys = lo.astype(np.int64) * n_vertices + hi
    uniq, inverse = np.unique(keys, return_inverse=True)
    return np.stack(np.divmod(uniq, n_vertices), axis=1), inverse.reshape(-1)


def same_direction_edges(corners: np.ndarray, sizes: np.ndarray, n_vertices: int, nxt=None) -> np.ndarray:
    """The directed edges ``a -> b`` that more than one loop corner runs along ``(R, 2)``, sorted: where
    loops of a consistently oriented surface meet, they run a shared edge in opposite directions,
    so each row is a place where the orientation breaks (Goldman §20.3).  nxt as for :func:`edge_table`.

    >>> same_direction_edges(*flatten([[0, 1, 2], [0, 1, 3], [1, 0, 4]]), 5).tolist()   # the first two run 0 -> 1
    [[0, 1]]
    """
    directed = corners.astype(np.int64) * n_vertices + corners[_next_corner(sizes) if nxt is None else nxt]
    uniq, count = np.unique(directed, return_counts=True)
    return np.stack(np.divmod(uniq[count > 1], n_vertices), axis=1)


def fan_triangles(corners: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """Every face of ``(corners, sizes)`` cut into triangles fanned from its first vertex, face by face,
    same orientation: ``(sum (k - 2), 3)`` (right for convex faces; Goldman §21.1, §30.4).

    >>> fan_triangles(*flatten([[0, 1, 2, 3], [4, 5, 6]])).tolist()
    [[0, 1, 2], [0, 2, 3], [4, 5, 6]]
    """
    offsets = np.cumsum(sizes) - sizes
    count = sizes - 2
    face = np.repeat(np.arange(len(sizes)), count)
    local = np.arange(int(count.sum())) - np.repeat(np.cumsum(count) - count, count) + 1
    first = offsets[face]
    return np.stack([corners[first], corners[first + local], corners[first + local + 1]], axis=1)

#: Pixel candidates examined per batch of triangles (a memory bound, not a work budget).
BATCH = 1 << 20


def rasterise(S: np.ndarray, T: np.ndarray, width: int, height: int):
    """Scan-convert triangles T ``(m, 3)`` (indices into the screen points S ``(n, 3)``: pixel x, y and
    depth z in [0, 1)) on a ``width`` x ``height`` image (Goldman §21.2, §22.2): per pixel the nearest
    triangle whose closed screen triangle covers the pixel centre.  Returns ``(triangle, depth,
    weights)``: ``(h, w)`` indices (-1 for none), ``(h, w)`` depths (1.0 for none) and ``(h, w, 3)``
    screen-space barycentric coordinates (zeros for none).

    >>> tri, depth, _ = rasterise(np.array([[0.0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5]]), np.array([[0, 1, 2]]), 4, 4)
    >>> tri.tolist()
    [[0, 0, 0, 0], [0, 0, 0, -1], [0, 0, -1, -1], [0, -1, -1, -1]]
    """
    tri_buf = np.full(width * height, -1, dtype=np.intp)
    depth = np.ones(width * height)
    weights = np.zeros((width * height, 3))
    if len(T) == 0:
        return tri_buf.reshape(height, width), depth.reshape(height, width), weights.reshape(height, width, 3)
    X, Y, Z = S[T, 0], S[T, 1], S[T, 2]                   # (m, 3) each
    area2 = (X[:, 1] - X[:, 0]) * (Y[:, 2] - Y[:, 0]) - (X[:, 2] - X[:, 0]) * (Y[:, 1] - Y[:, 0])
    scale = 1.0 + np.abs(X).max(1) + np.abs(Y).max(1)
    x0 = np.clip(np.ceil(X.min(1) - 0.5), 0, width).astype(np.intp)
    x1 = np.clip(np.floor(X.max(1) - 0.5), -1, width - 1).astype(np.intp)
    y0 = np.clip(np.ceil(Y.min(1) - 0.5), 0, height).astype(np.intp)
    y1 = np.clip(np.floor(Y.max(1) - 0.5), -1, height - 1).astype(np.intp)
    bw, bh = x1 - x0 + 1, y1 - y0 + 1
    ok = (np.abs(area2) > 1e-12 * scale * scale) & (bw > 0) & (bh > 0) & (Z.max(1) >= 0) & (Z.min(1) < 1)
    ids = np.flatnonzero(ok)
    # barycentric coordinate i of the point (x, y) is a_i x + b_i y + c_i: the edge function of the
    # edge opposite vertex i over twice the signed area (so both orientations are "inside")
    j, k_ = [1, 2, 0], [2, 0, 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = np.where(ok, 1.0 / np.where(ok, area2, 1.0), 0.0)[:, None]
    coef = np.stack([(Y[:, j] - Y[:, k_]) * inv, (X[:, k_] - X[:, j]) * inv,
                     (X[:, j] * Y[:, k_] - X[:, k_] * Y[:, j]) * inv, Z], axis=1)   # (m, 4, 3): a, b, c, z
    counts = (bw * bh)[ids]
    ends = np.cumsum(counts)
    start = 0
    while start < len(ids):
        stop = max(start + 1, int(np.searchsorted(ends, (ends[start - 1] if start else 0) + BATCH, "right")))
        tris, c = ids[start:stop], counts[start:stop]
        start = stop
        k = np.repeat(tris, c)
        local = np.arange(int(c.sum())) - np.repeat(np.cumsum(c) - c, c)
        bwk = bw[k]
        py, px = np.divmod(local, bwk)
        px += x0[k]
        py += y0[k]
        cx, cy = px + 0.5, py + 0.5
        E = coef[k]                                       # (n, 4, 3): a_i, b_i, c_i, z_i per vertex
        lam = E[:, 0] * cx[:, None] + E[:, 1] * cy[:, None] + E[:, 2]
        z = np.einsum("ij,ij->i", lam, E[:, 3])
        keep = np.flatnonzero((lam.min(1) >= 0) & (z >= 0) & (z < 1))
        k, lam, z = k[keep], lam[keep], z[keep]
        pix = py[keep] * width + px[keep]
        # by pixel, then depth (z in [0, 1) packed below the pixel index: one float sort, exact to
        # ~1e-11 in z for images up to 2**20 pixels; a stable sort, so ties keep the earlier triangle)
        sel = np.argsort(pix + z * (1 - 2 ** -40), kind="stable") \
            if width * height <= 1 << 20 else np.lexsort((z, pix))
        first = np.ones(len(sel), bool)
        ps = pix[sel]
        first[1:] = ps[1:] != ps[:-1]
        sel = sel[first]
        p = pix[sel]
        better = (z[sel] < depth[p]) | ((z[sel] == depth[p]) & (tri_buf[p] < 0))
        sel, p = sel[better], p[better]
        depth[p] = z[sel]
        tri_buf[p] = k[sel]
        weights[p] = lam[sel]
    return tri_buf.reshape(height, width), depth.reshape(height, width), weights.reshape(height, width, 3)
