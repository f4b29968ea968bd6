"""Tie-rods of a steel grade: their strength, and the time history's force checked against it.

The time history keeps the restrainer elastic; the check says when its force passes the design
tension resistance (NTC 2018 §4.2.4.1.2) or the anchor's capacity, and the verdict line says
the result is then not valid. The paper's façade (examples/facade.toml): a Ø20 S275 rod,
N_t,Rd = 82.28 kN (tests/codecheck/test_steel.py), against 747 kN in the elastic run under
the Ricker pulse.
"""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.steel import GRADES, rod_area, tension_resistance
from rockcli.errors import InputError
from rockcli.model.derive import to_block
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
FACADE = ROOT / "examples" / "facade.toml"

ROD: dict[str, Any] = {
    "name": "rod",
    "kind": "tie-rod",
    "diameter": 0.020,
    "length": 3.0,
    "position": "top",
    "grade": "S275",
}
WALL: dict[str, Any] = {
    "name": "wall with a rod",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 3.0},
    "mass": {"weight": 80.0},
    "restrainers": [ROD],
    "ntc": {"FC": 1.2},
}


def model_with(tmp_path: Path, **rod: Any) -> Path:
    data = copy.deepcopy(WALL)
    data["restrainers"][0].update(rod)
    data["restrainers"][0] = {k: v for k, v in data["restrainers"][0].items() if v is not None}
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


def test_a_graded_rod_carries_its_design_strength(tmp_path: Path) -> None:
    (rod,) = to_block(load_model(model_with(tmp_path))).restrainers
    fy, fu = GRADES["S275"]
    assert rod.strength == tension_resistance(rod_area(0.020), fy, fu).strength
    assert "S275" in rod.strength_rule and "N_pl,Rd" in rod.strength_rule


def test_measured_strengths_use_the_models_confidence_factor(tmp_path: Path) -> None:
    path = model_with(tmp_path, grade=None, fy=240e6, fu=380e6)
    (rod,) = to_block(load_model(path)).restrainers
    expected = tension_resistance(rod_area(0.020), 240e6, 380e6, factor=1.2).strength
    assert rod.strength == pytest.approx(expected, rel=1e-15)
    assert "FC = 1.2" in rod.strength_rule


def test_two_bars_double_the_stiffness_and_the_strength(tmp_path: Path) -> None:
    (one,) = to_block(load_model(model_with(tmp_path))).restrainers
    (two,) = to_block(load_model(model_with(tmp_path, count=2))).restrainers
    assert two.k_pos == pytest.approx(2 * one.k_pos, rel=1e-15)
    assert two.strength == pytest.approx(2 * one.strength, rel=1e-15)


def test_the_anchor_caps_a_rod_and_is_a_springs_strength(tmp_path: Path) -> None:
    (rod,) = to_block(load_model(model_with(tmp_path, anchor_capacity=40e3))).restrainers
    assert rod.strength == 40e3 and "anchor" in rod.strength_rule
    spring = {"name": "vault", "k": 4e6, "position": "top", "anchor_capacity": 25e3}
    data = {**copy.deepcopy(WALL), "restrainers": [spring]}
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    (vault,) = to_block(load_model(path)).restrainers
    assert vault.strength == 25e3


def test_a_rod_without_steel_has_no_strength(tmp_path: Path) -> None:
    (rod,) = to_block(load_model(model_with(tmp_path, grade=None))).restrainers
    assert math.isinf(rod.strength) and rod.strength_rule == ""


BAD = [
    ({"grade": "S460"}, "restrainers[0].grade", "S235"),
    # issue 9's bad inputs: the law's keys
    ({"pretension": 90e3}, "restrainers[0].pretension", "pretension <"),  # A·fy = 86.4 kN
    ({"pretension": -1.0}, "restrainers[0].pretension", "[N]"),
    ({"pretension": 30e3, "anchor_capacity": 25e3}, "restrainers[0].pretension", "anchor"),
    ({"yield_pos": 50e3}, "restrainers[0].yield_pos", "grade"),
    ({"grade": None, "law": "elastic-plastic"}, "restrainers[0].law", "grade"),
    ({"law": "plastic"}, "restrainers[0].law", "elastic"),
    ({"elongation_at_break": 0.2, "fails_at": 0.05}, "restrainers[0].fails_at", "one of"),
    ({"elongation_at_break": 0.0}, "restrainers[0].elongation_at_break", "[-]"),
    ({"elongation_at_break": 1.5}, "restrainers[0].elongation_at_break", "[-]"),
    ({"grade": None, "code_action": "force"}, "restrainers[0].code_action", "strength"),
    ({"code_action": "both"}, "restrainers[0].code_action", "force"),
    ({"k_pos": 1e6}, "restrainers[0].k_pos", "tie-rod"),
    ({"fy": 240e6}, "restrainers[0].fy", "grade"),
    ({"grade": None, "fy": 240e6}, "restrainers[0].fu", "fu >= fy"),
    ({"grade": None, "fy": 400e6, "fu": 300e6}, "restrainers[0].fu", "fu >= fy"),
    ({"grade": None, "fy": 5e6, "fu": 300e6}, "restrainers[0].fy", "[Pa]"),
    ({"anchor_capacity": 0.0}, "restrainers[0].anchor_capacity", "[N]"),
    ({"anchor_capacity": -5.0}, "restrainers[0].anchor_capacity", "[N]"),
    ({"count": 0}, "restrainers[0].count", ">= 1"),
]


