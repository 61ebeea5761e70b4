"""The chapter-22 hidden-surface algorithms (Goldman §22.2-22.7) on the chapter's scene, against a
plain per-pixel Python ray caster timed in the same run.

- each algorithm at 160x120 (the view's frames are built at 120x90);
- ray casting written as plain Python loops (for each pixel, for each polygon: the plane hit and the
  edge tests) on a small image, reported beside the vectorised ray caster and the z-buffer as pixels
  per second.

Run: ``python -m benchmarks.bench_hidden_surfaces``.
"""

from __future__ import annotations

import time

import numpy as np

from benchmarks.timing import best_time, report
from goldman_lib import hidden_surfaces as hs

SIZE = (160, 120)
SMALL = (40, 30)


def _python_ray_casting(polygons, camera):
    o, d = camera.rays()
    ids = np.full((camera.height, camera.width), -1)
    planes = []
    for P in polygons:
        n = np.cross(P[1] - P[0], P[2] - P[0])
        planes.append((P.tolist(), n.tolist()))
    for i in range(camera.height):
        for j in range(camera.width):
            D = d[i, j].tolist()
            best = float("inf")
            for k, (P, n) in enumerate(planes):
                nd = sum(n[c] * D[c] for c in range(3))
                if nd == 0:
                    continue
                t = sum(n[c] * (P[0][c] - o[c]) for c in range(3)) / nd
                if not 1e-9 < t < best:
                    continue
                X = [o[c] + t * D[c] for c in range(3)]
                inside = True
                for a in range(len(P)):
                    A, B = P[a], P[(a + 1) % len(P)]
                    e = [B[c] - A[c] for c in range(3)]
                    w = [X[c] - A[c] for c in range(3)]
                    cr = [e[1] * w[2] - e[2] * w[1], e[2] * w[0] - e[0] * w[2], e[0] * w[1] - e[1] * w[0]]
                    if sum(cr[c] * n[c] for c in range(3)) < 0:
                        inside = False
                        break
                if inside:
                    best, ids[i, j] = t, k
    return ids


def main() -> dict[str, float]:
    polygons, _ = hs.default_scene()
    camera = hs.default_camera(*SIZE)
    times = {}
    for name, (f, section) in hs.ALGORITHMS.items():
        times[name] = best_time(lambda: f(polygons, camera), repeat=5)
        print(f"{name:>17} {section}: {len(polygons)} polygons at {SIZE[0]}x{SIZE[1]}  {times[name] * 1e3:7.1f} ms")
    small = hs.default_camera(*SMALL)
    start = time.perf_counter()
    slow = _python_ray_casting(polygons, small)
    baseline = time.perf_counter() - start
    ours = hs.ray_casting(polygons, small).ids
    edges = hs.edge_pixels(ours)
    assert np.array_equal(slow[~edges], ours[~edges]), "the baseline disagrees with hidden_surfaces.ray_casting"
    ours_small = best_time(lambda: hs.ray_casting(polygons, small), repeat=5)
    report(f"ray casting at {SMALL[0]}x{SMALL[1]}", ours_small, baseline, "plain Python per pixel")
    pixels = SIZE[0] * SIZE[1]
    print(f"    pixels per second: z-buffer {pixels / times['z-buffer']:,.0f}, ray casting {pixels / times['ray casting']:,.0f}"
          f" (at {SIZE[0]}x{SIZE[1]}); plain Python ray casting {SMALL[0] * SMALL[1] / baseline:,.0f}")
    return times


if __name__ == "__main__":
    main()
