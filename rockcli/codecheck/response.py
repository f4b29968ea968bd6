"""The elastic response spectrum of a recorded accelerogram (the demand of the paper's comparison).

spec/ntc.md, "Elastic response spectrum": when the demand is a record, its own elastic
spectrum (pseudo-acceleration Sa, displacement Sd) replaces Se/SDe and its PGA replaces ag·S.

Method: exact integration of the linear oscillator u'' + 2ζωu' + ω²u = −a_g(t) for a ground
acceleration linear between samples (Nigam & Jennings 1969; the recurrence of Chopra, *Dynamics
of Structures*, §5.2, Table 5.2.1). The oscillator is at rest at the first sample.

Decisions (see the functions for details):

- **Damping units.** :func:`response_spectrum` takes ``damping`` as a **fraction** of critical
  (0.05), like the dynamics literature; :class:`RecordSpectrum` offers ``Se(T, xi)`` and
  ``SDe(T, xi)`` with ξ in **percent** (5.0), like :class:`~rockcli.codecheck.spectra.
  ElasticSpectrum`, so that the checks can take either as the demand.
- **Non-uniform records** are integrated exactly as they are: the recurrence coefficients are
  computed again whenever the step changes (no resampling, no error).
- **Free vibration after the record.** The peak includes the oscillator's free vibration after
  the last sample (the ground at rest there, a_g = 0), computed in closed form: for long
  periods the largest displacement can come after the shaking ends. ``free_tail=False`` gives
  the peak over the record's duration only, as many programs do.
- **Vectorisation.** The reference: a Python loop over time steps, each step a numpy operation
  on all periods at once. Measured on this machine (2 cores; ELC180-sized record, 4000 samples × 100
  periods, best of 5): 21 ms, against 0.27 s for a loop over periods with a scalar Python loop
  over time, and 5 ms for a loop over periods with ``scipy.signal.lfilter`` (uniform steps
  only, and its start-up differs unless the first sample is zero). The time loop is kept: one
  code path, exact on non-uniform records, fast enough (a check needs a handful of periods).
- **Compiled fast path** (``compiled=True``, what :class:`RecordSpectrum` uses): for a record
  whose steps all match the first one (the very records on which the loop above never
  recomputes its coefficients), the same recurrence with the same coefficients runs in
  :func:`rockcli.codecheck.response_kernel.peak_response` (numba), one compiled loop per
  period. The numpy loop costs one numpy call per sample whatever the number of periods:
  0.67 s for one period of AQV_EW_ITACA.cor.acc (112,600 samples), against ≈ 0.4 ms compiled;
  a study evaluates one period per case (the secant period). Same arithmetic in the same
  order: the results agree with the numpy loop to the last bit (tested to 1e-12). Non-uniform
  records keep the numpy loop.

Pure and silent: numpy only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike

from rockcli.errors import InputError
from rockcli.units import DEFAULT_GRAVITY

#: Damping of the record spectrum used by the checks, as a fraction of critical (spec/ntc.md).
DEFAULT_DAMPING = 0.05
#: Two steps whose lengths differ by less than this (relative) share the same coefficients.
STEP_MATCH = 1e-9
#: Oscillator-steps per compiled call of the uniform-step recurrence (periods × samples): about
#: 25 ms on this machine (5 ns a step), so that Ctrl-C is answered within that (a call cannot
#: be interrupted inside; rockcli.interrupts).
CHUNK_SAMPLES = 5_000_000


def response_spectrum(
    time: ArrayLike,
    accel_g: ArrayLike,
    periods: ArrayLike,
    damping: float = DEFAULT_DAMPING,
    g: float = DEFAULT_GRAVITY,
    *,
    free_tail: bool = True,
    compiled: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Pseudo-acceleration Sa [g] and displacement Sd [m] spectra of a record.

    Nigam & Jennings (1969), exact for a ground acceleration linear between samples.
    Sa = ω²·Sd/g; at T = 0, Sa is the PGA and Sd is 0.

    Args:
        time: sample times [s], strictly increasing (uniform or not).
        accel_g: ground acceleration at those times [g].
        periods: oscillator periods [s], ≥ 0.
        damping: viscous damping ratio as a **fraction** of critical, 0 ≤ ζ < 1 (0.05 = 5 %).
        g: gravity [m/s²] turning the record's g into m/s².
        free_tail: include the free vibration after the last sample in the peak.
        compiled: use the compiled recurrence when the steps are uniform (same results; it
            imports numba).

    Raises:
        InputError: bad record, periods or damping.
    """
    t, a = _check_record(time, accel_g)
    T = _check_periods(periods)
    _check_damping(damping)
    Sd = np.zeros(T.size)
    Sa = np.full(T.size, float(np.max(np.abs(a))))  # T = 0: the rigid oscillator, the PGA
    moving = T > 0
    if moving.any():
        omega = 2.0 * math.pi / T[moving]
        dt = uniform_step(t) if compiled else None
        if dt is None:
            Sd[moving] = peak_displacement(t, a * g, omega, damping, free_tail=free_tail)
        else:
            Sd[moving] = peak_displacement_uniform(a * g, dt, omega, damping, free_tail=free_tail)
        Sa[moving] = omega**2 * Sd[moving] / g
    return Sa, Sd


