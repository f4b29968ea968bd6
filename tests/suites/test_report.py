"""The suite's document and verdict line (the JSON contract of issue 10)."""

from __future__ import annotations

from rockcli.studies.suite_run.rule import RecordOutcome, suite_measure
from rockcli.terminal.suite import history_document, history_records_table, history_verdict

ROWS = [
    {"case": k, "name": f"r{k}", "scale": 1.0, "pga_g": 0.3, "max_ratio": 0.1 * (k + 1),
     "overturned": False, "verdict": "survives"}
    for k in range(3)
]  # fmt: skip


def measure():
    return suite_measure([RecordOutcome(r["name"], 1.0, 0.3, r["max_ratio"], False) for r in ROWS])


def test_the_document_has_the_contract_keys() -> None:
    doc = history_document(measure(), ROWS, {"passed": True, "period_range": [0.15, 2.0],
                                           "min_ratio": 0.95, "max_ratio": 1.2})  # fmt: skip
    assert set(doc) == {"n", "rule", "measure", "limit_ratio", "verdict",
                        "overturned_records", "records", "compatibility"}  # fmt: skip
    assert set(doc["records"][0]) == {"name", "scale", "pga_g", "max_ratio", "overturned"}
    assert (doc["n"], doc["rule"], doc["verdict"]) == (3, "worst", "passes")
    assert len(history_records_table(doc).rows) == 3


def test_the_verdict_line_says_the_rule_and_an_incompatible_suite() -> None:
    doc = history_document(measure(), ROWS, {"passed": False, "period_range": [0.15, 2.0],
                                           "min_ratio": 0.7, "max_ratio": 1.2})  # fmt: skip
    line = history_verdict(doc)
    assert line.startswith("passes: the largest of max θ/α over 3 records is 0.3000 against 1")
    assert line.endswith("not compatible with its target spectrum")
    assert "0 of 3 overturn" in history_verdict(history_document(measure(), ROWS))
