"""e*, M* and d* per rigid block for the 2019 edition, per weight for 2009.

Circolare 7/2019 Eqs. C8.7.1.4–C8.7.1.5 sum over the n+m rigid *blocks*, each with the
resultant of its own and carried weights at the resultant's point (§C8.7.1.2.1.1); Circolare
617/2009 Eqs. C8A.4.2–C8A.4.3 sum over the weights. Expected values worked by hand here.

The wall: one storey h = 4 m, t = 0.25 m, 1 m wide, 18 kN/m³ (W = 18 kN), in vertical flexure
with the hinge at a = 2 m: per unit δθ both blocks' centroids move out a/2 = 1 m
(tests/mechanisms/test_flexure_dynamics.py). A floor of L = 9 kN that moves with the wall at
z = 0.5 m lies on the lower block: δx = 0.5 m. The top is held by a weightless restraint that
does not move (it enters neither sum).

- 2019: lower block P1 = 9 + 9 = 18 kN, P1·δx1 = 9·1 + 9·0.5 = 13.5; upper P2 = 9, P2·δx2 = 9.
  Σ P δx = 22.5, Σ P_k δx_k² = 13.5²/18 + 9²/9 = 19.125, Σ P = 27:
  e* = 22.5²/(27·19.125) = 0.980392156862745 (= 50/51).
- 2009 (lumped): Σ P δx² = 9·1 + 9·1 + 9·0.25 = 20.25: e* = 22.5²/(27·20.25) = 0.925925925925926
  (= 25/27).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rockcli.analyses.kinematic import kinematic_model
from rockcli.model.load import load_model
from tests.demand import SOIL_B

WALL = (
    """
name = "flexure with a floor on the lower block"
kind = "wall"
[geometry]
width = 1.0
[[geometry.storeys]]
height = 4.0
thickness = 0.25
[mass]
unit_weight = 18.0
[[loads]]
name = "floor"
weight = 9.0
height = 0.5
from_pivot = 0.125
[[loads]]
name = "top restraint"
weight = 1e-6
height = 4.0
moves = false
[[mechanisms]]
name = "flexure"
type = "vertical-flexure"
storey = 1
hinge_height = 2.0
[ntc]
edition = "2019"
FC = 1.35
"""
    + SOIL_B
)


def flexure(tmp_path: Path, edition: str):
    path = tmp_path / "wall.toml"
    path.write_text(WALL)
    model = load_model(str(path))
    result = kinematic_model(model, edition=edition)
    return next(m for m in result.catalogue if m.name == "flexure")


def test_two_blocks_2019(tmp_path: Path) -> None:
    entry = flexure(tmp_path, "2019")
    assert entry.result.e_star == pytest.approx(50.0 / 51.0, rel=1e-12)
    assert entry.M_star == pytest.approx(22.5e3**2 / (9.81 * 19.125e3), rel=1e-12)


def test_per_weight_2009(tmp_path: Path) -> None:
    entry = flexure(tmp_path, "2009")
    assert entry.result.e_star == pytest.approx(25.0 / 27.0, rel=1e-12)


ONE_BLOCK = (
    """
name = "block with a floor"
kind = "wall"
[geometry]
thickness = 0.5
height = 4.0
width = 1.0
[mass]
unit_weight = 18.0
[[loads]]
name = "floor"
weight = 20.0
height = 4.0
from_pivot = 0.25
[ntc]
edition = "2019"
FC = 1.35
"""
    + SOIL_B
)


def test_one_block_with_a_load_has_e_star_one_in_2019(tmp_path: Path) -> None:
    """One block: e* = 1 and d* = the resultant's displacement. W = 18·0.5·4 = 36 kN at z = 2,
    the floor 20 kN at z = 4: the resultant 56 kN at z_P = (72 + 80)/56 = 2.714285714 m;
    d*/d_k = z_P/z_G (the control point the block's centroid, z_G = 2 m) = 1.357142857.
    2009: e* = (72 + 80)²/(56·(36·4 + 20·16)) = 23104/25984 = 0.889162561576355."""
    path = tmp_path / "block.toml"
    path.write_text(ONE_BLOCK)
    model = load_model(str(path))
    r19 = kinematic_model(model, edition="2019")
    assert r19.e_star == pytest.approx(1.0, rel=1e-12)
    d0_19 = r19.d0_star
    r09 = kinematic_model(model, edition="2009")
    assert r09.e_star == pytest.approx(23104.0 / 25984.0, rel=1e-12)
    # d0* = d_k,0·(Σ P δx²)/(δx_k Σ P δx): the ratio of the two editions' d0* is that of their
    # Σ P δx² (the same d_k,0, δx_k and Σ P δx): (152²/56)/464.
    assert d0_19 / r09.d0_star == pytest.approx((152.0**2 / 56.0) / 464.0, rel=1e-9)
