"""Issue 20, item 1: one `rock sweep` at a time in an output folder, and a study marked
complete only when its cases.csv holds every case once.

Measured before the change (main): two runs started at once with --force into one folder,
three tries: each time one exited 3 (`ValueError: zip() argument 2 is longer/shorter…`) and
the other exited 0 and marked the study complete — once with 71 of 136 cases in cases.csv.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.studies.folder.lock import LOCK_FILE, lock_folder, unlock_folder
from rockcli.studies.sweep.output import CASES_FILE, STATE_FILE, Output
from tests.sweep.conftest import ROOT, STUDY, WriteStudy

#: The 16 cases of the test study on the reference engine: about 3 s with --jobs 1 on this
#: machine, so that a second run started at the same moment finds the folder in use.
SLOW_STUDY = 'engine = "reference"\n' + STUDY
#: Seconds a run of SLOW_STUDY may take at most here (a loaded machine: 10 times the 3 s).
RUN_LIMIT = 60
#: Memory a test's rock process may take at most [bytes] (a run takes ≈ 250 MB).
MEMORY_LIMIT = 2 << 30
BUSY = re.compile(r"the output folder is in use by another rock sweep \(pid (\d+)\)")


def limits() -> None:
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def start(study: Path, out: Path) -> subprocess.Popen[str]:
    cmd = [sys.executable, "-m", "rockcli", "sweep", str(study), "--out", str(out)]
    cmd += ["-j", "1", "--no-progress", "--force"]
    return subprocess.Popen(
        cmd,
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=limits,
        start_new_session=True,
    )


def sweep(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, ["sweep", *args, "--no-progress"])
    return result.exit_code, result.stderr


@pytest.mark.skipif(sys.platform == "win32", reason="flock: POSIX")
def test_two_sweeps_started_at_once_one_runs(write_study: WriteStudy, tmp_path: Path) -> None:
    study = write_study(SLOW_STUDY)
    out = tmp_path / "out"
    procs = [start(study, out), start(study, out)]
    try:
        results = [p.communicate(timeout=RUN_LIMIT) for p in procs]
    finally:
        for p in procs:
            if p.poll() is None:
                os.killpg(p.pid, 9)
    codes = [p.returncode for p in procs]
    assert sorted(codes) == [0, 2], results
    ran, refused = (0, 1) if codes[0] == 0 else (1, 0)
    stderr = results[refused][1]
    assert stderr.count("\n") == 1, stderr
    match = BUSY.search(stderr)
    assert match and int(match[1]) == procs[ran].pid, stderr
    state = json.loads((out / STATE_FILE).read_text(encoding="utf-8"))
    assert state["complete"] is True
    assert not (out / LOCK_FILE).exists()
    # The same study run alone: cases.csv byte for byte (the engine is deterministic).
    code, err = sweep(str(study), "--out", str(tmp_path / "alone"), "-j", "1")
    assert code == 0, err
    assert (out / CASES_FILE).read_bytes() == (tmp_path / "alone" / CASES_FILE).read_bytes()


@pytest.mark.skipif(sys.platform == "win32", reason="flock: POSIX")
def test_a_folder_in_use_is_refused_before_any_work(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    fd = lock_folder(out)  # this process holds the folder, as a running sweep would
    try:
        code, stderr = sweep(str(write_study()), "--out", str(out), "-j", "1")
    finally:
        unlock_folder(out, fd)
    assert code == 2
    assert stderr == (
        f"error: {out}: --out: the output folder is in use by another rock sweep "
        f"(pid {os.getpid()}) (allowed: another --out, or wait until that run ends)\n"
    )
    assert sorted(p.name for p in out.iterdir()) == []


@pytest.mark.skipif(sys.platform == "win32", reason="flock: POSIX")
def test_a_lock_file_left_by_a_dead_run_does_not_block(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # A run killed with SIGKILL leaves its lock file (its pid inside); the kernel released
    # the lock with the process, so the next run goes ahead (and removes the file).
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True, timeout=60)  # fmt: skip
    out = tmp_path / "out"
    out.mkdir()
    (out / LOCK_FILE).write_text(dead.stdout, encoding="ascii")
    code, stderr = sweep(str(write_study()), "--out", str(out), "-j", "1", "--force")
    assert code == 0, stderr
    assert not (out / LOCK_FILE).exists()


def test_a_bad_study_leaves_no_folder(write_study: WriteStudy, tmp_path: Path) -> None:
    # The folder is made to hold the lock; a study refused before any work removes it.
    study = write_study(STUDY.replace("[1.5, 3.0]", "[1.5, -3.0]"))
    code, stderr = sweep(str(study), "--out", str(tmp_path / "out"), "-j", "1")
    assert code == 2 and "geometry.R" in stderr
    assert not (tmp_path / "out").exists()


def test_a_cases_file_another_program_wrote_to_is_not_marked_complete(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A writer that takes no lock (an older rock, a script) appends a row while the study
    # ends: the summary's pass over cases.csv finds it, and the study stays unfinished.
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep.run import run_sweep
    from rockcli.studies.sweep.study import load_study

    finish = Output.finish

    def finish_then_intruder(self: Output) -> None:
        finish(self)
        with open(self.cases_path, "a", encoding="utf-8") as fh:
            fh.write(self.cases_path.read_text(encoding="utf-8").splitlines()[1] + "\n")

    monkeypatch.setattr(Output, "finish", finish_then_intruder)
    out = tmp_path / "out"
    with local_executor(1) as lanes, pytest.raises(InputError) as caught:
        run_sweep(load_study(str(write_study())), str(out), lanes)
    assert "cases.csv changed during the run: line 18 is case 0, not case 16" in str(caught.value)
    assert "the study is not marked complete" in str(caught.value)
    assert json.loads((out / STATE_FILE).read_text(encoding="utf-8"))["complete"] is False


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs: POSIX")
def test_a_fifo_at_the_lock_name_is_refused_without_blocking(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # Opening a FIFO for writing waits for a reader: the lock file is opened non-blocking
    # and must be a regular file.
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / LOCK_FILE)
    code, stderr = sweep(str(write_study()), "--out", str(out), "-j", "1")
    assert code == 2
    assert stderr == (
        f"error: {out}: --out: the output folder cannot be locked ({LOCK_FILE}: not a regular "
        f"file) (allowed: remove {LOCK_FILE})\n"
    )
