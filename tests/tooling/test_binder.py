"""Binder's dependency list and pyproject.toml must not drift apart."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _requirements(path):
    lines = (line.split("#")[0].strip() for line in path.read_text().splitlines())
    return sorted(line.replace(" ", "") for line in lines if line)


def test_binder_requirements_match_pyproject_runtime_and_lab():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    wanted = sorted(d.replace(" ", "") for d in project["dependencies"] + project["optional-dependencies"]["lab"])
    assert _requirements(ROOT / "binder" / "requirements.txt") == wanted


def test_binder_postbuild_installs_the_library_and_runtime_is_pinned():
    post = (ROOT / "binder" / "postBuild").read_text()
    assert "pip install --no-deps -e ." in post
    assert (ROOT / "binder" / "runtime.txt").read_text().strip().startswith("python-3.")
