"""The assess workflow: model file + record → both polarities → result document."""

from __future__ import annotations

import dataclasses
from typing import Any

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.model.schema import Model
from rockcli.records.record import Record


def settings_from(options: Any) -> SolverSettings:
    """SolverSettings from the model's [analysis] options (same field names by design)."""
    return SolverSettings(**dataclasses.asdict(options))


def assess_model(
    model: Model, record: Record, engine: str, *, history: bool = False
) -> tuple[dict[str, Any], RockingRun]:
    """Both polarities of a validated model under a record: (JSON document, the worse run)."""
    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import describe, solver_options, to_block
    from rockcli.report.assess import assessment_document, model_document

    block = to_block(model)
    result = assess(
        block,
        record.time,
        record.accel,
        record.dt,
        settings=settings_from(solver_options(model)),
        engine=Engine(engine),
        history=history,
    )
    info = model_document(model.name, str(model.kind), block, describe(model).e_rule)
    return assessment_document(info, record, block, result), result.worst


def run_assessment(
    model_path: str, record: Record, engine: str, *, history: bool = False
) -> tuple[dict[str, Any], RockingRun]:
    """Load the model file, run both polarities, return (JSON document, the worse run)."""
    from rockcli.model.load import load_model

    return assess_model(load_model(model_path), record, engine, history=history)
