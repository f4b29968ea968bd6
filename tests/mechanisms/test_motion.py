"""The equation-of-motion terms of a mechanism (rockcli.mechanisms.motion).

Sources:
- one rectangle of half sizes b, h about its base corner (Housner 1963; the paper's Eq. 1–2;
  rockcli.mechanics' notation R = √(b² + h²), α = atan(b/h)): M = I0 = 4/3 m R² at every θ,
  V = m g R [cos(α − θ) − cos α] = 2 m g R sin(θ/2) sin(α − θ/2), V′ = m g R sin(α − θ),
  Γ = m R cos(α − θ) (the centroid at (b, h) turned by θ: X = b cos θ − h sin θ,
  Z = b sin θ + h cos θ);
- a point mass at rest at (x, z) from the pivot turning with the block: ∂X/∂θ = −(x sin θ +
  z cos θ), ∂Z/∂θ = x cos θ − z sin θ, so a load that moves adds m (x sin θ + z cos θ)²,
  one that bears m (x cos θ − z sin θ)², both m (x² + z²);
- the two-block chain (Doherty et al. 2002, EESD 31:833–850): at θ = 0 with the hinge at
  mid-height of a storey h × t, the lower block's centroid moves by (−h/4, t/2) per unit
  rotation, the upper's by (−h/4, 3t/2), the upper turns at −1 (derived in the comments);
  along θ, M from a central difference of the bodies' positions and angles done here.

Tolerances: closed forms against the sums of the module agree to rounding (a handful of
products and sums of order-one terms: 1e-13 relative, ~500 ulps); finite differences to their
truncation and rounding errors, bounded in each test's comment.
"""

from __future__ import annotations

import math

import pytest

from rockcli.codecheck.kinematic import Mechanism, alpha0
from rockcli.mechanics import Block, Load, point_moments, point_table, polar_inertia
from rockcli.mechanisms import catalogue
from rockcli.mechanisms.links import TwoBlock
from rockcli.mechanisms.motion import (
    MASS_STEP,
    generalised_mass,
    mass_slope,
    participation,
    potential,
    potential_slope,
)
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.wall import Storey, Wall, WallLoad

G = 9.81
GAMMA = 18e3  # unit weight [N/m³]
WIDTH = 1.2  # [m]
T, H = 0.5, 2.4  # one storey: thickness and height [m]; b = 0.25, h = 1.2
THETAS = (0.0, 1e-3, 0.05, 0.2, 0.6, 1.2)


def one_storey(*loads: WallLoad, f_m: float | None = None) -> Wall:
    """A one-storey wall T × H, WIDTH wide."""
    return Wall(storeys=(Storey(H, T),), width=WIDTH, unit_weight=GAMMA, g=G, loads=loads,
                f_m=f_m)  # fmt: skip


def housner() -> tuple[ChainSide, float, float, float]:
    """The wall overturning about its outer base edge, and its m, R, α."""
    b, h = T / 2, H / 2
    m = GAMMA * T * H * WIDTH / G
    side = catalogue.overturning(one_storey(), 0.0, 1, "o")
    return side, m, math.hypot(b, h), math.atan2(b, h)


@pytest.mark.parametrize("theta", THETAS)
def test_housner_block(theta: float) -> None:
    # Housner 1963: M = 4/3 m R², V = 2 m g R sin(θ/2) sin(α − θ/2) (the product form of
    # cos(α − θ) − cos α: no cancellation in the reference), V′ = m g R sin(α − θ),
    # Γ = m R cos(α − θ). Rounding only: 1e-13 relative.
    side, m, R, alpha = housner()
    assert generalised_mass(side, theta) == pytest.approx(4 / 3 * m * R * R, rel=1e-13)
    v = 2 * m * G * R * math.sin(theta / 2) * math.sin(alpha - theta / 2)
    assert potential(side, theta) == pytest.approx(v, rel=1e-13, abs=0.0)
    assert potential_slope(side, theta) == pytest.approx(m * G * R * math.sin(alpha - theta),
                                                         rel=1e-13)  # fmt: skip
    assert participation(side, theta) == pytest.approx(m * R * math.cos(alpha - theta),
                                                       rel=1e-13)  # fmt: skip


@pytest.mark.parametrize("theta", (*THETAS, math.pi / 2 - 0.5 * MASS_STEP))
def test_housner_mass_is_constant(theta: float) -> None:
    # M = I0 at every θ, so M′ = 0; the difference quotient of two roundings of M (ε·M each,
    # ε = 2.2e-16) over 2h = 2e-5 is below 2.2e-11·M: bound 1e-9·M. The last θ is within
    # one step of the limit π/2 (the one-sided formula).
    side, m, R, _ = housner()
    assert abs(mass_slope(side, theta)) <= 1e-9 * 4 / 3 * m * R * R


