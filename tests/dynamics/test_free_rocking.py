"""Free rocking released from rest at θ0 = φ0·α, no ground motion: the closed forms.

Source: spec/rocking.md, "Closed forms for tests", free rocking (Housner 1963):

- non-linear, exact: between impacts ½θ̇² + p² cos(α − |θ|) is conserved, so the impact
  velocity is θ̇² = 2p²[cos(α − θ0) − cos α] and successive amplitudes obey
  cos(α − θn+1) − cos α = e²·[cos(α − θn) − cos α];
- linearized: θ(t) = α − (α − θ0) cosh(pt); with e = 1 the period is
  T = (4/p)·arccosh(1/(1 − φ0)); after n impacts φn = 1 − √(1 − e^{2n}[1 − (1 − φ0)²]).

Timing of the linearized cycle with e = 1: released at rest from θ0 > 0 the block reaches θ = 0
after T/4 (first impact), −θ0 at T/2, θ = 0 again at 3T/4 (second impact), θ0 at T and the
third impact at 5T/4: impact k happens at (2k − 1)·T/4.

How the amplitudes are read:
- `theta_min` of a run stopped by `max_events = 2` is the amplitude after exactly one impact
  (the run ends at the second impact; `theta_max` is θ0 itself);
- the later amplitudes come from the history: the extreme sample of each half-cycle (runs of
  samples with the same sign of θ) refined by the vertex of the parabola through it and its two
  neighbours. d³θ/dt³ = p² cos(α − θ)·θ̇ vanishes at the peak, so that vertex is off by
  O(dt⁴·p⁴·α) ≈ 1e-11 rad for dt = 1e-3 s, far below the tolerance;
- an impact time is `t_end` of a run stopped by `max_events = k`: the run ends at the k-th
  impact (rockcli.dynamics.kernel.integrate: status EVENT_LIMIT at the event time).

Tolerances: the closed forms are exact for the equation the engine integrates (the linearized
ones for the linearized equation), so the only error is the integrator's, bounded by the default
rtol = atol = 1e-8; 1e-6 relative leaves a factor 100 for the error growth over a few
half-cycles. Event times: 1e-7 relative, rtol × a condition factor ≤ 10
(δt ≈ δθ/|θ̇| at impact for these φ0 ≤ 0.9).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.result import RockingRun, RunStatus
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, housner_restitution

#: Relative tolerance of amplitudes and velocities against the closed forms (see module doc).
AMPLITUDE_RTOL = 1e-6
#: Relative tolerance of impact times against the closed forms (see module doc).
TIME_RTOL = 1e-7
#: Sample interval of the free tail when the history is read [s] (parabolic peaks, module doc).
HISTORY_DT = 1e-3
#: Semi-diagonal of the test block [m]: p = √(3g/4R) = 2.71 rad/s, a cycle of a few seconds.
R_TEST = 1.0


def quiet_record(dt: float = 0.01) -> tuple[np.ndarray, np.ndarray, float]:
    """No ground motion: two zero samples; the free tail (SolverSettings.tail) does the rest."""
    return np.array([0.0, dt]), np.zeros(2), dt


def release(
    block: Block,
    theta0: float,
    *,
    tail: float,
    dt: float = 0.01,
    history: bool = False,
    max_events: int = 1_000_000,
) -> RockingRun:
    """Free rocking from rest at θ0 for `tail` seconds (no ground motion)."""
    time, accel, dt = quiet_record(dt)
    settings = SolverSettings(tail=tail, max_events=max_events)
    return simulate(block, time, accel, dt, theta0=theta0, settings=settings, history=history)


def nonlinear_amplitude(alpha: float, theta0: float, e: float, n: int) -> float:
    """θn from cos(α − θn+1) − cos α = e²[cos(α − θn) − cos α] applied n times (rocking.md)."""
    excess = e ** (2 * n) * (math.cos(alpha - theta0) - math.cos(alpha))
    return alpha - math.acos(math.cos(alpha) + excess)


def linear_amplitude_ratio(phi0: float, e: float, n: int) -> float:
    """φn = 1 − √(1 − e^{2n}[1 − (1 − φ0)²]) (rocking.md, linearized free rocking)."""
    return 1.0 - math.sqrt(1.0 - e ** (2 * n) * (1.0 - (1.0 - phi0) ** 2))


def linear_period(p: float, phi0: float) -> float:
    """T = (4/p)·arccosh(1/(1 − φ0)) (rocking.md, linearized free rocking, e = 1)."""
    return 4.0 / p * math.acosh(1.0 / (1.0 - phi0))


def half_cycle_amplitudes(time: np.ndarray, theta: np.ndarray) -> list[float]:
    """|θ| at the peak of each complete half-cycle of a sampled history (parabolic vertex)."""
    sign = np.sign(theta)
    edges = np.flatnonzero(np.diff(sign) != 0) + 1
    amplitudes = []
    for run in np.split(np.arange(theta.size), edges):
        a = np.abs(theta[run])
        k = int(np.argmax(a))
        if sign[run[0]] == 0 or k == 0 or k == run.size - 1:
            continue  # at rest, or the peak is not inside the run (the release, the cut end)
        y0, y1, y2 = a[k - 1], a[k], a[k + 1]
        amplitudes.append(y1 + (y0 - y2) ** 2 / (8.0 * (2.0 * y1 - y0 - y2)))
    return amplitudes


@pytest.mark.parametrize("alpha", [0.1, 0.25])
@pytest.mark.parametrize("phi0", [0.1, 0.5, 0.9])
def test_first_rebound_follows_energy_recursion(alpha: float, phi0: float) -> None:
    """θ1 after one impact: cos(α − θ1) − cos α = e²[cos(α − θ0) − cos α], Housner e."""
    block = Block(R=R_TEST, alpha=alpha, e=housner_restitution(alpha))
    theta0 = phi0 * alpha
    run = release(block, theta0, tail=20.0, max_events=2)
    assert run.status is RunStatus.EVENT_LIMIT and run.impacts == 2
    assert run.theta_max == pytest.approx(theta0, rel=1e-15)
    expected = nonlinear_amplitude(alpha, theta0, block.e, 1)
    assert -run.theta_min == pytest.approx(expected, rel=AMPLITUDE_RTOL)


@pytest.mark.parametrize("phi0", [0.3, 0.8])
def test_successive_amplitudes_follow_energy_recursion(phi0: float) -> None:
    """θn for n = 1…5 impacts from the history's half-cycle peaks, non-linear, e = 0.9."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=0.9)
    theta0 = phi0 * alpha
    run = release(block, theta0, tail=12.0, dt=HISTORY_DT, history=True)
    assert run.history is not None
    peaks = half_cycle_amplitudes(run.history.time, run.history.theta)
    assert len(peaks) >= 5, f"only {len(peaks)} complete half-cycles in the history"
    expected = [nonlinear_amplitude(alpha, theta0, block.e, n) for n in range(1, 6)]
    assert peaks[:5] == pytest.approx(expected, rel=AMPLITUDE_RTOL)


