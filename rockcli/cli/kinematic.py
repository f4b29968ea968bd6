"""`rock kinematic MODEL`: the NTC kinematic analysis of the mechanism (spec/ntc.md)."""

from __future__ import annotations

import click

from rockcli.cli.exits import EXIT_GATE
from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    announce_written,
    check_hazard_grid,
    check_outputs,
    check_record_options,
    edition_option,
    force_option,
    hazard_grid_option,
    load_record,
    output_format,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option


def _site(value: str | None, record_path: str | None) -> tuple[float, float] | None:
    from rockcli.errors import InputError

    if value is None:
        return None
    if record_path is not None:
        raise InputError(
            "conflicts with --record (the record's spectrum sets the demand)",
            where="--site",
            value=value,
            allowed="either --site LON,LAT or --record FILE",
        )
    from rockcli.cli.options import parse_site

    return parse_site(value)


@click.command(
    cls=RockCommand, short_help="NTC kinematic check of MODEL: α0, a0*, capacity curve, DLS, ULS."
)
@click.argument("model_path", metavar="MODEL", type=InputPath())
@edition_option
@with_record_options(required=False)
@click.option(
    "--site",
    default=None,
    metavar="LON,LAT",
    help="Take the demand from the hazard grid at this site (overrides the model).",
)
@hazard_grid_option
@click.option(
    "--fail-on-uls",
    is_flag=True,
    help=f"Exit with code {EXIT_GATE} when the ULS verdict of a mechanism is not satisfied, or "
    "not evaluated (a gate cannot pass on a check that was not made).",
)
@click.option(
    "--mechanism",
    "mechanism_name",
    default=None,
    metavar="NAME",
    help="Show this mechanism of the catalogue in detail (default: the governing one).",
)
@click.option(
    "--all", "all_mechanisms", is_flag=True, help="Show every mechanism of the catalogue."
)
@plot_option
@force_option
@output_format
def kinematic(
    model_path,
    edition,
    record_path,
    record_format,
    dt,
    units,
    scale,
    pga,
    site,
    grid_file,
    fail_on_uls,
    mechanism_name,
    all_mechanisms,
    plot_path,
    force,
    output,
):
    """NTC kinematic analysis of MODEL: α0, e*, a0*, capacity curve, DLS and ULS checks."""
    from rockcli.analyses.kinematic import run_kinematic
    from rockcli.terminal.kinematic import kinematic_document

    check_record_options(record_path, record_format, dt, units, scale, pga)
    lon_lat = _site(site, record_path)
    if site is None:  # with --site, the grid is used
        check_hazard_grid(grid_file, model_path, demand_from="--record" if record_path else None)
    check_outputs(force, plot=plot_path)
    record = None
    if record_path is not None:
        record = load_record(record_path, record_format, dt, units, scale, pga)
    out = run_kinematic(
        model_path, edition=edition, record=record, site=lon_lat, grid_file=grid_file
    )
    doc = kinematic_document(out.name, out.result, out.warnings, mechanism_name)
    if plot_path:
        from rockcli.plots import plot_kinematic

        plot_kinematic(doc, plot_path)
        announce_written(plot_path)
    show_catalogue(doc, out, output, all_mechanisms)
    if fail_on_uls:  # every mechanism's verdict, whichever is shown
        gate_uls(catalogue_uls(doc))


def show_catalogue(doc, out, output: str, all_mechanisms: bool) -> None:
    """JSON, or the summary of the catalogue and the detail of one mechanism (every one with
    ``all_mechanisms``) in the terminal."""
    from rockcli.terminal.kinematic import catalogue_reports, kinematic_document, kinematic_report
    from rockcli.terminal.table import console_for, render, show

    if output == "json" or len(doc.get("mechanisms", ())) < 2:
        show(doc, output, kinematic_report)
        return
    reports = catalogue_reports(doc, all_mechanisms)
    if all_mechanisms:
        others = [m.name for m in out.result.catalogue if m.name != doc["mechanism"]]
        reports += [
            kinematic_report(kinematic_document(out.name, out.result, out.warnings, name))
            for name in others
        ]
    console = console_for()
    for report in reports:
        render(report, console)


def catalogue_uls(doc) -> bool | None:
    """The ULS verdict of the catalogue: False if a mechanism fails, else None if one is not
    evaluated, else True (the document's own verdict without a catalogue)."""
    verdicts = [m["verdict"]["ULS"] for m in doc.get("mechanisms", ())] or [doc["verdict"]["ULS"]]
    if False in verdicts:
        return False
    return None if None in verdicts else True


def gate_uls(uls: bool | None) -> None:
    """--fail-on-uls: exit 1 unless the ULS verdict is satisfied (one line on stderr)."""
    from rockcli.terminal.kinematic import ULTIMATE_FIX

    if uls is True:
        return
    reason = "NOT satisfied" if uls is False else f"not evaluated ({ULTIMATE_FIX})"
    click.echo(f"--fail-on-uls: ULS {reason}", err=True)
    raise SystemExit(EXIT_GATE)
