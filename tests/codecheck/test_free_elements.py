"""Elements free to vibrate (Circolare 7/2019 §C8.7.1.2.1.3 and §C8.7.1.2.1.5).

The elastic branch a = 4π²d/T0² (Eq. C8.7.1.6) to its meeting (a_y, d_y) with the rigid curve,
T0 = κ·λ·L·√(W/(E·g)) (Eq. C8.7.1.7; κ = 6.2 cantilever, 2.2 vertical flexure), and the SLD
check at T0 with ξ = 5 % (Eq. C8.7.1.9). Every expected number is worked out here from the
clauses (NTC 2018 Eq. 3.2.2 for the ground spectrum), not read back from rock.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.demand import SOIL_A_FLAT

ROOT = Path(__file__).resolve().parents[2]
FACADE = ROOT / "examples" / "two-storey-facade.toml"
G = 9.81
#: Tolerance of the hand values that neglect the top restraint's 1 mN.
REL = 1e-7
#: A one-storey wall on the ground, 4 m × 0.5 m, 1 m wide, 18 kN/m³, E = 1 GPa; soil A.
WALL = (
    """
name = "free wall"
kind = "wall"
[geometry]
width = 1.0
[[geometry.storeys]]
height = 4.0
thickness = 0.5
[mass]
unit_weight = 18.0
[masonry]
{masonry}
[[loads]]
name = "top restraint"
weight = 1e-6
height = 4.0
moves = false
[[mechanisms]]
type = "{type}"
free = true
{extra}
[ntc]
edition = "2019"
FC = 1.35
soil = "A"
"""
    + SOIL_A_FLAT
)


def kinematic(path: Path, *args: str) -> dict:
    result = CliRunner().invoke(cli, ["kinematic", str(path), *args, "--format", "json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def wall(tmp_path: Path, kind: str = "overturning", masonry: str = "E = 1.0e9", extra="") -> Path:
    path = tmp_path / "wall.toml"
    path.write_text(WALL.format(type=kind, masonry=masonry, extra=extra))
    return path


def sld_of(doc: dict) -> dict:
    return next(c for c in doc["checks"] if c["limit_state"] == "SLD")


def test_overturning_free_on_the_ground(tmp_path: Path) -> None:
    """A cantilever of L = 4 m on t = 0.5 m: T0 = 6.2·8·4·√(18000/(1e9·9.81)) = 0.26876 s.
    α0 = b/h = 0.125 (the top restraint weighs nothing and does not move), e* = 1, a0* =
    0.125·9.81/1.35, straight to d0* = b = 0.25 m: d_y = a0*/(4π²/T0² + a0*/d0*), a_y =
    4π²d_y/T0². On the ground ag,SLD makes Se(T0, 5 %) = a_y: soil A (S = 1), T_B = 0.1,
    T_C = 0.3 s, T0 on the plateau: Se = ag·2.5, so ag = a_y/(2.5·g). (The top restraint's
    1 mN bearing on the wall moves α0 by 3e-8: REL.)"""
    doc = kinematic(wall(tmp_path))
    T0 = 6.2 * 8.0 * 4.0 * math.sqrt(18e3 / (1e9 * G))
    a0 = 0.125 * G / 1.35
    d_y = a0 / (4 * math.pi**2 / T0**2 + a0 / 0.25)
    a_y = 4 * math.pi**2 * d_y / T0**2
    assert doc["T0"] == pytest.approx(T0, rel=1e-12)
    assert doc["d_y"] == pytest.approx(d_y, rel=REL)
    assert doc["a_y"] == pytest.approx(a_y, rel=REL)
    sld = sld_of(doc)
    assert sld["demand_period"] == pytest.approx(T0, rel=1e-12)
    assert sld["demand_damping"] == 5.0
    assert sld["capacity"] == pytest.approx(a_y / (2.5 * G), rel=REL)
    # The curve starts with the elastic branch: (0, 0), then its end on the rigid line.
    first, second = doc["curve"][0], doc["curve"][1]
    assert (first["d_star"], first["a_star"]) == (0.0, 0.0)
    assert second["d_star"] == pytest.approx(d_y, rel=REL)
    assert second["a_star"] == pytest.approx(a_y, rel=REL)


def test_vertical_flexure_free_takes_kappa_2_2(tmp_path: Path) -> None:
    """A beam simply supported at its ends (Eq. C8.7.1.7, κ = 2.2), L = 4 m, t = 0.5 m."""
    path = wall(tmp_path, "vertical-flexure", extra="storey = 1\nhinge_height = 2.0")
    doc = kinematic(path)
    assert doc["T0"] == pytest.approx(2.2 * 8.0 * 4.0 * math.sqrt(18e3 / (1e9 * G)), rel=1e-12)


def test_a_masonry_type_gives_its_mean_modulus_cracked(tmp_path: Path) -> None:
    """Tab. C8.5.I, solid brick and lime mortar: E 1200–1800 MPa, mean 1500 (§C8.5.4.1),
    halved for cracking (NTC 2018 §7.2.6): 750 MPa."""
    doc = kinematic(wall(tmp_path, masonry='type = "solid-brick"'))
    assert doc["T0"] == pytest.approx(6.2 * 8.0 * 4.0 * math.sqrt(18e3 / (7.5e8 * G)), rel=1e-12)


def test_the_facade_s_gable_is_free_by_default() -> None:
    """The gable of the example: a cantilever of h_g = 2.5 m on t = 0.45 m, rough-cut stone
    (1020–1440 MPa, mean 1230, cracked 615 MPa), 20 kN/m³; SLD read at T0."""
    doc = kinematic(FACADE, "--mechanism", "gable")
    T0 = 6.2 * (2.5 / 0.45) * 2.5 * math.sqrt(20e3 / (615e6 * G))
    assert doc["T0"] == pytest.approx(T0, rel=1e-12)
    assert sld_of(doc)["demand_period"] == pytest.approx(T0, rel=1e-12)
    assert any("free to vibrate" in n for n in doc["notes"])


def test_a_rigid_mechanism_keeps_its_sld_at_rest() -> None:
    doc = kinematic(FACADE, "--mechanism", "overturning, whole wall")
    assert "T0" not in doc
    assert sld_of(doc)["demand_period"] is None


def run(path: Path) -> tuple[int, str]:
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    return result.exit_code, result.stderr


def test_a_free_element_without_modulus_is_one_line(tmp_path: Path) -> None:
    code, err = run(wall(tmp_path, masonry="f_m = 2.0e6"))
    assert code == 2 and err.count("\n") == 1
    assert "[masonry] E" in err and "[masonry] type" in err


def test_an_unknown_masonry_type_lists_the_types(tmp_path: Path) -> None:
    code, err = run(wall(tmp_path, masonry='type = "tuff"'))
    assert code == 2 and err.count("\n") == 1
    assert "masonry.type" in err and "soft-stone-irregular" in err and "rubble" in err


def test_a_free_wedge_is_refused(tmp_path: Path) -> None:
    text = WALL.format(type="wedge", masonry="E = 1.0e9", extra="angle = 30.0")
    path = tmp_path / "wedge.toml"
    path.write_text(text + "\n[return_walls]\nthickness = 0.4\n")
    code, err = run(path)
    assert code == 2 and err.count("\n") == 1
    assert "free" in err and "wedge" in err and "return walls" in err
