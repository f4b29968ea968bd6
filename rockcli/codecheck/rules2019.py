"""The 2019 rules: NTC 2018 + Circolare 7/2019 §C8.7.1 (in force).

Every check is turned into the ground acceleration that brings the demand to the capacity
(ag,SLD, ag,SLV, ag,SLC), compared with the code's ag of the limit state (or the record's
PGA); ζ_E = capacity/demand. At height the demand is the floor spectrum of §C7.2.3
(C7.2.5–C7.2.10 in spec/ntc.md). spec/ntc.md, "2019 rules".
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import TypeVar

import numpy as np

from rockcli.codecheck import spectra
from rockcli.codecheck.demand import (
    RANGE_STEP,
    LimitStateDemand,
    Spectrum,
    bound_note,
    capacity_ag,
    grid_SDe,
    range_maximum,
)
from rockcli.codecheck.kinematic import FAILURE_DROP, Capacity, failure_rotations
from rockcli.codecheck.position import Position
from rockcli.codecheck.result import Check, Location, Method, SpectralDemand
from rockcli.notes import Note

#: A period [s] or an array of them (the floor spectrum's formulas take either).
Periods = TypeVar("Periods", float, np.ndarray)

CLAUSE = "§C8.7.1.2.1"
#: The clause of the displacement demand of a record or a site response: the maximum of the
#: spectral displacement over [T0, T_SLV] (and [T0, T_SLC]).
CLAUSE_RANGE = "§C8.7.1.2.1.8"
#: T0 of a mechanism rigid until activation (no elastic branch, C8.7.1.6–7 not modelled): its
#: initial stiffness is infinite, its period zero; the range searched is [0, T_SLV]
#: (docs/interpretations.md).
T0_RIGID = 0.0
#: The secant periods' formulas as the Circolare writes them (C8.7.1.10, C8.7.1.11).
PERIOD_FORMULA = {
    "SLV": "T_SLV = 1.68π·√(d_SLV/a(d_SLV)) [C8.7.1.10]",
    "SLC": "T_SLC = 1.56π·√(d_SLC/a(d_SLC)) [C8.7.1.11]",
}
CLAUSE_FLOOR = "§C7.2.3"
#: d_SLV = 0.4·d0 and d_SLC = 0.6·d0 (§C8.7.1.2.1).
SLV_SHARE, SLC_SHARE = 0.4, 0.6
#: T_SLV = 1.68π √(d/a), T_SLC = 1.56π √(d/a) (§C8.7.1.2.1).
SLV_PERIOD, SLC_PERIOD = 1.68 * math.pi, 1.56 * math.pi
#: Damping of the mechanism in the demand spectrum [%] (§C8.7.1.2.1): 5 (SLD), 8 (SLV), 10 (SLC).
DAMPING = {"SLD": 5.0, "SLV": 8.0, "SLC": 10.0}
#: Damping of the building's mode in the floor spectrum [%] (§C7.2.3: ξ_k, 5 % unless given;
#: the model's `building.damping` when given, the one the floor motion uses too).
BUILDING_DAMPING = 5.0
#: Plateau limits of the floor spectrum, a·T_k ≤ T < b·T_k (§C7.2.3).
PLATEAU_A, PLATEAU_B = 0.8, 1.1
#: Reading adopted for ξ_k (spec/ntc.md, "Ambiguity"): a fraction in 1.1·ξ_k^−0.5, a
#: percentage in √(1 + 0.0004·ξ_k²).
FLOOR_READING = Note(
    "floor_reading",
    "floor spectrum: ξ_k as a fraction (0.05) in 1.1·ξ_k^−0.5 (plateau factor 4.92 at 5 %) and "
    "in percent (5) in √(1 + 0.0004·ξ_k²); the text says percent for both, which would give a "
    "plateau factor of 0.49, not the amplification the clause intends",
)


def floor_acceleration(spec: Spectrum, pos: Position) -> float:
    """a_Z = Se(T1, ξ_k)·|γ ψ(Z)|·√(1 + 0.0004 ξ_k²) [g], ξ_k in percent (§C7.2.3)."""
    assert pos.T1 is not None
    xi_k = 100.0 * pos.damping
    return spec.Se(pos.T1, xi_k) * abs(pos.gamma * pos.psi) * math.sqrt(1.0 + 0.0004 * xi_k**2)


def floor_plateau(xi_mechanism: float, xi_building: float = BUILDING_DAMPING) -> float:
    """1.1·ξ_k^−0.5·η(ξ) [-], ξ_k [%] read as a fraction, η of the mechanism's damping ξ [%]
    (§C7.2.3)."""
    return 1.1 * (xi_building / 100.0) ** -0.5 * spectra.damping_correction(xi_mechanism)


def floor_spectrum(
    T: Periods, a_z: float, T1: float, xi_mechanism: float, xi_building: float = BUILDING_DAMPING
) -> Periods:
    """S_eZ(T) [g]: the floor spectrum at height for a mechanism of period T (§C7.2.3); T a
    period or an array of them [s].

    a_z·A on the plateau a·T1 ≤ T < b·T1 (A = floor_plateau), a_z·A/{1 + (A − 1)(1 − T/(a T1))^1.6}
    below it, a_z·A/{1 + (A − 1)(T/(b T1) − 1)^1.2} above it: one expression, each branch's
    term zero outside it.
    """
    amp = floor_plateau(xi_mechanism, xi_building)
    below = _positive_part(1.0 - T / (PLATEAU_A * T1)) ** 1.6
    above = _positive_part(T / (PLATEAU_B * T1) - 1.0) ** 1.2
    return a_z * amp / (1.0 + (amp - 1.0) * (below + above))


def _positive_part(x: Periods) -> Periods:
    """max(x, 0) of a number or of each element of an array."""
    return np.maximum(x, 0.0) if isinstance(x, np.ndarray) else max(x, 0.0)


def _bounded_above(T: Periods, limit: float, value: Periods, bound: Periods) -> Periods:
    """``value``, not below ``bound`` where T > limit (T a period or an array of them)."""
    if isinstance(T, np.ndarray):
        return np.where(T > limit, np.maximum(value, bound), value)
    return max(value, bound) if T > limit else value


def bounded_floor_spectrum(spec: Spectrum, T: float, pos: Position, xi_mechanism: float) -> float:
    """S_eZ(T, ξ, z) [g] of the ground spectrum ``spec`` at the position: the floor spectrum
    of the first mode, not below the ground spectrum S_e(T, ξ) for T > T1.

    Circolare 7/2019 §C7.2.3, Eq. C7.2.5: "S_eZ(T, ξ, z) = √(Σ S_eZ,k²) (≥ S_e(T, ξ) per
    T > T1)": the floor spectrum at height may not fall below the ground spectrum beyond the
    building's first period, with the mechanism's damping ξ. A record's floor spectrum is
    bounded by the record's own response spectrum likewise (``spec`` is the demand's spectrum
    either way).
    """
    assert pos.T1 is not None
    value = floor_spectrum(
        T, floor_acceleration(spec, pos), pos.T1, xi_mechanism, 100.0 * pos.damping
    )
    return max(value, spec.Se(T, xi_mechanism)) if T > pos.T1 else value


def floor_displacement(
    T: Periods,
    a_z: float,
    T1: float,
    xi_mechanism: float,
    g: float,
    xi_building: float = BUILDING_DAMPING,
) -> Periods:
    """S_eZ(T)·T²/4π² [m] of the first mode's floor spectrum, not less than
    S_eZ(T1)·(b T1)²/4π² for T > b·T1 (§C8.7.1.2.1; the ground bound of Eq. C7.2.5 is
    :func:`bounded_floor_displacement`'s); T a period or an array of them [s]."""
    d = floor_spectrum(T, a_z, T1, xi_mechanism, xi_building) * g * T**2 / (4.0 * math.pi**2)
    floor = (
        floor_spectrum(T1, a_z, T1, xi_mechanism, xi_building)
        * g
        * (PLATEAU_B * T1) ** 2
        / (4.0 * math.pi**2)
    )
    return _bounded_above(T, PLATEAU_B * T1, d, floor)


def limit_displacements(
    cap: Capacity, limit: float | None
) -> tuple[float | None, float | None, str]:
    """(d_SLV, d_SLC, note): 0.4·d0 and 0.6·d0 capped by a restrainer failure that removes more
    than half the capacity (d_SLV) and by the given local limit (both) [m] (§C8.7.1.2.1)."""
    note: str = ""
    slv = [] if cap.d0_star is None else [SLV_SHARE * cap.d0_star]
    slc = [] if cap.d0_star is None else [SLC_SHARE * cap.d0_star]
    for name, theta_f, drop in failure_rotations(cap.mech):
        if drop > FAILURE_DROP:
            slv.append(cap.d_star_at(theta_f))
            note = Note("slv_capped", "d_SLV capped by the failure of {name} ({drop:.0f} % "
                        "capacity drop)", name=name, drop=100 * drop)  # fmt: skip
    if limit is not None:
        slv.append(limit)
        slc.append(limit)
    return (min(slv) if slv else None, min(slc) if slc else None, note)


def _period(
    share_period: float, d: float | None, cap: Capacity
) -> tuple[float | None, float | None]:
    if d is None:
        return None, None
    a = cap.a_star(d)
    return a, (share_period * math.sqrt(d / a) if a > 0 else None)


#: The damping of the SLD check of an element free to vibrate [%] (§C8.7.1.2.1.5: "per uno
#: smorzamento ξ = 5%").
FREE_DAMPING = 5.0
CLAUSE_FREE = "§C8.7.1.2.1.5"


def sld_check(cap: Capacity, sld: LimitStateDemand, pos: Position, g: float) -> Check:
    """ag,SLD: the ag at which the acceleration demand reaches a0* (rigid until activation).

    Ground: ag·S = a0*/g; at height: a_Z = a0*/g (S_eZ at T = 0 is a_Z). §C8.7.1.2.1 (C8.7.1.8).
    An element free to vibrate: :func:`free_sld_check`.
    """
    if cap.free:
        return free_sld_check(cap, sld, pos, g)
    if pos.at_height:
        ag = capacity_ag(sld, lambda sp: floor_acceleration(sp, pos) * g, cap.a0_star)
        where, note = Location.HEIGHT, "capacity: a_Z(ag) = a0*, floor spectrum at T = 0"
    else:
        ag = capacity_ag(sld, lambda sp: sp.pga_ground * g, cap.a0_star)
        where, note = Location.GROUND, "capacity: ag·S(ag) = a0*"
    return Check("SLD", Method.LINEAR, where, sld.ag, ag, "g", CLAUSE, note + bound_note(ag))


def free_sld_check(cap: Capacity, sld: LimitStateDemand, pos: Position, g: float) -> Check:
    """ag,SLD of an element free to vibrate: the ag at which the 5 %-damped spectrum at its
    period T0 reaches a_y, the end of its elastic branch (Circolare 7/2019 §C8.7.1.2.1.5,
    Eq. C8.7.1.9: S_eZ,SLD(T0) = a_y/FC ≃ α0·g/(e*·FC); a_y is read on the curve of
    Eq. C8.7.1.3, which carries FC once). At height the floor spectrum not below the ground's
    for T0 > T1 (Eq. C7.2.5); on the ground S_e(T0).
    """
    assert cap.T0 is not None and cap.a_y is not None
    T0, xi = cap.T0, FREE_DAMPING
    if pos.at_height:

        def accel(sp: Spectrum) -> float:
            return bounded_floor_spectrum(sp, T0, pos, xi) * g

        where, rule = Location.HEIGHT, f"S_eZ(T0, {xi:g} %) of the floor spectrum [C8.7.1.9]"
    else:

        def accel(sp: Spectrum) -> float:
            return sp.Se(T0, xi) * g

        where, rule = Location.GROUND, f"S_e(T0, {xi:g} %) [C8.7.1.9]"
    ag = capacity_ag(sld, accel, cap.a_y)
    at_own = accel(sld.spectrum)
    spectral = SpectralDemand(xi, T0, at_own * (T0 / (2.0 * math.pi)) ** 2, None,
                              f"{rule}: {at_own / g:.5g} g at T0", None)  # fmt: skip
    note = (f"free to vibrate: capacity {rule} = a_y = {cap.a_y:.5g} m/s², T0 = {T0:.4f} s"
            + bound_note(ag))  # fmt: skip
    return Check("SLD", Method.LINEAR, where, sld.ag, ag, "g", CLAUSE_FREE, note, spectral)


def slv_linear_check(
    sld_cap: float | None, slv: LimitStateDemand, q: float, where: Location
) -> Check:
    """ag,SLV = q·ag,SLD (§C8.7.1.2.1, linear analysis)."""
    cap = None if sld_cap is None else q * sld_cap
    return Check(
        "SLV", Method.LINEAR, where, slv.ag, cap, "g", CLAUSE, f"capacity q·ag,SLD, q = {q:g}"
    )


def displacement_measure(
    T: float, xi: float, pos: Position, g: float
) -> Callable[[Spectrum], float]:
    """The displacement demand [m] a spectrum gives the mechanism of secant period T [s] and
    damping ξ [%]: SDe(T, ξ) at the ground, S_eZ(T)·T²/4π² at height, not below the ground's
    SDe(T, ξ) for T > T1 (§C8.7.1.2.1; §C7.2.3, Eq. C7.2.5)."""
    if not pos.at_height:
        return lambda sp: sp.SDe(T, xi)
    return lambda sp: bounded_floor_displacement(sp, T, pos, xi, g)


def bounded_floor_displacement(
    spec: Spectrum, T: float, pos: Position, xi_mechanism: float, g: float
) -> float:
    """The displacement demand at height [m]: :func:`floor_displacement` of the first mode,
    not below the ground spectrum's SDe(T, ξ) for T > T1 (Circolare 7/2019 §C7.2.3,
    Eq. C7.2.5, the bound of :func:`bounded_floor_spectrum` read as a displacement,
    SDe = S_e·T²/4π² on the branches the secant periods reach)."""
    return bounded_floor_displacements(T, spec.SDe(T, xi_mechanism), spec, pos, xi_mechanism, g)


def bounded_floor_displacements(
    T: Periods, ground: Periods, spec: Spectrum, pos: Position, xi_mechanism: float, g: float
) -> Periods:
    """:func:`bounded_floor_displacement` at a period or an array of them, given the ground
    spectrum's SDe(T, ξ) there (``ground``)."""
    assert pos.T1 is not None
    d = floor_displacement(
        T, floor_acceleration(spec, pos), pos.T1, xi_mechanism, g, 100.0 * pos.damping
    )
    return _bounded_above(T, pos.T1, d, ground)


def grid_displacements(
    first: int, last: int, xi: float, pos: Position, g: float, spec: Spectrum
) -> np.ndarray:
    """:func:`displacement_measure` at the periods k·RANGE_STEP, k = first … last, at once [m]
    (the grid of :func:`rockcli.codecheck.demand.range_maximum`)."""
    ground = grid_SDe(spec, first, last, xi)
    if not pos.at_height:
        return ground
    periods = np.arange(first, last + 1) * RANGE_STEP
    return bounded_floor_displacements(periods, ground, spec, pos, xi, g)


def spectral_demand(
    ls: str, T: float, dem: LimitStateDemand, pos: Position, g: float, t0: float = T0_RIGID
) -> SpectralDemand:
    """Where the displacement demand of limit state ``ls`` is read, and its value [m] at the
    limit state's own ag.

    A code spectrum: at the secant period T (Circolare 7/2019 §C8.7.1.2.1.8: "per i valori
    caratteristici del periodo corrispondenti ai due stati limite"; the code's displacement
    spectrum does not decrease with T there). A record or a suite's mean spectrum (also its
    floor spectrum at height): "il valore massimo dello spostamento spettrale valutato
    nell'intervallo di periodi [T0, T_SLV]" (§C8.7.1.2.1.8), T0 = ``t0``: the period of an
    element free to vibrate, T0_RIGID for one rigid until activation; the same for SLC.
    A record's spectrum scales linearly with ag, so the period of the maximum is the same at
    every ag and the capacity's root search reads the spectrum there.
    """
    xi = DAMPING[ls]

    def at(period: float) -> float:
        return displacement_measure(period, xi, pos, g)(dem.spectrum)

    def on_grid(first: int, last: int) -> np.ndarray:
        return grid_displacements(first, last, xi, pos, g, dem.spectrum)

    at_secant = at(T)
    name = f"T_{ls}"
    if dem.record is None:
        rule = f"SDe({name}) of the code spectrum ({CLAUSE_RANGE})"
        return SpectralDemand(xi, T, at_secant, None, rule, at_secant)
    lo = min(t0, T)
    T_max, value = range_maximum(at, lo, T, on_grid)
    rule = f"max Sd over [T0, {name}] = [{lo:.4g}, {T:.4g}] s ({CLAUSE_RANGE})"
    return SpectralDemand(xi, T_max, value, (lo, T), rule, at_secant)


def slv_displacement_demand(checks: list[Check] | tuple[Check, ...]) -> float | None:
    """The SLV displacement demand d* [m] at the site's ag (None: no T_SLV).

    The demand side of the SLV non-linear check (§C8.7.1.2.1), whose capacity is d_SLV, as
    that check read it (:func:`displacement_check`): at T_SLV, or the maximum over
    [T0, T_SLV] of a record's spectrum (:func:`spectral_demand`).
    """
    for c in checks:
        if c.limit_state == "SLV" and c.method is Method.NONLINEAR and c.spectral is not None:
            return c.spectral.value
    return None


def displacement_check(
    ls: str,
    d: float | None,
    T: float | None,
    dem: LimitStateDemand,
    pos: Position,
    g: float,
    sld_cap: float | None,
    t0: float = T0_RIGID,
) -> Check:
    """ag at which the displacement demand reaches d (root search), §C8.7.1.2.1.

    Ground: SDe(T, ξ); at height: S_eZ(T)·T²/4π² (floor spectrum); at the secant period T, or
    for a record at the period of the maximum over [T0, T] (:func:`spectral_demand`). If the
    capacity is below ag,SLD it is taken as ag,SLD.
    """
    where = Location.HEIGHT if pos.at_height else Location.GROUND
    if d is None or T is None:
        return Check(
            ls,
            Method.NONLINEAR,
            where,
            dem.ag,
            None,
            "g",
            CLAUSE,
            "no limit displacement: positive global stiffness and no limit given",
        )
    xi = DAMPING[ls]
    spectral = spectral_demand(ls, T, dem, pos, g, t0)
    measure = displacement_measure(spectral.period, xi, pos, g)
    ag = capacity_ag(dem, measure, d)
    note = f"{PERIOD_FORMULA[ls]} = {T:.4f} s, ξ = {xi:g} %, d = {d:.5f} m" + bound_note(ag)
    if spectral.period_range is not None:
        note += (
            f"; demand {spectral.rule}: {spectral.value:.5g} m at T = {spectral.period:.4g} s"
            f" (at {ls} period itself {spectral.at_secant:.5g} m)"
        )
    if ag is not None and sld_cap is not None and ag < sld_cap:
        ag, note = sld_cap, note + "; below ag,SLD: ag,SLD taken"
    return Check(ls, Method.NONLINEAR, where, dem.ag, ag, "g", CLAUSE, note, spectral)


def check_2019(
    cap: Capacity,
    demands: dict[str, LimitStateDemand],
    pos: Position,
    q: float,
    limit: float | None,
) -> tuple[dict[str, float | None], list[Check], list[str]]:
    """Every 2019 check: SLD, SLV linear, SLV and SLC non-linear."""
    g = cap.mech.g
    d_slv, d_slc, cap_note = limit_displacements(cap, limit)
    a_slv, T_slv = _period(SLV_PERIOD, d_slv, cap)
    a_slc, T_slc = _period(SLC_PERIOD, d_slc, cap)
    sld = sld_check(cap, demands["SLD"], pos, g)
    t0 = T0_RIGID if cap.T0 is None else cap.T0
    checks = [
        sld,
        slv_linear_check(sld.capacity, demands["SLV"], q, sld.location),
        displacement_check("SLV", d_slv, T_slv, demands["SLV"], pos, g, sld.capacity, t0),
        displacement_check("SLC", d_slc, T_slc, demands["SLC"], pos, g, sld.capacity, t0),
    ]
    values = {
        "d_SLV": d_slv,
        "a_SLV": a_slv,
        "T_SLV": T_slv,
        "d_SLC": d_slc,
        "a_SLC": a_slc,
        "T_SLC": T_slc,
        "ag_SLD": sld.capacity,
    }
    if cap.free:
        values.update({"T0": cap.T0, "d_y": cap.d_y, "a_y": cap.a_y})
    if pos.at_height:
        checks = [replace(c, note=f"{c.note}; ξ_k reading in the notes") for c in checks]
    notes = [n for n in (cap_note, FLOOR_READING if pos.at_height else "") if n]
    return values, checks, notes
