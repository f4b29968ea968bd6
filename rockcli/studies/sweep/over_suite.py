"""A case of a study whose [[records]] entry names a record suite: every record of the suite
through the time history and the code's rule (rockcli.studies.suite_run.rule), the code check on
the suite's target spectrum at its limit state, and their classification — the verdicts of
`rock compare MODEL --suite SUITE` for each model of the study.

A suite case is one row of cases.csv, like a record case: ``max_ratio`` is the suite measure
(the mean or the largest of the records' max θ/α), ``rocking`` is "fails" or "passes"
against the model's limit, ``code_state`` the code's verdict of the target's limit state.
The summary counts cases, not records (docs/sweeps.md).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rockcli.studies.sweep.columns import kinematic_columns

if TYPE_CHECKING:
    from rockcli.model.schema import Model
    from rockcli.studies.suite_run.run import SuiteRecord
    from rockcli.studies.sweep.study import RecordSource, StudyPlan
    from rockcli.suites.load import SuiteSettings


@dataclass(frozen=True)
class SuiteInput:
    """A suite read once per process: its settings and its records, scaled."""

    settings: SuiteSettings
    items: tuple[SuiteRecord, ...]

    @property
    def npts(self) -> int:
        """The samples of all its records (the cost of a case)."""
        return sum(item.record.npts for item in self.items)


_suites: dict[RecordSource, SuiteInput] = {}
_lock = threading.Lock()


def read_suite(source: RecordSource) -> SuiteInput:
    """The suite of a source, read once per process (InputError naming the suite file)."""
    with _lock:
        found = _suites.get(source)
    if found is not None:
        return found
    from rockcli.studies.suite_run.run import SuiteRecord
    from rockcli.suites.load import load_suite, read_entries

    settings = load_suite(source.path, allow_outside=True)  # checked when the study loaded
    records = read_entries(settings)
    items = tuple(
        SuiteRecord(e.name, e.scale, r) for e, r in zip(settings.entries, records, strict=True)
    )
    with _lock:
        return _suites.setdefault(source, SuiteInput(settings, items))


def suite_facts(source: RecordSource, grid_file: str | None) -> tuple[int, dict[str, Any]]:
    """The suite's samples (for the chunk size) and its facts for the summary: the path, the
    number of records, the rule, and its compatibility with its target."""
    from rockcli.suites.compat import count_rule
    from rockcli.suites.run import check_numbers, run_suite_check

    suite = read_suite(source)
    check = run_suite_check(suite.settings, grid_file)
    numbers = check_numbers(check.check)
    return suite.npts, {
        "path": source.path,
        "suite": suite.settings.name,
        "suite_records": len(suite.items),
        "rule": count_rule(len(suite.items)).value,
        "limit_state": suite.settings.target.limit_state.value,
        "compatible": numbers["passed"],
        "min_ratio": numbers["min_ratio"],
        "max_ratio": numbers["max_ratio"],
        "npts": suite.npts,
        "warnings": list(check.warnings),
    }


def suite_checks(plan: StudyPlan) -> Callable[[Model], None] | None:
    """The check of what each suite of the study asks of a case's model, for the models
    validated before any work (rockcli.studies.sweep.cases.check_cases): the code check has
    a verdict of the target's limit state, and the target gives every limit state's spectrum
    the code check needs — what `rock compare MODEL --suite SUITE` refuses, refused once with
    its message (not as the same error in every case's row). Models alike in what decides
    this (edition, a code spectrum of their own, g) are checked once. None: nothing to check.
    """
    suites = [source for source in plan.records if source.suite]
    if not suites or "kinematic" not in plan.analyses:
        return None
    from rockcli.analyses.compare import code_sets_demand
    from rockcli.analyses.kinematic import check_settings

    seen: set[tuple[str, bool, float]] = set()

    def check(model: Model) -> None:
        key = (check_settings(model).edition, code_sets_demand(model), model.analysis.g)
        if key not in seen:
            seen.add(key)
            for source in suites:
                check_suite_demand(plan, model, source)

    return check


#: What a study can do about a suite's target that gives too little (compare's message names
#: its own options instead).
TARGET_ALLOWED = (
    "lon, lat in the suite's [target] (every limit state from the hazard grid), or "
    "[ntc.demand] or [ntc.site] in the base model"
)


def check_suite_demand(plan: StudyPlan, model: Model, source: RecordSource) -> None:
    """InputError when the code check of the model cannot be made under this suite:
    compare's problem, the suite file named as the study names it, what the study can do."""
    from rockcli.analyses.compare import CodeDemand
    from rockcli.analyses.kinematic import check_settings
    from rockcli.errors import InputError
    from rockcli.studies.suite_run.compare import VERDICT_KEY, target_demands, verdict_key
    from rockcli.studies.sweep.study import shown_path

    settings = read_suite(source).settings
    ntc = check_settings(model)
    try:
        verdict_key(ntc.edition, settings.target.limit_state.value, settings.file)
        if plan.code_demand == CodeDemand.RECORD:
            demand_of = target_demands(settings.target, settings.file, model, plan.grid_file)
            demand_of(ntc, model.analysis.g)
    except InputError as exc:
        if exc.file != settings.file:
            raise
        states = ", ".join(VERDICT_KEY[ntc.edition])
        allowed = {
            "target": TARGET_ALLOWED,
            "target.limit_state": f'{states} (or analyses = ["rocking"], the time history alone)',
        }.get(exc.where or "", exc.allowed)
        shown = shown_path(plan.file, settings.file)
        raise InputError(
            exc.problem, file=shown, where=exc.where, value=exc.value, allowed=allowed
        ) from None


def run_suite_case(plan: StudyPlan, model: Model, suite: SuiteInput) -> dict[str, Any]:
    """The analyses of one case under a suite: the records' time histories and the rule,
    the code check at the target's limit state, the classification."""
    from rockcli.analyses.compare import classify

    R, alpha = model.geometry.polar
    row: dict[str, Any] = {"block_R": R, "block_alpha": alpha}
    state = suite.settings.target.limit_state.value
    row["limit_state"] = state
    rocking_fails = code_fails = None
    if "rocking" in plan.analyses:
        row.update(suite_rocking_columns(plan, model, suite))
        rocking_fails = row["rocking"] == "fails"
    if "kinematic" in plan.analyses:
        kin, key = suite_code_check(plan, model, suite)
        row.update(kinematic_columns(kin))
        passed = kin.verdict()[key]
        row["code_state"] = None if passed is None else ("pass" if passed else "fail")
        code_fails = None if passed is None else not passed
    if "rocking" in plan.analyses and "kinematic" in plan.analyses:
        row["classification"] = str(classify(code_fails, rocking_fails))
    from rockcli.model.catalogue import catalogue
    from rockcli.studies.sweep.columns import sliding_columns

    row.update(sliding_columns(plan, catalogue(model), row.get("mechanism")))
    return row


def suite_rocking_columns(plan: StudyPlan, model: Model, suite: SuiteInput) -> dict[str, Any]:
    """Every record of the suite, both polarities, and the code's rule against the model's
    limit for the target's limit state."""
    from rockcli.analyses.floor import model_floor
    from rockcli.dynamics.tolerance import any_sensitive
    from rockcli.studies.suite_run.assess import limit_for
    from rockcli.studies.suite_run.rule import suite_measure
    from rockcli.studies.suite_run.run import outcomes, record_row

    ground = plan.ground and model_floor(model) is not None
    check = plan.check_tolerance
    rows = [record_row(model, item, plan.engine, ground, plan.base_file, tolerance_check=check)
            for item in suite.items]  # fmt: skip
    limit = limit_for(model, suite.settings.target.limit_state.value)
    measure = suite_measure(outcomes(rows), limit)
    extra = {"sensitive": any_sensitive(r.get("sensitive") for r in rows)} if check else {}
    return {
        **extra,
        "max_ratio": float(measure.measure),
        "overturned": measure.overturned_records > 0,
        "rocking": "passes" if measure.passed else "fails",
        "input": rows[0]["input"],
        "suite_rule": measure.rule,
        "suite_records": measure.n,
        "suite_overturned": measure.overturned_records,
    }


def suite_code_check(plan: StudyPlan, model: Model, suite: SuiteInput) -> tuple[Any, str]:
    """The code check of a suite case and the verdict key of the target's limit state: on the
    target's spectrum (code_demand "record": the suite's own earthquake) or on the model's
    own spectrum (code_demand "model")."""
    from rockcli.analyses.compare import CodeDemand
    from rockcli.analyses.kinematic import check_settings, kinematic_model
    from rockcli.studies.suite_run.compare import target_demands, verdict_key

    settings = suite.settings
    key = verdict_key(
        check_settings(model).edition, settings.target.limit_state.value, settings.file
    )
    if plan.code_demand == CodeDemand.MODEL:
        return kinematic_model(model, grid_file=plan.grid_file), key
    demand_of = target_demands(settings.target, settings.file, model, plan.grid_file)
    return kinematic_model(model, demand_of=demand_of), key
