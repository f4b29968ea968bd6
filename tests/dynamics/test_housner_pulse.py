"""Housner's rectangular pulse on the linearized block: the overturning criterion.

Source: spec/rocking.md, "Closed forms for tests" (Housner 1963): a constant üg = a [g] for
0 ≤ t ≤ t1 from rest overturns the linearized block iff a/α ≥ 1/(1 − e^{−p t1}).

Derivation (the tests rely on its pieces). The block uplifts at t = 0 only if a > α (the
linearized uplift threshold), which 1/(1 − e^{−p t1}) > 1 guarantees at the threshold; during
the pulse θ̈ = p²(θ − α + a), so θ(t1) = (a − α)(cosh pt1 − 1) and θ̇(t1) = p(a − α) sinh pt1.
After it ½θ̇² − ½p²(α − θ)² is conserved: the block passes θ = α (and then runs away, since the
linearized equation is unstable past α) iff θ̇(t1) ≥ p(α − θ(t1)), i.e. a(e^{pt1} − 1) ≥ α e^{pt1};
otherwise it stops at θm = α − √((α − θ(t1))² − (θ̇(t1)/p)²), falls back, and with e ≤ 1 never
comes closer to α again.

"Overturns" in the linearized model: there is no special angle at π/2 (sin x ≈ x), but past
θ = α with θ̇ > 0 the motion θ − α ∝ e^{pt} reaches any angle, so the default overturn angle
π/2 and overturn_angle = α give the same verdict; π/2 only takes longer (the default free tail,
≥ 20/p, is long enough, even 2 % above the threshold).

The record: the ground motion is linear between samples, so the step down at t1 is sampled as
two samples STEP_WIDTH = 1e-9 s apart. A ramp over one dt = 1e-3 s would add a·dt/2 to the
impulse a·t1, i.e. 0.05–0.3 % of it for these t1: harmless for the ±2 % checks, but not for the
bisection and the peak, whose tolerances (1e-5, 1e-6) rest on the sharp step (its extra impulse
is ≈ 1e-9 relative).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block

ALPHA = 0.2
#: Width of the sampled step down at the end of the pulse [s] (module doc).
STEP_WIDTH = 1e-9
#: (R [m], p·t1): three pulses from short (p t1 = 0.5, threshold 2.54 α) to long (p t1 = 2,
#: threshold 1.16 α); 0.98 × each threshold still exceeds α, so the survivor does rock.
CASES = [(3.0, 0.5), (1.0, 1.0), (0.5, 2.0)]
#: The brief's margins around the threshold.
JUST_BELOW, JUST_ABOVE = 0.98, 1.02
#: Bisection of the engine's threshold: resolution and tolerance against Housner's closed form
#: (integrator error 1e-8 and the 1e-9 step width, ×1000 margin).
BISECT_RESOLUTION = 1e-7
BISECT_RTOL = 1e-5
#: Peak of the sub-critical response against the closed form (integrator error 1e-8, ×100).
PEAK_RTOL = 1e-6


def rectangular_pulse(a: float, t1: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Constant üg = a [g] for 0 ≤ t ≤ t1 [s], then zero; free tail sampled at 1e-3 s."""
    return np.array([0.0, t1, t1 + STEP_WIDTH]), np.array([a, a, 0.0]), 1e-3


def housner_threshold(alpha: float, p_t1: float) -> float:
    """The pulse acceleration [g] at which the linearized block overturns: α/(1 − e^{−p t1})."""
    return alpha / (1.0 - math.exp(-p_t1))


def linear_block(R: float, e: float = 0.9) -> Block:
    return Block(R=R, alpha=ALPHA, e=e, linearized=True)


@pytest.mark.parametrize("overturn_angle", [math.pi / 2, ALPHA], ids=["pi/2", "alpha"])
@pytest.mark.parametrize(("R", "p_t1"), CASES)
def test_pulse_just_above_the_threshold_overturns(
    R: float, p_t1: float, overturn_angle: float
) -> None:
    block = linear_block(R)
    t1 = p_t1 / block.p
    a = JUST_ABOVE * housner_threshold(ALPHA, p_t1)
    run = simulate(
        block, *rectangular_pulse(a, t1), settings=SolverSettings(overturn_angle=overturn_angle)
    )
    assert run.overturned
    assert run.t_overturn is not None and run.t_overturn > t1  # past α only after the pulse
    assert run.impacts == 0


@pytest.mark.parametrize("overturn_angle", [math.pi / 2, ALPHA], ids=["pi/2", "alpha"])
@pytest.mark.parametrize(("R", "p_t1"), CASES)
def test_pulse_just_below_the_threshold_survives(
    R: float, p_t1: float, overturn_angle: float
) -> None:
    block = linear_block(R)
    t1 = p_t1 / block.p
    a = JUST_BELOW * housner_threshold(ALPHA, p_t1)
    assert a > ALPHA, "the pulse must exceed the linearized uplift threshold α to rock at all"
    run = simulate(
        block, *rectangular_pulse(a, t1), settings=SolverSettings(overturn_angle=overturn_angle)
    )
    assert not run.overturned
    assert run.t_uplift == 0.0
    assert 0.0 < run.max_ratio < 1.0


@pytest.mark.parametrize(("R", "p_t1"), CASES)
def test_peak_of_the_surviving_block(R: float, p_t1: float) -> None:
    """θm = α − √((α − θ(t1))² − (θ̇(t1)/p)²) from the piecewise solution (module doc)."""
    block = linear_block(R)
    a = JUST_BELOW * housner_threshold(ALPHA, p_t1)
    run = simulate(block, *rectangular_pulse(a, p_t1 / block.p))
    theta1 = (a - ALPHA) * (math.cosh(p_t1) - 1.0)
    omega1_over_p = (a - ALPHA) * math.sinh(p_t1)
    peak = ALPHA - math.sqrt((ALPHA - theta1) ** 2 - omega1_over_p**2)
    assert run.theta_max == pytest.approx(peak, rel=PEAK_RTOL)


@pytest.mark.parametrize(("R", "p_t1"), CASES)
def test_bisected_threshold_matches_housner(R: float, p_t1: float) -> None:
    """The pulse amplitude where the engine's verdict flips is Housner's α/(1 − e^{−p t1})."""
    block = linear_block(R)
    t1 = p_t1 / block.p
    expected = housner_threshold(ALPHA, p_t1)
    lo, hi = JUST_BELOW * expected, JUST_ABOVE * expected
    while hi - lo > BISECT_RESOLUTION * expected:
        mid = 0.5 * (lo + hi)
        if simulate(block, *rectangular_pulse(mid, t1)).overturned:
            hi = mid
        else:
            lo = mid
    assert 0.5 * (lo + hi) == pytest.approx(expected, rel=BISECT_RTOL)
