"""Exercise checkers for chapter 15, complex numbers and quaternions (Goldman §15.2-15.3).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0
is the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the
current instance.  The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) ask
for an identity, not a number, so they do not deal.  ``SLIPS`` holds the wrong answers of the kinds
each checker recognises, for the stored instance.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other numbers, quaternions and angles than the chapter's worked examples.  The
programming project, :func:`check_slerp_project`, runs the learner's ``slerp(q0, q1, t)`` against
:func:`goldman_lib.quaternions.slerp` on seeded cases, degenerate ones included.

Quaternions are written (w, x, y, z), w the scalar part; matrices follow the book's row convention
(v' = v M).

>>> print(PROBLEMS["check_quaternion_product"])
Compute the quaternion product p q for p = (1, 2, 0, -1) and q = (2, -1, 1, 3), written (w, x, y, z) = w + x i + y j + z k. Give [w, x, y, z] (Goldman §15.3.1).
>>> check_quaternion_product([7, 2, 6, -1])
Not yet: that is q p, the product in the other order: the quaternion product is not commutative (u × v changes sign), so p q and q p differ. Multiply with p on the left.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import quaternions as qt
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.deal import Deck, integers as _ints, memo, pick as _pick, steps_number as _f6, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "COMPLEX_FROM", "COMPLEX_TO", "PRODUCT_P", "PRODUCT_Q", "ROTATION_AXIS",
           "ROTATION_ANGLE", "ROTATION_V", "CONFORMAL_Q", "CONFORMAL_V", "MATRIX_Q", "SLERP_Q0", "SLERP_Q1", "SLERP_T",
           "LERP_ANGLE", "LERP_T", "DECK", "deal", "steps", "current", "deal_button", "check_complex_factor", "check_quaternion_product", "check_rotated_vector",
           "check_conformal_image", "check_rotation_matrix", "check_slerp_angle", "check_lerp_distortion",
           "check_slerp_project", "slerp_project_cases"]

#: Exercise 1 (§15.2): the complex number z with z (2 + i) = -1 + 3i.
COMPLEX_FROM = (2.0, 1.0)
COMPLEX_TO = (-1.0, 3.0)
#: Exercise 2 (§15.3.1): the factors of a product.
PRODUCT_P = (1.0, 2.0, 0.0, -1.0)
PRODUCT_Q = (2.0, -1.0, 1.0, 3.0)
#: Exercise 3 (§15.3.2): a rotation by axis and angle, and the vector it turns.
ROTATION_AXIS = (1.0, 0.0, 1.0)
ROTATION_ANGLE = 90.0
ROTATION_V = (1.0, 2.0, 0.0)
#: Exercise 4 (§15.3.2): a non-unit quaternion and the vector its conformal map sends.
CONFORMAL_Q = (1.0, 2.0, 0.0, 2.0)
CONFORMAL_V = (0.0, 1.0, 0.0)
#: Exercise 5 (§15.3.6): a unit quaternion to convert to a matrix.
MATRIX_Q = (0.6, 0.0, 0.48, 0.64)
#: Exercise 6 (§15.3.5): two orientations about the z-axis (q1 has w < 0) and the time.
SLERP_Q0 = (0.93969, 0.0, 0.0, 0.34202)
SLERP_Q1 = (-0.86603, 0.0, 0.0, 0.5)
SLERP_T = 0.3
#: Exercise 7 (§15.3.4): the linear blend (1 - t) I + t R of the identity and a turn about z.
LERP_ANGLE = 120.0
LERP_T = 0.25


DECK = Deck("ch15")


def _q_text(q) -> str:
    return "(" + ", ".join(fmt(v) for v in q) + ")"


def _q5(q) -> str:
    return "(" + ", ".join(f"{v:.5f}" for v in q) + ")"


def _arr(v) -> np.ndarray:
    return np.asarray(v, dtype=float)


def _tup(a) -> tuple:
    return tuple(float(x) for x in np.asarray(a, dtype=float).ravel())


def _root_text(n2: float) -> str:
    """The square root of a whole number as a learner writes it: 3 for 9, √2 for 2."""
    r = math.isqrt(int(round(n2)))
    return fmt(r) if r * r == int(round(n2)) else f"√{fmt(n2)}"


def _complex_text(c) -> str:
    """A Gaussian integer written a + b i: 2 + i, -1 + 3i, 2 - i, 3, -i."""
    re, im = (float(x) for x in c)
    if im == 0:
        return fmt(re)
    mag = "" if abs(im) == 1 else fmt(abs(im))
    if re == 0:
        return ("-" if im < 0 else "") + mag + "i"
    return f"{fmt(re)} {'-' if im < 0 else '+'} {mag}i"


def _named(name, phrases):
    """``well_posed`` part shared by the exercises: on this instance the checker accepts the answer
    and names every slip by its own misconception (the checker tests the forms it recognises in
    turn, so a slip must not fall into an earlier slip's test)."""
    def ok(p):
        ex = DECK.exercises[name]
        if not ex.check(_plain(ex.answer(p)), p).correct:
            return "the checker refuses the answer (rounding)"
        for slip, value in ex.slips(p).items():
            r = ex.check(_plain(value), p)
            if r.correct or phrases[slip] not in r.message:
                return f"the slip '{slip}' is not named by its own message"
        return None
    return ok


def _plain(value):
    arr = np.asarray(value)
    return arr.tolist() if arr.dtype.kind in "biuf" else value


# -- §15.2 ---------------------------------------------------------------------------------------------

_STORED_COMPLEX = {"a": COMPLEX_FROM, "b": COMPLEX_TO}
_COMPLEX_PHRASES = {"the product": "the product", "upside down": "upside down",
                    "the wrong conjugate": "instead of its conjugate", "coordinatewise": "one by one"}


@memo
def _complex_answers(p):
    a, b = complex(*p["a"]), complex(*p["b"])
    pair = lambda c: (c.real, c.imag)  # noqa: E731
    slips = {"the product": pair(a * b), "upside down": pair(a / b),
             "the wrong conjugate": pair(b * a / abs(a) ** 2),
             "coordinatewise": (b.real / a.real, b.imag / a.imag)}
    return pair(b / a), slips


def _complex_generate(rng) -> dict:
    return {"a": _ints(rng, -3, 3, 2), "b": _ints(rng, -4, 4, 2)}


def _complex_ok(p):
    a, b = p["a"], p["b"]
    if a[0] == 0 or a[1] == 0:
        return "2 + i must have both parts nonzero (the coordinatewise slip divides by them)"
    z = complex(*b) / complex(*a)
    if abs(z.imag) < 0.1 or abs(z.real) < 0.1:
        return "z is (nearly) real or imaginary: a turn by a multiple of 90 degrees teaches less"
    return _named("check_complex_factor", _COMPLEX_PHRASES)(p)


def _complex_statement(p) -> str:
    a, b = p["a"], p["b"]
    return (f"Which complex number z sends the point {_q_text(a)} = {_complex_text(a)} to {_q_text(b)} = "
            f"{_complex_text(b)} by multiplication (z ({_complex_text(a)}) = {_complex_text(b)})? Give z as [Re z, Im z]; "
            f"multiplying by z then rotates the whole plane by arg z and scales it by |z| (Goldman §15.2).")


def _complex_steps(p) -> str:
    a, b = complex(*p["a"]), complex(*p["b"])
    conj = a.conjugate()
    top = b * conj
    z = complex(*_complex_answers(p)[0])
    scale, angle = qt.complex_polar(z)
    n2 = abs(a) ** 2
    return (f"1. z = ({_complex_text(p['b'])}) / ({_complex_text(p['a'])}); multiply top and bottom by the conjugate "
            f"{_complex_text((conj.real, conj.imag))}.\n"
            f"2. Top: ({_complex_text(p['b'])})({_complex_text((conj.real, conj.imag))}) = "
            f"{_complex_text((top.real, top.imag))} (using i^2 = -1); bottom: |{_complex_text(p['a'])}|^2 = {fmt(n2)}.\n"
            f"3. z = ({_complex_text((top.real, top.imag))}) / {fmt(n2)} = {_f6(z.real)} + {_f6(z.imag)} i, "
            f"so [Re z, Im z] = {_f6([z.real, z.imag])}.\n"
            f"4. Check: |z| = {_f6(scale)} = |{_complex_text(p['b'])}| / |{_complex_text(p['a'])}|, and multiplying "
            f"by z turns the plane by arg z = {_f6(angle)} degrees.")


@DECK.exercise(stored=_STORED_COMPLEX, generate=_complex_generate, answer=lambda p: _complex_answers(p)[0],
               slips=lambda p: _complex_answers(p)[1], statement=_complex_statement, steps=_complex_steps,
               same=within(1e-4), well_posed=_complex_ok)
def check_complex_factor(answer, p) -> Result:
    """Check the complex number z that multiplies the statement's first point into its second, a
    quotient of complex numbers (Goldman §15.2); read as [Re z, Im z] or as a Python complex number.

    Recognises the product instead of the quotient, the quotient the other way up, a conjugate
    taken on the wrong factor, and coordinates divided one by one.
    """
    if isinstance(answer, (complex, np.complexfloating)):
        answer = [answer.real, answer.imag]   # the chapter computes with Python complex numbers too
    got, err = _read_vector(answer, "your z", 2, "z as [Re z, Im z]")
    if err is not None:
        return err
    a, b = complex(*p["a"]), complex(*p["b"])
    at, bt = _complex_text(p["a"]), _complex_text(p["b"])
    ct = _complex_text((a.real, -a.imag))
    expected, slips = _complex_answers(p)
    tol = 1e-4
    if _close(got, expected, tol):
        z = complex(*expected)
        scale, angle = qt.complex_polar(z)
        return correct(f"z = {fmt(z.real)} + {fmt(z.imag)} i: multiplying by z rotates the plane by "
                       f"{fmt(angle, 4)} degrees and scales it by |z| = {fmt(scale, 4)} = |{bt}| / |{at}|.")
    if _close(got, slips["the product"], tol):
        return wrong(f"that is ({at})({bt}), the product; z is the quotient ({bt}) / ({at}): multiply top and "
                     f"bottom by the conjugate {ct}.")
    if _close(got, slips["upside down"], tol):
        return wrong(f"that is ({at}) / ({bt}), the quotient upside down: it sends {bt} back to {at}.")
    if _close(got, slips["the wrong conjugate"], tol):
        return wrong(f"you multiplied by {at} instead of its conjugate {ct}: 1 / ({at}) = ({ct}) / |{at}|^2.")
    if _close(got, slips["coordinatewise"], tol):
        return wrong(f"you divided the coordinates one by one; complex division is not coordinatewise "
                     f"(i^2 = -1 mixes them): multiply top and bottom by the conjugate {ct}.")
    return wrong(f"your z is {_dist(got, expected)} from the right one; check that z ({at}) "
                 f"gives {bt}, using i^2 = -1.")


# -- §15.3.1 -------------------------------------------------------------------------------------------

_STORED_PRODUCT = {"p": PRODUCT_P, "q": PRODUCT_Q}
_PRODUCT_PHRASES = {"q p": "that is q p", "no cross product": "lacks the cross product",
                    "plus u·v": "adds u·v", "coordinatewise": "coordinate by coordinate"}


@memo
def _product_answers(p):
    P, Q = _arr(p["p"]), _arr(p["q"])
    a, u, b, v = P[0], P[1:], Q[0], Q[1:]
    slips = {"q p": qt.multiply(Q, P), "no cross product": np.r_[a * b - u @ v, a * v + b * u],
             "plus u·v": np.r_[a * b + u @ v, a * v + b * u + np.cross(u, v)], "coordinatewise": P * Q}
    return qt.multiply(P, Q), slips


def _product_generate(rng) -> dict:
    return {"p": _ints(rng, -3, 3, 4), "q": _ints(rng, -3, 3, 4)}


def _product_ok(p):
    P, Q = _arr(p["p"]), _arr(p["q"])
    if np.linalg.norm(np.cross(P[1:], Q[1:])) == 0:
        return "the vector parts are parallel: p and q commute, so the order would not matter"
    if P[0] == 0 or Q[0] == 0:
        return "a pure factor leaves out the terms a v and b u"
    return _named("check_quaternion_product", _PRODUCT_PHRASES)(p)


def _product_statement(p) -> str:
    return (f"Compute the quaternion product p q for p = {_q_text(p['p'])} and q = {_q_text(p['q'])}, written "
            f"(w, x, y, z) = w + x i + y j + z k. Give [w, x, y, z] (Goldman §15.3.1).")


def _product_steps(p) -> str:
    P, Q = _arr(p["p"]), _arr(p["q"])
    a, u, b, v = P[0], P[1:], Q[0], Q[1:]
    pq = _product_answers(p)[0]
    return (f"1. p = (a, u) with a = {fmt(a)}, u = {fmt(u)}; q = (b, v) with b = {fmt(b)}, v = {fmt(v)}.\n"
            f"2. Scalar part: ab - u·v = {fmt(a * b)} - ({fmt(u @ v)}) = {fmt(pq[0])}.\n"
            f"3. Vector part: a v + b u + u × v = {fmt(a * v)} + {fmt(b * u)} + {fmt(np.cross(u, v))} = {fmt(pq[1:])}.\n"
            f"4. p q = {fmt(pq)}; in the other order q p = {fmt(qt.multiply(Q, P))} (u × v changes sign).")


@DECK.exercise(stored=_STORED_PRODUCT, generate=_product_generate, answer=lambda p: _product_answers(p)[0],
               slips=lambda p: _product_answers(p)[1], statement=_product_statement, steps=_product_steps,
               same=within(1e-6), well_posed=_product_ok)
def check_quaternion_product(answer, p) -> Result:
    """Check the product p q = (ab - u·v, a v + b u + u × v) of the statement's p and q
    (Goldman §15.3.1).

    Recognises q p (the other order), a missing cross product, a plus sign on the dot product, and
    the coordinatewise product.
    """
    got, err = _read_vector(answer, "your product", 4, "p q as [w, x, y, z]")
    if err is not None:
        return err
    P, Q = _arr(p["p"]), _arr(p["q"])
    expected, slips = _product_answers(p)
    tol = 1e-6
    if _close(got, expected, tol):
        return correct(f"p q = {fmt(expected)}, while q p = {fmt(slips['q p'])}: the two differ by 2 u × v, "
                       f"so the product is not commutative.")
    if _close(got, slips["q p"], tol):
        return wrong("that is q p, the product in the other order: the quaternion product is not commutative "
                     "(u × v changes sign), so p q and q p differ. Multiply with p on the left.")
    if _close(got, slips["no cross product"], tol):
        return wrong("your vector part lacks the cross product u × v: (a, u)(b, v) = (ab - u·v, a v + b u + u × v), "
                     "since i j = k, j k = i, k i = j.")
    if _close(got, slips["plus u·v"], tol):
        return wrong("your scalar part adds u·v; it subtracts it, since i^2 = j^2 = k^2 = -1: "
                     "the scalar part is ab - u·v.")
    if _close(got, slips["coordinatewise"], tol):
        return wrong("you multiplied coordinate by coordinate; expand (a + u)(b + v) with the rules i^2 = -1, "
                     "i j = k = -j i, and so on.")
    return wrong(f"your product is {_dist(got, expected)} from p q; use (a, u)(b, v) = "
                 f"(ab - u·v, a v + b u + u × v) with a = {fmt(P[0])}, u = {fmt(P[1:])}, b = {fmt(Q[0])}, "
                 f"v = {fmt(Q[1:])}.")


# -- §15.3.2 -------------------------------------------------------------------------------------------

def _sandwich(a, v, b):
    """The vector part of a (0, v) b."""
    return qt.multiply(qt.multiply(a, np.r_[0.0, v]), b)[1:]


_STORED_ROTATION = {"axis": ROTATION_AXIS, "angle": ROTATION_ANGLE, "v": ROTATION_V}
#: cos and sin of the half angles of the rotations dealt, written exactly
_HALF_TRIG = {30.0: ("√3/2", "1/2"), 45.0: ("√2/2", "√2/2"), 135.0: ("-√2/2", "√2/2"), 150.0: ("-√3/2", "1/2")}
_ROTATION_AXES = ((1.0, 0.0, 1.0), (1.0, 1.0, 0.0), (0.0, 1.0, 1.0), (1.0, -1.0, 0.0), (1.0, 0.0, -1.0),
                  (0.0, 1.0, -1.0), (1.0, 1.0, 1.0), (1.0, -1.0, 1.0), (1.0, 1.0, -1.0), (-1.0, 1.0, 1.0),
                  (1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (2.0, 2.0, 1.0), (2.0, -1.0, 2.0), (0.0, 3.0, 4.0), (3.0, 0.0, 4.0))
_ROTATION_PHRASES = {"twice the angle": "twice the angle", "q* v q": "that is q* v q", "q v q": "q v q:",
                     "radians": "as if it were radians", "axis not normalised": "not a unit quaternion"}


@memo
def _rotation_answers(p):
    axis, th, v = _arr(p["axis"]), float(p["angle"]), _arr(p["v"])
    q = qt.from_axis_angle(axis, th)
    raw = np.r_[math.cos(math.radians(th) / 2), math.sin(math.radians(th) / 2) * axis]
    slips = {"twice the angle": qt.rotate(qt.from_axis_angle(axis, 2 * th), v),
             "q* v q": _sandwich(qt.conjugate(q), v, q), "q v q": _sandwich(q, v, q),
             "radians": qt.rotate(qt.from_axis_angle(axis, math.degrees(th)), v),
             "axis not normalised": _sandwich(raw, v, qt.conjugate(raw))}
    return qt.rotate(q, v), slips


def _rotation_generate(rng) -> dict:
    return {"axis": _pick(rng, _ROTATION_AXES), "angle": float(_pick(rng, (60.0, 90.0, 270.0, 300.0))),
            "v": _ints(rng, -2, 2, 3)}


def _rotation_ok(p):
    axis, v = _arr(p["axis"]), _arr(p["v"])
    if np.linalg.norm(np.cross(axis, v)) / np.linalg.norm(axis) < 0.5:
        return "v lies on (or near) the axis: it hardly moves"
    return _named("check_rotated_vector", _ROTATION_PHRASES)(p)


def _rotation_statement(p) -> str:
    return (f"Let q be the unit quaternion of the rotation by {fmt(p['angle'])} degrees about the axis "
            f"{_q_text(p['axis'])} (counterclockwise looking down the axis towards the origin). Rotate "
            f"v = {_q_text(p['v'])} by q v q*: give the image [x, y, z], to 4 decimals (Goldman §15.3.2).")


def _half_text(th) -> str:
    h = th / 2
    c, s = _HALF_TRIG.get(h, (_f6(math.cos(math.radians(h))), _f6(math.sin(math.radians(h)))))
    return f"θ/2 = {fmt(h)}°, cos {fmt(h)}° = {c}, sin {fmt(h)}° = {s}"


def _rotation_steps(p) -> str:
    axis, th, v = _arr(p["axis"]), float(p["angle"]), _arr(p["v"])
    q = qt.from_axis_angle(axis, th)
    qv = qt.multiply(q, np.r_[0.0, v])
    qvq = qt.multiply(qv, qt.conjugate(q))
    return (f"1. The unit axis u = {fmt(axis)} / {_root_text(axis @ axis)} = {_f6(axis / np.linalg.norm(axis))}; "
            f"{_half_text(th)}.\n"
            f"2. q = (cos(θ/2), sin(θ/2) u) = {_f6(q)}.\n"
            f"3. q v = {_f6(qv)} (its scalar part is -q⃗·v: not a vector yet).\n"
            f"4. (q v) q* = {_f6(qvq)}: scalar part 0, and the image is {_f6(qvq[1:])}, "
            f"of length |v| = {_f6(np.linalg.norm(v))}.")


@DECK.exercise(stored=_STORED_ROTATION, generate=_rotation_generate, answer=lambda p: _rotation_answers(p)[0],
               slips=lambda p: _rotation_answers(p)[1], statement=_rotation_statement, steps=_rotation_steps,
               same=within(2e-4), well_posed=_rotation_ok)
def check_rotated_vector(answer, p) -> Result:
    """Check q v q* for the unit quaternion q of the statement's rotation (an angle about an axis)
    and its vector v (Goldman §15.3.2).

    Recognises the full angle in q (cos θ, not cos θ/2: twice the rotation), the opposite rotation
    (q* v q), q v q instead of q v q*, the angle taken in radians, and an axis left unnormalised.
    """
    got, err = _read_vector(answer, "your image", 3, "the image as [x, y, z]")
    if err is not None:
        return err
    axis, th, v = _arr(p["axis"]), float(p["angle"]), _arr(p["v"])
    expected, slips = _rotation_answers(p)
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"q v q* = {fmt(expected)}: the part of v along the axis stays, the rest turns by "
                       f"{fmt(th)} degrees about it; the length {fmt(np.linalg.norm(v), 4)} is kept.")
    if _close(got, slips["twice the angle"], tol):
        return wrong("you rotated by twice the angle: q v q* turns by θ when q = (cos(θ/2), sin(θ/2) u), the half "
                     "angle, because q acts twice (once on each side).")
    if _close(got, slips["q* v q"], tol):
        return wrong("that is q* v q, the rotation the other way (clockwise looking down the axis); the "
                     "counterclockwise rotation is q v q*.")
    if _close(got, slips["q v q"], tol):
        return wrong("that is (the vector part of) q v q: the right side must be the conjugate q*, otherwise the "
                     "result is not even a pure vector.")
    if _close(got, slips["radians"], tol):
        return wrong(f"you took cos and sin of the angle in degrees as if it were radians: np.cos and math.cos take "
                     f"radians, so convert first ({_half_text(th)}).")
    if _close(got, slips["axis not normalised"], tol):
        return wrong(f"your q is not a unit quaternion: the axis {_q_text(axis)} has length {_root_text(axis @ axis)}, "
                     f"so normalise it to u = {_q_text(axis)}/{_root_text(axis @ axis)} before forming "
                     f"(cos(θ/2), sin(θ/2) u); otherwise q v q* also scales by |q|^2.")
    h = fmt(th / 2)
    return wrong(f"your image is {_dist(got, expected)} from q v q*; its length should stay "
                 f"|v| = {fmt(np.linalg.norm(v), 4)} (yours is {fmt(np.linalg.norm(got), 4)}). Split v into its part "
                 f"along u and the rest, or multiply out q v q* with q = (cos {h}°, sin {h}° u).")


_STORED_CONFORMAL = {"q": CONFORMAL_Q, "v": CONFORMAL_V}
_CONFORMAL_PHRASES = {"the rotation alone": "rotation alone", "scaled by |q|": "scaled by |q|",
                      "q* v q": "that is q* v q", "q v q": "q v q:"}


@memo
def _conformal_answers(p):
    q, v = _arr(p["q"]), _arr(p["v"])
    expected = qt.conformal_map(q, v)
    n = float(qt.norm(q))
    slips = {"the rotation alone": expected / (n * n), "scaled by |q|": expected / n,
             "q* v q": _sandwich(qt.conjugate(q), v, q), "q v q": _sandwich(q, v, q)}
    return expected, slips


def _conformal_generate(rng) -> dict:
    w = float(rng.choice([-2.0, -1.0, 1.0, 2.0]))
    return {"q": (w,) + _ints(rng, -2, 2, 3), "v": _ints(rng, -2, 2, 3)}


def _conformal_ok(p):
    q, v = _arr(p["q"]), _arr(p["v"])
    if np.linalg.norm(np.cross(q[1:], v)) < 0.5:
        return "v lies along the vector part of q (or q or v is zero there): the rotation leaves v alone"
    return _named("check_conformal_image", _CONFORMAL_PHRASES)(p)


def _conformal_statement(p) -> str:
    return (f"The quaternion q = {_q_text(p['q'])} is not a unit quaternion. Compute the vector part of q v q* for "
            f"v = {_q_text(p['v'])}: the image of v under the conformal map of q. Give [x, y, z] "
            f"(Goldman §15.3.2).")


def _conformal_steps(p) -> str:
    q, v = _arr(p["q"]), _arr(p["v"])
    w, u = q[0], q[1:]
    image = _conformal_answers(p)[0]
    return (f"1. q = (w, u) with w = {fmt(w)}, u = {fmt(u)}; multiplying out (w, u)(0, v)(w, -u) gives "
            f"q v q* = (w^2 - |u|^2) v + 2(u·v) u + 2w u × v.\n"
            f"2. w^2 - |u|^2 = {fmt(w * w - u @ u)}, u·v = {fmt(u @ v)}, u × v = {fmt(np.cross(u, v))}.\n"
            f"3. q v q* = {fmt(w * w - u @ u)} {fmt(v)} + {fmt(2 * (u @ v))} {fmt(u)} + {fmt(2 * w)} "
            f"{fmt(np.cross(u, v))} = {_f6(image)}.\n"
            f"4. Check: |q|^2 = {fmt(q @ q)} and |q v q*| = |q|^2 |v| = {_f6(np.linalg.norm(image))}.")


@DECK.exercise(stored=_STORED_CONFORMAL, generate=_conformal_generate, answer=lambda p: _conformal_answers(p)[0],
               slips=lambda p: _conformal_answers(p)[1], statement=_conformal_statement, steps=_conformal_steps,
               same=within(1e-4), well_posed=_conformal_ok)
def check_conformal_image(answer, p) -> Result:
    """Check the vector part of q v q* for the statement's quaternion q (not a unit quaternion) and
    its vector v: a rotation with a scaling by |q|^2 (Goldman §15.3.2).

    Recognises the rotation alone (divided by |q|^2), a scaling by |q| instead of |q|^2, q* v q
    (the other rotation) and q v q.
    """
    got, err = _read_vector(answer, "your image", 3, "the image as [x, y, z]")
    if err is not None:
        return err
    q = _arr(p["q"])
    expected, slips = _conformal_answers(p)
    n = float(qt.norm(q))
    tol = 1e-4
    if _close(got, expected, tol):
        return correct(f"q v q* = {fmt(expected)}: the rotation of q/|q| followed by the scaling by "
                       f"|q|^2 = {fmt(n * n)} (|q| = {fmt(n)}), a conformal map.")
    if _close(got, slips["the rotation alone"], tol):
        return wrong("that is the rotation alone (q/|q| v (q/|q|)*, or q v q^-1): q v q* with a non-unit q also "
                     "scales every vector by |q|^2.")
    if _close(got, slips["scaled by |q|"], tol):
        return wrong("you scaled by |q|; q v q* scales by |q|^2, since q and q* each contribute a factor |q|.")
    if _close(got, slips["q* v q"], tol):
        return wrong("that is q* v q: it turns the other way. Multiply q v first, then by q* on the right.")
    if _close(got, slips["q v q"], tol):
        return wrong(f"that is (the vector part of) q v q: the right factor is the conjugate "
                     f"q* = {_q_text(qt.conjugate(q))}.")
    return wrong(f"your image is {_dist(got, expected)} from q v q*; its length should be "
                 f"|q|^2 |v| (yours is {fmt(np.linalg.norm(got), 4)}). Multiply (0, v) by q on the left, then by "
                 f"q* on the right.")


# -- §15.3.6 -------------------------------------------------------------------------------------------

def _rational_units():
    """Unit quaternions whose entries are short decimals: (a, b, c, d)/n with a^2 + b^2 + c^2 + d^2 = n^2
    and n in 2, 5, 10, 25 (so a learner squares and doubles them by hand), sorted entries."""
    out = []
    for n in (2, 5, 10, 25):
        for a in range(n + 1):
            for b in range(a, n + 1):
                for c in range(b, n + 1):
                    d2 = n * n - a * a - b * b - c * c
                    d = math.isqrt(max(d2, 0))
                    if d2 >= 0 and d * d == d2 and d >= c and math.gcd(math.gcd(a, b), math.gcd(c, d)) == 1:
                        out.append(tuple(x / n for x in (a, b, c, d)))
    return tuple(out)


_UNITS = _rational_units()
_STORED_MATRIX = {"q": MATRIX_Q}
_MATRIX_PHRASES = {"transposed": "transposed matrix", "off-diagonal halved": "off-diagonal entries are half",
                   "diagonal without 2": "diagonal entries lack", "(x, y, z, w)": "order (x, y, z, w)"}


def _row_matrix(q) -> np.ndarray:
    return qt.to_matrix(q)[:3, :3]


@memo
def _matrix_answers(p):
    w, x, y, z = p["q"]
    expected = _row_matrix(p["q"])
    half = expected.copy()
    off = ~np.eye(3, dtype=bool)
    half[off] = expected[off] / 2
    no2 = expected.copy()
    no2[np.diag_indices(3)] = [1 - (y * y + z * z), 1 - (x * x + z * z), 1 - (x * x + y * y)]
    slips = {"transposed": expected.T, "off-diagonal halved": half, "diagonal without 2": no2,
             "(x, y, z, w)": _row_matrix((z, w, x, y))}
    return expected, slips


def _matrix_generate(rng) -> dict:
    q = np.array(_pick(rng, _UNITS))[rng.permutation(4)] * rng.choice([-1.0, 1.0], size=4)
    return {"q": _tup(q + 0.0)}


def _matrix_ok(p):
    w, x, y, z = p["q"]
    if w == 0 or (x, y, z) == (0, 0, 0):
        return "a half turn (w = 0) has a symmetric matrix, and the identity (x = y = z = 0) teaches nothing"
    if min(x * x, y * y, z * z) == 0 and sum(c != 0 for c in (x, y, z)) < 2:
        return "a turn about a coordinate axis: too many entries are 0 or 1"
    return _named("check_rotation_matrix", _MATRIX_PHRASES)(p)


def _matrix_statement(p) -> str:
    return (f"Convert the unit quaternion q = {_q_text(p['q'])} to the 3x3 matrix M of its rotation in the book's "
            f"row convention (v' = v M, so the first row is the image of (1, 0, 0)). Give M as [[..], [..], [..]] "
            f"(Goldman §15.3.6).")


def _matrix_steps(p) -> str:
    w, x, y, z = p["q"]
    M = _matrix_answers(p)[0]
    rows = [f"   row {i + 1}, the image of {fmt(e)} by q v q*: {_f6(qt.rotate(p['q'], e))}"
            for i, e in enumerate(np.eye(3))]
    return (f"1. w = {fmt(w)}, x = {fmt(x)}, y = {fmt(y)}, z = {fmt(z)}; w^2 + x^2 + y^2 + z^2 = "
            f"{fmt(w * w + x * x + y * y + z * z)}, a unit quaternion.\n"
            f"2. Row convention (v' = v M): M = [[1 - 2(y^2 + z^2), 2(xy + wz), 2(xz - wy)], "
            f"[2(xy - wz), 1 - 2(x^2 + z^2), 2(yz + wx)], [2(xz + wy), 2(yz - wx), 1 - 2(x^2 + y^2)]].\n"
            f"3. With the numbers: M = [" + ", ".join(_f6(r) for r in M) + "].\n"
            f"4. Check: the rows are the images of the axes,\n" + "\n".join(rows))


@DECK.exercise(stored=_STORED_MATRIX, generate=_matrix_generate, answer=lambda p: _matrix_answers(p)[0],
               slips=lambda p: _matrix_answers(p)[1], statement=_matrix_statement, steps=_matrix_steps,
               same=within(2e-4), well_posed=_matrix_ok)
def check_rotation_matrix(answer, p) -> Result:
    """Check the row-convention rotation matrix of the statement's unit quaternion (Goldman §15.3.6).

    Accepts the 4x4 matrix too.  Recognises the transposed (column-convention) matrix, off-diagonal
    entries without their factor 2, the diagonal 1 - (y^2 + z^2) without the 2, and q read in the
    order (x, y, z, w).
    """
    got, err = read_points(answer, "your matrix", ask="M as [[..], [..], [..]]")
    if err is not None:
        return err
    if got.shape == (4, 4):
        if not (_close(got[3], [0, 0, 0, 1], 1e-6) and _close(got[:3, 3], [0, 0, 0], 1e-6)):
            return wrong("a 4x4 rotation matrix has last row and last column (0, 0, 0, 1); or give the 3x3 block.")
        got = got[:3, :3]
    if got.shape != (3, 3):
        return wrong(f"M is a 3x3 matrix; yours has shape {got.shape}.")
    expected, slips = _matrix_answers(p)
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"M has determinant {fmt(np.linalg.det(got), 4)} and orthonormal rows; its first row "
                       f"{fmt(expected[0])} is the image of (1, 0, 0).")
    if _close(got, expected.T, tol):
        return wrong("that is the transposed matrix, for column vectors (v' = R v), which is also the matrix of the "
                     "rotation q*: in the row convention v' = v M, the first row is the image of (1, 0, 0).")
    xyzw = slips["(x, y, z, w)"]
    if _close(got, xyzw, tol) or _close(got, xyzw.T, tol):
        return wrong("you read q in the order (x, y, z, w): the course writes quaternions (w, x, y, z) = "
                     "w + x i + y j + z k, the scalar part first (some libraries, scipy among them, put it last).")
    half = slips["off-diagonal halved"]
    off = ~np.eye(3, dtype=bool)
    if _close(got[off], half[off], tol) or _close(got[off], half.T[off], tol):
        return wrong("your off-diagonal entries are half what they should be: they are 2(xy ± wz), 2(xz ± wy), "
                     "2(yz ± wx), with the factor 2.")
    if _close(np.diag(got), np.diag(slips["diagonal without 2"]), tol):
        return wrong("your diagonal entries lack the factor 2: they are 1 - 2(y^2 + z^2), 1 - 2(x^2 + z^2), "
                     "1 - 2(x^2 + y^2).")
    bad = np.argwhere(np.abs(got - expected) > tol)
    i, j = (int(k) for k in bad[0])
    return wrong(f"{len(bad)} of the 9 entries are off, the first, M[{i}][{j}], is "
                 f"{off_by(got[i, j], expected[i, j])}; check it against (1, 0, 0), (0, 1, 0), (0, 0, 1) "
                 f"rotated by q v q*: those images are the rows of M.")


