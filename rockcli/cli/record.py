"""`rock record`: inspect a ground-motion record file, or generate a synthetic pulse.

The record package (numpy) and rich are imported inside the commands, so that ``rock --help``
starts without them (spec/engine.md, "Speed"). Bad input raises InputError, which the group in
``cli/main.py`` turns into one ``error:`` line and exit code 2.
"""

from __future__ import annotations

import click

from rockcli.cli.options import output_format, plain_dt, plain_units, record_format
from rockcli.records.kinds import PulseKind


@click.group()
def record() -> None:
    """Ground-motion records: inspect a file, generate a pulse."""


@record.command("info")
@click.argument("file", type=click.Path())
@record_format
@plain_dt
@plain_units
@output_format
def info(
    file: str, record_format: str | None, dt: float | None, units: str | None, output: str
) -> None:
    """Format, samples, dt, duration and PGA of a record FILE (AT2, ESM, cor.acc, plain)."""
    from rockcli.records.files import read_record
    from rockcli.report.records import info_document, record_report
    from rockcli.report.table import show

    doc = info_document(read_record(file, fmt=record_format, dt=dt, units=units))
    show(doc, output, record_report)


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
