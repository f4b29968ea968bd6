"""`rock validate` and the bundled casebook (rockcli.casebook, examples/validation).

Every bundled case must pass: each expected value comes from the source the case file cites
(a paper's table or text, a code's formula by hand, a textbook's closed form), within the
tolerance the file justifies. The rest checks the command's contract: the JSON keys, exit 1
on a failed case, exit 2 with one line on bad input, the hazard cases skipped without a grid.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.casebook.load import load_casebook
from rockcli.casebook.run import Status, run_casebook
from rockcli.casebook.schema import Kind
from rockcli.cli.main import cli
from tests.casebook.conftest import CASEBOOK, CI_GRID, ROOT, SPECTRUM_CASE, write_casebook

#: Keys of the JSON contract (more may follow, none may go).
TOP_KEYS = {"schema", "rock_version", "cases", "passed", "failed"}
CASE_KEYS = {"id", "source", "quantity", "expected", "obtained", "tolerance", "passed"}
#: The whole casebook must run in about this long, warm (the calculation report runs it).


def invoke(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["validate", *args])
    return result.exit_code, result.stdout, result.stderr


# --- the bundled casebook -----------------------------------------------------------------------


def test_every_bundled_case_passes(no_grid: None) -> None:
    result = run_casebook()
    failed = [f"{c.id}: {c.obtained} vs {c.expected} ({c.note})" for c in result.cases
              if c.status is Status.FAILED]  # fmt: skip
    assert failed == []
    assert result.ok


def test_at_least_twenty_cases_over_every_topic() -> None:
    cases = load_casebook()
    assert len(cases) >= 20
    assert {c.case.kind for c in cases} == set(Kind)
    ids = {c.case.id for c in cases}
    # the topics, by the ids that carry them
    for prefix in ("free-rocking.period", "free-rocking.decay", "impulse.", "housner.rectangular",
                   "zhang-makris.", "makris-konstantinidis.", "paper.altar-a0", "paper.altar-d0",
                   "paper.altar-du", "paper.altar-Ts", "paper.eq18", "paper.table2", "ntc.",
                   "hazard.", "chopra.", "alpha0.roof", "alpha0.pretensioned", "floor.",
                   "suite."):  # fmt: skip
        assert any(i.startswith(prefix) for i in ids), prefix


def test_every_case_cites_a_source_and_a_reason() -> None:
    for loaded in load_casebook():
        case = loaded.case
        assert len(case.source) > 20, case.id
        assert len(case.tolerance_reason) > 10, case.id


# --- the command ------------------------------------------------------------------------------


def test_json_contract(no_grid: None) -> None:
    code, out, _ = invoke("--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert TOP_KEYS <= doc.keys()
    assert doc["schema"] == 1
    assert doc["passed"] + doc["failed"] + doc["skipped"] == len(doc["cases"])
    assert doc["failed"] == 0
    for case in doc["cases"]:
        assert CASE_KEYS <= case.keys()
        assert case["passed"] in (True, None)


def test_table_lists_case_source_and_result(no_grid: None) -> None:
    code, out, _ = invoke()
    assert code == 0
    for word in ("case", "source", "expected", "obtained", "error", "result"):
        assert word in out
    assert "paper.altar-Ts" in out and "pass" in out
    assert "cases:" in out and "0 failed" in out


def test_wrong_expected_value_exits_1(tmp_path: Path) -> None:
    wrong = SPECTRUM_CASE.replace("expected = 0.2070828", "expected = 0.25")
    folder = write_casebook(tmp_path / "book", SPECTRUM_CASE.replace("t.spectrum", "t.right")
                            + "\n" + wrong)  # fmt: skip
    code, out, err = invoke("--casebook", str(folder), "--format", "json")
    assert code == 1
    doc = json.loads(out)
    by_id = {c["id"]: c for c in doc["cases"]}
    assert by_id["t.spectrum"]["passed"] is False
    assert by_id["t.right"]["passed"] is True
    assert (doc["passed"], doc["failed"]) == (1, 1)
    assert err.strip() == "rock validate: 2 cases: 1 passed, 1 failed, 0 skipped"


def test_threshold_outside_the_bracket_fails_the_case(tmp_path: Path) -> None:
    text = (CASEBOOK / "thresholds.toml").read_text(encoding="utf-8")
    first = text[: text.index("[[cases]]", text.index("[[cases]]") + 1)]
    moved = first.replace("bracket = [0.40, 0.48]", "bracket = [0.30, 0.40]")
    code, out, _ = invoke("--casebook", str(write_casebook(tmp_path, moved)), "--format", "json")
    assert code == 1
    case = json.loads(out)["cases"][0]
    assert case["obtained"] is None and case["passed"] is False
    assert "does not flip" in case["note"]


BAD_INPUT = [
    ("malformed TOML", SPECTRUM_CASE.replace('kind = "spectrum"', "kind = spectrum"),
     "line 4"),
    ("missing field", SPECTRUM_CASE.replace('source = "closed form: NTC 2018 §3.2.3.2.1"\n', ""),
     "cases[0].source: "),
    ("unknown kind", SPECTRUM_CASE.replace('kind = "spectrum"', 'kind = "oracle"'),
     "cases[0].kind"),
    ("unknown quantity", SPECTRUM_CASE.replace('quantity = "Se"', 'quantity = "Sa"'),
     "cases[0].quantity: not a quantity of kind 'spectrum'"),
    ("negative tolerance", SPECTRUM_CASE.replace("tolerance = 1e-12", "tolerance = -1e-3"),
     "cases[0].tolerance"),
    ("unknown tolerance type", SPECTRUM_CASE.replace('"relative"', '"percent"'),
     "cases[0].tolerance_type"),
    ("relative to zero", SPECTRUM_CASE.replace("expected = 0.2070828", "expected = 0.0"),
     "cases[0].tolerance_type"),
    ("unknown input key", SPECTRUM_CASE.replace("period = 0.30", "periode = 0.30"),
     "cases[0].input.periode"),
    ("bad input value", SPECTRUM_CASE.replace('soil = "A"', 'soil = "Z"'),
     "cases[0].input.soil"),
    ("model for a kind without", SPECTRUM_CASE.replace("[cases.input]",
     'model = "wall.toml"\n[cases.input]'), "cases[0].model"),
    ("no model for a rocking kind", SPECTRUM_CASE.replace('kind = "spectrum"', 'kind = "impulse"')
     .replace('quantity = "Se"', 'quantity = "omega_threshold"'), "cases[0].model"),
    ("missing model file", SPECTRUM_CASE.replace('kind = "spectrum"', 'kind = "kinematic"')
     .replace('quantity = "Se"', 'quantity = "alpha0"')
     .replace(SPECTRUM_CASE[SPECTRUM_CASE.index("[cases.input]"):], 'model = "absent.toml"\n'),
     "absent.toml"),
    ("repeated id", SPECTRUM_CASE + "\n" + SPECTRUM_CASE, "repeated case id"),
    # A number written as text was converted on main (pydantic's lax mode): refused now.
    ("expected as text", SPECTRUM_CASE.replace("expected = 0.2070828",
     'expected = "0.2070828"'), "cases[0].expected: not a number (got '0.2070828'"),
    ("tolerance as text", SPECTRUM_CASE.replace("tolerance = 1e-12", 'tolerance = "1e-12"'),
     "cases[0].tolerance: not a number"),
    ("input as text", SPECTRUM_CASE.replace("period = 0.30", 'period = "0.30"'),
     "cases[0].input.period: not a number"),
    ("input as a boolean", SPECTRUM_CASE.replace("period = 0.30", "period = true"),
     "cases[0].input.period: not a number"),
    ("no cases", "# nothing here\n", "cases"),
]  # fmt: skip


@pytest.mark.parametrize(("text", "where"), [(t, w) for _, t, w in BAD_INPUT],
                         ids=[name for name, _, _ in BAD_INPUT])  # fmt: skip
def test_bad_case_file_exits_2_with_one_line(tmp_path: Path, text: str, where: str) -> None:
    folder = write_casebook(tmp_path / "book", text)
    code, out, err = invoke("--casebook", str(folder))
    assert code == 2, out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert where in lines[0]
    assert "Traceback" not in err + out


def test_bad_inline_model_names_the_case(tmp_path: Path) -> None:
    text = (CASEBOOK / "free-rocking.toml").read_text(encoding="utf-8")
    bad = text.replace("{ R = 1.0, alpha = 0.2 }", "{ R = -1.0, alpha = 0.2 }", 1)
    code, _, err = invoke("--casebook", str(write_casebook(tmp_path, bad)))
    assert code == 2
    assert "cases[0].model" in err and "geometry.R" in err
    assert "Traceback" not in err


def test_not_a_folder_exits_2(tmp_path: Path) -> None:
    # A missing folder is named before the command runs (issue 19), a file is refused by
    # the option's type: each one `error:` line.
    code, _, err = invoke("--casebook", str(tmp_path / "absent"))
    assert code == 2
    assert err == f"error: {tmp_path / 'absent'}: --casebook: the folder does not exist\n"
    (tmp_path / "file").write_text("", encoding="utf-8")
    code, _, err = invoke("--casebook", str(tmp_path / "file"))
    assert code == 2 and err.startswith("error: invalid value for '--casebook'")
    assert "is a file" in err and err.count("\n") == 1


# --- the hazard-grid cases ----------------------------------------------------------------------


def test_hazard_cases_skip_without_a_grid(no_grid: None) -> None:
    result = run_casebook()
    hazard = [c for c in result.cases if c.kind in ("hazard", "damage-rate")]
    assert {c.kind for c in hazard} == {"hazard", "damage-rate"}
    for case in hazard:
        assert case.status is Status.SKIPPED and case.passed is None
        assert "no hazard grid given" in case.note
    assert result.count(Status.SKIPPED) == len(hazard)


def test_hazard_cases_pass_with_the_grid(grid_file: Path) -> None:
    result = run_casebook(grid_file=str(grid_file))
    hazard = [c for c in result.cases if c.kind == "hazard"]
    assert hazard and all(c.status is Status.PASSED for c in hazard)
    assert result.count(Status.SKIPPED) == 0


def test_grid_from_the_environment(
    grid_file: Path, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("ROCK_HAZARD_GRID", str(grid_file))
    text = (CASEBOOK / "hazard.toml").read_text(encoding="utf-8")
    result = run_casebook(write_casebook(tmp_path, text))
    assert result.cases and all(c.status is Status.PASSED for c in result.cases)


def test_ci_runs_the_casebook(grid_file: Path) -> None:
    # How CI runs it: from the repository, the shared grid beside the clone.
    done = subprocess.run(
        [sys.executable, "-m", "rockcli", "validate", "--hazard-grid", CI_GRID],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "0 failed, 0 skipped" in done.stdout
