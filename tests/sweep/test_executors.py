"""Where the chunks run: this process, local processes, a dask cluster: same results.

Source: spec/engine.md, "Studies at scale" (code against concurrent.futures.Executor; past
one machine, distributed.Client(addr).get_executor()); the issue asks for a LocalCluster test
(processes=False), skipped with the reason when distributed is not installed.
"""

from __future__ import annotations

import importlib.util
import multiprocessing
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.parallel import executor as sweep_exec
from rockcli.studies.parallel.executor import START_METHODS, local_executor, start_method
from rockcli.studies.sweep.run import run_sweep
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import STUDY, WriteStudy

HAS_DISTRIBUTED = importlib.util.find_spec("distributed") is not None


def test_never_fork() -> None:
    assert "fork" not in START_METHODS
    assert start_method() in multiprocessing.get_all_start_methods()


def test_local_lanes() -> None:
    with local_executor(1) as lanes:
        assert [(lane.workers, lane.capacity) for lane in lanes] == [(1, 1)]
    with local_executor(3) as lanes:
        assert [(lane.workers, lane.capacity) for lane in lanes] == [(1, 1), (2, 4)]
        assert lanes[1].executor.submit(sum, [1, 2]).result() == 3


@pytest.mark.skipif(not HAS_DISTRIBUTED, reason="distributed not installed: pip install '.[dask]'")
@pytest.mark.parametrize(
    "analyses",
    ["", 'analyses = ["rocking"]\n'],
    ids=["case by case", "batched (rockcli/studies/sweep/batch.py)"],
)
def test_a_dask_cluster_gives_the_same_csv(
    write_study: WriteStudy, tmp_path: Path, analyses: str
) -> None:
    from distributed import LocalCluster

    study = write_study(analyses + STUDY)
    with local_executor(1) as lanes:
        run_sweep(load_study(str(study)), str(tmp_path / "local"), lanes)
    with LocalCluster(
        n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None
    ) as cluster:
        result = CliRunner().invoke(
            cli,
            ["sweep", str(study), "--out", str(tmp_path / "dask"), "--no-progress", "--format",
             "json", "--scheduler", cluster.scheduler_address],
        )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert '"scheduler": "inproc://' in result.output
    local = (tmp_path / "local" / "cases.csv").read_text()
    assert (tmp_path / "dask" / "cases.csv").read_text() == local


@pytest.mark.skipif(not HAS_DISTRIBUTED, reason="distributed not installed: pip install '.[dask]'")
def test_an_unreachable_scheduler_is_one_error_line(
    write_study: WriteStudy, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(sweep_exec, "CONNECT_TIMEOUT", 0.5)
    result = CliRunner().invoke(
        cli, ["sweep", str(write_study()), "--scheduler", "tcp://127.0.0.1:9", "--no-progress"]
    )
    assert result.exit_code == 2
    assert result.output.startswith("error: --scheduler: cannot connect to the dask scheduler")


def test_spawned_workers_where_there_is_no_fork_server(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Windows has no fork server: the workers are spawned, each loading the kernels itself.
    monkeypatch.setattr(sweep_exec, "START_METHODS", ("spawn",))
    study = load_study(str(write_study()))
    with local_executor(1) as lanes:
        run_sweep(study, str(tmp_path / "local"), lanes)
    with local_executor(2) as lanes:
        run_sweep(study, str(tmp_path / "spawn"), lanes, chunk_size=1)
    local = (tmp_path / "local" / "cases.csv").read_text()
    assert (tmp_path / "spawn" / "cases.csv").read_text() == local
