"""The seismic demand of each limit state: a spectrum, and how it grows with ag.

Either the code's elastic spectrum (NTC §3.2.3.2) from (ag, F0, Tc*) per limit state, or the
elastic response spectrum of a record, its PGA in place of ag·S (spec/ntc.md, last
paragraph of "Elastic response spectrum"). The 2019 rules turn demand into a capacity ground
acceleration by root search over ag with F0 and Tc* fixed; a record scales linearly.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from rockcli.codecheck.hazard_curve import HazardCurve
from rockcli.searches import brent_root

#: Root search bounds on ag [g] for the 2019 capacities (beyond, the capacity is reported as
#: "more than" the bound).
AG_MIN, AG_MAX = 1e-4, 5.0


class Spectrum(Protocol):
    """A 5 %-damped (or ξ) elastic spectrum: acceleration in g, displacement in m."""

    def Se(self, T: float, xi: float = 5.0) -> float: ...  # noqa: N802 (the code's symbol)

    def SDe(self, T: float, xi: float = 5.0) -> float: ...  # noqa: N802

    @property
    def pga_ground(self) -> float: ...


@dataclass(frozen=True)
class ScaledSpectrum:
    """A spectrum multiplied by a factor (a scaled record)."""

    base: Spectrum
    factor: float

    def Se(self, T: float, xi: float = 5.0) -> float:  # noqa: N802
        """Se of the base times the factor [g]."""
        return self.factor * self.base.Se(T, xi)

    def SDe(self, T: float, xi: float = 5.0) -> float:  # noqa: N802
        """SDe of the base times the factor [m]."""
        return self.factor * self.base.SDe(T, xi)

    def SDe_grid(self, first: int, last: int, step: float, xi: float) -> np.ndarray:  # noqa: N802
        """SDe of the base at the periods k·step, k = first … last, times the factor [m]."""
        return self.factor * grid_SDe(self.base, first, last, xi, step)

    @property
    def pga_ground(self) -> float:
        """PGA of the base times the factor [g]."""
        return self.factor * self.base.pga_ground


@dataclass(frozen=True)
class MeanSpectrum:
    """The mean of several spectra, period by period (a record suite's mean spectrum).

    NTC 2018 §3.2.3.6 judges a suite by the mean of its records' elastic spectra; used as a
    demand, the mean's Se, SDe and PGA are the arithmetic means of the records' own.
    """

    spectra: tuple[Spectrum, ...]

    def Se(self, T: float, xi: float = 5.0) -> float:  # noqa: N802
        """The mean of the spectra's Se at T [g]."""
        return sum(s.Se(T, xi) for s in self.spectra) / len(self.spectra)

    def SDe(self, T: float, xi: float = 5.0) -> float:  # noqa: N802
        """The mean of the spectra's SDe at T [m]."""
        return sum(s.SDe(T, xi) for s in self.spectra) / len(self.spectra)

    def SDe_grid(self, first: int, last: int, step: float, xi: float) -> np.ndarray:  # noqa: N802
        """The mean of the spectra's SDe at the periods k·step, k = first … last [m]."""
        total = np.zeros(max(last + 1 - first, 0))
        for s in self.spectra:  # in SDe's order of summation
            total = total + grid_SDe(s, first, last, xi, step)
        return total / len(self.spectra)

    @property
    def pga_ground(self) -> float:
        """The mean of the spectra's PGA [g] (in place of ag·S, as for one record)."""
        return sum(s.pga_ground for s in self.spectra) / len(self.spectra)


@dataclass(frozen=True)
class LimitStateDemand:
    """The demand of one limit state.

    Attributes:
        limit_state: "SLO", "SLD", "SLV" or "SLC".
        ag: the code's ag for it, or the record's PGA [g].
        at_ag: the spectrum for another ag (same F0, Tc*, soil; or the record scaled).
        source: how it was obtained, for the report.
        parameters: (ag, F0, Tc*) when from the code, None for a record.
        TR: the return period the parameters belong to [years]; None when the model gives
            the parameters directly, or for a record.
        record: the record's name when the demand is a record, None for the code spectrum.
        hazard: the site's hazard curve of ag on rock through the grid's return periods,
            when the demand comes from a site (the return period a capacity ag bears).
    """

    limit_state: str
    ag: float
    at_ag: Callable[[float], Spectrum]
    source: str
    parameters: tuple[float, float, float] | None = None
    TR: float | None = None
    record: str | None = None
    hazard: HazardCurve | None = None

    @property
    def spectrum(self) -> Spectrum:
        """The spectrum at the limit state's own ag."""
        return self.at_ag(self.ag)


#: How a record's spectrum stands in for the code's (the report's "source").
RECORD_SOURCE = "its response spectrum, PGA in place of ag·S"


def record_demand(
    limit_state: str, spectrum: Spectrum, name: str, source: str = RECORD_SOURCE
) -> LimitStateDemand:
    """A record as the demand: ag ↔ its PGA, scaling linearly (spec/ntc.md)."""
    pga = spectrum.pga_ground
    return LimitStateDemand(
        limit_state=limit_state,
        ag=pga,
        at_ag=lambda ag: ScaledSpectrum(spectrum, ag / pga),
        source=source,
        record=name,
    )


#: Spacing of the period grid on which the maximum of a record's spectrum over a range is
#: sought [s] (absolute, so that a study's cases share the grid's spectral values), and the
#: width to which the best grid interval is then narrowed by golden-section search [s].
RANGE_STEP = 0.01
RANGE_TOLERANCE = 1e-5
#: The golden ratio's conjugate, (√5 − 1)/2.
GOLDEN = 0.6180339887498949


def grid_range(lo: float, hi: float, step: float = RANGE_STEP) -> tuple[int, int]:
    """(first, last): the k of the periods k·step inside (lo, hi) (none when first > last)."""
    return math.floor(lo / step) + 1, math.ceil(hi / step) - 1


def period_grid(lo: float, hi: float, step: float = RANGE_STEP) -> list[float]:
    """The periods k·step inside (lo, hi), with hi itself (and lo when > 0) [s]."""
    first, last = grid_range(lo, hi, step)
    inner = [k * step for k in range(first, last + 1)]
    return sorted({*([lo] if lo > 0.0 else []), *inner, hi})


def range_maximum(
    f: Callable[[float], float],
    lo: float,
    hi: float,
    on_grid: Callable[[int, int], np.ndarray] | None = None,
) -> tuple[float, float]:
    """(T*, f(T*)): the largest value of f over the periods [lo, hi] [s].

    Circolare 7/2019 §C8.7.1.2.1.8: with site records (or a site response analysis) the
    displacement demand is "il valore massimo dello spostamento spettrale valutato
    nell'intervallo di periodi [T0, T_SLV]". A record's spectrum has peaks: f is sampled on a
    grid of RANGE_STEP (:func:`period_grid`), then the best grid point's two neighbouring
    intervals are narrowed by golden-section search to RANGE_TOLERANCE; the largest value seen
    wins (never less than the grid's maximum). ``on_grid(first, last)``: f at the grid's
    periods k·RANGE_STEP, k = first … last, at once (a record's cached ordinates, one array
    operation), in place of f at each.
    """
    grid, values = grid_values(f, lo, hi, on_grid)
    k = int(np.argmax(values))
    a, b = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    return max((grid[k], values[k]), golden_maximum(f, a, b), key=lambda tv: tv[1])


def grid_values(
    f: Callable[[float], float],
    lo: float,
    hi: float,
    on_grid: Callable[[int, int], np.ndarray] | None,
) -> tuple[list[float], list[float]]:
    """(periods, f there) of :func:`period_grid`, the inner ones from ``on_grid`` if given."""
    if on_grid is None:
        grid = period_grid(lo, hi)
        return grid, [f(T) for T in grid]
    first, last = grid_range(lo, hi)
    inner = np.arange(first, last + 1) * RANGE_STEP
    inner_values = on_grid(first, last) if last >= first else np.empty(0)
    ends = sorted({lo, hi} if lo > 0.0 else {hi})
    keep = (inner != lo) & (inner != hi)
    periods = np.concatenate((inner[keep], ends))
    values = np.concatenate((inner_values[keep], [f(T) for T in ends]))
    order = np.argsort(periods, kind="stable")
    return periods[order].tolist(), values[order].tolist()


def golden_maximum(f: Callable[[float], float], a: float, b: float) -> tuple[float, float]:
    """(T, f(T)): a local maximum of f in [a, b] by golden-section search, to RANGE_TOLERANCE
    (Kiefer 1953; Press et al., Numerical Recipes, §10.2)."""
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = f(c), f(d)
    while b - a > RANGE_TOLERANCE:
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = f(d)
    return (c, fc) if fc >= fd else (d, fd)


def grid_SDe(
    spec: Spectrum, first: int, last: int, xi: float, step: float = RANGE_STEP
) -> np.ndarray:  # noqa: N802 (the code's symbol)
    """SDe(k·step, ξ) for k = first … last [m]: at once where the spectrum keeps its grid
    (``SDe_grid``: a record's, a scaled record's, a suite's mean), else period by period."""
    on_grid = getattr(spec, "SDe_grid", None)
    if on_grid is not None:
        return on_grid(first, last, step, xi)
    return np.array([spec.SDe(k * step, xi) for k in range(first, last + 1)])


def bound_note(ag: float | None) -> str:
    """A note when a capacity is the search bound (the true capacity is larger)."""
    return f"; capacity at least {AG_MAX:g} g (search bound)" if ag == AG_MAX else ""


def capacity_ag(
    demand: LimitStateDemand, measure: Callable[[Spectrum], float], capacity: float
) -> float:
    """The ag at which measure(spectrum(ag)) equals the capacity [g], by Brent's search
    (rockcli.searches: the ag a bisection would find, in a dozen evaluations).

    Circolare 7/2019 §C8.7.1.2.1: the capacity of each check is the ground acceleration that
    makes the demand equal to it. measure must grow with ag. When even AG_MAX does not reach
    the capacity, AG_MAX is returned: a lower bound of the capacity, which the checks say
    (see :func:`bound_note`).
    """

    def short(ag: float) -> float:
        return capacity - measure(demand.at_ag(ag))

    short_hi = short(AG_MAX)
    if short_hi > 0.0:
        return AG_MAX
    short_lo = short(AG_MIN)
    if short_lo <= 0.0:
        return AG_MIN
    return brent_root(short, AG_MIN, AG_MAX, short_lo, short_hi)
