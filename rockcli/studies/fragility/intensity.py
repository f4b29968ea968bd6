"""Intensity measures of a ground motion, for fragility curves and overturning spectra.

- PGA [g]: the largest |a| of the samples.
- PGV [m/s]: the largest |v| of the ground velocity, integrated from the acceleration with the
  trapezoidal rule from rest (v(t0) = 0), which is exact for an acceleration linear between
  samples, as rock reads a record. No baseline correction is applied: a processed record (PEER
  AT2, ESM, ITACA) is corrected already; an uncorrected one whose velocity drifts gives a PGV
  that includes the drift.
- Sa(T) [g]: the 5 %-damped pseudo-acceleration ω²·Sd/g at the period T (Nigam & Jennings
  1969, rockcli.codecheck.response.response_spectrum); at T = 0, the PGA.
- The dimensionless measures of the rocking literature (Makris & Konstantinidis 2003, EESD
  32:265–289): PGA/(g·tan α) and PGV·p/(g·tan α), with tan α the block's uplift acceleration
  [g] (a mechanism's α0 in its place).

Pure and silent: a non-finite measure is a ValueError (the record holds a non-finite value).
"""

from __future__ import annotations

import math

import numpy as np

from rockcli.units import DEFAULT_GRAVITY

#: Damping of the Sa(T) measure, as a fraction of critical.
SA_DAMPING = 0.05


def pga(accel_g: np.ndarray) -> float:
    """Peak ground acceleration [g]."""
    return _finite(float(np.max(np.abs(accel_g))), "PGA")


def ground_velocity(
    time: np.ndarray, accel_g: np.ndarray, g: float = DEFAULT_GRAVITY
) -> np.ndarray:
    """v(t_k) [m/s] at each sample, from rest: the trapezoidal integral of a·g."""
    a = np.asarray(accel_g, dtype=float) * g
    steps = np.diff(np.asarray(time, dtype=float))
    return np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * steps)])


def pgv(time: np.ndarray, accel_g: np.ndarray, g: float = DEFAULT_GRAVITY) -> float:
    """Peak ground velocity [m/s] (module docstring: integrated, no baseline correction)."""
    return _finite(float(np.max(np.abs(ground_velocity(time, accel_g, g)))), "PGV")


def sa(time: np.ndarray, accel_g: np.ndarray, period: float, g: float = DEFAULT_GRAVITY) -> float:
    """Sa(T) [g], 5 % damped (module docstring)."""
    from rockcli.codecheck.response import response_spectrum

    values, _ = response_spectrum(time, accel_g, [period], SA_DAMPING, g)
    return _finite(float(values[0]), "Sa(T)")


def pga_ratio(pga_g: float, uplift_g: float) -> float:
    """PGA/(g·tan α): the PGA over the uplift acceleration (both in g)."""
    return pga_g / uplift_g


def pgv_ratio(pgv_ms: float, p: float, uplift_g: float, g: float = DEFAULT_GRAVITY) -> float:
    """PGV·p/(g·tan α), with p the frequency parameter [rad/s]."""
    return pgv_ms * p / (g * uplift_g)


def _finite(value: float, name: str) -> float:
    if not math.isfinite(value):
        raise ValueError(f"the {name} of the record is not finite")
    return value
