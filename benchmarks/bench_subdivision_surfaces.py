"""goldman_lib.subdivision_surfaces: one level of centroid averaging on 10,000-face meshes.

- a 100 x 100 quadrilateral grid (10,000 quads, heights random) and a triangulated 71 x 71 grid
  (9,800 triangles, about 10,000) through ``centroid_averaging(mesh, 1)``: times printed, target
  well under a second;
- the quadrilateral level against a plain-Python reference written here (dictionaries for the
  edges, a loop over faces and corners, the textbook way), timed in the same run, after checking
  that both give the same vertices: the ratio is printed.

>>> from benchmarks.bench_subdivision_surfaces import python_quad_level
>>> from goldman_lib import subdivision_surfaces as ss
>>> import numpy as np
>>> np.allclose(python_quad_level(ss.cube()), ss.centroid_averaging(ss.cube(), 1).vertices)
True
"""

from __future__ import annotations

import numpy as np

from benchmarks.timing import best_times, fmt_time, report
from goldman_lib import subdivision_surfaces as ss


def python_quad_level(mesh: ss.Mesh) -> np.ndarray:
    """One level of quadrilateral centroid averaging with Python loops, in the library's numbering
    (old vertices, edge points in sorted-edge order, face points)."""
    V = mesh.vertices.tolist()
    faces = [list(map(int, f)) for f in (mesh.faces if mesh.face_size else mesh.faces)]
    edge_ids = {}
    for f in faces:
        for i, a in enumerate(f):
            b = f[(i + 1) % len(f)]
            edge_ids.setdefault((min(a, b), max(a, b)), None)
    for k, e in enumerate(sorted(edge_ids)):
        edge_ids[e] = k
    nv, ne = len(V), len(edge_ids)
    pts = list(V)
    for a, b in sorted(edge_ids):
        pts.append([(x + y) / 2 for x, y in zip(V[a], V[b])])
    for f in faces:
        pts.append([sum(V[v][c] for v in f) / len(f) for c in range(len(V[0]))])
    sums = [[0.0] * len(V[0]) for _ in pts]
    counts = [0] * len(pts)
    for fi, f in enumerate(faces):
        k = len(f)
        for i, v in enumerate(f):
            a, b = f[(i + 1) % k], f[i - 1]
            quad = [v, nv + edge_ids[(min(v, a), max(v, a))], nv + ne + fi, nv + edge_ids[(min(v, b), max(v, b))]]
            centroid = [sum(pts[q][c] for q in quad) / 4 for c in range(len(V[0]))]
            for q in quad:
                counts[q] += 1
                for c in range(len(centroid)):
                    sums[q][c] += centroid[c]
    return np.array([[s / n for s in row] for row, n in zip(sums, counts)])


def main() -> dict[str, float]:
    rng = np.random.default_rng(30)
    I, J = np.meshgrid(np.arange(101.0), np.arange(101.0), indexing="ij")
    quads = ss.quad_grid(np.stack([I, J, rng.normal(size=I.shape)], axis=-1))
    I, J = np.meshgrid(np.arange(71.0), np.arange(71.0), indexing="ij")
    tris = ss.triangle_grid(np.stack([I, J, rng.normal(size=I.shape)], axis=-1))
    err = float(np.abs(python_quad_level(quads) - ss.centroid_averaging(quads, 1).vertices).max())
    if err > 1e-12:
        raise AssertionError(f"centroid_averaging disagrees with the Python reference by {err:.3g}")
    t_ref, t_quad, t_tri = best_times(lambda: python_quad_level(quads),
                                      lambda: ss.centroid_averaging(quads, 1),
                                      lambda: ss.centroid_averaging(tris, 1), repeat=3, budget=0.5)
    report(f"centroid_averaging quad, {quads.n_faces} faces, one level", t_quad, t_ref, "Python loops")
    print(f"  the Python-loop reference takes {t_ref / t_quad:.0f}x as long as the vectorised level")
    print(f"centroid_averaging triangle, {tris.n_faces} faces, one level: {fmt_time(t_tri)}")
    for name, t in (("quad", t_quad), ("triangle", t_tri)):
        print(f"target {name} level on ~10,000 faces < 1 s: {'met' if t < 1.0 else 'MISSED'} ({fmt_time(t)})")
    return {"quad": t_quad, "triangle": t_tri, "python_over_numpy": t_ref / t_quad}


if __name__ == "__main__":
    main()
