"""Chapter 19 hot paths: ray-surface intersection, vectorised over rays, against a per-ray
``numpy.roots`` loop timed in the same run.

For each kind of simple surface, 20,000 rays from a camera-like origin towards the surface's region
are intersected with ``surface.intersect`` (the library: every ray at once -- quadratics in closed
form, the torus by Ferrari's closed form after the bounding test of §19.6.1, surfaces of revolution
by batched companion-matrix eigenvalues).  The baseline builds each ray's polynomial with
``numpy.polynomial`` (the implicit equation composed with the ray) and calls ``numpy.roots`` on it,
one ray at a time, on the first 1,000 rays: roots only, no caps, bounds or sorting, so the
baseline does less work than the library.  Printed: rays per second of each, and the ratio.

Run: ``python -m benchmarks.bench_simple_surfaces``.
"""

from __future__ import annotations

import numpy as np
from numpy.polynomial import Polynomial as P

from benchmarks.timing import best_time
from goldman_lib import simple_surfaces as S

RAYS = 20_000
BASELINE_RAYS = 1_000


def _cases():
    t40 = np.tan(np.radians(30)) ** 2
    return [
        ("sphere", S.Sphere([0, 0, 0.8], 0.8), lambda x, y, z: x * x + y * y + (z - 0.8) ** 2 - 0.64),
        ("cylinder (capped)", S.Cylinder([0, 0, 0], [0, 0, 1], 0.8, height=1.6), lambda x, y, z: x * x + y * y - 0.64),
        ("cone (capped)", S.Cone([0, 0, 1.6], [0, 0, -1], 30, height=1.6),
         lambda x, y, z: x * x + y * y - t40 * (z - 1.6) ** 2),
        ("ellipsoid", S.Ellipsoid([0, 0, 0.8], [1.2, 0.8, 0.8]),
         lambda x, y, z: (x / 1.2) ** 2 + (y / 0.8) ** 2 + ((z - 0.8) / 0.8) ** 2 - 1),
        ("quadric (hyperboloid)", S.Quadric([1, 1, -0.5, 0, 0, 0, 0, 0, 1, -0.82]),
         lambda x, y, z: x * x + y * y - 0.5 * z * z + z - 0.82),
        ("torus", S.Torus([0, 0, 0.35], [0, 0, 1], 1.0, 0.35),
         lambda x, y, z: (x * x + y * y + (z - 0.35) ** 2 + 1 - 0.1225) ** 2 - 4 * (x * x + y * y)),
        ("surface of revolution (quadratic profile)",
         S.SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [0.8, -0.6, 0.3125], 1.6),
         lambda x, y, z: x * x + y * y - (0.8 - 0.6 * z + 0.3125 * z * z) ** 2),
    ]


def _baseline(f, o, d):
    out = []
    for k in range(len(o)):
        x, y, z = (P([o[k, i], d[k, i]]) for i in range(3))
        c = f(x, y, z).coef
        r = np.roots(c[::-1])
        out.append(np.sort(r.real[np.abs(r.imag) < 1e-9]))
    return out


def main() -> dict[str, float]:
    rng = np.random.default_rng(19)
    eye = np.array([4.2, -5.4, 3.0])
    target = rng.uniform([-1.5, -1.5, -0.2], [1.5, 1.5, 2.0], size=(RAYS, 3))
    o = np.broadcast_to(eye, (RAYS, 3)).copy()
    d = target - eye
    results = {}
    print(f"{RAYS:,} rays per surface; baseline: a per-ray numpy.roots loop on {BASELINE_RAYS:,} of them")
    for name, surface, f in _cases():
        ours = best_time(lambda: surface.intersect(o, d), repeat=5)
        base = best_time(lambda: _baseline(f, o[:BASELINE_RAYS], d[:BASELINE_RAYS]), repeat=3) / BASELINE_RAYS * RAYS
        extra = f"  (bound: {surface.quartics_solved:,} of {RAYS:,} rays solved the quartic)" \
            if isinstance(surface, S.Torus) else ""
        print(f"  {name:42s} ours {RAYS / ours / 1e6:6.2f} M rays/s   numpy.roots loop {RAYS / base / 1e3:6.1f} k rays/s"
              f"   speed-up {base / ours:6.0f}x{extra}")
        results[name] = ours
    return results


if __name__ == "__main__":
    main()
