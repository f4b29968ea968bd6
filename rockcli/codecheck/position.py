"""Where the mechanism sits in the building: height Z, building height H, storeys N, period T1."""

from __future__ import annotations

import math
from dataclasses import dataclass

from rockcli.notes import Note

#: C1 of the building period estimate T1 = C1·H^(3/4) for masonry and other buildings
#: (NTC 2008 §7.3.3.2 and NTC 2018 §7.3.3.2, Eq. 7.3.5: C1 = 0.050).
PERIOD_C1 = 0.050


def psi(Z: float, H: float) -> float:
    """First mode shape ψ(Z) = Z/H [-] (Circolare 617/2009 §C8A.4.2.2; linear mode)."""
    return Z / H


def gamma(N: int) -> float:
    """Modal participation factor γ = 3N/(2N+1) [-] (Circolare 617/2009 §C8A.4.2.2)."""
    return 3.0 * N / (2.0 * N + 1.0)


def building_period(H: float) -> float:
    """T1 = C1·H^(3/4) [s] with C1 = 0.050 (NTC §7.3.3.2, Eq. 7.3.5), H in m."""
    return PERIOD_C1 * H**0.75


def height_amplification(Ts: float, T1: float) -> float:
    """(Ts/T1)² / √[(1 − Ts/T1)² + 0.02·Ts/T1] [-].

    Circolare 617/2009 §C8A.4.2.3, non-linear check of a mechanism at height (the response of
    an oscillator of period Ts on a floor vibrating with period T1, 5 % damping).
    """
    r = Ts / T1
    return r**2 / math.sqrt((1.0 - r) ** 2 + 0.02 * r)


@dataclass(frozen=True)
class Position:
    """The mechanism's place in the building.

    Attributes:
        Z: height of the base of the mechanism above the foundation [m] (0: on the ground).
        H: building height [m]. T1: first period [s]. gamma, psi: as in the Circolare.
        notes: how defaults were taken (shown with the results).
        damping: damping ratio of the building's first mode ξ_k, a fraction (default 5 %,
            Circolare 7/2019 §C7.2.3); the 2019 floor spectrum and the floor motion use it.
    """

    Z: float = 0.0
    H: float | None = None
    T1: float | None = None
    gamma: float = 1.0
    psi: float = 0.0
    notes: tuple[str, ...] = ()
    damping: float = 0.05

    @property
    def at_height(self) -> bool:
        """True when the mechanism is above the ground (Z > 0)."""
        return self.Z > 0.0


def position(
    Z: float,
    H: float | None,
    N: int | None,
    T1: float | None,
    gamma_: float | None,
    psi_: float | None,
    damping: float = 0.05,
) -> Position:
    """Position with the Circolare's defaults: ψ = Z/H, γ = 3N/(2N+1), T1 = 0.05·H^0.75."""
    if Z <= 0.0 or H is None:
        return Position()
    notes = []
    if T1 is None:
        T1 = building_period(H)
        notes.append(Note("T1_default", "T1 = 0.05·H^0.75 = {T1:.3f} s (NTC §7.3.3.2), not given",
                          T1=float(T1)))  # fmt: skip
    g = gamma_ if gamma_ is not None else gamma(N or 1)
    p = psi_ if psi_ is not None else psi(Z, H)
    return Position(Z=Z, H=H, T1=T1, gamma=g, psi=p, notes=tuple(notes), damping=damping)
