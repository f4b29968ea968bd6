"""Every report states the demand it used, as numbers (issue #8, item 5): `demand.<LS>` of
`rock kinematic --format json` is an object, the terminal shows it as a table, and the
`rock compare` note is a line built from it."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import ROOT

ALTAR = ROOT / "examples" / "altar.toml"
#: The altar with LC1's FC, which the 2019 rules ask of a block (§C8.7.1.2.1.3).
ALTAR_2019 = ROOT / "tests" / "data" / "altar-2019.toml"
GRID = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
#: The keys of a code spectrum's demand (NTC 2018 §3.2.3.2.1) and of a record's.
SPECTRUM_KEYS = {"TR", "ag", "F0", "Tc_star", "SS", "ST", "S", "TB", "TC", "TD", "source"}
RECORD_KEYS = {"record", "PGA", "source", "spectral_values"}
#: Probability of exceedance in VR per limit state (NTC 2008 and 2018 Tab. 3.2.I).
P_VR = {"SLD": 0.63, "SLV": 0.10, "SLC": 0.05}
#: ELC180's PGA [g]: the value test_kinematic_cli's record test checks (0.3128806 g, the
#: record's largest absolute sample; PROVENANCE.md), to its 7 digits.
ELC180_PGA = 0.3128806
#: Tolerance on numbers computed in the same double-precision formula a different way.
REL = 1e-12


def kinematic_json(*args: str) -> dict:
    result = CliRunner().invoke(cli, ["kinematic", *args, "--format", "json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def soil_c_numbers(ag: float, F0: float, Tc_star: float) -> dict[str, float]:
    """Soil C, topography T1 written out from NTC 2018 §3.2.3.2.1 and Tab. 3.2.IV–3.2.V:
    SS = 1.70 − 0.60·F0·ag/g within [1.00, 1.50], CC = 1.05·Tc*^−0.33, ST = 1.0,
    TC = CC·Tc*, TB = TC/3, TD = 4·ag/g + 1.6 (ag in g)."""
    SS = min(max(1.70 - 0.60 * F0 * ag, 1.00), 1.50)
    TC = 1.05 * Tc_star**-0.33 * Tc_star
    return {"SS": SS, "ST": 1.0, "S": SS * 1.0, "TB": TC / 3.0, "TC": TC, "TD": 4.0 * ag + 1.6}


def test_model_parameters_come_back_with_the_ntc_spectrum() -> None:
    model = tomllib.loads(ALTAR.read_text(encoding="utf-8"))
    assert model["ntc"]["soil"] == "C" and model["ntc"]["topography"] == "T1"
    doc = kinematic_json(str(ALTAR))
    assert set(doc["demand"]) == {"SLD", "SLV"}  # the 2009 edition's limit states
    for ls, numbers in doc["demand"].items():
        given = model["ntc"]["demand"][ls]
        # The altar stands at height: its ground spectrum's values at T1, where the floor
        # spectra come from, and at Ts, which 2009's ground check reads (issue 36).
        assert set(numbers) == SPECTRUM_KEYS | {"spectral_values"}
        assert [v["at"] for v in numbers["spectral_values"]] == (
            ["T1"] if ls == "SLD" else ["T1", "Ts"]
        )
        # The model gives the parameters: no return period, the source names the table.
        assert numbers["TR"] is None and numbers["source"] == f"[ntc.demand.{ls}]"
        # Its own ag, F0, Tc* back, exactly (they are the model's numbers).
        assert (numbers["ag"], numbers["F0"], numbers["Tc_star"]) == (
            given["ag"],
            given["F0"],
            given["Tc_star"],
        )
        expected = soil_c_numbers(given["ag"], given["F0"], given["Tc_star"])
        for key, value in expected.items():
            assert numbers[key] == pytest.approx(value, rel=REL), key


def test_site_on_the_hazard_grid_gives_the_return_periods() -> None:
    if not GRID.is_file():
        pytest.skip(
            f"hazard grid not available: {GRID} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    doc = kinematic_json(
        str(ALTAR_2019), "--site", "10.807,44.918", "--hazard-grid", str(GRID), "--edition", "2019"
    )
    # The altar: VN = 50 years, CU = 1.0, so VR = 50 years; TR = −VR/ln(1 − PVR) (NTC 2018
    # §3.2.1): 50.3, 474.6 and 974.8 years.
    VR = 50.0 * 1.0
    assert set(doc["demand"]) == {"SLD", "SLV", "SLC"}
    for ls, numbers in doc["demand"].items():
        # At height (2019): the ground spectrum's values at T1 only, where the floor spectra
        # the checks read come from.
        assert set(numbers) == SPECTRUM_KEYS | {"spectral_values"}
        assert [v["at"] for v in numbers["spectral_values"]] == ["T1"]
        assert numbers["TR"] == pytest.approx(-VR / math.log(1.0 - P_VR[ls]), rel=REL)
        assert numbers["source"] == "hazard grid at 10.8070 E, 44.9180 N"
        assert all(math.isfinite(numbers[k]) for k in SPECTRUM_KEYS - {"source"})


def test_record_gives_its_name_and_pga(shared_records: Path) -> None:
    doc = kinematic_json(str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    for numbers in doc["demand"].values():
        assert set(numbers) == RECORD_KEYS
        assert numbers["record"] == "ELC180"
        # 7 digits given: half a unit of the 7th.
        assert numbers["PGA"] == pytest.approx(ELC180_PGA, abs=5e-8)
        assert numbers["source"] == "its response spectrum, PGA in place of ag·S"


def test_record_gives_the_spectral_values_its_checks_read(shared_records: Path) -> None:
    # The altar (2009) at height: Se and SDe of the record at the building's T1 (1.09 s, the
    # model) for both limit states, and at the mechanism's Ts for ULS = SLV (the result's own
    # Ts); SDe = Se·g·T²/4π² (the pseudo-spectral relation, 5 % damping; g = 9.81 as the
    # code check's; 1e-12: the same product in another order).
    doc = kinematic_json(str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    sld = doc["demand"]["SLD"]["spectral_values"]
    slv = doc["demand"]["SLV"]["spectral_values"]
    assert [v["at"] for v in sld] == ["T1"] and [v["at"] for v in slv] == ["T1", "Ts"]
    assert sld[0]["T"] == 1.09 and slv[1]["T"] == doc["Ts"]
    for v in (*sld, *slv):
        expected = v["Se"] * 9.81 * v["T"] ** 2 / (4 * math.pi**2)
        assert v["SDe"] == pytest.approx(expected, rel=REL)
    assert sld[0] == slv[0]  # one record, one spectrum


def test_terminal_shows_the_demand_as_a_table() -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(ALTAR)])
    assert result.exit_code == 0, result.stderr
    out = result.stdout
    # Column headers and the SLV row's numbers, formatted as the table's columns.
    for header in ("TR", "ag", "F0", "Tc*", "TB", "TC", "TD", "source"):
        assert header in out
    assert "0.1181" in out and "2.574" in out and "[ntc.demand.SLV]" in out
    # Not the old one-line string.
    assert "[ntc.demand] parameters" not in out


def test_compare_note_is_a_line_built_from_the_numbers(shared_records: Path) -> None:
    result = CliRunner().invoke(
        cli, ["compare", str(ALTAR), "--record", str(shared_records / "ELC180.AT2")]
    )
    assert result.exit_code in (0, 1), result.stderr
    text = " ".join(result.stdout.split())  # the note may wrap
    assert "demand:" in text and "{" not in text  # no dict printed as Python
    assert ("SLV ag 0.1181 g" in text) or ("SLV record ELC180, PGA 0.3129 g" in text)
