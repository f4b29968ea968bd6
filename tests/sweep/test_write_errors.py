"""Issue 20, item 10 (the sweep's parts): a full disk reports the cases that are on disk, and
the error column of cases.csv names files from the study's folder, never by absolute path.

Measured before the change (main): with a file-size limit that stops cases.csv in the second
row of a chunk, `rock sweep` said "3 of 16 cases saved" while cases.csv held 4 whole rows
(the chunk's first row was written before the error), which --resume then kept.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.studies.sweep.study import load_study
from rockcli.studies.sweep.worker import Chunk, run_chunk
from tests.sweep.conftest import ROOT, WriteStudy

#: Cases per chunk: chunks [0, 1, 2], [3, 4, 5], … (one record's cases, in order with -j 1).
CHUNK = "3"
#: Whole rows before the size limit: the header and cases 0–3; the limit falls 5 bytes into
#: case 4's row, the second row of the second chunk.
WHOLE_ROWS = 4
SAVED = re.compile(r"; (\d+) of 16 cases saved")


def sweep(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, ["sweep", *args, "--no-progress", "-j", "1"])
    return result.exit_code, result.stderr


def file_size_limit(size: int):  # noqa: ANN201 - a preexec_fn
    def limit() -> None:
        import resource

        # Writes past `size` fail with EFBIG (SIGXFSZ is ignored by Python), as on a full disk.
        resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))

    return limit


@pytest.mark.skipif(sys.platform == "win32", reason="RLIMIT_FSIZE: POSIX")
def test_a_full_disk_reports_the_cases_on_disk(write_study: WriteStudy, tmp_path: Path) -> None:
    study = str(write_study())
    code, stderr = sweep(study, "--out", str(tmp_path / "whole"), "--chunk-size", CHUNK)
    assert code == 0, stderr
    whole = (tmp_path / "whole" / "cases.csv").read_bytes()
    lines = whole.splitlines(keepends=True)
    limit = sum(len(line) for line in lines[: 1 + WHOLE_ROWS]) + 5
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "rockcli", "sweep", study, "--out", str(out), "-j", "1"]
    cmd += ["--chunk-size", CHUNK, "--no-progress"]
    done = subprocess.run(
        cmd,
        cwd=ROOT,
        env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"},
        capture_output=True,
        text=True,
        timeout=300,
        preexec_fn=file_size_limit(limit),
    )
    assert done.returncode == 2, done.stderr
    assert done.stderr.count("\n") == 1 and "cannot write the output folder" in done.stderr
    on_disk = (out / "cases.csv").read_bytes()
    assert len(on_disk) == limit
    assert on_disk.count(b"\n") - 1 == WHOLE_ROWS
    match = SAVED.search(done.stderr)
    assert match and int(match[1]) == WHOLE_ROWS, done.stderr
    # --resume keeps those rows and runs the others: the file of a run that never stopped.
    code, stderr = sweep(study, "--out", str(out), "--chunk-size", CHUNK, "--resume")
    assert code == 0, stderr
    assert (out / "cases.csv").read_bytes() == whole


def test_the_error_column_names_files_from_the_study_folder(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A case that fails on a file of the study (a suite's, read by absolute path) names it
    # from the study file's folder: cases.csv is the same on every machine.
    study = write_study()
    plan = load_study(str(study))
    suite = (tmp_path / "records" / "suite.toml").resolve()

    def refused(*args: object) -> None:
        raise InputError("a problem", file=str(suite), where="target", allowed="a fix")

    monkeypatch.setattr("rockcli.studies.sweep.worker.build_model", refused)
    rows = run_chunk(Chunk(plan, 0, range(1)))
    assert rows[0]["error"] == "records/suite.toml: target: a problem (allowed: a fix)"
    assert str(tmp_path) not in rows[0]["error"]
