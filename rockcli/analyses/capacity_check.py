"""The code check of one mechanism's capacity at its position, under the limit states'
demands: the checks of the settings' edition, the restrainers' actions and the demand's
numbers as the result reports them.

Shared by the block's workflow (rockcli.analyses.kinematic) and a wall's catalogue
(rockcli.analyses.catalogue), which both build a Capacity and hand it here: one road from a
capacity to a KinematicResult. Composition only: the formulas live in rockcli.codecheck.
"""

from __future__ import annotations

from typing import Any

from rockcli.codecheck import rules2009, rules2019
from rockcli.codecheck.demand import LimitStateDemand
from rockcli.codecheck.kinematic import Capacity, CapacityCurve
from rockcli.codecheck.position import Position
from rockcli.codecheck.restrainer_check import nonlinear_displacement_demand, restrainer_actions
from rockcli.codecheck.result import Check, KinematicResult, Location
from rockcli.model.derive_ntc import NtcSettings
from rockcli.notes import Items, Note


def demand_numbers(demand: LimitStateDemand) -> dict[str, object]:
    """The numbers of one limit state's demand, read from the spectrum the checks use.

    A code spectrum (NTC 2018 §3.2.3.2.1): TR [years] (None when the model gives the
    parameters), ag [g], F0, Tc* [s], SS, ST, S, TB, TC, TD [s]. A record: its name and PGA [g].
    Both with the `source` they come from.
    """
    from rockcli.codecheck.spectra import ElasticSpectrum

    spectrum = demand.spectrum
    if demand.record is not None or not isinstance(spectrum, ElasticSpectrum):
        return {"record": demand.record, "PGA": float(demand.ag), "source": demand.source}
    return {
        "TR": None if demand.TR is None else float(demand.TR),
        "ag": float(spectrum.ag),
        "F0": float(spectrum.F0),
        "Tc_star": float(spectrum.Tc_star),
        "SS": float(spectrum.S_S),
        "ST": float(spectrum.S_T),
        "S": float(spectrum.S),
        "TB": float(spectrum.TB),
        "TC": float(spectrum.TC),
        "TD": float(spectrum.TD),
        "source": demand.source,
    }


#: The periods each limit state's checks read a record's spectrum at, beyond T1 at height, by
#: the name of the quantity, with the damping [%] they read it at: Ts of the 2009 non-linear
#: (ULS = SLV) check at 5 %, the secant periods of 2019's SLV (8 %) and SLC (10 %) checks
#: (Circolare 7/2019 §C8.7.1.2.1.8); SLD's checks read accelerations only.
CHECK_PERIODS = {"SLD": (), "SLV": (("Ts", 5.0), ("T_SLV", 8.0)), "SLC": (("T_SLC", 10.0),)}


#: The names the 2009 checks give the limit states of the demand (Circolare 617/2009: DLS, ULS).
EDITION_2009_NAMES = {"SLD": "DLS", "SLV": "ULS"}


def with_spectral_values(
    numbers: dict[str, object],
    demand: LimitStateDemand,
    pos: Position,
    values: dict[str, float | None],
    limit_state: str,
    checks: tuple[Check, ...] | list[Check] = (),
) -> dict[str, object]:
    """The demand with its ground spectrum's values where the limit state's checks read it:
    Se [g] and SDe [m] at the damping the check uses. At height, at the building's T1 (its
    damping), where the floor spectrum the checks at height read is made from the ground's
    (their own values there are each check's ``demand_spectral``), for a record and a code
    spectrum alike; where the limit state has a check at the ground (every check on the
    ground; 2009's ground check of an element at height), a record's or, at height, the code
    spectrum's at the mechanism's periods (CHECK_PERIODS) and, where a check took the maximum
    over a range of periods (2019), at the period of that maximum. A code spectrum on the
    ground: none (its values are the checks' own)."""
    if demand.record is None and not pos.at_height:
        return numbers
    building = 100.0 * pos.damping
    periods: list[tuple[Any, float | None, float]] = (
        [("T1", pos.T1, building)] if pos.at_height else []
    )
    states = (limit_state, EDITION_2009_NAMES.get(limit_state))
    if any(c.limit_state in states and c.location is Location.GROUND for c in checks):
        periods += [(name, values.get(name), xi)
                    for name, xi in CHECK_PERIODS.get(limit_state, ())]  # fmt: skip
    periods += [
        (Note("max_over", "max over [{lo:g}, {hi:.4g}] s", lo=float(c.spectral.period_range[0]),
              hi=float(c.spectral.period_range[1])), c.spectral.period, c.spectral.damping)
        for c in checks
        if c.limit_state == limit_state and c.spectral and c.spectral.period_range
        and c.location is Location.GROUND
    ]  # fmt: skip
    spectrum = demand.spectrum
    numbers["spectral_values"] = [
        {"at": name, "T": T, "damping": xi, "Se": spectrum.Se(T, xi), "SDe": spectrum.SDe(T, xi)}
        for name, T, xi in periods
        if T is not None and T > 0
    ]
    return numbers


