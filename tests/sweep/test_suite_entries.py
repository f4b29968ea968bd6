"""A study whose [[records]] entry names a record suite: each case gets the suite's verdicts
(those of `rock compare MODEL --suite SUITE` for the case's model), and the summary counts
cases, not records."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.studies.sweep.output import fingerprint
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import BASE, WriteStudy

#: Three pulses with a target given by its parameters (SLV); the wall's base sets no code
#: spectrum, so the suite's studies below run with [ntc.demand] added (the code check needs
#: SLD too, from the model: docs/suites.md).
SUITE = """\
name = "three pulses"
[target]
ag = 0.25
F0 = 2.5
Tc_star = 0.3

[[records]]
path = "one-cosine_Tp2s_0.31g.txt"
[[records]]
path = "one-sine_Tp1s_0.35g.txt"
scale = 1.2
[[records]]
path = "ricker_Tp0.5s_0.5g.txt"
"""
DEMAND = """
[ntc.demand.SLD]
ag = 0.06
F0 = 2.5
Tc_star = 0.3
[ntc.demand.SLV]
ag = 0.15
F0 = 2.5
Tc_star = 0.3
"""
STUDY = """\
base = "wall.toml"
records_dir = "records"

[[axes]]
path = "geometry.alpha"
name = "alpha"
values = [0.1, 0.2]

[[axes]]
path = ["restrainers[0].k_pos", "restrainers[0].k_neg"]
name = "K"
values = [0.0, 1e6]

[[records]]
suite = "suite.toml"

