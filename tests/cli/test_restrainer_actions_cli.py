"""`rock kinematic` and `rock compare` report how each restrainer entered the check
(`restrainer_actions`, the table "Restrainers in the check"); code_action "force" without a
strength is one error line (issue 9, item 3).

Sources: NTC 2018 §4.2.4.1.2, N_pl,Rd = A f_yk / γ_M0 with γ_M0 = 1.05 (S275: f_yk 275 MPa,
f_tk 430 MPa, Tab. 11.3.IX; 0.9 A f_tk / 1.25 is larger, so N_pl,Rd governs); α0 with a tie
force T at height h_T: (W b + T h_T)/(W h_G), Circolare 617/2009 §C8A.4.1. Tolerance 1e-12
relative: the same sums in another order.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import PULSES
from tests.demand import SOIL_A_FLAT

ACTION_KEYS = {
    "name",
    "code_action",
    "force",
    "strength",
    "demand",
    "demand_at",
    "utilisation",
    "lost",
    "passed",
    "clause",
    "lost_at_d_star",
    "slack",
}
#: The wall: 0.6 m × 8 m, 300 kN (b = 0.3 m, h_G = 4 m); a tie-rod at h_T = 7.5 m.
B, H, W, H_T = 0.3, 4.0, 300e3, 7.5
#: S275 Ø20: N_pl,Rd = π·0.01²·275 MPa / 1.05 [N] (module docstring).
N_T_RD = math.pi * 0.01**2 * 275e6 / 1.05
REL = 1e-12
DEMAND = """
[ntc]
edition = "{edition}"
FC = 1.35
""" + SOIL_A_FLAT.lstrip("\n")


def wall(tmp_path: Path, restrainer: str, edition: str = "2009") -> Path:
    path = tmp_path / "wall.toml"
    path.write_text(
        'name = "wall"\nkind = "wall"\n[geometry]\nthickness = 0.6\nheight = 8.0\n'
        "[mass]\nweight = 300.0\n[[restrainers]]\n"
        + restrainer
        + "\nheight = 7.5\nfrom_pivot = 0.0\n"
        + DEMAND.format(edition=edition)
    )
    return path


TIE = 'name = "tie"\nkind = "tie-rod"\ngrade = "S275"\ndiameter = 0.02\nlength = 3.0'


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def kinematic_json(path: Path) -> dict:
    code, out, err = run("kinematic", str(path), "--format", "json")
    assert code == 0, err
    return json.loads(out)


def test_tie_rod_enters_as_its_design_strength(tmp_path: Path) -> None:
    doc = kinematic_json(wall(tmp_path, TIE))
    [a] = doc["restrainer_actions"]
    assert set(a) == ACTION_KEYS
    assert a["name"] == "tie" and a["code_action"] == "force"
    assert a["force"] == pytest.approx(N_T_RD, rel=REL)
    assert a["strength"] == pytest.approx(N_T_RD, rel=REL)
    assert a["demand"] == a["force"] and a["demand_at"] == "constant force"
    assert a["utilisation"] == pytest.approx(1.0, rel=REL) and a["passed"] is True
    assert a["clause"] == "NTC 2018 §4.2.4.1.2" and a["lost"] is False
    expected = (W * B + N_T_RD * H_T) / (W * H)
    assert doc["alpha0"] == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize("edition", ["2009", "2019"])
def test_spring_read_at_the_slv_displacement_demand(tmp_path: Path, edition: str) -> None:
    # A pretensioned spring: its pretension enters α0 (P0 h_T / (W h_G) above b/h_G); the
    # check computes the non-linear SLV check (d0* exists), so its demand is read there.
    spring = TIE + '\ncode_action = "spring"\npretension = 5000.0'
    doc = kinematic_json(wall(tmp_path, spring, edition))
    [a] = doc["restrainer_actions"]
    assert a["code_action"] == "spring" and a["force"] == 5000.0
    assert a["demand_at"].startswith("SLV displacement demand d* = ")
    assert 5000.0 < a["demand"] <= N_T_RD
    assert doc["alpha0"] == pytest.approx((W * B + 5000.0 * H_T) / (W * H), rel=REL)


def test_spring_without_pretension_gives_no_force(tmp_path: Path) -> None:
    doc = kinematic_json(wall(tmp_path, 'name = "vault"\nk = 4.0e6'))
    [a] = doc["restrainer_actions"]
    assert a["code_action"] == "spring" and a["force"] == 0.0
    assert a["strength"] is None and a["utilisation"] is None and a["passed"] is None
    assert doc["alpha0"] == pytest.approx(B / H, rel=REL)


def test_no_restrainer_gives_an_empty_list(tmp_path: Path) -> None:
    path = tmp_path / "bare.toml"
    path.write_text(
        'name = "w"\nkind = "wall"\n[geometry]\nthickness = 0.6\nheight = 8.0\n'
        + DEMAND.format(edition="2009")
    )
    assert kinematic_json(path)["restrainer_actions"] == []


def test_terminal_table(tmp_path: Path) -> None:
    code, out, err = run("kinematic", str(wall(tmp_path, TIE)))
    assert code == 0, err
    assert "Restrainers in the check" in out
    [row] = [line for line in out.splitlines() if "tie" in line and "force" in line]
    assert f"{N_T_RD / 1e3:.4g}" in row and "1.000" in row


def test_force_without_a_strength_is_one_error_line(tmp_path: Path) -> None:
    path = wall(tmp_path, 'name = "vault"\nk = 4.0e6\ncode_action = "force"')
    code, out, err = run("kinematic", str(path))
    assert code == 2 and "Traceback" not in out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("error: ") and "wall.toml" in lines[0]
    assert "code_action" in lines[0] and "force" in lines[0]


def test_compare_shows_the_restrainers_of_the_check(tmp_path: Path) -> None:
    code, out, err = run("compare", str(wall(tmp_path, TIE)), "--record", str(PULSES[0]))
    assert code == 0, err
    assert "Restrainers in the check" in out
    assert any("tie" in line and "force" in line for line in out.splitlines())


def test_tie_rod_that_breaks_before_the_demand_fails(tmp_path: Path) -> None:
    # ε_u = 1e-4 of 3 m: the bar breaks at 0.3 mm of elongation, long before the SLV
    # displacement demand; it is left out of the sure curve (d0* of the wall alone) and its
    # verification fails (lost).
    doc = kinematic_json(wall(tmp_path, TIE + "\nelongation_at_break = 1e-4"))
    [a] = doc["restrainer_actions"]
    assert a["code_action"] == "force" and a["lost"] is True and a["passed"] is False
    assert doc["d0_star"] == pytest.approx(B, rel=1e-9)  # d_k,0 = b, e* = 1 (bisection)