# -- §15.3.4-15.3.5 ------------------------------------------------------------------------------------

def _z_angle(q) -> float:
    """The signed angle (degrees, in (-180, 180]) of a rotation about +z given by a quaternion."""
    q = np.asarray(q, float)
    ang = math.degrees(2 * math.atan2(q[3], q[0]))
    return (ang + 180.0) % 360.0 - 180.0 if ang != 180.0 else 180.0


def _slerp_degrees_as_radians(q0, q1, t):
    """The slerp weights computed with the angle between q0 and q1 in degrees fed to a radian sine."""
    th = math.degrees(math.acos(float(np.clip(q0 @ q1, -1, 1))))
    return (math.sin((1 - t) * th) * q0 + math.sin(t * th) * q1) / math.sin(th)


def _longer(q0, q1, t):
    """The great arc from q0 to q1 itself (q1 not negated)."""
    th = math.acos(float(np.clip(q0 @ q1, -1, 1)))
    return (math.sin((1 - t) * th) * q0 + math.sin(t * th) * q1) / math.sin(th)


_STORED_SLERP = {"q0": SLERP_Q0, "q1": SLERP_Q1, "t": SLERP_T}
_SLERP_PHRASES = {"the longer arc": "longer way round", "the half angle": "half angle",
                  "t from q1": "measured t from q1", "radians": "as if it were radians",
                  "nlerp": "normalised linear interpolation"}


