"""A class on one JupyterHub: two learners follow the instructor's nbgitpuller link, each gets their
own copy of the course, runs chapter 6 in JupyterLab with its widgets, and a second pull after the
instructor pushed a change keeps each learner's own edit (nbgitpuller's merge rules: the learner's
edited notebook stays, lines both changed keep the learner's version, a deleted file comes back,
the instructor's new file arrives).

The test starts everything on 127.0.0.1 and stops it again:

* a JupyterHub (the ``jupyterhub`` package) with its proxy, configurable-http-proxy from npm,
  installed once into ``build/hub-proxy/`` (``npm install --prefix``; nothing global);
* the ``dummy`` authenticator (any password) for the learners ``learner1`` and ``learner2``, and
  ``SimpleLocalProcessSpawner``: each learner's single-user server (``jupyterhub-singleuser`` from
  this environment, with nbgitpuller) runs as the current user with its own home directory under a
  temporary folder, so no unix users are needed (``--allow-root`` when run as root, as CI is);
* the "course repository" the link points at: a bare git repository in the temporary folder holding
  this checkout's HEAD (``file://``, no network), to which the test pushes the instructor's change.

Learners log in through the hub's login page and log out between each other (one browser). After
the hub is stopped no process that it, its proxy, a learner's server or a kernel started is left
(they all carry a marker in their environment, looked for in /proc).
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.parse
import urllib.request
from pathlib import Path

import pytest

from .conftest import REPO, SCREENSHOTS, _free_port
from .labdriver import Lab, await_js, nudge_slider, wait_for, wait_nonblank

pytestmark = pytest.mark.browser

PROXY_DIR = REPO / "build" / "hub-proxy"
PROXY_VERSION = "5.3.0"      # configurable-http-proxy, the proxy JupyterHub's docs install from npm
PROXY_BIN = PROXY_DIR / "node_modules" / ".bin" / "configurable-http-proxy"
COURSE = "goldman-course"    # the repository's name: nbgitpuller clones it into ~/goldman-course
BRANCH = "main"
CHAPTER = "course/06_ifs_fractals.ipynb"
LEARNERS = ("learner1", "learner2")
MARKER = "GOLDMAN_HUB_TEST"  # in the environment of every process the hub starts
CHANGE_TOLERANCE = 0.001

_HUB_CONFIG = """
import os
c = get_config()  # noqa: F821
c.JupyterHub.bind_url = {bind_url!r}
c.JupyterHub.hub_bind_url = {hub_bind_url!r}
c.ConfigurableHTTPProxy.api_url = {proxy_api!r}
c.ConfigurableHTTPProxy.command = [{proxy!r}]
c.ConfigurableHTTPProxy.pid_file = {tmp!r} + '/proxy.pid'
c.JupyterHub.db_url = 'sqlite:///' + {tmp!r} + '/jupyterhub.sqlite'
c.JupyterHub.cookie_secret_file = {tmp!r} + '/cookie_secret'
c.JupyterHub.pid_file = {tmp!r} + '/jupyterhub.pid'
c.JupyterHub.cleanup_servers = True
c.JupyterHub.authenticator_class = 'dummy'
c.Authenticator.allowed_users = set({learners!r})
c.JupyterHub.spawner_class = 'simple'
c.SimpleLocalProcessSpawner.home_dir_template = {tmp!r} + '/home/{{username}}'
c.Spawner.ip = '127.0.0.1'
c.Spawner.cmd = [{singleuser!r}]
c.Spawner.args = {args!r}
c.Spawner.default_url = '/lab'
c.Spawner.start_timeout = 180
c.Spawner.http_timeout = 180
c.Spawner.environment = {environment!r}
"""

# The Lab settings of the learners' servers: every cell in the DOM (labdriver's assumption).
_LAB_SETTINGS = {
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings": {
        "checkForUpdates": False, "fetchNews": "false", "doNotDisturbMode": True},
}


def pull_link(hub: str, repo: str, branch: str = BRANCH, notebook: str = CHAPTER) -> str:
    """The link an instructor hands out (README, "A class on one JupyterHub")."""
    query = urllib.parse.urlencode({"repo": repo, "branch": branch,
                                    "urlpath": f"lab/tree/{repo.rstrip('/').split('/')[-1]}/{notebook}"})
    return f"{hub}/hub/user-redirect/git-pull?{query}"


def _proxy() -> str:
    if PROXY_BIN.exists():
        return str(PROXY_BIN)
    npm = shutil.which("npm")
    if npm is None:
        pytest.skip("the hub test installs configurable-http-proxy with npm once: sudo apt-get install npm")
    PROXY_DIR.mkdir(parents=True, exist_ok=True)
    subprocess.run([npm, "install", "--prefix", str(PROXY_DIR), "--no-audit", "--no-fund", "--no-save",
                    "--loglevel=error", f"configurable-http-proxy@{PROXY_VERSION}"], check=True)
    assert PROXY_BIN.exists(), f"npm did not install {PROXY_BIN}"
    return str(PROXY_BIN)


def _git(*args, cwd=None) -> str:
    return subprocess.run(["git", "-c", "user.name=Instructor", "-c", "user.email=instructor@example.org", *args],
                          cwd=cwd, check=True, capture_output=True, text=True).stdout


def _marked_processes(tag: str) -> list[int]:
    """Processes whose environment holds MARKER=tag (the hub, its proxy, the servers, the kernels)."""
    needle = f"{MARKER}={tag}".encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                if needle in f.read().split(b"\0"):
                    found.append(int(entry))
        except OSError:
            pass
    return found


def _stop(proc, tag: str, timeout: float = 60) -> list[int]:
    """Stop the hub (SIGTERM: it stops the learners' servers and its proxy), wait for every marked
    process to go; kill what is left and return the pids that had to be killed."""
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    try:
        wait_for(lambda: not _marked_processes(tag), 20, message="the hub's processes to end")
        return []
    except TimeoutError:
        left = _marked_processes(tag)
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        return left


@pytest.fixture(scope="module")
def hub():
    """A running hub; yields a dict with its URL, the course repository's URL and the temp folder."""
    if not shutil.which("git"):
        pytest.skip("git is needed for nbgitpuller")
    proxy = _proxy()
    tmp = Path(tempfile.mkdtemp(prefix="goldman-hub-"))
    tag = tmp.name
    # The course repository the instructor's link points at: this checkout's HEAD (its last commit
    # only) as branch main, whatever branch the checkout is on (or none).
    upstream = tmp / "upstream" / COURSE
    _git("clone", "--quiet", "--bare", "--depth", "1", REPO.as_uri(), str(upstream))
    _git("update-ref", f"refs/heads/{BRANCH}", "HEAD", cwd=upstream)
    _git("symbolic-ref", "HEAD", f"refs/heads/{BRANCH}", cwd=upstream)
    settings = tmp / "lab-settings"
    for rel, value in _LAB_SETTINGS.items():
        (settings / rel).parent.mkdir(parents=True, exist_ok=True)
        (settings / rel).write_text(json.dumps(value))
    bindir = os.path.dirname(sys.executable)
    args = ["--LabApp.expose_app_in_browser=True", f"--LabApp.user_settings_dir={settings}",
            "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        args.append("--allow-root")
    path = bindir + os.pathsep + os.environ.get("PATH", "/usr/local/bin:/usr/bin:/bin")
    environment = {"PATH": path, "PYTHONHASHSEED": "0", "MPLBACKEND": "Agg", MARKER: tag,
                   "LANG": os.environ.get("LANG", "C.UTF-8")}
    for keep in ("OPENBLAS_CORETYPE", "OPENBLAS_L2_SIZE", "LC_ALL"):
        if keep in os.environ:
            environment[keep] = os.environ[keep]
    port = _free_port()
    base = f"http://127.0.0.1:{port}"
    config = tmp / "jupyterhub_config.py"
    config.write_text(_HUB_CONFIG.format(
        bind_url=base, hub_bind_url=f"http://127.0.0.1:{_free_port()}",
        proxy_api=f"http://127.0.0.1:{_free_port()}", proxy=proxy, tmp=str(tmp), learners=list(LEARNERS),
        singleuser=os.path.join(bindir, "jupyterhub-singleuser"), args=args, environment=environment))
    env = dict(os.environ, PATH=path, **{MARKER: tag})
    log_path = tmp / "hub.log"
    log = open(log_path, "wb")
    proc = subprocess.Popen([os.path.join(bindir, "jupyterhub"), "-f", str(config)], cwd=tmp, env=env,
                            stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
    info = {"url": base, "repo": upstream.as_uri(), "tmp": tmp, "log": log_path, "proc": proc, "tag": tag}
    try:
        deadline = time.monotonic() + 90
        while True:
            if proc.poll() is not None:
                pytest.fail(f"jupyterhub exited with {proc.returncode}:\n{log_path.read_text()[-4000:]}")
            try:
                with urllib.request.urlopen(f"{base}/hub/api/", timeout=5) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline:
                pytest.fail(f"jupyterhub did not answer in 90 s:\n{log_path.read_text()[-4000:]}")
            time.sleep(0.3)
        yield info
    finally:
        info["killed"] = _stop(proc, tag)
        log.close()
        if info["killed"]:
            print(f"hub teardown: had to kill {info['killed']}\n{log_path.read_text()[-3000:]}")
        shutil.rmtree(tmp, ignore_errors=True)


def _follow_link(page, hub, learner: str, link: str, lab: bool = True):
    """Log in as ``learner`` with the link as the page to go to next, and wait until nbgitpuller
    has sent the page on to JupyterLab (and, with ``lab``, until JupyterLab is ready)."""
    page.goto(f"{hub['url']}/hub/logout", wait_until="domcontentloaded")
    page.context.clear_cookies(domain="127.0.0.1", path="/hub/")  # (logout clears them; belt and braces)
    next_path = link[len(hub["url"]):]
    page.goto(f"{hub['url']}/hub/login?next={urllib.parse.quote(next_path)}", wait_until="domcontentloaded")
    page.fill("#username_input", learner)
    page.fill("#password_input", "any")
    page.click("#login_submit")
    # hub -> spawn pending -> the learner's server -> nbgitpuller's page (clone or merge) -> Lab
    page.wait_for_url(f"**/user/{learner}/lab/tree/**", timeout=240_000, wait_until="commit")
    if not lab:
        return
    page.wait_for_function("() => window.jupyterapp !== undefined", timeout=90_000)
    await_js(page, "async () => { await window.jupyterapp.started; await window.jupyterapp.restored; }",
             what="JupyterLab to start and restore its layout")


def _note(learner: str) -> str:
    return f"My own note ({learner}): the attractor does not depend on the starting shape."


def test_class_on_one_hub(hub, browser_page):
    page, started = browser_page, time.monotonic()
    link = pull_link(hub["url"], hub["repo"])
    rel = f"{COURSE}/{CHAPTER}"
    report = [f"link: {link}"]
    home = hub["tmp"] / "home"
    for learner in LEARNERS:
        t0 = time.monotonic()
        _follow_link(page, hub, learner, link)
        t_lab = time.monotonic()
        copy = home / learner / COURSE
        assert (copy / ".git").is_dir() and (copy / CHAPTER).is_file(), f"{learner} has no copy of the course"
        lab = Lab(page, {"url": f"{hub['url']}/user/{learner}", "token": "", "root": home / learner})
        lab.open(rel)
        state = lab.run_all()
        t_run = time.monotonic()
        assert not state["errors"], f"{learner}: cells raised:\n" + "\n".join(state["errors"])
        assert not lab.dom_problems(), f"{learner}: widget errors: {lab.dom_problems()}"
        nb = page.locator(".jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook")
        canvases = nb.locator(".jupyter-matplotlib-canvas-div")
        assert canvases.count() > 0, f"{learner}: chapter 6 shows no ipympl figure"
        for i in range(canvases.count()):
            _, st = wait_nonblank(canvases.nth(i))
            assert st.nonblank(), f"{learner}: figure {i} of chapter 6 looks blank ({st})"
        # the widgets are live: the IFS map editor's first slider moves its picture
        view = nb.locator(".goldman-interactive", has_text="IFS map editor").first
        display = view.locator(".goldman-display").first
        before, _ = wait_nonblank(display)
        after, frac, _ = nudge_slider(view.locator(".goldman-controls .noUi-handle").first, display, before,
                                      CHANGE_TOLERANCE)
        (SCREENSHOTS / f"hub-{learner}-editor.png").write_bytes(after)
        assert frac > CHANGE_TOLERANCE, f"{learner}: the IFS map editor's slider changed {frac:.2%} of its picture"
        # the learner writes a note into the chapter's first cell and saves the notebook
        await_js(page, """async (note) => {
            const w = window.__goldmanNotebook;
            const cell = w.content.widgets[0].model.sharedModel;
            cell.setSource(cell.getSource() + '\\n\\n' + note);
            await w.context.save();
        }""", _note(learner))
        assert _note(learner) in (copy / CHAPTER).read_text(), f"{learner}'s note was not saved"
        report.append(f"{learner}: pulled, ran chapter 6 ({state['total']} code cells, {canvases.count()} figures), "
                      f"slider changed {frac:.1%} of the editor, note saved ({time.monotonic() - t0:.0f} s: "
                      f"{t_lab - t0:.0f} s to Lab, {t_run - t_lab:.0f} s to run)")

    # Between the pulls, learner 1 also adds a line at the end of the README (where the instructor
    # adds one too) and learner 2 deletes the course map.
    own_line = "My own line at the end of the README (learner1)."
    with open(home / "learner1" / COURSE / "README.md", "a") as f:
        f.write("\n" + own_line + "\n")
    (home / "learner2" / COURSE / "course" / "index.ipynb").unlink()

    # The instructor pushes a change to the course.
    work = hub["tmp"] / "instructor"
    _git("clone", "--quiet", "--depth", "1", "--branch", BRANCH, hub["repo"], str(work))
    announcement = "Week 2: read chapter 7 before Tuesday."
    (work / "course" / "ANNOUNCEMENTS.md").write_text(announcement + "\n")
    with open(work / "README.md", "a") as f:
        f.write("\n" + announcement + "\n")
    _git("add", "-A", cwd=work)
    _git("commit", "--quiet", "-m", "Week 2 announcement", cwd=work)
    _git("push", "--quiet", "origin", BRANCH, cwd=work)

    # Each learner follows the same link again: the change arrives, their own note stays, and
    # they do not get the other learner's note (each has their own copy).
    for learner in LEARNERS:
        t0 = time.monotonic()
        last = learner == LEARNERS[-1]   # the last one also looks at the chapter in Lab
        _follow_link(page, hub, learner, link, lab=last)
        copy = home / learner / COURSE
        text = (copy / CHAPTER).read_text()
        others = [other for other in LEARNERS if other != learner]
        assert _note(learner) in text, f"{learner}'s own edit of chapter 6 is gone after the second pull"
        assert not any(_note(o) in text for o in others), f"{learner}'s copy holds another learner's note"
        assert (copy / "course" / "ANNOUNCEMENTS.md").read_text().strip() == announcement, (
            f"{learner} did not get the instructor's new file")
        # nbgitpuller's merge rules: lines both changed keep the learner's version; a file the
        # learner deleted comes back
        readme = (copy / "README.md").read_text()
        if learner == "learner1":
            assert own_line in readme and announcement not in readme, (
                "learner1's README: where both changed the same lines, the learner's version should stay")
        else:
            assert announcement in readme and own_line not in readme, "learner2 did not get the README change"
            assert (copy / "course" / "index.ipynb").is_file(), "learner2's deleted course map did not come back"
        if last:
            page.wait_for_function("(note) => document.body.innerText.includes(note)", arg=_note(learner),
                                   timeout=60_000)
        log = _git("log", "--format=%s", cwd=copy)
        report.append(f"{learner}: second pull kept the note and brought the change ({time.monotonic() - t0:.0f} s); "
                      f"history: {log.splitlines()[:4]}")
    page.screenshot(path=str(SCREENSHOTS / "hub-second-pull.png"))

    page.goto("about:blank")
    killed = _stop(hub["proc"], hub["tag"])
    assert not killed, f"processes left after the hub stopped (killed): {killed}"
    report.append(f"hub, proxy and servers stopped; no process left; {time.monotonic() - started:.0f} s in all")
    print("\n" + "\n".join(report))
