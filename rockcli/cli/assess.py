"""`rock assess MODEL --record FILE`: the rocking time history, both polarities."""

from __future__ import annotations

import click

from rockcli.cli.exits import EXIT_GATE
from rockcli.cli.options import (
    announce_written,
    check_outputs,
    engine_option,
    exit_if_non_finite,
    force_option,
    ground_option,
    load_record,
    output_format,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option

#: Exit code of --fail-on-overturn when the block overturns (documented in the README).
EXIT_OVERTURNS = EXIT_GATE


@click.command()
@click.argument("model_path", metavar="MODEL", type=click.Path(dir_okay=False))
@with_record_options()
@engine_option
@ground_option
@click.option(
    "--history",
    "history_path",
    type=click.Path(dir_okay=False),
    default=None,
    help="Write the worse polarity's history to this CSV file: t, ground acceleration, θ, θ̇ "
    "and each restrainer's force.",
)
@click.option(
    "--fail-on-overturn",
    is_flag=True,
    help=f"Exit with code {EXIT_OVERTURNS} when the block overturns (for CI gates).",
)
@plot_option
@force_option
@output_format
def assess(
    model_path,
    record_path,
    record_format,
    dt,
    units,
    scale,
    pga,
    engine,
    ground,
    history_path,
    fail_on_overturn,
    plot_path,
    force,
    output,
):
    """Rocking time history of MODEL under a record, both polarities, with the verdict."""
    from rockcli.report.assess import assessment_output_document
    from rockcli.studies.assess import run_assessment_output

    check_outputs(force, history=history_path, plot=plot_path)
    record = load_record(record_path, record_format, dt, units, scale, pga)
    history = history_path is not None or plot_path is not None
    out = run_assessment_output(model_path, record, engine, history=history, ground=ground)
    shaking = out.shaking or record
    doc = assessment_output_document(out, record)
    if history_path:
        from rockcli.outfile import write_text
        from rockcli.report.assess import history_csv

        write_text(
            history_path,
            history_csv(out.result.worst, record, doc["model"], out.shaking),
            where="--history",
        )
        announce_written(history_path)
    if plot_path:
        from rockcli.report.plots import plot_assessment

        plot_assessment(
            doc, out.result.runs, plot_path, record=shaking, overturn_angle=out.overturn_angle
        )
        announce_written(plot_path)
    from rockcli.report.assess import assessment_report
    from rockcli.report.table import show

    show(doc, output, assessment_report)
    exit_if_non_finite(doc["runs"])
    if fail_on_overturn and doc["verdict"] == "overturns":
        raise SystemExit(EXIT_OVERTURNS)
