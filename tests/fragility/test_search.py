"""The first-exceedance search (rockcli/studies/fragility/search.py) on responses whose thresholds
are known by construction: a monotonic response, and a non-monotonic one where a bisection
over the whole range converges to the wrong boundary."""

from __future__ import annotations

import math

import pytest

from rockcli.studies.fragility.search import first_exceedances


def test_a_monotonic_response_is_found_to_the_tolerance() -> None:
    # response = 2·scale: level L is first reached at scale L/2
    found, runs = first_exceedances(lambda s: 2.0 * s, [0.1, 0.5, 1.0], first=0.01, step=0.1,
                                    last=2.0, tolerance=1e-6)  # fmt: skip
    for ex, level in zip(found, [0.1, 0.5, 1.0], strict=True):
        assert ex.scale is not None and ex.below is not None
        assert ex.below < level / 2.0 <= ex.scale
        assert ex.scale - level / 2.0 <= 1e-6
    assert runs < 100  # the scan's 6 steps and about 17 bisections per level, shared


def overturns_twice(scale: float) -> float:
    """Overturns (inf) on [0.30, 0.40], survives (0.3) above it up to 1.0, overturns from
    1.0 on: the "safe region" above a first overturning window."""
    if 0.3 <= scale <= 0.4 or scale >= 1.0:
        return math.inf
    return 0.3 if scale > 0.4 else 0.5 * scale


def test_a_safe_region_does_not_hide_the_first_overturn() -> None:
    found, _ = first_exceedances(overturns_twice, [math.inf], first=0.05, step=0.05, last=2.0,
                                 tolerance=1e-6)  # fmt: skip
    assert found[0].scale == pytest.approx(0.3, abs=1e-6)


def bisect(response, lo: float, hi: float, level: float) -> float:  # type: ignore[no-untyped-def]
    """A bisection over the whole range (what the search must not be)."""
    while hi - lo > 1e-6:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if response(mid) >= level else (mid, hi)
    return hi


def test_bisection_alone_finds_another_boundary() -> None:
    # the case the search exists for: from [0.05, 2.0] a bisection lands on 1.0, not 0.3
    assert bisect(overturns_twice, 0.05, 2.0, math.inf) == pytest.approx(1.0, abs=1e-5)


def test_a_window_narrower_than_the_step_is_missed_and_the_step_says_so() -> None:
    # overturning only on [0.52, 0.53]: a scan at 0.05 steps (0.50, 0.55) does not see it
    def narrow(scale: float) -> float:
        return math.inf if 0.52 <= scale <= 0.53 or scale >= 1.0 else 0.1

    coarse, _ = first_exceedances(narrow, [math.inf], first=0.05, step=0.05, last=2.0,
                                  tolerance=1e-6)  # fmt: skip
    fine, _ = first_exceedances(narrow, [math.inf], first=0.05, step=0.005, last=2.0,
                                tolerance=1e-6)  # fmt: skip
    assert coarse[0].scale == pytest.approx(1.0, abs=1e-6)
    assert fine[0].scale == pytest.approx(0.52, abs=1e-6)


def test_a_level_never_reached_and_one_reached_at_once() -> None:
    found, _ = first_exceedances(lambda s: s, [0.01, 5.0], first=0.1, step=0.1, last=1.0,
                                 tolerance=1e-3)  # fmt: skip
    assert found[0].scale == 0.1 and found[0].below is None
    assert found[1].scale is None


@pytest.mark.parametrize(
    "kwargs",
    [
        {"first": 0.0, "step": 0.1, "last": 1.0, "tolerance": 1e-3},
        {"first": 0.1, "step": 0.0, "last": 1.0, "tolerance": 1e-3},
        {"first": 0.5, "step": 0.1, "last": 0.4, "tolerance": 1e-3},
    ],
)
def test_an_empty_or_non_positive_scan_is_refused(kwargs: dict[str, float]) -> None:
    with pytest.raises(ValueError):
        first_exceedances(lambda s: s, [0.5], **kwargs)


def test_levels_out_of_order_are_refused() -> None:
    with pytest.raises(ValueError):
        first_exceedances(lambda s: s, [0.5, 0.1], first=0.1, step=0.1, last=1.0, tolerance=1e-3)


def test_a_tolerance_below_the_float_spacing_ends() -> None:
    """Issue 34, F5: the bisection stops when the floats run out, whatever the tolerance."""
    found, _ = first_exceedances(
        lambda s: math.inf if s >= 0.3 else 0.0,
        [math.inf],
        first=0.1,
        step=0.1,
        last=1.0,
        tolerance=1e-300,
    )
    assert found[0].scale == pytest.approx(0.3, abs=1e-15)
