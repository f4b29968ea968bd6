"""`rock compare MODEL --record FILE`: the code check and the rocking analysis side by side."""

from __future__ import annotations

import click

from rockcli.cli.options import (
    announce_written,
    check_hazard_grid,
    check_outputs,
    edition_option,
    engine_option,
    exit_if_non_finite,
    force_option,
    ground_option,
    hazard_grid_option,
    load_record,
    output_format,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option

#: Exit code of --fail-on when the classification matches (as assess's --fail-on-overturn).
EXIT_FAIL_ON = 1
#: The classifications of rockcli.studies.compare.Classification (kept here as strings so
#: that `rock --help` does not import the studies).
CLASSIFICATIONS = (
    "consistent-safe",
    "consistent-unsafe",
    "code-conservative",
    "code-unconservative",
    "undetermined",
)
#: The values of --code-demand (rockcli.studies.compare.CodeDemand).
CODE_DEMANDS = ("record", "model")


def refuse_record_demand(record_demand: bool) -> None:
    """--record-demand is the default now: refused with the way out (0.x, no silent alias)."""
    from rockcli.errors import InputError

    if record_demand:
        raise InputError(
            "removed: the record's spectrum is the code demand by default now",
            where="--record-demand",
            allowed="drop --record-demand (--code-demand model uses the model's spectrum)",
        )


@click.command()
@click.argument("model_path", metavar="MODEL", type=click.Path(dir_okay=False))
@with_record_options()
@edition_option
@engine_option
@ground_option
@click.option(
    "--code-demand",
    type=click.Choice(CODE_DEMANDS),
    default="record",
    show_default=True,
    help="The code check's demand: the record's response spectrum (one earthquake on both "
    "sides), or the model's own code spectrum ([ntc.demand] or [ntc.site]; the two sides then "
    "see different earthquakes).",
)
@click.option("--record-demand", is_flag=True, hidden=True)
@hazard_grid_option
@click.option(
    "--fail-on",
    "fail_on",
    multiple=True,
    type=click.Choice(CLASSIFICATIONS),
    help=f"Exit with code {EXIT_FAIL_ON} when the classification is this one (repeatable), "
    "so CI can gate on it.",
)
@plot_option
@force_option
@output_format
def compare(
    model_path,
    record_path,
    record_format,
    dt,
    units,
    scale,
    pga,
    edition,
    engine,
    ground,
    code_demand,
    record_demand,
    grid_file,
    fail_on,
    plot_path,
    force,
    output,
):
    """Kinematic check and rocking time history of MODEL on the same record, side by side."""
    from rockcli.report.compare import (
        comparison_output_document,
        comparison_report,
        comparison_warnings,
    )
    from rockcli.report.table import show
    from rockcli.studies.compare import run_comparison_output

    refuse_record_demand(record_demand)
    check_hazard_grid(
        grid_file, model_path, demand_from="--record" if code_demand == "record" else None
    )
    check_outputs(force, plot=plot_path)
    record = load_record(record_path, record_format, dt, units, scale, pga)
    out = run_comparison_output(
        model_path,
        record,
        engine=engine,
        edition=edition,
        grid_file=grid_file,
        code_demand=code_demand,
        history=plot_path is not None,
        ground=ground,
    )
    doc, rocking = comparison_output_document(out, record), out.rocking
    doc["warnings"] = comparison_warnings(doc)
    if plot_path:
        from rockcli.report.plots import plot_comparison

        runs = rocking.result.runs
        shaking = rocking.shaking or record
        plot_comparison(doc, runs, plot_path, record=shaking, overturn_angle=rocking.overturn_angle)
        announce_written(plot_path)
    show(doc, output, comparison_report)
    exit_if_non_finite(doc["rocking"]["runs"])
    if doc["classification"] in fail_on:
        raise SystemExit(EXIT_FAIL_ON)
