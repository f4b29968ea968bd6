"""The code check of every mechanism of a wall, and the governing one.

Composition only: the geometry of each mechanism comes from rockcli.mechanisms.catalogue, its
capacity from rockcli.codecheck.kinematic, its checks from the edition's rules through
:func:`rockcli.analyses.capacity_check.analyse_capacity` — the very path of today's block. A storey
mechanism stands in the building at the height of its hinge (Z + hinge height: ψ and the floor
spectra there). The governing mechanism is the one with the lowest ULS ζ_E (capacity over
demand of the deciding checks), then the lowest DLS ζ_E, then the lowest α0
(Circolare 7/2019 §C8.7.1: the assessment takes the most vulnerable mechanism).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from rockcli.analyses.capacity_check import analyse_capacity
from rockcli.codecheck.demand import LimitStateDemand
from rockcli.codecheck.free import MASONRY_TYPES, elastic_period
from rockcli.codecheck.hazard_curve import HazardCurve
from rockcli.codecheck.kinematic import Capacity, Mechanism, alpha0, capacity
from rockcli.codecheck.position import Position, position
from rockcli.codecheck.result import KinematicResult, deciding
from rockcli.errors import InputError
from rockcli.mechanisms.wall import NOT_ROCKED, MechanismSpec, MechanismType, Wall
from rockcli.model.catalogue import Arch, arch_of, named, placed
from rockcli.model.catalogue import Mechanism as CatalogueMechanism
from rockcli.model.derive_ntc import BuildingSettings, NtcSettings
from rockcli.notes import Note


def main_mechanism(kin: KinematicResult, name: str | None = None) -> MechanismResult | None:
    """The mechanism a wall's comparison shows in full: the one named, else the governing one
    of those the time history rocks (a horizontal flexure is the code check's alone); None
    for a model of one block (or a wall with one mechanism, and no name)."""
    if name is not None:
        return named_result(kin, name)
    if len(kin.catalogue) < 2:
        return None
    rocks = [m for m in kin.catalogue if MechanismType(m.type) not in NOT_ROCKED]
    return rocks[0] if rocks else kin.catalogue[0]


def named_result(kin: KinematicResult, name: str) -> MechanismResult:
    """The catalogue's entry of that name (InputError naming the catalogue's names)."""
    return named(kin.catalogue, name)


@dataclass(frozen=True)
class Friction:
    """The toothed return walls' friction on a mechanism (Circolare 7/2019 Eq. C8.7.1.2).

    Attributes:
        force: F of one return wall [N]. walls: how many resist (1 or 2). lever: its point
        above the hinge, h/3 [m]. height: h, the toothed height above the hinge [m].
        courses: n = h/h_b.
    """

    force: float
    walls: int
    lever: float
    height: float
    courses: float


def friction_of(mech: CatalogueMechanism) -> Friction | None:
    """The friction a mechanism's placement carries (None: none)."""
    view = mech.view(mech.sides[0])
    toothing = None if mech.wall is None else mech.wall.toothing
    frictions = getattr(view, "frictions", ())
    if not frictions or toothing is None:
        return None
    f = frictions[0]
    return Friction(f.force / toothing.walls, toothing.walls, f.lever, f.height,
                    f.height / toothing.course_height)  # fmt: skip


def friction_note(friction: Friction) -> Note:
    """The friction in a sentence, with the clause."""
    return Note("friction", "friction of {walls} toothed return wall(s): F = {F:.3f} kN each "
                "at h/3 = {lever:.3f} m above the hinge (Circolare 7/2019 Eq. C8.7.1.2: "
                "h = {h:.3f} m, n = {n:.4g} courses); the time history carries it as a Coulomb "
                "moment against the motion",
                walls=friction.walls, F=friction.force / 1e3, lever=friction.lever,
                h=friction.height, n=friction.courses)  # fmt: skip


