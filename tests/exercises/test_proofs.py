"""The "show that" exercises (goldman_lib.exercises.proofs): each accepts a right answer written two
independent ways and rejects two realistic slips, naming them.

The right answers here are derived independently of the module: with sympy's own Matrix.cross,
sympy.solve, sympy's Quaternion class, a determinant, or the book's closed form, and (for the
constrained exercises) in coordinates with a unit vector.  The wrong ones are the slips a learner
makes, written out by hand.
"""

from __future__ import annotations

import time

import pytest

sympy = pytest.importorskip("sympy")

from goldman_lib.exercises import proofs  # noqa: E402
from sympy.algebras.quaternion import Quaternion  # noqa: E402

S = proofs.symbols_for


def _right_and_wrong():
    """name -> ([two right answers], [(wrong answer, words its message must contain)] )"""
    cases = {}

    uu, uv, vv = S("ch09_perpendicular_part")
    cases["ch09_perpendicular_part"] = (
        [vv - uv**2 / uu, (uu * vv - uv**2) / uu],
        [(vv - 2 * uv**2 / uu, "k²(u·u) term"), (vv + uv**2 / uu, "wrong sign")])

    uu, vv, uv = S("ch09_cross_length")
    cases["ch09_cross_length"] = (
        [uu * vv - uv**2, uu * vv * (1 - uv**2 / (uu * vv))],
        [(uu * vv + uv**2, "1 + cos²θ"), (uu * vv, "missing a term")])

    u1, u2, u3, v1, v2, v3 = S("ch10_cross_product")
    u, v = sympy.Matrix([u1, u2, u3]), sympy.Matrix([v1, v2, v3])
    det_rule = [sympy.Matrix([[u2, u3], [v2, v3]]).det(), -sympy.Matrix([[u1, u3], [v1, v3]]).det(),
                sympy.Matrix([[u1, u2], [v1, v2]]).det()]
    cases["ch10_cross_product"] = (
        [u.cross(v), det_rule],
        [(list(v.cross(u)), "is v × u"), ([det_rule[0], -det_rule[1], det_rule[2]], "middle coordinate")])

    syms = S("ch10_triple_cross")
    u, v, w = (sympy.Matrix(syms[i:i + 3]) for i in (0, 3, 6))
    cases["ch10_triple_cross"] = (
        [u.cross(v).cross(w), list(u.dot(w) * v - v.dot(w) * u)],
        [(list(u.cross(v.cross(w))), "not associative"), (list(v.dot(w) * u - u.dot(w) * v), "sign")])

    x0, y0, x1, y1, x2, y2 = S("ch11_triangle_area")
    shoelace = ((x0 * y1 - x1 * y0) + (x1 * y2 - x2 * y1) + (x2 * y0 - x0 * y2)) / 2
    det = sympy.Matrix([[x0, y0, 1], [x1, y1, 1], [x2, y2, 1]]).det() / 2
    cases["ch11_triangle_area"] = ([shoelace, det], [(2 * det, "parallelogram"), (-shoelace, "clockwise")])

    p1, p2, u1, u2, q1, q2, v1, v2 = S("ch11_line_intersection")
    s, t = sympy.symbols("s t")
    sol = sympy.solve([p1 + s * u1 - q1 - t * v1, p2 + s * u2 - q2 - t * v2], [s, t], dict=True, simplify=False)[0]
    cramer = sympy.Matrix([[q1 - p1, -v1], [q2 - p2, -v2]]).det() / sympy.Matrix([[u1, -v1], [u2, -v2]]).det()
    cases["ch11_line_intersection"] = ([sol[s], cramer], [(sol[t], "parameter t"), (-cramer, "v × u")])

    c, sn, p, n = S("ch12_rodrigues_length")
    cases["ch12_rodrigues_length"] = (
        [(c**2 + sn**2) * n + (1 - c**2 - sn**2) * p**2,
         (c * 1)**2 * n + (1 - c)**2 * p**2 + 2 * c * (1 - c) * p * p + sn**2 * (n - p**2)],
        [(n, "end of the proof"), (c**2 * n + (1 - c)**2 * p**2 + 2 * c * (1 - c) * p**2 + sn**2 * n, "|a × v|² = |v|²")])

    syms = S("ch12_perspective_formula")
    P, E, Q, N = (sympy.Matrix(syms[i:i + 3]) for i in (0, 3, 6, 9))
    tt = sympy.symbols("tt")
    t_sol = sympy.solve((E + tt * (P - E) - Q).dot(N), tt, simplify=False)[0]
    goldman = (((P - Q).dot(N)) * E + ((Q - E).dot(N)) * P) / ((P - E).dot(N))
    cases["ch12_perspective_formula"] = (
        [list(E + t_sol * (P - E)), goldman.T],
        [(list(E + (P - E) / t_sol), "upside down"), (list(E - t_sol * (P - E)), "away from P")])

    syms = S("ch13_translation_row")
    Q = sympy.Matrix([syms[:3]])
    L = sympy.Matrix(3, 3, syms[3:])
    w = sympy.Matrix([sympy.symbols("w1:4")])
    w_sol = sympy.solve(list(Q * L + w - Q), list(w), dict=True, simplify=False)[0]
    cases["ch13_translation_row"] = (
        [Q * (sympy.eye(3) - L), [w_sol[k] for k in w]],
        [(Q * L - Q, "sign"), (Q - Q * L.T, "L Q")])

    n1, n2, n3 = S("ch13_mirror_linear_part")
    n = sympy.Matrix([[n1, n2, n3]])
    rows = [list(sympy.eye(3)[i, :] - 2 * n[i] * n) for i in range(3)]          # images of e1, e2, e3
    unit_form = [[n2**2 + n3**2 - n1**2, -2 * n1 * n2, -2 * n1 * n3],          # equal only when |n| = 1
                 [-2 * n1 * n2, n1**2 + n3**2 - n2**2, -2 * n2 * n3],
                 [-2 * n1 * n3, -2 * n2 * n3, n1**2 + n2**2 - n3**2]]
    cases["ch13_mirror_linear_part"] = (
        [rows, unit_form],
        [(sympy.eye(3) - n.T * n, "orthogonal projection"), (2 * n.T * n - sympy.eye(3), "half-turn")])

    m1, x1, m2, x2 = S("ch14_law_of_the_lever")
    x = sympy.symbols("x")
    lever = sympy.solve(m1 * (x - x1) + m2 * (x - x2), x, simplify=False)[0]
    cases["ch14_law_of_the_lever"] = (
        [lever, x1 + m2 / (m1 + m2) * (x2 - x1)],
        [((m2 * x1 + m1 * x2) / (m1 + m2), "other end"), ((x1 + x2) / 2, "midpoint")])

    t, w0, w1 = S("ch14_perspective_keeps_lines")
    cases["ch14_perspective_keeps_lines"] = (
        [t * w1 / ((1 - t) * w0 + t * w1), 1 - (1 - t) * w0 / ((1 - t) * w0 + t * w1)],
        [(t, "keeps the parameter"), (t * w0 / ((1 - t) * w0 + t * w1), "mass at R'")])

    w, x, y, z, v1, v2, v3 = S("ch15_sandwich_is_pure")
    q, vq, qc = Quaternion(w, x, y, z), Quaternion(0, v1, v2, v3), Quaternion(w, -x, -y, -z)
    sand = q * vq * qc
    qv, vv3 = sympy.Matrix([x, y, z]), sympy.Matrix([v1, v2, v3])
    closed = (w**2 - qv.dot(qv)) * vv3 + 2 * qv.dot(vv3) * qv + 2 * w * qv.cross(vv3)
    one = q * vq
    other = qc * vq * q
    cases["ch15_sandwich_is_pure"] = (
        [[sand.a, sand.b, sand.c, sand.d], [0] + list(closed)],
        [([one.a, one.b, one.c, one.d], "one-sided"), ([other.a, other.b, other.c, other.d], "other way")])

    w, x, y, z, v1, v2, v3 = S("ch15_one_sided_not_pure")
    one = Quaternion(w, x, y, z) * Quaternion(0, v1, v2, v3)
    cases["ch15_one_sided_not_pure"] = (
        [one.a, -sympy.Matrix([x, y, z]).dot(sympy.Matrix([v1, v2, v3]))],
        [(x * v1 + y * v2 + z * v3, "sign"), (sympy.Integer(0), "perpendicular")])
    b0, b1, b2, b3, t = S("ch24_casteljau_is_bernstein")
    bern = sum(sympy.binomial(3, k) * t**k * (1 - t)**(3 - k) * bk for k, bk in enumerate([b0, b1, b2, b3]))
    power = (b0 + 3 * (b1 - b0) * t + 3 * (b2 - 2 * b1 + b0) * t**2 + (b3 - 3 * b2 + 3 * b1 - b0) * t**3)
    cases["ch24_casteljau_is_bernstein"] = (
        [bern, power],
        [(sum(t**k * (1 - t)**(3 - k) * bk for k, bk in enumerate([b0, b1, b2, b3])), "binomial"),
         (bern.subs(t, 1 - t), "wrong way round")])

    b0, b1, b2, b3, t = S("ch24_derivative")
    cases["ch24_derivative"] = (
        [sympy.diff(power.subs(S("ch24_casteljau_is_bernstein")[4], t), t),
         3 * sum(sympy.binomial(2, k) * t**k * (1 - t)**(2 - k) * d for k, d in enumerate([b1 - b0, b2 - b1, b3 - b2]))],
        [(sum(sympy.binomial(2, k) * t**k * (1 - t)**(2 - k) * d for k, d in enumerate([b1 - b0, b2 - b1, b3 - b2])),
          "degree factor 3"),
         (-sympy.diff(bern, t), "sign")])

    b0, b1, b2, b3, r = S("ch25_left_half")
    u = sympy.symbols("u")
    # the left piece's control values from the polar form: p(0,0,0), p(0,0,r), p(0,r,r), p(r,r,r)
    def polar(x1, x2, x3):
        c = [b0, b1, b2, b3]
        for x in (x1, x2, x3):
            c = [(1 - x) * a + x * b for a, b in zip(c, c[1:])]
        return c[0]
    by_polar = [polar(0, 0, 0), polar(0, 0, r), polar(0, r, r), polar(r, r, r)]
    # and by reparametrising P(r u) and converting back to Bernstein coefficients in u
    pru = sympy.Poly(sympy.expand(bern.subs(t, r * u)), u)
    a = [pru.coeff_monomial(u**k) for k in range(4)]
    by_conversion = [a[0], a[0] + a[1] / 3, a[0] + 2 * a[1] / 3 + a[2] / 3, a[0] + a[1] + a[2] + a[3]]
    cases["ch25_left_half"] = (
        [by_polar, by_conversion],
        [([polar(r, r, r), polar(r, r, 1), polar(r, 1, 1), polar(1, 1, 1)], "right piece"),
         (by_polar[::-1], "reverse order")])

    b2, b3, h0, h1 = S("ch25_smooth_join")
    c1 = sympy.symbols("c1")
    sol = sympy.solve(sympy.Eq(3 * (b3 - b2) / h0, 3 * (c1 - b3) / h1), c1, simplify=False)[0]
    cases["ch25_smooth_join"] = (
        [sol, (b3 * (h0 + h1) - h1 * b2) / h0],
        [(2 * b3 - b2, "equal parameter lengths"), (b3 + h0 / h1 * (b3 - b2), "upside down")])

    a0, a1, a2, a3, u1, u2, u3 = S("ch26_cubic_blossom")
    from itertools import permutations
    perms = list(permutations([u1, u2, u3]))
    avg = sum(a0 + a1 * x + a2 * x * y + a3 * x * y * z for x, y, z in perms) / len(perms)
    cases["ch26_cubic_blossom"] = (
        [avg, a0 + a1 * (u1 + u2 + u3) / 3 + a2 * (u1 * u2 + u2 * u3 + u3 * u1) / 3 + a3 * u1 * u2 * u3],
        [(a0 + a1 * (u1 + u2 + u3) + a2 * (u1 * u2 + u2 * u3 + u3 * u1) + a3 * u1 * u2 * u3, "diagonal"),
         (a0 + a1 * (u1 + u2 + u3) / 3 + a2 * (u1**2 + u2**2 + u3**2) / 3 + a3 * u1 * u2 * u3, "multiaffine")])

    b0, b1, b2, u1, u2 = S("ch26_diagonal")
    # the blossom of the quadratic (1-t)^2 b0 + 2t(1-t) b1 + t^2 b2 from its power form, by averaging
    A, B, C = b0, 2 * (b1 - b0), b0 - 2 * b1 + b2          # P(t) = A + B t + C t^2
    cases["ch26_diagonal"] = (
        [A + B * (u1 + u2) / 2 + C * u1 * u2, (1 - u2) * ((1 - u1) * b0 + u1 * b1) + u2 * ((1 - u1) * b1 + u1 * b2)],
        [((1 - u1) * (1 - u2) * b0 + 2 * u1 * (1 - u2) * b1 + u1 * u2 * b2, "not symmetric"),
         (u1 * u2 * b0 + (u1 * (1 - u2) + u2 * (1 - u1)) * b1 + (1 - u1) * (1 - u2) * b2, "swaps the ends")])

    P0, P1, P2, t1, t2, t3, t4, t = S("ch27_local_de_boor")
    # Cox-de Boor recursion for the three quadratic B-splines on t1..t4 (with t0, t5 outside)
    t0, t5 = sympy.symbols("t0 t5")
    knots = [t0, t1, t2, t3, t4, t5]
    def N(i, k):       # basis function on knots[i..i+k+1], restricted to the span [t2, t3)
        if k == 0:
            return sympy.Integer(1) if i == 2 else sympy.Integer(0)
        left = (t - knots[i]) / (knots[i + k] - knots[i]) * N(i, k - 1) if N(i, k - 1) != 0 else 0
        right = (knots[i + k + 1] - t) / (knots[i + k + 1] - knots[i + 1]) * N(i + 1, k - 1) if N(i + 1, k - 1) != 0 else 0
        return left + right
    cox = N(0, 2) * P0 + N(1, 2) * P1 + N(2, 2) * P2
    a = ((t3 - t) * P0 + (t - t1) * P1) / (t3 - t1)
    b = ((t4 - t) * P1 + (t - t2) * P2) / (t4 - t2)
    cases["ch27_local_de_boor"] = (
        [cox, sympy.factor(((t3 - t) * a + (t - t2) * b) / (t3 - t2))],
        [(((t - t2) * a + (t3 - t) * b) / (t3 - t2), "swaps the weights"), ((a + b) / 2, "averages")])

    t = S("ch27_nurbs_circle")
    cases["ch27_nurbs_circle"] = (
        [[(1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)], sympy.Matrix([[1 - t**2, 2 * t]]) / (1 + t**2)],
        [([(1 - t)**2 + 2 * t * (1 - t), 2 * t * (1 - t) + t**2], "ignores the weights"),
         ([1 - t**2, 2 * t], "divide")])

    P0, P1, P2, t1, t2, t3, t4, u = S("ch28_boehm")
    # the new control points are the blossom values, computed by sympy.solve from the blossom's
    # affine property p(t2, u) = alpha P0 + (1 - alpha) P1 with u = alpha t1 + (1 - alpha) t3
    al = sympy.symbols("alpha")
    alpha = sympy.solve(al * t1 + (1 - al) * t3 - u, al, simplify=False)[0]
    beta = sympy.solve(al * t2 + (1 - al) * t4 - u, al, simplify=False)[0]
    cases["ch28_boehm"] = (
        [[alpha * P0 + (1 - alpha) * P1, beta * P1 + (1 - beta) * P2],
         [P0 + (u - t1) / (t3 - t1) * (P1 - P0), P1 + (u - t2) / (t4 - t2) * (P2 - P1)]],
        [([(1 - alpha) * P0 + alpha * P1, (1 - beta) * P1 + beta * P2], "swap the weights"),
         ([beta * P1 + (1 - beta) * P2, alpha * P0 + (1 - alpha) * P1], "wrong order")])

    P0, P1 = S("ch28_chaikin")
    cases["ch28_chaikin"] = (
        [[P0 + (P1 - P0) / 4, P1 - (P1 - P0) / 4], sympy.Matrix([[3, 1], [1, 3]]) * sympy.Matrix([P0, P1]) / 4],
        [([(P0 + P1) / 2, P1], "averages once"), ([(P0 + 3 * P1) / 4, (3 * P0 + P1) / 4], "wrong order")])

    r = S("ch29_left_matrix")
    b = sympy.symbols("c0:3")
    left = [b[0], (1 - r) * b[0] + r * b[1], (1 - r)**2 * b[0] + 2 * r * (1 - r) * b[1] + r**2 * b[2]]
    jac = sympy.Matrix(left).jacobian(b)                     # the weights, read off by differentiation
    cases["ch29_left_matrix"] = (
        [jac, [[1, 0, 0], [1 - r, r, 0], [1 - 2 * r + r**2, 2 * r - 2 * r**2, r**2]]],
        [(jac.T, "transpose"), ([[(1 - r)**2, 2 * r * (1 - r), r**2], [0, 1 - r, r], [0, 0, 1]], "right piece")])

    P0, P1, P2 = S("ch29_cubic_bspline_rules")
    cases["ch29_cubic_bspline_rules"] = (
        [[(P0 + 6 * P1 + P2) / 8, (P1 + P2) / 2], [P1 + ((P0 - P1) + (P2 - P1)) / 8, P1 + (P2 - P1) / 2]],
        [([(P0 + 2 * P1 + P2) / 4, (P1 + P2) / 2], "averages twice"), ([P1, (P1 + P2) / 2], "keeps the old point")])

    V, e1, e2, e3, e4, d1, d2, d3, d4 = S("ch30_bicubic_vertex")
    w = sympy.Matrix([[1, 6, 1]]) / 8
    block = sympy.Matrix([[d1, e1, d2], [e4, V, e2], [d4, e3, d3]])
    tensor = (w * block * w.T)[0]
    cases["ch30_bicubic_vertex"] = (
        [tensor, (36 * V + 6 * (e1 + e2 + e3 + e4) + (d1 + d2 + d3 + d4)) / 64],
        [((V + e1 + e2 + e3 + e4 + d1 + d2 + d3 + d4) / 9, "centroid"),
         (sympy.Rational(9, 16) * V + sympy.Rational(3, 32) * (e1 + e2 + e3 + e4), "diagonal neighbours")])

    nV, nE, nF = S("ch30_euler_characteristic")
    # a closed triangle mesh has 3F = 2E, but the counts must hold without using it
    cases["ch30_euler_characteristic"] = (
        [[nV + nE, 2 * nE + 3 * nF, 4 * nF], sympy.Matrix([[1, 1, 0], [0, 2, 3], [0, 0, 4]]) * sympy.Matrix([nV, nE, nF])],
        [([nV + nE, 2 * nE, 4 * nF], "interior edges"), ([nV + nE, 2 * nE + 3 * nF, 3 * nF], "four")])
    s1, n1 = S("ch01_spiral_ink")
    k1 = sympy.symbols("k", integer=True, nonnegative=True)
    summed = sympy.summation(s1**k1, (k1, 0, n1 - 1))          # sympy's own sum: Piecewise on s = 1
    cases["ch01_spiral_ink"] = (
        [summed.args[1][0] if isinstance(summed, sympy.Piecewise) else summed, (1 - s1**n1) / (1 - s1)],
        [((s1**(n1 + 1) - 1) / (s1 - 1), "one side too many"), (n1 * s1**(n1 - 1), "n copies")])

    r1, c1 = S("ch01_circle_step")
    P0 = sympy.Matrix([r1, 0])
    P1 = sympy.Matrix([r1 * c1, r1 * sympy.sqrt(1 - c1**2)])
    chord = (P1 - P0).dot(P1 - P0)                 # the square of the distance between two vertices
    cases["ch01_circle_step"] = (
        [sympy.expand(chord), r1**2 + r1**2 - 2 * r1 * r1 * c1],
        [(2 * r1**2 * (1 + c1), "sign"), (r1**2 * (1 - c1), "factor 2")])

    c, sn = S("ch02_three_steps")
    cr, sr = sympy.symbols("c s", real=True)
    closed = sympy.expand(1 + (cr + sympy.I * sr) + (cr + sympy.I * sr)**2)       # 1 + z + z², as a complex number
    by_complex = [sympy.re(closed).xreplace({cr: c, sr: sn}), sympy.im(closed).xreplace({cr: c, sr: sn})]
    A = sympy.symbols("A", real=True)
    steps = [sympy.Matrix([sympy.cos(k * A), sympy.sin(k * A)]) for k in range(3)]
    walk = sympy.expand_trig(sum(steps, sympy.zeros(2, 1))).subs({sympy.cos(A): c, sympy.sin(A): sn})
    cases["ch02_three_steps"] = (
        [by_complex, walk],
        [([1 + c + c**2 - sn**2, -sn - 2 * c * sn], "clockwise"), ([1 + 2 * c, 2 * sn], "first heading twice")])

    L, n = S("ch02_koch_length")
    cases["ch02_koch_length"] = (
        [L * 4**n / 3**n, L * sympy.Rational(4, 3)**n],
        [(L * sympy.Rational(3, 4)**n, "upside down"), (L * 4**n, "third")])

    N, s_ = S("ch03_dimension")
    D = sympy.symbols("D")
    sol = sympy.solve(sympy.Eq(N * s_**D, 1), D, simplify=False)[0]
    cases["ch03_dimension"] = (
        [sol, sympy.log(N) / sympy.log(1 / s_)],
        [(sympy.log(N) / sympy.log(s_), "sign"), (sympy.log(1 / s_) / sympy.log(N), "upside down")])

    m, a, r, q = S("ch03_finite_area")
    k = sympy.symbols("k", integer=True, nonnegative=True)
    x_ = sympy.symbols("x_")
    partial = sympy.summation(x_**k, (k, 0, 30))          # the partial sums approach 1/(1 - x) for |x| < 1
    assert sympy.cancel(partial * (1 - x_) - (1 - x_**31)) == 0
    series = m * a / (1 - r * q)
    cases["ch03_finite_area"] = (
        [series, m * a * (1 + r * q / (1 - r * q))],
        [(m * a * r * q / (1 - r * q), "level 0"), (m * a / (1 - q), "grows by r")])

    c, sn, w1, w2 = S("ch04_rotation_centre")
    qx, qy = sympy.symbols("qx qy")
    sol = sympy.solve([qx * c - qy * sn + w1 - qx, qx * sn + qy * c + w2 - qy], [qx, qy], dict=True, simplify=False)[0]
    cases["ch04_rotation_centre"] = (
        [[sol[qx], sol[qy]], [(w1 * (1 - c) - w2 * sn) / (2 - 2 * c), (w2 * (1 - c) + w1 * sn) / (2 - 2 * c)]],
        [([-sol[qx], -sol[qy]], "sign"), ([w1 / 2, w2 / 2], "half-turn")])

    x0, y0, x1, y1, x2, y2 = S("ch04_three_points")
    src = sympy.Matrix([[0, 0, 1], [1, 0, 1], [0, 1, 1]])
    dst = sympy.Matrix([[x0, y0, 1], [x1, y1, 1], [x2, y2, 1]])
    cases["ch04_three_points"] = (
        [src.inv() * dst, [[x1 - x0, y1 - y0, 0], [x2 - x0, y2 - y0, 0], [x0, y0, 1]]],
        [((src.inv() * dst).T, "transpose"), ([[x1, y1, 0], [x2, y2, 0], [x0, y0, 1]], "vectors")])

    P0, P1, P2 = S("ch05_centroid")
    cases["ch05_centroid"] = (
        [(P0 + P1 + P2) / 3, P1 + sympy.Rational(2, 3) * ((P0 + P2) / 2 - P1)],
        [(P0 + ((P1 + P2) / 2 - P0) / 3, "one third"), ((P1 + P2) / 2, "midpoint")])

    P0, P1, P2, P3 = S("ch05_varignon")
    cases["ch05_varignon"] = (
        [(P2 - P0) / 2, (P2 + P3) / 2 - (P3 + P0) / 2],
        [(P2 - P0, "diagonal"), ((P0 - P2) / 2, "sign")])

    s_, c, d, w1, w2 = S("ch06_fixed_point")
    x, y = sympy.symbols("x y")
    R = sympy.Matrix([[c, d], [-d, c]])
    img = s_ * sympy.Matrix([[x, y]]) * R + sympy.Matrix([[w1, w2]])
    sol = sympy.solve([img[0] - x, img[1] - y], [x, y], dict=True, simplify=False)[0]
    cases["ch06_fixed_point"] = (
        [[sol[x], sol[y]], sympy.Matrix([[w1, w2]]) * (sympy.eye(2) - s_ * R).adjugate() / (sympy.eye(2) - s_ * R).det()],
        [([w1 / (1 - s_), w2 / (1 - s_)], "ignores the rotation"),
         ((sympy.eye(2) - s_ * R).inv() * sympy.Matrix([w1, w2]), "column convention")])

    t = S("ch06_segment_attractor")
    A_, B_ = sympy.symbols("A_ B_")
    pt = (1 - t) * A_ + t * B_
    coeff = [sympy.expand((pt + A_) / 2).coeff(B_), sympy.expand((pt + B_) / 2).coeff(B_)]
    cases["ch06_segment_attractor"] = (
        [coeff, [t / 2, sympy.Rational(1, 2) + t / 2]],
        [([(1 + t) / 2, t / 2], "swaps"), ([(1 - t) / 2, (2 - t) / 2], "from B")])

    f0, f1, f2 = S("ch07_newton_derivative")
    xx = sympy.symbols("xx")
    f = sympy.Function("f")
    g = xx - f(xx) / sympy.diff(f(xx), xx)
    gp = sympy.diff(g, xx).subs(sympy.Derivative(f(xx), (xx, 2)), f2).subs(sympy.Derivative(f(xx), xx), f1).subs(f(xx), f0)
    cases["ch07_newton_derivative"] = (
        [gp, f0 * f2 / f1**2],
        [(-f0 * f2 / f1**2, "sign"), (f0 * f2 / f1**2 - 1, "derivative of x")])

    a11, a12, a21, a22, b1, b2 = S("ch07_jacobi_fixed_point")
    x, y = sympy.symbols("x y")
    sol = sympy.solve([(b1 - a12 * y) / a11 - x, (b2 - a21 * x) / a22 - y], [x, y], dict=True, simplify=False)[0]
    cases["ch07_jacobi_fixed_point"] = (
        [sol[x], sympy.Matrix([[a11, a12], [a21, a22]]).LUsolve(sympy.Matrix([b1, b2]))[0]],
        [(sol[y], "is y"), (b1 / a11, "one Jacobi step")])

    x, y, px, py, wx, wy, qx, qy, vx, vy = S("ch08_change_state")
    real = {sym: sympy.Symbol(str(sym), real=True) for sym in (x, y, px, py, wx, wy, qx, qy, vx, vy)}
    back = {v: k for k, v in real.items()}

    def re_im(zexpr):
        return [e.xreplace(back) for e in sympy.expand_complex(zexpr.xreplace(real)).as_real_imag()]

    Z, P_, Q_, W, V_ = (x + sympy.I * y, px + sympy.I * py, qx + sympy.I * qy, wx + sympy.I * wy, vx + sympy.I * vy)
    d = wx**2 + wy**2
    cases["ch08_change_state"] = (
        [re_im(Q_ + V_ / W * (Z - P_)),
         [qx + ((vx * wx + vy * wy) * (x - px) - (vy * wx - vx * wy) * (y - py)) / d,
          qy + ((vx * wx + vy * wy) * (y - py) + (vy * wx - vx * wy) * (x - px)) / d]],
        [(re_im(Q_ + W / V_ * (Z - P_)), "w/v"), (re_im(Q_ + V_ / W * Z), "subtract P")])

    a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y = S("ch08_compose")
    zs = sympy.symbols("zs")
    comp = sympy.expand(((a2x + sympy.I * a2y) * ((a1x + sympy.I * a1y) * zs + (b1x + sympy.I * b1y)) + (b2x + sympy.I * b2y)).subs(zs, 0))
    realc = {sym: sympy.Symbol(str(sym), real=True) for sym in (a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y)}
    backc = {v: k for k, v in realc.items()}
    Bre, Bim = (e.xreplace(backc) for e in comp.xreplace(realc).as_real_imag())
    cases["ch08_compose"] = (
        [[Bre, Bim], [a2x * b1x - a2y * b1y + b2x, a2x * b1y + a2y * b1x + b2y]],
        [([a1x * b2x - a1y * b2y + b1x, a1x * b2y + a1y * b2x + b1y], "w1(w2(z))"), ([b1x + b2x, b1y + b2y], "adds")])
    n1, n2, n3, l1, l2, l3, e1, e2, e3, I, kd = S("ch16_lambert")
    N, L_ = sympy.Matrix([n1, n2, n3]), sympy.Matrix([l1, l2, l3])
    cases["ch16_lambert"] = (
        [kd * I * N.dot(L_), I * (kd * (N.T * L_)[0])],
        [(kd * I * (n1 * e1 + n2 * e2 + n3 * e3), "eye"), (2 * kd * I * N.dot(L_), "factor of 2")])

    d, nn, ll = S("ch16_mirror_unit")
    # |2dN - L|^2 in coordinates, then read back in terms of d, nn, ll by substituting the dot products
    Nv, Lv = sympy.Matrix(sympy.symbols("N1:4")), sympy.Matrix(sympy.symbols("L1:4"))
    R = 2 * Nv.dot(Lv) * Nv - Lv
    coords = sympy.expand(R.dot(R))
    target = 4 * d**2 * nn - 4 * d**2 + ll
    assert sympy.expand(coords - target.subs({d: Nv.dot(Lv), nn: Nv.dot(Nv), ll: Lv.dot(Lv)})) == 0
    cases["ch16_mirror_unit"] = (
        [target, 4 * d**2 * (nn - 1) + ll],
        [(4 * d**2 * nn + ll, "cross terms"), (sympy.Integer(1), "end of the proof")])

    v1, v2, v3, n1, n2, n3 = S("ch17_reflected_ray")
    v, n = sympy.Matrix([v1, v2, v3]), sympy.Matrix([n1, n2, n3])
    r = v - 2 * v.dot(n) * n
    cases["ch17_reflected_ray"] = (
        [r.dot(n), -v.dot(n)],
        [(v.dot(n), "sign of v·n"), (sympy.Integer(0), "lies in the mirror")])

    v1, v2, v3, n1, n2, n3, eta1, eta2 = S("ch17_refraction_tangent")
    v, n = sympy.Matrix([v1, v2, v3]), sympy.Matrix([n1, n2, n3])
    # n × (v × n) is the tangential part for a unit n (BAC-CAB), computed with sympy's cross
    cases["ch17_refraction_tangent"] = (
        [eta1 / eta2 * n.cross(v.cross(n)), eta1 / eta2 * (v - v.dot(n) * n)],
        [(eta2 / eta1 * (v - v.dot(n) * n), "η2/η1"), (v - v.dot(n) * n, "does not bend")])

    u, v = S("ch18_parametric_normal")
    P = sympy.Matrix([u, v, u**2 + v**2])
    cases["ch18_parametric_normal"] = (
        [P.diff(u).cross(P.diff(v)), [-2 * u, -2 * v, 1]],
        [(P.diff(v).cross(P.diff(u)), "P_v × P_u"), ([-2 * u, -2 * v, 0], "z-component")])

    u, v = S("ch18_gaussian_curvature")
    # K = det(II)/det(I) from the fundamental forms of (u, v, u² + v²)
    X = sympy.Matrix([u, v, u**2 + v**2])
    Xu, Xv = X.diff(u), X.diff(v)
    nrm = Xu.cross(Xv)
    nunit_num = nrm                                        # divide by |nrm| below
    E_, F_, G_ = Xu.dot(Xu), Xu.dot(Xv), Xv.dot(Xv)
    L2, M2, N2 = (X.diff(u, 2).dot(nunit_num), X.diff(u).diff(v).dot(nunit_num), X.diff(v, 2).dot(nunit_num))
    K = (L2 * N2 - M2**2) / nrm.dot(nrm) / (E_ * G_ - F_**2)
    cases["ch18_gaussian_curvature"] = (
        [K, 4 / (1 + 4 * u**2 + 4 * v**2)**2],
        [(4 / (1 + 4 * u**2 + 4 * v**2), "square of the denominator"), (sympy.Integer(4), "numerator")])

    p1, p2, p3, v1, v2, v3, c1, c2, c3, r = S("ch19_ray_sphere")
    tt = sympy.symbols("tt")
    X = sympy.Matrix([p1, p2, p3]) + tt * sympy.Matrix([v1, v2, v3]) - sympy.Matrix([c1, c2, c3])
    poly = sympy.Poly(sympy.expand(X.dot(X) - r**2), tt)
    coeffs = [poly.coeff_monomial(tt**2), poly.coeff_monomial(tt), poly.coeff_monomial(1)]
    w = sympy.Matrix([p1 - c1, p2 - c2, p3 - c3])
    vv = sympy.Matrix([v1, v2, v3])
    cases["ch19_ray_sphere"] = (
        [coeffs, [vv.dot(vv), 2 * vv.dot(w), w.dot(w) - r**2]],
        [([vv.dot(vv), vv.dot(w), w.dot(w) - r**2], "factor 2"), ([vv.dot(vv), 2 * vv.dot(w), w.dot(w) + r**2], "adds r²")])

    x1, x2, x3, p1, p2, p3, v1, v2, v3 = S("ch19_inversion")
    Xp, vv = sympy.Matrix([x1 - p1, x2 - p2, x3 - p3]), sympy.Matrix([v1, v2, v3])
    # least squares: the t minimising |X - P - t v|, which is t itself for points on the line
    t_ls = sympy.solve(sympy.diff((Xp - tt * vv).dot(Xp - tt * vv), tt), tt, simplify=False)[0]
    cases["ch19_inversion"] = (
        [t_ls, (x1 - p1) / v1],                         # on the line any coordinate gives t (v1 ≠ 0)
        [(Xp.dot(vv), "unit direction"), (sympy.Matrix([x1, x2, x3]).dot(vv) / vv.dot(vv), "subtract P")])

    n = S("ch20_prism_euler")
    cases["ch20_prism_euler"] = (
        [[2 * n, 3 * n, n + 2], [n + n, n + n + n, 2 + n]],
        [([2 * n, 2 * n, n + 2], "vertical edges"), ([2 * n, 3 * n, n + 1], "n-gon faces")])

    n = S("ch20_frame_euler")
    walls = 2 * n                        # outer and inner walls, one loop each
    cases["ch20_frame_euler"] = (
        [[4 * n, 6 * n, 2 * n + 2, 2 * n + 4], [2 * n + 2 * n, 4 * n + 2 * n, walls + 2, walls + 2 * 2]],
        [([4 * n, 6 * n, 2 * n + 2, 2 * n + 2], "inner loop"), ([4 * n, 4 * n, 2 * n + 2, 2 * n + 4], "vertical edges")])

    x0, y0, z0, x1, y1, z1, x2, y2, z2 = S("ch21_newell_triangle")
    P0, P1, P2 = sympy.Matrix([x0, y0, z0]), sympy.Matrix([x1, y1, z1]), sympy.Matrix([x2, y2, z2])
    cases["ch21_newell_triangle"] = (
        [(P1 - P0).cross(P2 - P0), P0.cross(P1) + P1.cross(P2) + P2.cross(P0)],
        [((P1 - P0).cross(P2 - P0) / 2, "twice the area"), ((P2 - P0).cross(P1 - P0), "other way")])

    t, a, b, c = S("ch21_phong_length")
    N0, N1 = sympy.Matrix(sympy.symbols("a1:4")), sympy.Matrix(sympy.symbols("b1:4"))
    Nt = (1 - t) * N0 + t * N1
    expr = sympy.expand(Nt.dot(Nt))
    # read the coordinates' expansion back with a, b, c (check it, then give the dot-product form)
    cand = (1 - t)**2 * a + 2 * t * (1 - t) * b + t**2 * c
    assert sympy.expand(expr - cand.subs({a: N0.dot(N0), b: N0.dot(N1), c: N1.dot(N1)})) == 0
    cases["ch21_phong_length"] = (
        [cand, a - 2 * t * (a - b) + t**2 * (a - 2 * b + c)],
        [((1 - t) * a + t * c, "squared lengths"), ((1 - t)**2 * a + t**2 * c, "cross term")])

    a, b, c, d, x, y = S("ch22_depth_increment")
    zz = sympy.symbols("zz")
    zsol = sympy.solve(a * x + b * y + c * zz + d, zz, simplify=False)[0]
    cases["ch22_depth_increment"] = (
        [zsol.subs(x, x + 1) - zsol, -a / c],
        [(a / c, "sign"), (-b / c, "column")])

    syms = S("ch22_split_edge")
    P0, P1, Q, N = (sympy.Matrix(syms[i:i + 3]) for i in (0, 3, 6, 9))
    t_sol = sympy.solve((P0 + tt * (P1 - P0) - Q).dot(N), tt, simplify=False)[0]
    cases["ch22_split_edge"] = (
        [t_sol, (Q - P0).dot(N) / (P1 - P0).dot(N)],
        [((P1 - Q).dot(N) / ((P1 - Q).dot(N) - (P0 - Q).dot(N)), "from P1"),
         ((P0 - Q).dot(N) / ((P0 - Q).dot(N) + (P1 - Q).dot(N)), "adds")])

    E1, E2, rho1, rho2, F12, F21 = S("ch23_two_patches")
    B1s, B2s = sympy.symbols("B1s B2s")
    sol = sympy.solve([E1 + rho1 * F12 * B2s - B1s, E2 + rho2 * F21 * B1s - B2s], [B1s, B2s], dict=True, simplify=False)[0]
    Kmat = sympy.Matrix([[1, -rho1 * F12], [-rho2 * F21, 1]])
    cases["ch23_two_patches"] = (
        [sol[B1s], Kmat.LUsolve(sympy.Matrix([E1, E2]))[0]],
        [(E1 + rho1 * F12 * E2, "one bounce"), ((E1 + rho1 * F21 * E2) / (1 - rho1 * rho2 * F12 * F21), "F21")])

    A1, A2 = S("ch23_reciprocity")
    f21, f22 = sympy.symbols("f21 f22")
    sol = sympy.solve([A1 * 1 - A2 * f21, f21 + f22 - 1], [f21, f22], dict=True, simplify=False)[0]
    cases["ch23_reciprocity"] = (
        [[sol[f21], sol[f22]], [A1 / A2, (A2 - A1) / A2]],
        [([A2 / A1, 1 - A2 / A1], "upside down"), ([A1 / A2, 0], "sees itself")])
    return cases


