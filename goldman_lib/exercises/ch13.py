"""Exercise checkers for chapter 13, the 4x4 matrices of the transformations of chapter 12 in the
row convention ``[P 1] @ M`` (Goldman §13.1-13.6), and the checker of the chapter's programming
project (the projective map through five points).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The chapter's "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) ask for an identity, not a number, and the programming
project runs the learner's function on its own cases, so neither deals.  ``SLIPS`` holds the
wrong answers of the kinds each checker recognises, for the stored instance.  Hand-computed
decimals are accepted to a relative 1e-4.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import transforms
from goldman_lib.exercises import far_off, guard_checkers, off_by
from goldman_lib.exercises import Result, correct, fmt, read_points, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, memo, plain as _tup
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "ROT_AXIS", "ROT_ANGLE", "ROT_POINT", "MIRROR_PLANE_POINT", "MIRROR_NORMAL",
           "COMPOSE_SHIFT", "COMPOSE_ANGLE", "PERSP_EYE", "PERSP_PLANE_POINT", "PERSP_NORMAL", "PERSP_POINT",
           "AFFINE_MATRIX", "AFFINE_COORDS", "FRAME_SOURCES", "FRAME_IMAGES", "INVERSE_AXIS", "INVERSE_ANGLE",
           "INVERSE_POINT", "INVERSE_SCALE", "DECK", "deal", "steps", "current", "deal_button",
           "check_rotation_block", "check_translation_row", "check_mirror_matrix",
           "check_composite_matrix", "check_perspective_image", "check_point_and_vector", "check_frame_matrix",
           "check_inverse_matrix", "check_projective_map_project"]

#: Exercises 1 and 2: the rotation by 90 degrees about the y direction (through the origin, then through Q).
ROT_AXIS = np.array([0.0, 1.0, 0.0])
ROT_ANGLE = 90.0
ROT_POINT = np.array([1.0, 0.0, 2.0])
#: Exercise 3: the mirror in the plane x + y = 2.
MIRROR_PLANE_POINT = np.array([2.0, 0.0, 0.0])
MIRROR_NORMAL = np.array([1.0, 1.0, 0.0])
#: Exercise 4: first translate by COMPOSE_SHIFT, then rotate by COMPOSE_ANGLE about the z axis.
COMPOSE_SHIFT = np.array([1.0, 2.0, 0.0])
COMPOSE_ANGLE = 90.0
#: Exercise 5: the perspective from the eye (0, 0, 5) onto the plane z = 0, applied to P.
PERSP_EYE = np.array([0.0, 0.0, 5.0])
PERSP_PLANE_POINT = np.array([0.0, 0.0, 0.0])
PERSP_NORMAL = np.array([0.0, 0.0, 1.0])
PERSP_POINT = np.array([2.0, 4.0, 3.0])
#: Exercise 6: an affine matrix, and the coordinates read once as a point and once as a vector.
AFFINE_MATRIX = np.array([[0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [2.0, -1.0, 3.0, 1.0]])
AFFINE_COORDS = np.array([1.0, 2.0, 3.0])
#: Exercise 7: the affine map sending the frame P0..P3 to Q0..Q3.
FRAME_SOURCES = np.array([[1.0, 1.0, 0.0], [2.0, 1.0, 0.0], [1.0, 2.0, 1.0], [1.0, 1.0, 1.0]])
FRAME_IMAGES = np.array([[2.0, 0.0, 1.0], [2.0, 1.0, 1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 3.0]])
#: Exercise 8: rotate by 90 degrees about the line through (0, 1, 1) along x, then scale by 2; invert.
INVERSE_AXIS = np.array([1.0, 0.0, 0.0])
INVERSE_ANGLE = 90.0
INVERSE_POINT = np.array([0.0, 1.0, 1.0])
INVERSE_SCALE = 2.0

REL_TOL = 1e-4

DECK = Deck("ch13")

_AXIS_NAMES = {(1.0, 0.0, 0.0): "x", (0.0, 1.0, 0.0): "y", (0.0, 0.0, 1.0): "z"}
_AXES = tuple(_AXIS_NAMES)
#: cos and sin of the angles dealt, written exactly
_TRIG = {30.0: ("√3/2", "1/2"), 45.0: ("√2/2", "√2/2"), 60.0: ("1/2", "√3/2"), 90.0: ("0", "1"),
         120.0: ("-1/2", "√3/2"), 135.0: ("-√2/2", "√2/2"), 150.0: ("-√3/2", "1/2"), 180.0: ("-1", "0"),
         270.0: ("0", "-1")}


def _rows(M) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(x) for x in row) + "]" for row in np.asarray(M, float)) + "]"


def _arr(v):
    return np.asarray(v, dtype=float)


def _r(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return np.round(np.asarray(x, dtype=float), 6) + 0.0


def _f6(x) -> str:
    return fmt(_r(x), 6)


def _rows6(M) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(x, 6) for x in row) + "]" for row in _r(M)) + "]"


def _axis_name(axis) -> str:
    return _AXIS_NAMES[_tup(axis)]


def _trig(angle):
    th = np.radians(angle)
    return _TRIG.get(float(angle), (_f6(np.cos(th)), _f6(np.sin(th))))


def _plane_eq(N, d) -> str:
    """The plane N·X = d as text, ``x + y = 2``."""
    terms = []
    for c, var in zip(np.asarray(N, float), "xyz"):
        if c == 0:
            continue
        mag = "" if abs(c) == 1 else fmt(abs(c))
        sign = ("-" if c < 0 else "") if not terms else (" - " if c < 0 else " + ")
        terms.append(f"{sign}{mag}{var}")
    return "".join(terms) + f" = {fmt(d)}"


def _length_text(N) -> str:
    k = float(np.asarray(N, float) @ np.asarray(N, float))
    r = math.isqrt(int(round(k)))
    return fmt(r) if r * r == k else f"√{fmt(k)}"


def _perpendicular(v, axis) -> bool:
    """Whether v has a component of at least 1/2 off the axis direction."""
    v, a = _arr(v), _arr(axis)
    return float(np.linalg.norm(np.cross(v, a / np.linalg.norm(a)))) >= 0.5


# -- reading and comparing -------------------------------------------------------------------------

def _read(answer, ask, shape, what):
    got, err = read_points(answer, what, ask=ask)
    if err is not None:
        return None, err
    if got.shape != shape:
        return None, wrong(f"{what} should have shape {shape}; yours has shape {got.shape}. Check what the "
                           f"exercise asks for.")
    return got, None


def _close(got, expected) -> bool:
    exp = np.asarray(expected, dtype=float)
    return got.shape == exp.shape and bool(np.all(np.abs(got - exp) <= REL_TOL * np.maximum(1.0, np.abs(exp))))


def _same(a, b) -> bool:
    """The checkers' tolerance, both ways (the ``same`` of every exercise that deals)."""
    a, b = _arr(a), _arr(b)
    return a.shape == b.shape and _close(a, b) and _close(b, a)


def _entry(got, expected, name, hint) -> Result:
    bad = np.argwhere(np.abs(got - expected) > REL_TOL * np.maximum(1.0, np.abs(expected)))
    i, j = (int(x) for x in bad[0])
    return wrong(f"the entry in row {i}, column {j} of {name} is {off_by(got[i, j], expected[i, j])} "
                 f"({len(bad)} entries are off); {hint}.")