@pytest.mark.parametrize(("rod", "where", "allowed"), BAD, ids=[w for _, w, _ in BAD])
def test_bad_steel_is_one_line(tmp_path: Path, rod: dict, where: str, allowed: str) -> None:
    with pytest.raises(InputError) as info:
        load_model(model_with(tmp_path, **rod))
    assert info.value.where == where
    assert info.value.allowed is not None and allowed in info.value.allowed


SPRING_BAD = [
    ({"yield_pos": 0.0, "yield_neg": 1e3}, "restrainers[0].yield_pos", "[N]"),
    ({"yield_pos": -5.0, "yield_neg": 1e3}, "restrainers[0].yield_pos", "[N]"),
    ({"yield_pos": 1e3}, "restrainers[0].yield_neg", "yield_neg"),
    ({"law": "elastic-plastic"}, "restrainers[0].yield_pos", "yield_pos"),
    ({"law": "elastic", "yield_pos": 1e3, "yield_neg": 1e3}, "restrainers[0].yield_pos", "law"),
    ({"yield_pos": 1e3, "yield_neg": 1e3, "pretension": 1e3}, "restrainers[0].pretension", "<"),
    ({"elongation_at_break": 0.2}, "restrainers[0].elongation_at_break", "tie-rod"),
]


@pytest.mark.parametrize(
    ("law", "where", "allowed"), SPRING_BAD, ids=[str(b[0]) for b in SPRING_BAD]
)
def test_bad_spring_law_is_one_line(tmp_path: Path, law: dict, where: str, allowed: str) -> None:
    spring = {"name": "vault", "k": 4e6, "position": "top", **law}
    data = {**copy.deepcopy(WALL), "restrainers": [spring]}
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_model(path)
    assert info.value.where == where
    assert info.value.allowed is not None and allowed in info.value.allowed


def test_pretension_above_the_measured_yield_over_fc_is_refused(tmp_path: Path) -> None:
    # fy = 240 MPa on Ø20: A·fy = 75.4 kN as given (the file's own check passes 70 kN), but
    # the member yields at A·fy/FC = 62.8 kN with FC = 1.2: refused where the block is derived.
    path = model_with(tmp_path, grade=None, fy=240e6, fu=380e6, pretension=70e3)
    with pytest.raises(InputError) as info:
        load_model(path)
    assert info.value.where == "restrainers[0].pretension" and "FC" in str(info.value)


def test_a_bad_law_key_exits_2_with_one_line(tmp_path: Path) -> None:
    path = model_with(tmp_path, pretension=90e3)
    result = CliRunner().invoke(cli, ["assess", str(path), "--record", str(PULSE)])
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "restrainers[0].pretension" in result.stderr


def test_steel_keys_belong_to_tie_rods(tmp_path: Path) -> None:
    spring = {"name": "vault", "k": 4e6, "position": "top", "grade": "S275"}
    data = {**copy.deepcopy(WALL), "restrainers": [spring]}
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    result = CliRunner().invoke(cli, ["assess", str(path), "--record", str(PULSE)])
    assert result.exit_code == 2 and result.stdout == ""
    assert "restrainers[0].grade" in result.stderr and result.stderr.count("\n") == 1


