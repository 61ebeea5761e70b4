"""Exercise checkers for chapter 13, the 4x4 matrices of the transformations of chapter 12 in the
row convention ``[P 1] @ M`` (Goldman §13.1-13.6), and the checker of the chapter's programming
project (the projective map through five points).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  Hand-computed decimals are
accepted to a relative 1e-4.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import transforms
from goldman_lib.exercises import far_off, guard_checkers, off_by
from goldman_lib.exercises import Result, correct, fmt, read_points, wrong
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "ROT_AXIS", "ROT_ANGLE", "ROT_POINT", "MIRROR_PLANE_POINT", "MIRROR_NORMAL",
           "COMPOSE_SHIFT", "COMPOSE_ANGLE", "PERSP_EYE", "PERSP_PLANE_POINT", "PERSP_NORMAL", "PERSP_POINT",
           "AFFINE_MATRIX", "AFFINE_COORDS", "check_rotation_block", "check_translation_row", "check_mirror_matrix",
           "check_composite_matrix", "check_perspective_image", "check_point_and_vector",
           "check_projective_map_project"]

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

REL_TOL = 1e-4


def _rows(M) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(x) for x in row) + "]" for row in np.asarray(M, float)) + "]"


PROBLEMS = {
    "check_rotation_block": (
        f"Give the upper-left 3x3 block L of the 4x4 matrix of the rotation by {fmt(ROT_ANGLE)} degrees about the "
        f"y axis (direction {fmt(ROT_AXIS)}, through the origin; counterclockwise looking down the axis), in the "
        f"row convention [P 1] M: row i of L is the image of the i-th unit vector. Give [[...], [...], [...]] "
        f"(Goldman §13.3)."),
    "check_translation_row": (
        f"Now rotate by the same {fmt(ROT_ANGLE)} degrees about the line through Q = {fmt(ROT_POINT)} parallel to "
        f"the y axis. The 4x4 matrix keeps the block L of the previous exercise; give its last row's first three "
        f"entries, the translation row [a, b, c] (Goldman §13.3)."),
    "check_mirror_matrix": (
        f"Give the 4x4 matrix (row convention, [P 1] M) of the mirror in the plane through Q = "
        f"{fmt(MIRROR_PLANE_POINT)} with normal N = {fmt(MIRROR_NORMAL)} (the plane x + y = 2), as four rows "
        f"(Goldman §13.3)."),
    "check_composite_matrix": (
        f"Give the 4x4 matrix (row convention) of the map that first translates by {fmt(COMPOSE_SHIFT)} and then "
        f"rotates by {fmt(COMPOSE_ANGLE)} degrees about the z axis (through the origin), as four rows "
        f"(Goldman §13.3; composition)."),
    "check_perspective_image": (
        f"The perspective projection from the eye E = {fmt(PERSP_EYE)} onto the plane z = 0 has the 4x4 matrix "
        f"M = {_rows(transforms.perspective(PERSP_EYE, PERSP_PLANE_POINT, PERSP_NORMAL))} in the row "
        f"convention. Apply it to P = {fmt(PERSP_POINT)} and give the image point [x, y, z] (Goldman §13.6.2)."),
    "check_point_and_vector": (
        f"The affine map with the 4x4 matrix M = {_rows(AFFINE_MATRIX)} (row convention) is applied to the "
        f"coordinates {fmt(AFFINE_COORDS)}, once read as a point P and once as a vector v. Give "
        f"[[image of P], [image of v]] (Goldman §13.1)."),
}


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


def _entry(got, expected, name, hint) -> Result:
    bad = np.argwhere(np.abs(got - expected) > REL_TOL * np.maximum(1.0, np.abs(expected)))
    i, j = (int(x) for x in bad[0])
    return wrong(f"the entry in row {i}, column {j} of {name} is {off_by(got[i, j], expected[i, j])} "
                 f"({len(bad)} entries are off); {hint}.")


def _far(got, expected, what, hint) -> Result:
    return wrong(f"{what} is {far_off(got, expected)} from where it should be; {hint}.")


# -- §13.3.2 rotation -----------------------------------------------------------------------------------------

def _rotation():
    return transforms.rotation(ROT_AXIS, ROT_ANGLE, point=ROT_POINT)


def check_rotation_block(answer) -> Result:
    """Check the 3x3 block of the rotation by 90° about the y axis (Goldman §13.3); recognises the
    transpose (column convention, which is also the rotation the other way) and the rotation about
    another axis.
    """
    got, err = _read(answer, "the 3x3 block as [[...], [...], [...]]", (3, 3), "your block")
    if err is not None:
        return err
    L = _rotation()[:3, :3]
    if _close(got, L):
        return correct("row i is the image of the i-th unit vector: x goes to -z, y stays, z goes to x.")
    if _close(got, L.T):
        return wrong("that is the transpose: the column convention (M P with P a column), which in the row "
                     "convention is the rotation the other way. With [P 1] M, row i of L is the image of the "
                     "i-th unit vector; turn (1, 0, 0) by w × v with w = (0, 1, 0).")
    for other in ([1, 0, 0], [0, 0, 1]):
        for sign in (1, -1):
            if _close(got, transforms.rotation(other, sign * ROT_ANGLE)[:3, :3]):
                return wrong("that rotates about another coordinate axis: the y axis is the one whose row stays "
                             "(0, 1, 0).")
    if _close(got, transforms.rotation(ROT_AXIS, math.degrees(ROT_ANGLE))[:3, :3]):
        return wrong("you took cos and sin of 90 as if it were radians: the angle is in degrees (np.cos and math.cos "
                     "take radians; convert with np.radians first, cos 90° = 0).")
    if np.isclose(abs(np.linalg.det(got)), 1, atol=1e-3) and not np.allclose(got @ got.T, np.eye(3), atol=1e-3):
        return wrong("the rows of a rotation block are perpendicular unit vectors; yours are not.")
    return _entry(got, L, "your block", "apply Rodrigues' formula (§12.3) to (1, 0, 0), (0, 1, 0), (0, 0, 1) and "
                                        "write the images as rows")


def check_translation_row(answer) -> Result:
    """Check the translation row of the rotation about the line through ``ROT_POINT`` (Goldman §13.3);
    recognises Q L - Q (sign), Q itself, zero (the rotation about the origin), the row made with the
    transposed block, and -Q.

    >>> check_translation_row([3, 0, 1])
    Not yet: that row was made with the transposed block (the column convention): use Q - Q L with the L of [P 1] M.
    """
    got, err = _read(answer, "the translation row as [a, b, c]", (3,), "your row")
    if err is not None:
        return err
    M = _rotation()
    L, Q = M[:3, :3], ROT_POINT
    expected = M[3, :3]
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

def check_mirror_matrix(answer) -> Result:
    """Check the 4x4 mirror matrix in the plane x + y = 2 (Goldman §13.3); recognises the projection
    (factor 1), the unnormalised normal, the transposed matrix (translation in the last column),
    the wrong sign of the translation row, and the mirror in the plane through the origin.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    Q, N = MIRROR_PLANE_POINT, MIRROR_NORMAL
    M = transforms.mirror(Q, N)
    if _close(got, M):
        return correct("the block is I - 2 nᵀn with n = (1, 1, 0)/√2 (it swaps x and y with a sign), and the "
                       "translation row is 2 (Q·n) n.")
    if _close(got, M.T):
        return wrong("that is the transpose, the column convention: in the row convention [P 1] M the "
                     "translation goes in the last row and the last column is (0, 0, 0, 1).")
    if _close(got, transforms.orthogonal_projection(Q, N)):
        return wrong("that is the orthogonal projection onto the plane (factor 1): the mirror goes twice as "
                     "far, I - 2 nᵀn and the row 2 (Q·n) n.")
    raw = np.eye(4)
    raw[:3, :3] = np.eye(3) - 2 * np.outer(N, N)
    raw[3, :3] = Q - Q @ raw[:3, :3]
    if _close(got[:3, :3], raw[:3, :3]):
        return wrong("the normal (1, 1, 0) has length √2: I - 2 NᵀN needs the unit normal n = N/|N|.")
    if _close(got[:3, :3], M[:3, :3]) and _close(got[3, :3], -M[3, :3]):
        return wrong("the block is right but the translation row has the wrong sign: a point Q of the plane "
                     "must stay fixed, Q (I - 2 nᵀn) + t = Q.")
    if _close(got, transforms.mirror([0, 0, 0], N)):
        return wrong("that is the mirror in the parallel plane x + y = 0 through the origin: the plane x + y = 2 "
                     "needs the translation row 2 (Q·n) n.")
    return _entry(got, M, "your matrix", "the block is I - 2 nᵀn for the unit normal, the last row "
                                         "(2 (Q·n) n, 1), the last column (0, 0, 0, 1)")


