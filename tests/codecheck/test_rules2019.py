"""The 2019 rules (rockcli.codecheck.rules2019): floor spectra and capacities by root search.

Sources: spec/ntc.md "2019 rules" (Circolare 7/2019 §C8.7.1.2.1, §C7.2.3) and its reading of
the ξ_k ambiguity; closed forms where the spectrum is linear in ag (soil A: S = 1).
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from rockcli.codecheck.demand import LimitStateDemand
from rockcli.codecheck.kinematic import Mechanism, capacity, failure_rotations
from rockcli.codecheck.position import Position
from rockcli.codecheck.rules2019 import (
    PLATEAU_A,
    PLATEAU_B,
    check_2019,
    displacement_check,
    floor_acceleration,
    floor_plateau,
    floor_spectrum,
    limit_displacements,
    sld_check,
)
from rockcli.codecheck.spectra import ElasticSpectrum, Soil
from rockcli.mechanics import Block, Restrainer
from rockcli.mechanisms.block import BlockSide

G = 9.81
BLOCK = Block(R=2.0, alpha=0.15, mass=1e4, g=G)
GROUND = Position()
HIGH = Position(Z=6.0, H=12.0, T1=0.4, gamma=1.2, psi=0.5)


def code(ls: str, ag: float, soil: Soil = Soil.A) -> LimitStateDemand:
    return LimitStateDemand(ls, ag, lambda a: ElasticSpectrum(a, 2.5, 0.3, soil, g=G), "test")


def test_floor_plateau_reading() -> None:
    # spec/ntc.md "Ambiguity": ξ_k as a fraction in 1.1·ξ_k^−0.5: 1.1/√0.05 = 4.919 at 5 %,
    # times η(ξ) = √(10/(5 + ξ)) of the mechanism (1 at 5 %, √(10/13) at 8 %).
    assert floor_plateau(5.0) == pytest.approx(1.1 / math.sqrt(0.05), rel=1e-14)
    assert floor_plateau(8.0) == pytest.approx(
        1.1 / math.sqrt(0.05) * math.sqrt(10 / 13), rel=1e-14
    )


def test_floor_spectrum_shape() -> None:
    # §C7.2.3: a_Z at T = 0, the plateau a_Z·A on [a T1, b T1), continuous at both corners.
    a_z, T1 = 0.3, 0.5
    amp = floor_plateau(5.0)
    assert floor_spectrum(0.0, a_z, T1, 5.0) == pytest.approx(a_z, rel=1e-14)
    assert floor_spectrum(T1, a_z, T1, 5.0) == pytest.approx(a_z * amp, rel=1e-14)
    for corner in (PLATEAU_A * T1, PLATEAU_B * T1):
        below = floor_spectrum(corner * (1 - 1e-9), a_z, T1, 5.0)
        above = floor_spectrum(corner * (1 + 1e-9), a_z, T1, 5.0)
        assert below == pytest.approx(above, rel=1e-6)


def test_floor_acceleration() -> None:
    # a_Z = Se(T1)·|γψ|·√(1 + 0.0004·ξ_k²), ξ_k = 5 (percent).
    spec = ElasticSpectrum(0.2, 2.5, 0.3, Soil.A, g=G)
    expected = spec.Se(0.4) * 1.2 * 0.5 * math.sqrt(1.01)
    assert floor_acceleration(spec, HIGH) == pytest.approx(expected, rel=1e-14)


def test_floor_spectrum_uses_the_building_damping() -> None:
    # §C7.2.3 with ξ_k = 10 % (building.damping = 0.10): a_Z = Se(T1, ξ_k)·|γψ|·√(1 + 0.0004·ξ_k²)
    # and the plateau factor 1.1·ξ_k^−0.5 (ξ_k as a fraction; docs/interpretations.md).
    spec = ElasticSpectrum(0.2, 2.5, 0.3, Soil.A, g=G)
    damped = replace(HIGH, damping=0.10)
    expected = spec.Se(0.4, 10.0) * 1.2 * 0.5 * math.sqrt(1.04)
    assert floor_acceleration(spec, damped) == pytest.approx(expected, rel=1e-14)
    assert floor_plateau(5.0, 10.0) == pytest.approx(1.1 / math.sqrt(0.10), rel=1e-14)


def test_sld_capacity_on_the_ground_soil_a() -> None:
    # Soil A: S = 1, so ag·S(ag) = a0*/g gives ag,SLD = a0*/g = tan α (e* = FC = 1).
    cap = capacity(Mechanism(BlockSide(BLOCK, 1)), FC=1.0)
    check = sld_check(cap, code("SLD", 0.05), GROUND, G)
    assert check.capacity == pytest.approx(math.tan(0.15), rel=1e-12)
    assert check.demand == 0.05 and check.passed


def test_sld_capacity_at_height_inverts_the_floor_acceleration() -> None:
    cap = capacity(Mechanism(BlockSide(BLOCK, 1)), FC=1.0)
    dem = code("SLD", 0.05)
    check = sld_check(cap, dem, HIGH, G)
    assert check.capacity is not None
    a_z = floor_acceleration(dem.at_ag(check.capacity), HIGH)
    assert a_z * G == pytest.approx(cap.a0_star, rel=1e-9)


def test_displacement_capacity_inverts_the_spectrum() -> None:
    # The capacity ag makes SDe(T_SLV, 8 %) equal to d_SLV (root search, §C8.7.1.2.1).
    cap = capacity(Mechanism(BlockSide(BLOCK, 1)), FC=1.0)
    dem = code("SLV", 0.15, Soil.C)
    d, T = 0.4 * cap.d0_star, 1.2
    check = displacement_check("SLV", d, T, dem, GROUND, G, sld_cap=None)
    assert check.capacity is not None
    assert dem.at_ag(check.capacity).SDe(T, 8.0) == pytest.approx(d, rel=1e-9)


def test_capacity_below_sld_is_raised_to_sld() -> None:
    # §C8.7.1.2.1: if ag,SLV < ag,SLD take ag,SLD.
    check = displacement_check("SLV", 1e-6, 1.0, code("SLV", 0.15), GROUND, G, sld_cap=0.2)
    assert check.capacity == 0.2 and "ag,SLD taken" in check.note


def test_linear_slv_is_q_times_sld() -> None:
    cap = capacity(Mechanism(BlockSide(BLOCK, 1)), FC=1.0)
    dem = {ls: code(ls, ag) for ls, ag in (("SLD", 0.05), ("SLV", 0.15), ("SLC", 0.2))}
    values, checks, _ = check_2019(cap, dem, GROUND, 2.0, None)
    sld, slv_linear = checks[0], checks[1]
    assert slv_linear.capacity == pytest.approx(2.0 * sld.capacity, rel=1e-14)
    assert values["d_SLV"] == pytest.approx(0.4 * cap.d0_star, rel=1e-14)
    assert values["d_SLC"] == pytest.approx(0.6 * cap.d0_star, rel=1e-14)


def test_failing_tie_caps_d_slv() -> None:
    # §C8.7.1.2.1: d_SLV is also limited by a connection failing with a capacity drop > 50 %.
    # Here the tie carries about 3/4 of the restoring moment when it breaks at u = 5 cm.
    k = 20 * BLOCK.mass * G / (4 * BLOCK.R)
    tie = Restrainer("tie", k, k, 2 * BLOCK.R, 0.15, 2 * BLOCK.R, 0.15, fails_at=0.05)
    cap = capacity(
        Mechanism(BlockSide(Block(**{**BLOCK.__dict__, "restrainers": (tie,)}), 1)), FC=1.0
    )
    d_slv, d_slc, note = limit_displacements(cap, None)
    assert d_slv is not None and d_slc is not None and cap.d0_star is not None
    assert d_slv < 0.4 * cap.d0_star and "tie" in note
    ((name, theta_f, drop),) = failure_rotations(cap.mech)
    assert drop > 0.5 and d_slv == pytest.approx(cap.d_star_at(theta_f), rel=1e-12)
    assert d_slc == pytest.approx(0.6 * cap.d0_star)
