"""Worked solutions show only when asked for, pass their checkers, and wrong answers never give the
answer away.

A worked solution is a markdown cell tagged ``solution`` holding one collapsed ``<details>`` block:
a ``<summary>`` line, the reasoning, and the solution's code in a fenced ``python`` block whose last
line calls the chapter's checker with the answer (or, for a programming project, the project checker
with the reference function).  Markdown stores no output, so the answer is hidden in JupyterLab
before and after Run All, on GitHub and nbviewer, and in the offline deck, until the learner opens it.

This file runs every solution's code (it must be self-contained: it imports what it uses) and checks
that its checker says Correct; then, for every exercise checker, feeds it the wrong answers of the
kinds it recognises (``SLIPS`` in the chapter module) and a few generic ones, and fails if a message
contains a number of the expected answer that the learner was not given (in the statement or in
their own answer).
"""

from __future__ import annotations

import ast
import importlib
import json
import re
from pathlib import Path

import numpy as np
import pytest

from goldman_lib.exercises import Result

ROOT = Path(__file__).resolve().parents[2]
CHAPTERS = sorted((ROOT / "course").glob("[0-9][0-9]_*.ipynb"))
FENCE = re.compile(r"```python\n(.*?)```", re.S)


def solution_cells(path):
    nb = json.loads(path.read_text())
    return [(i, c) for i, c in enumerate(nb["cells"]) if "solution" in c["metadata"].get("tags", [])]


def solution_code(cell) -> str:
    return "\n".join(FENCE.findall("".join(cell["source"])))


def run_solution(code: str):
    """Execute the solution's code; return (namespace, last call node, value of the last expression)."""
    tree = ast.parse(code)
    assert tree.body and isinstance(tree.body[-1], ast.Expr), "a solution ends with the checker call"
    namespace: dict = {}
    exec(compile(ast.Module(tree.body[:-1], type_ignores=[]), "<solution>", "exec"), namespace)
    last = tree.body[-1].value
    value = eval(compile(ast.Expression(last), "<solution>", "eval"), namespace)
    return namespace, last, value


SOLUTIONS = [pytest.param(p, i, id=f"{p.stem[:2]}-cell{i}") for p in CHAPTERS for i, _ in solution_cells(p)]


