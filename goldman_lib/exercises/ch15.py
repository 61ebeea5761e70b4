"""Exercise checkers for chapter 15, complex numbers and quaternions (Goldman §15.2-15.3).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
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
from goldman_lib.exercises.projects import Case, check_project, describe

__all__ = ["PROBLEMS", "SLIPS", "COMPLEX_FROM", "COMPLEX_TO", "PRODUCT_P", "PRODUCT_Q", "ROTATION_AXIS",
           "ROTATION_ANGLE", "ROTATION_V", "CONFORMAL_Q", "CONFORMAL_V", "MATRIX_Q", "SLERP_Q0", "SLERP_Q1", "SLERP_T",
           "LERP_ANGLE", "LERP_T", "check_complex_factor", "check_quaternion_product", "check_rotated_vector",
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


def _q_text(q) -> str:
    return "(" + ", ".join(fmt(v) for v in q) + ")"


def _q5(q) -> str:
    return "(" + ", ".join(f"{v:.5f}" for v in q) + ")"


PROBLEMS = {
    "check_complex_factor": (
        f"Which complex number z sends the point {_q_text(COMPLEX_FROM)} = 2 + i to {_q_text(COMPLEX_TO)} = -1 + 3i "
        f"by multiplication (z (2 + i) = -1 + 3i)? Give z as [Re z, Im z]; multiplying by z then rotates the "
        f"whole plane by arg z and scales it by |z| (Goldman §15.2)."),
    "check_quaternion_product": (
        f"Compute the quaternion product p q for p = {_q_text(PRODUCT_P)} and q = {_q_text(PRODUCT_Q)}, written "
        f"(w, x, y, z) = w + x i + y j + z k. Give [w, x, y, z] (Goldman §15.3.1)."),
    "check_rotated_vector": (
        f"Let q be the unit quaternion of the rotation by {fmt(ROTATION_ANGLE)} degrees about the axis "
        f"{_q_text(ROTATION_AXIS)} (counterclockwise looking down the axis towards the origin). Rotate "
        f"v = {_q_text(ROTATION_V)} by q v q*: give the image [x, y, z], to 4 decimals (Goldman §15.3.2)."),
    "check_conformal_image": (
        f"The quaternion q = {_q_text(CONFORMAL_Q)} is not a unit quaternion. Compute the vector part of q v q* for "
        f"v = {_q_text(CONFORMAL_V)}: the image of v under the conformal map of q. Give [x, y, z] "
        f"(Goldman §15.3.2)."),
    "check_rotation_matrix": (
        f"Convert the unit quaternion q = {_q_text(MATRIX_Q)} to the 3x3 matrix M of its rotation in the book's "
        f"row convention (v' = v M, so the first row is the image of (1, 0, 0)). Give M as [[..], [..], [..]] "
        f"(Goldman §15.3.6)."),
    "check_slerp_angle": (
        f"Two key orientations are the unit quaternions q0 = {_q5(SLERP_Q0)} and q1 = {_q5(SLERP_Q1)} "
        f"(to 5 decimals), both rotations about the z-axis. Slerp between them (the shorter way) at t = {fmt(SLERP_T)}: "
        f"the result is a rotation about the z-axis. Give its signed angle in degrees, between -180 and 180 "
        f"(positive = counterclockwise looking down z), to 2 decimals (Goldman §15.3.5)."),
    "check_lerp_distortion": (
        f"Let R be the matrix of the rotation by {fmt(LERP_ANGLE)} degrees about the z-axis. Blend it linearly "
        f"with the identity: M = (1 - t) I + t R at t = {fmt(LERP_T)}. How far is M from a rotation? Give its "
        f"distortion, the largest |σ - 1| over M's singular values σ (0 for a rotation), to 4 decimals "
        f"(Goldman §15.3.4)."),
}


# -- reading answers ---------------------------------------------------------------------------------

# -- §15.2 ---------------------------------------------------------------------------------------------

def check_complex_factor(answer) -> Result:
    """Check the complex number z with z (2 + i) = -1 + 3i, a quotient of complex numbers (Goldman
    §15.2); read as [Re z, Im z] or as a Python complex number.

    Recognises the product instead of the quotient, the quotient the other way up, a conjugate
    taken on the wrong factor, and coordinates divided one by one.
    """
    if isinstance(answer, (complex, np.complexfloating)):
        answer = [answer.real, answer.imag]   # the chapter computes with Python complex numbers too
    got, err = _read_vector(answer, "your z", 2, "z as [Re z, Im z]")
    if err is not None:
        return err
    a, b = complex(*COMPLEX_FROM), complex(*COMPLEX_TO)
    z = b / a
    tol = 1e-4
    pair = lambda c: (c.real, c.imag)  # noqa: E731
    if _close(got, pair(z), tol):
        scale, angle = qt.complex_polar(z)
        return correct(f"z = {fmt(z.real)} + {fmt(z.imag)} i: multiplying by z rotates the plane by "
                       f"{fmt(angle, 4)} degrees and scales it by |z| = {fmt(scale, 4)} = |-1 + 3i| / |2 + i|.")
    if _close(got, pair(a * b), tol):
        return wrong("that is (2 + i)(-1 + 3i), the product; z is the quotient (-1 + 3i) / (2 + i): multiply top and "
                     "bottom by the conjugate 2 - i.")
    if _close(got, pair(a / b), tol):
        return wrong("that is (2 + i) / (-1 + 3i), the quotient upside down: it sends -1 + 3i back to 2 + i.")
    if _close(got, pair(b * a / abs(a) ** 2), tol):
        return wrong("you multiplied by 2 + i instead of its conjugate 2 - i: 1 / (2 + i) = (2 - i) / |2 + i|^2.")
    if _close(got, (b.real / a.real, b.imag / a.imag), tol):
        return wrong("you divided the coordinates one by one; complex division is not coordinatewise "
                     "(i^2 = -1 mixes them): multiply top and bottom by the conjugate 2 - i.")
    return wrong(f"your z is {_dist(got, pair(z))} from the right one; check that z (2 + i) "
                 f"gives -1 + 3i, using i^2 = -1.")


# -- §15.3.1 -------------------------------------------------------------------------------------------

def check_quaternion_product(answer) -> Result:
    """Check the product p q = (ab - u·v, a v + b u + u × v) of ``PRODUCT_P`` and ``PRODUCT_Q``
    (Goldman §15.3.1).

    Recognises q p (the other order), a missing cross product, a plus sign on the dot product, and
    the coordinatewise product.
    """
    got, err = _read_vector(answer, "your product", 4, "p q as [w, x, y, z]")
    if err is not None:
        return err
    p, q = np.array(PRODUCT_P), np.array(PRODUCT_Q)
    expected = qt.multiply(p, q)
    a, u, b, v = p[0], p[1:], q[0], q[1:]
    tol = 1e-6
    if _close(got, expected, tol):
        return correct(f"p q = {fmt(expected)}, while q p = {fmt(qt.multiply(q, p))}: the two differ by 2 u × v, "
                       f"so the product is not commutative.")
    if _close(got, qt.multiply(q, p), tol):
        return wrong("that is q p, the product in the other order: the quaternion product is not commutative "
                     "(u × v changes sign), so p q and q p differ. Multiply with p on the left.")
    if _close(got, np.r_[a * b - u @ v, a * v + b * u], tol):
        return wrong("your vector part lacks the cross product u × v: (a, u)(b, v) = (ab - u·v, a v + b u + u × v), "
                     "since i j = k, j k = i, k i = j.")
    if _close(got, np.r_[a * b + u @ v, a * v + b * u + np.cross(u, v)], tol):
        return wrong("your scalar part adds u·v; it subtracts it, since i^2 = j^2 = k^2 = -1: "
                     "the scalar part is ab - u·v.")
    if _close(got, p * q, tol):
        return wrong("you multiplied coordinate by coordinate; expand (a + u)(b + v) with the rules i^2 = -1, "
                     "i j = k = -j i, and so on.")
    return wrong(f"your product is {_dist(got, expected)} from p q; use (a, u)(b, v) = "
                 f"(ab - u·v, a v + b u + u × v) with a = 1, u = (2, 0, -1), b = 2, v = (-1, 1, 3).")


# -- §15.3.2 -------------------------------------------------------------------------------------------

def _sandwich(a, v, b):
    """The vector part of a (0, v) b."""
    return qt.multiply(qt.multiply(a, np.r_[0.0, v]), b)[1:]


def check_rotated_vector(answer) -> Result:
    """Check q v q* for the unit quaternion q of the rotation ``ROTATION_ANGLE`` about ``ROTATION_AXIS``
    and v = ``ROTATION_V`` (Goldman §15.3.2).

    Recognises the full angle in q (cos θ, not cos θ/2: twice the rotation), the opposite rotation
    (q* v q), q v q instead of q v q*, and an axis left unnormalised.
    """
    got, err = _read_vector(answer, "your image", 3, "the image as [x, y, z]")
    if err is not None:
        return err
    v = np.array(ROTATION_V)
    q = qt.from_axis_angle(ROTATION_AXIS, ROTATION_ANGLE)
    expected = qt.rotate(q, v)
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"q v q* = {fmt(expected)}: the part of v along the axis stays, the rest turns by "
                       f"{fmt(ROTATION_ANGLE)} degrees about it; the length {fmt(np.linalg.norm(v), 4)} is kept.")
    full = qt.from_axis_angle(ROTATION_AXIS, 2 * ROTATION_ANGLE)
    if _close(got, qt.rotate(full, v), tol):
        return wrong("you rotated by twice the angle: q v q* turns by θ when q = (cos(θ/2), sin(θ/2) u), the half "
                     "angle, because q acts twice (once on each side).")
    if _close(got, _sandwich(qt.conjugate(q), v, q), tol):
        return wrong("that is q* v q, the rotation the other way (clockwise looking down the axis); the "
                     "counterclockwise rotation is q v q*.")
    if _close(got, _sandwich(q, v, q), tol):
        return wrong("that is (the vector part of) q v q: the right side must be the conjugate q*, otherwise the "
                     "result is not even a pure vector.")
    if _close(got, qt.rotate(qt.from_axis_angle(ROTATION_AXIS, math.degrees(ROTATION_ANGLE)), v), tol):
        return wrong("you took cos and sin of the angle in degrees as if it were radians: np.cos and math.cos take "
                     "radians, so convert first (θ/2 = 45°, cos 45° = sin 45° = √2/2).")
    raw = np.r_[math.cos(math.radians(ROTATION_ANGLE) / 2), math.sin(math.radians(ROTATION_ANGLE) / 2) * np.array(ROTATION_AXIS)]
    if _close(got, _sandwich(raw, v, qt.conjugate(raw)), tol):
        return wrong("your q is not a unit quaternion: the axis (1, 0, 1) has length √2, so normalise it to "
                     "u = (1, 0, 1)/√2 before forming (cos(θ/2), sin(θ/2) u); otherwise q v q* also scales by |q|^2.")
    return wrong(f"your image is {_dist(got, expected)} from q v q*; its length should stay "
                 f"|v| = {fmt(np.linalg.norm(v), 4)} (yours is {fmt(np.linalg.norm(got), 4)}). Split v into its part "
                 f"along u and the rest, or multiply out q v q* with q = (cos 45°, sin 45° u).")


def check_conformal_image(answer) -> Result:
    """Check the vector part of q v q* for the quaternion ``CONFORMAL_Q`` (not a unit quaternion) and
    v = ``CONFORMAL_V``: a rotation with a scaling by |q|^2 (Goldman §15.3.2).

    Recognises the rotation alone (divided by |q|^2), a scaling by |q| instead of |q|^2, q* v q
    (the other rotation) and q v q.
    """
    got, err = _read_vector(answer, "your image", 3, "the image as [x, y, z]")
    if err is not None:
        return err
    q, v = np.array(CONFORMAL_Q), np.array(CONFORMAL_V)
    expected = qt.conformal_map(q, v)
    n = float(qt.norm(q))
    tol = 1e-4
    if _close(got, expected, tol):
        return correct(f"q v q* = {fmt(expected)}: the rotation of q/|q| followed by the scaling by "
                       f"|q|^2 = {fmt(n * n)} (|q| = {fmt(n)}), a conformal map.")
    if _close(got, expected / (n * n), tol):
        return wrong("that is the rotation alone (q/|q| v (q/|q|)*, or q v q^-1): q v q* with a non-unit q also "
                     "scales every vector by |q|^2.")
    if _close(got, expected / n, tol):
        return wrong("you scaled by |q|; q v q* scales by |q|^2, since q and q* each contribute a factor |q|.")
    if _close(got, _sandwich(qt.conjugate(q), v, q), tol):
        return wrong("that is q* v q: it turns the other way. Multiply q v first, then by q* on the right.")
    if _close(got, _sandwich(q, v, q), tol):
        return wrong("that is (the vector part of) q v q: the right factor is the conjugate q* = (1, -2, 0, -2).")
    return wrong(f"your image is {_dist(got, expected)} from q v q*; its length should be "
                 f"|q|^2 |v| (yours is {fmt(np.linalg.norm(got), 4)}). Multiply (0, v) by q on the left, then by "
                 f"q* on the right.")


# -- §15.3.6 -------------------------------------------------------------------------------------------

def check_rotation_matrix(answer) -> Result:
    """Check the row-convention rotation matrix of the unit quaternion ``MATRIX_Q`` (Goldman §15.3.6).

    Accepts the 4x4 matrix too.  Recognises the transposed (column-convention) matrix, off-diagonal
    entries without their factor 2, and the diagonal 1 - (y^2 + z^2) without the 2.
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
    w, x, y, z = MATRIX_Q
    expected = qt.to_matrix(MATRIX_Q)[:3, :3]
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"M has determinant {fmt(np.linalg.det(got), 4)} and orthonormal rows; its first row "
                       f"{fmt(expected[0])} is the image of (1, 0, 0).")
    if _close(got, expected.T, tol):
        return wrong("that is the transposed matrix, for column vectors (v' = R v), which is also the matrix of the "
                     "rotation q*: in the row convention v' = v M, the first row is the image of (1, 0, 0).")
    xyzw = qt.to_matrix((MATRIX_Q[3], MATRIX_Q[0], MATRIX_Q[1], MATRIX_Q[2]))[:3, :3]
    if _close(got, xyzw, tol) or _close(got, xyzw.T, tol):
        return wrong("you read q in the order (x, y, z, w): the course writes quaternions (w, x, y, z) = "
                     "w + x i + y j + z k, the scalar part first (some libraries, scipy among them, put it last).")
    half = expected.copy()
    off = ~np.eye(3, dtype=bool)
    half[off] = expected[off] / 2
    if _close(got[off], half[off], tol) or _close(got[off], half.T[off], tol):
        return wrong("your off-diagonal entries are half what they should be: they are 2(xy ± wz), 2(xz ± wy), "
                     "2(yz ± wx), with the factor 2.")
    diag = np.array([1 - (y * y + z * z), 1 - (x * x + z * z), 1 - (x * x + y * y)])
    if _close(np.diag(got), diag, tol):
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


