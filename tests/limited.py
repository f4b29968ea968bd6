"""`rock` run in a child process under limits, for the tests that feed it special or huge
files: its own address-space limit, a timeout (a child still running then is killed with its
process group, and the test fails: a FIFO that blocks cannot hang the suite), and the
working tree's rockcli first on its path."""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
import time
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@dataclass(frozen=True)
class Finished:
    """How the child ended: its exit code, what it printed, how long it took [s]."""

    code: int
    out: str
    err: str
    seconds: float


def run_rock(
    *args: str,
    memory: int,
    timeout: float,
    cwd: Path | None = None,
    env: Mapping[str, str] | None = None,
    columns: int = 200,
) -> Finished:
    """``python -m rockcli ARGS`` with at most ``memory`` bytes of address space, killed
    (and the test failed) after ``timeout`` seconds; ``env``: variables added to the
    child's environment."""

    def limited() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))

    variables = {**os.environ, "PYTHONPATH": str(ROOT), "COLUMNS": str(columns), **(env or {})}
    started = time.perf_counter()
    proc = subprocess.Popen(
        [sys.executable, "-m", "rockcli", *args], stdout=subprocess.PIPE,
        stderr=subprocess.PIPE, text=True, env=variables, cwd=cwd, preexec_fn=limited,
        start_new_session=True,
    )  # fmt: skip
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        pytest.fail(f"rock {' '.join(args)} still running after {timeout:g} s (blocked?)")
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    return Finished(proc.returncode, out, err, time.perf_counter() - started)
