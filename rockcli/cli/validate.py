"""`rock validate`: run the validation casebook and compare every case with its source."""

from __future__ import annotations

import click

from rockcli.cli.exits import EXIT_GATE
from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import hazard_grid, output_format

#: Exit code when a case is outside its tolerance (README, exit codes).
EXIT_CASE_FAILED = EXIT_GATE


@click.command(
    cls=RockCommand, short_help="Run the validation casebook: each case against its source."
)
@click.option(
    "--casebook",
    "folder",
    default=None,
    type=InputPath("folder"),
    help="A folder of case files to run instead of the bundled casebook (examples/validation).",
)
@hazard_grid(
    "NTC Allegato B grid file for the hazard-grid cases (default: $ROCK_HAZARD_GRID; "
    "without one those cases are skipped)."
)
@output_format
def validate(folder, grid_file, output):
    """Run the validation casebook: each case's expected value, its published source, the
    value rock obtains, the error and the tolerance. Exit 1 when a case fails; the hazard-grid
    cases are skipped without a grid."""
    from rockcli.casebook.run import run_casebook
    from rockcli.terminal.table import show
    from rockcli.terminal.validate import summary, validate_document, validate_report

    doc = validate_document(run_casebook(folder, grid_file))
    show(doc, output, validate_report)
    if doc["failed"]:
        click.echo(f"rock validate: {summary(doc)}", err=True)
        raise SystemExit(EXIT_CASE_FAILED)
