"""A suite's time history as data and as tables: the records, the code's rule, the verdict.

The JSON contract (issue 10): ``suite`` = {"n", "rule": "mean" | "worst", "measure",
"limit_ratio", "verdict", "overturned_records", "records": [{"name", "scale", "pga_g",
"max_ratio", "overturned"}], "compatibility": {"passed", "period_range": [a, b], "min_ratio",
"max_ratio"} or null}.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.report.table import Column, Table
from rockcli.studies.suite.rule import SuiteMeasure

RECORD_COLUMNS = (
    Column("name", "record", ""),
    Column("scale", "scale", "", "{:.4g}"),
    Column("pga_g", "PGA", "g", "{:.4f}"),
    Column("max_ratio", "max θ/α", "", "{:.4f}"),
    Column("overturned", "overturned", ""),
)


def suite_document(
    measure: SuiteMeasure,
    rows: Sequence[Mapping[str, Any]],
    compatibility: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The ``suite`` section of assess/compare JSON with a suite."""
    return {
        "n": measure.n,
        "rule": measure.rule,
        "measure": measure.measure,
        "limit_ratio": measure.limit_ratio,
        "verdict": "passes" if measure.passed else "fails",
        "overturned_records": measure.overturned_records,
        "records": [
            {k: r[k] for k in ("name", "scale", "pga_g", "max_ratio", "overturned")} for r in rows
        ],
        "compatibility": None if compatibility is None else dict(compatibility),
    }


def records_table(doc: Mapping[str, Any]) -> Table:
    """One row per record: its scale, PGA, max θ/α over both polarities, overturned."""
    return Table("Records of the suite, both polarities", RECORD_COLUMNS, tuple(doc["records"]))


def suite_verdict(doc: Mapping[str, Any]) -> str:
    """The verdict line: the rule, the measure against its limit, the overturns, and whether
    the suite is compatible with its target spectrum."""
    how = "mean" if doc["rule"] == "mean" else "largest"
    line = (
        f"{doc['verdict']}: the {how} of max θ/α over {doc['n']} records is "
        f"{doc['measure']:.4f} against {doc['limit_ratio']:g} (NTC 2018 §7.3.5); "
        f"{doc['overturned_records']} of {doc['n']} overturn"
    )
    compat = doc.get("compatibility")
    if compat is not None and not compat["passed"]:
        line += " — the suite is not compatible with its target spectrum"
    return line
