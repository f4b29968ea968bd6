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
