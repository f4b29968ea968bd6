"""Which mechanism of a wall the time history rocks, as a block, and on which floor motion.

Composition only. A wall's rigid mechanisms (overturning about a storey's base, the wedge, the
gable) rock as a Block of their own shape (rockcli.mechanisms.rigid); the mechanism is the one
named (``--mechanism``) or the governing one of the code check on the same record (like with
like: the code side's spectrum is the record's, as `rock compare` takes it). A storey
mechanism rocks on the floor motion at its hinge, Z + the hinge's height, through the same
first mode as the code check's floor spectrum (rockcli.studies.catalogue.spec_position); a
vertical flexure on the motion of its storey's base (the floor above, which holds its top,
moves otherwise: docs/interpretations.md). The two-block vertical flexure rocks as its chain
(rockcli.mechanisms.flexure).
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.errors import InputError
from rockcli.mechanics import Block
from rockcli.mechanisms.wall import MechanismSpec, Wall
from rockcli.model.schema import Model
from rockcli.records.record import Record
from rockcli.studies.floor import Floor


@dataclass(frozen=True)
class Rocked:
    """The mechanism the time history rocks: its name and type, its block, its floor."""

    name: str
    type: str
    block: Block
    floor: Floor | None


def named_spec(wall: Wall, name: str) -> MechanismSpec:
    """The mechanism of that name (InputError listing the catalogue's names)."""
    from rockcli.studies.catalogue import named

    return named(wall.mechanisms, name)


def governing_spec(model: Model, wall: Wall, record: Record) -> MechanismSpec:
    """The governing mechanism of the code check: under the model's own demand when it sets
    one (so that every record of a suite rocks the same mechanism), else under the record's
    spectrum (`rock compare` names the mechanism it rocks itself)."""
    from rockcli.studies.compare import main_mechanism
    from rockcli.studies.kinematic import kinematic_model

    own = model.ntc is not None and model.ntc.demand is not None  # a site needs the grid
    kin = kinematic_model(model) if own else kinematic_model(model, record=record)
    main = main_mechanism(kin)  # the governing one when it rocks, else the first that does
    return named_spec(wall, main.name if main is not None else kin.governing or "")


def mechanism_block(model: Model, wall: Wall, spec: MechanismSpec) -> Block:
    """The mechanism as the engine rocks it, with the e of its bodies (system_restitution): one
    rigid body as a Block of its own shape (rockcli.mechanisms.rigid), a vertical flexure as
    a Block carrying its two-block chain (rockcli.mechanisms.flexure; its hinge resolved as
    the code check resolves it)."""
    from rockcli.mechanisms.catalogue import sides_of
    from rockcli.mechanisms.flexure import UpperMemberError, flexure_block
    from rockcli.mechanisms.rigid import rigid_block
    from rockcli.mechanisms.wall import MechanismType
    from rockcli.model.derive import block_of
    from rockcli.studies.catalogue import resolved
    from rockcli.studies.kinematic import check_settings

    block = block_of(model)
    if spec.type is not MechanismType.VERTICAL_FLEXURE:
        return system_restitution(rigid_block(wall, spec, block), model)
    # The hinge the code check finds: the optimum over the sides the wall can open to.
    sides = sides_of(spec, block.free_side if block.one_sided else None)
    spec, _ = resolved(wall, spec, sides, check_settings(model))
    try:
        return system_restitution(flexure_block(wall, spec, block), model)
    except UpperMemberError as exc:
        from rockcli.notes import Note

        problem = Note(
            "cannot_rock_upper", "the time history cannot rock '{name}' with restrainer "
            "'{member}' on its upper block ({z:g} m above the storey's base, between the "
            "intermediate hinge at {hinge:.3f} m and the held top at {top:g} m)",
            name=spec.name, member=exc.member, z=float(exc.z), hinge=float(exc.hinge),
            top=float(exc.top),
        )  # fmt: skip
        allowed = Note("upper_allowed", "restrainers of a vertical flexure at or below its "
                       "intermediate hinge, or at its storey's top; rock kinematic checks it as "
                       "given")  # fmt: skip
        raise InputError(problem, where="restrainers", value=exc.member, allowed=allowed) from None


def system_restitution(block: Block, model: Model) -> Block:
    """The coefficient of restitution of the mechanism's bodies with their loads, per side,
    times the model's factor (an explicit e as given): two-sided, Housner's balance of angular
    momentum about the new pivot (mechanics.impact_restitution; a chain's projection on the
    motion after the impact); one-sided (the wedge, a wall stopped on one side), the energy
    that impact keeps, the body turning back about its own pivot (mechanics.
    rebound_restitution, below 1 for every body; docs/physics.md, "One-sided impacts")."""
    from rockcli.model.derive import with_system_restitution

    return with_system_restitution(block, model)


def rocked_mechanism(model: Model, record: Record, name: str | None) -> Rocked:
    """The mechanism of a wall model the time history rocks, its block and its floor."""
    from rockcli.model.derive_wall import to_wall

    wall = to_wall(model)
    spec = named_spec(wall, name) if name is not None else governing_spec(model, wall, record)
    block = mechanism_block(model, wall, spec)
    return Rocked(spec.name, spec.type.value, block, mechanism_floor(model, wall, spec))


def mechanism_floor(model: Model, wall: Wall, spec: MechanismSpec) -> Floor | None:
    """The floor at the mechanism's base hinge (None on the ground)."""
    from rockcli.studies.catalogue import spec_position
    from rockcli.studies.kinematic import check_settings

    pos = spec_position(wall, spec, check_settings(model))
    if not pos.at_height:
        return None
    assert pos.T1 is not None
    b = model.building
    return Floor(Z=pos.Z, T1=pos.T1, psi=pos.psi, gamma=pos.gamma, xi=b.damping, notes=pos.notes)


def rockable_names(model_path: str) -> list[str | None]:
    """The mechanisms of the model file the time history rocks: every one, in the catalogue's
    order ([None]: a model of one block, its own)."""
    from rockcli.model.derive_wall import is_wall, to_wall
    from rockcli.model.load import load_model

    model = load_model(model_path)
    if not is_wall(model):
        return [None]
    return [spec.name for spec in to_wall(model).mechanisms]
