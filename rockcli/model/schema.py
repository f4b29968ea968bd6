"""The model file, as pydantic sees it: one macro-element, validated once at the edge.

Every table forbids unknown keys and is frozen; every number carries its unit in the field
description (``[m]``, ``[kN]``, ``[rad]``…), which the error translation in
:mod:`rockcli.model.load` quotes back to the user. The either/or rules of the file (R + alpha
or thickness + height, weight or unit_weight, the forms of a restrainer) raise
:func:`rule_error`, which names the offending key, so a bad file gets one line naming the
field, the value and what is allowed (spec/README.md, "The model file").

Sources: spec/README.md (the model file), spec/rocking.md (restrainers, restitution,
one-sided motion), the brief of the model package (the decisions listed on each field).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from enum import StrEnum
from typing import Annotated, Any

from pydantic import Field, model_validator

from rockcli.codecheck.categories import LimitState
from rockcli.codecheck.steel import GRADES, rod_area, tension_resistance
from rockcli.model.bounds import (
    MAX_GRAVITY,
    MAX_LENGTH,
    MAX_MODULUS,
    MAX_REACH,
    MAX_STIFFNESS,
    MAX_STOREYS,
    MAX_UNIT_WEIGHT,
    MAX_WEIGHT,
    MIN_ELONGATION,
    MIN_FORCE,
    MIN_GRAVITY,
    MIN_LENGTH,
    MIN_MODULUS,
    MIN_SLENDERNESS,
    MIN_STIFFNESS,
    MIN_UNIT_WEIGHT,
    MIN_WEIGHT,
    PRETENSION_ALLOWED,
)
from rockcli.model.frame_table import FrameTable, check_frame, frame_geometry
from rockcli.model.ntc import Ntc
from rockcli.model.physical import (
    Base,
    Building,
    Load,
    Position,
    Thrust,
    check_mass,
    check_points,
)
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import choose_group, forbid, number, rule_error
from rockcli.model.wall_tables import Masonry, MechanismEntry, ReturnWalls, Storey, check_mechanisms
from rockcli.units import DEFAULT_GRAVITY

#: Default steel modulus of a tie-rod [Pa] (paper Table 2: E = 210 GPa).
STEEL_MODULUS = 210e9

#: Default overturning angle |θ| [rad]: the paper's choice, π/2 (paper §3.1; spec/rocking.md).
OVERTURN_ANGLE = math.pi / 2

#: Default relative and absolute tolerance of the integration (spec/engine.md, "defaults").
TOLERANCE = 1e-8

#: Loosest tolerance accepted: looser runs are not trustworthy (spec/rocking.md, "Accuracy").
LOOSEST_TOLERANCE = 1e-2

#: Tightest tolerance accepted: below it a step's error estimate is mostly rounding (float64
#: holds about 16 digits and the estimate sums seven stages), so the controller shrinks the
#: steps without gaining accuracy and the run only spends its work budget. The reference
#: engine itself runs at atol = 1e-12.
TIGHTEST_TOLERANCE = 1e-12

#: Longest free-vibration tail accepted [s]: one hour. Free rocking dies out within tens of
#: seconds (the default 20/p is 74 s for a block of R = 100 m); a longer tail only costs work.
LONGEST_TAIL = 3600.0

#: Default rest threshold on |θ̇| after an impact [rad/s] (spec/engine.md, "Rest rule").
REST_VELOCITY = 1e-4
#: Largest rest threshold accepted [rad/s]: 100 times the default. The threshold ends Zeno
#: cascades of ever smaller impacts; at 0.1 rad/s it stopped the altar of the examples after
#: its first impacts under El Centro (it survives, where it overturns at 1e-4 to 1e-2), and a
#: large slender block rocks at p·α of a few 1e-3 rad/s (R = 100 m, α = 0.01: 2.7e-3 rad/s).
MAX_REST_VELOCITY = 1e-2

#: Relative slack when checking that a point lies within the thickness: the file's dimensions
#: are rounded (the altar's R = 1.499, α = 0.163 give 2b = 0.4865 m for a 0.487 m wall: the
#: half-unit of α's third decimal alone is 0.3 % of b).
CONTAINMENT_RTOL = 1e-2


class Kind(StrEnum):
    """What the macro-element is: a wall, an altar and a façade are identities only (the
    mechanics are the same); a frame is equal piers capped by a rigid roof ([frame])."""

    WALL = "wall"
    ALTAR = "altar"
    FACADE = "facade"
    FRAME = "frame"


class RestitutionModel(StrEnum):
    """How the coefficient of restitution e is obtained."""

    HOUSNER = "housner"
    EXPLICIT = "explicit"


class Sides(StrEnum):
    """Whether the block can rock to both sides or is stopped on one."""

    TWO = "two"
    ONE = "one"


class StoppedSide(StrEnum):
    """The side of rotation the transverse walls block in one-sided motion."""

    NEGATIVE = "negative"
    POSITIVE = "positive"


class RestrainerKind(StrEnum):
    """A restrainer given by its stiffness, or a steel tie-rod given by its size."""

    SPRING = "spring"
    TIE_ROD = "tie-rod"


class Law(StrEnum):
    """The force–elongation law of a restrainer."""

    ELASTIC = "elastic"
    ELASTIC_PLASTIC = "elastic-plastic"


class CodeAction(StrEnum):
    """How a restrainer enters the kinematic check."""

    FORCE = "force"
    SPRING = "spring"


class Acts(StrEnum):
    """The side(s) of rotation on which a tie-rod works."""

    BOTH = "both"
    POSITIVE = "positive"
    NEGATIVE = "negative"


class Geometry(Table):
    """The rocking block: either R + alpha, or thickness + height (spec/README.md)."""

    R: float | None = number(
        "Semi-diagonal R = √(b² + h²), with R + alpha [m]", ge=MIN_LENGTH, le=MAX_LENGTH
    )
    alpha: float | None = number(
        "Slenderness α = atan(b/h), strictly between 0 and π/2, with R [rad]",
        ge=MIN_SLENDERNESS,
        lt=math.pi / 2,
    )
    thickness: float | None = number(
        "Full thickness 2b, with height [m]", ge=MIN_LENGTH, le=MAX_LENGTH
    )
    height: float | None = number(
        "Full height 2h above the pivot, with thickness [m]", ge=MIN_LENGTH, le=MAX_LENGTH
    )
    width: float | None = number(
        "Out-of-plane length, needed only with mass.unit_weight (volume = 2b·2h·width) [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    pivot_height: float | None = number(
        "Height of the pivot above ground when the block is the upper portion of a taller "
        "wall; informational for now [m]",
        ge=0,
        le=MAX_LENGTH,
    )
    storeys: tuple[Storey, ...] | None = Field(
        None,
        max_length=MAX_STOREYS,
        description="A wall of several storeys, bottom up (instead of thickness + height or "
        "R + alpha): each with height and thickness [m], the outer face plumb",
    )
    gable_height: float | None = number(
        "A triangular gable of base width on top of the last storey, of its thickness [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )

    @model_validator(mode="after")
    def _one_form(self) -> Geometry:
        """Exactly one of (R, alpha), (thickness, height) and storeys."""
        allowed = "either R + alpha, thickness + height, or [[geometry.storeys]]"
        values = self.__dict__
        groups = [("R", "alpha"), ("thickness", "height"), ("storeys",)]
        if choose_group(values, groups, allowed) is None:
            raise rule_error(None, "missing the block's dimensions", allowed)
        if self.storeys is not None and not self.storeys:
            raise rule_error("storeys", "no storey", "one [[geometry.storeys]] table or more, "
                             "bottom up, each with height and thickness [m]")  # fmt: skip
        if self.gable_height is not None and self.width is None:
            raise rule_error("width", "required with gable_height (the gable's base)",
                             LENGTH_ALLOWED)  # fmt: skip
        return self

    @property
    def storey_list(self) -> tuple[Storey, ...]:
        """The storeys, bottom up: the given ones, or the block as one storey."""
        if self.storeys is not None:
            return self.storeys
        b, h = self.half_sizes
        # The block's own sizes, already validated as its form's (2R may exceed a storey's).
        return (Storey.model_construct(height=2.0 * h, thickness=2.0 * b),)

    @property
    def half_sizes(self) -> tuple[float, float]:
        """(b, h): half-thickness and half-height [m] (b = R sin α, h = R cos α); a wall of
        storeys: half the ground storey's thickness and half the storeys' height."""
        if self.storeys is not None:
            return self.storeys[0].thickness / 2.0, sum(s.height for s in self.storeys) / 2.0
        if self.thickness is not None and self.height is not None:
            return self.thickness / 2.0, self.height / 2.0
        assert self.R is not None and self.alpha is not None
        return self.R * math.sin(self.alpha), self.R * math.cos(self.alpha)

    @property
    def polar(self) -> tuple[float, float]:
        """(R, α) [m, rad]: R = √(b² + h²), α = atan(b/h) (spec/rocking.md, notation)."""
        if self.R is not None and self.alpha is not None:
            return self.R, self.alpha
        b, h = self.half_sizes
        return math.hypot(b, h), math.atan2(b, h)


class Mass(Table):
    """The weight of the block: total weight, or unit weight × volume (spec/README.md)."""

    weight: float | None = number("Total weight W of the block [kN]", ge=MIN_WEIGHT, le=MAX_WEIGHT)
    unit_weight: float | None = number(
        "Unit weight γ; W = γ·2b·2h·width, needs geometry.width [kN/m³]",
        ge=MIN_UNIT_WEIGHT,
        le=MAX_UNIT_WEIGHT,
    )

    @model_validator(mode="after")
    def _one_form(self) -> Mass:
        """Exactly one of weight and unit_weight."""
        allowed = "either weight [kN] or unit_weight [kN/m³]"
        if choose_group(self.__dict__, [("weight",), ("unit_weight",)], allowed) is None:
            raise rule_error(None, "missing the weight", allowed)
        return self


#: What a length accepts, for the rules that require one.
LENGTH_ALLOWED = f"a number >= {MIN_LENGTH:g} and <= {MAX_LENGTH:g} [m]"

EITHER_E = 'model = "housner" with optional factor, or model = "explicit" with e'


class Restitution(Table):
    """Energy lost at impact: Housner's e (times a factor), or an explicit e (paper Eq. 3)."""

    model: RestitutionModel | None = Field(
        None,
        description="'housner' (e = 1 − 1.5 sin²α, times factor; 0 when that is ≤ 0, "
        "α ≥ 54.74°) or 'explicit' (e given); default: 'explicit' if e is given, else "
        "'housner'",
    )
    factor: float | None = number(
        "Factor on Housner's e, in (0, 1]; the paper's systemic study uses 0.9; default 1 [-]",
        gt=0,
        le=1,
    )
    e: float | None = number(
        "Explicit coefficient of restitution (ratio of angular velocities), in [0, 1] [-]",
        ge=0,
        le=1,
    )

    @model_validator(mode="after")
    def _consistent(self) -> Restitution:
        """e and factor exclude each other; 'explicit' needs e, 'housner' refuses it."""
        if self.e is not None and self.factor is not None:
            raise rule_error("factor", "not allowed together with e", EITHER_E, self.factor)
        if self.rule is RestitutionModel.HOUSNER:
            forbid(self.__dict__, ["e"], 'not allowed with model = "housner"', EITHER_E)
        elif self.e is None:
            raise rule_error("e", 'required with model = "explicit"', "a number >= 0 and <= 1 [-]")
        return self

    @property
    def rule(self) -> RestitutionModel:
        """The model in force: the one given, else 'explicit' if e is given, else 'housner'."""
        if self.model is not None:
            return self.model
        return RestitutionModel.EXPLICIT if self.e is not None else RestitutionModel.HOUSNER


