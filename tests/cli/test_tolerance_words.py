"""The words of the tolerance check (rockcli.terminal.tolerance) for the cases a real record
rarely gives: an overturning verdict that changes with the tolerance, a check that is not
known, a surviving block whose envelope moves; and how tolerances are written.

Source: the rule as docs/interpretations.md ("Tolerance check") states it; the documents here
are written by hand in the shape `rock assess --format json` gives.
"""

from __future__ import annotations

from typing import Any

import pytest

from rockcli.terminal.tolerance import (
    compare_rows,
    sensitive_warning,
    tol,
    tolerance_note,
    verdict_caveat,
)


def run(polarity: int, ratio: float, impacts: int, overturned: bool, **tight: Any) -> dict:
    """A run document and its check: at 1e-11, max θ/α 0.8 with 40 impacts, survived,
    sensitive, unless ``tight`` says otherwise (keys with a ``t_`` prefix)."""
    check = {"rtol": 1e-11, "max_ratio": 0.8, "impacts": 40, "overturned": False,
             "sensitive": True} | {k.removeprefix("t_"): v for k, v in tight.items()}  # fmt: skip
    return {"polarity": polarity, "max_ratio": ratio, "impacts": impacts,
            "overturned": overturned, "tolerance_check": check}  # fmt: skip


def doc(*runs: dict, verdict: str, max_ratio: float, sensitive: bool | None) -> dict:
    engine = {"name": "fast", "rtol": 1e-8, "atol": 1e-8, "tolerance_check": {
        "rtol": 1e-11, "atol": 1e-11, "factor": 1000.0, "max_ratio_change": 0.01}}  # fmt: skip
    return {"runs": list(runs), "engine": engine, "verdict": verdict, "max_ratio": max_ratio,
            "sensitive": sensitive}  # fmt: skip


@pytest.mark.parametrize(("x", "text"), [(1e-8, "1e-8"), (1e-11, "1e-11"), (2.5e-9, "2.5e-9")])
def test_tolerances_are_written_without_a_padded_exponent(x: float, text: str) -> None:
    assert tol(x) == text


def test_a_verdict_that_changes_is_read_as_undecided() -> None:
    flipped = run(1, 12.63, 30, True)  # overturns at 1e-8, survives at 1e-11
    warning = sensitive_warning(flipped, 1e-8)
    assert warning is not None
    assert warning.startswith(
        "polarity +1: the overturning verdict depends on the integration tolerance: overturns "
        "at rtol 1e-8, 0.8000 (40) at 1e-11 — read it as undecided on this record"
    )
    d = doc(flipped, run(-1, 0.3, 10, False, t_max_ratio=0.3, t_impacts=10, t_sensitive=False),
            verdict="overturns", max_ratio=12.63, sensitive=True)  # fmt: skip
    assert verdict_caveat(d) == " — the verdict depends on the integration tolerance (see the " \
        "warning)"  # fmt: skip
    assert "polarity +1 sensitive" in tolerance_note(d)
    (row,) = compare_rows(d)
    assert row["rocking"] == "sensitive: overturns at rtol 1e-8, 0.8000 (40) at 1e-11"


def test_an_envelope_that_moves_gets_a_caveat_and_one_that_does_not_none() -> None:
    moved = doc(run(1, 0.9, 50, False), run(-1, 0.5, 20, False, t_max_ratio=0.5, t_sensitive=False),
                verdict="survives", max_ratio=0.9, sensitive=True)  # fmt: skip
    assert verdict_caveat(moved) == " — max θ/α depends on the integration tolerance (see the " \
        "warning)"  # fmt: skip
    # Polarity −1 moves but +1 decides the envelope and does not: no caveat on the verdict.
    inner = doc(run(1, 0.9, 50, False, t_max_ratio=0.9, t_sensitive=False), run(-1, 0.5, 20, False),
                verdict="survives", max_ratio=0.9, sensitive=True)  # fmt: skip
    assert verdict_caveat(inner) == ""
    assert sensitive_warning(inner["runs"][0], 1e-8) is None


def test_a_check_stopped_at_a_guard_is_not_known() -> None:
    unknown = run(-1, 0.5, 20, False, t_sensitive=None)
    warning = sensitive_warning(unknown, 1e-8)
    assert warning == (
        "polarity -1: the run again at rtol 1e-11 stopped before the end (an engine guard): "
        "whether the result depends on the integration tolerance is not known"
    )
    d = doc(unknown, verdict="survives", max_ratio=0.5, sensitive=None)
    assert "polarity -1 not known" in tolerance_note(d)
    assert verdict_caveat(d) == "" and compare_rows(d) == []
