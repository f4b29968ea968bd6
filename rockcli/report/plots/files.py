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

from rockcli.errors import InputError, install_hint, printable

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


def save(fig: Figure, path: str | Path) -> None:
    """Write the figure to ``path`` atomically (rockcli.outfile: temporary file + rename)."""
    from io import BytesIO

    from rockcli.outfile import write_bytes

    buffer = BytesIO()
    try:
        printable_text(fig)
        fig.savefig(buffer, format=plot_format(path), dpi=DPI)
    finally:
        fig.clear()
    write_bytes(path, buffer.getvalue(), where=OPTION)


def printable_text(fig: Figure) -> None:
    """Every text of the figure (titles, labels, legends, ticks) with its control characters
    shown as ``\\xNN``, as on the terminal (rockcli.errors.printable); line breaks kept.

    A name comes from a file: a record's file name, a model's ``name`` can hold an escape
    sequence or a bell, for which no font has a glyph (matplotlib warned "Glyph 27 missing
    from font(s) DejaVu Sans" on stderr, with its own source path) and which an SVG, being
    XML, may not hold.
    """
    from matplotlib.text import Text

    for artist in fig.findobj(Text):
        text = artist.get_text()
        if not text.replace("\n", "").isprintable():
            artist.set_text("\n".join(printable(line) for line in text.split("\n")))
