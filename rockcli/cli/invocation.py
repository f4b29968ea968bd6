"""The command line of this run, as the user typed it: set when `rock` starts
(rockcli.cli.main.RockGroup.main), read by a command that records it (the report, to be
re-run)."""

from __future__ import annotations

_command_line: tuple[str, ...] = ("rock",)


def set_command_line(args: tuple[str, ...]) -> None:
    """Record this run's command line (``rock`` and its arguments)."""
    global _command_line
    _command_line = ("rock", *args)


def command_line() -> tuple[str, ...]:
    """This run's command line: ``rock`` and its arguments."""
    return _command_line
