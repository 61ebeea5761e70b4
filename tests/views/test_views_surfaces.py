"""Chapter 18 view: a surface coloured by K or H in three.js, deformed in place; what is drawn is
checked against the closed forms (sphere K = 1, cylinder K = 0 and |H| = 1/(2r), torus
K = cos v / (r (R + r cos v))) and the normals against the deformed surface's tangents."""

import numpy as np

from goldman_lib import surfaces as sf
from goldman_lib.views import surfaces as sv


def test_colours_follow_the_closed_forms():
    view = sv.curvature_view(resolution=16)
    r = view.set_values(surface="sphere", curvature="Gaussian K", amount=0.0)
    assert np.allclose(r["values"], 1.0, atol=1e-5)
    assert np.allclose(r["colours"], r["colours"][0])                       # one colour: constant K
    r = view.set_values(surface="cylinder", curvature="mean H")
    assert np.allclose(np.abs(r["values"]), 1 / 1.4, atol=1e-5)
    r = view.set_values(surface="torus", curvature="Gaussian K")
    _, _, u, v = sf.parametric_torus(1.0, 0.4).grid_mesh(16)
    assert np.allclose(r["values"], np.cos(v) / (0.4 * (1 + 0.4 * np.cos(v))), atol=1e-5)
    # outside red, inside blue
    assert r["colours"][np.argmax(r["values"])][0] > 0.6 and r["colours"][np.argmin(r["values"])][2] > 0.6
    assert np.allclose(view.scene.data("surface")["colors"], r["colours"])


def test_the_deformation_moves_the_mesh_in_place_and_maps_normals_by_the_inverse_transpose():
    view = sv.curvature_view(resolution=16)
    first = view.set_values(surface="torus", deform="taper along z", amount=0.0)["positions"].copy()
    geometry = view.scene._items["surface"]["geometry"]
    r = view.set_values(amount=0.8)
    assert view.scene._items["surface"]["geometry"] is geometry
    assert not np.allclose(first, r["positions"])
    assert np.allclose(view.scene.data("surface")["positions"], r["positions"])
    # the taper with k = 0.48 scales x and y by 1 + 0.48 z
    assert np.allclose(r["positions"][:, :2], first[:, :2] * (1 + 0.48 * first[:, 2:]))
    # each drawn normal is perpendicular to the deformed surface (tangents of A(X(u, v)))
    torus, A = sf.parametric_torus(1.0, 0.4), sf.taper(0.48)
    _, _, u, v = torus.grid_mesh(16)
    pick = np.zeros((16, 16), dtype=bool)
    pick[::2, ::2] = True
    uu, vv = u[pick.ravel()], v[pick.ravel()]
    h = 1e-6
    Y = lambda a, b: A.apply(torus.point(a, b))  # noqa: E731
    for Yt in ((Y(uu + h, vv) - Y(uu - h, vv)) / (2 * h), (Y(uu, vv + h) - Y(uu, vv - h)) / (2 * h)):
        assert np.abs(np.einsum("ij,ij->i", r["normals"], Yt)).max() < 1e-6
    # a twist changes the curvature of the torus (not a rigid motion)
    K0 = view.set_values(deform="twist about x", amount=0.0, curvature="Gaussian K")["values"]
    K1 = view.set_values(amount=1.0)["values"]
    assert np.abs(K1 - K0).max() > 0.5 and "twist" in view.last_result["status"]


def test_the_saddle_has_negative_gaussian_curvature():
    view = sv.curvature_view(resolution=16)
    r = view.set_values(surface="saddle", curvature="Gaussian K", amount=0.0)
    assert np.all(r["values"] < 0)


def test_terrain_png_draws_one_panel_per_roughness():
    import io

    from PIL import Image

    one = Image.open(io.BytesIO(sv.terrain_png((0.5,), level=4)))
    three = Image.open(io.BytesIO(sv.terrain_png((0.35, 0.5, 0.7), level=4)))
    assert three.size[0] == 3 * one.size[0] and three.size[1] == one.size[1]
    import numpy as np

    assert len(np.unique(np.asarray(three.convert("RGB")).reshape(-1, 3), axis=0)) > 100   # shaded, not flat
    import pytest

    with pytest.raises(ValueError, match="roughnesses"):
        sv.terrain_png(())


def test_the_normal_map_picture_and_its_validation():
    import pytest

    assert sv.normal_map_png(arrows=4, size=(16, 12))[:4] == b"\x89PNG"
    with pytest.raises(ValueError, match="y = 0"):
        sv.normal_map_png(M=[[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(ValueError, match="arrows"):
        sv.normal_map_png(arrows=1)


def test_the_full_size_render_control_renders_its_scene_on_request():
    import pytest

    from goldman_lib import ray_tracing as rt

    scene, camera = rt.default_scene(), rt.default_camera()
    rc = sv.full_size_render(scene, camera, 24, 18, samples=2, depth=1)
    assert rc.last_image is None                                            # nothing until the button
    image = rc.render()
    assert np.array_equal(image, rt.render(scene, camera, 24, 18, depth=1, samples=2))
    assert rc.progress.fraction == 1.0 and "24 x 18" in rc.status.value
    with pytest.raises(TypeError, match="Scene and Camera"):
        sv.full_size_render("scene", camera)
