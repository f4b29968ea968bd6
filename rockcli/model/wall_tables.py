"""The wall of several storeys and its mechanisms, as the model file gives them.

`[[geometry.storeys]]`, `geometry.gable_height`, `[return_walls]`, `[masonry]` and
`[[mechanisms]]` (docs/mechanisms.md). Validated here at the edge like every other table; the
rules that need the whole model (a hinge at a storey's base, a wedge needs return walls, a
vertical flexure needs a restrained top, the gable needs its height) are
:func:`check_mechanisms`, called by the model.

Sources: Circolare 7/2019 §C8.7.1 and Circolare 617/2009 §C8A.4 (the local mechanisms);
Doherty et al. 2002, EESD 31:833–850 (vertical flexure).
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import Field, model_validator

from rockcli.codecheck.free import MasonryType
from rockcli.mechanisms.wall import MechanismType
from rockcli.model.bounds import MAX_LENGTH, MAX_STOREYS, MIN_LENGTH
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import number, rule_error

#: The wedge's crack angle from the vertical: above 0, at most 60° (a flatter crack would
#: drag more of the return wall than a wedge is: the Circolare's compound overturning).
MAX_WEDGE_ANGLE = 60.0
#: Lowest masonry strength accepted [Pa]: 0.1 MPa (the weakest rubble masonry of Circolare
#: 7/2019 Tab. C8.5.I has f_m ≥ 1.0 MPa; below 0.1 MPa the value is a slip of units).
MIN_STRENGTH = 1e5
#: Highest [Pa]: 100 MPa (the strongest squared stone of Tab. C8.5.I is below 10 MPa).
MAX_STRENGTH = 1e8
#: Lowest Young's modulus of masonry accepted [Pa]: 100 MPa (Tab. C8.5.I's lowest mean E is
#: 690 MPa; halved for cracking, 345 MPa). Highest: 50 GPa (a stone, not a masonry).
MIN_MODULUS, MAX_MODULUS = 1e8, 5e10
#: hinge_height of an overturning for one mechanism per storey base.
EACH_FLOOR = "each-floor"
#: hinge_height of a vertical flexure whose hinge the code finds.
OPTIMAL = "optimal"


#: The mechanism types of the catalogue, the core's own (one list for the file and the core).
MechanismKind = MechanismType


class Storey(Table):
    """One storey of the wall, bottom up: the outer face plumb, set-backs on the inner face."""

    height: float = number("Height of the storey [m]", ..., ge=MIN_LENGTH, le=MAX_LENGTH)
    thickness: float = number(
        "Thickness of the storey, from the outer face [m]", ..., ge=MIN_LENGTH, le=MAX_LENGTH
    )


#: The friction coefficient's bounds: above 0, at most 1.5 (masonry joints: the Circolare's
#: reference value is 0.577, §C8.7.1.2.1.1; above 1.5 no joint slides).
MAX_FRICTION = 1.5
#: Circolare 7/2019 §C8.7.1.2.1.1: "un valore di riferimento è 0,577".
REFERENCE_FRICTION = 0.577
#: A horizontal flexure's thrust limit [kN]: from 0.1 kN to 10⁵ kN (a ring beam's or a
#: tie's strength; below, a slip of units).
MIN_THRUST_LIMIT, MAX_THRUST_LIMIT = 0.1, 1e5
#: The toothing's keys, given only with toothed = true.
TOOTHING_KEYS = ("mu", "course_height", "overlap", "sides")


class ReturnWalls(Table):
    """The walls at right angles to the façade at its ends, where a wedge can form, and
    whose toothing into it resists an overturning by friction (Circolare 7/2019
    §C8.7.1.2.1.1, Eq. C8.7.1.2)."""

    thickness: float = number(
        "Thickness of the return walls [m]", ..., ge=MIN_LENGTH, le=MAX_LENGTH
    )
    toothed: bool = Field(
        False,
        strict=True,
        description="The return walls' courses are toothed into the wall (no evident "
        "detachment): an overturning is resisted by their friction, Circolare 7/2019 Eq. "
        "C8.7.1.2",
    )
    mu: float | None = number(
        "toothed: the friction coefficient μ of the joints [-] (default 0.577, the "
        "Circolare's reference value)",
        gt=0.0,
        le=MAX_FRICTION,
    )
    course_height: float | None = number(
        "toothed: h_b, the mean height of a course [m]", ge=MIN_LENGTH, le=MAX_LENGTH
    )
    overlap: float | None = number(
        "toothed: l, the overlap of a course of the return wall into the wall (the length of "
        "one friction joint) [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    sides: int | None = Field(
        None,
        strict=True,
        ge=1,
        le=2,
        description="toothed: the return walls toothed into the wall, 1 or 2 (default 2)",
    )

    @model_validator(mode="after")
    def _toothing(self) -> ReturnWalls:
        """The toothing's keys with toothed = true, and its course and overlap."""
        if not self.toothed:
            for key in TOOTHING_KEYS:
                if getattr(self, key) is not None:
                    raise rule_error(key, "a key of toothed return walls",
                                     "toothed = true with it, or no " + key,
                                     getattr(self, key))  # fmt: skip
            return self
        for key in ("course_height", "overlap"):
            if getattr(self, key) is None:
                allowed = f"a number >= {MIN_LENGTH:g} and <= {MAX_LENGTH:g} [m]"
                raise rule_error(key, "required with toothed = true", allowed)
        return self

    @property
    def friction(self) -> float:
        """μ as given, else the Circolare's reference value."""
        return REFERENCE_FRICTION if self.mu is None else self.mu


