"""The command line a person types (issue 19, item 7): one error style, every missing path
named at once, the code's years for --edition, a missing suite folder said so, and a command
list whose descriptions are whole."""

from __future__ import annotations

import json
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from rockcli.cli.inputs import RockCommand
from rockcli.cli.main import cli
from tests.cli.conftest import ROOT

ALTAR = str(ROOT / "examples" / "altar.toml")
RICKER = str(ROOT / "records" / "ricker_Tp0.5s_0.5g.txt")
TARGET = "ag=0.2,F0=2.4,Tc_star=0.3"
KINEMATIC_USAGE = "(usage: rock kinematic [OPTIONS] MODEL)"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


# --- click's errors in rock's style ----------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "line"),
    [
        (
            ["kinematic", ALTAR, "--format", "xml"],
            f"error: invalid value for '--format': 'xml' is not one of 'table', 'json' "
            f"{KINEMATIC_USAGE}",
        ),
        (["kinematic"], f"error: missing argument 'MODEL' {KINEMATIC_USAGE}"),
        (["kinematic", ALTAR, "--bogus"], f"error: no such option '--bogus' {KINEMATIC_USAGE}"),
        (
            ["kinematic", ALTAR, "--recrd", RICKER],
            f"error: no such option '--recrd'; did you mean '--record'? {KINEMATIC_USAGE}",
        ),
        (["tower"], "error: no such command 'tower' (usage: rock [OPTIONS] COMMAND [ARGS]...)"),
        (["--bogus"], "error: no such option '--bogus' (usage: rock [OPTIONS] COMMAND [ARGS]...)"),
        (
            ["record", "nosuch"],
            "error: no such command 'nosuch' (usage: rock record [OPTIONS] COMMAND [ARGS]...)",
        ),
    ],
)
def test_click_errors_are_rock_error_lines(args: list[str], line: str) -> None:
    # On main: "Usage: rock kinematic [OPTIONS] MODEL\nTry 'rock kinematic --help' for
    # help.\n\nError: Invalid value for '--format': …", beside rock's own "error: …" lines.
    code, stdout, stderr = run(*args)
    assert (code, stdout, stderr) == (2, "", line + "\n")


def test_a_bare_group_still_shows_its_help() -> None:
    code, _, stderr = run("record")
    assert code == 2 and stderr.startswith("Usage: rock record") and "Commands:" in stderr


# --- every missing input named at once -------------------------------------------------------


def test_both_missing_paths_are_named() -> None:
    # On main only the record: "error: nope.txt: cannot read the record file (…)".
    code, stdout, stderr = run("compare", "nope.toml", "--record", "nope.txt")
    assert (code, stdout) == (2, "")
    assert stderr.splitlines() == [
        "error: nope.toml: MODEL: the file does not exist",
        "error: nope.txt: --record: the file does not exist",
    ]


@pytest.mark.parametrize("command", ["assess", "kinematic", "retrofit", "report"])
def test_every_command_reading_a_model_and_a_record_names_both(command: str) -> None:
    extra = ["-o", "r.html"] if command == "report" else []
    code, _, stderr = run(command, "nope.toml", "--record", "nope.txt", *extra)
    assert code == 2
    assert [line.split(": ")[1:3] for line in stderr.splitlines()] == [
        ["nope.toml", "MODEL"],
        ["nope.txt", "--record"],
    ]


def test_every_missing_record_of_record_info_is_named() -> None:
    code, _, stderr = run("record", "info", "a.txt", RICKER, "b.txt")
    assert code == 2
    assert stderr.splitlines() == [
        "error: a.txt: FILES: the file does not exist",
        "error: b.txt: FILES: the file does not exist",
    ]


def test_a_present_model_and_a_missing_record() -> None:
    code, _, stderr = run("assess", ALTAR, "--record", "nope.txt")
    assert (code, stderr) == (2, "error: nope.txt: --record: the file does not exist\n")


def test_every_command_checks_its_inputs() -> None:
    # Each command of the tree is a RockCommand (its InputPath parameters checked, all at
    # once, before it runs).
    def commands(group: click.Group) -> list[click.Command]:
        out: list[click.Command] = []
        for command in group.commands.values():
            out += commands(command) if isinstance(command, click.Group) else [command]
        return out

    found = commands(cli)
    assert len(found) >= 14
    assert [c.name for c in found if not isinstance(c, RockCommand)] == []


# --- a suite folder that does not exist ------------------------------------------------------


def test_suite_check_on_a_missing_folder_says_so(tmp_path: Path) -> None:
    # On main: "error: --target: not used: a suite file has its own [target] (…)".
    folder = tmp_path / "records"
    code, _, stderr = run("suite", "check", str(folder), "--target", TARGET)
    assert (code, stderr) == (
        2,
        f"error: {folder}: SUITE: the folder does not exist (allowed: an existing folder of "
        "records with --target)\n",
    )


def test_compare_on_a_missing_suite_folder_says_so(tmp_path: Path) -> None:
    folder = tmp_path / "records"
    code, _, stderr = run("compare", ALTAR, "--suite", str(folder), "--target", TARGET)
    assert code == 2
    assert stderr.startswith(f"error: {folder}: --suite: the folder does not exist")


def test_a_missing_suite_file_without_target() -> None:
    code, _, stderr = run("suite", "check", "nowhere.toml")
    assert (code, stderr) == (2, "error: nowhere.toml: SUITE: no file or folder of that name\n")


# --- --edition takes the code's years, as the model file does --------------------------------


@pytest.mark.parametrize(("year", "circular"), [("2008", "2009"), ("2018", "2019")])
def test_edition_takes_the_codes_year(year: str, circular: str) -> None:
    # On main: "Error: Invalid value for '--edition': '2018' is not one of '2009', '2019'",
    # while `edition = 2018` in a model file is NTC 2018 + Circ. 7/2019.
    # The altar with LC1's FC, which the 2019 rules ask of a block (§C8.7.1.2.1.3).
    altar = str(ROOT / "tests" / "data" / "altar-2019.toml")
    code, by_year, _ = run("kinematic", altar, "--edition", year, "--format", "json")
    assert code == 0
    _, by_circular, _ = run("kinematic", altar, "--edition", circular, "--format", "json")
    assert json.loads(by_year)["edition"] == circular
    assert json.loads(by_year) == json.loads(by_circular)


# --- the command list --------------------------------------------------------------------------


@pytest.mark.parametrize("group", [[], ["record"], ["suite"]], ids=["rock", "record", "suite"])
def test_the_command_list_shows_whole_descriptions(group: list[str]) -> None:
    # On main click cut every description at about 45 characters ("Rocking time history of
    # MODEL under a record (or every...").
    result = CliRunner().invoke(cli, [*group, "--help"], terminal_width=80)
    assert result.exit_code == 0
    listing = result.output.split("Commands:\n", 1)[1]
    assert "..." not in listing
    target = cli if not group else cli.commands[group[0]]
    assert isinstance(target, click.Group)
    for name, command in target.commands.items():
        assert command.short_help, name
        line = next(line for line in listing.splitlines() if line.split()[0] == name)
        assert line.split(None, 1)[1] == command.short_help, name
        assert len(line) <= 80, name
