"""`rock retrofit MODEL [--record FILE]`: size a tie-rod by the code check and the time history
(without a record, by the code check on the model's own spectra alone)."""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    ASCII_FLOAT,
    AsciiIntRange,
    announce_written,
    check_outputs,
    check_record_options,
    check_rocking_options,
    edition_option,
    engine_option,
    exit_if_non_finite,
    force_option,
    ground_option,
    hazard_grid,
    jobs_option,
    load_record,
    output_format,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option

#: Exit code of --fail-if-none when no diameter passes (a verdict gate, as --fail-on).
EXIT_NONE = 1


@click.command(
    cls=RockCommand, short_help="Size a tie-rod of MODEL by the code check and the time history."
)
@click.argument("model_path", metavar="MODEL", type=InputPath())
@with_record_options(
    required=False,
    optional_help=" (none: the code check alone, on the model's own spectra; no time history).",
)
@click.option("--name", default=None, help="The model's tie-rod to size, when it has several.")
@click.option(
    "--at",
    "at",
    default=None,
    metavar="HEIGHT,FROM_PIVOT",
    help="Size a new rod at this point [m] (added to the model's restrainers; needs --length).",
)
@click.option("--length", type=ASCII_FLOAT, default=None, help="Free length of the new rod [m].")
@click.option(
    "--diameters",
    default=None,
    metavar="D1,D2,…",
    help="Diameters to try [mm], at most 1000 [default: 10,12,14,16,18,20,22,24,27,30,33,36,40].",
)
@click.option(
    "--grade",
    default=None,
    metavar="S235|S275|S355",
    help="Steel grade of the rod [default: the model's tie-rod's, else S275].",
)
@click.option(
    "--count",
    type=AsciiIntRange(min=1),
    default=None,
    help="Bars side by side [default: the model's tie-rod's, else 1].",
)
@jobs_option(
    "Workers: this process and N − 1 worker processes (a candidate takes about 10 ms "
    "on a 40 s record: more pays off for long records or the reference engine)."
)
@click.option(
    "--progress/--no-progress",
    default=None,
    help="Progress bar on stderr [default: when stderr is a terminal].",
)
@click.option(
    "--fail-if-none",
    is_flag=True,
    help=f"Exit with code {EXIT_NONE} when no diameter in the range passes.",
)
@click.option(
    "--code-demand",
    type=click.Choice(("record", "model")),
    default=None,
    help="The code check's demand: record, the record's response spectrum (one earthquake on "
    "both sides), or model, the model's own code spectra (the report's verification) "
    "[default: record with --record, else model].",
)
@hazard_grid(
    "NTC Allegato B grid file, for a model whose spectra come from its site ([ntc.site]) with "
    "--code-demand model (default: $ROCK_HAZARD_GRID)."
)
@click.option(
    "--details",
    is_flag=True,
    help="Also a row per diameter and mechanism (the table shows one per diameter).",
)
@edition_option
@engine_option
@ground_option
@plot_option
@force_option
@output_format
def retrofit(model_path, record_path, record_format, dt, units, scale, pga, name, at, length,
             diameters, grade, count, jobs, progress, fail_if_none, code_demand, grid_file,
             details, edition, engine, ground, plot_path, force, output):  # fmt: skip
    """Size a tie-rod of MODEL: for each diameter, the code's ULS check of every mechanism and
    the time history of each one the rod is on, under the record; the smallest diameter that
    makes safe every mechanism the rod restrains, its force held. A mechanism the rod does not
    restrain (not on it, or slack on the side it fails on) and that fails needs another
    intervention: it is named, and it does not fail the rod. Without --record, the code check
    alone on the model's own spectra (a site or [ntc.demand]): no time history."""
    from rockcli.analyses.choices import Analyses
    from rockcli.cli.sweep import worker_count
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.retrofit.choose import choose
    from rockcli.studies.retrofit.run import run_retrofit
    from rockcli.terminal.retrofit import retrofit_document, retrofit_report
    from rockcli.terminal.sweep import progress_bar
    from rockcli.terminal.table import show

    check_record_options(record_path, record_format, dt, units, scale, pga)
    if record_path is None:
        check_rocking_options("engine", "ground")
    code_demand = demand_without_record(record_path, code_demand)
    plan, model = retrofit_plan(model_path, name, at, length, diameters, grade, count)
    if code_demand == "model":
        from rockcli.analyses.compare import check_code_demand, code_sets_demand

        if record_path is None and not code_sets_demand(model):
            from rockcli.errors import InputError

            raise InputError("the model sets no code spectrum ([ntc.demand] or [ntc.site]) to "
                             "size the rod on", file=model_path, where="ntc",
                             allowed="[ntc.demand.SLD/SLV/SLC] or [ntc.site] in the model, or "
                             "--record FILE")  # fmt: skip
        check_code_demand(model, code_demand, file=model_path)
    check_outputs(force, plot=plot_path)
    record = None
    if record_path is not None:
        record = load_record(record_path, record_format, dt, units, scale, pga)
    analyses = Analyses(engine, edition, ground)
    jobs = worker_count(jobs, len(plan.diameters_mm))
    with local_executor(jobs) as lanes, progress_bar(progress) as bar:
        rows = run_retrofit(plan, record, lanes, analyses, bar, code_demand, grid_file)
    chosen, reason = choose(rows, rocked=record is not None)
    doc = retrofit_document(
        plan, model, record, rows, chosen, reason, ground=ground, code_demand=code_demand
    )
    if plot_path:
        from rockcli.plots.retrofit import plot_retrofit

        plot_retrofit(doc, plot_path)
        announce_written(plot_path)
    show(doc, output, lambda d: retrofit_report(d, details))
    exit_if_non_finite(
        [{**r, "message": f"Ø{c['diameter_mm']:g} mm: {r['message']}"}
         for c in rows for r in c["broken_runs"]]
    )  # fmt: skip
    if fail_if_none and chosen is None:
        raise SystemExit(EXIT_NONE)


