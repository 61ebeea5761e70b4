"""Fixtures for the browser tests: one JupyterLab server and one headless Chromium per session.

``lab_server`` starts ``jupyter lab`` from this environment on 127.0.0.1 with a random token, an
isolated config/runtime/settings/workspaces directory (so a developer's own settings never leak in)
and notebook windowing switched off (every cell is attached to the DOM, so every output can be
found and screenshotted).  ``browser_context`` drives Debian's Chromium (``/usr/bin/chromium``)
through Playwright; Playwright's own browser download does not work on these machines.
``lab`` gives each test a fresh page with JupyterLab loaded and ready.

Set ``GOLDMAN_LAB_ROOT`` to serve another directory holding a ``course/`` folder (used while the
chapters were being written); by default the repository is served.
"""

from __future__ import annotations

import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
LAB_ROOT = Path(os.environ.get("GOLDMAN_LAB_ROOT", REPO)).resolve()
SCREENSHOTS = Path(__file__).resolve().parent / "screenshots"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--disable-background-networking",
    "--disable-component-update", "--disable-sync", "--no-first-run", "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
]
NO_CHROMIUM = "install Debian's chromium: sudo apt-get install chromium"

# Settings written into the isolated user-settings directory.
LAB_SETTINGS = {
    # Attach every cell to the DOM (JupyterLab 4 windows long notebooks by default).
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
    # Never write the notebooks we run back to disk (other people are editing them).
    "@jupyterlab/docmanager-extension/plugin.jupyterlab-settings": {"autosave": False},
    # No news / update toasts over the outputs we screenshot.
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings": {
        "checkForUpdates": False, "fetchNews": "false", "doNotDisturbMode": True},
}


def course_notebooks() -> list[Path]:
    """The notebooks the browser tests open (collected when the test modules are imported)."""
    return sorted((LAB_ROOT / "course").glob("*.ipynb"))


#: Two browser processes share the chapter runs of test_notebooks_in_lab (``make test`` starts both):
#: each notebook is run by whichever process claims it first, through a file created exclusively in
#: this folder; the second process walks the notebooks from the end.
CLAIMS = os.environ.get("GOLDMAN_BROWSER_CLAIMS")
CLAIMED_ELSEWHERE = "run by the other browser process"


def pytest_collection_modifyitems(config, items):
    if os.environ.get("GOLDMAN_BROWSER_REVERSE"):
        items.reverse()


def pytest_runtest_setup(item):
    """Before any fixture (no page is opened for a notebook the other process has)."""
    if not CLAIMS or getattr(item, "originalname", None) != "test_notebook_runs_and_views_respond":
        return          # only the chapter runs are shared out (the live-deck tests also take a notebook)
    notebook = item.callspec.params["notebook"]
    try:
        os.close(os.open(os.path.join(CLAIMS, Path(notebook).stem), os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:
        pytest.skip(CLAIMED_ELSEWHERE)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    rep = outcome.get_result()
    setattr(item, "rep_" + rep.when, rep)


@pytest.fixture(scope="session")
def lab_server():
    """A running JupyterLab: yields ``{"url": base_url, "token": token, "root": root_dir, "log": path}``."""
    tmp = Path(tempfile.mkdtemp(prefix="goldman-lab-"))
    settings = tmp / "settings"
    for rel, value in LAB_SETTINGS.items():
        path = settings / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(value))
    for d in ("config", "runtime", "workspaces", "ipython", "checkpoints"):
        (tmp / d).mkdir()
    bindir = os.path.dirname(sys.executable)
    env = dict(os.environ)
    env.update(
        JUPYTER_CONFIG_DIR=str(tmp / "config"), JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
        IPYTHONDIR=str(tmp / "ipython"), PATH=bindir + os.pathsep + env.get("PATH", ""),
        JUPYTER_PLATFORM_DIRS="1", PYTHONHASHSEED="0", MPLBACKEND="Agg",
    )
    env.pop("JUPYTERLAB_SETTINGS_DIR", None)
    env.pop("JUPYTERLAB_WORKSPACES_DIR", None)
    port, token = _free_port(), secrets.token_hex(16)
    log_path = tmp / "lab.log"
    cmd = [
        os.path.join(bindir, "jupyter-lab"), "--no-browser", "--ip=127.0.0.1", f"--port={port}",
        "--ServerApp.port_retries=0", f"--IdentityProvider.token={token}",
        f"--ServerApp.root_dir={LAB_ROOT}", "--LabApp.expose_app_in_browser=True",
        f"--LabApp.user_settings_dir={settings}", f"--LabApp.workspaces_dir={tmp / 'workspaces'}",
        "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
        "--ServerApp.terminals_enabled=False",
        # Lab writes a checkpoint when it opens a notebook: keep those out of course/.
        f"--FileCheckpoints.root_dir={tmp / 'checkpoints'}",
    ]
    if hasattr(os, "geteuid") and os.geteuid() == 0:   # containers and CI runners often run as root
        cmd.append("--allow-root")
    log = open(log_path, "wb")
    proc = subprocess.Popen(cmd, env=env, cwd=LAB_ROOT, stdout=log, stderr=subprocess.STDOUT,
                            start_new_session=True)
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120
    try:
        while True:
            if proc.poll() is not None:
                pytest.fail(f"jupyter lab exited with {proc.returncode}:\n{log_path.read_text()[-4000:]}")
            try:
                with urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=5) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline:
                pytest.fail(f"jupyter lab did not answer /api/status in 120 s:\n{log_path.read_text()[-4000:]}")
            time.sleep(0.3)
        yield {"url": base, "token": token, "root": LAB_ROOT, "log": log_path}
    finally:
        _stop_lab(proc, base, token)
        log.close()
        shutil.rmtree(tmp, ignore_errors=True)


