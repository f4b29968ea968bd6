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

from rich.cells import cell_len
from rich.console import Console
from rich.markup import escape
from rich.table import Table as RichTable

from rockcli.errors import printable
from rockcli.report.text import encodable


@dataclass(frozen=True)
class Column:
    """A column: the row key it shows, its label, unit and number format."""

    key: str
    label: str
    unit: str = ""
    fmt: str = "{:.4g}"
    align: str = ""  # "left" or "right"; default: left for labels and names, right otherwise


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
    console's encoding cannot carry spelled in ASCII); numbers are never cut (see
    :func:`column_widths`).
    """
    text = _terminal_text(console)
    console.print(f"[bold]{escape(text(report.title))}[/bold]")
    for table in report.tables:
        _print_table(console, table, text)
    for note in report.notes:
        console.print(f"[yellow]note:[/yellow] {escape(text(note))}")
    for warning in report.warnings:
        console.print(f"[bold red]warning:[/bold red] {escape(text(warning))}")
    if report.verdict:
        console.print(f"[bold]verdict:[/bold] {escape(text(report.verdict))}")


def _terminal_text(console: Console) -> Callable[[str], str]:
    encoding = console.encoding
    if encoding.replace("_", "-").startswith("utf"):
        return printable
    return lambda value: encodable(printable(value), encoding)


def _print_table(console: Console, table: Table, text: Callable[[str], str]) -> None:
    """One table; wider than the console only when a column's longest word demands it."""
    labels = [text(f"{c.label} [{c.unit}]" if c.unit else c.label) for c in table.columns]
    cells = [
        [text(format_value(row.get(c.key), c.fmt)) for c in table.columns] for row in table.rows
    ]
    columns = [[label, *(row[i] for row in cells)] for i, label in enumerate(labels)]
    extra = TABLE_FRAME + len(columns) * (CELL_PADDING + 1)
    widths = column_widths(columns, console.width - extra)
    # The title is its own line (a rich table title is padded to the table's width, which
    # leaves trailing blanks in a file).
    console.print(escape(text(table.title)), style="italic")
    out = RichTable()
    for i, col in enumerate(table.columns):
        default = "left" if col.key in ("label", "unit", "name") else "right"
        width = None if widths is None else widths[i]
        out.add_column(escape(labels[i]), justify=col.align or default, width=width)  # type: ignore[arg-type]
    for row in cells:
        out.add_row(*(escape(cell) for cell in row))
    needed = extra + sum(widths) if widths is not None else 0
    if needed <= console.width:
        console.print(out)
        return
    saved = console.width
    console.width = needed  # wider than the terminal: the terminal wraps, no digit is lost
    try:
        console.print(out)
    finally:
        console.width = saved


#: Characters of a table's frame outside its columns (the outer borders, rich's default box).
TABLE_FRAME = 1
#: Padding of a rich table cell (one space either side).
CELL_PADDING = 2


def column_widths(columns: list[list[str]], available: int) -> list[int] | None:
    """Content widths that wrap text at spaces and never cut a word or a number.

    Args:
        columns: every column's header and cells, as shown.
        available: the width the columns' content may take (console width minus the frame).

    Returns:
        None when every cell fits on one line (rich's natural layout); else each column at
        least its longest word, the remaining width shared in proportion to what each column
        would still use.
    """
    longest = [max(_line_width(cell) for cell in col) for col in columns]
    if sum(longest) <= available:
        return None
    words = [max(_word_width(cell) for cell in col) for col in columns]
    spare = available - sum(words)
    slack = [full - word for full, word in zip(longest, words, strict=True)]
    if spare <= 0 or not sum(slack):
        return words
    return [word + spare * s // sum(slack) for word, s in zip(words, slack, strict=True)]


def _line_width(cell: str) -> int:
    return max((cell_len(line) for line in cell.splitlines()), default=0)


def _word_width(cell: str) -> int:
    return max((cell_len(word) for word in cell.split()), default=0)


class _Console(Console):
    """rich's Console, except that a closed pipe raises BrokenPipeError for the CLI to handle
    (rich's own handler exits with 1)."""

    def on_broken_pipe(self) -> None:
        raise BrokenPipeError


#: Width of a report written to a file or a pipe: no terminal to fit, so no line is wrapped.
FILE_WIDTH = 10_000


def console_for(file: TextIO | None = None) -> Console:
    """The console of a report: the terminal's width, or no width limit for a file or pipe."""
    stream = file if file is not None else sys.stdout
    terminal = hasattr(stream, "isatty") and stream.isatty()
    return _Console(file=stream, highlight=False, width=None if terminal else FILE_WIDTH)


def show(doc: dict[str, Any], output: str, to_report: Callable[[dict[str, Any]], Report]) -> None:
    """Print a result document as JSON (``output == "json"``) or as its rich Report."""
    if output == "json":
        print(json.dumps(doc, indent=2, allow_nan=False))
        return
    render(to_report(doc), console_for())
