"""Symbolic checking for the book's "show that" exercises.

Goldman's exercises are largely derivations.  A "show that" exercise gives the learner sympy symbols
(``symbols``); the learner builds, in a code cell their own kernel runs, the expression a step of the
proof produces (the image of a vector, a row of a matrix, a scalar part); :func:`check_expression`
decides whether it is identically the right one, and if not, names the slip.

Nothing here evaluates text: a string answer is refused unread (``sympify`` is never called on
learner input).  Answers are sympy expressions, sympy matrices, plain numbers, or lists of these.

How an answer is decided, with the exercise's constraints substituted first (a unit vector, or
``c**2 + s**2 = 1``, through a rational parametrisation, so everything stays a rational function):

1. an exact spot check: both sides at a dozen random rational points from a fixed generator.  A
   point where they differ proves the answer wrong;
2. sympy's canonical form (``cancel`` of the difference), which decides identity of rational
   functions completely, under a size bound and a time limit.  Acceptance needs both: every spot
   check equal *and* the difference cancelling to zero.  If the spot checks all agree but sympy
   cannot finish (too large, or not a rational function and ``simplify`` gives up), the answer is
   not accepted and the learner is asked to simplify it by hand first.

A wrong answer is compared (again by exact spot checks) with the slip forms the exercise names, and
with the generic slips: the negative, twice or half the right expression, another constant
multiple, the transpose of a matrix, one term missing, doubled or of the wrong sign, the wrong
entries of a vector or matrix.  Messages describe the slip in words and never print the expected
expression.

Importing this module imports sympy; ``import goldman_lib`` and ``goldman_lib.exercises`` do not.

>>> x, y = symbols("x y")
>>> check_expression((x + y)**2, x**2 + 2*x*y + y**2, what="the square", symbols=(x, y))
Correct: the square is right (checked symbolically and at 12 exact rational points).
>>> check_expression(x**2 + y**2, x**2 + 2*x*y + y**2, what="the square", symbols=(x, y))
Not yet: the square is missing a term: the one in x·y.
"""

from __future__ import annotations

import math
import signal
import threading
from contextlib import contextmanager
from fractions import Fraction
from numbers import Integral, Real

import numpy as np
import sympy

from goldman_lib.exercises import Result, correct, is_unanswered, unanswered, wrong

__all__ = ["symbols", "unit_vector_substitution", "unit_circle_substitution", "check_expression",
           "to_sympy", "AnswerError", "SPOT_POINTS", "MAX_NODES", "MAX_DEGREE", "TIME_LIMIT"]

#: Exact rational spot checks made for every answer.
SPOT_POINTS = 12
#: An answer with more nodes than this is refused as too large to check (simplify it first).
MAX_NODES = 6000
#: ... and one whose polynomial degree (estimated from its tree) exceeds this.
MAX_DEGREE = 40
#: CPU seconds allowed for the symbolic step (an ITIMER_PROF timer where the platform and thread allow;
#: CPU time, not wall time, so a busy machine does not cut a right answer short: measured, the slowest
#: right answer of the course takes 0.6 s).
TIME_LIMIT = 3.0
_SEED = 20240917


def symbols(names: str):
    """The exercise's sympy symbols, plain (no assumptions), so that they equal the symbols of the
    same names a learner makes with ``sympy.symbols``.

    >>> a1, a2 = symbols("a1 a2"); a1 * a2
    a1*a2
    """
    out = sympy.symbols(names)
    return out


def unit_circle_substitution(c, s, w):
    """``{c: cos, s: sin}`` through the rational parametrisation of the unit circle by ``w``
    (``c = (1 - w²)/(1 + w²)``, ``s = 2w/(1 + w²)``), so that ``c**2 + s**2 = 1`` holds exactly."""
    return {c: (1 - w**2) / (1 + w**2), s: 2 * w / (1 + w**2)}


def unit_vector_substitution(a1, a2, a3, u, v):
    """``{a1, a2, a3}`` as a unit vector through inverse stereographic projection from ``(u, v)``,
    so that ``a1**2 + a2**2 + a3**2 = 1`` holds exactly."""
    d = 1 + u**2 + v**2
    return {a1: 2 * u / d, a2: 2 * v / d, a3: (1 - u**2 - v**2) / d}


class AnswerError(Exception):
    """The learner's answer is not something the checker can read (the message says why)."""


def _has_text(obj) -> bool:
    if isinstance(obj, (str, bytes)):
        return True
    if isinstance(obj, (list, tuple)):
        return any(_has_text(x) for x in obj)
    if isinstance(obj, np.ndarray) and obj.dtype.kind in "OUS":
        return any(_has_text(x) for x in obj.ravel().tolist())
    return False