@pytest.mark.parametrize("alpha", [0.1, 0.25])
@pytest.mark.parametrize("phi0", [0.1, 0.5, 0.9])
def test_impact_velocity_from_energy(alpha: float, phi0: float) -> None:
    """|θ̇| at the first impact (e = 1): θ̇² = 2p²[cos(α − θ0) − cos α]."""
    block = Block(R=R_TEST, alpha=alpha, e=1.0)
    theta0 = phi0 * alpha
    run = release(block, theta0, tail=20.0, max_events=1)
    assert run.status is RunStatus.EVENT_LIMIT and run.impacts == 1
    expected = math.sqrt(2.0 * block.p2 * (math.cos(alpha - theta0) - math.cos(alpha)))
    assert run.max_velocity == pytest.approx(expected, rel=AMPLITUDE_RTOL)


@pytest.mark.parametrize("phi0", [0.1, 0.5, 0.9])
def test_linearized_impact_times_give_the_period(phi0: float) -> None:
    """Impact k at (2k − 1)·T/4, T = (4/p)·arccosh(1/(1 − φ0)), linearized, e = 1."""
    block = Block(R=R_TEST, alpha=0.2, e=1.0, linearized=True)
    period = linear_period(block.p, phi0)
    times = {}
    for k in (1, 2, 3):
        run = release(block, phi0 * block.alpha, tail=3.0 * period, max_events=k)
        assert run.status is RunStatus.EVENT_LIMIT and run.impacts == k
        times[k] = run.t_end
    assert times[1] == pytest.approx(period / 4.0, rel=TIME_RTOL)
    assert times[2] == pytest.approx(3.0 * period / 4.0, rel=TIME_RTOL)
    assert times[3] - times[1] == pytest.approx(period, rel=TIME_RTOL)


@pytest.mark.parametrize("phi0", [0.3, 0.8])
def test_linearized_trajectory_before_the_first_impact(phi0: float) -> None:
    """θ(t) = α − (α − θ0) cosh(pt) at every history sample until the first impact."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=1.0, linearized=True)
    theta0 = phi0 * alpha
    run = release(block, theta0, tail=5.0, dt=HISTORY_DT, history=True, max_events=1)
    assert run.history is not None
    t, theta = run.history.time, run.history.theta
    before = t < run.t_end
    assert before.sum() > 100
    expected = alpha - (alpha - theta0) * np.cosh(block.p * t[before])
    # Absolute: θ passes through 0; rtol·α = 2e-9 rad is the integrator's scale, ×100 margin.
    np.testing.assert_allclose(theta[before], expected, rtol=0.0, atol=AMPLITUDE_RTOL * alpha)


@pytest.mark.parametrize("e", [0.9, 0.7])
@pytest.mark.parametrize("phi0", [0.3, 0.8])
def test_linearized_amplitude_after_n_impacts(phi0: float, e: float) -> None:
    """φn = 1 − √(1 − e^{2n}[1 − (1 − φ0)²]) for n = 1 (theta_min) and n = 1…4 (history)."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=e, linearized=True)
    theta0 = phi0 * alpha
    first = release(block, theta0, tail=20.0, max_events=2)
    assert -first.theta_min / alpha == pytest.approx(
        linear_amplitude_ratio(phi0, e, 1), rel=AMPLITUDE_RTOL
    )
    run = release(block, theta0, tail=12.0, dt=HISTORY_DT, history=True)
    assert run.history is not None
    peaks = half_cycle_amplitudes(run.history.time, run.history.theta)
    assert len(peaks) >= 4, f"only {len(peaks)} complete half-cycles in the history"
    expected = [alpha * linear_amplitude_ratio(phi0, e, n) for n in range(1, 5)]
    assert peaks[:4] == pytest.approx(expected, rel=AMPLITUDE_RTOL)


