"""The choice rule of `rock retrofit` on synthetic candidates (no analysis runs)."""

from __future__ import annotations

from typing import Any

import pytest

from rockcli.studies.retrofit.choose import choose, failures


def row(d: float, **changes: Any) -> dict[str, Any]:
    """A candidate that passes every criterion, with some fields changed."""
    base = {
        "diameter_mm": d,
        "code_uls_passed": True,
        "code_zeta": 1.5,
        "rocking": "survives",
        "overturned": False,
        "ruptured": False,
        "utilisation": 0.5,
    }
    return {**base, **changes}


def test_smallest_passing_diameter_is_chosen() -> None:
    rows = [row(10, code_uls_passed=False, code_zeta=0.8), row(12), row(16)]
    chosen, reason = choose(rows)
    assert chosen is rows[1]
    assert reason.startswith("Ø12 mm is the smallest diameter")


def test_a_pass_below_a_failure_is_still_the_smallest() -> None:
    # The rule does not assume monotony: 12 passes although 16 overturns.
    rows = [row(10, overturned=True, rocking="overturns"), row(12), row(16, overturned=True)]
    assert choose(rows)[0] is rows[1]


@pytest.mark.parametrize(
    ("changes", "phrase"),
    [
        ({"code_uls_passed": False, "code_zeta": 0.8}, "the code ULS fails (ζ = 0.800)"),
        ({"code_uls_passed": None, "code_zeta": None}, "the code ULS is not evaluated"),
        ({"overturned": True, "rocking": "overturns"}, "the block overturns"),
        ({"rocking": "undecided"}, "the time history is undecided"),
        ({"ruptured": True}, "the rod ruptures"),
        ({"utilisation": 1.2}, "the rod's utilisation is 1.20 > 1"),
    ],
)
def test_each_criterion_fails_a_candidate(changes: dict[str, Any], phrase: str) -> None:
    assert [phrase in f for f in failures(row(20, **changes))] == [True]


def test_utilisation_of_exactly_one_passes() -> None:
    # Utilisation ≤ 1 is the criterion (NTC 2018 §4.2.4.1.2: N_Ed / N_t,Rd ≤ 1); a rod that
    # yielded at its strength reports 1 within the rounding of its plateau (FORCE_RTOL = 1e-9;
    # 1 + 3e-14 measured): it passes, 1 + 1e-6 does not.
    assert failures(row(20, utilisation=1.0)) == []
    assert failures(row(20, utilisation=1.0 + 3e-14)) == []
    assert failures(row(20, utilisation=1.0 + 1e-6)) != []


def test_none_in_the_range_names_what_fails_at_the_largest() -> None:
    rows = [
        row(10, overturned=True, rocking="overturns", utilisation=3.0),
        row(40, code_uls_passed=False, code_zeta=0.9, utilisation=1.5),
    ]
    chosen, reason = choose(rows)
    assert chosen is None
    assert reason == (
        "none in the range: at the largest, 40 mm, the code ULS fails (ζ = 0.900); "
        "the rod's utilisation is 1.50 > 1"
    )


def test_no_candidate() -> None:
    assert choose([]) == (None, "no diameter tried")


def mechanism(**changes: Any) -> dict[str, Any]:
    """A wall's mechanism row that the rod does not restrain and that passes."""
    base = {"name": "gable", "mechanism": "gable", "on_mechanism": False, "restrained": False,
            "code_uls_passed": True, "code_zeta": 1.2, "rocking": None, "max_ratio": None,
            "overturned": False, "ruptured": False, "utilisation": None,
            "status": "safe"}  # fmt: skip
    return {**base, **changes}


def test_a_rod_on_nothing_where_nothing_fails_is_not_needed() -> None:
    # Every diameter passes (nothing fails): the smallest is chosen, the rod not needed, and
    # --fail-if-none has nothing to fail on.
    rows = [row(10, mechanisms=[mechanism()]), row(12, mechanisms=[mechanism()])]
    chosen, reason = choose(rows)
    assert chosen is rows[0]
    assert "no mechanism fails and the rod restrains none" in reason


def test_code_alone_says_so() -> None:
    rows = [row(10, mechanisms=[mechanism(on_mechanism=True, restrained=True)])]
    chosen, reason = choose(rows, rocked=False)
    assert chosen is rows[0] and "the code check alone: no record" in reason
    assert "survives" not in reason


def test_a_rod_that_restrains_nothing_where_something_fails_is_no_choice() -> None:
    # The rod on the mechanism but slack on the side it fails on, overturning: no diameter.
    failing = mechanism(on_mechanism=True, overturned=True, rocking="overturns", status="fails")
    chosen, reason = choose([row(10, mechanisms=[failing])])
    assert chosen is None and "'gable'" in reason
