"""Issue 20, item 2: no file of the output folder is written through a link planted at its
name, and an --out that is itself a link out of the current folder is refused.

Measured before the change (main): a link planted as cases.csv.sorting or
cases.parquet.writing was followed — its target overwritten, and cases.csv or cases.parquet
became the link. The names are taken from the code (output.FOLDER_FILES), and a first test
checks, by Python's audit events, that every file a study creates or renames in its folder
has one of those names (or is a temporary file beside one of them): the list cannot go stale.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.outfile import is_temp_of
from rockcli.studies.sweep.output import (
    CASES_FILE,
    FOLDER_FILES,
    PARQUET_FILE,
    STATE_FILE,
    Output,
    parquet_available,
)
from rockcli.studies.sweep.study import StudyPlan, load_study
from tests.sweep.conftest import ROOT, WriteStudy

#: The two names the issue found followed (the temporary files of earlier versions).
OLD_TEMP_NAMES = ("cases.csv.sorting", "cases.parquet.writing")
SENTINEL = "do not overwrite\n"
OUTPUT = ("--output", "parquet") if parquet_available() else ()

#: Run a study and an out-of-order sort in one process with an audit hook that notes every
#: file opened for writing, created, renamed or removed in the output folder.
AUDIT = """
import json, os, sys
folder = os.path.realpath(sys.argv[1])
names = set()
WRITES = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC

def note(path):
    if isinstance(path, (str, bytes, os.PathLike)):
        path = os.path.realpath(os.fsdecode(path))
        if os.path.dirname(path) == folder:
            names.add(os.path.basename(path))

def hook(event, args):
    if event == "open":
        path, mode, flags = args
        if (set(mode) & set("wax+")) if isinstance(mode, str) else (flags or 0) & WRITES:
            note(path)
    elif event in ("os.rename", "os.link", "os.symlink"):
        note(args[0]); note(args[1])
    elif event in ("os.remove", "os.truncate", "tempfile.mkstemp", "os.chmod"):
        note(args[0])

sys.addaudithook(hook)
from rockcli.cli.main import cli
from rockcli.studies.sweep.output import Output
from rockcli.studies.sweep.study import load_study
code = cli.main(["sweep", sys.argv[2], "--out", folder, "-j", "1", "--no-progress", "--force",
                 *sys.argv[3:]], standalone_mode=False)
plan = load_study(sys.argv[2])
out = Output(folder, plan, 16)
with out.lock():
    out.check(resume=False, overwrite=True)
    out.start({})
    for block in ([8, 9, 10, 11, 12, 13, 14, 15], [0, 1, 2, 3, 4, 5, 6, 7]):
        out.append({"case": k} for k in block)
    out.finish()
