"""Special and huge files as inputs: each is refused at once (exit 2, one line), never read.

On main, ``/dev/zero`` as a record grew the process until the kernel killed it (24 GB), and a
FIFO (a named pipe) as a record, a suite, a case file or a model blocked forever waiting for a
writer. Each test runs ``rock`` in a child process under a memory limit (RLIMIT_AS, 2 GiB: the
process needs ~0.4 GB with numpy and numba loaded) and a timeout, in its own process group
killed in a ``finally``: a regression fails the test instead of hanging it or exhausting the
machine.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import tomli_w

from rockcli.textfile import RECORD_LIMIT, TOML_LIMIT
from tests.limited import run_rock

ROOT = Path(__file__).resolve().parents[2]
PULSES = sorted((ROOT / "records").glob("*.txt"))
MODEL = ROOT / "examples" / "wall.toml"
#: Address space of the child [bytes]: far above what rock needs, far below the machine's.
MEMORY_LIMIT = 2 << 30
#: Seconds a refusal may take (the interpreter and rock's imports take about 1–2 s).
TIMEOUT = 30.0
#: The target of the test suites: a spectrum given by its parameters (no hazard grid).
TARGET = {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3}

pytestmark = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs POSIX FIFOs")


def rock(*args: str) -> tuple[int, str]:
    """Run ``rock ARGS`` in a child under limits (tests/limited.py): (code, stderr)."""
    done = run_rock(*args, memory=MEMORY_LIMIT, timeout=TIMEOUT)
    return done.code, done.err


def fifo(folder: Path, name: str) -> Path:
    path = folder / name
    os.mkfifo(path)
    return path


def suite_with(folder: Path, record: str) -> Path:
    """A suite file in ``folder``: two shipped pulses and ``record``."""
    for pulse in PULSES[:2]:
        (folder / pulse.name).write_bytes(pulse.read_bytes())
    records = [{"path": p.name} for p in PULSES[:2]] + [{"path": record}]
    path = folder / "suite.toml"
    path.write_text(
        tomli_w.dumps({"name": "s", "target": TARGET, "records": records}), encoding="utf-8"
    )
    return path


def assert_refused(code: int, err: str, path: object, problem: str) -> None:
    line = err.strip()
    assert code == 2, err
    assert "\n" not in line and "Traceback" not in err, err
    assert str(path) in line and problem in line, line


def test_dev_zero_as_a_record() -> None:
    code, err = rock("record", "info", "/dev/zero")
    assert_refused(code, err, "/dev/zero", "not a regular file (a character device)")


def test_dev_zero_as_a_suite() -> None:
    code, err = rock("suite", "check", "/dev/zero")
    assert_refused(code, err, "/dev/zero", "not a regular file")


def test_dev_zero_as_a_model() -> None:
    code, err = rock("kinematic", "/dev/zero")
    assert_refused(code, err, "/dev/zero", "not a regular file")


def test_dev_zero_named_in_a_suite(tmp_path: Path) -> None:
    suite = suite_with(tmp_path, "/dev/zero")
    code, err = rock("suite", "check", str(suite), "--allow-outside")
    assert_refused(code, err, suite, "/dev/zero: not a regular file")


def test_fifo_as_a_record(tmp_path: Path) -> None:
    path = fifo(tmp_path, "pipe.AT2")
    code, err = rock("record", "info", str(path))
    assert_refused(code, err, path, "not a regular file (a named pipe)")


def test_fifo_as_a_suite(tmp_path: Path) -> None:
    path = fifo(tmp_path, "suite.toml")
    code, err = rock("suite", "check", str(path))
    assert_refused(code, err, path, "not a regular file (a named pipe)")


def test_fifo_named_in_a_suite(tmp_path: Path) -> None:
    fifo(tmp_path, "pipe.txt")
    suite = suite_with(tmp_path, "pipe.txt")
    code, err = rock("suite", "check", str(suite))
    assert_refused(code, err, suite, "pipe.txt: not a regular file (a named pipe)")


def test_fifo_in_a_folder_suite(tmp_path: Path) -> None:
    suite_with(tmp_path, "pipe.txt")
    path = fifo(tmp_path, "pipe.txt")
    code, err = rock("suite", "check", str(tmp_path), "--target", "ag=0.25,F0=2.5,Tc_star=0.3")
    assert_refused(code, err, path, "not a regular file (a named pipe)")


def test_fifo_as_a_case_file(tmp_path: Path) -> None:
    path = fifo(tmp_path, "cases.toml")
    code, err = rock("validate", "--casebook", str(tmp_path))
    assert_refused(code, err, path, "not a regular file (a named pipe)")


def test_fifo_as_a_model(tmp_path: Path) -> None:
    path = fifo(tmp_path, "model.toml")
    code, err = rock("assess", str(path), "--record", str(PULSES[0]))
    assert_refused(code, err, path, "not a regular file (a named pipe)")


def test_huge_sparse_record_is_too_large(tmp_path: Path) -> None:
    path = tmp_path / "huge.txt"
    with path.open("wb") as handle:
        handle.truncate(RECORD_LIMIT + 1)  # sparse: no disk used
    code, err = rock("record", "info", str(path))
    assert_refused(code, err, path, f"too large ({RECORD_LIMIT + 1:,} bytes; the limit is")


def test_huge_sparse_model_is_too_large(tmp_path: Path) -> None:
    path = tmp_path / "huge.toml"
    with path.open("wb") as handle:
        handle.truncate(100 << 30)  # 100 GiB, sparse
    code, err = rock("kinematic", str(path))
    assert_refused(code, err, path, f"too large ({100 << 30:,} bytes; the limit is {TOML_LIMIT:,})")


def test_fifo_as_a_study_record(tmp_path: Path) -> None:
    (tmp_path / "wall.toml").write_bytes(MODEL.read_bytes())
    fifo(tmp_path, "pipe.txt")
    study = tmp_path / "study.toml"
    study.write_text(
        tomli_w.dumps({
            "name": "s", "base": "wall.toml", "analyses": ["rocking"],
            "axes": [{"path": "geometry.thickness", "values": [0.5]}],
            "records": [{"path": "pipe.txt"}],
        }),
        encoding="utf-8",
    )  # fmt: skip
    code, err = rock("sweep", str(study), "--out", str(tmp_path / "out"), "--no-progress")
    assert_refused(code, err, study, "records[0].path: not a regular file (a named pipe)")


def test_fifo_named_in_a_studys_suite(tmp_path: Path) -> None:
    # A suite of a study names a FIFO: the study's fingerprint hashes every record of its
    # suites (rockcli.studies.sweep.output.file_digest), which opened and blocked on main.
    (tmp_path / "wall.toml").write_bytes(MODEL.read_bytes())
    fifo(tmp_path, "pipe.txt")
    suite_with(tmp_path, "pipe.txt")
    study = tmp_path / "study.toml"
    study.write_text(
        tomli_w.dumps({
            "name": "s", "base": "wall.toml", "analyses": ["rocking"],
            "axes": [{"path": "geometry.thickness", "values": [0.5]}],
            "records": [{"suite": "suite.toml"}],
        }),
        encoding="utf-8",
    )  # fmt: skip
    code, err = rock("sweep", str(study), "--out", str(tmp_path / "out"), "--no-progress")
    assert_refused(code, err, "pipe.txt", "not a regular file (a named pipe)")


def test_fifo_as_the_hazard_grid(tmp_path: Path) -> None:
    path = fifo(tmp_path, "grid.txt")
    code, err = rock("kinematic", str(MODEL), "--site", "13.40,42.35", "--hazard-grid", str(path))
    assert_refused(code, err, path, "not a regular file (a named pipe)")