def peak_displacement(
    time: np.ndarray,
    accel: np.ndarray,
    omega: np.ndarray,
    damping: float,
    *,
    free_tail: bool = True,
) -> np.ndarray:
    """max |u(t)| [m] of oscillators of circular frequencies ω [rad/s] under a ground motion.

    Nigam & Jennings (1969); Chopra §5.2: the state (u, u̇) advances one step by
    x_{i+1} = A·x_i + b0·p_i + b1·p_{i+1} with p = −a_g.

    Args:
        time: sample times [s], strictly increasing.
        accel: ground acceleration [m/s²].
        omega: circular frequencies [rad/s], > 0.
        damping: fraction of critical, 0 ≤ ζ < 1.
        free_tail: include the free vibration after the last sample.
    """
    u = np.zeros(omega.size)
    v = np.zeros(omega.size)
    peak = np.zeros(omega.size)
    steps = np.diff(time)
    dt = math.nan
    for i, step in enumerate(steps):
        if not abs(step - dt) <= STEP_MATCH * step:
            dt = float(step)
            c = step_coefficients(dt, omega, damping)
        p0, p1 = -accel[i], -accel[i + 1]
        u, v = (
            c[0] * u + c[1] * v + c[2] * p0 + c[3] * p1,
            c[4] * u + c[5] * v + c[6] * p0 + c[7] * p1,
        )
        np.maximum(peak, np.abs(u), out=peak)
    if free_tail:
        np.maximum(peak, free_vibration_peak(u, v, omega, damping), out=peak)
    return peak


def uniform_step(time: np.ndarray) -> float | None:
    """The step [s] when every step matches the first within STEP_MATCH, else None.

    Exactly the records on which :func:`peak_displacement` computes its coefficients once.
    """
    steps = np.diff(time)
    dt = float(steps[0])
    return dt if bool(np.all(np.abs(steps - dt) <= STEP_MATCH * steps)) else None


