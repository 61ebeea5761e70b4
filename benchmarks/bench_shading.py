"""The chapter-21 rasteriser (Goldman §21.2-21.4) against a plain per-pixel Python baseline timed in
the same run.

- a 2,000-triangle sphere at 256x256 with Phong shading (target: under 100 ms), and each of the
  other shading modes at the same size;
- the same Phong rendering written as plain Python loops (for each triangle, for each pixel of its
  bounding box: barycentric test, depth test, interpolated normal, the lighting model), on a small
  image, reported as pixels per second beside ours.

Run: ``python -m benchmarks.bench_shading``.
"""

from __future__ import annotations

import math
import time

import numpy as np

from benchmarks.timing import best_time, best_times, report
from goldman_lib import lighting, shading
from goldman_lib.camera import Camera

SIZE = 256
STACKS, SLICES = 26, 40          # 2 * 40 * 25 = 2,000 triangles
TARGET = 0.1
SMALL = 48                       # the per-pixel Python baseline's image size


def _python_phong(V, T, N, cam, light, material):
    """The per-pixel baseline: loops over triangles and pixels, one pixel at a time."""
    S = cam.project(V)
    W, H = cam.width, cam.height
    depth = [[1.0] * W for _ in range(H)]
    image = [[(0.0, 0.0, 0.0)] * W for _ in range(H)]
    L = light.position
    E = cam.eye
    C = material.colour
    for a, b, c in T.tolist():
        (xa, ya, za, wa), (xb, yb, zb, wb), (xc, yc, zc, wc) = S[a], S[b], S[c]
        area = (xb - xa) * (yc - ya) - (xc - xa) * (yb - ya)
        if abs(area) < 1e-12:
            continue
        for i in range(max(0, math.ceil(min(ya, yb, yc) - 0.5)), min(H - 1, math.floor(max(ya, yb, yc) - 0.5)) + 1):
            for j in range(max(0, math.ceil(min(xa, xb, xc) - 0.5)), min(W - 1, math.floor(max(xa, xb, xc) - 0.5)) + 1):
                px, py = j + 0.5, i + 0.5
                l0 = ((xb - px) * (yc - py) - (xc - px) * (yb - py)) / area
                l1 = ((xc - px) * (ya - py) - (xa - px) * (yc - py)) / area
                l2 = 1 - l0 - l1
                if l0 < 0 or l1 < 0 or l2 < 0:
                    continue
                z = l0 * za + l1 * zb + l2 * zc
                if not 0 <= z < depth[i][j]:
                    continue
                depth[i][j] = z
                u = [l0 / wa, l1 / wb, l2 / wc]
                s = sum(u)
                u = [k / s for k in u]
                P = [u[0] * V[a][k] + u[1] * V[b][k] + u[2] * V[c][k] for k in range(3)]
                n = [u[0] * N[a][k] + u[1] * N[b][k] + u[2] * N[c][k] for k in range(3)]
                ln = math.sqrt(sum(x * x for x in n))
                n = [x / ln for x in n]
                tv = [E[k] - P[k] for k in range(3)]
                lv = [L[k] - P[k] for k in range(3)]
                tl, ll = math.sqrt(sum(x * x for x in tv)), math.sqrt(sum(x * x for x in lv))
                v = [x / tl for x in tv]
                lv = [x / ll for x in lv]
                if sum(n[k] * v[k] for k in range(3)) < 0:
                    n = [-x for x in n]
                ln_ = sum(n[k] * lv[k] for k in range(3))
                d = max(ln_, 0.0)
                spec = 0.0
                if ln_ > 0:
                    r = [2 * ln_ * n[k] - lv[k] for k in range(3)]
                    rv = max(sum(r[k] * v[k] for k in range(3)), 0.0)
                    spec = rv ** material.exponent if rv > 0 else 0.0
                image[i][j] = tuple(min(1.0, 0.2 * material.ambient * C[k] + light.intensity *
                                        (material.diffuse * d * C[k] + material.specular * spec)) for k in range(3))
    return np.array(image)


def main() -> dict[str, float]:
    V, T = shading.uv_sphere(STACKS, SLICES)
    assert len(T) == 2000
    cam = Camera(eye=(0, -6, 2), target=(0, 0, 0), fov=30, width=SIZE, height=SIZE)
    light = lighting.Light((4, -6, 6))
    times = {}
    for mode in shading.SHADING_MODES:
        times[mode] = best_time(lambda: shading.render(V, T, cam, light, mode=mode), repeat=5)
        print(f"{mode:>10}: 2,000 triangles at {SIZE}x{SIZE}  {times[mode] * 1e3:6.1f} ms")
    ok = times["phong"] <= TARGET
    print(f"    target {TARGET * 1e3:g} ms for Phong: {'met' if ok else 'MISSED'} ({times['phong'] * 1e3:.1f} ms)")

    small = Camera(eye=(0, -6, 2), target=(0, 0, 0), fov=30, width=SMALL, height=SMALL)
    N = shading.average_vertex_normals(V, T)
    material = lighting.Material()
    ours_img = shading.render(V, T, small, light, material, mode="phong")
    start = time.perf_counter()
    base_img = _python_phong(V, T, N, small, light, material)
    baseline = time.perf_counter() - start
    assert np.abs(ours_img - base_img).max() < 1e-6, "the baseline disagrees with shading.render"
    ours_small, = best_times(lambda: shading.render(V, T, small, light, material, mode="phong"), repeat=5)
    report(f"Phong, 2,000 triangles at {SMALL}x{SMALL}", ours_small, baseline, "plain Python per pixel")
    print(f"    pixels per second: ours {SIZE * SIZE / times['phong']:,.0f} (at {SIZE}x{SIZE}), "
          f"plain Python {SMALL * SMALL / baseline:,.0f}")
    return times


if __name__ == "__main__":
    main()