print(json.dumps(sorted(names)))
"""


def sweep(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, ["sweep", *args, "--no-progress"])
    return result.exit_code, result.stderr


def test_every_name_written_in_the_folder_is_known(write_study: WriteStudy, tmp_path: Path) -> None:
    out = tmp_path / "out"
    cmd = [sys.executable, "-c", AUDIT, str(out), str(write_study()), *OUTPUT]
    done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    names = json.loads(done.stdout.splitlines()[-1])
    assert {CASES_FILE, STATE_FILE} <= set(names)
    unknown = [
        n
        for n in names
        if n not in FOLDER_FILES and not any(is_temp_of(n, f) for f in FOLDER_FILES)
    ]
    assert unknown == []


def plant(folder: Path, names: tuple[str, ...], sentinel: Path) -> None:
    """A link to sentinel at each name in folder."""
    folder.mkdir(exist_ok=True)
    for name in names:
        (folder / name).unlink(missing_ok=True)
        (folder / name).symlink_to(sentinel)


def assert_regular(folder: Path, names: tuple[str, ...]) -> None:
    for name in names:
        path = folder / name
        assert not path.is_symlink(), name
        assert not path.exists() or path.is_file(), name


@pytest.fixture
def sentinel(tmp_path: Path) -> Path:
    path = tmp_path / "sentinel.txt"
    path.write_text(SENTINEL, encoding="utf-8")
    return path


def test_links_at_every_name_are_not_followed(
    write_study: WriteStudy, tmp_path: Path, sentinel: Path
) -> None:
    study = str(write_study())
    out = tmp_path / "out"
    plant(out, FOLDER_FILES + OLD_TEMP_NAMES, sentinel)
    code, stderr = sweep(study, "--out", str(out), "-j", "1", "--force", *OUTPUT)
    assert code == 0, stderr
    assert sentinel.read_text(encoding="utf-8") == SENTINEL
    assert_regular(out, FOLDER_FILES)
    assert len((out / CASES_FILE).read_text(encoding="utf-8").splitlines()) == 17
    if OUTPUT:
        assert (out / PARQUET_FILE).read_bytes()[:4] == b"PAR1"


def test_links_are_not_followed_on_resume(
    write_study: WriteStudy, tmp_path: Path, sentinel: Path
) -> None:
    # An unfinished study whose cases.csv and sweep.json are links to files outside (read
    # through, never written through), and links at every other name.
    study = str(write_study())
    out = tmp_path / "out"
    code, stderr = sweep(study, "--out", str(out), "-j", "1")
    assert code == 0, stderr
    lines = (out / CASES_FILE).read_text(encoding="utf-8").splitlines(keepends=True)
    state = json.loads((out / STATE_FILE).read_text(encoding="utf-8"))
    outside_cases = tmp_path / "cases-outside.csv"
    outside_cases.write_text("".join(lines[:7]), encoding="utf-8")  # header and 6 cases
    outside_state = tmp_path / "state-outside.json"
    outside_state.write_text(json.dumps({**state, "complete": False}), encoding="utf-8")
    kept = {p: p.read_bytes() for p in (outside_cases, outside_state)}
    others = tuple(n for n in FOLDER_FILES if n not in (CASES_FILE, STATE_FILE))
    plant(out, others + OLD_TEMP_NAMES, sentinel)
    plant(out, (CASES_FILE,), outside_cases)
    plant(out, (STATE_FILE,), outside_state)
    code, stderr = sweep(study, "--out", str(out), "-j", "1", "--resume", *OUTPUT)
    assert code == 0, stderr
    assert sentinel.read_text(encoding="utf-8") == SENTINEL
    assert {p: p.read_bytes() for p in kept} == kept
    assert_regular(out, FOLDER_FILES)
    assert (out / CASES_FILE).read_text(encoding="utf-8").splitlines(keepends=True) == lines


@pytest.fixture
def plan(write_study: WriteStudy) -> StudyPlan:
    return load_study(str(write_study()))


def test_the_sort_of_blocks_writes_through_no_link(
    plan: StudyPlan, tmp_path: Path, sentinel: Path
) -> None:
    # Chunks completed out of order: cases.csv is sorted by copying its blocks to a new file.
    out = Output(str(tmp_path / "out"), plan, 16)
    with out.lock():
        out.check(resume=False, overwrite=True)
        out.start({})
        plant(out.folder, OLD_TEMP_NAMES, sentinel)
        for block in ([8, 9, 10, 11, 12, 13, 14, 15], [0, 1, 2, 3, 4, 5, 6, 7]):
            out.append({"case": k} for k in block)
        out.finish()
    assert sentinel.read_text(encoding="utf-8") == SENTINEL
    assert_regular(out.folder, (CASES_FILE,))
    assert [k for k, _ in out.typed_rows()] == list(range(16))


def test_an_out_link_leading_out_of_the_current_folder_is_refused(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    study = str(write_study())
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    here = tmp_path / "here"
    here.mkdir()
    (here / "sweep-study").symlink_to(elsewhere)
    monkeypatch.chdir(here)
    code, stderr = sweep(study, "-j", "1")  # the default --out, ./sweep-study
    assert code == 2
    assert stderr == (
        f"error: sweep-study: --out: the output folder is a symbolic link to {elsewhere}, "
        "outside the current folder (allowed: the folder itself as --out, or a link to a "
        "folder inside the current one)\n"
    )
    assert list(elsewhere.iterdir()) == []
    # A link to a folder inside the current one is the user's own arrangement: accepted.
    (here / "runs").mkdir()
    (here / "latest").symlink_to(here / "runs")
    code, stderr = sweep(study, "--out", "latest", "-j", "1")
    assert code == 0, stderr
    assert (here / "runs" / CASES_FILE).is_file()
    assert os.path.islink(here / "latest")
