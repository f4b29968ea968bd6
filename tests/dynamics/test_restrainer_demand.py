"""Restrainer demand reported by a run, and the paper's quick effectiveness check (§4.3).

Sources:
- spec/rocking.md, "Restrainers": u(θ) = r[sin φ − sin(φ − |θ|)] with the (K, r, φ) of the active
  pivot; a run reports each restrainer's peak displacement and force K·u (paper Eq. 9–10). u
  grows with |θ| (for |θ| < φ + π/2), so the peak displacement on a side is u at that side's
  extreme rotation: max_displacement = max over the sides with K ≠ 0 of u_side(|θ_side|max).
  Both the engine and this test evaluate the same formula (mechanics.spring_elongation) at the
  same peak angle, so they agree to rounding: 1e-12 relative.
- paper §4.3 (façade R = 5.04 m, α = 0.05, W = 1755 kN, K = 1e7 N/m): c_K = 4KR²/I0 = 167.7
  and c_E = p² = 1.46 [1/s²], printed to 4 and 3 significant digits: compared to half a unit
  of the last printed digit.
- paper Eq. (18): the linearized global stiffness of the block with the top spring is positive
  iff 4KR/(mg) > 1/cos α.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import (
    Block,
    Restrainer,
    housner_restitution,
    linear_global_stiffness,
    point_polar,
    polar_inertia,
    spring_elongation,
    stiffness_coefficient,
)

#: The paper's façade (§4.3).
R_FACADE, ALPHA_FACADE, W_FACADE, G = 5.04, 0.05, 1755e3, 9.81
M_FACADE = W_FACADE / G
#: Same formula, same angle: rounding only.
SAME_FORMULA_RTOL = 1e-12


def sine_pulse(
    amplitude: float, period: float, dt: float = 0.01
) -> tuple[np.ndarray, np.ndarray, float]:
    """One full sine cycle of `amplitude` [g] and `period` [s], sampled at dt."""
    time = np.arange(int(round(period / dt)) + 1) * dt
    return time, amplitude * np.sin(2.0 * np.pi * time / period), dt


def facade(*restrainers: Restrainer, linearized: bool = False) -> Block:
    return Block(
        R=R_FACADE,
        alpha=ALPHA_FACADE,
        mass=M_FACADE,
        g=G,
        e=housner_restitution(ALPHA_FACADE),
        linearized=linearized,
        restrainers=restrainers,
    )


def top_spring(k_pos: float, k_neg: float | None = None, fails_at: float = math.inf) -> Restrainer:
    """The paper's spring at the top corner: r = 2R, φ = α on both pivots."""
    k_neg = k_pos if k_neg is None else k_neg
    r, phi = 2 * R_FACADE, ALPHA_FACADE
    return Restrainer("top", k_pos, k_neg, r, phi, r, phi, fails_at)


def expected_demand(block: Block, run: RockingRun) -> tuple[float, float]:
    """(peak u [m], peak K·u [N]) of the block's only restrainer from the run's signed extremes."""
    spring = block.restrainers[0]
    sides = [
        (spring.k_pos, spring.r_pos, spring.phi_pos, run.theta_max),
        (spring.k_neg, spring.r_neg, spring.phi_neg, -run.theta_min),
    ]
    u = [spring_elongation(r, phi, a, block.linearized) if k else 0.0 for k, r, phi, a in sides]
    f = [k * ui for (k, *_), ui in zip(sides, u, strict=True)]
    return max(u), max(f)


@pytest.mark.parametrize("linearized", [False, True])
def test_symmetric_top_spring_demand(linearized: bool) -> None:
    """K = 1e6 both ways: u at max|θ| (the larger swing is θ < 0 here), force K·u."""
    k = 1e6
    block = facade(top_spring(k), linearized=linearized)
    run = simulate(block, *sine_pulse(0.15, 2.0))
    assert not run.overturned and run.max_ratio > 0.3  # a real swing, not chatter
    peak = run.restrainers[0]
    u = spring_elongation(2 * R_FACADE, ALPHA_FACADE, run.max_ratio * ALPHA_FACADE, linearized)
    assert peak.max_displacement == pytest.approx(u, rel=SAME_FORMULA_RTOL)
    assert peak.max_force == pytest.approx(k * peak.max_displacement, rel=SAME_FORMULA_RTOL)
    assert peak.t_fail is None


