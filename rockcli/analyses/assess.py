"""The assess workflow: model file + record → both polarities → results (data, no document)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

from rockcli.dynamics.result import Assessment
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.mechanics import Chain, Rocker
from rockcli.mechanisms.wall import WHOLE_WALL
from rockcli.model.schema import Model
from rockcli.notes import Note
from rockcli.records.record import Record

if TYPE_CHECKING:
    from rockcli.analyses.floor import Floor
    from rockcli.analyses.rocked import Rocked
    from rockcli.model.catalogue import Mechanism as CatalogueMechanism


@dataclass(frozen=True)
class AssessmentOutput:
    """Both polarities of a model under a record, and what a document says of the block.

    Attributes:
        name, kind: the model's name and kind.
        block: the block as analysed.
        e_rule: how the coefficient of restitution was chosen.
        result: both polarities (with θ(t), θ̇(t) when asked for).
        overturn_angle: |θ| at which a run counts as overturned [rad] (the model's setting, or
            a chain's collapse rotation when smaller).
        warnings: magnitudes of the model and the record that look like unit slips.
        floor: the floor whose motion shook the block (None: the record itself, at the base).
        ground: True when the user asked to run the record at the base of a block at height.
        shaking: the floor motion the block saw (None: the record itself).
        mechanism: (name, type) of the wall's mechanism rocked (None: the model's block).
    """

    name: str
    kind: str
    block: Rocker
    e_rule: str
    result: Assessment
    overturn_angle: float
    warnings: tuple[str, ...] = ()
    floor: Floor | None = None
    ground: bool = False
    shaking: Record | None = None
    mechanism: tuple[str, str] | None = None

    @cached_property
    def restrainer_checks(self) -> list[dict[str, Any]]:
        """Each restrainer against its strength over both polarities, as data
        (rockcli.analyses.strength.restrainer_checks)."""
        from rockcli.analyses.strength import restrainer_checks

        return restrainer_checks(self.block, self.result)

    @cached_property
    def effectiveness(self) -> list[dict[str, Any]]:
        """The paper's §4.3 quick check of every restrainer, per side
        (rockcli.analyses.strength.restrainer_effectiveness)."""
        from rockcli.analyses.strength import restrainer_effectiveness

        return restrainer_effectiveness(self.block)


def settings_from(options: Any) -> SolverSettings:
    """SolverSettings from the model's [analysis] options (same field names by design)."""
    return SolverSettings(**{f.name: getattr(options, f.name) for f in dataclasses.fields(options)})


def assess_model_output(
    model: Model,
    record: Record,
    engine: str,
    *,
    history: bool = False,
    ground: bool = False,
    file: str | None = None,
    tolerance_check: bool = True,
    mechanism: str | None = None,
    mechanisms: Catalogue | None = None,
) -> AssessmentOutput:
    """Both polarities of a validated model under a record: the record itself for a block on
    the ground (or with ``ground``), its floor motion for a block at height (analyses.floor).

    tolerance_check: run each polarity again at tighter tolerances and attach the check to
    its run (dynamics.tolerance; the fast engine only: the reference engine is the accuracy
    reference, its tolerances fixed). mechanism: the wall's mechanism to rock (None: the
    governing one; a model of one block has only its own, "overturning, whole wall").
    mechanisms: the model's catalogue when the caller has derived it (derived here else).
    """
    from rockcli.analyses.rocked import mechanism_notes
    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import describe, solver_options
    from rockcli.model.plausible import model_warnings

    rocked_value, shaking, floor = rocked_motion(model, record, ground, file, mechanism,
                                                 mechanisms)  # fmt: skip
    block, rocked = rocked_value.block, rocked_value.named
    settings = settings_from(solver_options(model))
    result = assess(
        block,
        shaking.time,
        shaking.accel,
        shaking.dt,
        settings=settings,
        engine=Engine(engine),
        history=history,
    )
    if tolerance_check and Engine(engine) is Engine.FAST:
        from rockcli.dynamics.tolerance import check_tolerance

        result = check_tolerance(block, shaking.time, shaking.accel, shaking.dt, settings, result)
    return AssessmentOutput(
        model.name,
        str(model.kind),
        block,
        restitution_rule(describe(model).e_rule, block, rocked),
        result,
        overturn_angle(settings, block),
        warnings=(
            *model_warnings(model),
            *record.warnings,
            *mechanism_notes(rocked_value.mechanism),
        ),
        floor=floor,
        ground=ground,
        shaking=shaking if floor is not None else None,
        mechanism=rocked,
    )


