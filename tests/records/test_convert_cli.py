"""`rock record convert`: trim, resample, scale and flip a record into plain text in g."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.records.files import read_record

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "one-sine_Tp1s_0.35g.txt"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_convert_trim_resample_scale(tmp_path: Path) -> None:
    out = tmp_path / "c.txt"
    code, _, err = run(
        "record",
        "convert",
        str(PULSE),
        "--trim",
        "0.1,1.1",
        "--resample",
        "0.001",
        "--pga",
        "0.5",
        "-o",
        str(out),
    )
    assert code == 0, err
    rec = read_record(out)
    # 1 s window at 1 ms: 1001 samples from t = 0 (re-zeroed); the PGA hits the target exactly.
    assert rec.npts == 1001 and rec.dt == 0.001 and rec.time[0] == 0.0
    assert rec.pga == 0.5


def test_flip_twice_is_the_original(tmp_path: Path) -> None:
    once, twice = tmp_path / "1.txt", tmp_path / "2.txt"
    assert run("record", "convert", str(PULSE), "--flip", "-o", str(once))[0] == 0
    assert run("record", "convert", str(once), "--flip", "-o", str(twice))[0] == 0
    original, back = read_record(PULSE), read_record(twice)
    assert np.array_equal(original.accel, back.accel)
    assert np.array_equal(-original.accel, read_record(once).accel)


def test_bad_window_is_one_error_line(tmp_path: Path) -> None:
    code, _, err = run(
        "record", "convert", str(PULSE), "--trim", "soon", "-o", str(tmp_path / "x.txt")
    )
    assert code == 2 and err.startswith("error: --trim: ") and "'soon'" in err


def test_bad_scale_names_the_option(tmp_path: Path) -> None:
    code, _, err = run(
        "record", "convert", str(PULSE), "--scale", "0", "-o", str(tmp_path / "x.txt")
    )
    assert code == 2 and err.startswith("error: --scale: ")


def test_scale_and_pga_together_are_refused(tmp_path: Path) -> None:
    # Item 17, found in review: convert accepted both and let --pga override --scale silently.
    out = tmp_path / "x.txt"
    code, _, err = run(
        "record", "convert", str(PULSE), "--scale", "2", "--pga", "0.3", "-o", str(out)
    )
    assert code == 2 and err.startswith("error: --scale: conflicts with --pga")
    assert not out.exists()


def test_output_is_checked_before_reading(tmp_path: Path) -> None:
    """An existing output without --force is refused before the input is read: the input is
    not a record, and the error is the output's. (A missing input is named first, with every
    missing input, before the command runs: issue 19.)"""
    out = tmp_path / "exists.txt"
    out.write_text("keep me\n")
    garbage = tmp_path / "garbage.AT2"
    garbage.write_text("not a record\n")
    code, _, err = run("record", "convert", str(garbage), "-o", str(out))
    assert code == 2 and "file exists" in err and "--force" in err
    assert out.read_text() == "keep me\n"
    code, _, err = run("record", "convert", str(tmp_path / "missing.AT2"), "-o", str(out))
    assert (code, err) == (2, f"error: {tmp_path / 'missing.AT2'}: FILE: the file does not exist\n")
    assert out.read_text() == "keep me\n"


def test_force_overwrites_and_wrote_goes_to_stderr(tmp_path: Path) -> None:
    out = tmp_path / "c.txt"
    out.write_text("old\n")
    code, stdout, err = run("record", "convert", str(PULSE), "-o", str(out), "--force")
    assert code == 0 and stdout == "" and err.startswith(f"wrote {out}: ")
    assert read_record(out).npts == read_record(PULSE).npts


def test_dash_writes_to_stdout(tmp_path: Path) -> None:
    code, stdout, err = run("record", "convert", str(PULSE), "-o", "-")
    assert code == 0 and err == ""
    assert stdout.startswith("# rock record: time [s], acceleration [g]\n")
    back = tmp_path / "back.txt"
    back.write_text(stdout)
    assert np.array_equal(read_record(back).accel, read_record(PULSE).accel)


def test_pulse_output_policy(tmp_path: Path) -> None:
    out = tmp_path / "p.txt"
    out.write_text("old\n")
    args = ["record", "pulse", "ricker", "--amplitude", "0.3", "--period", "0.5", "-o", str(out)]
    code, _, err = run(*args)
    assert code == 2 and "file exists" in err
    assert run(*args, "--force")[0] == 0


def test_resample_lowering_the_pga_warns_on_stderr_and_in_the_file(tmp_path: Path) -> None:
    """The one-sine of Tp = 1 s peaks at 0.35 g on the 5 ms grid; 0.3 s samples miss it."""
    out = tmp_path / "coarse.txt"
    code, _, err = run("record", "convert", str(PULSE), "--resample", "0.3", "-o", str(out))
    assert code == 0 and "warning: resampling to dt = 0.3 s lowered the PGA by" in err
    assert "# warning: resampling to dt = 0.3 s lowered the PGA by" in out.read_text()


def test_resample_beyond_the_sample_cap_names_the_option(tmp_path: Path) -> None:
    # The 3 s pulse at dt = 1e-8 s (within the bounds of a record's dt) is 3e8 samples.
    code, _, err = run(
        "record", "convert", str(PULSE), "--resample", "1e-8", "-o", str(tmp_path / "x.txt")
    )
    assert code == 2 and err.startswith("error: --resample: ") and "10,000,000" in err


def test_pulse_dt_beyond_the_sample_cap(tmp_path: Path) -> None:
    code, _, err = run(
        "record", "pulse", "half-sine", "--amplitude", "0.3", "--period", "1",
        "--dt", "1e-9", "-o", str(tmp_path / "x.txt"),
    )  # fmt: skip
    assert code == 2 and "10,000,000" in err


def test_converted_times_are_clean(tmp_path: Path) -> None:
    out = tmp_path / "c.txt"
    assert run("record", "convert", str(PULSE), "--resample", "0.1", "-o", str(out))[0] == 0
    text = out.read_text()
    assert "\n0.3 " in text and "0.30000000000000004" not in text