def _fraction(v: float):
    """The fraction a float stands for: the simplest one within 1e-12 (Python's 4/3 is 4/3), else the
    float's exact decimal."""
    if not math.isfinite(v):
        raise AnswerError("contains an infinite or NaN number")
    exact = Fraction(repr(v)) if abs(v) < 1e15 else Fraction(v)
    simple = exact.limit_denominator(10**6)
    chosen = simple if abs(simple - exact) <= 1e-12 * max(1.0, abs(v)) else exact
    return sympy.Rational(chosen.numerator, chosen.denominator)


def _scalar(x):
    """One entry of an answer as a sympy object, without ever reading text."""
    if isinstance(x, sympy.Basic):
        if isinstance(x, (sympy.Eq, sympy.Ne)) or x in (sympy.true, sympy.false):
            raise AnswerError("is an equation or a truth value; give the expression itself (for an identity "
                              "lhs = rhs, the expression the exercise asks for)")
        floats = x.atoms(sympy.Float)
        if floats:  # decimals (0.5*x, or Python's 4/3) are read as the fractions they stand for
            x = x.xreplace({f: _fraction(float(f)) for f in floats})
        return x
    if isinstance(x, (bool, np.bool_)):
        raise AnswerError("is True or False: `==` compares sympy expressions by their form, not their value; "
                          "give the expression itself")
    if isinstance(x, Integral):
        return sympy.Integer(int(x))
    if isinstance(x, Fraction):
        return sympy.Rational(x.numerator, x.denominator)
    if isinstance(x, Real):
        v = float(x)
        if not math.isfinite(v):
            raise AnswerError("contains an infinite or NaN number")
        return _fraction(v)
    raise AnswerError(f"should be built from the exercise's sympy symbols; it contains a {type(x).__name__}")


def to_sympy(answer):
    """The learner's answer as a sympy expression or an immutable matrix (a list becomes a row).

    Raises :class:`AnswerError` for text (never evaluated), equations, truth values and other types.
    """
    if _has_text(answer):
        raise AnswerError("is text: the checker evaluates no text. Build it in Python from the symbols "
                          "the exercise gives you (for example a1*b2 - a2*b1), not as a string")
    if isinstance(answer, sympy.MatrixBase):
        return sympy.ImmutableMatrix(answer.shape[0], answer.shape[1], [_scalar(x) for x in answer])
    if isinstance(answer, np.ndarray):
        answer = answer.tolist()
    if isinstance(answer, (list, tuple)):
        if not answer:
            raise AnswerError("is an empty list")
        if all(isinstance(r, (list, tuple)) for r in answer):
            widths = {len(r) for r in answer}
            if len(widths) != 1:
                raise AnswerError("has rows of different lengths")
            return sympy.ImmutableMatrix([[_scalar(x) for x in r] for r in answer])
        if any(isinstance(r, (list, tuple, sympy.MatrixBase)) for r in answer):
            raise AnswerError("mixes numbers and lists")
        return sympy.ImmutableMatrix([[_scalar(x) for x in answer]])
    return _scalar(answer)


# -- bounded symbolic work -------------------------------------------------------------------------

class _Timeout(Exception):
    pass


@contextmanager
def _time_limit(seconds: float):
    """Raise _Timeout after ``seconds`` of this process's CPU time (``ITIMER_PROF``: user and system
    time, so a checker on a busy machine is not cut short because other processes had the cores)
    where ``setitimer`` is available in the main thread; otherwise rely on the size and degree bounds
    alone."""
    usable = (hasattr(signal, "setitimer") and hasattr(signal, "SIGPROF")
              and threading.current_thread() is threading.main_thread())
    if not usable:
        yield
        return

    def _raise(signum, frame):
        raise _Timeout()

    old = signal.signal(signal.SIGPROF, _raise)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)


def _nodes(expr, limit: int) -> int:
    """Tree nodes of ``expr``, counting stops once past ``limit``."""
    n = 0
    for _ in sympy.preorder_traversal(expr):
        n += 1
        if n > limit:
            break
    return n


def _degree(expr) -> float:
    """An upper estimate of the polynomial degree that expanding ``expr`` (numerator and
    denominator) would reach."""
    if expr.is_Symbol:
        return 1
    if expr.is_Number or not expr.free_symbols:
        return 0
    if expr.is_Add:
        return max(_degree(a) for a in expr.args)
    if expr.is_Mul:
        return sum(_degree(a) for a in expr.args)
    if expr.is_Pow:
        base, e = expr.args
        if e.is_Integer:
            return _degree(base) * abs(int(e))
        return _degree(base) * 2 + 2
    return sum(_degree(a) for a in expr.args) + 1


