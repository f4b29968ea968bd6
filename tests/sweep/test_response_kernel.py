"""The compiled response recurrence (rockcli.codecheck.response_kernel) against the numpy one.

Source: the same Nigam–Jennings equations (Chopra Table 5.2.1), the same coefficients and the
same order of operations: the peaks must agree to 1e-12 relative (the issue's tolerance; on
this machine they agree to the last bit), on a noisy record and on the shipped pulses.
"""

from __future__ import annotations

import numpy as np
import pytest

from rockcli.codecheck.response import (
    RecordSpectrum,
    peak_displacement,
    peak_displacement_uniform,
    response_spectrum,
    uniform_step,
)
from rockcli.records.files import read_record
from tests.sweep.conftest import PULSES

PERIODS = np.array([0.05, 0.3, 1.09, 2.5, 7.0])


@pytest.mark.parametrize("damping", [0.0, 0.05, 0.2])
@pytest.mark.parametrize("free_tail", [True, False])
def test_compiled_matches_numpy_on_noise(damping: float, free_tail: bool) -> None:
    rng = np.random.default_rng(7)
    dt = 0.01
    t = dt * np.arange(3000)
    accel = 9.81 * 0.3 * rng.standard_normal(t.size)
    omega = 2 * np.pi / PERIODS
    numpy_peak = peak_displacement(t, accel, omega, damping, free_tail=free_tail)
    compiled = peak_displacement_uniform(accel, dt, omega, damping, free_tail=free_tail)
    np.testing.assert_allclose(compiled, numpy_peak, rtol=1e-12, atol=0)


@pytest.mark.parametrize("path", sorted(PULSES.glob("*.txt")), ids=lambda p: p.name)
def test_record_spectrum_uses_it_with_the_same_values(path: object) -> None:
    record = read_record(str(path))
    Sa0, Sd0 = response_spectrum(record.time, record.accel, PERIODS)
    Sa1, Sd1 = response_spectrum(record.time, record.accel, PERIODS, compiled=True)
    np.testing.assert_allclose(Sd1, Sd0, rtol=1e-12, atol=0)
    np.testing.assert_allclose(Sa1, Sa0, rtol=1e-12, atol=0)
    spectrum = RecordSpectrum.from_record(record)
    assert spectrum.compiled
    assert spectrum.SDe(1.09) == pytest.approx(Sd0[2], rel=1e-12, abs=0)


def test_a_non_uniform_record_keeps_the_numpy_loop() -> None:
    t = np.array([0.0, 0.01, 0.02, 0.035, 0.05])
    assert uniform_step(t) is None
    assert uniform_step(0.01 * np.arange(5)) == pytest.approx(0.01)
    a = np.array([0.0, 0.1, -0.2, 0.05, 0.0])
    Sa, Sd = response_spectrum(t, a, [0.5], compiled=True)
    assert Sd[0] == response_spectrum(t, a, [0.5])[1][0]