@dataclass(frozen=True)
class MechanismResult:
    """One mechanism of the catalogue and its code check.

    Attributes:
        name, type: as in the model (``type`` a MechanismType value).
        hinge_height: the base hinge's height above the wall's base [m] (vertical flexure:
            its intermediate hinge's).
        storey: vertical flexure's storey (1 = ground), else None.
        M_star: participating mass [kg].
        result: the code check, as for today's block.
        friction: the toothed return walls' friction on it (None: none).
        arch: a horizontal flexure's arch: its thrust and stress block (None: another type).
        T_Rc: the return period of the action that brings it to each limit state [years]
            (:func:`return_periods`; None: the demand is not a site's).
        pga_SLV: (PGA_C, PGA_D) at the SLV: the ground's peak acceleration ag·S of the
            capacity ag of its deciding checks and of the demand [g] (:func:`pga_at_slv`;
            None: the demand is not the code's spectrum, or no capacity ag).
        hazard: the hazard curve T_Rc was read on (None: none).
    """

    name: str
    type: str
    hinge_height: float
    storey: int | None
    M_star: float
    result: KinematicResult
    friction: Friction | None = None
    arch: Arch | None = None
    T_Rc: dict[str, float] | None = None
    pga_SLV: tuple[float, float] | None = None
    hazard: HazardCurve | None = None

    def zeta(self, states: tuple[str, ...]) -> float | None:
        """ζ_E of these limit states: the lowest capacity/demand of the deciding checks
        (None: not evaluated)."""
        ratios = [c.ratio for c in deciding(self.result.checks, states)]
        known = [r for r in ratios if r is not None]
        if not ratios or len(known) < len(ratios):
            return None
        return min(known)

    @property
    def zeta_uls(self) -> float | None:
        """ULS ζ_E (2009: ULS; 2019: the lower of SLV and SLC)."""
        return self.zeta(("ULS", "SLV", "SLC"))

    @property
    def zeta_dls(self) -> float | None:
        """DLS ζ_E."""
        return self.zeta(("DLS", "SLD"))


def governing_order(m: MechanismResult) -> tuple[float, float, float]:
    """The key that sorts the governing mechanism first: ULS ζ, DLS ζ, α0 (not evaluated:
    last)."""
    uls, dls = m.zeta_uls, m.zeta_dls
    return (math.inf if uls is None else uls, math.inf if dls is None else dls,
            m.result.alpha0)  # fmt: skip


def mechanism_of(wall: Wall, spec: MechanismSpec, side: int, settings: NtcSettings) -> Mechanism:
    """The code check's view of one mechanism of a wall on one side (its hinge resolved)."""
    return Mechanism(placed(wall, spec, side), settings.distributed, settings.edition == "2019")


def side_check(mech: CatalogueMechanism, side: int, settings: NtcSettings) -> Mechanism:
    """The code check's view of ``side`` of a catalogue's mechanism with the edition's sums."""
    return mech.check(side, settings.distributed, settings.edition == "2019")


def mechanism_position(mech: CatalogueMechanism, building: BuildingSettings) -> Position:
    """Where the mechanism stands: Z + the height of its base hinge (a vertical flexure: the
    middle of its storey, rockcli.model.catalogue.spec_base); without the building's H,
    H = Z + the wall's height, N its storeys."""
    b = building
    Z = b.Z + mech.base
    if mech.base == 0.0:
        return position(b.Z, b.H, b.N, b.T1, b.gamma, b.psi, b.damping)
    H = b.H if b.H is not None else b.Z + mech.wall_height
    # The wall's storeys stand for the building's only when the wall is the building (H
    # taken from it); a building's H without N keeps the block's default, γ of N = 1.
    N = b.N if b.N is not None else (mech.storey_count if b.H is None else None)
    if Z > H * (1.0 + 1e-9):
        raise InputError(
            f"below the base of mechanism '{mech.name}' (Z + its hinge = {Z:g} m): ψ = Z/H "
            "would exceed 1",
            where="building.H",
            value=b.H,
            allowed=f"the building's height, at least Z + the hinge's height = {Z:g} m",
        )
    pos = position(Z, H, N, b.T1, b.gamma, None, b.damping)
    if b.H is None:
        pos = replace(pos, notes=(*pos.notes, Note(
            "H_default", "building height H = Z + the wall's height = {H:.3f} m and N = {N} "
            "storeys, not given", H=float(H), N=N)))  # fmt: skip
    return pos


