"""The floor spectrum's lower bound of Circolare 7/2019 §C7.2.3, Eq. C7.2.5:
S_eZ(T, ξ, z) = √(Σ S_eZ,k²) (≥ S_e(T, ξ) per T > T1).

Every expected number is written out here from the clause's formulas (NTC 2018 §3.2.3.2.1 for
the ground spectrum, Eqs. C7.2.6–C7.2.10 for the first mode's floor spectrum), not read back
from rock's functions.
"""

from __future__ import annotations

import math

import pytest

from rockcli.codecheck.position import Position
from rockcli.codecheck.rules2019 import bounded_floor_displacement, bounded_floor_spectrum
from rockcli.codecheck.spectra import ElasticSpectrum, Soil

G = 9.81
AG, F0, TC_STAR = 0.15, 2.5, 0.29
POS = Position(Z=4.0, H=10.0, T1=0.3, gamma=1.2, psi=0.5)


def ground_se(T: float, xi: float) -> float:
    """NTC 2018 Eq. 3.2.2, soil B, T1 topography, T_C ≤ T < T_D (the branch used here) [g]."""
    S = min(1.20, max(1.00, 1.40 - 0.40 * F0 * AG))  # 1.25 → 1.20
    TC = 1.10 * TC_STAR**-0.20 * TC_STAR
    TD = 4.0 * AG + 1.6
    assert TC <= T < TD
    eta = math.sqrt(10.0 / (5.0 + xi))
    return AG * S * eta * F0 * TC / T


def first_mode_floor(T: float, xi: float) -> float:
    """Eqs. C7.2.6–C7.2.10 for the first mode, T ≥ b·T1 (ξ_k = 5 % read as in the notes) [g]."""
    S = 1.20
    a_z = AG * S * F0 * abs(1.2 * 0.5) * math.sqrt(1.0 + 0.0004 * 5.0**2)  # T1 on the plateau
    amp = 1.1 * 0.05**-0.5 * math.sqrt(10.0 / (5.0 + xi))
    return a_z * amp / (1.0 + (amp - 1.0) * (T / (1.1 * 0.3) - 1.0) ** 1.2)


def spectrum() -> ElasticSpectrum:
    return ElasticSpectrum(AG, F0, TC_STAR, Soil.B, g=G)


def test_beyond_t1_the_ground_spectrum_bounds_the_floor_spectrum() -> None:
    T, xi = 2.0, 8.0
    floor, ground = first_mode_floor(T, xi), ground_se(T, xi)
    assert floor < ground  # the case the bound is for: secant periods far above T1
    assert bounded_floor_spectrum(spectrum(), T, POS, xi) == pytest.approx(ground, rel=1e-12)


def test_beyond_t1_the_displacement_demand_is_the_ground_one() -> None:
    T, xi = 2.0, 8.0
    expected = ground_se(T, xi) * G * T**2 / (4.0 * math.pi**2)
    got = bounded_floor_displacement(spectrum(), T, POS, xi, G)
    assert got == pytest.approx(expected, rel=1e-12)


def test_below_t1_the_floor_spectrum_is_unbounded() -> None:
    """T < T1: the clause's bound does not apply, the floor spectrum stands (its rising branch
    a_Z·A/{1 + (A − 1)(1 − T/(a·T1))^1.6}, Eq. C7.2.8)."""
    T, xi = 0.2, 8.0
    a_z = AG * 1.20 * F0 * 0.6 * math.sqrt(1.01)
    amp = 1.1 * 0.05**-0.5 * math.sqrt(10.0 / 13.0)
    expected = a_z * amp / (1.0 + (amp - 1.0) * (1.0 - T / (0.8 * 0.3)) ** 1.6)
    assert bounded_floor_spectrum(spectrum(), T, POS, xi) == pytest.approx(expected, rel=1e-12)


def test_on_the_plateau_the_floor_spectrum_governs() -> None:
    """Just above T1 the amplified floor spectrum is far above the ground one: unchanged."""
    T, xi = 0.32, 5.0
    a_z = AG * 1.20 * F0 * 0.6 * math.sqrt(1.01)
    expected = a_z * 1.1 * 0.05**-0.5
    assert bounded_floor_spectrum(spectrum(), T, POS, xi) == pytest.approx(expected, rel=1e-12)
