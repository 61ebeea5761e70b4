"""Chapter 7 views: what they draw is the library's iteration, checked against closed forms."""

import math

import matplotlib.pyplot as plt
import numpy as np
import pytest

from goldman_lib.views import fixed_point as views


def test_newton_view_iterates_and_names_failures():
    v = views.newton_view()
    r = v.update(function="x^2 - 2", x0=1.0, steps=2)
    np.testing.assert_allclose(r["xs"], [1.0, 1.5, 17 / 12])
    r = v.update(function="x^2 - 2", x0=1.0, steps=8)
    assert abs(r["xs"][-1] - math.sqrt(2)) < 1e-15 and "converged" in r["status"]
    assert "cycle" in v.update(function="x^3 - 2x + 2 (cycles from 0)", x0=0.0, steps=6)["status"]
    assert "diverged" in v.update(function="arctan x (diverges from |x0| > 1.39)", x0=1.5, steps=10)["status"]
    assert "zero derivative" in v.update(function="x^2 - 2", x0=0.0, steps=3)["status"]
    plt.close(v.figure)


def test_relaxation_view_converges_to_the_solution_and_diverges_when_not_dominant():
    v = views.relaxation_view()
    r = v.update(method="Gauss-Seidel", steps=30, diagonal=3.0)
    np.testing.assert_allclose(r["iterates"][-1], np.linalg.solve([[3, 1], [2, 3]], [1, 2]), atol=1e-12)
    # Jacobi's first step is b / diag
    np.testing.assert_allclose(v.update(method="Jacobi", steps=1, diagonal=4.0)["iterates"][1], [1 / 4, 2 / 4])
    r = v.update(method="Jacobi", steps=30, diagonal=1.0)
    assert r["residuals"][-1] > r["residuals"][1]
    plt.close(v.figure)


def test_fractal_theorem_view_reports_the_bound():
    v = views.fractal_theorem_view()
    r = v.update(system="Sierpinski gasket", start="a far-away point", level=4)
    assert np.all(r["distances"] <= r["bounds"] + 0.05)
    assert r["distances"][-1] < r["distances"][0] / 10
    assert len(r["iterate"]) == 3 ** 4
    plt.close(v.figure)


def test_cobweb_path_goes_up_to_the_graph_and_across_to_the_diagonal():
    import math
    from goldman_lib.views import fixed_point as fpv
    ax = fpv.cobweb(math.cos, [0.0, 1.0], 30, (0.0, 1.2))
    path = ax.lines[2].get_xydata()
    np.testing.assert_allclose(path[1::2, 1], np.cos(path[1::2, 0]), atol=1e-15)   # on the graph
    np.testing.assert_allclose(path[2::2, 0], path[2::2, 1], atol=0)                # on the diagonal
    assert abs(path[-1, 0] - 0.7390851332) < 1e-4 and len(ax.lines) == 4
    with pytest.raises(ValueError, match="interval"):
        fpv.cobweb(math.cos, [0.0], 3, (1, 0))
    with pytest.raises(ValueError, match="steps"):
        fpv.cobweb(math.cos, [0.0], 0, (0, 1))


def test_convergence_plot_skips_zeros():
    from goldman_lib.views import fixed_point as fpv
    ax = fpv.convergence_plot({"a": [1, 0.1, 0.0], "b": [2, 1]})
    assert ax.lines[0].get_xydata().tolist() == [[0.0, 1.0], [1.0, 0.1]] and len(ax.lines) == 2


def test_two_panel_views_draw_few_ticks_and_plain_log_labels():
    """Tick labels were most of a redraw (issue 13 §5): the relaxation and fractal-theorem views keep
    a few ticks per axis, and their log axes label decades in plain text with no minor ticks."""
    from goldman_lib.widgets import style

    for view in (views.relaxation_view(), views.fractal_theorem_view()):
        view.figure.canvas.draw()
        for ax in view.figure.axes:
            for axis in (ax.xaxis, ax.yaxis):
                shown = [t for t in axis.get_ticklabels() if t.get_text()]
                assert 1 <= len(shown) <= 6, (view.title, [t.get_text() for t in shown])
                if axis.get_scale() == "log":
                    assert len(axis.get_minorticklocs()) == 0
                    assert all("$" not in t.get_text() for t in shown)
        plt.close(view.figure)
    assert [style._plain_power(v) for v in (1e-3, 1.0, 100.0, 3e-5, 0.0)] == ["1e-3", "1e0", "1e2", "3e-5", ""]