def _entries(obj):
    return list(obj) if isinstance(obj, sympy.MatrixBase) else [obj]


def _too_large(obj) -> str | None:
    for e in _entries(obj):
        if _nodes(e, MAX_NODES) > MAX_NODES:
            return f"has more than {MAX_NODES} operations"
        if _degree(e) > MAX_DEGREE:
            return f"has a degree above {MAX_DEGREE} once multiplied out"
    return None


def _draw(sym, rng):
    """A random exact value for ``sym`` that respects its assumptions (integer, positive)."""
    if sym.is_integer:
        return sympy.Integer(int(rng.integers(1 if sym.is_positive else 0, 9)))
    num = int(rng.integers(1, 10)) if sym.is_positive else int(rng.integers(-9, 10))
    return sympy.Rational(num, int(rng.integers(1, 8)))


def _points(syms, count: int, seed: int):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        yield {s: _draw(s, rng) for s in syms}


def _value(expr, point):
    """Exact value of ``expr`` at ``point``; None where it is undefined."""
    v = expr.xreplace(point)
    if v.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
        return None
    if v.free_symbols:
        return None
    if not v.is_Rational:
        try:
            f = complex(v.evalf(40))
        except (TypeError, ValueError):
            return None
        return f
    return v


def _is_zero_value(v) -> bool:
    if isinstance(v, complex):
        return abs(v) < 1e-25
    return v == 0


def _spot_diff(a, b, syms, count=SPOT_POINTS, seed=_SEED):
    """(points where a and b are both defined, points where they differ) over exact rational points."""
    used = differ = 0
    tries = 0
    for point in _points(syms, count * 4, seed):
        tries += 1
        if used >= count:
            break
        va, vb = _value(a, point), _value(b, point)
        if va is None or vb is None:
            continue
        used += 1
        if not _is_zero_value(va - vb):
            differ += 1
    return used, differ


def _same(a, b, syms, count=8) -> bool:
    """Whether a and b agree at ``count`` exact rational points (for naming slips)."""
    ea, eb = _entries(a), _entries(b)
    if len(ea) != len(eb):
        return False
    # every symbol either side uses gets a value (a slip form may use symbols the answer does not)
    syms = sorted(set(syms).union(*(x.free_symbols for x in ea + eb)), key=str)
    for x, y in zip(ea, eb):
        used, differ = _spot_diff(x, y, syms, count, seed=_SEED + 1)
        if used == 0 or differ:
            return False
    return True


def _symbolic_zero(expr) -> bool | None:
    """True if sympy shows ``expr`` is identically zero, False if it shows it is not, None if it
    cannot tell (not a rational function and simplify leaves something)."""
    syms = sorted(expr.free_symbols, key=str)
    if not syms:
        return bool(sympy.simplify(expr) == 0)
    if expr.is_rational_function(*syms):
        return sympy.cancel(sympy.together(expr)) == 0
    s = sympy.simplify(expr)
    return True if s == 0 else None


def _describe_term(term) -> str:
    """A term of a sum named by its symbols and powers, without its coefficient."""
    _, monomial = term.as_coeff_Mul()
    if not monomial.free_symbols:
        return "the constant term"
    num, den = sympy.fraction(monomial)

    def words(m):
        fs = sorted((f for f in sympy.Mul.make_args(m) if f.free_symbols), key=str)
        return "·".join(str(f).replace("**", "^").replace("*", "·") for f in fs)

    text = words(num) or "1"
    if den.free_symbols:
        d = words(den)
        text += "/" + (f"({d})" if "·" in d else d)
    return "the one in " + text


# -- the checker -----------------------------------------------------------------------------------