@memo
def _slerp_answers(p):
    q0, q1, t = _arr(p["q0"]), _arr(p["q1"]), float(p["t"])
    expected = _z_angle(qt.slerp(q0, q1, t))
    slips = {"the longer arc": _z_angle(_longer(q0, q1, t)), "the half angle": expected / 2,
             "t from q1": _z_angle(qt.slerp(q0, q1, 1 - t)),
             "radians": _z_angle(_slerp_degrees_as_radians(q0, -q1, t)),
             "nlerp": _z_angle(qt.normalize((1 - t) * q0 - t * q1))}
    return expected, slips


def _z_quaternion(half_degrees) -> tuple:
    h = math.radians(half_degrees)
    return tuple(round(v, 5) + 0.0 for v in (math.cos(h), 0.0, 0.0, math.sin(h)))


def _slerp_generate(rng) -> dict:
    a0 = 10.0 * int(rng.integers(-15, 16))
    d = 10.0 * int(rng.integers(8, 17)) * float(rng.choice([-1.0, 1.0]))
    # q1 is written as the negative of the half-angle quaternion of a0 + d: the same rotation, q0·q1 < 0
    q1 = tuple(-v + 0.0 for v in _z_quaternion((a0 + d) / 2))
    return {"q0": _z_quaternion(a0 / 2), "q1": q1,
            "t": float(_pick(rng, (0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8)))}


