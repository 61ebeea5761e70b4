"""Meshes: scan conversion of triangle meshes (Goldman §21.2-21.3, §22.2), unchecked.

:func:`rasterise` is the one scan conversion of chapters 21 and 22: ``rasteriser.rasterise_triangles``
and ``rasteriser.gouraud_triangle`` (checked), the shading modes of ``shading.render`` and
``hidden_surfaces``' painter's coverage run it.  Nothing here checks its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rasterise", "BATCH"]

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