class Masonry(Table):
    """The masonry: its strength, for the hinges' set-back (off when not given), and its
    stiffness, for the elastic branch of elements free to vibrate."""

    f_m: float | None = number(
        "Compressive strength of the masonry: each hinge moves inward by half the stress "
        "block a = N/(f_m·width) carrying the weight N above it [Pa]",
        ge=MIN_STRENGTH,
        le=MAX_STRENGTH,
    )
    E: float | None = number(
        "Young's modulus of the masonry for the period T0 of an element free to vibrate, as "
        "used (give a cracked value: Circolare 7/2019 §C8.7.1.2.1.3 suggests a reduced one) "
        "[Pa]",
        ge=MIN_MODULUS,
        le=MAX_MODULUS,
    )
    type: MasonryType | None = Field(
        None,
        description="The masonry type of Circolare 7/2019 Tab. C8.5.I, for E when not given: "
        "the mean of its range (§C8.5.4.1) halved for cracking (NTC 2018 §7.2.6). One of: "
        + ", ".join(f"'{t.value}'" for t in MasonryType),
    )


class MechanismEntry(Table):
    """One local mechanism to check (docs/mechanisms.md)."""

    name: str | None = Field(
        None, min_length=1, description="Label; default from the type and the hinge"
    )
    type: MechanismKind = Field(
        ...,
        description="'overturning', 'wedge', 'vertical-flexure', 'gable' or 'horizontal-flexure'",
    )
    hinge_height: float | str | None = Field(
        None,
        description="overturning: a storey base's height above the wall's base [m] (default "
        "0), 'each-floor', or 'optimal' (the height of the lowest α0); vertical-flexure: the "
        "intermediate hinge's height [m] or 'optimal' (default)",
    )
    storey: int | None = Field(
        None,
        strict=True,
        ge=1,
        le=MAX_STOREYS,
        description="vertical-flexure: the storey (1 = ground)",
    )
    angle: float | None = number(
        "wedge, corner: the cracks' angle from the vertical, through the base corner [degrees]",
        gt=0.0,
        le=MAX_WEDGE_ANGLE,
    )
    sides: int | None = Field(
        None, strict=True, ge=1, le=2, description="wedge: return walls dragged, 1 or 2"
    )
    level: float | None = number(
        "horizontal-flexure: the strip's base above the wall's base [m]", ge=0.0, le=MAX_LENGTH
    )
    strip_height: float | None = number(
        "horizontal-flexure: the strip's height b [m]", ge=MIN_LENGTH, le=MAX_LENGTH
    )
    span: float | None = number(
        "horizontal-flexure: the span L between the return walls, default the wall's width [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    thrust_limit: float | None = number(
        "horizontal-flexure: the largest thrust the abutments take (a ring beam, a tie), "
        "default rigid abutments [kN]",
        ge=MIN_THRUST_LIMIT,
        le=MAX_THRUST_LIMIT,
    )
    tie: str | None = Field(
        None,
        min_length=1,
        description="horizontal-flexure: the restrainer whose strength limits the thrust (its "
        "name)",
    )
    thickness_return: float | None = number(
        "corner: the return wall's thickness, default [return_walls] thickness [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    hip_thrust: float | None = number(
        "corner: a hip beam's thrust at the corner's top, outward along its bisector [kN]",
        ge=MIN_THRUST_LIMIT,
        le=MAX_THRUST_LIMIT,
    )
    friction: bool | None = Field(
        None,
        strict=True,
        description="overturning: resisted by the friction of the toothed return walls "
        "(Circolare 7/2019 Eq. C8.7.1.2); default true where [return_walls] toothed = true",
    )
    free: bool | None = Field(
        None,
        strict=True,
        description="Free to vibrate before it activates (a parapet, a free-standing part of a "
        "façade: Circolare 7/2019 §C8.7.1.2.1.3): an elastic branch of period T0 and the SLD "
        "check at T0; needs [masonry] E or type. Default: true for the gable, false otherwise; "
        "not for a wedge (bonded to its return walls)",
    )

    @model_validator(mode="after")
    def _keys_of_type(self) -> MechanismEntry:
        """Each type's keys and no other's."""
        own = {
            MechanismKind.OVERTURNING: {"hinge_height", "friction"},
            MechanismKind.WEDGE: {"angle", "sides"},
            MechanismKind.VERTICAL_FLEXURE: {"hinge_height", "storey"},
            MechanismKind.GABLE: set(),
            MechanismKind.HORIZONTAL_FLEXURE: {"level", "strip_height", "span",
                                               "thrust_limit", "tie"},
            MechanismKind.CORNER: {"angle", "thickness_return", "hip_thrust"},
        }[self.type]  # fmt: skip
        for key in ("hinge_height", "storey", "angle", "sides", "friction", "level",
                    "strip_height", "span", "thrust_limit", "tie", "thickness_return",
                    "hip_thrust"):  # fmt: skip
            if key not in own and getattr(self, key) is not None:
                raise rule_error(
                    key, f"not a key of a {self.type.value} mechanism", _allowed(self.type),
                    getattr(self, key),
                )  # fmt: skip
        self._check_hinge()
        if self.type in (MechanismKind.WEDGE, MechanismKind.CORNER) and self.angle is None:
            raise rule_error("angle", f"required with type = '{self.type.value}'",
                             _allowed(self.type))  # fmt: skip
        if self.type is MechanismKind.CORNER and self.free:
            raise rule_error("free", "a corner cannot stand free: it is bonded to both walls",
                             "free = false, or no free key", self.free)  # fmt: skip
        if self.type is MechanismKind.HORIZONTAL_FLEXURE:
            for key in ("level", "strip_height"):
                if getattr(self, key) is None:
                    raise rule_error(key, "required with type = 'horizontal-flexure'",
                                     _allowed(self.type))  # fmt: skip
            if self.thrust_limit is not None and self.tie is not None:
                allowed = "thrust_limit [kN] or tie = a restrainer's name"
                raise rule_error("tie", "not allowed together with thrust_limit", allowed,
                                 self.tie)  # fmt: skip
            if self.free:
                raise rule_error("free", "a horizontal flexure is not free to vibrate: its "
                                 "strip is held by the return walls",
                                 "free = false, or no free key", self.free)  # fmt: skip
        if self.type is MechanismKind.WEDGE and self.free:
            raise rule_error(
                "free", "a wedge cannot stand free: it is bonded to its return walls, whose "
                "wedges move with it", "free = false, or no free key", self.free,
            )  # fmt: skip
        return self

    @property
    def is_free(self) -> bool:
        """Free to vibrate: as given, or by default the gable (a cantilever above the eaves)."""
        return self.free if self.free is not None else self.type is MechanismKind.GABLE

    def _check_hinge(self) -> None:
        value = self.hinge_height
        words = (EACH_FLOOR, OPTIMAL) if self.type is MechanismKind.OVERTURNING else (OPTIMAL,)
        if isinstance(value, str) and value not in words:
            raise rule_error("hinge_height", "not a hinge height", _allowed(self.type), value)
        if isinstance(value, bool) or (
            isinstance(value, float) and not (math.isfinite(value) and 0 <= value <= MAX_LENGTH)
        ):
            raise rule_error("hinge_height", "not a hinge height", _allowed(self.type), value)


