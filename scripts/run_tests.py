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

Prints each part's time, the total wall time and the counts of both parts on one line, and fails
if either part fails.  Extra arguments go to both pytest runs (``make test ARGS="-k ch24"``); a
part whose tests they all leave out counts as passed when the other part ran tests.

Usage: python scripts/run_tests.py [pytest arguments]
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LOG = ROOT / "build" / "test-browser.log"
LOG2 = ROOT / "build" / "test-browser-2.log"
NOTEBOOK_TESTS = ["tests/browser/test_notebooks_in_lab.py"]
CLAIM_SKIP = re.compile(r"^SKIPPED \[(\d+)\].*run by the other browser process", re.M)
WORKERS = os.environ.get("GOLDMAN_TEST_WORKERS", "2")
PYTEST = [sys.executable, "-m", "pytest", "-rs"]
UNIT = ["-n", WORKERS, "--dist", "loadfile", "--nbval-lax", "tests", "goldman_lib", "benchmarks", "course",
        "--ignore=tests/browser"]
BROWSER = ["tests/browser"]
NICE = 5
NO_TESTS = 5   # pytest's exit status when it ran no test
COUNT = re.compile(r"(\d+) (passed|failed|skipped|errors?|xfailed|xpassed|deselected)\b")


def counts(output: str) -> dict[str, int]:
    """The counts on pytest's closing line (``3708 passed, 3 skipped in 324.67s``)."""
    for line in reversed(output.splitlines()):
        if re.search(r"\bin [\d.]+s\b", line) and COUNT.search(line):
            found = {}
            for n, kind in COUNT.findall(line):
                found["error" if kind.startswith("error") else kind] = int(n)
            return found
    return {}


def main(args: list[str]) -> int:
    start = time.monotonic()
    LOG.parent.mkdir(exist_ok=True)
    claims = tempfile.mkdtemp(prefix="goldman-browser-claims-")
    env = dict(os.environ, GOLDMAN_BROWSER_CLAIMS=claims)
    browser2 = None
    with open(LOG, "w") as log, open(LOG2, "w") as log2:
        browser = subprocess.Popen(PYTEST + BROWSER + args, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, env=env)
        browser2 = subprocess.Popen(PYTEST + NOTEBOOK_TESTS + args, cwd=ROOT, stdout=log2, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, env=dict(env, GOLDMAN_BROWSER_REVERSE="1"))
        try:
            print(f"make test: the browser tests run beside the rest (their output follows at the end; "
                  f"also in {LOG.relative_to(ROOT)})", flush=True)
            # Part 1 goes to the terminal as it runs; a copy is kept for its counts.  It runs at a
            # lower priority (nice 5): the browser tests are the longer part and wait on timeouts,
            # the xdist workers take whatever CPU the browser leaves.
            unit = subprocess.Popen(PYTEST + UNIT + args, cwd=ROOT, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True,
                                    errors="replace", bufsize=1, preexec_fn=lambda: os.nice(NICE))
            lines = []
            for line in unit.stdout:
                sys.stdout.write(line)
                sys.stdout.flush()
                lines.append(line)
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
    parts = {"unit+nbval": (unit_status, counts("".join(lines))), "browser": (browser_status, counts(browser_output))}
    print("\n" + "=" * 25 + " browser tests, second process " + "=" * 25, flush=True)
    sys.stdout.write(browser2_output)
    parts["browser 2"] = (browser2_status, counts(browser2_output))
    # a notebook the other browser process ran is skipped here: not a skip of the suite
    shared = sum(int(n) for out in (browser_output, browser2_output) for n in CLAIM_SKIP.findall(out))
    ran = {name: sum(c.get(k, 0) for k in ("passed", "failed", "error", "xfailed", "xpassed"))
           for name, (_, c) in parts.items()}
    failed = []
    for name, (status, _) in parts.items():
        if status == 0:
            continue
        if status == NO_TESTS and args and any(ran[other] for other in ran if other != name):
            continue   # the arguments selected tests of the other part only
        failed.append(f"{name} (pytest exit status {status})")
    total = {k: sum(c.get(k, 0) for _, c in parts.values()) for k in ("passed", "failed", "error", "skipped")}
    total["skipped"] -= shared
    print(f"\nmake test: unit+nbval {unit_seconds:.0f} s, browser {browser_seconds:.0f} s (side by side, "
          f"two browser processes); "
          f"total wall time {time.monotonic() - start:.0f} s")
    if failed:
        print("make test: FAILED: " + ", ".join(failed))
    print(f"total: {total['passed']} passed, {total['failed'] + total['error']} failed, {total['skipped']} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
