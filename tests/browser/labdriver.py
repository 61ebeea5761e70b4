"""Driving JupyterLab through ``window.jupyterapp`` (exposed by ``--LabApp.expose_app_in_browser``)
and comparing what the page shows by pixels (element screenshots decoded with Pillow).

Nothing here saves a notebook: autosave is off in the test settings and documents are closed
without saving, so running a chapter never rewrites the file others are editing.
"""

from __future__ import annotations

import io
import json
import time
import urllib.request
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

WIDGET_MIME = "application/vnd.jupyter.widget-view+json"


# -- pixels ----------------------------------------------------------------------------------------
@dataclass
class PixelStats:
    width: int
    height: int
    colours: int          # distinct colours (quantised to 5 bits per channel)
    ink: float            # fraction of pixels that differ from the most common colour

    def nonblank(self, min_ink: float = 0.004, min_colours: int = 3) -> bool:
        return self.width > 0 and self.height > 0 and self.colours >= min_colours and self.ink >= min_ink

    def __str__(self):
        return f"{self.width}x{self.height}, {self.colours} colours, {self.ink:.1%} ink"


def _rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def pixel_stats(png: bytes, threshold: int = 16) -> PixelStats:
    """Colour count and the fraction of pixels away from the background (most common) colour."""
    a = _rgb(png)
    h, w = a.shape[:2]
    if a.size == 0:
        return PixelStats(w, h, 0, 0.0)
    flat = a.reshape(-1, 3)
    q = (flat >> 3).astype(np.int32)
    keys = (q[:, 0] << 10) | (q[:, 1] << 5) | q[:, 2]
    values, counts = np.unique(keys, return_counts=True)
    bg_key = values[np.argmax(counts)]
    bg = flat[keys == bg_key][0]
    ink = float((np.abs(flat - bg).max(axis=1) > threshold).mean())
    return PixelStats(w, h, len(values), ink)


def changed_fraction(before: bytes, after: bytes, threshold: int = 24) -> float:
    """Fraction of pixels whose colour moved by more than ``threshold`` in some channel (the
    images are compared over their common top-left region if their sizes differ)."""
    a, b = _rgb(before), _rgb(after)
    h, w = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
    if h == 0 or w == 0:
        return 0.0
    d = np.abs(a[:h, :w] - b[:h, :w]).max(axis=2) > threshold
    size_change = 1.0 - (h * w) / max(a.shape[0] * a.shape[1], b.shape[0] * b.shape[1])
    return float(d.mean()) + size_change


def wait_for(predicate, timeout: float, interval: float = 0.25, message: str = "condition"):
    """Poll ``predicate()`` until it returns something truthy; return it, or raise after ``timeout``."""
    deadline = time.monotonic() + timeout
    last = None
    while True:
        last = predicate()
        if last:
            return last
        if time.monotonic() > deadline:
            raise TimeoutError(f"timed out after {timeout:.0f} s waiting for {message}")
        time.sleep(interval)


# -- awaiting in the page --------------------------------------------------------------------------
# ``page.evaluate("async () => { await ... }")`` hands Chromium a promise that the DevTools protocol
# holds only weakly; under memory pressure V8 may collect it while the page still works on it, and
# Playwright fails with "Resulting promise was garbage collected" (seen once in a CI run, in a
# fixture that awaited ``jupyterapp.restored``).  So nothing here awaits across the protocol: the
# async work starts in the page, its promise is kept on ``window`` (a strong reference), and the
# test polls a plain flag until the work has settled.
_JS_START = """
([source, arg, key]) => {
  const store = (window.__goldmanAsync = window.__goldmanAsync || {});
  const fn = (0, eval)('(' + source + ')');
  const entry = {done: false};
  entry.promise = Promise.resolve().then(() => fn(arg)).then(
    v => { entry.value = v; entry.ok = true; entry.done = true; },
    e => { entry.error = String((e && e.stack) || e); entry.ok = false; entry.done = true; });
  store[key] = entry;
  return true;
}
"""
_JS_SETTLED = """
(key) => {
  const store = window.__goldmanAsync;
  if (!store || !store[key]) return 'lost';
  return store[key].done ? 'done' : '';
}
"""
_JS_TAKE = """
(key) => {
  const e = window.__goldmanAsync[key];
  delete window.__goldmanAsync[key];
  return {ok: e.ok, value: e.ok ? e.value : null, error: e.ok ? null : e.error};
}
"""
_async_keys = iter(range(1, 1 << 62))


