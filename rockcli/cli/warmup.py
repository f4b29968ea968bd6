"""`rock warmup`: compile the rocking engine into the numba cache."""

from __future__ import annotations

import click

from rockcli.cli.inputs import RockCommand


@click.command(cls=RockCommand, short_help="Compile the rocking engine ahead of the first run.")
def warmup() -> None:
    """Compile the rocking engine and the response-spectrum kernel now (CI images, workers)."""
    from rockcli.kernels import compile_engine

    seconds = compile_engine()
    click.echo(f"engine ready ({seconds:.1f} s)")
