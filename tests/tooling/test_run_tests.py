"""`make test` reads each pytest run's counts from its JUnit XML report (scripts/run_tests.py)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("run_tests", ROOT / "scripts" / "run_tests.py")
run_tests = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(run_tests)

REPORT = """<?xml version="1.0" encoding="utf-8"?>
<testsuites><testsuite name="pytest" errors="1" failures="1" skipped="3" tests="7">
<testcase classname="a" name="ok1" time="0.1"/>
<testcase classname="a" name="ok2" time="0.1"><system-out>printed</system-out></testcase>
<testcase classname="a" name="bad" time="0.1"><failure message="assert 1 == 2">...</failure></testcase>
<testcase classname="a" name="broken" time="0.1"><error message="fixture failed">...</error></testcase>
<testcase classname="a" name="nb1" time="0"><skipped type="pytest.skip" message="run by the other browser process">x</skipped></testcase>
<testcase classname="a" name="nb2" time="0"><skipped type="pytest.skip" message="run by the other browser process">x</skipped></testcase>
<testcase classname="a" name="nochromium" time="0"><skipped type="pytest.skip" message="install chromium">x</skipped></testcase>
</testsuite></testsuites>
"""


def test_counts_read_from_junit(tmp_path):
    path = tmp_path / "junit.xml"
    path.write_text(REPORT)
    assert run_tests.counts(path) == {"passed": 2, "failed": 1, "error": 1, "skipped": 3, "shared": 2}


def test_a_missing_or_broken_report_counts_nothing(tmp_path):
    assert sum(run_tests.counts(tmp_path / "none.xml").values()) == 0
    (tmp_path / "cut.xml").write_text(REPORT[:200])
    assert sum(run_tests.counts(tmp_path / "cut.xml").values()) == 0
