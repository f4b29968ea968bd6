"""Results as data, rendered by one generic reporter (spec/style.md, principle 6).

A command builds a :class:`Report` (titles, columns with label/unit/format, rows of plain
values, notes) and a JSON document; :func:`render` turns any Report into rich tables. No
command formats numbers by hand.
"""

from __future__ import annotations

import json
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TextIO

from rich.console import Console
from rich.segment import Segment, Segments
from rich.table import Table as RichTable
from rich.text import Text

from rockcli.errors import printable
from rockcli.terminal.layout import ColumnText, Layout, fit, wrap_text
from rockcli.terminal.text import encodable


@dataclass(frozen=True)
class Column:
    """A column: the row key it shows, its label, unit and number format."""

    key: str
    label: str
    unit: str = ""
    fmt: str = "{:.4g}"
    align: str = ""  # "left" or "right"; default: left for labels and names, right otherwise
    #: A shorter label, shown (with the unit) when the full header does not fit the width.
    short: str = ""


@dataclass(frozen=True)
class Table:
    """Rows of values (dicts keyed by Column.key) under a title."""

    title: str
    columns: tuple[Column, ...]
    rows: tuple[dict[str, Any], ...]


@dataclass(frozen=True)
class Report:
    """Everything a command shows in the terminal."""

    title: str
    tables: tuple[Table, ...]
    notes: tuple[str, ...] = field(default_factory=tuple)
    verdict: str | None = None
    #: Inputs that look wrong (a unit slip, a record above 3 g): shown after the notes.
    warnings: tuple[str, ...] = field(default_factory=tuple)


def key_value(title: str, items: list[tuple[str, Any, str, str]]) -> Table:
    """A two-column table (quantity, value [unit]) from (label, value, unit, fmt) items."""
    cols = (Column("label", ""), Column("value", "value"), Column("unit", "unit"))
    rows = tuple(
        {"label": lab, "value": format_value(v, fmt), "unit": u} for lab, v, u, fmt in items
    )
    return Table(title=title, columns=cols, rows=rows)


