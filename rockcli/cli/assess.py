"""`rock assess MODEL --record FILE`: the rocking time history, both polarities."""

from __future__ import annotations

import click

from rockcli.cli.options import engine_option, load_record, output_format, with_record_options
from rockcli.cli.plot_option import plot_option

#: Exit code of --fail-on-overturn when the block overturns (documented in the README).
EXIT_OVERTURNS = 1


@click.command()
@click.argument("model_path", metavar="MODEL", type=click.Path(dir_okay=False))
@with_record_options()
@engine_option
@click.option(
    "--history",
    "history_path",
    type=click.Path(dir_okay=False),
    default=None,
    help="Write t, θ, θ̇ of the worse polarity to this CSV file.",
)
@click.option(
    "--fail-on-overturn",
    is_flag=True,
    help=f"Exit with code {EXIT_OVERTURNS} when the block overturns (for CI gates).",
)
@plot_option
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
    history_path,
    fail_on_overturn,
    plot_path,
    output,
):
    """Rocking time history of MODEL under a record, both polarities, with the verdict."""
    from rockcli.report.assess import assessment_output_document
    from rockcli.studies.assess import run_assessment_output

    record = load_record(record_path, record_format, dt, units, scale, pga)
    history = history_path is not None or plot_path is not None
    out = run_assessment_output(model_path, record, engine, history=history)
    doc = assessment_output_document(out, record)
    if history_path:
        write_history(history_path, out.result.worst)
    if plot_path:
        from rockcli.report.plots import plot_assessment

        plot_assessment(
            doc, out.result.runs, plot_path, record=record, overturn_angle=out.overturn_angle
        )
    from rockcli.report.assess import assessment_report
    from rockcli.report.table import show

    show(doc, output, assessment_report)
    if fail_on_overturn and doc["verdict"] == "overturns":
        raise SystemExit(EXIT_OVERTURNS)


def write_history(path, run):
    """CSV of t [s], θ [rad], θ̇ [rad/s] at the sample times (tail included)."""
    from rockcli.errors import InputError

    hist = run.history
    lines = [f"# polarity {run.polarity:+d}, {run.message}", "t_s,theta_rad,omega_rad_s"]
    lines += [
        f"{t:.6f},{a:.10e},{w:.10e}"
        for t, a, w in zip(hist.time, hist.theta, hist.omega, strict=True)
    ]
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("\n".join(lines) + "\n")
    except OSError as exc:
        raise InputError(
            "cannot write the history file",
            file=path,
            value=exc.strerror,
            allowed="a writable path",
        ) from None
