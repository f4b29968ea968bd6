"""A suite through the time history: every record on the sweep's lanes, the code's rule."""

from __future__ import annotations

import tomllib

import pytest

from rockcli.analyses.assess import assess_model_output
from rockcli.model.load import validate_model
from rockcli.records.files import read_record
from rockcli.records.transform import scale
from rockcli.studies.parallel.executor import local_executor
from rockcli.studies.suite_run.rule import suite_measure
from rockcli.studies.suite_run.run import SuiteRecord, outcomes, run_suite
from tests.cli.conftest import ROOT

WALL = ROOT / "examples" / "wall.toml"
PULSES = sorted((ROOT / "records").glob("*.txt"))


def suite() -> list[SuiteRecord]:
    """The three shipped pulses as a suite, the second scaled by 1.5."""
    items = []
    for k, path in enumerate(PULSES):
        rec = read_record(str(path))
        factor = 1.5 if k == 1 else 1.0
        items.append(SuiteRecord(path.stem, factor, scale(rec, factor)))
    return items


def test_each_record_is_its_own_assessment_and_the_worst_decides() -> None:
    # Three records: the rule is the worst (NTC 2018 §7.3.5); each row is exactly the
    # assessment of the model under that record (the same engine, run on a lane).
    table = tomllib.loads(WALL.read_text(encoding="utf-8"))
    items = suite()
    with local_executor(1) as lanes:
        rows = run_suite(table, items, lanes, file=str(WALL))
    assert [r["name"] for r in rows] == [p.stem for p in PULSES]
    model = validate_model(table)
    for row, item in zip(rows, items, strict=True):
        alone = assess_model_output(model, item.record, "fast")
        assert row["max_ratio"] == alone.result.max_ratio
        assert row["pga_g"] == pytest.approx(item.record.pga, rel=1e-15)
    m = suite_measure(outcomes(rows))
    assert m.rule == "worst" and m.measure == max(r["max_ratio"] for r in rows)


def test_jobs_2_gives_the_rows_of_jobs_1() -> None:
    table = tomllib.loads(WALL.read_text(encoding="utf-8"))
    results = []
    for jobs in (1, 2):
        with local_executor(jobs) as lanes:
            results.append(run_suite(table, suite(), lanes, file=str(WALL)))
    assert results[0] == results[1]


def test_a_broken_record_is_named() -> None:
    with pytest.raises(ValueError, match="record 2 of the suite: worker died"):
        outcomes([{"case": 0, "name": "a", "scale": 1.0, "pga_g": 0.1, "max_ratio": 0.1,
                   "overturned": False}, {"case": 1, "error": "worker died"}])  # fmt: skip
