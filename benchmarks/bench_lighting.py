"""The lighting model (Goldman ch 16) over a million points against a plain per-point Python loop
timed in the same run.

``lighting.intensity`` of 1,000,000 sphere points (two lights, ambient + diffuse + specular) against
the same formula written point by point in plain Python (``math`` only) on a 2,000-point subset; the
ratio compares time per point.  Both give the same colours on the subset (checked).

Run: ``python -m benchmarks.bench_lighting``.
"""

from __future__ import annotations

import math

import numpy as np

from benchmarks.timing import best_time, fmt_time
from goldman_lib import lighting
from goldman_lib.lighting import Light, Material

POINTS = 1_000_000
SUBSET = 2_000


def _plain(points, normals, eye, lights, m, ambient_light):
    """I_a k_a C + sum_j I_j (k_d C (L.N) + k_s S (R.V)^n), one point at a time, in plain Python."""
    out = []
    C, S = m.colour, m.specular_colour
    for (px, py, pz), (nx, ny, nz) in zip(points, normals):
        ln = math.sqrt(nx * nx + ny * ny + nz * nz)
        nx, ny, nz = nx / ln, ny / ln, nz / ln
        vx, vy, vz = eye[0] - px, eye[1] - py, eye[2] - pz
        lv = math.sqrt(vx * vx + vy * vy + vz * vz)
        vx, vy, vz = vx / lv, vy / lv, vz / lv
        rgb = [ambient_light * m.ambient * c for c in C]
        for light in lights:
            lx, ly, lz = (light.position[0] - px, light.position[1] - py, light.position[2] - pz)
            ll = math.sqrt(lx * lx + ly * ly + lz * lz)
            lx, ly, lz = lx / ll, ly / ll, lz / ll
            cos = lx * nx + ly * ny + lz * nz
            if cos <= 0:
                continue
            rx, ry, rz = 2 * cos * nx - lx, 2 * cos * ny - ly, 2 * cos * nz - lz
            rv = rx * vx + ry * vy + rz * vz
            spec = rv ** m.exponent if rv > 0 else 0.0
            I = light.rgb
            for k in range(3):
                rgb[k] += I[k] * (m.diffuse * C[k] * cos + m.specular * S[k] * spec)
        out.append(rgb)
    return np.array(out)


def main() -> dict[str, float]:
    rng = np.random.default_rng(16)
    normals = lighting.unit_rows(rng.normal(size=(POINTS, 3)))
    points = normals.copy()                      # points of the unit sphere; the normal at P is P
    eye = np.array([0.0, 0.0, 6.0])
    lights = [Light((3.0, 2.0, 5.0)), Light((-5.0, -1.0, 2.0), colour=(1.0, 0.85, 0.6), intensity=0.6)]
    material = Material(colour=(0.24, 0.49, 0.85), ambient=0.2, diffuse=0.6, specular=0.6, exponent=20)
    sub_p, sub_n = points[:SUBSET].tolist(), normals[:SUBSET].tolist()
    ours = best_time(lambda: lighting.intensity(points, normals, eye, lights, material, 1.0), repeat=3)
    plain = best_time(lambda: _plain(sub_p, sub_n, eye, lights, material, 1.0), repeat=3)
    same = np.allclose(_plain(sub_p, sub_n, eye, lights, material, 1.0),
                       lighting.intensity(points[:SUBSET], normals[:SUBSET], eye, lights, material, 1.0), atol=1e-12)
    assert same, "the plain loop and lighting.intensity disagree"
    per_ours, per_plain = ours / POINTS, plain / SUBSET
    print(f"lighting.intensity, {POINTS:,} points, 2 lights: {fmt_time(ours)} "
          f"({POINTS / ours / 1e6:.1f} million points/s)")
    print(f"plain per-point Python loop, {SUBSET:,} points: {fmt_time(plain)} ({SUBSET / plain / 1e6:.3f} million points/s)")
    print(f"    per point: numpy is {per_plain / per_ours:.0f}x faster than the plain loop (same colours, to 1e-12)")
    return {"intensity_1e6": ours, "plain_per_point": per_plain}


if __name__ == "__main__":
    main()