def await_js(page, source: str, arg=None, timeout: float = 120, what: str = "the page's work"):
    """Run the async JavaScript function ``source`` (``async (arg) => ...``) in ``page`` and return
    its value, without handing its promise to the DevTools protocol (see above).  A rejection raises
    RuntimeError with the page's message; a page that navigated away meanwhile raises too."""
    key = f"k{next(_async_keys)}"
    page.evaluate(_JS_START, [source, arg, key])

    def settled():
        state = page.evaluate(_JS_SETTLED, key)
        if state == "lost":
            raise RuntimeError(f"the page reloaded or navigated while waiting for {what}")
        return state == "done"

    wait_for(settled, timeout, interval=0.1, message=what)
    out = page.evaluate(_JS_TAKE, key)
    if not out["ok"]:
        raise RuntimeError(f"{what} failed in the page: {out['error'][:2000]}")
    return out["value"]


# -- JupyterLab --------------------------------------------------------------------------------------
# Runs code in the current notebook's kernel and returns what it printed.
_JS_KERNEL = """
async (code) => {
  const w = window.jupyterapp.shell.currentWidget;
  const kernel = w.sessionContext.session.kernel;
  const future = kernel.requestExecute({code, silent: false, store_history: false});
  let out = '';
  future.onIOPub = (msg) => {
    if (msg.header.msg_type === 'stream') out += msg.content.text;
    if (msg.header.msg_type === 'error') out += 'ERROR ' + msg.content.ename + ': ' + msg.content.evalue;
  };
  await future.done;
  return out;
}
"""

_JS_OPEN = """
async (path) => {
  const app = window.jupyterapp;
  const w = await app.commands.execute('docmanager:open', {path, factory: 'Notebook'});
  await w.context.ready;
  await w.sessionContext.ready;
  app.shell.activateById(w.id);
  window.__goldmanNotebook = w;
  return {id: w.id, windowingMode: w.content.notebookConfig.windowingMode};
}
"""

_JS_RUN_ALL = """
async () => {
  const app = window.jupyterapp;
  const w = window.__goldmanNotebook;
  app.shell.activateById(w.id);
  await app.commands.execute('notebook:clear-all-cell-outputs');
  // do not await: run-all resolves only when every cell has run; we poll instead
  app.commands.execute('notebook:run-all-cells');
  return true;
}
"""

_JS_STATE = """
() => {
  const w = window.__goldmanNotebook;
  const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
  const code = w.content.widgets.filter(c => c.model.type === 'code' && c.model.sharedModel.getSource().trim());
  const pending = code.filter(c => c.model.executionCount == null || c.model.executionState === 'running' ||
                                   (c.promptNode && c.promptNode.textContent.includes('*'))).length;
  const errors = [];
  code.forEach((c, i) => {
    for (const o of c.model.outputs.toJSON()) {
      if (o.output_type === 'error') errors.push(`cell ${i}: ${o.ename}: ${o.evalue}`);
      if (o.output_type === 'stream' && o.name === 'stderr' && /Traceback/.test(o.text)) errors.push(`cell ${i}: ${o.text.slice(0, 400)}`);
    }
  });
  return {status: kernel ? kernel.status : 'no kernel', pending, total: code.length, errors};
}
"""

