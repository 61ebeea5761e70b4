"""Chapter 25 widgets: every callback swept over its controls (corners included) draws finite
geometry, and what it draws is what the library computes (checked against de Casteljau
evaluation and closed forms, not against the view's own arithmetic)."""

import matplotlib
import numpy as np
import pytest

from goldman_lib import bezier
from goldman_lib.views import subdivision as views

matplotlib.use("Agg")

FACTORIES = [views.subdivision_view, views.adaptive_rendering_view, views.intersection_view,
             views.patch_rendering_view]


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def finite(obj):
    if isinstance(obj, dict):
        return all(finite(v) for k, v in obj.items() if k != "status")
    if isinstance(obj, (list, tuple)):
        return all(finite(v) for v in obj)
    return bool(np.all(np.isfinite(np.asarray(obj, dtype=float))))


@pytest.mark.parametrize("factory", FACTORIES, ids=lambda f: f.__name__)
def test_sweep_every_control(factory):
    view = factory()
    for values in view.sweep_values():
        result = view.update(**values)
        assert finite(result), f"non-finite drawing at {values}"
        assert isinstance(result["status"], str) and result["status"]
    assert view.static_png().startswith(b"\x89PNG")


def test_subdivision_view_draws_pieces_of_the_curve():
    view = views.subdivision_view()
    ctrl = views.DEFAULT_CUBIC
    for depth, t in ((0, 0.5), (2, 0.5), (3, 0.3)):
        polys = view.set_values(depth=depth, t=t)["polygons"]
        assert len(polys) == 2 ** depth
        # consecutive pieces share end points, first and last are the curve's ends
        np.testing.assert_allclose(polys[0, 0], ctrl[0])
        np.testing.assert_allclose(polys[-1, -1], ctrl[-1])
        np.testing.assert_allclose(polys[1:, 0], polys[:-1, -1])
        # every joint is a point of the curve: the joints at depth 2, t=1/2 are C(k/4)
        if depth == 2 and t == 0.5:
            np.testing.assert_allclose(polys[:, 0], bezier.de_casteljau(ctrl, [0, 0.25, 0.5, 0.75]), atol=1e-12)
    gaps = [view.update(depth=d, t=0.5)["gap"] for d in range(5)]
    assert all(g1 < g0 for g0, g1 in zip(gaps, gaps[1:]))


def test_adaptive_rendering_view_polyline_lies_on_the_curve():
    view = views.adaptive_rendering_view()
    prev = 0
    for digits in (1, 2, 3, 4):
        r = view.set_values(digits=digits)
        np.testing.assert_allclose(r["polyline"], bezier.de_casteljau(views.WAVY, r["t"]), atol=1e-12)
        assert r["segments"] > prev
        prev = r["segments"]


def test_intersection_view_points_are_on_both_curves():
    view = views.intersection_view()
    r = view.set_values(case="two cubics, three crossings", level=10, shift=0.0)
    a, b = views.INTERSECTION_EXAMPLES["two cubics, three crossings"]
    # this pair is symmetric under the half turn about (1.5, 0.5) and meets at t = 1/2 and two more points
    assert len(r["params"]) == 3
    np.testing.assert_allclose(r["params"][1], [0.5, 0.5], atol=1e-12)
    np.testing.assert_allclose(bezier.de_casteljau(b, r["params"][:, 1]), r["points"], atol=1e-10)
    # the boxes kept at a deep level contain the intersection points
    for p in r["points"]:
        inside = np.all((r["boxes_a"][:, 0] <= p + 1e-9) & (p <= r["boxes_a"][:, 1] + 1e-9), axis=1)
        assert inside.any()


def test_intersection_view_shift_moves_the_second_curve():
    view = views.intersection_view()
    r0 = view.set_values(case="parabola and line", level=0, shift=0.0)
    r1 = view.set_values(case="parabola and line", level=0, shift=1.0)
    # parabola y = 6t(1-t) (max 1.5), line from 0.8 to 1.2: lifted by 1 it clears the apex
    assert len(r0["params"]) == 2 and len(r1["params"]) == 0
    np.testing.assert_allclose(r1["boxes_b"][0], [[0, 1.8], [3, 2.2]])


def test_intersection_view_rejects_an_unknown_case():
    with pytest.raises(ValueError, match="case must be one of"):
        views.intersection_view(case="nope")


def test_patch_rendering_view_covers_the_domain():
    view = views.patch_rendering_view()
    counts = []
    for digits in (0, 1, 2):
        r = view.set_values(digits=digits)
        dom = r["domains"]
        assert ((dom[:, 1] - dom[:, 0]) * (dom[:, 3] - dom[:, 2])).sum() == pytest.approx(1.0)
        np.testing.assert_allclose(r["corners"][:, 0], bezier.patch_de_casteljau(views.DEFAULT_PATCH_25, dom[:, 0], dom[:, 2]),
                                   atol=1e-12)
        counts.append(r["pieces"])
    assert counts[0] < counts[1] < counts[2]