def format_value(value: Any, fmt: str = "{:.4g}") -> str:
    """One cell: numbers by `fmt`, None as an em dash, booleans as yes/no."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int | float):
        return fmt.format(value)
    return str(value)


def render(report: Report, console: Console) -> None:
    """Print a Report: its tables, then the notes and warnings, then the verdict line.

    Every text is made safe for the terminal first (control characters escaped, symbols the
    console's encoding cannot carry spelled in ASCII); every table fits the console's width
    with no number cut (:mod:`rockcli.terminal.layout`), and the notes, warnings and verdict
    wrap at spaces, their later lines indented under the first.
    """
    text = _terminal_text(console)
    _print_wrapped(console, text(report.title), "bold")
    for table in report.tables:
        _print_table(console, table, text)
    for note in report.notes:
        _print_labelled(console, "note:", "yellow", text(note))
    for warning in report.warnings:
        _print_labelled(console, "warning:", "bold red", text(warning))
    if report.verdict:
        _print_labelled(console, "verdict:", "bold", text(report.verdict))


def _terminal_text(console: Console) -> Callable[[str], str]:
    encoding = console.encoding
    if encoding.replace("_", "-").startswith("utf"):
        return printable
    return lambda value: encodable(printable(value), encoding)


#: Blanks before the later lines of a note, a warning or the verdict.
HANGING_INDENT = 2


def _print_wrapped(console: Console, line: str, style: str) -> None:
    """A title, wrapped at the console's width (no trailing blank at the break)."""
    for part in wrap_text(line, console.width, indent=HANGING_INDENT).split("\n"):
        console.print(Text(part, style=style), soft_wrap=True)


def _print_labelled(console: Console, label: str, style: str, body: str) -> None:
    """``label body`` wrapped at the console's width, the later lines indented."""
    lines = wrap_text(f"{label} {body}", console.width, indent=HANGING_INDENT).split("\n")
    console.print(Text(label, style=style) + Text(lines[0][len(label) :]), soft_wrap=True)
    for line in lines[1:]:
        console.print(Text(line), soft_wrap=True)


def _print_table(console: Console, table: Table, text: Callable[[str], str]) -> None:
    """One table fitted to the console's width (:func:`rockcli.terminal.layout.fit`): wider
    only when its numbers alone are, and then the terminal wraps, no digit is lost."""
    columns = [_column_text(column, table.rows, text) for column in table.columns]
    layout = fit(columns, console.width)
    # The title is its own line (a rich table title is padded to the table's width, which
    # leaves trailing blanks in a file).
    _print_wrapped(console, text(table.title), "italic")
    out = RichTable(
        box=layout.frame.box,
        show_edge=layout.frame.show_edge,
        pad_edge=layout.frame.pad_edge,
        padding=(0, layout.frame.right, 0, layout.frame.left),
    )
    for i, col in enumerate(table.columns):
        default = "left" if col.key in ("label", "unit", "name") else "right"
        width = None if layout.widths is None else layout.widths[i]
        header = layout.headers[i] if width is None else wrap_text(layout.headers[i], width)
        out.add_column(Text(header), justify=col.align or default, width=width, no_wrap=True)  # type: ignore[arg-type]
    for row in zip(*(c.cells for c in columns), strict=True):
        out.add_row(*(_cell(cell, columns[i], layout, i) for i, cell in enumerate(row)))
    options = console.options.update(width=max(console.width, layout.total()))
    lines = console.render_lines(out, options, pad=False)
    segments = [s for line in lines for s in (*_without_trailing_blanks(line), Segment.line())]
    console.print(Segments(segments), soft_wrap=True)


def _column_text(column: Column, rows: tuple[dict[str, Any], ...], text) -> ColumnText:
    """A column's headers (full, short) and cells as shown."""
    unit = f" [{column.unit}]" if column.unit else ""
    headers: tuple[str, ...] = (text(f"{column.label}{unit}"),)
    if column.short:
        headers += (text(f"{column.short}{unit}"),)
    values = [row.get(column.key) for row in rows]
    numeric = all(_is_number(v) for v in values)
    return ColumnText(headers, tuple(text(format_value(v, column.fmt)) for v in values), numeric)


def _is_number(value: Any) -> bool:
    """A numeric cell (its format makes it a number, or the dash of a missing one)."""
    return value is None or (isinstance(value, int | float) and not isinstance(value, bool))


def _cell(cell: str, column: ColumnText, layout: Layout, index: int) -> Text:
    """A cell, its text wrapped to the column's width (a number as it is)."""
    if layout.widths is None or column.numeric:
        return Text(cell)
    return Text(wrap_text(cell, layout.widths[index]))


def _without_trailing_blanks(line: list[Segment]) -> list[Segment]:
    """A rendered line without the blanks after its last character (a file is diffed)."""
    segments = list(line)
    while segments and not segments[-1].text.rstrip():
        segments.pop()
    if segments:
        last = segments[-1]
        segments[-1] = Segment(last.text.rstrip(), last.style, last.control)
    return segments


class _Console(Console):
    """rich's Console, except that a closed pipe raises BrokenPipeError for the CLI to handle
    (rich's own handler exits with 1)."""

    def on_broken_pipe(self) -> None:
        raise BrokenPipeError


#: Width of a report written to a file or a pipe [characters]: no terminal to fit, a bound
#: that a reader's editor and a diff show whole (JSON and CSV are the machines' formats).
FILE_WIDTH = 100


def console_for(file: TextIO | None = None) -> Console:
    """The console of a report: the terminal's width, or FILE_WIDTH for a file or a pipe."""
    stream = file if file is not None else sys.stdout
    width = None if is_terminal(stream) else FILE_WIDTH
    return _Console(file=stream, highlight=False, width=width)


def is_terminal(stream: TextIO) -> bool:
    """Whether a report goes to a terminal (rich then takes its width, or $COLUMNS)."""
    return hasattr(stream, "isatty") and stream.isatty()


def show(doc: dict[str, Any], output: str, to_report: Callable[[dict[str, Any]], Report]) -> None:
    """Print a result document as JSON (``output == "json"``) or as its rich Report."""
    if output == "json":
        print(json.dumps(doc, indent=2, allow_nan=False))
        return
    render(to_report(doc), console_for())
