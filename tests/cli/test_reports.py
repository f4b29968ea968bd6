"""What the reports say (issue 7, items 18 and 6): an overturned run reads "overturned", the
2019 verdict line names each limit state once, "not evaluated" names the fix, and every
document carries a "warnings" list that the table shows."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.terminal.compare import comparison_report
from rockcli.terminal.kinematic import kinematic_report
from tests.cli.conftest import PULSES, ROOT

ALTAR = str(ROOT / "examples" / "altar.toml")
#: The altar with LC1's FC, which the 2019 rules ask of a block (§C8.7.1.2.1.3).
ALTAR_2019 = str(ROOT / "tests" / "data" / "altar-2019.toml")
RECORD = str(PULSES[0])
FIX = "set ntc.ultimate_displacement or a restrainer's fails_at"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def as_json(*args: str) -> dict:
    code, out, err = run(*args, "--format", "json")
    assert code == 0, err
    return json.loads(out)


@pytest.fixture(scope="module")
def overturning(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, str]:
    """A slender free wall (R = 1 m, α = 0.1) and a 0.6 g, 2 s one-sine pulse: it overturns
    (the pulse is six times tan α; test_assess_cli.test_fail_on_overturn_exit_code)."""
    folder = tmp_path_factory.mktemp("overturn")
    pulse, model = folder / "p.txt", folder / "m.toml"
    code, _, err = run(
        "record", "pulse", "one-sine", "--amplitude", "0.6", "--period", "2",
        "--duration", "6", "-o", str(pulse),
    )  # fmt: skip
    assert code == 0, err
    model.write_text('name = "slender"\nkind = "wall"\n[geometry]\nR = 1.0\nalpha = 0.1\n')
    return str(model), str(pulse)


def test_an_overturned_run_reads_overturned(overturning: tuple[str, str]) -> None:
    # The JSON keeps max θ/α (the overturn angle over α) and flags what it means; the table
    # does not show that number as if it were a peak amplitude.
    model, pulse = overturning
    doc = as_json("assess", model, "--record", pulse)
    assert doc["verdict"] == "overturns" and doc["max_ratio_overturned"] is True
    assert isinstance(doc["max_ratio"], float)
    code, out, _ = run("assess", model, "--record", pulse)
    assert code == 0
    row = next(line for line in out.splitlines() if "max θ/α" in line)
    over = [r for r in doc["runs"] if r["overturned"]]
    assert row.count("overturned") == len(over) >= 1
    assert f"{over[0]['max_ratio']:.4f}" not in row
    assert out.splitlines()[-1] == "verdict: overturns"


def test_a_survived_run_keeps_its_amplitude() -> None:
    # The altar under a fifth of the 0.31 g one-cosine pulse survives (0.062 g < tan α).
    scaled = ("--record", RECORD, "--scale", "0.2")
    doc = as_json("assess", ALTAR, *scaled)
    assert doc["verdict"] == "survives" and doc["max_ratio_overturned"] is False
    _, out, _ = run("assess", ALTAR, *scaled)
    assert f"max θ/α = {doc['max_ratio']:.4f}" in out.splitlines()[-1]


def test_compare_shows_overturned_not_a_ratio(overturning: tuple[str, str]) -> None:
    model, pulse = overturning
    _, out, err = run("compare", model, "--record", pulse)
    assert "verdict" in out, err
    row = next(line for line in out.splitlines() if "amplitude" in line)
    assert "overturned" in row and "max θ/α" not in row


def test_the_2019_verdict_line_names_each_limit_state_once() -> None:
    # 2019 checks SLD, SLV and SLC; DLS is SLD and ULS is SLV with SLC: the line said both.
    _, out, _ = run("kinematic", ALTAR_2019, "--edition", "2019")
    line = out.splitlines()[-1]
    assert line.startswith("verdict: SLD ")
    for state in ("SLD", "SLV", "SLC"):
        assert line.count(state) == 1, line
    assert "DLS" not in line and "ULS" not in line
    _, out, _ = run("kinematic", ALTAR)
    assert out.splitlines()[-1] == "verdict: DLS satisfied, ULS NOT satisfied"


def _stiff_facade(tmp_path: Path) -> str:
    """The façade with a tie-rod 100 times stiffer and its vault elastic: positive global
    stiffness on the free side once the rod breaks (at its ε_u·L/γ_ε, which caps d_SLV), so
    the curve has no d0*, and without an ultimate displacement SLC is not evaluated."""
    text = (ROOT / "examples" / "facade.toml").read_text(encoding="utf-8")
    model = tmp_path / "stiff.toml"
    # and its vault elastic (no fails_at): a spring of unlimited strength, the curve hardens
    text = text.replace("\nfails_at = 0.001 ", "\n# fails_at = 0.001 ", 1)
    model.write_text(text.replace("diameter = 0.020", "diameter = 0.200", 1), encoding="utf-8")
    return str(model)


def test_not_evaluated_names_the_fix(tmp_path: Path) -> None:
    model = _stiff_facade(tmp_path)
    assert as_json("kinematic", model, "--record", RECORD)["verdict"]["ULS"] is None
    _, out, _ = run("kinematic", model, "--record", RECORD)
    # The façade is a 2019 model: SLC is not evaluated, the fix is named once. The verdict
    # wraps at the output's width (100 columns here), its later lines indented.
    verdict = out[out.index("verdict:") :]
    assert " ".join(verdict.split()).endswith(f"SLC not evaluated ({FIX})")
    _, out, _ = run("compare", model, "--record", RECORD)
    row = next(line for line in out.splitlines() if "collapse" in line)
    assert "not evaluated" in row
    assert "ultimate_displacement" in out  # the fix, in the collapse cell (it may wrap)


def test_kinematic_and_compare_documents_carry_warnings() -> None:
    # Item 6: model-plausibility and record warnings go into one "warnings" list per document.
    kin = as_json("kinematic", ALTAR)
    assert kin["warnings"] == []
    cmp = as_json("compare", ALTAR, "--record", RECORD)
    assert cmp["warnings"] == [*kin["warnings"], *cmp["rocking"]["warnings"]]


def test_warnings_are_shown_under_the_table() -> None:
    kin = as_json("kinematic", ALTAR)
    report = kinematic_report({**kin, "warnings": ["thickness > height: a unit slip?"]})
    assert report.warnings == ("thickness > height: a unit slip?",)
    cmp = as_json("compare", ALTAR, "--record", RECORD)
    report = comparison_report({**cmp, "warnings": ["PGA 245 g: cm/s² read as g?"]})
    assert report.warnings == ("PGA 245 g: cm/s² read as g?",)


SLIPPED = """name = "slipped wall"
kind = "wall"
[geometry]
thickness = 500.0   # meant in millimetres
height = 4.0
width = 1.0
[mass]
unit_weight = 18.0
[ntc.demand.SLV]
ag = 0.15
F0 = 2.5
Tc_star = 0.3
[ntc.demand.SLD]
ag = 0.06
F0 = 2.5
Tc_star = 0.25
[ntc.demand.SLC]
ag = 0.2
F0 = 2.5
Tc_star = 0.32
"""


@pytest.mark.parametrize("command", ["kinematic", "assess", "compare"])
def test_a_unit_slip_warns_in_the_table_and_the_json(tmp_path: Path, command: str) -> None:
    # Item 6: a thickness typed in millimetres (2b = 500 m, α = 1.563 rad) gave a confident
    # verdict with no word; now every command warns, in the JSON and under the table.
    model = tmp_path / "slip.toml"
    model.write_text(SLIPPED, encoding="utf-8")
    args = (
        (command, str(model))
        if command == "kinematic"
        else (command, str(model), "--record", RECORD)
    )
    doc = as_json(*args)
    assert any("thickness 2b = 500 m" in w for w in doc["warnings"]), doc["warnings"]
    _, out, _ = run(*args)
    assert any(
        line.startswith("warning: geometry: thickness 2b = 500 m") for line in out.splitlines()
    )


def test_a_record_warning_reaches_the_assess_document(tmp_path: Path) -> None:
    # Item 6: a record read in the wrong unit (m/s² as g: PGA 24.5 g) warns in assess too.
    rec = tmp_path / "ms2.txt"
    rec.write_text("".join(f"{0.01 * i:.2f} {24.5 if i == 5 else 0.0}\n" for i in range(20)))
    doc = as_json("assess", ALTAR, "--record", str(rec))
    assert any("check the unit" in w and "--units" in w for w in doc["warnings"]), doc["warnings"]
