"""The book's "show that" exercises, checked symbolically (:mod:`goldman_lib.exercises.show_that`).

One module for every chapter's derivations, so that the chapters' numeric checkers
(``goldman_lib.exercises.chNN``) stay as they are.  An exercise is named ``chNN_topic``:

- ``PROBLEMS[name]`` is its statement (with the book section it follows);
- ``symbols_for(name)`` gives the sympy symbols, in the order the statement lists them;
- ``name(answer)`` is the checker: ``answer`` is a sympy expression (or a list / matrix of them)
  that the learner built from those symbols in their own code cell.  No text is evaluated.
- ``SLIPS[name]`` lists wrong answers of the kinds the checker names (used by the tests).

Each exercise asks for the expression one step of the proof produces, in a form where that step's
work shows (an expansion before the last simplification, a formula before numbers go in), and the
checker's verdict says what the step proves.  Checker docstrings say what is checked, never the
expression.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import sympy

from goldman_lib.exercises.show_that import (check_expression, symbols, unit_circle_substitution,
                                             unit_vector_substitution)

__all__ = ["PROBLEMS", "SLIPS", "symbols_for"]


@dataclass(frozen=True)
class _Exercise:
    name: str
    statement: str
    symbol_names: str
    build: Callable  # symbols -> dict(expected=..., slips=[(form, words)], substitutions=..., what=, success=)
    assumptions: dict = field(default_factory=dict)  # sympy assumptions, e.g. {"positive": True}


_EXERCISES: dict[str, _Exercise] = {}


def _dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def _cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def _qmul(p, q):
    """Quaternion product, (w, x, y, z) order (Goldman §15.3.1)."""
    pw, pv = p[0], list(p[1:])
    qw, qv = q[0], list(q[1:])
    w = pw * qw - _dot(pv, qv)
    v = [pw * b + qw * a + c for a, b, c in zip(pv, qv, _cross(pv, qv))]
    return [w] + v


def symbols_for(name: str):
    """The sympy symbols of exercise ``name``, in the order its statement lists them (a tuple, or
    the one symbol itself when there is only one).

    >>> symbols_for("ch09_cross_length")
    (uu, vv, uv)
    """
    if name not in _EXERCISES:
        raise ValueError(f"name must be one of the show-that exercises {sorted(_EXERCISES)}; got {name!r}")
    ex = _EXERCISES[name]
    return sympy.symbols(ex.symbol_names, **ex.assumptions) if ex.assumptions else symbols(ex.symbol_names)


def _symbol_tuple(name: str):
    syms = symbols_for(name)
    return syms if isinstance(syms, tuple) else (syms,)


def _check(name: str, answer):
    ex = _EXERCISES[name]
    syms = _symbol_tuple(name)
    spec = ex.build(*syms)
    return check_expression(answer, spec["expected"], what=spec["what"], symbols=syms,
                            substitutions=spec.get("substitutions"), slips=spec.get("slips", ()),
                            success=spec.get("success"), ask=spec.get("ask"))


def _define(name, statement, symbol_names, doc, **assumptions):
    def build(fn):
        _EXERCISES[name] = _Exercise(name, statement, symbol_names, fn, assumptions)

        def checker(answer):
            return _check(name, answer)

        checker.__name__ = checker.__qualname__ = name
        checker.__doc__ = doc + "\n\n``answer``: a sympy expression built from ``symbols_for(%r)``." % name
        globals()[name] = checker
        __all__.append(name)
        return fn
    return build


# == Chapter 1: turtle programs ====================================================================

@_define("ch01_spiral_ink", (
    "The spiral REPEAT n [FORWARD 1 TURN a RESIZE s] (s > 0, s ≠ 1) starts with step |w| = 1. Show that its "
    "ink (the total length it draws) is a geometric sum in closed form: give it in terms of s and n "
    "(n a whole number) (Goldman §1.3)."),
    "s n", "Check the ink of the spiral in closed form.", positive=True, integer=True)
def _(s, n):
    return dict(expected=(s**n - 1) / (s - 1), what="the ink",
                slips=[((s**(n + 1) - 1) / (s - 1), "adds one side too many: the last RESIZE lengthens no side, "
                        "so the sides are 1, s, ..., s^(n-1)."),
                       (s**n / (s - 1), "leaves out the -1 of the geometric sum (1 + s + ... + s^(n-1))(s - 1) "
                        "= s^n - 1."),
                       ((1 - s**n) / (s - 1), "has the sign of the numerator turned: for s > 1 the ink must be "
                        "positive."),
                       (n * s**(n - 1), "adds n copies of the last side: the sides grow by a factor s each time.")],
                success="the sides are 1, s, ..., s^(n-1), and (1 + s + ... + s^(n-1))(s - 1) = s^n - 1 telescopes.")


@_define("ch01_circle_step", (
    "REPEAT n [FORWARD d TURN 360/n] draws a regular n-gon whose vertices lie on a circle of radius r. "
    "Two neighbouring vertices and the centre make a triangle with sides r, r, d and angle 360°/n at "
    "the centre. Show how d depends on r: give d² in terms of r and c = cos(360°/n) (Goldman §1.3)."),
    "r c", "Check the square of the polygon's step.")
def _(r, c):
    return dict(expected=2 * r**2 * (1 - c), what="d²",
                slips=[(2 * r**2 * (1 + c), "has the sign of the cosine term turned: the law of cosines is "
                        "d² = r² + r² - 2 r r cos t."),
                       (r**2 * (1 - c), "loses a factor 2: both sides r² + r² count."),
                       (2 * r * (1 - c), "forgets to square r: every term of the law of cosines is a square "
                        "of a length."),
                       (2 * r**2 - c, "drops r² from the cosine term: it is 2 r r cos t.")],
                success="d² = 2r²(1 - cos t) = 4r² sin²(t/2), so d = 2r sin(180°/n): the chord, a little shorter "
                        "than the arc 2πr/n.")


# == Chapter 2: looping lemmas ====================================================================

@_define("ch02_three_steps", (
    "REPEAT 3 [FORWARD 1, TURN A] starting at the origin heading along the x-axis. Show that the turtle "
    "comes back to its start exactly when 1 + z + z² = 0 for z = cos A + i sin A (A = 120° or 240°): "
    "give its position after the three steps as [x, y] in terms of c = cos A and s = sin A (turns are "
    "counterclockwise; use cos 2A = c² − s² and sin 2A = 2cs) (Goldman §2.2)."),
    "c s", "Check the turtle's position after three steps.")
def _(c, s):
    w = symbols("w_")
    return dict(expected=sympy.Matrix([[1 + c + c**2 - s**2, s + 2 * c * s]]), what="the position",
                substitutions=unit_circle_substitution(c, s, w),
                slips=[(sympy.Matrix([[c + c**2 - s**2 + c**3 - 3 * c * s**2, s + 2 * c * s + 3 * c**2 * s - s**3]]),
                        "turns before the first step: FORWARD comes first, along the initial heading."),
                       (sympy.Matrix([[1 + c + c**2 - s**2, -s - 2 * c * s]]),
                        "turns clockwise: TURN A turns counterclockwise, so y grows with sin A."),
                       (sympy.Matrix([[1 + 2 * c, 2 * s]]), "uses the first heading twice: the third step is at angle 2A.")],
                success="the steps are 1, z, z², so the loop closes exactly when 1 + z + z² = 0, that is z³ = 1 with "
                        "z ≠ 1.")


@_define("ch02_koch_length", (
    "Each level of the Koch curve replaces every segment by 4 segments a third as long. Show that the "
    "length grows without bound: give the length after n levels, starting from one segment of length L, "
    "in terms of L and n (n a whole number) (Goldman §2.3.2)."),
    "L n", "Check the length of the Koch curve after n levels.", positive=True, integer=True)
def _(L, n):
    return dict(expected=L * sympy.Rational(4, 3)**n, what="the length",
                slips=[(L * sympy.Rational(3, 4)**n, "has the ratio upside down: 4 pieces of a third each make 4/3 "
                        "of the length."),
                       (L * (1 + n * sympy.Rational(1, 3)), "grows linearly: each level multiplies the length, it does "
                        "not add a fixed amount."),
                       (L * 4**n, "forgets that the pieces are a third as long.")],
                success="(4/3)^n L grows without bound, while the curve stays in a bounded region.")


# == Chapter 3: fractal strangeness ================================================================

@_define("ch03_dimension", (
    "A fractal made of N copies of itself, each scaled by s (0 < s < 1), has dimension D with N s^D = 1. "
    "Solve for D: give D in terms of N and s, using sympy.log (Goldman §3.2.1)."),
    "N s", "Check the dimension D of a self-similar fractal.", positive=True)
def _(N, s):
    return dict(expected=sympy.log(N) / sympy.log(1 / s), what="D",
                slips=[(sympy.log(N) / sympy.log(s), "differs by a sign: log s < 0 for s < 1; use log(1/s)."),
                       (sympy.log(1 / s) / sympy.log(N), "is upside down: taking logs of N s^D = 1 gives "
                        "log N + D log s = 0."),
                       (N * s, "is not a logarithm: D is an exponent, so solving for it takes logs.")],
                success="D = log N / log(1/s): 1 for a segment (N = 2, s = 1/2), log 4/log 3 for the Koch curve.")


@_define("ch03_finite_area", (
    "A bump fractal adds m·r^k new triangles at level k (k = 0, 1, 2, ...), each of area a·q^k, with "
    "r q < 1. Show that its total added area is finite: give the sum over all levels in terms of "
    "m, a, r, q (Goldman §3.1)."),
    "m a r q", "Check the total area added by all the levels.")
def _(m, a, r, q):
    return dict(expected=m * a / (1 - r * q), what="the total area",
                slips=[(m * a * r * q / (1 - r * q), "leaves out level 0: the sum starts at k = 0."),
                       (m * a / (1 - q), "uses only the shrinking of the area: the number of triangles grows by r too."),
                       (m * a / (1 - r) / (1 - q), "multiplies two geometric series: each level's area is "
                        "m a (r q)^k, one series with ratio r q.")],
                success="a geometric series with ratio r q < 1: finite area (8/5 of the triangle for the Koch "
                        "snowflake), though the boundary's length is infinite.")


# == Chapter 4: affine transformations =============================================================

@_define("ch04_rotation_centre", (
    "Show that a rotation by A about the origin followed by a translation by w = (w1, w2) is a rotation "
    "by A about some point Q (A ≠ 0): find the fixed point Q of P ↦ P R + w, where R is the 2x2 "
    "rotation matrix in the row convention (rows (c, s) and (−s, c), c = cos A, s = sin A). Give Q as "
    "[x, y] in terms of c, s, w1, w2 (Goldman §4.6)."),
    "c s w1 w2", "Check the centre Q of the rotation.")
def _(c, s, w1, w2):
    R = sympy.Matrix([[c, s], [-s, c]])
    w = sympy.Matrix([[w1, w2]])
    Q = w * (sympy.eye(2) - R).inv()
    Qcol = ((sympy.eye(2) - R).inv() * w.T).T
    return dict(expected=Q, what="Q", substitutions=unit_circle_substitution(c, s, symbols("w_")),
                slips=[(Qcol, "uses the column convention ((I − R)⁻¹ w): with rows, Q R + w = Q gives Q (I − R) = w."),
                       (-Q, "differs by a sign: Q R + w = Q gives Q (I − R) = w, not −w."),
                       (w / 2, "halves the translation: that is the centre only for a half-turn (A = 180°).")],
                success="Q (I − R) = w has one solution when A ≠ 0, and P R + w = Q + (P − Q) R: a rotation about Q.")


@_define("ch04_three_points", (
    "Show that there is exactly one affine map sending (0, 0), (1, 0), (0, 1) to P0, P1, P2: give its "
    "3x3 matrix in the row convention ([x, y, 1] M; the last row is the translation), in terms of "
    "x0, y0, x1, y1, x2, y2 (Goldman §4.7.3)."),
    "x0 y0 x1 y1 x2 y2", "Check the 3x3 matrix of the affine map fixed by three points.")
def _(x0, y0, x1, y1, x2, y2):
    M = sympy.Matrix([[x1 - x0, y1 - y0, 0], [x2 - x0, y2 - y0, 0], [x0, y0, 1]])
    return dict(expected=M, what="the matrix",
                slips=[(sympy.Matrix([[x1, y1, 0], [x2, y2, 0], [x0, y0, 1]]), "uses the points P1, P2 as the first "
                        "rows: the rows are the images of the vectors (1, 0) and (0, 1), P1 − P0 and P2 − P0."),
                       (sympy.Matrix([[x0, y0, 1], [x1 - x0, y1 - y0, 0], [x2 - x0, y2 - y0, 0]]),
                        "puts the translation in the first row: in the book's convention it is the last row.")],
                success="(0, 0, 1) M = P0, (1, 0, 1) M = P1 and (0, 1, 1) M = P2, and the vector rows are forced.")


# == Chapter 5: affine geometry ====================================================================

@_define("ch05_centroid", (
    "Show that the medians of a triangle meet at the centroid: the point two thirds of the way from P0 "
    "to the midpoint of P1 P2 is the same for every vertex. Give that point (one coordinate) in terms "
    "of P0, P1, P2 as an affine combination (Goldman §5.2)."),
    "P0 P1 P2", "Check the point two thirds of the way along the median from P0.")
def _(P0, P1, P2):
    M = (P1 + P2) / 2
    return dict(expected=P0 + sympy.Rational(2, 3) * (M - P0), what="the point",
                slips=[(P0 + (M - P0) / 3, "goes one third of the way: the centroid is two thirds from the vertex."),
                       (P0 + sympy.Rational(2, 3) * (P1 + P2 - P0), "uses P1 + P2 for the midpoint: the midpoint is "
                        "(P1 + P2)/2, weights summing to 1."),
                       (M, "stops at the midpoint of P1 P2.")],
                success="it is (P0 + P1 + P2)/3, symmetric in the vertices: all three medians pass through it.")


@_define("ch05_varignon", (
    "Show that the midpoints of the sides of any quadrilateral P0 P1 P2 P3 form a parallelogram: give "
    "the vector from the midpoint of P0 P1 to the midpoint of P1 P2 (one coordinate) in terms of "
    "P0, P1, P2, P3; the checker compares it with the opposite side (Goldman §5.2)."),
    "P0 P1 P2 P3", "Check the side vector of the midpoint quadrilateral.")
def _(P0, P1, P2, P3):
    return dict(expected=(P1 + P2) / 2 - (P0 + P1) / 2, what="the vector",
                slips=[(P2 - P0, "is the diagonal itself: the side of the midpoint figure is half of it."),
                       ((P0 + P1) / 2 - (P1 + P2) / 2, "differs by a sign: from the midpoint of P0 P1 to that of P1 P2."),
                       ((P1 + P2) / 2, "is the midpoint, a point: the side is a difference of two midpoints.")],
                success="it is (P2 − P0)/2, and the opposite side, from the midpoint of P3 P0 to that of P2 P3, is "
                        "(P2 − P0)/2 too: a parallelogram.")


# == Chapter 6: iterated function systems ==========================================================

@_define("ch06_fixed_point", (
    "Show that a contractive similarity P ↦ s P R + w (0 < s < 1, R a rotation by A in the row "
    "convention, rows (c, d) and (−d, c) with c = cos A, d = sin A) has one fixed point: solve "
    "P = s P R + w and give P as [x, y] in terms of s, c, d, w1, w2 (Goldman §6.2)."),
    "s c d w1 w2", "Check the fixed point of a contractive similarity.")
def _(s, c, d, w1, w2):
    R = sympy.Matrix([[c, d], [-d, c]])
    w = sympy.Matrix([[w1, w2]])
    P = w * (sympy.eye(2) - s * R).inv()
    return dict(expected=P, what="the fixed point", substitutions=unit_circle_substitution(c, d, symbols("w_")),
                slips=[(((sympy.eye(2) - s * R).inv() * w.T).T, "uses the column convention: with rows, "
                        "P (I − s R) = w."),
                       (w / (1 - s), "ignores the rotation: that is the fixed point only when A = 0."),
                       (w * (sympy.eye(2) + s * R), "keeps the first two terms of the series w (I + sR + s²R² + ...).")],
                success="the iterates converge to it from any start: the series w Σ (s R)^k converges because s < 1.")


@_define("ch06_segment_attractor", (
    "Show that the segment from A to B is the attractor of the IFS {P ↦ (P + A)/2, P ↦ (P + B)/2}: the "
    "two maps send the point (1 − t) A + t B of the segment to points of the segment. Give the two "
    "image parameters [t1, t2] (the first map's, then the second's) in terms of t (Goldman §6.3)."),
    "t", "Check the parameters of the images of a point of the segment.")
def _(t):
    return dict(expected=sympy.Matrix([[t / 2, (1 + t) / 2]]), what="[t1, t2]",
                slips=[(sympy.Matrix([[(1 + t) / 2, t / 2]]), "swaps the maps: the first pulls toward A, where t = 0."),
                       (sympy.Matrix([[(1 - t) / 2, (2 - t) / 2]]), "measures from B: the parameter t is 0 at A."),
                       (sympy.Matrix([[t / 2, t / 2 + 1]]), "goes past B: the second map halves the distance to B.")],
                success="the images cover [0, 1/2] and [1/2, 1]: together the whole segment, so it is the attractor.")


# == Chapter 7: fixed-point theorem ================================================================

@_define("ch07_newton_derivative", (
    "Newton's method iterates g(x) = x − f(x)/f'(x). Show that it converges fast near a simple root: "
    "give g'(x) in terms of f0 = f(x), f1 = f'(x), f2 = f''(x); at a root f0 = 0, so g' = 0 there "
    "(Goldman §7.3.1)."),
    "f0 f1 f2", "Check g'(x) for Newton's iteration.")
def _(f0, f1, f2):
    return dict(expected=f0 * f2 / f1**2, what="g'(x)",
                slips=[(-f0 * f2 / f1**2, "differs by a sign: check the sign of the second term of the quotient rule."),
                       (sympy.Integer(0), "is g' at the root only: away from the root f(x) ≠ 0; differentiate "
                        "x − f/f' with the quotient rule."),
                       (f0 * f2 / f1**2 - 1, "forgets the derivative of x itself, which is 1.")],
                success="g'(x) = f f''/f'², zero at a simple root: the error squares at each step.")


@_define("ch07_jacobi_fixed_point", (
    "For the system a11 x + a12 y = b1, a21 x + a22 y = b2, the Jacobi map is "
    "(x, y) ↦ ((b1 − a12 y)/a11, (b2 − a21 x)/a22). Show that its fixed point solves the system: give "
    "the fixed point's x in terms of a11, a12, a21, a22, b1, b2 (Goldman §7.3.2)."),
    "a11 a12 a21 a22 b1 b2", "Check the x of the Jacobi map's fixed point.")
def _(a11, a12, a21, a22, b1, b2):
    det = a11 * a22 - a12 * a21
    return dict(expected=(b1 * a22 - a12 * b2) / det, what="x",
                slips=[((b2 * a11 - a21 * b1) / det, "is y: Cramer's rule for x replaces the first column by b."),
                       ((b1 * a22 - a12 * b2) / (a11 * a22 + a12 * a21), "adds in the determinant: it is "
                        "a11 a22 − a12 a21."),
                       (b1 / a11, "is one Jacobi step from y = 0: the fixed point needs both equations at once.")],
                success="a fixed point of the Jacobi map satisfies both equations: it is the solution (Cramer's rule).")


# == Chapter 8: turtles and conformal IFS ==========================================================

@_define("ch08_change_state", (
    "A turtle program drawn from the state (P, w) (position P, heading w, complex numbers) draws, from "
    "the state (Q, v), the image of its figure under the conformal map z ↦ Q + (v/w)(z − P). Give the "
    "image of the point z = x + i y as [real part, imaginary part] in terms of x, y, px, py, wx, wy, "
    "qx, qy, vx, vy (Goldman §8.2)."),
    "x y px py wx wy qx qy vx vy", "Check the image of a point when the turtle's initial state changes.")
def _(x, y, px, py, wx, wy, qx, qy, vx, vy):
    def mul(a, b):
        return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])

    def div(a, b):
        d = b[0]**2 + b[1]**2
        return ((a[0] * b[0] + a[1] * b[1]) / d, (a[1] * b[0] - a[0] * b[1]) / d)

    def parts(z):
        return sympy.Matrix([list(z)])

    zp = (x - px, y - py)
    img = tuple(q + m for q, m in zip((qx, qy), mul(div((vx, vy), (wx, wy)), zp)))
    inv = tuple(q + m for q, m in zip((qx, qy), mul(div((wx, wy), (vx, vy)), zp)))
    conj = tuple(q + m / (wx**2 + wy**2) for q, m in zip((qx, qy), mul(mul((vx, vy), (wx, wy)), zp)))
    noP = tuple(q + m for q, m in zip((qx, qy), mul(div((vx, vy), (wx, wy)), (x, y))))
    return dict(expected=parts(img), what="the image",
                slips=[(parts(inv), "uses w/v: the map turns and scales the heading w into v, so it multiplies by v/w."),
                       (parts(conj), "multiplies by v w/|w|²: dividing by w multiplies by its conjugate."),
                       (parts(noP),
                        "forgets to subtract P: the figure is moved from P to Q.")],
                success="z ↦ Q + (v/w)(z − P) sends P to Q and turns w into v: a conformal map.")


@_define("ch08_compose", (
    "Show that the composite of two conformal maps is conformal: with w1(z) = a1 z + b1 and "
    "w2(z) = a2 z + b2 (complex, a = ax + i ay, b = bx + i by), w2(w1(z)) = A z + B. Give B as "
    "[real, imaginary] in terms of a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y (Goldman §8.3)."),
    "a1x a1y b1x b1y a2x a2y b2x b2y", "Check the translation part B of w2(w1(z)).")
def _(a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y):
    def mul(ax, ay, bx, by):
        return ax * bx - ay * by, ax * by + ay * bx
    re, im = mul(a2x, a2y, b1x, b1y)
    wre, wim = mul(a1x, a1y, b2x, b2y)
    return dict(expected=sympy.Matrix([[re + b2x, im + b2y]]), what="B",
                slips=[(sympy.Matrix([[wre + b1x, wim + b1y]]), "is the translation of w1(w2(z)): the first map "
                        "applied is w1, so a2 multiplies b1."),
                       (sympy.Matrix([[b1x + b2x, b1y + b2y]]), "adds the translations: w2 also turns and scales b1."),
                       (sympy.Matrix([[a2x * b1x + a2y * b1y + b2x, a2x * b1y - a2y * b1x + b2y]]),
                        "multiplies by the conjugate of a2: (a2x + i a2y)(b1x + i b1y) has real part a2x b1x − a2y b1y.")],
                success="A = a2 a1 and B = a2 b1 + b2: again z ↦ A z + B, a conformal map.")


# == Chapter 9: coordinate-free vector geometry =====================================================

@_define("ch09_perpendicular_part", (
    "Show that v minus its projection on u is perpendicular to u, and find its length. With "
    "k = (u·v)/(u·u), expand |v − k u|² = (v − k u)·(v − k u) by the rules of the dot product and "
    "give it in terms of the scalars uu = u·u, uv = u·v, vv = v·v (Goldman §9.4.1)."),
    "uu uv vv", "Check |v − k u|², the squared length of the part of v perpendicular to u.")
def _(uu, uv, vv):
    k = uv / uu
    return dict(expected=vv - 2 * k * uv + k**2 * uu, what="|v − k u|²",
                slips=[(vv - 2 * uv**2 / uu, "is missing the k²(u·u) term: (v − k u)·(v − k u) has four products, "
                        "and k u · k u = k²(u·u)."),
                       (vv - uv**2 / uu**2, "divides by (u·u)² where one factor of u·u cancels: k²(u·u) = (u·v)²/(u·u)."),
                       (vv - uv**2, "treats k as u·v: the projection divides by u·u (u is not a unit vector).")],
                success="and (v − k u)·u = u·v − k(u·u) = 0, so v − k u is the part of v perpendicular to u.")


@_define("ch09_cross_length", (
    "Show that the area of the parallelogram on u and v can be computed from dot products alone: "
    "from |u × v| = |u||v| sin θ and u·v = |u||v| cos θ, give |u × v|² in terms of uu = u·u, "
    "vv = v·v and uv = u·v only (no angle) (Goldman §9.4.2)."),
    "uu vv uv", "Check |u × v|² written with dot products only.")
def _(uu, vv, uv):
    return dict(expected=uu * vv - uv**2, what="|u × v|²",
                slips=[(uu * vv + uv**2, "uses sin²θ = 1 + cos²θ: the identity is sin²θ = 1 − cos²θ."),
                       (uu * vv - uv, "subtracts u·v where its square belongs: |u|²|v|² cos²θ = (u·v)²."),
                       (uv**2 - uu * vv, "differs by a sign: a squared length cannot be negative; check sin²θ = 1 − cos²θ.")],
                success="|u × v|² = |u|²|v|²(1 − cos²θ): the area of the parallelogram from dot products alone.")


# == Chapter 10: coordinates ========================================================================

@_define("ch10_cross_product", (
    "Show that u × v is perpendicular to both u and v. Write u × v in coordinates as "
    "[x, y, z] from u = (u1, u2, u3) and v = (v1, v2, v3) by the determinant rule; the checker then "
    "expands (u × v)·u and (u × v)·v (Goldman §10.3.2)."),
    "u1 u2 u3 v1 v2 v3", "Check the coordinates of u × v.")
def _(u1, u2, u3, v1, v2, v3):
    u, v = [u1, u2, u3], [v1, v2, v3]
    c = _cross(u, v)
    return dict(expected=sympy.Matrix([c]), what="u × v",
                slips=[(sympy.Matrix([_cross(v, u)]), "is v × u: the cross product changes sign when the factors swap."),
                       (sympy.Matrix([[c[0], -c[1], c[2]]]), "has the middle coordinate's sign flipped: the "
                        "determinant rule subtracts the middle minor (u3 v1 − u1 v3, not u1 v3 − u3 v1)."),
                       (sympy.Matrix([[u2 * v3 + u3 * v2, u3 * v1 + u1 * v3, u1 * v2 + u2 * v1]]),
                        "adds the two products of each minor: each coordinate is a difference of products.")],
                success="(u × v)·u and (u × v)·v both expand to 0 term by term: u × v is perpendicular to u and v.")


@_define("ch10_triple_cross", (
    "Show that the cross product is not associative: (u × v) × w lies in the plane of u and v, "
    "while u × (v × w) lies in the plane of v and w. Compute (u × v) × w in coordinates from "
    "u = (u1, u2, u3), v = (v1, v2, v3), w = (w1, w2, w3) and give it as [x, y, z]; then look for "
    "the dot products in your coordinates (Goldman §10.3.2)."),
    "u1 u2 u3 v1 v2 v3 w1 w2 w3", "Check the coordinates of (u × v) × w.")
def _(u1, u2, u3, v1, v2, v3, w1, w2, w3):
    u, v, w = [u1, u2, u3], [v1, v2, v3], [w1, w2, w3]
    e = _cross(_cross(u, v), w)
    other = _cross(u, _cross(v, w))
    return dict(expected=sympy.Matrix([e]), what="(u × v) × w",
                slips=[(sympy.Matrix([other]), "is u × (v × w) = (u·w) v − (u·v) w: the cross product is not "
                        "associative, so the brackets matter."),
                       (sympy.Matrix([_cross(w, _cross(u, v))]), "is w × (u × v): swapping the factors of the "
                        "outer cross product flips the sign.")],
                success="it is (u·w) v − (v·w) u, while u × (v × w) = (u·w) v − (u·v) w: not associative.")


# == Chapter 11: applications ======================================================================

@_define("ch11_triangle_area", (
    "Show that the shoelace sum ½[(x0 y1 − x1 y0) + (x1 y2 − x2 y1) + (x2 y0 − x0 y2)] is the "
    "signed area of the triangle P0 P1 P2, half the cross product (P1 − P0) × (P2 − P0) in the plane. "
    "Give the signed area (positive counterclockwise) from the cross-product formula, in terms of "
    "x0, y0, x1, y1, x2, y2 (Goldman §11.4.2.1)."),
    "x0 y0 x1 y1 x2 y2", "Check the signed area of the triangle P0 P1 P2.")
def _(x0, y0, x1, y1, x2, y2):
    area = ((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)) / 2
    return dict(expected=area, what="the signed area",
                slips=[(2 * area, "is the parallelogram's area: a triangle is half of it."),
                       (-area, "has the clockwise sign: (P1 − P0) × (P2 − P0) is positive counterclockwise."),
                       (((x1 - x0) * (y2 - y0) + (x2 - x0) * (y1 - y0)) / 2,
                        "adds the two products: the 2D cross product is a difference (a determinant).")],
                success="it equals the shoelace sum term by term: the area does not depend on where the origin is.")


@_define("ch11_line_intersection", (
    "Two lines in the plane, P + s u and Q + t v with u × v ≠ 0, meet where P + s u = Q + t v. "
    "Find s by crossing both sides with a vector that removes t (in the plane a × b = "
    "a1 b2 − a2 b1). Give s in terms of p1, p2, u1, u2, q1, q2, v1, v2 (Goldman §11.5.1)."),
    "p1 p2 u1 u2 q1 q2 v1 v2", "Check the parameter s of the intersection point on the line P + s u.")
def _(p1, p2, u1, u2, q1, q2, v1, v2):
    def cr(a, b):
        return a[0] * b[1] - a[1] * b[0]
    d = [q1 - p1, q2 - p2]
    return dict(expected=cr(d, [v1, v2]) / cr([u1, u2], [v1, v2]), what="s",
                slips=[(cr(d, [u1, u2]) / cr([u1, u2], [v1, v2]), "is the parameter t on the other line "
                        "(crossing with u removes s, not t): cross both sides with v."),
                       (cr(d, [v1, v2]) / cr([v1, v2], [u1, u2]), "divides by v × u: crossing s u with v gives "
                        "s (u × v).")],
                success="crossing with v removes t (v × v = 0): s = ((Q − P) × v)/(u × v), defined when the lines "
                        "are not parallel.")


# == Chapter 12: affine and projective formulas =====================================================

@_define("ch12_rodrigues_length", (
    "Show that Rodrigues' formula R(v) = cos θ v + (1 − cos θ)(a·v) a + sin θ (a × v), a a unit "
    "vector, preserves length. Expand |R(v)|² = R(v)·R(v) into its six dot products, use "
    "v·(a × v) = a·(a × v) = 0 and |a × v|² = |v|² − (a·v)², and give |R(v)|² in terms of "
    "c = cos θ, s = sin θ, p = a·v and n = |v|² *before* using c² + s² = 1 "
    "(Goldman §12.3.2)."),
    "c s p n", "Check |R(v)|² expanded, before c² + s² = 1 is used.")
def _(c, s, p, n):
    expected = c**2 * n + (1 - c)**2 * p**2 + 2 * c * (1 - c) * p**2 + s**2 * (n - p**2)
    return dict(expected=expected, what="|R(v)|²",
                slips=[(n, "is the end of the proof: give the expansion before using c² + s² = 1, so that the "
                        "check sees the steps (it should still contain c and s)."),
                       (c**2 * n + (1 - c)**2 * p**2 + s**2 * (n - p**2),
                        "is missing the two cross products of the cos θ v part with "
                        "the (1 − cos θ)(a·v) a part."),
                       (c**2 * n + (1 - c)**2 * p**2 + 2 * c * (1 - c) * p**2 + s**2 * n,
                        "uses |a × v|² = |v|²: it is |v|² sin² of the angle between a and v, that is |v|² − (a·v)².")],
                success="it is (c² + s²)|v|² + (1 − c² − s²)(a·v)², which is |v|² because c² + s² = 1: "
                        "rotation keeps length.")


@_define("ch12_perspective_formula", (
    "Derive the perspective image P' of a point P from the eye E on the plane through Q with normal "
    "N: intersect the line E + t(P − E) with the plane (X − Q)·N = 0, solve for t, and give P' as "
    "[x, y, z] in terms of p1, p2, p3, e1, e2, e3, q1, q2, q3, n1, n2, n3 (Goldman §12.5.2)."),
    "p1 p2 p3 e1 e2 e3 q1 q2 q3 n1 n2 n3", "Check the coordinates of the perspective image P'.")
def _(p1, p2, p3, e1, e2, e3, q1, q2, q3, n1, n2, n3):
    P, E, Q, N = [p1, p2, p3], [e1, e2, e3], [q1, q2, q3], [n1, n2, n3]
    t = _dot([a - b for a, b in zip(Q, E)], N) / _dot([a - b for a, b in zip(P, E)], N)
    img = [e + t * (p - e) for p, e in zip(P, E)]
    t_inv = 1 / t
    t_pq = _dot([a - b for a, b in zip(P, Q)], N) / _dot([a - b for a, b in zip(P, E)], N)
    return dict(expected=sympy.Matrix([img]), what="P'",
                slips=[(sympy.Matrix([[e + t_inv * (p - e) for p, e in zip(P, E)]]),
                        "uses t upside down: the plane condition gives t = ((Q − E)·N)/((P − E)·N)."),
                       (sympy.Matrix([[e + t_pq * (p - e) for p, e in zip(P, E)]]),
                        "uses (P − Q)·N in t: the plane condition (E + t(P − E) − Q)·N = 0 gives (Q − E)·N."),
                       (sympy.Matrix([[e - t * (p - e) for p, e in zip(P, E)]]),
                        "walks from E away from P: the image lies on E + t(P − E), on the side of P.")],
                success="P' = ((P − Q)·N E + (Q − E)·N P)/((P − E)·N), Goldman's formula: on the line EP and on the "
                        "plane, undefined exactly when EP is parallel to the plane.")


# == Chapter 13: matrices ==========================================================================

@_define("ch13_translation_row", (
    "An affine map with linear part L (3x3, rows act on the right, P ↦ P L + w) fixes the point Q. "
    "Find its translation row w, and show that the map is L acting about Q. Give w as [x, y, z] in "
    "terms of q1, q2, q3 and the entries l11 ... l33 of L (row i, column j is lij) (Goldman §13.2.2)."),
    "q1 q2 q3 l11 l12 l13 l21 l22 l23 l31 l32 l33", "Check the translation row w of a map fixing Q.")
def _(q1, q2, q3, l11, l12, l13, l21, l22, l23, l31, l32, l33):
    Q = sympy.Matrix([[q1, q2, q3]])
    L = sympy.Matrix([[l11, l12, l13], [l21, l22, l23], [l31, l32, l33]])
    return dict(expected=Q - Q * L, what="the translation row w",
                slips=[(Q - (L * Q.T).T, "uses L Q (a column vector times L from the left): the book's points are rows, "
                        "so Q maps to Q L."),
                       (Q * L - Q, "differs by a sign: Q L + w = Q gives w = Q − Q L."),
                       (Q, "forgets the linear part: Q L + w = Q, so w = Q − Q L is Q only when L is the identity.")],
                success="w = Q − Q L, and every P maps to P L + Q − Q L = Q + (P − Q) L: L acting about Q.")


@_define("ch13_mirror_linear_part", (
    "The mirror in a plane with unit normal n = (n1, n2, n3) sends a vector v to v − 2 (v·n) n. "
    "Find its linear part M (row vectors: v ↦ v M) and show that M M = I. Give M as a 3x3 matrix "
    "(a list of rows) in terms of n1, n2, n3 (Goldman §13.3.3)."),
    "n1 n2 n3", "Check the 3x3 linear part of the mirror in the plane with unit normal n.")
def _(n1, n2, n3):
    n = sympy.Matrix([[n1, n2, n3]])
    I3 = sympy.eye(3)
    return dict(expected=I3 - 2 * n.T * n, what="M",
                substitutions=unit_vector_substitution(n1, n2, n3, *symbols("u_ v_")),
                slips=[(I3 - n.T * n, "is the orthogonal projection onto the plane: the mirror goes twice as far, "
                        "v − 2 (v·n) n."),
                       (2 * n.T * n - I3, "is the half-turn about the normal line (its negative): the mirror keeps "
                        "the plane's directions and reverses n."),
                       (I3 + 2 * n.T * n, "adds the normal part: the mirror subtracts 2 (v·n) n.")],
                success="M = I − 2 nᵀn: symmetric, n M = −n, vectors in the plane kept, and "
                        "M M = I − 4 nᵀn + 4 nᵀ(n nᵀ)n = I because n nᵀ = 1.")


# == Chapter 14: projective space and mass-points ===================================================

@_define("ch14_law_of_the_lever", (
    "Show that the sum of the mass-points (m1 P1, m1) and (m2 P2, m2) (m1 + m2 ≠ 0) sits where the "
    "law of the lever balances it: m1 (P − P1) + m2 (P − P2) = 0. On a line (coordinates x1, x2), "
    "give the position x of the sum in terms of m1, x1, m2, x2 (Goldman §14.3, §14.4.1)."),
    "m1 x1 m2 x2", "Check the position of the sum of two mass-points on a line.")
def _(m1, x1, m2, x2):
    return dict(expected=(m1 * x1 + m2 * x2) / (m1 + m2), what="x",
                slips=[((m2 * x1 + m1 * x2) / (m1 + m2), "puts each mass at the other end: the heavier mass pulls "
                        "the balance point toward itself."),
                       (m1 * x1 + m2 * x2, "is the mass-point's first coordinate (its moment), not a "
                        "point: divide by the total mass."),
                       ((x1 + x2) / 2, "is the midpoint: it ignores the masses.")],
                success="m1 (x − x1) + m2 (x − x2) = 0: the lever balances, and x lies on the line through x1 and x2.")


@_define("ch14_perspective_keeps_lines", (
    "A projective map (a perspective) sends P and R to the mass-points (w0 P', w0) and (w1 R', w1). "
    "Show that it keeps lines straight: the image of (1 − t) P + t R is the sum (1 − t)(w0 P', w0) + "
    "t (w1 R', w1), which is the point (1 − τ) P' + τ R' of the line P'R'. Give τ in terms of t, w0 "
    "and w1 (Goldman §14.4.1)."),
    "t w0 w1", "Check the parameter τ of the image on the image line P'R'.")
def _(t, w0, w1):
    return dict(expected=t * w1 / ((1 - t) * w0 + t * w1), what="τ",
                slips=[(t, "keeps the parameter: an affine map would, but a perspective changes it by the masses."),
                       (t * w0 / ((1 - t) * w0 + t * w1), "weights R' by P's mass: the mass at R' is t w1."),
                       (t * w1 / (w0 + w1), "normalises by w0 + w1: the total mass is (1 − t) w0 + t w1.")],
                success="every point of the segment PR lands on the line P'R' (lines stay straight), but τ ≠ t "
                        "unless w0 = w1: a perspective does not keep ratios along a line.")


# == Chapter 15: quaternions =======================================================================

@_define("ch15_sandwich_is_pure", (
    "Show that q v q* is a pure vector (scalar part 0) for any quaternion q = (w, x, y, z) and pure "
    "v = (0, v1, v2, v3), q* = (w, −x, −y, −z). Multiply it out with the product rule "
    "(a, a⃗)(b, b⃗) = (ab − a⃗·b⃗, a b⃗ + b a⃗ + a⃗ × b⃗) and give q v q* as [w, x, y, z] in terms of "
    "w, x, y, z, v1, v2, v3 (Goldman §15.3.2)."),
    "w x y z v1 v2 v3", "Check the four components of q v q*.")
def _(w, x, y, z, v1, v2, v3):
    q, v, qc = [w, x, y, z], [0, v1, v2, v3], [w, -x, -y, -z]
    e = _qmul(_qmul(q, v), qc)
    return dict(expected=sympy.Matrix([e]), what="q v q*",
                slips=[(sympy.Matrix([_qmul(q, v)]), "is the one-sided product q v: its scalar part is "
                        "minus a dot product, not 0; the conjugate on the right cancels it."),
                       (sympy.Matrix([_qmul(_qmul(qc, v), q)]), "is q* v q: it rotates the other way."),
                       (sympy.Matrix([_qmul(_qmul(q, v), q)]), "multiplies by q on both sides: the right-hand "
                        "factor is the conjugate q*.")],
                success="its scalar part cancels identically: q v q* is a pure vector (of length |q|²|v|).")


@_define("ch15_one_sided_not_pure", (
    "Show that the one-sided product q v is not a pure vector in general. For q = (w, x, y, z) and "
    "pure v = (0, v1, v2, v3), give the scalar part of q v in terms of w, x, y, z, v1, v2, v3 "
    "(Goldman §15.3.1)."),
    "w x y z v1 v2 v3", "Check the scalar part of the product q v.")
def _(w, x, y, z, v1, v2, v3):
    return dict(expected=_qmul([w, x, y, z], [0, v1, v2, v3])[0], what="the scalar part of q v",
                slips=[(x * v1 + y * v2 + z * v3, "differs by a sign: i·i = j·j = k·k = −1, so the vector parts "
                        "contribute minus their dot product."),
                       (w * 0 - (x * v1 + y * v2 + z * v3) + w, "keeps w: v has scalar part 0, so w·0 drops out."),
                       (sympy.Integer(0), "is 0, which holds only when the vector part of q is perpendicular to v.")],
                success="it is −(x v1 + y v2 + z v3), nonzero unless (x, y, z) ⊥ v: q v leaves the pure vectors, "
                        "which is why a rotation needs the sandwich q v q*.")


# == Chapter 16: color and intensity ==============================================================

@_define("ch16_lambert", (
    "Show that the diffuse (Lambert) term does not depend on where the eye is. With the unit normal "
    "N = (n1, n2, n3), the unit direction to the light L = (l1, l2, l3), the unit direction to the eye "
    "E = (e1, e2, e3), the light's intensity I and the diffuse coefficient kd, give the diffuse "
    "intensity (Goldman §16.4)."),
    "n1 n2 n3 l1 l2 l3 e1 e2 e3 I kd", "Check the diffuse intensity.")
def _(n1, n2, n3, l1, l2, l3, e1, e2, e3, I, kd):
    N, L, E = [n1, n2, n3], [l1, l2, l3], [e1, e2, e3]
    R = [2 * _dot(N, L) * n - l for n, l in zip(N, L)]
    return dict(expected=kd * I * _dot(N, L), what="the diffuse intensity",
                slips=[(kd * I * _dot(N, E), "uses the eye's direction: diffuse light is scattered equally in every "
                        "direction, so only the light's angle to the surface counts."),
                       (kd * I * _dot(R, E), "is the specular term's cosine (R·E): the diffuse term uses N·L."),
                       (kd * I * _dot(N, L) * _dot(N, E), "multiplies by N·E: the apparent area of a patch and the "
                        "light it sends toward the eye cancel (Lambert's law).")],
                success="kd I (N·L): no e in it, the same from every viewpoint.")


@_define("ch16_mirror_unit", (
    "The specular term uses the mirror direction R = 2 (N·L) N − L of the light direction L about the "
    "normal N. Show that R is a unit vector when N and L are: expand |R|² = R·R and give it in terms of "
    "d = N·L, nn = N·N and ll = L·L, *before* using nn = ll = 1 (Goldman §16.5)."),
    "d nn ll", "Check |R|² expanded, before |N| = |L| = 1 is used.")
def _(d, nn, ll):
    return dict(expected=4 * d**2 * nn - 4 * d**2 + ll, what="|R|²",
                slips=[(4 * d**2 * nn + ll, "is missing the cross terms: (2dN − L)·(2dN − L) has two products "
                        "of 2dN with −L."),
                       (4 * d**2 * nn - 2 * d**2 + ll, "counts the cross term once: 2dN·(−L) appears twice."),
                       (sympy.Integer(1), "is the end of the proof: give the expansion before using nn = ll = 1, so "
                        "the check sees the step (it should still contain d).")],
                success="4d²(nn − 1) + ll, which is 1 when N and L are unit vectors: R is a unit vector, and R·N = N·L "
                        "gives the same angle with the normal.")


# == Chapter 17: ray tracing =======================================================================

@_define("ch17_reflected_ray", (
    "A ray travelling in direction v hits a mirror with unit normal n and leaves along r = v − 2 (v·n) n. "
    "Show that the angle of incidence equals the angle of reflection: give r·n (for the checker, as an "
    "expression) in terms of v1, v2, v3, n1, n2, n3 (Goldman §17.4)."),
    "v1 v2 v3 n1 n2 n3", "Check r·n for the reflected ray.")
def _(v1, v2, v3, n1, n2, n3):
    v, n = [v1, v2, v3], [n1, n2, n3]
    sub = unit_vector_substitution(n1, n2, n3, *symbols("u_ w_"))
    return dict(expected=_dot([a - 2 * _dot(v, n) * b for a, b in zip(v, n)], n), what="r·n", substitutions=sub,
                slips=[(_dot(v, n), "has the sign of v·n: the reflected ray leaves the surface on the side v arrived from."),
                       (_dot(v, n) - 2 * _dot(v, n) * _dot(v, v), "uses n·n = v·v: n is a unit vector, n·n = 1."),
                       (sympy.Integer(0), "says r lies in the mirror: only the normal component is reversed, "
                        "not removed.")],
                success="r·n = v·n − 2(v·n)(n·n) = −v·n because n·n = 1, and r − v is along n: the angles are equal.")


@_define("ch17_refraction_tangent", (
    "Snell's law η1 sin θ1 = η2 sin θ2 keeps the refracted ray in the plane of v and n. Show that the "
    "tangential part of the refracted unit direction t is (η1/η2) times the tangential part of the "
    "incident unit direction v: give t's tangential part t − (t·n) n as [x, y, z] in terms of "
    "v1, v2, v3, n1, n2, n3, eta1, eta2 (n a unit normal) (Goldman §17.5)."),
    "v1 v2 v3 n1 n2 n3 eta1 eta2", "Check the tangential part of the refracted direction.")
def _(v1, v2, v3, n1, n2, n3, eta1, eta2):
    v, n = [v1, v2, v3], [n1, n2, n3]
    tan = [a - _dot(v, n) * b for a, b in zip(v, n)]
    sub = unit_vector_substitution(n1, n2, n3, *symbols("u_ w_"))
    return dict(expected=sympy.Matrix([[eta1 / eta2 * x for x in tan]]), what="the tangential part",
                substitutions=sub,
                slips=[(sympy.Matrix([[eta2 / eta1 * x for x in tan]]), "uses η2/η1: from η1 sin θ1 = η2 sin θ2, "
                        "the new sine is the old one times η1/η2."),
                       (sympy.Matrix([[eta1 / eta2 * x for x in v]]), "scales all of v: only the part along the "
                        "surface scales; the normal part is fixed by |t| = 1."),
                       (sympy.Matrix([tan]), "does not bend the ray: that holds only when η1 = η2.")],
                success="|tangential part| = sin θ2 = (η1/η2) sin θ1, in the plane of v and n: Snell's law.")


# == Chapter 18: surfaces ==========================================================================

@_define("ch18_parametric_normal", (
    "Show that P_u × P_v is normal to the parametric surface P(u, v) = (u, v, u² + v²) (a paraboloid): "
    "give P_u × P_v as [x, y, z] in terms of u, v; the checker confirms it is perpendicular to both "
    "tangents (Goldman §18.2.2)."),
    "u v", "Check the normal P_u × P_v of the paraboloid.")
def _(u, v):
    Pu, Pv = [1, 0, 2 * u], [0, 1, 2 * v]
    return dict(expected=sympy.Matrix([_cross(Pu, Pv)]), what="P_u × P_v",
                slips=[(sympy.Matrix([_cross(Pv, Pu)]), "is P_v × P_u: the order of the factors flips the normal "
                        "(the book's normal points up here)."),
                       (sympy.Matrix([[-2 * u, -2 * v, 0]]), "drops the z-component: the cross product of (1, 0, ·) and "
                        "(0, 1, ·) has z = 1.")],
                success="(−2u, −2v, 1): its dot product with P_u = (1, 0, 2u) and with P_v = (0, 1, 2v) is 0.")


@_define("ch18_gaussian_curvature", (
    "For the surface z = f(u, v) the Gaussian curvature is K = (f_uu f_vv − f_uv²)/(1 + f_u² + f_v²)². "
    "Show that the paraboloid z = u² + v² is curved most at its vertex: give K in terms of u, v "
    "(Goldman §18.4.2)."),
    "u v", "Check the Gaussian curvature of the paraboloid.")
def _(u, v):
    return dict(expected=4 / (1 + 4 * u**2 + 4 * v**2)**2, what="K",
                slips=[(4 / (1 + 4 * u**2 + 4 * v**2), "drops the square of the denominator: (1 + f_u² + f_v²)²."),
                       (4 / (1 + 2 * u**2 + 2 * v**2)**2, "uses f_u = u: the derivative of u² is 2u, squared 4u²."),
                       (sympy.Integer(4), "uses only the numerator: the curvature is 4 at the vertex and falls off.")],
                success="K = 4/(1 + 4u² + 4v²)², largest (4) at the vertex and positive everywhere.")


# == Chapter 19: simple surfaces ===================================================================

@_define("ch19_ray_sphere", (
    "Substitute the ray P + t v into the sphere |X − C|² = r² and show that the intersections are the "
    "roots of a quadratic a t² + b t + c = 0. Give [a, b, c] in terms of p1, p2, p3, v1, v2, v3, "
    "c1, c2, c3, r (Goldman §19.4.1)."),
    "p1 p2 p3 v1 v2 v3 c1 c2 c3 r", "Check the coefficients [a, b, c] of the ray-sphere quadratic.")
def _(p1, p2, p3, v1, v2, v3, c1, c2, c3, r):
    v, w = [v1, v2, v3], [p1 - c1, p2 - c2, p3 - c3]
    return dict(expected=sympy.Matrix([[_dot(v, v), 2 * _dot(v, w), _dot(w, w) - r**2]]), what="[a, b, c]",
                slips=[(sympy.Matrix([[_dot(v, v), _dot(v, w), _dot(w, w) - r**2]]), "is missing the factor 2 in b: expand the "
                        "square of a sum."),
                       (sympy.Matrix([[_dot(v, v), 2 * _dot(v, w), _dot(w, w) + r**2]]), "adds r²: moving r² to the "
                        "left subtracts it."),
                       (sympy.Matrix([[1, 2 * _dot(v, w), _dot(w, w) - r**2]]), "takes a = 1: that needs a unit direction; "
                        "here v is any vector.")],
                success="two real roots, one or none as b² − 4ac is positive, zero or negative: hit, graze or miss.")


@_define("ch19_inversion", (
    "Show how to find the parameter of a point on a line: if X = P + t v lies on the line, then "
    "t is recovered from X by a dot product. Give t in terms of the coordinates of X, P and v "
    "(x1, x2, x3, p1, p2, p3, v1, v2, v3) (Goldman §19.4.1.2)."),
    "x1 x2 x3 p1 p2 p3 v1 v2 v3", "Check the parameter t of a point X on the line P + t v.")
def _(x1, x2, x3, p1, p2, p3, v1, v2, v3):
    X, P, v = [x1, x2, x3], [p1, p2, p3], [v1, v2, v3]
    t = symbols("t_")
    sub = {x: p + t * vv for x, p, vv in zip(X, P, v)}
    d = [a - b for a, b in zip(X, P)]
    return dict(expected=_dot(d, v) / _dot(v, v), what="t", substitutions=sub,
                slips=[(_dot(d, v), "does not divide by v·v: that is t only for a unit direction."),
                       (_dot(X, v) / _dot(v, v), "forgets to subtract P: t is measured from P."),
                       (_dot(d, v) / _dot(d, d), "divides by (X − P)·(X − P): dot X − P = t v with v, so v·v divides.")],
                success="(X − P)·v = t (v·v), so t = (X − P)·v/(v·v): exact for points on the line.")


# == Chapter 20: solid modeling ====================================================================

@_define("ch20_prism_euler", (
    "Build a prism over an n-gon (two n-gon faces and n rectangles). Show that it satisfies Euler's "
    "formula V − E + F = 2: give its counts [V, E, F] in terms of n (Goldman §20.3)."),
    "n", "Check the vertex, edge and face counts of the prism.", positive=True, integer=True)
def _(n):
    return dict(expected=sympy.Matrix([[2 * n, 3 * n, n + 2]]), what="[V, E, F]",
                slips=[(sympy.Matrix([[2 * n, 2 * n, n + 2]]), "forgets the n vertical edges between the two n-gons."),
                       (sympy.Matrix([[2 * n, 3 * n, n + 1]]), "forgets one of the two n-gon faces."),
                       (sympy.Matrix([[n, 3 * n, n + 2]]), "counts only one n-gon's vertices.")],
                success="2n − 3n + n + 2 = 2 for every n.")


@_define("ch20_frame_euler", (
    "Build a picture frame: an n-gon prism with an n-gon hole through it (outer and inner walls, a top "
    "and a bottom face each bounded by two loops). Show that V − E + F − (L − F) = 2(S − G) with S = 1 "
    "shell and genus G = 1: give [V, E, F, L] (L counts every loop, outer and inner) in terms of n "
    "(Goldman §20.3)."),
    "n", "Check the vertex, edge, face and loop counts of the frame.", positive=True, integer=True)
def _(n):
    return dict(expected=sympy.Matrix([[4 * n, 6 * n, 2 * n + 2, 2 * n + 4]]), what="[V, E, F, L]",
                slips=[(sympy.Matrix([[4 * n, 6 * n, 2 * n + 2, 2 * n + 2]]), "counts one loop per face: the top and "
                        "the bottom each have an inner loop around the hole."),
                       (sympy.Matrix([[4 * n, 4 * n, 2 * n + 2, 2 * n + 4]]), "forgets the vertical edges of the outer "
                        "and inner walls."),
                       (sympy.Matrix([[4 * n, 6 * n, 2 * n, 2 * n + 2]]), "forgets the top and bottom faces.")],
                success="4n − 6n + (2n + 2) − (2n + 4 − 2n − 2) = 0 = 2(1 − 1): one hole, genus 1.")


# == Chapter 21: shading ===========================================================================

@_define("ch21_newell_triangle", (
    "Show that Newell's formula, N = Σ ((y_i − y_{i+1})(z_i + z_{i+1}), (z_i − z_{i+1})(x_i + x_{i+1}), "
    "(x_i − x_{i+1})(y_i + y_{i+1})) summed around a polygon, gives for a triangle P0 P1 P2 the cross "
    "product (P1 − P0) × (P2 − P0). Give Newell's N for the triangle as [x, y, z] in terms of "
    "x0, y0, z0, x1, y1, z1, x2, y2, z2 (Goldman §21.1.1)."),
    "x0 y0 z0 x1 y1 z1 x2 y2 z2", "Check Newell's normal of a triangle.")
def _(x0, y0, z0, x1, y1, z1, x2, y2, z2):
    P = [[x0, y0, z0], [x1, y1, z1], [x2, y2, z2]]
    N = [0, 0, 0]
    for i in range(3):
        a, b = P[i], P[(i + 1) % 3]
        N[0] += (a[1] - b[1]) * (a[2] + b[2])
        N[1] += (a[2] - b[2]) * (a[0] + b[0])
        N[2] += (a[0] - b[0]) * (a[1] + b[1])
    return dict(expected=sympy.Matrix([N]), what="Newell's N",
                slips=[(sympy.Matrix([N]) / 2, "halves it: Newell's sum is twice the area vector, the full cross product."),
                       (-sympy.Matrix([N]), "goes round the other way: the sum runs P0 → P1 → P2 → P0."),
                       (sympy.Matrix([[N[0], N[1], 0]]), "leaves out the last component's sum.")],
                success="term by term it equals (P1 − P0) × (P2 − P0), and for any planar polygon it is twice the area "
                        "times the unit normal.")


@_define("ch21_phong_length", (
    "Phong shading interpolates normals: N(t) = (1 − t) N0 + t N1. Show that N(t) must be renormalised: "
    "give |N(t)|² in terms of t and the dot products a = N0·N0, b = N0·N1, c = N1·N1 (Goldman §21.4)."),
    "t a b c", "Check |N(t)|² for the interpolated normal.")
def _(t, a, b, c):
    return dict(expected=(1 - t)**2 * a + 2 * t * (1 - t) * b + t**2 * c, what="|N(t)|²",
                slips=[((1 - t) * a + t * c, "interpolates the squared lengths: the length of an interpolated "
                        "normal is not the interpolated length."),
                       ((1 - t)**2 * a + t**2 * c, "is missing the cross term between N0 and N1."),
                       ((1 - t)**2 * a + t * (1 - t) * b + t**2 * c, "counts the cross term once: N0·N1 and N1·N0 "
                        "both appear.")],
                success="with unit N0, N1 it is 1 − 2t(1 − t)(1 − b) < 1 between the ends unless N0 = N1: "
                        "renormalise before shading.")


# == Chapter 22: hidden surfaces ===================================================================

@_define("ch22_depth_increment", (
    "On the plane a x + b y + c z + d = 0 (c ≠ 0), show that depth changes by the same amount at every "
    "step along a scan line, which is what makes the z-buffer's incremental depth work: give "
    "z(x + 1, y) − z(x, y) in terms of a, b, c, d, x, y (Goldman §22.3)."),
    "a b c d x y", "Check the depth step along a scan line.")
def _(a, b, c, d, x, y):
    z = lambda X, Y: -(a * X + b * Y + d) / c  # noqa: E731
    return dict(expected=z(x + 1, y) - z(x, y), what="the depth step",
                slips=[(a / c, "differs by a sign: z = −(a x + b y + d)/c decreases with x when a/c > 0."),
                       (-c / a, "is upside down: solve the plane's equation for z, not for x."),
                       (-b / c, "is the step down a column (y + 1), not along a scan line.")],
                success="−a/c, the same at every pixel: one addition per pixel along a scan line.")


@_define("ch22_split_edge", (
    "Depth sort and BSP trees split a polygon by a plane (X − Q)·N = 0. Show where an edge P0 P1 "
    "crosses it: give the parameter t of P0 + t (P1 − P0) on the plane in terms of the coordinates "
    "p01, p02, p03 (P0), p11, p12, p13 (P1), q1, q2, q3, n1, n2, n3 (Goldman §22.6.1)."),
    "p01 p02 p03 p11 p12 p13 q1 q2 q3 n1 n2 n3", "Check the parameter where the edge crosses the plane.")
def _(p01, p02, p03, p11, p12, p13, q1, q2, q3, n1, n2, n3):
    P0, P1, Q, N = [p01, p02, p03], [p11, p12, p13], [q1, q2, q3], [n1, n2, n3]
    d0 = _dot([a - b for a, b in zip(P0, Q)], N)
    d1 = _dot([a - b for a, b in zip(P1, Q)], N)
    return dict(expected=d0 / (d0 - d1), what="t",
                slips=[(d1 / (d1 - d0), "is measured from P1: at t = 0 the point is P0."),
                       (d0 / (d0 + d1), "adds the two signed distances: they have opposite signs across the plane, "
                        "so the denominator is their difference."),
                       (-d0 / (d0 - d1), "differs by a sign: check which signed distance "
                        "goes in the numerator and the order of the difference below.")],
                success="t = d0/(d0 − d1) with the signed distances d0, d1: between 0 and 1 exactly when they have "
                        "opposite signs.")


# == Chapter 23: radiosity =========================================================================

@_define("ch23_two_patches", (
    "Two patches see each other: B1 = E1 + ρ1 F12 B2 and B2 = E2 + ρ2 F21 B1. Show that the light "
    "bouncing back and forth sums to a closed form: solve for B1 in terms of E1, E2, rho1, rho2, F12, "
    "F21 (Goldman §23.2.3)."),
    "E1 E2 rho1 rho2 F12 F21", "Check the radiosity B1 of the first patch.")
def _(E1, E2, rho1, rho2, F12, F21):
    den = 1 - rho1 * rho2 * F12 * F21
    return dict(expected=(E1 + rho1 * F12 * E2) / den, what="B1",
                slips=[(E1 + rho1 * F12 * E2, "stops after one bounce: the light keeps bouncing "
                        "between the patches (a geometric series of bounces)."),
                       ((E1 + rho1 * F21 * E2) / den, "uses F21 in the first equation: patch 1 gathers through F12."),
                       ((E1 + rho1 * F12 * E2) / (1 + rho1 * rho2 * F12 * F21), "adds in the denominator: the "
                        "geometric series 1 + x + x² + ... is 1/(1 − x).")],
                success="a geometric series of bounces, ratio ρ1ρ2F12F21 < 1: what gathering and shooting add up.")


@_define("ch23_reciprocity", (
    "A small flat patch of area A1 sits inside a closed sphere of area A2. In a closed scene each "
    "patch's form factors sum to 1, a flat patch does not see itself (F11 = 0), and form factors satisfy "
    "reciprocity A_i F_ij = A_j F_ji. Show how much the sphere sees of the patch and of itself: give "
    "[F21, F22] in terms of A1, A2 (Goldman §23.3)."),
    "A1 A2", "Check the sphere's form factors [F21, F22].", positive=True)
def _(A1, A2):
    return dict(expected=sympy.Matrix([[A1 / A2, 1 - A1 / A2]]), what="[F21, F22]",
                slips=[(sympy.Matrix([[A2 / A1, 1 - A2 / A1]]), "uses the areas upside down: A1 F12 = A2 F21 with "
                        "F12 = 1."),
                       (sympy.Matrix([[1, 0]]), "assumes F21 = F12: that holds only for equal areas."),
                       (sympy.Matrix([[A1 / A2, 0]]), "forgets that the sphere sees itself: its form factors sum to 1.")],
                success="F12 = 1, so F21 = A1/A2 and F22 = 1 − A1/A2: a small patch sees the sphere fully, the sphere "
                        "barely sees it.")


# == Chapter 24: Bezier curves =====================================================================

def _bernstein(n, k, t):
    return sympy.binomial(n, k) * t**k * (1 - t)**(n - k)


def _casteljau(ctrl, t):
    pts = list(ctrl)
    while len(pts) > 1:
        pts = [(1 - t) * a + t * b for a, b in zip(pts, pts[1:])]
    return pts[0]


@_define("ch24_casteljau_is_bernstein", (
    "Show that the de Casteljau algorithm computes the Bernstein form: for a cubic with control "
    "values b0, b1, b2, b3 (one coordinate of the control points), run the three levels of "
    "de Casteljau at t and give the point, in terms of b0, b1, b2, b3, t; the checker compares it "
    "with the sum of the Bernstein polynomials times the b's (Goldman §24.3)."),
    "b0 b1 b2 b3 t", "Check the cubic's point at t computed by de Casteljau.")
def _(b0, b1, b2, b3, t):
    b = [b0, b1, b2, b3]
    return dict(expected=sum(_bernstein(3, k, t) * b[k] for k in range(4)), what="the point",
                slips=[(sum(t**k * (1 - t)**(3 - k) * b[k] for k in range(4)),
                        "is missing the binomial coefficients 1, 3, 3, 1: each b_k is reached along C(3, k) paths "
                        "of the de Casteljau triangle."),
                       (sum(_bernstein(3, k, 1 - t) * b[k] for k in range(4)),
                        "uses t and 1 − t the wrong way round: at t = 0 the curve starts at b0."),
                       (sum(_bernstein(3, k, t) * b[k] for k in range(3)),
                        "leaves out the last control value: all four b's contribute.")],
                success="the point is Σ C(3, k) t^k (1 − t)^(3−k) b_k: every path down the triangle is a product of "
                        "t's and (1 − t)'s.")


@_define("ch24_derivative", (
    "Show that the derivative of a cubic Bezier curve is 3 times the difference of the two points of "
    "the second-to-last de Casteljau level. Give P'(t) in terms of b0, b1, b2, b3, t (differentiate "
    "the Bernstein form, or take that difference) (Goldman §24.5)."),
    "b0 b1 b2 b3 t", "Check the derivative P'(t) of the cubic.")
def _(b0, b1, b2, b3, t):
    b = [b0, b1, b2, b3]
    p = sum(_bernstein(3, k, t) * b[k] for k in range(4))
    left = _casteljau(b[:3], t)
    right = _casteljau(b[1:], t)
    return dict(expected=sympy.diff(p, t), what="P'(t)",
                slips=[(right - left, "is missing the degree factor 3: the derivative of a degree-n curve is n times "
                        "the difference of the last two de Casteljau points."),
                       (3 * (left - right), "differs by a sign: take the right point minus the left point."),
                       (3 * (_casteljau(b[2:], t) - _casteljau(b[:2], t)),
                        "takes the difference one level too early: use the two points of the second-to-last level.")],
                success="3 (p(t, t, 1) − p(t, t, 0)) in blossom form: at t = 0 it is 3 (b1 − b0), the end tangent.")


# == Chapter 25: Bezier subdivision =================================================================

@_define("ch25_left_half", (
    "Show that de Casteljau subdivision at r gives the left piece: its control values are the left "
    "edge of the de Casteljau triangle, and its curve at u is the original curve at r u. For a cubic "
    "b0, b1, b2, b3, give the left piece's four control values [c0, c1, c2, c3] in terms of "
    "b0, b1, b2, b3, r (Goldman §25.2)."),
    "b0 b1 b2 b3 r", "Check the control values of the left piece after subdividing at r.")
def _(b0, b1, b2, b3, r):
    b = [b0, b1, b2, b3]
    left = [_casteljau(b[:k + 1], r) for k in range(4)]
    right = [_casteljau(b[k:], r) for k in range(4)]
    level1 = [(1 - r) * x + r * y for x, y in zip(b, b[1:])]
    return dict(expected=sympy.Matrix([left]), what="the left piece's control values",
                slips=[(sympy.Matrix([right]), "are the right piece's (the right edge of the triangle): the left piece "
                        "starts at b0."),
                       (sympy.Matrix([left[::-1]]), "are in reverse order: the left piece starts at b0 and ends at the "
                        "split point."),
                       (sympy.Matrix([[b0] + level1]), "stop at the first level: the left edge takes the first point of "
                        "every level of the triangle.")],
                success="the left piece's Bernstein form at u is the original at r u: the two halves trace the curve.")


@_define("ch25_smooth_join", (
    "Two cubic Bezier curves join at c0 = b3; the first runs over a parameter interval of length h0 "
    "and the second over one of length h1. Find the second control value c1 of the second curve that "
    "makes the join C1 (the same derivative with respect to the global parameter; a curve over an "
    "interval of length h has derivative (1/h) dP/du). Give c1 in terms of b2, b3, h0, h1 "
    "(Goldman §25.5)."),
    "b2 b3 h0 h1", "Check the second control value c1 of the next curve for a C1 join.")
def _(b2, b3, h0, h1):
    return dict(expected=b3 + h1 / h0 * (b3 - b2), what="c1",
                slips=[(2 * b3 - b2, "assumes equal parameter lengths: with h0 ≠ h1 the tangent scales by h1/h0."),
                       (b3 + h0 / h1 * (b3 - b2), "uses the ratio of the interval lengths upside down: each derivative is "
                        "divided by its own curve's length."),
                       (b3 - h1 / h0 * (b3 - b2), "goes back along the tangent: c1 continues the direction b2 → b3.")],
                success="3 (b3 − b2)/h0 = 3 (c1 − b3)/h1: the derivatives with respect to the global parameter agree, "
                        "and b2, b3, c1 are collinear.")


# == Chapter 26: blossoming ========================================================================

@_define("ch26_cubic_blossom", (
    "Find the blossom of the cubic P(t) = a0 + a1 t + a2 t² + a3 t³ and show it is symmetric, "
    "multiaffine and equals P on the diagonal. Give p(u1, u2, u3) in terms of a0, a1, a2, a3, "
    "u1, u2, u3 (Goldman §26.2)."),
    "a0 a1 a2 a3 u1 u2 u3", "Check the blossom p(u1, u2, u3) of a cubic.")
def _(a0, a1, a2, a3, u1, u2, u3):
    e1, e2, e3 = u1 + u2 + u3, u1 * u2 + u1 * u3 + u2 * u3, u1 * u2 * u3
    return dict(expected=a0 + a1 * e1 / 3 + a2 * e2 / 3 + a3 * e3, what="p(u1, u2, u3)",
                slips=[(a0 + a1 * e1 + a2 * e2 + a3 * e3, "does not give P back on the diagonal: divide each symmetric "
                        "sum by its number of terms (3 for t and for t²)."),
                       (a0 + a1 * e1 / 3 + a2 * (u1**2 + u2**2 + u3**2) / 3 + a3 * e3,
                        "is not multiaffine: u1² has degree 2 in u1; t² blossoms to the products of distinct u's."),
                       (a0 + a1 * u1 + a2 * u1 * u2 + a3 * e3, "is not symmetric: the blossom must not change when the "
                        "u's are permuted.")],
                success="symmetric, degree 1 in each u, and p(t, t, t) = P(t): the blossom is unique.")


@_define("ch26_diagonal", (
    "For a quadratic with control points b0 = p(0, 0), b1 = p(0, 1), b2 = p(1, 1), expand the blossom "
    "p(u1, u2) by multiaffinity (write u = (1 − u)·0 + u·1 in each argument) and give it in terms of "
    "b0, b1, b2, u1, u2. Its diagonal p(t, t) is the de Casteljau point (Goldman §26.3)."),
    "b0 b1 b2 u1 u2", "Check the blossom p(u1, u2) of a quadratic from its control points.")
def _(b0, b1, b2, u1, u2):
    return dict(expected=(1 - u1) * (1 - u2) * b0 + (u1 * (1 - u2) + u2 * (1 - u1)) * b1 + u1 * u2 * b2,
                what="p(u1, u2)",
                slips=[((1 - u1) * (1 - u2) * b0 + 2 * u1 * (1 - u2) * b1 + u1 * u2 * b2,
                        "is not symmetric: p(0, 1) and p(1, 0) are both b1, each reached once."),
                       (u1 * u2 * b0 + (u1 * (1 - u2) + u2 * (1 - u1)) * b1 + (1 - u1) * (1 - u2) * b2,
                        "swaps the ends: p(0, 0) = b0, so b0's weight is (1 − u1)(1 − u2)."),
                       ((1 - u1) * (1 - u2) * b0 + (u1 + u2) * b1 + u1 * u2 * b2,
                        "drops the u1 u2 terms of b1's weight: expand u1 (1 − u2) + u2 (1 − u1).")],
                success="on the diagonal it is (1 − t)² b0 + 2t(1 − t) b1 + t² b2, the de Casteljau point.")


# == Chapter 27: B-splines =========================================================================

def _de_boor2(P0, P1, P2, t1, t2, t3, t4, t):
    a = ((t3 - t) * P0 + (t - t1) * P1) / (t3 - t1)      # p(t2, t)
    b = ((t4 - t) * P1 + (t - t2) * P2) / (t4 - t2)      # p(t, t3)
    return ((t3 - t) * a + (t - t2) * b) / (t3 - t2)


@_define("ch27_local_de_boor", (
    "A quadratic B-spline segment over [t2, t3] has knots t1, t2, t3, t4 and control points "
    "P0 = p(t1, t2), P1 = p(t2, t3), P2 = p(t3, t4). Run the local de Boor algorithm with blossoms "
    "(first p(t2, t) and p(t, t3), then p(t, t)) and give the point p(t, t) in terms of P0, P1, P2, "
    "t1, t2, t3, t4, t (Goldman §27.2)."),
    "P0 P1 P2 t1 t2 t3 t4 t", "Check the point p(t, t) of a quadratic B-spline segment.")
def _(P0, P1, P2, t1, t2, t3, t4, t):
    wrong_den = (((t3 - t) * ((t3 - t) * P0 + (t - t2) * P1) + (t - t2) * ((t3 - t) * P1 + (t - t2) * P2))
                 / (t3 - t2)**2)
    a = ((t3 - t) * P0 + (t - t1) * P1) / (t3 - t1)
    b = ((t4 - t) * P1 + (t - t2) * P2) / (t4 - t2)
    return dict(expected=_de_boor2(P0, P1, P2, t1, t2, t3, t4, t), what="p(t, t)",
                slips=[(wrong_den, "uses the middle interval [t2, t3] at the first level too: p(t2, t) interpolates "
                        "between p(t1, t2) and p(t2, t3), over [t1, t3]."),
                       (((t - t2) * a + (t3 - t) * b) / (t3 - t2), "swaps the weights of the last step: at t = t2 the "
                        "point is p(t2, t2), from the left."),
                       ((a + b) / 2, "averages the last level: its weights are (t3 − t)/(t3 − t2) and (t − t2)/(t3 − t2).")],
                success="each step is affine in one blossom argument, so p(t, t) is the segment of the spline.")


@_define("ch27_nurbs_circle", (
    "Show that the rational quadratic Bezier curve with control points (1, 0), (1, 1), (0, 1) and "
    "weights 1, 1, 2 lies on the unit circle. Give its point [x, y] as functions of t (the weighted "
    "Bernstein sum divided by the weighted sum of the Bernstein polynomials) (Goldman §27.9)."),
    "t", "Check the point [x, y] of a rational quadratic Bezier curve.")
def _(t):
    B = [_bernstein(2, k, t) for k in range(3)]
    w = [1, 1, 2]
    ctrl = [(1, 0), (1, 1), (0, 1)]
    den = sum(wi * b for wi, b in zip(w, B))
    pt = [sum(wi * b * c[i] for wi, b, c in zip(w, B, ctrl)) / den for i in range(2)]
    poly = [sum(b * c[i] for b, c in zip(B, ctrl)) for i in range(2)]
    num = [sum(wi * b * c[i] for wi, b, c in zip(w, B, ctrl)) for i in range(2)]
    return dict(expected=sympy.Matrix([pt]), what="[x, y]",
                slips=[(sympy.Matrix([poly]), "ignores the weights: that is the polynomial Bezier curve, a parabola."),
                       (sympy.Matrix([num]), "forgets to divide by Σ w_k B_k: the weighted sum is a mass-point, not a point."),
                       (sympy.Matrix([[pt[1], pt[0]]]), "swaps x and y: the curve starts at (1, 0).")],
                success="x = (1 − t²)/(1 + t²), y = 2t/(1 + t²), and x² + y² = 1: a quarter of the unit circle.")


# == Chapter 28: knot insertion ====================================================================

@_define("ch28_boehm", (
    "Insert the knot u (t2 ≤ u ≤ t3) into the quadratic B-spline with knots t1, t2, t3, t4 and control "
    "points P0 = p(t1, t2), P1 = p(t2, t3), P2 = p(t3, t4). The new control points are P0, p(t2, u), "
    "p(u, t3), P2. Give [p(t2, u), p(u, t3)] in terms of P0, P1, P2, t1, t2, t3, t4, u; the checker "
    "then confirms the curve is unchanged (Goldman §28.3.1)."),
    "P0 P1 P2 t1 t2 t3 t4 u", "Check the two new control points of Boehm's knot insertion.")
def _(P0, P1, P2, t1, t2, t3, t4, u):
    a = ((t3 - u) * P0 + (u - t1) * P1) / (t3 - t1)
    b = ((t4 - u) * P1 + (u - t2) * P2) / (t4 - t2)
    return dict(expected=sympy.Matrix([[a, b]]), what="the new control points",
                slips=[(sympy.Matrix([[((t3 - u) * P0 + (u - t2) * P1) / (t3 - t2),
                                       ((t3 - u) * P1 + (u - t2) * P2) / (t3 - t2)]]),
                        "use the interval [t2, t3] for both: p(t2, u) interpolates over [t1, t3] and p(u, t3) over "
                        "[t2, t4]."),
                       (sympy.Matrix([[((u - t1) * P0 + (t3 - u) * P1) / (t3 - t1),
                                       ((u - t2) * P1 + (t4 - u) * P2) / (t4 - t2)]]),
                        "swap the weights: u near t1 gives a point near p(t1, t2) = P0."),
                       (sympy.Matrix([[b, a]]), "are in the wrong order: p(t2, u) comes first.")],
                success="they are the blossom at the new consecutive knots, so de Boor on the new knots gives the same "
                        "curve.")


@_define("ch28_chaikin", (
    "Show that one Lane–Riesenfeld step for a uniform quadratic B-spline (double every control point, "
    "then average neighbours twice) turns each edge P0 P1 into the two points of Chaikin's corner "
    "cutting. Give [Q0, Q1] (in order along the edge) in terms of P0, P1 (Goldman §28.4.1)."),
    "P0 P1", "Check the two new control points of one edge after a Lane–Riesenfeld step of degree 2.")
def _(P0, P1):
    return dict(expected=sympy.Matrix([[(3 * P0 + P1) / 4, (P0 + 3 * P1) / 4]]), what="[Q0, Q1]",
                slips=[(sympy.Matrix([[(P0 + P1) / 2, P1]]), "averages once: degree 2 needs two rounds of averaging."),
                       (sympy.Matrix([[(P0 + 3 * P1) / 4, (3 * P0 + P1) / 4]]), "gives the points in the wrong order: "
                        "the one nearer P0 comes first."),
                       (sympy.Matrix([[(2 * P0 + P1) / 3, (P0 + 2 * P1) / 3]]), "cuts at thirds: averaging twice "
                        "gives quarters.")],
                success="(3 P0 + P1)/4 and (P0 + 3 P1)/4: the knots doubled, the curve unchanged.")


# == Chapter 29: subdivision matrices ==============================================================

@_define("ch29_left_matrix", (
    "Show that subdividing a quadratic Bezier curve at r is linear in the control points: the left "
    "piece's control points are L(r) applied to b0, b1, b2, with row i the weights of the left piece's "
    "i-th control point. Give the 3x3 matrix L(r) (a list of rows) in terms of r (Goldman §29.2.1)."),
    "r", "Check the left subdivision matrix L(r) of a quadratic Bezier curve.")
def _(r):
    L = sympy.Matrix([[1, 0, 0], [1 - r, r, 0], [(1 - r)**2, 2 * r * (1 - r), r**2]])
    R = sympy.Matrix([[(1 - r)**2, 2 * r * (1 - r), r**2], [0, 1 - r, r], [0, 0, 1]])
    return dict(expected=L, what="L(r)",
                slips=[(R, "is the right piece's matrix: the left piece starts at b0, row 1 is (1, 0, 0)."),
                       (sympy.Matrix([[1, 0, 0], [r, 1 - r, 0], [r**2, 2 * r * (1 - r), (1 - r)**2]]),
                        "uses r and 1 − r the wrong way round: at r = 0 the left piece shrinks to b0.")],
                success="each row sums to 1 (an affine combination), and at r = 1/2 its eigenvalues are 1, 1/2, 1/4.")


@_define("ch29_cubic_bspline_rules", (
    "Show that the uniform cubic B-spline subdivision rules come from Lane–Riesenfeld: double every "
    "control point, then average neighbours three times. Give the new points around P1, "
    "[the vertex point that replaces P1, the edge point on P1 P2], in terms of P0, P1, P2 "
    "(Goldman §29.2.2)."),
    "P0 P1 P2", "Check the vertex and edge points of one uniform cubic B-spline subdivision step.")
def _(P0, P1, P2):
    return dict(expected=sympy.Matrix([[(P0 + 6 * P1 + P2) / 8, (P1 + P2) / 2]]), what="[vertex point, edge point]",
                slips=[(sympy.Matrix([[(P0 + 2 * P1 + P2) / 4, (P1 + P2) / 2]]), "averages twice: degree 3 needs three "
                        "rounds (twice is the quadratic rule, between old points)."),
                       (sympy.Matrix([[P1, (P1 + P2) / 2]]), "keeps the old point: a cubic B-spline does not interpolate "
                        "its control points; the vertex point moves toward its neighbours."),
                       (sympy.Matrix([[(P1 + P2) / 2, (P0 + 6 * P1 + P2) / 8]]), "gives the two points in the wrong "
                        "order: the vertex point first.")],
                success="the rows of the subdivision matrix: (1, 6, 1)/8 at a vertex and (1, 1)/2 on an edge.")


# == Chapter 30: subdivision surfaces ==============================================================

@_define("ch30_bicubic_vertex", (
    "Show that the vertex stencil of uniform bicubic B-spline subdivision is the tensor product of the "
    "cubic B-spline curve's vertex stencil (1/8, 6/8, 1/8). Give the new position of a vertex V (one "
    "coordinate) in terms of V, its four edge neighbours e1, e2, e3, e4 and its four diagonal "
    "neighbours d1, d2, d3, d4 (Goldman §30.3.2.1)."),
    "V e1 e2 e3 e4 d1 d2 d3 d4", "Check the bicubic vertex rule.")
def _(V, e1, e2, e3, e4, d1, d2, d3, d4):
    E, D = e1 + e2 + e3 + e4, d1 + d2 + d3 + d4
    return dict(expected=sympy.Rational(9, 16) * V + sympy.Rational(3, 32) * E + sympy.Rational(1, 64) * D,
                what="the new vertex",
                slips=[(sympy.Rational(3, 4) * V + E / 16, "uses the curve stencil along each direction and adds: "
                        "a tensor product multiplies the weights, which brings in the diagonal neighbours."),
                       ((V + E + D) / 9, "is the centroid of the 3x3 block: the weights are products of (1/8, 6/8, 1/8)."),
                       (sympy.Rational(9, 16) * V + sympy.Rational(3, 32) * E, "is missing the diagonal neighbours: "
                        "the tensor product gives each the product of two end weights.")],
                success="the weights are products (6/8)(6/8), (1/8)(6/8) and (1/8)(1/8), and they sum to 1.")


@_define("ch30_euler_characteristic", (
    "One step of triangle-mesh subdivision (Loop's split) puts a new vertex on every edge and cuts "
    "every triangle into four. Show that it keeps V − E + F: give the new counts [V', E', F'] of a "
    "closed triangle mesh in terms of nV, nE, nF (Goldman §30.4.1.2)."),
    "nV nE nF", "Check the vertex, edge and face counts after one split.")
def _(nV, nE, nF):
    return dict(expected=sympy.Matrix([[nV + nE, 2 * nE + 3 * nF, 4 * nF]]), what="[V', E', F']",
                slips=[(sympy.Matrix([[nV + nE, 2 * nE, 4 * nF]]), "counts only the halves of the old edges: each "
                        "triangle also gets three new interior edges."),
                       (sympy.Matrix([[nV + nE, 2 * nE + 3 * nF, 3 * nF]]), "cuts each triangle into three: the "
                        "midpoints cut it into four."),
                       (sympy.Matrix([[nV + nF, 2 * nE + 3 * nF, 4 * nF]]), "adds a vertex per face: the split adds "
                        "one per edge.")],
                success="V' − E' + F' = nV + nE − 2nE − 3nF + 4nF = nV − nE + nF: the Euler characteristic is kept.")


PROBLEMS = {name: ex.statement for name, ex in _EXERCISES.items()}


def _slips():
    out = {}
    for name, ex in _EXERCISES.items():
        spec = ex.build(*_symbol_tuple(name))
        out[name] = [form for form, _ in spec.get("slips", ())]
    return out


#: Wrong answers of the kinds each checker names (sympy expressions), for the tests.
SLIPS = _slips()
