"""The `--plot FILE` option of the commands that draw their result (rockcli.plots), and the
check of a study's plot before the study runs."""

from __future__ import annotations

from pathlib import Path

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


def check_study_plot(plot_path: str | None, force: bool, out: str) -> None:
    """A study's --plot (rock sweep, rock fragility), checked before the study runs as every
    output file is (rockcli.cli.options.check_outputs: an existing file is replaced only with
    --force). A plot straight inside the output folder ``out`` that the run has yet to make
    passes: nothing is there to replace, and the folder will exist when the plot is drawn."""
    from rockcli.cli.options import check_outputs

    if plot_path is None:
        return
    if not Path(out).exists() and Path(plot_path).parent.resolve() == Path(out).resolve():
        return
    check_outputs(force, plot=plot_path)
