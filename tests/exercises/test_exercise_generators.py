"""Exercises that deal new numbers (issue 17 §3): every exercise registered on a chapter's
:class:`~goldman_lib.exercises.deal.Deck` is drawn for a few hundred seeds, and each instance must be

- well posed: the library's answer is finite (or a program text, for exercise 5.4), and the exercise's own rule (``well_posed``: no
  degenerate or ill-conditioned data, stated beside each generator) holds;
- checkable: the checker accepts the library's answer for that instance;
- distinguishable: no named slip equals the answer and no two named slips coincide, within the
  checker's own tolerance (``same``); each slip fed to the checker is rejected, answered, with a
  message of its own (the messages of the slips differ pairwise, the learner's quoted answer
  removed) that gives neither the answer's numbers away (the rule of ``tests/exercises/test_solutions.py``);
- reproducible: the same seed twice gives the same instance (checked on every tenth seed); seed 0 is
  the stored instance.

Dealing is per chapter module and reversible: ``chNN.deal(name, seed=0)`` puts the stored instance
back, and the stored notebooks' outputs do not depend on it (``pytest --nbval-lax course/0[2-6]_*.ipynb``).
"""

from __future__ import annotations

import importlib
import pkgutil

import numpy as np
import pytest

import goldman_lib.exercises as exercises
from goldman_lib.exercises import Result, quote
from goldman_lib.exercises.deal import Deck, Exercise, IllPosed
from test_solutions import leaked

#: Seeds drawn per exercise (1..SEEDS); seed 0 is checked on its own.
SEEDS = 200


def _decks():
    out = []
    for info in pkgutil.iter_modules(exercises.__path__):
        if not info.name.startswith("ch"):
            continue
        module = importlib.import_module(f"goldman_lib.exercises.{info.name}")
        deck = getattr(module, "DECK", None)
        if isinstance(deck, Deck):
            out += [pytest.param(module, name, id=f"{info.name}.{name}") for name in deck.exercises]
    return out


DEALING = _decks()


@pytest.fixture(autouse=True)
def strict_and_reset(monkeypatch):
    """Checkers raise on their own failures here, and every deck is back on seed 0 afterwards (the
    solution and leak tests check the stored instance)."""
    monkeypatch.setattr(exercises, "STRICT", True)
    yield
    for p in DEALING:
        p.values[0].DECK.reset()


def _finite(value) -> bool:
    try:
        return bool(np.all(np.isfinite(np.asarray(value, dtype=float))))
    except (TypeError, ValueError):
        return False


def _plain(value):
    arr = np.asarray(value)
    return arr.tolist() if arr.dtype.kind in "biuf" else value


#: Exercises that ask for a program, an expression or a table of chosen cases, not a number: many
#: answers are right, each checked on its own cases, so they do not deal (each module says why).
NOT_NUMERIC = {
    "ch01": {"check_polygon_program", "check_star_program", "check_rosette_program"},
    "ch03": {"check_c_curve_base_case"},
    "ch04": {"check_commuting_pairs"},
    "ch05": {"check_hexagon_program", "check_parallelogram_vertex", "check_expression_types"},
    "ch08": {"check_tao_body"},
    "ch09": {"check_expression_types"},
}


def test_every_numeric_exercise_of_every_chapter_deals():
    """Issue 17 §3: the checkers of all thirty chapters deal, except the exercises that ask for no
    number (NOT_NUMERIC, a short list that must stay short)."""
    missing = {}
    for k in range(1, 31):
        module = importlib.import_module(f"goldman_lib.exercises.ch{k:02d}")
        deck = getattr(module, "DECK", None)
        dealt = set(deck.exercises) if isinstance(deck, Deck) else set()
        fixed = set(getattr(module, "PROBLEMS", {})) - dealt - NOT_NUMERIC.get(f"ch{k:02d}", set())
        if fixed:
            missing[f"ch{k:02d}"] = sorted(fixed)
    assert not missing, f"numeric exercises that do not deal: {missing}"


