"""The 2009 rules: NTC 2008 + Circolare 617/2009 §C8A.4 (the paper's edition).

Linear kinematic analysis (acceleration checks, DLS and ULS, at the ground and at height) and
non-linear kinematic analysis (displacement check at ULS). spec/ntc.md, "2009 rules".
"""

from __future__ import annotations

import math

from rockcli.codecheck.demand import LimitStateDemand, Spectrum, range_maximum
from rockcli.codecheck.kinematic import Capacity, failure_rotations
from rockcli.codecheck.position import Position, height_amplification
from rockcli.codecheck.result import Check, Location, Method, SpectralDemand

ACC = "m/s²"
#: du* = 0.4·d0* and ds* = 0.4·du* (Circolare 617/2009 §C8A.4.2.3).
DU_SHARE = 0.4
DS_SHARE = 0.4
CLAUSE_SLD = "§C8A.4.2.1"
CLAUSE_SLV_LINEAR = "§C8A.4.2.2"
CLAUSE_SLV_NONLINEAR = "§C8A.4.2.3"
#: Damping of the 2009 displacement demand [%]: the 5 %-damped elastic spectrum (§C8A.4.2.3).
DAMPING = 5.0


def du_star(d0: float | None, limit: float | None, failures: list[float]) -> float | None:
    """Ultimate displacement du* = 0.4·d0*, or a smaller local limit if given [m].

    Circolare 617/2009 §C8A.4.2.3. With a positive global stiffness (no d0*) the first
    restrainer failure (its d*) or the designer's limit defines it (spec/ntc.md, "Common").
    """
    if d0 is not None:
        candidates = [DU_SHARE * d0] + ([limit] if limit is not None else [])
    else:
        candidates = failures + ([limit] if limit is not None else [])
    return min(candidates) if candidates else None


def secant_period(ds: float, as_: float) -> float:
    """Ts = 2π √(ds*/as*) [s] (Circolare 617/2009 §C8A.4.2.3)."""
    return 2.0 * math.pi * math.sqrt(ds / as_)


def quantities(cap: Capacity, limit: float | None) -> dict[str, float | None]:
    """du*, ds*, as*, Ts of the non-linear analysis (None where they do not exist)."""
    failures = [cap.d_star_at(theta) for _, theta, _ in failure_rotations(cap.mech)]
    du = du_star(cap.d0_star, limit, failures)
    if du is None:
        return {"du_star": None, "ds_star": None, "as_star": None, "Ts": None}
    ds = DS_SHARE * du
    as_ = cap.a_star(ds)
    Ts = secant_period(ds, as_) if as_ > 0 else None
    return {"du_star": du, "ds_star": ds, "as_star": as_, "Ts": Ts}


def linear_checks(
    cap: Capacity, dem: LimitStateDemand, pos: Position, g: float, q: float, ls: str
) -> list[Check]:
    """a0* against ag·S (and Se(T1)·ψ·γ at height), divided by q at ULS.

    Circolare 617/2009 §C8A.4.2.1 (DLS, q = 1) and §C8A.4.2.2 (ULS).
    """
    spec = dem.spectrum
    clause = CLAUSE_SLD if ls == "DLS" else CLAUSE_SLV_LINEAR
    div = 1.0 if ls == "DLS" else q
    out = [
        Check(
            ls,
            Method.LINEAR,
            Location.GROUND,
            spec.pga_ground * g / div,
            cap.a0_star,
            ACC,
            clause,
            "demand ag·S" + ("" if div == 1 else f"/q, q = {q:g}"),
        )
    ]
    if pos.at_height:
        assert pos.T1 is not None
        demand = spec.Se(pos.T1) * pos.psi * pos.gamma * g / div
        out.append(
            Check(
                ls,
                Method.LINEAR,
                Location.HEIGHT,
                demand,
                cap.a0_star,
                ACC,
                clause,
                f"demand Se(T1)·ψ·γ{'' if div == 1 else '/q'}, T1 = {pos.T1:.3f} s, "
                f"ψ = {pos.psi:.3f}, γ = {pos.gamma:.3f}",
            )
        )
    return out


