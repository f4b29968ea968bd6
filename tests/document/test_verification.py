"""`rock report MODEL` without a record: the verification on the model's spectra is the
report (issue 36, item 1), α0 of every mechanism can be recomputed from the page (item 2), and
the limit states NTC 2018 §8.3 requires for the use class decide the conclusions."""

from __future__ import annotations

import html as htmlmod
import json
import re
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.existing import required_limit_states, use_class_of

ROOT = Path(__file__).resolve().parents[2]
FACADE = ROOT / "examples" / "two-storey-facade.toml"
BLOCK = ROOT / "examples" / "facade.toml"  # sets no code spectrum
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"

pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")


def run(*args: str) -> Any:
    return CliRunner().invoke(cli, list(args))


def data_of(page: str) -> dict[str, Any]:
    """The report's rock-data JSON."""
    found = re.search(r'<script type="application/json" id="rock-data">(.*?)</script>', page,
                      re.S)  # fmt: skip
    assert found is not None
    return json.loads(found.group(1))


@pytest.fixture(scope="module")
def filed(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, str]:
    """The two-storey façade's report without a record, and with one."""
    folder = tmp_path_factory.mktemp("verify")
    alone, scenario = folder / "alone.html", folder / "scenario.html"
    result = run("report", str(FACADE), "-o", str(alone), "--casebook", "none")
    assert result.exit_code == 0, result.output
    result = run("report", str(FACADE), "--record", str(PULSE), "-o", str(scenario),
                 "--casebook", "none", "--mechanisms", "governing")  # fmt: skip
    assert result.exit_code == 0, result.output
    return alone.read_text(encoding="utf-8"), scenario.read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def kinematic() -> dict[str, Any]:
    """`rock kinematic --all --format json` of the façade: the check on its own spectra."""
    result = run("kinematic", str(FACADE), "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_without_a_record_the_report_is_the_verification(filed: tuple[str, str]) -> None:
    page, _ = filed
    keys = re.findall(r'<section id="([^"]+)"', page)
    assert keys == ["identification", "summary", "wall", "model", "demand", "kinematic",
                    "virtual-work", "conclusions", "software"]  # fmt: skip
    assert "rocking" not in keys and "Scenario" not in page
    data = data_of(page)
    assert data["scenario"] is None
    assert data["verification"]["demand"] == "model"  # [ntc.demand.*] in the model


def test_the_verification_is_the_code_check_on_the_models_spectra(
    filed: tuple[str, str], kinematic: dict[str, Any]
) -> None:
    ver = data_of(filed[0])["verification"]
    assert ver["governing"] == kinematic["governing"]
    # ζ_E of a limit state: the smallest ratio of the checks that decide it, the non-linear
    # ones where the state has them (Circ. 7/2019 §C8.3), of the governing mechanism.
    expected = {}
    for state in ("SLD", "SLV", "SLC"):
        checks = [c for c in kinematic["checks"] if c["limit_state"] == state]
        deciding = [c for c in checks if c["method"] == "nonlinear"] or checks
        expected[state] = min(c["ratio"] for c in deciding)
    assert ver["zeta_E"] == expected


def test_a_record_adds_a_scenario_and_leaves_the_verification_as_it_is(
    filed: tuple[str, str],
) -> None:
    alone, scenario = (data_of(page) for page in filed)
    assert scenario["verification"] == alone["verification"]
    assert scenario["mechanisms"] == alone["mechanisms"]
    assert scenario["scenario"]["record"] == "ricker_Tp0.5s_0.5g"
    assert scenario["scenario"]["code_demand"] == "record"
    keys = re.findall(r'<section id="([^"]+)"', filed[1])
    assert keys.index("kinematic") < keys.index("scenario-demand") < keys.index("rocking")
    assert keys[-2:] == ["conclusions", "software"]


def test_alpha0_is_recomputed_from_the_pages_data(
    filed: tuple[str, str], kinematic: dict[str, Any]
) -> None:
    data = data_of(filed[0])
    checked = {m["name"]: m["alpha0"] for m in kinematic["mechanisms"]}
    assert len(data["mechanisms"]) == len(checked) == 6
    for m in data["mechanisms"]:
        up = sum(t["resisting_kNm"] for t in m["virtual_work"])
        down = sum(t["overturning_kNm"] for t in m["virtual_work"])
        assert up / down == pytest.approx(checked[m["name"]], rel=1e-12), m["name"]
        for t in m["virtual_work"]:  # each term from its own columns
            if t["kind"] in ("body", "load") and t["overturning_kNm"]:
                assert t["overturning_kNm"] == pytest.approx(t["weight_kN"] * t["dx"])


def table_rows(page: str, caption_start: str) -> list[list[str]]:
    """The body rows of the table whose caption starts with ``caption_start``, as text."""
    at = page.index(caption_start)
    end = page.index("</table>", at)
    rows = re.findall(r"<tr>(.*?)</tr>", page[at:end], re.S)
    cells = [[htmlmod.unescape(re.sub(r"<[^>]+>", "", c)).strip()
              for c in re.findall(r"<td[^>]*>(.*?)</td>", row, re.S)] for row in rows]  # fmt: skip
    return [c for c in cells if c]


def number(text: str) -> float:
    return float(text.replace(",", "."))


def test_the_gables_alpha0_by_hand_from_the_printed_table(filed: tuple[str, str]) -> None:
    # The gable of the façade: a triangle 6 m wide, 2.5 m high, 0.45 m thick, γ 20 kN/m³:
    # P = ½·6·2.5·0.45·20 = 67.5 kN at h/3 above its hinge; the ridge beam, 8 kN at the apex
    # (2.5 m). The hinge is set back from the face by half the stress block that carries the
    # weight, a = N/(f_m·L) = 75.5 kN / (2 MPa · 6 m): every lever x = t/2 − a/2. Eq.
    # C8.7.1.1 (Circ. 7/2019 §C8.7.1.2.1.1) at activation: α0·Σ P·z = Σ P·x.
    a = 75.5e3 / (2.0e6 * 6.0)
    x = 0.45 / 2 - a / 2
    alpha0 = (67.5 + 8.0) * x / (67.5 * 2.5 / 3 + 8.0 * 2.5)
    rows = table_rows(filed[0], "Meccanismo &#39;ribaltamento del timpano&#39;, polo")
    items = {r[0]: r for r in rows}
    assert number(items["timpano"][2]) == pytest.approx(67.5)
    assert number(items["timpano"][4]) == pytest.approx(2.5 / 3, abs=5e-5)
    assert number(items["ridge beam"][3]) == pytest.approx(x, abs=5e-5)
    up, down = number(items["Somma"][-2]), number(items["Somma"][-1])
    assert up == pytest.approx((67.5 + 8.0) * x, abs=5e-5)
    assert up / down == pytest.approx(alpha0, rel=1e-4)
    assert f"= {alpha0:.5f}".replace(".", ",") in filed[0]


def test_the_conclusions_follow_the_use_class(tmp_path: Path) -> None:
    # Class II (CU 1, the model's): §8.3 requires the ULS alone, verified at the SLV; the
    # façade's SLD fails (ζ 0.64) and is reported for information only. Class IV: the SLD is
    # required too, and the same wall needs an intervention.
    text = FACADE.read_text(encoding="utf-8").replace(
        'edition = "2019"', 'edition = "2019"\nuse_class = "IV"'
    )
    model = tmp_path / "facade-iv.toml"
    model.write_text(text, encoding="utf-8")
    page = tmp_path / "iv.html"
    result = run("report", str(model), "-o", str(page), "--casebook", "none")
    assert result.exit_code == 0, result.output
    assert "verification not satisfied" in result.output
    ver = data_of(page.read_text(encoding="utf-8"))["verification"]
    assert ver["use_class"] == "IV" and ver["required"] == ["SLD", "SLV"]
    assert ver["zeta_E"]["SLD"] < 1 and ver["verdict"]["SLD"] is False
    assert "aumentare la sicurezza strutturale" in page.read_text(encoding="utf-8")


def test_the_required_limit_states_of_each_use_class() -> None:
    # NTC 2018 §8.3 and Tab. 2.4.II.
    assert [use_class_of(cu) for cu in (0.7, 1.0, 1.5, 2.0, 1.2)] == ["I", "II", "III", "IV",
                                                                       None]  # fmt: skip
    assert required_limit_states("II") == ("SLV",)
    assert required_limit_states("III") == ("SLV",)
    assert required_limit_states("IV") == ("SLD", "SLV")
    assert required_limit_states(None) == ("SLV",)
    # The 2009 edition's check names them DLS and ULS (Circolare 617/2009 §C8A.4).
    assert required_limit_states("IV", "2009") == ("DLS", "ULS")
    assert required_limit_states("II", "2009") == ("ULS",)


@pytest.mark.parametrize(
    ("args", "words"),
    [
        ([str(BLOCK)], "ntc: sets no code spectrum for the verification"),
        ([str(FACADE), "--code-demand", "model"], "--code-demand: chooses the demand"),
        ([str(BLOCK), "--retrofit"], "ntc: sets no code spectrum for the verification"),
        ([str(FACADE), "--engine", "reference"], "--engine: acts on a time history"),
        ([str(FACADE), "--ground"], "--ground: acts on a time history"),
        ([str(FACADE), "--mechanism", "gable"], "--mechanism: acts on a time history"),
    ],
)
def test_bad_input_without_a_record(tmp_path: Path, args: list[str], words: str) -> None:
    result = run("report", *args, "-o", str(tmp_path / "r.html"))
    assert result.exit_code == 2 and words in result.output, result.output
    assert "Traceback" not in result.output and len(result.output.strip().splitlines()) == 1
    assert not (tmp_path / "r.html").exists()


def test_a_use_class_that_disagrees_with_cu_is_refused(tmp_path: Path) -> None:
    text = FACADE.read_text(encoding="utf-8").replace(
        'edition = "2019"', 'edition = "2019"\nuse_class = "IV"\nCU = 1.5'
    )
    model = tmp_path / "m.toml"
    model.write_text(text, encoding="utf-8")
    result = run("kinematic", str(model))
    assert result.exit_code == 2
    assert "ntc.CU: does not agree with use_class = 'IV' (CU 2)" in result.output


def test_the_wall_is_in_its_report(filed: tuple[str, str]) -> None:
    # The model file's own numbers (examples/two-storey-facade.toml): a storey 4.0 m × 0.60 m,
    # one 3.5 m × 0.45 m, a 2.5 m gable, γ 20 kN/m³, return walls 0.45 m, f_m 2 MPa (FC 1.35
    # given, LC1), the floors' and roof's loads, the roof thrust, the tie-rod at 7.5 m.
    page = filed[0]
    assert page.index('<section id="wall"') < page.index('<section id="model"')
    rows = {r[0]: r for r in table_rows(page, "Geometria e materiali della parete")}
    assert rows["Piano 1 (base a 0,00 m): altezza × spessore"][1] == "4,000 × 0,600"
    assert rows["Piano 2 (base a 4,00 m): altezza × spessore"][1] == "3,500 × 0,450"
    assert rows["Timpano: altezza sopra l'ultimo piano"][1] == "2,500"
    assert rows["Peso specifico della muratura"][1] == "20,00"
    assert rows["Larghezza della parete (nel suo piano)"][1] == "6,000"
    assert rows["Spessore delle pareti ortogonali"][1] == "0,450"
    assert rows["Fattore di confidenza FC"][1].startswith("1,35")
    loads = {r[0]: r for r in table_rows(page, "Carichi sulla parete")}
    assert [loads[k][1] for k in ("first floor", "roof", "ridge beam")] == ["60,00", "45,00",
                                                                          "8,00"]  # fmt: skip
    thrusts = table_rows(page, "Spinte orizzontali sulla parete")
    # No from_pivot in the file: the thrust acts at the mid-thickness of its storey.
    assert thrusts == [["roof thrust", "6,00", "verso l'esterno", "0,225", "7,500"]]
    ties = table_rows(page, "Vincoli (catene, collegamenti) della parete")
    assert [t[0] for t in ties] == ["tie-rod"] and ties[0][2] == "7,500"
    assert 'id="figure-wall"' in page  # the section drawn with every mechanism


def test_a_2009_check_is_verified_at_its_ultimate_limit_state(tmp_path: Path) -> None:
    # The altar (Circolare 617/2009, class II by its CU 1): its check names the limit states
    # DLS and ULS; §8.3 requires the ULS, which it fails on its [ntc.demand] (ζ_E < 1).
    altar = ROOT / "examples" / "altar.toml"
    page = tmp_path / "altar.html"
    result = run("report", str(altar), "-o", str(page), "--casebook", "none")
    assert result.exit_code == 0, result.output
    assert "verification not satisfied" in result.output
    ver = data_of(page.read_text(encoding="utf-8"))["verification"]
    assert ver["required"] == ["ULS"] and set(ver["zeta_E"]) == {"DLS", "ULS"}
    assert ver["zeta_E"]["ULS"] < 1 and ver["verdict"]["ULS"] is False


def test_the_scenarios_floor_spectra_are_the_ones_its_check_read(tmp_path: Path) -> None:
    # The top-storey wall at Z = 3.5 m under the Ricker pulse: the scenario's code check reads
    # the floor spectrum the code's rule makes from the record's spectrum (Circ. 7/2019
    # §C7.2.3); the report draws that curve (figures.floor_curve) and says so. At each
    # non-linear check's period and damping, the curve's Se·g·T²/4π² is the check's demand.
    import math

    import numpy as np

    from rockcli.analyses.compare import compare_model_output
    from rockcli.codecheck.response import RecordSpectrum
    from rockcli.document.figures import floor_curve
    from rockcli.model.load import load_model
    from rockcli.records.files import read_record

    model = load_model(str(ROOT / "examples" / "top-storey-wall.toml"))
    record = read_record(str(PULSE))
    kin = compare_model_output(model, record).kinematic
    assert kin.position is not None and kin.position.at_height
    spectrum = RecordSpectrum.from_record(record, g=model.analysis.g)
    checked = [c for c in kin.checks if c.spectral is not None]
    assert {c.limit_state for c in checked} == {"SLV", "SLC"}
    for c in checked:
        assert c.spectral is not None
        T = c.spectral.period
        _, se = floor_curve(spectrum, c.limit_state, kin.position, "2019", np.array([T]))
        drawn = float(se[0]) * model.analysis.g * T**2 / (4 * math.pi**2)
        assert drawn == pytest.approx(c.spectral.value, rel=1e-12)
    page = tmp_path / "wall.html"
    result = run("report", str(ROOT / "examples" / "top-storey-wall.toml"), "--record",
                 str(PULSE), "-o", str(page), "--casebook", "none")  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "applicata, come nella verifica, allo spettro di risposta dell&#39;accelerogramma" in (
        page.read_text(encoding="utf-8")
    )


def test_every_mechanism_decides_the_verification() -> None:
    # A class IV building: the governing mechanism (lowest ULS ζ) passes the SLD, another one
    # fails it — the verification fails, naming it; a state not evaluated for one mechanism
    # leaves the outcome open rather than satisfied.
    from rockcli.document.verification import Verification, outcome, state_outcome

    def verification(second: dict[str, bool | None]) -> Verification:
        doc = {"mechanisms": [
            {"name": "governing", "verdict": {"SLD": True, "SLV": True}},
            {"name": "gable", "verdict": second},
        ]}  # fmt: skip
        return Verification(None, doc, "model", "IV", ("SLD", "SLV"))  # type: ignore[arg-type]

    failing = verification({"SLD": False, "SLV": True})
    assert state_outcome(failing, "SLD") == (False, ["gable"])
    assert outcome(failing) == "fails" and outcome(failing, ("SLV",)) == "passes"
    assert outcome(verification({"SLD": True, "SLV": None})) == "unknown"
    assert outcome(verification({"SLD": True, "SLV": True})) == "passes"