def _slerp_ok(p):
    q0, q1 = _arr(p["q0"]), _arr(p["q1"])
    if not q0 @ q1 < -0.05:
        return "q0·q1 must be clearly negative: the exercise is about the shorter arc"
    return _named("check_slerp_angle", _SLERP_PHRASES)(p)


def _slerp_statement(p) -> str:
    return (f"Two key orientations are the unit quaternions q0 = {_q5(p['q0'])} and q1 = {_q5(p['q1'])} "
            f"(to 5 decimals), both rotations about the z-axis. Slerp between them (the shorter way) at t = "
            f"{fmt(p['t'])}: the result is a rotation about the z-axis. Give its signed angle in degrees, between -180 "
            f"and 180 (positive = counterclockwise looking down z), to 2 decimals (Goldman §15.3.5).")


def _raw_angle(q) -> float:
    """The angle 2 atan2(z, w) read off a quaternion about z as written, in (-360, 360]."""
    return math.degrees(2 * math.atan2(q[3], q[0]))


def _slerp_steps(p) -> str:
    q0, q1, t = _arr(p["q0"]), _arr(p["q1"]), float(p["t"])
    a0, a1 = _z_angle(q0), _z_angle(q1)
    d = float(q0 @ q1)
    th = math.degrees(math.acos(min(1.0, abs(d))))
    q = qt.slerp(q0, q1, t)
    return (f"1. q0 = (cos(θ0/2), 0, 0, sin(θ0/2)) turns by θ0 = {_f6(a0)} degrees about z; q1 as written has "
            f"2 atan2(z, w) = {_f6(_raw_angle(q1))}, the rotation by {_f6(a1)} degrees.\n"
            f"2. q0·q1 = {_f6(d)} < 0: negate q1 (-q1 is the same rotation); the angle between q0 and -q1 is "
            f"θ = arccos({_f6(-d)}) = {_f6(th)} degrees (half the turn between the two orientations).\n"
            f"3. slerp = sin((1 - t)θ)/sin θ q0 + sin(tθ)/sin θ (-q1) = {_f6(q)}.\n"
            f"4. Its angle 2 atan2(z, w) = {_f6(_z_angle(q))} degrees: from {_f6(a0)} a fraction t = {fmt(t)} of the "
            f"way to {_f6(a1)} along the shorter arc.")


