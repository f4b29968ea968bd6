"""Which motion shakes the block: the ground record, or its floor motion at the block's height.

An element at height Z > 0 in a building feels the acceleration of its floor, not the
ground's. The code check amplifies its demand through the building's first mode (ψ(Z), γ, T1;
Circolare 617/2009 §C8A.4.2.3, Circolare 7/2019 §C8.7.1.2 and §C7.2.3); the rocking analysis
is driven, in the same spirit, by the floor acceleration ü_Z = ü_g + γ·ψ·ẍ₁ of the first mode
under the ground record (:mod:`rockcli.codecheck.floor`), with the same γ, ψ and T1 the code
check uses (:func:`rockcli.codecheck.position.position`).
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from dataclasses import dataclass, replace

import numpy as np

from rockcli.codecheck.floor import floor_motion
from rockcli.codecheck.position import position
from rockcli.errors import InputError
from rockcli.model.schema import Model
from rockcli.notes import Note
from rockcli.records.record import Record


@dataclass(frozen=True)
class Floor:
    """The floor at the block's height: the building's first mode that filters the record.

    Attributes:
        Z: height of the block's base above the foundation [m] (None: not said, as in
            `rock record floor`).
        T1: first period of the building [s]. psi: its mode shape at Z [-]. gamma: its
        participation factor [-]. xi: its damping ratio [-].
        notes: how defaults were taken (T1 from H, ψ = Z/H, γ from N).
    """

    Z: float | None
    T1: float
    psi: float
    gamma: float
    xi: float
    notes: tuple[str, ...] = ()

    def document(self) -> dict[str, float | None]:
        """The JSON object ``record.floor`` (contract: T1, psi, gamma, xi, Z)."""
        return {"T1": self.T1, "psi": self.psi, "gamma": self.gamma, "xi": self.xi, "Z": self.Z}

    @property
    def label(self) -> Note:
        """One line for reports."""
        values = {"T1": self.T1, "psi": self.psi, "gamma": self.gamma, "xi": self.xi}
        if self.Z is None:
            return Note("floor_motion", "floor motion: ü_g + γ·ψ·ẍ₁ with T1 = {T1:.3g} s, "
                        "ψ = {psi:.3g}, γ = {gamma:.3g}, ξ = {xi:g}", **values)  # fmt: skip
        text = ("floor motion at Z = {Z:g} m: ü_g + γ·ψ·ẍ₁ with T1 = {T1:.3g} s, ψ = {psi:.3g}, "
                "γ = {gamma:.3g}, ξ = {xi:g}")  # fmt: skip
        return Note("floor_motion_at", text, Z=self.Z, **values)


def model_floor(model: Model) -> Floor | None:
    """The floor of the model's [building] at the block's height, or None on the ground."""
    b = model.building
    if b is None or b.Z <= 0.0:
        return None
    pos = position(b.Z, b.H, b.N, b.T1, b.gamma, b.psi, b.damping)
    assert pos.T1 is not None
    return Floor(Z=b.Z, T1=pos.T1, psi=pos.psi, gamma=pos.gamma, xi=b.damping, notes=pos.notes)


#: Floor motions a process keeps (:func:`floor_record`): a study's cases, a retrofit's
#: diameters and a report's mechanisms at one height filter the same record the same way.
FLOORS_KEPT = 8
_floors: OrderedDict[tuple[int, float, float, float, float], tuple[Record, np.ndarray]] = (
    OrderedDict()
)
_floors_lock = threading.Lock()


def floor_record(rec: Record, floor: Floor) -> Record:
    """The record's floor motion as a Record whose name and notes say how it was made (the
    motion filtered once per record object and floor in a process, kept read-only)."""
    key = (id(rec), floor.T1, floor.psi, floor.gamma, floor.xi)
    with _floors_lock:
        kept = _floors.get(key)
        if kept is not None:
            _floors.move_to_end(key)  # the least recently used dropped first
    if kept is not None and kept[0] is rec:
        accel = kept[1]
    else:
        accel = floor_motion(
            rec.time, rec.accel, T1=floor.T1, psi=floor.psi, gamma=floor.gamma, xi=floor.xi
        )
        accel.setflags(write=False)
        with _floors_lock:
            _floors[key] = (rec, accel)  # the record kept alive: its id stays its own
            while len(_floors) > FLOORS_KEPT:
                _floors.popitem(last=False)
    note = Note("floor_from", "{floor}, from the ground record {record}", floor=floor.label,
                record=rec.name)  # fmt: skip
    name = f"{rec.name} floor" if floor.Z is None else f"{rec.name} at Z = {floor.Z:g} m"
    return replace(rec, name=name, accel=accel, notes=(*rec.notes, note))


def block_input(
    model: Model, record: Record, *, ground: bool = False, file: str | None = None
) -> tuple[Record, Floor | None]:
    """The motion the block sees: the floor motion at its height, or the record itself.

    ``ground``: run the record at the base although the block is at height (``--ground``);
    refused for a block on the ground, where it would change nothing the user asked for.
    """
    floor = model_floor(model)
    if ground:
        if floor is None:
            raise InputError(
                "the block is on the ground already (building.Z = 0 or no [building])",
                file=file,
                where="--ground",
                allowed="--ground only with a block at height ([building] Z > 0)",
            )
        return record, None
    if floor is None:
        return record, None
    return floor_record(record, floor), floor