CASES = _right_and_wrong()


def test_every_exercise_is_tested_here():
    assert set(CASES) == set(proofs.PROBLEMS)


def test_two_show_that_exercises_in_every_chapter_that_proves_and_in_its_notebook():
    """Chapters 1-30 prove things (chapter 1: the closed forms of its spirals and circles); each has
    at least two exercises, and each exercise has its cell (answer = None) and a worked solution in
    its notebook."""
    from pathlib import Path

    course = Path(__file__).resolve().parents[2] / "course"
    for number in range(1, 31):
        names = [n for n in proofs.PROBLEMS if n.startswith(f"ch{number:02d}_")]
        assert len(names) >= 2, f"chapter {number} has {len(names)} show-that exercises"
        text = next(course.glob(f"{number:02d}_*.ipynb")).read_text()
        for name in names:
            assert f"proofs.{name}(answer)" in text, f"{name}: no exercise cell in the notebook"
            assert text.count(f"proofs.{name}(") >= 2, f"{name}: no worked solution in the notebook"


@pytest.mark.parametrize("name", sorted(CASES))
def test_right_answers_written_two_ways_are_accepted(name):
    check = getattr(proofs, name)
    for answer in CASES[name][0]:
        r = check(answer)
        assert r.correct, f"{name}: {r}"


