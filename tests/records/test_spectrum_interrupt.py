"""Ctrl-C during a compiled loop: "interrupted" and exit 130, never SIGSEGV (issue 20, item 7).

On main, SIGINT during `rock record spectrum`'s loop over periods ended in SIGSEGV (6 tries in
8 in the issue; here, on the record below, 2 in 6: SIGSEGV at 1.2 s and 1.6 s, and
``SystemError: CPUDispatcher(peak_response) returned a result with an exception set``,
exit 3, at 2.2 s and 3 s): Python's handler raised KeyboardInterrupt in the middle of the
numba-compiled call. SIGINT now only sets a flag while compiled code runs, and the loop over
periods, in chunks, raises KeyboardInterrupt between them (rockcli.interrupts).

The signal goes to the process group, as a terminal sends it, at several moments: during the
start and the reading of the records, then during the loop (ten records of 120,000 samples
and 2000 periods: about 1.5 s to read them, 8 s of loop on this machine, 2 cores).
"""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
#: Seconds after the start at which SIGINT is sent: the start-up and the reading (≤ 1 s), then
#: the loop over periods.
MOMENTS = [0.5, 1.2, 1.6, 2.2, 3.0]
#: Longest a stopped command may take to exit, and the whole run's CPU budget [s].
EXIT_WITHIN, CPU_SECONDS = 20.0, 60
#: Address space of the child [bytes]: numba and LLVM need about 1.5 GB of it.
ADDRESS_SPACE = 4 * 2**30


def limits() -> None:
    """In the child: a CPU and a memory ceiling, so that a runaway never takes the machine."""
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS))
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))


@pytest.fixture(scope="module")
def long_record(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A PEER AT2 record of 120,000 samples (1200 s at 0.01 s, 0.3 g amplitude-modulated)."""
    t = np.arange(120_000) * 0.01
    accel = 0.3 * np.sin(2 * np.pi * t) * np.sin(2 * np.pi * t / 37)
    rows = ["".join(f"{v:15.7E}" for v in accel[i : i + 5]) for i in range(0, accel.size, 5)]
    path = tmp_path_factory.mktemp("records") / "long.AT2"
    header = [
        "PEER NGA STRONG MOTION DATABASE RECORD",
        "synthetic record for the interrupt test",
        "ACCELERATION TIME SERIES IN UNITS OF G",
        f"NPTS= {accel.size}, DT= .0100 SEC",
    ]
    path.write_text("\n".join(header + rows) + "\n", encoding="ascii")
    return path


def interrupt_at(args: list[str], moment: float) -> subprocess.CompletedProcess[str]:
    """Run `rock ARGS` in its own session, SIGINT its group at `moment`; what it left."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "rockcli", *args],
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        preexec_fn=limits,
    )
    try:
        time.sleep(moment)
        assert proc.poll() is None, "the command ended before the signal: make it longer"
        os.killpg(proc.pid, signal.SIGINT)
        _, stderr = proc.communicate(timeout=EXIT_WITHIN)
        return subprocess.CompletedProcess(proc.args, proc.returncode, "", stderr)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()


@pytest.mark.skipif(not hasattr(os, "killpg"), reason="POSIX process groups")
@pytest.mark.parametrize("moment", MOMENTS)
def test_ctrl_c_during_record_spectrum_exits_130_with_one_line(
    long_record: Path, moment: float
) -> None:
    args = ["record", "spectrum", *[str(long_record)] * 10, "--periods", "0.01:4:2000"]
    done = interrupt_at([*args, "--format", "csv"], moment)
    assert done.returncode != -signal.SIGSEGV, "SIGSEGV"
    assert (done.returncode, done.stderr) == (130, "interrupted\n")