def test_housner_rest_and_alpha0() -> None:
    # V(0) = 0 by definition; α0 = V′(0)/(g Γ(0)) (Circ. 7/2019 §C8.7.1.1, no thrusts nor
    # restrainers) = tan α = b/h for the block; g Γ = H of work_terms (rounding: 1e-14).
    side, _, _, alpha = housner()
    assert potential(side, 0.0) == 0.0
    a0 = alpha0(Mechanism(side))
    assert potential_slope(side, 0.0) / (G * participation(side, 0.0)) == pytest.approx(
        a0, rel=1e-14
    )
    assert a0 == pytest.approx(math.tan(alpha), rel=1e-14)
    for theta in THETAS:
        assert G * participation(side, theta) == pytest.approx(side.work_terms(theta)[2],
                                                               rel=1e-14)  # fmt: skip


#: A load of 20 kN at (x, z) = (0.1, 2.0) from the outer base edge, on the one-storey wall.
LX, LZ, LW = 0.1, 2.0, 20e3


@pytest.mark.parametrize(("bears", "moves"), [(True, True), (False, True), (True, False)])
@pytest.mark.parametrize("theta", (0.0, 0.05, 0.4, 1.0))
def test_load_as_point_mass(bears: bool, moves: bool, theta: float) -> None:
    # Module docstring: a rigid point mass adds m (x² + z²); one that moves only
    # m (x sin θ + z cos θ)² (its horizontal velocity), one that bears only
    # m (x cos θ − z sin θ)²; M′ of the last two ±2m (x sin θ + z cos θ)(x cos θ − z sin θ).
    # V adds P [x sin θ − z (1 − cos θ)] when it bears, V′ P (x cos θ − z sin θ); Γ adds
    # m (x sin θ + z cos θ) when it moves. Rounding: 1e-13; M′ by central difference
    # (truncation h²|M‴|/6 ~ 1e-10·m z², rounding 2e-11·M): abs 1e-8·M.
    side, mb, R, alpha = housner()
    load = WallLoad("P", LW, LX, LZ, bears=bears, moves=moves)
    side = catalogue.overturning(one_storey(load), 0.0, 1, "o")
    m = LW / G
    c, s = math.cos(theta), math.sin(theta)
    hor, ver = LX * s + LZ * c, LX * c - LZ * s
    m0 = 4 / 3 * mb * R * R
    mass = m0 + (m * hor * hor if moves else 0.0) + (m * ver * ver if bears else 0.0)
    slope = 2 * m * hor * ver * ((1.0 if moves else 0.0) - (1.0 if bears else 0.0))
    v = 2 * mb * G * R * math.sin(theta / 2) * math.sin(alpha - theta / 2)
    v += LW * (LX * s - LZ * 2 * math.sin(theta / 2) ** 2) if bears else 0.0
    dv = mb * G * R * math.sin(alpha - theta) + (LW * ver if bears else 0.0)
    gamma = mb * R * math.cos(alpha - theta) + (m * hor if moves else 0.0)
    assert generalised_mass(side, theta) == pytest.approx(mass, rel=1e-13)
    assert mass_slope(side, theta) == pytest.approx(slope, abs=1e-8 * mass)
    assert potential(side, theta) == pytest.approx(v, rel=1e-13, abs=1e-13 * mb * G * R)
    assert potential_slope(side, theta) == pytest.approx(dv, rel=1e-13)
    assert participation(side, theta) == pytest.approx(gamma, rel=1e-13)


