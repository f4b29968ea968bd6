"""`rock record`: inspect a ground-motion record file, or generate a synthetic pulse.

The record package (numpy) and rich are imported inside the commands, so that ``rock --help``
starts without them (spec/engine.md, "Speed"). Bad input raises InputError, which the group in
``cli/main.py`` turns into one ``error:`` line and exit code 2.
"""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommands
from rockcli.cli.options import (
    ASCII_FLOAT,
    announce_written,
    force_option,
    output_format,
    plain_dt,
    plain_units,
    record_format,
)
from rockcli.records.kinds import PulseKind

plain_output = click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False, allow_dash=True),
    required=True,
    help="Plain-text file to write (time [s], acceleration [g]); '-' writes to stdout.",
)


def _write_record(rec, output: str, detail: str, made_by: str) -> None:
    """Write the record to ``output`` (or stdout for ``-``); warnings and "wrote" on stderr.

    The record is first checked as every reader checks a record (InputError naming the
    options ``made_by`` when it fails): nothing is written that ``rock record info`` refuses.
    """
    from rockcli import outfile
    from rockcli.records.files import check_to_write, write_plain
    from rockcli.records.plain import format_plain

    check_to_write(rec, made_by=made_by)
    for warning in rec.warnings:
        click.echo(f"warning: {warning}", err=True)
    if outfile.is_stdout(output):
        click.echo(format_plain(rec), nl=False)
        return
    write_plain(rec, output, where="--output", made_by=made_by)
    announce_written(output, detail)


def _named_options(call, options: dict[str, str]):
    """``call()``, its InputError naming the option (``--dt``) where it names the argument."""
    from rockcli.errors import InputError

    try:
        return call()
    except InputError as exc:
        where = options.get(exc.where or "", exc.where)
        raise InputError(
            exc.problem, file=exc.file, where=where, value=exc.value, allowed=exc.allowed
        ) from None


@click.group(
    cls=RockCommands, short_help="Records: inspect, convert, pulses, floor motion, spectra."
)
def record() -> None:
    """Ground-motion records: inspect, convert, generate a pulse, compute a floor motion or
    response spectra."""


@record.command("info", short_help="Format, header, samples, dt, duration and PGA of records.")
@click.argument("files", nargs=-1, required=True, type=InputPath())
@record_format
@plain_dt
@plain_units
@output_format
def info(
    files: tuple[str, ...],
    record_format: str | None,
    dt: float | None,
    units: str | None,
    output: str,
) -> None:
    """Format, header names, samples, dt, duration and PGA of record FILES.

    Reads AT2, ESM, cor.acc and plain text; one table per file, with the event, station and
    component when the file's header names them, then each record's warnings and notes.
    """
    from rockcli.records.files import read_record
    from rockcli.terminal.records import info_document, info_report
    from rockcli.terminal.table import show

    records = [read_record(file, fmt=record_format, dt=dt, units=units) for file in files]
    show(info_document(records), output, info_report)


def _window(value: str | None) -> tuple[float, float] | None:
    from rockcli.errors import InputError
    from rockcli.numbers import ascii_float

    if value is None:
        return None
    try:
        t0, t1 = (ascii_float(x) for x in value.split(","))
    except ValueError:
        raise InputError(
            "not a time window",
            where="--trim",
            value=value,
            allowed="T0,T1 in seconds, e.g. 1.5,20",
        ) from None
    return t0, t1


@record.command("convert", short_help="Trim, resample, scale or flip a record into plain text.")
@click.argument("file", type=InputPath())
@record_format
@plain_dt
@plain_units
@click.option("--scale", type=ASCII_FLOAT, default=None, help="Multiply the record by this factor.")
@click.option("--pga", type=ASCII_FLOAT, default=None, help="Scale the record to this PGA [g].")
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
    type=ASCII_FLOAT,
    default=None,
    help="Resample to this time step [s], 1e-9 to 1 (linear interpolation).",
)
@plain_output
@force_option
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
    force: bool,
) -> None:
    """Read a record FILE, transform it and write it as two-column plain text in g.

    The transformations apply in this order: trim, resample, scale or scale to a PGA, flip;
    each is noted in the file's header. A resampling that lowers the PGA by more than 0.1 %
    warns (on stderr and in the file's header).
    """
    from rockcli import outfile
    from rockcli.cli.options import check_record_options, load_record, scale_record
    from rockcli.records import transform

    check_record_options(file, record_format, dt, units, scale, pga)
    outfile.check_writable(output, force=force, where="--output")
    rec = load_record(file, record_format, dt, units, None, None)
    span = _window(window)
    if span is not None:
        rec = transform.trim(rec, *span)
    if new_dt is not None:
        rec = _named_options(lambda: transform.resample(rec, new_dt), {"dt": "--resample"})
    if scale is not None or pga is not None:
        rec = scale_record(rec, scale, pga)
    if flip:
        rec = transform.flip(rec)
    given = {"--trim": window, "--resample": new_dt, "--scale": scale, "--pga": pga}
    made_by = ", ".join(option for option, value in given.items() if value is not None)
    detail = f"{rec.npts} samples, dt = {rec.dt:g} s, PGA {rec.pga:.4g} g"
    _write_record(rec, output, detail, made_by or "FILE")


