"""`rock sweep STUDY`: a systemic study, in parallel, with the paper's summary tables."""

from __future__ import annotations

import os
import time

import click

from rockcli.cli.options import output_format
from rockcli.cli.plot_option import plot_option


@click.command()
@click.argument("study_path", metavar="STUDY", type=click.Path(dir_okay=False))
@click.option(
    "--out",
    "out",
    default=None,
    type=click.Path(file_okay=False),
    help="Output folder for cases.csv and summary.json [default: ./sweep-STUDY].",
)
@click.option(
    "--jobs",
    "-j",
    type=click.IntRange(min=1),
    default=None,
    help="Workers on this machine: this process and N − 1 worker processes "
    "[default: the CPU count].",
)
@click.option("--resume", is_flag=True, help="Skip the cases an interrupted run finished.")
@click.option("--overwrite", is_flag=True, help="Start over in an output folder in use.")
@click.option(
    "--scheduler",
    default=None,
    envvar="DASK_SCHEDULER_ADDRESS",
    show_envvar=True,
    metavar="ADDRESS",
    help="Run on a dask cluster, e.g. tcp://host:8786 (needs rockcli[dask]).",
)
@click.option(
    "--records-dir",
    default=None,
    envvar="ROCK_RECORDS_DIR",
    show_envvar=True,
    type=click.Path(file_okay=False),
    help="Folder the study's record paths are relative to (replaces records_dir).",
)
@click.option(
    "--chunk-size",
    type=click.IntRange(min=1),
    default=None,
    help="Cases per chunk [default: about 1 s of work].",
)
@click.option(
    "--progress/--no-progress",
    default=None,
    help="Progress bar on stderr [default: when stderr is a terminal].",
)
@plot_option
@output_format
def sweep(
    study_path,
    out,
    jobs,
    resume,
    overwrite,
    scheduler,
    records_dir,
    chunk_size,
    progress,
    plot_path,
    output,
):
    """Run the study STUDY.toml: every case, in parallel, with the paper's summary tables.

    The study names a base model, the axes (model fields by key path), the records and the
    analyses (examples/studies/). Every case goes to OUT/cases.csv as its chunk completes;
    --resume continues an interrupted study.
    """
    from rockcli.report.sweep import progress_bar, sweep_report
    from rockcli.report.table import show
    from rockcli.studies.sweep.executor import dask_executor, local_executor
    from rockcli.studies.sweep.run import run_sweep
    from rockcli.studies.sweep.study import load_study
    from rockcli.studies.sweep.worker import quick_exit

    started = time.perf_counter()
    quick_exit()
    if resume and overwrite:
        raise click.UsageError("--resume and --overwrite exclude each other")
    plan = load_study(study_path, records_dir)
    jobs = jobs or os.cpu_count() or 1
    out = out or f"sweep-{os.path.splitext(os.path.basename(study_path))[0]}"
    where = dask_executor(scheduler) if scheduler else local_executor(jobs)
    facts = {"jobs": None if scheduler else jobs, "scheduler": scheduler}
    with where as lanes, progress_bar(progress) as bar:
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
        )
    if plot_path:
        from rockcli.report.plots import plot_sweep

        plot_sweep(result.cases, plot_path, by=result.split)
    show(result.summary, output, sweep_report)
