"""`rock suite`: the group and its command are registered and documented; the shipped example
suite is a valid suite file (its records are read only where ../shared exists)."""

from __future__ import annotations

from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.model.load import read_toml
from rockcli.suites.load import resolve, validate_suite
from tests.suites.conftest import EXAMPLE_SUITE


def test_suite_group_lists_check() -> None:
    result = CliRunner().invoke(cli, ["suite", "--help"])
    assert result.exit_code == 0 and "check" in result.stdout


def test_check_help_names_its_options() -> None:
    result = CliRunner().invoke(cli, ["suite", "check", "--help"])
    assert result.exit_code == 0
    for option in ("--period", "--scale", "--hazard-grid", "--plot", "--format"):
        assert option in result.stdout


def test_example_suite_is_valid_without_its_records() -> None:
    suite = validate_suite(read_toml(str(EXAMPLE_SUITE)), str(EXAMPLE_SUITE))
    settings = resolve(suite, str(EXAMPLE_SUITE), None)
    assert len(settings.entries) == 7 and settings.target.site == (13.40, 42.35)
    assert settings.period_range == (0.15, 2.0) and settings.tolerance == (-0.10, 0.30)
    # The paths lead to the shared folder beside the clone, whatever the working directory.
    assert all(e.path.parts[-3:-1] == ("shared", "records") for e in settings.entries)
