"""`rock sweep STUDY`: a systemic study, in parallel, with the paper's summary tables."""

from __future__ import annotations

import os
import signal
import time
from collections.abc import Iterator
from contextlib import contextmanager

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    AsciiIntRange,
    announce_written,
    hazard_grid_option,
    output_format,
    overwrite_option,
    progress_option,
    records_dir_option,
    scheduler_option,
)
from rockcli.cli.plot_option import check_study_plot, plot_option

#: Name prefix of the thread that runs chunks in this process (studies.sweep.executor).
CHUNK_THREAD = "rock-sweep"
#: Exit code after Ctrl-C or SIGTERM (128 + SIGINT, the shell's convention).
EXIT_INTERRUPTED = 130


#: Longest default output folder name (file systems allow 255 bytes; room for a suffix).
OUT_NAME_MAX = 100
#: Hex digits of the study name's hash kept when the default folder name is shortened.
OUT_HASH_DIGITS = 10


def default_out(study_path: str) -> str:
    """``sweep-STUDY`` next to the current folder; a long study name is cut and hashed so the
    folder name stays within the file system's NAME_MAX."""
    import hashlib

    name = "sweep-" + os.path.splitext(os.path.basename(study_path))[0]
    if len(name.encode("utf-8")) <= OUT_NAME_MAX:
        return name
    digest = hashlib.sha256(name.encode("utf-8", "surrogateescape")).hexdigest()
    keep = name.encode("utf-8")[: OUT_NAME_MAX - OUT_HASH_DIGITS - 1].decode("utf-8", "ignore")
    return f"{keep}-{digest[:OUT_HASH_DIGITS]}"


def worker_count(jobs: int | None, cases: int) -> int:
    """--jobs capped at the CPU count and the cases (an idle worker costs ~100 MB); a note on
    stderr when capped. Default: the CPU count."""
    cpus = os.cpu_count() or 1
    wanted = jobs or cpus
    count = max(1, min(wanted, cpus, cases))
    if jobs is not None and count < jobs:
        why = "the CPU count" if count == cpus else "the cases of the study"
        click.echo(f"note: --jobs {jobs} capped to {count} ({why})", err=True)
    return count


def exit_now_if_busy(code: int) -> None:
    """Exit at once when this process's chunk thread is still running a case.

    The interpreter would wait for that case at exit (a case of the reference engine: up to
    tens of seconds); its result is lost anyway, every finished row is on disk (rows are
    written by the main thread only) and the worker processes end with this one.
    """
    import threading

    from rockcli.process import exit_at_once

    if any(t.name.startswith(CHUNK_THREAD) and t.is_alive() for t in threading.enumerate()):
        exit_at_once(code)


