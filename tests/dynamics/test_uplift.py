"""Uplift from rest: the block starts to rock when |üg| exceeds tan α (α when linearized).

Source: spec/rocking.md, "Uplift from rest" and "Closed forms for tests": a constant
acceleration of 0.999·tan α (in g) leaves the block at rest, 1.001·tan α uplifts it; one-sided
motion uplifts only towards the free side; a restrainer has no force at θ = 0 (u(0) = 0), so it
does not change the threshold. At θ = 0 the equation of motion gives θ̈ > 0 iff
üg·cos α > sin α, i.e. üg > tan α; linearized (sin x ≈ x, cos x ≈ 1) iff üg > α.

The ground motion is linear between samples (rocking.md), so a crossing of the threshold inside
a sample interval has an exact time: the tests of the ramp and of the one-sample spike compare it
to 1e-12 s (rounding of a few operations on times of order 1 s).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.result import RunStatus
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, Restrainer, housner_restitution

ALPHA = 0.2
R_BLOCK = 3.0
#: The closed form's margins on the threshold (rocking.md: 0.999 and 1.001 × tan α).
BELOW, ABOVE = 0.999, 1.001
#: A free tail of one sample: the run ends right after the record, before the block can fall
#: back and cross to the other side, so the side of the uplift shows in theta_max / theta_min.
SHORT = SolverSettings(tail=0.01)
#: Exact crossing times (linear ground motion between samples): rounding only [s].
CROSSING_ATOL = 1e-12


def constant(value: float, duration: float = 1.0) -> tuple[np.ndarray, np.ndarray, float]:
    """A constant ground acceleration `value` [g] from t = 0 to `duration` [s] (two samples)."""
    return np.array([0.0, duration]), np.array([value, value]), 0.01


def threshold(linearized: bool) -> float:
    """The closed form's uplift acceleration [g]: tan α, or α for the linearized equation."""
    return ALPHA if linearized else math.tan(ALPHA)


def top_spring(k: float, k_neg: float | None = None) -> Restrainer:
    """The paper's spring at the top corner: r = 2R, φ = α on both pivots."""
    k_neg = k if k_neg is None else k_neg
    return Restrainer("top", k, k_neg, 2 * R_BLOCK, ALPHA, 2 * R_BLOCK, ALPHA)


BLOCKS = {
    "free": Block(R=R_BLOCK, alpha=ALPHA, e=housner_restitution(ALPHA)),
    "linearized": Block(R=R_BLOCK, alpha=ALPHA, e=housner_restitution(ALPHA), linearized=True),
    "restrained": Block(
        R=R_BLOCK,
        alpha=ALPHA,
        mass=1.0e4,
        e=housner_restitution(ALPHA),
        restrainers=(top_spring(1e7),),
    ),
    "one-way spring": Block(
        R=R_BLOCK,
        alpha=ALPHA,
        mass=1.0e4,
        e=housner_restitution(ALPHA),
        restrainers=(top_spring(1e7, k_neg=0.0),),
    ),
}


def test_block_reports_the_closed_form_threshold() -> None:
    """Block.uplift_acceleration is tan α (α when linearized)."""
    assert BLOCKS["free"].uplift_acceleration == pytest.approx(math.tan(ALPHA), rel=1e-15)
    assert BLOCKS["linearized"].uplift_acceleration == pytest.approx(ALPHA, rel=1e-15)


@pytest.mark.parametrize("sign", [1, -1])
@pytest.mark.parametrize("name", sorted(BLOCKS))
def test_just_below_the_threshold_stays_at_rest(name: str, sign: int) -> None:
    """±0.999·tan α (±0.999·α linearized) for 1 s: no uplift, no rotation."""
    block = BLOCKS[name]
    run = simulate(block, *constant(sign * BELOW * threshold(block.linearized)))
    assert run.t_uplift is None
    assert run.uplifts == 0
    assert run.max_ratio == 0.0
    assert run.theta_max == 0.0 and run.theta_min == 0.0
    assert run.message == "never uplifted"


@pytest.mark.parametrize("sign", [1, -1])
@pytest.mark.parametrize("name", sorted(BLOCKS))
def test_just_above_the_threshold_uplifts_towards_the_push(name: str, sign: int) -> None:
    """±1.001·tan α uplifts at t = 0 and rotates to the side of the acceleration (paper's sign)."""
    block = BLOCKS[name]
    time = np.arange(101) * 0.01
    accel = np.full(time.size, sign * ABOVE * threshold(block.linearized))
    run = simulate(block, time, accel, 0.01, settings=SHORT, history=True)
    assert run.t_uplift == 0.0
    # A stiff restrainer makes θ = 0 a grazing point of a small oscillation about the static
    # equilibrium, so the block may come back to rest and uplift again: count at least one.
    assert run.uplifts >= 1
    assert run.max_ratio > 0.0
    assert run.history is not None
    first_motion = run.history.theta[np.flatnonzero(run.history.theta)[0]]
    assert np.sign(first_motion) == sign
    if not block.restrainers:
        # Negative global stiffness: the block keeps leaning the same way until the record ends.
        untouched = run.theta_min if sign > 0 else run.theta_max
        assert untouched == 0.0


@pytest.mark.parametrize("linearized", [False, True])
def test_crossing_located_inside_a_ramp(linearized: bool) -> None:
    """üg rising linearly from 0 to 2·tan α over [0, 1] s crosses tan α at exactly t = 0.5 s."""
    block = BLOCKS["linearized" if linearized else "free"]
    time = np.array([0.0, 1.0])
    accel = np.array([0.0, 2.0 * threshold(linearized)])
    run = simulate(block, time, accel, 0.01, settings=SHORT)
    assert run.t_uplift == pytest.approx(0.5, abs=CROSSING_ATOL)


