"""Corpus of the chapter-13 project (the projective map through five points): correct solutions
written from the statement alone, by other methods than the checker's (a null vector of the 15
linear conditions, a composition through the standard frame with Cramer's rule, the frame weights),
must be accepted; realistic wrong ones must be rejected with their slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch13


def _rows(points):
    return np.c_[np.asarray(points, dtype=float), np.ones(len(points))]


# -- accepted ------------------------------------------------------------------------------------------

def weights_solution(sources, images):
    """[P_4 1] = sum a_i [P_i 1], [R_4 1] = sum b_i [R_i 1]; M sends a_i [P_i 1] to b_i [R_i 1]."""
    HP, HR = _rows(sources), _rows(images)
    a = np.linalg.solve(HP[:4].T, HP[4])
    b = np.linalg.solve(HR[:4].T, HR[4])
    return np.linalg.solve(a[:, None] * HP[:4], b[:, None] * HR[:4])


def null_vector_solution(sources, images):
    """The direct linear transform: [P 1] M = λ [R 1] gives ([P 1]·M_k) - R_k ([P 1]·M_3) = 0 for
    k = 0, 1, 2: 15 equations in the 16 entries; M is the null vector (last right singular vector).
    Returned as a list of lists."""
    rows = []
    for P, R in zip(sources, images):
        h = list(P) + [1.0]
        for k in range(3):
            eq = [0.0] * 16
            for i in range(4):
                eq[4 * i + k] += h[i]          # entry M[i][k]
                eq[4 * i + 3] -= R[k] * h[i]   # entry M[i][3]
            rows.append(eq)
    _, _, vt = np.linalg.svd(np.array(rows))
    m = vt[-1].reshape(4, 4)
    return (-7.0 * m).tolist()


def _cramer(A, b):
    A = np.array(A, dtype=float)
    d = np.linalg.det(A)
    out = []
    for i in range(len(b)):
        Ai = A.copy()
        Ai[:, i] = b
        out.append(np.linalg.det(Ai) / d)
    return np.array(out)


def frame_solution(sources, images):
    """Through the standard frame: T_X sends e_0..e_3, (1, 1, 1, 1) to the five points X (rows
    c_i [X_i 1], the c_i by Cramer's rule); M = T_P^-1 T_R, with an explicit inverse, times 0.01."""
    def T(points):
        H = _rows(points)
        c = _cramer(H[:4].T, H[4])
        return np.diag(c) @ H[:4]
    return 0.01 * np.linalg.inv(T(sources)) @ T(images)


ACCEPTED = [weights_solution, null_vector_solution, frame_solution]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch13.check_projective_map_project(solution)
    assert r.correct, r.message
    assert "8 cases" in r.message


def test_the_accepted_solutions_agree_up_to_a_factor():
    P = np.array([[0, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 3], [1, 1, 1]], dtype=float)
    R = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1], [0.5, 0.2, 0.1]])
    Ms = [np.asarray(f(P, R), float) for f in ACCEPTED]
    for M in Ms[1:]:
        k = np.argmax(np.abs(Ms[0]))
        assert np.allclose(M * (Ms[0].flat[k] / M.flat[k]), Ms[0], atol=1e-9)


# -- rejected ------------------------------------------------------------------------------------------

def transposed(sources, images):                   # the column convention
    return weights_solution(sources, images).T


def inverse_map(sources, images):                  # the roles of sources and images swapped
    return weights_solution(images, sources)


def affine_through_four(sources, images):          # the affine map of the first four pairs
    HP, HR = _rows(sources), _rows(images)
    return np.linalg.solve(HP[:4], HR[:4])


def weights_without_transpose(sources, images):    # a = solve(H, p) instead of solve(Hᵀ, p)
    HP, HR = _rows(sources), _rows(images)
    a = np.linalg.solve(HP[:4], HP[4])
    b = np.linalg.solve(HR[:4], HR[4])
    return np.linalg.solve(a[:, None] * HP[:4], b[:, None] * HR[:4])


def weights_of_sources_only(sources, images):      # the images' factors forgotten
    HP, HR = _rows(sources), _rows(images)
    a = np.linalg.solve(HP[:4].T, HP[4])
    return np.linalg.solve(a[:, None] * HP[:4], HR[:4])


def affine_least_squares(sources, images):         # the best affine fit to all five pairs
    HP = _rows(sources)
    X, *_ = np.linalg.lstsq(HP, np.asarray(images, float), rcond=None)
    M = np.zeros((4, 4))
    M[:, :3] = X
    M[3, 3] = 1.0
    return M


REJECTED = [
    (transposed, "transposed (the column convention)"),
    (inverse_map, "inverse of the map asked for"),
    (affine_through_four, "affine map through the first four pairs"),
    (weights_without_transpose, "the first four sources go to the right images, the fifth does not"),
    (weights_of_sources_only, "the first four sources go to the right images, the fifth does not"),
    (affine_least_squares, "no affine map sends these five points"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch13.check_projective_map_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message


def test_the_checker_never_blames_the_homogeneous_divide():
    for solution, _ in REJECTED:
        assert "did you divide" not in ch13.check_projective_map_project(solution).message