@pytest.mark.parametrize("module,name", DEALING)
def test_seed_zero_is_the_stored_instance(module, name):
    ex: Exercise = module.DECK.exercises[name]
    stored_statement = module.PROBLEMS[name]
    assert ex.instance(0) == ex.stored
    module.deal(name, seed=12345)
    assert module.DECK.current(name)[0] == 12345
    module.deal(name, seed=0)
    assert module.DECK.current(name) == (0, ex.stored)
    assert module.PROBLEMS[name] == stored_statement
    assert getattr(module, name)(_plain(ex.answer(ex.stored))).correct


@pytest.mark.parametrize("module,name", DEALING)
def test_every_dealt_instance_is_well_posed_and_its_slips_are_told_apart(module, name):
    ex: Exercise = module.DECK.exercises[name]
    check = getattr(module, name)
    seen = set()
    for seed in range(SEEDS + 1):
        params = ex.instance(seed)
        if seed % 10 == 0:   # (every tenth seed: dealing twice doubles the cost of the draw)
            assert _same_params(ex.instance(seed), params), f"{name}: seed {seed} deals two different instances"
        key = repr(sorted(params.items()))
        if key in seen:
            continue          # an instance already checked (exercises with few instances repeat them)
        seen.add(key)
        answer = ex.answer(params)
        assert isinstance(answer, str) or _finite(answer), f"{name} seed {seed}: the answer is not finite: {answer!r}"
        assert ex.well_posed is None or ex.well_posed(params) is None, (name, seed, ex.well_posed(params))
        module.DECK.set(name, seed)
        statement = module.PROBLEMS[name]
        r = check(_plain(answer))
        assert isinstance(r, Result) and r.correct, f"{name} seed {seed} {params}: the answer is refused: {r}"
        slips = ex.slips(params)
        values = [("the answer", answer)] + list(slips.items())
        for i, (a, va) in enumerate(values):
            for b, vb in values[i + 1:]:
                assert not ex.same(va, vb), f"{name} seed {seed} {params}: {a} and {b} coincide"
        messages = {}
        for slip, value in slips.items():
            wrong = _plain(value)
            r = check(wrong)
            assert isinstance(r, Result) and r.answered and not r.correct, (
                f"{name} seed {seed} {params}: the slip '{slip}' is accepted: {r}")
            text = r.message.replace(quote(wrong), "<yours>")
            assert text not in messages.values(), (
                f"{name} seed {seed} {params}: the slips '{slip}' and "
                f"'{next(k for k, v in messages.items() if v == text)}' get the same message: {r}")
            messages[slip] = text
            given = statement + " " + repr(wrong) + " " + " ".join(str(x) for x in np.ravel(wrong))
            found = [v for v in leaked(r.message, answer, "") if not _small_int(v)]   # (cheap first pass)
            found = found and [v for v in leaked(r.message, answer, given) if not _small_int(v)]
            assert not found, (
                f"{name} seed {seed} {params}: the slip '{slip}' gives the answer away: {r}")
    assert len(seen) >= 2, f"{name}: {SEEDS} seeds deal only one instance"


def _small_int(value: float) -> bool:
    """A small whole number (a coordinate 0, 1, 2 or the "2" of "2x2") is in too many words and data
    to count as the answer given away (the rule of ``tests/exercises/test_exercises_leaks.py`` for docstrings)."""
    return abs(value - round(value)) <= 1e-9 and abs(value) <= 12


def _same_params(a: dict, b: dict) -> bool:
    return a.keys() == b.keys() and all(np.array_equal(np.asarray(a[k], dtype=object), np.asarray(b[k], dtype=object))
                                        for k in a)


