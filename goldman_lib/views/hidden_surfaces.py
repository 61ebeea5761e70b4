"""The view of chapter 22 (Goldman, hidden surfaces): pick an algorithm and step through its drawing
-- polygons or pieces painted back to front (heedless painter, depth sort, BSP tree), polygons added
to the z-buffer, scan lines, rows of rays -- beside its finished picture, where the pixels that
differ from the z-buffer's are marked (only the heedless painter has any away from the edges).

Every frame comes from :func:`goldman_lib.hidden_surfaces.frames`, computed once when the view is
built; a slider move only swaps the image data in place.

>>> view = hidden_surfaces_view()
>>> r = view.set_values(algorithm="BSP tree", step=3)
>>> r["step"], r["wrong"]
(3, 0)
"""

from __future__ import annotations

import numpy as np

from goldman_lib import hidden_surfaces as hs
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, int_slider

__all__ = ["hidden_surfaces_view"]


def _describe(name, order, step):
    if step == 0:
        return "nothing drawn yet"
    item = order[step - 1]
    if name == "scan line":
        return f"scan line {step - 1}"
    if name == "ray casting":
        return f"the rays of row {item}"
    if isinstance(item, tuple):
        return f"a piece of polygon {item[0]}"
    return f"polygon {item}"


def hidden_surfaces_view(algorithm: str = "depth sort", step: int = 0, width: int = 120,
                         height: int = 90) -> InteractiveView:
    """Step through a hidden-surface algorithm on the chapter's scene (Goldman §22.2-22.7).

    ``update(algorithm, step)`` shows the image after ``step`` drawing steps (``step`` 0 shows the
    finished image; a step past the last shows the last) and returns ``{"frame" (h, w) polygon
    indices, "final" (h, w), "step", "steps", "wrong" (pixels off the z-buffer's image away from
    edges), "status"}``.
    """
    polygons, colours = hs.default_scene()
    camera = hs.default_camera(width, height)
    finals = {name: f(polygons, camera) for name, (f, _) in hs.ALGORITHMS.items()}
    all_frames = {name: hs.frames(name, polygons, camera) for name in hs.ALGORITHMS}
    reference = finals["z-buffer"].ids
    edges = hs.edge_pixels(reference)
    most = max(len(f) for f in all_frames.values())
    controls = {"algorithm": dropdown("method", [(f"{n} ({s})", n) for n, (_, s) in hs.ALGORITHMS.items()], algorithm),
                "step": int_slider("step", step, 0, most)}

    fig = style.new_figure(figsize=(7.6, 3.0))
    axes = [fig.add_subplot(1, 2, k + 1) for k in range(2)]
    blank = np.ones((height, width, 3))
    images = [ax.imshow(blank, interpolation="nearest") for ax in axes]
    (marks,) = axes[1].plot([], [], "s", markersize=2.5, markerfacecolor="none", markeredgecolor="#d1495b",
                            markeredgewidth=0.6, label="differs from the z-buffer")
    axes[1].legend(loc="lower right", fontsize=7)
    titles = [ax.set_title("", fontsize=9) for ax in axes]
    for ax in axes:
        ax.set_axis_off()
    fig.tight_layout()
    finished = {}   # algorithm -> its finished picture (the step slider does not change it)

    def update(algorithm, step):
        frames = all_frames[algorithm]
        steps = len(frames)
        k = min(int(step), steps)
        frame = finals[algorithm].ids if k == 0 else frames[k - 1]
        images[0].set_data(hs.shade(frame, polygons, colours, camera))
        final = finals[algorithm].ids
        if algorithm not in finished:
            finished[algorithm] = hs.shade(final, polygons, colours, camera)
        images[1].set_data(finished[algorithm])
        wrong = (final != reference) & ~edges
        rows, cols = np.nonzero(wrong)
        marks.set_data(cols, rows)
        what = "finished" if k == 0 else f"step {k} of {steps}: {_describe(algorithm, finals[algorithm].order, k)}"
        titles[0].set_text(f"{algorithm}: {what}")
        titles[1].set_text(f"finished: {int(wrong.sum())} pixels off the z-buffer's")
        status = (f"{algorithm} ({hs.ALGORITHMS[algorithm][1]}) draws in {steps} steps; "
                  f"{'step 0 shows the finished image' if k == 0 else what}; "
                  f"{int(wrong.sum())} pixels differ from the z-buffer's image away from edges")
        return {"frame": frame, "final": final, "step": k, "steps": steps, "wrong": int(wrong.sum()), "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§22.2-22.7 hidden surfaces, step by step")
    style.pin_layout(fig)       # titles need not be placed again at each redraw
    return view
