"""The paths a command reads, checked before it runs: every missing one named at once.

click's ``Path(exists=True)`` stops at the first missing path, and rock's loaders each read
their file in turn: ``rock compare nope.toml --record nope.txt`` named only one of the two.
A parameter of type :class:`InputPath` is checked by :class:`RockCommand` before the command
runs, and every missing path is an ``error:`` line (exit 2, through the group in
``cli/main.py``).
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from typing import Any, Literal

import click

from rockcli.errors import InputError

#: What an input path may be.
Takes = Literal["file", "folder", "either"]
#: What a path that does not exist is called, by what the parameter takes.
MISSING: dict[str, str] = {
    "file": "the file does not exist",
    "folder": "the folder does not exist",
    "either": "no file or folder of that name",
}


class InputPath(click.Path):
    """A path the command reads: a file, a folder, or either (a suite file or a folder of
    records). Its existence is checked by :class:`RockCommand`, with the command's other
    inputs.

    Args:
        takes: "file", "folder" or "either".
        folder_with: for "either", the parameter (its name in the command) that makes the path
            a folder when it is given (``target``: a folder of records with --target).
    """

    def __init__(self, takes: Takes = "file", *, folder_with: str | None = None) -> None:
        super().__init__(dir_okay=takes != "file", file_okay=takes != "folder")
        self.takes = takes
        self.folder_with = folder_with

    def missing(self, path: str, where: str, params: dict[str, Any]) -> InputError | None:
        """The error of a path that does not exist, else None."""
        if os.path.exists(path):
            return None
        folder = self.folder_with is not None and params.get(self.folder_with) is not None
        takes: Takes = "folder" if folder else self.takes
        allowed = f"an existing folder of records with --{self.folder_with}" if folder else None
        return InputError(MISSING[takes], file=path, where=where, allowed=allowed)


def missing_inputs(ctx: click.Context) -> list[InputError]:
    """Every path of the command's InputPath parameters that does not exist, in the order of
    the command's parameters."""
    checked = (kind.missing(path, label, ctx.params) for kind, label, path in _input_paths(ctx))
    return [error for error in checked if error is not None]


def _input_paths(ctx: click.Context) -> Iterator[tuple[InputPath, str, str]]:
    """(its type, how the user names it, the path) of each path an InputPath parameter got."""
    for param in ctx.command.params:
        if not isinstance(param.type, InputPath) or param.name is None:
            continue
        value = ctx.params.get(param.name)
        for path in value if isinstance(value, tuple | list) else (value,):
            if path is not None:
                yield param.type, _label(param), os.fspath(path)


def _label(param: click.Parameter) -> str:
    """How the user names a parameter: its longest option, or its argument's metavar."""
    if isinstance(param, click.Option):
        return max(param.opts, key=len)
    return param.human_readable_name


def check_inputs(ctx: click.Context) -> None:
    """Raise the missing paths' error: one InputError, or InputErrors for several."""
    errors = missing_inputs(ctx)
    if len(errors) == 1:
        raise errors[0]
    if errors:
        from rockcli.model.load import InputErrors

        raise InputErrors(errors)


class RockCommand(click.Command):
    """A rock command: its input paths are checked, all of them, before it runs."""

    def invoke(self, ctx: click.Context) -> Any:
        check_inputs(ctx)
        return super().invoke(ctx)


class RockCommands(click.Group):
    """A group of rock commands (``rock record``, ``rock suite``): its commands are
    :class:`RockCommand`."""

    command_class = RockCommand
