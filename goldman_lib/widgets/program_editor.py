"""The one program editor of the course: a text box, an example picker, a help line and a live
drawing, shared by the turtle (chapter 1, :func:`goldman_lib.views.turtle.turtle_program_editor`)
and CODO (chapter 5, :func:`goldman_lib.views.codo.codo_program_editor`).

A language plugs in through ``make_runner(ax)``: called once with the editor's axes, it builds the
artists and returns ``run(program) -> dict``, which parses and runs a program, updates the artists
in place and returns what it drew with a ``"status"`` line (raising ValueError for a program that
does not parse or run; the view then shows the message and keeps the last good drawing).

It holds no factory of its own: the chapters' factories built on it are discovered in their
chapter modules (:func:`goldman_lib.views.factories`).
"""

from __future__ import annotations

from typing import Callable, Mapping

from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, figure_widget

__all__ = ["program_editor"]


def program_editor(program: str, *, make_runner: Callable, examples: Mapping[str, str], help_html: str,
                   title: str, picker_label: str = "(examples)", rows: int = 8, height: str = "170px",
                   max_length: int | None = None, figsize=style.FIGSIZE) -> InteractiveView:
    """A text box for a program with live drawing.

    program: the initial text.  make_runner: ``make_runner(ax) -> run`` (see the module's
    docstring).  examples: ``{name: program}`` offered by the picker (``view.examples``), which
    only fills the box.  help_html: the line under the picker.  max_length: the longest program
    ``update`` runs (it re-runs at every edit), or None.  ``update(program)`` raises TypeError for
    a non-string and ValueError for a program longer than ``max_length``, else returns ``run(program)``.

    >>> view = program_editor("ab", make_runner=lambda ax: lambda p: {"status": f"{len(p)} chars"},
    ...                       examples={"three": "abc"}, help_html="", title="demo")
    >>> view.examples.value = "three"
    >>> view.last_result["status"]
    '3 chars'
    """
    import ipywidgets as widgets

    if not isinstance(program, str):
        raise TypeError(f"program must be a string; got {type(program).__name__}")
    box = widgets.Textarea(value=program, continuous_update=False, rows=rows,
                           layout=widgets.Layout(width="330px", height=height))
    picker = widgets.Dropdown(options=[picker_label] + list(examples), value=picker_label,
                              layout=widgets.Layout(width="330px"))

    def pick(change):
        if change["new"] in examples:
            box.value = examples[change["new"]]

    picker.observe(pick, names="value")
    fig, ax = style.new_axes(figsize)
    run = make_runner(ax)

    def update(program):
        if not isinstance(program, str):
            raise TypeError(f"program must be a string; got {type(program).__name__}")
        if max_length is not None and len(program) > max_length:
            raise ValueError(f"program must be at most {max_length:,} characters in the editor (it re-runs "
                             f"as you type); got {len(program):,}: use REPEAT")
        return run(program)

    view = InteractiveView(controls={"program": box}, views=[figure_widget(fig)], update=update, figure=fig,
                           title=title, side=True,
                           extra=[picker, widgets.HTML(help_html, layout=widgets.Layout(width="330px"))])
    view.examples = picker  # the example picker (not a control: it only fills the text box)
    return view
