"""Restrainers in the kinematic check: code_action "force" and "spring" (issue 9, items 3-4).

Sources: the virtual work of α0 with a tie-rod as an external force, Circolare 617/2009
§C8A.4.1 and Circolare 7/2019 §C8.7.1.2: α0 = (W b + T h_T)/(W h_G), with a load P at the top
bearing on the block α0 = (W b + P x_P + T h_T)/(W h_G + P h_P); equilibrium in the rotated
position (Circolare 617/2009 §C8A.4.2.3): a horizontal force F at the point (x, z) from the
pivot has the arm z cos θ + x sin θ = r cos(φ − θ). Tolerance 1e-12 relative: the code and the
closed form add the same few terms in a different order (a few ulps).
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.codecheck.kinematic import (
    Mechanism,
    alpha0,
    capacity,
    curve_points,
    failure_rotations,
    force_at,
    load_multiplier,
    loss_rotation,
)
from rockcli.codecheck.rules2009 import quantities
from rockcli.codecheck.rules2019 import SLV_SHARE, limit_displacements
from rockcli.mechanics import Block, Load, Restrainer, point_polar, spring_elongation
from rockcli.mechanisms.block import BlockSide
from rockcli.model.derive import to_block
from rockcli.model.schema import Model

G = 9.81
#: A façade 0.6 m thick, 8 m tall, 300 kN (b = 0.3 m, h_G = 4 m).
B, H, W = 0.3, 4.0, 300e3
R, ALPHA = math.hypot(B, H), math.atan2(B, H)
#: Closed forms: a few ulps apart (see the module docstring).
REL = 1e-12
#: The zero of the curve is bisected to π/2·2⁻⁶⁰ in θ; d0* then carries ~1e-15 relative.
BISECTION_REL = 1e-9


def block(*restrainers: Restrainer, loads: tuple[Load, ...] = ()) -> Block:
    return Block(R=R, alpha=ALPHA, mass=W / G, g=G, restrainers=restrainers, loads=loads)


def tie(
    x: float,
    z: float,
    force: float,
    k: float = 2.2e7,
    fails_at: float = math.inf,
    action: str = "force",
    **extra: float,
) -> Restrainer:
    """A tie-rod at (x, z) from pivot O with strength = code force = ``force`` [N]."""
    r, phi = point_polar(x, z)
    return Restrainer(
        "tie",
        k,
        k,
        r,
        phi,
        r,
        phi,
        fails_at,
        strength=force,
        code_action=action,
        code_force=force if action == "force" else 0.0,
        **extra,
    )


@pytest.mark.parametrize("h_t", [2.0, 6.0, 8.0])
@pytest.mark.parametrize("force", [10e3, 82.28e3])
def test_alpha0_with_a_tie_force(h_t: float, force: float) -> None:
    # Circolare 617/2009 §C8A.4.1: α0 = (W b + T h_T)/(W h_G), the tie at the inner face x = 0.
    mech = Mechanism(BlockSide(block(tie(0.0, h_t, force)), 1))
    assert alpha0(mech) == pytest.approx((W * B + force * h_t) / (W * H), rel=REL)


def test_alpha0_with_a_tie_force_and_a_roof_load() -> None:
    # Circolare 7/2019 §C8.7.1.2: a load P_i at the top bearing on the block (x_P, h_P):
    # α0 = (W b + P x_P + T h_T)/(W h_G + P h_P).
    P, x_p, h_p, T, h_t = 50e3, 0.45, 2 * H, 82.28e3, 7.5
    roof = Load("roof", P, x_p, 2 * B - x_p, h_p)
    mech = Mechanism(BlockSide(block(tie(0.1, h_t, T), loads=(roof,)), 1))
    expected = (W * B + P * x_p + T * h_t) / (W * H + P * h_p)
    assert alpha0(mech) == pytest.approx(expected, rel=REL)


def test_force_is_constant_on_the_whole_curve() -> None:
    # The force keeps its size; its arm is the point's height in the rotated position
    # z cos θ + x sin θ; gravity W R sin(α − θ), the earthquake W R cos(α − θ).
    x, z, T = 0.2, 7.0, 60e3
    mech = Mechanism(BlockSide(block(tie(x, z, T)), 1))
    for theta in (0.0, 0.01, 0.05, 0.2, 0.5):
        arm = z * math.cos(theta) + x * math.sin(theta)
        expected = (W * R * math.sin(ALPHA - theta) + T * arm) / (W * R * math.cos(ALPHA - theta))
        assert load_multiplier(mech, theta) == pytest.approx(expected, rel=REL)


def test_force_at_the_inner_face_zero_of_the_curve() -> None:
    # A tie at x = 0 that is never lost: W R sin(α − θ) + T z cos θ = 0 gives
    # tan θ0 = (W b + T z)/(W h) = α0; d0* is the centroid's displacement there (e* = 1).
    T, z = 40e3, 8.0
    cap = capacity(Mechanism(BlockSide(block(tie(0.0, z, T)), 1)), FC=1.0)
    theta0 = math.atan((W * B + T * z) / (W * H))
    d0 = R * (math.sin(ALPHA) - math.sin(ALPHA - theta0))
    assert cap.d0_star == pytest.approx(d0, rel=BISECTION_REL)
    assert not cap.linear  # the curve with the force, not the straight line


def test_force_is_lost_at_rupture() -> None:
    # The member is lost when its elongation reaches fails_at (mechanics.spring_failure_rotation):
    # the curve has the force just before, gravity alone just after.
    u_f, T, z = 0.02, 50e3, 8.0
    mech = Mechanism(BlockSide(block(tie(0.0, z, T, fails_at=u_f)), 1))
    theta_f = loss_rotation(mech.restrainers[0], 1)
    assert spring_elongation(z, 0.0, theta_f) == pytest.approx(u_f, rel=REL)
    below, above = theta_f * (1 - 1e-6), theta_f * (1 + 1e-6)
    assert load_multiplier(mech, below) > math.tan(ALPHA - below)
    assert load_multiplier(mech, above) == pytest.approx(math.tan(ALPHA - above), rel=REL)
    [(name, theta, drop)] = failure_rotations(mech)
    assert (name, theta) == ("tie", theta_f)
    # drop = T z cos θ_f / (α_before · W R cos(α − θ_f)).
    before = load_multiplier(mech, theta_f, intact=True)
    lost = T * z * math.cos(theta_f) / (W * R * math.cos(ALPHA - theta_f))
    assert drop == pytest.approx(lost / before, rel=REL)


def test_du_star_2009_from_the_rupture_of_a_force() -> None:
    # Circolare 617/2009 §C8A.4.2.3 as the code applies it (rules2009.du_star): with positive
    # stiffness (a stiff spring that is never lost) du* is the first restrainer's loss.
    stiff = Restrainer("stiff", 1e9, 1e9, 2 * R, ALPHA, 2 * R, ALPHA)
    mech = Mechanism(BlockSide(block(stiff, tie(0.0, 8.0, 50e3, fails_at=0.01)), 1))
    cap = capacity(mech, FC=1.0)
    assert cap.d0_star is None
    theta_f = loss_rotation(mech.restrainers[1], 1)
    assert quantities(cap, None)["du_star"] == pytest.approx(cap.d_star_at(theta_f), rel=REL)


def test_d_slv_2019_capped_by_the_loss_of_a_force() -> None:
    # Circolare 7/2019 §C8.7.1.2.1 (rules2019.limit_displacements): a loss that removes more
    # than half the capacity caps d_SLV at its d*. A tie of 3 W b/h_T triples α0; lost early.
    T, z = 3 * W * B / 8.0, 8.0
    mech = Mechanism(BlockSide(block(tie(0.0, z, T, fails_at=0.001)), 1))
    cap = capacity(mech, FC=1.0)
    [(_, theta_f, drop)] = failure_rotations(mech)
    assert drop > 0.5
    d_slv, _, note = limit_displacements(cap, None)
    assert cap.d0_star is not None and cap.d_star_at(theta_f) < SLV_SHARE * cap.d0_star
    assert d_slv == pytest.approx(cap.d_star_at(theta_f), rel=REL)
    assert "tie" in note


def test_force_only_on_the_side_it_works() -> None:
    # A tie-rod acting on θ > 0 only (K = 0 on the other side) gives no force towards θ < 0.
    r, phi = point_polar(0.0, 8.0)
    one = Restrainer("tie", 2.2e7, 0.0, r, phi, r, phi, strength=5e4, code_action="force",
                     code_force=5e4)  # fmt: skip
    assert force_at(one, 1, 0.0) == 5e4
    assert force_at(one, -1, 0.0) == 0.0
    assert alpha0(Mechanism(BlockSide(block(one), -1))) == pytest.approx(B / H, rel=REL)


def test_spring_without_pretension_leaves_alpha0() -> None:
    # Paper §4.4 / Circolare: a spring without initial force does no work at θ = 0.
    mech = Mechanism(BlockSide(block(tie(0.0, 8.0, 5e4, action="spring")), 1))
    assert alpha0(mech) == pytest.approx(B / H, rel=REL)


def test_pretension_raises_alpha0() -> None:
    # A spring pretensioned to P0 at (r, φ) does the work P0 r cos φ at θ = 0:
    # α0 = tan α + P0 r cos φ / (W h_G).
    P0, x, z = 20e3, 0.3, 7.0
    sp = tie(x, z, 8e4, action="spring", pretension=P0)
    assert alpha0(Mechanism(BlockSide(block(sp), 1))) == pytest.approx(
        B / H + P0 * z / (W * H), rel=REL
    )


def test_spring_is_capped_at_its_strength() -> None:
    # min(strength, yield force of the side): K u grows past it, the force does not.
    k, z, S, Y = 2.2e7, 8.0, 8.0e4, 9.0e4
    sp = tie(0.0, z, S, k=k, action="spring", yield_pos=Y, yield_neg=Y)
    mech = Mechanism(BlockSide(block(sp), 1))
    theta_cap = math.asin(S / (k * z))  # K z sin θ = S: u = z sin θ at x = 0
    small = theta_cap / 2
    assert force_at(sp, 1, small) == pytest.approx(k * z * math.sin(small), rel=REL)
    for theta in (theta_cap * 1.01, 0.1, 0.5):
        assert force_at(sp, 1, theta) == S
        expected = (W * R * math.sin(ALPHA - theta) + S * z * math.cos(theta)) / (
            W * R * math.cos(ALPHA - theta)
        )
        assert load_multiplier(mech, theta) == pytest.approx(expected, rel=REL)


def test_spring_cap_is_the_yield_force_when_lower() -> None:
    # An elastic-plastic spring yields at Y below the member's strength: the cap is Y.
    sp = tie(0.0, 8.0, 8.0e4, action="spring", yield_pos=5.0e4, yield_neg=5.0e4)
    assert force_at(sp, 1, 0.3) == 5.0e4


def test_spring_lost_when_its_force_reaches_the_anchor() -> None:
    # An elastic spring whose anchor gives way at 60 kN is lost when P0 + K u = 60 kN:
    # u = (60 kN − P0)/K; with yield below the anchor it yields first and is never lost.
    k, z, P0 = 1e7, 8.0, 1e4
    sp = tie(0.0, z, 6e4, k=k, action="spring", pretension=P0, rupture_force=6e4)
    theta_r = loss_rotation(sp, 1)
    assert spring_elongation(z, 0.0, theta_r) == pytest.approx((6e4 - P0) / k, rel=REL)
    yields = tie(0.0, z, 4e4, k=k, action="spring", rupture_force=6e4, yield_pos=4e4, yield_neg=4e4)
    assert loss_rotation(yields, 1) == math.inf


def test_curve_rows_never_exceed_gravity_plus_strengths() -> None:
    # On every row of the capacity curve α(θ) ≤ [G(θ) + Σ strength·arm]/H(θ): no member gives
    # more than its strength. Springs stiff enough to reach their cap early.
    members = (
        tie(0.0, 8.0, 82.28e3),
        tie(0.2, 6.0, 40e3, k=1e9, action="spring", yield_pos=6e4, yield_neg=6e4),
    )
    mech = Mechanism(BlockSide(block(*members), 1))
    for row in curve_points(capacity(mech, FC=1.0), n=41):
        theta = row["theta"]
        bound = W * R * math.sin(ALPHA - theta) + sum(
            sp.strength * sp.r_pos * math.cos(sp.phi_pos - theta) for sp in members
        )
        assert row["alpha"] * W * R * math.cos(ALPHA - theta) <= bound + REL * W * R


@settings(max_examples=40, deadline=None)
@given(
    diameter=st.floats(0.008, 0.04),
    height=st.floats(1.0, 8.0),
    from_pivot=st.floats(0.0, 0.6),
    action=st.sampled_from(["force", "spring"]),
    pretension=st.just(0.0) | st.floats(1.0, 5e3),  # 0, or at least 1 N (model.bounds)
)
def test_model_tie_rod_never_gives_more_than_its_strength(
    diameter: float, height: float, from_pivot: float, action: str, pretension: float
) -> None:
    # A tie-rod of S275 from the model (its strength N_t,Rd, NTC 2018 §4.2.4.1.2, derived by
    # model.derive): on the whole capacity curve its force is at most its strength and α(θ)
    # at most what gravity plus that strength give.
    model = Model.model_validate(
        {
            "name": "wall",
            "kind": "facade",
            "geometry": {"thickness": 2 * B, "height": 2 * H},
            "mass": {"weight": W / 1e3},
            "restrainers": [
                {
                    "kind": "tie-rod",
                    "grade": "S275",
                    "diameter": diameter,
                    "length": 3.0,
                    "height": height,
                    "from_pivot": from_pivot,
                    "pretension": pretension,
                    "code_action": action,
                }
            ],
        }
    )
    blk = to_block(model)
    [sp] = blk.restrainers
    assert math.isfinite(sp.strength)
    mech = Mechanism(BlockSide(blk, 1))
    for row in curve_points(capacity(mech, FC=1.0), n=21):
        theta = row["theta"]
        assert force_at(sp, 1, theta) <= sp.strength
        bound = blk.weight * R * math.sin(ALPHA - theta) + sp.strength * sp.r_pos * math.cos(
            sp.phi_pos - theta
        )
        # In moments, to a few ulps of W R (the curve ends where α = 0).
        overturning = blk.weight * R * math.cos(ALPHA - theta)
        assert row["alpha"] * overturning <= bound + REL * blk.weight * R
