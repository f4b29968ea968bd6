"""The design tension resistance of a steel tie-rod, NTC 2018 §4.2.4.1.2, by hand.

Numbers: NTC 2018 Tab. 11.3.IX (S235 235/360 MPa, S275 275/430, S355 355/510 for t ≤ 40 mm),
γ_M0 = 1.05 and γ_M2 = 1.25 (Tab. 4.2.VII). A Ø20 bar: A = π·0.02²/4 = 314.159 mm². Written
out below with the digits a designer would; 1e-12 relative where the same product is formed in
another order.
"""

from __future__ import annotations

import math

import pytest

from rockcli.codecheck.steel import GRADES, rod_area, tension_resistance

A20 = math.pi * 0.020**2 / 4  # [m²]


def test_s275_bar_of_20_mm() -> None:
    # N_pl,Rd = 314.159e-6 · 275e6 / 1.05 = 82 280 N; N_u,Rd = 0.9 · 314.159e-6 · 430e6 / 1.25
    # = 97 263 N: the plastic resistance governs.
    fy, fu = GRADES["S275"]
    res = tension_resistance(rod_area(0.020), fy, fu)
    assert res.plastic == pytest.approx(A20 * 275e6 / 1.05, rel=1e-12)
    assert res.plastic == pytest.approx(82_280.0, abs=1.0)
    assert res.ultimate == pytest.approx(0.9 * A20 * 430e6 / 1.25, rel=1e-12)
    assert res.strength == res.plastic and res.governs == "plastic"


def test_the_ultimate_resistance_governs_a_high_yield_ratio() -> None:
    # fy/fu = 0.95: 0.9·fu/1.25 = 0.758·fy < fy/1.05 = 0.952·fy.
    res = tension_resistance(A20, 400e6, 421e6)
    assert res.governs == "ultimate"
    assert res.strength == pytest.approx(0.9 * A20 * 421e6 / 1.25, rel=1e-12)


def test_the_anchor_caps_the_strength() -> None:
    fy, fu = GRADES["S355"]
    res = tension_resistance(A20, fy, fu, anchor=50e3)
    assert res.strength == 50e3 and res.governs == "anchor"


def test_measured_strengths_are_divided_by_the_confidence_factor() -> None:
    plain = tension_resistance(A20, 300e6, 450e6)
    existing = tension_resistance(A20, 300e6, 450e6, factor=1.35)
    assert existing.plastic == pytest.approx(plain.plastic / 1.35, rel=1e-12)
    assert existing.ultimate == pytest.approx(plain.ultimate / 1.35, rel=1e-12)


def test_bars_side_by_side_add_their_areas() -> None:
    assert rod_area(0.020, 3) == pytest.approx(3 * A20, rel=1e-15)
