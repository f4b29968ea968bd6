"""α0 of every mechanism of the catalogue against closed forms written from the geometry.

Sources: the Circolare's virtual work at θ = 0 (Circ. 617/2009 Eq. C8A.4.1; Circ. 7/2019
§C8.7.1.1): α0 = (Σ_bearing P_i x_i − Σ F_h z_h + Σ T_k z_k) / Σ_moving P_i z_i, with (x, z)
each point's distance into the wall from the pivot and height above it, F_h a thrust pushing
the mechanism open, T_k a tie's force pulling it back; each storey's weight γ·t·h·width at its
centroid; the gable a triangle of base ``width`` whose centroid is a third of its height up;
the wedge a triangle with vertices (t, 0), (t, H), (t + H tan β, H) (centroid at their mean);
the two-block vertical flexure of Doherty et al. 2002 (EESD 31:833–850), its virtual
displacements derived in each test; the hinge's set-back a/2 = N/(2 f_m width) (the stress
block carrying N at f_m, Circ. 7/2019 §C8.7.1 "arretramento della cerniera").

Tolerance: the code sums the same few products in another order: 1e-13 relative (a few
hundred ulps).
"""

from __future__ import annotations

import math
from typing import Any

import pytest

from rockcli.codecheck.kinematic import Mechanism, alpha0, zero_rotation
from rockcli.mechanics import Restrainer
from rockcli.mechanisms import catalogue
from rockcli.mechanisms.catalogue import CrushingError
from rockcli.mechanisms.links import TwoBlock
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.wall import Storey, Wall, WallLoad, WallRestrainer, WallThrust

G = 9.81
GAMMA = 18e3  # [N/m³]
WIDTH = 4.0  # [m]
REL = 1e-13
SIDES = (1, -1)


def wall(*storeys: tuple[float, float], **kw: Any) -> Wall:
    """A wall of storeys (height, thickness), bottom up."""
    return Wall(storeys=tuple(Storey(h, t) for h, t in storeys), width=WIDTH,
                unit_weight=GAMMA, g=G, **kw)  # fmt: skip


def weight(h: float, t: float, depth: float = WIDTH) -> float:
    """γ·t·h·depth [N]."""
    return GAMMA * t * h * depth


def a0(side: ChainSide, s: int) -> float:
    """α0 of the code check of the mechanism on side s."""
    return alpha0(Mechanism(side))


def tie(force: float) -> Restrainer:
    """A tie-rod the check takes as a constant force (its r, φ unused by the catalogue)."""
    return Restrainer("tie", 1e7, 1e7, 1.0, 0.0, 1.0, 0.0, code_action="force", code_force=force)


# One storey 3.0 × 0.45 m.
H1, T1 = 3.0, 0.45
W1 = weight(H1, T1)


def arm(x: float, s: int, pivot_in: float = 0.0, pivot_out: float = T1) -> float:
    """x from the pivot of side s: from the outer edge (side 1) or back from the inner."""
    return x - pivot_in if s > 0 else pivot_out - x


@pytest.mark.parametrize("s", SIDES)
def test_one_storey_with_loads(s: int) -> None:
    # A floor P1 bearing and moving at (0.30, 3.0), a P2 moving only at (0.10, 2.0) (the
    # Circolare's P_j: denominator only), a P3 bearing only at (0.40, 3.0) (numerator only).
    p1, p2, p3 = 30e3, 8e3, 5e3
    loads = (WallLoad("P1", p1, 0.30, 3.0), WallLoad("P2", p2, 0.10, 2.0, bears=False),
             WallLoad("P3", p3, 0.40, 3.0, moves=False))  # fmt: skip
    side = catalogue.overturning(wall((H1, T1), loads=loads), 0.0, s, "o")
    num = W1 * T1 / 2 + p1 * arm(0.30, s) + p3 * arm(0.40, s)
    den = W1 * H1 / 2 + p1 * 3.0 + p2 * 2.0
    assert a0(side, s) == pytest.approx(num / den, rel=REL)


@pytest.mark.parametrize("s", SIDES)
@pytest.mark.parametrize("direction", (1, -1))
def test_one_storey_thrust(s: int, direction: int) -> None:
    # A thrust F at height 2.8 m: direction +1 opens side 1 (does positive work, lowers α0)
    # and shuts side −1: α0 = (W t/2 − d·s·F z)/(W h/2).
    f = 6e3
    thrust = WallThrust("roof", f, direction, 0.2, 2.8)
    side = catalogue.overturning(wall((H1, T1), thrusts=(thrust,)), 0.0, s, "o")
    expected = (W1 * T1 / 2 - direction * s * f * 2.8) / (W1 * H1 / 2)
    assert a0(side, s) == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize("s", SIDES)
