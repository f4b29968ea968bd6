"""The floor motion at height (rockcli.codecheck.floor): ü_Z = ü_g + γ·ψ·ẍ₁.

Sources: independent integrations of the oscillator ẍ + 2ξωẋ + ω²x = −ü_g — scipy.signal.lsim
(exact first-order-hold discretisation by matrix exponential) on ELC180.AT2, and
scipy.integrate.solve_ivp (DOP853, rtol 1e-10) sample to sample on pulses — and closed forms
of the linear oscillator (Chopra, *Dynamics of Structures*: resonance §3.2; the particular
solution under a linear load §4.4).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, signal

from rockcli.codecheck.floor import floor_motion
from rockcli.records.pulses import make_pulse
from rockcli.records.record import Record

XI = 0.05


def lsim_floor(rec: Record, T1: float, gamma_psi: float, xi: float = XI) -> np.ndarray:
    """ü_g + γψ·ẍ with ẍ = −ω²x − 2ξωẋ − ü_g the output of a state-space model (scipy)."""
    w = 2 * math.pi / T1
    model = signal.StateSpace(
        [[0, 1], [-w * w, -2 * xi * w]], [[0], [-1]], [[-w * w, -2 * xi * w]], [[-1]]
    )
    _, relative, _ = signal.lsim(model, rec.accel, rec.time)
    return rec.accel + gamma_psi * relative


def ivp_floor(time: np.ndarray, accel: np.ndarray, T1: float, gamma_psi: float) -> np.ndarray:
    """The same by DOP853 at rtol 1e-10, one solve per step (ü_g linear, smooth inside it)."""
    w = 2 * math.pi / T1
    state = np.zeros(2)
    states = [state]
    for i in range(time.size - 1):
        t0, t1, a0, a1 = time[i], time[i + 1], accel[i], accel[i + 1]

        def rhs(t: float, y: np.ndarray, t0=t0, t1=t1, a0=a0, a1=a1) -> list[float]:
            ag = a0 + (a1 - a0) * (t - t0) / (t1 - t0)
            return [y[1], -ag - 2 * XI * w * y[1] - w * w * y[0]]

        sol = integrate.solve_ivp(rhs, (t0, t1), state, method="DOP853", rtol=1e-10, atol=1e-14)
        state = sol.y[:, -1]
        states.append(state)
    x, v = np.array(states).T
    return accel + gamma_psi * (-accel - 2 * XI * w * v - w * w * x)


@pytest.mark.parametrize("T1", [0.1, 0.5, 2.0])
def test_matches_lsim_on_elc180(elc180: Record, T1: float) -> None:
    # Both are exact for a record linear between samples; what is left is round-off over 4000
    # steps (measured 6e-15 of the peak at T1 = 0.3 s). Tolerance 1e-10 of the peak.
    psi, gamma = 1.0, 1.3
    ours = floor_motion(elc180.time, elc180.accel, T1=T1, psi=psi, gamma=gamma, xi=XI)
    reference = lsim_floor(elc180, T1, psi * gamma)
    assert np.max(np.abs(ours - reference)) <= 1e-10 * np.max(np.abs(reference))
    # The floor is not the ground: a test of the comparison, not of two equal inputs.
    assert np.max(np.abs(ours - elc180.accel)) > 0.1 * elc180.pga


@pytest.mark.parametrize("uniform", [True, False], ids=["uniform", "non-uniform"])
def test_matches_solve_ivp_on_a_pulse(uniform: bool) -> None:
    # One-sine pulse of 0.35 g, Tp = 1 s, 0.01 s steps, 1 s of free vibration after it. The
    # non-uniform one has every other step 0.015 s (the coefficients recomputed at each step).
    pulse = make_pulse("one-sine", 0.35, 1.0, dt=0.01, total=2.0)
    time = pulse.time
    if not uniform:
        time = np.cumsum(np.r_[0.0, np.where(np.arange(time.size - 1) % 2, 0.015, 0.01)])
    T1, psi, gamma = 0.4, 1.2, 1.1
    ours = floor_motion(time, pulse.accel, T1=T1, psi=psi, gamma=gamma)
    reference = ivp_floor(time, pulse.accel, T1, psi * gamma)
    # rtol 1e-10 per step over 200 steps, relative to a peak near 1 g: tolerance 1e-8 of it.
    assert np.max(np.abs(ours - reference)) <= 1e-8 * np.max(np.abs(reference))


def test_gamma_psi_zero_is_the_ground_exactly(elc180: Record) -> None:
    floor = floor_motion(elc180.time, elc180.accel, T1=0.3, psi=0.0, gamma=1.4)
    assert np.array_equal(floor, elc180.accel)


def test_gamma_psi_one_is_the_absolute_acceleration(elc180: Record) -> None:
    # γψ = 1: ü_g + ẍ = −2ξωẋ − ω²x, the oscillator's absolute acceleration, whose peak is the
    # record's 5 % spectral acceleration near Sa = ω²·Sd: they differ by the damping term
    # 2ξω·ẋ ≲ 2ξ·Sa (Chopra §6.12.2), so tolerance 2ξ (measured 0.56 % at T1 = 0.5 s).
    from rockcli.codecheck.response import response_spectrum

    T1 = 0.5
    floor = floor_motion(elc180.time, elc180.accel, T1=T1, psi=1.0, gamma=1.0)
    Sa, _ = response_spectrum(elc180.time, elc180.accel, [T1], damping=XI, free_tail=False)
    assert np.max(np.abs(floor)) == pytest.approx(Sa[0], rel=2 * XI)


def test_stiff_building_moves_with_the_ground(elc180: Record) -> None:
    # Within a step ü_g is linear and x_p = −ü_g/ω² + 2ξü̇_g/ω³ solves the oscillator with
    # ẍ_p = 0 (Chopra §4.4); the transient each kink adds decays by e^(−ξω·dt) per step:
    # e^(−31) at T1 = 1e-4 s, dt = 0.01 s. So from the second sample on, ẍ₁ is round-off
    # (ω²x cancels ü_g: a few ε of the PGA); tolerance 1e-12 g. The first sample is the
    # oscillator at rest under ü_g(0) ≠ 0 (ELC180 starts at −0.0064 g): ẍ₁ = −ü_g(0) exactly.
    psi, gamma = 1.0, 1.5
    floor = floor_motion(elc180.time, elc180.accel, T1=1e-4, psi=psi, gamma=gamma)
    assert floor[0] == pytest.approx(elc180.accel[0] * (1 - psi * gamma), rel=1e-12)
    assert np.max(np.abs(floor[1:] - elc180.accel[1:])) <= 1e-12
    # A less stiff building (T1 = 0.01 s, ξω·dt = 0.31) does not: the test can fail.
    moderate = floor_motion(elc180.time, elc180.accel, T1=1e-2, psi=psi, gamma=gamma)
    assert np.max(np.abs(moderate[1:] - elc180.accel[1:])) > 1e-3


def test_resonant_sine_is_amplified_by_one_over_two_xi() -> None:
    # ü_g = A sin ωt at the building's own ω: the steady state is x = A/(2ξω²)·cos ωt, so
    # ẍ = −A/(2ξ)·cos ωt and ü_Z = A sin ωt − γψ·A/(2ξ)·cos ωt (Chopra §3.2), amplitude
    # A·√(1 + (γψ/2ξ)²). 60 periods leave e^(−ξω·58T) = 1e-8 of the transient over the last two;
    # joining samples at dt = T/400 by straight lines shrinks the sine by (ωdt)²/12 = 2.1e-5:
    # tolerance 5e-5 of the amplitude.
    T1, A, psi, gamma = 1.0, 0.1, 1.0, 1.2
    w = 2 * math.pi / T1
    dt = T1 / 400
    t = np.arange(0, 60 * T1 + dt / 2, dt)
    floor = floor_motion(t, A * np.sin(w * t), T1=T1, psi=psi, gamma=gamma, xi=XI)
    closed = A * np.sin(w * t) - psi * gamma * A / (2 * XI) * np.cos(w * t)
    amplitude = A * math.hypot(1.0, psi * gamma / (2 * XI))
    last = t >= 58 * T1
    assert np.max(np.abs(floor[last] - closed[last])) <= 5e-5 * amplitude
    assert np.max(np.abs(floor[last])) == pytest.approx(amplitude, rel=5e-5)
