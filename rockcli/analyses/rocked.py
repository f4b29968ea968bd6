"""Which mechanism of the model's catalogue the time history rocks, and on which floor motion.

Composition only. The catalogue (rockcli.model.catalogue) gives each mechanism once, with
what the engine rocks: a block file's block; a wall's rigid mechanisms (overturning about a
storey's base, the wedge, the gable) as a RigidBody of their own shape
(rockcli.mechanisms.rigid). The mechanism is the one named (``--mechanism``), the only one, or
the governing one of the code check on the same record (like with like: the code side's
spectrum is the record's, as `rock compare` takes it). A storey mechanism rocks on the floor
motion at its hinge, Z + the hinge's height, through the same first mode as the code check's
floor spectrum (rockcli.analyses.catalogue.mechanism_position); a
vertical flexure on the motion of its storey's base (the floor above, which holds its top,
moves otherwise: docs/interpretations.md). The two-block vertical flexure rocks as its chain
(rockcli.mechanisms.flexure), with its restrainers on either block.
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.analyses.floor import Floor
from rockcli.mechanics import Rocker
from rockcli.mechanisms.wall import MechanismSpec, Wall
from rockcli.model.catalogue import Mechanism as CatalogueMechanism
from rockcli.model.derive_ntc import BuildingSettings
from rockcli.model.schema import Model
from rockcli.notes import Note
from rockcli.records.record import Record


@dataclass(frozen=True)
class Rocked:
    """The mechanism the time history rocks: the catalogue's value, what the engine rocks
    (its ``rocker``), and the floor it stands on (None: on the ground)."""

    mechanism: CatalogueMechanism
    floor: Floor | None

    @property
    def name(self) -> str:
        """Its name."""
        return self.mechanism.name

    @property
    def type(self) -> str:
        """Its type (a MechanismType value)."""
        return self.mechanism.type.value

    @property
    def block(self) -> Rocker:
        """What the engines rock."""
        return self.mechanism.rocker

    @property
    def named(self) -> tuple[str, str] | None:
        """(name, type) of a wall's mechanism, as the outputs name it; None for a block
        file's block, which the outputs describe as the model itself."""
        return None if self.mechanism.wall is None else (self.name, self.type)


def named_spec(wall: Wall, name: str) -> MechanismSpec:
    """The mechanism of that name (InputError listing the catalogue's names)."""
    from rockcli.analyses.catalogue import named

    return named(wall.mechanisms, name)


def governing(model: Model, mechanisms: tuple[CatalogueMechanism, ...],
              record: Record) -> CatalogueMechanism:  # fmt: skip
    """The governing mechanism of the code check: under the model's own demand when it sets
    one (so that every record of a suite rocks the same mechanism), else under the record's
    spectrum (`rock compare` names the mechanism it rocks itself)."""
    from rockcli.analyses.catalogue import main_mechanism, named
    from rockcli.analyses.kinematic import kinematic_model

    own = model.ntc is not None and model.ntc.demand is not None  # a site needs the grid
    kin = kinematic_model(model, record=None if own else record, mechanisms=mechanisms)
    main = main_mechanism(kin)  # the governing one when it rocks, else the first that does
    return named(mechanisms, main.name if main is not None else kin.governing or "")


def mechanism_block(model: Model, wall: Wall, spec: MechanismSpec) -> Rocker:
    """What the engine rocks of the wall's mechanism ``spec`` (its catalogue value's rocker:
    rockcli.model.catalogue.Mechanism.rocker, a vertical flexure's hinge resolved as the code
    check resolves it)."""
    from rockcli.model.catalogue import free_side_of, wall_mechanism

    return wall_mechanism(model, wall, spec, free_side_of(model)).rocker


#: The note on a member of a flexure's upper block taken as at its held top.
HELD_AT_TOP = (
    "'{name}': restrainer '{member}' on its upper block ({z:g} m above the storey's base) is "
    "taken as at the held top in the time history, as the floor holds it (not a spring of the "
    "motion): all but at the top, its point turns back towards its anchor at {rotation:.3g} rad "
    "on side {side}, before the chain's end ({end:.3g} rad); the code check takes it as given"
)


