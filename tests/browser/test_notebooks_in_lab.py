"""Every chapter in real JupyterLab (headless Chromium): it runs without an error, its widgets and
three.js canvases render (non-blank pixels), moving a slider changes each interactive view,
moving the light of a view with the light-position control changes its picture, and in every view
whose points the mouse drags, a real mouse drag moves a point, changes the picture, and the point's
sliders show its new place (chapter 24's de Casteljau explorer among them).  A chapter with checks
of its own (chapter_checks.EXTRAS: chapter 11's query-point drag, chapter 15's Play button, the live
decks of chapters 6 and 24) gets them right after it has run, so no chapter runs twice.

Screenshots of every canvas and of each view before/after its slider moved are written to
tests/browser/screenshots/ on every run, so a person can look at what the test saw.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from .chapter_checks import EXTRAS, render_button_renders
from .conftest import SCREENSHOTS, course_notebooks
from .labdriver import drag_until, nudge_slider, pixel_stats, wait_changed, wait_for, wait_nonblank

pytestmark = pytest.mark.browser

NOTEBOOKS = course_notebooks()
# A slider move must change more than this fraction of the display's pixels (0.1%: a few hundred
# pixels of a ~400k-pixel display; two renders of the same values differ by none at threshold 24).
CHANGE_TOLERANCE = 0.001
# At the end of a drag the point is this close to the mouse (figure pixels): sliders snap the point
# to their steps, a few pixels at the default sizes (at most 3.7 px when the same drags are made
# with matplotlib events on Agg).
DRAG_TOLERANCE = 10.0

# Whether view UID has points the mouse drags on an ipympl canvas, and the drag a real mouse can
# make there (kernel_hooks.drag_plan, run in the kernel; None if no point can be dragged 40 px).
_HOOKS = str(Path(__file__).resolve().parent / "kernel_hooks.py")
_PLAN = """
import json as _json, runpy as _runpy
_goldman = _runpy.run_path(HOOKS)
def _goldman_plan(v):
    d = getattr(v, "drag", None)
    live = d is not None and d.enabled and type(d.ax.figure.canvas).__module__.startswith("ipympl")
    return {"drag": live, "plan": _goldman["drag_plan"](d) if live else None}
print(_json.dumps(_goldman_plan(_goldman["find_view"](UID))))
del _goldman_plan
""".replace("HOOKS", repr(_HOOKS))
# Where point K of view UID is now (data coordinates).
_WHERE = "import json as _json; print(_json.dumps(_goldman['position'](_goldman['find_view'](UID).drag, K)))"
# The label and the readout (as the slider formats it) of the sliders that point K of view UID
# moves, or null if its drag moves no slider.
_SLIDERS = """
import json as _json
def _goldman_sliders(v, k):
    names = v.drag.sliders[k] if v.drag.sliders else []
    out = []
    for n in names:
        c = v.controls[n]
        out.append([c.description, format(c.value, getattr(c, "readout_format", None) or "")])
    return out or None