def _allowed(kind: MechanismKind) -> str:
    """What each type accepts."""
    return {
        MechanismKind.OVERTURNING: "hinge_height = a storey base's height [m], 'each-floor' or "
        "'optimal'; friction = true or false",
        MechanismKind.WEDGE: "angle (0–60 degrees from the vertical), sides = 1 or 2",
        MechanismKind.VERTICAL_FLEXURE: "storey (1 = ground), hinge_height [m] or 'optimal'",
        MechanismKind.GABLE: "no other key (the gable is geometry.gable_height)",
        MechanismKind.HORIZONTAL_FLEXURE: "level and strip_height [m], span [m], thrust_limit "
        "[kN] or tie (a restrainer's name)",
        MechanismKind.CORNER: "angle (0–60 degrees from the vertical), thickness_return [m], "
        "hip_thrust [kN]",
    }[kind]


def storey_bases(storeys: tuple[Storey, ...]) -> list[float]:
    """The height of each storey's base above the wall's base, bottom up [m]."""
    out, z = [], 0.0
    for s in storeys:
        out.append(z)
        z += s.height
    return out


def check_mechanisms(model: Any) -> None:
    """The rules between the mechanisms and the rest of the model (raises a rule error)."""
    storeys = model.geometry.storey_list
    if model.geometry.storeys is not None or model.mechanisms:
        if model.geometry.width is None:
            raise rule_error(("geometry", "width"), "required for a wall of storeys or with "
                             "[[mechanisms]] (the bodies' weights)",
                             f"a number >= {MIN_LENGTH:g} and <= {MAX_LENGTH:g} [m]")  # fmt: skip
        if model.mass is None:
            raise rule_error("mass", "required for a wall of storeys or with [[mechanisms]]",
                             "a [mass] table with unit_weight [kN/m³] or weight [kN]")  # fmt: skip
    check_set_backs(storeys)
    if model.geometry.storeys is not None or model.mechanisms:
        check_wall_points(model, storeys)
        _check_toothing(model, storeys)
    elif model.return_walls is not None and model.return_walls.toothed:
        raise rule_error(("return_walls", "toothed"), "a block file has no overturning the "
                         "toothing's friction holds (its block is not a wall's mechanism)",
                         "toothed = false, or a wall of [[geometry.storeys]] or with "
                         "[[mechanisms]]", True)  # fmt: skip
    for i, entry in enumerate(model.mechanisms):
        where = ("mechanisms", i)
        if entry.type is MechanismKind.WEDGE and model.return_walls is None:
            raise rule_error(
                (*where, "type"), "a wedge needs the return walls", "a [return_walls] table "
                "with thickness [m]", entry.type.value,
            )  # fmt: skip
        if entry.type is MechanismKind.CORNER:
            _check_corner(model, entry, storeys, where)
        if (entry.type is MechanismKind.CORNER and entry.thickness_return is None
                and model.return_walls is None):  # fmt: skip
            raise rule_error(
                (*where, "thickness_return"), "a corner needs the return wall's thickness",
                "thickness_return [m], or a [return_walls] table with thickness",
            )  # fmt: skip
        toothed = model.return_walls is not None and model.return_walls.toothed
        if entry.friction and not toothed:
            raise rule_error(
                (*where, "friction"), "no toothed return walls to resist by friction",
                "[return_walls] with toothed = true, course_height and overlap", entry.friction,
            )  # fmt: skip
        if entry.type is MechanismKind.GABLE and model.geometry.gable_height is None:
            raise rule_error((*where, "type"), "no gable to overturn",
                             "geometry.gable_height [m]", entry.type.value)  # fmt: skip
        if entry.type is MechanismKind.OVERTURNING:
            _check_floor(entry, storeys, where)
        if entry.type is MechanismKind.VERTICAL_FLEXURE:
            _check_flexure(model, entry, storeys, where)
        if entry.type is MechanismKind.HORIZONTAL_FLEXURE:
            _check_strip(model, entry, storeys, where)