@pytest.mark.parametrize("sign", [1, -1])
def test_one_sample_spike_is_never_skipped(sign: int) -> None:
    """A single sample of 1.01·tan α in a record of zeros: uplift at t_(k−1) + dt/1.01.

    The piecewise-linear ground motion rises from 0 at t_(k−1) to 1.01·tan α at t_k, so it
    crosses tan α at t_(k−1) + dt/1.01 (rocking.md: "never skip a short spike").
    """
    dt, k = 0.01, 150
    time = np.arange(400) * dt
    accel = np.zeros(400)
    accel[k] = sign * 1.01 * math.tan(ALPHA)
    run = simulate(BLOCKS["free"], time, accel, dt)
    assert run.uplifts == 1
    assert run.t_uplift == pytest.approx(time[k - 1] + dt / 1.01, abs=CROSSING_ATOL)
    assert (run.theta_max > 0.0) if sign > 0 else (run.theta_min < 0.0)


@pytest.mark.parametrize("free_side", [1, -1])
def test_one_sided_block_uplifts_only_towards_the_free_side(free_side: int) -> None:
    """One-sided: 1.001·tan α towards the free side uplifts; 3·tan α towards the walls does not."""
    block = Block(
        R=R_BLOCK,
        alpha=ALPHA,
        e=housner_restitution(ALPHA),
        one_sided=True,
        free_side=free_side,
        rebound=0.9,
    )
    towards_free = simulate(block, *constant(free_side * ABOVE * math.tan(ALPHA)))
    assert towards_free.t_uplift == 0.0
    assert towards_free.max_ratio > 0.0
    # θ never crosses to the stopped side, even after the record (rocking.md, one-sided motion).
    stopped = towards_free.theta_min if free_side > 0 else towards_free.theta_max
    assert stopped == 0.0
    towards_walls = simulate(block, *constant(-free_side * 3.0 * math.tan(ALPHA)))
    assert towards_walls.t_uplift is None
    assert towards_walls.max_ratio == 0.0


# --- uplift from rest while |üg| already exceeds the threshold ----------------------------------
#
# The block can be at rest while the ground acceleration already exceeds tan α: at the start of
# a record whose first sample does, or right after the rest rule stops it (rocking.md, "Rest":
# "then wait for the next uplift"). It must uplift at once, and when |üg| drops back below tan α
# a fraction of a millisecond later, make a tiny excursion, come back to rest and go on with the
# record. Budget: these runs need a few hundred steps (the reference engine: one uplift); a
# budget of 1e5 steps (STEP_BUDGET) makes a zero-progress loop fail in milliseconds instead of
# burning the default 5e7 steps (≈ 20 s).

STEP_BUDGET = 100_000
#: Bound on the excursion: |üg| exceeds tan α by ≤ 1 % for ≤ 0.5 ms, so
#: θ ≤ ½·p²·(0.01 tan α)·(5e-4 s)² ≈ 2e-9 rad ≈ 1e-8 α; 1e-6 α is a generous bound.
TINY_RATIO = 1e-6


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_record_starting_just_above_the_threshold(engine: Engine) -> None:
    """üg(0) = 1.01·tan α falling to 0 at t = 0.01 s: beyond tan α for the first 0.1 ms only."""
    block = Block(R=1.0, alpha=ALPHA, e=0.9)
    time = np.array([0.0, 0.01])
    accel = np.array([1.01 * math.tan(ALPHA), 0.0])
    settings = SolverSettings(tail=1.0, max_steps=STEP_BUDGET)
    run = simulate(block, time, accel, 0.01, settings=settings, engine=engine)
    assert run.status is RunStatus.COMPLETED, run.message
    assert run.t_uplift == 0.0
    assert run.uplifts == 1
    assert 0.0 < run.max_ratio < TINY_RATIO
    assert run.t_end == pytest.approx(1.01, abs=1e-9)


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_uplift_right_after_the_rest_rule(engine: Engine) -> None:
    """Linearized, e = 0, released at α/2: the impact at t_i = arccosh(2)/p brings it to rest
    (rocking.md, free rocking: t_i = T/4) while üg = −1.01·α, which ramps to 0 by t_i + 0.01 s.

    The record is zero until 2 µs before t_i (its effect on the fall is ≈ 1e-12 s), so the
    block comes to rest inside the window where üg is beyond −α; it must uplift to the negative
    side once, come back to rest, and finish the record and the tail.
    """
    block = Block(R=1.0, alpha=ALPHA, e=0.0, linearized=True)
    t_i = math.acosh(2.0) / block.p
    time = np.array([0.0, t_i - 2e-6, t_i - 1e-6, t_i + 0.01, t_i + 0.02])
    accel = np.array([0.0, 0.0, -1.01 * ALPHA, 0.0, 0.0])
    settings = SolverSettings(tail=1.0, max_steps=STEP_BUDGET)
    run = simulate(block, time, accel, 0.01, theta0=ALPHA / 2, settings=settings, engine=engine)
    assert run.status is RunStatus.COMPLETED, run.message
    assert run.uplifts == 1
    assert -TINY_RATIO * ALPHA < run.theta_min < 0.0
    assert run.t_end == pytest.approx(t_i + 1.02, abs=1e-9)