def peak_displacement_uniform(
    accel: np.ndarray,
    dt: float,
    omega: np.ndarray,
    damping: float,
    *,
    free_tail: bool = True,
) -> np.ndarray:
    """:func:`peak_displacement` for uniform steps, by the compiled recurrence [m].

    Same equations, coefficients and order of operations (Nigam & Jennings 1969; Chopra
    §5.2), one compiled loop over time per frequency.

    Args:
        accel: ground acceleration at uniform steps [m/s²].
        dt: the step [s]. omega: circular frequencies [rad/s], > 0.
        damping: fraction of critical, 0 ≤ ζ < 1.
        free_tail: include the free vibration after the last sample.
    """
    from rockcli import interrupts, jitcache
    from rockcli.codecheck.response_kernel import peak_response

    jitcache.ensure_compiled()
    coefficients = np.array(step_coefficients(dt, omega, damping))
    load = np.ascontiguousarray(-accel)
    peak, u, v = np.empty(omega.size), np.empty(omega.size), np.empty(omega.size)
    # A few periods per compiled call, Ctrl-C checked between calls (rockcli.interrupts).
    width = max(1, CHUNK_SAMPLES // max(load.size, 1))
    with interrupts.deferred():
        for start in range(0, omega.size, width):
            part = slice(start, start + width)
            peak[part], u[part], v[part] = peak_response(
                load, np.ascontiguousarray(coefficients[:, part])
            )
            interrupts.check()
    if free_tail:
        np.maximum(peak, free_vibration_peak(u, v, omega, damping), out=peak)
    return peak


def step_coefficients(dt: float, omega: np.ndarray, damping: float) -> tuple[np.ndarray, ...]:
    """The eight coefficients A, B, C, D, A′, B′, C′, D′ of one step, per frequency.

    Chopra, *Dynamics of Structures*, Table 5.2.1 (unit mass, k = ω², force p = −a_g):
    u_{i+1} = A u_i + B u̇_i + C p_i + D p_{i+1}; u̇_{i+1} = A′ u_i + B′ u̇_i + C′ p_i + D′ p_{i+1}.

    Args:
        dt: step [s]. omega: circular frequencies [rad/s]. damping: fraction, 0 ≤ ζ < 1.
    """
    z = damping
    root = math.sqrt(1.0 - z * z)
    wd = omega * root
    e = np.exp(-z * omega * dt)
    s, c = np.sin(wd * dt), np.cos(wd * dt)
    k = omega**2
    zr = z / root
    two_z_wdt = 2.0 * z / (omega * dt)
    A = e * (zr * s + c)
    B = e * s / wd
    C = (two_z_wdt + e * (((1 - 2 * z * z) / (wd * dt) - zr) * s - (1 + two_z_wdt) * c)) / k
    D = (1 - two_z_wdt + e * ((2 * z * z - 1) / (wd * dt) * s + two_z_wdt * c)) / k
    A1 = -e * omega / root * s
    B1 = e * (c - zr * s)
    C1 = (-1 / dt + e * ((omega / root + zr / dt) * s + c / dt)) / k
    D1 = (1 - e * (zr * s + c)) / (k * dt)
    return A, B, C, D, A1, B1, C1, D1


def free_vibration_peak(
    u: np.ndarray, v: np.ndarray, omega: np.ndarray, damping: float
) -> np.ndarray:
    """Largest |u| of the damped free vibration starting from (u, u̇) [m].

    Closed form (Chopra Eq. 2.2.4): successive extrema of a damped free vibration shrink, so
    the largest |u| is |u0| or the first turning point, at the first t ≥ 0 with u̇(t) = 0,
    i.e. tan(ω_D t) = u̇0·ω_D / (ω² u0 + ζω u̇0), ω_D t in [0, π).

    Args:
        u, v: displacement [m] and velocity [m/s] at the last sample.
        omega: circular frequencies [rad/s]. damping: fraction, 0 ≤ ζ < 1.
    """
    z = damping
    wd = omega * math.sqrt(1.0 - z * z)
    # u̇(t) = e^{−ζωt}[v cos ω_D t − (ω² u + ζω v)/ω_D sin ω_D t]: first zero at angle φ.
    phi = np.mod(np.arctan2(v * wd, omega**2 * u + z * omega * v), math.pi)
    t = phi / wd
    B = (v + z * omega * u) / wd
    turning = np.exp(-z * omega * t) * (u * np.cos(wd * t) + B * np.sin(wd * t))
    return np.maximum(np.abs(u), np.abs(turning))


def step_overshoot(damping: float) -> float:
    """Peak of a damped oscillator's response to a suddenly applied constant force, over the
    static response: 1 + exp(−πζ/√(1 − ζ²)) (2 undamped).

    Chopra, *Dynamics of Structures*, §4.3 (step force): u(t)/u_st = 1 − e^{−ζωt}(cos ω_D t +
    ζ/√(1 − ζ²)·sin ω_D t), whose first and largest peak is at ω_D t = π.

    Args:
        damping: fraction of critical, 0 ≤ ζ < 1.
    """
    _check_damping(damping)
    return 1.0 + math.exp(-math.pi * damping / math.sqrt(1.0 - damping * damping))


def rigid_limit(accel_g: ArrayLike, damping: float) -> float:
    """Sa [g] of a stiff oscillator (T → 0) at rest at the first sample of a record.

    It follows the ground (Sa → PGA), except for a record that starts away from zero: the
    jump from rest to a_g(0) is a step force, which it overshoots by :func:`step_overshoot`
    (Chopra §4.3), so the limit is max(PGA, overshoot·|a_g(0)|).

    Args:
        accel_g: ground acceleration [g]. damping: fraction of critical, 0 ≤ ζ < 1.
    """
    a = np.asarray(accel_g, dtype=float)
    return max(float(np.max(np.abs(a))), step_overshoot(damping) * abs(float(a[0])))


def _check_record(time: ArrayLike, accel_g: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    t = np.asarray(time, dtype=float)
    a = np.asarray(accel_g, dtype=float)
    if t.ndim != 1 or a.shape != t.shape or t.size < 2:
        raise InputError(
            "time and acceleration must be 1-D arrays of the same length ≥ 2",
            where="record",
            value=f"{t.shape} and {a.shape}",
        )
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(a))):
        raise InputError("the record has non-finite values", where="record")
    if not np.all(np.diff(t) > 0):
        raise InputError("the sample times must increase strictly", where="record.time")
    return t, a


def _check_periods(periods: ArrayLike) -> np.ndarray:
    T = np.atleast_1d(np.asarray(periods, dtype=float))
    if T.ndim != 1 or not np.all(np.isfinite(T)) or np.any(T < 0):
        raise InputError("periods out of range", where="periods", allowed="T ≥ 0 [s]")
    return T


def _check_damping(damping: float) -> None:
    if not 0.0 <= damping < 1.0:
        raise InputError(
            "damping out of range",
            where="damping",
            value=damping,
            allowed="a fraction of critical, 0 ≤ ζ < 1 (0.05 = 5 %)",
        )


class _Samples(Protocol):
    """A record as the spectrum needs it (:class:`rockcli.records.record.Record` is one)."""

    @property
    def time(self) -> np.ndarray: ...

    @property
    def accel(self) -> np.ndarray: ...


