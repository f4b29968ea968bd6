"""What a suite may read and which values it takes (issue 20, items 6, 8, 9, 10).

- A suite reads only files inside its own folder (``..``, absolute paths and symlinks to
  elsewhere refused) unless ``--allow-outside``, in every command that takes a suite; an
  unrecognised file is named, never quoted. On main a suite naming /etc/passwd printed its
  first line.
- A NUL in a record path, a period range or ``--period`` beyond the response spectra's periods
  are bad input (exit 2); on main they exited 3, or printed a NaN verdict with exit 0.
- A folder suite with a dangling ``*.AT2`` link is an error (main left the record out).
- ``period_range``/``tolerance`` written under ``[target]`` are named as top-level keys, and
  the shipped suite files and docs/suites.md show them above ``[target]``.
- ``--target`` numbers are ASCII: ``０.３`` (fullwidth) was read as 0.3 on main.
"""

from __future__ import annotations

import re
import shutil
import tomllib
from pathlib import Path

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD
from rockcli.suites.load import load_suite, validate_suite
from tests.suites.conftest import PULSES, ROOT, TARGET, write_suite

WALL = ROOT / "examples" / "wall.toml"
TARGET_TEXT = ",".join(f"{k}={v}" for k, v in TARGET.items())
#: A line no output may show: the content of a file a suite names.
SECRET = "root:x:0:0:SECRET-TOKEN-7f3a:/root:/bin/bash"