def free_period(
    mech: CatalogueMechanism, settings: NtcSettings
) -> tuple[float | None, tuple[str, ...]]:
    """(T0 [s], notes) of a mechanism free to vibrate (None: rigid until activation).

    Circolare 7/2019 Eq. C8.7.1.7, T0 = κ·λ·L·√(W/(E·g)) with λ = L/t, of the member the
    catalogue gives (rockcli.model.catalogue.free_member). The 2009 edition has no elastic
    branch: a note says the declaration is not used.
    """
    if mech.free is None:
        return None, ()
    if settings.edition != "2019":
        return None, (Note("free_2009", "free to vibrate: the elastic branch is a rule of "
                           "Circ. 7/2019 (§C8.7.1.2.1.3); the 2009 check is rigid until "
                           "activation"),)  # fmt: skip
    member = mech.free
    if member.E is None:
        default = " (a gable is free by default)" if mech.type is MechanismType.GABLE else ""
        raise InputError(
            f"mechanism '{mech.name}' is free to vibrate{default}: its period T0 needs the "
            "masonry's Young's modulus (Circolare 7/2019 Eq. C8.7.1.7)",
            where="masonry",
            allowed="[masonry] E [Pa], or [masonry] type (one of "
            + ", ".join(MASONRY_TYPES)
            + "); or free = false on the mechanism",
        )
    kappa, length, thickness = member.kappa, member.length, member.thickness
    T0 = elastic_period(kappa, length, thickness, member.unit_weight, member.E, member.g)
    note = Note(
        "free_T0", "free to vibrate: elastic branch a = 4π²d/T0² to (a_y, d_y) "
        "[C8.7.1.6], T0 = κ·λ·L·√(W/(E·g)) = {T0:.4f} s [C8.7.1.7] with κ = {kappa:g}, "
        "L = {length:.3f} m, λ = L/t = {slender:.3g}, E = {E:g} MPa; SLD at S_e(T0) "
        "[C8.7.1.9]", T0=T0, kappa=kappa, length=length, slender=length / thickness,
        E=member.E / 1e6,
    )  # fmt: skip
    return T0, (note,)


def refuse_unstable(name: str, cap: Capacity, where: str = "thrusts") -> None:
    """InputError when the thrusts open the mechanism with no earthquake (α0 ≤ 0), as for
    the block (rockcli.model.derived_checks): no code check describes a wall already falling.
    ``where``: the field that holds them (the model's thrusts, or a corner's hip_thrust)."""
    if cap.alpha0 > 0.0:
        return
    side = "outward (side 1)" if cap.mech.side > 0 else "inward (side −1)"
    raise InputError(
        f"the thrusts open mechanism '{name}' {side} with no earthquake (α0 = {cap.alpha0:.4g})",
        where=where,
        allowed="thrusts whose work is less than that of the weights (α0 > 0 on each side "
        "each mechanism can open to)",
    )


def thrusts_field(mech: CatalogueMechanism) -> str:
    """The model file's field of the thrusts on ``mech``: a corner's own hip_thrust
    (``mechanisms[i].hip_thrust``, i its entry's index), else the model's ``thrusts``."""
    spec = mech.spec
    if spec is None or spec.type is not MechanismType.CORNER or not spec.hip_thrust:
        return "thrusts"
    entries = [(i, e) for i, e in enumerate(mech.model.mechanisms or ())
               if e.type.value == MechanismType.CORNER.value and e.hip_thrust]  # fmt: skip
    named_entry = [i for i, e in entries if e.name == mech.name]
    index = named_entry or [i for i, _ in entries]
    return f"mechanisms[{index[0]}].hip_thrust" if len(index) == 1 else "hip_thrust"


