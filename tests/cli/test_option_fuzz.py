"""Every numeric option of every command, set to an edge of double precision: a result or one
error line, never an internal error, a traceback or a NaN (issue 20, items 8 and 9).

On main, `rock record floor --T1 1e-300` exited 3 (OverflowError) and `--T1 1e300` wrote NaN
samples, `rock assess --dt 1e300` on a one-column record exited 3 (a non-finite state), and
`rock suite check --period 1e300` exited 3. Each option now has the bounds of its model
counterpart (the time step of a record read, a building's T1 and γ, a response spectrum's
periods, a tie-rod's length and count).

Every option with every value: 28 × 15 command lines, about 10 s (a 3 s pulse rocks in
milliseconds once the engine is compiled).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
ALTAR = str(ROOT / "examples" / "altar.toml")
WALL = str(ROOT / "examples" / "wall.toml")
PULSE = str(ROOT / "records" / "one-sine_Tp1s_0.35g.txt")
PULSES = str(ROOT / "records")
TARGET = "ag=0.25,F0=2.5,Tc_star=0.3,limit_state=SLV"
#: The NTC hazard grid beside the clone (--site needs it; without it --site is refused first).
GRID = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
WITH_GRID = ["--hazard-grid", str(GRID)] if GRID.is_file() else []

#: The edges of double precision, signed zero, the non-finite values, and ordinary numbers.
EXTREMES = ["1e300", "-1e300", "1e-300", "5e-324", "1.7e308", "-0.0", "0", "nan", "inf", "-inf"]
ORDINARY = ["0.5", "1", "3", "0.02", "100"]

#: (the command line before the option, the option, how the value is written in it).
#: ``{}`` is the fuzzed number; a pair option keeps its other half ordinary.
ONE_COLUMN = "one.txt"  # written in the test's folder: a one-column record that needs --dt
OPTIONS: list[tuple[list[str], str, str]] = [
    (["record", "floor", PULSE, "--psi", "1", "--gamma", "1.2", "-o", "-"], "--T1", "{}"),
    (["record", "floor", PULSE, "--T1", "0.5", "--gamma", "1.2", "-o", "-"], "--psi", "{}"),
    (["record", "floor", PULSE, "--T1", "0.5", "--psi", "1", "-o", "-"], "--gamma", "{}"),
    (["record", "floor", PULSE, "--T1", "0.5", "--psi", "1", "--gamma", "1", "-o", "-"], "--xi",
     "{}"),
    (["record", "convert", PULSE, "-o", "-"], "--resample", "{}"),
    (["record", "convert", PULSE, "-o", "-"], "--scale", "{}"),
    (["record", "convert", PULSE, "-o", "-"], "--pga", "{}"),
    (["record", "convert", PULSE, "-o", "-"], "--trim", "{},2"),
    (["record", "convert", PULSE, "-o", "-"], "--trim", "0.5,{}"),
    (["record", "convert", ONE_COLUMN, "-o", "-"], "--dt", "{}"),
    (["record", "pulse", "ricker", "--period", "0.5", "-o", "-"], "--amplitude", "{}"),
    (["record", "pulse", "one-sine", "--amplitude", "0.3", "-o", "-"], "--period", "{}"),
    (["record", "pulse", "half-sine", "--amplitude", "0.3", "--period", "1", "-o", "-"], "--dt",
     "{}"),
    (["record", "pulse", "rectangular", "--amplitude", "0.3", "--period", "1", "-o", "-"],
     "--duration", "{}"),
    (["record", "info", ONE_COLUMN], "--dt", "{}"),
    (["record", "spectrum", PULSE, "--periods", "0.1,1", "--format", "json"], "--damping", "{}"),
    (["record", "spectrum", PULSE, "--periods", "0.1,1", "--format", "json"], "--scale", "{}"),
    (["record", "spectrum", PULSE, "--format", "json"], "--periods", "{},1"),
    (["assess", ALTAR, "--record", PULSE, "--format", "json"], "--pga", "{}"),
    (["assess", ALTAR, "--record", ONE_COLUMN, "--format", "json"], "--dt", "{}"),
    (["compare", ALTAR, "--record", PULSE, "--format", "json"], "--scale", "{}"),
    (["kinematic", ALTAR, "--record", PULSE, "--format", "json"], "--pga", "{}"),
    (["kinematic", ALTAR, *WITH_GRID, "--format", "json"], "--site", "{},42.35"),
    (["kinematic", ALTAR, *WITH_GRID, "--format", "json"], "--site", "13.4,{}"),
    (["retrofit", WALL, "--record", PULSE, "--at", "3,0.2", "--diameters", "20"], "--length",
     "{}"),
    (["retrofit", WALL, "--record", PULSE, "--length", "3", "--diameters", "20"], "--at", "{},0.2"),
    (["retrofit", WALL, "--record", PULSE, "--at", "3,0.2", "--length", "3"], "--diameters",
     "{}"),
    (["suite", "check", PULSES, "--target", TARGET, "--format", "json"], "--period", "{}"),
]  # fmt: skip

#: A NaN or an infinity in a result (JSON's NaN/Infinity, Python's nan/inf).
NON_FINITE = re.compile(r"\b(nan|inf|infinity)\b", re.IGNORECASE)


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder with the one-column record (0.3 g sine samples, 200 values) the --dt options
    read."""
    path = tmp_path_factory.mktemp("fuzz")
    (path / ONE_COLUMN).write_text("".join(f"{0.3 * ((i % 8) - 4) / 4}\n" for i in range(200)))
    return path