def mechanism_notes(mech: CatalogueMechanism) -> tuple[Note, ...]:
    """What the reader needs to know of a mechanism as the time history rocks it: that it
    slides on its base before it lifts (rockcli.analyses.sliding); a member on a vertical
    flexure's upper block taken as at its held top (rockcli.mechanisms.flexure.held_at_top)."""
    from rockcli.analyses.sliding import sliding_note, uplift_of

    return (*sliding_note(mech, uplift_of(mech)), *held_members(mech))


def held_members(mech: CatalogueMechanism) -> tuple[Note, ...]:
    """A member on a vertical flexure's upper block taken as at its held top."""
    from rockcli.mechanisms.flexure import held_at_top
    from rockcli.mechanisms.wall import MechanismType

    wall, spec = mech.wall, mech.spec
    if wall is None or spec is None or spec.type is not MechanismType.VERTICAL_FLEXURE:
        return ()
    if not wall.restrainers:
        return ()
    return tuple(
        Note(
            "held_at_top",
            HELD_AT_TOP,
            name=mech.name,
            member=h.name,
            z=float(h.z),
            rotation=float(h.rotation),
            side=f"{h.side:+d}",
            end=float(h.end),
        )  # fmt: skip
        for h in held_at_top(wall, spec)
    )


def rocked_mechanism(model: Model, record: Record, name: str | None,
                     mechanisms: tuple[CatalogueMechanism, ...] | None = None,
                     ) -> Rocked:  # fmt: skip
    """The mechanism of the model the time history rocks (the one named, the only one, or
    the governing one of the code check) and its floor. mechanisms: the model's catalogue
    when the caller has derived it (rockcli.model.catalogue.catalogue); else the mechanism
    named is derived alone, or the catalogue here."""
    from rockcli.model.catalogue import catalogue, named, named_mechanism
    from rockcli.model.derive_ntc import building_settings

    if name is not None:
        mech = named_mechanism(model, name) if mechanisms is None else named(mechanisms, name)
    else:
        mechanisms = catalogue(model) if mechanisms is None else mechanisms
        mech = mechanisms[0] if len(mechanisms) == 1 else governing(model, mechanisms, record)
        refuse_unrocked(mech)
    return Rocked(mech, mechanism_floor(mech, building_settings(model)))


def refuse_unrocked(mech: CatalogueMechanism) -> None:
    """InputError when the mechanism the time history would rock by default is one it
    cannot (a catalogue of horizontal flexures only)."""
    from rockcli.errors import InputError
    from rockcli.mechanisms.wall import NOT_ROCKED

    if mech.type in NOT_ROCKED:
        raise InputError(
            "no mechanism of the model rocks: its mechanisms are the code check's alone ("
            + NOT_ROCKED[mech.type]
            + ")",
            where="mechanisms",
            value=mech.name,
            allowed="an overturning, wedge, vertical flexure or gable among [[mechanisms]] "
            "for the time history, or rock kinematic",
        )


def mechanism_floor(mech: CatalogueMechanism, building: BuildingSettings) -> Floor | None:
    """The floor at the mechanism's base (None on the ground): Z + its base, through the
    position the code check gives it (rockcli.analyses.catalogue.mechanism_position)."""
    from rockcli.analyses.catalogue import mechanism_position

    pos = mechanism_position(mech, building)
    if not pos.at_height:
        return None
    assert pos.T1 is not None
    return Floor(Z=pos.Z, T1=pos.T1, psi=pos.psi, gamma=pos.gamma, xi=building.damping,
                 notes=pos.notes)  # fmt: skip


def rockable_names(model_path: str) -> list[str | None]:
    """The mechanisms of the model file the time history rocks: every one, in the catalogue's
    order ([None]: a block file, its block)."""
    from rockcli.model.catalogue import catalogue
    from rockcli.model.load import load_model

    mechanisms = catalogue(load_model(model_path))
    return [None if m.wall is None else m.name for m in mechanisms]
