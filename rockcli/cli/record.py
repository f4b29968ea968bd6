"""`rock record`: inspect a ground-motion record file, or generate a synthetic pulse.

The record package (numpy) and rich are imported inside the commands, so that ``rock --help``
starts without them (spec/engine.md, "Speed"). Bad input raises InputError, which the group in
``cli/main.py`` turns into one ``error:`` line and exit code 2.
"""

from __future__ import annotations

import click

from rockcli.cli.options import output_format, plain_dt, plain_units, record_format
from rockcli.records.kinds import PulseKind

plain_output = click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False),
    required=True,
    help="Plain-text file to write (time [s], acceleration [g]).",
)


@click.group()
def record() -> None:
    """Ground-motion records: inspect, convert (scale, flip, trim, resample), generate a pulse."""


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


def _window(value: str | None) -> tuple[float, float] | None:
    from rockcli.errors import InputError

    if value is None:
        return None
    try:
        t0, t1 = (float(x) for x in value.split(","))
    except ValueError:
        raise InputError(
            "not a time window",
            where="--trim",
            value=value,
            allowed="T0,T1 in seconds, e.g. 1.5,20",
        ) from None
    return t0, t1


@record.command("convert")
@click.argument("file", type=click.Path())
@record_format
@plain_dt
@plain_units
@click.option("--scale", type=float, default=None, help="Multiply the record by this factor.")
@click.option("--pga", type=float, default=None, help="Scale the record to this PGA [g].")
@click.option("--flip", is_flag=True, help="Reverse the polarity.")
@click.option(
    "--trim",
    "window",
    default=None,
    metavar="T0,T1",
    help="Keep the window T0 ≤ t ≤ T1 [s], time re-zeroed.",
)
@click.option(
    "--resample",
    "new_dt",
    type=float,
    default=None,
    help="Resample to this time step [s] (linear interpolation).",
)
@plain_output
def convert(
    file: str,
    record_format: str | None,
    dt: float | None,
    units: str | None,
    scale: float | None,
    pga: float | None,
    flip: bool,
    window: str | None,
    new_dt: float | None,
    output: str,
) -> None:
    """Read a record FILE, transform it and write it as two-column plain text in g.

    The transformations apply in this order: trim, resample, scale or scale to a PGA, flip;
    each is noted in the file's header.
    """
    from rockcli.cli.options import load_record, scale_record
    from rockcli.records import transform
    from rockcli.records.files import write_plain

    rec = load_record(file, record_format, dt, units, None, None)
    span = _window(window)
    if span is not None:
        rec = transform.trim(rec, *span)
    if new_dt is not None:
        rec = transform.resample(rec, new_dt)
    if scale is not None or pga is not None:
        rec = scale_record(rec, scale, pga)
    if flip:
        rec = transform.flip(rec)
    write_plain(rec, output)
    click.echo(f"wrote {output}: {rec.npts} samples, dt = {rec.dt:g} s, PGA {rec.pga:.4g} g")


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
@plain_output
def pulse(
    kind: str, amplitude: float, period: float, dt: float, duration: float | None, output: str
) -> None:
    """Write a synthetic pulse KIND as a two-column plain-text record."""
    from rockcli.records.files import write_plain
    from rockcli.records.pulses import make_pulse

    rec = make_pulse(kind, amplitude, period, dt=dt, total=duration)
    write_plain(rec, output)
    click.echo(f"wrote {output}: {rec.name}, {rec.npts} samples, dt = {rec.dt:g} s")
