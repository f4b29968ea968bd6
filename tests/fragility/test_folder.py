"""Issue 34, findings F1, F4, F8, F9, F11, F13: `rock fragility` writes its output folder
through the one study folder machinery (rockcli.studies.folder), as `rock sweep` does.

Each test plays the fault campaign's reproducer: links planted at the temporary files, a linked
--out, a record edited between a run and its resume, a damaged cases.csv, a full disk, a
folder moved before it is resumed.
"""

from __future__ import annotations

import errno
import json
import shutil
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.folder.folder import StudyFolder

MODEL = """name = "Linearized block"
kind = "wall"
geometry = { R = 3.0, alpha = 0.2 }
restitution = { e = 0.9 }
analysis = { linearized = true }
"""

STUDY = """name = "Housner IDA"
model = "model.toml"
method = "ida"

[intensity]
measure = "pga"

[[damage_states]]
level = "overturning"

[[records]]
path = "r1.txt"

[[records]]
path = "r2.txt"

[ida]
first = 0.2
step = 0.1
last = 1.0
tolerance = 0.01
"""


def make_study(here: Path) -> Path:
    """A study folder: the model, two rectangular pulses, the study file."""
    here.mkdir(parents=True, exist_ok=True)
    (here / "model.toml").write_text(MODEL, encoding="utf-8")
    for name, t1 in (("r1", 0.32), ("r2", 0.5)):
        args = ["record", "pulse", "rectangular", "--amplitude", "1", "--period", str(t1),
                "--dt", "1e-3", "-o", str(here / f"{name}.txt")]  # fmt: skip
        assert CliRunner().invoke(cli, args).exit_code == 0
    (here / "study.toml").write_text(STUDY, encoding="utf-8")
    return here / "study.toml"


