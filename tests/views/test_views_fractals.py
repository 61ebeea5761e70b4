"""Chapter 2-3 views: what is drawn equals the library's fractal at those control values, the
status reports the right numbers, and every control position draws without error."""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from goldman_lib import fractals  # noqa: E402
from goldman_lib.views import fractals as fv  # noqa: E402


def _same(a, b):
    assert len(a) == len(b)
    for p, q in zip(a, b):
        np.testing.assert_allclose(p, q, atol=1e-12)


@pytest.mark.parametrize("name", list(fractals.PROGRAMS))
def test_fractal_explorer_draws_the_library_fractal(name):
    view = fv.fractal_explorer()
    for level in (0, 2, 8):
        out = view.update(name=name, level=level)  # the plain callback (no PNG refresh)
        prog = fractals.PROGRAMS[name]()
        shown = out["level"]
        assert shown == min(level, prog.max_level(fv.MAX_DRAWN))
        direction = (0, 1) if name in fv.GROWS_UP else (1, 0)
        _same(out["polylines"], prog.polylines(shown, direction=direction))
        # the single Line2D holds the strokes, NaN-separated
        x, _ = view.figure.axes[0].lines[0].get_data()
        assert np.isnan(np.asarray(x, float)).sum() == len(out["polylines"]) - 1
        if shown < level:
            assert f"showing level {shown}" in out["status"]


def test_fractal_explorer_status_numbers():
    view = fv.fractal_explorer()
    out = view.set_values(name="Koch curve", level=5)
    assert out["status"].startswith("Koch curve, level 5: 1,024 segments, 1 stroke, ink length 4.21 = (4/3)^5")
    assert "dimension 1.262" in out["status"]           # log 4 / log 3 = 1.2619
    out = view.set_values(name="Sierpinski gasket", level=4)
    assert "81 strokes" in out["status"] and "dimension 1.585" in out["status"]  # log 3 / log 2
    out = view.set_values(name="Koch curve", level=7)
    assert out["level"] == 7 and len(out["polylines"][0]) == 4**7 + 1


def test_fractal_explorer_rejects_unknown_names():
    with pytest.raises(ValueError, match="name must be one of"):
        fv.fractal_explorer("Mandelbrot")


@pytest.mark.parametrize("angle, k", [(144, 5), (144, 4), (90, 4), (100, 18), (100, 9), (0, 3), (360, 2)])
def test_looping_lemma_explorer_closes_iff_k_angle_is_a_multiple_of_360(angle, k):
    view = fv.looping_lemma_explorer()
    out = view.set_values(angle=float(angle), repetitions=k, bend=0.0)
    expected = (k * angle) % 360 == 0 and angle % 360 != 0
    assert out["closes"] == expected
    (path,) = out["polylines"]
    assert len(path) == k + 1
    assert ("is back where it started" in out["status"]) == expected
    if angle % 360:
        assert out["period"] == 360 // math.gcd(angle, 360)
        # every pass starts on one circle about the centre
        r = np.hypot(*(out["starts"] - out["center"][0]).T)
        np.testing.assert_allclose(r, r[0], rtol=1e-9)


def test_looping_lemma_explorer_with_a_bend_keeps_the_period_of_the_total_turn():
    view = fv.looping_lemma_explorer()
    out = view.set_values(angle=135.0, repetitions=8, bend=40.0)   # T = 135 = 3/8 of 360
    assert out["closes"] and out["period"] == 8
    assert len(out["polylines"][0]) == 2 * 8 + 1


def test_base_case_explorer_draws_that_base_and_the_distance():
    view = fv.base_case_explorer()
    for label, (fractal, base) in fv.BASE_OPTIONS.items():
        prog = fractals.PROGRAMS[fractal]().with_base(fractals.BASE_CASES[fractal][base])
        out = view.update(base=label, level=2)
        _same(out["polylines"], prog.polylines(2))
        _same(out["base_polylines"], prog.polylines(0))
        ref = fractals.base_case_distances(fractals.PROGRAMS[fractal](), [prog.base], [2], per_segment=1)[0, 0]
        assert out["distance"] == pytest.approx(ref, abs=1e-12)


def test_base_case_explorer_distance_shrinks_by_the_scale():
    view = fv.base_case_explorer()
    d = [view.update(base="Koch: tent", level=n)["distance"] for n in range(6)]
    for a, b in zip(d, d[1:]):
        assert b <= a / 3 + 1e-7
    assert d[5] < 0.005
    d = [view.update(base="gasket: stick", level=n)["distance"] for n in range(6)]
    for a, b in zip(d, d[1:]):
        assert b <= a / 2 + 1e-7


def test_plot_fractal_and_static_images():
    ax = fv.plot_fractal("Koch snowflake", 2)
    assert ax.lines[0].get_xydata().shape == (49, 2)
    with pytest.raises(ValueError, match="name must be one of"):
        fv.plot_fractal("nothing")
    for view in (fv.fractal_explorer(), fv.looping_lemma_explorer(), fv.base_case_explorer()):
        assert view.static_png().startswith(b"\x89PNG")
