"""A model under a record suite: the suite's compatibility with its target, every record
through the time history, and the code's rule — as data (rendered by rockcli.report.suite).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rockcli.studies.suite.rule import DEFAULT_LIMIT_RATIO, SuiteMeasure, suite_measure
from rockcli.studies.suite.run import SuiteRecord, outcomes, run_suite


@dataclass(frozen=True)
class SuiteAssessment:
    """The model's name and kind, the suite's name, every record's row (run.record_row), the
    code's rule over them, and the compatibility of the suite (passed, range, ratios)."""

    name: str
    kind: str
    suite: str
    rows: list[dict[str, Any]]
    measure: SuiteMeasure
    compatibility: dict[str, Any]


def assess_suite(
    model_path: str,
    suite_path: str,
    grid_file: str | None,
    *,
    engine: str = "fast",
    ground: bool = False,
    jobs: int = 1,
    progress: Callable[[int, int], None] | None = None,
) -> SuiteAssessment:
    """Both polarities of the model under every record of the suite (its scales applied), on
    ``jobs`` local workers, and the suite measure by the code's rule (rule.suite_measure)
    against the model's limit for the suite target's limit state (limit_for).

    The compatibility check runs first: a suite that fails it still runs, and says so.
    """
    from rockcli.model.load import read_toml, validate_model
    from rockcli.studies.sweep.executor import local_executor
    from rockcli.suites.load import load_suite
    from rockcli.suites.run import check_numbers, run_suite_check

    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    settings = load_suite(suite_path)
    check = run_suite_check(settings, grid_file)
    items = [
        SuiteRecord(entry.name, entry.scale, record)
        for entry, record in zip(settings.entries, check.records, strict=True)
    ]
    with local_executor(min(jobs, len(items))) as lanes:
        rows = run_suite(
            table, items, lanes, engine=engine, ground=ground, file=model_path, progress=progress
        )
    limit = limit_for(model, settings.target.limit_state.value)
    measure = suite_measure(outcomes(rows), limit)  # ValueError: a worker died twice
    numbers = check_numbers(check.check)
    compatibility = {
        "passed": numbers["passed"],
        "period_range": list(settings.period_range),
        "min_ratio": numbers["min_ratio"],
        "max_ratio": numbers["max_ratio"],
    }
    return SuiteAssessment(model.name, str(model.kind), settings.name, rows, measure, compatibility)


def limit_for(model: Any, limit_state: str) -> float:
    """The model's ``analysis.limit_ratio`` for the limit state, else θ/α = 1."""
    limits = model.analysis.limit_ratio or {}
    for state, value in limits.items():
        if str(state) == limit_state:
            return float(value)
    return DEFAULT_LIMIT_RATIO
