"""The wall as the mechanisms see it: one physical description, in SI units, frame fixed.

What the model file describes (``[[geometry.storeys]]``, ``gable_height``, ``[return_walls]``,
``[masonry]``, ``[[loads]]``, ``[[thrusts]]``, ``[[restrainers]]``, ``[[mechanisms]]``) after
validation and unit conversion at the edge (rockcli.model): the catalogue
(rockcli.mechanisms) builds every mechanism from it, so the code check and the time history
read one geometry.

The frame, for every quantity here: x horizontal, out of the wall's plane, measured **inward
from the outer face** (the outer face is plumb, at x = 0); z vertical, **up from the wall's
base**. Positive rotation is outward (the top moves towards x < 0), about the outer edge of
the hinge section (side 1); side −1 turns inward about the inner edge. A storey's inner face is
at x = its thickness (set-backs on the inner face). Weights in N, forces in N, lengths in m,
stresses in Pa, angles in rad.

Pure data: no validation here (the model's edge does it), no numerics.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum

from rockcli.mechanics import Restrainer
from rockcli.notes import Note


@dataclass(frozen=True)
class Storey:
    """One storey of the wall, bottom up.

    Attributes:
        height: its height [m] (> 0).
        thickness: its thickness [m] (> 0), from the outer face x = 0 to x = thickness.
    """

    height: float
    thickness: float


@dataclass(frozen=True)
class WallLoad:
    """A weight on the wall (a floor, the roof, an overburden): the Circolare's P_i or P_j.

    Attributes:
        name: label.
        weight: [N].
        x: horizontal distance of its point from the outer face [m].
        z: height of its point above the wall's base [m]. A load exactly at a hinge's height
            belongs to the part below the hinge.
        bears: its weight rests on the wall (it restores and it is lifted).
        moves: its mass follows the wall horizontally (it pushes).
    """

    name: str
    weight: float
    x: float
    z: float
    bears: bool = True
    moves: bool = True


@dataclass(frozen=True)
class WallThrust:
    """A horizontal force independent of the earthquake (a roof's or an arch's thrust).

    Attributes:
        name: label.
        force: its magnitude [N] (> 0).
        direction: +1 pushes outward (towards positive rotation), −1 inward.
        x, z: its point, from the outer face and above the wall's base [m].
    """

    name: str
    force: float
    direction: int
    x: float
    z: float


@dataclass(frozen=True)
class WallRestrainer:
    """A horizontal member (a tie-rod, a floor's connection) holding a point of the wall.

    Attributes:
        member: its laws, strengths and losses, as rockcli.mechanics.Restrainer gives them
            (its ``r_pos/phi_pos/r_neg/phi_neg`` are those about the whole wall's base edges;
            a mechanism places it again about its own hinges from ``x`` and ``z``).
        x, z: its attachment point, from the outer face and above the wall's base [m].
    """

    member: Restrainer
    x: float
    z: float


@dataclass(frozen=True)
class Toothing:
    """The return walls toothed into the wall (Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.2):
    what resists an overturning by friction on their interlocked courses.

    Attributes:
        mu: the friction coefficient μ of the masonry's joints [-].
        course_height: h_b, the height of a course [m].
        overlap: l, how far a course of the return wall runs into the wall (the toothing's
            overlap) [m].
        walls: the return walls toothed, 1 or 2.
        thickness: t_s, the return walls' thickness [m].
        unit_weight: their unit weight W [N/m³] (the wall's masonry).
    """

    mu: float
    course_height: float
    overlap: float
    walls: int
    thickness: float
    unit_weight: float


class MechanismType(StrEnum):
    """The mechanisms of the catalogue (Circolare 7/2019 §C8.7.1; Circolare 617/2009 §C8A.4)."""

    OVERTURNING = "overturning"
    WEDGE = "wedge"
    VERTICAL_FLEXURE = "vertical-flexure"
    GABLE = "gable"
    HORIZONTAL_FLEXURE = "horizontal-flexure"
    CORNER = "corner"


#: The mechanisms the time history cannot rock, and why.
NOT_ROCKED: dict[MechanismType, Note] = {
    MechanismType.HORIZONTAL_FLEXURE: Note(
        "not_a_rocker", "the time history does not apply: its strip is held by the arch's "
        "thrust between the return walls, not by its weight (not a gravity rocking "
        "mechanism); the code check keeps it"),
    MechanismType.CORNER: Note(
        "corner_not_rocked", "the time history does not rock it: the corner turns about an "
        "axis through the corner's base, on which it stands on a point, and its impacts on "
        "the walls' inclined cracks are not the rocking of a body on its bed that the engine "
        "integrates; the code check keeps it"),
}  # fmt: skip


#: ``hinge_height`` of a vertical flexure whose hinge the code finds (the lowest α0).
OPTIMAL = "optimal"
#: The name of the whole wall's (or block's) overturning about its base.
WHOLE_WALL = Note("name_whole_wall", "overturning, whole wall")


@dataclass(frozen=True)
class MechanismSpec:
    """One ``[[mechanisms]]`` entry, resolved ("each-floor" already expanded).

    Attributes:
        name: its label (the model's, or made from its type and hinge).
        type: which mechanism.
        hinge_height: overturning: the hinge's height above the wall's base, at a storey's
            base (0: the whole wall) [m]; vertical flexure: the intermediate hinge's height
            above the wall's base [m], or :data:`OPTIMAL`; None for wedge and gable.
        storey: vertical flexure: the storey it spans (1 = the ground storey); else None.
        angle: wedge, corner: the cracks' angle from the vertical [rad]; else None.
        sides: wedge: 1 or 2 return walls dragged; else None.
        free: free to vibrate before it activates (Circolare 7/2019 §C8.7.1.2.1.3): its
            capacity curve starts with an elastic branch.
        friction: overturning: the toothed return walls resist it by friction (Circolare
            7/2019 Eq. C8.7.1.2; the wall's ``toothing``).
        level, strip_height, span: horizontal flexure: the strip's base above the wall's
            base, its height and its span between the return walls [m].
        thrust_limit: horizontal flexure: the largest thrust the abutments (a tie, a ring
            beam) take [N]; None: rigid abutments (the masonry's crushing limits it).
        limit_by: what sets ``thrust_limit`` (a tie's name, or "thrust_limit").
        return_thickness: corner: the return wall's thickness [m].
        hip_thrust: corner: a hip beam's thrust at the corner's top, outward along its
            bisector [N]; None: none.
    """

    name: str
    type: MechanismType
    hinge_height: float | str | None = None
    storey: int | None = None
    angle: float | None = None
    sides: int | None = None
    free: bool = False
    friction: bool = False
    level: float | None = None
    strip_height: float | None = None
    span: float | None = None
    thrust_limit: float | None = None
    limit_by: str | None = None
    return_thickness: float | None = None
    hip_thrust: float | None = None


@dataclass(frozen=True)
class Wall:
    """The wall, its surroundings and the mechanisms to check.

    Attributes:
        storeys: bottom up (at least one).
        width: the wall's width along its plane [m] (the strip the model describes).
        unit_weight: the masonry's unit weight [N/m³].
        g: gravity [m/s²].
        gable_height: a triangular gable of base ``width`` on top of the last storey, of the
            last storey's thickness [m]; None: no gable.
        return_wall_thickness: thickness of the return walls, where a wedge can form [m];
            None: no return walls given.
        f_m: the masonry's compressive strength used for the hinge's set-back (already divided
            by FC when the model says so) [Pa]; None: infinitely strong (hinges at the edges).
        loads, thrusts, restrainers: as described above, in the wall's frame.
        mechanisms: the mechanisms to check; empty: the whole wall overturning about its base.
        E: the masonry's Young's modulus for the period of elements free to vibrate [Pa]
            (None: not given; no mechanism is free).
        toothing: the return walls toothed into the wall, for the friction of an overturning
            (None: not toothed, or no return walls).
    """

    storeys: tuple[Storey, ...]
    width: float
    unit_weight: float
    g: float
    gable_height: float | None = None
    return_wall_thickness: float | None = None
    f_m: float | None = None
    loads: tuple[WallLoad, ...] = field(default_factory=tuple)
    thrusts: tuple[WallThrust, ...] = field(default_factory=tuple)
    restrainers: tuple[WallRestrainer, ...] = field(default_factory=tuple)
    mechanisms: tuple[MechanismSpec, ...] = field(default_factory=tuple)
    E: float | None = None
    toothing: Toothing | None = None

    @property
    def height(self) -> float:
        """Height of the storeys together (the gable above them not counted) [m]."""
        return sum(s.height for s in self.storeys)

    def storey_bases(self) -> tuple[float, ...]:
        """Height of each storey's base above the wall's base, bottom up [m] (0 first)."""
        bases, z = [], 0.0
        for s in self.storeys:
            bases.append(z)
            z += s.height
        return tuple(bases)
