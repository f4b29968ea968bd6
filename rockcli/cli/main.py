"""The `rock` command group: the one place where bad input becomes an error line and exit code.

Command modules keep numpy, scipy and numba imports inside their functions, so that
``rock --help`` and model validation start without them (spec/engine.md, "Speed").
"""

from __future__ import annotations

import click

from rockcli import __version__
from rockcli.errors import RockError

#: Exit code for bad input (same as click's usage errors).
EXIT_INPUT = 2


class RockGroup(click.Group):
    """click group that renders every :class:`RockError` as one line on stderr."""

    def invoke(self, ctx: click.Context) -> object:
        try:
            return super().invoke(ctx)
        except RockError as exc:
            click.echo(f"error: {exc}", err=True)
            ctx.exit(EXIT_INPUT)


@click.group(cls=RockGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="rock")
def cli() -> None:
    """Out-of-plane seismic assessment of masonry walls, altars and façades.

    The Italian code's kinematic check and a Housner rocking time history, on one TOML model.
    """


def _register() -> None:
    from rockcli.cli import commands

    for command in commands.ALL:
        cli.add_command(command)


_register()