@DECK.exercise(stored=_STORED_SLERP, generate=_slerp_generate, answer=lambda p: _slerp_answers(p)[0],
               slips=lambda p: _slerp_answers(p)[1], statement=_slerp_statement, steps=_slerp_steps,
               same=within(0.02), well_posed=_slerp_ok)
def check_slerp_angle(answer, p) -> Result:
    """Check the rotation angle of slerp(q0, q1, t) for rotations about z, where q0·q1 < 0 makes slerp
    take the shorter arc by negating q1 (Goldman §15.3.5).

    Recognises the longer arc (q1 not negated), the half angle of the quaternion, t measured from
    q1, the weights' angle taken in radians, and normalised linear interpolation.
    """
    value, err = read_number(answer, "the angle", "number of degrees")
    if err is not None:
        return err
    q0, q1 = _arr(p["q0"]), _arr(p["q1"])
    expected, slips = _slerp_answers(p)
    a0, a1, raw = fmt(_z_angle(q0)), fmt(_z_angle(q1)), fmt(_raw_angle(q1))
    tol = 0.02
    if abs(value - expected) <= tol:
        return correct(f"the result turns by {fmt(expected, 4)} degrees about z: q0·q1 < 0, so slerp negates q1 "
                       f"(-q1 is the same rotation, by {a1} degrees) and runs the shorter arc from {a0} to {a1} degrees "
                       f"at constant speed.")
    if abs(value - slips["the longer arc"]) <= tol:
        return wrong(f"you went the longer way round (from {a0} to {raw} degrees, as q1 is written): q0·q1 < 0, so "
                     f"negate q1 first; -q1 is the same rotation, and the arc from q0 to -q1 is the shorter one.")
    if abs(value - expected / 2) <= tol or abs(value - slips["the longer arc"] / 2) <= tol:
        return wrong("that is the half angle, the angle in the quaternion (cos(θ/2), sin(θ/2) k); the rotation's "
                     "angle θ is twice it.")
    if abs(value - slips["t from q1"]) <= tol:
        return wrong("you measured t from q1: slerp(q0, q1, t) starts at q0 for t = 0, so q0 gets the weight "
                     "sin((1 - t)θ)/sin θ.")
    if abs(value - slips["radians"]) <= tol:
        return wrong("your slerp weights took θ in degrees as if it were radians: sin((1 - t)θ)/sin θ needs θ in "
                     "radians for np.sin and math.sin (θ, the angle between q0 and -q1, is the half angle).")
    if abs(value - slips["nlerp"]) <= tol:
        return wrong("that is normalised linear interpolation: the right arc, but not at constant speed; slerp "
                     "weights q0 and -q1 by sin((1 - t)θ)/sin θ and sin(tθ)/sin θ, θ the angle between them.")
    return wrong(f"your angle is {off_by(value, expected)}; read the angles of q0 and q1 from "
                 f"w = cos(θ/2), z = sin(θ/2), check the sign of q0·q1, then interpolate.")