@pytest.mark.parametrize("name", sorted(CASES))
def test_slips_are_rejected_and_named(name):
    check = getattr(proofs, name)
    for answer, words in CASES[name][1]:
        r = check(answer)
        assert r.answered and not r.correct, f"{name}: {r}"
        assert words in r.message, f"{name}: expected {words!r} in {r}"


# Every form in proofs.SLIPS is fed to its checker by tests/exercises/test_solutions.py
# (test_wrong_answers_are_explained_without_the_answer), which finds these checkers through the
# worked solutions in the notebooks: wrong, answered, explained, no number of the answer printed.


@pytest.mark.parametrize("name", sorted(CASES))
def test_text_none_and_docstrings(name, monkeypatch):
    check = getattr(proofs, name)
    assert not check(None).answered
    monkeypatch.setattr(sympy, "sympify", lambda *a, **k: pytest.fail("text was evaluated"))
    syms = S(name) if isinstance(S(name), tuple) else (S(name),)
    r = check(" + ".join(str(s) for s in syms))
    assert r.answered and not r.correct and "evaluates no text" in r.message
    # the docstring (Shift+Tab) says what is checked, not the expression
    right = CASES[name][0][0]
    for entry in (right if isinstance(right, (list, sympy.MatrixBase)) else [right]):
        for item in (entry if isinstance(entry, list) else [entry]):
            text = str(sympy.expand(item))
            if len(text) > 4:
                assert text not in check.__doc__


