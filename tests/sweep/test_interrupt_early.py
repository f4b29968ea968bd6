"""Issue 20, item 7: Ctrl-C in the first seconds of `rock sweep` prints one line and exits
130; SIGKILL of `rock sweep` in its first second leaves none of its processes behind.

Measured before the change (main), on this machine (2 cores): SIGINT to the process group
(as a terminal sends Ctrl-C) 0.6 s after the start printed 50 lines (the fork server's
traceback: it imports rock before it ignores SIGINT); SIGKILL of the main process 0.3–0.55 s
after the start left the resource tracker, the fork server and a worker alive in 9 of 10
tries (the server read its parent's pid after its imports, when the parent was gone, and
then forked the worker asked for before). Each run here is identified by a marker in its
environment, which every process of the run inherits: its processes are found by pid in
/proc while it runs, and looked for again after it ended.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.process import interrupted
from tests.sweep.conftest import ROOT, STUDY, WriteStudy

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="finds the run's processes in /proc"
)

#: The test study on the reference engine with 60 slendernesses (480 cases, ≈ 0.13 s each):
#: still running after the last moment below.
LONG_STUDY = 'engine = "reference"\n' + STUDY.replace(
    "[0.1, 0.2]", str([round(0.05 + 0.0025 * i, 4) for i in range(60)])
)
#: Seconds after the start at which Ctrl-C is sent: during the imports, the study's loading,
#: the fork server's start, the first case (numba's kernels loading) and the chunks.
INTERRUPT_AT = (0.2, 0.6, 1.0, 1.5, 3.0)
#: Seconds after the start at which the main process is killed (and "server": just after the
#: fork server appears, while it imports rock).
KILL_AT: tuple[float | str, ...] = ("server", 0.3, 0.8, 1.2)
#: Seconds within which the run's processes must all be gone once the main one ended.
GONE_WITHIN = 5.0
#: Seconds a stopped run may take to exit (an interrupted run exits at once).
EXIT_WITHIN = 30.0
#: Memory each process of a run may take at most [bytes] (a worker takes ≈ 150 MB).
MEMORY_LIMIT = 2 << 30
MARK = "ROCK_TEST_RUN"


def limits() -> None:
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def start(study: Path, out: Path, marker: str) -> subprocess.Popen[bytes]:
    """`rock sweep -j 2` in a new session (its own process group, as a terminal's job)."""
    cmd = [sys.executable, "-m", "rockcli", "sweep", str(study), "--out", str(out)]
    cmd += ["-j", "2", "--no-progress"]
    with open(out.with_suffix(".err"), "wb") as err:
        return subprocess.Popen(
            cmd,
            cwd=ROOT,
            env={**os.environ, MARK: marker},
            stdout=subprocess.DEVNULL,
            stderr=err,  # a file, not a pipe: no wait on what the children hold open
            preexec_fn=limits,
            start_new_session=True,
        )


def processes_of(marker: str) -> dict[int, str]:
    """The live processes whose environment holds the marker: pid → command line."""
    found = {}
    needle = f"{MARK}={marker}".encode()
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            if needle in Path(f"/proc/{entry}/environ").read_bytes().split(b"\0"):
                stat = Path(f"/proc/{entry}/stat").read_text()
                if stat.rsplit(")", 1)[1].split()[0] != "Z":
                    found[int(entry)] = Path(f"/proc/{entry}/cmdline").read_bytes()[:100]
        except OSError:  # gone meanwhile, or not ours to read
            continue
    return {pid: cmd.replace(b"\0", b" ").decode(errors="replace") for pid, cmd in found.items()}


def watch_until(moment: float | str, proc: subprocess.Popen[bytes], marker: str) -> set[int]:
    """Note the run's processes until the moment (seconds after the start, or "server":
    0.05 s after the fork server appears); their pids."""
    started = time.monotonic()
    seen: set[int] = set()
    while time.monotonic() - started < (moment if isinstance(moment, float) else 20.0):
        now = processes_of(marker)
        seen |= set(now)
        if moment == "server" and any("forkserver" in cmd for cmd in now.values()):
            time.sleep(0.05)
            return seen | set(processes_of(marker))
        assert proc.poll() is None, "the study ended before it was stopped"
        time.sleep(0.02)
    return seen | set(processes_of(marker))


def left_after(seen: set[int], marker: str) -> dict[int, str]:
    """The run's processes still alive GONE_WITHIN s after its main process ended (the ones
    seen while it ran, and any other that holds its marker)."""
    assert seen, "no process of the run was found"
    deadline = time.monotonic() + GONE_WITHIN
    while True:
        alive = processes_of(marker)  # a pid seen and alive still holds the marker
        if not alive or time.monotonic() > deadline:
            return alive
        time.sleep(0.1)


@pytest.fixture
def run(write_study: WriteStudy, tmp_path: Path) -> Iterator[tuple[Path, Path, str]]:
    """The study, the output folder and the run's marker; whatever is left is killed."""
    marker = uuid.uuid4().hex
    yield write_study(LONG_STUDY), tmp_path / "out", marker
    for pid in processes_of(marker):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


@pytest.mark.parametrize("moment", INTERRUPT_AT)
def test_ctrl_c_early_is_one_line_and_130(run: tuple[Path, Path, str], moment: float) -> None:
    study, out, marker = run
    proc = start(study, out, marker)
    try:
        seen = watch_until(moment, proc, marker)
        os.killpg(proc.pid, signal.SIGINT)
        code = proc.wait(timeout=EXIT_WITHIN)
        left = left_after(seen, marker)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    stderr = out.with_suffix(".err").read_text(encoding="utf-8", errors="replace")
    assert code == 130, stderr
    assert stderr.count("\n") == 1 and stderr.startswith("interrupted"), stderr
    assert left == {}


@pytest.mark.parametrize("moment", KILL_AT)
def test_a_sweep_killed_early_leaves_no_process(
    run: tuple[Path, Path, str], moment: float | str
) -> None:
    study, out, marker = run
    proc = start(study, out, marker)
    try:
        seen = watch_until(moment, proc, marker)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=EXIT_WITHIN)
        left = left_after(seen, marker)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert left == {}


def numba_interrupt(*args: object, **kwargs: object) -> None:
    """What numba's dispatcher raises when Ctrl-C comes during a compiled function."""
    try:
        raise KeyboardInterrupt
    except KeyboardInterrupt:  # numba's: the interrupt is the SystemError's __context__
        raise SystemError(  # noqa: B904
            "CPUDispatcher(<function peak_response>) returned a result with an exception set"
        )


def test_a_system_error_caused_by_ctrl_c_is_an_interrupt(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Seen once in the campaign: exit 3, "internal error: SystemError: CPUDispatcher(…)".
    monkeypatch.setattr("rockcli.studies.sweep.run.measure", numba_interrupt)
    args = ["sweep", str(write_study()), "--out", str(tmp_path / "out"), "-j", "1"]
    result = CliRunner().invoke(cli, [*args, "--no-progress"])
    assert result.exit_code == 130
    assert result.stderr == f"interrupted: 0 of 16 cases saved in {tmp_path / 'out'}; " \
        "rerun with --resume\n"  # fmt: skip
    try:
        numba_interrupt()
    except SystemError as exc:
        assert interrupted(exc)
    assert not interrupted(SystemError("a bug of rock"))
