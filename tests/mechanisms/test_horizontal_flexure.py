"""Horizontal flexure (issue 38, item 2): a strip between the return walls as a three-hinge
flat arch in plan.

By hand, for a strip of height b and thickness s between abutments L apart, with stress
blocks of depth a = H/(f_m·b) at its hinges: α·γ·s·b·L²/8 = H·(s − a) (the simply supported
moment of the strip's inertia α·γ·s·b per metre of span against the arch's thrust H on the
lever s − a). With rigid abutments the largest moment is at H* = f_m·b·s/2, a = s/2:
α_max = 2·f_m·s/(γ·L²) (s 0.5, b 1, L 5, γ 18 kN/m³, f_m 1 MPa: 2.2222); with a tie of
strength T holding the abutments, α0 = 8·T·(s − T/(f_m·b))/(γ·s·b·L²) (T = 73.83 kN, L 6,
f_m 1.5 MPa: 0.82176). Along the rotation θ of each half about its abutment hinge, the lever
becomes (s − a)·cos θ − (L/2)·sin θ and the half's centroid, (s − a)/2 from the abutment
hinge's line and L/4 along the span, moves out by (s − a)/2·sin θ + (L/4)·cos θ per unit
rotation. The expected numbers are these formulas, not the code's output.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.kinematic import Mechanism as SideCheck
from rockcli.codecheck.kinematic import load_multiplier
from rockcli.model.catalogue import catalogue, named
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
DEMAND = {
    state: {"ag": ag, "F0": 2.5, "Tc_star": tc}
    for state, ag, tc in (("SLD", 0.06, 0.27), ("SLV", 0.15, 0.29), ("SLC", 0.19, 0.30))
}
STRIP = "horizontal flexure at 3 m"


def wall(width: float, f_m: float, **strip: Any) -> dict[str, Any]:
    """A one-storey wall 4 m × 0.5 m, γ 18, with a strip 1 m high at 3 m and its overturning."""
    return {
        "name": "long top storey",
        "kind": "wall",
        "geometry": {"width": width, "storeys": [{"height": 4.0, "thickness": 0.5}]},
        "mass": {"unit_weight": 18.0},
        "masonry": {"f_m": f_m},
        "mechanisms": [
            {"type": "horizontal-flexure", "level": 3.0, "strip_height": 1.0, **strip},
            {"type": "overturning"},
        ],
        "ntc": {"edition": "2019", "q": 2.0, "soil": "B", "demand": DEMAND},
    }


def write(tmp_path: Path, model: dict[str, Any]) -> Path:
    path = tmp_path / "wall.toml"
    path.write_text(tomli_w.dumps(model), encoding="utf-8")
    return path


def entry(path: Path) -> dict[str, Any]:
    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 0, result.output
    return {m["name"]: m for m in json.loads(result.stdout)["mechanisms"]}[STRIP]


def test_rigid_abutments_give_the_largest_thrust(tmp_path: Path) -> None:
    found = entry(write(tmp_path, wall(5.0, 1.0e6)))
    s, b, L, gamma, f_m = 0.5, 1.0, 5.0, 18e3, 1e6
    assert found["alpha0"] == pytest.approx(2 * f_m * s / (gamma * L**2), rel=1e-12)
    assert found["alpha0"] == pytest.approx(2.2222, abs=5e-5)
    assert found["thrust_kN"] == pytest.approx(f_m * b * s / 2 / 1e3, rel=1e-12)  # 250 kN
    assert found["stress_block_depth"] == pytest.approx(s / 2, rel=1e-12)
    # the strip's mass, both halves: M* = γ·s·b·L/g, e* = 1 (2019, each half a block)
    assert found["M_star"] == pytest.approx(gamma * s * b * L / 9.81, rel=1e-12)
    assert found["e_star"] == pytest.approx(1.0, rel=1e-12)


def test_a_thrust_limit_below_the_masonrys(tmp_path: Path) -> None:
    found = entry(write(tmp_path, wall(6.0, 1.5e6, thrust_limit=73.83)))
    T, s, b, L, gamma, f_m = 73.83e3, 0.5, 1.0, 6.0, 18e3, 1.5e6
    expected = 8 * T * (s - T / (f_m * b)) / (gamma * s * b * L**2)
    assert found["alpha0"] == pytest.approx(expected, rel=1e-12)
    assert found["alpha0"] == pytest.approx(0.82176, abs=5e-6)
    assert found["thrust_kN"] == pytest.approx(73.83, rel=1e-12)
    assert found["stress_block_depth"] == pytest.approx(T / (f_m * b), rel=1e-12)


def test_a_tie_limits_it_with_its_design_strength(tmp_path: Path) -> None:
    model = wall(6.0, 1.5e6, tie="eaves tie")
    model["restrainers"] = [{"name": "eaves tie", "kind": "tie-rod", "grade": "S235",
                             "diameter": 0.020, "length": 6.0, "height": 3.5,
                             "from_pivot": 0.25}]  # fmt: skip
    found = entry(write(tmp_path, model))
    # NTC 2018 §4.2.4.1.2: min(A·fy/γM0, 0.9·A·fu/γM2), S235: fy 235, fu 360 MPa
    area = math.pi * 0.020**2 / 4
    T = min(area * 235e6 / 1.05, 0.9 * area * 360e6 / 1.25)
    assert found["thrust_kN"] == pytest.approx(T / 1e3, rel=1e-9)
    s, b, L, gamma, f_m = 0.5, 1.0, 6.0, 18e3, 1.5e6
    expected = 8 * T * (s - T / (f_m * b)) / (gamma * s * b * L**2)
    assert found["alpha0"] == pytest.approx(expected, rel=1e-9)


def test_a_tie_stronger_than_the_masonry_changes_nothing(tmp_path: Path) -> None:
    rigid = entry(write(tmp_path, wall(5.0, 1.0e6)))
    strong = entry(write(tmp_path, wall(5.0, 1.0e6, thrust_limit=1000.0)))
    assert strong["alpha0"] == rigid["alpha0"]
    assert strong["thrust_kN"] == rigid["thrust_kN"]


@pytest.mark.parametrize("theta", [0.0, 0.02, 0.05, 0.1, 0.14])
def test_the_capacity_curve_as_the_lever_arm_closes(tmp_path: Path, theta: float) -> None:
    mech = named(catalogue(load_model(write(tmp_path, wall(6.0, 1.5e6, thrust_limit=73.83)))),
                 STRIP)  # fmt: skip
    T, s, b, L, gamma, f_m = 73.83e3, 0.5, 1.0, 6.0, 18e3, 1.5e6
    a = T / (f_m * b)
    half = gamma * s * b * L / 2
    lever = (s - a) * math.cos(theta) - (L / 2) * math.sin(theta)
    arm = (s - a) / 2 * math.sin(theta) + (L / 4) * math.cos(theta)
    for side in (1, -1):  # the strip bulging out or in: the same numbers
        got = load_multiplier(SideCheck(mech.view(side)), theta)
        assert got == pytest.approx(T * lever / (half * arm), rel=1e-12, abs=1e-15)


def test_the_time_history_does_not_apply_and_says_so(tmp_path: Path) -> None:
    path = write(tmp_path, wall(5.0, 1.0e6))
    result = CliRunner().invoke(cli, ["assess", str(path), "--record", str(PULSE),
                                      "--mechanism", STRIP])  # fmt: skip
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "the time history does not apply: its strip" in lines[0]
    # compare keeps it in the catalogue, not rocked, and rocks the overturning
    result = CliRunner().invoke(cli, ["compare", str(path), "--record", str(PULSE),
                                      "--format", "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    rows = {m["name"]: m for m in doc["mechanisms"]}
    assert rows[STRIP]["rocking"] is None and "does not apply" in rows[STRIP]["not_rocked"]
    assert doc["rocking"]["mechanism"]["name"] == "overturning, whole wall"


BAD = [
    ({"masonry": None}, "mechanisms[0].type"),
    ({"level": 3.5}, "mechanisms[0].level"),
    ({"level": None}, "mechanisms[0].level"),
    ({"tie": "nothing"}, "mechanisms[0].tie"),
    ({"tie": "x", "thrust_limit": 50.0}, "mechanisms[0].tie"),
    ({"thrust_limit": 0.0}, "mechanisms[0].thrust_limit"),
    ({"span": -1.0}, "mechanisms[0].span"),
]


@pytest.mark.parametrize(("change", "key"), BAD)
def test_bad_input_is_one_line_naming_the_key(
    tmp_path: Path, change: dict[str, Any], key: str
) -> None:
    model = wall(5.0, 1.0e6)
    if "masonry" in change:
        del model["masonry"]
    else:
        strip = {**model["mechanisms"][0], **change}
        model["mechanisms"][0] = {k: v for k, v in strip.items() if v is not None}
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert key in lines[0] or key.replace("[0]", ".0") in lines[0], lines[0]


def test_where_it_governs_the_time_history_rocks_the_next_mechanism(tmp_path: Path) -> None:
    from dataclasses import replace

    from rockcli.analyses.catalogue import main_mechanism
    from rockcli.analyses.kinematic import kinematic_model

    kin = kinematic_model(load_model(write(tmp_path, wall(5.0, 1.0e6, thrust_limit=2.0))))
    strip_first = sorted(kin.catalogue, key=lambda m: m.name != STRIP)
    kin = replace(kin, catalogue=tuple(strip_first), governing=STRIP)
    main = main_mechanism(kin)
    assert main is not None and main.name == "overturning, whole wall"


def test_a_tie_without_a_strength_is_refused(tmp_path: Path) -> None:
    # a spring of stiffness alone has no strength: the thrust would be unlimited, silently
    model = wall(5.0, 1.0e6, tie="spring")
    model["restrainers"] = [{"name": "spring", "k": 1e7, "position": "top"}]
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "mechanisms[0].tie" in lines[0], result.stderr
    assert "without a strength" in lines[0]


def test_a_wall_of_horizontal_flexures_only_says_nothing_rocks(tmp_path: Path) -> None:
    model = wall(5.0, 1.0e6)
    model["mechanisms"] = model["mechanisms"][:1]
    path = write(tmp_path, model)
    for command in (["assess", str(path), "--record", str(PULSE)],
                    ["compare", str(path), "--record", str(PULSE)]):  # fmt: skip
        result = CliRunner().invoke(cli, command)
        assert result.exit_code == 2 and result.stdout == "", result.output
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1 and "no mechanism of the model rocks" in lines[0], lines
        assert "--mechanism" not in lines[0]
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 0, result.output
