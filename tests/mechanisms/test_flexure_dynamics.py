"""The two-block vertical flexure rocks (issue 22): its chain's equation of motion, tabulated.

Checked against closed forms worked by hand for a wall of height h = 4 m and thickness
t = 0.25 m with the hinge at mid-height and no overburden (x inward from the pivot, z up; the
lower block about the outer base edge, the upper one hanging from the hinge (t, h/2) on the
inner face, its top (0, h) held horizontally):

- at rest the velocities per unit rate are, for the lower block's centroid (t/2, h/4),
  (−h/4, t/2) with φ′ = 1; the hinge's (−h/2, t); the top's X′ = 0 gives the upper block
  φ′ = −1 and its centroid (t/2, 3h/4) the velocity (−h/4, 3t/2). So, with m the wall's mass
  and I_G = (m/2)·(h²/4 + t²)/12 each block's own inertia:
  M(0) = (m/2)·[(h/4)² + (t/2)²] + (m/2)·[(h/4)² + (3t/2)²] + 2·I_G;
  V′(0) = W·t (W/2·t/2 + W/2·3t/2), g·Γ(0) = W·h/4 (Doherty et al. 2002: α0 = 4t/h);
- to second order the upper block turns by −θ (the top's constraint t cos θ − (h/2) sin θ −
  t cos φ − (h/2) sin φ = 0 gives φ = −θ + O(θ³)), so the centroids rise as
  (t/2) sin θ + (h/4) cos θ and (3t/2) sin θ + (3h/4) cos θ: V″(0) = −W·h/2. The linearised
  motion from rest at θ0 with no ground motion, M(0)·θ̈ = −V′(0) − V″(0)·θ, reaches θ = 0 at
  cosh(λ·t*) = c/(c − θ0) with λ² = −V″(0)/M(0) and c = −V′(0)/V″(0) = 2t/h;
- the impact ratio by projection on the post-impact mode (rockcli.mechanisms.motion
  .impact_ratio), with the mirror-image velocities about the inner edge, is
  Σ[m_x X′X′′ − m_z Z′Z′′ + I_G φ′φ′′]/Σ[m_x X′′² + m_z Z′′² + I_G φ′′²] = 121/136 for this wall
  (per m/2: numerator 1 − 1/64 + 1 − 9/64 + 2·(4.0625/12), denominator 1 + 1/64 + 1 + 9/64 +
  2·(4.0625/12)).
"""

from __future__ import annotations

import math
import random
from pathlib import Path

import numpy as np
import pytest

from rockcli.analyses.rocked import mechanism_block, named_spec
from rockcli.codecheck.kinematic import Mechanism, alpha0
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import chain_terms, impact_restitution, uplift_accelerations
from rockcli.mechanisms import motion
from rockcli.mechanisms.catalogue import build
from rockcli.mechanisms.flexure import flexure_block
from rockcli.mechanisms.table import tabulate, terms
from rockcli.model.derive import derive_block
from rockcli.model.derive_wall import to_wall
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
FLEXURE = ROOT / "examples" / "validation" / "models" / "mech-flexure.toml"
FACADE = ROOT / "examples" / "two-storey-facade.toml"
MID = "vertical flexure at mid-height"
H, T, G = 4.0, 0.25, 9.81
MASS = 18e3 * H * T * 1.0 / G  # 18 kN/m³, 1 m wide [kg]


def model_with(tmp_path: Path, extra: str = "") -> Path:
    """The casebook's flexure wall with extra TOML appended."""
    path = tmp_path / "wall.toml"
    path.write_text(FLEXURE.read_text() + "\n" + extra)
    return path


def flexure(path: Path, name: str = MID):
    model = load_model(str(path))
    wall = to_wall(model)
    return model, wall, named_spec(wall, name)


def mid_height_mass() -> float:
    """M(0) of the hand derivation (module docstring) [kg·m²]."""
    half = MASS / 2
    i_g = half * (H * H / 4 + T * T) / 12
    return half * ((H / 4) ** 2 + (T / 2) ** 2) + half * ((H / 4) ** 2 + (1.5 * T) ** 2) + 2 * i_g


def test_the_terms_at_rest_are_the_hand_derivations() -> None:
    _, wall, spec = flexure(FLEXURE)
    side = build(wall, spec, 1)
    g, h, t, m, _ = terms(side, 0.0)
    w = MASS * G
    # The 1e-6 kN top load bears and rises 1.5t per unit rotation at its point (t/2, h):
    # 1e-3 N × 0.375 m = 8.3e-8 of W·t.
    assert g == pytest.approx(w * T, rel=1e-7)
    assert h == pytest.approx(w * H / 4, rel=1e-12)
    assert t == 0.0
    # The top load's mass 1e-4 kg moves vertically at 0.375 m/rad: 1.4e-5 kg·m² of 2599.
    assert m == pytest.approx(mid_height_mass(), rel=1e-8)


