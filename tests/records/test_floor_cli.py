"""`rock record floor`: a record's floor motion at height, written as plain text in g."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.floor import floor_motion
from rockcli.records.files import read_record

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "one-sine_Tp1s_0.35g.txt"
PARAMETERS = ["--T1", "0.3", "--psi", "1.0", "--gamma", "1.2"]


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_help_names_the_formula_and_options() -> None:
    code, stdout, _ = run("record", "floor", "--help")
    assert code == 0
    for text in ("ü_Z(t) = ü_g(t) + γ·ψ·ẍ₁(t)", "--T1", "--psi", "--gamma", "--xi", "--force"):
        assert text in stdout


def test_writes_the_floor_motion_with_its_parameters(tmp_path: Path) -> None:
    out = tmp_path / "floor.txt"
    code, stdout, err = run(
        "record", "floor", str(PULSE), *PARAMETERS, "--xi", "0.02", "-o", str(out)
    )
    assert code == 0 and stdout == "" and err.startswith(f"wrote {out}: 601 samples")
    ground, floor = read_record(PULSE), read_record(out)
    # The file holds the exact floats (written with repr), so the core's result bit for bit.
    expected = floor_motion(ground.time, ground.accel, T1=0.3, psi=1.0, gamma=1.2, xi=0.02)
    assert np.array_equal(floor.accel, expected) and np.array_equal(floor.time, ground.time)
    text = out.read_text()
    assert "# source: " + str(PULSE) in text
    assert "T1 = 0.3 s, ψ = 1, γ = 1.2, ξ = 0.02" in text


def test_the_default_damping_is_five_percent(tmp_path: Path) -> None:
    code, stdout, _ = run("record", "floor", str(PULSE), *PARAMETERS, "-o", "-")
    assert code == 0 and "ξ = 0.05" in stdout


def test_dash_writes_to_stdout(tmp_path: Path) -> None:
    code, stdout, err = run("record", "floor", str(PULSE), *PARAMETERS, "-o", "-")
    assert code == 0 and err == ""
    assert stdout.startswith("# rock record: time [s], acceleration [g]\n")
    back = tmp_path / "back.txt"
    back.write_text(stdout)
    ground = read_record(PULSE)
    expected = floor_motion(ground.time, ground.accel, T1=0.3, psi=1.0, gamma=1.2)
    assert np.array_equal(read_record(back).accel, expected)


def test_plain_record_options_are_read(tmp_path: Path) -> None:
    """A one-column file in cm/s² with --dt: the same floor motion as the same record in g."""
    ground = read_record(PULSE)
    one_column = tmp_path / "cm.txt"
    one_column.write_text("".join(f"{float(a) * 980.665!r}\n" for a in ground.accel))
    out = tmp_path / "floor.txt"
    args = ["--as", "plain", "--dt", "0.005", "--units", "cm/s2", "-o", str(out)]
    code, _, err = run("record", "floor", str(one_column), *PARAMETERS, *args)
    assert code == 0, err
    expected = floor_motion(ground.time, ground.accel, T1=0.3, psi=1.0, gamma=1.2)
    # cm/s² → g divides by 980.665 again: each input sample off by ~2 ε, which the (linear,
    # stable) oscillator carries to the output at the scale of its peak: tolerance 1e-13 of it.
    error = np.max(np.abs(read_record(out).accel - expected))
    assert error <= 1e-13 * np.max(np.abs(expected))


def test_output_is_checked_before_reading(tmp_path: Path) -> None:
    out = tmp_path / "exists.txt"
    out.write_text("keep me\n")
    # The input is not a record: the error is the output's, so it was checked first.
    garbage = tmp_path / "garbage.AT2"
    garbage.write_text("not a record\n")
    code, _, err = run("record", "floor", str(garbage), *PARAMETERS, "-o", str(out))
    assert code == 2 and "file exists" in err and "--force" in err
    assert out.read_text() == "keep me\n"


def test_force_overwrites(tmp_path: Path) -> None:
    out = tmp_path / "floor.txt"
    out.write_text("old\n")
    code, _, err = run("record", "floor", str(PULSE), *PARAMETERS, "-o", str(out), "--force")
    assert code == 0 and err.startswith(f"wrote {out}: ")
    assert read_record(out).npts == 601


@pytest.mark.parametrize(
    ("option", "value", "allowed"),
    [
        ("--T1", "0", "0.01 s ≤ T1 ≤ 10 s"),
        ("--T1", "-0.3", "0.01 s ≤ T1 ≤ 10 s"),
        ("--T1", "nan", "0.01 s ≤ T1 ≤ 10 s"),
        ("--psi", "-0.1", "0 ≤ ψ ≤ 1.5"),
        ("--psi", "1.6", "0 ≤ ψ ≤ 1.5"),
        ("--psi", "nan", "0 ≤ ψ ≤ 1.5"),
        ("--gamma", "0", "0.001 ≤ γ ≤ 3"),
        ("--gamma", "inf", "0.001 ≤ γ ≤ 3"),
        ("--xi", "1", "0 ≤ ξ < 1"),
        ("--xi", "-0.01", "0 ≤ ξ < 1"),
    ],
)
def test_bad_value_is_one_error_line(tmp_path: Path, option: str, value: str, allowed: str) -> None:
    values = dict(zip(PARAMETERS[::2], PARAMETERS[1::2], strict=True))
    values[option] = value
    args = [x for pair in values.items() for x in pair]
    out = tmp_path / "floor.txt"
    code, stdout, err = run("record", "floor", str(PULSE), *args, "-o", str(out))
    assert code == 2 and stdout == "" and not out.exists()
    assert err.count("\n") == 1 and err.startswith(f"error: {option}: out of range (got ")
    assert allowed in err and repr(float(value)) in err


def test_missing_parameter_is_a_usage_error(tmp_path: Path) -> None:
    code, _, err = run("record", "floor", str(PULSE), "--T1", "0.3", "--psi", "1", "-o", "-")
    assert code == 2 and "--gamma" in err


def test_real_record(shared_records: Path, tmp_path: Path) -> None:
    """ELC180.AT2 through the CLI: the AT2 reader, then the core, bit for bit."""
    source = shared_records / "ELC180.AT2"
    out = tmp_path / "elc-floor.txt"
    code, _, err = run(
        "record",
        "floor",
        str(source),
        "--T1",
        "0.5",
        "--psi",
        "1.5",
        "--gamma",
        "1.3",
        "-o",
        str(out),
    )
    assert code == 0, err
    ground = read_record(source)
    expected = floor_motion(ground.time, ground.accel, T1=0.5, psi=1.5, gamma=1.3)
    assert np.array_equal(read_record(out).accel, expected)
