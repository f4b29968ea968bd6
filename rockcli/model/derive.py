"""From the validated model to the core's parameters: SI floats in frozen dataclasses.

The rocking engine and the code check receive a :class:`rockcli.mechanics.Block` and an
:class:`AnalysisOptions`, never the pydantic model (spec/style.md, principle 2). The rules
that turn the file's convenient forms into r, φ, K and e live here, each in one function.

Pure: only :mod:`math` and :mod:`rockcli.mechanics` (no numpy, scipy or numba, so that model
validation starts fast; spec/engine.md, "Speed").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, TypeVar

from rockcli.codecheck.steel import (
    CLAUSE,
    GRADES,
    TensionResistance,
    elongation_at_break,
    rod_area,
    tension_resistance,
)
from rockcli.codecheck.tie import (
    ELONGATION_CLAUSE,
    GAMMA_ELONGATION,
    GAMMA_OV,
    MEASURED_OV,
    elongation_capacity,
    overstrength_force,
)
from rockcli.mechanics import (
    NEGATIVE,
    POSITIVE,
    Block,
    Load,
    Restrainer,
    Rocker,
    Thrust,
    frequency_parameter_sq,
    housner_restitution,
    impact_restitution,
    point_polar,
    rebound_restitution,
    tie_rod_stiffness,
)
from rockcli.model.ntc import Ntc
from rockcli.model.physical import Direction
from rockcli.model.physical import Load as LoadTable
from rockcli.model.physical import Thrust as ThrustTable
from rockcli.model.schema import (
    STEEL_MODULUS,
    Acts,
    CodeAction,
    Law,
    Model,
    Position,
    RestitutionModel,
    RestrainerKind,
    Sides,
    StoppedSide,
)
from rockcli.model.schema import Restrainer as RestrainerTable
from rockcli.notes import Note

#: kN → N.
NEWTONS_PER_KILONEWTON = 1e3

#: Any kind of what the engines rock (a function that keeps the kind it is given).
AnyRocker = TypeVar("AnyRocker", bound=Rocker)


@dataclass(frozen=True)
class AnalysisOptions:
    """Settings of a time-history run, as the dynamics engine consumes them.

    Attributes:
        tail: free-vibration time after the record [s] (``None``: the engine's default).
        overturn_angle: |θ| at which the block counts as overturned [rad].
        rtol: relative tolerance of the integration [-].
        atol: absolute tolerance of the integration [rad].
        rest_velocity: rest threshold on |θ̇⁺| after an impact [rad/s].
    """

    tail: float | None
    overturn_angle: float
    rtol: float
    atol: float
    rest_velocity: float


@dataclass(frozen=True)
class Description:
    """The block's derived quantities, for reports (SI units).

    Attributes:
        b, h: half-thickness and half-height [m].
        thickness, height: full thickness 2b and height 2h [m].
        R: semi-diagonal [m].
        alpha: slenderness [rad].
        width: out-of-plane length [m] (``None`` when not given).
        pivot_height: height of the pivot above ground [m] (``None`` when not given).
        mass: mass [kg] (``None`` without a [mass] table).
        weight: weight W = m g [N] (``None`` without a [mass] table).
        e: coefficient of restitution in force [-].
        e_rule: how e was obtained, e.g. "0.9 × Housner (1 − 1.5 sin²α)".
        p: frequency parameter √(3g/(4R)) [rad/s].
        loads, thrusts: the block's loads and thrusts, one row each (SI, as in the block).
    """

    b: float
    h: float
    thickness: float
    height: float
    R: float
    alpha: float
    width: float | None
    pivot_height: float | None
    mass: float | None
    weight: float | None
    e: float
    e_rule: str
    p: float
    loads: tuple[Load, ...] = ()
    thrusts: tuple[Thrust, ...] = ()


def to_block(model: Model) -> Block:
    """The rigid block with its restrainers, in SI floats (spec/rocking.md).

    A wall whose mechanisms are not the block's (rockcli.model.derive_wall) is refused: the
    time history rocks the rectangular block only (InputError). Derived anew on each call:
    a caller that needs it twice keeps it (rockcli.model.catalogue derives it once a model).
    """
    refuse_unrockable(model)
    return derive_block(model)


def refuse_unrockable(model: Model) -> None:
    """InputError unless the time history can rock the model: a block, or a one-storey wall
    without a gable and without a masonry strength (the set-back hinge) whose mechanisms are
    none or include its overturning about the base (the rectangle the engine rocks; the
    other mechanisms are checked by the code only, rockcli.analyses.compare says so)."""
    geometry = model.geometry
    storeys = geometry.storeys or ()
    rocked = not model.mechanisms or any(
        m.type.value == "overturning" and m.hinge_height in (None, 0.0) for m in model.mechanisms
    )
    plain = len(storeys) <= 1 and geometry.gable_height is None
    if plain and rocked and (model.masonry is None or model.masonry.f_m is None):
        return
    from rockcli.errors import InputError

    raise InputError(
        "the time history cannot yet rock this wall (it rocks the rectangular block: one "
        "storey, no gable, no masonry.f_m, with its overturning about the base)",
        where="geometry.storeys" if len(storeys) > 1 else "mechanisms",
        allowed="rock kinematic, which checks every mechanism of the catalogue; for a time "
        "history, a model of one block or of one storey",
    )


def derive_block(model: Model) -> Block:
    """:func:`to_block` without the check of the mechanisms (the model's validation derives
    the block's numbers of any model to check they are finite; a wall's mechanisms take the
    engine's settings from it)."""
    R, alpha = model.geometry.polar
    motion = model.motion
    one_sided = motion.sides is Sides.ONE
    block = Block(
        R=R,
        alpha=alpha,
        mass=block_mass(model),
        g=model.analysis.g,
        e=restitution(model)[0],
        one_sided=one_sided,
        free_side=free_side(motion.stopped) if one_sided else POSITIVE,
        rebound=motion.rebound if motion.rebound is not None else 1.0,
        linearized=model.analysis.linearized,
        restrainers=tuple(to_restrainer(model, i) for i in range(len(model.restrainers))),
        loads=tuple(to_load(model, i) for i in range(len(model.loads))),
        thrusts=tuple(to_thrust(model, i) for i in range(len(model.thrusts))),
    )
    return with_system_restitution(block, model)


def with_system_restitution(block: AnyRocker, model: Model) -> AnyRocker:
    """The block with Housner's e of the block and its loads (or of a wall's mechanism as a
    body of its own shape), per side; a one-sided block with the e of its own impact.

    Source: mechanics.impact_restitution (Housner 1963, angular momentum about the new pivot,
    written for the block with its loads; docs/physics.md, "Impacts"): two-sided, e of each
    side as it is (above 1 too: the new pivot's inertia is then smaller, and the energy kept,
    e₊·e₋, is below 1). One-sided, mechanics.rebound_restitution on both sides, √(e₊·e₋): the
    energy Housner's impact at the other pivot keeps, the block turning back about its own
    (docs/physics.md, "One-sided impacts"). The factor and the clip at 0 apply as for the lone
    block; an explicit e stays as given on both sides.
    """
    table = model.restitution
    if table.rule is RestitutionModel.EXPLICIT or block.mass is None:
        return block
    if isinstance(block, Block) and not block.loads:
        return block
    factor = 1.0 if table.factor is None else table.factor
    if block.one_sided:
        e_pos = e_neg = max(rebound_restitution(block), 0.0) * factor
    else:
        e_pos, e_neg = (max(impact_restitution(block, s), 0.0) * factor for s in (1, -1))
    return replace(block, e=e_pos, e_neg=e_neg)


def solver_options(model: Model) -> AnalysisOptions:
    """The run settings of the [analysis] table (defaults: spec/engine.md)."""
    a = model.analysis
    return AnalysisOptions(
        tail=a.tail,
        overturn_angle=a.overturn_angle,
        rtol=a.rtol,
        atol=a.atol,
        rest_velocity=a.rest_velocity,
    )


def describe(model: Model) -> Description:
    """Derived quantities of the block for reports: sizes, mass, weight, e and its rule, p."""
    b, h = model.geometry.half_sizes
    R, alpha = model.geometry.polar
    mass = block_mass(model)
    g = model.analysis.g
    e, rule = restitution(model)
    return Description(
        b=b,
        h=h,
        thickness=2 * b,
        height=2 * h,
        R=R,
        alpha=alpha,
        width=model.geometry.width,
        pivot_height=model.geometry.pivot_height,
        mass=mass,
        weight=None if mass is None else mass * g,
        e=e,
        e_rule=rule,
        p=math.sqrt(frequency_parameter_sq(R, g)),
        loads=tuple(to_load(model, i) for i in range(len(model.loads))),
        thrusts=tuple(to_thrust(model, i) for i in range(len(model.thrusts))),
    )


def block_weight(model: Model) -> float | None:
    """W [N]: the weight given, or γ·2b·2h·width (spec/README.md, "mass"); None without mass."""
    m = model.mass
    if m is None:
        return None
    if m.weight is not None:
        return m.weight * NEWTONS_PER_KILONEWTON
    assert m.unit_weight is not None and model.geometry.width is not None
    b, h = model.geometry.half_sizes
    return m.unit_weight * NEWTONS_PER_KILONEWTON * (2 * b) * (2 * h) * model.geometry.width


def block_mass(model: Model) -> float | None:
    """m = W/g [kg] (g of the model's [analysis] table); None without a [mass] table."""
    weight = block_weight(model)
    return None if weight is None else weight / model.analysis.g


def restitution(model: Model) -> tuple[float, str]:
    """(e, rule): Housner's e = 1 − 1.5 sin²α times the factor (0 if ≤ 0), or e as given.

    Source: paper Eq. (3) (Housner 1963); spec/rocking.md, "Two-sided impact": for
    α ≥ 54.74° Housner's e ≤ 0, no rocking after the first impact, so e = 0.
    """
    table = model.restitution
    if table.rule is RestitutionModel.EXPLICIT:
        assert table.e is not None
        return table.e, EXPLICIT
    factor = 1.0 if table.factor is None else table.factor
    e = max(housner_restitution(model.geometry.polar[1]), 0.0) * factor
    rule = HOUSNER_LOADS if model.loads else HOUSNER
    return e, rule if factor == 1.0 else factored(factor, rule)


def factored(factor: float, rule: Note) -> Note:
    """ "0.9 × rule": a restitution rule times the model's factor."""
    return Note("factored", "{factor:g} × {rule}", factor=float(factor), rule=rule)


def free_side(stopped: StoppedSide | None) -> int:
    """The side a one-sided block can rotate to: the opposite of the stopped one.

    Default stopped side: negative (spec of the model file), so the free side is +1.
    """
    return NEGATIVE if stopped is StoppedSide.POSITIVE else POSITIVE


def to_restrainer(model: Model, index: int) -> Restrainer:
    """Restrainer ``index`` of the model with per-side K, r, φ and its failure elongation."""
    table = model.restrainers[index]
    k_pos, k_neg = stiffness(table)
    (r_pos, phi_pos), (r_neg, phi_neg) = attachment(model, table)
    strength, rule = member_strength(model, table)
    yield_pos, yield_neg, rupture_force = member_law(model, table)
    code_force = code_force_of(table, strength, (yield_pos, yield_neg))
    return Restrainer(
        name=table.name or f"restrainer {index + 1}",
        k_pos=k_pos,
        k_neg=k_neg,
        r_pos=r_pos,
        phi_pos=phi_pos,
        r_neg=r_neg,
        phi_neg=phi_neg,
        fails_at=rupture_elongation(table, max(k_pos, k_neg)),
        breaks_at=default_rupture_elongation(table, max(k_pos, k_neg)),
        strength=strength,
        strength_rule=rule,
        law=table.effective_law.value,
        yield_pos=yield_pos,
        yield_neg=yield_neg,
        pretension=table.pretension or 0.0,
        rupture_force=rupture_force,
        anchor_capacity=math.inf if table.anchor_capacity is None else table.anchor_capacity,
        code_action=table.effective_code_action.value,
        code_force=code_force,
        slack_side=slack_side(table),
        **bar_verification(table),
    )


def slack_side(table: RestrainerTable) -> int:
    """The side on which a member can only push (rockcli.mechanics.Restrainer.slack_side):
    −1 for a tie-rod acting both ways (a bar anchored in the building pulls the wall back when
    it turns outward and goes slack when it turns inward), else 0."""
    if table.kind is RestrainerKind.TIE_ROD and (table.acts or Acts.BOTH) is Acts.BOTH:
        return NEGATIVE
    return 0


def bar_verification(table: RestrainerTable) -> dict[str, Any]:
    """A steel bar's ductility capacity ε_u·L/γ_ε [m] (with where ε_u comes from) and its
    over-strength γ_ov·A·f_y [N] for its anchorage (codecheck.tie); nothing for another member.

    ε_u: the model's ``elongation_at_break``, else the grade's A of EN 10025-2 Tab. 7; a bar of
    measured f_y, f_u without it has no ductility capacity. f_y: the grade's nominal f_yk or the
    measured value (not divided by FC: an upper value is wanted), γ_ov of NTC 2018 §7.5.1
    (1.25 for a measured bar). docs/interpretations.md, "Tie-rods: ductility and anchorage".
    """
    if not table.has_steel:
        return {}
    assert table.diameter is not None and table.length is not None
    grade = None if table.grade is None else table.grade.value
    fy = GRADES[grade][0] if grade is not None else table.fy
    assert fy is not None
    out: dict[str, Any] = {
        "overstrength": overstrength_force(
            rod_area(table.diameter, table.count or 1), fy, GAMMA_OV.get(grade or "", MEASURED_OV)
        )
    }
    if table.elongation_at_break is not None:
        eps, rule = table.elongation_at_break, Note("eps_given", "elongation_at_break of the model")
    elif grade is not None:
        eps, rule = (
            elongation_at_break(grade),
            Note("eps_grade", "A of {grade} ({clause})", grade=grade, clause=ELONGATION_CLAUSE),
        )
    else:
        return out
    out["elongation_capacity"] = elongation_capacity(eps, table.length)
    out["ductility_rule"] = Note(
        "ductility_rule", "ε_u·L/γ_ε = {percent:.3g} % × {length:g} m / {gamma:g}, ε_u: {rule}",
        percent=100 * eps, length=float(table.length), gamma=float(GAMMA_ELONGATION), rule=rule,
    )  # fmt: skip
    return out


def confidence_factor(model: Model) -> float:
    """FC of [ntc] (its default when the table is absent)."""
    return (model.ntc or Ntc.model_validate({})).confidence_factor


def rupture_elongation(table: RestrainerTable, k: float) -> float:
    """Elongation u of the spring, from rest, at which the model says the member is lost [m]
    (inf: never); both analyses rely on it.

    ``fails_at`` as given; for a tie-rod with an elongation at break ε_u, the bar breaks when
    its whole elongation, the pretension's P0/K included, reaches ε_u·L (bar_rupture).
    """
    if table.fails_at is not None:
        return table.fails_at
    if table.elongation_at_break is None:
        return math.inf
    return bar_rupture(table, table.elongation_at_break, k)


def default_rupture_elongation(table: RestrainerTable, k: float) -> float:
    """Elongation u at which a tie-rod of a standard grade breaks when the model gives neither
    ``fails_at`` nor ``elongation_at_break`` [m] (inf: no default); the time history only.

    The grade's elongation after fracture A of EN 10025-2 Table 7
    (codecheck.steel.elongation_at_break), through bar_rupture. A bar given by its measured
    f_y, f_u has no grade, hence no default: it breaks only where the model says
    (docs/interpretations.md, "Restrainer laws").
    """
    if table.fails_at is not None or table.elongation_at_break is not None:
        return math.inf
    if table.kind is not RestrainerKind.TIE_ROD or table.grade is None:
        return math.inf
    return bar_rupture(table, elongation_at_break(table.grade.value), k)


def bar_rupture(table: RestrainerTable, strain: float, k: float) -> float:
    """u = ε_u·L − P0/K [m]: the spring elongation from rest at which the bar's whole
    elongation, the pretension's stretch P0/K included, reaches ε_u·L (docs/interpretations.md).
    """
    assert table.length is not None
    return strain * table.length - (table.pretension or 0.0) / k


def code_force_of(table: RestrainerTable, strength: float, yields: tuple[float, float]) -> float:
    """The force the kinematic check relies on with code_action "force" [N], 0 with "spring".

    A tie-rod of known steel: its design strength N_t,Rd capped by the anchor (NTC 2018
    §4.2.4.1.2); another member: the lowest of its yield forces and its anchor capacity.
    """
    if table.effective_code_action is CodeAction.SPRING:
        return 0.0
    if table.has_steel:
        return strength
    return min(*yields, strength)


def steel_resistance(model: Model, table: RestrainerTable) -> tuple[TensionResistance, str] | None:
    """A tie-rod's design tension resistance and its steel's label; None without a steel.

    Source: NTC 2018 §4.2.4.1.2 (codecheck.steel.tension_resistance): a standard grade with its
    nominal strengths; measured fy, fu of an existing bar divided by the confidence factor FC
    of [ntc] (docs/interpretations.md); capped by the anchor's capacity.
    """
    if table.kind is not RestrainerKind.TIE_ROD or (table.grade is None and table.fy is None):
        return None
    assert table.diameter is not None
    anchor = math.inf if table.anchor_capacity is None else table.anchor_capacity
    area = rod_area(table.diameter, table.count or 1)
    if table.grade is not None:
        fy, fu = GRADES[table.grade.value]
        factor, steel = 1.0, table.grade.value
    else:
        assert table.fy is not None and table.fu is not None
        fy, fu = table.fy, table.fu
        factor = confidence_factor(model)
        steel = f"measured fy, fu ÷ FC = {factor:g}"
    return tension_resistance(area, fy, fu, factor, anchor), steel


#: The coefficient of restitution as the model gives it, or Housner's (of the block alone, or
#: with its loads).
EXPLICIT = Note("explicit", "explicit")
HOUSNER = Note("housner", "Housner (1 − 1.5 sin²α)")
HOUSNER_LOADS = Note("housner_loads", "Housner of the block with its loads")
#: The strength of a member set by its anchor (rather than a steel's resistance).
ANCHOR = Note("anchor_capacity", "anchor capacity")


def member_strength(model: Model, table: RestrainerTable) -> tuple[float, str]:
    """(strength [N], what sets it): a tie-rod's design tension resistance, capped by the
    anchor's capacity; a restrainer given by its stiffness has the anchor's capacity only.
    (inf, "") when neither a steel nor an anchor is given (steel_resistance).
    """
    steel = steel_resistance(model, table)
    if steel is None:
        anchor = math.inf if table.anchor_capacity is None else table.anchor_capacity
        return (anchor, ANCHOR) if math.isfinite(anchor) else (math.inf, "")
    res, label = steel
    what = {"plastic": "N_pl,Rd", "ultimate": "N_u,Rd", "anchor": ANCHOR}[res.governs]
    return res.strength, Note(
        "strength_rule", "{label}: {what} governs ({clause})", label=label, what=what, clause=CLAUSE
    )


def member_law(model: Model, table: RestrainerTable) -> tuple[float, float, float]:
    """(yield while θ > 0, yield while θ < 0, rupture force) [N] of the member's law.

    Elastic: no yield; lost at its anchor's capacity. A spring: its yield_pos, yield_neg. A
    tie-rod of known steel yields at its design plastic resistance N_pl,Rd = A·f_y/γ_M0 and
    breaks at the lower of its anchor's capacity and its net section's N_u,Rd = 0.9·A·f_u/γ_M2
    (NTC 2018 §4.2.4.1.2): its force never exceeds its design strength N_t,Rd
    (docs/interpretations.md, "Restrainer laws").
    """
    anchor = math.inf if table.anchor_capacity is None else table.anchor_capacity
    steel = steel_resistance(model, table)
    if table.effective_law is Law.ELASTIC or steel is None:
        yield_pos, yield_neg = table.yield_forces()
        return yield_pos, yield_neg, anchor
    res = steel[0]
    return res.plastic, res.plastic, min(anchor, res.ultimate)


def stiffness(table: RestrainerTable) -> tuple[float, float]:
    """(k_pos, k_neg) [N/m]: as given, k on both sides, or a tie-rod's count·E·π·d²/4 / L.

    Source: spec/README.md (convenience form ``tie-rod``); paper Table 2.
    """
    if table.kind is RestrainerKind.TIE_ROD:
        assert table.diameter is not None and table.length is not None
        modulus = STEEL_MODULUS if table.E is None else table.E
        k = tie_rod_stiffness(table.diameter, table.length, modulus) * (table.count or 1)
        acts = table.acts or Acts.BOTH
        return (k if acts is not Acts.NEGATIVE else 0.0, k if acts is not Acts.POSITIVE else 0.0)
    if table.k is not None:
        return table.k, table.k
    assert table.k_pos is not None and table.k_neg is not None
    return table.k_pos, table.k_neg


def attachment(
    model: Model, table: RestrainerTable
) -> tuple[tuple[float, float], tuple[float, float]]:
    """((r⁺, φ⁺), (r⁻, φ⁻)) of the attachment point about pivot O (θ > 0) and O′ (θ < 0).

    Source: spec/rocking.md, "Restrainers": radius + angle is the paper's form, the same for
    both pivots; a point at height z and distance x from O is at 2b − x from O′
    (r = √(x² + z²), φ = atan(x/z)); the top corner is r = 2R, φ = α (paper Eq. 4).
    """
    if table.position is Position.TOP:
        R, alpha = model.geometry.polar
        return (2 * R, alpha), (2 * R, alpha)
    if table.radius is not None and table.angle is not None:
        return (table.radius, table.angle), (table.radius, table.angle)
    assert table.height is not None and table.from_pivot is not None
    thickness = 2 * model.geometry.half_sizes[0]
    # The schema allows x up to the thickness plus a rounding slack; clamp the other side at 0.
    x_other = max(thickness - table.from_pivot, 0.0)
    return point_polar(table.from_pivot, table.height), point_polar(x_other, table.height)


def point(model: Model, table: LoadTable | ThrustTable) -> tuple[float, float, float]:
    """(x_pos, x_neg, z) [m] of a load's or a thrust's point.

    x_pos from pivot O (θ > 0), default the mid-plane b; x_neg = 2b − x_pos from O′, clamped at
    0 (the schema allows a rounding slack past the face); z the height, 2h for the top.
    """
    b, h = model.geometry.half_sizes
    x_pos = b if table.from_pivot is None else table.from_pivot
    z = 2.0 * h if table.position is Position.TOP else table.height
    assert z is not None
    return x_pos, max(2.0 * b - x_pos, 0.0), z


def to_load(model: Model, index: int) -> Load:
    """Load ``index`` of the model: weight in N, its point about each pivot, bears and moves."""
    table = model.loads[index]
    x_pos, x_neg, z = point(model, table)
    return Load(
        name=table.name or f"load {index + 1}",
        weight=table.weight * NEWTONS_PER_KILONEWTON,
        x_pos=x_pos,
        x_neg=x_neg,
        z=z,
        bears=table.bears,
        moves=table.moves,
    )


def to_thrust(model: Model, index: int) -> Thrust:
    """Thrust ``index`` of the model: force in N, direction ±1, its point about each pivot."""
    table = model.thrusts[index]
    x_pos, x_neg, z = point(model, table)
    return Thrust(
        name=table.name or f"thrust {index + 1}",
        force=table.force * NEWTONS_PER_KILONEWTON,
        direction=POSITIVE if table.direction is Direction.POSITIVE else NEGATIVE,
        x_pos=x_pos,
        x_neg=x_neg,
        z=z,
    )
