"""Spectrum compatibility of a record suite: the mean 5 %-damped elastic spectrum of the
records against the target spectrum (NTC 2008 and NTC 2018 §3.2.3.6).

The code's rule: at least 7 records, whose mean spectrum lies nowhere more than 10 % below
the target (and, in NTC 2018, nowhere more than 30 % above) over the period range; with 3 to
6 records the worst effect of the records governs instead of the mean.

Pure and silent: numpy and the code-check package only.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from enum import StrEnum
from typing import Protocol

import numpy as np

from rockcli.codecheck.response import DEFAULT_DAMPING, response_spectrum
from rockcli.codecheck.spectra import ElasticSpectrum
from rockcli.records.record import Record

#: Periods of the check per decade, log-spaced (≈ 6 % apart): fine enough that the code
#: spectrum's corners and a record spectrum's peaks fall between points closer than the
#: tolerance's own resolution.
POINTS_PER_DECADE = 40
#: Records needed for the mean to govern (NTC §3.2.3.6); with fewer, the worst effect.
MIN_RECORDS_FOR_MEAN = 7
#: A ratio this close to a bound (relative) is on it: a factor chosen to put the minimum on
#: the lower bound must pass the check it was chosen for.
BOUND_SLACK = 1e-9


class CountRule(StrEnum):
    """How the code uses a suite of this size (NTC §3.2.3.6)."""

    MEAN = "mean"  # 7 or more records: the mean effect
    WORST = "worst"  # 3 to 6 records: the worst effect


def count_rule(count: int) -> CountRule:
    """``mean`` for 7 records or more, ``worst`` for 3 to 6 (NTC §3.2.3.6)."""
    return CountRule.MEAN if count >= MIN_RECORDS_FOR_MEAN else CountRule.WORST


def period_grid(lo: float, hi: float) -> np.ndarray:
    """Log-spaced periods [s] from lo to hi, both included, POINTS_PER_DECADE per decade."""
    count = max(2, math.ceil(POINTS_PER_DECADE * math.log10(hi / lo)) + 1)
    grid = np.geomspace(lo, hi, count)
    grid[0], grid[-1] = lo, hi  # exactly the bounds the user gave
    return grid


def record_spectra(records: Sequence[Record], periods: np.ndarray) -> np.ndarray:
    """Pseudo-acceleration Sa [g] of each record at the periods, 5 % damping; shape (n, m).

    Nigam & Jennings (1969) via :func:`rockcli.codecheck.response.response_spectrum`.
    """
    return np.array(
        [
            response_spectrum(r.time, r.accel, periods, DEFAULT_DAMPING, compiled=True)[0]
            for r in records
        ]
    )


def target_spectrum(spectrum: ElasticSpectrum, periods: np.ndarray) -> np.ndarray:
    """Se(T) [g] of the code's elastic horizontal spectrum at the periods (NTC §3.2.3.2.1)."""
    return spectrum.curve(periods)[0]


class FloorFilter(Protocol):
    """The building's first mode at the block's height (rockcli.analyses.floor.Floor)."""

    Z: float | None
    T1: float
    psi: float
    gamma: float
    xi: float


#: The mechanism's damping in the floor target [%]: the suite's check is at 5 % (§3.2.3.6).
TARGET_DAMPING = 5.0


def floor_target(
    spectrum: ElasticSpectrum, floor: FloorFilter, periods: np.ndarray
) -> tuple[np.ndarray, float]:
    """The code's floor spectrum S_eZ(T) [g] at 5 % at the periods, and its floor
    acceleration a_Z [g], from the ground target (Circolare 7/2019 §C7.2.3, with NTC 2018
    §7.2.3: a_Z = Se(T1, ξ_k)·|γ·ψ(Z)|·√(1 + 0.0004·ξ_k²), then the plateau 0.8–1.1·T1 and
    its branches, not below the ground target for T > T1 (Eq. C7.2.5); ξ_k the building's
    damping, read as in rock kinematic)."""
    from rockcli.codecheck.position import Position
    from rockcli.codecheck.rules2019 import bounded_floor_spectrum, floor_acceleration

    pos = Position(Z=floor.Z or 0.0, T1=floor.T1, gamma=floor.gamma, psi=floor.psi,
                   damping=floor.xi)  # fmt: skip
    a_z = floor_acceleration(spectrum, pos)
    curve = np.array([bounded_floor_spectrum(spectrum, T, pos, TARGET_DAMPING) for T in periods])
    return curve, a_z