class Motion(Table):
    """Two-sided rocking, or one-sided (a façade stopped by transverse walls; spec/rocking.md)."""

    sides: Sides = Field(Sides.TWO, description="'two' (default) or 'one'")
    stopped: StoppedSide | None = Field(
        None,
        description="With sides = 'one': the side the transverse walls block, 'negative' "
        "(default) or 'positive'; the block rotates only towards the other side",
    )
    rebound: float | None = number(
        "With sides = 'one': rebound reduction factor r_f in [0, 1], θ̇⁺ = −r_f·e·θ̇⁻; "
        "default 1 (no additional damping) [-]",
        ge=0,
        le=1,
    )

    @model_validator(mode="after")
    def _one_sided_keys(self) -> Motion:
        """stopped and rebound belong to one-sided motion only."""
        if self.sides is Sides.TWO:
            forbid(
                self.__dict__,
                ["stopped", "rebound"],
                'only allowed with sides = "one"',
                'sides = "one" with stopped and rebound, or remove it',
            )
        return self


class Analysis(Table):
    """Settings of the time-history run (spec/rocking.md; defaults from spec/engine.md)."""

    tail: float | None = number(
        "Free-vibration time after the end of the record, at most 3600; default: the engine's [s]",
        ge=0,
        le=LONGEST_TAIL,
    )
    overturn_angle: float = number(
        "Rotation |θ| at which the block counts as overturned, in (0, π/2]; default π/2 [rad]",
        OVERTURN_ANGLE,
        gt=0,
        le=OVERTURN_ANGLE,
    )
    rtol: float = number(
        "Relative tolerance of the integration, in [1e-12, 1e-2]; default 1e-8 [-]",
        TOLERANCE,
        ge=TIGHTEST_TOLERANCE,
        le=LOOSEST_TOLERANCE,
    )
    atol: float = number(
        "Absolute tolerance of the integration, in [1e-12, 1e-2]; default 1e-8 [rad, rad/s]",
        TOLERANCE,
        ge=TIGHTEST_TOLERANCE,
        le=LOOSEST_TOLERANCE,
    )
    rest_velocity: float = number(
        "Rest rule: after an impact, |θ̇⁺| below this means rest, at most 1e-2; default 1e-4 "
        "[rad/s]",
        REST_VELOCITY,
        gt=0,
        le=MAX_REST_VELOCITY,
    )
    linearized: bool = Field(
        False,
        strict=True,
        description="Use the linearized equation (sin x ≈ x, cos x ≈ 1); default false",
    )
    g: float = number(
        "Gravity, 9 to 10 (the Earth's surface gravity is 9.76 to 9.83); default 9.81 [m/s²]",
        DEFAULT_GRAVITY,
        ge=MIN_GRAVITY,
        le=MAX_GRAVITY,
    )
    limit_ratio: dict[LimitState, LimitRatio] | None = Field(
        None,
        description="A record suite's limit on its measure of max θ/α, per limit state of the "
        "suite's target, e.g. {SLV = 1.0, SLC = 1.5}; default 1, the static instability [-]",
    )