_STORED_LERP = {"angle": LERP_ANGLE, "t": LERP_T}
_LERP_PHRASES = {"a rotation": "not a rotation", "the scale": "the scale factor", "σ^2": "σ^2",
                 "halfway": "halfway"}


@memo
def _lerp_answers(p):
    R = _row_matrix(qt.from_axis_angle([0, 0, 1], p["angle"]))
    M = qt.matrix_lerp(np.eye(3), R, p["t"])
    expected = float(qt.matrix_distortion(M))
    scale = float(np.linalg.svd(M, compute_uv=False)[-1])
    slips = {"a rotation": 0.0, "the scale": scale, "σ^2": 1 - scale * scale,
             "halfway": float(qt.matrix_distortion(qt.matrix_lerp(np.eye(3), R, 0.5)))}
    return expected, slips


def _lerp_generate(rng) -> dict:
    return {"angle": float(_pick(rng, (60.0, 90.0, 120.0, 150.0))),
            "t": float(_pick(rng, (0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8)))}


def _lerp_statement(p) -> str:
    return (f"Let R be the matrix of the rotation by {fmt(p['angle'])} degrees about the z-axis. Blend it linearly "
            f"with the identity: M = (1 - t) I + t R at t = {fmt(p['t'])}. How far is M from a rotation? Give its "
            f"distortion, the largest |σ - 1| over M's singular values σ (0 for a rotation), to 4 decimals "
            f"(Goldman §15.3.4).")


