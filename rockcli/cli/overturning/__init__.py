"""`rock spectrum overturning` (rockcli.cli.overturning.command)."""

from rockcli.cli.overturning.command import spectrum

__all__ = ["spectrum"]
