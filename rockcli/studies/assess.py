"""The assess workflow: model file + record → both polarities → results (data, no document)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from rockcli.dynamics.result import Assessment
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.mechanics import Block
from rockcli.model.schema import Model
from rockcli.records.record import Record


@dataclass(frozen=True)
class AssessmentOutput:
    """Both polarities of a model under a record, and what a document says of the block.

    Attributes:
        name, kind: the model's name and kind.
        block: the block as analysed.
        e_rule: how the coefficient of restitution was chosen.
        result: both polarities (with θ(t), θ̇(t) when asked for).
        overturn_angle: |θ| at which a run counts as overturned [rad] (the model's setting).
        warnings: magnitudes of the model and the record that look like unit slips.
    """

    name: str
    kind: str
    block: Block
    e_rule: str
    result: Assessment
    overturn_angle: float
    warnings: tuple[str, ...] = ()


def settings_from(options: Any) -> SolverSettings:
    """SolverSettings from the model's [analysis] options (same field names by design)."""
    return SolverSettings(**dataclasses.asdict(options))


def assess_model_output(
    model: Model, record: Record, engine: str, *, history: bool = False
) -> AssessmentOutput:
    """Both polarities of a validated model under a record."""
    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import describe, solver_options, to_block
    from rockcli.model.plausible import model_warnings

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
    return AssessmentOutput(
        model.name,
        str(model.kind),
        block,
        describe(model).e_rule,
        result,
        settings.overturn_angle,
        warnings=(*model_warnings(model), *record.warnings),
    )


def assess_model(model: Model, record: Record, engine: str) -> Assessment:
    """Both polarities of a validated model under a record (the runs only)."""
    return assess_model_output(model, record, engine).result


def run_assessment_output(
    model_path: str, record: Record, engine: str, *, history: bool = False
) -> AssessmentOutput:
    """Load the model file and run :func:`assess_model_output`."""
    from rockcli.model.load import load_model

    return assess_model_output(load_model(model_path), record, engine, history=history)
