"""Corpus of the chapter-21 project (Gouraud shading of one triangle): correct shaders written from the
statement alone (a loop over pixels with barycentric coordinates and nested lists, vectorised edge
functions, the book's scan-line way -- intensities interpolated down the edges, then across each
span) must be accepted; realistic wrong ones must be rejected with the slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch21


def _det(a, b):
    return a[0] * b[1] - a[1] * b[0]


# -- accepted ------------------------------------------------------------------------------------------

def pixel_loop(screen, intensities, width, height):
    P = [tuple(map(float, p)) for p in screen]
    area = _det((P[1][0] - P[0][0], P[1][1] - P[0][1]), (P[2][0] - P[0][0], P[2][1] - P[0][1]))
    img = [[0.0] * width for _ in range(height)]
    if area == 0:
        return img
    for i in range(height):
        for j in range(width):
            q = (j + 0.5 - P[0][0], i + 0.5 - P[0][1])
            b = _det(q, (P[2][0] - P[0][0], P[2][1] - P[0][1])) / area
            g = _det((P[1][0] - P[0][0], P[1][1] - P[0][1]), q) / area
            a = 1 - b - g
            if min(a, b, g) >= 0:
                img[i][j] = a * intensities[0] + b * intensities[1] + g * intensities[2]
    return img


def edge_functions(screen, intensities, width, height):
    """Three edge functions E_k(p) = det(P_{k+2} - P_{k+1}, p - P_{k+1}), each the signed area opposite
    vertex k; covered where all have the sign of the total."""
    P = np.asarray(screen, float)
    x, y = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    E = []
    for k in range(3):
        A, B = P[(k + 1) % 3], P[(k + 2) % 3]
        E.append((B[0] - A[0]) * (y - A[1]) - (B[1] - A[1]) * (x - A[0]))
    total = E[0] + E[1] + E[2]
    if abs(total.flat[0]) < 1e-12:
        return np.zeros((height, width))
    lam = [e / total for e in E]
    inside = (lam[0] >= 0) & (lam[1] >= 0) & (lam[2] >= 0)
    return np.where(inside, sum(l * c for l, c in zip(lam, intensities)), 0.0)


def scan_lines(screen, intensities, width, height):
    """Gouraud's own way: for each row, where the scan line y = i + 1/2 crosses the edges, the
    intensities interpolated along the edges; then along the span between the two crossings."""
    P = np.asarray(screen, float)
    I = np.asarray(intensities, float)
    img = np.zeros((height, width))
    area = _det(P[1] - P[0], P[2] - P[0])
    if abs(area) < 1e-12:
        return img
    for i in range(height):
        y = i + 0.5
        hits = []
        for k in range(3):
            A, B, ia, ib = P[k], P[(k + 1) % 3], I[k], I[(k + 1) % 3]
            if A[1] == B[1]:
                if A[1] == y:
                    hits += [(A[0], ia), (B[0], ib)]
                continue
            s = (y - A[1]) / (B[1] - A[1])
            if 0 <= s <= 1:
                hits.append((A[0] + s * (B[0] - A[0]), ia + s * (ib - ia)))
        if not hits:
            continue
        (xl, il), (xr, ir) = min(hits), max(hits)
        for j in range(width):
            x = j + 0.5
            if xl <= x <= xr:
                img[i, j] = il if xr == xl else il + (x - xl) / (xr - xl) * (ir - il)
    return img


ACCEPTED = [pixel_loop, edge_functions, scan_lines]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch21.check_gouraud_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def edges_excluded(screen, intensities, width, height):      # > 0: centres on an edge left out
    P = np.asarray(screen, float)
    lam = _bary(P, width, height)
    if lam is None:
        return np.zeros((height, width))
    return np.where((lam > 0).all(-1), lam @ np.asarray(intensities, float), 0.0)


def _bary(P, width, height, offset=0.5):
    area = _det(P[1] - P[0], P[2] - P[0])
    if abs(area) < 1e-12:
        return None
    x, y = np.meshgrid(np.arange(width) + offset, np.arange(height) + offset)
    qx, qy = x - P[0, 0], y - P[0, 1]
    b = (qx * (P[2, 1] - P[0, 1]) - qy * (P[2, 0] - P[0, 0])) / area
    g = ((P[1, 0] - P[0, 0]) * qy - (P[1, 1] - P[0, 1]) * qx) / area
    return np.stack([1 - b - g, b, g], -1)


def nearest_vertex(screen, intensities, width, height):      # uniform shading by the nearest vertex
    lam = _bary(np.asarray(screen, float), width, height)
    if lam is None:
        return np.zeros((height, width))
    return np.where((lam >= 0).all(-1), np.asarray(intensities, float)[lam.argmax(-1)], 0.0)


def pixel_corners(screen, intensities, width, height):       # sampled at (j, i)
    lam = _bary(np.asarray(screen, float), width, height, offset=0.0)
    if lam is None:
        return np.zeros((height, width))
    return np.where((lam >= 0).all(-1), lam @ np.asarray(intensities, float), 0.0)


def one_orientation(screen, intensities, width, height):     # |area|: the signs flip for clockwise triangles
    P = np.asarray(screen, float)
    lam = _bary(P, width, height)
    if lam is None:
        return np.zeros((height, width))
    if _det(P[1] - P[0], P[2] - P[0]) < 0:
        lam = -lam
    return np.where((lam >= 0).all(-1), lam @ np.asarray(intensities, float), 0.0)


def transposed_image(screen, intensities, width, height):    # (width, height): x taken as the row
    return edge_functions(screen, intensities, width, height).T


def divides_by_zero_area(screen, intensities, width, height):  # no degenerate case
    P = np.asarray(screen, float)
    x, y = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    area = _det(P[1] - P[0], P[2] - P[0])
    with np.errstate(all="ignore"):
        b = ((x - P[0, 0]) * (P[2, 1] - P[0, 1]) - (y - P[0, 1]) * (P[2, 0] - P[0, 0])) / area
        g = ((P[1, 0] - P[0, 0]) * (y - P[0, 1]) - (P[1, 1] - P[0, 1]) * (x - P[0, 0])) / area
        lam = np.stack([1 - b - g, b, g], -1)
        return np.where((lam >= 0).all(-1) | np.isnan(lam).any(-1), lam @ np.asarray(intensities, float), 0.0)


REJECTED = [
    (edges_excluded, "on an edge (it counts as inside)"),
    (nearest_vertex, "the nearest vertex's intensity"),
    (pixel_corners, "at its corner (j, i)"),
    (one_orientation, "the other orientation"),
    (transposed_image, "the image is 12 rows by 16 columns"),
    (divides_by_zero_area, "a degenerate triangle has zero area"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch21.check_gouraud_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message