def test_one_storey_tie_force(s: int) -> None:
    # A tie-rod taken as its force T = 10 kN at (0.2, 2.7): T·δx = T·z at θ = 0 on either
    # side (k on both): α0 = (W t/2 + T z)/(W h/2).
    force = 10e3
    ties = (WallRestrainer(tie(force), 0.2, 2.7),)
    side = catalogue.overturning(wall((H1, T1), restrainers=ties), 0.0, s, "o")
    assert a0(side, s) == pytest.approx((W1 * T1 / 2 + force * 2.7) / (W1 * H1 / 2), rel=REL)


# Two storeys with a set-back on the inner face: (3.5 m, 0.6 m), (3.0 m, 0.45 m); a floor at
# the first floor's level (3.5 m), a roof on top (6.5 m), a roof thrust.
S1, S2 = (3.5, 0.6), (3.0, 0.45)
WS1, WS2 = weight(*S1), weight(*S2)
FLOOR = WallLoad("floor", 40e3, 0.45, 3.5)
ROOF = WallLoad("roof", 25e3, 0.30, 6.5)
ROOF_THRUST = WallThrust("roof thrust", 5e3, 1, 0.2, 6.5)


@pytest.mark.parametrize("s", SIDES)
def test_two_storeys_about_the_base(s: int) -> None:
    # Storey 1's centroid (0.30, 1.75), storey 2's (0.225, 5.0); side −1 turns about the
    # ground storey's inner edge x = 0.6. The roof thrust opens side 1: −s·F·6.5.
    w = wall(S1, S2, loads=(FLOOR, ROOF), thrusts=(ROOF_THRUST,))
    side = catalogue.overturning(w, 0.0, s, "o")
    x = [arm(v, s, pivot_out=0.6) for v in (0.30, 0.225, 0.45, 0.30)]
    num = WS1 * x[0] + WS2 * x[1] + FLOOR.weight * x[2] + ROOF.weight * x[3]
    num -= s * ROOF_THRUST.force * 6.5
    den = WS1 * 1.75 + WS2 * 5.0 + FLOOR.weight * 3.5 + ROOF.weight * 6.5
    assert a0(side, s) == pytest.approx(num / den, rel=REL)


@pytest.mark.parametrize("s", SIDES)
def test_two_storeys_about_the_floor(s: int) -> None:
    # About the first floor (3.5 m): storey 2 alone, centroid 0.225 in and 1.5 up from the
    # hinge; side −1 about its inner edge x = 0.45. The floor load at the hinge's height
    # belongs below it (not on the mechanism); the roof 3.0 m above the hinge.
    w = wall(S1, S2, loads=(FLOOR, ROOF), thrusts=(ROOF_THRUST,))
    side = catalogue.overturning(w, 3.5, s, "o")
    num = WS2 * 0.225 + ROOF.weight * arm(0.30, s, pivot_out=0.45)
    num -= s * ROOF_THRUST.force * 3.0
    den = WS2 * 1.5 + ROOF.weight * 3.0
    assert a0(side, s) == pytest.approx(num / den, rel=REL)
    assert [ld.name for ld in side.loads] == ["roof"]


# A gable 1.8 m high on the one-storey wall, of its thickness.
HG = 1.8
WG = GAMMA * T1 * WIDTH * HG / 2


@pytest.mark.parametrize("s", SIDES)
def test_gable(s: int) -> None:
    # The gable about its base: centroid t/2 in and hg/3 up: α0 = (t/2)/(hg/3).
    side = catalogue.gable_mechanism(wall((H1, T1), gable_height=HG), s, "g")
    assert a0(side, s) == pytest.approx((T1 / 2) / (HG / 3), rel=REL)


@pytest.mark.parametrize("s", SIDES)
def test_gable_with_ridge_load(s: int) -> None:
    # A ridge beam 3 kN bearing and moving at (0.15, top of the gable): its arm from the
    # pivot 0.15 (side 1) or 0.30 (side −1), its height hg above the gable's base.
    ridge = WallLoad("ridge", 3e3, 0.15, H1 + HG)
    side = catalogue.gable_mechanism(wall((H1, T1), gable_height=HG, loads=(ridge,)), s, "g")
    num = WG * T1 / 2 + ridge.weight * arm(0.15, s)
    den = WG * HG / 3 + ridge.weight * HG
    assert a0(side, s) == pytest.approx(num / den, rel=REL)