@pytest.mark.parametrize("s", (1, -1))
@pytest.mark.parametrize("theta", (0.0, 0.05, 0.4, 1.0))
def test_the_engines_block_sees_the_same_terms(s: int, theta: float) -> None:
    # The rocking engine's equation of the loaded block (rockcli.mechanics.point_moments):
    # I0 + J = M, dJ = M′, G = V′, H = g Γ for the same block and loads (x_neg = t − x).
    # Rounding: 1e-13; M′ as above (abs 1e-8·M).
    loads = (WallLoad("a", 15e3, 0.3, 2.4), WallLoad("b", 6e3, 0.1, 1.9, moves=False),
             WallLoad("c", 9e3, 0.45, 2.1, bears=False))  # fmt: skip
    side = catalogue.overturning(one_storey(*loads), 0.0, s, "o")
    b, h = T / 2, H / 2
    m = GAMMA * T * H * WIDTH / G
    block = Block(R=math.hypot(b, h), alpha=math.atan2(b, h), mass=m, g=G,
                  loads=tuple(Load(ld.name, ld.weight, ld.x, T - ld.x, ld.z, ld.bears, ld.moves)
                              for ld in loads))  # fmt: skip
    g_, h_, _, j, dj = point_moments(point_table(block), s, math.sin(theta), math.cos(theta))
    mass = polar_inertia(m, block.R) + j
    assert generalised_mass(side, theta) == pytest.approx(mass, rel=1e-13)
    assert mass_slope(side, theta) == pytest.approx(dj, abs=1e-8 * mass)
    assert potential_slope(side, theta) == pytest.approx(g_, rel=1e-13)
    assert G * participation(side, theta) == pytest.approx(h_, rel=1e-13)


# The two-block chain: one storey 3.0 × 0.45 m, a floor at its top (it holds the top).
FH, FT = 3.0, 0.45


def flexure_side(hinge: float, s: int, f_m: float | None = None) -> ChainSide:
    """Vertical flexure of the storey, overburden 12 kN bearing only at (0.15, top), a
    rigid 5 kN load at (0.3, 0.8) on the lower block and a 4 kN one moving only at
    (0.2, 2.6) on the upper."""
    loads = (WallLoad("over", 12e3, 0.15, FH, moves=False), WallLoad("low", 5e3, 0.3, 0.8),
             WallLoad("up", 4e3, 0.2, 2.6, bears=False))  # fmt: skip
    wall = Wall(storeys=(Storey(FH, FT),), width=WIDTH, unit_weight=GAMMA, g=G, loads=loads,
                f_m=f_m)  # fmt: skip
    return catalogue.flexure(wall, 1, hinge, s, "f")


def numeric_mass(side: ChainSide, theta: float, step: float) -> float:
    """M(θ) from central differences of the positions and link angles of the chain's states
    (the bodies' centroids and the loads' points), summed here."""
    plus, minus = side.states(theta + step), side.states(theta - step)

    def velocity(link: int, x: float, z: float) -> tuple[float, float]:
        xp, zp, _, _ = plus[link].place(x, z)
        xm, zm, _, _ = minus[link].place(x, z)
        return (xp - xm) / (2 * step), (zp - zm) / (2 * step)

    total = 0.0
    for link, body in side.bodies:
        vx, vz = velocity(link, body.x, body.z)
        dphi = (plus[link].phi - minus[link].phi) / (2 * step)
        total += body.mass * (vx * vx + vz * vz) + body.inertia * dphi * dphi
    for ld in side.loads:
        vx, vz = velocity(ld.at.link, ld.at.x, ld.at.z)
        m = ld.weight / G
        total += m * ((vx * vx if ld.moves else 0.0) + (vz * vz if ld.bears else 0.0))
    return total


CHAINS = [(1.5, 1, None), (1.1, 1, None), (1.9, -1, None), (1.3, 1, 2e6), (1.6, -1, 2e6)]


@pytest.mark.parametrize(("hinge", "s", "f_m"), CHAINS)
@pytest.mark.parametrize("share", (0.0, 0.01, 0.2, 0.5, 0.9))
def test_two_block_mass_against_positions(hinge: float, s: int, f_m: float | None,
                                          share: float) -> None:  # fmt: skip
    # M(θ) from positions differenced here with step 1e-6 rad: truncation ~h²·|r‴|/|r′| ≲
    # 1e-12 relative away from the limit (share ≤ 0.9 of it: the upper link's rate stays
    # within a few times its rest value), rounding ε·|r|/h ~ 1e-9 relative of each velocity:
    # bound 1e-7 relative.
    side = flexure_side(hinge, s, f_m)
    theta = share * side.limit
    assert generalised_mass(side, theta) == pytest.approx(numeric_mass(side, theta, 1e-6),
                                                          rel=1e-7)  # fmt: skip


