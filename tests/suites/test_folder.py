"""A folder of records as the suite (`--suite DIR --target KEY=VALUE,…`), and a suite that
lists one motion twice under two files."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.suites.load import load_suite, parse_target
from tests.suites.conftest import PULSES, ROOT, TARGET, pulse_copies, write_suite

WALL = ROOT / "examples" / "wall.toml"
TARGET_TEXT = ",".join(f"{k}={v}" for k, v in TARGET.items())


def invoke(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def folder_of_pulses(tmp_path: Path) -> Path:
    """The three shipped pulses and two files that are not records (notes, metadata)."""
    folder = tmp_path / "records"
    folder.mkdir()
    for p in PULSES:
        shutil.copyfile(p, folder / p.name)
    (folder / "README.md").write_text("notes\n", encoding="utf-8")
    (folder / "meta.csv").write_text("a,b\n", encoding="utf-8")
    return folder


def test_a_folder_is_the_suite_of_its_record_files(tmp_path: Path) -> None:
    folder = folder_of_pulses(tmp_path)
    settings = load_suite(folder, target=TARGET_TEXT)
    assert [e.path.name for e in settings.entries] == sorted(p.name for p in PULSES)
    assert all(e.scale == 1.0 for e in settings.entries)
    assert settings.target.parameters == (TARGET["ag"], TARGET["F0"], TARGET["Tc_star"])
    assert settings.name == "records"


def test_a_folder_checks_as_the_same_suite_written_out(tmp_path: Path) -> None:
    # The same three records in a suite file give the same numbers, to the last digit.
    folder = folder_of_pulses(tmp_path)
    file = write_suite(tmp_path, [{"path": str(folder / p.name)} for p in sorted(PULSES)])
    code, out, err = invoke("suite", "check", str(folder), "--target", TARGET_TEXT,
                            "--format", "json")  # fmt: skip
    assert code == 0, err
    from_folder = json.loads(out)
    from_file = json.loads(invoke("suite", "check", str(file), "--format", "json")[1])
    assert from_folder["mean"] == from_file["mean"]
    assert from_folder["target"] == from_file["target"]


def test_assess_and_compare_take_a_folder(tmp_path: Path) -> None:
    folder = folder_of_pulses(tmp_path)
    code, out, err = invoke("assess", str(WALL), "--suite", str(folder), "--target", TARGET_TEXT,
                            "--format", "json")  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["suite"]["n"] == 3
    code, out, err = invoke("compare", str(WALL), "--suite", str(folder), "--target", TARGET_TEXT,
                            "--code-demand", "suite-mean", "--format", "json")  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["suite"]["n"] == 3


@pytest.mark.parametrize(
    ("target", "expected"),
    [
        ("lon=13.4,lat=42.35", {"lon": 13.4, "lat": 42.35}),
        ("ag=0.25, F0=2.5 ,Tc_star=0.3,soil=B,edition=2018",
         {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3, "soil": "B", "edition": 2018}),
    ],
)  # fmt: skip
def test_target_text(target: str, expected: dict) -> None:
    assert parse_target(target) == expected


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--target", "lon13"), "error: --target: not a KEY=VALUE pair (got 'lon13'"),
        (("--target", "ag=0.2,ag=0.3"), "error: --target: key given twice"),
        (("--target", "ag=0.2,F0=2.5,Tc_star=0.3,soil=Q"), "--target soil: unknown value"),
        (("--target", "ag=0.2"), "--target F0: missing key"),
        (("--target", "ag=0.2,F0=2.5,Tc_star=0.3,colour=red"), "--target colour: unknown key"),
        ((), "--target: a folder of records needs its target spectrum"),
    ],
)
def test_bad_target(tmp_path: Path, args: tuple[str, ...], message: str) -> None:
    folder = folder_of_pulses(tmp_path)
    code, out, err = invoke("suite", "check", str(folder), *args)
    assert code == 2 and message in err and len(err.strip().splitlines()) == 1, err


def test_target_with_a_suite_file_or_a_record_is_refused(tmp_path: Path) -> None:
    file = write_suite(tmp_path, [{"path": str(p)} for p in pulse_copies(tmp_path, 3)])
    code, _, err = invoke("suite", "check", str(file), "--target", TARGET_TEXT)
    assert code == 2 and "--target: not used: a suite file has its own [target]" in err
    code, _, err = invoke("assess", str(WALL), "--record", str(PULSES[0]), "--target", "ag=1")
    assert code == 2 and "--target: applies only to a folder of records" in err


def test_a_folder_with_too_few_records(tmp_path: Path) -> None:
    folder = tmp_path / "two"
    folder.mkdir()
    for p in PULSES[:2]:
        shutil.copyfile(p, folder / p.name)
    code, _, err = invoke("suite", "check", str(folder), "--target", TARGET_TEXT)
    assert code == 2 and "records: too few records" in err


def test_one_motion_under_two_files_is_refused(tmp_path: Path) -> None:
    # A copy of a record under another name (and with other line ends) is one record for the
    # code's count: the suite is refused, naming both entries.
    copy = tmp_path / "copy.txt"
    copy.write_bytes(PULSES[0].read_bytes().replace(b"\n", b"\r\n"))
    records = [{"path": str(p)} for p in PULSES] + [{"path": str(copy)}]
    file = write_suite(tmp_path, records)
    code, _, err = invoke("suite", "check", str(file))
    assert code == 2, err
    assert "records[3].path: record 'copy' is the same motion as" in err
    assert "(records[0])" in err
