"""The suite's tolerance band as the verdict line says it (rockcli.terminal.suite.band_text):
each bound to the digits the file gives (issue 34 F18: a band of [-0.999, 0.001] was said
"-100% / +0%", which reads as no lower bound and no room above the target)."""

from __future__ import annotations

import pytest

from rockcli.terminal.suite import band_text


@pytest.mark.parametrize(
    ("tolerance", "text"),
    [
        ([-0.10, 0.30], "-10% / +30%"),
        ([-0.10, None], "-10% / no upper bound"),
        ([-0.999, 0.001], "-99.9% / +0.1%"),
        ([-0.5, 0.0], "-50% / +0%"),
        ([-0.125, 0.0625], "-12.5% / +6.25%"),
    ],
)
def test_the_band_says_each_bound_to_its_digits(tolerance: list[float | None], text: str) -> None:
    assert band_text(tolerance) == text