def _lerp_steps(p) -> str:
    th, t = float(p["angle"]), float(p["t"])
    c = (1 - t) + t * qt.complex_rotation(th)
    s2 = (1 - t) ** 2 + t * t + 2 * t * (1 - t) * math.cos(math.radians(th))
    expected, slips = _lerp_answers(p)
    return (f"1. R turns the xy-plane by {fmt(th)} degrees and keeps z; in the xy-plane M acts as the complex "
            f"number c = (1 - t) + t e^{{iθ}} = {_f6(c.real)} + {_f6(c.imag)} i.\n"
            f"2. |c|^2 = (1 - t)^2 + t^2 + 2t(1 - t) cos θ = {_f6(s2)}, so σ = |c| = {_f6(math.sqrt(s2))} "
            f"(twice: the xy-plane shrinks by σ); along z, σ = 1.\n"
            f"3. The distortion is max |σ - 1| = 1 - σ = {_f6(expected)} (the library's matrix_distortion: "
            f"{_f6(qt.matrix_distortion(qt.matrix_lerp(np.eye(3), _row_matrix(qt.from_axis_angle([0, 0, 1], th)), t)))}).")


@DECK.exercise(stored=_STORED_LERP, generate=_lerp_generate, answer=lambda p: _lerp_answers(p)[0],
               slips=lambda p: _lerp_answers(p)[1], statement=_lerp_statement, steps=_lerp_steps,
               same=within(2e-4), well_posed=_named("check_lerp_distortion", _LERP_PHRASES))
def check_lerp_distortion(answer, p) -> Result:
    """Check the distortion 1 - |scale| of the blend M = (1 - t) I + t R, R the statement's turn about
    z: in the xy-plane M acts as a complex number, a scaling with a rotation (Goldman §15.3.4).

    Recognises 0 (taking the blend for a rotation), the scale σ itself, 1 - σ^2 (the squared scale),
    and the halfway blend's distortion.
    """
    value, err = read_number(answer, "the distortion")
    if err is not None:
        return err
    expected, slips = _lerp_answers(p)
    scale = slips["the scale"]
    tol = 2e-4
    if abs(value - expected) <= tol:
        return correct(f"the distortion is {fmt(expected, 4)}: the blend shrinks the xy-plane (by the factor "
                       f"{fmt(scale, 4)}) and keeps z, so it is no rotation; slerp of the quaternions would give one.")
    if abs(value) <= tol:
        return wrong("M is not a rotation: a weighted sum of rotation matrices is not orthogonal in general. In the "
                     "xy-plane it acts like the complex number (1 - t) + t e^{iθ}, whose modulus is below 1.")
    if abs(value - scale) <= tol:
        return wrong("that is the scale factor σ of the xy-plane; the distortion is |σ - 1|, how far it is from 1.")
    if abs(value - slips["σ^2"]) <= tol:
        return wrong("you used σ^2 = |(1 - t) + t e^{iθ}|^2; the singular value is its square root.")
    if abs(value - slips["halfway"]) <= tol:
        return wrong(f"that is the distortion halfway (t = 1/2); here t = {fmt(p['t'])}.")
    return wrong(f"your distortion is {off_by(value, expected)}; in the xy-plane M acts like the complex number "
                 f"(1 - t) + t e^{{iθ}}: find its modulus σ (the z-axis keeps σ = 1).")


#: Deal another instance of an exercise (``deal("check_rotated_vector")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


# -- the programming project --------------------------------------------------------------------------

def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def slerp_project_cases(seed: int = 15, vectorised: bool = False) -> list[Case]:
    """The cases of :func:`check_slerp_project`, generated from a fixed seed: random pairs on the
    shorter side, t = 0 and t = 1, pairs with q0·q1 < 0 (the shorter arc needs -q1), q1 = -q0,
    identical and nearly identical quaternions (θ ≈ 0), close pairs (q0·q1 = 0.8 to 0.998) asked at t = 0.1,
    0.25, 0.3 and 0.75 (where normalised lerp is not slerp), and quaternions half a turn apart (q0·q1 = 0:
    both arcs are equally short, either one is accepted).
    With ``vectorised=True`` three more cases pass ``t`` as an array (the result is then one
    quaternion per t, shape (len(t), 4)).

    >>> cases = slerp_project_cases()
    >>> len(cases), cases[0].kind, cases[-1].kind
    (21, 'random pair', 'q0·q1 < 0 (the shorter arc)')
    """
    rng = np.random.default_rng(seed)
    cases: list[Case] = []

    def add(q0, q1, t, kind, label=None):
        q0, q1 = _unit(q0), _unit(q1)
        label = label or f"q0 = {fmt(q0)}, q1 = {fmt(q1)}, t = {fmt(t)}"
        cases.append(Case(label, (q0, q1, float(t)), kind=kind))

    def pair(sign):
        while True:
            a, b = _unit(rng.normal(size=4)), _unit(rng.normal(size=4))
            if sign * (a @ b) > 0.15:
                return a, b

    for t in (0.3, 0.5, 0.85):
        add(*pair(+1), t, "random pair")
    a, b = pair(+1)
    add(a, b, 0.0, "t = 0")
    add(a, b, 1.0, "t = 1")
    for t in (0.25, 0.6, 0.9):
        add(*pair(-1), t, "q0·q1 < 0 (the shorter arc)")
    a, b = pair(-1)
    add(a, b, 1.0, "q0·q1 < 0 (the shorter arc)")
    a = _unit(rng.normal(size=4))
    add(a, -a, 0.4, "q1 = -q0 (the same rotation)")
    add(a, a, 0.7, "identical (θ = 0)")
    b = _unit(rng.normal(size=4))
    cases.append(Case(f"q0 = {fmt(b)}, q1 = q0 + 1e-9 noise, t = 0.5", (b, _unit(b + 1e-9 * rng.normal(size=4)), 0.5),
                      kind="nearly equal (θ ≈ 1e-9)"))
    add([1, 0, 0, 0], qt.from_axis_angle([0, 0, 1], 90), 0.5, "a quarter turn about z")
    # close pairs away from t = 0, 1/2, 1, where normalised lerp is not slerp (it does not keep a constant speed)
    for d, t in ((0.8, 0.25), (0.9, 0.75), (0.99, 0.25), (0.998, 0.3), (-0.95, 0.1)):
        a = _unit(rng.normal(size=4))
        u = rng.normal(size=4)
        u = _unit(u - (u @ a) * a)
        add(a, d * a + math.sqrt(1 - d * d) * u, t,
            "close pairs (q0·q1 < 0, the shorter arc)" if d < 0 else "close pairs (q0·q1 near 1)")
    add([0, 1, 0, 0], [0, 0, 1, 0], 0.25, "half a turn apart (q0·q1 = 0: either arc)")
    add([0.6, 0, 0.8, 0], [0.6, 0, 0.8, 1e-7], 0.5, "nearly equal (θ ≈ 1e-7)",
        label="q0 = (0.6, 0, 0.8, 0), q1 = (0.6, 0, 0.8, 1e-7) normalised, t = 0.5")
    add(qt.from_axis_angle([1, 2, 2], 170), qt.from_axis_angle([1, 2, 2], -170), 0.5, "q0·q1 < 0 (the shorter arc)")
    if vectorised:
        for sign, ts in ((1, [0.0, 0.25, 0.5, 0.75, 1.0]), (-1, [0.1, 0.9]), (1, [0.5])):
            a, b = pair(sign)
            cases.append(Case(f"q0 = {fmt(a)}, q1 = {fmt(b)}, t = np.array({ts})", (a, b, np.array(ts)),
                              kind="an array of t"))
    return cases


