"""`rock fragility STUDY.toml` (run IDA or MSA, fit the fragility) and `rock fragility fit`."""

from __future__ import annotations

from typing import TYPE_CHECKING

import click

from rockcli.cli.inputs import InputPath, RockCommand, RockCommands
from rockcli.cli.options import (
    AsciiIntRange,
    output_format,
    overwrite_option,
    progress_option,
    records_dir_option,
    resume_option,
    scheduler_option,
)
from rockcli.cli.plot_option import check_study_plot, plot_option

if TYPE_CHECKING:
    from rockcli.studies.fragility.study import FragilityPlan


class FragilityCommands(RockCommands):
    """``rock fragility STUDY.toml`` runs the study (the hidden ``run`` command); a known
    command name (``fit``) runs that command."""

    def resolve_command(
        self, ctx: click.Context, args: list[str]
    ) -> tuple[str | None, click.Command | None, list[str]]:
        if args and args[0] not in self.commands and not args[0].startswith("-"):
            return "run", self.commands["run"], args
        return super().resolve_command(ctx, args)


@click.group(
    cls=FragilityCommands,
    short_help="Fragility curves: run IDA or MSA on a study, or fit a data set.",
)
def fragility() -> None:
    """Fragility curves: the probability of a damage state given the intensity.

    \b
    rock fragility STUDY.toml [OPTIONS]  run the study's IDA or MSA, fit each state
    rock fragility fit DATA.csv          fit a data set you already have

    `rock fragility run --help` lists the study's options.
    """


@fragility.command(cls=RockCommand, short_help="Fit a lognormal fragility to IDA or MSA data.")
@click.argument("data", type=InputPath("file"))
@click.option(
    "--method",
    type=click.Choice(["msa", "ida"]),
    default="msa",
    show_default=True,
    help="msa: columns im, runs, exceedances (counts at intensity levels); ida: column im "
    "(each record's intensity at which the damage state is first reached) and optionally "
    "censored (1: the record did not reach it up to im).",
)
@click.option(
    "--ddof",
    type=click.Choice(["0", "1"]),
    default="0",
    show_default=True,
    help="IDA: the divisor of β², n (0: the maximum likelihood) or n − 1 (1: Baker 2015).",
)
@output_format
def fit(data, method, ddof, output):
    """Fit P(DS | IM) = Φ(ln(IM/θ)/β) to DATA.csv: the median θ and dispersion β, and a 95 %
    band (MSA: profile likelihood; IDA: exact noncentral-t, or a parametric bootstrap with
    censored records). MSA by maximum likelihood on the binomial counts (Baker 2015); IDA
    as the lognormal of the collapse intensities. At most 10 000 data rows, intensities in
    (0, 1e4]; the band at the data's intensities (at most 100 of them)."""
    import numpy as np

    from rockcli.errors import InputError
    from rockcli.studies.fragility.data import read_data
    from rockcli.studies.fragility.fit import band_points, ida_curve, msa_curve
    from rockcli.terminal.fragility import fit_document, fit_report
    from rockcli.terminal.table import show

    found = read_data(data, method)
    at = band_points(found.im, msa=method == "msa")
    try:
        if method == "ida":
            flags = found.censored if found.censored is not None else np.zeros(found.im.size, bool)
            result, band = ida_curve(found.im[~flags], found.im[flags], at, int(ddof))
        else:
            assert found.runs is not None and found.exceedances is not None
            result, band = msa_curve(found.im, found.runs, found.exceedances, at)
    except ValueError as exc:
        raise InputError(
            str(exc),
            file=data,
            allowed="a data set that defines a fragility "
            "(some runs reach the damage state, some do not)",
        ) from None
    show(fit_document(found, result, at, band), output, fit_report)


@fragility.command(
    "run",
    cls=RockCommand,
    hidden=True,
    short_help="Run a fragility study STUDY.toml (also: rock fragility STUDY.toml).",
)
@click.argument("study_path", metavar="STUDY", type=InputPath())
@click.option(
    "--out",
    default=None,
    type=click.Path(file_okay=False),
    help="Output folder for cases.csv and fragility.json [default: ./fragility-STUDY].",
)
@click.option(
    "--jobs",
    "-j",
    type=AsciiIntRange(min=1),
    default=None,
    help="Workers on this machine: this process and N − 1 worker processes, at most the CPU "
    "count and the number of records × grid points [default: the CPU count].",
)
@resume_option
@overwrite_option
@click.option(
    "--allow-outside",
    is_flag=True,
    help="Let the study's files (model, records) lie outside the study file's folder.",
)
@scheduler_option
@records_dir_option
@progress_option
@click.option(
    "--extrapolate",
    is_flag=True,
    help="--plot: draw the curves beyond the analysed intensities (from 0 to twice the last).",
)
@plot_option
@output_format
def run(
    study_path,
    out,
    jobs,
    resume,
    overwrite,
    allow_outside,
    scheduler,
    records_dir,
    progress,
    extrapolate,
    plot_path,
    output,
):
    """Run the fragility study STUDY.toml: IDA (each record scaled up until each damage state
    is first reached) or MSA (each record at each intensity level), then the lognormal
    fragility of each damage state with its 95 % band.

    Every run goes to OUT/cases.csv as its record completes; --resume continues an
    interrupted study (Ctrl-C or SIGTERM: exit 130, finished records kept).
    """
    import os
    import time

    from rockcli.cli.options import announce_written
    from rockcli.cli.sweep import interrupt_exits, terminate_as_interrupt, worker_count
    from rockcli.studies.fragility.analysis import FragilityInterrupted, run_fragility
    from rockcli.studies.fragility.study import load_fragility
    from rockcli.studies.parallel.executor import dask_executor, local_executor
    from rockcli.terminal.fragility import study_report
    from rockcli.terminal.sweep import progress_bar
    from rockcli.terminal.table import show

    started = time.perf_counter()
    if resume and overwrite:
        raise click.UsageError("--resume and --force exclude each other")
    plan = load_fragility(study_path, records_dir, allow_outside=allow_outside)
    count = len(plan.study.records) * max(1, _points(plan))
    jobs = worker_count(jobs, count)
    out = out or default_out(study_path)
    check_study_plot(plot_path, overwrite, out)
    where = dask_executor(scheduler) if scheduler else local_executor(jobs)
    facts = {"jobs": None if scheduler else jobs, "scheduler": scheduler}
    with interrupt_exits("record", FragilityInterrupted):
        with terminate_as_interrupt(), where as lanes, progress_bar(progress, "records") as bar:
            result = run_fragility(
                plan,
                out,
                lanes,
                resume=resume,
                overwrite=overwrite,
                progress=bar,
                run_facts=facts,
                started=started,
            )
    for name in ("cases.csv", "fragility.json"):
        announce_written(os.path.join(result.out, name))
    if plot_path:
        from rockcli.plots.fragility import grid_points, plot_fragility

        drawn = plot_fragility(result.document, plot_path, extrapolate=extrapolate)
        announce_written(plot_path)
        if drawn < len(grid_points(result.document)):
            click.echo(
                f"note: --plot draws the first {drawn} grid points; every point's fragility "
                "is in fragility.json",
                err=True,
            )
    show(result.document, output, study_report)


def _points(plan: FragilityPlan) -> int:
    import math

    return math.prod(len(a.values) for a in plan.study.axes)


def default_out(study_path: str) -> str:
    """``fragility-STUDY`` in the current folder (cut and hashed when long, as a sweep's)."""
    from rockcli.cli.sweep import default_out as sweep_out

    return "fragility-" + sweep_out(study_path).removeprefix("sweep-")
