"""Each restrainer's action in the kinematic check and its verification against its strength
(rockcli.codecheck.restrainer_check; analyses.capacity_check.governing_demand).

Sources: NTC 2018 §4.2.4.1.2 (the member's design strength is the limit); the spring's force
P0 + K·u with u = r[sin φ − sin(φ − θ)] (mechanics.spring_elongation) at the rotation of the
displacement the check relies on. Tolerance 1e-12 relative: the same formula evaluated twice.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from rockcli.analyses.capacity_check import governing_demand
from rockcli.codecheck import rules2019
from rockcli.codecheck.demand import LimitStateDemand
from rockcli.codecheck.kinematic import Mechanism, capacity, rotation_at
from rockcli.codecheck.position import Position
from rockcli.codecheck.restrainer_check import (
    CONSTANT,
    DISPLACEMENT_BASIS,
    GIVEN_BASIS,
    NO_BASIS,
    NOT_ACTING,
    STRENGTH_CLAUSE,
    nonlinear_displacement_demand,
    restrainer_actions,
)
from rockcli.codecheck.result import Check, Location, Method
from rockcli.codecheck.spectra import ElasticSpectrum, Soil, Topography
from rockcli.mechanics import Block, Restrainer, point_polar, spring_elongation
from rockcli.mechanisms.block import BlockSide

G = 9.81
B, H, W = 0.3, 4.0, 300e3
REL = 1e-12
Z_TIE = 7.5
R_TIE, PHI_TIE = point_polar(0.0, Z_TIE)


def member(action: str, strength: float = 8e4, **extra: float) -> Restrainer:
    k = extra.pop("k", 1e6)
    k_neg = extra.pop("k_neg", k)
    return Restrainer(
        action,
        k,
        k_neg,
        R_TIE,
        PHI_TIE,
        R_TIE,
        PHI_TIE,
        extra.pop("fails_at", math.inf),
        strength=strength,
        code_action=action,
        code_force=strength if action == "force" else 0.0,
        **extra,
    )


def cap_of(*members: Restrainer):
    block = Block(R=math.hypot(B, H), alpha=math.atan2(B, H), mass=W / G, g=G, restrainers=members)
    return capacity(Mechanism(BlockSide(block, 1)), FC=1.0)


def test_force_is_its_own_demand() -> None:
    # A force gives α0 its code_force and the check relies on exactly that force.
    [a] = restrainer_actions(cap_of(member("force", 6e4)), 0.05, "du* = 0.05 m")
    assert (a.code_action, a.force, a.demand, a.demand_at) == ("force", 6e4, 6e4, CONSTANT)
    # A member whose strength is given in the model (no steel) cites no steel clause.
    assert a.utilisation == 1.0 and a.passed is True and a.clause == GIVEN_BASIS
    steel = replace(
        member("force", 6e4), strength_rule=f"S275: N_pl,Rd governs ({STRENGTH_CLAUSE})"
    )
    [b] = restrainer_actions(cap_of(steel), 0.05, "du* = 0.05 m")
    assert b.clause == STRENGTH_CLAUSE
    # Neither a strength nor a failure elongation: no basis is claimed.
    [c] = restrainer_actions(cap_of(member("spring", math.inf)), 0.05, "du* = 0.05 m")
    assert c.clause == NO_BASIS
    [d] = restrainer_actions(cap_of(member("spring", math.inf, fails_at=0.01)), 0.05, "du*")
    assert d.clause == DISPLACEMENT_BASIS


def test_spring_demand_at_the_rotation_of_the_displacement() -> None:
    # The spring's demand is P0 + K u(θ) at the θ of the given d*, below its cap here.
    P0, k, d = 2e3, 1e6, 0.02
    cap = cap_of(member("spring", 8e4, k=k, pretension=P0))
    [a] = restrainer_actions(cap, d, "SLV displacement demand")
    theta = rotation_at(cap.mech, d / cap.factor)
    expected = P0 + k * spring_elongation(R_TIE, PHI_TIE, theta)
    assert a.force == P0
    assert a.demand == pytest.approx(expected, rel=REL)
    assert a.demand < 8e4 and a.utilisation == pytest.approx(expected / 8e4, rel=REL)
    assert a.demand_at == "SLV displacement demand" and a.passed is True


def test_spring_demand_capped_and_unknown_strength() -> None:
    # A stiff spring reaches its strength: demand = strength, utilisation 1; without a strength
    # the utilisation and the verdict are unknown (None).
    capped = restrainer_actions(cap_of(member("spring", 5e4, k=1e9)), 0.05, "du*")[0]
    assert capped.demand == 5e4 and capped.utilisation == 1.0 and capped.passed is True
    free = restrainer_actions(cap_of(member("spring", math.inf)), 0.05, "du*")[0]
    assert free.strength is None and free.utilisation is None and free.passed is None


def test_member_lost_before_the_demand_fails() -> None:
    # A member that breaks (fails_at) before the rotation of the demand did not carry it.
    [a] = restrainer_actions(cap_of(member("force", 5e4, fails_at=1e-3)), 0.05, "du*")
    assert a.lost is True and a.passed is False
    [b] = restrainer_actions(cap_of(member("force", 5e4, fails_at=1.0)), 0.05, "du*")
    assert b.lost is False and b.passed is True


def test_member_not_acting_on_the_side() -> None:
    # K = 0 on θ > 0: no force, no demand, nothing to verify.
    [a] = restrainer_actions(cap_of(member("force", 5e4, k=0.0, k_neg=1e6)), 0.05, "du*")
    assert (a.force, a.demand, a.demand_at, a.passed) == (0.0, 0.0, NOT_ACTING, None)


def _check(demand: float | None, method: Method = Method.NONLINEAR, unit: str = "m") -> Check:
    return Check("ULS", method, Location.GROUND, demand, 0.1, unit, "§C8A.4.2.3")


def test_nonlinear_displacement_demand_is_the_largest() -> None:
    # Ground and height: the governing demand is the larger; linear checks and missing
    # demands do not count.
    checks = [_check(0.01), _check(0.03), _check(None), _check(5.0, Method.LINEAR, "m/s²")]
    assert nonlinear_displacement_demand(checks) == 0.03
    assert nonlinear_displacement_demand([_check(None)]) is None


def test_governing_demand_falls_back_on_du_then_none() -> None:
    # No non-linear demand: du* (2009); no du* either: no displacement, the spring's demand
    # is not evaluated (reading it at the end of the drawn curve gave a 20 MN "demand" on the
    # façade's vault: a number no check asks for).
    cap = cap_of(member("spring"))
    values: dict[str, float | None] = {"du_star": 0.04}
    assert governing_demand("2009", values, []) == (0.04, "du* = 0.04 m")
    d, at = governing_demand("2009", {"du_star": None}, [])
    assert d is None and at == "the check reaches no displacement (no du*)"
    [a] = restrainer_actions(cap, None, at)
    assert (a.demand, a.utilisation, a.passed, a.lost) == (None, None, None, False)
    d, at = governing_demand("2009", values, [_check(0.02)])
    assert (d, at) == (0.02, "SLV displacement demand d* = 0.02 m")


def test_slv_displacement_demand_2019_at_the_ground() -> None:
    # Circolare 7/2019 §C8.7.1.2.1: at the ground the SLV displacement demand is SDe(T_SLV)
    # with the mechanism's 8 % damping, of the limit state's own spectrum (NTC 2018
    # §3.2.3.2.2); the same spectrum object read twice (exact). The spring is read where the
    # SLV non-linear check read the spectrum.
    spectrum = ElasticSpectrum(
        ag=0.15, F0=2.5, Tc_star=0.3, soil=Soil("A"), topography=Topography("T1"), g=G
    )
    slv = LimitStateDemand("SLV", 0.15, lambda a: spectrum, "test")
    check = rules2019.displacement_check("SLV", 0.05, 1.7, slv, Position(), G, None)
    assert rules2019.slv_displacement_demand([check]) == spectrum.SDe(1.7, 8.0)
    unchecked = rules2019.displacement_check("SLV", None, None, slv, Position(), G, None)
    assert rules2019.slv_displacement_demand([unchecked]) is None


def test_lost_force_makes_the_curve_not_the_straight_line() -> None:
    # A force that can be lost holds until it is lost (Circolare 7/2019 §C8.7.1.2.1.6: the
    # curve of the actions present until collapse): the checks read α(θ) with it until then,
    # not a0*(1 − d*/d0*). At rest: α0 = (W·b + F·z_T)/(W·h), e* = FC = 1.
    lost = cap_of(member("force", 5e4, fails_at=0.01))
    assert not lost.linear
    assert lost.a_star(0.0) == pytest.approx(G * (W * B + 5e4 * Z_TIE) / (W * H), rel=REL)
    # Past its loss (u = 0.01 m at the top, θ ≈ 0.01/7.5) only gravity: tan(α − θ) at θ = 0.1.
    d = lost.d_star_at(0.1)
    assert lost.a_star(d) == pytest.approx(G * math.tan(math.atan2(B, H) - 0.1), rel=1e-9)
    assert not cap_of(member("spring", 5e4, fails_at=0.01)).linear  # a spring's force grows
