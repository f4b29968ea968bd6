"""The code's rule over a suite of records: the mean of the effects over at least 7 records,
the most unfavourable over 3 to 6.

Source: NTC 2018 §7.3.5 (NTC 2008 §7.3.5 alike): with at least 7 groups of accelerograms the
effects on the structure are the mean of each analysis's most unfavourable effect, with fewer
the most unfavourable of them, and never fewer than 3 groups.
The effect of a rocking run is its amplitude ratio max θ/α over both polarities; a record
that overturns the block counts at the overturning angle over α (the engine's max θ/α of an
overturned run), so one overturn weighs on the mean as the collapse it is
(docs/interpretations.md, "Record suites").

Pure and silent: data in, data out.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from rockcli.suites.compat import CountRule, count_rule
from rockcli.suites.load import MIN_RECORDS

#: Default limit of the suite measure: θ/α = 1, the static instability of the free block.
DEFAULT_LIMIT_RATIO = 1.0

Rule = Literal["mean", "worst"]


@dataclass(frozen=True)
class RecordOutcome:
    """One record of the suite in the time history.

    Attributes:
        name: the record's name. scale: the factor applied to it. pga_g: its PGA after scaling.
        max_ratio: max θ/α over both polarities (overturn angle/α when it overturned) [-].
        overturned: True when either polarity overturned.
    """

    name: str
    scale: float
    pga_g: float
    max_ratio: float
    overturned: bool


@dataclass(frozen=True)
class SuiteMeasure:
    """The suite's verdict by the code's rule.

    Attributes:
        n: records. rule: "mean" (n ≥ 7) or "worst" (3 ≤ n < 7).
        measure: the mean or the largest of the records' max θ/α [-].
        limit_ratio: the limit the measure is held to [-].
        passed: measure < limit_ratio.
        overturned_records: how many records overturn the block.
    """

    n: int
    rule: Rule
    measure: float
    limit_ratio: float
    passed: bool
    overturned_records: int


def suite_rule(n: int) -> Rule:
    """ "mean" with at least 7 records, "worst" with 3 to 6 (NTC 2018 §7.3.5).

    Raises:
        ValueError: fewer than 3 records.
    """
    if n < MIN_RECORDS:
        raise ValueError(f"a suite needs at least {MIN_RECORDS} records, not {n}")
    return "mean" if count_rule(n) is CountRule.MEAN else "worst"


def suite_measure(
    outcomes: tuple[RecordOutcome, ...] | list[RecordOutcome],
    limit_ratio: float = DEFAULT_LIMIT_RATIO,
) -> SuiteMeasure:
    """The suite measure by the code's rule and its verdict against ``limit_ratio``."""
    rule = suite_rule(len(outcomes))
    ratios = [o.max_ratio for o in outcomes]
    measure = sum(ratios) / len(ratios) if rule == "mean" else max(ratios)
    return SuiteMeasure(
        n=len(outcomes),
        rule=rule,
        measure=measure,
        limit_ratio=limit_ratio,
        passed=measure < limit_ratio,
        overturned_records=sum(o.overturned for o in outcomes),
    )
