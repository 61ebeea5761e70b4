"""`make test`: the whole test suite as two pytest runs side by side, so both cores stay busy.

1. unit, property and doctest tests, widget sweeps, the fuzz test and every notebook under nbval
   (whose kernels run under another numpy SIMD dispatch: the portability check, see conftest.py),
   spread over two pytest-xdist workers by file (``--dist loadfile``: a notebook's cells run in
   order in one kernel, and a module's cached results, such as the fuzz test's, are made once).
2. the browser tests: the longest part, and mostly waiting (one process keeps about two thirds of
   a core busy), so two processes run them, each with its own JupyterLab and Chromium, at normal
   priority, and part 1 takes the rest.  The first runs every browser test from the start, the
   second only the chapter runs, from the end: each notebook is run once, by whichever process
   claims it first (tests/browser/conftest.py).  Their output is printed when they finish (and kept
   in build/test-browser.log and build/test-browser-2.log).

Prints each part's time, the total wall time and the counts of all three runs on one line (read
from their ``--junitxml`` reports in build/, not from pytest's summary text), and fails if any
run fails.  Extra arguments go to both pytest runs (``make test ARGS="-k ch24"``); a
part whose tests they all leave out counts as passed when the other part ran tests.

Usage: python scripts/run_tests.py [pytest arguments]
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from xml.etree import ElementTree

ROOT = Path(__file__).resolve().parents[1]
LOG = ROOT / "build" / "test-browser.log"
LOG2 = ROOT / "build" / "test-browser-2.log"
NOTEBOOK_TESTS = ["tests/browser/test_notebooks_in_lab.py"]
CLAIMED = "run by the other browser process"   # the skip message of tests/browser/conftest.py
JUNIT = {"unit+nbval": ROOT / "build" / "junit-unit.xml", "browser": ROOT / "build" / "junit-browser.xml",
         "browser 2": ROOT / "build" / "junit-browser-2.xml"}
WORKERS = os.environ.get("GOLDMAN_TEST_WORKERS", "2")
PYTEST = [sys.executable, "-m", "pytest", "-rs"]
UNIT = ["-n", WORKERS, "--dist", "loadfile", "--nbval-lax", "tests", "goldman_lib", "benchmarks", "course",
        "--ignore=tests/browser"]
BROWSER = ["tests/browser"]
NICE = 5
NO_TESTS = 5   # pytest's exit status when it ran no test


def counts(junit: Path) -> dict[str, int]:
    """What one pytest run did, read from its ``--junitxml`` report: passed, failed, error and
    skipped test counts, and ``shared``: the skips that only mean the other browser process ran
    that notebook.  An unreadable report (pytest died before writing it) counts nothing."""
    found = {"passed": 0, "failed": 0, "error": 0, "skipped": 0, "shared": 0}
    try:
        root = ElementTree.parse(junit).getroot()
    except (OSError, ElementTree.ParseError):
        return found
    for case in root.iter("testcase"):
        kinds = {child.tag for child in case}
        if "error" in kinds:
            found["error"] += 1
        elif "failure" in kinds:
            found["failed"] += 1
        elif "skipped" in kinds:
            found["skipped"] += 1
            if any(CLAIMED in (child.get("message") or "") for child in case if child.tag == "skipped"):
                found["shared"] += 1
        else:
            found["passed"] += 1
    return found


def main(args: list[str]) -> int:
    start = time.monotonic()
    LOG.parent.mkdir(exist_ok=True)
    claims = tempfile.mkdtemp(prefix="goldman-browser-claims-")
    env = dict(os.environ, GOLDMAN_BROWSER_CLAIMS=claims)
    browser2 = None
    with open(LOG, "w") as log, open(LOG2, "w") as log2:
        for path in JUNIT.values():
            path.unlink(missing_ok=True)
        junit = {name: [f"--junitxml={path}"] for name, path in JUNIT.items()}
        browser = subprocess.Popen(PYTEST + BROWSER + junit["browser"] + args, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, env=env)
        browser2 = subprocess.Popen(PYTEST + NOTEBOOK_TESTS + junit["browser 2"] + args, cwd=ROOT, stdout=log2, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, env=dict(env, GOLDMAN_BROWSER_REVERSE="1"))
        try:
            print(f"make test: the browser tests run beside the rest (their output follows at the end; "
                  f"also in {LOG.relative_to(ROOT)})", flush=True)
            # Part 1 goes to the terminal as it runs.  It runs at a
            # lower priority (nice 5): the browser tests are the longer part and wait on timeouts,
            # the xdist workers take whatever CPU the browser leaves.
            unit = subprocess.Popen(PYTEST + UNIT + junit["unit+nbval"] + args, cwd=ROOT, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True,
                                    errors="replace", bufsize=1, preexec_fn=lambda: os.nice(NICE))
            for line in unit.stdout:
                sys.stdout.write(line)
                sys.stdout.flush()
            unit_status = unit.wait()
            unit_seconds = time.monotonic() - start
            browser_status = browser.wait()
            browser2_status = browser2.wait()
            browser_seconds = time.monotonic() - start
        finally:
            for proc in (browser, browser2):
                if proc is not None and proc.poll() is None:   # interrupted: stop the browser tests
                    proc.send_signal(signal.SIGINT)   # too, letting their fixtures stop Lab and Chromium
                    try:
                        proc.wait(timeout=60)
                    except subprocess.TimeoutExpired:
                        proc.kill()
                        proc.wait()
            shutil.rmtree(claims, ignore_errors=True)
    browser_output = LOG.read_text(errors="replace")
    browser2_output = LOG2.read_text(errors="replace")
    print("\n" + "=" * 30 + " browser tests " + "=" * 30, flush=True)
    sys.stdout.write(browser_output)
    parts = {"unit+nbval": unit_status, "browser": browser_status, "browser 2": browser2_status}
    print("\n" + "=" * 25 + " browser tests, second process " + "=" * 25, flush=True)
    sys.stdout.write(browser2_output)
    found = {name: counts(JUNIT[name]) for name in parts}
    ran = {name: c["passed"] + c["failed"] + c["error"] for name, c in found.items()}
    failed = []
    for name, status in parts.items():
        if status == 0:
            continue
        if status == NO_TESTS and args and any(ran[other] for other in ran if other != name):
            continue   # the arguments selected tests of the other part only
        failed.append(f"{name} (pytest exit status {status})")
    # a notebook the other browser process ran is skipped here: not a skip of the suite
    total = {k: sum(c[k] for c in found.values()) for k in ("passed", "failed", "error", "skipped", "shared")}
    total["skipped"] -= total["shared"]
    print(f"\nmake test: unit+nbval {unit_seconds:.0f} s, browser {browser_seconds:.0f} s (side by side, "
          f"two browser processes); "
          f"total wall time {time.monotonic() - start:.0f} s")
    if failed:
        print("make test: FAILED: " + ", ".join(failed))
    print(f"total: {total['passed']} passed, {total['failed'] + total['error']} failed, {total['skipped']} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
