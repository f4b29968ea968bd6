"""`rock init KIND`: write a commented model-file template (spec/README.md, "Commands")."""

from __future__ import annotations

from pathlib import Path

import click

from rockcli.errors import InputError
from rockcli.model.schema import Kind


@click.command("init")
@click.argument("kind", type=click.Choice([k.value for k in Kind]))
@click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False, path_type=Path),
    help="Write the template to this file (default: standard output).",
)
@click.option("--force", is_flag=True, help="Overwrite OUTPUT if it exists.")
def init(kind: str, output: Path | None, force: bool) -> None:
    """Write a commented model-file template.

    KIND is wall, altar or facade (the altar and the facade are the source paper's cases).
    The template loads unchanged; edit its values for your element.
    """
    from rockcli.model.template import render_template

    text = render_template(Kind(kind))
    if output is None:
        click.echo(text, nl=False)
        return
    write_new(output, text, force=force)
    click.echo(f"wrote {output}", err=True)


def write_new(path: Path, text: str, *, force: bool) -> None:
    """Write ``text`` to ``path``; refuse to overwrite an existing file unless ``force``."""
    if path.exists() and not force:
        raise InputError("file exists", file=str(path), allowed="another path, or --force")
    try:
        path.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot write the file: {exc.strerror or exc}", file=str(path)) from None