def invoke(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def one_error(code: int, out: str, err: str) -> str:
    """The one error line of a refused command (exit 2, no traceback)."""
    assert code == 2, out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert "Traceback" not in out + err
    return lines[0]


def suite_in(folder: Path, third: str) -> Path:
    """A suite in ``folder``: two shipped pulses copied beside it and ``third`` as written."""
    folder.mkdir(parents=True, exist_ok=True)
    records = [{"path": str(p)} for p in PULSES[:2]]
    path = write_suite(folder, records)
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["records"].append({"path": third})
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


@pytest.fixture
def secret(tmp_path: Path) -> Path:
    """A file outside the suite's folder whose first line is a secret."""
    path = tmp_path / "secret.txt"
    path.write_text(f"{SECRET}\nsecond line\n", encoding="utf-8")
    return path


# --- item 6: confinement -----------------------------------------------------------------------


@pytest.mark.parametrize("how", ["absolute", "dotdot", "symlink"])
def test_a_record_outside_the_suites_folder_is_refused(
    tmp_path: Path, secret: Path, how: str
) -> None:
    folder = tmp_path / "suite"
    folder.mkdir()
    if how == "symlink":
        (folder / "link.txt").symlink_to(secret)
    written = {"absolute": str(secret), "dotdot": "../secret.txt", "symlink": "link.txt"}[how]
    suite = suite_in(folder, written)
    line = one_error(*invoke("suite", "check", str(suite)))
    assert line.startswith(f"error: {suite}: records[2].path: leaves the suite's folder"), line
    assert "--allow-outside" in line and "SECRET" not in line


def test_allow_outside_reads_it_and_never_quotes_it(tmp_path: Path, secret: Path) -> None:
    suite = suite_in(tmp_path / "suite", str(secret))
    code, out, err = invoke("suite", "check", str(suite), "--allow-outside")
    line = one_error(code, out, err)
    assert "unrecognised record format" in line and str(secret) in line
    assert "PEER AT2" in line  # the formats rock reads, instead of the file's content
    assert "SECRET" not in out + err


def test_allow_outside_lets_a_suite_use_records_elsewhere(tmp_path: Path) -> None:
    suite = tmp_path / "suite" / "suite.toml"
    suite.parent.mkdir()
    records = [{"path": str(p)} for p in PULSES]  # absolute paths to the shipped pulses
    suite.write_text(tomli_w.dumps({"name": "s", "target": TARGET, "records": records}))
    assert "leaves the suite's folder" in one_error(*invoke("suite", "check", str(suite)))
    code, _, err = invoke("suite", "check", str(suite), "--allow-outside")
    assert code == 0, err
    assert len(load_suite(suite, allow_outside=True).entries) == 3


def test_a_folder_suite_refuses_a_link_to_elsewhere(tmp_path: Path, secret: Path) -> None:
    folder = tmp_path / "records"
    folder.mkdir()
    for pulse in PULSES:
        shutil.copyfile(pulse, folder / pulse.name)
    (folder / "zz.txt").symlink_to(secret)
    line = one_error(*invoke("suite", "check", str(folder), "--target", TARGET_TEXT))
    assert "records[3].path: leaves the suite's folder" in line and "SECRET" not in line


@pytest.mark.parametrize(
    "command",
    [["assess", str(WALL)], ["compare", str(WALL)], ["report", str(WALL), "-o", "r.html"]],
    ids=lambda c: c[0],
)
def test_every_command_that_takes_a_suite_confines_it(
    tmp_path: Path, secret: Path, command: list[str]
) -> None:
    suite = suite_in(tmp_path / "suite", str(secret))
    line = one_error(*invoke(*command, "--suite", str(suite)))
    assert "records[2].path: leaves the suite's folder" in line and "SECRET" not in line
    line = one_error(*invoke(*command, "--suite", str(suite), "--allow-outside"))
    assert "unrecognised record format" in line and "SECRET" not in line


def test_allow_outside_without_a_suite_is_refused() -> None:
    line = one_error(*invoke("assess", str(WALL), "--record", str(PULSES[0]), "--allow-outside"))
    assert line.startswith("error: --allow-outside: applies only to a suite"), line


# --- items 8 and 9: NUL, period bounds ---------------------------------------------------------


@pytest.mark.parametrize("allow", [[], ["--allow-outside"]], ids=["confined", "allow-outside"])
def test_a_nul_in_a_record_path_is_bad_input(tmp_path: Path, allow: list[str]) -> None:
    suite = suite_in(tmp_path, "a\x00b.txt")
    line = one_error(*invoke("suite", "check", str(suite), *allow))
    assert line.startswith(f"error: {suite}: records[2].path: a NUL character in the path"), line


@pytest.mark.parametrize(
    "args",
    [
        ["suite", "check", "a\x00b.toml"],
        ["record", "info", "a\x00b.AT2"],
        ["kinematic", "a\x00b.toml"],
        ["assess", str(WALL), "--record", "a\x00b.AT2"],
        ["assess", str(WALL), "--suite", "a\x00b"],
    ],
    ids=lambda a: " ".join(a[:2]),
)
def test_a_nul_in_a_path_option_is_bad_input(args: list[str]) -> None:
    # A shell cannot pass a NUL; a program calling rock's CLI in process can.
    one_error(*invoke(*args))


@pytest.mark.parametrize(
    "period_range", [[0.15, 1e300], [1e-300, 1e-299], [0.15, MAX_PERIOD * 1.001], [1e-4, 2.0]]
)
def test_a_period_range_beyond_the_spectras_periods_is_refused(
    tmp_path: Path, period_range: list[float]
) -> None:
    # On main [0.15, 1e300] exited 3 (OverflowError) and [1e-300, 1e-299] printed a NaN
    # verdict with exit 0.
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES], period_range=period_range)
    line = one_error(*invoke("suite", "check", str(suite)))
    assert line.startswith(f"error: {suite}: period_range: period range out of bounds"), line
    assert f"{MIN_PERIOD:g} s to {MAX_PERIOD:g} s" in line


def test_the_widest_period_range_runs(tmp_path: Path) -> None:
    suite = write_suite(
        tmp_path, [{"path": str(p)} for p in PULSES], period_range=[MIN_PERIOD, MAX_PERIOD]
    )
    code, out, err = invoke("suite", "check", str(suite), "--format", "json")
    assert code == 0, err
    assert "nan" not in out.lower()


@pytest.mark.parametrize("value", ["1e300", "10.001", "1e-300"])
def test_a_period_beyond_a_buildings_periods_is_refused(tmp_path: Path, value: str) -> None:
    # On main --period 1e300 exited 3 (OverflowError). T bounded as a model's building.T1
    # (rockcli.model.bounds: 0.01–10 s), so the check's 2T stays within the spectra's 100 s.
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    line = one_error(*invoke("suite", "check", str(suite), "--period", value))
    assert line.startswith("error: --period: out of range"), line
    assert "0.01 s ≤ T ≤ 10 s" in line