def test_one_way_spring_counts_only_its_side() -> None:
    """k_neg = 0: the demand is u(θmax) of the positive side, not the larger negative swing."""
    block = facade(top_spring(1e7, k_neg=0.0))
    run = simulate(block, *sine_pulse(0.1, 1.0))
    assert not run.overturned
    assert -run.theta_min > 2.0 * run.theta_max  # the free side swings further
    u, f = expected_demand(block, run)
    assert u == spring_elongation(2 * R_FACADE, ALPHA_FACADE, run.theta_max)
    assert run.restrainers[0].max_displacement == pytest.approx(u, rel=SAME_FORMULA_RTOL)
    assert run.restrainers[0].max_force == pytest.approx(f, rel=SAME_FORMULA_RTOL)


def test_off_centre_point_uses_each_pivots_geometry() -> None:
    """A top point off the mid-plane: (r, φ) and K differ by side; demand = max over the sides."""
    b, h = R_FACADE * math.sin(ALPHA_FACADE), R_FACADE * math.cos(ALPHA_FACADE)
    r_pos, phi_pos = point_polar(0.5 * b, 2 * h)  # 0.5 b from pivot O (θ > 0)
    r_neg, phi_neg = point_polar(1.5 * b, 2 * h)  # 1.5 b from pivot O′ (θ < 0)
    spring = Restrainer("off-centre", 1e6, 2e6, r_pos, phi_pos, r_neg, phi_neg)
    block = facade(spring)
    run = simulate(block, *sine_pulse(0.15, 2.0))
    assert not run.overturned and run.max_ratio > 0.1
    u, f = expected_demand(block, run)
    assert run.restrainers[0].max_displacement == pytest.approx(u, rel=SAME_FORMULA_RTOL)
    assert run.restrainers[0].max_force == pytest.approx(f, rel=SAME_FORMULA_RTOL)


def test_failed_spring_demand_is_its_failure_elongation() -> None:
    """fails_at = 0.1 m, below the 0.33 m the intact spring reaches: it fails at u = fails_at.

    The failure is an event located on the dense output at the rotation where u = fails_at
    (mechanics.spring_failure_rotation): the recorded peak is fails_at to the root finder's
    resolution, 1e-9 relative.
    """
    intact = simulate(facade(top_spring(1e6)), *sine_pulse(0.15, 2.0))
    assert intact.restrainers[0].max_displacement > 0.3
    run = simulate(facade(top_spring(1e6, fails_at=0.1)), *sine_pulse(0.15, 2.0))
    peak = run.restrainers[0]
    assert peak.t_fail is not None and 0.0 < peak.t_fail < run.t_end
    assert peak.max_displacement == pytest.approx(0.1, rel=1e-9)
    assert peak.max_force == pytest.approx(1e6 * 0.1, rel=1e-9)


def test_paper_effectiveness_coefficients() -> None:
    """Paper §4.3: c_K = 4KR²/I0 = 167.7 and c_E = p² = 1.46 for the façade with K = 1e7."""
    inertia = polar_inertia(M_FACADE, R_FACADE)
    assert stiffness_coefficient(1e7, R_FACADE, inertia) == pytest.approx(167.7, abs=0.05)
    assert facade().p2 == pytest.approx(1.46, abs=0.005)
    assert facade().p2 == pytest.approx(M_FACADE * G * R_FACADE / inertia, rel=1e-14)


def test_global_stiffness_changes_sign_at_paper_eq_18() -> None:
    """dM/dθ at 0⁺ < 0 just below 4KR/(mg) = 1/cos α, > 0 just above (paper Eq. 18)."""
    k_flip = M_FACADE * G / (4.0 * R_FACADE * math.cos(ALPHA_FACADE))
    for s in (1, -1):
        assert linear_global_stiffness(facade(), s) < 0.0  # the free block: no restoring stiffness
        assert linear_global_stiffness(facade(top_spring(k_flip * (1 - 1e-6))), s) < 0.0
        assert linear_global_stiffness(facade(top_spring(k_flip * (1 + 1e-6))), s) > 0.0
        at_flip = linear_global_stiffness(facade(top_spring(k_flip)), s)
        assert abs(at_flip) < 1e-9 * M_FACADE * G * R_FACADE
