"""Intensity measures (rockcli/studies/fragility/intensity.py) against closed forms.

A sine a(t) = A·sin(ωt) [g] over whole periods: PGA = A (a sample on each crest), and the
velocity from rest v(t) = A·g·(1 − cos ωt)/ω, so PGV = 2·A·g/ω; the trapezoidal rule's error
is O((ω·dt)²): 1e-5 relative at 2000 samples a period. Sa at a period far below the motion's
is the PGA (a rigid oscillator follows the ground): 0.5 % at T = 0.02 s under a 2 s sine."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.studies.fragility.intensity import ground_velocity, pga, pga_ratio, pgv, pgv_ratio, sa
from rockcli.units import DEFAULT_GRAVITY as G

A, PERIOD = 0.3, 2.0
OMEGA = 2 * math.pi / PERIOD
TIME = np.linspace(0.0, 3 * PERIOD, 3 * 2000 + 1)
ACCEL = A * np.sin(OMEGA * TIME)


def test_pga_of_a_sine() -> None:
    assert pga(ACCEL) == pytest.approx(A, rel=1e-9)


def test_pgv_of_a_sine_from_rest() -> None:
    assert pgv(TIME, ACCEL) == pytest.approx(2 * A * G / OMEGA, rel=1e-5)
    v = ground_velocity(TIME, ACCEL)
    assert v[0] == 0.0 and v[-1] == pytest.approx(0.0, abs=1e-6)  # whole periods


def test_sa_of_a_stiff_oscillator_is_the_pga() -> None:
    assert sa(TIME, ACCEL, 0.02) == pytest.approx(A, rel=5e-3)
    assert sa(TIME, ACCEL, 0.0) == pga(ACCEL)


def test_the_dimensionless_measures() -> None:
    assert pga_ratio(0.3, 0.1) == pytest.approx(3.0)
    assert pgv_ratio(0.5, 2.0, 0.1) == pytest.approx(0.5 * 2.0 / (G * 0.1))


def test_a_non_finite_record_is_refused() -> None:
    with pytest.raises(ValueError):
        pga(np.array([0.1, np.inf]))
    with pytest.raises(ValueError):
        pgv(np.array([0.0, 1.0]), np.array([0.1, np.nan]))
