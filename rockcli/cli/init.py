"""`rock init KIND`: write a commented model-file template (spec/README.md, "Commands")."""

from __future__ import annotations

from pathlib import Path

import click

from rockcli.cli.inputs import RockCommand
from rockcli.cli.options import announce_written, force_option
from rockcli.model.schema import Kind


@click.command(
    "init",
    cls=RockCommand,
    short_help="Write a commented template: a model or a report's project.",
)
@click.argument("kind", type=click.Choice([*(k.value for k in Kind), "project"]))
@click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False, path_type=Path),
    help="Write the template to this file (default, or -: standard output).",
)
@force_option
def init(kind: str, output: Path | None, force: bool) -> None:
    """Write a commented model-file template.

    KIND is wall, altar or facade (the altar and the facade are the source paper's cases),
    frame (piers capped by a roof: a bell cell), or project: the project of a calculation
    report (rock report --project). The template loads unchanged; edit its values for your
    element.
    """
    from rockcli.model.template import render_template
    from rockcli.outfile import check_writable, is_stdout, write_text

    if kind == "project":
        from rockcli.document.project import TEMPLATE as text
    else:
        text = render_template(Kind(kind))
    if output is None or is_stdout(output):
        click.echo(text, nl=False)
        return
    check_writable(output, force=force, where="--output")
    write_text(output, text, where="--output")
    announce_written(output)
