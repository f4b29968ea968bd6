"""A record's displacement demand over [T0, T] reads the record spectrum's ordinates on its
period grid at once (RecordSpectrum.SDe_grid, and a scaled record's and a suite mean's): the
same numbers, bit for bit, as the ordinates read one by one, and the same grid, maximum and
period as the point-by-point range maximum."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.codecheck.demand import (
    RANGE_STEP,
    MeanSpectrum,
    ScaledSpectrum,
    grid_SDe,
    grid_values,
    period_grid,
    range_maximum,
)
from rockcli.codecheck.response import RecordSpectrum


def record(seed: int) -> RecordSpectrum:
    """A short synthetic record (white noise, 0.01 s, 8 s)."""
    rng = np.random.default_rng(seed)
    t = np.arange(800) * 0.01
    return RecordSpectrum(t, 0.2 * rng.standard_normal(t.size))


SPECTRA = {
    "record": record(1),
    "scaled": ScaledSpectrum(record(2), 1.7),
    "mean": MeanSpectrum((record(3), record(4), record(5))),
}


@pytest.mark.parametrize("name", sorted(SPECTRA))
def test_grid_ordinates_are_the_ordinates_one_by_one(name: str) -> None:
    spectrum = SPECTRA[name]
    for first, last in ((1, 40), (30, 90), (5, 12), (90, 120)):  # growing, overlapping windows
        at_once = grid_SDe(spectrum, first, last, 8.0)
        one_by_one = [spectrum.SDe(k * RANGE_STEP, 8.0) for k in range(first, last + 1)]
        assert at_once.tolist() == one_by_one


@settings(max_examples=80, deadline=None)
@given(st.one_of(st.just(0.0), st.floats(1e-4, 1.5)), st.one_of(st.just(0.0), st.floats(1e-6, 1.5)))
def test_the_grid_and_its_maximum_are_the_point_by_point_ones(lo: float, span: float) -> None:
    spectrum = SPECTRA["record"]
    hi = lo + span

    def f(T: float) -> float:
        return spectrum.SDe(T, 8.0)

    def on_grid(first: int, last: int) -> np.ndarray:
        return grid_SDe(spectrum, first, last, 8.0)

    periods, values = grid_values(f, lo, hi, on_grid)
    assert periods == period_grid(lo, hi)
    assert values == [f(T) for T in periods]
    assert range_maximum(f, lo, hi, on_grid) == range_maximum(f, lo, hi)