_JS_DOM_PROBLEMS = """
() => {
  const nb = window.__goldmanNotebook.node;
  const out = [];
  nb.querySelectorAll('.jp-RenderedText[data-mime-type="application/vnd.jupyter.stderr"]').forEach(e => {
    if (/Traceback/.test(e.textContent)) out.push('stderr: ' + e.textContent.slice(0, 400));
  });
  nb.querySelectorAll('.jp-OutputArea-output').forEach(e => {
    const t = e.textContent || '';
    if (/Error displaying widget|Error rendering|model not found|Failed to load model class/i.test(t)) out.push('widget: ' + t.slice(0, 300));
  });
  nb.querySelectorAll('.jupyter-widgets').forEach(e => {
    if (/Error displaying widget/.test(e.textContent || '')) out.push('widget error view: ' + e.textContent.slice(0, 300));
  });
  return out;
}
"""

# How many outputs carry a widget view, and how many have rendered it (or an error) in the DOM.
_JS_WIDGETS_RENDERED = f"""
() => {{
  const w = window.__goldmanNotebook;
  let expected = 0;
  w.content.widgets.filter(c => c.model.type === 'code').forEach(c => {{
    for (const o of c.model.outputs.toJSON()) if (o.data && o.data['{WIDGET_MIME}']) expected += 1;
  }});
  const outs = Array.from(w.node.querySelectorAll('.jp-OutputArea-output'));
  const rendered = outs.filter(o => o.querySelector('.jupyter-widgets, .jupyter-widget') || /Error displaying widget/.test(o.textContent)).length;
  const canvases = Array.from(w.node.querySelectorAll('.jupyter-widgets canvas, .jupyter-widget canvas'));
  const sized = canvases.filter(c => c.width > 0 && c.height > 0).length;
  return {{expected, rendered, canvases: canvases.length, sized}};
}}
"""


class Lab:
    """One browser page with JupyterLab, and the notebook currently open in it."""

    def __init__(self, page, server: dict):
        self.page = page
        self.server = server

    def load(self):
        url, token = self.server["url"], self.server["token"]
        self.page.goto(f"{url}/lab?reset&token={token}", wait_until="domcontentloaded")
        self.page.wait_for_function("() => window.jupyterapp !== undefined", timeout=90_000)
        await_js(self.page, "async () => { await window.jupyterapp.started; await window.jupyterapp.restored; }",
                 timeout=120, what="JupyterLab to start and restore its layout")

    def command(self, name: str, args: dict | None = None):
        return await_js(self.page, "async ([n, a]) => { const r = await window.jupyterapp.commands.execute(n, a || {}); "
                        "return (r === undefined || r === null || typeof r !== 'object') ? r : true; }", [name, args],
                        what=f"the command {name}")

    def open(self, relpath: str) -> str:
        """Open a notebook (path relative to the server root) and wait for its kernel."""
        opened = await_js(self.page, _JS_OPEN, relpath, what=f"{relpath} to open with its kernel")
        # A deck left running (by a test that failed half-way) would hide most cells.
        if self.page.evaluate("() => !!document.querySelector('.jp-Deck')"):
            self.command("deck:stop")
            self.page.wait_for_function("() => !document.querySelector('.jp-Deck')", timeout=30_000)
        # The isolated settings turn windowing off so every cell is in the DOM; say so if not.
        assert opened["windowingMode"] == "none", f"notebook windowing is {opened['windowingMode']!r}, not 'none'"
        return opened["id"]

    def run_all(self, timeout: float = 240) -> dict:
        """Clear outputs, run every cell, wait until each non-empty code cell has an execution count
        and the kernel is idle (or a cell failed); then wait for widget views to render."""
        await_js(self.page, _JS_RUN_ALL, what="Run All to start")
        idle_polls = 0

        def done():
            nonlocal idle_polls
            st = self.page.evaluate(_JS_STATE)
            if st["status"] == "idle" and (st["pending"] == 0 or st["errors"]):
                idle_polls += 1
            else:
                idle_polls = 0
            return st if idle_polls >= 3 else None

        state = wait_for(done, timeout, interval=0.3, message="all cells to run and the kernel to be idle")
        if not state["errors"]:
            wait_for(lambda: (lambda s: s["rendered"] >= s["expected"] and s["sized"] == s["canvases"])(
                self.page.evaluate(_JS_WIDGETS_RENDERED)), 60, message="widget views to render")
        return state

    def kernel(self, code: str) -> str:
        """Run ``code`` in the open notebook's kernel (not in a cell) and return what it printed;
        an exception comes back as the text ``ERROR name: message``."""
        return await_js(self.page, _JS_KERNEL, code, timeout=120, what="code run in the kernel")

    def dom_problems(self) -> list[str]:
        return self.page.evaluate(_JS_DOM_PROBLEMS)

    def shutdown_all(self):
        """Shut down every kernel session on the server (documents are never saved)."""
        url, token = self.server["url"], self.server["token"]
        try:
            with urllib.request.urlopen(f"{url}/api/sessions?token={token}", timeout=10) as r:
                sessions = json.load(r)
            for s in sessions:
                req = urllib.request.Request(f"{url}/api/sessions/{s['id']}?token={token}", method="DELETE")
                urllib.request.urlopen(req, timeout=30).close()
        except OSError as exc:
            print(f"could not shut down kernels: {exc}")


