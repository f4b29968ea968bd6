"""A site's hazard curve from the NTC grid, and the annual rate of a damage state.

The hazard curve λ(im) — the mean annual rate at which the peak ground acceleration at the
site's surface exceeds im — is known at the grid's nine return periods (DM 14/01/2008,
Allegato B: TR = 30 … 2475 years, λ = 1/TR), where im = ag·S (ag on rock from the grid at
the site, interpolated in space as Allegato A does; S = S_S·S_T of NTC 2018 §3.2.3.2 for
the soil, topography T1). Between two grid periods λ is interpolated log–log, the rule
Allegato A applies to ag itself (Eq. 3), so that the curve passes through the grid's own
points. Beyond them the curve goes on as the power law of its end segment: below the 30-year
ordinate with the slope between 30 and 50 years, above the 2475-year one with the slope
between 975 and 2475 years (the tails; the rate of a damage state says how much of it comes
from them).

The annual rate of a damage state of a lognormal fragility (median θ, dispersion β) is the
total probability λ_DS = ∫ P(DS | im)·|dλ(im)| (Cornell et al. 2002), by parts the
expectation of λ over the capacity's lognormal distribution, λ_DS = ∫ λ(im)·f_C(im) dim
(the boundary terms vanish: Φ·λ → 0 at both ends). On each segment λ = exp(y_j − k_j(x −
x_j)) in x = ln im, so the integral has a closed form, segment by segment (completing the
square): exp(y_j + k_j(x_j − μ) + k_j²β²/2)·[Φ(b_j + k_jβ) − Φ(a_j + k_jβ)], a_j and b_j the
segment's ends in (x − μ)/β, the first from −∞ and the last to +∞. Summed in log space
(log Φ differences, log-sum-exp): exact for this curve and bounded whatever θ and β. Beside it
the closed form k0·θ^−k·exp(k²β²/2) of a hazard curve k0·im^−k through the grid segment
that holds the median, and their ratio (None where it overflows).

Pure and silent: numpy, scipy and math.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rockcli.codecheck.hazard_curve import HazardCurve

#: The largest log-rate a result may have (a rate of e^700 a year is no rate).
LOG_RATE_MAX = 700.0


@dataclass(frozen=True)
class SitePoint:
    """The hazard at the site at one grid return period: TR [years], ag on rock [g], F0 [-],
    S = S_S·S_T [-] and the surface PGA ag·S [g]."""

    TR: float
    ag: float
    F0: float
    S: float

    @property
    def pga(self) -> float:
        """ag·S [g]."""
        return self.ag * self.S


def site_points(grid, lon: float, lat: float, soil: str, topography: str) -> tuple[SitePoint, ...]:
    """The site's hazard at the grid's nine return periods (DM 14/01/2008 Allegati A–B, in
    space as Allegato A interpolates), S = S_S(soil, ag, F0)·S_T(topography) (NTC 2018
    §3.2.3.2.1, Tabb. 3.2.V–VI) at each."""
    from rockcli.codecheck.categories import Soil, Topography
    from rockcli.codecheck.hazard import site_parameters
    from rockcli.codecheck.spectra import soil_amplification, topographic_amplification

    s_t = topographic_amplification(Topography(topography))
    out = []
    for TR in grid.return_periods:
        ag, F0, _ = site_parameters(grid, lon, lat, float(TR))
        out.append(SitePoint(float(TR), ag, F0, soil_amplification(Soil(soil), ag, F0) * s_t))
    return tuple(out)


def curve_of(points: tuple[SitePoint, ...]) -> HazardCurve:
    """The hazard curve of the surface PGA through the site's points."""
    return HazardCurve(tuple(p.pga for p in points), tuple(1.0 / p.TR for p in points))


