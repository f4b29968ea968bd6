"""A spring on the pivot face at height z, released from rest: time to impact and energy.

Source: spec/rocking.md, "Closed forms for tests". A point on the pivot face at height z has
r = z, φ = 0 about either pivot, so u = z sin|θ| and M = s·K z² sin|θ| cos|θ| ("Restrainers").
With κ = K z²/(m g R) and p² = m g R/I0:

- linearized (θ > 0: θ̈ − p²(1 − κ)θ = −p²α), from rest at θ0 the time to the first impact is
  t1 = arccosh[1/(1 − θ0(1 − κ)/α)]/(p√(1 − κ))   (κ < 1),
  t1 = √(2θ0/(p²α))                                (κ = 1),
  t1 = arccos[α/(α + (κ − 1)θ0)]/(p√(κ − 1))        (κ > 1);
- non-linear, the energy gives θ̇²(θ = 0) = p²{2[cos(α − θ0) − cos α] + κ sin²θ0}; θ̈ < 0 all the
  way down for θ0 < α, so that speed is the largest of the fall (max_velocity with e = 1 and
  the run stopped at the first impact).

Measuring t1: the run is stopped by max_events = 1, so it ends at the first impact and
`t_end` is its time (rockcli.dynamics.kernel.integrate). Tolerances as in test_free_rocking:
the closed forms are exact for the integrated equation, the default rtol = 1e-8 bounds the
error; 1e-7 relative for the time (condition factor ≤ 10), 1e-6 for the velocity.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.result import RockingRun, RunStatus
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, Restrainer, spring_moment

ALPHA, R_BLOCK, MASS, G = 0.15, 1.5, 1000.0, 9.81
#: The spring's height: 60 % of the block's height 2h (any height on the face would do).
Z = 1.2 * R_BLOCK * math.cos(ALPHA)
TIME_RTOL = 1e-7
VELOCITY_RTOL = 1e-6
#: Stop at the first impact: the run's t_end is its time, max_velocity its speed.
FIRST_IMPACT = SolverSettings(tail=20.0, max_events=1)


def face_spring_block(kappa: float, linearized: bool) -> Block:
    """The block with a spring of κ = K z²/(m g R) at height Z on the pivot face (r = z, φ = 0)."""
    k = kappa * MASS * G * R_BLOCK / Z**2
    spring = Restrainer("face", k, k, Z, 0.0, Z, 0.0)
    return Block(
        R=R_BLOCK, alpha=ALPHA, mass=MASS, g=G, e=1.0, linearized=linearized, restrainers=(spring,)
    )


def time_to_impact(p: float, kappa: float, theta0: float) -> float:
    """t1 of rocking.md for κ < 1, κ = 1 and κ > 1."""
    if kappa < 1.0:
        return math.acosh(1.0 / (1.0 - theta0 * (1.0 - kappa) / ALPHA)) / (
            p * math.sqrt(1.0 - kappa)
        )
    if kappa == 1.0:
        return math.sqrt(2.0 * theta0 / (p * p * ALPHA))
    return math.acos(ALPHA / (ALPHA + (kappa - 1.0) * theta0)) / (p * math.sqrt(kappa - 1.0))


def failure_time(p: float, kappa: float, omega0: float, theta_f: float) -> float:
    """First t with θ(t) = θ_f for the linearized solutions of the module doc, from θ = 0, θ̇0."""
    if kappa < 1.0:
        q = p * math.sqrt(1.0 - kappa)
        a, b = ALPHA / (1.0 - kappa), omega0 / q
        # a − a cosh + b sinh = θ_f with x = e^{qt}: (b − a)x² + 2(a − θ_f)x − (a + b) = 0.
        roots = np.roots([b - a, 2.0 * (a - theta_f), -(a + b)])
        x = min(r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 1.0)
        return math.log(x) / q
    w = p * math.sqrt(kappa - 1.0)
    c, d = ALPHA / (kappa - 1.0), omega0 / w
    # c cos wt + d sin wt = θ_f + c, i.e. √(c² + d²) cos(wt − ψ) = θ_f + c, first crossing wt < ψ.
    psi = math.atan2(d, c)
    return (psi - math.acos((theta_f + c) / math.hypot(c, d))) / w


def launch_speed(p: float, kappa: float, peak: float) -> float:
    """θ̇0 at θ = 0 that makes the linearized block turn back at θ = peak (module doc)."""
    if kappa < 1.0:
        a = ALPHA / (1.0 - kappa)  # max of a − a cosh + b sinh is a − √(a² − b²)
        return math.sqrt(a * a - (a - peak) ** 2) * p * math.sqrt(1.0 - kappa)
    c = ALPHA / (kappa - 1.0)  # max of −c + c cos + d sin is −c + √(c² + d²)
    return math.sqrt((peak + c) ** 2 - c * c) * p * math.sqrt(kappa - 1.0)


def release(block: Block, theta0: float) -> RockingRun:
    run = simulate(
        block, np.array([0.0, 0.01]), np.zeros(2), 0.01, theta0=theta0, settings=FIRST_IMPACT
    )
    assert run.status is RunStatus.EVENT_LIMIT and run.impacts == 1
    return run


def test_kappa_is_the_normalised_spring_moment() -> None:
    """The engine's linearized spring moment is K z² θ = κ·m g R·θ (the κ of the closed forms)."""
    block = face_spring_block(0.7, linearized=True)
    spring = block.restrainers[0]
    moment = spring_moment(spring.k_pos, spring.r_pos, spring.phi_pos, 0.01, linearized=True)
    assert moment == pytest.approx(0.7 * MASS * G * R_BLOCK * 0.01, rel=1e-14)


