"""Every bad suite file is one line on stderr naming the file, the key or record entry, the
value and what is allowed, and exit code 2 (never a traceback)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.suites.conftest import PULSES, TARGET, write_suite

THREE = [{"path": str(p)} for p in PULSES]


def refused(path: Path, *extra: str) -> str:
    """The one error line of `rock suite check` on ``path`` (exit 2)."""
    result = CliRunner().invoke(cli, ["suite", "check", str(path), *extra])
    assert result.exit_code == 2, result.output + result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert "Traceback" not in result.output + result.stderr
    return lines[0]


CASES: dict[str, tuple[dict[str, Any], str]] = {
    "two records": ({"records": THREE[:2]}, "records: too few records"),
    "no records": ({"records": []}, "records: too few records"),
    "same path twice": (
        {"records": [*THREE, THREE[0]]},
        "records[3]: record listed twice (the same path as records[0])",
    ),
    "same name twice": (
        {"records": [{**r, "name": "A"} if i < 2 else r for i, r in enumerate(THREE)]},
        "records[1]: record listed twice (the same name as records[0])",
    ),
    "scale zero": (
        {"records": [{**THREE[0], "scale": 0}, *THREE[1:]]},
        "records[0].scale: out of range (got 0; allowed: a number > 0)",
    ),
    "scale negative": (
        {"records": [{**THREE[0], "scale": -1.5}, *THREE[1:]]},
        "records[0].scale: out of range (got -1.5; allowed: a number > 0)",
    ),
    "empty range": ({"period_range": [1.0, 1.0]}, "period_range: not a period range"),
    "inverted range": ({"period_range": [2.0, 0.15]}, "period_range: not a period range"),
    "range at zero": ({"period_range": [0.0, 2.0]}, "period_range: not a period range"),
    "range of three": ({"period_range": [0.1, 1.0, 2.0]}, "period_range: not a period range"),
    "tolerance -100 %": ({"tolerance": [-1.0, 0.3]}, "tolerance: not a tolerance band"),
    "tolerance below -100 %": ({"tolerance": [-1.5, 0.3]}, "tolerance: not a tolerance band"),
    "tolerance lo = hi": ({"tolerance": [0.1, 0.1]}, "tolerance: not a tolerance band"),
    "tolerance lo > hi": ({"tolerance": [0.3, -0.1]}, "tolerance: not a tolerance band"),
    "tolerance nan": ({"tolerance": [float("nan"), 0.3]}, "tolerance: not a tolerance band"),
    "no target values": ({"target": {"soil": "B"}}, "target: no site and no parameters"),
    "site and parameters": (
        {"target": {**TARGET, "lon": 13.4, "lat": 42.35}},
        "target: both a site and spectrum parameters",
    ),
    "half a site": ({"target": {"lon": 13.4}}, "target.lat: missing key"),
    "two parameters": ({"target": {"ag": 0.2, "F0": 2.4}}, "target.Tc_star: missing key"),
    "unknown limit state": (
        {"target": {**TARGET, "limit_state": "ULS"}},
        "target.limit_state: unknown value (got 'ULS'; allowed: one of: 'SLO', 'SLD', 'SLV' or",
    ),
    "unknown edition": (
        {"target": {**TARGET, "edition": 2012}},
        "target.edition: unknown value (got '2012'",
    ),
    "unknown key": ({"colour": "red"}, "colour: unknown key"),
    "scale as text": (
        {"records": [{**THREE[0], "scale": "2"}, *THREE[1:]]},
        "records[0].scale: not a number (got '2'",
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_suite_is_one_line_exit_2(tmp_path: Path, case: str) -> None:
    keys, expected = CASES[case]
    records = keys.pop("records", THREE) if "records" in keys else THREE
    path = write_suite(tmp_path, records, **{k: v for k, v in keys.items() if k != "records"})
    line = refused(path)
    assert line.startswith(f"error: {path}: {expected}"), line


def test_missing_record_names_the_suite_and_the_entry(tmp_path: Path) -> None:
    path = write_suite(tmp_path, [*THREE, {"path": "nowhere.AT2", "name": "lost"}])
    line = refused(path)
    assert line.startswith(f"error: {path}: records[3].path: record 'lost' does not read: ")
    assert "cannot read the record file" in line and "nowhere.AT2" in line


def test_damaged_record_names_the_suite_and_the_entry(tmp_path: Path) -> None:
    (tmp_path / "bad.txt").write_text("0.0 0.1\n0.01 oops\n", encoding="utf-8")
    path = write_suite(tmp_path, [*THREE, {"path": "bad.txt"}])
    line = refused(path)
    assert line.startswith(f"error: {path}: records[3].path: record 'bad' does not read: ")


def test_record_scaled_beyond_plausible_is_refused(tmp_path: Path) -> None:
    path = write_suite(tmp_path, [{**THREE[0], "scale": 1e6}, *THREE[1:]])
    line = refused(path)
    assert line.startswith(f"error: {path}: records[0].scale: the scaled record would reach"), line


def test_record_of_zeros_is_refused(tmp_path: Path) -> None:
    # A file that parses but holds no motion: its spectrum is zero, no check means anything.
    (tmp_path / "zero.txt").write_text("0 0\n0.01 0\n0.02 0\n", encoding="utf-8")
    path = write_suite(tmp_path, [*THREE, {"path": "zero.txt"}])
    line = refused(path)
    assert line.startswith(f"error: {path}: records[3].path: record 'zero' is zero everywhere")


def test_site_outside_the_grid_names_the_suite(tmp_path: Path, grid_file: Path) -> None:
    path = write_suite(tmp_path, THREE, target={"lon": 0.0, "lat": 0.0})
    line = refused(path, "--hazard-grid", str(grid_file))
    assert line.startswith(f"error: {path}: site: site outside the NTC hazard grid"), line


def test_malformed_toml(tmp_path: Path) -> None:
    path = tmp_path / "suite.toml"
    path.write_text('name = "x"\n[target\n', encoding="utf-8")
    assert refused(path).startswith(f"error: {path}: line 2")


def test_missing_suite_file(tmp_path: Path) -> None:
    # Named before the command runs (issue 19): a suite file or a folder of records.
    path = tmp_path / "absent.toml"
    assert refused(path) == f"error: {path}: SUITE: no file or folder of that name"


def test_period_conflicts_with_the_files_range(tmp_path: Path) -> None:
    path = write_suite(tmp_path, THREE, period_range=[0.1, 1.0])
    assert refused(path, "--period", "0.5").startswith("error: --period: conflicts with")


@pytest.mark.parametrize("value", ["0", "-1", "nan", "inf", "1e300", "1e-300", "10.5"])
def test_bad_period(tmp_path: Path, value: str) -> None:
    # Issue 20, item 8: 1e300 exited 3 (an overflow in the spectra up to 2T), 1e-300 passed;
    # T is bounded as a model's building.T1, 0.01 to 10 s.
    path = write_suite(tmp_path, THREE)
    line = refused(path, "--period", value)
    assert line.startswith("error: --period: out of range") and "0.01 s ≤ T ≤ 10 s" in line


def test_grid_without_a_site_is_refused(tmp_path: Path) -> None:
    path = write_suite(tmp_path, THREE)
    assert refused(path, "--hazard-grid", "grid.txt").startswith("error: --hazard-grid: not used")


def test_site_without_a_grid_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROCK_HAZARD_GRID", raising=False)
    path = write_suite(tmp_path, THREE, target={"lon": 13.4, "lat": 42.35})
    assert "no hazard grid file given" in refused(path)
