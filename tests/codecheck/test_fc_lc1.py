"""The confidence factor of LC1 where α ignores the masonry's compressive strength.

Circolare 7/2019 §C8.7.1.2.1.3: "nel caso in cui, per la valutazione del moltiplicatore α, non
si tenga conto della resistenza a compressione della muratura, il fattore di confidenza da
utilizzare sarà comunque quello relativo al livello di conoscenza LC1" (FC = 1.35, §C8.5.4).

The wall: one storey 4 m × 0.5 m, 1 m wide, 18 kN/m³, no loads: α0 = b/h = 0.25/2 = 0.125, one
block, e* = 1 (Eq. C8.7.1.5), so a0* = α0·g/(e*·FC) = 0.125·9.81/FC (Eq. C8.7.1.3).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.analyses.kinematic import kinematic_model
from rockcli.cli.main import cli
from rockcli.model.load import load_model
from tests.demand import SOIL_B

WALL = (
    """
name = "wall"
kind = "wall"
[geometry]
width = 1.0
[[geometry.storeys]]
height = 4.0
thickness = 0.5
[mass]
unit_weight = 18.0
{masonry}
[ntc]
edition = "2019"
{fc}
"""
    + SOIL_B
)
STRENGTH = "[masonry]\nf_m = 2.0e6"


def model_file(tmp_path: Path, fc: str, masonry: str = "") -> Path:
    path = tmp_path / "wall.toml"
    path.write_text(WALL.format(fc=fc, masonry=masonry))
    return path


def test_lc3_without_strength_takes_lc1(tmp_path: Path) -> None:
    model = load_model(str(model_file(tmp_path, 'knowledge_level = "LC3"')))
    result = kinematic_model(model)
    assert result.FC == 1.35
    assert result.a0_star == pytest.approx(0.125 * 9.81 / 1.35, rel=1e-12)
    assert "§C8.7.1.2.1.3" in result.FC_rule
    assert any("§C8.7.1.2.1.3" in n for n in result.notes)


def test_lc3_with_strength_keeps_its_fc(tmp_path: Path) -> None:
    model = load_model(str(model_file(tmp_path, 'knowledge_level = "LC3"', STRENGTH)))
    result = kinematic_model(model)
    assert result.FC == 1.0
    assert "LC3" in result.FC_rule


def test_2009_keeps_the_given_level(tmp_path: Path) -> None:
    """The rule is read in the 2019 text; the 2009 edition keeps its FC
    (docs/interpretations.md)."""
    model = load_model(str(model_file(tmp_path, 'knowledge_level = "LC3"')))
    assert kinematic_model(model, edition="2009").FC == 1.0


def test_a_lower_fc_without_strength_is_refused(tmp_path: Path) -> None:
    path = model_file(tmp_path, "FC = 1.0")
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert "ntc.FC" in lines[0] and "1.35" in lines[0] and "f_m" in lines[0]


def test_a_lower_fc_with_strength_is_used(tmp_path: Path) -> None:
    model = load_model(str(model_file(tmp_path, "FC = 1.0", STRENGTH)))
    result = kinematic_model(model)
    assert result.FC == 1.0


def test_json_carries_fc_and_its_rule(tmp_path: Path) -> None:
    import json

    path = model_file(tmp_path, 'knowledge_level = "LC2"')
    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["FC"] == 1.35
    assert "LC1" in doc["FC_rule"] and "LC2" in doc["FC_rule"]