@pytest.mark.parametrize("phi0", [0.3, 0.8])
@pytest.mark.parametrize("kappa", [0.3, 1.0, 2.5])
def test_linearized_time_to_first_impact(kappa: float, phi0: float) -> None:
    block = face_spring_block(kappa, linearized=True)
    theta0 = phi0 * ALPHA
    run = release(block, theta0)
    assert run.t_end == pytest.approx(time_to_impact(block.p, kappa, theta0), rel=TIME_RTOL)


@pytest.mark.parametrize("phi0", [0.3, 0.8])
@pytest.mark.parametrize("kappa", [0.3, 1.0, 2.5])
def test_nonlinear_impact_velocity_from_energy(kappa: float, phi0: float) -> None:
    block = face_spring_block(kappa, linearized=False)
    theta0 = phi0 * ALPHA
    run = release(block, theta0)
    gravity = 2.0 * (math.cos(ALPHA - theta0) - math.cos(ALPHA))
    expected = math.sqrt(block.p2 * (gravity + kappa * math.sin(theta0) ** 2))
    assert run.max_velocity == pytest.approx(expected, rel=VELOCITY_RTOL)


@pytest.mark.parametrize("kappa", [0.5, 2.0])
def test_linearized_failure_time(kappa: float) -> None:
    """Launched from θ = 0 to turn back at 0.8α: the spring (fails_at = z·0.5α) fails on the way."""
    k = kappa * MASS * G * R_BLOCK / Z**2
    fails_at = Z * 0.5 * ALPHA
    spring = Restrainer("face", k, k, Z, 0.0, Z, 0.0, fails_at)
    block = Block(
        R=R_BLOCK, alpha=ALPHA, mass=MASS, g=G, e=1.0, linearized=True, restrainers=(spring,)
    )
    omega0 = launch_speed(block.p, kappa, 0.8 * ALPHA)
    run = simulate(
        block,
        np.array([0.0, 0.01]),
        np.zeros(2),
        0.01,
        omega0=omega0,
        settings=SolverSettings(tail=5.0),
    )
    peak = run.restrainers[0]
    assert peak.t_fail == pytest.approx(
        failure_time(block.p, kappa, omega0, 0.5 * ALPHA), rel=TIME_RTOL
    )
    assert peak.max_displacement == pytest.approx(fails_at, rel=1e-9)