def test_deal_prints_the_statement_and_the_seed(capsys):
    from goldman_lib.exercises import ch02

    ch02.deal("check_c_curve_commands", seed=4321)
    out = capsys.readouterr().out
    assert ch02.PROBLEMS["check_c_curve_commands"] in out
    assert "seed 4321: ch02.deal('check_c_curve_commands', seed=4321) gives it again" in out
    ch02.deal("check_c_curve_commands")
    seed = ch02.current("check_c_curve_commands")[0]
    assert 0 < seed and f"seed={seed})" in capsys.readouterr().out
    steps = ch02.steps("check_c_curve_commands")
    assert f"seed {seed}" in repr(steps) and "c(n) = 5 + 2 c(n-1)" in steps._repr_markdown_()


def test_bad_names_and_seeds_are_refused():
    from goldman_lib.exercises import ch02

    with pytest.raises(ValueError, match="name must be an exercise of ch02"):
        ch02.deal("check_nothing", seed=1)
    with pytest.raises(ValueError, match="seed must be 0 or positive"):
        ch02.deal("check_loop_period", seed=-1)
    with pytest.raises(TypeError, match="seed must be a whole number"):
        ch02.deal("check_loop_period", seed=1.5)


def test_a_generator_that_cannot_be_well_posed_says_so():
    ex = Exercise("check_x", lambda a, p: None, {"v": 1}, lambda rng: {"v": int(rng.integers(0, 3))},
                  answer=lambda p: p["v"], slips=lambda p: {"same": p["v"]}, statement=str, steps=str,
                  same=lambda a, b: a == b, max_tries=20)
    assert ex.problem({"v": 1}) == "the answer and same coincide"
    with pytest.raises(IllPosed, match="no well-posed instance in 20 draws from seed 3"):
        ex.instance(3)


def test_the_button_deals_through_the_same_function():
    pytest.importorskip("ipywidgets")
    from goldman_lib.exercises import ch02

    box = ch02.deal_button("check_star_angle")
    (again, seed_box, by_seed), out = box.children[0].children, box.children[1]
    seed_box.value = 77
    by_seed.click()
    assert ch02.current("check_star_angle")[0] == 77
    text = ch02.DECK.describe("check_star_angle")      # what the button prints (its Output needs a kernel)
    assert ch02.PROBLEMS["check_star_angle"] in text and "seed 77: ch02.deal('check_star_angle', seed=77)" in text
    again.click()
    assert ch02.current("check_star_angle")[0] == seed_box.value > 0
    bundle = box._repr_mimebundle_()
    assert "image/png" in bundle and "ch02.deal('check_star_angle')" in bundle["text/plain"]


_ROUNDING = __import__("re").compile(r"to (\d+) (decimals|decimal places|digits|significant digits|significant figures)")


@pytest.mark.parametrize("module, name", DEALING)
def test_an_answer_rounded_as_the_statement_asks_is_accepted(module, name):
    """A statement that says "to 4 decimals" (or "4 significant digits") must accept the answer
    rounded so: the checker's tolerance is at least the rounding the statement asks for (a learner
    who types 2.667 for 8/3 after "4 digits" was told wrong)."""
    ex: Exercise = module.DECK.exercises[name]
    for seed in range(0, 41):
        p = ex.instance(seed)
        found = _ROUNDING.search(ex.statement(p))
        if not found:
            return
        answer = ex.answer(p)
        try:
            arr = np.asarray(answer, dtype=float)
        except (TypeError, ValueError):
            return
        if not np.all(np.isfinite(arr)):
            return
        n, kind = int(found.group(1)), found.group(2)
        if kind in ("decimals", "decimal places"):
            typed = np.round(arr, n)
        else:
            typed = np.array([float(f"{v:.{n}g}") for v in arr.ravel()]).reshape(arr.shape)
        result = ex.check(typed.tolist() if typed.ndim else float(typed), p)
        assert isinstance(result, Result) and result.correct, (
            f"seed {seed}: the statement asks for {n} {kind}; {typed.tolist()} (the answer so rounded) is told "
            f"{result.message!r}")
