"""`rock compare MODEL --record FILE`: the code check and the rocking analysis side by side."""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    allow_outside_option,
    announce_written,
    check_allow_outside,
    check_hazard_grid,
    check_outputs,
    check_record_options,
    edition_option,
    engine_option,
    exit_if_non_finite,
    force_option,
    ground_option,
    hazard_grid_option,
    jobs_option,
    load_record,
    output_format,
    suite_option,
    target_option,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option

#: Exit code of --fail-on when the classification matches (as assess's --fail-on-overturn).
EXIT_FAIL_ON = 1
#: The classifications of rockcli.analyses.compare.Classification (kept here as strings so
#: that `rock --help` does not import the studies).
CLASSIFICATIONS = (
    "consistent-safe",
    "consistent-unsafe",
    "code-conservative",
    "code-unconservative",
    "undetermined",
)
#: The values of --code-demand with --record (rockcli.analyses.compare.CodeDemand) and with
#: --suite (rockcli.studies.suite_run.compare.SuiteCodeDemand); the first of each is the default.
RECORD_DEMANDS = ("record", "model")
SUITE_DEMANDS = ("target", "suite-mean")


def refuse_record_demand(record_demand: bool) -> None:
    """--record-demand is the default now: refused with the way out (0.x, no silent alias)."""
    from rockcli.errors import InputError

    if record_demand:
        raise InputError(
            "removed: the record's spectrum is the code demand by default now",
            where="--record-demand",
            allowed="drop --record-demand (--code-demand model uses the model's spectrum)",
        )


@click.command(
    cls=RockCommand, short_help="Code check and rocking time history of MODEL, side by side."
)
@click.argument("model_path", metavar="MODEL", type=InputPath())
@with_record_options(required=False)
@suite_option(
    "A record suite file (TOML; rock suite check), or a folder of records with --target: "
    "every record through the time history by the code's rule, against the code check on "
    "the suite's target spectrum."
)
@target_option
@allow_outside_option
@jobs_option("With --suite: workers, this process and N − 1 worker processes.")
@edition_option
@engine_option
@ground_option
@click.option(
    "--code-demand",
    type=click.Choice(RECORD_DEMANDS + SUITE_DEMANDS),
    default=None,
    help="The code check's demand. With --record: record (default), the record's response "
    "spectrum (one earthquake on both sides), or model, the model's own code spectrum "
    "([ntc.demand] or [ntc.site]; the two sides then see different earthquakes). With "
    "--suite: target (default), the suite's target spectrum, or suite-mean, the mean "
    "spectrum of its records.",
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
@click.option(
    "--mechanism",
    "mechanism_name",
    default=None,
    metavar="NAME",
    help="A wall's mechanism to compare in full (default: the governing one); every mechanism "
    "is listed either way.",
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
    suite_path,
    target,
    allow_outside,
    jobs,
    edition,
    engine,
    ground,
    code_demand,
    record_demand,
    grid_file,
    fail_on,
    mechanism_name,
    plot_path,
    force,
    output,
):
    """Kinematic check and rocking time history of MODEL on the same record (or suite of
    records), side by side."""
    from rockcli.analyses.compare import run_comparison_output
    from rockcli.cli.assess import one_record_or_suite
    from rockcli.terminal.compare import (
        comparison_output_document,
        comparison_report,
        comparison_warnings,
    )
    from rockcli.terminal.table import show

    refuse_record_demand(record_demand)
    check_allow_outside(allow_outside, suite_path)
    with_suite = one_record_or_suite(record_path, suite_path, None, plot_path, None, target)
    code_demand = demand_for(code_demand, with_suite)
    if with_suite:
        check_record_options(None, record_format, dt, units, scale, pga)
        if mechanism_name is not None:
            from rockcli.errors import InputError

            raise InputError("not with --suite yet", where="--mechanism", value=mechanism_name,
                             allowed="--mechanism with --record")  # fmt: skip
        doc = compare_with_suite(
            model_path, (suite_path, target, allow_outside), grid_file, code_demand, edition,
            engine, ground, jobs, output,
        )  # fmt: skip
        if doc["classification"] in fail_on:
            raise SystemExit(EXIT_FAIL_ON)
        return
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
        mechanism=mechanism_name,
    )
    doc, rocking = comparison_output_document(out, record), out.rocking
    doc["warnings"] = comparison_warnings(doc)
    if plot_path:
        from rockcli.plots import plot_comparison

        runs = rocking.result.runs
        shaking = rocking.shaking or record
        plot_comparison(doc, runs, plot_path, record=shaking, overturn_angle=rocking.overturn_angle)
        announce_written(plot_path)
    show(doc, output, comparison_report)
    exit_if_non_finite(doc["rocking"]["runs"])
    if doc["classification"] in fail_on:
        raise SystemExit(EXIT_FAIL_ON)


def demand_for(code_demand: str | None, with_suite: bool) -> str:
    """--code-demand's value, its default for a record or a suite; InputError for a value of
    the other kind."""
    from rockcli.errors import InputError

    allowed = SUITE_DEMANDS if with_suite else RECORD_DEMANDS
    if code_demand is None:
        return allowed[0]
    if code_demand not in allowed:
        raise InputError(
            "applies to " + ("a record, not a suite" if with_suite else "a suite (--suite)"),
            where="--code-demand",
            value=code_demand,
            allowed=" or ".join(allowed) + (" with --suite" if with_suite else " with --record"),
        )
    return code_demand


def compare_with_suite(
    model_path, suite, grid_file, code_demand, edition, engine, ground, jobs, output
) -> dict:
    """The code check and every record of the suite, side by side; the document shown.

    suite: (the suite file or folder, the --target of a folder, --allow-outside)."""
    from rockcli.studies.suite_run.compare import compare_suite
    from rockcli.terminal.suite import suite_comparison_document, suite_comparison_report
    from rockcli.terminal.sweep import progress_bar
    from rockcli.terminal.table import show

    with progress_bar(None) as bar:
        result = compare_suite(
            model_path, suite[0], grid_file, code_demand=code_demand, edition=edition,
            engine=engine, ground=ground, jobs=jobs, progress=bar, target=suite[1],
            allow_outside=suite[2],
        )  # fmt: skip
    doc = suite_comparison_document(result)
    show(doc, output, suite_comparison_report)
    return doc
