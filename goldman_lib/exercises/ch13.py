"""Exercise checkers for chapter 13, the 4x4 matrices of the transformations of chapter 12 in the
row convention ``[P 1] @ M`` (Goldman §13.1-13.6), and the checker of the chapter's programming
project (a perspective matrix).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  Hand-computed decimals are
accepted to a relative 1e-4.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import transforms
from goldman_lib.exercises import far_off, guard_checkers, off_by
from goldman_lib.exercises import Result, correct, fmt, read_points, wrong
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "ROT_AXIS", "ROT_ANGLE", "ROT_POINT", "MIRROR_PLANE_POINT", "MIRROR_NORMAL",
           "COMPOSE_SHIFT", "COMPOSE_ANGLE", "PERSP_EYE", "PERSP_PLANE_POINT", "PERSP_NORMAL", "PERSP_POINT",
           "AFFINE_MATRIX", "AFFINE_COORDS", "check_rotation_block", "check_translation_row", "check_mirror_matrix",
           "check_composite_matrix", "check_perspective_image", "check_point_and_vector",
           "check_perspective_matrix_project"]

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
        f"(Goldman §13.6)."),
    "check_perspective_image": (
        f"The perspective projection from the eye E = {fmt(PERSP_EYE)} onto the plane z = 0 has the 4x4 matrix "
        f"M = {_rows(transforms.perspective(PERSP_EYE, PERSP_PLANE_POINT, PERSP_NORMAL))} in the row "
        f"convention. Apply it to P = {fmt(PERSP_POINT)} and give the image point [x, y, z] (Goldman §13.5)."),
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


# -- §13.3 rotation -------------------------------------------------------------------------------------------

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


# -- §13.3 mirror ---------------------------------------------------------------------------------------------

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


# -- §13.6 composition ------------------------------------------------------------------------------------------

def _parts():
    return transforms.translation(COMPOSE_SHIFT), transforms.rotation([0, 0, 1], COMPOSE_ANGLE)


def check_composite_matrix(answer) -> Result:
    """Check the matrix of "first translate, then rotate" (Goldman §13.6); recognises the wrong order,
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


# -- §13.5 perspective ---------------------------------------------------------------------------------------------

def _perspective():
    return transforms.perspective(PERSP_EYE, PERSP_PLANE_POINT, PERSP_NORMAL)


