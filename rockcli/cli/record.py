"""`rock record`: inspect a ground-motion record file, or generate a synthetic pulse.

The record package (numpy) and rich are imported inside the commands, so that ``rock --help``
starts without them (spec/engine.md, "Speed"). Bad input raises InputError, which the group in
``cli/main.py`` turns into one ``error:`` line and exit code 2.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING

import click

from rockcli.records.kinds import FILE_FORMATS, PulseKind

if TYPE_CHECKING:
    from rockcli.records.record import Record

#: Version of the JSON written by ``rock record info --format json``.
INFO_SCHEMA = 1

#: Display symbols of the acceleration units (rockcli.units.AccelUnit values).
_SYMBOLS = {"g": "g", "m/s2": "m/s²", "cm/s2": "cm/s²"}


@click.group()
def record() -> None:
    """Ground-motion records: inspect a file, generate a pulse."""


def info_data(rec: Record) -> dict[str, object]:
    """The JSON document of ``record info`` (full precision, schema version)."""
    return {
        "schema": INFO_SCHEMA,
        "name": rec.name,
        "source": rec.source,
        "format": rec.format,
        "npts": rec.npts,
        "dt": rec.dt,
        "duration": rec.duration,
        "pga_g": rec.pga,
        "t_pga": rec.t_pga,
        "unit": rec.unit,
        "notes": list(rec.notes),
    }


def _pga_rows(rec: Record) -> list[tuple[str, str]]:
    """PGA in g, in m/s² and in the file's unit (each unit once)."""
    from rockcli.units import AccelUnit

    units = dict.fromkeys([AccelUnit.G, AccelUnit.M_S2, AccelUnit(rec.unit)])
    return [(f"PGA [{_SYMBOLS[unit]}]", f"{rec.pga / unit.to_g:.6g}") for unit in units]


def _info_rows(rec: Record) -> list[tuple[str, str]]:
    """Label and value of each line of the ``record info`` table."""
    return [
        ("Record", rec.name),
        ("Source", rec.source),
        ("Format", rec.format),
        ("Unit in file", _SYMBOLS.get(rec.unit, rec.unit)),
        ("Samples", str(rec.npts)),
        ("dt [s]", f"{rec.dt:.6g}"),
        ("Duration [s]", f"{rec.duration:.6g}"),
        *_pga_rows(rec),
        ("Time of PGA [s]", f"{rec.t_pga:.6g}"),
    ]


def _print_info(rec: Record) -> None:
    """The rich table of ``record info``, notes under it."""
    from rich.console import Console
    from rich.table import Table
    from rich.text import Text

    table = Table(title=f"Record {rec.name}")
    table.add_column("Quantity")
    table.add_column("Value", justify="right")
    for label, value in _info_rows(rec):
        table.add_row(Text(label), Text(value))  # Text: "[s]" is not rich markup
    console = Console(highlight=False)
    console.print(table)
    for note in rec.notes:
        console.print(Text(f"note: {note}"))


@record.command("info")
@click.argument("file", type=click.Path())
@click.option(
    "--as",
    "fmt",
    type=click.Choice([str(f) for f in FILE_FORMATS]),
    default=None,
    help="Force the record format (default: detected from the content).",
)
@click.option("--dt", type=float, default=None, help="Time step [s] of a one-column plain file.")
@click.option(
    "--units",
    default=None,
    metavar="g|m/s2|cm/s2",
    help="Acceleration unit of a plain file (default g).",
)
@click.option(
    "--format",
    "output",
    type=click.Choice(["table", "json"]),
    default="table",
    show_default=True,
    help="Output: a table, or JSON with full precision.",
)
def info(file: str, fmt: str | None, dt: float | None, units: str | None, output: str) -> None:
    """Format, samples, dt, duration and PGA of a record FILE (AT2, ESM, cor.acc, plain)."""
    from rockcli.records.files import read_record

    rec = read_record(file, fmt=fmt, dt=dt, units=units)
    if output == "json":
        click.echo(json.dumps(info_data(rec), indent=2))
    else:
        _print_info(rec)


@record.command("pulse")
@click.argument("kind", type=click.Choice([str(k) for k in PulseKind]))
@click.option("--amplitude", type=float, required=True, help="Peak acceleration ap [g].")
@click.option(
    "--period",
    type=float,
    required=True,
    help="Tp [s]: 2π/ωp of the sine pulses (the half-sine lasts Tp/2, one-sine and one-cosine "
    "Tp), 1/fp of the Ricker wavelet (it lasts 3 Tp), the duration of the rectangular pulse.",
)
@click.option("--dt", type=float, default=0.005, show_default=True, help="Time step [s].")
@click.option(
    "--duration",
    type=float,
    default=None,
    help="Total duration [s], zeros after the pulse (default: the pulse alone).",
)
@click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False),
    required=True,
    help="Plain-text file to write (time [s], acceleration [g]).",
)
def pulse(
    kind: str, amplitude: float, period: float, dt: float, duration: float | None, output: str
) -> None:
    """Write a synthetic pulse KIND as a two-column plain-text record."""
    from rockcli.records.files import write_plain
    from rockcli.records.pulses import make_pulse

    rec = make_pulse(kind, amplitude, period, dt=dt, total=duration)
    write_plain(rec, output)
    click.echo(f"wrote {output}: {rec.name}, {rec.npts} samples, dt = {rec.dt:g} s")
