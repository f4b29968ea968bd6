"""`rock sweep` from the command line: the pulse study of examples/studies, errors, help.

Sources: the issue's contract (the study runs in one command, writes OUT/cases.csv, prints
the summary tables or the JSON document; bad input is one `error:` line and exit code 2).
"""

from __future__ import annotations

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.sweep.conftest import ROOT, STUDIES, WriteStudy


def sweep(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["sweep", *args])
    return result.exit_code, result.stdout, result.stderr


def test_the_pulse_study_runs(tmp_path: Path) -> None:
    out = tmp_path / "pulses"
    study = str(STUDIES / "pulses.toml")
    code, stdout, _ = sweep(study, "--out", str(out), "--no-progress", "--allow-outside")
    assert code == 0, stdout
    for text in (
        "Per record and α: code / rocking collapses (code conservative)",
        "Per K and α",
        "Totals: collapses",
        "Inconsistencies (paper §3.3)",
        "54 cases",
    ):
        assert text in stdout
    with (out / "cases.csv").open(encoding="utf-8") as f:
        assert len(list(csv.DictReader(f))) == 3 * 3 * 2 * 3


def test_json_summary(tmp_path: Path, write_study: WriteStudy) -> None:
    out = tmp_path / "out"
    code, stdout, _ = sweep(str(write_study()), "--out", str(out), "-j", "1", "--format", "json")
    assert code == 0, stdout
    doc = json.loads(stdout)
    assert doc["schema"] == 1
    assert doc["cases"] == 16
    assert doc["jobs"] == 1
    assert doc["out"] == str(out)
    assert doc == json.loads((out / "summary.json").read_text())


def test_bad_input_is_one_line_and_exit_2(write_study: WriteStudy) -> None:
    study = write_study(write_study().read_text().replace("geometry.R", "geometry.Q"))
    code, _, stderr = sweep(str(study), "--no-progress")
    assert code == 2
    assert stderr.count("\n") == 1
    assert stderr.startswith(f"error: {study}: axes[0].path: not a field of the model")


def test_resume_and_overwrite_exclude_each_other(write_study: WriteStudy) -> None:
    code, _, stderr = sweep(str(write_study()), "--resume", "--overwrite")
    assert code == 2
    assert "exclude each other" in stderr


def test_help_imports_no_numeric_stack() -> None:
    code = (
        "import sys\nfrom click.testing import CliRunner\nfrom rockcli.cli.main import cli\n"
        "r = CliRunner().invoke(cli, ['sweep', '--help'])\nassert r.exit_code == 0, r.output\n"
        "assert '--resume' in r.output and '--scheduler' in r.output\n"
        "heavy = {'numpy', 'numba', 'scipy'} & set(sys.modules)\nassert not heavy, heavy\n"
    )
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_the_collapse_map(tmp_path: Path, write_study: WriteStudy) -> None:
    pytest.importorskip("matplotlib", reason="matplotlib not installed: pip install '.[plot]'")
    png = tmp_path / "map.png"
    code, stdout, _ = sweep(str(write_study()), "--out", str(tmp_path / "o"), "--plot", str(png))
    assert code == 0, stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