@dataclass(frozen=True, eq=False)
class RecordSpectrum:
    """A record's own elastic spectrum, computed on demand (the demand of a record).

    Same interface as :class:`~rockcli.codecheck.spectra.ElasticSpectrum`: ``Se(T, xi)`` [g],
    ``SDe(T, xi)`` [m] with ξ in **percent**, ``pga_ground`` [g], ``curve``. Values are cached
    by (T, ξ).

    Attributes:
        time: sample times [s], strictly increasing.
        accel: ground acceleration [g].
        g: gravity [m/s²].
        free_tail: include the free vibration after the record in the peaks.
        compiled: the compiled recurrence on uniform records (same values, see the module).
    """

    time: np.ndarray
    accel: np.ndarray
    g: float = DEFAULT_GRAVITY
    free_tail: bool = True
    compiled: bool = True
    _cache: dict[tuple[float, float], tuple[float, float]] = field(
        default_factory=dict, init=False, repr=False
    )
    _grids: dict[tuple[float, float], np.ndarray] = field(
        default_factory=dict, init=False, repr=False
    )

    def __post_init__(self) -> None:
        t, a = _check_record(self.time, self.accel)
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "accel", a)
        if not (math.isfinite(self.g) and self.g > 0):
            raise InputError("must be a finite number > 0", where="g", value=self.g)

    @classmethod
    def from_record(
        cls, record: _Samples, g: float = DEFAULT_GRAVITY, *, free_tail: bool = True
    ) -> RecordSpectrum:
        """The spectrum of a :class:`rockcli.records.record.Record` (its time [s], accel [g])."""
        return cls(record.time, record.accel, g, free_tail)

    @property
    def pga_ground(self) -> float:
        """The record's PGA max |a_g| [g] (in place of ag·S)."""
        return float(np.max(np.abs(self.accel)))

    def Se(self, T: float, xi: float = 5.0) -> float:
        """Pseudo-acceleration Sa(T) [g] at damping ξ [%] (5.0 = 5 %)."""
        return self._value(T, xi)[0]

    def SDe(self, T: float, xi: float = 5.0) -> float:
        """Displacement Sd(T) [m] at damping ξ [%] (5.0 = 5 %)."""
        return self._value(T, xi)[1]

    def _value(self, T: float, xi: float) -> tuple[float, float]:
        """(Sa [g], Sd [m]) at one period: the cached pair as it is (a pair is cached once its
        period was checked), else :meth:`_values`'. The 2019 demand of a record reads a few
        hundred cached ordinates per check (rockcli.codecheck.demand.range_maximum), for
        which checking the period again as an array cost more than the rest of the check."""
        cached = self._cache.get((float(T), float(xi)))
        if cached is not None:
            return cached
        Sa, Sd = self._values(np.array([T]), xi)
        return float(Sa[0]), float(Sd[0])

    def SDe_grid(self, first: int, last: int, step: float, xi: float = 5.0) -> np.ndarray:  # noqa: N802
        """Sd [m] at the periods k·step, k = first … last (first ≥ 1), damping ξ [%]: the
        values :meth:`SDe` gives there, kept as an array by grid index, so that a check's
        range of periods (rockcli.codecheck.demand.range_maximum) is read in one slice."""
        table = self._grids.get((step, float(xi)), np.empty(0))
        if len(table) <= last:
            table = np.concatenate((table, np.full(last + 1 - len(table), np.nan)))
            self._grids[(step, float(xi))] = table
        unknown = first + np.flatnonzero(np.isnan(table[first : last + 1]))
        if len(unknown):
            table[unknown] = self._values(unknown * step, xi)[1]
        return table[first : last + 1].copy()

    def curve(self, periods: ArrayLike, xi: float = 5.0) -> tuple[np.ndarray, np.ndarray]:
        """Sa [g] and Sd [m] at an array of periods [s], damping ξ [%] (one vectorised pass)."""
        return self._values(np.asarray(periods, dtype=float).ravel(), xi)

    def _values(self, periods: np.ndarray, xi: float) -> tuple[np.ndarray, np.ndarray]:
        T = _check_periods(periods)
        missing = sorted({float(p) for p in T if (float(p), float(xi)) not in self._cache})
        if missing:
            Sa, Sd = response_spectrum(
                self.time,
                self.accel,
                np.array(missing),
                xi / 100.0,
                self.g,
                free_tail=self.free_tail,
                compiled=self.compiled,
            )
            for p, a, d in zip(missing, Sa, Sd, strict=True):
                self._cache[(p, float(xi))] = (float(a), float(d))
        pairs = [self._cache[(float(p), float(xi))] for p in T]
        return np.array([a for a, _ in pairs]), np.array([d for _, d in pairs])
