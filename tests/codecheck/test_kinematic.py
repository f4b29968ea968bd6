"""The kinematic analysis of the mechanism (rockcli.codecheck.kinematic, position, rules2009).

Sources: spec/ntc.md "Test vectors" (the altar, the amplification function), the closed forms
of a rigid block (α0 = tan α, α(θ) = tan(α − θ), d0 = b), the paper §4.4 (a restrainer
leaves α0 unchanged), spec/README.md (a0*·e*·FC = g tan α = the engine's uplift threshold).
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from rockcli.codecheck.kinematic import (
    Mechanism,
    alpha0,
    capacity,
    control_displacement,
    e_star,
    load_multiplier,
)
from rockcli.codecheck.position import building_period, gamma, height_amplification, psi
from rockcli.codecheck.rules2009 import quantities
from rockcli.mechanics import Block, Load, Restrainer
from rockcli.mechanisms.block import BlockSide

G = 9.81
ALTAR = Block(R=1.499, alpha=0.163, mass=1000.0, g=G)


def top_spring(block: Block, k: float, fails_at: float = math.inf) -> Restrainer:
    return Restrainer("top", k, k, 2 * block.R, block.alpha, 2 * block.R, block.alpha, fails_at)


def test_altar_vectors_2009_fc_105() -> None:
    # spec/ntc.md, test vectors (computed from the formulas, printed to 5 significant digits:
    # tolerance half a unit of the last digit).
    cap = capacity(Mechanism(BlockSide(ALTAR, 1)), FC=1.05)
    q = quantities(cap, None)
    assert cap.a0_star == pytest.approx(1.5365, abs=5e-5)
    assert cap.d0_star == pytest.approx(0.24326, abs=5e-6)
    assert q["du_star"] == pytest.approx(0.09730, abs=5e-6)
    assert q["ds_star"] == pytest.approx(0.03892, abs=5e-6)
    assert q["as_star"] == pytest.approx(1.2907, abs=5e-5)
    assert q["Ts"] == pytest.approx(1.0911, abs=5e-5)  # the paper's Ts = 1.09 s (§3.2)


def test_altar_ts_with_fc_1() -> None:
    # spec/ntc.md: with FC = 1.00, Ts = 1.0648 s.
    q = quantities(capacity(Mechanism(BlockSide(ALTAR, 1)), FC=1.0), None)
    assert q["Ts"] == pytest.approx(1.0648, abs=5e-5)


def test_activation_equals_engine_uplift_threshold() -> None:
    # spec/README.md "Architecture": a0*·e*·FC = g·tan α = the rocking engine's uplift
    # acceleration (mechanics.Block.uplift_acceleration, in g) — the same function by design.
    for alpha in (0.05, 0.163, 0.25, 0.6):
        block = Block(R=2.0, alpha=alpha, mass=500.0, g=G)
        cap = capacity(Mechanism(BlockSide(block, 1)), FC=1.2)
        assert cap.a0_star * cap.e_star * cap.FC == pytest.approx(G * math.tan(alpha), rel=1e-14)
        assert cap.alpha0 == pytest.approx(block.uplift_acceleration, rel=1e-14)


def test_free_block_curve_is_tan_alpha_minus_theta() -> None:
    # Equilibrium of the rotated block alone: α(θ) = tan(α − θ) (spec/ntc.md).
    mech = Mechanism(BlockSide(ALTAR, 1))
    for theta in (0.0, 0.05, 0.1, 0.163):
        assert load_multiplier(mech, theta) == pytest.approx(math.tan(0.163 - theta), abs=1e-15)
    assert control_displacement(mech, 0.163) == pytest.approx(ALTAR.b, rel=1e-14)


def test_restrainer_raises_the_curve_not_alpha0() -> None:
    # Paper §4.4: "for all K values the acceleration that triggers motion a0* does not change,
    # as the spring at u = 0 is inactive"; the curve rises with K (Fig. 18).
    block = Block(R=3.0, alpha=0.05, mass=18e3 * 6 * 6 * 0.05 * 3 / G, g=G)
    free = capacity(Mechanism(BlockSide(block, 1)), FC=1.0)
    tied = capacity(
        Mechanism(
            BlockSide(Block(**{**block.__dict__, "restrainers": (top_spring(block, 1e3),)}), 1)
        ),
        FC=1.0,
    )
    assert tied.a0_star == free.a0_star
    assert tied.d0_star is not None and free.d0_star is not None
    assert tied.d0_star > free.d0_star
    assert not tied.linear and free.linear
    d = 0.5 * free.d0_star
    assert tied.a_star(d) > free.a_star(d)


def test_stiff_restrainer_gives_positive_stiffness() -> None:
    # Paper Eq. 18: the slope at θ = 0 turns positive when 4KR/(mg) > 1/cos α. The top spring's
    # arm 2R cos(α − θ) shrinks with θ, so at twice that stiffness α(θ) still comes back to 0
    # (here near θ = 1.13 rad); at fifty times it stays positive up to θ = π/2: no d0*.
    block = Block(R=3.0, alpha=0.05, mass=1e4, g=G)
    k_limit = block.mass * G / (4 * block.R * math.cos(block.alpha))
    twice = Block(**{**block.__dict__, "restrainers": (top_spring(block, 2 * k_limit),)})
    stiff = Block(**{**block.__dict__, "restrainers": (top_spring(block, 50 * k_limit),)})
    far = capacity(Mechanism(BlockSide(twice, 1)), FC=1.0).d0_star
    assert far is not None and far > 10 * block.b
    assert capacity(Mechanism(BlockSide(stiff, 1)), FC=1.0).d0_star is None


def test_failing_restrainer_is_left_out_of_d0() -> None:
    # spec/ntc.md: d0* on the curve of the actions sure to last (a restrainer that can fail is
    # left out): the same d0* as the free block.
    block = Block(R=3.0, alpha=0.05, mass=1e4, g=G)
    k = 2.0 * block.mass * G / (4 * block.R * math.cos(block.alpha))
    weak = Block(**{**block.__dict__, "restrainers": (top_spring(block, k, fails_at=0.01),)})
    assert capacity(Mechanism(BlockSide(weak, 1)), FC=1.0).d0_star == pytest.approx(
        capacity(Mechanism(BlockSide(block, 1)), FC=1.0).d0_star, rel=1e-12
    )


def test_distributed_mass_changes_a0_and_d0_not_ts() -> None:
    # spec/ntc.md: spread over the height e* = 0.75 for a rectangle; a0* and d0* change, Ts
    # does not.
    lumped = capacity(Mechanism(BlockSide(ALTAR, 1)), FC=1.05)
    spread = capacity(Mechanism(BlockSide(ALTAR, 1), distributed=True), FC=1.05)
    assert spread.e_star == pytest.approx(0.75, rel=1e-14)
    assert spread.a0_star == pytest.approx(lumped.a0_star / 0.75, rel=1e-14)
    assert spread.d0_star == pytest.approx(lumped.d0_star * 4 / 3, rel=1e-12)
    assert quantities(spread, None)["Ts"] == pytest.approx(
        quantities(lumped, None)["Ts"], rel=1e-12
    )


def test_roof_load_at_the_top() -> None:
    # Virtual work (Circ. 617/2009 §C8A.4.1): α0 = Σ P x / Σ P z. A roof weight P at the top of
    # the mid-plane (x = b, z = 2h): α0 = (W + P) b / (W h + 2 P h); e* = (W h + 2 P h)² /
    # ((W h² + 4 P h²)(W + P)) with M* = (Σ P δx)²/(g Σ P δx²).
    W = ALTAR.weight
    P = 0.5 * W
    b, h = ALTAR.b, ALTAR.h
    roof = Load("roof", P, b, b, 2 * h)
    mech = Mechanism(BlockSide(replace(ALTAR, loads=(roof,)), 1))
    assert alpha0(mech) == pytest.approx((W + P) * b / (W * h + 2 * P * h), rel=1e-14)
    expected_e = (W * h + 2 * P * h) ** 2 / ((W * h**2 + 4 * P * h**2) * (W + P))
    assert e_star(mech) == pytest.approx(expected_e, rel=1e-14)


def test_pushing_load_only_in_the_denominator() -> None:
    # Circ. 7/2019 §C8.7.1.1: a weight that does not bear on the block adds to the
    # denominator of α0 only.
    W, b, h = ALTAR.weight, ALTAR.b, ALTAR.h
    Q = 0.3 * W
    floor = Load("floor", Q, b, b, 2 * h, bears=False)
    mech = Mechanism(BlockSide(replace(ALTAR, loads=(floor,)), 1))
    assert alpha0(mech) == pytest.approx(W * b / (W * h + Q * 2 * h), rel=1e-14)


@pytest.mark.parametrize(("r", "value"), [(0.5, 0.4903), (1.0, 7.0711), (2.0, 3.9223)])
def test_height_amplification_vectors(r: float, value: float) -> None:
    # spec/ntc.md, test vectors (4 decimals printed).
    assert height_amplification(r * 1.3, 1.3) == pytest.approx(value, abs=5e-5)


def test_position_defaults() -> None:
    # Circ. 617/2009 §C8A.4.2.2: ψ = Z/H, γ = 3N/(2N+1); NTC §7.3.3.2: T1 = 0.05·H^0.75.
    assert psi(3.0, 12.0) == 0.25
    assert gamma(3) == pytest.approx(9 / 7)
    assert building_period(16.0) == pytest.approx(0.05 * 8.0)


def test_positive_stiffness_needs_a_limit_2009() -> None:
    # spec/ntc.md: with a positive global stiffness there is no d0*; the ultimate displacement
    # comes from a restrainer failure or a user limit, else the non-linear check is not
    # evaluated (reported, never a silently wrong number).
    block = Block(R=3.0, alpha=0.05, mass=1e4, g=G)
    k = 50 * block.mass * G / (4 * block.R * math.cos(block.alpha))
    stiff = Block(**{**block.__dict__, "restrainers": (top_spring(block, k),)})
    cap = capacity(Mechanism(BlockSide(stiff, 1)), FC=1.0)
    assert quantities(cap, None)["du_star"] is None
    assert quantities(cap, 0.05)["du_star"] == 0.05
    both = Block(
        **{**stiff.__dict__, "restrainers": (top_spring(block, k), top_spring(block, k, 0.02))}
    )
    cap2 = capacity(Mechanism(BlockSide(both, 1)), FC=1.0)
    theta_f = 0.02 / (
        2 * block.R * math.cos(block.alpha)
    )  # u = 2R[sin α − sin(α − θ)] ≈ 2R cos α θ
    assert quantities(cap2, None)["du_star"] == pytest.approx(cap2.d_star_at(theta_f), rel=1e-3)


def test_the_activation_terms_sum_to_alpha0_and_the_tied_block_closed_form() -> None:
    # Circolare 617/2009 §C8A.4.1 (Circolare 7/2019 §C8.7.1.2): a lone block held by a tie-rod
    # taken as its force T at height h_T has α0 = (W b + T h_T)/(W h); the terms are the sums
    # α0 is made of, so they must give α0 itself (to rounding).
    import math

    from rockcli.codecheck.kinematic import Mechanism, activation_terms, alpha0
    from rockcli.mechanics import Block, Restrainer

    W_kg, T, h_T = 50_000.0, 80e3, 5.5  # kg, N, m
    R, a = 3.0, 0.12
    tie = Restrainer("tie", 2e7, 2e7, h_T / math.cos(0.05), 0.05, h_T / math.cos(0.05), 0.05,
                     code_action="force", code_force=T)  # fmt: skip
    block = Block(R=R, alpha=a, mass=W_kg, e=0.9, restrainers=(tie,))
    mech = Mechanism(BlockSide(block, 1), distributed=False)
    terms = activation_terms(mech)
    W = W_kg * block.g
    b, h = R * math.sin(a), R * math.cos(a)
    assert terms["stabilising"] == pytest.approx(W * b, rel=1e-12)
    assert terms["restrainers"] == pytest.approx(T * h_T, rel=1e-12)
    assert terms["overturning"] == pytest.approx(W * h, rel=1e-12)
    assert terms["thrusts"] == 0.0
    assert terms["alpha0"] == pytest.approx((W * b + T * h_T) / (W * h), rel=1e-12)
    assert terms["alpha0"] == pytest.approx(alpha0(mech), rel=1e-12)
