"""`rock kinematic MODEL`: the NTC kinematic analysis of the mechanism (spec/ntc.md)."""

from __future__ import annotations

import click

from rockcli.cli.options import (
    edition_option,
    hazard_grid_option,
    load_record,
    output_format,
    with_record_options,
)
from rockcli.cli.plot_option import plot_option


def _site(value: str | None) -> tuple[float, float] | None:
    from rockcli.errors import InputError

    if value is None:
        return None
    try:
        lon, lat = (float(x) for x in value.split(","))
    except ValueError:
        raise InputError(
            "not a site",
            where="--site",
            value=value,
            allowed="LON,LAT in decimal degrees, e.g. 13.40,42.35",
        ) from None
    return lon, lat


@click.command()
@click.argument("model_path", metavar="MODEL", type=click.Path(dir_okay=False))
@edition_option
@with_record_options(required=False)
@click.option(
    "--site",
    default=None,
    metavar="LON,LAT",
    help="Take the demand from the hazard grid at this site (overrides the model).",
)
@hazard_grid_option
@plot_option
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
    plot_path,
    output,
):
    """NTC kinematic analysis of MODEL: α0, e*, a0*, capacity curve, DLS and ULS checks."""
    from rockcli.report.kinematic import kinematic_document, kinematic_report
    from rockcli.report.table import show
    from rockcli.studies.kinematic import run_kinematic

    record = None
    if record_path is not None:
        record = load_record(record_path, record_format, dt, units, scale, pga)
    out = run_kinematic(
        model_path, edition=edition, record=record, site=_site(site), grid_file=grid_file
    )
    doc = kinematic_document(out.name, out.result)
    if plot_path:
        from rockcli.report.plots import plot_kinematic

        plot_kinematic(doc, plot_path)
    show(doc, output, kinematic_report)
