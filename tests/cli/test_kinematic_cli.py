"""`rock kinematic`: the altar reproduces the paper's structure, JSON keys, demand sources,
exit codes and error lines (issue #3)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import ROOT

ALTAR = ROOT / "examples" / "altar.toml"
#: The altar with LC1's FC, which the 2019 rules ask of a block (§C8.7.1.2.1.3).
ALTAR_2019 = ROOT / "tests" / "data" / "altar-2019.toml"
GRID = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
KEYS_2009 = {
    "schema",
    "rock_version",
    "edition",
    "alpha0",
    "e_star",
    "a0_star",
    "FC",
    "d0_star",
    "du_star",
    "Ts",
    "checks",
    "verdict",
}
KEYS_2019 = {"d_SLV", "T_SLV", "d_SLC", "T_SLC"}
CHECK_KEYS = {"limit_state", "method", "location", "demand", "capacity", "unit", "passed", "clause"}


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def kinematic_json(*args: str) -> dict:
    code, out, err = run("kinematic", *args, "--format", "json")
    assert code == 0, err
    return json.loads(out)


def test_altar_2009_reproduces_the_paper() -> None:
    # Paper §3.2 / spec/ntc.md: Ts = 1.09 s with FC = 1.05 (1.0911 s to 4 decimals); DLS and
    # ULS checks, with demand and capacity side by side.
    doc = kinematic_json(str(ALTAR))
    assert KEYS_2009 <= set(doc)
    assert doc["edition"] == "2009" and doc["FC"] == 1.05
    assert doc["Ts"] == pytest.approx(1.0911, abs=5e-5)
    assert doc["a0_star"] == pytest.approx(1.5365, abs=5e-5)
    states = {(c["limit_state"], c["method"], c["location"]) for c in doc["checks"]}
    assert {
        ("DLS", "linear", "ground"),
        ("DLS", "linear", "height"),
        ("ULS", "linear", "ground"),
        ("ULS", "nonlinear", "ground"),
        ("ULS", "nonlinear", "height"),
    } <= states
    for c in doc["checks"]:
        assert CHECK_KEYS <= set(c)
        assert c["passed"] == (c["capacity"] >= c["demand"])
        assert c["clause"].startswith("Circolare 617/2009 §C8A.4.2")
    assert set(doc["verdict"]) >= {"DLS", "ULS"}


def test_altar_2019_keys_and_limit_states() -> None:
    doc = kinematic_json(str(ALTAR_2019), "--edition", "2019")
    assert KEYS_2019 <= set(doc) and doc["edition"] == "2019"
    assert {c["limit_state"] for c in doc["checks"]} == {"SLD", "SLV", "SLC"}
    assert all(c["unit"] == "g" for c in doc["checks"])
    # T_SLV = 1.68π √(d_SLV / a(d_SLV)), d_SLV = 0.4 d0 on the straight line (Circ. 7/2019).
    a_slv = doc["a0_star"] * (1 - 0.4)
    assert doc["T_SLV"] == pytest.approx(1.68 * 3.141592653589793 * (doc["d_SLV"] / a_slv) ** 0.5)


def test_table_shows_checks_and_verdict() -> None:
    code, out, _ = run("kinematic", str(ALTAR))
    assert code == 0
    assert "Checks (Circolare 617/2009)" in out and "verdict:" in out and "§C8A.4.2.3" in out


def test_record_spectrum_as_demand(shared_records: Path) -> None:
    # spec/ntc.md: the record's PGA in place of ag·S: the DLS ground demand is the PGA·g.
    doc = kinematic_json(str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    dls = next(c for c in doc["checks"] if c["limit_state"] == "DLS" and c["location"] == "ground")
    assert dls["demand"] == pytest.approx(0.3128806 * 9.81, rel=1e-6)
    assert doc["demand"]["SLV"]["record"] == "ELC180"


def test_site_from_the_hazard_grid(tmp_path: Path) -> None:
    if not GRID.is_file():
        pytest.skip(
            f"hazard grid not available: {GRID} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    # The example's [ntc.demand] values are the grid at Reggiolo, rounded: the site gives the
    # same verdict and a DLS demand within the rounding (3 significant digits of ag).
    doc = kinematic_json(str(ALTAR), "--site", "10.807,44.918", "--hazard-grid", str(GRID))
    ref = kinematic_json(str(ALTAR))
    assert doc["verdict"] == ref["verdict"]
    for a, b in zip(doc["checks"], ref["checks"], strict=True):
        assert a["demand"] == pytest.approx(b["demand"], rel=2e-3)


def test_site_outside_the_grid_is_one_error_line() -> None:
    if not GRID.is_file():
        pytest.skip(
            f"hazard grid not available: {GRID} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    code, _, err = run("kinematic", str(ALTAR), "--site", "9.1,39.2", "--hazard-grid", str(GRID))
    assert code == 2 and err.startswith("error: ") and len(err.strip().splitlines()) == 1


def test_missing_grid_says_how_to_give_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROCK_HAZARD_GRID", raising=False)
    code, _, err = run("kinematic", str(ALTAR), "--site", "13.4,42.35")
    assert code == 2 and "ROCK_HAZARD_GRID" in err


def test_bad_site_option() -> None:
    code, _, err = run("kinematic", str(ALTAR), "--site", "north")
    assert code == 2 and "--site" in err and "'north'" in err


def _model(tmp_path: Path, ntc: str) -> Path:
    path = tmp_path / "m.toml"
    path.write_text('name = "w"\nkind = "wall"\n[geometry]\nR = 2.0\nalpha = 0.15\n' + ntc)
    return path


@pytest.mark.parametrize(
    ("ntc", "fragment"),
    [
        ("[ntc]\nFC = 0.9\n", "ntc.FC"),
        ('[ntc]\nsoil = "F"\n', "ntc.soil"),
        ("[building]\nZ = -1.0\n", "building.Z"),
        ("[building]\nZ = 12.0\nH = 10.0\nN = 3\n", "building.Z"),
        ("[building]\nZ = 3.0\nN = 3\n", "building.H"),
        ("[ntc]\nZ = 3.0\n", "ntc.Z: moved to [building]"),
        ('[ntc]\nFC = 1.2\nknowledge_level = "LC2"\n', "ntc"),
        ('[ntc]\nedition = "2023"\n', "ntc.edition"),
    ],
)
def test_bad_ntc_settings(tmp_path: Path, ntc: str, fragment: str) -> None:
    code, out, err = run("kinematic", str(_model(tmp_path, ntc)))
    assert code == 2 and "Traceback" not in out + err
    line = err.strip()
    assert line.startswith("error: ") and "m.toml" in line and fragment in line


def test_no_demand_is_one_error_line(tmp_path: Path) -> None:
    code, _, err = run("kinematic", str(_model(tmp_path, '[ntc]\nedition = "2009"\n')))
    assert code == 2 and "no seismic demand" in err and "--record" in err


def test_missing_limit_state_parameters(tmp_path: Path) -> None:
    ntc = '[ntc]\nedition = "2019"\n[ntc.demand.SLD]\nag = 0.05\nF0 = 2.5\nTc_star = 0.3\n'
    code, _, err = run("kinematic", str(_model(tmp_path, ntc)))
    assert code == 2 and "ntc.demand.SLV" in err


def test_record_without_motion_is_one_error_line(tmp_path: Path) -> None:
    # A record of zeros has no spectrum to scale (PGA 0): one error line, not a traceback.
    rec = tmp_path / "zeros.txt"
    rec.write_text("0 0\n0.01 0\n0.02 0\n")
    code, out, err = run("kinematic", str(ROOT / "examples" / "wall.toml"), "--record", str(rec))
    assert code == 2 and "Traceback" not in out + err
    assert err.startswith("error: ") and "zeros.txt" in err and "PGA 0 g" in err
