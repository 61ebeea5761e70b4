"""The symbolic checker of the "show that" exercises (goldman_lib.exercises.show_that): right answers
in several forms accepted, recognised slips named, text refused unread, huge answers bounded in time.

Expected verdicts come from algebra done by hand here ((x + y)^2 = x^2 + 2xy + y^2, the transpose,
c^2 + s^2 = 1), not from the checker.
"""

from __future__ import annotations

import time

import pytest

sympy = pytest.importorskip("sympy")

from goldman_lib.exercises import show_that as st  # noqa: E402

x, y, z = st.symbols("x y z")
SQUARE = x**2 + 2 * x * y + y**2


def check(answer, expected=SQUARE, **kw):
    kw.setdefault("what", "the square")
    kw.setdefault("symbols", (x, y, z))
    return st.check_expression(answer, expected, **kw)


@pytest.mark.parametrize("answer", [(x + y)**2, x * (x + y) + y * (x + y), [SQUARE], 1.0 * x**2 + 2.0 * x * y + y**2,
                                    sympy.Symbol("x", real=True)**2 + 2 * x * y + y**2])
def test_right_answers_in_any_form_are_accepted(answer):
    r = check(answer)
    assert r.correct and r.answered, r


@pytest.mark.parametrize("answer,words", [
    (-(x + y)**2, "differs by a sign"),
    (2 * (x + y)**2, "factor of 2"),
    ((x + y)**2 / 2, "factor of 2"),
    (3 * (x + y)**2, "constant multiple"),
    (x**2 + y**2, "missing a term: the one in x·y"),
    (x**2 + 4 * x * y + y**2, "counts a term twice: the one in x·y"),
    (x**2 + 2 * x * y - y**2, "wrong sign: the one in y^2"),
    (SQUARE + x * y * z, "should not have"),
    (x**3 + y, "not identically right"),
])
def test_slips_are_named(answer, words):
    r = check(answer)
    assert r.answered and not r.correct
    assert words in r.message, r
    assert "2*x*y" not in r.message and "x**2" not in r.message, "never print the expected expression"


def test_python_floats_are_read_as_the_fractions_they_stand_for():
    assert check((4 / 3) * x**2, sympy.Rational(4, 3) * x**2).correct
    assert check(0.1 * x + 0.2 * y, (x + 2 * y) / 10).correct
    assert not check(1.3333 * x**2, sympy.Rational(4, 3) * x**2).correct


def test_an_exercise_slip_is_named_before_the_generic_ones():
    r = check(-(x + y)**2, slips=[((-(x + y)**2), "subtracts where the rule adds.")])
    assert "subtracts where the rule adds" in r.message


def test_matrices_transpose_and_wrong_entries():
    m = sympy.Matrix([[x, y], [z, 1]])
    assert check(m, m, what="M").correct
    assert check([[x, y], [z, 1]], m, what="M").correct
    assert "transpose" in check(m.T, m, what="M").message
    r = check([[x, -y], [z, 1]], m, what="M")
    assert "row 1, column 2" in r.message and "wrong sign" in r.message
    assert "shape 2x2" in check([x, y, z], m, what="M").message
    # a vector given as a list, a row or a column is the same vector
    v = sympy.Matrix([x, y, z])
    assert check([x, y, z], v, what="v").correct and check(sympy.Matrix([[x, y, z]]), v, what="v").correct


def test_constraints_are_substituted_before_deciding():
    c, s, w = st.symbols("c s w")
    sub = st.unit_circle_substitution(c, s, w)
    r = st.check_expression(c**4 - s**4, c**2 - s**2, what="it", symbols=(c, s), substitutions=sub)
    assert r.correct, r
    assert not st.check_expression(c**4 + s**4, c**2 - s**2, what="it", symbols=(c, s), substitutions=sub).correct
    a1, a2, a3, u, v = st.symbols("a1 a2 a3 u v")
    sub = st.unit_vector_substitution(a1, a2, a3, u, v)
    assert st.check_expression(a1**2 + a2**2 + a3**2, 1, what="|a|^2", symbols=(a1, a2, a3), substitutions=sub).correct


def test_none_and_ellipsis_are_not_answered_yet():
    for answer in (None, ...):
        r = check(answer)
        assert not r.answered and r.verdict == "Not answered yet"


def test_text_is_refused_unread(monkeypatch):
    def boom(*a, **k):
        raise AssertionError("learner text was evaluated")

    monkeypatch.setattr(sympy, "sympify", boom)
    monkeypatch.setattr(sympy, "parse_expr", boom)
    for answer in ["(x + y)**2", ["x", y], [[x, "__import__('os')"]], b"x"]:
        r = check(answer, expected=sympy.Matrix([[x, y]]) if isinstance(answer, list) else SQUARE)
        assert r.answered and not r.correct and "evaluates no text" in r.message, r


@pytest.mark.parametrize("answer,words", [
    (x == y, "True or False"), (sympy.Eq(x, y), "equation"), ({"x": 1}, "dict"),
    (sympy.Symbol("q") + x, "q, which is not among"),
])
def test_other_answers_are_explained(answer, words):
    r = check(answer)
    assert r.answered and not r.correct and words in r.message, r


@pytest.mark.parametrize("answer", [
    (x + y + z)**300,                                                     # degree bound
    sympy.Add(*[x**i * y**j for i in range(40) for j in range(40)]),      # degree bound on a long sum
    sympy.Mul(*[(x + i * y + z) / (x - i * z + 1) for i in range(14)]),  # inside the bounds, still checked
])
def test_huge_answers_return_quickly(answer):
    t0 = time.process_time()     # CPU time: the suite runs beside two browsers
    r = check(answer)
    assert time.process_time() - t0 < 8 and r.answered and not r.correct


def test_spot_checks_and_simplification_must_both_agree(monkeypatch):
    # sympy could not decide (for example a function simplify cannot reduce): not accepted
    monkeypatch.setattr(st, "_symbolic_zero", lambda e: None)
    r = check((x + y)**2)
    assert not r.correct and "could not simplify" in r.message
    # sympy says "not zero" though the spot checks agree: not accepted either
    monkeypatch.setattr(st, "_symbolic_zero", lambda e: False)
    r = check((x + y)**2)
    assert not r.correct and "not identically right" in r.message


def test_the_symbolic_step_is_bounded_in_time(monkeypatch):
    def slow(e):                       # sympy stuck in a long computation: it burns CPU time
        n = 0
        while True:
            n = (n * 31 + 7) % 1000003

    monkeypatch.setattr(st, "_symbolic_zero", slow)
    monkeypatch.setattr(st, "TIME_LIMIT", 0.3)
    t0 = time.process_time()     # CPU time: the limit is ITIMER_PROF, CPU time too
    r = check((x + y)**2)
    assert time.process_time() - t0 < 3
    assert not r.correct and "could not confirm" in r.message


def test_a_spot_check_difference_is_a_proof_of_non_identity(monkeypatch):
    # even if the symbolic step (wrongly) said zero, one differing rational point rejects
    monkeypatch.setattr(st, "_symbolic_zero", lambda e: True)
    assert not check(x**2 + y**2).correct
