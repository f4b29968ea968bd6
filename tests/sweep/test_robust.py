"""Issue 7, items 9 and 13: the edges of a study run (resume, workers, a failing disk)."""

from __future__ import annotations

import errno
from concurrent.futures import Executor, Future
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path
from typing import Any

import pytest

from rockcli.errors import InputError
from rockcli.studies.parallel.executor import local_executor
from rockcli.studies.sweep import output as sweep_output
from rockcli.studies.sweep.run import run_sweep
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import WriteStudy

N_CASES = 16  # conftest.STUDY: 2 R × 2 α × 2 K × 2 pulses


def test_resume_refuses_a_record_changed_at_the_same_size(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # Before: the fingerprint hashed the record's name and size, so an edited record of the
    # same size resumed with the old rows. One digit changed, same byte count.
    study = write_study()
    out = tmp_path / "out"
    with local_executor(1) as lanes:
        run_sweep(load_study(str(study)), str(out), lanes)
    record = tmp_path / "records" / "ricker_Tp0.5s_0.5g.txt"
    text = record.read_text()
    lines = text.splitlines(keepends=True)
    k = next(
        i for i, line in enumerate(lines) if line.strip() and line[0].isdigit() and "1" in line
    )
    lines[k] = lines[k].replace("1", "2", 1)
    edited = "".join(lines)
    assert len(edited) == len(text) and edited != text
    record.write_text(edited)
    with local_executor(1) as lanes, pytest.raises(InputError, match="another study"):
        run_sweep(load_study(str(study)), str(out), lanes, resume=True)


def test_a_full_disk_mid_sweep_says_how_many_cases_are_saved(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[int] = []
    original = sweep_output.Output.append_lines

    def append_then_fail(self: Any, ids: Any, lines: Any) -> Any:
        calls.append(1)
        if len(calls) > 2:
            raise OSError(errno.ENOSPC, "No space left on device")
        return original(self, ids, lines)

    monkeypatch.setattr(sweep_output.Output, "append_lines", append_then_fail)
    with local_executor(1) as lanes, pytest.raises(InputError) as info:
        run_sweep(load_study(str(write_study())), str(tmp_path / "out"), lanes, chunk_size=2)
    text = str(info.value)
    assert f"No space left on device; 4 of {N_CASES} cases saved" in text  # 2 chunks of 2
    assert "rerun with --resume" in text


@pytest.mark.parametrize(
    ("jobs", "cpus", "cases", "expected", "note"),
    [
        (None, 2, 100, 2, None),
        (8, 2, 100, 2, "--jobs 8 capped to 2 (the CPU count)"),
        (4, 8, 3, 3, "--jobs 4 capped to 3 (the cases of the study)"),
        (2, 8, 100, 2, None),
    ],
)
def test_workers_are_capped_at_the_cpus_and_the_cases(
    jobs: int | None,
    cpus: int,
    cases: int,
    expected: int,
    note: str | None,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    from rockcli.cli import sweep as cli_sweep

    monkeypatch.setattr(cli_sweep.os, "cpu_count", lambda: cpus)
    assert cli_sweep.worker_count(jobs, cases) == expected
    err = capsys.readouterr().err
    assert (note in err) if note else err == ""


def test_an_element_of_an_array_the_base_lacks_is_one_error(write_study: WriteStudy) -> None:
    # Before: KeyError (set_path indexed a table created for the absent array).
    from tests.sweep.conftest import BASE, STUDY

    base = BASE.split("[[restrainers]]")[0] + '[ntc]\nedition = "2009"\nFC = 1.0\n'
    study = STUDY.split("[[axes]]\npath = [")[0] + STUDY.split("values = [0.0, 1e6]\n")[1]
    study = study.replace('path = "geometry.R"', 'path = "restrainers[0].k_pos"')
    with pytest.raises(InputError) as info:
        load_study(str(write_study(study, base=base)))
    assert "axes[0].path: restrainers[0] is not in the base model" in str(info.value)


class DyingPool(Executor):
    """An executor whose every submission fails as a killed worker's does (a fake pool)."""

    def __init__(self) -> None:
        self.submitted = 0

    def submit(self, fn: Any, /, *args: Any, **kwargs: Any) -> Future[Any]:
        self.submitted += 1
        future: Future[Any] = Future()
        future.set_exception(BrokenProcessPool("a worker died"))
        return future


def test_a_chunk_whose_worker_always_dies_becomes_error_rows(write_study: WriteStudy) -> None:
    # Before: the first BrokenProcessPool aborted the study. Now the pool is restarted and the
    # chunk sent again; after CHUNK_ATTEMPTS deaths its cases are rows with an error.
    from rockcli.studies.parallel import chunks
    from rockcli.studies.parallel.executor import Lane
    from rockcli.studies.sweep.worker import Chunk, run_chunk

    plan = load_study(str(write_study()))
    chunk = Chunk(plan, 0, range(3))
    pools: list[DyingPool] = []

    def restart() -> DyingPool:
        pools.append(DyingPool())
        return pools[-1]

    lanes = [Lane(restart(), 1, 2, restart)]
    results = list(chunks.run_chunks(lanes, [chunk], run_chunk))
    assert len(results) == 1
    assert [r["case"] for r in results[0]] == [0, 1, 2]
    assert all("died 3 times" in r["error"] for r in results[0])
    assert sum(p.submitted for p in pools) == chunks.CHUNK_ATTEMPTS
    assert len(pools) == chunks.CHUNK_ATTEMPTS + 1  # one restart after each death


def test_a_pool_without_restart_still_raises(write_study: WriteStudy) -> None:
    from rockcli.studies.parallel.chunks import run_chunks
    from rockcli.studies.parallel.executor import Lane
    from rockcli.studies.sweep.cases import expand
    from rockcli.studies.sweep.worker import Chunk, run_chunk

    plan = load_study(str(write_study()))
    chunk = Chunk(plan, 0, range(len(expand(plan))))
    with pytest.raises(BrokenProcessPool):
        list(run_chunks([Lane(DyingPool(), 1, 1)], [chunk], run_chunk))


def test_a_killed_worker_is_replaced_and_its_chunk_run_again(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # A real pool: one worker process is SIGKILLed once the study has started; the study
    # still completes, every case with its results, as a run in one process gives.
    import os
    import signal
    import threading
    import time

    psutil = pytest.importorskip("psutil")  # comes with distributed (the test extra)
    plan = load_study(str(write_study()))
    with local_executor(1) as lanes:
        run_sweep(plan, str(tmp_path / "one"), lanes)
    killed: list[int] = []

    def kill_a_worker() -> None:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not killed:
            for p in psutil.Process().children(recursive=True):
                if p.ppid() != os.getpid():  # a worker (a child of the fork server)
                    os.kill(p.pid, signal.SIGKILL)
                    killed.append(p.pid)
                    return
            time.sleep(0.05)

    def workers() -> list:
        return [p for p in psutil.Process().children(recursive=True) if p.ppid() != os.getpid()]

    killer = threading.Thread(target=kill_a_worker)
    with local_executor(2) as lanes:
        # The pool's process starts in the background; with warm kernels this process's own
        # lane could finish every case first, so wait for the worker to exist before the run.
        deadline = time.monotonic() + 60
        while not workers() and time.monotonic() < deadline:
            time.sleep(0.05)
        killer.start()
        summary = run_sweep(plan, str(tmp_path / "two"), lanes, chunk_size=1).summary
    killer.join()
    assert killed, "no worker process to kill"
    assert summary["errors"] == 0 and summary["cases"] == N_CASES
    one = (tmp_path / "one" / "cases.csv").read_text()
    assert (tmp_path / "two" / "cases.csv").read_text() == one


def test_chunks_are_sized_by_measured_time(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Before: chunks were sized from the fast engine's estimated cost (≈ 2 ms a case here),
    # so a slow engine gave long chunks (the reference engine: 14 s, and Ctrl-C waited for
    # them). Each case is made ≥ 50 ms slower; with a 0.1 s chunk target the measured time
    # gives chunks of one case (the estimate alone gives 3: a 16-case study, 4 chunks).
    import time

    from rockcli.studies.sweep import run as sweep_run

    sizes: list[int] = []
    original = sweep_run.run_chunk_lines

    def slow(chunk: Any) -> Any:
        sizes.append(len(chunk.cases))
        time.sleep(0.05 * len(chunk.cases))
        return original(chunk)

    monkeypatch.setattr(sweep_run, "run_chunk_lines", slow)
    monkeypatch.setattr(sweep_run, "CHUNK_SECONDS", 0.1)
    with local_executor(1) as lanes:
        summary = run_sweep(load_study(str(write_study())), str(tmp_path / "out"), lanes).summary
    assert summary["cases"] == N_CASES
    assert sizes == [1] * N_CASES  # the measured case, then chunks of one
