"""Results as data, rendered by one generic reporter (spec/style.md, principle 6).

A command builds a :class:`Report` (titles, columns with label/unit/format, rows of plain
values, notes) and a JSON document; :func:`render` turns any Report into rich tables. No
command formats numbers by hand.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table as RichTable


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
    """Print a Report: its tables, then the notes, then the verdict line."""
    console.print(f"[bold]{escape(report.title)}[/bold]")
    for table in report.tables:
        console.print(_rich_table(table))
    for note in report.notes:
        console.print(f"[yellow]note:[/yellow] {escape(note)}")
    if report.verdict:
        console.print(f"[bold]verdict:[/bold] {escape(report.verdict)}")


def _rich_table(table: Table) -> RichTable:
    out = RichTable(title=escape(table.title), title_justify="left")
    for col in table.columns:
        label = escape(f"{col.label} [{col.unit}]" if col.unit else col.label)
        default = "left" if col.key in ("label", "unit", "name") else "right"
        out.add_column(label, justify=col.align or default)  # type: ignore[arg-type]
    for row in table.rows:
        out.add_row(*(escape(format_value(row.get(c.key), c.fmt)) for c in table.columns))
    return out


def show(doc: dict[str, Any], output: str, to_report: Callable[[dict[str, Any]], Report]) -> None:
    """Print a result document as JSON (``output == "json"``) or as its rich Report."""
    if output == "json":
        print(json.dumps(doc, indent=2, allow_nan=False))
        return
    render(to_report(doc), Console(highlight=False))