def analyse_capacity(
    cap: Capacity,
    settings: NtcSettings,
    dem: dict[str, LimitStateDemand],
    pos: Position,
    alpha0_by_side: dict[str, float],
    extra_notes: tuple[str, ...] = (),
    activation_by_side: dict[str, dict[str, float]] | None = None,
) -> KinematicResult:
    """The checks of the settings' edition on one mechanism's capacity at its position."""
    notes = [*pos.notes, *extra_notes]
    if getattr(settings.FC_rule, "key", None) == "fc_lc1":
        notes.append(settings.FC_rule)
    if settings.defaults:
        notes.append(Note("defaults", "defaults (not in the model's [ntc]): {settings}",
                          settings=Items(settings.defaults)))  # fmt: skip
    notes.append(
        Note("capacity_linear", "capacity curve: linear a0*(1 − d*/d0*), constant forces "
             "(Circ. 617/2009 §C8A.4.2.3; Circ. 7/2019 §C8.7.1.2)")
        if cap.linear
        else Note("capacity_curve", "capacity curve: α(θ) with the restrainers that cannot "
                  "fail (an interpretation of rock's: the code's linear curve does not hold "
                  "for restrainers)")
    )  # fmt: skip
    if cap.d0_star is None:
        notes.append(Note("no_d0", "positive global stiffness: α never vanishes, no d0*"))
    notes += [
        Note(
            "tie_slack",
            "{name}: a tie-rod only pulls, so it adds nothing when the mechanism "
            "opens inward (side −1: α0 and the curve without it); the time history keeps its "
            "spring on both sides",
            name=sp.name,
        )  # fmt: skip
        for sp in cap.mech.restrainers
        if sp.slack_side
    ]
    if settings.edition == "2009":
        values, checks = rules2009.check_2009(
            cap, dem["SLD"], dem["SLV"], pos, settings.q, local_limit(cap, settings)
        )
    else:
        values, checks, extra = rules2019.check_2019(
            cap, dem, pos, settings.q, local_limit(cap, settings)
        )
        notes += extra
        if not cap.free:
            notes.append(Note("rigid", "rigid until activation: not declared free to vibrate "
                              "(the elastic branch of Circ. 7/2019 §C8.7.1.2.1.3, Eqs. "
                              "C8.7.1.6–7, is for elements free to vibrate: [[mechanisms]] "
                              "free = true)"))  # fmt: skip
    actions = restrainer_actions(cap, *governing_demand(settings.edition, values, checks))
    return KinematicResult(
        edition=settings.edition,
        side=cap.mech.side,
        alpha0=cap.alpha0,
        e_star=cap.e_star,
        a0_star=cap.a0_star,
        FC=cap.FC,
        d0_star=cap.d0_star,
        linear_curve=cap.linear,
        quantities=values,
        checks=tuple(checks),
        curve=CapacityCurve(cap),
        demand={
            ls: with_spectral_values(demand_numbers(d), d, pos, values, ls, checks)
            for ls, d in dem.items()
        },
        notes=tuple(notes),
        alpha0_by_side=alpha0_by_side,
        restrainer_actions=actions,
        FC_rule=str(settings.FC_rule),
        position=pos,
        activation_by_side=activation_by_side or {},
    )


def governing_demand(
    edition: str, values: dict[str, float | None], checks: list[Check]
) -> tuple[float | None, str]:
    """(d* [m], what it is) at which a spring's force is verified against its strength.

    The displacement demand of the non-linear SLV check when it is computed (2009: the largest
    of SDe(Ts) and the demand at height; 2019: the SLV spectrum's at T_SLV), else the ultimate
    displacement (du*; d_SLV), else none (positive stiffness and no limit: the check reaches no
    displacement, so a spring's force there is not evaluated).
    """
    if edition == "2009":
        demand = nonlinear_displacement_demand(checks)
        ultimate, name = values.get("du_star"), "du*"
    else:
        demand = rules2019.slv_displacement_demand(checks)
        ultimate, name = values.get("d_SLV"), "d_SLV"
    if demand is not None:
        return demand, f"SLV displacement demand d* = {demand:.4g} m"
    if ultimate is not None:
        return ultimate, f"{name} = {ultimate:.4g} m"
    return None, f"the check reaches no displacement (no {name})"


def local_limit(cap: Capacity, settings: NtcSettings) -> float | None:
    """The local ultimate displacement as a spectral displacement d* [m]."""
    return None if settings.limit is None else settings.limit * cap.factor
