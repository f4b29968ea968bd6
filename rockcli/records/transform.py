"""Operations on records: scale, flip, trim, resample (spec/records.md, "Record operations").

Each function is pure: it returns a new Record with a note appended that says what was done,
and raises InputError for a bad argument.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from rockcli.errors import InputError
from rockcli.records.lines import (
    EDGE_TOL,
    MAX_ABS_ACCEL_G,
    MIN_RECORD_SAMPLES,
    check_dt,
    check_positive,
    check_sample_count,
)
from rockcli.records.record import Record


def _with(record: Record, note: str, **changes: Any) -> Record:
    """A copy of the record with some fields changed and a note appended."""
    return replace(record, notes=(*record.notes, note), **changes)


#: Relative loss of PGA beyond which a resampling warns (0.1 %).
PGA_LOSS_WARNING = 1e-3


def _check_bounded(record: Record, pga: float, *, where: str, value: float) -> None:
    """A scaled record must stay within ±MAX_ABS_ACCEL_G (as every record read does)."""
    if not pga <= MAX_ABS_ACCEL_G:
        raise InputError(
            f"the scaled record would reach {pga:.4g} g",
            file=record.source,
            where=where,
            value=value,
            allowed=f"a PGA ≤ {MAX_ABS_ACCEL_G:g} g",
        )


def scale(record: Record, factor: float) -> Record:
    """Multiply the accelerations by ``factor`` (> 0; use :func:`flip` to reverse polarity)."""
    check_positive(factor, where="factor", unit="[-]")
    _check_bounded(record, record.pga * factor, where="factor", value=factor)
    return _with(record, f"scaled by {factor:g}", accel=record.accel * factor)


def scale_to_pga(record: Record, pga: float) -> Record:
    """Scale the record so that max|a| equals ``pga`` [g] exactly.

    a/PGA is exactly ±1 at the peak (and ≤ 1 in magnitude elsewhere, IEEE division being
    monotonic), so the product with the target hits it to the last bit.
    """
    check_positive(pga, where="pga", unit="[g]")
    _check_bounded(record, pga, where="pga", value=pga)
    if record.pga == 0.0:
        raise InputError(
            "cannot scale a record of zero acceleration to a PGA",
            file=record.source,
            value=record.pga,
            allowed="a record with max|a| > 0",
        )
    note = f"scaled to PGA {pga:g} g (factor {pga / record.pga:.6g})"
    return _with(record, note, accel=record.accel / record.pga * pga)


def flip(record: Record) -> Record:
    """Reverse the polarity: a → −a (the record's mirror image)."""
    return _with(record, "polarity reversed", accel=-record.accel)


def _window(record: Record, t0: float, t1: float) -> np.ndarray:
    """Indices of the samples with t0 ≤ t ≤ t1 (edges within EDGE_TOL·dt count)."""
    start, end = float(record.time[0]), float(record.time[-1])
    tol = EDGE_TOL * record.dt
    if not (start - tol <= t0 < t1 <= end + tol):
        raise InputError(
            "time window outside the record",
            file=record.source,
            where="window",
            value=(t0, t1),
            allowed=f"{start:g} ≤ t0 < t1 ≤ {end:g} [s]",
        )
    return np.flatnonzero((record.time >= t0 - tol) & (record.time <= t1 + tol))


def trim(record: Record, t0: float, t1: float) -> Record:
    """Keep the samples in [t0, t1] [s] and re-zero the time at the first one kept."""
    kept = _window(record, t0, t1)
    if kept.size < 2:
        raise InputError(
            "time window holds fewer than 2 samples",
            file=record.source,
            where="window",
            value=(t0, t1),
            allowed=f"a window longer than dt = {record.dt:g} s",
        )
    time = record.time[kept] - record.time[kept[0]]
    note = f"trimmed to {t0:g}–{t1:g} s, time re-zeroed"
    return _with(record, note, time=time, accel=record.accel[kept])


def resample(record: Record, dt: float) -> Record:
    """Resample at a new uniform step dt [s] by linear interpolation (no anti-alias filter).

    dt within the bounds of every record read (:func:`rockcli.records.lines.check_dt`), at
    most MAX_SAMPLES samples and at least MIN_RECORD_SAMPLES (InputError otherwise). A coarser
    step can miss the peak: when the PGA drops by more than PGA_LOSS_WARNING, the record
    carries a warning saying how much.
    """
    check_dt(dt, file=None, where="dt")
    wanted = record.duration / dt * (1.0 + EDGE_TOL) + 1.0
    count = check_sample_count(wanted, where="dt", what=f"resampling at dt = {dt:g} s")
    if count < MIN_RECORD_SAMPLES:
        raise InputError(
            f"resampling at dt = {dt:g} s leaves {count} sample(s) of the {record.duration:g} s "
            "record",
            file=record.source,
            where="dt",
            value=dt,
            allowed=f"dt ≤ {record.duration:g} s (at least {MIN_RECORD_SAMPLES} samples)",
        )
    time = record.time[0] + np.arange(count) * dt
    accel = np.interp(time, record.time, record.accel)
    note = f"resampled from dt = {record.dt:g} s to {dt:g} s (linear interpolation)"
    resampled = _with(record, note, time=time, accel=accel, dt=dt)
    return replace(resampled, warnings=(*record.warnings, *_pga_loss(record, resampled)))


def _pga_loss(before: Record, after: Record) -> tuple[str, ...]:
    """A warning when resampling lowered the PGA by more than PGA_LOSS_WARNING."""
    if before.pga == 0.0:
        return ()
    loss = 1.0 - after.pga / before.pga
    if loss <= PGA_LOSS_WARNING:
        return ()
    return (f"resampling to dt = {after.dt:g} s lowered the PGA by {loss:.2%} "
            f"({before.pga:.4g} g → {after.pga:.4g} g): a smaller dt keeps the peak",)  # fmt: skip