def _stop_lab(proc, base, token):
    """Shut the server down through its API (it stops its kernels), then by signal if needed."""
    if proc.poll() is None:
        try:
            req = urllib.request.Request(f"{base}/api/shutdown?token={token}", method="POST")
            urllib.request.urlopen(req, timeout=10).close()
        except OSError:
            proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.terminate()
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()


@pytest.fixture(scope="session")
def browser_context():
    """One headless Chromium (a fresh profile) for the whole session."""
    if not os.path.exists(CHROMIUM):
        pytest.skip(NO_CHROMIUM)
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:  # pragma: no cover - the test extra installs it
        pytest.skip("install the test extra: pip install -e '.[test]' (playwright is missing)")
    profile = tempfile.mkdtemp(prefix="goldman-chromium-")
    with sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(
            user_data_dir=profile, executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS,
            viewport={"width": 1400, "height": 1000}, device_scale_factor=1)
        context.set_default_timeout(60_000)
        try:
            yield context
        finally:
            context.close()
            shutil.rmtree(profile, ignore_errors=True)


@pytest.fixture
def browser_page(browser_context, request):
    """A fresh page; on failure a screenshot goes to tests/browser/screenshots/<test>-FAILED.png."""
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    page = browser_context.new_page()
    messages: list[str] = []
    page.on("console", lambda m: messages.append(f"{m.type}: {m.text}") if m.type == "error" else None)
    page.on("pageerror", lambda e: messages.append(f"pageerror: {e}"))
    page.console_errors = messages
    yield page
    rep = getattr(request.node, "rep_call", None)
    if rep is not None and rep.failed:
        name = "".join(c if c.isalnum() or c in "-_." else "_" for c in request.node.name)
        try:
            page.screenshot(path=str(SCREENSHOTS / f"{name}-FAILED.png"), full_page=True)
        except Exception as exc:  # noqa: BLE001 - the test's own failure matters more
            print(f"could not take a failure screenshot: {exc}")
        if messages:
            print("browser console errors:\n  " + "\n  ".join(messages[-30:]))
    page.close()


@pytest.fixture
def lab(browser_page, lab_server):  # the browser first: without chromium, skip before starting Lab
    """A page with JupyterLab loaded (workspace reset) and ``window.jupyterapp`` restored."""
    from .labdriver import Lab

    driver = Lab(browser_page, lab_server)
    driver.load()
    yield driver
    driver.shutdown_all()
