"""Today's block is the catalogue's overturning of a one-storey wall without a gable.

The same wall seen two ways must give the same code check: the general chain
(rockcli.mechanisms.catalogue.overturning, a ChainSide) and the block's closed forms
(rockcli.mechanisms.block.BlockSide through Mechanism(BlockSide(..., 1))), with the same loads,
thrusts and restrainers (a restrainer's r, φ about the block's pivots from
rockcli.mechanics.point_polar of its point: (x, z) about O, (t − x, z) about O′; a load's
x_pos = x, x_neg = t − x). Block: R = √(b² + h²), α = atan2(b, h), mass = W/g.

Tolerance: the two compute the same sums with other roundings (X = x cos θ − z sin θ against
the chain's rotated offsets; R sin α against t/2): 1e-12 relative, and 1e-12 absolute for
quantities that pass through zero (α(θ) at d0*, elongations at rest).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pytest

from rockcli.codecheck.kinematic import (
    Mechanism,
    alpha0,
    capacity,
    e_star,
    failure_rotations,
    load_multiplier,
    participating_mass,
)
from rockcli.mechanics import Block, Load, Restrainer, Thrust, point_polar
from rockcli.mechanisms import catalogue
from rockcli.mechanisms.block import BlockSide
from rockcli.mechanisms.wall import Storey, Wall, WallLoad, WallRestrainer, WallThrust

G = 9.81
GAMMA = 18e3  # [N/m³]
WIDTH = 2.5  # [m]
HEIGHT, THICK = 3.2, 0.5
REL = 1e-12
THETAS = [k * 0.06 for k in range(21)]  # 0 to 1.2 rad


@dataclass(frozen=True)
class Point:
    """A restrainer's law and its point in the wall's frame."""

    name: str
    k: float
    x: float
    z: float
    fails_at: float = math.inf
    code_action: str = "spring"
    code_force: float = 0.0

    def member(self) -> Restrainer:
        """The Restrainer with its r, φ about O (x, z) and about O′ (t − x, z)."""
        r_pos, phi_pos = point_polar(self.x, self.z)
        r_neg, phi_neg = point_polar(THICK - self.x, self.z)
        return Restrainer(self.name, self.k, self.k, r_pos, phi_pos, r_neg, phi_neg,
                          fails_at=self.fails_at, code_action=self.code_action,
                          code_force=self.code_force)  # fmt: skip


LOADS = (
    WallLoad("floor", 35e3, 0.3, HEIGHT),
    WallLoad("beam", 6e3, 0.1, 2.5, moves=False),
    WallLoad("shelf", 4e3, 0.45, 1.8, bears=False),
)
THRUSTS = (WallThrust("roof", 3e3, 1, 0.2, 3.0), WallThrust("arch", 1.5e3, -1, 0.4, 2.2))
CASES = {
    "loads and thrusts": ((), LOADS, THRUSTS),
    "weak spring": ((Point("tie", 2e4, 0.25, 3.0),), LOADS, THRUSTS),
    "spring that fails": (
        (Point("tie", 4e5, 0.35, 2.9, fails_at=0.02), Point("anchor", 3e4, 0.1, 2.0)),
        LOADS,
        (),
    ),
    "tie force": ((Point("tie", 1e7, 0.25, 3.1, code_action="force", code_force=8e3),), (), ()),
    "stiff spring": ((Point("tie", 5e6, 0.25, 3.1),), (), ()),
}


def pair(case: str, s: int, distributed: bool = False) -> tuple[Mechanism, Mechanism]:
    """The chain and the block of a case, on side s."""
    points, loads, thrusts = CASES[case]
    members = [p.member() for p in points]
    held = tuple(WallRestrainer(m, p.x, p.z) for m, p in zip(members, points, strict=True))
    wall = Wall(storeys=(Storey(HEIGHT, THICK),), width=WIDTH, unit_weight=GAMMA, g=G,
                loads=loads, thrusts=thrusts, restrainers=held)  # fmt: skip
    chain = Mechanism(catalogue.overturning(wall, 0.0, s, "o"), distributed=distributed)
    b, h = THICK / 2, HEIGHT / 2
    block = Block(
        R=math.hypot(b, h),
        alpha=math.atan2(b, h),
        mass=GAMMA * THICK * HEIGHT * WIDTH / G,
        g=G,
        restrainers=tuple(members),
        loads=tuple(
            Load(ld.name, ld.weight, ld.x, THICK - ld.x, ld.z, ld.bears, ld.moves) for ld in loads
        ),  # fmt: skip
        thrusts=tuple(
            Thrust(th.name, th.force, th.direction, th.x, THICK - th.x, th.z) for th in thrusts
        ),  # fmt: skip
    )
    return chain, Mechanism(BlockSide(block, s), distributed=distributed)


PARAMS = [(case, s) for case in CASES for s in (1, -1)]


@pytest.mark.parametrize(("case", "s"), PARAMS)
def test_capacity_curve(case: str, s: int) -> None:
    chain, block = pair(case, s)
    assert alpha0(chain) == pytest.approx(alpha0(block), rel=REL)
    for theta in THETAS:
        for kw in ({}, {"sure_only": True}, {"intact": True}):
            assert load_multiplier(chain, theta, **kw) == pytest.approx(
                load_multiplier(block, theta, **kw), rel=REL, abs=REL
            )


@pytest.mark.parametrize(("case", "s"), PARAMS)
@pytest.mark.parametrize("distributed", (False, True))
def test_equivalent_oscillator(case: str, s: int, distributed: bool) -> None:
    # e* (1 lumped, 0.75 spread for the lone block), M*, d0* = capacity(...).d0_star and the
    # factor d*/d_k; d0* is None for both when the stiff spring keeps α > 0.
    chain, block = pair(case, s, distributed)
    assert e_star(chain) == pytest.approx(e_star(block), rel=REL)
    assert participating_mass(chain) == pytest.approx(participating_mass(block), rel=REL)
    c_chain, c_block = capacity(chain, 1.35), capacity(block, 1.35)
    assert c_chain.factor == pytest.approx(c_block.factor, rel=REL)
    assert c_chain.linear == c_block.linear
    if c_block.d0_star is None:
        assert c_chain.d0_star is None
    else:
        assert c_chain.d0_star == pytest.approx(c_block.d0_star, rel=REL)


@pytest.mark.parametrize("distributed", (False, True))
def test_lone_block_e_star(distributed: bool) -> None:
    # No loads: e* = 1 lumped, 3/4 spread over the height (spec/ntc.md; ∫z = W h,
    # ∫z² = W (2h)²/3 → (W h)²/(W·4h²/3)/W = 3/4).
    chain, block = pair("stiff spring", 1, distributed)
    expected = 0.75 if distributed else 1.0
    assert e_star(chain) == pytest.approx(expected, rel=REL)
    assert e_star(block) == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize(("case", "s"), PARAMS)
def test_restrainer_points(case: str, s: int) -> None:
    # Elongation u(θ) = r[sin φ − sin(φ − θ)] (block) against X(0) − X(θ) (chain), the
    # moment of a unit force, the loss rotations and the failures with their drops. The
    # chain's difference of positions X(0) − X(θ) rounds to ε·r ≈ 7e-16 m (r ≤ 3.3 m), so the
    # rotation of a given elongation u agrees to 1e-12 + 1e-15/u relative (1e-9 at u = 1 µm).
    chain, block = pair(case, s)
    for i in range(len(chain.restrainers)):
        p_chain, p_block = chain.placement(i), block.placement(i)
        for theta in THETAS:
            assert p_chain.elongation(theta) == pytest.approx(p_block.elongation(theta),
                                                              rel=REL, abs=REL)  # fmt: skip
            assert p_chain.moment(1.0, theta) == pytest.approx(p_block.moment(1.0, theta),
                                                               rel=REL, abs=REL)  # fmt: skip
        for u in (1e-6, 0.01, 0.3):
            assert p_chain.rotation_at(u) == pytest.approx(p_block.rotation_at(u),
                                                           rel=REL + 1e-15 / u)  # fmt: skip
    for (n1, t1, d1), (n2, t2, d2) in zip(failure_rotations(chain), failure_rotations(block),
                                          strict=True):  # fmt: skip
        assert n1 == n2
        assert t1 == pytest.approx(t2, rel=REL)
        assert d1 == pytest.approx(d2, rel=REL, abs=REL)