def test_a_huge_answer_returns_quickly():
    w, x, y, z, v1, v2, v3 = S("ch15_sandwich_is_pure")
    huge = [(w + x + y + z + v1 + v2 + v3)**60] * 4
    t0 = time.process_time()     # CPU time: the suite runs beside two browsers
    r = proofs.ch15_sandwich_is_pure(huge)
    assert time.process_time() - t0 < 5 and not r.correct and "too large" in r.message


def test_the_rodrigues_exercise_is_the_real_expansion():
    """|R(v)|² in coordinates with a unit axis equals the exercise's expression with p = a·v, n = |v|²
    and any c, s (so the exercise asks for a true step of the proof), at exact rational points."""
    c, sn, p, n = S("ch12_rodrigues_length")
    step = (c**2 + sn**2) * n + (1 - c**2 - sn**2) * p**2
    R = sympy.Rational
    for uu, vv, cc, ss, v in [(R(1, 2), R(-3, 4), R(2, 3), R(5, 7), [1, -2, 3]), (R(3), R(1, 5), R(-1, 3), R(4), [R(1, 2), 0, -7])]:
        d = 1 + uu**2 + vv**2
        a = sympy.Matrix([2 * uu / d, 2 * vv / d, (1 - uu**2 - vv**2) / d])
        assert a.dot(a) == 1
        v = sympy.Matrix(v)
        rot = cc * v + (1 - cc) * a.dot(v) * a + ss * a.cross(v)
        assert rot.dot(rot) == step.subs({c: cc, sn: ss, p: a.dot(v), n: v.dot(v)})