@pytest.mark.parametrize("s", SIDES)
def test_whole_wall_with_gable(s: int) -> None:
    # The storey and the gable about the base: (W + W_g) t/2 over W h/2 + W_g (h + hg/3).
    side = catalogue.overturning(wall((H1, T1), gable_height=HG), 0.0, s, "o")
    expected = (W1 + WG) * T1 / 2 / (W1 * H1 / 2 + WG * (H1 + HG / 3))
    assert a0(side, s) == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize("sides", (1, 2))
def test_wedge(sides: int) -> None:
    # The façade W_f (centroid t/2, H/2) and the wedge of each return wall of thickness
    # t_r: W_w = γ t_r H² tan β/2 per wall, centroid (t + H tan β/3, 2H/3):
    # α0 = (W_f t/2 + W_w (t + H tan β/3)) / (W_f H/2 + W_w 2H/3). Side 1 only.
    beta, t_r = math.radians(30.0), 0.3
    w = wall((H1, T1), return_wall_thickness=t_r)
    side = catalogue.wedge(w, beta, sides, "w")
    ww = GAMMA * t_r * sides * H1 * H1 * math.tan(beta) / 2
    num = W1 * T1 / 2 + ww * (T1 + H1 * math.tan(beta) / 3)
    den = W1 * H1 / 2 + ww * 2 * H1 / 3
    assert a0(side, 1) == pytest.approx(num / den, rel=REL)


# Vertical flexure of the one-storey wall: its top held (a floor at 3.0 m).
@pytest.mark.parametrize("s", SIDES)
@pytest.mark.parametrize("psi", (0.0, 0.25, 1.0))
def test_flexure_doherty(s: int, psi: float) -> None:
    # Doherty et al. 2002: a mid-height hinge, overburden ψW bearing (not moving) at the
    # middle of the top: total lateral capacity 4 W t/h (1 + 1.5ψ), so α0 = 4t/h (1 + 1.5ψ).
    over = WallLoad("overburden", psi * W1, T1 / 2, H1, moves=False)
    side = catalogue.flexure(wall((H1, T1), loads=(over,)), 1, H1 / 2, s, "f")
    assert a0(side, s) == pytest.approx(4 * T1 / H1 * (1 + 1.5 * psi), rel=REL)


@pytest.mark.parametrize("s", SIDES)
@pytest.mark.parametrize("z_h", (0.8, 1.1, 2.2))
def test_flexure_off_mid_height(s: int, z_h: float) -> None:
    # Hinge at z_h on the inner face, the upper link turns at −r, r = z_h/(h − z_h)
    # (chain.py: ψ′ = z_H/(z_T − z_H)). Per unit rotation: the lower block (W z_h/h at
    # (t/2, z_h/2)) moves by (−z_h/2, t/2); the hinge by (−z_h, t); the upper block
    # (W (h − z_h)/h at (t/2, (h + z_h)/2)) by (−z_h + r (h − z_h)/2, t + r t/2) =
    # (−z_h/2, t(1 + r/2)); an overburden P at (x_s, h) from the pivot by
    # t + r (t − x_s) up. P = 20 kN, 0.1 m from the outer face: x_s = 0.1 (side 1),
    # 0.35 (side −1).
    p = 20e3
    over = WallLoad("overburden", p, 0.1, H1, moves=False)
    side = catalogue.flexure(wall((H1, T1), loads=(over,)), 1, z_h, s, "f")
    r = z_h / (H1 - z_h)
    w_lo, w_up = weight(z_h, T1), weight(H1 - z_h, T1)
    num = w_lo * T1 / 2 + w_up * T1 * (1 + r / 2) + p * (T1 + r * (T1 - arm(0.1, s)))
    den = (w_lo + w_up) * z_h / 2
    assert a0(side, s) == pytest.approx(num / den, rel=REL)