def check_slerp_angle(answer) -> Result:
    """Check the rotation angle of slerp(q0, q1, t) for rotations about z, where q0·q1 < 0 makes slerp
    take the shorter arc by negating q1 (Goldman §15.3.5).

    Recognises the longer arc (q1 not negated), the half angle of the quaternion, t measured from
    q1, and normalised linear interpolation.
    """
    value, err = read_number(answer, "the angle", "number of degrees")
    if err is not None:
        return err
    q0, q1 = np.array(SLERP_Q0), np.array(SLERP_Q1)
    expected = _z_angle(qt.slerp(q0, q1, SLERP_T))
    tol = 0.02
    if abs(value - expected) <= tol:
        return correct(f"the result turns by {fmt(expected, 4)} degrees about z: q0·q1 < 0, so slerp negates q1 "
                       f"(-q1 is the same rotation, by -60 degrees) and runs the shorter arc from 40 to -60 degrees "
                       f"at constant speed.")
    # the longer arc: the great circle from q0 to q1 itself
    th = math.acos(float(np.clip(q0 @ q1, -1, 1)))
    longer = (math.sin((1 - SLERP_T) * th) * q0 + math.sin(SLERP_T * th) * q1) / math.sin(th)
    if abs(value - _z_angle(longer)) <= tol:
        return wrong("you went the longer way round (from 40 through 180 to 300 degrees): q0·q1 < 0, so negate q1 "
                     "first; -q1 is the same rotation, and the arc from q0 to -q1 is the shorter one.")
    if abs(value - expected / 2) <= tol or abs(value - _z_angle(longer) / 2) <= tol:
        return wrong("that is the half angle, the angle in the quaternion (cos(θ/2), sin(θ/2) k); the rotation's "
                     "angle θ is twice it.")
    if abs(value - _z_angle(qt.slerp(q0, q1, 1 - SLERP_T))) <= tol:
        return wrong(f"you measured t from q1: slerp(q0, q1, t) starts at q0 for t = 0, so q0 gets the weight "
                     f"sin((1 - t)θ)/sin θ.")
    if abs(value - _z_angle(_slerp_degrees_as_radians(q0, -q1, SLERP_T))) <= tol:
        return wrong("your slerp weights took θ in degrees as if it were radians: sin((1 - t)θ)/sin θ needs θ in "
                     "radians for np.sin and math.sin (θ, the angle between q0 and -q1, is the half angle).")
    nlerp = qt.normalize((1 - SLERP_T) * q0 - SLERP_T * q1)
    if abs(value - _z_angle(nlerp)) <= tol:
        return wrong("that is normalised linear interpolation: the right arc, but not at constant speed; slerp "
                     "weights q0 and -q1 by sin((1 - t)θ)/sin θ and sin(tθ)/sin θ, θ the angle between them.")
    return wrong(f"your angle is {off_by(value, expected)}; read the angles of q0 and q1 from "
                 f"w = cos(θ/2), z = sin(θ/2), check the sign of q0·q1, then interpolate.")