@pytest.mark.parametrize("path", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_solutions_are_collapsed_markdown_with_no_output(path):
    cells = solution_cells(path)
    assert len(cells) >= 5, "at least five worked solutions a chapter"
    for i, cell in cells:
        text = "".join(cell["source"]).strip()
        assert cell["cell_type"] == "markdown", f"cell {i}: a solution is a markdown cell (code cells store output)"
        assert text.startswith("<details") and text.endswith("</details>"), f"cell {i}: one <details> block"
        assert "<details open" not in text, f"cell {i}: the solution must start collapsed"
        assert "<summary>" in text and solution_code(cell).strip(), f"cell {i}: a <summary> and a python block"


@pytest.mark.parametrize("path,index", SOLUTIONS)
def test_every_worked_solution_passes_its_checker(path, index):
    cell = dict(solution_cells(path))[index]
    _, _, value = run_solution(solution_code(cell))
    assert isinstance(value, Result), f"the solution's last line should call a checker, got {value!r}"
    assert value.correct, f"the worked solution fails its own checker: {value}"


# -- wrong answers explained, never answered ------------------------------------------------------

NUMBER = re.compile(r"(?<![\w§.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
# Numbers that count things rather than answer them ("point 2", "level 3", "case 1 of 4").
COUNTER = re.compile(r"(?:point|points|level|levels|case|step|steps|degree|row|column|map|maps|index|of|"
                     r"P|Q|B|line|iteration|iterations|exercise|n =|k =)\s*$", re.I)


def numbers_in(text: str, drop_counters: bool = False) -> list[tuple[float, int]]:
    """(value, significant digits) for every number written in ``text``."""
    found = []
    for m in NUMBER.finditer(text):
        if drop_counters and COUNTER.search(text[max(0, m.start() - 12):m.start()]):
            continue
        token = m.group(0).lstrip("+-")
        mantissa = token.split("e")[0].replace(".", "").lstrip("0") or "0"
        found.append((float(m.group(0)), max(1, len(mantissa))))
    return found


def _digits_needed(value: float) -> int:
    """Significant digits that write ``value`` to within 1e-9 (2 -> 1, 0.375 -> 3, 1/3 -> 10)."""
    for digits in range(1, 16):
        if abs(float(f"{value:.{digits}g}") - value) <= 1e-9 * max(1.0, abs(value)):
            return digits
    return 16


def _matches(expected: float, written: float, digits: int) -> bool:
    """Whether a number written with ``digits`` significant digits gives ``expected`` away: it is
    ``expected`` rounded to that precision, written precisely enough to tell it (three digits, or
    all the digits ``expected`` has) -- "1" does not give away 1.2034, "1.20" does."""
    if abs(expected - written) <= 1e-9:
        return True
    return digits >= min(3, _digits_needed(expected)) and float(f"{expected:.{digits}g}") == written


def leaked(message: str, answer, given: str) -> list[float]:
    """Numbers of the expected ``answer`` that ``message`` prints and ``given`` (the statement and
    the learner's own answer) does not."""
    try:
        values = np.asarray(answer, dtype=float).ravel()
    except (TypeError, ValueError):
        return []
    known = [v for v, _ in numbers_in(given)]
    out = []
    for e in values:
        if any(abs(e - k) <= 1e-9 for k in known):
            continue
        if any(_matches(e, v, d) for v, d in numbers_in(message, drop_counters=True)):
            out.append(float(e))
    return out


def perturbations(answer) -> list:
    """Generic wrong answers: nudged, and moved a little differently, from the right one."""
    try:
        arr = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return []
    if arr.dtype == bool or arr.size == 0:
        return []
    first = arr.copy().ravel()
    first[0] += 0.37
    scaled = arr * 1.1 + 0.013
    return [first.reshape(arr.shape).tolist(), scaled.tolist()]


def _exercise_answers():
    """(module, checker name, answer) for every exercise solution: the argument of its last call."""
    found = []
    for path in CHAPTERS:
        for index, cell in solution_cells(path):
            code = solution_code(cell)
            tree = ast.parse(code)
            last = tree.body[-1].value if tree.body and isinstance(tree.body[-1], ast.Expr) else None
            if not (isinstance(last, ast.Call) and isinstance(last.func, ast.Attribute)
                    and isinstance(last.func.value, ast.Name) and len(last.args) == 1):
                continue
            module_name = f"goldman_lib.exercises.{last.func.value.id}"
            try:
                module = importlib.import_module(module_name)
            except ImportError:
                continue
            name = last.func.attr
            if name not in getattr(module, "PROBLEMS", {}):
                continue  # a project checker
            found.append(pytest.param(path, index, module, name, id=f"{module.__name__.rsplit('.', 1)[1]}.{name}"))
    return found


EXERCISES = _exercise_answers()


def test_every_checker_has_a_worked_solution_and_slips():
    by_module = {}
    for p in EXERCISES:
        by_module.setdefault(p.values[2], set()).add(p.values[3])
    for path in CHAPTERS:
        module = importlib.import_module(f"goldman_lib.exercises.ch{path.name[:2]}")
        missing = set(module.PROBLEMS) - by_module.get(module, set())
        assert not missing, f"{module.__name__}: no worked solution in {path.name} calls {sorted(missing)}"
        slips = getattr(module, "SLIPS", {})
        assert set(slips) == set(module.PROBLEMS), (
            f"{module.__name__}.SLIPS must list the recognised wrong answers of every checker")
        assert all(len(v) >= 1 for v in slips.values())


@pytest.mark.parametrize("path,index,module,name", EXERCISES)
def test_wrong_answers_are_explained_without_the_answer(path, index, module, name):
    cell = dict(solution_cells(path))[index]
    namespace, last, _ = run_solution(solution_code(cell))
    answer = eval(compile(ast.Expression(last.args[0]), "<solution>", "eval"), namespace)
    checker = getattr(module, name)
    statement = module.PROBLEMS[name]
    for slip in list(module.SLIPS.get(name, [])) + perturbations(answer):
        r = checker(slip)
        assert isinstance(r, Result) and r.answered and not r.correct, f"{name}({slip!r}) should be wrong: {r}"
        assert len(r.message) > 20, f"{name}({slip!r}) says too little: {r}"
        given = statement + " " + json.dumps(slip, default=str)
        assert not leaked(r.message, answer, given), (
            f"{name}({slip!r}) gives the answer away (prints {leaked(r.message, answer, given)}): {r}")