def floor_records(records: Sequence[Record], floor: FloorFilter) -> list[Record]:
    """Each record's floor motion ü_g + γ·ψ·ẍ₁ (rockcli.codecheck.floor.floor_motion), the
    motion a block at that height rocks on in `rock assess`."""
    from rockcli.codecheck.floor import floor_motion

    return [
        replace(
            r,
            accel=floor_motion(
                r.time, r.accel, T1=floor.T1, psi=floor.psi, gamma=floor.gamma, xi=floor.xi
            ),
        )  # fmt: skip
        for r in records
    ]


@dataclass(frozen=True)
class Compatibility:
    """The mean spectrum against the target.

    Attributes:
        periods: the grid [s]. target: Se [g]. mean: the records' mean Sa [g].
        ratio: mean/target [-]. within: each ratio inside [1 + lo, 1 + hi].
        tolerance: (lo, hi) as fractions. passed: every point within.
        worst_index: the point furthest outside the band (or closest to leaving it).
    """

    periods: np.ndarray
    target: np.ndarray
    mean: np.ndarray
    ratio: np.ndarray
    within: np.ndarray
    tolerance: tuple[float, float]
    passed: bool
    worst_index: int


def compatibility(
    periods: np.ndarray, target: np.ndarray, mean: np.ndarray, tolerance: tuple[float, float]
) -> Compatibility:
    """Check mean/target against the band 1 + lo ≤ ratio ≤ 1 + hi at every period.

    NTC 2008 and 2018 §3.2.3.6 (lo = −10 %; hi = +30 % in 2018, none in 2008).
    """
    lo, hi = tolerance
    ratio = mean / target
    within = (ratio >= (1.0 + lo) * (1.0 - BOUND_SLACK)) & (ratio <= (1.0 + hi) * (1 + BOUND_SLACK))
    return Compatibility(
        periods=periods,
        target=target,
        mean=mean,
        ratio=ratio,
        within=within,
        tolerance=tolerance,
        passed=bool(within.all()),
        worst_index=worst_point(ratio, tolerance),
    )


def worst_point(ratio: np.ndarray, tolerance: tuple[float, float]) -> int:
    """Index of the ratio with the smallest margin to the band (negative margin: outside).

    The margin is measured in ratio units: ratio − (1 + lo) below, (1 + hi) − ratio above.
    """
    lo, hi = tolerance
    margin = np.minimum(ratio - (1.0 + lo), (1.0 + hi) - ratio)
    return int(np.argmin(margin))


@dataclass(frozen=True)
class AutoScale:
    """The common factor of ``--scale auto``.

    Attributes:
        factor: the factor that puts the mean's smallest ratio on the lower bound 1 + lo
            (None when the mean is zero somewhere: no factor can lift it).
        feasible: the largest ratio times the factor stays within 1 + hi.
    """

    factor: float | None
    feasible: bool


def auto_scale(ratio: np.ndarray, tolerance: tuple[float, float]) -> AutoScale:
    """One factor on every record: f = (1 + lo)/min(ratio); feasible when f·max(ratio) ≤ 1 + hi.

    The mean spectrum is linear in the records, so a common factor f scales every ratio by f.
    The smallest f that satisfies the lower bound is this one; any larger f only brings the
    maximum closer to the upper bound, so when this f fails the upper bound no factor passes.
    """
    lo, hi = tolerance
    smallest = float(np.min(ratio))
    if not smallest > 0.0:  # a mean of zero somewhere: no factor lifts it
        return AutoScale(factor=None, feasible=False)
    factor = (1.0 + lo) / smallest
    feasible = factor * float(np.max(ratio)) <= (1.0 + hi) * (1.0 + BOUND_SLACK)
    return AutoScale(factor=factor, feasible=feasible)