def _far(got, expected, what, hint) -> Result:
    return wrong(f"{what} is {far_off(got, expected)} from where it should be; {hint}.")


# -- §13.3.2 rotation -----------------------------------------------------------------------------------------

_STORED_BLOCK = {"axis": _tup(ROT_AXIS), "angle": ROT_ANGLE}
_BLOCK_ANGLES = (30.0, 45.0, 60.0, 90.0, 120.0, 135.0, 150.0, 270.0)


def _block(p):
    return transforms.rotation(p["axis"], p["angle"])[:3, :3]


def _other_axes(axis):
    return [a for a in _AXES if a != _tup(axis)]


@memo
def _block_slips(p):
    L = _block(p)
    return {"transposed": L.T,
            "about another axis": transforms.rotation(_other_axes(p["axis"])[0], p["angle"])[:3, :3],
            "radians": transforms.rotation(p["axis"], math.degrees(p["angle"]))[:3, :3]}


def _block_generate(rng) -> dict:
    return {"axis": _AXES[int(rng.integers(0, 3))], "angle": float(rng.choice(_BLOCK_ANGLES))}


def _block_statement(p) -> str:
    return (f"Give the upper-left 3x3 block L of the 4x4 matrix of the rotation by {fmt(p['angle'])} degrees about "
            f"the {_axis_name(p['axis'])} axis (direction {fmt(p['axis'])}, through the origin; counterclockwise "
            f"looking down the axis), in the row convention [P 1] M: row i of L is the image of the i-th unit "
            f"vector. Give [[...], [...], [...]] (Goldman §13.3).")


def _block_steps(p) -> str:
    w, th = _arr(p["axis"]), p["angle"]
    c, s = _trig(th)
    images = transforms.rotate(np.eye(3), w, th)
    lines = [f"1. The unit axis w = {fmt(w)}; cos {fmt(th)}° = {c}, sin {fmt(th)}° = {s}.",
             "2. Rodrigues' formula (§12.3) on each unit vector: R(e_i) = cos θ e_i + (1 - cos θ)(e_i·w) w + "
             "sin θ (w × e_i)."]
    for i, e in enumerate(np.eye(3)):
        lines.append(f"   R(e_{i + 1}) = R({fmt(e)}) = {_f6(images[i])}: row {i + 1} of L "
                     f"(w × e_{i + 1} = {fmt(np.cross(w, e))}).")
    lines.append(f"3. L = {_rows6(_block(p))}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_BLOCK, generate=_block_generate, answer=_block, slips=_block_slips,
               statement=_block_statement, steps=_block_steps, same=_same)
def check_rotation_block(answer, p) -> Result:
    """Check the 3x3 block of the statement's rotation about a coordinate axis (Goldman §13.3);
    recognises the transpose (column convention, which is also the rotation the other way), the
    rotation about another axis and the angle taken in radians.
    """
    got, err = _read(answer, "the 3x3 block as [[...], [...], [...]]", (3, 3), "your block")
    if err is not None:
        return err
    th = p["angle"]
    L = _block(p)
    if _close(got, L):
        if p == _STORED_BLOCK:
            return correct("row i is the image of the i-th unit vector: x goes to -z, y stays, z goes to x.")
        return correct("row i is the image of the i-th unit vector under the rotation.")
    if _close(got, L.T):
        return wrong("that is the transpose: the column convention (M P with P a column), which in the row "
                     "convention is the rotation the other way. With [P 1] M, row i of L is the image of the "
                     f"i-th unit vector; turn (1, 0, 0) by cos θ v + (1 - cos θ)(v·w) w + sin θ (w × v) with "
                     f"w = {fmt(p['axis'])}.")
    for other in _other_axes(p["axis"]):
        for sign in (1, -1):
            if _close(got, transforms.rotation(other, sign * th)[:3, :3]):
                return wrong(f"that rotates about another coordinate axis: the {_axis_name(p['axis'])} axis is the "
                             f"one whose row stays {fmt(p['axis'])}.")
    c, _ = _trig(th)
    if _close(got, transforms.rotation(p["axis"], math.degrees(th))[:3, :3]):
        return wrong(f"you took cos and sin of {fmt(th)} as if it were radians: the angle is in degrees (np.cos and "
                     f"math.cos take radians; convert with np.radians first, cos {fmt(th)}° = {c}).")
    if np.isclose(abs(np.linalg.det(got)), 1, atol=1e-3) and not np.allclose(got @ got.T, np.eye(3), atol=1e-3):
        return wrong("the rows of a rotation block are perpendicular unit vectors; yours are not.")
    return _entry(got, L, "your block", "apply Rodrigues' formula (§12.3) to (1, 0, 0), (0, 1, 0), (0, 0, 1) and "
                                        "write the images as rows")


_STORED_ROW = {"axis": _tup(ROT_AXIS), "angle": ROT_ANGLE, "Q": _tup(ROT_POINT)}
_ROW_ANGLES = (60.0, 90.0, 120.0, 270.0)


def _row_parts(p):
    M = transforms.rotation(p["axis"], p["angle"], point=p["Q"])
    return M[:3, :3], _arr(p["Q"]), M[3, :3]


@memo
def _row_slips(p):
    L, Q, _ = _row_parts(p)
    return {"sign": Q @ L - Q, "about the origin": np.zeros(3), "Q itself": Q, "transposed block": Q - Q @ L.T}


def _row_generate(rng) -> dict:
    return {"axis": _AXES[int(rng.integers(0, 3))], "angle": float(rng.choice(_ROW_ANGLES)),
            "Q": _ints(rng, -3, 3)}


def _row_ok(p):
    if not _perpendicular(p["Q"], p["axis"]):
        return "Q lies on the parallel axis through the origin: the translation row is zero"
    return None


def _row_statement(p) -> str:
    if p == _STORED_ROW:
        return (f"Now rotate by the same {fmt(ROT_ANGLE)} degrees about the line through Q = {fmt(ROT_POINT)} "
                f"parallel to the y axis. The 4x4 matrix keeps the block L of the previous exercise; give its last "
                f"row's first three entries, the translation row [a, b, c] (Goldman §13.3).")
    return (f"Rotate by {fmt(p['angle'])} degrees about the line through Q = {fmt(p['Q'])} parallel to the "
            f"{_axis_name(p['axis'])} axis (direction {fmt(p['axis'])}; counterclockwise looking down the axis). "
            f"Its 4x4 matrix in the row convention [P 1] M has the block L of the rotation by the same angle about "
            f"the parallel axis through the origin (row i of L is the image of the i-th unit vector); give its last "
            f"row's first three entries, the translation row [a, b, c] (Goldman §13.3).")


def _row_steps(p) -> str:
    L, Q, t = _row_parts(p)
    return (f"1. The block of the rotation by {fmt(p['angle'])}° about the {_axis_name(p['axis'])} axis: "
            f"L = {_rows6(L)}.\n"
            f"2. Q lies on the axis, so [Q 1] M = [Q L + t 1] must be [Q 1]: t = Q - Q L.\n"
            f"3. Q L = {_f6(Q @ L)}, so t = {fmt(Q)} - {_f6(Q @ L)} = {_f6(t)}.")


@DECK.exercise(stored=_STORED_ROW, generate=_row_generate, answer=lambda p: _row_parts(p)[2], slips=_row_slips,
               statement=_row_statement, steps=_row_steps, same=_same, well_posed=_row_ok)