@record.command("pulse", short_help="Write a synthetic pulse KIND as a plain-text record.")
@click.argument("kind", type=click.Choice([str(k) for k in PulseKind]))
@click.option(
    "--amplitude", type=ASCII_FLOAT, required=True, help="Peak acceleration ap [g], up to 100."
)
@click.option(
    "--period",
    type=ASCII_FLOAT,
    required=True,
    help="Tp [s], 0.001 to 100: 2π/ωp of the sine pulses (the half-sine lasts Tp/2, one-sine "
    "and one-cosine Tp), 1/fp of the Ricker wavelet (it lasts 3 Tp), the duration of the "
    "rectangular pulse.",
)
@click.option(
    "--dt", type=ASCII_FLOAT, default=0.005, show_default=True, help="Time step [s], 1e-9 to 1."
)
@click.option(
    "--duration",
    type=ASCII_FLOAT,
    default=None,
    help="Total duration [s], zeros after the pulse (default: the pulse alone).",
)
@plain_output
@force_option
def pulse(
    kind: str,
    amplitude: float,
    period: float,
    dt: float,
    duration: float | None,
    output: str,
    force: bool,
) -> None:
    """Write a synthetic pulse KIND as a two-column plain-text record."""
    from rockcli import outfile
    from rockcli.records.pulses import make_pulse

    outfile.check_writable(output, force=force, where="--output")
    options = {"amplitude": "--amplitude", "period": "--period", "dt": "--dt",
               "duration": "--duration"}  # fmt: skip
    rec = _named_options(
        lambda: make_pulse(kind, amplitude, period, dt=dt, total=duration), options
    )
    detail = f"{rec.name}, {rec.npts} samples, dt = {rec.dt:g} s"
    _write_record(rec, output, detail, ", ".join(options.values()))


#: ψ(Z) above this is refused: the mode shapes of the code's formulas stay below it.
MAX_PSI = 1.5


@record.command(
    "floor", short_help="The floor acceleration at a height of a building, as plain text."
)
@click.argument("file", type=InputPath())
@record_format
@plain_dt
@plain_units
@click.option(
    "--T1", "t1", type=ASCII_FLOAT, required=True, help="First-mode period T1 [s], 0.01 to 10."
)
@click.option(
    "--psi", type=ASCII_FLOAT, required=True, help="Mode shape ψ at the element's height, 0 to 1.5."
)
@click.option(
    "--gamma", type=ASCII_FLOAT, required=True, help="Participation factor γ, 0.001 to 3."
)
@click.option(
    "--xi",
    type=ASCII_FLOAT,
    default=0.05,
    show_default=True,
    help="First-mode damping ratio, a fraction of critical (0.05 = 5 %).",
)
@plain_output
@force_option
def floor(
    file: str,
    record_format: str | None,
    dt: float | None,
    units: str | None,
    t1: float,
    psi: float,
    gamma: float,
    xi: float,
    output: str,
    force: bool,
) -> None:
    """Write the floor acceleration at a height of a building under the ground record FILE.

    ü_Z(t) = ü_g(t) + γ·ψ·ẍ₁(t), with ẍ₁ the relative acceleration of the building's first
    mode (a linear oscillator of period T1 and damping ξ, at rest at the first sample) under
    the record, integrated exactly between samples. Written as two-column plain text in g,
    the parameters noted in the header.
    """
    from rockcli import outfile
    from rockcli.cli.options import load_record

    _check_floor_parameters(t1, psi, gamma, xi)
    outfile.check_writable(output, force=force, where="--output")
    rec = _floor_record(load_record(file, record_format, dt, units, None, None), t1, psi, gamma, xi)
    detail = f"{rec.npts} samples, dt = {rec.dt:g} s, PGA {rec.pga:.4g} g"
    _write_record(rec, output, detail, "--T1, --psi, --gamma, --xi")


def _check_floor_parameters(t1: float, psi: float, gamma: float, xi: float) -> None:
    """One InputError naming the option for each value out of range (NaN included).

    T1 and γ take the bounds of the model's building.T1 and building.gamma
    (rockcli.model.bounds): the amplification γ·ψ·ẍ₁ of a γ = 1000 made a 900 g "floor
    motion", and a T1 of 1e300 s or 1e-300 s NaN samples or an overflow.
    """
    from rockcli.errors import InputError
    from rockcli.model.bounds import MAX_PARTICIPATION, MAX_PERIOD, MIN_MODAL, MIN_PERIOD

    checks = (
        ("--T1", t1, MIN_PERIOD <= t1 <= MAX_PERIOD,
         f"a period {MIN_PERIOD:g} s ≤ T1 ≤ {MAX_PERIOD:g} s, as the model's building.T1"),
        ("--psi", psi, 0 <= psi <= MAX_PSI, f"0 ≤ ψ ≤ {MAX_PSI:g}"),
        ("--gamma", gamma, MIN_MODAL <= gamma <= MAX_PARTICIPATION,
         f"{MIN_MODAL:g} ≤ γ ≤ {MAX_PARTICIPATION:g}, as the model's building.gamma"),
        ("--xi", xi, 0 <= xi < 1, "a fraction of critical, 0 ≤ ξ < 1 (0.05 = 5 %)"),
    )  # fmt: skip
    for option, value, ok, allowed in checks:
        if not ok:
            raise InputError("out of range", where=option, value=value, allowed=allowed)


def _floor_record(rec, t1: float, psi: float, gamma: float, xi: float):
    """The record's floor motion, as a Record whose notes say how it was made."""
    from rockcli.analyses.floor import Floor, floor_record

    return floor_record(rec, Floor(Z=None, T1=t1, psi=psi, gamma=gamma, xi=xi))


def _register_spectrum() -> None:
    """`rock record spectrum` lives in its own module (cli/spectrum.py)."""
    from rockcli.cli.spectrum import spectrum

    record.add_command(spectrum)


_register_spectrum()