def _check_corner(model: Any, entry: MechanismEntry, storeys: tuple, where: tuple) -> None:
    """A corner's wedge no longer along the wall than the wall is wide (h·tan β ≤ width)."""
    assert entry.angle is not None
    height, width = sum(s.height for s in storeys), model.geometry.width
    reach = height * math.tan(math.radians(entry.angle))
    if width is not None and reach > width * (1 + 1e-9):
        top = math.degrees(math.atan(width / height))
        raise rule_error((*where, "angle"), f"the wedge would reach {reach:.3g} m along the "
                         f"wall, longer than its width {width:g} m",
                         f"an angle up to atan(width/height) = {top:.3g} degrees",
                         entry.angle)  # fmt: skip


def _check_strip(model: Any, entry: MechanismEntry, storeys: tuple, where: tuple) -> None:
    """A horizontal flexure: f_m given, its strip inside one storey, its tie a restrainer
    with a strength."""
    if model.masonry is None or model.masonry.f_m is None:
        raise rule_error((*where, "type"), "a horizontal flexure needs the masonry's strength "
                         "(its arch's stress blocks)", "[masonry] f_m [Pa]",
                         entry.type.value)  # fmt: skip
    assert entry.level is not None and entry.strip_height is not None
    bases = storey_bases(storeys)
    tops = [b + s.height for b, s in zip(bases, storeys, strict=True)]
    inside = [k for k, (b, t) in enumerate(zip(bases, tops, strict=True))
              if b - 1e-9 <= entry.level < t - 1e-9]  # fmt: skip
    top = entry.level + entry.strip_height
    if not inside or top > tops[inside[0]] * (1 + 1e-9) + 1e-9:
        spans = ", ".join(f"{b:g}–{t:g}" for b, t in zip(bases, tops, strict=True))
        raise rule_error((*where, "level"), f"a strip from {entry.level:g} to {top:g} m is not "
                         "inside one storey of the wall",
                         f"level and strip_height within a storey: {spans} [m]",
                         entry.level)  # fmt: skip
    if entry.tie is not None:
        names = [r.name for r in model.restrainers if r.name]
        if entry.tie not in names:
            allowed = ("one of: " + ", ".join(f"'{n}'" for n in names) if names
                       else "the name of a [[restrainers]] entry")  # fmt: skip
            raise rule_error((*where, "tie"), "no such restrainer", allowed, entry.tie)
        member = next(r for r in model.restrainers if r.name == entry.tie)
        if not (member.has_steel or member.anchor_capacity is not None):  # a finite strength
            raise rule_error((*where, "tie"), "a restrainer without a strength cannot limit "
                             "the arch's thrust", "a tie-rod with a grade (or fy, fu), or a "
                             "restrainer with anchor_capacity; or thrust_limit [kN]",
                             entry.tie)  # fmt: skip