def check_translation_row(answer, p) -> Result:
    """Check the translation row of the rotation about the statement's line through Q (Goldman §13.3);
    recognises Q L - Q (sign), Q itself, zero (the rotation about the origin), the row made with the
    transposed block, and -Q.

    >>> check_translation_row([3, 0, 1])
    Not yet: that row was made with the transposed block (the column convention): use Q - Q L with the L of [P 1] M.
    """
    got, err = _read(answer, "the translation row as [a, b, c]", (3,), "your row")
    if err is not None:
        return err
    L, Q, expected = _row_parts(p)
    if _close(got, expected):
        return correct(f"the translation row is Q - Q L = {fmt(Q)} - {fmt(Q @ L)}, so that Q stays where it is.")
    if _close(got, Q @ L - Q):
        return wrong("the sign is wrong: the row t must satisfy Q L + t = Q, since Q lies on the axis; "
                     "so t = Q - Q L.")
    if _close(got, np.zeros(3)):
        return wrong("a zero translation row is the rotation about the parallel axis through the origin; this "
                     "axis passes through Q, which must stay fixed: Q L + t = Q.")
    if _close(got, Q) or _close(got, -Q):
        return wrong("the translation row is not ±Q: it is what moves Q L back to Q, t = Q - Q L. (Translating "
                     "to the origin, rotating and translating back gives the same row.)")
    if _close(got, Q - Q @ L.T):
        return wrong("that row was made with the transposed block (the column convention): use Q - Q L with "
                     "the L of [P 1] M.")
    return _far(got, expected, "your row", "Q lies on the axis, so [Q 1] M = [Q 1]: solve Q L + t = Q for t")


# -- §13.3.3 mirror image ------------------------------------------------------------------------------------

