"""The light-position control: the one widget that places lights, shared by chapters 16, 17, 19,
21 and 23 (and any view lit by :mod:`goldman_lib.lighting`).

For each light it makes an x, a y and a z slider, an intensity slider and (optionally) a colour
picker, named ``light0_x``, ``light0_y``, ``light0_z``, ``light0_I``, ``light0_colour``,
``light1_x``, ...  A view merges :attr:`LightControl.controls` into its own controls, so the
light's sliders call the view's plain ``update`` like any other slider, are swept by the widget
tests and are moved by the browser tests; ``update`` turns its values back into lights with
:meth:`LightControl.lights`.  The image then updates in place (``imshow`` data, vertex colours,
:meth:`SceneView.set_lights`), never by rebuilding the figure.

Lights are drawn as markers (:meth:`LightControl.marker_positions` for a 2D view;
:meth:`LightControl.show_in_scene` for a three.js view) and, in a 2D view, dragged with the mouse
through the shared drag helper: :meth:`LightControl.drag_in` connects a marker to two of its
sliders (the plane the view shows), so the mouse and the keyboard set the same values.

>>> control = LightControl([((2.0, 3.0, 4.0))])
>>> sorted(control.controls)
['light0_I', 'light0_colour', 'light0_x', 'light0_y', 'light0_z']
>>> light, = control.lights({**control.defaults(), "light0_x": -1.0})
>>> light.position
(-1.0, 3.0, 4.0)
"""

from __future__ import annotations

from typing import Mapping, Sequence

import ipywidgets as widgets
import numpy as np

from goldman_lib.lighting import Light
from goldman_lib.validation import as_points
from goldman_lib.widgets.interactive import float_slider

__all__ = ["LightControl"]


def _hex(rgb) -> str:
    return "#" + "".join(f"{int(round(255 * c)):02x}" for c in rgb)


class LightControl:
    """Sliders (and colour pickers) for the positions, intensities and colours of point lights.

    lights: the starting lights, as :class:`~goldman_lib.lighting.Light` or as positions ``(x, y, z)``.
    box: the slider range of each coordinate, one ``(low, high)`` for all three or three pairs.
    intensity_range: the intensity slider's range.  colour: whether to add colour pickers.
    prefix: the start of every control name (two controls in one view need two prefixes).
    axes: the coordinates that get a slider (default all of ``"xyz"``); the others stay where the
    starting light is (a light on a ceiling: ``axes="xy"``).  A light given as a ``Light`` keeps its
    intensity and colour as the sliders' starting values.
    """

    def __init__(self, lights: Sequence = ((3.0, -3.0, 5.0),), box=(-6.0, 6.0), intensity_range=(0.0, 2.0),
                 colour: bool = True, prefix: str = "light", step: float = 0.1, axes: str = "xyz"):
        lights = [light if isinstance(light, Light) else Light(tuple(as_points(light, "lights", ndim=1, dim=3)))
                  for light in lights]
        if not lights:
            raise ValueError("lights must hold at least one light")
        box = np.asarray(box, dtype=float)
        boxes = np.broadcast_to(box, (3, 2)) if box.shape == (2,) else box
        if boxes.shape != (3, 2) or np.any(boxes[:, 0] >= boxes[:, 1]):
            raise ValueError(f"box must be (low, high) or three (low, high) pairs with low < high; got {box.tolist()}")
        if not isinstance(axes, str) or not axes or not set(axes) <= set("xyz") or len(set(axes)) != len(axes):
            raise ValueError(f"axes must name some of the coordinates 'xyz', each once (e.g. 'xy'); got {axes!r}")
        self.axes = "".join(a for a in "xyz" if a in axes)
        self.prefix = str(prefix)
        self.count = len(lights)
        self.colour = bool(colour)
        self.controls: dict[str, widgets.Widget] = {}
        self._fixed = [tuple(float(v) for v in light.position) for light in lights]
        for k, light in enumerate(lights):
            for axis, (lo, hi), value in zip("xyz", boxes, light.position):
                if axis not in self.axes:
                    continue
                self.controls[self.name(k, axis)] = float_slider(
                    f"{'L' + str(k) if self.count > 1 else 'light'} {axis}", float(np.clip(value, lo, hi)), float(lo),
                    float(hi), step)
            lo, hi = intensity_range
            self.controls[self.name(k, "I")] = float_slider("intensity", float(np.clip(light.intensity, lo, hi)),
                                                            float(lo), float(hi), 0.05)
            if self.colour:
                self.controls[self.name(k, "colour")] = widgets.ColorPicker(
                    value=_hex(light.colour), description="colour", concise=False,
                    style={"description_width": "48px"}, layout=widgets.Layout(width="290px"))
        self._colours = [light.colour for light in lights]

    def name(self, k: int, part: str) -> str:
        """The control name of light ``k``'s ``part`` (``x``, ``y``, ``z``, ``I`` or ``colour``)."""
        return f"{self.prefix}{k}_{part}"

    def defaults(self) -> dict:
        """The controls' current values, by name."""
        return {name: w.value for name, w in self.controls.items()}

    def lights(self, values: Mapping) -> tuple[Light, ...]:
        """The lights the controls' ``values`` (an update's keyword arguments) describe."""
        from matplotlib.colors import to_rgb

        out = []
        for k in range(self.count):
            position = self._position(k, values)
            colour = to_rgb(values[self.name(k, "colour")]) if self.colour else self._colours[k]
            out.append(Light(position, colour=colour, intensity=float(values[self.name(k, "I")])))
        return tuple(out)

    def _position(self, k: int, values: Mapping) -> tuple:
        return tuple(float(values[self.name(k, axis)]) if axis in self.axes else self._fixed[k][i]
                     for i, axis in enumerate("xyz"))

    def marker_positions(self, values: Mapping) -> np.ndarray:
        """Where the lights are: ``(count, 3)``, to draw as markers."""
        return np.array([self._position(k, values) for k in range(self.count)])

    def own(self, values: Mapping) -> dict:
        """The part of ``values`` that belongs to this control (so an update can split its kwargs)."""
        return {name: values[name] for name in self.controls if name in values}

    def drag_in(self, view, ax, plane: str = "xz", radius: float = 12.0):
        """Let the mouse drag each light's marker in ``ax``, a 2D view of the ``plane`` (two of x, y, z,
        in the order of the axes' horizontal and vertical directions): a drag sets those two sliders
        of the light (through the shared drag helper).  Returns the :class:`PointDrag`."""
        from goldman_lib.widgets.drag import drag_sliders

        if len(plane) != 2 or not set(plane) <= set("xyz") or plane[0] == plane[1]:
            raise ValueError(f"plane must be two different letters of 'xyz' (e.g. 'xz'); got {plane!r}")
        if not set(plane) <= set(self.axes):
            raise ValueError(f"plane must use coordinates the control has sliders for ({self.axes!r}); got {plane!r}")
        pairs = [(self.name(k, plane[0]), self.name(k, plane[1])) for k in range(self.count)]
        return drag_sliders(view, ax, pairs, radius=radius)

    def show_in_scene(self, scene, values: Mapping, name: str = "lights", size: float = 0.25):
        """Draw the lights as yellow markers in a :class:`~goldman_lib.widgets.three.SceneView` and light
        the scene with them; call again with new values to move both in place.  Build the scene with
        ``SceneView(lights=control.lights(control.defaults()))`` so it has as many lights."""
        lights = self.lights(values)
        positions = self.marker_positions(values)
        if name in scene:
            scene.set_points(name, positions)
        else:
            scene.add_points(name, positions, color="#f2b700", size=size)
        scene.set_lights(lights)
        return lights
