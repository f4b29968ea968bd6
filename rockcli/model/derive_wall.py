"""From the validated model to the wall the mechanism catalogue reads (SI floats, one frame).

The frame of rockcli.mechanisms.wall: x inward from the outer face at the base (a load's or
restrainer's ``from_pivot``), z up from the wall's base (its ``height``). A model with
``[[geometry.storeys]]`` or ``[[mechanisms]]`` is a wall (rockcli.model.catalogue.block_file
tells the two forms apart); a model of one block is its block (rockcli.model.derive.to_block).

Pure: only :mod:`math`, the model and the mechanisms' data.
"""

from __future__ import annotations

import math

from rockcli.codecheck.free import type_modulus
from rockcli.mechanisms.wall import (
    OPTIMAL,
    WHOLE_WALL,
    MechanismSpec,
    MechanismType,
    Storey,
    Toothing,
    Wall,
    WallLoad,
    WallRestrainer,
    WallThrust,
)
from rockcli.model.derive import NEWTONS_PER_KILONEWTON, to_restrainer
from rockcli.model.physical import Direction
from rockcli.model.schema import Model, Position
from rockcli.model.wall_tables import EACH_FLOOR, MechanismEntry, point_height, thickness_at
from rockcli.notes import Note


def to_wall(model: Model) -> Wall:
    """The wall of the model, its loads, thrusts, restrainers and mechanisms (SI units)."""
    storeys = tuple(Storey(s.height, s.thickness) for s in model.geometry.storey_list)
    width = model.geometry.width
    assert width is not None  # the schema requires it of a wall
    wall = Wall(
        storeys=storeys,
        width=width,
        unit_weight=unit_weight(model, storeys, width),
        g=model.analysis.g,
        gable_height=model.geometry.gable_height,
        return_wall_thickness=None if model.return_walls is None else model.return_walls.thickness,
        f_m=None if model.masonry is None else model.masonry.f_m,
        E=masonry_modulus(model),
    )
    from dataclasses import replace

    wall = replace(wall, toothing=toothing(model, wall))
    wall = replace(
        wall,
        loads=tuple(wall_load(model, wall, i) for i in range(len(model.loads))),
        thrusts=tuple(wall_thrust(model, wall, i) for i in range(len(model.thrusts))),
        restrainers=tuple(wall_restrainer(model, wall, i) for i in range(len(model.restrainers))),
    )
    return replace(wall, mechanisms=mechanism_specs(model, wall))


def toothing(model: Model, wall: Wall) -> Toothing | None:
    """The return walls' toothing, for the friction of an overturning (None: not toothed)."""
    walls = model.return_walls
    if walls is None or not walls.toothed:
        return None
    assert walls.course_height is not None and walls.overlap is not None  # the schema's rule
    return Toothing(walls.friction, walls.course_height, walls.overlap, walls.sides or 2,
                    walls.thickness, wall.unit_weight)  # fmt: skip


def masonry_modulus(model: Model) -> float | None:
    """E for elements free to vibrate [Pa]: ``[masonry] E`` as given, else its ``type``'s
    (codecheck.free.type_modulus: Tab. C8.5.I's mean, cracked); None: neither."""
    masonry = model.masonry
    if masonry is None:
        return None
    if masonry.E is not None:
        return masonry.E
    return None if masonry.type is None else type_modulus(masonry.type)


def unit_weight(model: Model, storeys: tuple[Storey, ...], width: float) -> float:
    """γ [N/m³]: the model's unit weight, or its weight over the wall's volume."""
    assert model.mass is not None  # the schema requires it of a wall
    if model.mass.unit_weight is not None:
        return model.mass.unit_weight * NEWTONS_PER_KILONEWTON
    volume = sum(s.height * s.thickness for s in storeys) * width
    if model.geometry.gable_height is not None:
        volume += storeys[-1].thickness * width * model.geometry.gable_height / 2.0
    assert model.mass.weight is not None
    return model.mass.weight * NEWTONS_PER_KILONEWTON / volume


def _xz(model: Model, wall: Wall, table) -> tuple[float, float]:
    """(x, z) of a load's or thrust's point: from_pivot (default mid-thickness at its height),
    its height (``position = "top"``: the storeys' top)."""
    z = point_height(table, wall.height)
    assert z is not None
    if table.from_pivot is not None:
        return float(table.from_pivot), z
    return thickness_at(model.geometry.storey_list, z) / 2.0, z


def wall_load(model: Model, wall: Wall, index: int) -> WallLoad:
    """Load ``index`` in the wall's frame, weight in N."""
    table = model.loads[index]
    x, z = _xz(model, wall, table)
    return WallLoad(table.name or f"load {index + 1}", table.weight * NEWTONS_PER_KILONEWTON,
                    x, z, table.bears, table.moves)  # fmt: skip


def wall_thrust(model: Model, wall: Wall, index: int) -> WallThrust:
    """Thrust ``index`` in the wall's frame, force in N, +1 outward."""
    table = model.thrusts[index]
    x, z = _xz(model, wall, table)
    direction = 1 if table.direction is Direction.POSITIVE else -1
    return WallThrust(table.name or f"thrust {index + 1}",
                      table.force * NEWTONS_PER_KILONEWTON, direction, x, z)  # fmt: skip


