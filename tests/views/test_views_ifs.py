"""Chapter 6 views draw the library's deterministic iterates and condensation trees."""

import matplotlib.pyplot as plt
import numpy as np
import pytest

from goldman_lib import ifs
from goldman_lib.views import ifs as views


def test_iteration_view_draws_w_n_of_the_start_shape():
    v = views.iteration_view()
    r = v.update(system="Koch curve", start="segment", level=3)
    expected = ifs.deterministic(ifs.koch(), 3, start=[[0, 0], [1, 0]]).reshape(-1, 2, 2)
    np.testing.assert_allclose(r["copies"], expected)
    # consecutive copies of the segment join up: the Koch curve's polyline (§6.1)
    np.testing.assert_allclose(expected[1:, 0], expected[:-1, 1], atol=1e-12)
    r = v.update(system="Sierpinski carpet", start="far-away circle", level=8)
    assert "capped" in r["status"] and len(r["copies"]) * 25 <= 60_000
    plt.close(v.figure)


def test_condensation_view_counts_branches():
    v = views.condensation_view()
    for level in (0, 3, 7):
        r = v.update(angle=25.0, ratio=0.5, level=level)
        assert len(r["branches"]) == 2 ** (level + 1) - 1
    np.testing.assert_allclose(r["branches"][0], [[0, 0], [0, 1]])
    plt.close(v.figure)


def test_bad_arguments():
    with pytest.raises(ValueError, match="system must be one of"):
        views.iteration_view(system="fractal tree")
    with pytest.raises(ValueError, match="start must be one of"):
        views.iteration_view(start="blob")