# -- composition (our formulation: the book has no section on it) ----------------------------------------------

def _parts():
    return transforms.translation(COMPOSE_SHIFT), transforms.rotation([0, 0, 1], COMPOSE_ANGLE)


def check_composite_matrix(answer) -> Result:
    """Check the matrix of "first translate, then rotate" (Goldman §13.3, composed); recognises the wrong order,
    the transposed matrix (column convention) and the rotation the other way.
    """
    got, err = _read(answer, "the 4x4 matrix as four rows", (4, 4), "your matrix")
    if err is not None:
        return err
    T, R = _parts()
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
    if _close(got, T @ transforms.rotation([0, 0, 1], -COMPOSE_ANGLE)):
        return wrong("that rotates clockwise: 90 degrees about z takes (1, 0, 0) to (0, 1, 0), so the first row "
                     "of the rotation block is (0, 1, 0).")
    return _entry(got, M, "your matrix", "multiply the translation matrix by the rotation matrix, in that order")


# -- §13.6.2 perspective -------------------------------------------------------------------------------------------

def _perspective():
    return transforms.perspective(PERSP_EYE, PERSP_PLANE_POINT, PERSP_NORMAL)


def check_perspective_image(answer) -> Result:
    """Check the image of ``PERSP_POINT`` under the perspective matrix (Goldman §13.6.2); recognises
    the homogeneous divide left out, the transposed matrix, and the divide by -w.

    >>> check_perspective_image([-10, -20, 0])
    Not yet: those are the first three homogeneous coordinates of [P 1] M; the point is what you get after dividing them by the fourth, w.
    """
    got, err = _read(answer, "the image as [x, y, z]", (3,), "your point")
    if err is not None:
        return err
    M, P = _perspective(), PERSP_POINT
    expected = transforms.apply(P[None], M)[0]
    h = transforms.homogeneous(P[None], M)[0]
    if _close(got, expected):
        return correct(f"[P 1] M = {fmt(h)}; dividing by w = {fmt(h[3])} gives a point of the plane z = 0 on the "
                       f"line from E through P.")
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

def check_point_and_vector(answer) -> Result:
    """Check the images of the same coordinates read as a point and as a vector (Goldman §13.1);
    recognises a translated vector, an untouched vector, the two answers swapped and the block
    transposed.

    >>> check_point_and_vector([[0, 0, 6], [0, 0, 6]])
    Not yet: your vector was translated: a vector has homogeneous coordinate 0, [v 0] M, so the last row of M does not act on it.
    """
    got, err = _read(answer, "[[image of P], [image of v]]", (2, 3), "your answer")
    if err is not None:
        return err
    M, c = AFFINE_MATRIX, AFFINE_COORDS
    point = transforms.apply(c[None], M)[0]
    vector = transforms.apply_to_vectors(c[None], M)[0]
    expected = np.stack([point, vector])
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
