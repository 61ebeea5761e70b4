"""Exercises that deal new numbers (issue 17 §3): every numeric exercise is a generator.

The stored notebook shows instance 0 (the chapter's module constants, so nbval stays
deterministic); a learner deals another instance by keyboard (``chNN.deal("check_...")``, with
an optional seed) or with the button beside the exercise (``chNN.deal_button("check_...")``), and
the seed shown deals it again.  The module-level checker ``chNN.check_...`` always checks the
*current* instance of its exercise, and ``chNN.PROBLEMS[...]`` states it; ``chNN.steps("check_...")``
shows the worked steps of the current instance, computed by the library, only when asked for.

A chapter module registers each numeric exercise on its :class:`Deck`::

    DECK = Deck("ch02")

    @DECK.exercise(stored=dict(turns=(60, 24)), generate=_gen, answer=_ans, slips=_slips,
                   statement=_text, steps=_steps, same=_same, well_posed=_ok)
    def check_loop_period(answer, p):
        '''Exercise 2.1: ... (the docstring Shift+Tab shows: what is checked, never the value)'''
        ...   # the checker of the instance p (a plain dict)

    deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
    PROBLEMS = DECK.problems({"check_fixed_one": "statement of an exercise that does not deal"})

The decorator returns ``check_loop_period(answer)``, bound to the current instance.  The parts of
an :class:`Exercise`:

- ``stored``: instance 0, the parameters the stored notebook shows (a plain dict);
- ``generate(rng) -> params``: a fresh instance from a ``numpy.random.Generator`` (never global
  randomness); draws that are not well posed are rejected and redrawn (at most ``max_tries``), so
  the distribution is that of the well-posed draws, not silently skewed into them;
- ``answer(params)``: the right answer, computed by the library;
- ``slips(params) -> {name: value}``: the wrong answers the checker names;
- ``same(a, b) -> bool``: the checker's tolerance (whether two answers count as one);
- ``well_posed(params) -> str | None``: why an instance is not well posed (degenerate,
  ill-conditioned), or None; on top of it every draw must keep the answer and its slips pairwise
  apart (no slip equals the answer, no two slips coincide, by ``same``);
- ``statement(params)``, ``steps(params)``: the problem text (citing the book's section) and the worked
  steps (markdown text).

``tests/exercises/test_exercise_generators.py`` draws a few hundred seeds of every exercise that deals and
checks these properties against the checker itself.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

__all__ = ["Deck", "Exercise", "Steps", "IllPosed", "fresh_seed", "memo", "within", "plain", "integers", "pick",
           "tenths", "steps_number"]

#: Seeds dealt when none is given lie in 1 .. SEED_RANGE - 1 (short enough to read and type).
SEED_RANGE = 100_000


class IllPosed(RuntimeError):
    """No well-posed instance was found in ``max_tries`` draws (a generator that needs fixing)."""


def within(tol: float, relative: bool = False):
    """The ``same`` of an exercise whose checker accepts answers within ``tol``: two answers (numbers
    or arrays) count as one when every entry differs by at most ``tol`` (``relative``: by at most
    ``tol * (1 + max(|a|, |b|))``, and of one shape).  Arrays that do not broadcast are not the same.

    >>> within(0.01)(1.0, 1.005), within(0.01)([1, 2], [1, 2.1]), within(1e-3, relative=True)(1000.0, 1000.5)
    (True, False, True)
    """
    tol = float(tol)
    if not tol >= 0:
        raise ValueError(f"tol must be a number >= 0; got {tol!r}")

    def same(a, b) -> bool:
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if relative:
            return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol * (1 + np.maximum(np.abs(a), np.abs(b)))))
        try:
            return bool(np.all(np.abs(a - b) <= tol))
        except ValueError:            # shapes that do not broadcast: not one answer
            return False
    return same


# -- the generators' kit: one home for what every chapter's generators need ------------------------

def plain(a):
    """``a`` as plain data an instance can hold: a float, or nested tuples of floats (an instance
    is a plain dict, so it prints, compares and caches by value).

    >>> plain(np.array([[1, 2], [3, 4]])), plain(np.float64(2.5))
    (((1.0, 2.0), (3.0, 4.0)), 2.5)
    """
    a = np.asarray(a, dtype=float)
    return float(a) if a.ndim == 0 else tuple(plain(x) for x in a)


def integers(rng, lo: int, hi: int, size=3):
    """Whole numbers from ``lo`` to ``hi`` (both included) drawn by ``rng``, as plain floats:
    ``size`` of them (a tuple), or an array of that shape as nested tuples.

    >>> integers(np.random.default_rng(0), 1, 9, 3)
    (8.0, 6.0, 5.0)
    """
    return plain(rng.integers(lo, hi + 1, size=size))


def pick(rng, options):
    """One of ``options`` (a sequence), drawn by ``rng``.

    >>> pick(np.random.default_rng(1), ["a", "b", "c"])
    'b'
    """
    return options[int(rng.integers(0, len(options)))]


def tenths(rng, lo: float, hi: float, size=None):
    """Multiples of 0.1 from ``lo`` to ``hi`` (a learner works them by hand): one float, or ``size``
    of them as plain data.

    >>> tenths(np.random.default_rng(2), 0.5, 1.5), tenths(np.random.default_rng(2), 0.5, 1.5, 2)
    (1.4, (1.4, 0.7))
    """
    v = rng.integers(round(lo * 10), round(hi * 10) + 1, size=size) / 10
    return float(v) if size is None else plain(v)


def steps_number(x) -> str:
    """A number (or vector) of the worked steps, rounded to six digits so no floating-point noise
    shows (``0.30000000000000004`` is ``0.3``, ``-0.0`` is ``0``).

    >>> steps_number(0.1 + 0.2), steps_number([-1e-17, 2 / 3])
    ('0.3', '(0, 0.666667)')
    """
    from goldman_lib.exercises import fmt

    return fmt(np.round(np.asarray(x, dtype=float), 6) + 0.0, 6)


def memo(function):
    """Cache ``function(params)`` by the instance's parameters (a plain dict): a checker, its slips
    and its steps ask for the same answer many times.  The results are shared: do not modify them."""
    cache: dict = {}

    @functools.wraps(function)
    def cached(params):
        key = repr(sorted(params.items()))
        if key not in cache:
            if len(cache) >= 512:
                cache.clear()
            cache[key] = function(params)
        return cache[key]
    return cached


def fresh_seed() -> int:
    """A new seed from the operating system's entropy (not numpy's global state), never 0."""
    return int(np.random.default_rng().integers(1, SEED_RANGE))


@dataclass
class Exercise:
    """One numeric exercise: how to deal an instance, its answer, its named slips, its text, its
    worked steps and its checker ``check(answer, params) -> Result``."""

    name: str
    check: Callable[[Any, dict], Any]
    stored: dict
    generate: Callable[[np.random.Generator], dict]
    answer: Callable[[dict], Any]
    slips: Callable[[dict], dict]
    statement: Callable[[dict], str]
    steps: Callable[[dict], str]
    same: Callable[[Any, Any], bool]
    well_posed: Callable[[dict], str | None] | None = None
    max_tries: int = 500
    doc: str = field(default="", repr=False)

    def problem(self, params: dict) -> str | None:
        """Why ``params`` is not a usable instance (the exercise's own rule, then a slip equal to
        the answer or two slips equal to each other), or None."""
        if self.well_posed is not None:
            why = self.well_posed(params)
            if why:
                return why
        values = [("the answer", self.answer(params))] + list(self.slips(params).items())
        for i, (a, va) in enumerate(values):
            for b, vb in values[i + 1:]:
                if self.same(va, vb):
                    return f"{a} and {b} coincide"
        return None

    def instance(self, seed: int) -> dict:
        """The instance dealt by ``seed``: seed 0 is the stored one; any other seed draws from
        ``numpy.random.default_rng(seed)`` until a draw is well posed."""
        seed = _seed(seed)
        if seed == 0:
            return dict(self.stored)
        rng = np.random.default_rng(seed)
        for _ in range(self.max_tries):
            params = self.generate(rng)
            if self.problem(params) is None:
                return params
        raise IllPosed(f"{self.name}: no well-posed instance in {self.max_tries} draws from seed {seed}")


def _seed(seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed must be a whole number; got {type(seed).__name__}")
    if seed < 0:
        raise ValueError(f"seed must be 0 or positive; got {seed}")
    return int(seed)


class Steps:
    """Worked steps of one instance: markdown in a notebook, plain text elsewhere."""

    def __init__(self, title: str, text: str):
        self.title, self.text = title, text

    def __repr__(self) -> str:
        return f"{self.title}\n{self.text}"

    def _repr_markdown_(self) -> str:
        return f"**{self.title}**\n\n{self.text}"


class _Problems(Mapping):
    """``PROBLEMS``: checker name -> statement of its *current* instance (fixed texts for the
    exercises that do not deal)."""

    def __init__(self, deck: "Deck", fixed: dict):
        self._deck, self._fixed = deck, dict(fixed)
        self._order = list(deck.exercises) + [k for k in fixed if k not in deck.exercises]

    def __getitem__(self, name):
        if name in self._deck.exercises:
            return self._deck.statement(name)
        return self._fixed[name]

    def __iter__(self):
        return iter(self._order)

    def __len__(self):
        return len(self._order)

    def __repr__(self):
        return repr(dict(self))


class Deck:
    """The exercises of one chapter that deal, and the instance each one is on now."""

    def __init__(self, chapter: str):
        self.chapter = chapter
        self.exercises: dict[str, Exercise] = {}
        self._current: dict[str, tuple[int, dict]] = {}

    # -- registering ------------------------------------------------------------------------------
    def exercise(self, *, stored, generate, answer, slips, statement, steps, same, well_posed=None,
                 max_tries=500):
        """Decorator: register ``check(answer, params)`` and return ``check(answer)`` bound to the
        current instance (name and docstring kept)."""
        def register(check):
            name = check.__name__
            ex = Exercise(name, check, dict(stored), generate, answer, slips, statement, steps, same,
                          well_posed, max_tries, check.__doc__ or "")
            self.exercises[name] = ex
            self._current[name] = (0, ex.instance(0))

            @functools.wraps(check)
            def bound(answer):
                return check(answer, self._current[name][1])

            del bound.__wrapped__   # Shift+Tab shows the signature (answer), not (answer, p)
            bound.exercise = ex
            return bound
        return register

    def problems(self, fixed: dict | None = None) -> Mapping:
        """The chapter's ``PROBLEMS``: live statements of the dealing exercises, then ``fixed``."""
        return _Problems(self, fixed or {})

    # -- the learner's side -----------------------------------------------------------------------
    def _get(self, name) -> Exercise:
        if name not in self.exercises:
            known = ", ".join(self.exercises) or "none"
            raise ValueError(f"name must be an exercise of {self.chapter} that deals ({known}); got {name!r}")
        return self.exercises[name]

    def current(self, name) -> tuple[int, dict]:
        """``(seed, params)`` of the instance ``name`` is on now."""
        self._get(name)
        seed, params = self._current[name]
        return seed, dict(params)

    def statement(self, name) -> str:
        """The statement of the current instance of ``name``."""
        return self._get(name).statement(self._current[name][1])

    def set(self, name, seed: int = 0) -> dict:
        """Put ``name`` on the instance of ``seed`` (0: the stored one) and return its params."""
        ex = self._get(name)
        params = ex.instance(seed)
        self._current[name] = (_seed(seed), params)
        return dict(params)

    def deal(self, name, seed: int | None = None) -> None:
        """Deal a new instance of exercise ``name`` (a fresh seed, or ``seed``; 0 is the stored
        instance) and print its statement and the seed that deals it again.

        >>> from goldman_lib.exercises import ch02
        >>> ch02.deal("check_c_curve_commands", seed=7)    # doctest: +ELLIPSIS
        The C-curve: ... How many turtle commands ... does level 10 execute? (Goldman §2.3)
        seed 7: ch02.deal('check_c_curve_commands', seed=7) gives it again; check your answer with ...
        >>> ch02.deal("check_c_curve_commands", seed=0)    # doctest: +ELLIPSIS
        The C-curve: ... does level 6 execute? (Goldman §2.3)
        seed 0: the stored instance; ch02.deal('check_c_curve_commands') deals another; ...
        """
        seed = fresh_seed() if seed is None else _seed(seed)
        self.set(name, seed)
        print(self.describe(name))

    def describe(self, name) -> str:
        """The statement of the current instance and how to deal it again."""
        seed, _ = self._current[name]
        again = (f"seed {seed}: {self.chapter}.deal({name!r}, seed={seed}) gives it again"
                 if seed else f"seed 0: the stored instance; {self.chapter}.deal({name!r}) deals another")
        return f"{self.statement(name)}\n{again}; check your answer with {self.chapter}.{name}(answer)."

    def steps(self, name) -> Steps:
        """The worked steps of the current instance of ``name`` (computed by the library)."""
        ex = self._get(name)
        seed, params = self._current[name]
        return Steps(f"Worked steps, {self.chapter} {name}, seed {seed}", ex.steps(params))

    def reset(self) -> None:
        """Every exercise back on the stored instance (seed 0)."""
        for name in self.exercises:
            self.set(name, 0)

    def button(self, name):
        """A "Deal another" button for exercise ``name``, with a seed box, a "Deal this seed" button
        and the new statement (an ipywidgets box, not displayed).  Its callbacks are :meth:`set` and
        :meth:`describe`, plain functions.  In a stored notebook it leaves a small static image of
        itself and a line of text saying how to deal by keyboard."""
        self._get(name)
        import ipywidgets as widgets   # lazy: the library imports without ipywidgets

        seed_box = widgets.BoundedIntText(value=self._current[name][0], min=0, max=2 ** 31 - 1,
                                          description="seed", layout=widgets.Layout(width="170px"))
        again = widgets.Button(description="Deal another", tooltip="a new instance of this exercise")
        by_seed = widgets.Button(description="Deal this seed", tooltip="the instance of the seed in the box "
                                                                         "(0: the stored one)")
        out = widgets.Output()

        def show(seed):
            self.set(name, seed)
            seed_box.value = seed
            out.clear_output()
            with out:
                print(self.describe(name))

        again.on_click(lambda _: show(fresh_seed()))
        by_seed.on_click(lambda _: show(int(seed_box.value)))
        box = _deal_box_class()([widgets.HBox([again, seed_box, by_seed]), out])
        box.keyboard = f"{self.chapter}.deal({name!r})"
        return box


