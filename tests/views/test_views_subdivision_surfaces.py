"""Chapter 30 widgets: what they draw is the library's subdivision at the slider values, the
three.js geometry is replaced in place (same buffer attributes), and no slider position raises."""

import numpy as np
import pytest

from goldman_lib import subdivision_surfaces as ss
from goldman_lib.views import subdivision_surfaces as views


def test_viewer_draws_the_library_mesh_and_replaces_geometry_in_place():
    view = views.subdivision_surface_view()
    geom = view.scene._items["surface"]["geometry"]
    position = geom.attributes["position"]
    for name in views.MESHES:
        for scheme in ("quad", "triangle"):
            for level in (0, 1, 3):
                result = view.set_values(mesh=name, scheme=scheme, level=level)
                base = views.MESHES[name]()
                control = ss.triangulate(base) if scheme == "triangle" else base
                expected = ss.centroid_averaging(control, level, scheme=scheme)
                np.testing.assert_allclose(result["vertices"], expected.vertices)
                np.testing.assert_array_equal(result["triangles"], expected.triangles())
                np.testing.assert_allclose(result["control"], control.vertices[control.edges])
                assert result["euler"] == base.euler_characteristic()
                # what three.js holds is what was returned
                np.testing.assert_allclose(position.array, expected.vertices.astype(np.float32))
                assert geom.attributes["index"].array.size == 3 * len(expected.triangles())
    assert view.scene._items["surface"]["geometry"] is geom and geom.attributes["position"] is position


def test_viewer_status_reports_counts_and_extraordinary_valences():
    view = views.subdivision_surface_view()
    status = view.update(mesh="cube", scheme="quad", level=1)["status"]
    assert "V=26, E=48, F=24, V-E+F=2" in status and "extraordinary valences 3" in status
    assert "extraordinary valences 5" in view.update(mesh="star (valence 5)", scheme="quad", level=2)["status"]


def test_split_and_average_view_draws_the_library_polygon():
    view = views.split_and_average_view()
    result = view.set_values(degree=2, levels=2)
    np.testing.assert_allclose(result["polygon"], ss.split_and_average(views.DEFAULT_POLYGON, 2, 2))
    assert len(result["polygon"]) == 2 * (2 * 6 - 2) - 2


def test_static_pictures():
    ax = views.plot_mesh(ss.centroid_averaging(ss.cube(), 2), control=ss.cube())
    assert len(ax.collections) == 2
    assert views.plot_quad_stencils(5).texts[0].get_text() == "9/16"
    assert views.plot_triangle_stencils(6).texts[1].get_text() == "1/16"
    assert len(views.plot_polygon_levels(views.DEFAULT_POLYGON, 3, 2)) == 3


def test_factories_reject_bad_arguments():
    with pytest.raises(ValueError, match="mesh must be one of"):
        views.subdivision_surface_view(mesh="torus")
    with pytest.raises(ValueError, match="scheme must be"):
        views.subdivision_surface_view(scheme="loop")
    with pytest.raises(ValueError, match="level must be <= 4"):
        views.subdivision_surface_view(level=7)


def test_viewer_rule_picker_draws_the_library_rule():
    view = views.subdivision_surface_view(mesh="tetrahedron", scheme="triangle", level=2)
    for rule in ss.VERTEX_RULES:
        result = view.set_values(rule=rule)
        expected = ss.centroid_averaging(ss.tetrahedron(), 2, scheme="triangle", rule=rule)
        np.testing.assert_allclose(result["vertices"], expected.vertices)
        assert f"({rule} vertex rule)" in result["status"]
    # the quad scheme has one rule: the picker leaves it alone and says so
    quad = view.set_values(scheme="quad", rule="loop")
    np.testing.assert_allclose(quad["vertices"], ss.centroid_averaging(ss.tetrahedron(), 2, scheme="quad").vertices)
    assert "vertex rules are the triangle scheme's" in quad["status"]
    with pytest.raises(ValueError, match="rule must be one of"):
        views.subdivision_surface_view(rule="butterfly")


def test_cone_pictures_are_the_library_ratios():
    ratios = views.plot_cone_ratios(3)
    assert set(ratios) == set(views.CONE_CASES)
    for label, (make, scheme, rule) in views.CONE_CASES.items():
        np.testing.assert_allclose(ratios[label], ss.cone_ratios(make(), 3, 0, scheme=scheme, rule=rule))
    fig = views.plot_rule_comparison(level=2)
    assert len(fig.axes) == len(ss.VERTEX_RULES)


def test_angle_defect_picture_shows_the_library_defects():
    import matplotlib.pyplot as plt

    from goldman_lib import subdivision_surfaces as ss

    fig = plt.figure()
    out = views.plot_angle_defects(level=2, fig=fig)
    assert list(out) == list(ss.VERTEX_RULES)
    for rule, d in out.items():
        np.testing.assert_allclose(d, ss.angle_defects(ss.centroid_averaging(ss.tetrahedron(), 2, "triangle", rule=rule)))
    assert out["centroid"][:4] == pytest.approx([np.pi] * 4) and out["warren"][:4].max() < 0.1
    assert len([ax for ax in fig.axes if ax.name == "3d"]) == 3 and len(fig.axes) == 4      # and a colour bar
    plt.close(fig)