def check_expression(answer, expected, *, what: str, symbols, substitutions=None, slips=(),
                     success: str | None = None, ask: str | None = None) -> Result:
    """Decide whether ``answer`` is identically ``expected`` (a sympy expression or matrix).

    symbols: the symbols the exercise provides (the only ones an answer may use).  substitutions:
    a dict applied to both sides before deciding (constraints as rational parametrisations; see
    :func:`unit_vector_substitution`).  slips: ``(form, message)`` pairs, recognised wrong answers
    with the words that name them.  success: what a right answer shows (appended to "Correct").
    ask: what the "not answered yet" message asks for (default ``what``).

    Returns a :class:`~goldman_lib.exercises.Result`.  Never prints ``expected``.
    """
    if is_unanswered(answer):
        return unanswered(ask or what)
    try:
        got = to_sympy(answer)
    except AnswerError as exc:
        return wrong(f"{what} {exc}.")
    syms = tuple(symbols)
    by_name = {str(s): s for s in syms}
    exp = to_sympy(expected)
    if isinstance(exp, sympy.MatrixBase) and len(exp) == 1:
        exp = exp[0]
    # the learner's symbols by name (sympy.symbols("a1", real=True) is a different Symbol)
    free = set().union(*(e.free_symbols for e in _entries(got)))
    unknown = sorted(str(s) for s in free if str(s) not in by_name)
    if unknown:
        return wrong(f"{what} uses {', '.join(unknown)}, which {'is' if len(unknown) == 1 else 'are'} not among "
                     f"the exercise's symbols ({', '.join(by_name)}).")
    got = got.xreplace({s: by_name[str(s)] for s in free})
    # shapes
    if isinstance(exp, sympy.MatrixBase):
        if not isinstance(got, sympy.MatrixBase):
            return wrong(f"{what} should be a vector or matrix of {exp.shape[0] * exp.shape[1]} entries; "
                         "yours is a single expression.")
        if got.shape != exp.shape:
            if len(got) == len(exp) and 1 in got.shape and 1 in exp.shape:
                got = sympy.ImmutableMatrix(exp.shape[0], exp.shape[1], list(got))
            else:
                return wrong(f"{what} should have shape {exp.shape[0]}x{exp.shape[1]}; yours has shape "
                             f"{got.shape[0]}x{got.shape[1]}.")
    elif isinstance(got, sympy.MatrixBase):
        if len(got) == 1:  # a one-entry list
            got = got[0]
        else:
            return wrong(f"{what} is a single expression; yours is a matrix of shape {got.shape[0]}x{got.shape[1]}.")
    big = _too_large(got)
    if big:
        return wrong(f"{what} {big}: too large to check within the time limit. Simplify it by hand first "
                     "(cancel, collect, use the exercise's relations) and try again.")
    sub = dict(substitutions or {})
    g, e = _apply(got, sub), _apply(exp, sub)
    params = sorted(set().union(*(x.free_symbols for x in _entries(g) + _entries(e))), key=str)
    # 1. exact spot checks
    bad_entries = []
    for k, (x, y) in enumerate(zip(_entries(g), _entries(e))):
        used, differ = _spot_diff(x, y, params)
        if differ:
            bad_entries.append(k)
    if bad_entries:
        return wrong(_name_slip(what, got, exp, g, e, bad_entries, sub, params, syms, slips))
    # 2. the symbolic decision, bounded
    try:
        with _time_limit(TIME_LIMIT):
            verdicts = [_symbolic_zero(x - y) for x, y in zip(_entries(g), _entries(e))]
    except _Timeout:
        verdicts = ["timeout"]
    if all(v is True for v in verdicts):
        return correct(f"{what} is right (checked symbolically and at {SPOT_POINTS} exact rational points)"
                       + (f": {success}" if success else "."))
    if "timeout" in verdicts:
        return wrong(f"{what} agrees at {SPOT_POINTS} exact rational points, but sympy could not confirm it within "
                     f"{TIME_LIMIT:g} s. Simplify it by hand first (cancel common factors, collect terms) and try again.")
    if any(v is False for v in verdicts):
        # sympy's canonical form says it is not an identity: look harder for a witness
        k = next(i for i, v in enumerate(verdicts) if v is False)
        used, differ = _spot_diff(_entries(g)[k], _entries(e)[k], params, count=60, seed=_SEED + 7)
        return wrong(f"{what} is not identically right: it agrees at the first {SPOT_POINTS} random points "
                     + ("but not everywhere" if differ else "but its difference does not cancel to zero")
                     + ". Check it term by term.")
    return wrong(f"{what} agrees at {SPOT_POINTS} exact rational points, but sympy could not simplify the difference "
                 "to zero. Write it with the exercise's symbols only, using +, -, *, / and powers, and try again.")


def _apply(obj, sub):
    if not sub:
        return obj
    if isinstance(obj, sympy.MatrixBase):
        return obj.xreplace(sub)
    return obj.xreplace(sub)