def test_the_table_interpolates_the_configuration_function() -> None:
    # Cubic Hermite on NODES nodes: error h⁴·|f⁗|/384 with h ≈ 6e-4 rad; G, H, T, M measured
    # to about 1e-11 of their size, M′ (itself a central difference, its slope another: the
    # table's CURVATURE_STEP) to 1e-7 of M per radian near the table's end; at a node the
    # stored values themselves.
    _, wall, spec = flexure(FACADE, "vertical flexure, storey 2")
    from rockcli.model.catalogue import resolved

    spec, _ = resolved(wall, spec, (1, -1))
    plus, minus = build(wall, spec, 1), build(wall, spec, -1)
    chain = tabulate(plus, minus)
    rng = random.Random(22)
    for s, side in ((1, plus), (-1, minus)):
        assert chain_terms(chain.table, s, 0.0) == terms(side, 0.0)
        for _ in range(40):
            a = rng.uniform(0.0, 0.95 * chain.end)
            got, want = chain_terms(chain.table, s, a), terms(side, a)
            scale = (abs(want[0]) + abs(want[1]), abs(want[1]), abs(want[1]), want[3])
            for x, y, sc in zip(got[:4], want[:4], scale, strict=True):
                assert abs(x - y) <= 1e-10 * sc, (s, a)
            m_slope = (motion.generalised_mass(side, a + 1e-6)
                       - motion.generalised_mass(side, a - 1e-6)) / 2e-6  # fmt: skip
            assert abs(got[4] - m_slope) <= 2e-7 * want[3], (s, a)


def test_the_uplift_of_each_side_is_the_codes_alpha0_bit_for_bit() -> None:
    model = load_model(str(FACADE))
    wall = to_wall(model)
    from rockcli.model.catalogue import resolved

    for name in ("vertical flexure, storey 1", "vertical flexure, storey 2"):
        spec, _ = resolved(wall, named_spec(wall, name), (1, -1))
        block = mechanism_block(model, wall, spec)
        code = tuple(alpha0(Mechanism(build(wall, spec, s))) for s in (1, -1))
        assert uplift_accelerations(block) == code


def flexure_of(model, wall, spec):
    """The flexure as the engine rocks it, from its placement about each pivot (its storey's
    height: where the floor holds its top)."""
    top = wall.storeys[spec.storey - 1].height
    return flexure_block(build(wall, spec, 1), build(wall, spec, -1), top, derive_block(model))


def test_the_impact_ratio_is_the_hand_projection() -> None:
    model, wall, spec = flexure(FLEXURE)
    block = flexure_of(model, wall, spec)
    # 121/136 by hand; the negligible top load (5.6e-8 of the wall's weight, bearing) moves
    # it by 1.2e-8.
    for s in (1, -1):
        assert impact_restitution(block, s) == pytest.approx(121 / 136, rel=1e-7)


def test_each_sides_impact_ratio_on_an_asymmetric_chain() -> None:
    # The façade's storey 1 (loads off the mid-plane, hinges set back by f_m): the two sides
    # differ. An impact ending a phase on side s projects on side −s's mode, whose M(0) is
    # the denominator; the kinetic energy kept, e²·M(0)_−s / M(0)_s, is at most 1
    # (Cauchy–Schwarz); and the chain keeps each side's ratio in its own place.
    model = load_model(str(FACADE))
    wall = to_wall(model)
    from rockcli.model.catalogue import resolved

    spec, _ = resolved(wall, named_spec(wall, "vertical flexure, storey 1"), (1, -1))
    plus, minus = build(wall, spec, 1), build(wall, spec, -1)
    chain = tabulate(plus, minus)
    e_pos, e_neg = motion.impact_ratio(plus, minus), motion.impact_ratio(minus, plus)
    assert e_pos != e_neg
    assert chain.restitution == (e_pos, e_neg)
    m_pos, m_neg = motion.generalised_mass(plus, 0.0), motion.generalised_mass(minus, 0.0)
    assert chain.inertia == (m_pos, m_neg) and m_pos != m_neg
    assert 0.0 < e_pos**2 * m_neg / m_pos <= 1.0 and 0.0 < e_neg**2 * m_pos / m_neg <= 1.0


def test_a_member_on_the_lower_block_acts_in_both_engines(tmp_path: Path) -> None:
    # A pretensioned tie at 1.5 m, below the mid-height hinge, turns with the lower block:
    # a polar spring about each pivot, exact. The fast engine (table) and the reference
    # (configuration function) agree on the peak (1e-6) and the member's force.
    tie = ('[[restrainers]]\nname = "low tie"\nkind = "tie-rod"\ngrade = "S275"\n'
           'diameter = 0.012\nlength = 4.0\nheight = 1.5\nfrom_pivot = 0.125\n'
           'pretension = 2000.0\n')  # fmt: skip
    model, wall, spec = flexure(model_with(tmp_path, tie))
    block = mechanism_block(model, wall, spec)
    assert [r.name for r in block.restrainers] == ["low tie"]
    time = np.arange(0.0, 3.0, 0.005)
    accel = 0.6 * np.sin(2 * np.pi * time / 0.5) * (time < 1.0)
    fast = simulate(block, time, accel, 0.005)
    ref = simulate(block, time, accel, 0.005, engine=Engine.REFERENCE)
    assert fast.impacts == ref.impacts and fast.impacts >= 1
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
    f_fast, f_ref = fast.restrainers[0].max_force, ref.restrainers[0].max_force
    assert f_fast > 2.0e3 and f_fast == pytest.approx(f_ref, rel=1e-6)


