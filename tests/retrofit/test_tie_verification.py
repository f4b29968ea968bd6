"""A tie-rod check that can fail (issue #19, item 3): a yielding rod is verified for its
ductility (largest elongation against ε_u·L/γ_ε) and its anchorage by capacity design (the
anchor against γ_ov·A·f_y, NTC 2018 §7.5.1); a member known only by fails_at is verified on
displacement without a steel clause; `rock retrofit` keeps only diameters that pass all three.

Expected values are written out from the formulas: A = π·d²/4, f_yk of S275 = 275 MPa
(NTC 2018 Tab. 11.3.IX), γ_ov = 1.25 (§7.5.1), A_min of S275 = 23 % (EN 10025-2 Tab. 7),
γ_ε = 2 (docs/interpretations.md).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.retrofit.choose import failures
from tests.cli.conftest import ROOT

FACADE = ROOT / "examples" / "facade.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: γ_ov·A·f_yk of one Ø20 S275 bar [N]: 1.25·π·0.020²/4·275e6.
OVERSTRENGTH_D20 = 1.25 * math.pi * 0.020**2 / 4 * 275e6
#: Same numbers written two ways in double precision.
REL = 1e-12


def facade_with(tmp_path: Path, extra: str) -> Path:
    """The façade example with lines added to its tie-rod table (the file's last table)."""
    path = tmp_path / "facade.toml"
    path.write_text(FACADE.read_text(encoding="utf-8") + extra, encoding="utf-8")
    return path


def assess_json(model: Path) -> dict:
    result = CliRunner().invoke(cli, ["assess", str(model), "--record", str(RICKER),
                                      "--format", "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def rod_check(doc: dict, name: str = "tie-rod") -> dict:
    return next(c for c in doc["restrainer_checks"] if c["name"] == name)


def test_the_facade_rod_reports_its_elongation_against_what_it_can_take() -> None:
    # The Ø20 S275 rod, 3.00 m, yields under the Ricker pulse (about 110 mm of elongation): its
    # force check reads 1.000 whatever it stretches; the ductility check has the capacity
    # 0.23·3.00/2 = 0.345 m and the largest elongation, the anchor its over-strength.
    c = rod_check(assess_json(FACADE))
    assert c["yielded"]
    assert c["ductility"]["capacity"] == pytest.approx(0.23 * 3.00 / 2, rel=REL)
    assert 0.09 < c["ductility"]["demand"] < c["ductility"]["capacity"]
    assert c["ductility"]["passed"] is True
    assert c["anchor"]["demand"] == pytest.approx(OVERSTRENGTH_D20, rel=REL)
    assert c["anchor"]["capacity"] is None and c["anchor"]["passed"] is None
    assert c["passed"] is True


def test_a_rod_stretched_past_its_design_elongation_fails(tmp_path: Path) -> None:
    # elongation_at_break 6 %: capacity 0.06·3/2 = 90 mm < the ~110 mm the rod reaches, and
    # the bar breaks only at 0.06·3 = 180 mm: not broken, yet not satisfied.
    doc = assess_json(facade_with(tmp_path, "elongation_at_break = 0.06\n"))
    c = rod_check(doc)
    assert c["ductility"]["capacity"] == pytest.approx(0.09, rel=REL)
    assert c["ductility"]["demand"] > 0.09
    assert not c["ruptured"]
    assert c["ductility"]["passed"] is False and c["passed"] is False
    assert any("exceeds what it can take" in w for w in doc["warnings"])


def test_a_rod_stretched_past_its_elongation_at_break_breaks(tmp_path: Path) -> None:
    # elongation_at_break 2 %: it breaks at 0.02·3 = 60 mm in the time history.
    c = rod_check(assess_json(facade_with(tmp_path, "elongation_at_break = 0.02\n")))
    assert c["ruptured"]
    assert c["passed"] is False and c["ductility"]["passed"] is False


@pytest.mark.parametrize(("anchor", "passed"), [(100e3, False), (120e3, True)])
def test_the_anchor_must_exceed_the_bars_overstrength(
    tmp_path: Path, anchor: float, passed: bool
) -> None:
    # Capacity design: 100 kN < γ_ov·A·f_y = 108 kN fails ("the anchor governs"); 120 kN
    # passes. The anchor is above the rod's yield force (82.3 kN) in both: the time history
    # is the same, only the verification differs.
    doc = assess_json(facade_with(tmp_path, f"anchor_capacity = {anchor:g}\n"))
    c = rod_check(doc)
    assert c["anchor"] == {
        "demand": pytest.approx(OVERSTRENGTH_D20, rel=REL),
        "capacity": anchor,
        "passed": passed,
        "rule": c["anchor"]["rule"],
    }
    assert c["passed"] is passed
    assert any("the anchor governs" in w for w in doc["warnings"]) is not passed


def test_a_vault_known_by_fails_at_is_verified_on_displacement() -> None:
    doc = assess_json(FACADE)
    vault = rod_check(doc, "groin vault")
    assert vault["strength"] is None and vault["clause"] is None
    assert vault["ductility"]["capacity"] == pytest.approx(0.001, rel=REL)
    assert "§4.2.4.1.2" not in vault["rule"]
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--record", str(RICKER),
                                      "--format", "json"])  # fmt: skip
    actions = {a["name"]: a for a in json.loads(result.stdout)["restrainer_actions"]}
    assert "§4.2.4.1.2" not in actions["groin vault"]["clause"]
    assert actions["tie-rod"]["clause"] == "NTC 2018 §4.2.4.1.2"


def test_retrofit_leaves_out_a_diameter_whose_anchor_governs(tmp_path: Path) -> None:
    # anchor 100 kN: Ø20's over-strength 108 kN exceeds it, Ø16's 1.25·π·0.016²/4·275e6 =
    # 69.1 kN does not; both keep the block standing under the pulse (the façade's table).
    model = facade_with(tmp_path, "anchor_capacity = 100e3\n")
    result = CliRunner().invoke(cli, ["retrofit", str(model), "--record", str(RICKER),
                                      "--diameters", "20,24", "--format", "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["chosen"] is None
    assert "the anchor governs" in doc["reason"]
    result = CliRunner().invoke(cli, ["retrofit", str(model), "--record", str(RICKER),
                                      "--diameters", "16,20", "--format", "json"])  # fmt: skip
    doc = json.loads(result.stdout)
    assert doc["chosen"]["diameter_mm"] == 16
    why = failures(doc["candidates"][1])
    assert any("anchor governs" in w for w in why)


def test_retrofit_failures_name_the_ductility() -> None:
    row = {
        "code_uls_passed": True, "code_zeta": 2.0, "overturned": False, "rocking": "survives",
        "ruptured": False, "utilisation": 1.0,
        "ductility": {"demand": 0.12, "capacity": 0.10, "passed": False, "rule": ""},
        "anchor": None,
    }  # fmt: skip
    assert failures(row) == ["the rod stretches 120 mm, more than the 100 mm it can take"]
