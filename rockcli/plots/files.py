"""Plot files: the format from the suffix, the figure, writing it (InputError on bad input).

The figures are :class:`matplotlib.figure.Figure` objects written by the Agg (PNG) or SVG
canvas, never made through pyplot: no backend switch, no global figure registry, nothing left
open (matplotlib's advice for figures made in servers and loops, "Embedding in a web
application server"). matplotlib is imported here, inside the functions, and nowhere at the
top of a module.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path
from typing import TYPE_CHECKING

from rockcli.errors import InputError, display_text, install_hint

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: File suffixes → the format matplotlib writes.
FORMATS = {".png": "png", ".svg": "svg"}
#: The option the path comes from, named in the error lines.
OPTION = "--plot"
MISSING = f"plots need matplotlib: {install_hint('plot')}"
#: Resolution of PNG files [dots per inch].
DPI = 150


def plot_format(path: str | Path, where: str = OPTION) -> str:
    """The format of a plot file from its suffix: "png" or "svg" (InputError otherwise)."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise InputError(
            f"cannot write a plot as {suffix or 'a file without suffix'}",
            where=where,
            value=str(path),
            allowed="a file name ending in " + " or ".join(FORMATS),
        )
    return FORMATS[suffix]


def check_plot_path(path: str | Path, where: str = OPTION) -> None:
    """Fail early, before a long run: a known suffix, and matplotlib installed."""
    plot_format(path, where)
    if importlib.util.find_spec("matplotlib") is None:
        raise InputError(MISSING)


def new_figure(path: str | Path, size: tuple[float, float]) -> Figure:
    plot_format(path)
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(MISSING) from None
    return Figure(figsize=size, layout="constrained")


def clean_texts(fig: Figure) -> None:
    """Make every text of the figure safe to draw and to write, before it is saved.

    The texts carry names from the user's files (a model, a record, a restrainer): a control
    character in one (``\\x07``, an escape sequence) reached the SVG, which Typst then refused,
    and matplotlib warned of a missing glyph; a ``$`` pair made matplotlib parse the name as
    mathematics (``$\\frac$`` raised). Each text is passed through
    :func:`rockcli.errors.display_text` and drawn literally (rock's own labels use no
    mathematics). The tick labels are the formatters' numbers, left as they are.
    """
    from matplotlib.text import Text

    ticks = {
        id(label)
        for ax in fig.axes
        for axis in (ax.xaxis, ax.yaxis)
        for tick in (*axis.get_major_ticks(), *axis.get_minor_ticks())
        for label in (tick.label1, tick.label2)
    }
    for text in fig.findobj(Text):
        if id(text) not in ticks:
            text.set_text(display_text(text.get_text()))
            text.set_parse_math(False)


def save(fig: Figure, path: str | Path) -> None:
    """Write the figure to ``path`` atomically (rockcli.outfile: temporary file + rename),
    its texts cleaned first (:func:`clean_texts`)."""
    from io import BytesIO

    from rockcli.outfile import write_bytes

    buffer = BytesIO()
    try:
        clean_texts(fig)
        fig.savefig(buffer, format=plot_format(path), dpi=DPI)
    finally:
        fig.clear()
    write_bytes(path, buffer.getvalue(), where=OPTION)
