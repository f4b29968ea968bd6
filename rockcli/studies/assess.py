"""The assess workflow: model file + record → both polarities → result document."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from rockcli.dynamics.result import Assessment, RockingRun
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.model.schema import Model
from rockcli.records.record import Record


@dataclass(frozen=True)
class AssessmentOutput:
    """The assess workflow's document and the runs behind it (for the history file and plots).

    Attributes:
        doc: the `rock assess --format json` document.
        result: both polarities (with θ(t), θ̇(t) when asked for).
        overturn_angle: |θ| at which a run counts as overturned [rad] (the model's setting).
    """

    doc: dict[str, Any]
    result: Assessment
    overturn_angle: float


def settings_from(options: Any) -> SolverSettings:
    """SolverSettings from the model's [analysis] options (same field names by design)."""
    return SolverSettings(**dataclasses.asdict(options))


def assess_model_output(
    model: Model, record: Record, engine: str, *, history: bool = False
) -> AssessmentOutput:
    """Both polarities of a validated model under a record: the document and both runs."""
    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import describe, solver_options, to_block
    from rockcli.report.assess import assessment_document, model_document

    block = to_block(model)
    settings = settings_from(solver_options(model))
    result = assess(
        block,
        record.time,
        record.accel,
        record.dt,
        settings=settings,
        engine=Engine(engine),
        history=history,
    )
    info = model_document(model.name, str(model.kind), block, describe(model).e_rule)
    doc = assessment_document(info, record, block, result)
    return AssessmentOutput(doc, result, settings.overturn_angle)


def assess_model(
    model: Model, record: Record, engine: str, *, history: bool = False
) -> tuple[dict[str, Any], RockingRun]:
    """Both polarities of a validated model under a record: (JSON document, the worse run)."""
    out = assess_model_output(model, record, engine, history=history)
    return out.doc, out.result.worst


def run_assessment_output(
    model_path: str, record: Record, engine: str, *, history: bool = False
) -> AssessmentOutput:
    """Load the model file and run :func:`assess_model_output`."""
    from rockcli.model.load import load_model

    return assess_model_output(load_model(model_path), record, engine, history=history)


def run_assessment(
    model_path: str, record: Record, engine: str, *, history: bool = False
) -> tuple[dict[str, Any], RockingRun]:
    """Load the model file, run both polarities, return (JSON document, the worse run)."""
    out = run_assessment_output(model_path, record, engine, history=history)
    return out.doc, out.result.worst
