"""The code check of every mechanism of a wall, and the governing one.

Composition only: the geometry of each mechanism comes from rockcli.mechanisms.catalogue, its
capacity from rockcli.codecheck.kinematic, its checks from the edition's rules through
:func:`rockcli.studies.capacity_check.analyse_capacity` — the very path of today's block. A storey
mechanism stands in the building at the height of its hinge (Z + hinge height: ψ and the floor
spectra there). The governing mechanism is the one with the lowest ULS ζ_E (capacity over
demand of the deciding checks), then the lowest DLS ζ_E, then the lowest α0
(Circolare 7/2019 §C8.7.1: the assessment takes the most vulnerable mechanism).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from rockcli.codecheck.demand import LimitStateDemand
from rockcli.codecheck.free import (
    KAPPA_CANTILEVER,
    KAPPA_FLEXURE,
    MASONRY_TYPES,
    elastic_period,
)
from rockcli.codecheck.kinematic import Capacity, Mechanism, alpha0, capacity
from rockcli.codecheck.position import Position, position
from rockcli.codecheck.result import KinematicResult, deciding
from rockcli.errors import InputError
from rockcli.mechanisms.catalogue import (
    CrushingError,
    build,
    flexure_range,
    hinge_of,
    optimal_hinge,
    overburden_above,
    sides_of,
    storey_at,
)
from rockcli.mechanisms.wall import OPTIMAL, MechanismSpec, MechanismType, Wall
from rockcli.model.derive_ntc import NtcSettings
from rockcli.notes import Note
from rockcli.studies.capacity_check import analyse_capacity


def named(items, name: str, where: str = "--mechanism", problem: str = "no such mechanism"):
    """The item of ``items`` (mechanisms, specs, results: anything with a ``name``) called
    ``name``; InputError naming ``where`` and every name there is otherwise."""
    for item in items:
        if item.name == name:
            return item
    raise InputError(
        problem,
        where=where,
        value=name,
        allowed="one of: " + "; ".join(f"'{item.name}'" for item in items),
    )


def main_mechanism(kin: KinematicResult, name: str | None = None) -> MechanismResult | None:
    """The mechanism a wall's comparison shows in full: the one named, else the governing one;
    None for a model of one block (or a wall with one mechanism, and no name)."""
    if name is not None:
        return named_result(kin, name)
    if len(kin.catalogue) < 2:
        return None
    return kin.catalogue[0]


def named_result(kin: KinematicResult, name: str) -> MechanismResult:
    """The catalogue's entry of that name (InputError naming the catalogue's names)."""
    return named(kin.catalogue, name)


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
    """

    name: str
    type: str
    hinge_height: float
    storey: int | None
    M_star: float
    result: KinematicResult

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
    """The code check's view of one mechanism on one side."""
    try:
        geometry = build(wall, spec, side)
    except CrushingError as exc:
        raise InputError(
            f"the wall crushes before it rocks: at a hinge of '{exc.hinge}' the stress block "
            f"is {exc.depth:.3g} m deep, the section {exc.thickness:.3g} m",
            where="masonry.f_m",
            value=wall.f_m,
            allowed="a strength at which the weight above each hinge needs a stress block "
            "thinner than the wall (a = N/(f_m·width))",
        ) from None
    return Mechanism(
        side=side,
        distributed=settings.distributed,
        geometry=geometry,
        per_block=settings.edition == "2019",
    )


def resolved(wall: Wall, spec: MechanismSpec, sides: tuple[int, ...], settings: NtcSettings):
    """The spec with an optimal flexure hinge found: the height that minimises the smaller
    α0 of its sides (rockcli.mechanisms.catalogue.optimal_hinge)."""
    if spec.type is not MechanismType.VERTICAL_FLEXURE or spec.hinge_height != OPTIMAL:
        return spec, ()
    assert spec.storey is not None
    lo, hi = flexure_range(wall, spec.storey)

    def smallest(z: float) -> float:
        return min(
            alpha0(mechanism_of(wall, replace(spec, hinge_height=z), s, settings)) for s in sides
        )

    z = optimal_hinge(lo, hi, smallest)
    found = ("optimal hinge at {z:.3f} m (the lowest α0 between {lo:.3f} and {hi:.3f} m: the "
             "storey less max(thickness, a tenth of its height) at each end)")  # fmt: skip
    values = {"z": z, "lo": lo, "hi": hi}
    if min(z - lo, hi - z) <= RANGE_END * (hi - lo):
        note = Note("hinge_at_end", found + "; the optimum lies at the end of the range, which "
                    "decides it (α0 keeps falling towards it): give hinge_height where a crack "
                    "shows the hinge", **values)  # fmt: skip
    else:
        note = Note("hinge_optimal", found, **values)
    return replace(spec, hinge_height=z), (note,)