@pytest.mark.parametrize("sign", [1, -1])
def test_release_on_the_negative_side_is_the_mirror(sign: int) -> None:
    """Released at ±θ0: the first rebound has the same amplitude on the other side."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=housner_restitution(alpha))
    theta0 = 0.5 * alpha
    run = release(block, sign * theta0, tail=20.0, max_events=2)
    first_rebound = -run.theta_min if sign > 0 else run.theta_max
    assert first_rebound == pytest.approx(
        nonlinear_amplitude(alpha, theta0, block.e, 1), rel=AMPLITUDE_RTOL
    )


@pytest.mark.parametrize("sign", [1, -1])
def test_start_from_the_ground_with_a_velocity(sign: int) -> None:
    """From θ = 0 with θ̇0: it rocks to the side of θ̇0 up to cos(α − θ1) − cos α = θ̇0²/(2p²)."""
    alpha, omega0 = 0.2, 0.3
    block = Block(R=R_TEST, alpha=alpha, e=1.0)
    time, accel, dt = quiet_record()
    run = simulate(
        block,
        time,
        accel,
        dt,
        omega0=sign * omega0,
        settings=SolverSettings(tail=20.0, max_events=1),
    )
    expected = alpha - math.acos(math.cos(alpha) + omega0**2 / (2.0 * block.p2))
    reached = run.theta_max if sign > 0 else -run.theta_min
    untouched = run.theta_min if sign > 0 else run.theta_max
    assert reached == pytest.approx(expected, rel=AMPLITUDE_RTOL)
    assert untouched == 0.0
    assert run.max_velocity == pytest.approx(omega0, rel=AMPLITUDE_RTOL)  # energy: back at θ = 0


def test_one_sided_rebound_recursion() -> None:
    """One-sided: θ̇⁺ = −r_f·e·θ̇⁻ about the same pivot: the recursion with (r_f·e)² (rocking.md)."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=0.9, one_sided=True, free_side=1, rebound=0.8)
    theta0 = 0.5 * alpha
    run = release(block, theta0, tail=5.0, dt=HISTORY_DT, history=True)
    assert run.theta_min == 0.0  # never on the stopped side
    assert run.history is not None
    # Every half-cycle is on the free side: split the history at the impacts (θ = 0 samples are
    # rare), i.e. at the local minima of θ; the peaks between them are the amplitudes.
    theta = run.history.theta
    minima = np.flatnonzero((theta[1:-1] < theta[:-2]) & (theta[1:-1] <= theta[2:])) + 1
    pieces = np.split(theta, minima)[1:-1]  # skip the release and the cut end
    peaks = [half_cycle_amplitudes(run.history.time, piece)[0] for piece in pieces[:4]]
    rf_e = block.rebound * block.e
    expected = [nonlinear_amplitude(alpha, theta0, rf_e, n) for n in range(1, 5)]
    assert peaks == pytest.approx(expected, rel=AMPLITUDE_RTOL)


def test_zero_restitution_stops_at_the_first_impact() -> None:
    """e = 0 (Housner e ≤ 0 for α ≥ 54.74°): no rocking after the first impact (rocking.md)."""
    block = Block(R=R_TEST, alpha=0.2, e=0.0)
    run = release(block, 0.1, tail=5.0)
    assert run.impacts == 1
    assert run.theta_min == 0.0 and run.theta_max == 0.1


@pytest.mark.parametrize(("factor", "overturns"), [(1 - 1e-3, False), (1 + 1e-3, True)])
def test_static_stability_limit_is_alpha(factor: float, overturns: bool) -> None:
    """Non-linear, from rest: θ0 < α falls back, θ0 > α falls over (at θ = α the CG is above O)."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=1.0)
    run = release(block, factor * alpha, tail=20.0)
    assert run.overturned is overturns
    if overturns:
        assert run.max_ratio == pytest.approx(math.pi / 2 / alpha, rel=1e-15)  # stops at π/2
        assert run.impacts == 0


def test_linearized_overturning_time() -> None:
    """From θ0 = 1.1α, θ = α + (θ0 − α) cosh(pt) reaches π/2 at arccosh((π/2 − α)/(θ0 − α))/p."""
    alpha = 0.2
    block = Block(R=R_TEST, alpha=alpha, e=1.0, linearized=True)
    theta0 = 1.1 * alpha
    run = release(block, theta0, tail=10.0)
    assert run.overturned
    expected = math.acosh((math.pi / 2 - alpha) / (theta0 - alpha)) / block.p
    assert run.t_overturn == pytest.approx(expected, rel=TIME_RTOL)
