"""Issue 7, item 13: a killed or terminated `rock sweep` leaves no process behind, SIGTERM
behaves like Ctrl-C (the finished cases saved, a line saying how many, exit 130).

Measured before the change (main): after SIGTERM or SIGKILL of the main process, the fork
server (≈ 164 MB) and each worker (≈ 89 MB) stayed alive. The study here is the pulse study
of the tests with more slenderness values and chunks of one case, so that it runs long
enough (tens of seconds on 2 cores) to be stopped half-way.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.sweep.conftest import ROOT, STUDY, WriteStudy

psutil = pytest.importorskip("psutil")  # comes with distributed (the test extra)

#: 2 R × 24 α × 2 K × 2 pulses: long enough to be interrupted (≈ 0.1 s per case).
ALPHAS = [round(0.05 + 0.005 * i, 3) for i in range(24)]
N_CASES = 2 * len(ALPHAS) * 2 * 2
#: Seconds allowed for a stop and for the orphans to notice (the watcher polls every 0.5 s).
STOP_WITHIN = 15.0


def start(write_study: WriteStudy, out: Path) -> subprocess.Popen[str]:
    study = write_study(STUDY.replace("[0.1, 0.2]", str(ALPHAS)))
    cmd = [sys.executable, "-m", "rockcli", "sweep", str(study), "--out", str(out)]
    cmd += ["-j", "2", "--chunk-size", "1", "--no-progress"]
    return subprocess.Popen(
        cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )


def wait_for_rows(out: Path, proc: subprocess.Popen[str], rows: int) -> list[psutil.Process]:
    """Wait until cases.csv holds `rows` rows; the descendants of the process then."""
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        path = out / "cases.csv"
        if path.exists() and path.read_text().count("\n") > rows:
            children = psutil.Process(proc.pid).children(recursive=True)
            assert children, "a sweep with -j 2 has worker processes"
            return children
        assert proc.poll() is None, proc.communicate()
        time.sleep(0.1)
    raise AssertionError("the study wrote no row in 120 s")


def gone(process: psutil.Process) -> bool:
    try:
        return process.status() == psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return True


def assert_all_gone(processes: list[psutil.Process]) -> None:
    deadline = time.monotonic() + STOP_WITHIN
    while time.monotonic() < deadline and not all(gone(p) for p in processes):
        time.sleep(0.2)
    left = [f"{p.pid} {p.cmdline()[:3]}" for p in processes if not gone(p)]
    for p in processes:
        if not gone(p):
            p.kill()
    assert not left, f"left behind: {left}"


@pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="POSIX signals")
def test_sigterm_is_like_ctrl_c(write_study: WriteStudy, tmp_path: Path) -> None:
    out = tmp_path / "out"
    proc = start(write_study, out)
    children = wait_for_rows(out, proc, 2)
    proc.send_signal(signal.SIGTERM)
    _, stderr = proc.communicate(timeout=STOP_WITHIN)
    assert proc.returncode == 130, stderr
    assert f"cases saved in {out}; rerun with --resume" in stderr
    saved = int(stderr.split("interrupted: ")[1].split(" of ")[0])
    assert 2 <= saved < N_CASES
    assert f" of {N_CASES} cases saved" in stderr
    assert "Traceback" not in stderr
    assert_all_gone(children)


@pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="POSIX signals")
def test_a_killed_sweep_leaves_no_worker_nor_fork_server(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    proc = start(write_study, out)
    children = wait_for_rows(out, proc, 2)
    os.kill(proc.pid, signal.SIGKILL)
    proc.communicate(timeout=STOP_WITHIN)
    assert_all_gone(children)
