"""Shared fixtures of the view tests."""

import runpy
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def hooks():
    """The tests' hooks (tests/browser/kernel_hooks.py: ``find_view``, ``drag_plan``, ``position``,
    ``screen_position`` and the mouse driven from code, ``press_at``, ``move_to``, ``release``),
    loaded as the browser tests load them in the notebook's kernel."""
    return runpy.run_path(str(Path(__file__).resolve().parents[1] / "browser" / "kernel_hooks.py"))
