"""Views and widget factories for the course notebooks.

- ``views.style``        one figure size, dpi and palette for every chapter
- ``views.interactive``  the widget pattern: :class:`InteractiveView` (controls + view + a plain
                         ``update`` callback + a static fallback image)
- ``views.three``        every use of pythreejs goes through :class:`SceneView`
- ``views.agreement``    a check printed as the values it compares (ours | reference | gap, the
                         gap as a portable bound), not as "...: True"
- ``views.turtle``       chapter 1 views and widgets
- ``views.bezier``       chapter 24 views and widgets

Importing this package imports matplotlib (Agg unless the notebook chose ``%matplotlib widget``);
ipywidgets and pythreejs are imported by the modules that need them.
"""