#: An optimal hinge this close to an end of its range (a share of the range) is at the end.
RANGE_END = 1e-6


def spec_position(wall: Wall, spec: MechanismSpec, settings: NtcSettings) -> Position:
    """Where the mechanism stands: Z + the height of its base hinge (a vertical flexure: the
    middle of its storey, :func:`spec_base`); without the building's H, H = Z + the wall's
    height, N its storeys."""
    b = settings.building
    base = spec_base(wall, spec)
    Z = b.Z + base
    if base == 0.0:
        return position(b.Z, b.H, b.N, b.T1, b.gamma, b.psi, b.damping)
    H = b.H if b.H is not None else b.Z + wall.height
    # The wall's storeys stand for the building's only when the wall is the building (H
    # taken from it); a building's H without N keeps the block's default, γ of N = 1.
    N = b.N if b.N is not None else (len(wall.storeys) if b.H is None else None)
    if Z > H * (1.0 + 1e-9):
        raise InputError(
            f"below the base of mechanism '{spec.name}' (Z + its hinge = {Z:g} m): ψ = Z/H "
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


def spec_base(wall: Wall, spec: MechanismSpec) -> float:
    """The height above the wall's base at which the mechanism stands in the building [m].

    Circolare 617/2009 §C8A.4.2.2 defines Z as "l'altezza, rispetto alla fondazione
    dell'edificio, del baricentro delle linee di vincolo tra i blocchi interessati dal
    meccanismo ed il resto della struttura": a rigid mechanism's one line, its base hinge; a
    vertical flexure's two, its storey's base and its held top, whose centroid is the middle
    of the storey. Circolare 7/2019 names only "la quota z a cui si colloca il meccanismo"
    (§C8.7.1.2.1.5) and is read the same way (docs/interpretations.md).
    """
    if spec.type is MechanismType.VERTICAL_FLEXURE:
        assert spec.storey is not None
        storey = wall.storeys[spec.storey - 1]
        return wall.storey_bases()[spec.storey - 1] + 0.5 * storey.height
    return hinge_of(spec, wall)


def free_period(
    wall: Wall, spec: MechanismSpec, settings: NtcSettings
) -> tuple[float | None, tuple[str, ...]]:
    """(T0 [s], notes) of a mechanism free to vibrate (None: rigid until activation).

    Circolare 7/2019 Eq. C8.7.1.7, T0 = κ·λ·L·√(W/(E·g)) with λ = L/t: the gable, a
    cantilever of its height on the last storey's thickness (κ = 6.2); an overturning, a
    cantilever of the wall above its hinge, gable included, on the hinge section's thickness
    (κ = 6.2); a vertical flexure, a beam of its storey's height and thickness simply
    supported at its ends (κ = 2.2). The 2009 edition has no elastic branch: a note says the
    declaration is not used.
    """
    if not spec.free:
        return None, ()
    if settings.edition != "2019":
        return None, (Note("free_2009", "free to vibrate: the elastic branch is a rule of "
                           "Circ. 7/2019 (§C8.7.1.2.1.3); the 2009 check is rigid until "
                           "activation"),)  # fmt: skip
    if wall.E is None:
        default = " (a gable is free by default)" if spec.type is MechanismType.GABLE else ""
        raise InputError(
            f"mechanism '{spec.name}' is free to vibrate{default}: its period T0 needs the "
            "masonry's Young's modulus (Circolare 7/2019 Eq. C8.7.1.7)",
            where="masonry",
            allowed="[masonry] E [Pa], or [masonry] type (one of "
            + ", ".join(MASONRY_TYPES)
            + "); or free = false on the mechanism",
        )
    kappa, length, thickness = free_member(wall, spec)
    T0 = elastic_period(kappa, length, thickness, wall.unit_weight, wall.E, wall.g)
    note = Note(
        "free_T0", "free to vibrate: elastic branch a = 4π²d/T0² to (a_y, d_y) "
        "[C8.7.1.6], T0 = κ·λ·L·√(W/(E·g)) = {T0:.4f} s [C8.7.1.7] with κ = {kappa:g}, "
        "L = {length:.3f} m, λ = L/t = {slender:.3g}, E = {E:g} MPa; SLD at S_e(T0) "
        "[C8.7.1.9]", T0=T0, kappa=kappa, length=length, slender=length / thickness,
        E=wall.E / 1e6,
    )  # fmt: skip
    return T0, (note,)


def free_member(wall: Wall, spec: MechanismSpec) -> tuple[float, float, float]:
    """(κ, L [m], t [m]) of a mechanism free to vibrate (:func:`free_period`)."""
    gable = wall.gable_height or 0.0
    if spec.type is MechanismType.GABLE:
        return KAPPA_CANTILEVER, gable, wall.storeys[-1].thickness
    if spec.type is MechanismType.VERTICAL_FLEXURE:
        assert spec.storey is not None
        storey = wall.storeys[spec.storey - 1]
        return KAPPA_FLEXURE, storey.height, storey.thickness
    hinge = hinge_of(spec, wall)
    k = storey_at(wall, hinge)
    return KAPPA_CANTILEVER, wall.height - hinge + gable, wall.storeys[k].thickness


def flexure_notes(wall: Wall, spec: MechanismSpec) -> tuple[str, ...]:
    """What a vertical flexure carries from above, in a sentence (none for other types)."""
    if spec.type is not MechanismType.VERTICAL_FLEXURE or spec.storey is None:
        return ()
    weight, x = overburden_above(wall, spec.storey)
    if weight <= 0.0:
        return (Note("flexure_nothing_above", "vertical flexure: nothing above the storey's top "
                     "but the loads at it"),)  # fmt: skip
    return (Note("flexure_above", "vertical flexure: the wall above (storeys, gable, bearing "
                 "loads) bears on the held top, {weight:.4g} kN at {x:.3f} m from the outer "
                 "face, without horizontal inertia", weight=weight / 1e3, x=x),)  # fmt: skip


def refuse_unstable(spec: MechanismSpec, cap: Capacity) -> None:
    """InputError when the thrusts open the mechanism with no earthquake (α0 ≤ 0), as for
    the block (rockcli.model.derived_checks): no code check describes a wall already falling."""
    if cap.alpha0 > 0.0:
        return
    side = "outward (side 1)" if cap.mech.side > 0 else "inward (side −1)"
    raise InputError(
        f"the thrusts open mechanism '{spec.name}' {side} with no earthquake "
        f"(α0 = {cap.alpha0:.4g})",
        where="thrusts",
        allowed="thrusts whose work is less than that of the weights (α0 > 0 on each side "
        "each mechanism can open to)",
    )


def analyse_mechanism(
    wall: Wall,
    spec: MechanismSpec,
    settings: NtcSettings,
    dem: dict[str, LimitStateDemand],
    free_side: int | None,
) -> MechanismResult:
    """One mechanism: each side it opens to, the governing side (the smaller d0*, as for the
    block), its checks at its position."""

    sides = sides_of(spec, free_side)
    spec, notes = resolved(wall, spec, sides, settings)
    T0, free_notes = free_period(wall, spec, settings)
    caps: list[Capacity] = [capacity(mechanism_of(wall, spec, s, settings), settings.FC, T0)
                            for s in sides]  # fmt: skip
    for c in caps:
        refuse_unstable(spec, c)
    cap = min(caps, key=lambda c: (c.d0_star is None, c.d0_star or 0.0, -c.mech.side))
    by_side = {str(c.mech.side): c.alpha0 for c in caps}
    notes = (*notes, *flexure_notes(wall, spec), *free_notes)
    if wall.f_m is not None:
        set_back = Note("set_back", "hinges set back by half the stress block a = N/(f_m·width), "
                        "f_m = {f_m:g} MPa", f_m=wall.f_m / 1e6)  # fmt: skip
        notes = (*notes, set_back)
    result = analyse_capacity(cap, settings, dem, spec_position(wall, spec, settings),
                              by_side, notes)  # fmt: skip
    from rockcli.codecheck.kinematic import participating_mass

    hinge = spec.hinge_height if isinstance(spec.hinge_height, float) else hinge_of(spec, wall)
    return MechanismResult(spec.name, spec.type.value, hinge, spec.storey,
                           participating_mass(cap.mech),
                           replace(result, mechanism=spec.name))  # fmt: skip


def analyse_wall(
    wall: Wall, settings: NtcSettings, dem: dict[str, LimitStateDemand], free_side: int | None
) -> tuple[MechanismResult, ...]:
    """Every mechanism of the wall, the governing one first."""
    out = [analyse_mechanism(wall, spec, settings, dem, free_side) for spec in wall.mechanisms]
    return tuple(sorted(out, key=governing_order))
