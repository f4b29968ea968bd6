"""The --periods parser (rockcli.records.periods): any text gives periods or one InputError."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD, parse_periods

#: The characters of both forms, and of what a user might mistype in them.
ALPHABET = "0123456789.,:-+eE _naifINF\t;/x"
IN_RANGE = st.floats(MIN_PERIOD, MAX_PERIOD)


@settings(max_examples=500, deadline=None)
@given(text=st.one_of(st.text(alphabet=ALPHABET, max_size=30), st.text(max_size=30)))
def test_any_text_is_periods_or_one_input_error(text: str) -> None:
    try:
        periods = parse_periods(text)
    except InputError as exc:
        assert exc.where == "--periods" and exc.value == text
        assert "\n" not in exc.problem
        return
    assert periods.ndim == 1 and periods.size >= 1
    assert np.all(np.diff(periods) > 0)  # sorted, no repeats
    assert all(math.isfinite(p) and MIN_PERIOD <= p <= MAX_PERIOD for p in periods)


@settings(max_examples=200, deadline=None)
@given(values=st.lists(IN_RANGE, min_size=1, max_size=20))
def test_a_list_gives_its_periods_sorted(values: list[float]) -> None:
    text = ",".join(repr(v) for v in values)
    assert parse_periods(text).tolist() == sorted(set(values))


@settings(max_examples=200, deadline=None)
@given(a=IN_RANGE, b=IN_RANGE, n=st.integers(2, 300))
def test_a_range_is_log_spaced_between_its_ends(a: float, b: float, n: int) -> None:
    start, stop = sorted((a, b))
    if not start < stop:
        return
    periods = parse_periods(f"{start!r}:{stop!r}:{n}")
    assert periods[0] == start and periods[-1] == stop
    assert periods.size <= n  # fewer only where the ratio rounds two periods together
    ratios = periods[1:] / periods[:-1]
    if periods.size == n:
        # geometric: equal ratios, to the rounding of a power, 1e-9
        assert ratios == pytest.approx(np.full(n - 1, ratios[0]), rel=1e-9)
