"""Exercise checkers for chapter 30, subdivision surfaces (Goldman §30.2-30.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> check_cube_counts([26, 48, 24])
Correct: after one level the cube has V, E, F = (26, 48, 24), and V - E + F = 2 still.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import subdivision_surfaces as ss
from goldman_lib.exercises import fmt_points, Result, check_points, correct, fmt, read_points, wrong

__all__ = ["PROBLEMS", "CHAIKIN_CTRL", "STENCIL_VALENCE", "EDGE_POINTS",
           "check_cube_counts", "check_quad_vertex_stencil", "check_cube_vertex_point",
           "check_triangle_edge_point", "check_chaikin"]

#: Exercise 2: the valence of the extraordinary vertex whose stencil is asked for.
STENCIL_VALENCE = 5
#: Exercise 4: the edge (v, w) and the opposite vertices x, y of its two triangles.
EDGE_POINTS = np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [2.0, 3.0, 1.0], [2.0, -3.0, 3.0]])
#: Exercise 5: the open control polygon refined by one level of split and average with degree 2.
CHAIKIN_CTRL = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]])


PROBLEMS = {
    "check_cube_counts": (
        "The cube has V = 8 vertices, E = 12 edges and F = 6 faces. After one level of centroid averaging "
        "(the quadrilateral scheme), how many vertices, edges and faces are there? Give [V, E, F] (Goldman §30.3)."),
    "check_quad_vertex_stencil": (
        f"A vertex v of valence n = {STENCIL_VALENCE} in a quadrilateral mesh moves, after one level of centroid "
        f"averaging, to a v + b (sum of its edge neighbours) + c (sum of its diagonal neighbours). "
        f"Give [a, b, c] (Goldman §30.3.2)."),
    "check_cube_vertex_point": (
        "Where does the cube's vertex (1, 1, 1) go after one level of quadrilateral centroid averaging? "
        "Give the point [x, y, z] (Goldman §30.3.2)."),
    "check_triangle_edge_point": (
        f"An edge of a triangle mesh runs from v = {fmt(EDGE_POINTS[0])} to w = {fmt(EDGE_POINTS[1])}; its two "
        f"triangles have opposite vertices x = {fmt(EDGE_POINTS[2])} and y = {fmt(EDGE_POINTS[3])}. Where is the new "
        f"edge point after one level of the triangle scheme (weights 1/4, 3/8, 3/8)? (Goldman §30.4.2)"),
    "check_chaikin": (
        f"Apply one level of split and average with degree 2 to the open polygon {fmt_points(CHAIKIN_CTRL)}: split "
        f"(double every point), then average twice. Give the new control points (Goldman §30.2)."),
}


def check_cube_counts(answer) -> Result:
    """Check [V, E, F] of the cube after one level of the quadrilateral scheme (Goldman §30.3).

    Recognises the triangle scheme's counts, the counts without face points, and an answer whose
    V - E + F is not 2.

    >>> check_cube_counts([20, 48, 24])
    Not yet: V should be 8 old vertices + 12 edge points + 6 face points = 26; you left out the face points.
    """
    what = "[V, E, F]"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} should be three numbers; yours has shape {got.shape}.")
    V, E, F = (int(round(x)) for x in got)
    m = ss.centroid_averaging(ss.cube(), 1)
    expected = (m.n_vertices, m.n_edges, m.n_faces)
    if (V, E, F) == expected and np.allclose(got, expected):
        return correct(f"after one level the cube has V, E, F = {expected}, and V - E + F = 2 still.")
    if V == 8 + 12:
        return wrong("V should be 8 old vertices + 12 edge points + 6 face points = 26; you left out the face points.")
    tri = ss.centroid_averaging(ss.triangulate(ss.cube()), 1)
    if (V, E, F) == (tri.n_vertices, tri.n_edges, tri.n_faces):
        return wrong("those are the counts of the triangle scheme on the triangulated cube; the quadrilateral "
                     "scheme splits each of the 6 squares into 4 squares.")
    parts = []
    if V != expected[0]:
        parts.append("V = 8 old vertices + 12 edge points + 6 face points")
    if F != expected[2]:
        parts.append("F = 4 quadrilaterals for each of the 6 faces")
    if E != expected[1]:
        parts.append("E = 2 halves of each of the 12 edges + 4 new edges inside each of the 6 faces")
    euler = V - E + F
    note = f" Your V - E + F = {euler}, but subdivision never changes it from 2." if euler != 2 else ""
    return wrong("count again: " + "; ".join(parts) + "." + note)


def check_quad_vertex_stencil(answer) -> Result:
    """Check the weights [a, b, c] of the quadrilateral vertex stencil at valence ``STENCIL_VALENCE``
    (Goldman §30.3.2).  Recognises the valence-4 weights and weights that do not sum to one.

    >>> check_quad_vertex_stencil([9 / 16, 3 / 40, 1 / 80])
    Correct: [a, b, c] = [9/16, 3/(8n), 1/(16n)] = (0.5625, 0.075, 0.0125) for n = 5.
    >>> check_quad_vertex_stencil([9 / 16, 3 / 32, 1 / 64])
    Not yet: these are the weights of a regular vertex (n = 4); with n = 5 neighbours of each kind the 7/16 left over is shared by 5, not 4.
    """
    n = STENCIL_VALENCE
    got, err = read_points(answer, "[a, b, c]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"[a, b, c] should be three numbers; yours has shape {got.shape}.")
    expected = np.array(ss.quad_vertex_stencil(n))
    if np.allclose(got, expected, atol=1e-9):
        return correct(f"[a, b, c] = [9/16, 3/(8n), 1/(16n)] = {fmt(expected)} for n = {n}.")
    if np.allclose(got, ss.quad_vertex_stencil(4), atol=1e-9):
        return wrong(f"these are the weights of a regular vertex (n = 4); with n = {n} neighbours of each kind "
                     f"the 7/16 left over is shared by {n}, not 4.")
    total = got[0] + n * got[1] + n * got[2]
    if abs(total - 1) > 1e-9:
        return wrong(f"the weights must sum to one over the vertex and its {2 * n} neighbours "
                     f"(a + {n} b + {n} c = 1); yours sum to {fmt(total)}.")
    return wrong(f"[a, b, c] should be {fmt(expected)}: average the centroids of the {n} quadrilaterals "
                 f"(v, m_i, F_i, m_(i+1)) around v after the bilinear split.")


def check_cube_vertex_point(answer) -> Result:
    """Check the image of the cube's vertex (1, 1, 1) after one level of the quad scheme (Goldman §30.3.2).

    Recognises Catmull-Clark's vertex point (a different rule at valence 3) and the valence-4 stencil.

    >>> check_cube_vertex_point([2 / 3, 2 / 3, 2 / 3])
    Correct: (1, 1, 1) goes to (0.6667, 0.6667, 0.6667) = 9/16 v + 1/8 (sum of 3 neighbours) + 1/48 (sum of 3 diagonals).
    >>> check_cube_vertex_point([5 / 9, 5 / 9, 5 / 9])
    Not yet: (0.5556, 0.5556, 0.5556) is the Catmull-Clark vertex point; centroid averaging agrees with Catmull-Clark only at valence 4. Use 9/16, 3/(8n), 1/(16n) with n = 3.
    """
    got, err = read_points(answer, "your point", ask="the new vertex as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"the new vertex should be one point [x, y, z]; yours has shape {got.shape}.")
    expected = np.full(3, 2 / 3)
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"(1, 1, 1) goes to {fmt(expected)} = 9/16 v + 1/8 (sum of 3 neighbours) + 1/48 (sum of 3 diagonals).")
    if np.allclose(got, 5 / 9, atol=1e-6):
        return wrong(f"{fmt(got)} is the Catmull-Clark vertex point; centroid averaging agrees with Catmull-Clark "
                     f"only at valence 4. Use 9/16, 3/(8n), 1/(16n) with n = 3.")
    if np.allclose(got, 41 / 64, atol=1e-6):
        return wrong("you used the valence-4 weights 3/32 and 1/64; the cube's vertices have valence 3, so "
                     "b = 3/24 and c = 1/48.")
    return check_points(got, expected, what="the new vertex", tol=1e-6,
                        hint="neighbours sum to (1, 1, 1), diagonal neighbours to (-1, -1, -1)")


def check_triangle_edge_point(answer) -> Result:
    """Check the new edge point of the triangle scheme for ``EDGE_POINTS`` (Goldman §30.4.2).

    Recognises the plain midpoint (no averaging) and the plain-centroid weights 7/18, 1/9.

    >>> check_triangle_edge_point([2, 0, 0.5])
    Correct: the edge point is 3/8 (v + w) + 1/8 (x + y) = (2, 0, 0.5).
    >>> check_triangle_edge_point([2, 0, 0])
    Not yet: (2, 0, 0) is the midpoint of the edge, the split alone; the averaging step then pulls it towards the opposite vertices: 3/8 (v + w) + 1/8 (x + y).
    """
    got, err = read_points(answer, "your point", ask="the edge point as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"the edge point should be one point [x, y, z]; yours has shape {got.shape}.")
    v, w, x, y = EDGE_POINTS
    a, b = ss.triangle_edge_stencil()
    expected = a * (v + w) + b * (x + y)
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"the edge point is 3/8 (v + w) + 1/8 (x + y) = {fmt(expected)}.")
    if np.allclose(got, (v + w) / 2, atol=1e-6):
        return wrong(f"{fmt(got)} is the midpoint of the edge, the split alone; the averaging step then pulls it "
                     f"towards the opposite vertices: 3/8 (v + w) + 1/8 (x + y).")
    pa, pb = ss.triangle_edge_stencil(1 / 3)
    if np.allclose(got, pa * (v + w) + pb * (x + y), atol=1e-6):
        return wrong("these are the weights 7/18, 1/9 of plain centroids; the scheme here weights each corner "
                     "1/4 itself and 3/8 the other two, giving 3/8 and 1/8.")
    return check_points(got, expected, what="the edge point", tol=1e-6, hint="3/8 (v + w) + 1/8 (x + y)")


def check_chaikin(answer) -> Result:
    """Check one level of degree-2 split and average on ``CHAIKIN_CTRL`` (Goldman §30.2).

    Recognises a single averaging (degree 1) and the split alone.

    >>> check_chaikin([[1, 0], [3, 0], [4, 1], [4, 3]])
    Correct: split and average with degree 2 cuts every corner at 1/4 and 3/4 (Chaikin): the points match.
    >>> check_chaikin([[0, 0], [2, 0], [4, 0], [4, 2], [4, 4]])
    Not yet: you averaged once (degree 1: the midpoints are added and the polygon is unchanged); degree 2 averages twice.
    """
    got, err = read_points(answer, "your points")
    if err is not None:
        return err
    expected = ss.split_and_average(CHAIKIN_CTRL, 2, 1)
    if got.shape == expected.shape and np.allclose(got, expected, atol=1e-6):
        return correct("split and average with degree 2 cuts every corner at 1/4 and 3/4 (Chaikin): the points match.")
    once = ss.split_and_average(CHAIKIN_CTRL, 1, 1)
    if got.shape == once.shape and np.allclose(got, once, atol=1e-6):
        return wrong("you averaged once (degree 1: the midpoints are added and the polygon is unchanged); degree 2 "
                     "averages twice.")
    split = np.repeat(CHAIKIN_CTRL, 2, axis=0)
    if got.shape == split.shape and np.allclose(got, split, atol=1e-6):
        return wrong("that is the split alone; now average twice, each time replacing the polygon by the "
                     "midpoints of its legs.")
    if got.ndim != 2 or got.shape[-1] != 2 or len(got) != len(expected):
        return wrong(f"there should be {len(expected)} points [x, y]: the split gives {2 * len(CHAIKIN_CTRL)}, "
                     f"and each of the two averagings of an open polygon drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what="the new control points", tol=1e-6,
                        hint="each new point is 3/4 of one old point plus 1/4 of its neighbour")
