"""A member whose loss elongation is negative (its bar breaks at ε_u·L below the P0/K its
pretension already takes) is lost at rest: α0 is the block's without it (Circ. 617/2009 Eq.
C8A.4.1 with the forces present at activation), and the virtual-work table says the same."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.demand import SOIL_A_FLAT

MODEL = (
    """\
name = "lost at rest"
kind = "wall"
[geometry]
thickness = 0.50
height = 4.00
width = 1.00
[mass]
unit_weight = 18.0
[[restrainers]]
name = "tie"
kind = "tie-rod"
diameter = 0.02
length = 3.0
E = 210e9
grade = "S275"
height = 3.50
from_pivot = 0.25
pretension = 5000.0
elongation_at_break = 0.00005
code_action = "spring"
[ntc]
edition = "2009"
FC = 1.0
soil = "A"
"""
    + SOIL_A_FLAT
)


def test_a_member_lost_at_rest_is_not_in_alpha0(tmp_path: Path) -> None:
    # ε_u·L = 5e-5 × 3 m = 0.15 mm; P0/K = 5 kN / (E·A/L = 210e9 × 3.1416e-4 / 3 = 21.99 MN/m)
    # = 0.227 mm: the bar is past its break before the block moves. α0 = t/h = 0.5/4 = 0.125.
    model = tmp_path / "m.toml"
    model.write_text(MODEL, encoding="utf-8")
    result = CliRunner().invoke(cli, ["kinematic", str(model), "--format", "json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["alpha0"] == 0.125
    assert 5e-5 * 3.0 < 5000.0 / (210e9 * 3.14159265e-4 / 3.0)