@pytest.mark.parametrize("s", SIDES)
def test_flexure_with_hinge_set_back(s: int) -> None:
    # f_m = 1.5 MPa, overburden P = 60 kN bearing at x_P = 0.2 m. Stress blocks: at the base
    # a_b = (W + P)/(f_m B), at the hinge a_m = (W/2 + P)/(f_m B). From the base pivot (a_b/2
    # in from its edge) the mid hinge is at X_H = t − a_m/2 − a_b/2; with ψ′ = 1 the lower
    # centroid rises x_G = t/2 − a_b/2, the upper 2X_H − x_G, the overburden 2X_H − x_s
    # (x_s = x_P − a_b/2, or t − a_b/2 − x_P on side −1): G = W X_H + P (2X_H − x_s),
    # H = W h/4 (as unset back: the heights do not move).
    f_m, p, x_p = 1.5e6, 60e3, 0.2
    over = WallLoad("overburden", p, x_p, H1, moves=False)
    side = catalogue.flexure(wall((H1, T1), loads=(over,), f_m=f_m), 1, H1 / 2, s, "f")
    a_b, a_m = (W1 + p) / (f_m * WIDTH), (W1 / 2 + p) / (f_m * WIDTH)
    x_h = T1 - a_m / 2 - a_b / 2
    x_s = x_p - a_b / 2 if s > 0 else T1 - a_b / 2 - x_p
    assert a0(side, s) == pytest.approx((W1 * x_h + p * (2 * x_h - x_s)) / (W1 * H1 / 4),
                                        rel=REL)  # fmt: skip


def test_flexure_instability_displacement() -> None:
    # Doherty et al. 2002: without overburden the mid-height hinge's displacement at
    # instability is Δ_ins = t. Exactly so by finite rotations here: the upper block stays
    # the lower's mirror through the hinge's level (its top point then at x = 0), so
    # V = W·Z_H = W (t sin θ + h/2 cos θ), zero slope at tan θ0 = 2t/h, where
    # t − X_H = t − t cos θ0 + (h/2) sin θ0 = t. θ0 by bisection of α(θ), resolved to
    # rounding (ε·W·h on G, slope W·h): 1e-12 relative.
    side = catalogue.flexure(wall((H1, T1)), 1, H1 / 2, 1, "f")
    theta0 = zero_rotation(Mechanism(side))
    assert theta0 is not None
    assert theta0 == pytest.approx(math.atan(2 * T1 / H1), rel=1e-12)
    assert isinstance(side.motion, TwoBlock)
    upper = side.states(theta0)[1]
    assert side.motion.hinge_x - upper.cx == pytest.approx(T1, rel=1e-12)


@pytest.mark.parametrize("s", SIDES)
def test_overturning_with_hinge_set_back(s: int) -> None:
    # f_m = 0.4 MPa: the hinge a/2 = W/(2 f_m B) in from either edge:
    # α0 = (t/2 − a/2)/(h/2); with a roof P bearing and moving at the middle of the top,
    # a = (W + P)/(f_m B) and α0 = (W + P)(t/2 − a/2)/(W h/2 + P h).
    f_m = 0.4e6
    a = W1 / (f_m * WIDTH)
    side = catalogue.overturning(wall((H1, T1), f_m=f_m), 0.0, s, "o")
    assert a0(side, s) == pytest.approx((T1 / 2 - a / 2) / (H1 / 2), rel=REL)
    p = 30e3
    roof = WallLoad("roof", p, T1 / 2, H1)
    side = catalogue.overturning(wall((H1, T1), f_m=f_m, loads=(roof,)), 0.0, s, "o")
    a = (W1 + p) / (f_m * WIDTH)
    expected = (W1 + p) * (T1 / 2 - a / 2) / (W1 * H1 / 2 + p * H1)
    assert a0(side, s) == pytest.approx(expected, rel=REL)


def test_crushing() -> None:
    # f_m below γ h (= W/(t B)): the stress block a = W/(f_m B) = t·γh/f_m is deeper than
    # the section at the base (overturning) and at the base of the flexure.
    f_m = 0.9 * GAMMA * H1
    w = wall((H1, T1), f_m=f_m)
    with pytest.raises(CrushingError) as info:
        catalogue.overturning(w, 0.0, 1, "o")
    assert info.value.depth == pytest.approx(W1 / (f_m * WIDTH), rel=REL)
    assert info.value.depth == pytest.approx(T1 / 0.9, rel=REL)
    assert info.value.thickness == T1
    with pytest.raises(CrushingError):
        catalogue.flexure(w, 1, H1 / 2, -1, "f")