def nonlinear_checks(
    values: dict[str, float | None], dem: LimitStateDemand, pos: Position
) -> list[Check]:
    """du* against SDe(Ts) (and the amplified SDe(T1) at height) (Circ. 617/2009 §C8A.4.2.3)."""
    du, Ts = values["du_star"], values["Ts"]
    spec = dem.spectrum
    if du is None or Ts is None:
        reason = (
            "no ultimate displacement: positive global stiffness and no limit given "
            "(ntc.ultimate_displacement or a restrainer's fails_at)"
        )
        return [
            Check(
                "ULS",
                Method.NONLINEAR,
                Location.GROUND,
                None,
                None,
                "m",
                CLAUSE_SLV_NONLINEAR,
                reason,
            )
        ]
    ground = ground_demand(Ts, dem)
    out = [
        Check(
            "ULS",
            Method.NONLINEAR,
            Location.GROUND,
            ground.value,
            du,
            "m",
            CLAUSE_SLV_NONLINEAR,
            f"demand SDe(Ts), Ts = 2π·√(ds*/as*) = {Ts:.4f} s, ξ = {DAMPING:g} %"
            + later_rule_note(Ts, dem),
            ground,
        )
    ]
    if pos.at_height:
        assert pos.T1 is not None
        demand = height_displacement(spec, pos, Ts)
        out.append(
            Check(
                "ULS",
                Method.NONLINEAR,
                Location.HEIGHT,
                demand,
                du,
                "m",
                CLAUSE_SLV_NONLINEAR,
                "demand SDe(T1)·ψ·γ·(Ts/T1)²/√[(1 − Ts/T1)² + 0.02·Ts/T1]",
                SpectralDemand(
                    DAMPING, pos.T1, spec.SDe(pos.T1), None, f"SDe(T1) ({CLAUSE_SLV_NONLINEAR})"
                ),
            )
        )
    return out


def height_displacement(spec: Spectrum, pos: Position, Ts: float) -> float:
    """The displacement demand at height SDe(T1)·ψ·γ·(Ts/T1)²/√[(1 − Ts/T1)² + 0.02·Ts/T1] [m]
    of a mechanism of secant period Ts [s] (Circolare 617/2009 §C8A.4.2.3), 5 % damping."""
    assert pos.T1 is not None
    return spec.SDe(pos.T1) * pos.psi * pos.gamma * height_amplification(Ts, pos.T1)


def ground_demand(Ts: float, dem: LimitStateDemand) -> SpectralDemand:
    """SDe(Ts) at 5 % damping [m], the ground demand of Circolare 617/2009 §C8A.4.2.3.

    The 2009 text reads the demand at Ts, with a record as with the code's spectrum: it has no
    rule for a record's spectrum, and the source paper (and the 2009 assessments it compares
    with) read it so (docs/interpretations.md); :func:`later_rule_note` says what the 2019 rule
    would read.
    """
    value = dem.spectrum.SDe(Ts, DAMPING)
    return SpectralDemand(DAMPING, Ts, value, None, f"SDe(Ts) ({CLAUSE_SLV_NONLINEAR})", value)


def later_rule_note(Ts: float, dem: LimitStateDemand) -> str:
    """For a record as the demand, what the 2019 rule would read: the maximum of its spectrum
    over [0, Ts] (Circolare 7/2019 §C8.7.1.2.1.8), when it is larger than SDe(Ts); "" else."""
    if dem.record is None:
        return ""
    spec = dem.spectrum
    T_max, value = range_maximum(lambda T: spec.SDe(T, DAMPING), 0.0, Ts)
    at_ts = spec.SDe(Ts, DAMPING)
    if value <= at_ts:
        return ""
    return (
        f"; the record's spectrum peaks below Ts: max Sd over [0, Ts] = {value:.5g} m at "
        f"T = {T_max:.4g} s ({value / at_ts:.3g}× SDe(Ts)); the 2019 rule (Circ. 7/2019 "
        "§C8.7.1.2.1.8) reads that maximum, the 2009 text reads SDe(Ts)"
    )


def check_2009(
    cap: Capacity,
    sld: LimitStateDemand,
    slv: LimitStateDemand,
    pos: Position,
    q: float,
    limit: float | None,
) -> tuple[dict[str, float | None], list[Check]]:
    """Every 2009 check of a mechanism: DLS and ULS linear, ULS non-linear."""
    g = cap.mech.g
    values = quantities(cap, limit)
    checks = [
        *linear_checks(cap, sld, pos, g, q, "DLS"),
        *linear_checks(cap, slv, pos, g, q, "ULS"),
        *nonlinear_checks(values, slv, pos),
    ]
    return values, checks
