"""The elastic response spectrum of a record (rockcli.codecheck.response).

Sources: closed forms of the linear oscillator (Chopra, *Dynamics of Structures*: resonance
§3.2, the step with a finite rise time §4.4, free vibration §2.2) and the reference integration
scipy.signal.lsim (exact first-order-hold discretisation by matrix exponential) on ELC180.AT2.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from scipy import signal

from rockcli.codecheck import response
from rockcli.codecheck.response import RecordSpectrum, response_spectrum
from rockcli.codecheck.spectra import ElasticSpectrum, pga_ground
from rockcli.errors import InputError
from rockcli.records.record import Record

G = 9.81


def oscillator(T: float, damping: float) -> signal.StateSpace:
    """u'' + 2ζωu' + ω²u = −a_g [m/s²], output u [m]."""
    w = 2 * math.pi / T
    return signal.StateSpace([[0, 1], [-w * w, -2 * damping * w]], [[0], [-1]], [[1, 0]], [[0]])


def ramp_step_peak(a0: float, T: float, rise: float) -> float:
    """Undamped peak |u| for a ground acceleration rising linearly from 0 to a0 in `rise` s.

    Chopra §4.4 (step force with finite rise time): u_max = (a0/ω²)·(1 + |sin(ωt_r/2)/(ωt_r/2)|).
    """
    w = 2 * math.pi / T
    x = w * rise / 2
    return a0 / w**2 * (1 + abs(math.sin(x) / x))


# --- closed forms -------------------------------------------------------------------------------


def test_resonance_reaches_the_steady_state_amplitude() -> None:
    # a_g = a·sin ωt at the oscillator's own ω, ζ = 5 %, 60 periods (e^(−ζω·60T) = 7e-9 of the
    # transient left): Sd = a/(2ζω²). Sampling a sine at dt = T/400 and joining the samples
    # linearly shrinks its amplitude by sinc²(ωdt/2) ≈ 1 − (ωdt)²/12 = 1 − 2.1e-5; tolerance 5e-5.
    T, zeta, a = 1.0, 0.05, 0.1
    w = 2 * math.pi / T
    dt = T / 400
    t = np.arange(0, 60 * T + dt / 2, dt)
    Sa, Sd = response_spectrum(t, a * np.sin(w * t), [T], damping=zeta)
    assert Sd[0] == pytest.approx(a * G / (2 * zeta * w**2), rel=5e-5)
    assert Sa[0] == pytest.approx(a / (2 * zeta), rel=5e-5)  # Sa = ω²Sd, in g


def test_step_with_one_sample_rise_is_exact() -> None:
    # Undamped, a0 reached in one step dt; with dt = T/21 the peak (at t = dt/2 + T/2) falls on
    # a sample, so the recurrence must give the closed form to round-off.
    T, a0 = 1.0, 0.2
    dt = T / 21
    t = np.arange(0, 3 * T, dt)
    a = np.full(t.size, a0)
    a[0] = 0.0
    Sa, Sd = response_spectrum(t, a, [T], damping=0.0, free_tail=False)
    assert Sd[0] == pytest.approx(ramp_step_peak(a0 * G, T, dt), rel=1e-12)


def test_step_tends_to_twice_the_static_displacement() -> None:
    # dt → 0: u_max → 2·a0/ω² (Chopra §4.3); the rise-time factor is 1 − (ωdt)²/48 = 1 − 8e-7
    # at dt = T/1001, and the peak lies on a sample (odd divisor, as above).
    T, a0 = 0.5, 0.3
    dt = T / 1001
    t = np.arange(0, 2 * T, dt)
    a = np.full(t.size, a0)
    a[0] = 0.0
    w = 2 * math.pi / T
    _, Sd = response_spectrum(t, a, [T], damping=0.0)
    assert Sd[0] == pytest.approx(2 * a0 * G / w**2, rel=1e-6)


