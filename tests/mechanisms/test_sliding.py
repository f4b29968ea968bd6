"""Sliding before rocking (issue 38, item 4): ``[base] mu``.

A rigid body on a joint of friction μ slides when the horizontal force exceeds μ times the
normal force, and lifts when the load multiplier reaches its α0 (Shenton 1996, J. Eng. Mech.
122(7):690–693: a block slides first where μ < tan α). By hand, for the issue's chimney
0.5 × 1.5 m: tan α = 0.5/1.5 = 1/3; with μ = 0.30 it slides first (0.30 < 0.3333), with
μ = 0.35 it lifts first. With a thrust F pushing towards the side checked, α_s = (μ·W − F)/W.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.analyses.sliding import alpha0_of, slides_first, sliding_multiplier
from rockcli.cli.main import cli
from rockcli.model.catalogue import catalogue
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
DEMAND = {
    state: {"ag": ag, "F0": 2.5, "Tc_star": tc}
    for state, ag, tc in (("SLD", 0.06, 0.27), ("SLV", 0.15, 0.29), ("SLC", 0.19, 0.30))
}
CHIMNEY: dict[str, Any] = {
    "name": "chimney",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 1.5, "width": 0.5},
    "mass": {"unit_weight": 18.0},
    "base": {"mu": 0.30},
    "ntc": {"edition": "2019", "q": 2.0, "soil": "B", "demand": DEMAND},
}


def write(tmp_path: Path, model: dict[str, Any], name: str = "model.toml") -> Path:
    path = tmp_path / name
    path.write_text(tomli_w.dumps(model), encoding="utf-8")
    return path


def flat(text: str) -> str:
    return " ".join(text.split())


@pytest.mark.parametrize("command", ["assess", "compare"])
def test_the_chimney_slides_first_and_the_output_says_so(tmp_path: Path, command: str) -> None:
    path = write(tmp_path, CHIMNEY)
    result = CliRunner().invoke(cli, [command, str(path), "--record", str(PULSE)])
    assert result.exit_code == 0, result.output
    text = flat(result.output)
    assert "warning: 'overturning, whole wall' slides first" in text
    assert "μ = 0.3 holds it only up to 0.3 g, below the 0.3333 g that lifts it" in text
    assert "the rocking verdict does not apply" in text


def test_the_catalogue_notes_it(tmp_path: Path) -> None:
    path = write(tmp_path, CHIMNEY)
    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 0, result.output
    notes = json.loads(result.stdout)["notes"]
    assert any("slides first" in n for n in notes)


def test_a_rougher_base_lifts_first(tmp_path: Path) -> None:
    model = {**CHIMNEY, "base": {"mu": 0.35}}
    path = write(tmp_path, model)
    result = CliRunner().invoke(cli, ["assess", str(path), "--record", str(PULSE)])
    assert result.exit_code == 0 and "slides" not in result.output


def test_without_a_base_nothing_is_checked(tmp_path: Path) -> None:
    model = {k: v for k, v in CHIMNEY.items() if k != "base"}
    result = CliRunner().invoke(cli, ["assess", str(write(tmp_path, model)), "--record",
                                      str(PULSE)])  # fmt: skip
    assert result.exit_code == 0 and "slides" not in result.output


def test_a_thrust_towards_a_side_lowers_its_sliding_multiplier(tmp_path: Path) -> None:
    # wall 0.5 × 3.0 × 1.0 m, γ 18: W = 27 kN; a 2 kN thrust outward (θ > 0) at the top:
    # α_s(+) = (0.5·27 − 2)/27, α_s(−) = (0.5·27 + 2)/27
    model = {**CHIMNEY, "geometry": {"thickness": 0.5, "height": 3.0, "width": 1.0},
             "base": {"mu": 0.5},
             "thrusts": [{"force": 2.0, "position": "top", "direction": "positive"}]}  # fmt: skip
    mech = catalogue(load_model(write(tmp_path, model)))[0]
    assert sliding_multiplier(mech.view(1), 0.5) == pytest.approx((13.5 - 2) / 27, rel=1e-12)
    assert sliding_multiplier(mech.view(-1), 0.5) == pytest.approx((13.5 + 2) / 27, rel=1e-12)
    # μ = 0.5 above tan α = 1/6 (less the thrust's help): it lifts first on both sides
    assert slides_first(mech, 0.5, alpha0_of(mech)) is None
    # μ = 0.1: towards θ > 0 the thrust helps both, and it lifts first (α0 = (6.75 − 6)/40.5
    # = 0.0185 below α_s = 0.7/27 = 0.0259); towards θ < 0 the thrust holds it back from
    # lifting more than from sliding: α_s = 4.7/27 = 0.174 below α0 = 12.75/40.5 = 0.315
    side, slide, lift = slides_first(mech, 0.1, alpha0_of(mech))  # type: ignore[misc]
    assert side == -1 and slide == pytest.approx(4.7 / 27, rel=1e-12)
    assert lift == pytest.approx(12.75 / 40.5, rel=1e-12)


def test_a_storey_above_the_base_is_not_checked(tmp_path: Path) -> None:
    model = {
        **CHIMNEY,
        "geometry": {
            "width": 1.0,
            "storeys": [{"height": 3.0, "thickness": 0.6}, {"height": 3.0, "thickness": 0.4}],
        },  # fmt: skip
        "base": {"mu": 0.05},
        "mechanisms": [{"type": "overturning", "hinge_height": "each-floor"}],
    }
    whole, storey = catalogue(load_model(write(tmp_path, model)))
    assert slides_first(whole, 0.05, alpha0_of(whole)) is not None
    assert slides_first(storey, 0.05, alpha0_of(storey)) is None


@pytest.mark.parametrize("mu", [0.0, -0.1, 1.6, "0.3", True])
def test_a_bad_mu_is_one_line_naming_it(tmp_path: Path, mu: Any) -> None:
    path = write(tmp_path, {**CHIMNEY, "base": {"mu": mu}})
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "base.mu" in lines[0], result.stderr


def test_a_base_without_mu_is_refused(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, {**CHIMNEY, "base": {}}))])
    assert result.exit_code == 2 and "base.mu" in result.stderr


def test_a_sweep_has_a_slides_column(tmp_path: Path) -> None:
    write(tmp_path, CHIMNEY, "chimney.toml")
    (tmp_path / "pulse.txt").write_bytes(PULSE.read_bytes())
    study = {
        "name": "chimney sliding",
        "base": "chimney.toml",
        "analyses": ["rocking"],
        "records": [{"path": "pulse.txt"}],
        "axes": [{"path": "base.mu", "name": "mu", "values": [0.2, 0.3, 0.4]}],
    }
    path = write(tmp_path, study, "study.toml")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["sweep", str(path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    with open(out / "cases.csv", encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [(r["mu"], r["slides"]) for r in rows] == [
        ("0.2", "true"),
        ("0.3", "true"),
        ("0.4", "false"),
    ]
