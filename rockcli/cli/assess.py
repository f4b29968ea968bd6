"""`rock assess MODEL --record FILE`: the rocking time history, both polarities."""

from __future__ import annotations

import click

from rockcli.cli.exits import EXIT_GATE
from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    allow_outside_option,
    announce_written,
    check_allow_outside,
    check_outputs,
    check_record_options,
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

#: Exit code of --fail-on-overturn when the block overturns (documented in the README).
EXIT_OVERTURNS = EXIT_GATE


@click.command(cls=RockCommand, short_help="Rocking time history of MODEL on a record or a suite.")
@click.argument("model_path", metavar="MODEL", type=InputPath())
@with_record_options(required=False)
@suite_option(
    "A record suite file (TOML; rock suite check), or a folder of records with --target: "
    "every record, both polarities, and the code's rule (the mean over 7 or more records, "
    "the worst over 3–6)."
)
@hazard_grid_option
@target_option
@allow_outside_option
@jobs_option("With --suite: workers, this process and N − 1 worker processes.")
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
@click.option(
    "--mechanism",
    "mechanism_name",
    default=None,
    metavar="NAME",
    help="A wall's mechanism to rock (overturning, wedge, vertical flexure, gable; default: "
    "the governing one of the code check, under the model's demand or else the record's).",
)
@click.option(
    "--all",
    "all_mechanisms",
    is_flag=True,
    help="Rock every mechanism of a wall, one after the other.",
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
    suite_path,
    target,
    allow_outside,
    grid_file,
    jobs,
    engine,
    ground,
    history_path,
    fail_on_overturn,
    mechanism_name,
    all_mechanisms,
    plot_path,
    force,
    output,
):
    """Rocking time history of MODEL under a record (or every record of a suite), both
    polarities, with the verdict."""
    from rockcli.analyses.assess import run_assessment_output
    from rockcli.terminal.assess import assessment_output_document

    check_allow_outside(allow_outside, suite_path)
    if one_record_or_suite(record_path, suite_path, history_path, plot_path, grid_file, target):
        check_record_options(None, record_format, dt, units, scale, pga)
        if all_mechanisms:
            from rockcli.errors import InputError

            raise InputError(
                "is one record's: not with --suite",
                where="--all",
                allowed="--record FILE --all, or --suite with --mechanism NAME",
            )
        return assess_with_suite(
            model_path, (suite_path, target, allow_outside), grid_file, engine, ground, jobs,
            output, mechanism_name,
        )  # fmt: skip
    check_outputs(force, history=history_path, plot=plot_path)
    record = load_record(record_path, record_format, dt, units, scale, pga)
    if all_mechanisms:
        singles = (mechanism_name, history_path, plot_path)
        return assess_every_mechanism(
            model_path, record, engine, ground, output, fail_on_overturn, singles
        )
    history = history_path is not None or plot_path is not None
    out = run_assessment_output(
        model_path, record, engine, history=history, ground=ground, mechanism=mechanism_name
    )
    shaking = out.shaking or record
    doc = assessment_output_document(out, record)
    if history_path:
        from rockcli.outfile import write_text
        from rockcli.terminal.assess import history_csv

        write_text(
            history_path,
            history_csv(out.result.worst, record, doc["model"], out.shaking),
            where="--history",
        )
        announce_written(history_path)
    if plot_path:
        from rockcli.plots import plot_assessment

        plot_assessment(
            doc, out.result.runs, plot_path, record=shaking, overturn_angle=out.overturn_angle
        )
        announce_written(plot_path)
    from rockcli.terminal.assess import assessment_report
    from rockcli.terminal.table import show

    show(doc, output, assessment_report)
    exit_if_non_finite(doc["runs"])
    if fail_on_overturn and doc["verdict"] == "overturns":
        raise SystemExit(EXIT_OVERTURNS)


def assess_every_mechanism(
    model_path, record, engine, ground, output, fail_on_overturn, single_options
) -> None:
    """--all: each mechanism the time history rocks, a document each (JSON ``mechanisms``)."""
    from rockcli.analyses.assess import run_assessment_output
    from rockcli.analyses.rocked import rockable_names
    from rockcli.errors import InputError
    from rockcli.terminal.assess import assessment_output_document, assessment_report
    from rockcli.terminal.table import console_for, render

    for option, value in zip(("--mechanism", "--history", "--plot"), single_options, strict=True):
        if value is not None:
            raise InputError("not with --all (one mechanism's option)", where=option,
                             value=value, allowed=f"either --all or {option}")  # fmt: skip
    docs, refused = [], []
    for name in rockable_names(model_path):
        try:
            out = run_assessment_output(model_path, record, engine, ground=ground, mechanism=name)
        except InputError as exc:  # this mechanism only (a member on a flexure's upper block)
            refused.append({"name": name, "not_rocked": exc.render().removeprefix("error: ")})
            continue
        docs.append(assessment_output_document(out, record))
    if output == "json":
        import json

        print(json.dumps({"mechanisms": docs, "not_rocked": refused}, indent=2,
                         allow_nan=False))  # fmt: skip
    else:
        console = console_for()
        for doc in docs:
            render(assessment_report(doc), console)
        for item in refused:
            console.print(f"note: '{item['name']}' is not rocked: {item['not_rocked']}",
                          markup=False, highlight=False)  # fmt: skip
    for doc in docs:
        exit_if_non_finite(doc["runs"])
    if fail_on_overturn and any(doc["verdict"] == "overturns" for doc in docs):
        raise SystemExit(EXIT_OVERTURNS)


def one_record_or_suite(
    record_path, suite_path, history_path, plot_path, grid_file, target=None
) -> bool:
    """True for --suite, False for --record; InputError for both, neither, a one-record
    option with --suite (a history or a plot is one record's), or --target with --record."""
    from rockcli.errors import InputError

    if (record_path is None) == (suite_path is None):
        where, value = ("--suite", suite_path) if record_path else ("--record", None)
        raise InputError(
            "give one record or one suite" if record_path else "missing",
            where=where,
            value=value,
            allowed="--record FILE, or --suite SUITE.toml",
        )
    if suite_path is None:
        if target is not None:
            raise InputError(
                "applies only to a folder of records given as the suite",
                where="--target",
                value=target,
                allowed="--suite DIR --target KEY=VALUE,…",
            )
        if grid_file is not None:
            raise InputError(
                "applies only to a suite whose target is a site",
                where="--hazard-grid",
                value=grid_file,
                allowed="--suite SUITE.toml with a [target] lon, lat",
            )
        return False
    for option, value in (("--history", history_path), ("--plot", plot_path)):
        if value is not None:
            raise InputError(
                "is one record's: not with --suite",
                where=option,
                value=value,
                allowed=f"--record FILE with {option}",
            )
    return True


def assess_with_suite(
    model_path, suite, grid_file, engine, ground, jobs, output, mechanism=None
) -> None:
    """Every record of the suite through the time history, the code's rule, the report.

    suite: (the suite file or folder, the --target of a folder, --allow-outside)."""
    from rockcli.studies.suite_run.assess import assess_suite
    from rockcli.terminal.suite import suite_assessment_document, suite_assessment_report
    from rockcli.terminal.sweep import progress_bar
    from rockcli.terminal.table import show

    with progress_bar(None) as bar:
        result = assess_suite(
            model_path, suite[0], grid_file, engine=engine, ground=ground, jobs=jobs,
            progress=bar, target=suite[1], allow_outside=suite[2], mechanism=mechanism,
        )  # fmt: skip
    show(suite_assessment_document(result), output, suite_assessment_report)