_STORED_MIRROR = {"Q": _tup(MIRROR_PLANE_POINT), "N": _tup(MIRROR_NORMAL)}
#: normals whose 2 nᵀn has rational entries (hand-workable), none a unit vector
_NORMALS = ((1.0, 1.0, 0.0), (1.0, 0.0, 1.0), (0.0, 1.0, 1.0), (1.0, -1.0, 0.0), (1.0, 0.0, -1.0), (0.0, 1.0, -1.0),
            (1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (2.0, 2.0, 1.0), (2.0, -1.0, 2.0), (1.0, -2.0, 2.0), (0.0, 3.0, 4.0),
            (3.0, 0.0, 4.0), (4.0, 3.0, 0.0), (1.0, 1.0, 1.0), (1.0, -1.0, 1.0))


def _mirror_raw(Q, N):
    """The mirror's matrix made with the normal as given (not normalised)."""
    raw = np.eye(4)
    raw[:3, :3] = np.eye(3) - 2 * np.outer(N, N)
    raw[3, :3] = Q - Q @ raw[:3, :3]
    return raw


@memo
def _mirror_slips(p):
    Q, N = _arr(p["Q"]), _arr(p["N"])
    M = transforms.mirror(Q, N)
    sign = M.copy()
    sign[3, :3] = -M[3, :3]
    return {"transposed": M.T, "projection": transforms.orthogonal_projection(Q, N), "unnormalised": _mirror_raw(Q, N),
            "wrong sign": sign, "through the origin": transforms.mirror([0, 0, 0], N)}


def _mirror_generate(rng) -> dict:
    return {"Q": _ints(rng, -2, 2), "N": _NORMALS[int(rng.integers(0, len(_NORMALS)))]}


def _mirror_ok(p):
    if abs(float(_arr(p["Q"]) @ _arr(p["N"]))) < 0.5:
        return "the plane passes through the origin: the translation row is zero"
    return None


def _mirror_statement(p) -> str:
    Q, N = _arr(p["Q"]), _arr(p["N"])
    return (f"Give the 4x4 matrix (row convention, [P 1] M) of the mirror in the plane through Q = "
            f"{fmt(Q)} with normal N = {fmt(N)} (the plane {_plane_eq(N, Q @ N)}), as four rows "
            f"(Goldman §13.3).")


def _mirror_steps(p) -> str:
    Q, N = _arr(p["Q"]), _arr(p["N"])
    n = N / np.linalg.norm(N)
    M = transforms.mirror(Q, N)
    return (f"1. |N| = {_length_text(N)}, so n = N/|N| = {_f6(n)} and nᵀn = NᵀN/{fmt(N @ N)} = "
            f"{_rows6(np.outer(n, n))}.\n"
            f"2. The block: L = I - 2 nᵀn = {_rows6(M[:3, :3])}.\n"
            f"3. Q·n = {_f6(Q @ n)}, so the translation row is 2 (Q·n) n = {_f6(M[3, :3])} (check: Q L + t = Q).\n"
            f"4. M = {_rows6(M)}.")


@DECK.exercise(stored=_STORED_MIRROR, generate=_mirror_generate, answer=lambda p: transforms.mirror(p["Q"], p["N"]),
               slips=_mirror_slips, statement=_mirror_statement, steps=_mirror_steps, same=_same,
               well_posed=_mirror_ok)
def check_mirror_matrix(answer, p) -> Result:
    """Check the 4x4 matrix of the mirror in the statement's plane (Goldman §13.3); recognises the
    projection (factor 1), the unnormalised normal, the transposed matrix (translation in the last
    column), the wrong sign of the translation row, and the mirror in the plane through the origin.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    Q, N = _arr(p["Q"]), _arr(p["N"])
    M = transforms.mirror(Q, N)
    if _close(got, M):
        how = " (it swaps x and y with a sign)" if p == _STORED_MIRROR else ""
        return correct(f"the block is I - 2 nᵀn with n = {fmt(N)}/{_length_text(N)}{how}, and the "
                       f"translation row is 2 (Q·n) n.")
    if _close(got, M.T):
        return wrong("that is the transpose, the column convention: in the row convention [P 1] M the "
                     "translation goes in the last row and the last column is (0, 0, 0, 1).")
    if _close(got, transforms.orthogonal_projection(Q, N)):
        return wrong("that is the orthogonal projection onto the plane (factor 1): the mirror goes twice as "
                     "far, I - 2 nᵀn and the row 2 (Q·n) n.")
    if _close(got[:3, :3], _mirror_raw(Q, N)[:3, :3]):
        return wrong(f"the normal {fmt(N)} has length {_length_text(N)}: I - 2 NᵀN needs the unit normal n = N/|N|.")
    if _close(got[:3, :3], M[:3, :3]) and _close(got[3, :3], -M[3, :3]):
        return wrong("the block is right but the translation row has the wrong sign: a point Q of the plane "
                     "must stay fixed, Q (I - 2 nᵀn) + t = Q.")
    if _close(got, transforms.mirror([0, 0, 0], N)):
        return wrong(f"that is the mirror in the parallel plane {_plane_eq(N, 0)} through the origin: the plane "
                     f"{_plane_eq(N, Q @ N)} needs the translation row 2 (Q·n) n.")
    return _entry(got, M, "your matrix", "the block is I - 2 nᵀn for the unit normal, the last row "
                                         "(2 (Q·n) n, 1), the last column (0, 0, 0, 1)")


# -- composition (our formulation: the book has no section on it) ----------------------------------------------

_STORED_COMPOSE = {"shift": _tup(COMPOSE_SHIFT), "axis": (0.0, 0.0, 1.0), "angle": COMPOSE_ANGLE}


def _parts(p):
    return transforms.translation(p["shift"]), transforms.rotation(p["axis"], p["angle"])


def _compose_answer(p):
    T, R = _parts(p)
    return T @ R


@memo
def _compose_slips(p):
    T, R = _parts(p)
    return {"wrong order": R @ T, "transposed": (T @ R).T, "transposed other order": (R @ T).T,
            "clockwise": T @ transforms.rotation(p["axis"], -p["angle"])}


def _compose_generate(rng) -> dict:
    return {"shift": _ints(rng, -3, 3), "axis": _AXES[int(rng.integers(0, 3))],
            "angle": float(rng.choice(_ROW_ANGLES))}


def _compose_ok(p):
    if not _perpendicular(p["shift"], p["axis"]):
        return "the shift runs along the axis: the two orders agree"
    return None


def _compose_statement(p) -> str:
    return (f"Give the 4x4 matrix (row convention) of the map that first translates by {fmt(p['shift'])} and then "
            f"rotates by {fmt(p['angle'])} degrees about the {_axis_name(p['axis'])} axis (through the origin), as "
            f"four rows (Goldman §13.3; composition).")


def _compose_steps(p) -> str:
    T, R = _parts(p)
    v = _arr(p["shift"])
    return (f"1. T = the identity with {fmt(v)} in the last row; R has the block {_rows6(R[:3, :3])} "
            f"(rows: the images of the unit vectors).\n"
            f"2. With row vectors [P 1] T R applies T first, so M = T R.\n"
            f"3. The block of T R is R's; its last row is the shift turned by R: {fmt(v)} R = {_f6(v @ R[:3, :3])}.\n"
            f"4. M = {_rows6(T @ R)}.")


@DECK.exercise(stored=_STORED_COMPOSE, generate=_compose_generate, answer=_compose_answer, slips=_compose_slips,
               statement=_compose_statement, steps=_compose_steps, same=_same, well_posed=_compose_ok)
def check_composite_matrix(answer, p) -> Result:
    """Check the matrix of "first translate, then rotate" (Goldman §13.3, composed); recognises the wrong order,
    the transposed matrix (column convention) and the rotation the other way.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    T, R = _parts(p)
    M = T @ R
    if _close(got, M):
        return correct("with row vectors the first map stands on the left, M = T R; its last row is the shift "
                       "turned by R.")
    if _close(got, R @ T):
        return wrong("that is R T: first rotate, then translate. With row vectors [P 1] T R applies T first, "
                     "so the first map stands on the left.")
    if _close(got, M.T):
        return wrong("that is the transpose, the column convention (R T as column matrices); in the row "
                     "convention the translation is in the last row.")
    if _close(got, (R @ T).T):
        return wrong("that is the transpose of the other order: in the row convention the first map stands on "
                     "the left, and the translation sits in the last row.")
    if _close(got, T @ transforms.rotation(p["axis"], -p["angle"])):
        if p == _STORED_COMPOSE:
            return wrong("that rotates clockwise: 90 degrees about z takes (1, 0, 0) to (0, 1, 0), so the first row "
                         "of the rotation block is (0, 1, 0).")
        return wrong(f"that rotates clockwise: counterclockwise looking down the {_axis_name(p['axis'])} axis, row i "
                     f"of the block is the image of the i-th unit vector turned by +{fmt(p['angle'])} degrees; check "
                     f"the sign of the sin θ entries.")
    return _entry(got, M, "your matrix", "multiply the translation matrix by the rotation matrix, in that order")


# -- §13.6.2 perspective -------------------------------------------------------------------------------------------

_STORED_PERSP = {"E": _tup(PERSP_EYE), "Q": _tup(PERSP_PLANE_POINT), "N": _tup(PERSP_NORMAL), "P": _tup(PERSP_POINT)}


def _perspective(p):
    return transforms.perspective(p["E"], p["Q"], p["N"])


@memo
def _persp_answers(p):
    M, P = _perspective(p), _arr(p["P"])
    h = transforms.homogeneous(P[None], M)[0]
    ht = np.append(P, 1) @ M.T
    return transforms.apply(P[None], M)[0], {"no divide": h[:3], "divided by -w": -h[:3] / h[3],
                                             "transposed": ht[:3] / ht[3]}


def _persp_generate(rng) -> dict:
    k = int(rng.integers(0, 3))
    N = np.eye(3)[k]
    q = float(rng.integers(-1, 3))
    h = int(rng.integers(3, 7))
    E = np.array(_ints(rng, -2, 2))
    E[k] = q + h
    P = np.array(_ints(rng, -3, 3))
    P[k] = q + int(rng.integers(1, h))
    return {"E": _tup(E), "Q": _tup(q * N), "N": _tup(N), "P": _tup(P)}


def _persp_ok(p):
    P = _arr(p["P"])
    ht = np.append(P, 1) @ _perspective(p).T
    if abs(ht[3]) < 0.5:
        return "the transposed matrix sends P to infinity"
    return None


def _persp_statement(p) -> str:
    N = _arr(p["N"])
    return (f"The perspective projection from the eye E = {fmt(p['E'])} onto the plane {_plane_eq(N, _arr(p['Q']) @ N)} "
            f"has the 4x4 matrix M = {_rows(_perspective(p))} in the row convention. Apply it to P = {fmt(p['P'])} and "
            f"give the image point [x, y, z] (Goldman §13.6.2).")


def _persp_steps(p) -> str:
    M, P = _perspective(p), _arr(p["P"])
    h = transforms.homogeneous(P[None], M)[0]
    return (f"1. [P 1] M = {fmt(P)} times the rows of the block, plus the last row: {_f6(h)}.\n"
            f"2. The homogeneous coordinate is w = {_f6(h[3])}; divide the first three by it: "
            f"{_f6(transforms.apply(P[None], M)[0])}.\n"
            f"3. Check: the image lies on the plane and on the line from E through P.")


@DECK.exercise(stored=_STORED_PERSP, generate=_persp_generate, answer=lambda p: _persp_answers(p)[0],
               slips=lambda p: _persp_answers(p)[1], statement=_persp_statement, steps=_persp_steps, same=_same,
               well_posed=_persp_ok)
def check_perspective_image(answer, p) -> Result:
    """Check the image of the statement's point under the perspective matrix (Goldman §13.6.2);
    recognises the homogeneous divide left out, the transposed matrix, and the divide by -w.

    >>> check_perspective_image([-10, -20, 0])
    Not yet: those are the first three homogeneous coordinates of [P 1] M; the point is what you get after dividing them by the fourth, w.
    """
    got, err = _read(answer, "the image as [x, y, z]", (3,), "your point")
    if err is not None:
        return err
    M, P = _perspective(p), _arr(p["P"])
    expected = transforms.apply(P[None], M)[0]
    h = transforms.homogeneous(P[None], M)[0]
    N = _arr(p["N"])
    if _close(got, expected):
        return correct(f"[P 1] M = {fmt(h)}; dividing by w = {fmt(h[3])} gives a point of the plane "
                       f"{_plane_eq(N, _arr(p['Q']) @ N)} on the line from E through P.")
    if _close(got, h[:3]):
        return wrong("those are the first three homogeneous coordinates of [P 1] M; the point is what you get "
                     "after dividing them by the fourth, w.")
    if _close(got, -h[:3] / h[3]):
        return wrong("the sign is wrong: divide the homogeneous coordinates by w itself (it is negative here), "
                     "not by |w|.")
    ht = np.append(P, 1) @ M.T
    if _close(got, ht[:3] / ht[3]) or _close(got, ht[:3]):
        return wrong("that multiplies by the transpose (the column convention); with the row convention the "
                     "point is the row [P 1] times M.")
    return _far(got, expected, "your point", "compute the row [x y z 1] times M, then divide by its last entry")


# -- §13.1 points and vectors -----------------------------------------------------------------------------------------

_STORED_PV = {"M": _tup(AFFINE_MATRIX), "c": _tup(AFFINE_COORDS)}


@memo
def _pv_answers(p):
    M, c = _arr(p["M"]), _arr(p["c"])
    point = transforms.apply(c[None], M)[0]
    vector = transforms.apply_to_vectors(c[None], M)[0]
    Lt, t = M[:3, :3].T, M[3, :3]
    slips = {"vector translated": np.stack([point, point]), "point not translated": np.stack([vector, vector]),
             "swapped": np.stack([vector, point]), "vector untouched": np.stack([point, c]),
             "column convention": np.stack([c @ Lt + t, c @ Lt])}
    return np.stack([point, vector]), slips


def _pv_generate(rng) -> dict:
    while True:
        L = rng.integers(-1, 3, size=(3, 3)).astype(float)
        if abs(np.linalg.det(L)) >= 0.5 and not np.array_equal(L, L.T):
            break
    M = np.eye(4)
    M[:3, :3] = L
    M[3, :3] = _ints(rng, -3, 3)
    return {"M": _tup(M), "c": _ints(rng, -3, 3)}


def _pv_ok(p):
    M, c = _arr(p["M"]), _arr(p["c"])
    L = M[:3, :3]
    if not np.any(M[3, :3]) or not np.any(c):
        return "no translation, or the zero vector: point and vector agree"
    if _same(c @ L.T, c) or _same(c @ L, c):
        return "the block leaves the coordinates (or their column-convention image) alone"
    return None


def _pv_statement(p) -> str:
    return (f"The affine map with the 4x4 matrix M = {_rows(p['M'])} (row convention) is applied to the "
            f"coordinates {fmt(p['c'])}, once read as a point P and once as a vector v. Give "
            f"[[image of P], [image of v]] (Goldman §13.1).")


def _pv_steps(p) -> str:
    M, c = _arr(p["M"]), _arr(p["c"])
    point, vector = _pv_answers(p)[0]
    terms = " + ".join(f"{fmt(x)}·{fmt(row)}" for x, row in zip(c, M[:3, :3]))
    return (f"1. The vector is [v 0]: [v 0] M = v L = {terms} = {_f6(vector)} (the last row does not act).\n"
            f"2. The point is [P 1]: [P 1] M = P L + t = {_f6(vector)} + {fmt(M[3, :3])} = {_f6(point)}.")


@DECK.exercise(stored=_STORED_PV, generate=_pv_generate, answer=lambda p: _pv_answers(p)[0],
               slips=lambda p: _pv_answers(p)[1], statement=_pv_statement, steps=_pv_steps, same=_same,
               well_posed=_pv_ok)
def check_point_and_vector(answer, p) -> Result:
    """Check the images of the same coordinates read as a point and as a vector (Goldman §13.1);
    recognises a translated vector, an untouched vector, the two answers swapped and the block
    transposed.

    >>> check_point_and_vector([[0, 0, 6], [0, 0, 6]])
    Not yet: your vector was translated: a vector has homogeneous coordinate 0, [v 0] M, so the last row of M does not act on it.
    """
    got, err = _read(answer, "[[image of P], [image of v]]", (2, 3), "your answer")
    if err is not None:
        return err
    M, c = _arr(p["M"]), _arr(p["c"])
    expected = _pv_answers(p)[0]
    point, vector = expected
    if _close(got, expected):
        return correct("[P 1] M adds the last row to P L, while [v 0] M = v L leaves the translation out.")
    if _close(got, np.stack([point, point])):
        return wrong("your vector was translated: a vector has homogeneous coordinate 0, [v 0] M, so the last "
                     "row of M does not act on it.")
    if _close(got, np.stack([vector, vector])):
        return wrong("your point was not translated: a point has homogeneous coordinate 1, [P 1] M, so the last "
                     "row of M is added.")
    if _close(got, np.stack([vector, point])):
        return wrong("the two answers are swapped: the point gets the translation row, the vector does not.")
    if _close(got[1], c):
        return wrong("the vector is not left alone: only the translation misses it; the block L still acts, "
                     "[v 0] M = v L.")
    Lt = M[:3, :3].T
    if _close(got[1], c @ Lt) or _close(got[0], c @ Lt + M[3, :3]):
        return wrong("that uses the columns of the block (the column convention); in the row convention the "
                     "coordinates are a row times M: x times row 0 plus y times row 1 plus z times row 2.")
    which = 0 if not _close(got[0], point) else 1
    name = "the image of P" if which == 0 else "the image of v"
    return _far(got[which], expected[which], name, "multiply the row [x y z 1] (point) or [x y z 0] (vector) by M")


# -- §13.1 the map fixed by the images of an affine frame ------------------------------------------------------

_STORED_FRAME = {"P": _tup(FRAME_SOURCES), "Q": _tup(FRAME_IMAGES)}
#: the condition number a dealt frame may have at most (no nearly coplanar sources)
FRAME_MAX_CONDITION = 12.0


@memo
def _frame_answers(p):
    P, Q = _arr(p["P"]), _arr(p["Q"])
    M = transforms.affine_from_points(P, Q)
    L = M[:3, :3]
    row_q0, row_shift, v_ignored = M.copy(), M.copy(), np.eye(4)
    row_q0[3, :3] = Q[0]
    row_shift[3, :3] = Q[0] - P[0]
    v_ignored[:3, :3] = Q[1:] - Q[0]
    v_ignored[3, :3] = Q[0] - P[0] @ v_ignored[:3, :3]
    slips = {"transposed": M.T, "inverse": transforms.affine_from_points(Q, P), "row Q0": row_q0,
             "row Q0 - P0": row_shift, "the vectors P_i - P0 taken as unit vectors": v_ignored}
    del L
    return M, slips


def _frame_generate(rng) -> dict:
    while True:
        V = rng.integers(-1, 2, size=(3, 3)).astype(float)
        if round(abs(np.linalg.det(V))) == 1:
            break
    while True:
        W = rng.integers(-2, 3, size=(3, 3)).astype(float)
        if abs(np.linalg.det(W)) >= 0.5:
            break
    P0, Q0 = np.array(_ints(rng, -2, 2)), np.array(_ints(rng, -2, 2))
    return {"P": _tup(np.vstack([P0, P0 + V])), "Q": _tup(np.vstack([Q0, Q0 + W]))}


def _frame_ok(p):
    P, Q = _arr(p["P"]), _arr(p["Q"])
    if np.linalg.cond(P[1:] - P[0]) > FRAME_MAX_CONDITION:
        return "the sources are nearly coplanar (the vectors P_i - P0 are ill-conditioned)"
    if abs(np.linalg.det(Q[1:] - Q[0])) < 0.5:
        return "the images are coplanar: the map has no inverse (the inverse slip would not exist)"
    if not np.any(P[0]):
        return "P0 is the origin: the translation row is Q0"
    return None


def _frame_statement(p) -> str:
    P, Q = _arr(p["P"]), _arr(p["Q"])
    return ("An affine map of 3-space sends the four points " + ", ".join(f"P{i} = {fmt(x)}" for i, x in enumerate(P))
            + " (an affine frame: the vectors P1 - P0, P2 - P0, P3 - P0 are independent) to "
            + ", ".join(f"Q{i} = {fmt(x)}" for i, x in enumerate(Q))
            + ". Give its 4x4 matrix in the row convention [P 1] M, as four rows (Goldman §13.1).")


def _frame_steps(p) -> str:
    P, Q = _arr(p["P"]), _arr(p["Q"])
    M = _frame_answers(p)[0]
    V, W = P[1:] - P[0], Q[1:] - Q[0]
    # V⁻¹ is the block of the map sending the frame to the unit frame (0, e1, e2, e3)
    V_inv = transforms.affine_from_points(P, np.vstack([np.zeros(3), np.eye(3)]))[:3, :3]
    return (f"1. An affine map is fixed by the image of a point and of three independent vectors: "
            f"[P_i 1] M = [Q_i 1] gives (P_i - P0) L = Q_i - Q0 and P0 L + t = Q0.\n"
            f"2. The vectors as rows: V = {_rows6(V)}, their images W = {_rows6(W)}.\n"
            f"3. V L = W, so L = V⁻¹ W with V⁻¹ = {_rows6(V_inv)}: L = {_rows6(M[:3, :3])}.\n"
            f"4. t = Q0 - P0 L = {fmt(Q[0])} - {_f6(P[0] @ M[:3, :3])} = {_f6(M[3, :3])}.\n"
            f"5. M = {_rows6(M)}; check: [P_i 1] M = [Q_i 1] for i = 0..3.")


@DECK.exercise(stored=_STORED_FRAME, generate=_frame_generate, answer=lambda p: _frame_answers(p)[0],
               slips=lambda p: _frame_answers(p)[1], statement=_frame_statement, steps=_frame_steps, same=_same,
               well_posed=_frame_ok)
def check_frame_matrix(answer, p) -> Result:
    """Check the 4x4 matrix (row convention) of the affine map sending the statement's four points to
    their four images (Goldman §13.1); recognises the transpose (column convention), the inverse map
    (frame and images swapped), the translation row taken as Q0 or as Q0 - P0, and the vectors
    P_i - P0 treated as if they were the unit vectors.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    P, Q = _arr(p["P"]), _arr(p["Q"])
    M, slips = _frame_answers(p)
    if _close(got, M):
        return correct("[P_i 1] M = [Q_i 1] for the four points: the block sends the vectors P_i - P0 to "
                       "Q_i - Q0, and the last row sends P0 to Q0.")
    if _close(got, M.T):
        return wrong("that is the transpose, the column convention: in the row convention [P 1] M the "
                     "translation goes in the last row and the last column is (0, 0, 0, 1).")
    if _close(got, slips["inverse"]):
        return wrong("that matrix sends the images back to the frame: it is the inverse of the map asked for. "
                     "The rows [P_i 1] of the sources stand on the left, [P_i 1] M = [Q_i 1].")
    if _close(got[:3, :3], M[:3, :3]):
        if _close(got[3, :3], Q[0]):
            return wrong("the block is right, but the translation row is not Q0: P0 moves under L too, "
                         "[P0 1] M = [P0 L + t 1] must be [Q0 1], so t = Q0 - P0 L.")
        if _close(got[3, :3], Q[0] - P[0]):
            return wrong("the block is right, but Q0 - P0 is the shift of P0 before L acts; with the row "
                         "convention L acts first: P0 L + t = Q0, so t = Q0 - P0 L.")
        if not _close(got[:, 3], np.array([0, 0, 0, 1.0])):
            return wrong("the block is right, but an affine map has the last column (0, 0, 0, 1).")
        return _far(got[3, :3], M[3, :3], "your translation row", "solve P0 L + t = Q0 for t")
    if _close(got[:3, :3], Q[1:] - Q[0]):
        return wrong("the rows of your block are the images Q_i - Q0, as if P_i - P0 were the unit vectors; "
                     "here they are not: L solves (P_i - P0) L = Q_i - Q0, that is L = V⁻¹ W with the vectors as "
                     "rows of V and W.")
    return _entry(got, M, "your matrix", "solve (P_i - P0) L = Q_i - Q0 for the block L, then t = Q0 - P0 L")


# -- §13.3-13.4 the inverse of a composite: a rigid motion, then a scaling ---------------------------------------

_STORED_INVERSE = {"axis": _tup(INVERSE_AXIS), "angle": INVERSE_ANGLE, "Q": _tup(INVERSE_POINT), "s": INVERSE_SCALE}
_INVERSE_ANGLES = (90.0, 180.0, 270.0)


def _inverse_parts(p):
    R = transforms.rotation(p["axis"], p["angle"], point=p["Q"])
    S = transforms.scaling(p["s"])
    return R, S


@memo
def _inverse_answers(p):
    R, S = _inverse_parts(p)
    M = transforms.compose(R, S)
    R_inv, S_inv = transforms.rigid_inverse(R), transforms.scaling(1 / p["s"])
    answer = transforms.compose(S_inv, R_inv)
    negated = answer.copy()
    negated[3, :3] = -M[3, :3]
    return answer, {"same order": transforms.compose(R_inv, S_inv), "transposed": M.T, "translation negated": negated}


def _inverse_generate(rng) -> dict:
    return {"axis": _AXES[int(rng.integers(0, 3))], "angle": float(rng.choice(_INVERSE_ANGLES)),
            "Q": _ints(rng, -2, 2), "s": float(rng.choice([2.0, 3.0, 0.5, -2.0]))}


def _inverse_ok(p):
    if not _perpendicular(p["Q"], p["axis"]):
        return "the axis passes through the origin: the rotation has no translation row"
    return None


def _inverse_matrix(p):
    R, S = _inverse_parts(p)
    return transforms.compose(R, S)


def _inverse_statement(p) -> str:
    return (f"The map M first rotates by {fmt(p['angle'])} degrees about the line through Q = {fmt(p['Q'])} parallel "
            f"to the {_axis_name(p['axis'])} axis (counterclockwise looking down the axis), then scales uniformly by "
            f"s = {fmt(p['s'])} about the origin: M = R S = {_rows(_r(_inverse_matrix(p)))} (row convention). Give the "
            f"4x4 matrix of the inverse map M⁻¹ as four rows, the book's way: invert each factor (the rigid motion "
            f"R and the scaling S) and multiply the inverses (Goldman §13.3, §13.4).")


def _inverse_steps(p) -> str:
    R, S = _inverse_parts(p)
    R_inv = transforms.rigid_inverse(R)
    answer = _inverse_answers(p)[0]
    return (f"1. R = {_rows6(R)}: an orthogonal block R₀ and the row t = {_f6(R[3, :3])}.\n"
            f"2. R is rigid, so R⁻¹ has the block R₀ᵀ and the row -t R₀ᵀ = {_f6(R_inv[3, :3])}: "
            f"R⁻¹ = {_rows6(R_inv)}.\n"
            f"3. S scales by s = {fmt(p['s'])}, so S⁻¹ scales by 1/s = {fmt(1 / p['s'])}.\n"
            f"4. (R S)⁻¹ = S⁻¹ R⁻¹ (the reverse order: undo the last map first): the rows of R⁻¹'s block are "
            f"multiplied by 1/s, its last row stays: M⁻¹ = {_rows6(answer)}.\n"
            f"5. Check: M M⁻¹ = I.")


@DECK.exercise(stored=_STORED_INVERSE, generate=_inverse_generate, answer=lambda p: _inverse_answers(p)[0],
               slips=lambda p: _inverse_answers(p)[1], statement=_inverse_statement, steps=_inverse_steps,
               same=_same, well_posed=_inverse_ok)
def check_inverse_matrix(answer, p) -> Result:
    """Check the inverse of the statement's composite M = R S (Goldman §13.3, §13.4); recognises the
    inverses multiplied in the same order, the transposed 4x4 (right only for a rigid motion's block,
    and never for its translation), and the translation row only negated.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    expected, slips = _inverse_answers(p)
    M = _inverse_matrix(p)
    if _close(got, expected):
        return correct("(R S)⁻¹ = S⁻¹ R⁻¹: R⁻¹ has the transposed block and the row -t Rᵀ, and S⁻¹ divides the "
                       "block by s; M M⁻¹ = I.")
    if _close(got, slips["same order"]):
        return wrong("that is R⁻¹ S⁻¹, the inverses in the same order: the inverse of a product is the product of "
                     "the inverses in the reverse order, (R S)⁻¹ = S⁻¹ R⁻¹ (undo the last map first).")
    if _close(got, M.T):
        return wrong("that is the transpose of M: the transpose inverts only an orthogonal block (a rotation's), "
                     "not a scaling, and it moves the translation out of the last row. Invert R and S "
                     "separately.")
    if _close(got[:3, :3], expected[:3, :3]) and _close(got[3, :3], -M[3, :3]):
        return wrong("the block is right, but the translation row is not just -t: undoing [P 1] M = [P L + t 1] "
                     "gives P = (Q - t) L⁻¹, so the row is -t L⁻¹ (for a rigid motion, -t Rᵀ).")
    if _close(got[:3, :3], expected[:3, :3]):
        return _far(got[3, :3], expected[3, :3], "your translation row",
                    "invert R as a rigid motion (block Rᵀ, row -t Rᵀ), then multiply S⁻¹ R⁻¹")
    return _entry(got, expected, "your matrix", "invert each factor and multiply them in the reverse order, "
                                                "S⁻¹ R⁻¹; check that M M⁻¹ = I")


#: Deal another instance of an exercise (``deal("check_mirror_matrix")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_rotation_block": [
        [[0, 0, 1], [0, 1, 0], [-1, 0, 0]],          # transposed
        [[1, 0, 0], [0, 0, 1], [0, -1, 0]],          # about x
        [[0, 1, 0], [-1, 0, 0], [0, 0, 1]],          # about z
        [[math.cos(90), 0, -math.sin(90)], [0, 1, 0], [math.sin(90), 0, math.cos(90)]],   # 90 taken as radians
    ],
    "check_translation_row": [
        [1, 0, -3],          # Q L - Q
        [0, 0, 0],           # about the origin
        [1, 0, 2],           # Q
        [3, 0, 1],           # with the transposed block
    ],
    "check_mirror_matrix": [
        [[0, -1, 0, 2], [-1, 0, 0, 2], [0, 0, 1, 0], [0, 0, 0, 1]],               # transposed
        [[0.5, -0.5, 0, 0], [-0.5, 0.5, 0, 0], [0, 0, 1, 0], [1, 1, 0, 1]],       # projection
        [[-1, -2, 0, 0], [-2, -1, 0, 0], [0, 0, 1, 0], [4, 4, 0, 1]],             # unnormalised normal
        [[0, -1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [-2, -2, 0, 1]],             # wrong sign
        [[0, -1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],               # plane through the origin
    ],
    "check_composite_matrix": [
        [[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [1, 2, 0, 1]],                # R T: the wrong order
        [[0, -1, 0, -2], [1, 0, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]],               # transposed
        [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [2, -1, 0, 1]],               # clockwise
    ],
    "check_perspective_image": [
        [-10, -20, 0],       # no divide
        [-5, -10, 0],        # divided by -w
        [2, 4, -0.2],        # transposed
    ],
    "check_point_and_vector": [
        [[0, 0, 6], [0, 0, 6]],        # vector translated
        [[-2, 1, 3], [-2, 1, 3]],      # point not translated
        [[-2, 1, 3], [0, 0, 6]],       # swapped
        [[0, 0, 6], [1, 2, 3]],        # vector untouched
        [[4, -2, 6], [2, -1, 3]],      # column convention
    ],
    "check_frame_matrix": [
        [[0, -2, 0, 4], [1, 0, 0, -1], [0, -1, 2, 2], [0, 0, 0, 1]],                # transposed
        transforms.affine_from_points(FRAME_IMAGES, FRAME_SOURCES).tolist(),         # the inverse map
        [[0, 1, 0, 0], [-2, 0, -1, 0], [0, 0, 2, 0], [2, 0, 1, 1]],                 # row Q0
        [[0, 1, 0, 0], [-2, 0, -1, 0], [0, 0, 2, 0], [1, -1, 1, 1]],                # row Q0 - P0
        [[0, 1, 0, 0], [-2, 0, 1, 0], [0, 0, 2, 0], [4, -1, 0, 1]],                 # P_i - P0 taken as unit vectors
    ],
    "check_inverse_matrix": [
        [[0.5, 0, 0, 0], [0, 0, -0.5, 0], [0, 0.5, 0, 0], [0, 0, 1, 1]],            # the same order
        [[2, 0, 0, 0], [0, 0, -2, 4], [0, 2, 0, 0], [0, 0, 0, 1]],                  # M transposed
        [[0.5, 0, 0, 0], [0, 0, -0.5, 0], [0, 0.5, 0, 0], [0, -4, 0, 1]],           # translation only negated
    ],
}


# -- the programming project ------------------------------------------------------------------------

#: The project's tolerance: each image within PROJECT_TOL * max(1, |expected image|) of where it belongs.
PROJECT_TOL = 1e-6


def _homogeneous(points) -> np.ndarray:
    P = np.asarray(points, dtype=float)
    return np.c_[P, np.ones(len(P))]


def _frame_matrix(points) -> np.ndarray:
    """The 4x4 matrix whose rows are a_i [P_i 1], i < 4, with weights a_i making their sum [P_4 1]:
    it sends the standard frame (e_1, ..., e_4 and (1, 1, 1, 1)) to the five points."""
    H = _homogeneous(points)
    a = np.linalg.solve(H[:4].T, H[4])
    return a[:, None] * H[:4]


def _projective_reference(sources, images) -> np.ndarray:
    """The matrix of the projective map sending sources[i] to images[i] (row convention)."""
    return np.linalg.solve(_frame_matrix(sources), _frame_matrix(images))


def _general_position(points) -> bool:
    """No four of the five points (nearly) coplanar: every tetrahedron of four has a volume of at
    least 1% of the cube of its longest edge."""
    P = np.asarray(points, dtype=float)
    for skip in range(5):
        Q = np.delete(P, skip, axis=0)
        edges = Q[1:] - Q[0]
        size = max(np.linalg.norm(a - b) for a in Q for b in Q)
        if abs(np.linalg.det(edges)) < 0.06 * size ** 3:
            return False
    return True


class _Expected:
    """What a case expects: the test points (the five sources, then three more) and their images."""

    def __init__(self, points, images):
        self.points = points
        self.images = images


def _project_cases():
    """Seeded cases: (sources, images) in general position (no four of either coplanar), with three
    extra test points whose images are finite.  Kinds: random projective maps, an affine map, the
    identity, a map permuting five points, the standard frame as sources, large coordinates."""
    rng = np.random.default_rng(1313)
    specs = []

    def five(scale=2.0, shift=0.0):
        while True:
            P = np.round(rng.uniform(-scale, scale, (5, 3)) + shift, 1)
            if _general_position(P):
                return P

    def image_of(P, M):
        h = _homogeneous(P) @ M
        return h[:, :3] / h[:, 3:]

    def other_five(P, scale=2.0, shift=0.0):
        """Images in general position for which the map is not affine (five points in general position
        and any five images in general position determine one projective map)."""
        while True:
            R = five(scale, shift)
            if not np.allclose(_projective_reference(P, R)[:3, 3], 0, atol=1e-3):
                return R

    for _ in range(3):
        P = five()
        specs.append((P, other_five(P), "random projective maps"))
    P = five()
    A = np.eye(4)
    A[:3, :3] = np.round(rng.uniform(-2, 2, (3, 3)), 1)
    A[3, :3] = np.round(rng.uniform(-2, 2, 3), 1)
    specs.append((P, np.round(image_of(P, A), 6), "an affine map"))
    P = five()
    specs.append((P, P.copy(), "the identity"))
    P = five()
    specs.append((P, P[[1, 2, 3, 4, 0]], "a map permuting five points"))
    frame = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    specs.append((frame, other_five(frame), "the unit frame as sources"))
    P = five(scale=40.0, shift=100.0)
    specs.append((P, other_five(P, scale=30.0, shift=-60.0), "large coordinates"))

    cases, expected = [], {}
    for P, R, kind in specs:
        M = _projective_reference(P, R)
        extra = []
        while len(extra) < 3:
            X = np.round(rng.uniform(-1, 1, 3) * np.ptp(P, axis=0) + P.mean(axis=0), 1)
            h = np.r_[X, 1.0] @ M
            if np.linalg.norm(h[:3] / h[3] - R.mean(axis=0)) < 3 * np.ptp(R, axis=0).max():
                extra.append(X)
        pts = np.r_[P, np.array(extra)]
        h = _homogeneous(pts) @ M
        label = ("sources " + ", ".join(fmt(p) for p in P) + "; images " + ", ".join(fmt(r) for r in R))
        expected[label] = _Expected(pts, h[:, :3] / h[:, 3:])
        cases.append(Case(label, (P, R), kind=kind))
    return cases, expected


def _apply(M, pts):
    h = _homogeneous(pts) @ M
    return h, h[:, 3]


def _maps(M, pts, targets) -> np.ndarray:
    """Which of pts M sends (with the homogeneous divide) to targets, to the project's tolerance."""
    h, w = _apply(M, pts)
    ok = np.abs(w) > 1e-12 * np.maximum(1.0, np.abs(h[:, :3]).max(axis=1))
    out = np.zeros(len(pts), dtype=bool)
    img = h[ok, :3] / w[ok, None]
    tgt = np.asarray(targets, float)[ok]
    out[ok] = np.linalg.norm(img - tgt, axis=1) <= PROJECT_TOL * np.maximum(1.0, np.abs(tgt).max(axis=1))
    return out


def _compare_projective(got, expected, case):
    M = np.asarray(got, dtype=float)
    if M.shape != (4, 4):
        return f"it has shape {M.shape}; a 4x4 matrix is expected"
    if not np.all(np.isfinite(M)):
        return "it contains NaN or infinite entries"
    P, R = (np.asarray(a, float) for a in case.args)
    pts, exp = expected.points, expected.images
    good = _maps(M, pts, exp)
    if good.all():
        return None
    k = int(np.flatnonzero(~good)[0])
    which = f"source {k}" if k < 5 else f"the test point {fmt(pts[k])}"
    h, w = _apply(M, pts)
    if abs(w[k]) <= 1e-12 * max(1.0, np.abs(h[k, :3]).max()):
        msg = f"{which}, {fmt(pts[k])}, gets the homogeneous coordinate w = 0 (sent to infinity)"
    else:
        msg = f"{which}, {fmt(pts[k])}, goes to {fmt(h[k, :3] / w[k])} (after the divide by w)"
        msg += f"; it belongs at {fmt(exp[k])}" if k < 5 else "; it lies elsewhere under the map the five pairs fix"
    if np.all(_maps(M.T, pts, exp)):
        return msg + (" -- your matrix is transposed (the column convention): in the row convention the image of "
                      "P is the row [P 1] M, so row i of M is where the i-th coordinate goes")
    if np.all(_maps(M, R, P)):
        return msg + (" -- your matrix maps the images back to the sources: it is the inverse of the map asked for "
                      "(the rows built from the sources come first, on the left)")
    affine = np.allclose(M[:3, 3], 0, atol=1e-12 * np.abs(M).max()) and abs(M[3, 3]) > 0
    first_four = bool(_maps(M, P[:4], R[:4]).all())
    if affine and first_four:
        return msg + (" -- that is the affine map through the first four pairs (last column (0, 0, 0, 1)): it "
                      "ignores the fifth pair. A projective map sends [P_i 1] only to a multiple λ_i [R_i 1]; "
                      "the fifth pair is what fixes the four factors")
    if affine:
        return msg + (" -- your matrix is affine (last column (0, 0, 0, 1)), and no affine map sends these five "
                      "points to those five: a projective map needs a last column that makes w vary")
    if first_four:
        return msg + (" -- the first four sources go to the right images, the fifth does not: the factors of the "
                      "four rows are off. Write [P_4 1] as a combination of the first four rows [P_i 1], and "
                      "[R_4 1] as a combination of the [R_i 1], and use both sets of coefficients (solving "
                      "a H = [P_4 1] with the points as the rows of H is a solve with the transpose of H)")
    return msg


def check_projective_map_project(function) -> Result:
    """Run the learner's ``projective_map(sources, images)`` on seeded cases (random projective maps,
    an affine map, the identity, a map permuting five points, the unit frame as sources, large
    coordinates): the 4x4 matrix is applied in the row convention, with the homogeneous divide, to
    the five sources and three more points, and the images are compared with those of the one
    projective map the five pairs determine (to 1e-6 relative).  Any nonzero multiple of the right
    matrix passes; a list of lists is accepted as well as an array (our project, on §13.6.1).
    """
    cases, expected = _project_cases()

    def reference(sources, images):
        label = ("sources " + ", ".join(fmt(p) for p in sources) + "; images " + ", ".join(fmt(r) for r in images))
        return expected[label]

    return check_project(function, cases, reference=reference, compare=_compare_projective,
                         what="projective_map",
                         hint="the rows [P_i 1] of the first four sources, each scaled by a factor, must go to "
                              "the rows [R_i 1], each scaled by its factor; the fifth pair fixes the factors")


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