def run(study: Path, out: Path | str, *args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(
        cli, ["fragility", str(study), "--out", str(out), "--format", "json", "--no-progress",
              *args],
    )  # fmt: skip
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture
def study(tmp_path: Path) -> Path:
    return make_study(tmp_path / "study")


def test_links_planted_in_the_folder_are_never_followed(study: Path, tmp_path: Path) -> None:
    """F1: links at every temporary name and at the files' own names are replaced, not
    written through: the files they point to keep their bytes."""
    out = tmp_path / "out"
    out.mkdir()
    victims = []
    for name in ("state.json.tmp", "fragility.json.tmp", "cases.csv.tmp", "fragility.json"):
        victim = tmp_path / f"victim-{name}"
        victim.write_text("precious\n", encoding="utf-8")
        (out / name).symlink_to(victim)
        victims.append(victim)
    code, _, err = run(study, out)
    assert code == 0, err
    assert all(v.read_text(encoding="utf-8") == "precious\n" for v in victims)
    assert not (out / "fragility.json").is_symlink()


def test_a_linked_out_leading_elsewhere_is_refused(
    study: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """F11: --out a symbolic link to a folder outside the current folder: one line, exit 2,
    nothing written there."""
    work, elsewhere = tmp_path / "work", tmp_path / "elsewhere"
    work.mkdir()
    elsewhere.mkdir()
    (work / "out").symlink_to(elsewhere)
    monkeypatch.chdir(work)
    code, _, err = run(study, "out")
    assert code == 2 and err.count("\n") == 1
    assert "symbolic link" in err and "outside the current folder" in err
    assert list(elsewhere.iterdir()) == []


def test_a_record_edited_since_is_not_resumed(study: Path, tmp_path: Path) -> None:
    """F4: the record's bytes changed at the same size (its path did not): --resume refuses
    the folder rather than keep the old record's runs."""
    out = tmp_path / "out"
    assert run(study, out)[0] == 0
    record = study.parent / "r1.txt"
    text = record.read_text(encoding="utf-8")
    edited = text.replace("1.0", "0.9", 1) if "1.0" in text else text.replace("1", "2", 1)
    assert len(edited) == len(text) and edited != text
    record.write_text(edited, encoding="utf-8")
    code, _, err = run(study, out, "--resume")
    assert code == 2 and err.count("\n") == 1 and "another study" in err


def interrupted_copy(study: Path, out: Path) -> int:
    """Cut the second record's lines from a finished folder and mark it unfinished, as an
    interruption leaves it; the lines kept (after the header)."""
    cases = out / "cases.csv"
    lines = cases.read_text(encoding="utf-8").splitlines(keepends=True)
    kept = [ln for ln in lines if not ln.startswith("1,")]
    cases.write_text("".join(kept), encoding="utf-8")
    state = json.loads((out / "state.json").read_text(encoding="utf-8"))
    (out / "state.json").write_text(json.dumps({**state, "complete": False}), encoding="utf-8")
    (out / "fragility.json").unlink()
    return len(kept) - 1


def test_a_moved_folder_resumes(study: Path, tmp_path: Path) -> None:
    """F13: the study's folder and its output folder moved elsewhere (another machine, a
    backup): --resume keeps the runs on disk and computes only the others."""
    out = tmp_path / "out"
    code, whole, err = run(study, out)
    assert code == 0, err
    finished = (out / "cases.csv").read_bytes()
    kept = interrupted_copy(study, out)
    moved = tmp_path / "moved"
    shutil.copytree(study.parent, moved / "study")
    shutil.copytree(out, moved / "out")
    code, again, err = run(moved / "study" / "study.toml", moved / "out", "--resume")
    assert code == 0, err
    doc = json.loads(again)
    assert doc["run"]["resumed_runs"] == kept > 0
    assert doc["damage_states"] == json.loads(whole)["damage_states"]
    assert (moved / "out" / "cases.csv").read_bytes() == finished


def damage(line: str, how: str) -> str:
    """A line of cases.csv damaged as the campaign did."""
    cells = line.rstrip("\n").split(",")
    header = "task,point,record,mechanism,im,scale,max_theta_ratio,overturned,error".split(",")
    at = {k: i for i, k in enumerate(header)}
    if how == "duplicated":
        return line + line
    if how == "task":
        cells[at["task"]] = "7"
    elif how == "record":
        cells[at["record"]] = "r2"
    else:
        cells[at[how.split("=")[0]]] = how.split("=")[1]
    return ",".join(cells) + "\n"


@pytest.mark.parametrize(
    ("how", "said"),
    [
        ("im=nan", "not a finite number > 0"),
        ("im=inf", "not a finite number > 0"),
        ("im=-0.3", "not a finite number > 0"),
        ("task", "not a task of this study"),
        ("record", "not those of its task"),
        ("duplicated", "twice"),
        ("overturned=maybe", "not true or false"),
        ("max_theta_ratio=nan", "max_theta_ratio"),
    ],
)
def test_a_damaged_cases_csv_is_refused_on_resume(
    study: Path, tmp_path: Path, how: str, said: str
) -> None:
    """F8: NaN or inf intensities, a task id out of range, a line of another task, a line
    twice: one line naming the line, exit 2, never a crash or a "complete" file of it."""
    out = tmp_path / "out"
    assert run(study, out)[0] == 0
    interrupted_copy(study, out)
    cases = out / "cases.csv"
    lines = cases.read_text(encoding="utf-8").splitlines(keepends=True)
    row = next(k for k, ln in enumerate(lines) if k and ",false," in ln)
    lines[row] = damage(lines[row], how)
    cases.write_text("".join(lines), encoding="utf-8")
    code, _, err = run(study, out, "--resume")
    assert code == 2 and err.count("\n") == 1, err
    line = row + (2 if how == "duplicated" else 1)  # a line twice: its second copy
    assert f"line {line}:" in err and said in err
    assert json.loads((out / "state.json").read_text(encoding="utf-8"))["complete"] is False


def test_a_full_disk_is_bad_input_and_the_folder_resumes(
    study: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """F9: the disk fills after the first task's lines: exit 2 saying how many tasks are
    saved and to rerun with --resume; the rerun ends the study with the same bytes."""
    whole = tmp_path / "whole"
    assert run(study, whole)[0] == 0
    original = StudyFolder.append_bytes
    calls: list[int] = []

    def append_then_fail(self: Any, ids: Any, lines: Any) -> Any:
        calls.append(1)
        if len(calls) > 1:
            raise OSError(errno.ENOSPC, "No space left on device")
        return original(self, ids, lines)

    out = tmp_path / "out"
    with monkeypatch.context() as patch:
        patch.setattr(StudyFolder, "append_bytes", append_then_fail)
        code, _, err = run(study, out, "--jobs", "1")
    assert code == 2 and err.count("\n") == 1, err
    assert "No space left on device; 1 of 2 tasks saved" in err and "--resume" in err
    code, _, err = run(study, out, "--resume")
    assert code == 0, err
    assert (out / "cases.csv").read_bytes() == (whole / "cases.csv").read_bytes()


def test_a_full_disk_at_the_start_leaves_no_empty_cases_csv(
    study: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """F9: the disk already full when the run starts: exit 2, and no empty cases.csv blocks
    the next run."""
    import rockcli.studies.folder.folder as folder

    def full(path: Any, text: Any, **_: Any) -> None:
        from rockcli.errors import InputError

        raise InputError("cannot write the file", file=str(path), value="No space left on device")

    out = tmp_path / "out"
    with monkeypatch.context() as patch:
        patch.setattr(folder, "write_text", full)
        code, _, err = run(study, out)
    assert code == 2 and "No space left on device" in err
    assert not (out / "cases.csv").exists()
    code, _, err = run(study, out)
    assert code == 0, err
