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
total probability λ_DS = ∫ P(DS | im)·|dλ(im)| (Cornell et al. 2002), computed as the
expectation of λ over the capacity's lognormal distribution (integration by parts:
λ_DS = ∫ λ(im)·f_C(im) dim, f_C the lognormal density), by adaptive quadrature in
x = ln im with the curve's kinks as break points, over μ ± 12β (the rest below 1e-30 of the
total). Beside it the closed form k0·θ^−k·exp(k²β²/2) of a hazard curve k0·im^−k through
the grid segment that holds the median (the tangent's secant), and their ratio.

Pure and silent: numpy, scipy and math.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: How far either side of the median the integral of a damage state's rate goes [β].
SPAN_BETAS = 12.0


@dataclass(frozen=True)
class HazardCurve:
    """The site's λ(im) through its points (im ascending, λ descending).

    Attributes:
        im: the surface PGA at each grid return period [g], ascending.
        rate: 1/TR at each [1/year], descending.
    """

    im: tuple[float, ...]
    rate: tuple[float, ...]

    def slopes(self) -> np.ndarray:
        """k of each segment, λ ∝ im^−k, and of the two tails (first and last segment's)."""
        x, y = np.log(self.im), np.log(self.rate)
        return -np.diff(y) / np.diff(x)

    def rate_at(self, im: float | np.ndarray) -> np.ndarray:
        """λ(im) [1/year]: log–log between the points, the end segments' power law beyond."""
        x, y = np.log(np.asarray(self.im)), np.log(np.asarray(self.rate))
        k = self.slopes()
        q = np.log(np.asarray(im, dtype=float))
        seg = np.clip(np.searchsorted(x, q) - 1, 0, len(k) - 1)
        return np.exp(y[seg] - k[seg] * (q - x[seg]))

    def return_period_of(self, im: float) -> float:
        """The return period [years] of the surface PGA ``im``: 1/λ(im)."""
        return float(1.0 / self.rate_at(im))

    def local_power_law(self, im: float) -> tuple[float, float]:
        """(k0, k) of λ = k0·im^−k through the segment that holds ``im`` (an end
        segment beyond the points)."""
        x, y = np.log(np.asarray(self.im)), np.log(np.asarray(self.rate))
        k = self.slopes()
        seg = int(np.clip(np.searchsorted(x, math.log(im)) - 1, 0, len(k) - 1))
        return float(math.exp(y[seg] + k[seg] * x[seg])), float(k[seg])


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
    from rockcli.codecheck.hazard import site_parameters
    from rockcli.codecheck.spectra import soil_amplification, topographic_amplification

    s_t = topographic_amplification(topography)  # type: ignore[arg-type]
    out = []
    for TR in grid.return_periods:
        ag, F0, _ = site_parameters(grid, lon, lat, float(TR))
        out.append(SitePoint(float(TR), ag, F0, soil_amplification(soil, ag, F0) * s_t))  # type: ignore[arg-type]
    return tuple(out)


def curve_of(points: tuple[SitePoint, ...]) -> HazardCurve:
    """The hazard curve of the surface PGA through the site's points."""
    return HazardCurve(tuple(p.pga for p in points), tuple(1.0 / p.TR for p in points))


@dataclass(frozen=True)
class DamageRate:
    """The annual rate of a damage state and what it means.

    Attributes:
        rate: λ_DS [1/year] by integration. closed_form: k0·θ^−k·exp(k²β²/2) [1/year].
        k0, k: the power law of the closed form. median_rate: λ(θ) [1/year].
        tails: the share of λ_DS from intensities beyond the grid's points (∫ P·|dλ| there,
            over λ_DS) [-].
    """

    rate: float
    closed_form: float
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


def damage_rate(curve: HazardCurve, median: float, beta: float) -> DamageRate:
    """λ_DS of a lognormal fragility (median θ [g], dispersion β) on ``curve`` (module
    docstring)."""
    from scipy.integrate import quad

    mu = math.log(median)
    lo, hi = mu - SPAN_BETAS * beta, mu + SPAN_BETAS * beta
    kinks = [x for x in np.log(curve.im) if lo < x < hi]

    def integrand(x: float) -> float:
        z = (x - mu) / beta
        return (
            float(curve.rate_at(math.exp(x)))
            * math.exp(-0.5 * z * z)
            / (beta * math.sqrt(2.0 * math.pi))
        )

    edges = [lo, *kinks, hi]
    pieces = [quad(integrand, a, b, epsabs=0.0, epsrel=1e-11, limit=200)[0]
              for a, b in zip(edges[:-1], edges[1:], strict=True)]  # fmt: skip
    rate = math.fsum(pieces)
    k0, k = curve.local_power_law(median)
    closed = k0 * median**-k * math.exp(0.5 * k * k * beta * beta)
    return DamageRate(rate, closed, k0, k, float(curve.rate_at(median)),
                      tail_share(curve, mu, beta) / rate)  # fmt: skip


def tail_share(curve: HazardCurve, mu: float, beta: float) -> float:
    """∫ P(DS | im)·|dλ| over the intensities beyond the grid's points [1/year]: below the
    30-year PGA and above the 2475-year one, where the curve is extrapolated."""
    from scipy.integrate import quad
    from scipy.special import ndtr

    slopes = curve.slopes()
    x = np.log(curve.im)

    def density(t: float, k: float) -> float:  # P(DS | e^t)·|dλ/dt|
        return float(ndtr((t - mu) / beta)) * k * float(curve.rate_at(math.exp(t)))

    below_from = min(x[0], mu - SPAN_BETAS * beta)
    below = quad(density, below_from, x[0], args=(slopes[0],), epsrel=1e-10)[0]
    above_to = x[-1] + 60.0 / slopes[-1]  # λ down by e^−60
    above = quad(density, x[-1], above_to, args=(slopes[-1],), epsrel=1e-10, limit=200)[0]
    return below + above
