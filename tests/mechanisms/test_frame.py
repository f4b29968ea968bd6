"""The rocking frame (issue 38, item 5): equal piers capped by a rigid roof, a bell cell.

Closed forms (Makris & Vassiliou 2013, Earthquake Engng Struct. Dyn. 42:431–449), with
γ = m_roof/(N·m_pier) and a pier of semi-diagonal R and slenderness α:

- uplift at g·tan α, whatever the roof's mass;
- p̂ = p·√((1 + 2γ)/(1 + 3γ)), p = √(3g/(4R));
- e = [1 − (3/2)·sin²α + 3γ·cos 2α]/(1 + 3γ).

The issue's bell cell: four piers 0.6 × 0.6 × 3.0 m of ρ = 1.9 t/m³ (m_pier = 2052 kg), a roof
of 15 t: γ = 1.8275, uplift 0.2000 g, p̂ = 1.8584 rad/s (one pier 2.1931), e = 0.92604 (one
pier 0.94231). The code check by hand (Circolare 7/2019 Eqs. C8.7.1.4–5 over the blocks,
each pier's weight at h with δx = h, the roof's carried by the piers' top corners with
δx = 2h): M* = (Σ m δx)²/Σ m δx², e* = M*/Σ m.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.cli.main import cli
from rockcli.model.catalogue import catalogue
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
G = 9.81
DEMAND = {
    state: {"ag": ag, "F0": 2.5, "Tc_star": tc}
    for state, ag, tc in (("SLD", 0.06, 0.27), ("SLV", 0.15, 0.29), ("SLC", 0.19, 0.30))
}


def bell(roof: float = 15000.0, **frame: Any) -> dict[str, Any]:
    """The issue's bell cell on a tower (Z = 20 m of 23 m)."""
    return {
        "name": "bell cell",
        "kind": "frame",
        "frame": {
            "piers": 4,
            "pier_width": 0.6,
            "pier_depth": 0.6,
            "pier_height": 3.0,
            "roof_mass": roof,
            **frame,
        },  # fmt: skip
        "mass": {"unit_weight": 1.9 * G},  # kN/m³ of ρ = 1.9 t/m³
        "building": {"Z": 20.0, "H": 23.0, "N": 1},
        "ntc": {"edition": "2019", "q": 2.0, "soil": "B", "demand": DEMAND},
    }


def write(tmp_path: Path, model: dict[str, Any], name: str = "bell.toml") -> Path:
    path = tmp_path / name
    path.write_text(tomli_w.dumps(model), encoding="utf-8")
    return path


def closed_forms(roof: float, piers: int = 4) -> tuple[float, float, float]:
    """(uplift [g], p̂ [rad/s], e) of the bell cell's frame with a roof of ``roof`` kg."""
    b, h = 0.3, 1.5
    R, alpha = math.hypot(b, h), math.atan2(b, h)
    m_pier = 1900.0 * 0.6 * 0.6 * 3.0
    gamma = roof / (piers * m_pier)
    p = math.sqrt(3 * G / (4 * R)) * math.sqrt((1 + 2 * gamma) / (1 + 3 * gamma))
    e = (1 - 1.5 * math.sin(alpha) ** 2 + 3 * gamma * math.cos(2 * alpha)) / (1 + 3 * gamma)
    return math.tan(alpha), p, e


def test_the_issues_numbers_by_hand() -> None:
    uplift, p, e = closed_forms(15000.0)
    assert (uplift, p, e) == pytest.approx((0.2, 1.8584, 0.92604), abs=5e-5)
    _, p1, e1 = closed_forms(0.0)
    assert (p1, e1) == pytest.approx((2.1931, 0.94231), abs=5e-5)


def test_assess_gives_the_frames_uplift_p_and_e(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["assess", str(write(tmp_path, bell())), "--record",
                                      str(PULSE), "--format", "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    model = json.loads(result.stdout)["model"]
    uplift, p, e = closed_forms(15000.0)
    assert model["kind"] == "frame"
    assert model["uplift_acceleration_g"] == pytest.approx(uplift, rel=1e-12)
    assert model["p"] == pytest.approx(p, rel=1e-9)
    assert model["e"] == pytest.approx(e, rel=1e-12)


@settings(max_examples=25, deadline=None)
@given(roof=st.floats(min_value=0.0, max_value=1e6), piers=st.integers(2, 12))
def test_the_uplift_is_the_piers_whatever_the_roof(tmp_path_factory, roof: float,
                                                   piers: int) -> None:  # fmt: skip
    folder = tmp_path_factory.mktemp("frame")
    (mech,) = catalogue(load_model(write(folder, bell(roof, piers=piers))))
    uplift, p, e = closed_forms(roof, piers)
    for side in (0, 1):
        assert mech.openings[side].uplift == pytest.approx(uplift, rel=1e-12)
        assert mech.openings[side].alpha0 == pytest.approx(uplift, rel=1e-12)
    assert mech.rocker.p == pytest.approx(p, rel=1e-9)
    assert mech.rocker.e == pytest.approx(e, rel=1e-12)


def test_the_code_check_sums_the_piers_and_the_roof(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, bell())), "--format",
                                      "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    piers, roof, h = 4 * 2052.0, 15000.0, 1.5
    first = piers * h + roof * 2 * h
    second = piers * h**2 + roof * (2 * h) ** 2
    M_star = first**2 / second
    assert doc["alpha0"] == pytest.approx(0.2, rel=1e-12)
    assert doc["mechanisms"][0]["M_star"] == pytest.approx(M_star, rel=1e-9)
    assert doc["e_star"] == pytest.approx(M_star / (piers + roof), rel=1e-9)


def test_the_roof_rocks_on_the_floor_motion_of_the_tower(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["assess", str(write(tmp_path, bell())), "--record",
                                      str(PULSE)])  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "input: floor motion at Z = 20 m" in " ".join(result.output.split())


BAD = [
    ({"piers": 1}, "frame.piers"),
    ({"roof_mass": 2e6}, "frame.roof_mass"),
    ({"pier_width": 0.0}, "frame.pier_width"),
    ({"roof_mass": -1.0}, "frame.roof_mass"),
]


@pytest.mark.parametrize(("change", "key"), BAD)
def test_a_bad_frame_is_one_line_naming_the_key(
    tmp_path: Path, change: dict[str, Any], key: str
) -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, bell(**change)))])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and key in lines[0], result.stderr


@pytest.mark.parametrize(
    ("change", "key"),
    [
        ({"frame": None}, "frame"),
        ({"geometry": {"thickness": 0.6, "height": 3.0}}, "geometry"),
        ({"kind": "wall"}, "frame"),
        ({"mechanisms": [{"type": "gable"}]}, "mechanisms"),
        ({"mass": {"weight": 10.0}}, "mass.unit_weight"),
        ({"loads": [{"weight": 5.0, "position": "top"}]}, "loads"),
    ],
)
def test_what_a_frame_does_not_take_is_refused(
    tmp_path: Path, change: dict[str, Any], key: str
) -> None:
    model = {k: v for k, v in {**bell(), **change}.items() if v is not None}
    path = write(tmp_path, model)
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].split(f"{path}: ", 1)[1].startswith(key + ":"), lines[0]
