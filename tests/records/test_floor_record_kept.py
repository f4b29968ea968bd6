"""rockcli.analyses.floor.floor_record filters a record once per record object and floor in a
process: the same motion, bit for bit, as filtering it again, and read-only."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from rockcli.analyses.floor import Floor, floor_record
from rockcli.codecheck.floor import floor_motion
from rockcli.records.record import Record


def record() -> Record:
    t = np.arange(0.0, 5.0, 0.01)
    return Record(name="sine", source="generated", format="pulse", time=t,
                  accel=0.2 * np.sin(2.0 * np.pi * t), dt=0.01)  # fmt: skip


def test_the_kept_motion_is_the_filtered_one() -> None:
    rec = record()
    floor = Floor(Z=4.0, T1=0.3, psi=0.5, gamma=1.2, xi=0.05)
    first, again = floor_record(rec, floor), floor_record(rec, floor)
    assert again.accel is first.accel  # filtered once
    expected = floor_motion(rec.time, rec.accel, T1=0.3, psi=0.5, gamma=1.2, xi=0.05)
    assert np.array_equal(first.accel, expected)
    with pytest.raises(ValueError):
        first.accel[0] = 1.0  # read-only: no caller can change another's motion
    other = floor_record(rec, Floor(Z=4.0, T1=0.4, psi=0.5, gamma=1.2, xi=0.05))
    assert not np.array_equal(other.accel, first.accel)


def test_another_record_with_the_same_floor_is_filtered_anew() -> None:
    floor = Floor(Z=4.0, T1=0.3, psi=0.5, gamma=1.2, xi=0.05)
    a = floor_record(record(), floor)
    rec = record()
    scaled = replace(rec, name="sine x2", accel=2.0 * rec.accel)
    b = floor_record(scaled, floor)
    assert np.allclose(b.accel, 2.0 * a.accel, rtol=1e-12, atol=1e-15)