def test_non_uniform_steps_are_integrated_exactly() -> None:
    # The same ramp-step with irregular samples after the ramp (the input is constant there, so
    # any sampling is the same piecewise-linear motion), keeping the peak time as a sample.
    T, a0 = 1.0, 0.2
    dt = T / 21
    rng = np.random.default_rng(7)
    later = np.sort(rng.uniform(dt, 3 * T, 300))
    peak_time = dt / 2 + T / 2
    t = np.unique(np.concatenate([[0.0, dt, peak_time], later]))
    a = np.where(t > 0, a0, 0.0)
    _, Sd = response_spectrum(t, a, [T], damping=0.0, free_tail=False)
    assert Sd[0] == pytest.approx(ramp_step_peak(a0 * G, T, dt), rel=1e-12)


def test_zero_period_is_the_pga() -> None:
    t = np.linspace(0, 1, 101)
    a = 0.3 * np.sin(7 * t) - 0.4 * t**2
    Sa, Sd = response_spectrum(t, a, [0.0, 0.5])
    assert Sa[0] == np.max(np.abs(a))
    assert Sd[0] == 0.0


def test_free_vibration_after_the_record() -> None:
    # A 0.2 s half-sine pulse and a 2 s oscillator: its peak comes after the record ends. The
    # closed-form tail must equal the free vibration integrated by lsim on a fine grid (peak
    # sampled every T/20000: error ≤ (2π/20000)²/8 = 1.2e-8).
    T, zeta = 2.0, 0.05
    t = np.linspace(0, 0.2, 41)
    a = 0.5 * np.sin(math.pi * t / 0.2)
    a[-1] = 0.0
    _, Sd_tail = response_spectrum(t, a, [T], damping=zeta)
    _, Sd_record = response_spectrum(t, a, [T], damping=zeta, free_tail=False)
    sys = oscillator(T, zeta)
    _, y, x = signal.lsim(sys, a * G, t, interp=True)
    tail = np.arange(0, 2 * T, T / 20000)
    _, y_free, _ = signal.lsim(sys, np.zeros(tail.size), tail, X0=x[-1], interp=True)
    assert Sd_record[0] == pytest.approx(np.max(np.abs(y)), rel=1e-12)
    assert Sd_tail[0] == pytest.approx(np.max(np.abs(np.concatenate([y, y_free]))), rel=1e-7)
    assert Sd_tail[0] > 1.5 * Sd_record[0]


# --- reference integration on a real record ----------------------------------------------------


@pytest.mark.parametrize("T", [0.1, 0.5, 1.09, 3.0])
def test_matches_lsim_on_elc180(elc180: Record, T: float) -> None:
    # lsim with interp=True discretises the same piecewise-linear input exactly (matrix
    # exponential); measured agreement 1e-13, asserted to 1e-8.
    _, y, _ = signal.lsim(oscillator(T, 0.05), elc180.accel * G, elc180.time, interp=True)
    Sa, Sd = response_spectrum(elc180.time, elc180.accel, [T], damping=0.05, free_tail=False)
    assert Sd[0] == pytest.approx(np.max(np.abs(y)), rel=1e-8)
    assert Sa[0] == pytest.approx((2 * math.pi / T) ** 2 * Sd[0] / G, rel=1e-15)


def test_short_period_tends_to_pga_on_elc180(elc180: Record) -> None:
    # a stiff oscillator follows the ground: Sa → PGA (quasi-static lag 2ζ/ω of the slope;
    # measured 4e-5 at T = 1 ms)
    Sa, _ = response_spectrum(elc180.time, elc180.accel, [1e-3])
    assert Sa[0] == pytest.approx(elc180.pga, rel=1e-4)


# --- RecordSpectrum: the demand of a record -----------------------------------------------------


def test_record_spectrum_same_as_the_function_with_xi_in_percent(elc180: Record) -> None:
    demand = RecordSpectrum.from_record(elc180)
    Sa, Sd = response_spectrum(elc180.time, elc180.accel, [1.09], damping=0.10)
    assert demand.Se(1.09, 10.0) == Sa[0]
    assert demand.SDe(1.09, 10.0) == Sd[0]
    assert demand.pga_ground == elc180.pga
    assert pga_ground(demand) == elc180.pga
    assert demand.Se(0.0) == elc180.pga