def _check_toothing(model: Any, storeys: tuple[Storey, ...]) -> None:
    """A toothing's course within the wall's height and its overlap within its width."""
    walls = model.return_walls
    if walls is None or not walls.toothed:
        return
    height, width = sum(s.height for s in storeys), model.geometry.width
    if walls.course_height > height:
        raise rule_error(("return_walls", "course_height"), "higher than the wall",
                         f"a course height up to the wall's height, {height:g} m",
                         walls.course_height)  # fmt: skip
    if width is not None and walls.overlap > width:
        raise rule_error(("return_walls", "overlap"), "longer than the wall is wide",
                         f"an overlap up to the wall's width, {width:g} m",
                         walls.overlap)  # fmt: skip


def _check_floor(entry: MechanismEntry, storeys: tuple[Storey, ...], where: tuple) -> None:
    """An overturning's hinge at a storey's base; an optimal one with a range to search."""
    value = entry.hinge_height
    if value == OPTIMAL:
        height = sum(s.height for s in storeys)
        margin = max(storeys[-1].thickness, 0.1 * height)
        if height - margin <= 0.0:
            raise rule_error((*where, "hinge_height"), "no range to search: the wall is not "
                             "taller than its top storey is thick",
                             "a hinge height [m] at a storey's base", value)  # fmt: skip
        return
    if not isinstance(value, float):  # None (the base) or "each-floor"
        return
    bases = storey_bases(storeys)
    if not any(math.isclose(value, b, rel_tol=1e-9, abs_tol=1e-9) for b in bases):
        raise rule_error(
            (*where, "hinge_height"), "not at a storey's base",
            "one of " + ", ".join(f"{b:g}" for b in bases) + " [m], 'each-floor' or 'optimal'",
            value,
        )  # fmt: skip


