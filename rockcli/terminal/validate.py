"""`rock validate`: the JSON document and the terminal Report of a casebook run.

JSON (a fixed contract): ``{"schema", "rock_version", "casebook", "cases": [{"id", "title",
"kind", "source", "source_it", "quantity", "unit", "expected", "obtained", "error",
"tolerance", "tolerance_type", "tolerance_reason", "passed", "status", "note", "file"}],
"passed", "failed", "skipped"}``; a skipped case has ``"passed": null``, a case without an
obtained value ``"obtained": null``, a case without an Italian source ``"source_it": null``.
"""

from __future__ import annotations

import math
from typing import Any

from rockcli.casebook.run import CasebookResult, CaseResult, Status
from rockcli.terminal.table import Column, Report, Table
from rockcli.version import __version__

SCHEMA = 1

#: What the result column says for each status.
RESULT_TEXT = {"passed": "pass", "failed": "FAIL", "skipped": "skipped"}


def validate_document(result: CasebookResult) -> dict[str, Any]:
    """The `rock validate --format json` document, full precision."""
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "casebook": result.folder,
        "cases": [case_document(case) for case in result.cases],
        "passed": result.count(Status.PASSED),
        "failed": result.count(Status.FAILED),
        "skipped": result.count(Status.SKIPPED),
    }


def case_document(case: CaseResult) -> dict[str, Any]:
    """One case; a non-finite number (an obtained NaN) as null."""
    return {
        "id": case.id,
        "title": case.title,
        "kind": case.kind,
        "source": case.source,
        "source_it": case.source_it,
        "quantity": case.quantity,
        "unit": case.unit,
        "expected": case.expected,
        "obtained": _finite(case.obtained),
        "error": _finite(case.error),
        "tolerance": case.tolerance,
        "tolerance_type": case.tolerance_type,
        "tolerance_reason": case.tolerance_reason,
        "passed": case.passed,
        "status": case.status.value,
        "note": case.note,
        "file": case.file,
    }


def _finite(value: float | None) -> float | None:
    return value if value is not None and math.isfinite(value) else None


COLUMNS = (
    Column("id", "case", align="left"),
    Column("quantity", "quantity", align="left"),
    Column("expected", "expected", fmt="{:.7g}"),
    Column("obtained", "obtained", fmt="{:.7g}"),
    Column("error", "error", fmt="{:.2g}"),
    Column("tolerance", "tolerance", align="right", short="tol."),
    Column("result", "result", align="left"),
)
#: Each case's published source: a table of its own, so that the results' table fits a
#: terminal (a source is a sentence, the other cells a word or a number).
SOURCE_COLUMNS = (Column("id", "case", align="left"), Column("source", "source", align="left"))


def validate_report(doc: dict[str, Any]) -> Report:
    """The Report: one row per case, each case's source, then why cases failed or were
    skipped, then the count."""
    rows = tuple(_row(case) for case in doc["cases"])
    notes = tuple(
        dict.fromkeys(
            f"{case['id']}: {case['note']}" if case["status"] == "failed" else case["note"]
            for case in doc["cases"]
            if case["note"]
        )
    )
    return Report(
        title=f"rock validate — {doc['casebook']}",
        tables=(
            Table("Validation casebook", COLUMNS, rows),
            Table("Sources", SOURCE_COLUMNS, rows),
        ),
        notes=notes,
        verdict=summary(doc),
    )


def _row(case: dict[str, Any]) -> dict[str, Any]:
    kind = "rel" if case["tolerance_type"] == "relative" else "abs"
    unit = "" if case["unit"] == "-" else f" [{case['unit']}]"
    return {
        "id": case["id"],
        "source": case["source"],
        "quantity": f"{case['quantity']}{unit}",
        "expected": case["expected"],
        "obtained": case["obtained"],
        "error": case["error"],
        "tolerance": f"{case['tolerance']:.2g} {kind}",
        "result": RESULT_TEXT[case["status"]],
    }


def summary(doc: dict[str, Any]) -> str:
    """``N cases: P passed, F failed, S skipped``."""
    total = len(doc["cases"])
    return (
        f"{total} cases: {doc['passed']} passed, {doc['failed']} failed, {doc['skipped']} skipped"
    )