#: Largest limit of a suite's measure of max θ/α: the overturning angle π/2 over the most
#: slender block's α would be larger still, but a limit past 100 no longer limits anything.
MAX_LIMIT_RATIO = 100.0
LimitRatio = Annotated[float, Field(strict=True, gt=0, le=MAX_LIMIT_RATIO, allow_inf_nan=False)]

#: The three ways of placing a restrainer's attachment point.
PLACEMENTS = (("radius", "angle"), ("height", "from_pivot"), ("position",))
PLACEMENT_ALLOWED = 'radius + angle, or height + from_pivot, or position = "top"'
SPRING_ALLOWED = 'k or k_pos + k_neg [N/m]; or kind = "tie-rod" with diameter and length [m]'
STIFFNESS_ALLOWED = f"0 (none), or >= {MIN_STIFFNESS:g} and <= {MAX_STIFFNESS:g} [N/m]"
TIE_ROD_KEYS = (
    "diameter",
    "length",
    "E",
    "acts",
    "grade",
    "fy",
    "fu",
    "count",
    "elongation_at_break",
)
LAW_ALLOWED = (
    'law = "elastic" (no yield), or "elastic-plastic" with yield_pos and yield_neg [N] '
    "(a tie-rod: its grade or fy, fu)"
)
CODE_ACTION_ALLOWED = (
    'code_action = "spring", or "force" for a member with a strength (a tie-rod\'s grade or '
    "fy, fu; a yield force; an anchor capacity)"
)
#: Largest elongation at break of a bar [-]: 100 % (structural steels break near 20–30 %).
MAX_ELONGATION_AT_BREAK = 1.0
TIE_ROD_ALLOWED = 'kind = "tie-rod" with diameter and length [m], optional E [Pa] and acts'
STEEL_ALLOWED = 'grade = "S235" | "S275" | "S355", or fy and fu [Pa] with fu >= fy'
#: Range of the measured strengths of an existing steel member [Pa] (wrought iron ~ 200 MPa
#: to high-strength bars ~ 1000 MPa).
MIN_STEEL_STRENGTH, MAX_STEEL_STRENGTH = 100e6, 2000e6
#: Most bars of one tie-rod restrainer.
MAX_BARS = 100
#: Largest anchor capacity accepted [N] (100 MN: beyond any masonry anchorage).
MAX_ANCHOR = 1e8
#: The keys of a restrainer that are forces [N]: each at least MIN_FORCE (1 N) and at most
#: MAX_ANCHOR; pretension may also be 0 (none). tests/unit/test_model_bounds.py checks that
#: every key whose unit is N is listed here.
FORCE_KEYS = ("yield_pos", "yield_neg", "anchor_capacity", "pretension")