def test_record_spectrum_caches_by_period_and_damping(monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[int] = []
    original = response.response_spectrum

    def counting(*args: Any, **kwargs: Any) -> Any:
        calls.append(len(args[2]))
        return original(*args, **kwargs)

    monkeypatch.setattr(response, "response_spectrum", counting)
    t = np.linspace(0, 2, 201)
    demand = RecordSpectrum(t, 0.2 * np.sin(9 * t))
    demand.curve([0.5, 1.0], xi=5.0)
    demand.Se(1.0)
    demand.SDe(0.5)
    assert calls == [2]
    demand.Se(1.0, xi=8.0)  # another damping: computed anew
    assert calls == [2, 1]


def test_record_spectrum_reads_a_cached_ordinate_as_it_is(monkeypatch: pytest.MonkeyPatch) -> None:
    # The 2019 demand of a record reads a few hundred cached ordinates per check
    # (codecheck.demand.range_maximum): a hit is the pair cached, its period not checked again
    # as an array (issue 34, F15); a period never computed goes through the checks as before.
    t = np.linspace(0, 2, 201)
    demand = RecordSpectrum(t, 0.2 * np.sin(9 * t))
    Sa, Sd = demand.curve([0.5])
    calls: list[Any] = []
    original = RecordSpectrum._values

    def counting(self: RecordSpectrum, *args: Any) -> Any:
        calls.append(args)
        return original(self, *args)

    monkeypatch.setattr(RecordSpectrum, "_values", counting)
    assert (demand.Se(0.5), demand.SDe(0.5)) == (Sa[0], Sd[0])
    assert calls == []
    for bad in (-0.5, math.nan):
        with pytest.raises(InputError, match="periods"):
            demand.SDe(bad)


def test_both_demands_answer_the_same_questions(elc180: Record) -> None:
    for demand in (ElasticSpectrum(0.26, 2.36, 0.35), RecordSpectrum(elc180.time, elc180.accel)):
        assert demand.Se(1.0, 5.0) > 0
        assert demand.SDe(1.0, 5.0) > 0
        assert pga_ground(demand) > 0


# --- bad input ----------------------------------------------------------------------------------


@pytest.mark.parametrize("damping", [-0.01, 1.0, 5.0])
def test_damping_must_be_a_fraction_below_one(damping: float) -> None:
    with pytest.raises(InputError, match="fraction"):
        response_spectrum(np.linspace(0, 1, 11), np.zeros(11), [0.5], damping=damping)


def test_time_must_increase() -> None:
    with pytest.raises(InputError, match="increase"):
        response_spectrum(np.array([0.0, 0.1, 0.1]), np.zeros(3), [0.5])


def test_lengths_must_agree() -> None:
    with pytest.raises(InputError, match="same length"):
        RecordSpectrum(np.linspace(0, 1, 11), np.zeros(10))


def test_negative_period_refused() -> None:
    with pytest.raises(InputError, match="periods"):
        response_spectrum(np.linspace(0, 1, 11), np.zeros(11), [-0.5])


# --- the short-period limit ---------------------------------------------------------------------


def test_step_overshoot_undamped_is_two() -> None:
    """Chopra §4.3: a suddenly applied force on an undamped oscillator peaks at 2·u_st."""
    assert response.step_overshoot(0.0) == 2.0


def test_rigid_limit_is_the_pga_for_a_record_from_rest() -> None:
    assert response.rigid_limit([0.0, 0.3, -0.4, 0.1], 0.05) == 0.4


def test_rigid_limit_of_a_record_starting_off_zero() -> None:
    """Starting at 0.3 g, peak 0.4 g: the step overshoots, 1 + e^{−πζ/√(1−ζ²)} (Chopra §4.3)."""
    overshoot = 1 + math.exp(-math.pi * 0.05 / math.sqrt(1 - 0.05**2))  # 1.8545
    assert response.rigid_limit([0.3, 0.4, 0.0], 0.05) == pytest.approx(0.3 * overshoot, rel=1e-15)
