"""The full-size render (issue 18 §4): ray_tracing.render's samples and progress, the shared
ProgressBar and RenderControl."""

import numpy as np
import pytest

from goldman_lib import ray_tracing as rt
from goldman_lib.widgets.interactive import InteractiveView, float_slider
from goldman_lib.widgets.render_control import ProgressBar, RenderControl, image_png


@pytest.fixture(scope="module")
def scene_camera():
    return rt.default_scene(), rt.default_camera()


def test_bands_give_the_same_image_and_counts(scene_camera):
    scene, camera = scene_camera
    calls, whole, banded = [], {}, {}
    a = rt.render(scene, camera, 40, 30, 3, counts=whole)
    b = rt.render(scene, camera, 40, 30, 3, counts=banded, progress=lambda k, n: calls.append((k, n)))
    assert np.array_equal(a, b)
    assert whole == banded and whole["rays"] > 40 * 30
    assert [n for _, n in calls] == [30] * len(calls)
    assert [k for k, _ in calls] == sorted(k for k, _ in calls) and calls[-1] == (30, 30)
    assert 2 <= len(calls) <= rt.BANDS


def test_supersampling_is_the_mean_of_the_sub_pixel_picture(scene_camera):
    scene, camera = scene_camera
    fine = rt.render(scene, camera, 48, 36, 2)                       # the sub-pixel grid, one ray each
    aa = rt.render(scene, camera, 24, 18, 2, samples=2)
    expected = fine.reshape(18, 2, 24, 2, 3).mean(axis=(1, 3))
    assert np.allclose(aa, expected, atol=1e-15)
    one = rt.render(scene, camera, 24, 18, 2)
    # the edges of the spheres are where anti-aliasing changes a pixel; flat floor pixels barely move
    assert 0.02 < np.mean(np.abs(aa - one).max(axis=2) > 0.05) < 0.6


def test_render_refuses_bad_samples_and_progress(scene_camera):
    scene, camera = scene_camera
    for bad in (0, rt.MAX_SAMPLES + 1):
        with pytest.raises(ValueError, match="samples"):
            rt.render(scene, camera, 8, 6, 1, samples=bad)
    with pytest.raises(TypeError, match="samples"):
        rt.render(scene, camera, 8, 6, 1, samples=1.5)
    with pytest.raises(TypeError, match="progress"):
        rt.render(scene, camera, 8, 6, 1, progress=3)
    with pytest.raises(ValueError, match="max_rays"):
        rt.render(scene, camera, 40, 30, 1, samples=4, max_rays=10_000)


def test_full_size_render_traces_few_rays_per_pixel(scene_camera):
    scene, camera = scene_camera
    counts = {}
    img = rt.render(scene, camera, 320, 240, 5, samples=2, counts=counts, progress=lambda k, n: None)
    assert img.shape == (240, 320, 3) and 0.0 <= img.min() and img.max() <= 1.0
    per_pixel = (counts["rays"] + counts["shadow"]) / (640 * 480)
    assert 1.5 < per_pixel < 4.0          # a full binary tree at depth 5 would be 63 rays + shadows


def test_progress_bar_is_a_callback():
    bar = ProgressBar("work")
    bar(0, 4)
    bar(3, 4)
    assert (bar.bar.value, bar.bar.max, bar.fraction, bar.label.value) == (3, 4, 0.75, "3 / 4")
    bar(1, 2)                              # a smaller total: the bar follows
    assert (bar.bar.value, bar.bar.max) == (1, 2)
    bar(50, 100)
    assert (bar.bar.value, bar.bar.max) == (50, 100)
    for done, total in ((5, 4), (-1, 4), (0, 0)):
        with pytest.raises(ValueError, match="done <= total"):
            bar(done, total)
    with pytest.raises(TypeError):
        bar(True, 4)
    with pytest.raises(TypeError, match="description"):
        ProgressBar(3)
    bar.reset()
    assert bar.fraction == 0.0 and bar.bar.value == 0


def test_render_control_renders_the_views_current_values(scene_camera):
    scene, camera = scene_camera
    seen = []
    view = InteractiveView(controls={"index": float_slider("index", 1.5, 1.0, 2.5)}, views=[],
                           update=lambda index: {})

    def full(progress, index):
        seen.append(index)
        return rt.render(rt.default_scene(index=index), camera, 32, 24, 3, samples=2, progress=progress)

    rc = RenderControl(full, view=view, label="Render")
    assert len(rc.image.value) == 0 and "Press" in rc.status.value
    view.set_values(index=2.0)
    rc._on_click()                                        # what a click does
    assert seen == [2.0] and rc.last_error is None
    assert rc.progress.fraction == 1.0 and bytes(rc.image.value[:4]) == b"\x89PNG"
    assert rc.last_image.shape == (24, 32, 3) and "32 x 24 pixels" in rc.status.value
    assert not rc.button.disabled
    first = rc.last_image.copy()
    view.set_values(index=1.0)
    rc._on_click()
    assert seen == [2.0, 1.0] and not np.array_equal(first, rc.last_image)


def test_render_control_shows_errors_and_interrupts_without_a_traceback():
    def refuses(progress):
        raise ValueError("width must be at most 4096")

    rc = RenderControl(refuses)
    rc._on_click()
    assert rc.last_error.startswith("ValueError") and "width must be" in rc.status.value
    assert not rc.button.disabled

    def interrupted(progress):
        progress(1, 4)
        raise KeyboardInterrupt

    rc = RenderControl(interrupted)
    rc._on_click()                                        # the click handler must not raise
    assert "interrupted at 25 %" in rc.status.value and not rc.button.disabled
    with pytest.raises(KeyboardInterrupt):
        rc.render()                                       # from the keyboard the interrupt goes on

    rc = RenderControl(lambda progress: np.full((2, 2), 0.5))
    rc._on_click()
    assert "image must be" in rc.status.value


def test_bad_arguments_are_named():
    with pytest.raises(TypeError, match="render"):
        RenderControl(3)
    with pytest.raises(TypeError, match="view"):
        RenderControl(lambda p: None, view=object())
    with pytest.raises(TypeError, match="label"):
        RenderControl(lambda p: None, label="")
    with pytest.raises(ValueError, match="image"):
        image_png(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="finite"):
        image_png(np.full((2, 2, 3), np.nan))
