"""Long work that says how far it is (issue 18 §4): a progress bar any library computation can
report to, and a "render" button for a full-size picture of what a view shows.

The slider callbacks of the rendering chapters draw small pictures (160x120 rays) so that a slider
feels instant.  A learner who wants a picture to keep presses the button of a :class:`RenderControl`
under the view: the library renders the view's current state at full size (640x480, anti-aliased)
while a :class:`ProgressBar` fills, and the picture appears under the button.  The work can be
interrupted with the kernel's stop button (the status line then says how far it got).

Library functions that take a while take an optional ``progress(done, total)`` callback (for
example :func:`goldman_lib.ray_tracing.render`); a :class:`ProgressBar` is such a callback, so a
notebook cell shows the progress of any of them::

    bar = ProgressBar("hemi-cube")
    display(bar)
    F = radiosity.form_factors(..., progress=bar)

Both are framework pieces: they know no chapter.  The mathematics stays in the library function
they are given.
"""

from __future__ import annotations

import base64
import html
import io
import time
from typing import Callable

import ipywidgets as widgets
import numpy as np

__all__ = ["ProgressBar", "RenderControl", "image_png"]


def image_png(image) -> bytes:
    """PNG bytes of an RGB image ``(h, w, 3)`` with values in [0, 1] (row 0 at the top).

    >>> image_png(np.zeros((2, 3, 3)))[:4]
    b'\\x89PNG'
    """
    import matplotlib.image

    a = np.asarray(image, dtype=float)
    if a.ndim != 3 or a.shape[2] not in (3, 4) or a.shape[0] < 1 or a.shape[1] < 1:
        raise ValueError(f"image must be an array (height, width, 3) of RGB values; got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError("image must hold finite values")
    buf = io.BytesIO()
    matplotlib.image.imsave(buf, np.clip(a, 0.0, 1.0), format="png")
    return buf.getvalue()


def _static_png(button: str | None, bar: str, fraction: float) -> bytes:
    """A small picture of a button and a progress bar, for pages without the widget state (a stored
    notebook opened before it runs, the website): what the control looks like, not a result."""
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch, Rectangle

    fig = Figure(figsize=(6.4, 0.34), dpi=80)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_axis_off()
    x = 0.005
    if button is not None:
        w = min(0.6, 0.012 * len(button) + 0.04)
        ax.add_patch(FancyBboxPatch((x, 0.1), w, 0.8, boxstyle="round,pad=0,rounding_size=0.05",
                                    facecolor="#2a7ab0", edgecolor="#1f5f8b", transform=ax.transAxes))
        ax.text(x + w / 2, 0.5, button, ha="center", va="center", color="white", fontsize=8, transform=ax.transAxes)
        x += w + 0.02
    ax.text(x, 0.5, bar, ha="left", va="center", fontsize=8, transform=ax.transAxes)
    x += 0.012 * len(bar) + 0.01
    ax.add_patch(Rectangle((x, 0.3), 0.3, 0.4, facecolor="#eeeeee", edgecolor="#bbbbbb", transform=ax.transAxes))
    ax.add_patch(Rectangle((x, 0.3), 0.3 * fraction, 0.4, facecolor="#2a7ab0", transform=ax.transAxes))
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


class ProgressBar(widgets.HBox):
    """A progress bar that is a ``progress(done, total)`` callback: ``bar(3, 10)`` shows 30 %.

    description: the words before the bar.  The bar counts ``done`` of ``total`` (any positive
    integer total; it may change between calls); :attr:`done` and :attr:`total` keep the last call.

    >>> bar = ProgressBar("rows")
    >>> bar(3, 12); bar.fraction
    0.25
    >>> bar(12, 12); bar.bar.value == bar.bar.max, bar.label.value
    (True, '12 / 12')
    """

    def __init__(self, description: str = "progress"):
        if not isinstance(description, str):
            raise TypeError(f"description must be a string; got {type(description).__name__}")
        self.bar = widgets.IntProgress(value=0, min=0, max=1, description=description,
                                       style={"description_width": "initial", "bar_color": "#2a7ab0"},
                                       layout=widgets.Layout(width="340px"))
        self.label = widgets.Label("")
        self.done, self.total = 0, 0
        super().__init__([self.bar, self.label])
        self.add_class("goldman-progress")

    def __call__(self, done: int, total: int) -> None:
        if isinstance(done, bool) or isinstance(total, bool):
            raise TypeError("done and total must be integers")
        done, total = int(done), int(total)
        if total < 1 or not 0 <= done <= total:
            raise ValueError(f"progress needs 0 <= done <= total and total >= 1; got done={done}, total={total}")
        self.done, self.total = done, total
        # max first when it grows, value first when it shrinks: the widget clamps value into [min, max]
        if total >= self.bar.max:
            self.bar.max = total
            self.bar.value = done
        else:
            self.bar.value = min(done, total)
            self.bar.max = total
        self.label.value = f"{done} / {total}"

    def __repr__(self) -> str:
        # what a page without the widget state (a stored notebook, the website) shows in its place
        return f"[progress bar: {self.bar.description}]"

    def _repr_mimebundle_(self, **kwargs):
        data = super()._repr_mimebundle_(**kwargs)
        data["image/png"] = base64.b64encode(_static_png(None, self.bar.description, self.fraction)).decode("ascii")
        return data

    @property
    def fraction(self) -> float:
        """How far the last call said the work was, in [0, 1]."""
        return self.done / self.total if self.total else 0.0

    def reset(self) -> None:
        """Back to empty."""
        self.done, self.total = 0, 0
        self.bar.value = 0
        self.label.value = ""


class RenderControl(widgets.VBox):
    """A button that renders a full-size picture of what ``view`` shows, with a progress bar.

    render: ``render(progress, **values) -> image`` (an RGB array ``(h, w, 3)`` in [0, 1]): a
    library call (e.g. :func:`goldman_lib.ray_tracing.render` with ``samples=2, depth=5``) that
    calls ``progress(done, total)`` as it goes; ``values`` are the view's current control values
    (nothing when ``view`` is None).  label: the button's text, naming what the picture will be
    ("Render 640 x 480, 2 x 2 anti-aliased, depth 5").  An error of ``render`` (a budget, a bad
    value) is shown in the status line, never as a traceback; an
    interrupt while the button's render runs says how far it got.

    :meth:`render` does the same from the keyboard (or a test) and returns the image.  The browser
    test of every chapter presses the button, waits for the bar to reach the end and the picture to
    show, then moves the view's first slider, renders again and expects the picture to change: give
    the view a first slider that changes what is rendered.

    >>> rc = RenderControl(lambda progress, k: (progress(1, 1), np.full((4, 6, 3), k / 2))[1],
    ...                    view=None, label="render")
    >>> rc.render(k=1).shape, rc.progress.fraction, bytes(rc.image.value[:4])
    ((4, 6, 3), 1.0, b'\\x89PNG')
    """

    def __init__(self, render: Callable[..., np.ndarray], *, view=None, label: str = "Render full size",
                 width: str = "640px"):
        if not callable(render):
            raise TypeError(f"render must be a function render(progress, **values); got {type(render).__name__}")
        if view is not None and not callable(getattr(view, "values", None)):
            raise TypeError(f"view must be an InteractiveView (with .values()) or None; got {type(view).__name__}")
        if not isinstance(label, str) or not label:
            raise TypeError("label must be a non-empty string")
        self._render = render
        self.view = view
        self.button = widgets.Button(description=label, icon="camera", button_style="primary",
                                     layout=widgets.Layout(width="auto"))
        self.progress = ProgressBar("rendering")
        self.status = widgets.HTML(value=html.escape("Press the button for a full-size picture of the view as it is now."))
        self.image = widgets.Image(format="png", layout=widgets.Layout(width=width, height="auto"))
        self.last_image: np.ndarray | None = None
        self.last_error: str | None = None
        self.seconds: float | None = None
        self.button.on_click(self._on_click)
        super().__init__([widgets.HBox([self.button, self.progress]), self.status, self.image])
        self.add_class("goldman-render-control")
        if isinstance(getattr(view, "uid", None), int):
            # the browser test finds the view this control renders (its box is goldman-view-<uid>)
            self.add_class(f"goldman-renders-{view.uid}")

    def __repr__(self) -> str:
        # what a page without the widget state (a stored notebook, the website) shows in its place
        return f"[render button: {self.button.description}; run the notebook to use it]"

    def _repr_mimebundle_(self, **kwargs):
        data = super()._repr_mimebundle_(**kwargs)
        data["image/png"] = base64.b64encode(_static_png(self.button.description, "rendering", 0.0)).decode("ascii")
        return data

    def render(self, **values) -> np.ndarray | None:
        """Render with the view's current values (or ``values``, for a test or a keyboard user) and
        show the picture; returns it, or None if ``render`` refused the values (the status says why)."""
        if not values and self.view is not None:
            values = self.view.values()
        self.progress.reset()
        self.status.value = "rendering..."
        self.button.disabled = True
        start = time.perf_counter()
        try:
            image = self._render(self.progress, **values)
            png = image_png(image)
        except Exception as exc:  # noqa: BLE001 - a widget must never show a traceback
            self.last_error = f"{type(exc).__name__}: {exc}"
            self.status.value = f'<span style="color:#b3261e">&#9888; {html.escape(str(exc))}</span>'
            return None
        finally:
            self.button.disabled = False
        self.seconds = time.perf_counter() - start
        self.last_error = None
        self.last_image = np.asarray(image, dtype=float)
        self.image.value = png
        h, w = self.last_image.shape[:2]
        self.status.value = html.escape(f"{w} x {h} pixels, rendered in {self.seconds:.1f} s")
        return self.last_image

    def _on_click(self, _button=None) -> None:
        try:
            self.render()
        except KeyboardInterrupt:
            self.status.value = html.escape(f"interrupted at {100 * self.progress.fraction:.0f} %")
