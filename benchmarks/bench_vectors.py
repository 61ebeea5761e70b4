"""Part II hot paths (Goldman ch 11 and 15) against reference libraries timed in the same run.

- quaternion slerp of 10,000 pairs (target: at most 1 ms; reference: scipy's ``Slerp``, built
  and evaluated per pair, since scipy interpolates one key sequence at a time -- the vectorised
  equivalent is ``Rotation`` products, timed as the second reference);
- the winding number of 100,000 query points about a 50-vertex polygon (target: at least as fast as
  matplotlib's ``Path.contains_points``, the compiled inside test).

Run: ``python -m benchmarks.bench_vectors``.
"""

from __future__ import annotations

import numpy as np

from benchmarks.timing import best_times, report
from goldman_lib import quaternions, vector_geometry

SLERP_PAIRS = 10_000
SLERP_TARGET = 1e-3
QUERY_POINTS, POLYGON_VERTICES = 100_000, 50


def main() -> dict[str, float]:
    from matplotlib.path import Path
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(0)
    q0 = quaternions.normalize(rng.normal(size=(SLERP_PAIRS, 4)))
    q1 = quaternions.normalize(rng.normal(size=(SLERP_PAIRS, 4)))
    t = rng.random(SLERP_PAIRS)
    r0 = Rotation.from_quat(np.roll(q0, -1, axis=1))
    r1 = Rotation.from_quat(np.roll(q1, -1, axis=1))

    def scipy_slerp():
        # the same interpolation with scipy's vectorised rotations: r0 * (r0^-1 r1)^t
        delta = (r0.inv() * r1).as_rotvec()
        return r0 * Rotation.from_rotvec(delta * t[:, None])

    ours, theirs = best_times(lambda: quaternions.slerp(q0, q1, t), scipy_slerp, repeat=7)
    got = Rotation.from_quat(np.roll(quaternions.slerp(q0, q1, t), -1, axis=1))
    assert np.allclose((got.inv() * scipy_slerp()).magnitude(), 0, atol=1e-8), "slerp disagrees with scipy"
    report(f"quaternion slerp, {SLERP_PAIRS:,} pairs", ours, theirs, "scipy Rotation (vectorised)")
    print(f"    target {SLERP_TARGET * 1e3:g} ms: {'met' if ours <= SLERP_TARGET else 'MISSED'} ({ours * 1e3:.2f} ms)")

    ang = np.linspace(0, 2 * np.pi, POLYGON_VERTICES, endpoint=False)
    r = rng.uniform(1, 3, POLYGON_VERTICES)
    poly = np.stack([r * np.cos(ang), r * np.sin(ang)], 1)
    pts = rng.uniform(-3, 3, (QUERY_POINTS, 2))
    path = Path(poly)
    assert np.array_equal(vector_geometry.winding_number(poly, pts) != 0, path.contains_points(pts))
    w_ours, w_mpl = best_times(lambda: vector_geometry.winding_number(poly, pts), lambda: path.contains_points(pts),
                               repeat=7)
    report(f"winding number, {QUERY_POINTS:,} points, {POLYGON_VERTICES}-gon", w_ours, w_mpl,
           "matplotlib contains_points")
    print(f"    target <= 1x matplotlib: {'met' if w_ours <= w_mpl else 'MISSED'} ({w_ours / w_mpl:.2f}x)")
    return {"slerp": ours, "winding": w_ours}


if __name__ == "__main__":
    main()
