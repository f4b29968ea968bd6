"""`rock spectrum overturning`: the lowest overturning pulse against ωp/p, or the lowest
overturning scale of records against the block's size or the building's period
(rockcli.studies.fragility.spectrum), run on the sweep's executor
(rockcli.studies.fragility.overturning); the options are read into the plan of the runs by
rockcli.cli.overturning.plan."""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommands
from rockcli.cli.options import (
    ASCII_FLOAT,
    announce_written,
    check_outputs,
    engine_option,
    force_option,
    jobs_option,
    output_format_csv,
    plain_dt,
    plain_units,
    progress_option,
    record_format,
    scheduler_option,
)
from rockcli.cli.overturning.plan import (
    DEFAULT_RATIOS,
    PULSES,
    block_sizes,
    check_mode,
    make_scan,
    model_sizes,
    pulse_plan,
    read_records,
    validated,
)
from rockcli.cli.plot_option import plot_option


@click.group(cls=RockCommands, short_help="Overturning spectra of pulses and records.")
def spectrum() -> None:
    """Spectra of rocking blocks: the lowest intensity that overturns, point by point."""


@spectrum.command(short_help="Lowest overturning pulse or record scale, as a spectrum.")
@click.option(
    "--pulse",
    type=click.Choice(PULSES),
    default=None,
    help="A pulse spectrum: the lowest ap that overturns against ωp/p.",
)
@click.option(
    "--record",
    "record_paths",
    multiple=True,
    type=InputPath(),
    help="A record spectrum (repeat for several): the lowest scale that overturns "
    "against the size (--p or --R) or the building's period (--floor-periods).",
)
@record_format
@plain_dt
@plain_units
@click.option("--alpha", type=ASCII_FLOAT, default=None, help="A block of slenderness α [rad].")
@click.option(
    "--e",
    "e",
    type=ASCII_FLOAT,
    default=None,
    help="The block's restitution [default: Housner's, 1 − 1.5 sin²α].",
)
@click.option("--linearized", is_flag=True, help="The block's linearized equation (sin x ≈ x).")
@click.option(
    "--model",
    "model_path",
    type=InputPath(),
    default=None,
    help="MODEL's block or mechanism (instead of --alpha).",
)
@click.option("--mechanism", default=None, help="The wall's mechanism to rock (with --model).")
@click.option(
    "--ground",
    is_flag=True,
    help="With --model at height: the pulse at the block's base, not its floor's.",
)
@click.option(
    "--ratios",
    default=None,
    metavar="R1,R2,…",
    help=f"The pulses' ωp/p [default: {DEFAULT_RATIOS}].",
)
@click.option(
    "--p",
    "p_values",
    default=None,
    metavar="P1,P2,…",
    help="Records: the blocks' frequency parameters p [rad/s] (α kept).",
)
@click.option(
    "--R",
    "R_values",
    default=None,
    metavar="R1,R2,…",
    help="Records: the blocks' semi-diagonals R [m] (α kept).",
)
@click.option(
    "--floor-periods",
    "floor_periods",
    default=None,
    metavar="T1,T2,…",
    help="Records with --model at height: the building's periods T1 [s] (its floor motion "
    "follows).",
)
@click.option(
    "--scan-from",
    type=ASCII_FLOAT,
    default=1.0,
    show_default=True,
    help="The scan's first intensity, ap/a0 or PGA·scale/a0 (a0: the uplift "
    "acceleration; nothing uplifts below 1).",
)
@click.option(
    "--scan-step",
    type=ASCII_FLOAT,
    default=0.05,
    show_default=True,
    help="The scan's step (a window of overturning narrower than it can be missed).",
)
@click.option(
    "--scan-to",
    type=ASCII_FLOAT,
    default=20.0,
    show_default=True,
    help="The scan's last intensity.",
)
@click.option(
    "--tolerance",
    type=ASCII_FLOAT,
    default=1e-3,
    show_default=True,
    help="The bisection's last bracket inside the first overturning step.",
)
@engine_option
@jobs_option("Workers: this process and N − 1 worker processes (one spectrum point each).")
@scheduler_option
@progress_option
@output_format_csv("A table, one JSON document, or CSV.")
@plot_option
@force_option
def overturning(
    pulse,
    record_paths,
    record_format,
    dt,
    units,
    alpha,
    e,
    linearized,
    model_path,
    mechanism,
    ground,
    ratios,
    p_values,
    R_values,
    floor_periods,
    scan_from,
    scan_step,
    scan_to,
    tolerance,
    engine,
    jobs,
    scheduler,
    progress,
    output,
    plot_path,
    force,
):
    """The overturning spectrum: for each pulse ωp/p (--pulse) the lowest ap/a0 that
    overturns the block (--alpha, or --model), or for each block size (--p or --R, of
    --alpha or of --model's block) or building period (--floor-periods, --model at height)
    the lowest scale of each --record that overturns it. a0 is the uplift
    acceleration (g·tan α for a block). The search scans the intensity up at --scan-step and
    bisects inside the first step that overturns: the lowest overturn, not a boundary of the
    safe region above it (docs/spectra.md)."""
    scan = make_scan(scan_from, scan_step, scan_to, tolerance)
    check_outputs(force, plot=plot_path)
    if pulse is not None:
        check_mode(
            "--pulse", record=record_paths, p=p_values, R=R_values, floor_periods=floor_periods
        )
        target, subject, cases = pulse_plan(
            pulse, ratios, alpha, e, linearized, model_path, mechanism, ground, engine, scan
        )
    else:
        check_mode("--record", ratios=ratios)
        records = read_records(record_paths, record_format, dt, units)
        if model_path is None:
            check_mode("--alpha", mechanism=mechanism, ground=ground, floor_periods=floor_periods)
            target, subject, cases, sizes = block_sizes(
                records, alpha, e, linearized, p_values, R_values, engine
            )
        else:
            check_mode("--model", e=e is not None, linearized=linearized, alpha=alpha is not None)
            target, subject, cases, sizes = model_sizes(
                records, model_path, mechanism, ground, p_values, R_values, floor_periods, engine
            )
    rows = run_points(target, scan, cases, jobs, scheduler, progress)
    doc = (
        pulse_doc(pulse, cases, rows, scan, subject, target)
        if pulse is not None
        else record_doc(records, sizes, rows, scan, subject)
    )
    show_spectrum(doc, output, plot_path)