def analyse_mechanism(
    mech: CatalogueMechanism, settings: NtcSettings, dem: dict[str, LimitStateDemand]
) -> MechanismResult:
    """One mechanism: each side it opens to, the governing side (the smaller d0*; a side
    without d0*, positive stiffness, is the stronger; ties: θ > 0), its checks at its
    position."""
    T0, free_notes = free_period(mech, settings)
    caps: list[Capacity] = [capacity(side_check(mech, s, settings), settings.FC, T0)
                            for s in mech.sides]  # fmt: skip
    for c in caps:
        refuse_unstable(mech.name, c, thrusts_field(mech))
    cap = min(caps, key=lambda c: (c.d0_star is None, c.d0_star or 0.0, -c.mech.side))
    by_side = {str(s): alpha0(side_check(mech, s, settings)) for s in mech.reported}
    from rockcli.analyses.sliding import alpha0_of, sliding_note

    friction = friction_of(mech)
    notes = (*mech.notes, *free_notes, *mech.strength_notes,
             *(() if friction is None else (friction_note(friction),)),
             *sliding_note(mech, alpha0_of(mech)))  # fmt: skip
    pos = mechanism_position(mech, settings.building)
    from rockcli.codecheck.kinematic import activation_terms, activation_work, participating_mass

    sides = sorted({*mech.reported, cap.mech.side}, reverse=True)
    checks = {str(s): side_check(mech, s, settings) for s in sides}
    terms = {key: activation_terms(check) for key, check in checks.items()}
    result = analyse_capacity(cap, settings, dem, pos, by_side, notes, terms)
    result = replace(result, work_by_side={key: activation_work(c) for key, c in checks.items()})

    arch = None
    if mech.type is MechanismType.HORIZONTAL_FLEXURE and mech.wall and mech.spec:
        arch = arch_of(mech.wall, mech.spec)
    return MechanismResult(mech.name, mech.type.value, mech.hinge_height, mech.storey,
                           participating_mass(cap.mech),
                           replace(result, mechanism=mech.name), friction, arch,
                           return_periods(result.checks, dem),
                           pga_at_slv(result.checks, dem),
                           next((d.hazard for d in dem.values() if d.hazard), None))  # fmt: skip


#: The demand's limit state of each check's (2009 calls SLD and SLV its DLS and ULS).
DEMAND_STATE = {"DLS": "SLD", "ULS": "SLV", "SLD": "SLD", "SLV": "SLV", "SLC": "SLC"}


def return_periods(checks, dem: dict[str, LimitStateDemand]) -> dict[str, float] | None:
    """T_Rc of each limit state whose demand comes from a site: the return period, on the
    site's hazard curve of ag (rockcli.codecheck.hazard_curve: log–log between the grid's
    30–2475 years as Allegato A interpolates, the end segments' power law beyond), of the
    capacity ag of its deciding checks (the lowest: the action that first brings it to the
    limit state; DM 58/2017 Allegato A's TR_C). None without a site."""
    out = {}
    for ls, demand in dem.items():
        states = tuple(k for k, v in DEMAND_STATE.items() if v == ls)
        caps = [c.capacity for c in deciding(checks, states)
                if c.unit == "g" and c.capacity is not None]  # fmt: skip
        if demand.hazard is not None and caps:
            out[ls] = demand.hazard.return_period_of(min(caps))
    return out or None


def pga_at_slv(checks, dem: dict[str, LimitStateDemand]) -> tuple[float, float] | None:
    """(PGA_C, PGA_D) at the SLV [g]: the peak ground acceleration ag·S (S = S_S·S_T of the
    soil at that ag, NTC 2018 §3.2.3.2.1) of the lowest capacity ag of the SLV's deciding checks
    and of the demand's ag: the two terms of DM 58/2017 Allegato A's IS-V = PGA_C/PGA_D
    (rockcli.risk.classification). None for a record's demand (not the code's spectrum) or
    without a capacity ag (2009: the checks are not in ag)."""
    demand = dem.get("SLV")
    caps = [c.capacity for c in deciding(checks, ("SLV",))
            if c.unit == "g" and c.capacity is not None]  # fmt: skip
    if demand is None or demand.parameters is None or not caps:
        return None
    return demand.at_ag(min(caps)).pga_ground, demand.spectrum.pga_ground


def analyse_catalogue(
    mechanisms: tuple[CatalogueMechanism, ...],
    settings: NtcSettings,
    dem: dict[str, LimitStateDemand],
) -> tuple[MechanismResult, ...]:
    """Every mechanism of the catalogue, the governing one first."""
    out = [analyse_mechanism(mech, settings, dem) for mech in mechanisms]
    return tuple(sorted(out, key=governing_order))
