"""`rock suite check SUITE`: a record suite's mean spectrum against the code's target."""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommands
from rockcli.cli.options import (
    ASCII_FLOAT,
    allow_outside_option,
    announce_written,
    check_outputs,
    force_option,
    hazard_grid_option,
    output_format,
    target_option,
)
from rockcli.cli.plot_option import plot_option


@click.group(cls=RockCommands, short_help="Record suites against the code's target spectrum.")
def suite() -> None:
    """Record suites: a set of scaled records and their target spectrum (a TOML suite file)."""


@suite.command(short_help="Check a suite's mean spectrum against its target (NTC §3.2.3.6).")
@click.argument("suite_path", metavar="SUITE", type=InputPath("either", folder_with="target"))
@target_option
@click.option(
    "--period",
    type=ASCII_FLOAT,
    default=None,
    metavar="T",
    help="The structure's period [s]: check 0.15 s to max(2.0 s, 2T) (default 0.15–2.0 s).",
)
@click.option(
    "--scale",
    "scale_mode",
    type=click.Choice(["none", "auto"]),
    default="none",
    show_default=True,
    help="auto: also find the common factor that puts the mean's smallest ratio on the "
    "lower bound, and check the suite with it.",
)
@click.option(
    "--model",
    "model_path",
    type=InputPath(),
    default=None,
    help="A model at height ([building] Z > 0): check the records' floor motions at its "
    "height against the code's floor spectrum there (what its rocking analysis runs on).",
)
@hazard_grid_option
@allow_outside_option
@plot_option
@force_option
@output_format
def check(
    suite_path, target, period, scale_mode, model_path, grid_file, allow_outside, plot_path,
    force, output,
):  # fmt: skip
    """Check that the mean 5 %-damped spectrum of the suite's records matches the target
    (NTC §3.2.3.6: nowhere below −10 %, and in NTC 2018 nowhere above +30 %).

    SUITE is a suite file (TOML), or a folder of records with --target."""
    from rockcli.suites.load import load_suite
    from rockcli.suites.run import run_suite_check, suite_document
    from rockcli.terminal.suite import suite_report
    from rockcli.terminal.table import show

    settings = load_suite(suite_path, period=period, target=target, allow_outside=allow_outside)
    check_grid_option(grid_file, settings.target.site is not None, suite_path)
    check_outputs(force, plot=plot_path)
    floor = model_floor_of(model_path)
    result = run_suite_check(settings, grid_file, scale_auto=scale_mode == "auto", floor=floor)
    doc = suite_document(result)
    if plot_path:
        from rockcli.plots.suite import plot_suite

        plot_suite(doc, plot_path)
        announce_written(plot_path)
    show(doc, output, suite_report)


def check_grid_option(grid_file: str | None, has_site: bool, suite_path: str) -> None:
    """Refuse --hazard-grid when the suite's target gives its parameters (InputError)."""
    from rockcli.errors import InputError

    if grid_file is not None and not has_site:
        raise InputError(
            "not used: the suite's [target] gives ag, F0 and Tc_star",
            where="--hazard-grid",
            value=grid_file,
            allowed=f"--hazard-grid only with lon and lat in [target] of {suite_path}",
        )


def model_floor_of(model_path: str | None):
    """The floor at the model's height (rockcli.analyses.floor.Floor); None without --model;
    InputError for a model on the ground (its check is the ground's: drop --model)."""
    if model_path is None:
        return None
    from rockcli.analyses.floor import model_floor
    from rockcli.errors import InputError
    from rockcli.model.load import load_model

    floor = model_floor(load_model(model_path))
    if floor is None:
        raise InputError(
            "the model stands on the ground (no [building] or building.Z = 0): its suite is "
            "checked at the ground",
            file=model_path,
            where="--model",
            allowed="--model with a block at height ([building] Z > 0), or no --model",
        )
    return floor
