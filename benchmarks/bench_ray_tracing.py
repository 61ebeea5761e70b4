"""Chapter 17's recursive ray tracer: the default scene at the view's default size (160 x 120) with
recursion depth 3 (target: under 100 ms), in rays per second beside a plain per-pixel Python loop
timed in the same run; then the full-size picture (640 x 480, depth 3; target under 3 s, printed as
a ratio against the 160 x 120 callback) and what the render button draws (2 x 2 anti-aliased, depth 5).

The baseline traces the same scene ray by ray: a Python loop over the pixels of a small image
(24 x 18) calling :func:`goldman_lib.ray_tracing.trace` for one primary ray at a time -- the book's
recursion one ray at a time, with no vectorisation across pixels.  Its image is checked to equal
the vectorised one, pixel for pixel.  Rays counted: primary, reflected and refracted rays plus
shadow rays.  Both wall time (best of several rounds) and process CPU time are printed: on a shared
machine the CPU time is the steadier figure.

Run: ``python -m benchmarks.bench_ray_tracing``.
"""

from __future__ import annotations

import time

import numpy as np

from benchmarks.timing import best_time, fmt_time
from goldman_lib import lighting
from goldman_lib import ray_tracing as rt

WIDTH, HEIGHT, DEPTH = 160, 120, 3
SMALL = (24, 18)
TARGET = 0.100
FULL, FULL_TARGET = (640, 480), 3.0


def _cpu_time(fn, repeat: int = 7) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.process_time()
        fn()
        best = min(best, time.process_time() - start)
    return best


def main() -> dict[str, float]:
    scene, camera = rt.default_scene(), rt.default_camera()
    counts: dict = {}
    rt.render(scene, camera, WIDTH, HEIGHT, DEPTH, counts=counts)
    rays = counts["rays"] + counts["shadow"]
    wall = best_time(lambda: rt.render(scene, camera, WIDTH, HEIGHT, DEPTH), repeat=7, number=1,
                     clock=time.perf_counter)
    cpu = _cpu_time(lambda: rt.render(scene, camera, WIDTH, HEIGHT, DEPTH))
    print(f"ray tracing, default scene, {WIDTH}x{HEIGHT}, depth {DEPTH}: {counts['rays']:,} rays + "
          f"{counts['shadow']:,} shadow rays")
    print(f"    vectorised: {fmt_time(wall)} wall (best of 7), {fmt_time(cpu)} CPU;  "
          f"{rays / wall / 1e6:.2f} M rays/s")
    print(f"    target {TARGET * 1e3:g} ms: {'met' if wall <= TARGET else 'MISSED'} ({wall * 1e3:.1f} ms wall, "
          f"{cpu * 1e3:.1f} ms CPU)")

    w, h = SMALL
    eye, d = rt.default_camera(width=w, height=h).rays()
    d = d.reshape(-1, 3)
    o = np.broadcast_to(eye, d.shape)

    def per_pixel():
        out = np.zeros((h * w, 3))
        n = {"rays": 0, "shadow": 0}
        for i in range(h * w):
            c: dict = {}
            out[i] = rt.trace(scene, o[i], d[i], DEPTH, counts=c)[0]
            n["rays"] += c["rays"]
            n["shadow"] += c["shadow"]
        return lighting.to_image(out.reshape(h, w, 3)), n

    image, n = per_pixel()
    assert np.allclose(image, rt.render(scene, camera, w, h, DEPTH), atol=1e-12), "per-pixel and vectorised differ"
    start = time.perf_counter()
    per_pixel()
    slow = time.perf_counter() - start
    slow_rays = n["rays"] + n["shadow"]
    print(f"    plain per-pixel Python loop ({w}x{h}, same tracer one ray at a time): {fmt_time(slow)};  "
          f"{slow_rays / slow / 1e3:.1f} k rays/s")
    ratio = (rays / wall) / (slow_rays / slow)
    print(f"    vectorised / per-pixel rays per second = {ratio:.0f}x")

    # The full-size picture (issue 18 §4): 640 x 480 at depth 3 under FULL_TARGET seconds, as a
    # ratio against the 160 x 120 callback timed above; and what the render button draws.
    big_w, big_h = FULL
    full = best_time(lambda: rt.render(scene, camera, big_w, big_h, DEPTH), repeat=3, number=1)
    button = best_time(lambda: rt.render(scene, camera, big_w, big_h, 5, samples=2, progress=lambda k, n: None),
                       repeat=2, number=1)
    print(f"    full size {big_w}x{big_h}, depth {DEPTH}: {fmt_time(full)} = {full / wall:.1f}x the "
          f"{WIDTH}x{HEIGHT} callback (16x the pixels); target {FULL_TARGET:g} s: "
          f"{'met' if full <= FULL_TARGET else 'MISSED'}")
    print(f"    the render button ({big_w}x{big_h}, 2x2 anti-aliased, depth 5, with progress): {fmt_time(button)} "
          f"= {button / wall:.1f}x the callback")
    return {"render": wall, "render_cpu": cpu, "rays_per_second": rays / wall, "ratio": ratio,
            "full": full, "full_ratio": full / wall, "button": button}


if __name__ == "__main__":
    main()
