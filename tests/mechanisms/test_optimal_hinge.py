"""The optimal hinge of a vertical flexure (rockcli.mechanisms.catalogue.optimal_hinge).

The function minimised is the code check's: the smaller α0 of sides 1 and −1 of the flexure
at each hinge height (rockcli.analyses.catalogue.resolved). Each case is checked against a
brute-force scan of 2001 heights over catalogue.flexure_range (the optimum's α0 no more than
the scan's least + 1e-9 relative, its height within one scan step of the scan's best) and
against the closed form of the two-block chain.

Closed form (virtual work at θ = 0, Doherty et al. 2002, EESD 31:833–850; derived in
tests/mechanisms/test_closed_forms.py::test_flexure_off_mid_height): a storey h × t of weight
W, the hinge z above its base, an overburden P bearing at x_s from the pivot at the top (the
top point does not move horizontally, so P adds nothing to H whether it moves or not):
G = (W + P) t + P (t − x_s) z/(h − z), H = W z/2, so α0 = (2/W)[A/z + B/(h − z)] with
A = (W + P) t and B = P (t − x_s); the smaller over the sides has the larger x_s. Without
overburden (B = 0) α0 = 2t/z falls all the way up: the optimum is the top of the range.
With B > 0 the least is at z* = h/(1 + √(B/A)), α0* = 2(√A + √B)²/(W h).

Tolerances: the golden section resolves a flat minimum to √ε of the height (1e-8; its α0 to
ε): heights within 1e-6 relative, α0 within 1e-12.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from rockcli.codecheck.kinematic import Mechanism, alpha0
from rockcli.mechanisms import catalogue
from rockcli.mechanisms.wall import Storey, Wall, WallLoad

G = 9.81
GAMMA = 18e3  # [N/m³]
WIDTH = 1.0  # [m]
SCAN = 2001


def smallest(wall: Wall, storey: int) -> Callable[[float], float]:
    """z ↦ the smaller α0 of the flexure's two sides with the hinge at z."""

    def f(z: float) -> float:
        return min(alpha0(Mechanism(catalogue.flexure(wall, storey, z, s, "f"))) for s in (1, -1))

    return f


def check_against_scan(wall: Wall, storey: int) -> tuple[float, float]:
    """The optimum (z, α0), after checking it against the scan of 2001 heights."""
    lo, hi = catalogue.flexure_range(wall, storey)
    f = smallest(wall, storey)
    z = catalogue.optimal_hinge(lo, hi, f)
    step = (hi - lo) / (SCAN - 1)
    zs = [lo + step * k for k in range(SCAN)]
    values = [f(v) for v in zs]
    k = min(range(SCAN), key=values.__getitem__)
    assert lo <= z <= hi
    assert f(z) <= values[k] * (1 + 1e-9)
    assert abs(z - zs[k]) <= step * (1 + 1e-9)
    return z, f(z)


def test_no_overburden_top_of_the_range() -> None:
    # One storey 3.0 × 0.45, nothing on it: α0 = 2t/z decreasing, so the optimum is the top
    # of flexure_range, h − max(t, h/10) = 2.55 m, α0 = 0.9/2.55 (not mid-height: gravity
    # breaks the up-down symmetry of the chain, the lower block's base being fixed and the
    # top free to rise).
    h, t = 3.0, 0.45
    wall = Wall(storeys=(Storey(h, t),), width=WIDTH, unit_weight=GAMMA, g=G)
    z, a0 = check_against_scan(wall, 1)
    top = h - max(t, 0.1 * h)
    assert z == pytest.approx(top, rel=1e-12)
    assert a0 == pytest.approx(2 * t / top, rel=1e-12)
    mid = smallest(wall, 1)(h / 2)
    assert mid == pytest.approx(4 * t / h, rel=1e-12)  # Doherty's mid-height 4t/h is higher
    assert a0 < mid


@pytest.mark.parametrize(("share", "x_e"), [(0.5, 0.1), (0.5, 0.225), (1.5, 0.4), (3.0, 0.3)])
def test_eccentric_overburden(share: float, x_e: float) -> None:
    # Overburden P = share·W bearing only at x_e from the outer face on the top: the side
    # with the larger arm x_s = max(x_e, t − x_e) governs; z* = h/(1 + √(B/A)).
    h, t = 3.0, 0.45
    w = GAMMA * t * h * WIDTH
    p = share * w
    over = WallLoad("overburden", p, x_e, h, moves=False)
    wall = Wall(storeys=(Storey(h, t),), width=WIDTH, unit_weight=GAMMA, g=G, loads=(over,))
    a, b = (w + p) * t, p * (t - max(x_e, t - x_e))
    z_star = h / (1 + math.sqrt(b / a))
    lo, hi = catalogue.flexure_range(wall, 1)
    assert lo < z_star < hi
    z, a0 = check_against_scan(wall, 1)
    assert z == pytest.approx(z_star, rel=1e-6)
    assert a0 == pytest.approx(2 * (math.sqrt(a) + math.sqrt(b)) ** 2 / (w * h), rel=1e-12)


def test_upper_storey_of_two() -> None:
    # Storeys (3.5, 0.6), (3.0, 0.45); the flexure of storey 2 between 3.5 and 6.5 m. The
    # floor at 3.5 m (the storey's base) is not on it; the roof 30 kN bearing and moving at
    # 0.12 m from the outer face on top (the held top: no H). z* = 3.5 + 3.0/(1 + √(B/A)).
    h, t = 3.0, 0.45
    floor = WallLoad("floor", 50e3, 0.5, 3.5)
    roof = WallLoad("roof", 30e3, 0.12, 6.5)
    wall = Wall(storeys=(Storey(3.5, 0.6), Storey(h, t)), width=WIDTH, unit_weight=GAMMA, g=G,
                loads=(floor, roof))  # fmt: skip
    w = GAMMA * t * h * WIDTH
    a, b = (w + roof.weight) * t, roof.weight * (t - max(0.12, t - 0.12))
    z, a0 = check_against_scan(wall, 2)
    assert z == pytest.approx(3.5 + h / (1 + math.sqrt(b / a)), rel=1e-6)
    assert a0 == pytest.approx(2 * (math.sqrt(a) + math.sqrt(b)) ** 2 / (w * h), rel=1e-12)