print(_json.dumps(_goldman_sliders(_goldman["find_view"](UID), K)))
del _goldman_sliders
"""
# The readout a slider shows in the page, found by its label (exact text) in one view.
_JS_READOUT = """
([view, label]) => {
  for (const s of view.querySelectorAll('.widget-slider')) {
    const l = s.querySelector('.widget-label');
    if (l && l.textContent.trim() === label) {
      const r = s.querySelector('.widget-readout');
      // d3-format writes a minus as U+2212; Python's format writes '-'
      return r ? (r.value !== undefined && r.tagName === 'INPUT' ? r.value : r.textContent).trim().replace(/\u2212/g, '-') : null;
    }
  }
  return null;
}
"""

# ipympl draws its figure in .jupyter-matplotlib-canvas-div; pythreejs renderers are .jupyter-threejs.
MPL = ".jupyter-matplotlib-canvas-div"
THREE = ".jupyter-threejs canvas"


@pytest.mark.skipif(not NOTEBOOKS, reason="no notebooks in course/ yet")
@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS] or None)
def test_notebook_runs_and_views_respond(lab, notebook):
    rel = notebook.relative_to(lab.server["root"]).as_posix()
    page, stem = lab.page, notebook.stem
    lab.open(rel)
    state = lab.run_all()
    assert not state["errors"], f"{rel}: cells raised:\n" + "\n".join(state["errors"])
    problems = lab.dom_problems()
    assert not problems, f"{rel}: error output or widget error views:\n" + "\n".join(problems)
    nb = page.locator(".jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook")
    # After Run All no answer shows: worked solutions are closed <details> blocks, and no checker
    # says "Correct" (every exercise cell starts unanswered).
    details = nb.locator("details")
    assert all(not details.nth(k).evaluate("d => d.open") for k in range(details.count())), (
        f"{rel}: a worked solution is open after Run All")
    assert "Correct:" not in nb.inner_text(), f"{rel}: an answer's verdict shows after Run All"

    report = [f"{rel}: {state['total']} code cells ran"]
    for kind, selector in (("mpl", MPL), ("three", THREE)):
        canvases = nb.locator(selector)
        for i in range(canvases.count()):
            png, st = wait_nonblank(canvases.nth(i))
            (SCREENSHOTS / f"{stem}-{kind}{i}.png").write_bytes(png)
            report.append(f"  {kind} canvas {i}: {st}")
            assert st.nonblank(), f"{rel}: {kind} canvas {i} looks blank ({st}); see screenshots/{stem}-{kind}{i}.png"

    for extra in EXTRAS.get(stem, {}).get("first", []):    # the chapter's own interactions (chapter_checks.py)
        report.append(extra(lab, nb))

    views = nb.locator(".goldman-interactive")
    for i in range(views.count()):
        view = views.nth(i)
        display = view.locator(".goldman-display").first
        handles = view.locator(".goldman-controls .noUi-handle")
        if handles.count() == 0:
            # A program editor: type a new program (the editor's own example if it shows one, a
            # turtle program otherwise), leave the box (continuous_update=False), and the drawing
            # must change.
            box = view.locator(".goldman-controls textarea").first
            assert box.count(), f"{rel}: interactive view {i} has neither a slider nor a text box"
            before, st = wait_nonblank(display)
            box.scroll_into_view_if_needed()
            # An editor for another language shows an example program in code.goldman-example.
            example = view.locator("code.goldman-example")
            program = (example.first.inner_text() if example.count()
                       else "REPEAT 3 [FORWARD 2 TURN 120]\nMOVE 3\nREPEAT 4 [FORWARD 1 TURN 90]")
            box.fill(program)
            box.press("Tab")
            after, frac = wait_changed(display, before, CHANGE_TOLERANCE, timeout=15)
            (SCREENSHOTS / f"{stem}-view{i}-before.png").write_bytes(before)
            (SCREENSHOTS / f"{stem}-view{i}-after.png").write_bytes(after)
            report.append(f"  view {i}: typed a program, changed {frac:.1%} of the display")
            assert frac > CHANGE_TOLERANCE, f"{rel}: typing a program into view {i} did not change its drawing"
            continue
        # A view whose points the mouse drags: drag one with the real mouse, at the view's first
        # values (before the sliders move a point out of the axes).  The kernel says which point a
        # press grabs and where to take it (kernel_hooks.drag_plan); the point must follow the mouse and the
        # picture must change.
        uid = view.evaluate("e => ([...e.classList].find(c => c.startsWith('goldman-view-')) || '').slice(13)")
        assert uid, f"{rel}: interactive view {i} has no goldman-view-<uid> class"
        found = json.loads(lab.kernel(_PLAN.replace("UID", uid)).strip())
        assert not (found["drag"] and found["plan"] is None), (
            f"{rel}: view {i} has draggable points but none that a press can grab and move 40 px")
        plan = found["plan"]
        if plan:
            canvas = view.locator(MPL + " canvas").first
            drag_before, _ = wait_nonblank(canvas)
            length = float(np.hypot(*np.subtract(plan["end"], plan["start"])))
            tries = []

            def replan():
                # asked afresh before each retry: it starts from wherever the point is now
                nonlocal plan
                if tries:
                    plan = json.loads(lab.kernel(_PLAN.replace("UID", uid)).strip())["plan"]
                    assert plan, f"{rel}: view {i} offers no drag any more"
                tries.append(plan)
                return plan["start"], plan["end"], plan["figure"]

            def moved_by():
                # where the point is, in pixels of the axes' scale when the drag began (data
                # coordinates: a view may refit its axes once the mouse lets go)
                now = np.array(json.loads(lab.kernel(_WHERE.replace("UID", uid).replace("K", str(plan["index"]))).strip()))
                per_unit = np.array(plan["pixels_per_unit"])
                return (now - plan["start_data"]) * per_unit, (now - plan["end_data"]) * per_unit

            def followed():
                # the kernel handles the motion events one at a time: wait for the end of the drag,
                # where the point must be under the mouse (to its sliders' steps: a few pixels)
                from_start, from_end = moved_by()
                unit = np.subtract(plan["end"], plan["start"]) / length
                along, off = float(from_start @ unit), float(np.hypot(*from_end))
                return (along, off) if off <= DRAG_TOLERANCE else None

            def missed(attempt):
                # A press that missed moved nothing.  A point that stopped short on the way to the
                # mouse (the last events of the drag lost, seen once in three full runs on a loaded
                # machine) is reported and dragged again from where it is.  A point that went
                # anywhere else is a bug.
                from_start, from_end = moved_by()
                unit = np.subtract(plan["end"], plan["start"]) / length
                along = float(from_start @ unit)
                across = float(np.hypot(*(from_start - along * unit)))
                if 0 < along < length and across <= DRAG_TOLERANCE:
                    report.append(f"  view {i}: a drag stopped {length - along:.0f} px short of the mouse; dragged again")
                    return
                assert np.hypot(*from_start) < 1.0, (
                    f"{rel}: view {i}'s point {plan['index']} moved {from_start.round(1).tolist()} px, "
                    f"ending {from_end.round(1).tolist()} px from the mouse")

            along, off = drag_until(page, canvas, replan, followed, timeout=45,
                                    on_miss=missed, message=f"point {plan['index']} of view {i} to follow the mouse")
            drag_after, drag_frac = wait_changed(canvas, drag_before, CHANGE_TOLERANCE, timeout=20)
            # The sliders that place the point show where it went (the mouse and the keyboard drive
            # the same controls): their readouts in the page read what the kernel holds.
            sliders = json.loads(lab.kernel(_SLIDERS.replace("UID", uid).replace("K", str(plan["index"]))).strip())
            if sliders:
                handle_view = view.element_handle()

                def readouts():
                    shown = [page.evaluate(_JS_READOUT, [handle_view, label]) for label, _ in sliders]
                    return shown if shown == [text for _, text in sliders] else None

                try:
                    wait_for(readouts, 20, interval=0.25, message="the point's sliders to show the drag")
                except TimeoutError:
                    shown = [page.evaluate(_JS_READOUT, [handle_view, label]) for label, _ in sliders]
                    raise AssertionError(f"{rel}: after dragging point {plan['index']} of view {i}, its sliders "
                                         f"{[label for label, _ in sliders]} read {shown} in the page, not "
                                         f"{[text for _, text in sliders]} as in the kernel") from None
                report.append(f"  view {i}: the sliders {', '.join(f'{a} = {b}' for a, b in sliders)} followed the drag")
            (SCREENSHOTS / f"{stem}-view{i}-drag.png").write_bytes(drag_after)
            report.append(f"  view {i}: dragging point {plan['index']} {length:.0f} px moved it {along:.0f} px "
                          f"({off:.1f} px from the mouse) and changed {drag_frac:.1%} of the canvas")
            assert drag_frac > CHANGE_TOLERANCE, (
                f"{rel}: dragging point {plan['index']} of view {i} changed only {drag_frac:.2%} of its canvas "
                f"(see screenshots/{stem}-view{i}-drag.png)")
        before, st = wait_nonblank(display)
        (SCREENSHOTS / f"{stem}-view{i}-before.png").write_bytes(before)
        assert st.nonblank(), f"{rel}: interactive view {i} looks blank ({st})"
        # small steps may not show (then End); the default may be the maximum (then Home)
        after, frac, how = nudge_slider(handles.first, display, before, CHANGE_TOLERANCE)
        (SCREENSHOTS / f"{stem}-view{i}-after.png").write_bytes(after)
        status = view.locator(":scope > .widget-html, :scope .widget-html").last.inner_text()
        report.append(f"  view {i}: {how} changed {frac:.1%} of the display; {pixel_stats(after)}")
        assert frac > CHANGE_TOLERANCE, (
            f"{rel}: moving the first slider of interactive view {i} changed only {frac:.2%} of its pixels "
            f"(see screenshots/{stem}-view{i}-before.png and -after.png)")
        assert "\u26a0" not in status, f"{rel}: view {i} reports an error after the slider moved: {status}"
        # A view lit through the light-position control: moving the light must change its three.js
        # view where it has one, its figure otherwise (the views' unit tests check that the rendered
        # image itself changes with the light, not only the light's marker).
        light = view.locator(".goldman-controls .widget-slider", has_text="light x")
        if light.count():
            target = view.locator(THREE).first if view.locator(THREE).count() else view.locator(MPL).first
            lit_before, _ = wait_nonblank(target)
            knob = light.first.locator(".noUi-handle").first
            knob.scroll_into_view_if_needed()
            knob.focus()
            knob.press("End")
            lit_after, lit_frac = wait_changed(target, lit_before, CHANGE_TOLERANCE, timeout=20)
            if lit_frac <= CHANGE_TOLERANCE:       # the light started at the end of its range
                knob.press("Home")
                lit_after, lit_frac = wait_changed(target, lit_before, CHANGE_TOLERANCE, timeout=20)
            (SCREENSHOTS / f"{stem}-view{i}-light.png").write_bytes(lit_after)
            kind = "three.js view" if view.locator(THREE).count() else "image"
            report.append(f"  view {i}: moving the light changed {lit_frac:.1%} of its {kind}")
            assert lit_frac > CHANGE_TOLERANCE, (
                f"{rel}: moving the light of interactive view {i} changed only {lit_frac:.2%} of its {kind} "
                f"(see screenshots/{stem}-view{i}-light.png)")
    # A render button (widgets.render_control.RenderControl) under a view: pressed, its progress bar
    # must reach the end and a full-size picture show; after the view's first slider moves, a
    # second render must change the picture.
    renders = nb.locator(".goldman-render-control")
    for r in range(renders.count()):
        rc = renders.nth(r)
        rc.scroll_into_view_if_needed()
        report.append(render_button_renders(lab, nb, rc, f"{rel}: render control {r}", f"{stem}-render{r}"))
    for extra in EXTRAS.get(stem, {}).get("last", []):     # the live decks (chapter_checks.py)
        report.append(extra(lab, nb))
    problems = lab.dom_problems()
    assert not problems, f"{rel}: errors after moving sliders and dragging points:\n" + "\n".join(problems)
    # A widget model that refused a state update logs it only in the console (issue 19 §3: pythreejs
    # lights left to make their own shadow objects logged "Error setting state: t.on is not a function").
    refused = [m for m in getattr(page, "console_errors", []) if "Error setting state" in m]
    assert not refused, f"{rel}: widget models refused state updates:\n" + "\n".join(refused[:5])
    print("\n".join(report))