def retrofit_plan(model_path, name, at, length, diameters, grade, count):
    """The validated plan of the options (InputError on bad input) and the model."""
    from rockcli.errors import InputError
    from rockcli.model.load import read_toml, validate_model
    from rockcli.studies.retrofit.candidates import (
        Placement,
        make_plan,
        parse_at,
        parse_diameters,
    )

    sizes = parse_diameters(diameters)
    if (at is None) != (length is None):
        given, missing = ("--at", "--length") if length is None else ("--length", "--at")
        raise InputError(
            f"needs {missing}",
            where=given,
            allowed="--at HEIGHT,FROM_PIVOT "
            "with --length L [m] for a new rod, or neither for the model's tie-rod",
        )
    _check_rod_options(length, count)
    placement = None if at is None else Placement(*parse_at(at), length)
    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    plan = make_plan(table, model, file=model_path, diameters_mm=sizes, name=name,
                     placement=placement, grade=grade, count=count)  # fmt: skip
    return plan, model


def _check_rod_options(length: float | None, count: int | None) -> None:
    """--length and --count within the bounds of the model's tie-rod length and count (an
    out-of-range value named the first diameter tried, not the option)."""
    from rockcli.errors import InputError
    from rockcli.model.bounds import MAX_LENGTH, MIN_LENGTH
    from rockcli.model.schema import MAX_BARS

    if length is not None and not MIN_LENGTH <= length <= MAX_LENGTH:
        raise InputError(
            "not a length",
            where="--length",
            value=length,
            allowed=f"{MIN_LENGTH:g} m ≤ L ≤ {MAX_LENGTH:g} m, as a tie-rod's length",
        )
    if count is not None and count > MAX_BARS:
        raise InputError(
            "too many bars",
            where="--count",
            value=count,
            allowed=f"1 to {MAX_BARS} bars, as a tie-rod's count",
        )


def demand_without_record(record_path: str | None, code_demand: str | None) -> str:
    """The code check's demand: the record's spectrum by default with a record, the model's own
    spectra without one (a record's spectrum without a record is refused: InputError)."""
    if code_demand is None:
        return "record" if record_path is not None else "model"
    if code_demand == "record" and record_path is None:
        from rockcli.errors import InputError

        raise InputError("reads the spectrum of a record, and none is given",
                         where="--code-demand", value=code_demand,
                         allowed="--record FILE, or --code-demand model (the model's own "
                         "spectra; the default without a record)")  # fmt: skip
    return code_demand
