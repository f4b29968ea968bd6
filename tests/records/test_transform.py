"""Record transforms: scale, scale to PGA, flip, trim, resample (spec/records.md, operations)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from rockcli.errors import InputError
from rockcli.records.record import Record
from rockcli.records.transform import flip, resample, scale, scale_to_pga, trim


def noise_record(npts: int = 501, dt: float = 0.01, seed: int = 7) -> Record:
    """A reproducible random record (the transforms do not care about its physics)."""
    accel = np.random.default_rng(seed).normal(0.0, 0.1, npts)
    return Record("noise", "generated", "pulse", np.arange(npts) * dt, accel, dt)


@pytest.mark.parametrize("target", [0.35, 1.0, 0.123456789, 2.7e-3])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_scale_to_pga_hits_target_exactly(target: float, seed: int) -> None:
    """a/PGA is ±1 exactly at the peak, so the scaled peak equals the target to the bit."""
    scaled = scale_to_pga(noise_record(seed=seed), target)
    assert scaled.pga == target
    assert scaled.notes[-1].startswith(f"scaled to PGA {target:g} g")


def test_scale_by_factor() -> None:
    rec = noise_record()
    assert np.array_equal(scale(rec, 2.5).accel, rec.accel * 2.5)
    assert scale(rec, 2.5).notes == ("scaled by 2.5",)


def test_flip_is_an_involution() -> None:
    rec = noise_record()
    twice = flip(flip(rec))
    assert np.array_equal(twice.accel, rec.accel)
    assert np.array_equal(flip(rec).accel, -rec.accel)
    assert twice.notes == ("polarity reversed", "polarity reversed")


def test_trim_rezeros_time() -> None:
    rec = noise_record()
    cut = trim(rec, 1.0, 2.5)
    assert cut.time[0] == 0.0
    assert cut.npts == 151  # samples 100..250 of dt = 0.01 s
    assert np.array_equal(cut.accel, rec.accel[100:251])
    assert cut.duration == pytest.approx(1.5, abs=1e-12)


def test_resample_is_exact_on_a_linear_record() -> None:
    """Linear interpolation reproduces a linear signal a = 0.1·t."""
    rec = Record("ramp", "generated", "pulse", np.arange(11) * 0.1, np.arange(11) * 0.01, 0.1)
    fine = resample(rec, 0.025)
    assert fine.npts == 41 and fine.dt == 0.025
    assert fine.accel == pytest.approx(0.1 * fine.time, abs=1e-15)


def test_transforms_do_not_touch_the_input() -> None:
    rec = noise_record()
    before = rec.accel.copy()
    for result in (scale(rec, 3.0), flip(rec), trim(rec, 0.0, 1.0), resample(rec, 0.02)):
        assert result is not rec
    assert np.array_equal(rec.accel, before) and rec.notes == ()


@pytest.mark.parametrize(
    ("call", "where"),
    [
        (lambda r: scale(r, 0.0), "factor"),
        (lambda r: scale(r, float("nan")), "factor"),
        (lambda r: scale_to_pga(r, -0.3), "pga"),
        (lambda r: trim(r, 2.0, 1.0), "window"),
        (lambda r: trim(r, 0.0, 99.0), "window"),
        (lambda r: trim(r, 1.001, 1.002), "window"),
        (lambda r: resample(r, 0.0), "dt"),
    ],
)
def test_bad_transform_arguments(call: Callable[[Record], Record], where: str) -> None:
    with pytest.raises(InputError) as caught:
        call(noise_record())
    assert caught.value.where == where


def test_scale_to_pga_of_a_silent_record() -> None:
    rec = Record("zero", "generated", "pulse", np.arange(3) * 0.1, np.zeros(3), 0.1)
    with pytest.raises(InputError, match="zero acceleration"):
        scale_to_pga(rec, 0.3)
