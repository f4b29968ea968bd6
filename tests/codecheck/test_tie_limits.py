"""A tie-rod in the kinematic check: lost where its ductility check says, slack inward.

Circolare 7/2019 §C8.7.1.2.1.6: d0 on the curve of "solamente le azioni di cui è verificata
la presenza fino al collasso", and d_SLV capped by "rotture di elementi, quali catene" that
remove more than half the capacity. A bar is lost at the elongation its ductility check
allows, ε_u·L/γ_ε (codecheck.tie); a bar pulls, it does not push.

The wall by hand: 0.6 m × 8 m, W = 300 kN (b = 0.3, h = 4 m from the pivot O), one block,
e* = 1 and d* = d_k (the control point its centroid; Eqs. C8.7.1.4–C8.7.1.5). A tie-rod
S275 Ø20, L = 3 m, at the outer face 7.5 m up: T = N_pl,Rd = π·0.01²·275 MPa/1.05, ε_u = 23 %
(EN 10025-2 Tab. 7), so it is lost at u = 0.23·3/2 = 0.345 m. Its point (0, 7.5) about O moves
out by u = 7.5·sin θ: θ_f = asin(0.345/7.5). The centroid moves d_k = R[sin α − sin(α − θ)].
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.demand import SOIL_A_FLAT

WALL = (
    """
name = "tied wall"
kind = "wall"
[geometry]
thickness = 0.6
height = 8.0
width = 1.0
[mass]
weight = 300.0
[[restrainers]]
name = "tie"
kind = "tie-rod"
grade = "S275"
diameter = 0.02
length = 3.0
height = 7.5
from_pivot = 0.0
[ntc]
edition = "2019"
FC = 1.35
"""
    + SOIL_A_FLAT
)
W, B, H, H_T = 300e3, 0.3, 4.0, 7.5
R, ALPHA = math.hypot(B, H), math.atan2(B, H)
T = math.pi * 0.01**2 * 275e6 / 1.05
THETA_F = math.asin(0.23 * 3.0 / 2.0 / H_T)


def kinematic(tmp_path: Path) -> dict:
    path = tmp_path / "wall.toml"
    path.write_text(WALL)
    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_the_tie_is_lost_at_its_ductility_limit(tmp_path: Path) -> None:
    doc = kinematic(tmp_path)
    assert doc["side"] == 1  # both sides reach d0* = b: the tie goes to the outward side
    [tie] = doc["restrainer_actions"]
    d_f = R * (math.sin(ALPHA) - math.sin(ALPHA - THETA_F))
    assert tie["lost_at_d_star"] == pytest.approx(d_f, rel=1e-9)


def test_the_curve_drops_there_and_d0_is_the_bare_wall_s(tmp_path: Path) -> None:
    """θ_f = 0.0460 < α = 0.0748: the bare wall still stands after the drop, so d0 is its own
    zero, d_k = b; the drop 1 − tan(α − θ_f)/α(θ_f⁻) is far above 50 %, so d_SLV =
    min(0.4·d0, d*(θ_f)) (§C8.7.1.2.1.6)."""
    doc = kinematic(tmp_path)
    assert doc["d0_star"] == pytest.approx(B, rel=1e-9)
    before = (W * R * math.sin(ALPHA - THETA_F) + T * H_T * math.cos(THETA_F)) / (
        W * R * math.cos(ALPHA - THETA_F)
    )
    assert 1.0 - math.tan(ALPHA - THETA_F) / before > 0.5
    d_f = R * (math.sin(ALPHA) - math.sin(ALPHA - THETA_F))
    assert doc["d_SLV"] == pytest.approx(min(0.4 * B, d_f), rel=1e-9)


def test_a_tie_rod_does_not_push_inward(tmp_path: Path) -> None:
    """Outward α0 = (W·b + T·h_T)/(W·h) (Eq. C8.7.1.1 with the tie's force); inward the bar
    goes slack: b/h."""
    doc = kinematic(tmp_path)
    assert doc["alpha0_by_side"]["1"] == pytest.approx((W * B + T * H_T) / (W * H), rel=1e-9)
    assert doc["alpha0_by_side"]["-1"] == pytest.approx(B / H, rel=1e-12)
    assert any("only pulls" in n for n in doc["notes"])
