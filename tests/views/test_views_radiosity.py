"""Chapter 23 view: the Cornell box's patch colours follow the solver's iterates (indexed by the
iteration sliders), flat vs smooth display, the light square moved over the ceiling, and the
residual curves with the current iteration marked."""

import numpy as np

from goldman_lib import radiosity as rd
from goldman_lib.views import radiosity as rv


def test_iteration_sliders_index_the_solvers_iterates():
    view = rv.radiosity_view()
    box, F = rv.cornell_scene()
    E = view.last_result["emission"]
    _, h = rd.jacobi(F, box.reflectance, E, tol=1e-9, max_iter=rv.MAX_STEPS["jacobi"], full_output=True)
    r0 = view.set_values(solver="jacobi", jacobi_k=0)
    assert np.allclose(r0["radiosities"], E) and r0["iteration"] == 0       # the light alone
    r5 = view.set_values(jacobi_k=5)
    assert np.allclose(r5["radiosities"], h.history[5]) and r5["residual"] < r0["residual"]
    colours = view.scene.data("box")["colors"]
    assert np.allclose(colours, rd.to_colours(rd.corner_radiosities(box, h.history[5]), white=rv.WHITE), atol=1e-6)
    r_gs = view.set_values(solver="gauss_seidel", gs_k=5)
    assert r_gs["residual"] < r5["residual"]                                # Gauss-Seidel converges faster
    r_pr = view.set_values(solver="progressive", shots=200)
    assert "last shot" in r_pr["status"] and r_pr["iteration"] == 200
    marker = view.figure.axes[1].lines[-1].get_xydata()[0]
    assert np.allclose(marker, [200 / len(box), r_pr["residual"]])


def test_flat_and_smooth_display_and_the_light():
    view = rv.radiosity_view("jacobi")
    smooth = view.set_values(shading="smooth", jacobi_k=10)["colours"]
    flat = view.set_values(shading="flat")["colours"]
    assert not np.allclose(smooth, flat)
    box, _ = rv.cornell_scene()
    # flat: the four corners of a patch share its colour
    assert np.allclose(flat.reshape(len(box), 4, 3), flat.reshape(len(box), 4, 3)[:, :1])
    before = view.last_result["emission"]
    r = view.set_values(light0_x=0.3, light0_y=0.7)
    moved = r["emission"]
    assert not np.allclose(before, moved)
    ceiling = np.array(box.labels) == "ceiling"
    lit = box.centres[ceiling][moved[ceiling, 0] > 0]
    assert np.allclose(lit[:, :2].mean(axis=0), [0.3, 0.7], atol=0.07)
    assert np.allclose(view.scene.data("light")["positions"], [[0.3, 0.7, 0.99]])
    dark = view.set_values(light0_I=0.0)
    assert np.all(dark["radiosities"] == 0) and view.last_error is None


def test_the_light_is_dragged_on_the_ceiling_map(hooks):
    view = rv.radiosity_view("jacobi")
    hooks["press_at"](view.drag, 0.5, 0.5)
    hooks["move_to"](view.drag, 0.25, 0.7)
    hooks["release"](view.drag)
    assert abs(view.values()["light0_x"] - 0.25) < 0.02 and abs(view.values()["light0_y"] - 0.7) < 0.02
    glow = view.figure.axes[0].images[0].get_array()
    assert glow.max() == 1.0 and glow[5, 2] > 0 and glow[2, 5] == 0          # lit near (0.25, 0.7), not at (0.7, 0.25)


def test_the_scene_reports_its_hemicubes_to_a_progress_bar():
    from goldman_lib.widgets.render_control import ProgressBar

    bar = ProgressBar("hemi-cubes")
    box, F = rv.cornell_scene(2, 8, progress=bar)             # a size of its own: computed here
    assert (bar.done, bar.total) == (len(box), len(box)) and bar.fraction == 1.0
    calls = []
    again = rv.cornell_scene(2, 8, progress=lambda k, n: calls.append((k, n)))
    assert again[1] is F and calls == [(len(box), len(box))]  # cached: done at once
    assert rv.cornell_scene(2, 8)[1] is F
