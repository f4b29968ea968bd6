"""Synthetic acceleration pulses, as Records in g (format "pulse", source "generated").

The sine pulses share ωp = 2π/Tp:

* rectangular: a = ap for 0 ≤ t < td (Housner 1963, "The behavior of inverted pendulum
  structures during earthquakes", BSSA 53(2), rectangular pulse of duration t1);
* half-sine: a = ap·sin(ωp t), 0 ≤ t ≤ π/ωp = Tp/2 (Housner 1963, half-cycle sine pulse);
* one-sine: a = ap·sin(ωp t), 0 ≤ t ≤ 2π/ωp (Makris & Roussos 2000, "Rocking response of rigid
  blocks under near-source ground motions", Géotechnique 50(3), type A);
* one-cosine: a = ap·cos(ωp t), 0 ≤ t ≤ 2π/ωp (Makris & Roussos 2000, type B);
* Ricker: a = ap·(1 − 2π²fp²τ²)·exp(−π²fp²τ²), τ = t − tc, fp = 1/Tp (Ricker 1943, "Further
  developments in the wavelet theory of seismogram structure", BSSA 33(3)).

After the pulse the ground is at rest (zeros) up to an optional total duration.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from rockcli.errors import InputError
from rockcli.records.kinds import PulseKind, RecordFormat
from rockcli.records.lines import (
    EDGE_TOL,
    MAX_ABS_ACCEL_G,
    check_dt,
    check_positive,
    check_sample_count,
)
from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD
from rockcli.records.record import Record
from rockcli.units import AccelUnit

#: Fewest samples a pulse may have (a coarser dt would not describe its shape).
MIN_SAMPLES = 8
#: Half-width of the Ricker support, in periods Tp: at ±1.5 Tp the wavelet is ~1e-8·ap.
RICKER_HALF_WIDTH = 1.5

Shape = Callable[[np.ndarray], np.ndarray]


def check_amplitude(amplitude: float) -> float:
    """ap [g] in (0, MAX_ABS_ACCEL_G], the bound of every record read (InputError otherwise)."""
    check_positive(amplitude, where="amplitude", unit="[g]")
    if amplitude > MAX_ABS_ACCEL_G:
        raise InputError(
            "out of range",
            where="amplitude",
            value=amplitude,
            allowed=f"0 < ap ≤ {MAX_ABS_ACCEL_G:g} g, as in every record rock reads",
        )
    return amplitude


def check_period(period: float) -> float:
    """Tp [s] in [MIN_PERIOD, MAX_PERIOD], the periods of a response spectrum (InputError)."""
    if not MIN_PERIOD <= period <= MAX_PERIOD:
        raise InputError(
            "out of range",
            where="period",
            value=period,
            allowed=f"{MIN_PERIOD:g} s ≤ Tp ≤ {MAX_PERIOD:g} s, the periods of a response spectrum",
        )
    return period


def _sample_count(length: float, dt: float, total: float | None) -> int:
    """Samples from t = 0 to max(length, total) [s]; total must not cut the pulse."""
    if total is not None:
        check_positive(total, where="duration", unit="[s]")
    if total is not None and total < length * (1.0 - EDGE_TOL):
        raise InputError(
            "the total duration is shorter than the pulse",
            where="duration",
            value=total,
            allowed=f"a duration ≥ {length:g} s (or none)",
        )
    if length / dt < MIN_SAMPLES - 1:
        raise InputError(
            "time step too coarse for the pulse",
            where="dt",
            value=dt,
            allowed=f"dt ≤ {length / (MIN_SAMPLES - 1):g} s ({MIN_SAMPLES} samples per pulse)",
        )
    end = length if total is None else max(length, total)
    wanted = end / dt * (1.0 + EDGE_TOL) + 1.0
    where = "dt" if end == length else "duration"  # the longer of the two sets the count
    return check_sample_count(wanted, where=where, what=f"a record of {end:g} s at dt = {dt:g} s")


def _pulse_record(
    shape: Shape, length: float, dt: float, total: float | None, *, name: str, note: str
) -> Record:
    """Sample ``shape`` on 0 ≤ t ≤ length, zeros after; checks dt and the total duration."""
    check_dt(dt, file=None, where="dt")
    time = np.arange(_sample_count(length, dt, total)) * dt
    inside = time <= length * (1.0 + EDGE_TOL)
    accel = np.where(inside, shape(time), 0.0)
    return Record(
        name=name,
        source="generated",
        format=str(RecordFormat.PULSE),
        time=time,
        accel=accel,
        dt=dt,
        unit=str(AccelUnit.G),
        notes=(note,),
    )


def rectangular(
    amplitude: float, duration: float, *, dt: float, total: float | None = None
) -> Record:
    """Rectangular pulse: ap [g] for 0 ≤ t < td [s], then 0 (Housner 1963).

    The last sample inside the pulse is at t < td, so a td that is a multiple of dt gives
    exactly td/dt samples at ap.
    """
    check_amplitude(amplitude)
    check_period(duration)  # td: the `period` of make_pulse
    end = duration - EDGE_TOL * dt

    def shape(t: np.ndarray) -> np.ndarray:
        return np.where(t < end, amplitude, 0.0)

    name = f"rectangular ap={amplitude:g}g td={duration:g}s"
    note = f"rectangular pulse (Housner 1963): ap = {amplitude:g} g, td = {duration:g} s"
    return _pulse_record(shape, duration, dt, total, name=name, note=note)


def _sine_family(
    kind: PulseKind, amplitude: float, period: float, dt: float, total: float | None
) -> Record:
    """The half-sine, one-sine and one-cosine pulses: ap·sin or ap·cos of ωp t."""
    check_amplitude(amplitude)
    omega = 2.0 * math.pi / check_period(period)
    trig, length, source = {
        PulseKind.HALF_SINE: (np.sin, period / 2.0, "Housner 1963"),
        PulseKind.ONE_SINE: (np.sin, period, "Makris & Roussos 2000, type A"),
        PulseKind.ONE_COSINE: (np.cos, period, "Makris & Roussos 2000, type B"),
    }[kind]

    def shape(t: np.ndarray) -> np.ndarray:
        return amplitude * trig(omega * t)

    name = f"{kind} ap={amplitude:g}g Tp={period:g}s"
    note = f"{kind} pulse ({source}): ap = {amplitude:g} g, Tp = {period:g} s"
    return _pulse_record(shape, length, dt, total, name=name, note=note)


def half_sine(amplitude: float, period: float, *, dt: float, total: float | None = None) -> Record:
    """Half-sine pulse ap·sin(2πt/Tp), 0 ≤ t ≤ Tp/2 (Housner 1963); ap [g], Tp [s]."""
    return _sine_family(PulseKind.HALF_SINE, amplitude, period, dt, total)


def one_sine(amplitude: float, period: float, *, dt: float, total: float | None = None) -> Record:
    """One-sine pulse ap·sin(ωp t), 0 ≤ t ≤ 2π/ωp (Makris & Roussos 2000, type A)."""
    return _sine_family(PulseKind.ONE_SINE, amplitude, period, dt, total)


def one_cosine(amplitude: float, period: float, *, dt: float, total: float | None = None) -> Record:
    """One-cosine pulse ap·cos(ωp t), 0 ≤ t ≤ 2π/ωp (Makris & Roussos 2000, type B)."""
    return _sine_family(PulseKind.ONE_COSINE, amplitude, period, dt, total)


def ricker(amplitude: float, period: float, *, dt: float, total: float | None = None) -> Record:
    """Ricker wavelet of peak ap [g] and period Tp = 1/fp [s], centred at tc = 1.5 Tp.

    a(t) = ap·(1 − 2π²fp²τ²)·exp(−π²fp²τ²), τ = t − tc (Ricker 1943); the support is
    0 ≤ t ≤ 3 Tp, where the tails have decayed to about 1e-8·ap.
    """
    check_amplitude(amplitude)
    centre = RICKER_HALF_WIDTH * check_period(period)

    def shape(t: np.ndarray) -> np.ndarray:
        arg = (math.pi * (t - centre) / period) ** 2
        return amplitude * (1.0 - 2.0 * arg) * np.exp(-arg)

    name = f"ricker ap={amplitude:g}g Tp={period:g}s"
    note = f"Ricker wavelet (Ricker 1943): ap = {amplitude:g} g, Tp = 1/fp = {period:g} s"
    return _pulse_record(shape, 2.0 * centre, dt, total, name=name, note=note)


def make_pulse(
    kind: PulseKind | str,
    amplitude: float,
    period: float,
    *,
    dt: float,
    total: float | None = None,
) -> Record:
    """A pulse by kind; ``period`` is Tp [s] (for the rectangular pulse: its duration td).

    Raises:
        InputError: an unknown kind, ap outside (0, 100] g, Tp outside [0.001, 100] s, dt
            outside [1e-9, 1] s, a total duration shorter than the pulse, or too many samples.
    """
    try:
        chosen = PulseKind(str(kind))
    except ValueError:
        raise InputError(
            "unknown pulse kind",
            where="kind",
            value=str(kind),
            allowed=", ".join(PulseKind),
        ) from None
    if chosen is PulseKind.RECTANGULAR:
        return rectangular(amplitude, period, dt=dt, total=total)
    if chosen is PulseKind.RICKER:
        return ricker(amplitude, period, dt=dt, total=total)
    return _sine_family(chosen, amplitude, period, dt, total)
