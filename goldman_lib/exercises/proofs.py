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
    constraint_names: str = ""
    extra: dict = field(default_factory=dict)


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
    """The sympy symbols of exercise ``name``, in the order its statement lists them."""
    if name not in _EXERCISES:
        raise ValueError(f"name must be one of the show-that exercises {sorted(_EXERCISES)}; got {name!r}")
    syms = symbols(_EXERCISES[name].symbol_names)
    return syms if isinstance(syms, tuple) else (syms,)


def _check(name: str, answer):
    ex = _EXERCISES[name]
    syms = symbols_for(name)
    spec = ex.build(*syms)
    return check_expression(answer, spec["expected"], what=spec["what"], symbols=syms,
                            substitutions=spec.get("substitutions"), slips=spec.get("slips", ()),
                            success=spec.get("success"), ask=spec.get("ask"))


def _define(name, statement, symbol_names, doc):
    def build(fn):
        _EXERCISES[name] = _Exercise(name, statement, symbol_names, fn)

        def checker(answer):
            return _check(name, answer)

        checker.__name__ = checker.__qualname__ = name
        checker.__doc__ = doc + "\n\n``answer``: a sympy expression built from ``symbols_for(%r)``." % name
        globals()[name] = checker
        __all__.append(name)
        return fn
    return build


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
    "Show that |u × v|² = |u|²|v|² − (u·v)² follows from |u × v| = |u||v| sin θ and "
    "u·v = |u||v| cos θ. Give |u × v|² in terms of uu = u·u, vv = v·v and uv = u·v only "
    "(no angle) (Goldman §9.4.2)."),
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
    "Show that (u × v) × w = (u·w) v − (v·w) u, so that (u × v) × w and u × (v × w) differ and the "
    "cross product is not associative. Compute (u × v) × w in coordinates from "
    "u = (u1, u2, u3), v = (v1, v2, v3), w = (w1, w2, w3), or write the right-hand side with dot "
    "products in coordinates; give it as [x, y, z] (Goldman §10.3.2)."),
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
                success="it expands to (u·w) v − (v·w) u, while u × (v × w) = (u·w) v − (u·v) w: not associative.")


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
    "Show that s = ((Q − P) × v)/(u × v) by crossing both sides with v (in the plane a × b = "
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
                success="crossing P + s u = Q + t v with v removes t (v × v = 0) and leaves s (u × v) = (Q − P) × v.")


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
    "Show that the perspective image of P from the eye E on the plane through Q with normal N is "
    "P' = [((P − Q)·N) E + ((Q − E)·N) P] / ((P − E)·N). Intersect the line E + t(P − E) with the "
    "plane (P' − Q)·N = 0, solve for t, and give P' as [x, y, z] in terms of p1, p2, p3, "
    "e1, e2, e3, q1, q2, q3, n1, n2, n3 (Goldman §12.5.2)."),
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
                success="the image lies on the line EP and on the plane, and its denominator (P − E)·N vanishes "
                        "exactly when EP is parallel to the plane.")


# == Chapter 13: matrices ==========================================================================

@_define("ch13_translation_row", (
    "An affine map with linear part L (3x3, rows act on the right, P ↦ P L + w) fixes the point Q. "
    "Show that its translation row is w = Q − Q L. Give w as [x, y, z] in terms of q1, q2, q3 and the "
    "entries l11 ... l33 of L (row i, column j is lij) (Goldman §13.2.2)."),
    "q1 q2 q3 l11 l12 l13 l21 l22 l23 l31 l32 l33", "Check the translation row w of a map fixing Q.")
def _(q1, q2, q3, l11, l12, l13, l21, l22, l23, l31, l32, l33):
    Q = sympy.Matrix([[q1, q2, q3]])
    L = sympy.Matrix([[l11, l12, l13], [l21, l22, l23], [l31, l32, l33]])
    return dict(expected=Q - Q * L, what="the translation row w",
                slips=[(Q - (L * Q.T).T, "uses L Q (a column vector times L from the left): the book's points are rows, "
                        "so Q maps to Q L."),
                       (Q * L - Q, "differs by a sign: Q L + w = Q gives w = Q − Q L."),
                       (Q, "forgets the linear part: Q L + w = Q, so w = Q − Q L is Q only when L is the identity.")],
                success="Q L + (Q − Q L) = Q, and every P maps to Q + (P − Q) L: L acting about Q.")


@_define("ch13_mirror_linear_part", (
    "Show that the linear part of the mirror in a plane with unit normal n = (n1, n2, n3) is "
    "M = I − 2 nᵀn (row vectors: v ↦ v M = v − 2 (v·n) n), and that M M = I. Give M as a 3x3 "
    "matrix (a list of rows) in terms of n1, n2, n3 (Goldman §13.3.3)."),
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
                success="M is symmetric, n M = −n, a vector in the plane is kept, and M M = I − 4 nᵀn + 4 nᵀ(n nᵀ)n = I "
                        "because n nᵀ = 1.")


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


PROBLEMS = {name: ex.statement for name, ex in _EXERCISES.items()}


def _slips():
    out = {}
    for name, ex in _EXERCISES.items():
        spec = ex.build(*symbols_for(name))
        out[name] = [form for form, _ in spec.get("slips", ())]
    return out


#: Wrong answers of the kinds each checker names (sympy expressions), for the tests.
SLIPS = _slips()
