"""Chapter 20 hot paths against plain per-item Python timed in the same run.

- CSG by ray classification: ``Difference(ball, ball).hit`` for a 112 x 84 image of rays (the CSG
  view's default), in rays per second, beside a per-ray Python loop doing the same work (two
  ray-sphere quadratics with ``math``, the interval lists combined by a scalar merge);
- the octree of a ball at the octree view's default depth (4) and at depth 5, beside a recursive
  per-cell Python build that asks the same inside test for each cell's nine samples.

Run: ``python -m benchmarks.bench_solid_modeling``.
"""

from __future__ import annotations

import math

import numpy as np

from benchmarks.timing import best_times, report
from goldman_lib import solid_modeling as sm
from goldman_lib.simple_surfaces import Sphere

WIDTH, HEIGHT = 112, 84
A = Sphere([-0.45, 0.0, 0.0], 0.85)
B = Sphere([0.45, 0.0, 0.0], 0.85)


def _rays():
    X, Z = np.meshgrid(np.linspace(-1.6, 1.6, WIDTH), np.linspace(-1.2, 1.2, HEIGHT))
    d = np.stack([X.ravel(), np.full(X.size, 6.0), Z.ravel()], 1)
    return np.tile([0.0, -6.0, 0.0], (len(d), 1)), d


def _sphere_interval(o, d, c, r):
    oc = [o[i] - c[i] for i in range(3)]
    a = sum(x * x for x in d)
    b = 2 * sum(d[i] * oc[i] for i in range(3))
    cc = sum(x * x for x in oc) - r * r
    disc = b * b - 4 * a * cc
    if disc <= 0:
        return []
    s = math.sqrt(disc)
    return [((-b - s) / (2 * a), (-b + s) / (2 * a))]


def _difference(first, second):
    out = []
    for a0, a1 in first:
        pieces = [(a0, a1)]
        for b0, b1 in second:
            nxt = []
            for p0, p1 in pieces:
                if b1 <= p0 or b0 >= p1:
                    nxt.append((p0, p1))
                    continue
                if p0 < b0:
                    nxt.append((p0, b0))
                if b1 < p1:
                    nxt.append((b1, p1))
            pieces = nxt
        out += pieces
    return sorted(out)


def per_ray_loop(o, d):
    """The first boundary t > EPS of A - B for each ray, one ray at a time in Python."""
    ca, cb = A.center.tolist(), B.center.tolist()
    out = []
    for oi, di in zip(o.tolist(), d.tolist()):
        iv = _difference(_sphere_interval(oi, di, ca, A.radius), _sphere_interval(oi, di, cb, B.radius))
        ends = [t for pair in iv for t in pair if t > sm.EPS]
        out.append(min(ends) if ends else math.inf)
    return np.array(out)


def recursive_octree(inside, center, size, depth):
    """Counts of full/partial/empty leaves by a per-cell recursive Python build (the same rule)."""
    counts = {"full": 0, "partial": 0, "empty": 0}
    offsets = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)] + [[0, 0, 0]], float)

    def visit(c, s, level):
        res = inside(c + offsets * (s / 2))
        if res.all():
            counts["full"] += 1
        elif not res.any():
            counts["empty"] += 1
        elif level == depth:
            counts["partial"] += 1
        else:
            for dz in (-1, 1):
                for dy in (-1, 1):
                    for dx in (-1, 1):
                        visit(c + np.array([dx, dy, dz]) * s / 4, s / 2, level + 1)

    visit(np.asarray(center, float), float(size), 0)
    return counts


def main() -> dict[str, float]:
    o, d = _rays()
    tree = sm.Difference(A, B)
    t_ours = tree.intersect(o, d)
    t_loop = per_ray_loop(o, d)
    assert np.allclose(np.where(np.isfinite(t_ours), t_ours, -1), np.where(np.isfinite(t_loop), t_loop, -1)), \
        "the vectorised CSG disagrees with the per-ray loop"
    ours, loop = best_times(lambda: tree.hit(o, d), lambda: per_ray_loop(o, d), repeat=5)
    n = len(o)
    report(f"CSG A - B ray classification, {n:,} rays", ours, loop, "per-ray Python loop")
    print(f"    {n / ours:,.0f} rays/s vectorised, {n / loop:,.0f} rays/s per-ray loop "
          f"(CSG view target < 100 ms per image: {'met' if ours < 0.1 else 'MISSED'}, {ours * 1e3:.0f} ms)")

    from benchmarks.timing import best_time
    from goldman_lib.views.solid_modeling import csg_view

    view = csg_view()
    values = view.values()
    callback = best_time(lambda: view.update(**values), repeat=5)
    print(f"CSG view callback at its default size (ray_tracing.render, shadows, + one ray's intervals): "
          f"{callback * 1e3:.0f} ms (target < 100 ms: {'met' if callback < 0.1 else 'MISSED'})")

    ball = Sphere([0.0, 0.0, 0.0], 0.8)
    result = {"csg": ours, "csg_view": callback}
    for depth in (4, 5):
        built = sm.Octree.build(ball, size=2.0, depth=depth)
        assert built.counts() == recursive_octree(ball.contains, (0, 0, 0), 2.0, depth)
        t_build, t_rec = best_times(lambda: sm.Octree.build(ball, size=2.0, depth=depth),
                                    lambda: recursive_octree(ball.contains, (0, 0, 0), 2.0, depth), repeat=3)
        report(f"octree of a ball, depth {depth} ({sum(built.counts().values()):,} leaves)", t_build, t_rec,
               "recursive per-cell Python")
        result[f"octree{depth}"] = t_build
    return result


if __name__ == "__main__":
    main()
