"""Exercise checkers for chapter 6, fractals from iterated function systems (Goldman §6.1-6.4).

>>> print(PROBLEMS["check_fixed_point"])
Find the fixed point of the map w(P) = P/2 + (1, 0.5), i.e. the point with w(P) = P (Goldman §6.2).
>>> check_fixed_point([2, 1])
Correct: the fixed point of w is (2, 1).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine, ifs
from goldman_lib.exercises import (Result, check_number, correct, fmt, read_number, read_points, wrong)
from goldman_lib.fixed_point import hausdorff_distance

__all__ = ["PROBLEMS", "FIXED_POINT_MAP", "COUNT_LEVEL", "TREE_LEVEL", "SQUARE_MAP", "GASKET_CORNERS",
           "check_fixed_point", "check_gasket_count", "check_tree_branches", "check_square_image", "check_gasket_maps"]

#: Exercise 1: w(P) = P/2 + (1, 0.5).
FIXED_POINT_MAP = affine.scaling(0.5) @ affine.translation([1.0, 0.5])
#: Exercise 2: points of the Sierpinski gasket's deterministic algorithm at this level, from one point.
COUNT_LEVEL = 5
#: Exercise 3: trunk copies of the condensation tree at this level.
TREE_LEVEL = 4
#: Exercise 4: the map whose image of the unit square is asked for.
SQUARE_MAP = affine.from_parameters(angle=90, scale=(0.5, 0.5), translate=(1, 0))
#: Exercise 5: corners of the right-angled Sierpinski gasket to build an IFS for.
GASKET_CORNERS = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])

PROBLEMS = {
    "check_fixed_point": "Find the fixed point of the map w(P) = P/2 + (1, 0.5), i.e. the point with w(P) = P (Goldman §6.2).",
    "check_gasket_count": (f"The deterministic algorithm starts from one point and applies the three maps of the "
                           f"Sierpinski gasket {COUNT_LEVEL} times. How many points does it produce (Goldman §6.1)?"),
    "check_tree_branches": (f"The fractal tree has a trunk as condensation set and two maps; A_0 = trunk and "
                            f"A_(n+1) = trunk ∪ w_1(A_n) ∪ w_2(A_n). How many trunk copies (branches) does "
                            f"A_{TREE_LEVEL} hold (Goldman §6.4)?"),
    "check_square_image": ("The map M = from_parameters(angle=90, scale=(0.5, 0.5), translate=(1, 0)) scales by 1/2, "
                           "rotates by 90 degrees and then translates by (1, 0). Give the images of the unit square's "
                           "corners (0,0), (1,0), (1,1), (0,1), in that order (Goldman §6.1)."),
    "check_gasket_maps": ("Give an IFS (a list of 3x3 matrices, row-vector convention, translation in the last row) "
                          "whose attractor is the Sierpinski gasket with corners (0,0), (2,0), (0,2) (Goldman §6.3)."),
}


def check_fixed_point(answer) -> Result:
    """Check the fixed point of ``FIXED_POINT_MAP`` (Goldman §6.2): solve ``P = P/2 + (1, 0.5)``.

    Recognises the translation itself (one step from the origin instead of the limit).

    >>> check_fixed_point([1, 0.5])
    Not yet: (1, 0.5) is w(0, 0), one step from the origin; the fixed point is the limit of the iterates: solve P = P/2 + (1, 0.5).
    """
    what = "the fixed point of w"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} is one point [x, y]; yours has shape {got.shape}.")
    expected = affine.fixed_point(FIXED_POINT_MAP)
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"{what} is {fmt(expected)}.")
    if np.allclose(got, [1.0, 0.5], atol=1e-6):
        return wrong(f"{fmt(got)} is w(0, 0), one step from the origin; the fixed point is the limit of the "
                     f"iterates: solve P = P/2 + (1, 0.5).")
    image = affine.apply(got[None], FIXED_POINT_MAP)[0]
    return wrong(f"w{fmt(got)} = {fmt(image)}, not the same point; solve P = P/2 + (1, 0.5) for P.")


def check_gasket_count(answer) -> Result:
    """Check the number of points after ``COUNT_LEVEL`` levels of the gasket from one point: 3^level.

    >>> check_gasket_count(243)
    Correct: the number of points is 243.
    >>> check_gasket_count(15)
    Not yet: 15 = 3 x 5 adds the maps; each level applies all three maps to every point, so the count multiplies by 3: 3^5.
    """
    value, problem = read_number(answer, "the number of points")
    if problem is not None:
        return problem
    if value == 3 * COUNT_LEVEL:
        return wrong(f"{fmt(value)} = 3 x {COUNT_LEVEL} adds the maps; each level applies all three maps to every "
                     f"point, so the count multiplies by 3: 3^{COUNT_LEVEL}.")
    if value == sum(3 ** j for j in range(COUNT_LEVEL + 1)):
        return wrong(f"{fmt(value)} counts every level's points together; the algorithm keeps only the last level "
                     f"(no condensation set), 3^{COUNT_LEVEL}.")
    return check_number(value, 3 ** COUNT_LEVEL, what="the number of points", tol=0.5,
                        hint="each level applies each of the 3 maps to every point")


def check_tree_branches(answer) -> Result:
    """Check the number of trunk copies in ``A_TREE_LEVEL`` of the tree: 1 + 2 + ... + 2^level.

    >>> check_tree_branches(31)
    Correct: the number of branches is 31.
    >>> check_tree_branches(16)
    Not yet: 16 = 2^4 counts only the newest, smallest branches; the condensation set keeps every earlier level: 1 + 2 + 4 + ... + 2^4.
    """
    value, problem = read_number(answer, "the number of branches")
    if problem is not None:
        return problem
    if value == 2 ** TREE_LEVEL:
        return wrong(f"{fmt(value)} = 2^{TREE_LEVEL} counts only the newest, smallest branches; the condensation set "
                     f"keeps every earlier level: 1 + 2 + 4 + ... + 2^{TREE_LEVEL}.")
    if value == 2 ** (TREE_LEVEL + 1) - 2 or value == 2 ** TREE_LEVEL - 1:
        return wrong(f"{fmt(value)} is off by one level: A_0 is the trunk alone (1 branch) and A_{TREE_LEVEL} adds "
                     f"levels up to 2^{TREE_LEVEL}.")
    return check_number(value, 2 ** (TREE_LEVEL + 1) - 1, what="the number of branches", tol=0.5,
                        hint="level j adds 2^j copies of the trunk")


def check_square_image(answer) -> Result:
    """Check the images of the unit square's corners under ``SQUARE_MAP`` (Goldman §6.1).

    Recognises the rotation by -90 degrees (clockwise) and the translation applied before the rotation.

    >>> check_square_image([[1, 0], [1, 0.5], [0.5, 0.5], [0.5, 0]])
    Correct: the four image corners match.
    """
    what = "the four image corners"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    corners = ifs.UNIT_SQUARE[:4]
    expected = affine.apply(corners, SQUARE_MAP)
    if got.shape != (4, 2):
        return wrong(f"{what} should be four points [x, y]; yours have shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"{what} match.")
    clockwise = affine.apply(corners, affine.from_parameters(angle=-90, scale=(0.5, 0.5), translate=(1, 0)))
    if np.allclose(got, clockwise, atol=1e-6):
        return wrong("these corners are turned clockwise; a positive angle turns counterclockwise: (1, 0) -> (0, 1).")
    early = affine.apply(corners, affine.compose(affine.scaling(0.5), affine.translation([1, 0]), affine.rotation(90)))
    if np.allclose(got, early, atol=1e-6):
        return wrong("you translated before rotating; the translation comes last, after the scaling and rotation.")
    k = int(np.argmax(np.abs(got - expected).max(axis=1)))
    return wrong(f"corner {k} should be {fmt(expected[k])}, you gave {fmt(got[k])}: scale by 1/2, turn 90 degrees "
                 f"counterclockwise about the origin, then add (1, 0).")


def check_gasket_maps(answer) -> Result:
    """Check an IFS for the gasket with corners ``GASKET_CORNERS`` by its attractor (Goldman §6.3):
    any maps whose attractor is that gasket are right (in any order, with any symmetries).

    >>> from goldman_lib import affine
    >>> check_gasket_maps([affine.scaling(0.5, center=c) for c in GASKET_CORNERS])
    Correct: your IFS draws the gasket with corners (0, 0), (2, 0), (0, 2).
    """
    what = "your IFS"
    if answer is None or answer is Ellipsis:
        from goldman_lib.exercises import unanswered
        return unanswered("a list of three 3x3 matrices")
    try:
        s = ifs.IFS(answer)
    except (TypeError, ValueError) as exc:
        return wrong(f"{what} should be a list of 3x3 affine matrices (last column 0, 0, 1): {exc}")
    if not s.is_contractive():
        return wrong(f"{what} has a map that does not shrink (contraction factors {fmt(s.contraction_factors(), 3)}); "
                     f"the maps of the gasket scale by 1/2.")
    target = ifs.IFS([affine.scaling(0.5, center=c) for c in GASKET_CORNERS])
    A = ifs.deterministic(target, 7)
    B = ifs.chaos_game(s, 6000, rng=0)
    d = hausdorff_distance(A, B)
    corners = "(0, 0), (2, 0), (0, 2)"
    if d <= 0.05:
        return correct(f"{what} draws the gasket with corners {corners}.")
    if len(s) == 3 and np.allclose(s.fixed_points(), [[0, 0], [1, 0], [0, 1]], atol=1e-6):
        return wrong("your maps scale about (0,0), (1,0), (0,1): that is the gasket of the unit triangle; "
                     "scale by 1/2 about the corners (2, 0) and (0, 2) instead.")
    return wrong(f"the attractor of {what} is {fmt(d, 2)} (Hausdorff distance) from the gasket with corners {corners}; "
                 f"use three maps that scale by 1/2 about the three corners.")