def _check_flexure(model: Any, entry: MechanismEntry, storeys: tuple, where: tuple) -> None:
    """A vertical flexure: its storey exists, its hinge inside it, its top restrained."""
    if entry.storey is None:
        raise rule_error((*where, "storey"), "required with type = 'vertical-flexure'",
                         f"1 to {len(storeys)} (1 = ground)")  # fmt: skip
    if entry.storey > len(storeys):
        raise rule_error((*where, "storey"), "no such storey",
                         f"1 to {len(storeys)} (1 = ground)", entry.storey)  # fmt: skip
    base = storey_bases(storeys)[entry.storey - 1]
    storey = storeys[entry.storey - 1]
    top = base + storey.height
    if 2.0 * storey.thickness >= storey.height:
        raise rule_error(
            (*where, "storey"), "a storey at least half as thick as it is high has no slender "
            "blocks to bend in vertical flexure",
            "a storey higher than twice its thickness", entry.storey,
        )  # fmt: skip
    value = entry.hinge_height
    near = any(math.isclose(value, z, rel_tol=1e-9, abs_tol=1e-9) for z in (base, top)) if (
        isinstance(value, float)) else False  # fmt: skip
    if isinstance(value, float) and (not base < value < top or near):
        raise rule_error((*where, "hinge_height"), "not inside the storey",
                         f"above {base:g} and below {top:g} [m], or 'optimal'", value)  # fmt: skip
    wall_top = sum(s.height for s in storeys)
    heights = [point_height(t, wall_top) for t in (*model.loads, *model.restrainers)]
    if not any(z is not None and math.isclose(z, top, rel_tol=1e-9, abs_tol=1e-9) for z in heights):
        raise rule_error(
            (*where, "storey"), "nothing restrains the storey's top (no floor, tie or "
            "restrainer at its top)",
            f"a [[loads]] or [[restrainers]] entry at height = {top:g} m (the floor or tie "
            "that holds the top)", entry.storey,
        )  # fmt: skip


def point_height(table: Any, wall_top: float) -> float | None:
    """The height of a load's, thrust's or restrainer's point above the wall's base [m]:
    ``height``, the top of the storeys for ``position = "top"``, r·cos φ for radius + angle."""
    if getattr(table, "height", None) is not None:
        return float(table.height)
    if getattr(table, "position", None) is not None:
        return wall_top
    radius, angle = getattr(table, "radius", None), getattr(table, "angle", None)
    if radius is not None and angle is not None:
        return radius * math.cos(angle)
    return None


def check_set_backs(storeys: tuple[Storey, ...]) -> None:
    """Each storey at most as thick as the one below (the outer face plumb, set-backs on the
    inner face: a storey that overhangs the one below has no section to turn about)."""
    for i in range(1, len(storeys)):
        if storeys[i].thickness > storeys[i - 1].thickness * (1.0 + 1e-9):
            raise rule_error(
                ("geometry", "storeys", i, "thickness"), "thicker than the storey below",
                f"at most {storeys[i - 1].thickness:g} m (set-backs are on the inner face)",
                storeys[i].thickness,
            )  # fmt: skip


def check_wall_points(model: Any, storeys: tuple[Storey, ...]) -> None:
    """Every load's, thrust's and restrainer's point inside the wall's section: not above the
    storeys and the gable, not inward of the inner face at its height."""
    wall_top = sum(s.height for s in storeys)
    apex = wall_top + (model.geometry.gable_height or 0.0)
    for key in ("loads", "thrusts", "restrainers"):
        for i, table in enumerate(getattr(model, key)):
            z = point_height(table, wall_top)
            if z is None:
                continue
            if z > apex * (1.0 + 1e-9):
                raise rule_error((key, i, "height"), "above the wall",
                                 f"at most {apex:g} m (the storeys and the gable)", z)  # fmt: skip
            x = getattr(table, "from_pivot", None)
            limit = thickness_at(storeys, z)
            if x is not None and x > limit * (1.0 + 1e-9):
                raise rule_error((key, i, "from_pivot"), "inward of the wall's inner face",
                                 f"at most {limit:g} m, the thickness at its height",
                                 x)  # fmt: skip


def thickness_at(storeys: tuple[Storey, ...], z: float) -> float:
    """The thickness of the storey at height z (at a storey's top: that storey's; above the
    storeys: the last one's, the gable's)."""
    base = 0.0
    for s in storeys:
        if z <= base + s.height * (1.0 + 1e-12):
            return s.thickness
        base += s.height
    return storeys[-1].thickness
