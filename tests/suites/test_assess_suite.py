"""`rock assess MODEL --suite SUITE`: every record, both polarities, the code's rule."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import ROOT
from tests.suites.conftest import multiple_of

WALL = ROOT / "examples" / "wall.toml"
PULSES = sorted((ROOT / "records").glob("*.txt"))


def suite_file(tmp_path: Path, n: int = 3) -> Path:
    """A suite of the shipped pulses (past three, the pulses times 2, 3, … in files of their
    own: a suite holds each motion once) with a target given by its parameters (no hazard
    grid needed)."""
    paths = [multiple_of(PULSES[k % 3], tmp_path / f"r{k}.txt", 1 + k // 3) for k in range(n)]
    entries = "".join(
        f'[[records]]\npath = "{path}"\nname = "r{k}"\nscale = {1 + k / 10}\n\n'
        for k, path in enumerate(paths)
    )
    path = tmp_path / "suite.toml"
    path.write_text(
        'name = "pulses"\n[target]\nag = 0.2\nF0 = 2.5\nTc_star = 0.3\n\n' + entries,
        encoding="utf-8",
    )
    return path


def run(*args: str):
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_three_records_take_the_worst(tmp_path: Path) -> None:
    code, out, err = run("assess", str(WALL), "--suite", str(suite_file(tmp_path)),
                         "--format", "json")  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    suite = doc["suite"]
    assert set(suite) == {"n", "rule", "measure", "limit_ratio", "verdict",
                          "overturned_records", "records", "compatibility"}  # fmt: skip
    assert (suite["n"], suite["rule"], suite["limit_ratio"]) == (3, "worst", 1.0)
    ratios = [r["max_ratio"] for r in suite["records"]]
    assert suite["measure"] == max(ratios)
    assert suite["overturned_records"] == sum(r["overturned"] for r in suite["records"])
    assert [r["scale"] for r in suite["records"]] == [1.0, 1.1, 1.2]
    assert set(suite["compatibility"]) == {"passed", "period_range", "min_ratio", "max_ratio"}


def test_each_record_is_what_assess_says_of_it_alone(tmp_path: Path) -> None:
    # The second record is the one-sine pulse scaled by 1.1: `rock assess --record … --scale
    # 1.1` gives the same max θ/α (the same engine on the same scaled record).
    doc = json.loads(run("assess", str(WALL), "--suite", str(suite_file(tmp_path)),
                         "--format", "json")[1])  # fmt: skip
    alone = json.loads(run("assess", str(WALL), "--record", str(PULSES[1]), "--scale", "1.1",
                           "--format", "json")[1])  # fmt: skip
    assert doc["suite"]["records"][1]["max_ratio"] == alone["max_ratio"]


def test_seven_records_take_the_mean_and_the_table_reads(tmp_path: Path) -> None:
    code, out, err = run("assess", str(WALL), "--suite", str(suite_file(tmp_path, 7)))
    assert code == 0, err
    assert "Records of the suite, both polarities" in out
    last = " ".join(out[out.rindex("verdict: ") :].split())  # the verdict wraps within 100 columns
    assert "the mean of max θ/α over 7 records" in last


@pytest.mark.parametrize(
    ("extra", "where"),
    [
        (("--record", str(PULSES[0])), "--suite"),
        (("--history", "h.csv"), "--history"),
        (("--plot", "p.png"), "--plot"),
        (("--scale", "2"), "--scale"),
    ],
)
def test_one_record_options_with_a_suite_are_one_line(tmp_path: Path, extra, where) -> None:
    code, out, err = run("assess", str(WALL), "--suite", str(suite_file(tmp_path)), *extra)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and where in err


def test_neither_a_record_nor_a_suite_is_one_line() -> None:
    code, out, err = run("assess", str(WALL))
    assert code == 2 and out == "" and "--record" in err and err.count("\n") == 1


def test_a_hazard_grid_without_a_suite_is_one_line() -> None:
    code, _, err = run("assess", str(WALL), "--record", str(PULSES[0]), "--hazard-grid", "g.txt")
    assert code == 2 and "--hazard-grid" in err


def test_the_models_limit_for_the_targets_limit_state_applies(tmp_path: Path) -> None:
    # [analysis] limit_ratio = {SLV = 0.05}: the suite's target is SLV (its default), so the
    # measure is held to 0.05 instead of 1; another state's limit does not apply.
    suite = suite_file(tmp_path)
    text = WALL.read_text(encoding="utf-8")
    assert "[analysis]" not in text
    for limits, expected in (("{SLV = 0.05}", 0.05), ("{SLC = 0.05}", 1.0)):
        model = tmp_path / "wall.toml"
        model.write_text(f"{text}\n[analysis]\nlimit_ratio = {limits}\n", encoding="utf-8")
        doc = json.loads(run("assess", str(model), "--suite", str(suite), "--format", "json")[1])
        assert doc["suite"]["limit_ratio"] == expected


@pytest.mark.parametrize("limits", ["{SLX = 1.0}", "{SLV = 0}", "{SLV = -1}", "{SLV = 1e9}"])
def test_a_bad_limit_is_one_line(tmp_path: Path, limits: str) -> None:
    model = tmp_path / "wall.toml"
    model.write_text(f"{WALL.read_text()}\n[analysis]\nlimit_ratio = {limits}\n")
    code, out, err = run("assess", str(model), "--suite", str(suite_file(tmp_path)))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "analysis.limit_ratio" in err
