"""Issue 7, items 9, 14, 17 and 18 (sweep part): a study from an untrusted source, damaged
output folders, bad options, and the cases without a verdict."""

from __future__ import annotations

import csv
import json
import os
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.cli.sweep import OUT_NAME_MAX, default_out
from rockcli.errors import InputError
from rockcli.studies.parallel.executor import check_address, local_executor
from rockcli.studies.sweep.output import cell, escape, unescape
from rockcli.studies.sweep.run import run_sweep
from rockcli.studies.sweep.study import load_study
from rockcli.studies.sweep.summary import tally
from rockcli.terminal.sweep import _cell, printable
from tests.sweep.conftest import STUDY, WriteStudy

N_CASES = 16  # conftest.STUDY


def sweep(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["sweep", *args])
    return result.exit_code, result.stdout, result.stderr


# --- item 14: paths stay in the study's folder -------------------------------------------


@pytest.mark.parametrize(
    ("old", "new", "where"),
    [
        ('base = "wall.toml"', 'base = "../wall.toml"', "base"),
        ('records_dir = "records"', 'records_dir = "../records"', "records_dir"),
        ('path = "ricker_Tp0.5s_0.5g.txt"', 'path = "/etc/hostname"', "records[1].path"),
        ('path = "ricker_Tp0.5s_0.5g.txt"', 'path = "../../x.txt"', "records[1].path"),
    ],
)
def test_a_path_leaving_the_study_folder_needs_the_flag(
    write_study: WriteStudy, tmp_path: Path, old: str, new: str, where: str
) -> None:
    inner = tmp_path / "inner"
    inner.mkdir()
    shutil.copytree(tmp_path / "records", inner / "records")
    study = write_study(STUDY.replace(old, new), name="inner/study.toml")
    (inner / "wall.toml").write_text((tmp_path / "wall.toml").read_text())
    with pytest.raises(InputError) as info:
        load_study(str(study))
    assert f"{where}: leaves the study's folder" in str(info.value)


