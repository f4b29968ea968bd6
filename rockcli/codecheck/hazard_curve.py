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
        """The return period [years] of the intensity ``im``: 1/λ(im)."""
        return float(1.0 / self.rate_at(im))

    def local_power_law(self, im: float) -> tuple[float, float]:
        """(k0, k) of λ = k0·im^−k through the segment that holds ``im`` (an end
        segment beyond the points)."""
        x, y = np.log(np.asarray(self.im)), np.log(np.asarray(self.rate))
        k = self.slopes()
        seg = int(np.clip(np.searchsorted(x, math.log(im)) - 1, 0, len(k) - 1))
        return float(math.exp(y[seg] + k[seg] * x[seg])), float(k[seg])
