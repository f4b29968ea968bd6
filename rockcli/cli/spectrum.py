"""`rock record spectrum FILE…`: the elastic response spectra of records (table, JSON, CSV, plot).

Registered on the `record` group (``cli/record.py``). The spectra come from the code check's
own integrator (:func:`rockcli.codecheck.response.response_spectrum`, exact between samples).
"""

from __future__ import annotations

import math

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    ASCII_FLOAT,
    announce_written,
    check_outputs,
    force_option,
    output_format_csv,
    plain_dt,
    plain_units,
    record_format,
)
from rockcli.cli.plot_option import plot_option
from rockcli.records.periods import GRID_COUNT, GRID_FIRST, GRID_LAST

DAMPING_ALLOWED = "a fraction of critical, 0 < ζ < 1 (0.05 = 5 %)"


@click.command(
    "spectrum", cls=RockCommand, short_help="Elastic response spectra (Sa, Sd) of record FILES."
)
@click.argument("files", nargs=-1, required=True, type=InputPath())
@record_format
@plain_dt
@plain_units
@click.option(
    "--scale", type=ASCII_FLOAT, default=None, help="Multiply every record by this factor."
)
@click.option("--pga", type=ASCII_FLOAT, default=None, help="Scale every record to this PGA [g].")
@click.option(
    "--damping",
    type=ASCII_FLOAT,
    default=0.05,
    show_default=True,
    help="Viscous damping ratio, a fraction of critical (0.05 = 5 %).",
)
@click.option(
    "--periods",
    default=None,
    metavar="T1,T2,…|START:STOP:N",
    help=f"Periods [s]: a list (0.1,0.2,0.5) or N log-spaced from START to STOP (0.05:4:100) "
    f"[default: {GRID_COUNT} log-spaced from {GRID_FIRST:g} to {GRID_LAST:g} s and the round "
    "periods 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.75, 1, 1.5, 2, 3 s].",
)
@output_format_csv("A table (up to 3 records), one JSON document, or CSV (a row per period).")
@plot_option
@force_option
def spectrum(files, record_format, dt, units, scale, pga, damping, periods, output, plot_path,
             force):  # fmt: skip
    """Elastic response spectra of record FILES: pseudo-acceleration Sa [g] and displacement
    Sd [m] against the period T.

    Sd is the peak relative displacement of a linear oscillator (period T, damping ζ) at rest
    at the first sample, integrated exactly between samples, its free vibration after the
    record included; Sa = ω²·Sd with ω = 2π/T (so Sa tends to the PGA as T → 0 for a record
    that starts at rest). --scale and --pga apply to every record.
    """
    from rockcli.cli.options import load_record
    from rockcli.codecheck.response import response_spectrum
    from rockcli.records.periods import parse_periods
    from rockcli.terminal.spectrum import spectrum_document, unique_names

    _check_damping(damping)
    grid = parse_periods(periods)
    _check_table_size(output, len(files))
    check_outputs(force, plot=plot_path)
    records = [load_record(file, record_format, dt, units, scale, pga) for file in files]
    spectra = [
        response_spectrum(rec.time, rec.accel, grid, damping, compiled=True) for rec in records
    ]
    doc = spectrum_document(unique_names(records), damping, grid, spectra)
    if plot_path:
        from rockcli.plots.spectrum import plot_spectra

        plot_spectra(doc, plot_path)
        announce_written(plot_path)
    _show(doc, records, output)


def _check_damping(damping: float) -> None:
    """0 < ζ < 1 (InputError naming --damping; NaN refused too)."""
    from rockcli.errors import InputError

    if not (math.isfinite(damping) and 0.0 < damping < 1.0):
        raise InputError("out of range", where="--damping", value=damping, allowed=DAMPING_ALLOWED)


def _check_table_size(output: str, count: int) -> None:
    """A table shows at most MAX_TABLE_RECORDS records (InputError otherwise)."""
    from rockcli.errors import InputError
    from rockcli.terminal.spectrum import MAX_TABLE_RECORDS

    if output == "table" and count > MAX_TABLE_RECORDS:
        raise InputError(
            f"{count} records do not fit in a table",
            where="--format",
            value=output,
            allowed=f"--format table with up to {MAX_TABLE_RECORDS} files, or --format json|csv",
        )


def _show(doc, records, output: str) -> None:
    """The spectra on stdout as a table, JSON or CSV; with JSON or CSV warnings on stderr."""
    from rockcli.terminal.spectrum import spectrum_csv, spectrum_report
    from rockcli.terminal.table import show

    if output != "table":
        for rec in records:
            for warning in rec.warnings:
                click.echo(f"warning: {rec.name}: {warning}", err=True)
    if output == "csv":
        click.echo(spectrum_csv(doc), nl=False)
        return
    show(doc, output, lambda d: spectrum_report(d, records))