def test_the_facade_rod_yields_at_its_strength_and_says_so() -> None:
    """The façade's S275 Ø20 tie-rod is elastic-plastic: it yields at its design plastic
    resistance N_pl,Rd = π·0.01²·275e6/1.05 = 82.28 kN (by hand), its strength, so the Ricker
    pulse's force never exceeds it (1e-9: FORCE_RTOL, the rounding of the slack point); it
    yielded, its check passes, and the report says when and how much it stretched."""
    result = CliRunner().invoke(
        cli, ["assess", str(FACADE), "--record", str(PULSE), "--format", "json"]
    )
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    (check,) = doc["restrainer_checks"]
    rod = next(r for r in doc["model"]["restrainers"] if r["name"] == "tie-rod")
    n_pl = math.pi * 0.01**2 * 275e6 / 1.05
    assert check["strength"] == rod["strength"] == pytest.approx(n_pl, rel=1e-12)
    assert rod["law"] == "elastic-plastic" and rod["yield_pos"] == pytest.approx(n_pl, rel=1e-12)
    # the net section's N_u,Rd = 0.9·A·430e6/1.25 = 97.26 kN > N_pl,Rd: no brittle rupture
    assert rod["rupture_force"] == pytest.approx(0.9 * math.pi * 0.01**2 * 430e6 / 1.25)
    assert rod["anchor_capacity"] is None
    j = [r["name"] for r in doc["model"]["restrainers"]].index("tie-rod")
    assert check["demand"] == max(run["restrainers"][j]["max_force"] for run in doc["runs"])
    assert check["demand"] <= check["strength"] * (1 + 1e-9)
    assert check["utilisation"] == pytest.approx(1.0, rel=1e-9)
    assert check["passed"] is True and check["yielded"] is True and check["ruptured"] is False
    assert check["plastic_elongation"] > 0.05  # 106 mm over 3 m: 3.5 % strain
    assert check["time_history_valid"] is True and check["clause"] == "NTC 2018 §4.2.4.1.2"
    assert not doc["warnings"]
    text = CliRunner().invoke(cli, ["assess", str(FACADE), "--record", str(PULSE)]).stdout
    assert "note: restrainer 'tie-rod' yielded at its design strength 82.28 kN" in text
    verdict = text[text.rindex("verdict: ") :]  # the verdict wraps within 100 columns
    assert verdict.startswith("verdict: survives (max θ/α = ")


def test_a_rod_whose_net_section_is_weaker_breaks_there(tmp_path: Path) -> None:
    """Measured fy = 400 MPa, fu = 420 MPa: N_u,Rd = 0.9·A·fu/(1.25·FC) < N_pl,Rd =
    A·fy/(1.05·FC), so the bar breaks at N_u,Rd (brittle) instead of yielding: the model's
    rupture force is N_u,Rd, its strength too."""
    path = model_with(tmp_path, grade=None, fy=400e6, fu=420e6)
    (rod,) = to_block(load_model(path)).restrainers
    n_u = 0.9 * rod_area(0.020) * 420e6 / (1.25 * 1.2)
    assert rod.rupture_force == pytest.approx(n_u, rel=1e-12)
    assert rod.strength == pytest.approx(n_u, rel=1e-12) and "N_u,Rd" in rod.strength_rule
    assert rod.yield_pos > rod.rupture_force


def elastic_facade(tmp_path: Path) -> Path:
    """The façade with its tie-rod forced elastic (law = "elastic"): the first versions' spring."""
    import tomllib

    data = tomllib.loads(FACADE.read_text(encoding="utf-8"))
    for r in data["restrainers"]:
        if r.get("kind") == "tie-rod":
            r["law"] = "elastic"
    path = tmp_path / "elastic.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


def test_an_elastic_rod_beyond_its_strength_makes_the_run_not_valid(tmp_path: Path) -> None:
    """law = "elastic": the Ricker pulse drives 747 kN into the rod (9 times its strength); the
    time history is not valid beyond that, and both assess and compare say so."""
    path = elastic_facade(tmp_path)
    doc = json.loads(
        CliRunner()
        .invoke(cli, ["assess", str(path), "--record", str(PULSE), "--format", "json"])
        .stdout
    )
    (check,) = doc["restrainer_checks"]
    assert check["utilisation"] > 9 and check["time_history_valid"] is False
    assert any("it is elastic in this model" in w for w in doc["warnings"])
    for command in ("assess", "compare"):
        result = CliRunner().invoke(cli, [command, str(path), "--record", str(PULSE)])
        assert result.exit_code == 0, result.stderr
        # the verdict line wraps within 100 columns: read it whole
        last = " ".join(result.stdout[result.stdout.rindex("verdict: ") :].split())
        assert "not valid: 'tie-rod' beyond its strength" in last
