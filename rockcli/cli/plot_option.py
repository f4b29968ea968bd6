"""The `--plot FILE` option of assess, kinematic and compare (rockcli.plots)."""

from __future__ import annotations

import click


def _check(ctx: click.Context, param: click.Parameter, value: str | None) -> str | None:
    """Refuse a bad suffix or a missing matplotlib before the run, not after it."""
    if value is not None:
        from rockcli.plots import check_plot_path

        check_plot_path(value)
    return value


plot_option = click.option(
    "--plot",
    "plot_path",
    type=click.Path(dir_okay=False),
    default=None,
    metavar="FILE",
    callback=_check,
    help="Also draw the result to FILE: .png or .svg "
    "(needs matplotlib: pip install '.[plot]' from the repository's folder).",
)
