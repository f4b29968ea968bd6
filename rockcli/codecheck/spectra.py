"""NTC elastic response spectra of the horizontal components, and the return period.

NTC 2008 §3.2.3.2 and NTC 2018 §3.2.3.2 give the same spectrum (spec/ntc.md, "Elastic response
spectrum"); the return period differs only in the 35-year floor on VR (NTC 2008 §2.4.3).

Units of this module, one convention throughout:

- ag in **g** (a fraction of gravity, as in the hazard grid); Se in g; SDe in **m**;
- periods T in s;
- damping ξ in **percent** (5.0 = 5 %), as in the code's η = √(10/(5 + ξ)). The record spectrum of
  :mod:`rockcli.codecheck.response` takes its ``damping`` as a fraction (0.05); its
  :class:`~rockcli.codecheck.response.RecordSpectrum` methods take ξ in percent like these.

Pure and silent: only :mod:`math` and numpy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from typing import NamedTuple, Protocol, TypeVar

import numpy as np
from numpy.typing import ArrayLike

from rockcli.codecheck.categories import Edition, LimitState, Soil, Topography
from rockcli.errors import InputError
from rockcli.units import DEFAULT_GRAVITY

_E = TypeVar("_E", bound=StrEnum)


#: S_S = clip(c0 − c1·F0·ag/g, low, high) per soil (NTC §3.2.3.2.1, Tab. 3.2.V).
_SS_TERMS: dict[Soil, tuple[float, float, float, float]] = {
    Soil.A: (1.00, 0.00, 1.00, 1.00),
    Soil.B: (1.40, 0.40, 1.00, 1.20),
    Soil.C: (1.70, 0.60, 1.00, 1.50),
    Soil.D: (2.40, 1.50, 0.90, 1.80),
    Soil.E: (2.00, 1.10, 1.00, 1.60),
}
#: C_C = k·(TC*)^n per soil (NTC §3.2.3.2.1, Tab. 3.2.V).
_CC_TERMS: dict[Soil, tuple[float, float]] = {
    Soil.A: (1.00, 0.00),
    Soil.B: (1.10, -0.20),
    Soil.C: (1.05, -0.33),
    Soil.D: (1.25, -0.50),
    Soil.E: (1.15, -0.40),
}
#: Topographic amplification S_T (NTC §3.2.3.2.1, Tab. 3.2.VI; at the top of the relief).
_ST: dict[Topography, float] = {
    Topography.T1: 1.0,
    Topography.T2: 1.2,
    Topography.T3: 1.2,
    Topography.T4: 1.4,
}
#: TE [s] per soil, start of the displacement spectrum's long-period branches (NTC 2008
#: §3.2.3.2.3, Tab. 3.2.VII).
_TE: dict[Soil, float] = {Soil.A: 4.5, Soil.B: 5.0, Soil.C: 6.0, Soil.D: 6.0, Soil.E: 6.0}
#: TF [s], beyond which SDe = dg (same table, all soils).
TF = 10.0
#: Probability of exceedance P_VR in VR per limit state (NTC §3.2.1, Tab. 3.2.I).
P_VR: dict[LimitState, float] = {
    LimitState.SLO: 0.81,
    LimitState.SLD: 0.63,
    LimitState.SLV: 0.10,
    LimitState.SLC: 0.05,
}
#: Floor on VR in NTC 2008 §2.4.3 ("Se VR ≤ 35 anni si pone comunque VR = 35 anni") [years].
VR_MIN_2008 = 35.0
#: Lower bound of the damping correction η (NTC §3.2.3.2.1, Eq. 3.2.6).
ETA_MIN = 0.55
#: Damping of the reference spectrum [%] (η = 1).
XI_REFERENCE = 5.0
#: Factor of the peak ground displacement dg = 0.025·ag·S·TC·TD (NTC 2008 Eq. 3.2.13;
#: EN 1998-1 Eq. 3.12).
DG_FACTOR = 0.025


class CornerPeriods(NamedTuple):
    """Corner periods of the acceleration spectrum [s]."""

    TB: float
    TC: float
    TD: float


def soil_amplification(soil: Soil, ag: float, F0: float) -> float:
    """Stratigraphic amplification S_S, with its bounds.

    NTC §3.2.3.2.1, Tab. 3.2.V (NTC 2008 and NTC 2018).

    Args:
        soil: subsoil category A–E.
        ag: peak ground acceleration on rock [g].
        F0: maximum spectral amplification [-].
    """
    c0, c1, low, high = _SS_TERMS[Soil(soil)]
    return min(max(c0 - c1 * F0 * ag, low), high)


def period_coefficient(soil: Soil, Tc_star: float) -> float:
    """Coefficient C_C of the corner period TC = C_C·TC*.

    NTC §3.2.3.2.1, Tab. 3.2.V.

    Args:
        soil: subsoil category A–E.
        Tc_star: TC* of the hazard grid [s].
    """
    k, n = _CC_TERMS[Soil(soil)]
    return k * Tc_star**n


def topographic_amplification(topography: Topography) -> float:
    """Topographic amplification S_T (at the top of the relief).

    NTC §3.2.3.2.1, Tab. 3.2.VI.

    Args:
        topography: topographic category T1–T4.
    """
    return _ST[Topography(topography)]


def damping_correction(xi: float) -> float:
    """Damping correction η = √(10/(5 + ξ)) ≥ 0.55.

    NTC §3.2.3.2.1, Eq. 3.2.6.

    Args:
        xi: viscous damping ratio **in percent** [%] (5.0 for 5 %; η = 1).
    """
    if not xi > -5.0:
        raise InputError("damping out of range", where="xi", value=xi, allowed="ξ > −5 [%]")
    return max(math.sqrt(10.0 / (5.0 + xi)), ETA_MIN)


def corner_periods(soil: Soil, ag: float, Tc_star: float) -> CornerPeriods:
    """Corner periods TB = TC/3, TC = C_C·TC*, TD = 4.0·ag/g + 1.6.

    NTC §3.2.3.2.1, Eqs. 3.2.7–3.2.9.

    Args:
        soil: subsoil category A–E.
        ag: peak ground acceleration on rock [g] (so ag/g is ag itself).
        Tc_star: TC* of the hazard grid [s].
    """
    TC = period_coefficient(soil, Tc_star) * Tc_star
    return CornerPeriods(TB=TC / 3.0, TC=TC, TD=4.0 * ag + 1.6)


def displacement_corner_periods(soil: Soil) -> tuple[float, float]:
    """TE and TF of the displacement spectrum [s] (A 4.5, B 5.0, C–E 6.0; TF = 10).

    NTC 2008 §3.2.3.2.3, Tab. 3.2.VII.

    Args:
        soil: subsoil category A–E.
    """
    return _TE[Soil(soil)], TF


def reference_period(VN: float, CU: float, edition: Edition | str) -> float:
    """Reference period VR = VN·CU [years]; NTC 2008 also sets VR ≥ 35 years.

    NTC 2008 §2.4.3, Eq. 2.4.1 ("Se VR ≤ 35 anni si pone comunque VR = 35 anni");
    NTC 2018 §2.4.3, Eq. 2.4.1. For the 2019 edition no floor is applied: we could not check
    the NTC 2018 text here and, to our reading, it no longer carries the 35-year sentence
    (unverified; its Tab. 2.4.I sets minimum VN instead). A VR below 35 years in 2019 gives a
    TR that the hazard grid may refuse (TR < 30 years).

    Args:
        VN: nominal life [years].
        CU: use coefficient [-] (class I 0.7, II 1.0, III 1.5, IV 2.0).
        edition: "2009" (NTC 2008) or "2019" (NTC 2018).
    """
    VR = VN * CU
    if _edition(edition) is Edition.E2009:
        return max(VR, VR_MIN_2008)
    return VR


def return_period(VN: float, CU: float, limit_state: LimitState, edition: Edition | str) -> float:
    """Return period TR = −VR / ln(1 − P_VR) [years].

    NTC §3.2.1, Tab. 3.2.I and Allegato A (Eq. 2 of DM 14/01/2008); VR from §2.4.3.

    Args:
        VN: nominal life [years].
        CU: use coefficient [-].
        limit_state: SLO (P_VR 81 %), SLD (63 %), SLV (10 %), SLC (5 %).
        edition: "2009" (VR ≥ 35 years) or "2019".
    """
    VR = reference_period(VN, CU, edition)
    return -VR / math.log(1.0 - P_VR[LimitState(limit_state)])


def _edition(edition: Edition | str) -> Edition:
    try:
        return Edition(edition)
    except ValueError:
        raise InputError(
            "unknown code edition", where="edition", value=edition, allowed="'2009' or '2019'"
        ) from None


class SpectralDemand(Protocol):
    """What the checks need of a demand: a code spectrum or a record's own spectrum."""

    @property
    def pga_ground(self) -> float:
        """Peak ground acceleration at the site [g]."""
        ...

    def Se(self, T: float, xi: float = XI_REFERENCE) -> float:
        """Elastic (pseudo-)acceleration at period T [s], damping ξ [%], in g."""
        ...

    def SDe(self, T: float, xi: float = XI_REFERENCE) -> float:
        """Elastic displacement at period T [s], damping ξ [%], in m."""
        ...