def _name_slip(what, got, exp, g, e, bad, sub, params, syms, slips) -> str:
    """Words for what is wrong with ``got`` (exact spot checks against each recognised form)."""
    for form, message in slips:
        f = _apply(to_sympy(form), sub)
        if isinstance(f, sympy.MatrixBase) and isinstance(g, sympy.MatrixBase) and f.shape != g.shape:
            if len(f) != len(g):
                continue
            f = sympy.ImmutableMatrix(g.shape[0], g.shape[1], list(f))
        if _same(g, f, params):
            return f"{what} {message}"
    if _same(g, -e, params):
        return f"{what} differs by a sign: it is the negative of the right expression. Check the order of a " \
               "difference or a cross product."
    if _same(g, 2 * e, params):
        return f"{what} is off by a factor of 2: it is twice the right expression."
    if _same(g, e / 2, params):
        return f"{what} is off by a factor of 2: it is half the right expression."
    if isinstance(e, sympy.MatrixBase) and e.shape[0] == e.shape[1] and e.shape[0] > 1 and _same(g, e.T, params):
        return f"{what} is the transpose of the right matrix: the book writes points as rows, with the matrix " \
               "acting on the right (P M)."
    # a constant multiple?
    ratio = _constant_ratio(g, e, params)
    if ratio is not None:
        return f"{what} is a constant multiple of the right expression: check the numerical factors."
    if isinstance(e, sympy.MatrixBase) and len(e) > 1:
        n = len(e)
        places = [_place(k, e.shape) for k in bad]
        lead = (f"{len(bad)} of the {n} entries are wrong ({', '.join(places)})" if len(bad) > 1
                else f"entry {places[0]} is wrong")
        k = bad[0]
        inner = _term_slip(_entries(got)[k], _entries(exp)[k], _entries(g)[k], _entries(e)[k], sub, params)
        return f"{what}: {lead}" + (f"; entry {places[0]} {inner}" if inner else ".")
    inner = _term_slip(got, exp, g, e, sub, params)
    if inner:
        return f"{what} {inner}"
    if sub:
        return f"{what} is not identically right: check it term by term."
    return f"{what} is not identically right: {_involves(got, exp, params)}"


def _place(k, shape) -> str:
    rows, cols = shape
    if rows == 1 or cols == 1:
        return f"{k + 1}"
    return f"row {k // cols + 1}, column {k % cols + 1}"


def _constant_ratio(g, e, params):
    """The constant c with g = c e at every spot point, if there is one (c not 0, 1, -1, 2, 1/2)."""
    ge, ee = _entries(g), _entries(e)
    ratio = None
    for point in _points(params, 8, _SEED + 3):
        for x, y in zip(ge, ee):
            vx, vy = _value(x, point), _value(y, point)
            if vx is None or vy is None:
                continue
            if _is_zero_value(vy):
                if not _is_zero_value(vx):
                    return None
                continue
            r = vx / vy
            if ratio is None:
                ratio = r
            elif not _is_zero_value(r - ratio):
                return None
    if ratio is None or _is_zero_value(ratio):
        return None
    return ratio


def _term_slip(got, exp, g, e, sub, params) -> str | None:
    """A missing, doubled or sign-flipped term of the expected sum, or one extra term."""
    try:
        terms = sympy.Add.make_args(sympy.expand(exp))
    except Exception:  # pragma: no cover - expand of the exercise's own expression
        return None
    if len(terms) > 40:
        return None
    for t in terms:
        tt = _apply(t, sub)
        if _same(g, e - tt, params):
            return f"is missing a term: {_describe_term(t)}."
        if _same(g, e + tt, params):
            return f"counts a term twice: {_describe_term(t)}."
        if _same(g, e - 2 * tt, params):
            return f"has one term with the wrong sign: {_describe_term(t)}."
    if _nodes(got, 400) < 400 and _degree(got) <= 12:
        extra = sympy.Add.make_args(sympy.expand(got - exp))
        if len(extra) == 1 and extra[0] != 0:
            return f"has a term it should not have, or one with the wrong coefficient: {_describe_term(extra[0])}."
    return None


def _involves(g, e, params) -> str:
    """Which of the (substituted) parameters the difference depends on, in words."""
    diff = g - e
    base = next(iter(_points(params, 1, _SEED + 5)), {})
    moving = []
    for p in params:
        other = dict(base)
        other[p] = base[p] + (2 if p.is_integer else sympy.Rational(3, 2))
        v1, v2 = _value(diff, base), _value(diff, other)
        if v1 is None or v2 is None or not _is_zero_value(v1 - v2):
            moving.append(str(p))
    if not moving:
        return "it is off by a constant; check the constant terms."
    return f"the difference from the right expression changes with {', '.join(moving)}; check the terms in them."
