"""The steps of a member law, one at a time, on a packed restrainer table.

motion.py's law functions are plain Python that both engines run (the fast engine compiled by
numba, the reference engine as is); the kernel's event step (_apply_law_event) wraps them.
Each step is checked against the law written here: F = K·(u − c) elastic, F_y on the plateau,
0 slack (docs/physics.md, "Restrainers with strength").
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics import layout as L
from rockcli.dynamics import motion
from rockcli.dynamics.kernel import _apply_law_event, _uplift_thresholds
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import pack_parameters, pack_springs
from rockcli.mechanics import Block, Restrainer, spring_elongation

K = 2e6
F_Y = 20e3
P0 = 4e3
R, PHI = 6.0, 0.1


def table(**law: float | str) -> np.ndarray:
    """The packed table of one tie (both sides) with the law given, reset to rest."""
    sp = Restrainer("tie", K, K, R, PHI, R, PHI, **law)  # type: ignore[arg-type]
    springs = pack_springs(Block(R=3.0, alpha=0.1, mass=1e4, restrainers=(sp,)))
    motion.reset_laws(springs, False)
    return springs


def a_at(u: float) -> float:
    """The rotation at which the tie's elongation is u [rad] (inverse of u(a), written here)."""
    return PHI - math.asin(math.sin(PHI) - u / R)


def test_rest_state_has_the_pretension_and_the_yield_level() -> None:
    """At rest c = −P0/K: F(0) = P0, and the upward level is where K(u − c) = F_y."""
    springs = table(law="elastic-plastic", yield_pos=F_Y, yield_neg=F_Y, pretension=P0)
    assert motion.member_force(springs, 0, 1, K, 0.0) == pytest.approx(P0, rel=1e-15)
    assert springs[0, motion.COL_UP] == pytest.approx(a_at((F_Y - P0) / K), rel=1e-12)
    assert springs[0, motion.COL_UP_KIND] == motion.UP_YIELD
    assert springs[0, motion.COL_DOWN] == motion.NO_LEVEL_DOWN  # c < 0: never slack near rest


def test_yield_then_unload_then_slack_then_reengage() -> None:
    """The law's cycle, step by step, with the plastic work F_y·Δc."""
    springs = table(law="elastic-plastic", yield_pos=F_Y, yield_neg=F_Y)
    out = np.zeros((1, L.N_SPRING_OUT))
    out[:, L.S_T_YIELD] = np.nan
    alive = np.ones(1, dtype=np.int64)
    a_y = springs[0, motion.COL_UP]
    assert not _apply_law_event(L.EV_LAW_UP, 0, 1, a_y, 0.5, springs, alive, out, False)
    assert springs[0, motion.COL_MODE] == motion.MODE_PLASTIC and out[0, L.S_T_YIELD] == 0.5
    u_peak = 0.03
    assert motion.member_force(springs, 0, 1, K, u_peak) == F_Y  # the plateau
    _apply_law_event(L.EV_UNLOAD, -1, 1, a_at(u_peak), 0.7, springs, alive, out, False)
    c = springs[0, motion.COL_C]
    assert c == pytest.approx(u_peak - F_Y / K, rel=1e-12)
    assert out[0, L.S_ENERGY] == pytest.approx(F_Y * c, rel=1e-12)
    assert motion.member_force(springs, 0, 1, K, 0.5 * (c + u_peak)) == pytest.approx(
        K * 0.5 * (u_peak - c), rel=1e-12
    )
    assert springs[0, motion.COL_DOWN] == pytest.approx(a_at(c), rel=1e-12)
    assert springs[0, motion.COL_UP] == pytest.approx(a_at(u_peak), rel=1e-12)  # yields again
    _apply_law_event(L.EV_SLACK, 0, 1, a_at(c), 0.8, springs, alive, out, False)
    assert motion.member_force(springs, 0, 1, K, 0.5 * c) == 0.0
    assert springs[0, motion.COL_UP_KIND] == motion.UP_ENGAGE
    _apply_law_event(L.EV_LAW_UP, 0, 1, a_at(c), 0.9, springs, alive, out, False)
    assert springs[0, motion.COL_MODE] == motion.MODE_ELASTIC
    assert out[0, L.S_T_YIELD] == 0.5  # the first yield time is kept
    # the member of the other pivot kept its own state
    assert springs[0, motion.COL_C + 1] == 0.0 and springs[0, motion.COL_MODE + 1] == 0.0


def test_anchor_rupture_step_loses_the_member_and_its_stored_energy() -> None:
    """An anchor below the yield force: the upward level is a break; crossing it loses the
    member, keeps the time and counts ½·R²/K released."""
    springs = table(law="elastic-plastic", yield_pos=F_Y, yield_neg=F_Y, rupture_force=15e3)
    assert springs[0, motion.COL_UP_KIND] == motion.UP_BREAK
    out = np.zeros((1, L.N_SPRING_OUT))
    alive = np.ones(1, dtype=np.int64)
    a_b = springs[0, motion.COL_UP]
    assert _apply_law_event(L.EV_LAW_UP, 0, 1, a_b, 1.25, springs, alive, out, False)
    assert alive[0] == 0 and out[0, L.S_T_FAIL] == 1.25
    assert out[0, L.S_ENERGY] == pytest.approx(0.5 * 15e3**2 / K, rel=1e-9)


def test_uplift_threshold_step_adds_the_pretension_moment() -> None:
    """_uplift_thresholds: tan α plus P0·r·cos φ/(m g R cos α) on each pretensioned side, and
    tan α again once the member is slack (c > 0)."""
    sp = Restrainer(
        "tie",
        K,
        0.0,
        R,
        PHI,
        R,
        PHI,
        law="elastic-plastic",
        yield_pos=F_Y,
        yield_neg=F_Y,
        pretension=P0,
    )
    blk = Block(R=3.0, alpha=0.1, mass=1e4, restrainers=(sp,))
    par = pack_parameters(blk, SolverSettings(), 1e-8, 1e-8)
    springs = pack_springs(blk)
    motion.reset_laws(springs, False)
    alive = np.ones(1, dtype=np.int64)
    pos, neg = _uplift_thresholds(par, springs, alive, False, True)
    w_h = 1e4 * 9.81 * 3.0 * math.cos(0.1)
    assert pos == pytest.approx(math.tan(0.1) + P0 * R * math.cos(PHI) / w_h, rel=1e-12)
    assert neg == math.tan(0.1)  # no member on that side
    springs[0, motion.COL_C] = 0.01  # yielded: slack at rest
    assert _uplift_thresholds(par, springs, alive, False, True)[0] == math.tan(0.1)


def test_member_moment_is_the_spring_moment_for_an_elastic_spring() -> None:
    """F·r·cos(φ − a) with F = K·(u − 0) has the same bits as mechanics' K·u·r·cos(φ − a)."""
    from rockcli.mechanics import spring_moment

    springs = table()
    for a in (1e-6, 0.01, 0.3):
        got = motion.member_moment(
            springs, 0, 1, K, R, math.sin(PHI), math.cos(PHI), a, math.sin(a), math.cos(a), False
        )
        assert got == spring_moment(K, R, PHI, a)
        assert spring_elongation(R, PHI, a) > 0.0