class SteelGrade(StrEnum):
    """Structural steel grades (NTC 2018 Tab. 11.3.IX)."""

    S235 = "S235"
    S275 = "S275"
    S355 = "S355"


class Restrainer(Table):
    """A horizontal spring (tie-rod, vault, transverse wall) acting on the block.

    Stiffness: k_pos + k_neg, or k (both sides), or kind = "tie-rod" with diameter, length,
    E (K = E·π·d²/4 / L). Placement: radius + angle, height + from_pivot, or position = "top"
    (spec/rocking.md, "Restrainers").
    """

    name: str | None = Field(None, min_length=1, description="Label; default 'restrainer N'")
    kind: RestrainerKind = Field(
        RestrainerKind.SPRING, description="'spring' (default: stiffness given) or 'tie-rod'"
    )
    k_pos: float | None = number(
        f"Stiffness while θ > 0, with k_neg: 0 (none), or at least {MIN_STIFFNESS:g} N/m [N/m]",
        ge=0,
        le=MAX_STIFFNESS,
    )
    k_neg: float | None = number(
        f"Stiffness while θ < 0, with k_pos: 0 (none), or at least {MIN_STIFFNESS:g} N/m [N/m]",
        ge=0,
        le=MAX_STIFFNESS,
    )
    k: float | None = number(
        "Stiffness on both sides (instead of k_pos + k_neg): 0 (none), or at least "
        f"{MIN_STIFFNESS:g} N/m [N/m]",
        ge=0,
        le=MAX_STIFFNESS,
    )
    diameter: float | None = number("Tie-rod: bar diameter d [m]", ge=MIN_LENGTH, le=MAX_LENGTH)
    length: float | None = number("Tie-rod: free length L [m]", ge=MIN_LENGTH, le=MAX_LENGTH)
    E: float | None = number(
        "Tie-rod: Young's modulus; default 210e9 [Pa]", ge=MIN_MODULUS, le=MAX_MODULUS
    )
    acts: Acts | None = Field(
        None, description="Tie-rod: side(s) it works on, 'both' (default), 'positive', 'negative'"
    )
    grade: SteelGrade | None = Field(
        None,
        description="Tie-rod: steel grade 'S235', 'S275' or 'S355' (NTC 2018 Tab. 11.3.IX), "
        "for its design strength; or fy and fu",
    )
    fy: float | None = number(
        "Tie-rod: yield strength of an existing bar, with fu; divided by FC [Pa]",
        ge=MIN_STEEL_STRENGTH,
        le=MAX_STEEL_STRENGTH,
    )
    fu: float | None = number(
        "Tie-rod: ultimate strength of an existing bar, with fy; divided by FC [Pa]",
        ge=MIN_STEEL_STRENGTH,
        le=MAX_STEEL_STRENGTH,
    )
    count: int | None = Field(
        None,
        strict=True,
        ge=1,
        le=MAX_BARS,
        description="Tie-rod: number of equal bars side by side (stiffness and strength); "
        "default 1",
    )
    anchor_capacity: float | None = number(
        "Force at which the anchorage (plate, masonry) gives way; caps the strength [N]",
        ge=MIN_FORCE,
        le=MAX_ANCHOR,
    )
    radius: float | None = number(
        "Distance of the attachment point from the pivot, same for both pivots (paper's form; "
        "with angle) [m]",
        ge=MIN_LENGTH,
        le=MAX_REACH,
    )
    angle: float | None = number(
        "Angle of that radius from the vertical, into the block, in [0, π/2] (with radius) [rad]",
        ge=0,
        le=math.pi / 2,
    )
    height: float | None = number(
        "Height z of the attachment point above the base (with from_pivot) [m]",
        ge=MIN_LENGTH,
        le=MAX_REACH,
    )
    from_pivot: float | None = number(
        "Horizontal distance x of the point from the pivot of positive rotation, at most the "
        "thickness; from the other pivot it is 2b − x (with height) [m]",
        ge=0,
        le=MAX_REACH,
    )
    position: Position | None = Field(
        None, description="'top': the corner at the top, r = 2R, φ = α (paper Eq. 4)"
    )
    fails_at: float | None = number(
        "Spring elongation at which the restrainer is lost for the rest of the run; default "
        "never [m]",
        ge=MIN_ELONGATION,
        le=MAX_LENGTH,
    )
    law: Law | None = Field(
        None,
        description="'elastic' or 'elastic-plastic' (yields, goes slack, cannot push); default "
        "elastic-plastic for a tie-rod with a grade or fy, fu, for a spring with yield forces",
    )
    yield_pos: float | None = number(
        "Spring: yield force while θ > 0 (elastic-plastic law) [N]", ge=MIN_FORCE, le=MAX_ANCHOR
    )
    yield_neg: float | None = number(
        "Spring: yield force while θ < 0 (elastic-plastic law) [N]", ge=MIN_FORCE, le=MAX_ANCHOR
    )
    pretension: float | None = number(
        f"Force in the member at rest: 0, or at least {MIN_FORCE:g} N and below its yield force; "
        "default 0 [N]",
        ge=0,
        le=MAX_ANCHOR,
    )
    elongation_at_break: float | None = number(
        "Tie-rod: elongation at break of the steel, a fraction of the length (0.2 = 20 %); "
        "the bar ruptures there; default: a grade's minimum elongation after fracture (EN "
        "10025-2 Tab. 7: S235 0.26, S275 0.23, S355 0.22) in the time history only, none for "
        "measured fy, fu [-]",
        gt=0,
        le=MAX_ELONGATION_AT_BREAK,
    )
    code_action: CodeAction | None = Field(
        None,
        description="How the kinematic check takes it: 'force' (its strength, a constant "
        "stabilising force in α0 and on the whole curve; default for a tie-rod with a grade or "
        "fy, fu) or 'spring' (its pretension plus its stiffness, capped at its strength; "
        "default otherwise); either until it breaks",
    )

    @model_validator(mode="after")
    def _one_stiffness_one_place(self) -> Restrainer:
        """One stiffness form matching the kind, and exactly one placement form."""
        values = self.__dict__
        if self.kind is RestrainerKind.TIE_ROD:
            self._check_tie_rod(values)
        else:
            self._check_spring(values)
        if choose_group(values, PLACEMENTS, PLACEMENT_ALLOWED) is None:
            raise rule_error(None, "missing the attachment point", PLACEMENT_ALLOWED)
        self._check_law()
        self._check_pretension()
        if self.code_action is CodeAction.FORCE and not self.has_strength:
            raise rule_error(
                "code_action", "needs a member with a strength", CODE_ACTION_ALLOWED, "force"
            )
        return self

    @property
    def has_steel(self) -> bool:
        """True for a tie-rod whose steel is given (a grade, or measured fy and fu)."""
        return self.kind is RestrainerKind.TIE_ROD and (
            self.grade is not None or self.fy is not None
        )

    @property
    def has_strength(self) -> bool:
        """True when the member's strength is known: its steel, a yield force or an anchor."""
        return (
            self.has_steel
            or self.yield_pos is not None
            or self.yield_neg is not None
            or self.anchor_capacity is not None
        )

    @property
    def effective_law(self) -> Law:
        """The law as given, else elastic-plastic for a member with a yield, else elastic."""
        if self.law is not None:
            return self.law
        if self.has_steel or self.yield_pos is not None or self.yield_neg is not None:
            return Law.ELASTIC_PLASTIC
        return Law.ELASTIC

    @property
    def effective_code_action(self) -> CodeAction:
        """The code action as given, else "force" for a tie-rod of known steel, else "spring"."""
        if self.code_action is not None:
            return self.code_action
        return CodeAction.FORCE if self.has_steel else CodeAction.SPRING

    def yield_forces(self) -> tuple[float, float]:
        """(yield while θ > 0, yield while θ < 0) [N] of the elastic-plastic law (inf: none).

        A tie-rod yields at its design plastic resistance count·π·d²/4·f_y/γ_M0 (NTC 2018
        §4.2.4.1.2; a measured f_y is further divided by FC where the model is derived,
        rockcli.model.derive.member_law); both sides alike.
        """
        if self.effective_law is Law.ELASTIC:
            return math.inf, math.inf
        if self.kind is RestrainerKind.TIE_ROD:
            assert self.diameter is not None
            fy, fu = GRADES[self.grade.value] if self.grade is not None else (self.fy, self.fu)
            assert fy is not None and fu is not None
            force = tension_resistance(rod_area(self.diameter, self.count or 1), fy, fu).plastic
            return force, force
        pos = math.inf if self.yield_pos is None else self.yield_pos
        neg = math.inf if self.yield_neg is None else self.yield_neg
        return pos, neg

    def _check_law(self) -> None:
        """An elastic-plastic law needs yield forces (a spring) or steel (a tie-rod)."""
        values = self.__dict__
        if self.kind is RestrainerKind.TIE_ROD:
            forbid(
                values,
                ["yield_pos", "yield_neg"],
                'not allowed with kind = "tie-rod": its yield force comes from its steel',
                STEEL_ALLOWED,
            )
            if self.law is Law.ELASTIC_PLASTIC and not self.has_steel:
                raise rule_error("law", "needs the tie-rod's steel", STEEL_ALLOWED, self.law.value)
            if self.elongation_at_break is not None:
                forbid(values, ["fails_at"], "not allowed with elongation_at_break", "one of them")
            return
        if self.law is Law.ELASTIC:
            forbid(
                values, ["yield_pos", "yield_neg"], 'not allowed with law = "elastic"', LAW_ALLOWED
            )
        k_pos = self.k if self.k is not None else self.k_pos
        k_neg = self.k if self.k is not None else self.k_neg
        if self.effective_law is Law.ELASTIC_PLASTIC:
            for key, k in (("yield_pos", k_pos), ("yield_neg", k_neg)):
                if k and values.get(key) is None:
                    raise rule_error(key, 'required with law = "elastic-plastic"', LAW_ALLOWED)

    def _check_pretension(self) -> None:
        """A pretension of 0, or of at least MIN_FORCE below every yield force and the anchor's
        capacity."""
        p0 = self.pretension
        if not p0:
            return
        if p0 < MIN_FORCE:
            raise rule_error("pretension", f"below {MIN_FORCE:g} N", PRETENSION_ALLOWED, p0)
        limits = [f for f in self.yield_forces() if math.isfinite(f)]
        if self.anchor_capacity is not None:
            limits.append(self.anchor_capacity)
        if limits and p0 >= min(limits):
            raise rule_error("pretension", f"not below {min(limits):g} N", PRETENSION_ALLOWED, p0)

    @staticmethod
    def _check_spring(values: Mapping[str, Any]) -> None:
        forbid(values, TIE_ROD_KEYS, 'only allowed with kind = "tie-rod"', SPRING_ALLOWED)
        if choose_group(values, [("k",), ("k_pos", "k_neg")], SPRING_ALLOWED) is None:
            raise rule_error(None, "missing the stiffness", SPRING_ALLOWED)
        for key in ("k", "k_pos", "k_neg"):
            k = values.get(key)
            if k is not None and 0 < k < MIN_STIFFNESS:
                raise rule_error(key, f"below {MIN_STIFFNESS:g} N/m", STIFFNESS_ALLOWED, k)

    @staticmethod
    def _check_tie_rod(values: Mapping[str, Any]) -> None:
        forbid(
            values, ["k", "k_pos", "k_neg"], 'not allowed with kind = "tie-rod"', TIE_ROD_ALLOWED
        )
        missing = [k for k in ("diameter", "length") if values.get(k) is None]
        if missing:
            raise rule_error(missing[0], 'required with kind = "tie-rod"', TIE_ROD_ALLOWED)
        if values.get("grade") is not None:
            forbid(values, ["fy", "fu"], "not allowed together with grade", STEEL_ALLOWED)
        elif (values.get("fy") is None) != (values.get("fu") is None):
            key = "fu" if values.get("fu") is None else "fy"
            raise rule_error(key, "required with the other measured strength", STEEL_ALLOWED)
        elif values.get("fy") is not None and values["fu"] < values["fy"]:
            raise rule_error("fu", "below fy", STEEL_ALLOWED, values["fu"])

    @property
    def is_stiff(self) -> bool:
        """True when the restrainer has a nonzero stiffness on some side (tie-rods always)."""
        if self.kind is RestrainerKind.TIE_ROD:
            return True
        return any(v for v in (self.k, self.k_pos, self.k_neg))