def check_perspective_image(answer) -> Result:
    """Check the image of ``PERSP_POINT`` under the perspective matrix (Goldman §13.5); recognises
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

class _Expected:
    """What a case expects: the test points and their images by :func:`transforms.project_perspective`."""

    def __init__(self, eye, plane_point, normal, points):
        self.points = points
        self.images = transforms.project_perspective(points, eye, plane_point, normal)


def _case_points(rng, eye, plane_point, normal, count=6):
    """Points on both sides of the screen, none near the plane through the eye parallel to it."""
    n = normal / np.linalg.norm(normal)
    depth = float((plane_point - eye) @ n)
    pts = []
    while len(pts) < count:
        p = plane_point + rng.uniform(-3, 3, 3)
        if abs(float((p - eye) @ n)) > 0.2 * max(1.0, abs(depth)) and abs(float((p - eye) @ n)) > 0.3:
            pts.append(p)
    return np.round(np.array(pts), 2)


def _project_cases():
    rng = np.random.default_rng(1313)
    specs = []
    # unit normals with rational coordinates (a, b, c)/d, a² + b² + c² = d², in random order and signs
    quadruples = np.array([[1, 2, 2, 3], [2, 3, 6, 7], [1, 4, 8, 9], [2, 6, 9, 11]], dtype=float)
    for a, b, c, d in quadruples:
        n = rng.permutation([a, b, c]) * rng.choice([-1.0, 1.0], size=3) / d
        Q = np.round(rng.uniform(-2, 2, 3), 2)
        E = np.round(Q + rng.uniform(2, 5) * n + rng.uniform(-1, 1, 3), 2)
        specs.append((E, Q, n, "random eyes and planes"))
    specs.append((np.array([1.0, -2.0, 6.0]), np.array([0.5, 0.0, 1.0]), np.array([0.0, 0.0, 3.7]),
                  "an unnormalised normal"))
    specs.append((np.array([0.0, 0.0, 1000.0]), np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]),
                  "the eye far away"))
    specs.append((np.array([2.0, 1.0, -3.0]), np.array([0.0, 0.0, 0.0]), np.array([0.6, 0.0, 0.8]),
                  "a plane through the origin"))
    specs.append((np.array([-1.0, 0.5, 0.0]), np.array([1.0, 1.0, 1.0]), np.array([2.0, 3.0, 6.0]) / 7,
                  "a plane not perpendicular to an axis"))
    specs.append((np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0]),
                  "the eye at the origin, the plane z = 1"))
    cases, points = [], {}
    for E, Q, N, kind in specs:
        label = f"eye {fmt(E)}, plane through {fmt(Q)} with normal {fmt(N)}"
        points[label] = _case_points(rng, E, Q, N)
        cases.append(Case(label, (E, Q, N), kind=kind))
    return cases, points


def _compare_matrix(points):
    def compare(got, expected, case):
        M = np.asarray(got, dtype=float)
        if M.shape != (4, 4):
            return f"it has shape {M.shape}; a 4x4 matrix is expected"
        if not np.all(np.isfinite(M)):
            return "it contains NaN or infinite entries"
        P = expected.points
        h = np.c_[P, np.ones(len(P))] @ M
        w = h[:, 3]
        tiny = np.abs(w) <= 1e-12 * np.maximum(1.0, np.abs(h[:, :3]).max(axis=1))
        if np.any(tiny):
            k = int(np.flatnonzero(tiny)[0])
            why = (" Your last column is (0, 0, 0, 0): it must hold the normal and -E·N so that w = (P - E)·N."
                   if np.allclose(M[:, 3], 0) else "")
            return (f"the point {fmt(P[k])} gets the homogeneous coordinate w = 0 with your matrix (sent to "
                    f"infinity), but its line of sight does meet the plane.{why}")
        images = h[:, :3] / w[:, None]
        exp = expected.images
        err = np.linalg.norm(images - exp, axis=1)
        bad = np.flatnonzero(err > 1e-6 * np.maximum(1.0, np.abs(exp).max(axis=1)))
        if bad.size == 0:
            return None
        k = int(bad[0])
        msg = (f"the point {fmt(P[k])} goes to {fmt(images[k])} with your matrix (after the divide by "
               f"w = {fmt(w[k])}), expected {fmt(exp[k])}")
        ht = np.c_[P, np.ones(len(P))] @ M.T
        if np.all(np.abs(ht[:, 3]) > 1e-12) and np.allclose(ht[:, :3] / ht[:, 3:], exp, rtol=1e-6, atol=1e-6):
            return msg + (" -- is the matrix transposed (the column convention)? With [P 1] M the normal N goes in "
                          "the last column and -(Q·N) E in the last row")
        if np.allclose(M[:3, 3], 0):
            return msg + (" -- your last column is (0, 0, 0, w): that matrix is affine, and the homogeneous divide "
                          "then divides by a constant; a perspective matrix puts N in the last column so that "
                          "w = (P - E)·N")
        if not np.isclose(np.linalg.norm(case.args[2]), 1.0):
            return msg + (" -- the normal is not a unit vector here: use the same N in every entry (normalise it "
                          "first, or nowhere)")
        return msg + (" -- did you divide by the homogeneous coordinate? Compare your entries with "
                      "[[c I + Nᵀ E, Nᵀ], [-(Q·N) E, -E·N]], c = (Q - E)·N")

    return compare


def check_perspective_matrix_project(function) -> Result:
    """Run the learner's ``perspective_matrix(eye, plane_point, normal)`` on seeded cases (random
    eyes and planes, an unnormalised normal, a far eye, a plane through the origin, a plane not
    perpendicular to an axis, the classic eye at the origin): each matrix is applied with the
    homogeneous divide to six points and compared with :func:`goldman_lib.transforms.project_perspective`.
    Matrices that differ by a nonzero factor give the same images and pass.
    """
    cases, points = _project_cases()

    def reference(eye, plane_point, normal):
        return _Expected(eye, plane_point, normal, points[f"eye {fmt(eye)}, plane through {fmt(plane_point)} "
                                                          f"with normal {fmt(normal)}"])

    return check_project(function, cases, reference=reference, compare=_compare_matrix(points),
                         what="perspective_matrix",
                         hint="the image of P is E + [(Q - E)·N / (P - E)·N] (P - E); multiply through by "
                              "(P - E)·N, the homogeneous coordinate")


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