def check_lerp_distortion(answer) -> Result:
    """Check the distortion 1 - |scale| of the blend M = (3/4) I + (1/4) R, R a turn about z: in the
    xy-plane M acts as a complex number, a scaling with a rotation (Goldman §15.3.4).

    Recognises 0 (taking the blend for a rotation), the scale √7/4 itself, the squared scale
    (7/16), and the halfway blend's 0.5.
    """
    value, err = read_number(answer, "the distortion")
    if err is not None:
        return err
    R = qt.to_matrix(qt.from_axis_angle([0, 0, 1], LERP_ANGLE))[:3, :3]
    M = qt.matrix_lerp(np.eye(3), R, LERP_T)
    expected = float(qt.matrix_distortion(M))
    scale = float(np.linalg.svd(M, compute_uv=False)[-1])
    tol = 2e-4
    if abs(value - expected) <= tol:
        return correct(f"the distortion is {fmt(expected, 4)}: the blend shrinks the xy-plane (by the factor "
                       f"{fmt(scale, 4)}) and keeps z, so it is no rotation; slerp of the quaternions would give one.")
    if abs(value) <= tol:
        return wrong("M is not a rotation: a weighted sum of rotation matrices is not orthogonal in general. In the "
                     "xy-plane it acts like the complex number (1 - t) + t e^{iθ}, whose modulus is below 1.")
    if abs(value - scale) <= tol:
        return wrong("that is the scale factor σ of the xy-plane; the distortion is |σ - 1|, how far it is from 1.")
    if abs(value - (1 - scale * scale)) <= tol:
        return wrong("you used σ^2 = |(1 - t) + t e^{iθ}|^2; the singular value is its square root.")
    if abs(value - float(qt.matrix_distortion(qt.matrix_lerp(np.eye(3), R, 0.5)))) <= tol:
        return wrong(f"that is the distortion halfway (t = 1/2); here t = {fmt(LERP_T)}.")
    return wrong(f"your distortion is {off_by(value, expected)}; in the xy-plane M acts like the complex number "
                 f"(1 - t) + t e^{{iθ}}: find its modulus σ (the z-axis keeps σ = 1).")


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