def screenshot(locator, path: Path | None = None) -> bytes:
    """Element screenshot (scrolled into view first), optionally also written to ``path``."""
    locator.scroll_into_view_if_needed()
    png = locator.screenshot(animations="disabled")
    if path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(png)
    return png


def wait_nonblank(locator, timeout: float = 30, **kw) -> tuple[bytes, PixelStats]:
    """Screenshot ``locator`` until it shows something (returns the last try if it never does)."""
    deadline = time.monotonic() + timeout
    while True:
        png = screenshot(locator)
        st = pixel_stats(png)
        if st.nonblank(**kw) or time.monotonic() > deadline:
            return png, st
        time.sleep(0.5)


def wait_changed(locator, before: bytes, tolerance: float, timeout: float = 20) -> tuple[bytes, float]:
    """Screenshot ``locator`` until it differs from ``before`` by more than ``tolerance``."""
    deadline = time.monotonic() + timeout
    while True:
        png = screenshot(locator)
        frac = changed_fraction(before, png)
        if frac > tolerance or time.monotonic() > deadline:
            return png, frac
        time.sleep(0.4)


# -- dragging on an ipympl canvas ----------------------------------------------------------------------
def figure_to_page(box: dict, figure_size, xy) -> tuple[float, float]:
    """A point in figure pixels (origin bottom left, as matplotlib's transforms give it) of a
    figure of ``figure_size`` = (width, height) pixels, on the page: mapped onto the canvas
    element's ``box`` (``locator.bounding_box()``), whatever CSS size the browser gave it."""
    fw, fh = figure_size
    return box["x"] + xy[0] * box["width"] / fw, box["y"] + (fh - xy[1]) * box["height"] / fh


def stable_box(locator, timeout: float = 10, interval: float = 0.15) -> dict | None:
    """The element's box once it holds still (the same in four reads ``interval`` apart): the page
    may still be scrolling, or outputs above may still be laying out, and a mouse pressed at a box
    read mid-move lands beside the point (a real-mouse drag then carries the point to the wrong
    place: seen as 12-14 px misses in three chapters)."""
    deadline = time.monotonic() + timeout
    last, still = locator.bounding_box(), 0
    while True:
        time.sleep(interval)
        box = locator.bounding_box()
        still = still + 1 if box == last else 0
        if still >= 3 or time.monotonic() > deadline:      # still for three reads in a row
            return box
        last = box