@dataclass(frozen=True)
class DamageRate:
    """The annual rate of a damage state and what it means.

    Attributes:
        rate: λ_DS [1/year]. closed_form: k0·θ^−k·exp(k²β²/2) [1/year] (None: overflows).
        k0, k: the power law of the closed form. median_rate: λ(θ) [1/year].
        tails: the share of λ_DS from intensities beyond the grid's points (∫ P·|dλ| there,
            over λ_DS) [-].
    """

    rate: float
    closed_form: float | None
    k0: float
    k: float
    median_rate: float
    tails: float

    @property
    def return_period(self) -> float:
        """1/λ_DS [years]."""
        return 1.0 / self.rate

    def probability_in(self, years: float) -> float:
        """P(at least one exceedance in ``years``) = 1 − exp(−λ·t) (Poisson)."""
        return -math.expm1(-self.rate * years)


def log_phi_between(a: float, b: float) -> float:
    """log(Φ(b) − Φ(a)) for a < b, accurate in both tails (−inf when it underflows)."""
    from scipy.special import log_ndtr

    if a > 0.0:  # Φ(b) − Φ(a) = Φ(−a) − Φ(−b): the small upper tails
        a, b = -b, -a
    lb, la = float(log_ndtr(b)), float(log_ndtr(a))
    return lb + math.log1p(-math.exp(la - lb)) if la < lb else -math.inf


def segment_terms(curve: HazardCurve, mu: float, beta: float) -> list[float]:
    """log ∫ λ·f_C over each segment of the curve (module docstring), the first from −∞ and
    the last to +∞."""
    x, y = np.log(curve.im), np.log(curve.rate)
    k = curve.slopes()
    edges = [-math.inf, *x[1:-1].tolist(), math.inf]
    return [
        float(y[j] + k[j] * (x[j] - mu) + 0.5 * (k[j] * beta) ** 2)
        + log_phi_between(
            (edges[j] - mu) / beta + k[j] * beta, (edges[j + 1] - mu) / beta + k[j] * beta
        )  # fmt: skip
        for j in range(len(k))
    ]


def log_damage_rate(curve: HazardCurve, median: float, beta: float) -> float:
    """log λ_DS [log 1/year] of a lognormal fragility on ``curve``."""
    from scipy.special import logsumexp

    return float(logsumexp(segment_terms(curve, math.log(median), beta)))


def damage_rate(curve: HazardCurve, median: float, beta: float) -> DamageRate | None:
    """λ_DS of a lognormal fragility (median θ [g], dispersion β) on ``curve`` (module
    docstring); None when it is not a usable rate (beyond e^±700 a year)."""
    log_rate = log_damage_rate(curve, median, beta)
    if not -LOG_RATE_MAX < log_rate < LOG_RATE_MAX:
        return None
    rate = math.exp(log_rate)
    k0, k = curve.local_power_law(median)
    log_closed = math.log(k0) - k * math.log(median) + 0.5 * k * k * beta * beta
    closed = math.exp(log_closed) if abs(log_closed) < LOG_RATE_MAX else None
    share = tail_rate(curve, math.log(median), beta) / rate
    return DamageRate(rate, closed, k0, k, float(curve.rate_at(median)), min(max(share, 0.0), 1.0))


def tail_rate(curve: HazardCurve, mu: float, beta: float) -> float:
    """∫ P(DS | im)·|dλ| over the intensities beyond the grid's points [1/year], by parts:
    below the first, I_0(−∞, x_0) − Φ(z_0)·λ_0; above the last, I_last(x_last, ∞) +
    Φ(z_last)·λ_last (I the segments' closed forms, z = (x − μ)/β)."""
    from scipy.special import ndtr

    x, y = np.log(curve.im), np.log(curve.rate)
    k = curve.slopes()
    z0, z8 = (x[0] - mu) / beta, (x[-1] - mu) / beta

    def piece(j: int, lo: float, hi: float) -> float:
        log_i = float(y[j] + k[j] * (x[j] - mu) + 0.5 * (k[j] * beta) ** 2) + log_phi_between(
            lo + k[j] * beta, hi + k[j] * beta
        )
        return math.exp(min(log_i, LOG_RATE_MAX))

    below = piece(0, -math.inf, z0) - float(ndtr(z0)) * curve.rate[0]
    above = piece(len(k) - 1, z8, math.inf) + float(ndtr(z8)) * curve.rate[-1]
    return max(below, 0.0) + above