def run_points(target, scan, cases, jobs, scheduler, progress):
    """Every point's row, on local workers or a dask cluster, with a progress bar."""
    from rockcli.cli.sweep import worker_count
    from rockcli.studies.fragility.overturning import run_spectrum
    from rockcli.studies.parallel.executor import dask_executor, local_executor
    from rockcli.terminal.sweep import progress_bar

    where = (
        dask_executor(scheduler) if scheduler else local_executor(worker_count(jobs, len(cases)))
    )
    with where as lanes, progress_bar(progress, "points") as bar:
        return run_spectrum(target, scan, cases, lanes, bar)


def pulse_doc(pulse, cases, rows, scan, subject, target):
    """The pulse spectrum's document; its threshold in units of the block's a0, named."""
    from rockcli.terminal.overturning import pulse_document

    if subject["kind"] == "model" and not _plain_block(target):
        name = "a_p/a_0"
    else:
        name = "a_p/(g alpha)" if rows[0]["linearized"] else "a_p/(g tan alpha)"
    return pulse_document(pulse, [c.ratio for c in cases], rows, scan, subject, name)


def _plain_block(target) -> bool:
    """The model's mechanism rocked is the paper's rectangle without loads, restrainers or a
    stopped side (its a0 is g·tan α, or g·α)."""
    from rockcli.mechanics import Block
    from rockcli.studies.fragility.overturning import rocked_block

    block, _ = rocked_block(validated(target), target)
    plain = not block.loaded and not block.restrainers and not block.one_sided
    return isinstance(block, Block) and plain


def record_doc(records, sizes, rows, scan, subject):
    """The record spectrum's document: ``sizes`` (option, values), rows record by record."""
    from rockcli.terminal.overturning import records_document

    option, values = sizes
    per = [rows[i * len(values) : (i + 1) * len(values)] for i in range(len(records))]
    named = [
        {"name": rec.name, "file": rec.source, "pga_g": float(abs(rec.accel).max())}
        for rec in records
    ]
    name = {"--p": "p", "--R": "R", "--floor-periods": "T1"}[option]
    return records_document(named, name, values, per, scan, subject)


def show_spectrum(doc, output: str, plot_path: str | None) -> None:
    """The plot (when asked), then the table, JSON or CSV on stdout."""
    from rockcli.terminal.overturning import overturning_csv, overturning_report
    from rockcli.terminal.table import show

    if plot_path:
        from rockcli.plots.overturning import plot_overturning

        plot_overturning(doc, plot_path)
        announce_written(plot_path)
    if output == "csv":
        click.echo(overturning_csv(doc), nl=False)
        return
    show(doc, output, overturning_report)