def test_the_projection_of_one_rectangle_is_housners() -> None:
    # A one-storey wall overturning: one rigid rectangle; the projection reduces to the angular
    # momentum about the new pivot, 1 − 1.5 sin²α (Housner 1963).
    model = load_model(str(FLEXURE))
    wall = to_wall(model)
    from rockcli.mechanisms.catalogue import overturning

    plus, minus = overturning(wall, 0.0, 1, "o"), overturning(wall, 0.0, -1, "o")
    alpha = math.atan(T / H)
    ratio = motion.impact_ratio(plus, minus)
    assert ratio == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2, rel=1e-8)


def energy(block, side_plus, side_minus, theta: float, omega: float) -> float:
    """½·M(θ)·θ̇² + V(θ) from the configuration function (rockcli.mechanisms.motion)."""
    side = side_plus if theta >= 0 else side_minus
    a = abs(theta)
    return 0.5 * motion.generalised_mass(side, a) * omega**2 + motion.potential(side, a)


def test_free_rocking_with_e_1_conserves_the_lagrangians_energy(tmp_path: Path) -> None:
    path = model_with(tmp_path, "[restitution]\ne = 1.0\n")
    model, wall, spec = flexure(path)
    block = mechanism_block(model, wall, spec)
    assert block.e == 1.0 and block.restitution(-1) == 1.0
    plus, minus = build(wall, spec, 1), build(wall, spec, -1)
    theta0 = 0.6 * block.alpha
    time = np.arange(0.0, 6.0 + 1e-9, 0.01)
    settings = SolverSettings(rtol=1e-11, atol=1e-12, tail=0.0)
    run = simulate(block, time, np.zeros_like(time), 0.01, settings=settings, history=True,
                   theta0=theta0)  # fmt: skip
    assert run.impacts >= 6  # several impacts, both sides
    hist = run.history
    assert hist is not None
    e0 = energy(block, plus, minus, theta0, 0.0)
    worst = max(
        abs(energy(block, plus, minus, th, om) - e0)
        for th, om in zip(hist.theta, hist.omega, strict=True)
        if np.isfinite(th)
    )
    assert worst <= 1e-8 * e0


@pytest.mark.parametrize("share", [1e-3, 1e-4])
def test_the_linearised_motion_about_rest(share: float) -> None:
    # From rest at θ0 = share·c with no ground motion, the first impact comes at t* of the
    # linearised equation (module docstring); the error is of the order of θ0/c itself.
    model, wall, spec = flexure(FLEXURE)
    block = flexure_of(model, wall, spec)
    m0 = mid_height_mass()
    lam = math.sqrt(MASS * G * H / 2 / m0)
    # M(0) = m·h²/12 + (4/3)·m·t²: the slender idealisation with horizontal inertia only (the
    # rigid two-block wall of Doherty et al. 2002), m·h²/12, gives λ² = 6g/h; the thickness's
    # share (the blocks' vertical motion and rotary inertia) divides it by 1 + 16 t²/h².
    assert m0 == pytest.approx(MASS * H * H / 12 + 4 / 3 * MASS * T * T, rel=1e-12)
    assert lam**2 == pytest.approx(6 * G / H / (1 + 16 * (T / H) ** 2), rel=1e-12)
    c = 2 * T / H
    theta0 = share * c
    t_star = math.acosh(c / (c - theta0)) / lam
    time = np.array([0.0, 1.0])
    settings = SolverSettings(rtol=1e-12, atol=1e-14, max_events=1, tail=0.0)
    run = simulate(block, time, np.zeros(2), 1.0, settings=settings, theta0=theta0)
    assert run.impacts == 1
    assert run.t_end == pytest.approx(t_star, rel=3 * share)


def test_the_fast_engine_agrees_with_the_reference_on_the_chain() -> None:
    # The reference integrates the configuration function itself (DOP853, 1e-10), the fast
    # engine the table (DP5(4), 1e-8): the peak to 1e-6 measures both the table and the steps.
    model = load_model(str(FACADE))
    wall = to_wall(model)
    block = mechanism_block(model, wall, named_spec(wall, "vertical flexure, storey 2"))
    time = np.arange(0.0, 3.0, 0.005)
    accel = 1.2 * np.sin(2 * np.pi * time / 0.5) * (time < 1.0)
    fast = simulate(block, time, accel, 0.005)
    ref = simulate(block, time, accel, 0.005, engine=Engine.REFERENCE)
    assert fast.status == ref.status
    assert fast.impacts == ref.impacts and fast.impacts >= 2
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
    assert fast.t_uplift == ref.t_uplift
