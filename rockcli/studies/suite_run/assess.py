"""A model under a record suite: the suite's compatibility with its target, every record
through the time history, and the code's rule — as data (rendered by rockcli.terminal.suite).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rockcli.studies.suite_run.rule import DEFAULT_LIMIT_RATIO, SuiteMeasure, suite_measure
from rockcli.studies.suite_run.run import SuiteRecord, outcomes, run_suite

if TYPE_CHECKING:
    from rockcli.suites.load import SuiteSettings
    from rockcli.suites.run import SuiteCheck


@dataclass(frozen=True)
class SuiteAssessment:
    """The model's name and kind, the suite's name, every record's row (run.record_row), the
    code's rule over them, the compatibility of the suite (passed, range, ratios), and the
    warnings of the model and of the records (a unit slip)."""

    name: str
    kind: str
    suite: str
    rows: list[dict[str, Any]]
    measure: SuiteMeasure
    compatibility: dict[str, Any]
    warnings: tuple[str, ...] = ()


@dataclass(frozen=True)
class LoadedSuite:
    """A model and a suite, read and checked: the model file's table and validated model,
    the suite's settings and its compatibility check (with the scaled records)."""

    model_path: str
    table: dict[str, Any]
    model: Any
    check: SuiteCheck

    @property
    def settings(self) -> SuiteSettings:
        """The suite file's settings."""
        return self.check.settings


def load_suite_and_model(
    model_path: str,
    suite_path: str,
    grid_file: str | None,
    target: str | None = None,
    allow_outside: bool = False,
) -> LoadedSuite:
    """Read the model and the suite (a file, or a folder with its ``target`` text), and check
    the suite against its target (InputError on bad input in either; the compatibility
    check's verdict itself is data). allow_outside: the suite's records may lie outside its
    folder (rockcli.suites.load.load_suite)."""
    from rockcli.model.load import read_toml, validate_model
    from rockcli.suites.load import load_suite
    from rockcli.suites.run import run_suite_check

    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    settings = load_suite(suite_path, target=target, allow_outside=allow_outside)
    check = run_suite_check(settings, grid_file)
    return LoadedSuite(model_path, table, model, check)


def assess_suite(
    model_path: str,
    suite_path: str,
    grid_file: str | None,
    *,
    engine: str = "fast",
    ground: bool = False,
    jobs: int = 1,
    progress: Callable[[int, int], None] | None = None,
    target: str | None = None,
    allow_outside: bool = False,
    mechanism: str | None = None,
) -> SuiteAssessment:
    """Both polarities of the model under every record of the suite (its scales applied), on
    ``jobs`` local workers, and the suite measure by the code's rule (rule.suite_measure)
    against the model's limit for the suite target's limit state (limit_for).

    The compatibility check runs first: a suite that fails it still runs, and says so.
    """
    loaded = load_suite_and_model(model_path, suite_path, grid_file, target, allow_outside)
    return assess_loaded(loaded, engine=engine, ground=ground, jobs=jobs, progress=progress,
                         mechanism=mechanism)  # fmt: skip


def assess_loaded(
    loaded: LoadedSuite,
    *,
    engine: str = "fast",
    ground: bool = False,
    jobs: int = 1,
    progress: Callable[[int, int], None] | None = None,
    mechanism: str | None = None,
) -> SuiteAssessment:
    """:func:`assess_suite` on a model and suite already read (``mechanism``: a wall's
    mechanism rocked under every record; None: the governing one)."""
    from rockcli.model.plausible import model_warnings
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.suites.run import check_numbers

    settings, model = loaded.settings, loaded.model
    items = [
        SuiteRecord(entry.name, entry.scale, record)
        for entry, record in zip(settings.entries, loaded.check.records, strict=True)
    ]
    with local_executor(min(jobs, len(items))) as lanes:
        rows = run_suite(
            loaded.table, items, lanes, engine=engine, ground=ground, file=loaded.model_path,
            progress=progress, mechanism=mechanism,
        )  # fmt: skip
    limit = limit_for(model, settings.target.limit_state.value)
    measure = suite_measure(outcomes(rows), limit)  # ValueError: a worker died twice
    numbers = check_numbers(loaded.check.check)
    compatibility = {
        "passed": numbers["passed"],
        "period_range": list(settings.period_range),
        "min_ratio": numbers["min_ratio"],
        "max_ratio": numbers["max_ratio"],
    }
    warnings = (*model_warnings(model), *loaded.check.warnings)
    return SuiteAssessment(
        model.name, str(model.kind), settings.name, rows, measure, compatibility, warnings
    )


def limit_for(model: Any, limit_state: str) -> float:
    """The model's ``analysis.limit_ratio`` for the limit state, else θ/α = 1."""
    limits = model.analysis.limit_ratio or {}
    for state, value in limits.items():
        if str(state) == limit_state:
            return float(value)
    return DEFAULT_LIMIT_RATIO
