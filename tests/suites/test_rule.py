"""The code's rule over a suite (NTC 2018 §7.3.5), on hand-built outcomes."""

from __future__ import annotations

import math

import pytest

from rockcli.studies.suite_run.rule import RecordOutcome, suite_measure, suite_rule

#: An overturned run's max θ/α: the overturning angle π/2 over α = 0.2.
OVERTURNED = (math.pi / 2) / 0.2


def outcome(ratio: float, overturned: bool = False) -> RecordOutcome:
    return RecordOutcome("r", 1.0, 0.3, OVERTURNED if overturned else ratio, overturned)


@pytest.mark.parametrize(("n", "rule"), [(3, "worst"), (6, "worst"), (7, "mean"), (11, "mean")])
def test_the_rule_follows_the_count(n: int, rule: str) -> None:
    assert suite_rule(n) == rule


@pytest.mark.parametrize("n", [0, 1, 2])
def test_fewer_than_three_records_is_refused(n: int) -> None:
    with pytest.raises(ValueError, match="at least 3"):
        suite_rule(n)


def test_seven_records_take_the_mean() -> None:
    # Mean of 0.1 … 0.7 = 0.4 exactly (by hand); below the limit 1: passes.
    m = suite_measure([outcome(k / 10) for k in range(1, 8)])
    assert (m.n, m.rule, m.passed, m.overturned_records) == (7, "mean", True, 0)
    assert m.measure == pytest.approx(0.4, rel=1e-15)


def test_an_overturn_counts_at_the_overturning_angle_in_the_mean() -> None:
    # Six records at 0.1 and one overturn: (0.6 + 7.854)/7 = 1.2077 > 1: the suite fails,
    # although six records of seven barely rock.
    m = suite_measure([outcome(0.1)] * 6 + [outcome(0.0, overturned=True)])
    assert m.measure == pytest.approx((0.6 + OVERTURNED) / 7, rel=1e-15)
    assert not m.passed and m.overturned_records == 1


def test_three_to_six_records_take_the_worst() -> None:
    m = suite_measure([outcome(0.2), outcome(0.9), outcome(0.5)])
    assert (m.rule, m.measure, m.passed) == ("worst", 0.9, True)
    m = suite_measure([outcome(0.2), outcome(0.9), outcome(0.5)], limit_ratio=0.8)
    assert not m.passed and m.limit_ratio == 0.8


def test_the_limit_itself_does_not_pass() -> None:
    # θ/α = 1 is the static instability: a measure equal to the limit is not below it.
    assert not suite_measure([outcome(1.0)] * 3).passed