@functools.lru_cache(maxsize=1)
def _deal_box_class():
    """The button's box class (built on first use: ipywidgets is imported lazily)."""
    import base64

    import ipywidgets as widgets

    class DealBox(widgets.VBox):
        keyboard = ""

        def _repr_mimebundle_(self, **kwargs):
            data = super()._repr_mimebundle_(**kwargs)
            data["image/png"] = base64.b64encode(_button_png()).decode("ascii")
            data["text/plain"] = (f"[Deal another: run the notebook to use the button, or {self.keyboard} "
                                  f"with an optional seed=]")
            return data

    return DealBox


@functools.lru_cache(maxsize=1)
def _button_png() -> bytes:
    """A small picture of the button for static pages (the same for every exercise)."""
    import io

    import matplotlib
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch

    with matplotlib.rc_context({"font.size": 9}):
        fig = Figure(figsize=(3.6, 0.32), dpi=80)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
        for x, w, text in ((0.01, 0.3, "Deal another"), (0.34, 0.28, "seed 0"), (0.65, 0.33, "Deal this seed")):
            ax.add_patch(FancyBboxPatch((x, 0.12), w, 0.76, boxstyle="round,pad=0,rounding_size=0.05",
                                                           facecolor="#eeeeee" if x != 0.34 else "white",
                                                           edgecolor="#999999", transform=ax.transAxes))
            ax.text(x + w / 2, 0.5, text, ha="center", va="center", transform=ax.transAxes)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()
