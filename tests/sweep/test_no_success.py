"""Issue 20, item 3: a study that cannot give any result is bad input (exit 2), not a study
done.

Measured before the change (main): a study whose suite target gives the SLV spectrum only,
on a base model without a code spectrum of its own, wrote every case as a row with the same
error (naming the suite file by its absolute path) and exited 0; `rock compare --suite` on the
same model and suite exits 2. Now the study is refused when it loads, with compare's message
(what is allowed: the study's own options); and any study whose every case fails ends with
exit 2 once cases.csv and summary.json are written.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.sweep.conftest import BASE, STUDY, WriteStudy
from tests.sweep.test_suite_entries import DEMAND, SUITE

#: The suite entry alone: a study of 2 α × 2 K under the three pulses' suite.
SUITE_STUDY = """\
base = "wall.toml"
records_dir = "records"

[[axes]]
path = "geometry.alpha"
name = "alpha"
values = [0.1, 0.2]

[[axes]]
path = ["restrainers[0].k_pos", "restrainers[0].k_neg"]
name = "K"
values = [0.0, 1e6]

[[records]]
suite = "suite.toml"
"""


def run(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stderr


def suite_study(write_study: WriteStudy, tmp_path: Path, base: str) -> Path:
    study = write_study(SUITE_STUDY, base)
    (tmp_path / "records" / "suite.toml").write_text(SUITE, encoding="utf-8")
    return study


def test_a_suite_target_the_code_check_cannot_use_is_refused_as_compare_does(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    suite_study(write_study, tmp_path, BASE)  # the base sets no code spectrum
    monkeypatch.chdir(tmp_path)
    code, stderr = run("sweep", "study.toml", "--out", "out", "--no-progress", "-j", "1")
    compare_code, compare_stderr = run("compare", "wall.toml", "--suite", "records/suite.toml")
    assert (code, compare_code) == (2, 2)
    assert stderr.count("\n") == 1
    # compare's line, but for what is allowed: what a study can do about it.
    problem, allowed = stderr.split("allowed: ")
    assert compare_stderr.startswith(problem)
    assert problem == (
        "error: records/suite.toml: target: the target gives the SLV spectrum only; the code "
        "check also needs SLD (got 'ag, F0, Tc_star (SLV)'; "
    )
    assert allowed == (
        "lon, lat in the suite's [target] (every limit state from the hazard grid), or "
        "[ntc.demand] or [ntc.site] in the base model)\n"
    )
    assert not (tmp_path / "out").exists()  # refused before any work


def test_the_same_study_runs_when_the_model_gives_the_spectra(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = suite_study(write_study, tmp_path, BASE + DEMAND)
    code, stderr = run("sweep", str(study), "--out", str(tmp_path / "out"), "--no-progress")
    assert code == 0, stderr


def test_a_study_where_no_case_succeeds_exits_2(write_study: WriteStudy, tmp_path: Path) -> None:
    # The kinematic check alone, without records and without a code spectrum in the model:
    # each case fails as it runs. The files are written (each case's error is in cases.csv),
    # then the study ends as bad input with the first case's error.
    text = STUDY.split("[[records]]")[0].replace("base =", 'analyses = ["kinematic"]\nbase =')
    study = write_study(text)
    out = tmp_path / "out"
    code, stderr = run("sweep", str(study), "--out", str(out), "--no-progress", "-j", "1")
    assert code == 2
    assert stderr.count("\n") == 1
    assert stderr.startswith(
        f"error: {study}: no case of the study succeeded (each case's error is in "
        f"{out / 'cases.csv'}); case 0: ntc: no seismic demand"
    )
    with (out / "cases.csv").open(encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 8 and all(r["error"] for r in rows)
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert summary["cases"] == summary["errors"] == 8


def test_a_suite_state_the_edition_lacks_is_refused_when_the_study_loads(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # The base model's edition (2009) checks SLD and SLV only; the suite's target is at SLC.
    study = suite_study(write_study, tmp_path, BASE + DEMAND)
    suite = tmp_path / "records" / "suite.toml"
    suite.write_text(SUITE.replace("[target]", '[target]\nlimit_state = "SLC"'), encoding="utf-8")
    code, stderr = run("sweep", str(study), "--out", str(tmp_path / "out"), "--no-progress")
    assert code == 2
    assert stderr == (
        f"error: {tmp_path / 'records' / 'suite.toml'}: target.limit_state: the code check of "
        "this edition (2009) has no SLC verdict to compare the suite with (got 'SLC'; allowed: "
        'SLD, SLV (or analyses = ["rocking"], the time history alone))\n'
    )