def overturn_angle(settings: SolverSettings, block: Rocker) -> float:
    """The rotation at which a run counts as overturned [rad]: the model's setting, or a
    chain's collapse rotation when smaller (rockcli.dynamics.simulate.pack_parameters)."""
    return min(settings.overturn_angle, block.collapse_limit)


def restitution_rule(rule: str, block: Rocker, rocked: tuple[str, str] | None) -> str:
    """How e was obtained, said for what is rocked: the model's rule for its block; for a
    wall's mechanism, Housner's balance about the new pivot of its body (one rigid body) or
    the projection on the motion after the impact (a chain), or for a one-sided mechanism
    the energy that impact keeps (mechanics.rebound_restitution), times the model's factor
    (an explicit e as given). A frame (a chain of its own file) is a chain."""
    if (rocked is None and not isinstance(block, Chain)) or rule == "explicit":
        return rule
    if block.one_sided:
        own = Note("one_sided_impact", "the energy Housner's impact at the other edge keeps, "
                   "the mechanism turning back about its own pivot: √(e₊·e₋)")  # fmt: skip
    elif isinstance(block, Chain):
        own = Note("projection", "projection of the chain's motion on the motion after the impact")
    else:
        own = Note("housner_pivot", "Housner of the mechanism's body about the new pivot")
    if isinstance(rule, Note) and rule.key == "factored":
        from rockcli.model.derive import factored

        return factored(rule.values["factor"], own)
    return own


#: A model's mechanisms as derived once (rockcli.model.catalogue.catalogue).
Catalogue = tuple["CatalogueMechanism", ...]

#: The one mechanism of a model of one block.
BLOCK_MECHANISM = WHOLE_WALL


def rocked_input(model: Model, record: Record, ground: bool, file: str | None,
                 mechanism: str | None, mechanisms: Catalogue | None = None):  # fmt: skip
    """(what the engine rocks, the motion it sees, its floor, (name, type) of a wall's
    mechanism or None for a block file's block) (:func:`rocked_motion`)."""
    rocked, shaking, floor = rocked_motion(model, record, ground, file, mechanism, mechanisms)
    return rocked.block, shaking, floor, rocked.named


def rocked_motion(model: Model, record: Record, ground: bool, file: str | None,
                  mechanism: str | None, mechanisms: Catalogue | None = None,
                  ) -> tuple[Rocked, Record, Floor | None]:  # fmt: skip
    """(the mechanism rocked, the motion it sees, its floor): the catalogue's mechanism
    named, the only one or the governing one (rockcli.analyses.rocked), on its floor motion
    unless ``ground`` (refused for a mechanism on the ground, where it would change nothing
    the user asked). mechanisms: the model's catalogue when the caller has derived it."""
    from rockcli.analyses.floor import floor_record
    from rockcli.analyses.rocked import rocked_mechanism
    from rockcli.errors import InputError

    rocked = rocked_mechanism(model, record, mechanism, mechanisms)
    if ground and rocked.floor is None:
        raise InputError(
            "the block is on the ground already (building.Z = 0 or no [building], and the "
            "mechanism's base at the wall's base)",
            file=file,
            where="--ground",
            allowed="--ground only with a block at height ([building] Z > 0) or a mechanism "
            "above the wall's base",
        )
    floor = None if ground else rocked.floor
    shaking = record if floor is None else floor_record(record, floor)
    return rocked, shaking, floor


def assess_model(model: Model, record: Record, engine: str, *, ground: bool = False) -> Assessment:
    """Both polarities of a validated model under a record (the runs only)."""
    return assess_model_output(model, record, engine, ground=ground).result


def run_assessment_output(
    model_path: str,
    record: Record,
    engine: str,
    *,
    history: bool = False,
    ground: bool = False,
    mechanism: str | None = None,
) -> AssessmentOutput:
    """Load the model file and run :func:`assess_model_output`."""
    from rockcli.model.load import load_model

    return assess_model_output(
        load_model(model_path), record, engine, history=history, ground=ground, file=model_path,
        mechanism=mechanism,
    )  # fmt: skip
