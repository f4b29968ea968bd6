"""Output at scale: cases.csv sorted by streaming its ordered blocks (no row kept in
memory), and cases.parquet (--output parquet) with the same values, typed, readable by pyarrow
and polars."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.sweep.output import PARQUET_FILE, Output
from rockcli.studies.sweep.study import StudyPlan, load_study
from tests.sweep.conftest import STUDY, WriteStudy


@pytest.fixture
def plan(write_study: WriteStudy) -> StudyPlan:
    return load_study(str(write_study()))


def row(case: int) -> dict[str, object]:
    return {"case": case, "record": "cosine", "R": 1.5, "alpha": 0.1, "K": 0.0,
            "max_ratio": case / 10, "rocking": "survives"}  # fmt: skip


def ids_in(path: Path) -> list[int]:
    with open(path, encoding="utf-8") as fh:
        return [int(r["case"]) for r in csv.DictReader(fh)]


def test_blocks_out_of_order_are_sorted_by_copying(plan: StudyPlan, tmp_path: Path) -> None:
    # Chunks complete in any order; each is one ascending block of ids: the final file is
    # their concatenation in the order of their first id.
    out = Output(str(tmp_path / "out"), plan, 16)
    out.check(resume=False, overwrite=True)
    out.start({})
    for block in ([8, 9, 10], [0, 1], [11, 12, 13, 14, 15], [2, 3, 4, 5, 6, 7]):
        out.append(row(k) for k in block)
    out.finish()
    assert ids_in(out.cases_path) == list(range(16))
    assert [r for _, r in out.typed_rows()][3]["max_ratio"] == 0.3


def test_interleaved_blocks_are_sorted_in_memory(plan: StudyPlan, tmp_path: Path) -> None:
    # A resumed study: the kept rows and the new ones interleave; sorted all the same.
    out = Output(str(tmp_path / "out"), plan, 16)
    out.check(resume=False, overwrite=True)
    out.start({})
    for block in ([0, 4, 8], [1, 5], [2, 3, 6, 7, 9]):
        out.append(row(k) for k in block)
    out.finish()
    assert ids_in(out.cases_path) == [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]


def test_parquet_holds_the_csv_values_typed(write_study: WriteStudy, tmp_path: Path) -> None:
    pq = pytest.importorskip("pyarrow.parquet", reason="the parquet extra (pyarrow)")
    # A record named like a spreadsheet formula: guarded by a quote in the CSV, not in Parquet.
    study = write_study(STUDY.replace('name = "cosine"', 'name = "=cosine"'))
    out = tmp_path / "out"
    result = CliRunner().invoke(
        cli, ["sweep", str(study), "--out", str(out), "--jobs", "1", "--output", "parquet"]
    )
    assert result.exit_code == 0, result.stderr
    table = pq.read_table(out / PARQUET_FILE)
    with open(out / "cases.csv", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    assert table.num_rows == len(rows) == 16
    assert table.schema.field("case").type == "int64"
    assert table.schema.field("max_ratio").type == "double"
    assert table.schema.field("overturned").type == "bool"
    data = table.to_pylist()
    for mine, theirs in zip(data, rows, strict=True):
        assert mine["case"] == int(theirs["case"])
        assert math.isclose(mine["max_ratio"], float(theirs["max_ratio"]), rel_tol=0, abs_tol=0)
        assert mine["overturned"] == (theirs["overturned"] == "true")
        assert mine["t_overturn"] is None if theirs["t_overturn"] == "" else True
    assert {r["record"] for r in rows} == {"'=cosine", "ricker"}
    assert {r["record"] for r in data} == {"=cosine", "ricker"}
    pl = pytest.importorskip("polars", reason="polars reads it too, when installed")
    assert (
        pl.read_parquet(out / PARQUET_FILE)["max_ratio"].to_list()
        == table.column("max_ratio").to_pylist()
    )


def test_parquet_without_pyarrow_is_refused_before_any_work(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from rockcli.studies.sweep import output

    monkeypatch.setattr(output, "parquet_available", lambda: False)
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["sweep", str(write_study()), "--out", str(out),
                                      "--output", "parquet"])  # fmt: skip
    assert result.exit_code == 2
    assert "--output parquet: needs pyarrow" in result.stderr and "'.[parquet]'" in result.stderr
    assert not out.exists()