def command_line(index: int, number: str, folder: Path) -> list[str]:
    head, option, shape = OPTIONS[index]
    head = [str(folder / ONE_COLUMN) if arg == ONE_COLUMN else arg for arg in head]
    return [*head, option, shape.format(number)]


@pytest.mark.parametrize("number", EXTREMES + ORDINARY)
@pytest.mark.parametrize("index", range(len(OPTIONS)), ids=[f"{o[0][0]} {o[1]}" for o in OPTIONS])
def test_a_numeric_option_gives_a_result_or_one_error_line(
    folder: Path, index: int, number: str
) -> None:
    args = command_line(index, number, folder)
    result = CliRunner().invoke(cli, args)
    assert result.exit_code in (0, 1, 2), (args, result.output)
    assert "Traceback" not in result.output, args
    if result.exit_code == 2:
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: "), (args, result.stderr)
    else:
        assert not NON_FINITE.search(result.stdout), (args, result.stdout[:500])


@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["record", "floor", PULSE, "--T1", "1e-300", "--psi", "1", "--gamma", "1"], "--T1"),
        (["record", "floor", PULSE, "--T1", "1e300", "--psi", "1", "--gamma", "1"], "--T1"),
        (["record", "floor", PULSE, "--T1", "0.5", "--psi", "1", "--gamma", "1000"], "--gamma"),
        (["record", "convert", PULSE, "--resample", "100"], "--resample"),
        (["record", "convert", PULSE, "--resample", "1e308"], "--resample"),
        (["record", "pulse", "ricker", "--amplitude", "1000", "--period", "1"], "--amplitude"),
        (["record", "pulse", "ricker", "--amplitude", "1", "--period", "1e300"], "--period"),
    ],
    ids=["T1 1e-300", "T1 1e300", "gamma 1000", "resample 100", "resample 1e308",
         "amplitude 1000", "period 1e300"],
)  # fmt: skip
def test_the_issues_options_are_refused_by_name(
    tmp_path: Path, args: list[str], option: str
) -> None:
    # Issue 20, items 8 and 9: each exited 3 or wrote a file `rock record info` refused.
    out = tmp_path / "out.txt"
    result = CliRunner().invoke(cli, [*args, "-o", str(out)])
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith(f"error: {option}: ") and result.stderr.count("\n") == 1
    assert not out.exists()


def test_a_one_column_record_with_a_huge_dt_is_refused(folder: Path) -> None:
    # On main: accepted, then the rocking run ended in a non-finite state (exit 3).
    args = ["assess", ALTAR, "--record", str(folder / ONE_COLUMN), "--dt", "1e300"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 2, result.output
    assert "dt: the time step is implausibly large" in result.stderr
    assert "1e-09 s ≤ dt ≤ 1 s" in result.stderr


@pytest.mark.parametrize(("value", "option"), [("1e300", "--length"), ("101", "--count")])
def test_retrofit_rod_options_name_themselves(value: str, option: str) -> None:
    # On main the error named --diameters ("the rod of 10 mm makes the model invalid").
    args = ["retrofit", WALL, "--record", PULSE, "--at", "3,0.2", "--length", "3", option, value]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 2 and result.stderr.startswith(f"error: {option}: ")


def test_the_helps_state_the_bounds_the_checks_apply() -> None:
    # The help texts give the bounds as numbers; they must be the constants the checks use.
    from rockcli.model.bounds import MAX_PARTICIPATION, MAX_PERIOD, MIN_MODAL, MIN_PERIOD
    from rockcli.records import periods
    from rockcli.records.lines import MAX_ABS_ACCEL_G, MAX_DT, MIN_DT

    floor = CliRunner().invoke(cli, ["record", "floor", "--help"], terminal_width=200).stdout
    assert f"T1 [s], {MIN_PERIOD:g} to {MAX_PERIOD:g}." in floor
    assert f"γ, {MIN_MODAL:g} to {MAX_PARTICIPATION:g}." in floor
    pulse = CliRunner().invoke(cli, ["record", "pulse", "--help"], terminal_width=200).stdout
    assert f"ap [g], up to {MAX_ABS_ACCEL_G:g}." in pulse
    assert f"Tp [s], {periods.MIN_PERIOD:g} to {periods.MAX_PERIOD:g}:" in pulse
    assert f"Time step [s], {MIN_DT:.0e} to {MAX_DT:g}.".replace("e-09", "e-9") in pulse