class Model(Table):
    """One macro-element: identity, block, mass, restitution, motion, analysis, restrainers,
    loads, thrusts, the building it stands in and the code check's settings."""

    name: str = Field(..., min_length=1, description="Name shown in reports")
    kind: Kind = Field(
        ..., description="'wall', 'altar', 'facade', or 'frame' (piers capped by a roof: [frame])"
    )
    notes: str | None = Field(None, description="Free text")
    geometry: Geometry = Field(..., description="The rocking block")
    mass: Mass | None = Field(
        None, description="Weight of the block; required when a restrainer has stiffness"
    )
    # Defaults are shared instances: the tables are frozen.
    restitution: Restitution = Field(
        Restitution.model_validate({}), description="Energy loss at impact"
    )
    motion: Motion = Field(Motion.model_validate({}), description="Two- or one-sided")
    analysis: Analysis = Field(Analysis.model_validate({}), description="Run settings")
    restrainers: tuple[Restrainer, ...] = Field((), description="Horizontal springs, any number")
    loads: tuple[Load, ...] = Field(
        (), description="Weights on the block (floors, roof); need a [mass] table"
    )
    thrusts: tuple[Thrust, ...] = Field(
        (), description="Horizontal forces (roof, arch); need a [mass] table"
    )
    building: Building = Field(
        Building.model_validate({}), description="Where the element stands in the building"
    )
    base: Base | None = Field(
        None, description="The base joint's friction: whether it slides before it rocks"
    )
    ntc: Ntc | None = Field(None, description="Settings of the NTC kinematic check")
    return_walls: ReturnWalls | None = Field(
        None, description="The return walls, where a wedge can form"
    )
    masonry: Masonry | None = Field(None, description="The masonry's strength")
    mechanisms: tuple[MechanismEntry, ...] = Field(
        (), description="The local mechanisms to check; none: overturning about the base"
    )
    frame: FrameTable | None = Field(
        None, description="A rocking frame's piers and roof, with kind = 'frame'"
    )

    @model_validator(mode="before")
    @classmethod
    def _frame_sizes(cls, data: Any) -> Any:
        """A frame's [geometry] written from its [frame] (rockcli.model.frame_table)."""
        return frame_geometry(data)

    @model_validator(mode="after")
    def _cross_table_rules(self) -> Model:
        """Rules that span tables: width for unit_weight, mass for springs and loads, points
        within the block."""
        self._check_width()
        self._check_mass()
        self._check_points()
        b, h = self.geometry.half_sizes
        physical: dict[str, Sequence[Load | Thrust]] = {
            "loads": self.loads,
            "thrusts": self.thrusts,
        }
        check_mass(physical, self.mass is not None)
        top = 2.0 * h + (self.geometry.gable_height or 0.0)
        check_points(physical, 2.0 * b, top, CONTAINMENT_RTOL)
        check_frame(self)
        check_mechanisms(self)
        return self

    def _check_width(self) -> None:
        if self.mass is not None and self.mass.unit_weight is not None:
            if self.geometry.width is None:
                raise rule_error(
                    ("geometry", "width"), "required with mass.unit_weight", LENGTH_ALLOWED
                )

    def _check_mass(self) -> None:
        stiff = [i for i, r in enumerate(self.restrainers) if r.is_stiff]
        if stiff and self.mass is None:
            raise rule_error(
                "mass",
                f"required because restrainers[{stiff[0]}] has a stiffness (paper §4.3)",
                "a [mass] table with weight [kN] or unit_weight [kN/m³]",
            )

    def _check_points(self) -> None:
        thickness = 2.0 * self.geometry.half_sizes[0]
        for i, r in enumerate(self.restrainers):
            if r.from_pivot is not None and r.from_pivot > thickness * (1 + CONTAINMENT_RTOL):
                raise rule_error(
                    ("restrainers", i, "from_pivot"),
                    "outside the block",
                    f"a number >= 0 and <= the thickness 2b = {thickness:.4g} [m]",
                    r.from_pivot,
                )
