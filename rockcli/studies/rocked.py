"""Which mechanism of a wall the time history rocks, as a block, and on which floor motion.

Composition only. A wall's rigid mechanisms (overturning about a storey's base, the wedge, the
gable) rock as a RigidBody of their own shape (rockcli.mechanisms.rigid); the mechanism is the one
named (``--mechanism``) or the governing one of the code check on the same record (like with
like: the code side's spectrum is the record's, as `rock compare` takes it). A storey
mechanism rocks on the floor motion at its hinge, Z + the hinge's height, through the same
first mode as the code check's floor spectrum (rockcli.studies.catalogue.spec_position); a
vertical flexure on the motion of its storey's base (the floor above, which holds its top,
moves otherwise: docs/interpretations.md). The two-block vertical flexure rocks as its chain
(rockcli.mechanisms.flexure), with its restrainers on either block.
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.mechanics import Rocker
from rockcli.mechanisms.wall import MechanismSpec, Wall
from rockcli.model.schema import Model
from rockcli.notes import Note
from rockcli.records.record import Record
from rockcli.studies.floor import Floor


@dataclass(frozen=True)
class Rocked:
    """The mechanism the time history rocks: its name and type, its block, its floor."""

    name: str
    type: str
    block: Rocker
    floor: Floor | None


def named_spec(wall: Wall, name: str) -> MechanismSpec:
    """The mechanism of that name (InputError listing the catalogue's names)."""
    from rockcli.studies.catalogue import named

    return named(wall.mechanisms, name)


def governing_spec(model: Model, wall: Wall, record: Record) -> MechanismSpec:
    """The governing mechanism of the code check: under the model's own demand when it sets
    one (so that every record of a suite rocks the same mechanism), else under the record's
    spectrum (`rock compare` names the mechanism it rocks itself)."""
    from rockcli.studies.catalogue import main_mechanism
    from rockcli.studies.kinematic import kinematic_model

    own = model.ntc is not None and model.ntc.demand is not None  # a site needs the grid
    kin = kinematic_model(model) if own else kinematic_model(model, record=record)
    main = main_mechanism(kin)  # the governing one when it rocks, else the first that does
    return named_spec(wall, main.name if main is not None else kin.governing or "")


def mechanism_block(model: Model, wall: Wall, spec: MechanismSpec) -> Rocker:
    """The mechanism as the engine rocks it, with the e of its bodies (system_restitution): one
    rigid body as a RigidBody of its own shape (rockcli.mechanisms.rigid), a vertical flexure as
    a Chain carrying its two-block table (rockcli.mechanisms.flexure; its hinge resolved as
    the code check resolves it)."""
    from rockcli.mechanisms.flexure import flexure_block
    from rockcli.mechanisms.rigid import rigid_block
    from rockcli.mechanisms.wall import MechanismType
    from rockcli.model.derive import block_of

    block = block_of(model)
    if spec.type is not MechanismType.VERTICAL_FLEXURE:
        return system_restitution(rigid_block(wall, spec, block), model)
    spec = flexure_spec(model, wall, spec)
    return system_restitution(flexure_block(wall, spec, block), model)


def flexure_spec(model: Model, wall: Wall, spec: MechanismSpec) -> MechanismSpec:
    """The vertical flexure ``spec`` with the hinge the code check finds: given, or the
    optimum over the sides the wall can open to."""
    from rockcli.mechanisms.catalogue import sides_of
    from rockcli.model.derive import block_of
    from rockcli.studies.catalogue import resolved
    from rockcli.studies.kinematic import check_settings

    block = block_of(model)
    sides = sides_of(spec, block.free_side if block.one_sided else None)
    return resolved(wall, spec, sides, check_settings(model))[0]


#: The note on a member of a flexure's upper block taken as at its held top.
HELD_AT_TOP = (
    "'{name}': restrainer '{member}' on its upper block ({z:g} m above the storey's base) is "
    "taken as at the held top in the time history, as the floor holds it (not a spring of the "
    "motion): all but at the top, its point turns back towards its anchor at {rotation:.3g} rad "
    "on side {side}, before the chain's end ({end:.3g} rad); the code check takes it as given"
)


def mechanism_notes(model: Model, name: str) -> tuple[Note, ...]:
    """What the reader needs to know of the wall's mechanism ``name`` as the time history
    rocks it: a member on a vertical flexure's upper block taken as at its held top
    (rockcli.mechanisms.flexure.held_at_top)."""
    from rockcli.mechanisms.flexure import held_at_top
    from rockcli.mechanisms.wall import MechanismType
    from rockcli.model.derive_wall import to_wall

    wall = to_wall(model)
    spec = named_spec(wall, name)
    if spec.type is not MechanismType.VERTICAL_FLEXURE or not wall.restrainers:
        return ()
    return tuple(
        Note(
            "held_at_top",
            HELD_AT_TOP,
            name=name,
            member=h.name,
            z=float(h.z),
            rotation=float(h.rotation),
            side=f"{h.side:+d}",
            end=float(h.end),
        )  # fmt: skip
        for h in held_at_top(wall, flexure_spec(model, wall, spec))
    )


def system_restitution(block: Rocker, model: Model) -> Rocker:
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