#: The project's tolerance: the distance (up to sign) between a learner's quaternion and slerp's.
SLERP_TOL = 1e-6


def _longer_arc(q0, q1, t):
    d = float(np.clip(q0 @ q1, -1.0, 1.0))
    th = math.acos(d)
    if math.sin(th) < 1e-9:
        return None
    return (math.sin((1 - t) * th) * q0 + math.sin(t * th) * q1) / math.sin(th)


def _compare_slerp(got, expected, case) -> str | None:
    arr = np.asarray(got, dtype=float)
    exp = np.asarray(expected, dtype=float)
    if exp.ndim == 2:       # an array of t: one quaternion per t, each compared up to sign
        if arr.shape != exp.shape:
            return f"it has shape {arr.shape}; for {len(exp)} values of t the result is {len(exp)} quaternions, shape {exp.shape}"
        q0, q1, ts = case.args
        for k, t in enumerate(ts):
            problem = _compare_slerp(arr[k], exp[k], Case(case.label, (q0, q1, float(t))))
            if problem is not None:
                return f"at t = {fmt(t)} (entry {k}) " + problem
        return None
    if arr.shape != (4,):
        return f"it has shape {arr.shape}; a quaternion is 4 numbers (w, x, y, z)"
    if not np.all(np.isfinite(arr)):
        return ("it contains NaN or infinity: when q0 and q1 are (nearly) equal, θ = 0 and sin θ = 0, and q0·q1 "
                "may round to just above 1 (arccos is then NaN): clip q0·q1 to [-1, 1] and fall back to linear "
                "interpolation when sin θ is tiny")
    err = float(min(np.linalg.norm(arr - exp), np.linalg.norm(arr + exp)))
    if err <= SLERP_TOL:
        return None
    q0, q1, t = case.args
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    if abs(float(q0 @ q1)) <= 1e-12:
        # a tie: q1 and -q1 are equally near (both arcs are a quarter of the great circle): either is right
        other = qt.slerp(q0, -q1, t)
        if min(np.linalg.norm(arr - other), np.linalg.norm(arr + other)) <= SLERP_TOL:
            return None
    near = lambda x: x is not None and min(np.linalg.norm(arr - x), np.linalg.norm(arr + x)) <= SLERP_TOL  # noqa: E731
    head = f"it is {fmt(err, 2)} from slerp's result {fmt(exp)} (q and -q count as the same)"
    length = float(np.linalg.norm(arr))
    if q0 @ q1 < 0 and near(_longer_arc(q0, q1, t)):
        return head + "; it takes the longer arc: negate q1 when q0·q1 < 0"
    if near((1 - t) * q0 + t * q1) or near((1 - t) * q0 - t * q1):
        return head + (f"; it is the linear interpolation (1 - t) q0 + t q1, of length {fmt(length, 4)}: it cuts "
                       f"through the sphere of unit quaternions instead of following its arc")
    for sign in (1, -1):
        lerp = (1 - t) * q0 + sign * t * q1
        if np.linalg.norm(lerp) > 0 and near(lerp / np.linalg.norm(lerp)):
            return head + ("; it is normalised linear interpolation: on the arc, but not at constant speed "
                           "(use the weights sin((1 - t)θ)/sin θ and sin(tθ)/sin θ)")
    if near(qt.slerp(q0, q1, 1 - t)):
        return head + "; q0 and q1 have swapped weights: at t = 0 slerp gives q0"
    if abs(length - 1) > SLERP_TOL:
        return head + f"; it has length {fmt(length, 4)}, but a rotation is a unit quaternion"
    return head


def check_slerp_project(function, vectorised: bool = False) -> Result:
    """Check the learner's ``slerp(q0, q1, t)`` (unit quaternions (w, x, y, z), t a number) against
    :func:`goldman_lib.quaternions.slerp` on :func:`slerp_project_cases`, up to sign (q and -q are
    the same rotation) (Goldman §15.3.4-15.3.5).  ``vectorised=True`` (for a slerp that accepts an
    array of t) adds cases with t an array, the result one quaternion per t.

    >>> def lerp(q0, q1, t):
    ...     return (1 - t) * np.asarray(q0) + t * np.asarray(q1)
    >>> print(check_slerp_project(lerp).message)   # doctest: +ELLIPSIS
    case 1 of 21 (q0 = ..., t = 0.3): your function returned ...; it is ... from slerp's result ... it is the linear interpolation (1 - t) q0 + t q1, of length ...
    """
    return check_project(function, slerp_project_cases(vectorised=bool(vectorised)), reference=qt.slerp,
                         compare=_compare_slerp,
                         what="slerp",
                         hint="with cos θ = q0·q1 (after negating q1 if it is negative), slerp is "
                              "sin((1 - t)θ)/sin θ q0 + sin(tθ)/sin θ q1")


SLIPS = {
    "check_complex_factor": [[-5, 5], [0.1, -0.7], [-1, 1], [-0.5, 3]],
    "check_quaternion_product": [[7, 2, 6, -1], [7, 3, 1, 1], [-3, 4, -4, 3], [2, -2, 0, -3]],
    "check_rotated_vector": [[0, -2, 1], [0.5 + math.sqrt(2), -math.sqrt(0.5), 0.5 - math.sqrt(2)],
                             [0.5, 2, -0.5], [-1.5, 0, 3],
                             # 90 taken as radians: v cos θ + (1 - cos θ)(v·u) u + sin θ (u × v), u = (1, 0, 1)/√2
                             list(np.array(ROTATION_V) * math.cos(90) + (1 - math.cos(90)) * 0.5 * np.array([1, 0, 1])
                                  + math.sin(90) * np.cross([1, 0, 1], ROTATION_V) / math.sqrt(2))],
    "check_conformal_image": [[-4 / 9, -7 / 9, 4 / 9], [-4 / 3, -7 / 3, 4 / 3], [4, -7, -4], [0, 9, 0]],
    "check_rotation_matrix": [
        [[-0.28, -0.768, 0.576], [0.768, 0.1808, 0.6144], [-0.576, 0.6144, 0.5392]],
        [[-0.28, 0.384, -0.288], [-0.384, 0.1808, 0.3072], [0.288, 0.3072, 0.5392]],
        [[0.36, 0.768, -0.576], [-0.768, 0.5904, 0.6144], [0.576, 0.6144, 0.7696]],
        # read as (x, y, z, w): w = 0.64, x = 0.6, y = 0, z = 0.48 (row convention)
        [[1 - 2 * 0.48 ** 2, 2 * (0.6 * 0 + 0.64 * 0.48), 2 * (0.6 * 0.48 - 0.64 * 0)],
         [2 * (0.6 * 0 - 0.64 * 0.48), 1 - 2 * (0.6 ** 2 + 0.48 ** 2), 2 * (0 * 0.48 + 0.64 * 0.6)],
         [2 * (0.6 * 0.48 + 0.64 * 0), 2 * (0 * 0.48 - 0.64 * 0.6), 1 - 2 * 0.6 ** 2]],
    ],
    "check_slerp_angle": [118.0, 5.0, -30.0, 11.13,
                          # the weights' angle taken in degrees as radians
                          _z_angle(_slerp_degrees_as_radians(np.array(SLERP_Q0), -np.array(SLERP_Q1), SLERP_T))],
    "check_lerp_distortion": [0.0, math.sqrt(7) / 4, 0.5625, 0.5],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals(), complex_ok=("check_complex_factor",))