# --- item 10: dangling links, top-level keys, ASCII numbers ------------------------------------


def test_a_dangling_link_in_a_folder_suite_is_an_error(tmp_path: Path) -> None:
    # On main the link was left out silently: 7 files became a suite of 6 (the worst rule).
    folder = tmp_path / "records"
    folder.mkdir()
    for pulse in PULSES:
        shutil.copyfile(pulse, folder / pulse.name)
    (folder / "moved.AT2").symlink_to(tmp_path / "elsewhere" / "moved.AT2")
    line = one_error(*invoke("suite", "check", str(folder), "--target", TARGET_TEXT))
    assert line.startswith(f"error: {folder / 'moved.AT2'}: a link to a file that does not"), line


def test_a_subfolder_with_a_records_suffix_is_an_error(tmp_path: Path) -> None:
    folder = tmp_path / "records"
    folder.mkdir()
    for pulse in PULSES:
        shutil.copyfile(pulse, folder / pulse.name)
    (folder / "more.txt").mkdir()
    line = one_error(*invoke("suite", "check", str(folder), "--target", TARGET_TEXT))
    assert "more.txt: not a regular file (a folder)" in line


@pytest.mark.parametrize("key", ["period_range", "tolerance"])
def test_a_top_level_key_under_target_is_named(tmp_path: Path, key: str) -> None:
    text = (
        'name = "s"\n[target]\nag = 0.25\nF0 = 2.5\nTc_star = 0.3\n'
        f"{key} = [0.15, 2.0]\n" + "".join(f'[[records]]\npath = "{p.name}"\n' for p in PULSES)
    )
    for pulse in PULSES:
        shutil.copyfile(pulse, tmp_path / pulse.name)
    (tmp_path / "suite.toml").write_text(text, encoding="utf-8")
    line = one_error(*invoke("suite", "check", str(tmp_path / "suite.toml")))
    assert f"target.{key}: a top-level key, write it above [target]" in line, line


def suite_texts() -> list[tuple[str, str]]:
    """(name, text) of every suite file shipped and every suite block of docs/suites.md."""
    found = [(p.name, p.read_text(encoding="utf-8"))
             for p in sorted((ROOT / "examples" / "suites").glob("*.toml"))]  # fmt: skip
    page = (ROOT / "docs" / "suites.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```toml\n(.*?)^```", page, re.S | re.M)
    found += [(f"suites.md#{i}", b) for i, b in enumerate(blocks) if "[target]" in b]
    return found


@pytest.mark.parametrize(("name", "text"), suite_texts(), ids=lambda v: v[:30])
def test_the_shipped_suites_keys_are_valid_when_uncommented(name: str, text: str) -> None:
    # The commented-out period_range/tolerance lines are what a user uncomments: on main they
    # sat after [target], where TOML puts them inside it and rock refuses them.
    uncommented = re.sub(r"^# ((?:period_range|tolerance) = )", r"\1", text, flags=re.M)
    assert uncommented != text, f"{name} shows no period_range/tolerance line"
    data = tomllib.loads(uncommented)
    if len(data.get("records", [])) < 3:  # a docs block shows one [[records]]: "…"
        data["records"] = [{"path": f"r{i}.AT2"} for i in range(3)]
    suite = validate_suite(data, name)
    assert suite.period_range == [0.15, 2.0] and suite.tolerance == [-0.10, 0.30]


@pytest.mark.parametrize("value", ["０.２５", "٠.٢٥"])
def test_target_numbers_are_ascii(tmp_path: Path, value: str) -> None:
    folder = tmp_path / "records"
    folder.mkdir()
    for pulse in PULSES:
        shutil.copyfile(pulse, folder / pulse.name)
    target = TARGET_TEXT.replace("ag=0.25", f"ag={value}")
    line = one_error(*invoke("suite", "check", str(folder), "--target", target))
    assert "--target ag: not a number" in line, line  # on main: read as 0.25, exit 0
    with pytest.raises(InputError):
        load_suite(folder, target=target)
