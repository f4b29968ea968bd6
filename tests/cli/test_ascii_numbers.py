"""Numbers rock parses by hand are ASCII: Python's float() reads fullwidth ("０.５") and other
Unicode digits ("٠.٥", Arabic-Indic) as numbers, so on main each of these options took text
that only looks like a number as the value it resembles (rockcli.numbers)."""

from __future__ import annotations

from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.cli.options import AsciiFloat, AsciiIntRange
from rockcli.codecheck.hazard import parse_grid
from rockcli.errors import InputError
from rockcli.numbers import ascii_float, ascii_int
from rockcli.records.periods import parse_periods
from rockcli.studies.retrofit.candidates import parse_at, parse_diameters
from rockcli.studies.sweep.paths import parse_path
from tests.cli.conftest import PULSES, ROOT

WALL = ROOT / "examples" / "wall.toml"
#: "0.5" in fullwidth and in Arabic-Indic digits.
LOOKALIKES = ("０.５", "٠.٥")


@pytest.mark.parametrize("text", LOOKALIKES)
def test_ascii_float_and_int_refuse_other_digits(text: str) -> None:
    assert float(text) == 0.5  # what Python does, and rock must not
    with pytest.raises(ValueError):
        ascii_float(text)
    with pytest.raises(ValueError):
        ascii_int("１２")
    assert ascii_float(" 0.5 ") == 0.5 and ascii_int("12") == 12


def error_line(*args: str) -> str:
    result = CliRunner().invoke(cli, list(args))
    assert result.exit_code == 2, result.output
    return result.stderr.strip()


@pytest.mark.parametrize("text", LOOKALIKES)
def test_command_options(text: str, tmp_path: Path) -> None:
    record = str(PULSES[0])
    assert "--periods: not a number" in error_line("record", "spectrum", record, "--periods", text)
    assert "--site: not a site" in error_line("kinematic", str(WALL), "--site", f"13.4,4{text}")
    out = str(tmp_path / "out.txt")
    assert "--trim: not a time window" in error_line(
        "record", "convert", record, "--trim", f"0,{text}", "-o", out
    )


@pytest.mark.parametrize("text", LOOKALIKES)
def test_hand_parsed_numbers(text: str) -> None:
    with pytest.raises(InputError):
        parse_periods(f"0.1,{text}")
    with pytest.raises(InputError):
        parse_diameters(f"12,{text}")
    with pytest.raises(InputError):
        parse_at(f"2.0,{text}")
    assert parse_path("restrainers[０].k_pos") is None  # main: ("restrainers", 0, "k_pos")


def test_the_hazard_grid_reads_ascii_numbers_only() -> None:
    from tests.codecheck.test_hazard_grid import small_grid_text

    text = small_grid_text().replace("\t2.5\t", "\t２.5\t", 1)
    with pytest.raises(InputError) as info:
        parse_grid(text, source="grid.txt")
    assert (info.value.where, info.value.value) == ("line 2", "２.5")


def number_options(command: click.Command, path: str = "rock"):
    """Every option of every command that reads a number, with its command's path."""
    if isinstance(command, click.Group):
        for name, sub in command.commands.items():
            yield from number_options(sub, f"{path} {name}")
        return
    for param in command.params:
        if isinstance(param.type, (click.types.FloatParamType, click.types.IntParamType)):
            yield path, param


def test_every_number_option_reads_ascii_only() -> None:
    """click's FLOAT, INT, FloatRange and IntRange read "０.５" through float()/int(): every
    number option of every command is one of rock's ASCII types instead (cli/options.py)."""
    loose = [
        f"{path} {param.opts[0]}"
        for path, param in number_options(cli)
        if not isinstance(param.type, (AsciiFloat, AsciiIntRange))
    ]
    assert not loose, loose


@pytest.mark.parametrize("text", LOOKALIKES)
def test_plain_float_options_refuse_lookalikes(text: str, tmp_path: Path) -> None:
    """`record pulse --amplitude ０.５` wrote a 0.5 g pulse on main."""
    out = tmp_path / "p.txt"
    line = error_line(
        "record", "pulse", "ricker", "--amplitude", text, "--period", "0.5", "-o", str(out)
    )
    assert "ASCII" in line and not out.exists()
    assert "ASCII" in error_line(
        "record", "spectrum", str(ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"), "--scale", text
    )
