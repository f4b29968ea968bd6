"""`rock warmup`: compile the rocking engine into the numba cache."""

from __future__ import annotations

import click


@click.command()
def warmup() -> None:
    """Compile the rocking engine and the response-spectrum kernel now (CI images, workers)."""
    from rockcli.dynamics.warmup import compile_engine

    seconds = compile_engine()
    click.echo(f"engine ready ({seconds:.1f} s)")