@contextmanager
def terminate_as_interrupt() -> Iterator[None]:
    """SIGTERM behaves like Ctrl-C during the study (finished cases saved, exit 130)."""

    def interrupt(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    try:
        previous = signal.signal(signal.SIGTERM, interrupt)
    except ValueError:  # not the main thread (an embedding caller): leave SIGTERM alone
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


@contextmanager
def interrupt_exits(unit: str, saved_type: type[BaseException]) -> Iterator[None]:
    """Ctrl-C or SIGTERM during a study as one line on stderr and exit 130: how many
    ``unit``s are saved (``saved_type``, raised by the study with saved, total and out), or
    that none ran yet."""
    from rockcli.process import interrupted

    try:
        yield
    except saved_type as exc:
        saved, total, out = exc.saved, exc.total, exc.out  # type: ignore[attr-defined]
        click.echo(
            f"interrupted: {saved} of {total} {unit}s saved in {out}; rerun with --resume",
            err=True,
        )
        exit_now_if_busy(EXIT_INTERRUPTED)
        raise SystemExit(EXIT_INTERRUPTED) from None
    except (KeyboardInterrupt, SystemError) as exc:  # SystemError: Ctrl-C in compiled code
        if not interrupted(exc):
            raise
        click.echo(f"interrupted before any {unit} ran", err=True)
        raise SystemExit(EXIT_INTERRUPTED) from None


@click.command(
    cls=RockCommand, short_help="Run a systemic study STUDY.toml in parallel, with its summary."
)
@click.argument("study_path", metavar="STUDY", type=InputPath())
@click.option(
    "--out",
    "out",
    default=None,
    type=click.Path(file_okay=False),
    help="Output folder for cases.csv and summary.json, one rock sweep at a time "
    "[default: ./sweep-STUDY].",
)
@click.option(
    "--jobs",
    "-j",
    type=AsciiIntRange(min=1),
    default=None,
    help="Workers on this machine: this process and N − 1 worker processes, at most the CPU "
    "count and the number of cases [default: the CPU count].",
)
@click.option("--resume", is_flag=True, help="Skip the cases an interrupted run finished.")
@overwrite_option
@click.option(
    "--allow-outside",
    is_flag=True,
    help="Let the study's files (base model, records) lie outside the study file's folder.",
)
@scheduler_option
@records_dir_option
@click.option(
    "--chunk-size",
    type=AsciiIntRange(min=1),
    default=None,
    help="Cases per chunk [default: about 1 s of work].",
)
@progress_option
@click.option(
    "--output",
    "cases_format",
    type=click.Choice(["csv", "parquet"]),
    default="csv",
    show_default=True,
    help="The cases' file: cases.csv, or also cases.parquet (typed columns, for pandas and "
    "polars; needs the parquet extra: pip install '.[parquet]').",
)
@click.option(
    "--check-tolerance",
    is_flag=True,
    help="Run each rocking case again at its tolerances over 1000: a sensitive column in "
    "cases.csv (max θ/α moved by more than 1 % or the overturning verdict changed) and the "
    "count of sensitive cases in the summary. About doubles the rocking time.",
)
@hazard_grid_option
@plot_option
@output_format
def sweep(
    study_path,
    out,
    jobs,
    resume,
    overwrite,
    allow_outside,
    scheduler,
    records_dir,
    chunk_size,
    progress,
    cases_format,
    check_tolerance,
    grid_file,
    plot_path,
    output,
):
    """Run the study STUDY.toml: every case, in parallel, with the paper's summary tables.

    The study names a base model, the axes (model fields by key path), the records and the
    analyses (examples/studies/). Every case goes to OUT/cases.csv as its chunk completes;
    --resume continues an interrupted study (Ctrl-C or SIGTERM: exit 130, finished cases
    kept). A case that fails is a row with its error, and the study goes on; a study in
    which no case succeeds exits 2.
    """
    from rockcli.studies.parallel.executor import dask_executor, local_executor
    from rockcli.studies.sweep.cases import expand
    from rockcli.studies.sweep.run import SweepInterrupted, run_sweep
    from rockcli.studies.sweep.study import load_study
    from rockcli.terminal.sweep import progress_bar, sweep_report
    from rockcli.terminal.table import show

    started = time.perf_counter()
    if resume and overwrite:
        raise click.UsageError("--resume and --force exclude each other")
    check_parquet(cases_format)
    plan = load_study(study_path, records_dir, allow_outside=allow_outside, grid_file=grid_file)
    if check_tolerance:
        from dataclasses import replace

        plan = replace(plan, check_tolerance=True)
    jobs = worker_count(jobs, len(expand(plan)))
    out = out or default_out(study_path)
    check_study_plot(plot_path, overwrite, out)
    where = dask_executor(scheduler) if scheduler else local_executor(jobs)
    facts = {"jobs": None if scheduler else jobs, "scheduler": scheduler}
    with interrupt_exits("case", SweepInterrupted):
        with terminate_as_interrupt(), where as lanes, progress_bar(progress) as bar:
            result = run_sweep(
                plan,
                out,
                lanes,
                resume=resume,
                overwrite=overwrite,
                chunk_size=chunk_size,
                progress=bar,
                run_facts=facts,
                started=started,
                parquet=cases_format == "parquet",
            )
    names = ("cases.csv", "cases.parquet") if cases_format == "parquet" else ("cases.csv",)
    for name in (*names, "summary.json"):
        announce_written(os.path.join(result.out, name))
    if plot_path:
        from rockcli.plots import plot_sweep
        from rockcli.studies.sweep.run import plot_rows

        plot_sweep(plot_rows(plan, result.out), plot_path, by=result.split)
        announce_written(plot_path)
    show(result.summary, output, sweep_report)


def check_parquet(cases_format: str) -> None:
    """Refuse --output parquet without pyarrow, before any work (InputError naming the extra)."""
    if cases_format != "parquet":
        return
    from rockcli.studies.sweep.output import PARQUET_EXTRA, parquet_available

    if not parquet_available():
        from rockcli.errors import InputError

        raise InputError(
            "needs pyarrow, which is not installed",
            where="--output parquet",
            allowed=PARQUET_EXTRA + ", or --output csv",
        )