def test_a_symlinked_record_leaving_the_folder_needs_the_flag(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    (tmp_path / "records" / "link.txt").symlink_to(tmp_path / "wall.toml")
    (tmp_path / "records" / "link.txt").unlink()
    outside = tmp_path.parent / f"{tmp_path.name}-outside.txt"
    outside.write_text("0.0\n")
    (tmp_path / "records" / "link.txt").symlink_to(outside)
    study = write_study(STUDY.replace("ricker_Tp0.5s_0.5g.txt", "link.txt"))
    with pytest.raises(InputError, match="records\\[1\\].path: leaves the study's folder"):
        load_study(str(study))
    assert load_study(str(study), allow_outside=True).records[1].name == "ricker"


def test_records_dir_given_by_the_user_is_trusted(write_study: WriteStudy, tmp_path: Path) -> None:
    study = write_study(STUDY.replace('records_dir = "records"', 'records_dir = "/nowhere"'))
    plan = load_study(str(study), records_dir=str(tmp_path / "records"))
    assert len(plan.records) == 2


def test_an_unrecognised_record_is_named_not_quoted(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    (tmp_path / "records" / "secret.txt").write_text("root:x:0:0:TOKEN-123:/root\n")
    study = write_study(STUDY.replace("ricker_Tp0.5s_0.5g.txt", "secret.txt"))
    code, _, stderr = sweep(str(study), "--out", str(tmp_path / "out"), "-j", "1")
    assert code == 2
    assert "secret.txt" in stderr and "unrecognised" in stderr
    assert "TOKEN" not in stderr


# --- item 14: cases.csv cells that a spreadsheet would run -------------------------------


@pytest.mark.parametrize(
    ("value", "written"),
    [
        ('=HYPERLINK("http://x")', '\'=HYPERLINK("http://x")'),
        ("+1+cmd", "'+1+cmd"),
        ("-2+3", "'-2+3"),
        ("@SUM(A1)", "'@SUM(A1)"),
        ("\tx", "'\tx"),
        ("\rx", "'\rx"),
        ("'=x", "''=x"),  # already quoted: one more, so unescape gives it back
        ("-0.5", "-0.5"),  # numbers stay numbers
        ("-1e-3", "-1e-3"),
        ("ELC180", "ELC180"),
        ("'plain", "'plain"),
    ],
)
def test_formula_cells_are_escaped_and_numbers_kept(value: str, written: str) -> None:
    assert cell(value) == escape(value) == written
    assert unescape(written) == value
    assert cell(-0.5) == "-0.5"


def test_a_formula_record_name_is_escaped_in_the_csv(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = write_study(STUDY.replace('name = "ricker"', 'name = "=cmd|calc"'))
    with local_executor(1) as lanes:
        result = run_sweep(load_study(str(study)), str(tmp_path / "out"), lanes)
    with (tmp_path / "out" / "cases.csv").open(encoding="utf-8", newline="") as f:
        records = {r["record"] for r in csv.DictReader(f)}
    assert records == {"cosine", "'=cmd|calc"}
    assert result.summary["cases"] == N_CASES
    with local_executor(1) as lanes:  # and resumes from it
        assert run_sweep(load_study(str(study)), str(tmp_path / "out"), lanes, resume=True)


# --- item 14: control characters ---------------------------------------------------------


def test_control_characters_in_names_are_escaped_for_the_terminal(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = write_study(STUDY.replace('name = "ricker"', 'name = "r\\u001b[2J\\u0007x"'))
    code, stdout, _ = sweep(str(study), "--out", str(tmp_path / "out"), "-j", "1")
    assert code == 0
    assert "\x1b" not in stdout and "\x07" not in stdout
    assert "r\\x1b[2J\\x07x" in stdout
    assert printable({"k": ["a\u202eb"]}) == {"k": ["a\\u202eb"]}  # a bidi override too


# --- item 9: damaged cases.csv, bad scheduler addresses, long names -----------------------


def _complete(write_study: WriteStudy, tmp_path: Path) -> tuple[Path, Path]:
    study = write_study()
    out = tmp_path / "out"
    with local_executor(1) as lanes:
        run_sweep(load_study(str(study)), str(out), lanes)
    state = json.loads((out / "sweep.json").read_text())
    state["complete"] = False  # as after an interruption
    (out / "sweep.json").write_text(json.dumps(state))
    return study, out


@pytest.mark.parametrize(
    ("damage", "where"),
    [
        (lambda lines: ["case,oops\n", *lines[1:]], "line 1: cannot resume: cases.csv the header"),
        (lambda lines: [*lines[:3], "7,cosine,1.5\n", *lines[3:]], "line 4: cannot resume"),
        (lambda lines: [*lines[:2], lines[2].replace(",", ",x", 3), *lines[3:]], "line 3"),
        (lambda lines: [*lines[:5], "999" + lines[5][1:], *lines[6:]], "line 6"),
        (lambda lines: [*lines[:2], "\x00\x00\n", *lines[2:]], "cannot resume"),
    ],
)
def test_a_damaged_cases_csv_on_resume_names_its_line(
    write_study: WriteStudy, tmp_path: Path, damage: object, where: str
) -> None:
    study, out = _complete(write_study, tmp_path)
    lines = (out / "cases.csv").read_text().splitlines(keepends=True)
    (out / "cases.csv").write_text("".join(damage(lines)))  # type: ignore[operator]
    code, _, stderr = sweep(str(study), "--out", str(out), "-j", "1", "--resume")
    assert code == 2, stderr
    assert stderr.count("\n") == 1 and where in stderr and "--force" in stderr
    code, _, stderr = sweep(str(study), "--out", str(out), "-j", "1", "--force")
    assert code == 0, stderr


@pytest.mark.parametrize(
    "address",
    ["nonsense", "foo://bar:1", "tcp://[::1", "tls://host:8786", "wss://h:1", "tcp://h:99999"],
)
def test_a_malformed_scheduler_address_is_one_error_line(
    write_study: WriteStudy, address: str
) -> None:
    with pytest.raises(InputError, match="--scheduler"):
        check_address(address)
    code, _, stderr = sweep(str(write_study()), "--scheduler", address)
    assert code == 2
    assert stderr.count("\n") == 1 and stderr.startswith("error: --scheduler: ")


@pytest.mark.parametrize("address", ["tcp://10.0.0.5:8786", "tcp://[::1]:8786", "host:1"])
def test_a_scheduler_address_rock_can_use(address: str) -> None:
    check_address(address)


def test_a_long_study_name_gives_a_short_default_folder() -> None:
    name = "s" * 250  # a file name of 255 bytes with .toml; "sweep-" + it is 256
    out = default_out(f"/x/{name}.toml")
    assert len(out.encode()) <= OUT_NAME_MAX
    assert out != default_out(f"/x/{name[:-1]}t.toml")  # the hash keeps them apart
    assert default_out("/x/paper.toml") == "sweep-paper"


# --- item 17: the output folder, before any work -----------------------------------------


def test_the_out_folder_is_checked_before_the_study_runs(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study = write_study()
    (tmp_path / "afile").write_text("x")
    code, _, stderr = sweep(str(study), "--out", str(tmp_path / "afile"), "-j", "1")
    assert code == 2 and "is a file" in stderr
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        if os.access(ro, os.W_OK):
            pytest.skip("root writes into read-only folders")
        code, _, stderr = sweep(str(study), "--out", str(ro / "out"), "-j", "1")
        assert code == 2 and "cannot be written" in stderr
    finally:
        ro.chmod(0o700)


def test_wrote_is_said_on_stderr_and_force_starts_over(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    study, out = write_study(), tmp_path / "out"
    code, stdout, stderr = sweep(str(study), "--out", str(out), "-j", "1", "--format", "json")
    assert code == 0
    assert f"wrote {out / 'cases.csv'}\n" in stderr and "wrote /" not in stdout
    other = write_study(STUDY.replace("[1.5, 3.0]", "[1.5, 4.0]"), name="o.toml")
    code, _, stderr = sweep(str(other), "--out", str(out), "-j", "1")
    assert code == 2 and "--force to start over" in stderr
    code, _, _ = sweep(str(other), "--out", str(out), "-j", "1", "--force")
    assert code == 0


# --- item 18: undetermined cases are never zero collapses --------------------------------


def test_undetermined_and_failed_cases_are_counted_apart() -> None:
    rows = [
        {"code_uls": "fail", "rocking": "overturns", "classification": "consistent-unsafe"},
        {"code_uls": "fail", "rocking": "undecided", "classification": "undetermined"},
        {"code_uls": None, "rocking": "survives", "classification": "undetermined"},
        {"error": "internal error: x"},
    ]
    counts = tally(rows, ["rocking", "kinematic"])
    assert counts["cases"] == 4
    assert counts["undetermined"] == 3
    assert counts["errors"] == 1
    assert counts["code_collapses"] == 2 and counts["rocking_collapses"] == 1
    one = tally(rows[1:2], ["rocking"])  # one analysis: still counted
    assert one["undetermined"] == 1 and one["rocking_collapses"] == 0


def test_a_pivot_cell_shows_the_cases_without_a_verdict() -> None:
    row = {"code_collapses": 0, "rocking_collapses": 0, "code_conservative": 0, "undetermined": 3}
    assert _cell(row, ["rocking", "kinematic"]) == "0 / 0 (0) +3 ?"
    assert _cell({**row, "undetermined": 0}, ["rocking", "kinematic"]) == "0 / 0 (0)"
    assert _cell({"rocking_collapses": 0, "undetermined": 2}, ["rocking"]) == "0 +2 ?"


def test_the_collapse_map_marks_failed_and_undetermined_cases() -> None:
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from rockcli.plots.collapse import _draw_map, outcome

    base = {"R": 1.5, "alpha": 0.1, "record": "r"}
    rows = [
        {**base, "code_collapse": True, "rocking_collapse": False},
        {**base, "code_collapse": None, "rocking_collapse": False},
        {**base, "code_collapse": None, "rocking_collapse": None, "error": "internal error"},
    ]
    assert [outcome(r) for r in rows] == ["code", "undetermined", "error"]
    fig, ax = plt.subplots()
    try:
        _draw_map(ax, rows, [1.5], [0.1], "r")
        assert ax.get_title().endswith("collapses: code 1, rocking 0 of 3; no verdict 2")
    finally:
        plt.close(fig)


#: A file name longer than NAME_MAX (255 bytes on Linux, macOS and Windows file systems).
TOO_LONG = "a" * 300


@pytest.mark.parametrize(
    ("old", "new", "where"),
    [
        ('base = "wall.toml"', f'base = "{TOO_LONG}.toml"', "base"),
        ('path = "ricker_Tp0.5s_0.5g.txt"', f'path = "{TOO_LONG}.txt"', "records[1].path"),
        ('path = "ricker_Tp0.5s_0.5g.txt"', 'path = "a\\u0000b"', "records[1].path"),
    ],
)
def test_a_study_path_longer_than_name_max_is_one_error(
    write_study: WriteStudy, old: str, new: str, where: str
) -> None:
    # Before: OSError (File name too long) from Path.is_file, or ValueError (embedded null
    # byte; found by a fuzz of 3000 mutated study files), with a traceback.
    code, _, stderr = sweep(str(write_study(STUDY.replace(old, new))), "-j", "1")
    assert code == 2, stderr
    assert stderr.count("\n") == 1 and f"{where}: cannot use this path" in stderr


def test_an_out_folder_name_longer_than_name_max_is_one_error(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    code, _, stderr = sweep(str(write_study()), "-j", "1", "--out", str(tmp_path / TOO_LONG))
    assert code == 2, stderr
    assert stderr.count("\n") == 1 and "--out: the output folder cannot be used" in stderr


def test_a_failed_case_without_a_block_is_grouped_and_shown() -> None:
    # Before: TypeError ('<' between float and None) sorting the groups by α, when a case
    # failed before its block was known (found by running 40 mutated studies).
    from rockcli.studies.sweep.summary import grouped
    from rockcli.terminal.sweep import pivot

    rows = [
        {"record": "r", "_alpha": 0.1, "code_uls": "fail", "rocking": "survives"},
        {"record": "r", "_alpha": None, "error": "internal error"},
        {"record": "r", "_alpha": "x", "code_uls": "pass", "rocking": "survives"},
    ]
    groups = grouped(rows, lambda r: (r["record"], r["_alpha"]), ["rocking", "kinematic"])
    assert [k for k, _ in groups] == [("r", 0.1), ("r", "x"), ("r", None)]
    table = pivot(
        "t",
        [{"record": "r", "alpha": a, **t} for (_, a), t in groups if not isinstance(a, str)],
        "record",
        "record",
        ["rocking", "kinematic"],
    )
    assert [c.label for c in table.columns][1:] == ["α = 0.1", "α unknown"]


def test_links_planted_in_the_out_folder_are_replaced_not_followed(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # A study run twice into a folder where someone put links named like its files: the
    # files the links point at stay as they were (temp file + rename replaces the link).
    out = tmp_path / "out"
    out.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me\n")
    for name in ("cases.csv", "summary.json", "sweep.json"):
        (out / name).symlink_to(victim)
    study = write_study()
    code, _, stderr = sweep(str(study), "--out", str(out), "-j", "1", "--force")
    assert code == 0, stderr
    assert victim.read_text() == "keep me\n"
    assert not any((out / n).is_symlink() for n in ("cases.csv", "summary.json", "sweep.json"))