[[records]]
path = "ricker_Tp0.5s_0.5g.txt"
name = "ricker"
"""


def write(write_study: WriteStudy, tmp_path: Path, study: str = STUDY, suite: str = SUITE) -> Path:
    (tmp_path / "records").mkdir(exist_ok=True)
    path = write_study(study, BASE + DEMAND)
    (tmp_path / "records" / "suite.toml").write_text(suite, encoding="utf-8")
    return path


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def cases(out: Path) -> list[dict[str, str]]:
    with open(out / "cases.csv", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_each_suite_case_is_the_suite_comparison_of_its_model(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = write(write_study, tmp_path)
    out = tmp_path / "out"
    code, _, err = run("sweep", str(study), "--out", str(out), "--jobs", "2", "--format", "json")
    assert code == 0, err
    rows = [r for r in cases(out) if r["record"] == "three pulses"]
    assert len(rows) == 4
    for row in rows:
        model = (tmp_path / "wall.toml").read_text(encoding="utf-8")
        model = model.replace("alpha = 0.1", f"alpha = {row['alpha']}")
        model = model.replace("k_pos = 0.0\nk_neg = 0.0", f"k_pos = {row['K']}\nk_neg = {row['K']}")
        alone = tmp_path / f"case{row['case']}.toml"
        alone.write_text(model, encoding="utf-8")
        suite = str(tmp_path / "records" / "suite.toml")
        code, out_text, err = run("compare", str(alone), "--suite", suite, "--format", "json")
        assert code == 0, err
        doc = json.loads(out_text)
        assert float(row["max_ratio"]) == doc["suite"]["measure"]
        assert row["rocking"] == ("passes" if doc["suite"]["verdict"] == "passes" else "fails")
        assert row["classification"] == doc["classification"]
        code_fails = doc["collapse"]["code"]  # None: not evaluated (a stiff spring, no d0*)
        assert row["code_state"] == {None: "", True: "fail", False: "pass"}[code_fails]
        assert (row["limit_state"], row["suite_rule"], row["suite_records"]) == (
            "SLV",
            "worst",
            "3",
        )
        assert int(row["suite_overturned"]) == doc["suite"]["overturned_records"]


def test_the_summary_counts_cases_not_records(write_study: WriteStudy, tmp_path: Path) -> None:
    study = write(write_study, tmp_path)
    out = tmp_path / "out"
    code, text, err = run("sweep", str(study), "--out", str(out), "--format", "json")
    assert code == 0, err
    doc = json.loads(text)
    assert doc["cases"] == 8  # 2 α × 2 K × (1 suite + 1 record)
    by_name = {r["record"]: r for r in doc["records"]}
    assert by_name["three pulses"]["cases"] == 4 and by_name["ricker"]["cases"] == 4
    assert by_name["three pulses"]["suite_records"] == 3
    assert by_name["three pulses"]["rule"] == "worst"
    # Both polarities of each of the suite's 3 records for 4 cases, and of 1 record for 4.
    assert doc["runs"] == 2 * 3 * 4 + 2 * 4
    rows = cases(out)
    collapses = sum(r["rocking"] in ("overturns", "fails") for r in rows)
    assert doc["rocking_collapses"] == collapses


def test_the_report_says_what_a_suite_entry_is(write_study: WriteStudy, tmp_path: Path) -> None:
    study = write(write_study, tmp_path)
    code, text, err = run("sweep", str(study), "--out", str(tmp_path / "out"))
    assert code == 0, err
    assert "three pulses: a suite of 3 records (each case counts once)" in text


def test_a_suite_record_edited_changes_the_fingerprint(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = write(write_study, tmp_path)
    before = fingerprint(load_study(str(study)))
    record = tmp_path / "records" / "one-cosine_Tp2s_0.31g.txt"
    record.write_text(record.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    assert fingerprint(load_study(str(study))) != before


@pytest.mark.parametrize(
    ("entry", "where", "problem"),
    [
        ('path = "ricker_Tp0.5s_0.5g.txt"\nsuite = "suite.toml"', "records[0]", "path and suite"),
        ('name = "nothing"', "records[0]", "give a record file or a suite file"),
        ('suite = "suite.toml"\nscale = 2.0', "records[0].scale", "not with suite"),
        ('suite = "none.toml"', "records[0].suite", "suite file not found"),
        ('suite = "../outside.toml"', "records[0].suite", "leaves the study's folder"),
    ],
)
def test_bad_suite_entries(
    write_study: WriteStudy, tmp_path: Path, entry: str, where: str, problem: str
) -> None:
    (tmp_path / "outside.toml").write_text(SUITE, encoding="utf-8")
    study = write(write_study, tmp_path, 'base = "wall.toml"\nrecords_dir = "records"\n'
                  f"[[records]]\n{entry}\n")  # fmt: skip
    with pytest.raises(InputError) as info:
        load_study(str(study))
    text = str(info.value)
    assert text.startswith(f"{study}: {where}: ") and problem in text


def test_a_suite_whose_records_leave_the_folder_is_refused(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    outside = tmp_path.parent / f"{tmp_path.name}-outside.txt"
    outside.write_text("0 0\n0.01 0.1\n0.02 0\n", encoding="utf-8")
    suite = SUITE.replace('path = "ricker_Tp0.5s_0.5g.txt"', f'path = "{outside}"')
    study = write(write_study, tmp_path, suite=suite)
    with pytest.raises(InputError) as info:
        load_study(str(study))
    assert "records[0].suite" in str(info.value) and "leaves the study's folder" in str(info.value)
    assert load_study(str(study), allow_outside=True).records[0].suite


def test_a_bad_suite_file_names_the_suite(write_study: WriteStudy, tmp_path: Path) -> None:
    short = SUITE.split("[[records]]")[0] + '[[records]]\npath = "ricker_Tp0.5s_0.5g.txt"\n'
    study = write(write_study, tmp_path, suite=short)
    code, _, err = run("sweep", str(study), "--out", str(tmp_path / "out"))
    assert code == 2 and "suite.toml" in err and len(err.strip().splitlines()) == 1


def test_an_absent_optional_suite_is_skipped(write_study: WriteStudy, tmp_path: Path) -> None:
    entry = 'suite = "none.toml"\noptional = true'
    study = write(write_study, tmp_path, STUDY.replace('suite = "suite.toml"', entry))
    plan = load_study(str(study))
    assert [r.name for r in plan.records] == ["ricker"]
    assert [s.name for s in plan.skipped] == ["none.toml"]