def pga_ground(spectrum: SpectralDemand) -> float:
    """Peak ground acceleration at the site, ag·S for the code spectrum [g].

    Circolare 617/2009 §C8A.4.2.1 (the DLS check a0* ≥ ag·S); a record's PGA in its place
    (spec/ntc.md, "Elastic response spectrum").

    Args:
        spectrum: an :class:`ElasticSpectrum` or a record spectrum.
    """
    return spectrum.pga_ground


@dataclass(frozen=True)
class ElasticSpectrum:
    """The NTC elastic spectrum of the horizontal components at a site.

    NTC §3.2.3.2.1 (acceleration, Eq. 3.2.4) and NTC 2008 §3.2.3.2.3 (displacement).

    Attributes:
        ag: peak ground acceleration on rock [g].
        F0: maximum spectral amplification [-].
        Tc_star: TC* [s].
        soil: subsoil category A–E.
        topography: topographic category T1–T4.
        g: gravity [m/s²] turning g into m/s² for SDe (the NTC worked examples use 9.81).
    """

    ag: float
    F0: float
    Tc_star: float
    soil: Soil = Soil.A
    topography: Topography = Topography.T1
    g: float = DEFAULT_GRAVITY

    def __post_init__(self) -> None:
        for name in ("ag", "F0", "Tc_star", "g"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise InputError("must be a finite number > 0", where=name, value=value)
        object.__setattr__(self, "soil", _member(Soil, self.soil, "soil", "A, B, C, D, E"))
        object.__setattr__(
            self, "topography", _member(Topography, self.topography, "topography", "T1–T4")
        )

    @property
    def S_S(self) -> float:
        """Stratigraphic amplification [-]."""
        return soil_amplification(self.soil, self.ag, self.F0)

    @property
    def S_T(self) -> float:
        """Topographic amplification [-]."""
        return topographic_amplification(self.topography)

    @property
    def S(self) -> float:
        """S = S_S·S_T [-] (NTC Eq. 3.2.5)."""
        return self.S_S * self.S_T

    @property
    def C_C(self) -> float:
        """Coefficient of TC [-]."""
        return period_coefficient(self.soil, self.Tc_star)

    @property
    def TB(self) -> float:
        """Start of the plateau [s]."""
        return corner_periods(self.soil, self.ag, self.Tc_star).TB

    @property
    def TC(self) -> float:
        """End of the plateau [s]."""
        return corner_periods(self.soil, self.ag, self.Tc_star).TC

    @property
    def TD(self) -> float:
        """Start of the constant-displacement branch [s]."""
        return corner_periods(self.soil, self.ag, self.Tc_star).TD

    @property
    def TE(self) -> float:
        """Start of the displacement spectrum's long-period branches [s]."""
        return displacement_corner_periods(self.soil)[0]

    @property
    def TF(self) -> float:
        """Start of the constant SDe = dg [s]."""
        return displacement_corner_periods(self.soil)[1]

    @property
    def dg(self) -> float:
        """Peak ground displacement dg = 0.025·ag·S·TC·TD, ag in m/s² [m] (NTC 2008 Eq. 3.2.13)."""
        return DG_FACTOR * self.ag * self.g * self.S * self.TC * self.TD

    @property
    def pga_ground(self) -> float:
        """ag·S [g]."""
        return self.ag * self.S

    def Se(self, T: float, xi: float = XI_REFERENCE) -> float:
        """Elastic acceleration Se(T) [g], the four branches of NTC §3.2.3.2.1, Eq. 3.2.4.

        Args:
            T: period [s], ≥ 0.
            xi: viscous damping [%] (5.0 = 5 %).
        """
        _check_period(T)
        eta = damping_correction(xi)
        TB, TC, TD = corner_periods(self.soil, self.ag, self.Tc_star)
        plateau = self.ag * self.S * eta * self.F0
        if T < TB:
            return plateau * (T / TB + (1.0 - T / TB) / (eta * self.F0))
        if T < TC:
            return plateau
        if T < TD:
            return plateau * TC / T
        return plateau * TC * TD / T**2

    def SDe(self, T: float, xi: float = XI_REFERENCE) -> float:
        """Elastic displacement SDe(T) [m].

        NTC 2008 §3.2.3.2.3, Eqs. 3.2.12–3.2.13: SDe = Se·g·(T/2π)² for T ≤ TE; for
        TE < T ≤ TF, SDe = 0.025·ag·S·TC·TD·[F0·η + (1 − F0·η)·(T − TE)/(TF − TE)]; for T > TF,
        SDe = dg = 0.025·ag·S·TC·TD (ag in m/s²).

        The TE–TF branches are written from the brief (spec/ntc.md names them without the
        formula) and match EN 1998-1 Annex A (Eq. A.2) with its 2.5 replaced by F0; the NTC text
        itself could not be checked here: **unverified**. They do not join the Se branch
        exactly at TE (0.025 against 1/4π² = 0.02533: a 1.3 % step down), as in EN 1998-1.

        Args:
            T: period [s], ≥ 0.
            xi: viscous damping [%] (5.0 = 5 %).
        """
        _check_period(T)
        if T <= self.TE:
            return self.Se(T, xi) * self.g * (T / (2.0 * math.pi)) ** 2
        if T <= self.TF:
            F0_eta = self.F0 * damping_correction(xi)
            return self.dg * (F0_eta + (1.0 - F0_eta) * (T - self.TE) / (self.TF - self.TE))
        return self.dg

    def curve(self, periods: ArrayLike, xi: float = XI_REFERENCE) -> tuple[np.ndarray, np.ndarray]:
        """Se [g] and SDe [m] at an array of periods [s] (for tables and plots).

        Args:
            periods: periods [s], ≥ 0.
            xi: viscous damping [%].
        """
        T = np.asarray(periods, dtype=float).ravel()
        Se = np.array([self.Se(float(t), xi) for t in T])
        SDe = np.array([self.SDe(float(t), xi) for t in T])
        return Se, SDe


def _check_period(T: float) -> None:
    if not (math.isfinite(T) and T >= 0.0):
        raise InputError("period out of range", where="T", value=T, allowed="T ≥ 0 [s]")


def _member(enum: type[_E], value: object, where: str, allowed: str) -> _E:
    try:
        return enum(str(value))
    except ValueError:
        raise InputError(f"unknown {where}", where=where, value=value, allowed=allowed) from None
