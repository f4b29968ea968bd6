"""`rock record info` and `rock record pulse` through click's CliRunner."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

from click.testing import CliRunner

from rockcli.cli.main import cli

#: Keys of each record of the `record info --format json` document (schema 2).
INFO_KEYS = {
    "name", "source", "format", "npts", "dt", "duration", "pga_g", "t_pga", "unit",
    "unit_declared", "event", "station", "component", "notes", "warnings",
}  # fmt: skip


def run(*args: str) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of `rock ARGS`."""
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_info_table_on_elc180(shared_records: Path) -> None:
    """Values of spec/records.md for ELC180.AT2: 4000 samples, dt 0.01 s, t(PGA) = 2.15 s."""
    code, out, _ = run("record", "info", str(shared_records / "ELC180.AT2"))
    assert code == 0
    for label in ("format", "samples", "time of PGA", "PGA (m/s²)"):
        assert f"│ {label}" in out
    assert "4000" in out and "0.01" in out and "2.15" in out
    assert "0.312881" in out  # the file's largest sample -.3128806E+00, to 6 digits
    assert "3.06831" in out  # × 9.80665 m/s² (units.STANDARD_GRAVITY)


def test_info_json_on_elc180(shared_records: Path) -> None:
    code, out, _ = run("record", "info", str(shared_records / "ELC180.AT2"), "--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert set(doc) == {"schema", "records"} and doc["schema"] == 2
    (data,) = doc["records"]
    assert set(data) == INFO_KEYS
    assert (data["format"], data["npts"], data["dt"]) == ("at2", 4000, 0.01)
    assert data["pga_g"] == 0.3128806  # the literal sample of the file, full precision
    assert (data["name"], data["unit"], data["notes"]) == ("ELC180", "g", [])
    # line 2 of the file: "IMPERIAL VALLEY 5/19/40 0439, EL CENTRO ARRAY #9, 180 (USGS ...)"
    assert (data["event"], data["station"], data["component"]) == (
        "IMPERIAL VALLEY 5/19/40 0439", "EL CENTRO ARRAY #9", "180"
    )  # fmt: skip
    assert data["warnings"] == []


def test_pulse_writes_a_file_that_info_reads_back(tmp_path: Path) -> None:
    path = tmp_path / "pulse.txt"
    code, out, err = run(
        "record", "pulse", "one-sine", "--amplitude", "0.3", "--period", "0.5",
        "--dt", "0.005", "--duration", "2", "-o", str(path),
    )  # fmt: skip
    assert code == 0 and out == "" and err.startswith(f"wrote {path}: one-sine")
    code, out, _ = run("record", "info", str(path), "--format", "json")
    (data,) = json.loads(out)["records"]
    assert code == 0
    # 0…2 s at 0.005 s: 401 samples; sin(ωp·Tp/4) = 1 at t = 0.125 s, a sample of the grid.
    assert (data["format"], data["npts"], data["dt"]) == ("plain", 401, 0.005)
    assert data["pga_g"] == 0.3 and data["t_pga"] == 0.125


def test_bad_file_is_one_error_line_and_exit_2(write_file: Callable[[str, str], Path]) -> None:
    path = write_file(
        "short.AT2",
        "PEER\nX\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=     3, DT= .0100 SEC\n .1 .2\n",
    )
    code, out, err = run("record", "info", str(path))
    assert code == 2 and out == ""
    assert err == (
        f"error: {path}: line 4 (NPTS): 2 values read but the header declares 3 "
        "(got 2; allowed: exactly 3 values)\n"
    )


def test_missing_file_exit_2() -> None:
    code, _, err = run("record", "info", "nowhere.AT2")
    assert code == 2
    # Named before the command runs, with every other missing input (issue 19).
    assert err == "error: nowhere.AT2: FILES: the file does not exist\n"


def test_bad_pulse_argument_exit_2(tmp_path: Path) -> None:
    args = ["record", "pulse", "ricker", "--amplitude", "-1", "--period", "0.5"]
    code, _, err = run(*args, "-o", str(tmp_path / "x.txt"))
    assert code == 2
    assert err == (
        "error: --amplitude: must be greater than 0 (got -1.0; allowed: a finite number > 0 [g])\n"
    )


def test_help_lists_the_record_commands() -> None:
    code, out, _ = run("record", "--help")
    assert code == 0 and "info" in out and "pulse" in out


def test_record_command_module_does_not_import_numpy() -> None:
    """cli/record.py imports the record package lazily, so `rock --help` stays light."""
    probe = "import sys, rockcli.cli.record; print('numpy' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "False"


def test_info_takes_several_files(shared_records: Path) -> None:
    files = [str(shared_records / n) for n in ("ELC180.AT2", "ESM_GREECE2019_HL.DLFA.HNE.ASC")]
    code, out, _ = run("record", "info", *files)
    assert code == 0
    assert "Record ELC180" in out and "Record ESM_GREECE2019_HL.DLFA.HNE" in out
    assert "EL CENTRO ARRAY #9" in out and "HL.DLFA" in out and "HNE" in out
    code, out, _ = run("record", "info", *files, "--format", "json")
    names = [rec["name"] for rec in json.loads(out)["records"]]
    assert names == ["ELC180", "ESM_GREECE2019_HL.DLFA.HNE"]


def test_info_shows_warnings_under_the_table(write_file: Callable[[str, str], Path]) -> None:
    path = write_file("ms2.txt", "0 24.5\n0.01 -12\n0.02 1.2\n")  # m/s² values read as g
    code, out, _ = run("record", "info", str(path))
    assert code == 0 and "warning: PGA 24.5 g" in out.replace("\n", " ")
    code, out, _ = run("record", "info", str(path), "--format", "json")
    (data,) = json.loads(out)["records"]
    assert len(data["warnings"]) == 1 and "check the unit" in data["warnings"][0]
