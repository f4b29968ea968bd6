"""A hazard curve through the points of the NTC grid: λ(im) = 1/TR at the grid's return
periods, log–log between them (the rule DM 14/01/2008 Allegato A, Eq. 3, applies to ag:
log ag linear in log TR is log λ linear in log ag), and the power law of the end segment
beyond them. The intensity is ag on rock (a mechanism's capacity ag: the return period it
bears) or the surface PGA ag·S (a fragility's rate: rockcli.risk.curve).

Pure and silent: numpy and math.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: The return periods [years] a capacity's T_Rc is read within: beyond, the end segment's power
#: law has no support (a capacity far below the curve's first point would come back every
#: 1e-35 years, one far above it after 1e75), and T_Rc is the bound (the notes say so).
TR_BOUNDS = (1.0, 1e6)
#: The steepest segment a hazard curve may have, λ ∝ im^−k (the grid's curves of ag: k ≈ 1.5–4;
#: two points whose ag barely differ would make T_Rc jump by orders of magnitude for a small
#: change of the capacity).
STEEPEST = 30.0


def rising(im: list[float] | tuple[float, ...], periods: list[float] | tuple[float, ...]) -> bool:
    """The points make a hazard curve: im grows with the return period, each segment no
    steeper than STEEPEST."""
    points = list(zip(im, periods, strict=True))
    return len(points) >= 2 and all(
        b_im > a_im and b_tr > a_tr and math.log(b_tr / a_tr) <= STEEPEST * math.log(b_im / a_im)
        for (a_im, a_tr), (b_im, b_tr) in zip(points[:-1], points[1:], strict=True)
    )


@dataclass(frozen=True)
class HazardCurve:
    """The site's λ(im) through its points (im ascending, λ descending).

    Attributes:
        im: the intensity at each grid return period [g], ascending.
        rate: 1/TR at each [1/year], descending.
        source: where the points come from: "grid" (the hazard grid's return periods at a
            site) or "model" (the ag the model gives each limit state, at the limit state's
            return period from V_R).
    """

    im: tuple[float, ...]
    rate: tuple[float, ...]
    source: str = "grid"

    @property
    def periods(self) -> tuple[float, ...]:
        """The return periods of the points [years], ascending."""
        return tuple(1.0 / r for r in self.rate)

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
        """The return period [years] of the intensity ``im``: 1/λ(im), within TR_BOUNDS."""
        years = float(1.0 / self.rate_at(im)) if im > 0.0 else TR_BOUNDS[0]
        return min(max(years, TR_BOUNDS[0]), TR_BOUNDS[1])

    def local_power_law(self, im: float) -> tuple[float, float]:
        """(k0, k) of λ = k0·im^−k through the segment that holds ``im`` (an end
        segment beyond the points)."""
        x, y = np.log(np.asarray(self.im)), np.log(np.asarray(self.rate))
        k = self.slopes()
        seg = int(np.clip(np.searchsorted(x, math.log(im)) - 1, 0, len(k) - 1))
        return float(math.exp(y[seg] + k[seg] * x[seg])), float(k[seg])