def wall_restrainer(model: Model, wall: Wall, index: int) -> WallRestrainer:
    """Restrainer ``index`` at its point in the wall's frame: height + from_pivot, the
    paper's radius + angle about the outer base edge, or the top inner corner."""
    table = model.restrainers[index]
    member = to_restrainer(model, index)
    if table.position is Position.TOP:
        return WallRestrainer(member, wall.storeys[-1].thickness, wall.height)
    if table.radius is not None and table.angle is not None:
        r, phi = table.radius, table.angle
        return WallRestrainer(member, r * math.sin(phi), r * math.cos(phi))
    assert table.height is not None and table.from_pivot is not None
    return WallRestrainer(member, table.from_pivot, table.height)


def mechanism_specs(model: Model, wall: Wall) -> tuple[MechanismSpec, ...]:
    """The mechanisms to check, "each-floor" expanded, names made and kept unique; none:
    overturning about the base."""
    entries = model.mechanisms or (MechanismEntry.model_validate({"type": "overturning"}),)
    specs = [spec for entry in entries for spec in expand(entry, wall)]
    seen: dict[str, int] = {}
    out = []
    for spec in specs:
        count = seen.get(spec.name, 0) + 1
        seen[spec.name] = count
        out.append(spec if count == 1 else _renamed(spec, f"{spec.name} ({count})"))
    return tuple(out)


def _renamed(spec: MechanismSpec, name: str) -> MechanismSpec:
    from dataclasses import replace

    return replace(spec, name=name)


def expand(entry: MechanismEntry, wall: Wall) -> list[MechanismSpec]:
    """One entry as mechanism specs (several for "each-floor")."""
    kind = MechanismType(entry.type.value)
    if kind is MechanismType.OVERTURNING:
        friction = wall.toothing is not None if entry.friction is None else entry.friction
        hinge = 0.0 if entry.hinge_height is None else entry.hinge_height
        if hinge == OPTIMAL:
            name = entry.name or Note("name_optimal_overturning", "overturning, optimal hinge")
            return [MechanismSpec(name, kind, OPTIMAL, free=entry.is_free, friction=friction)]
        heights = list(wall.storey_bases()) if hinge == EACH_FLOOR else [float(hinge)]
        return [MechanismSpec(entry.name if entry.name and len(heights) == 1 else
                              overturning_name(wall, z), kind, z, free=entry.is_free,
                              friction=friction)
                for z in heights]  # fmt: skip
    if kind is MechanismType.WEDGE:
        sides = entry.sides or 1
        angle = entry.angle or 0.0
        name = entry.name or (
            Note("name_wedge_both", "wedge {angle:g}°, both return walls", angle=float(angle))
            if sides == 2
            else Note("name_wedge_one", "wedge {angle:g}°, one return wall", angle=float(angle))
        )
        return [MechanismSpec(name, kind, angle=math.radians(angle), sides=sides)]
    if kind is MechanismType.GABLE:
        return [MechanismSpec(entry.name or Note("name_gable", "gable"), kind,
                              free=entry.is_free)]  # fmt: skip
    if kind is MechanismType.HORIZONTAL_FLEXURE:
        return [strip_spec(entry, wall)]
    if kind is MechanismType.CORNER:
        angle = entry.angle or 0.0
        thickness = entry.thickness_return or wall.return_wall_thickness
        hip = None if entry.hip_thrust is None else entry.hip_thrust * NEWTONS_PER_KILONEWTON
        name = entry.name or Note("name_corner", "corner, cracks at {angle:g}°",
                                  angle=float(angle))  # fmt: skip
        return [MechanismSpec(name, kind, angle=math.radians(angle),
                              return_thickness=thickness, hip_thrust=hip)]  # fmt: skip
    hinge = OPTIMAL if entry.hinge_height is None else entry.hinge_height
    name = entry.name or Note(
        "name_flexure", "vertical flexure, storey {storey}", storey=entry.storey
    )
    value = hinge if hinge == OPTIMAL else float(hinge)
    return [MechanismSpec(name, kind, value, storey=entry.storey, free=entry.is_free)]


def strip_spec(entry: MechanismEntry, wall: Wall) -> MechanismSpec:
    """A horizontal flexure's spec: its strip, span (default the wall's width) and the thrust
    its abutments take (a thrust_limit in kN, or its tie's strength; None: rigid)."""
    assert entry.level is not None and entry.strip_height is not None
    limit, by = None, None
    if entry.thrust_limit is not None:
        limit, by = entry.thrust_limit * NEWTONS_PER_KILONEWTON, "thrust_limit"
    elif entry.tie is not None:
        member = next(r for r in wall.restrainers if r.member.name == entry.tie).member
        limit, by = member.strength, entry.tie
    name = entry.name or Note("name_horizontal_flexure", "horizontal flexure at {level:g} m",
                              level=float(entry.level))  # fmt: skip
    span = wall.width if entry.span is None else entry.span
    return MechanismSpec(name, MechanismType.HORIZONTAL_FLEXURE, level=entry.level,
                         strip_height=entry.strip_height, span=span, thrust_limit=limit,
                         limit_by=by)  # fmt: skip


def overturning_name(wall: Wall, hinge: float) -> str:
    """'overturning, whole wall' at the base, 'overturning, storey k' above a floor."""
    bases = wall.storey_bases()
    k = min(range(len(bases)), key=lambda i: abs(bases[i] - hinge))
    if k == 0:
        return WHOLE_WALL
    return Note("name_storey", "overturning, storey {storey}", storey=k + 1)
