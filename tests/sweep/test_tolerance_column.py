"""`rock sweep --check-tolerance`: each rocking case run again at rtol/1000, a ``sensitive``
column in cases.csv (and cases.parquet), the count of sensitive cases in the summary; without
the flag, cases.csv and the work are what they were.

Sources: the case of the project's issue 19 (item 5) — the wall 0.50 × 4.00 × 1.00 m with an
18 kN load on top 0.10 m from O, on NORTHR_ARL360 × 0.8, whose polarity −1 moves from
max θ/α 0.2727 to 0.2524 at rtol 1e-11 (tests/cli/test_tolerance_check.py) — beside the same
wall with its load on the mid-plane and under the shipped Ricker pulse, which do not move
(measured: by less than 1e-6 relative, or both polarities overturn at both tolerances).
"""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.sweep.output import RESULT_COLUMNS
from tests.cli.test_tolerance_check import ISSUE_WALL, RECORD
from tests.sweep.conftest import PULSES

#: The issue's wall with its load 0.10 m from O (the issue's) or on the mid-plane (0.25 m),
#: under the issue's record and the Ricker pulse: 4 cases, case 0 the issue's.
STUDY = f"""\
name = "the issue's wall"
base = "wall.toml"
analyses = ["rocking"]
records_dir = "records"

[[axes]]
path = "loads[0].from_pivot"
name = "x"
values = [0.10, 0.25]

[[records]]
name = "northr"
path = "{RECORD}"
scale = 0.8

[[records]]
name = "ricker"
path = "ricker_Tp0.5s_0.5g.txt"
"""


@pytest.fixture
def study(tmp_path: Path, shared_records: Path) -> Path:
    records = tmp_path / "records"
    records.mkdir()
    shutil.copy(shared_records / RECORD, records)
    shutil.copy(PULSES / "ricker_Tp0.5s_0.5g.txt", records)
    (tmp_path / "wall.toml").write_text(ISSUE_WALL, encoding="utf-8")
    path = tmp_path / "study.toml"
    path.write_text(STUDY, encoding="utf-8")
    return path


def sweep(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["sweep", *args, "--jobs", "1", "--no-progress"])
    return result.exit_code, result.stdout, result.stderr


def read_csv(path: Path) -> tuple[list[str], list[dict[str, str]]]:
    with path.open(encoding="utf-8", newline="") as f:
        reader = csv.DictReader(f)
        return list(reader.fieldnames or []), list(reader)


def test_check_tolerance_adds_the_column_and_counts_sensitive_cases(study: Path) -> None:
    out = study.parent / "checked"
    code, stdout, err = sweep(str(study), "--out", str(out), "--check-tolerance", "--format",
                              "json")  # fmt: skip
    assert code == 0, err
    header, rows = read_csv(out / "cases.csv")
    assert header == ["case", "record", "x", *RESULT_COLUMNS, "sensitive"]
    assert [r["sensitive"] for r in rows] == ["true", "false", "false", "false"]
    doc = json.loads(stdout)
    assert doc["sensitive_cases"] == 1 and doc["check_tolerance"] is True
    by_record = {r["record"]: r["sensitive_cases"] for r in doc["records"]}
    assert by_record == {"northr": 1, "ricker": 0}
    code, stdout, err = sweep(str(study), "--out", str(out), "--check-tolerance", "--force")
    assert code == 0, err
    assert "tol.-sensitive" in stdout
    assert "1 of 4 cases tolerance-sensitive" in " ".join(stdout.split())


def test_without_the_flag_cases_csv_is_unchanged_and_nothing_runs_again(
    study: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    checked, plain = study.parent / "checked", study.parent / "plain"
    assert sweep(str(study), "--out", str(checked), "--check-tolerance")[0] == 0

    def no_check(*args: object, **kwargs: object) -> None:
        raise AssertionError("the tolerance check ran without --check-tolerance")

    monkeypatch.setattr("rockcli.dynamics.tolerance.check_tolerance", no_check)
    code, stdout, err = sweep(str(study), "--out", str(plain), "--format", "json")
    assert code == 0, err
    header, rows = read_csv(plain / "cases.csv")
    assert header == ["case", "record", "x", *RESULT_COLUMNS]  # the header it always had
    _, with_check = read_csv(checked / "cases.csv")
    assert rows == [{k: v for k, v in r.items() if k != "sensitive"} for r in with_check]
    doc = json.loads(stdout)
    assert doc["sensitive_cases"] is None and doc["check_tolerance"] is False
    assert "tol.-sensitive" not in sweep(str(study), "--out", str(plain), "--resume")[1]


def test_the_parquet_file_has_the_column_typed(study: Path) -> None:
    pq = pytest.importorskip("pyarrow.parquet", reason="the parquet extra is not installed")
    out = study.parent / "parquet"
    code, _, err = sweep(str(study), "--out", str(out), "--check-tolerance", "--output",
                         "parquet")  # fmt: skip
    assert code == 0, err
    table = pq.read_table(out / "cases.parquet")
    assert str(table.schema.field("sensitive").type) == "bool"
    assert table.column("sensitive").to_pylist() == [True, False, False, False]