@pytest.mark.parametrize(("hinge", "s", "f_m"), CHAINS)
@pytest.mark.parametrize("share", (0.0, 0.01, 0.2, 0.5, 0.9))
def test_two_block_energy(hinge: float, s: int, f_m: float | None, share: float) -> None:
    # V′ = dV/dθ: the central difference of V with step 1e-6 (truncation h²|V‴|/6 ~ 1e-12·W·h,
    # rounding ε·|V|/h ≲ 1e-9·W·h) equals potential_slope to 1e-8·(W h) absolute, W h =
    # the weights times the storey height (the scale of V′). M′ against the five-point
    # difference of M with step 1e-4 (truncation h⁴|M⁽⁵⁾|/30 and rounding ε|M|/h, both
    # below 1e-11 relative): the error is mass_slope's own h²|M‴|/6, 1e-10 relative at rest
    # and 1e-8 at 0.9 of the limit, where M grows steepest (M′/M ≈ 8 at hinge 1.9 m, side −1):
    # rel 1e-7, and abs 1e-8·M where M′ passes through zero.
    side = flexure_side(hinge, s, f_m)
    theta = share * side.limit
    step = 1e-6
    scale = (sum(b.weight for _, b in side.bodies) + sum(ld.weight for ld in side.loads)) * FH
    dv = (potential(side, theta + step) - potential(side, theta - step)) / (2 * step)
    assert potential_slope(side, theta) == pytest.approx(dv, abs=1e-8 * scale)
    k = 1e-4
    m = [generalised_mass(side, theta + j * k) for j in (-2, -1, 1, 2)]
    five = (m[0] - 8 * m[1] + 8 * m[2] - m[3]) / (12 * k)
    mass = generalised_mass(side, theta)
    assert mass_slope(side, theta) == pytest.approx(five, rel=1e-7, abs=1e-8 * mass)


def test_two_block_potential_from_positions() -> None:
    # V(θ) = Σ W [Z(θ) − Z(0)] over the bodies and bearing loads, the heights read from the
    # chain's states here; V(0) = 0. Rounding of differences of heights ~ε·W·h: 1e-12·W·h.
    side = flexure_side(1.2, 1)
    scale = (sum(b.weight for _, b in side.bodies) + sum(ld.weight for ld in side.loads)) * FH
    assert potential(side, 0.0) == pytest.approx(0.0, abs=1e-15 * scale)
    for theta in (0.01, 0.1, 0.5 * side.limit):
        now, rest = side.states(theta), side.states(0.0)
        v = sum(b.weight * (now[k].place(b.x, b.z)[1] - rest[k].place(b.x, b.z)[1])
                for k, b in side.bodies)  # fmt: skip
        for ld in side.loads:
            if ld.bears:
                z1 = now[ld.at.link].place(ld.at.x, ld.at.z)[1]
                v += ld.weight * (z1 - rest[ld.at.link].place(ld.at.x, ld.at.z)[1])
        assert potential(side, theta) == pytest.approx(v, abs=1e-12 * scale)


def test_two_block_mid_height_at_rest() -> None:
    # Mid-height hinge, no loads, side 1 (pivot at the outer base edge, hinge on the inner
    # face at (t, h/2), top held at (0, h)): the upper link turns at ψ′ = z_H/(z_T − z_H) = 1
    # (chain.py), i.e. φ′ = −1. Lower centroid (t/2, h/4): ∂(X, Z)/∂θ = (−h/4, t/2). Upper
    # centroid (t/2, 3h/4): the hinge moves (−h/2, t), plus φ′·(−v_z, v_x) with
    # v = (−t/2, h/4): (−h/2 + h/4, t + t/2) = (−h/4, 3t/2). Each half has m/2 and
    # I_G = (m/2)(t² + h²/4)/12. So M(0) = (m/2)(h²/16 + t²/4) + (m/2)(h²/16 + 9t²/4)
    # + 2 I_G, Γ(0) = m h/4, V′(0) = W t/4 + 3 W t/4 = W t (Doherty et al. 2002: α0 = 4t/h).
    wall = Wall(storeys=(Storey(FH, FT),), width=WIDTH, unit_weight=GAMMA, g=G)
    side = catalogue.flexure(wall, 1, FH / 2, 1, "f")
    assert isinstance(side.motion, TwoBlock)
    w = GAMMA * FT * FH * WIDTH
    m, h, t = w / G, FH, FT
    i_g = (m / 2) * (t * t + h * h / 4) / 12
    mass = (m / 2) * (h * h / 16 + t * t / 4) + (m / 2) * (h * h / 16 + 9 * t * t / 4) + 2 * i_g
    assert generalised_mass(side, 0.0) == pytest.approx(mass, rel=1e-13)
    assert participation(side, 0.0) == pytest.approx(m * h / 4, rel=1e-13)
    assert potential_slope(side, 0.0) == pytest.approx(w * t, rel=1e-13)
    assert potential_slope(side, 0.0) / (G * participation(side, 0.0)) == pytest.approx(
        alpha0(Mechanism(side)), rel=1e-14
    )