def nudge_slider(handle, target, before: bytes, tolerance: float, timeout: float = 20) -> tuple[bytes, float, str]:
    """Move a noUi slider with the keyboard until ``target``'s picture changes by more than
    ``tolerance`` from ``before``: ArrowRight five times; if that shows nothing (small steps), End;
    if the slider was already at its end, Home.  Returns the picture after, the changed fraction
    and the keys pressed (``"ArrowRight x5"``, ``"... + End"``, ``"... + End + Home"``)."""
    handle.scroll_into_view_if_needed()
    handle.focus()
    for _ in range(5):
        handle.press("ArrowRight")
    after, frac = wait_changed(target, before, tolerance, timeout=timeout)
    how = "ArrowRight x5"
    for key in ("End", "Home"):
        if frac > tolerance:
            break
        handle.press(key)
        after, frac = wait_changed(target, before, tolerance, timeout=timeout)
        how += f" + {key}"
    return after, frac, how


def drag_until(page, canvas, plan, arrived, *, attempts: int = 3, timeout: float = 60, steps: int = 4,
               pause: float = 0.1, refine=None, on_miss=None, message: str = "the drag to arrive"):
    """Drag with the mouse on an ipympl ``canvas`` until ``arrived()`` returns something truthy,
    and return that.

    ``plan()`` gives ``(start, end, figure_size)``, positions in figure pixels (asked afresh each
    attempt, so a retry starts from wherever the point is now).  The mouse goes down at ``start``
    (moved to ``refine(start_on_page, box)`` if given), moves to ``end`` in ``steps`` motion events
    ``pause`` seconds apart, and comes up.  The kernel handles the motion events one at a time, so
    a loaded machine may take a while: ``arrived`` is polled for ``timeout`` seconds.  If it never
    holds, ``on_miss(attempt)`` may raise (the press must have missed: nothing should have moved)
    and the drag is tried again, up to ``attempts`` times: a press can miss when the page shifts
    under the mouse (an image above finishing its layout) between measuring and pressing.  If the
    canvas itself moved during the drag (a formula above typeset late), the mouse's later
    positions fell elsewhere on it: ``on_miss`` is not asked, and the drag is planned afresh.
    """
    misses = []
    for attempt in range(attempts):
        canvas.scroll_into_view_if_needed()
        # ipympl focuses the canvas and its div when the mouse goes down, and focusing may scroll
        # the notebook: focus them first, so any such scroll is over before the box is measured
        canvas.evaluate("c => { c.focus({preventScroll: false}); const d = c.closest('.jupyter-matplotlib-canvas-div');"
                        " if (d) d.focus({preventScroll: false}); }")
        box = stable_box(canvas)
        assert box and box["width"] > 10 and box["height"] > 10, f"the canvas has no size: {box}"
        start_fig, end_fig, size = plan()
        start, end = figure_to_page(box, size, start_fig), figure_to_page(box, size, end_fig)
        if refine is not None:
            moved = refine(start, box)
            end = (end[0] + moved[0] - start[0], end[1] + moved[1] - start[1])
            start = moved
        page.mouse.move(*start)
        page.mouse.down()
        for k in range(1, steps + 1):
            page.mouse.move(start[0] + (end[0] - start[0]) * k / steps, start[1] + (end[1] - start[1]) * k / steps)
            time.sleep(pause)
        page.mouse.up()
        shifted = canvas.bounding_box() != box
        try:
            return wait_for(arrived, timeout, interval=0.5, message=message)
        except TimeoutError:
            misses.append(f"attempt {attempt}: pressed at page {tuple(round(v) for v in start)} "
                          f"(figure {tuple(round(v) for v in start_fig)}, canvas box {box}"
                          f"{'; the canvas moved during the drag' if shifted else ''})")
            print(misses[-1])
            if on_miss is not None and not shifted:
                on_miss(attempt)
    raise AssertionError(f"{attempts} drags never brought {message}:\n" + "\n".join(misses))
