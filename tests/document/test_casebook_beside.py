"""The report's casebook runs in a worker process beside the report's analyses (two cores or
more), and here when no worker process can be started, on one core or when the worker dies:
the same casebook document either way."""

from __future__ import annotations

import pytest

from rockcli.document import run


def casebook_of(front: dict) -> dict:
    with run.casebook_beside(front, None) as front_of:
        return front_of()


@pytest.fixture(scope="module")
def here() -> dict:
    """The casebook run in this process (the reference)."""
    return run.report_front({"casebook": "annex"}, None)


def test_the_worker_gives_the_casebook_run_here(here: dict) -> None:
    assert run.usable_cores() >= 2, "this machine has one core: the worker path is not run"
    got = casebook_of({"casebook": "annex"})
    assert got == here
    assert got["casebook"]["passed"] > 0 and got["casebook_place"] == "annex"


def test_without_a_worker_process_it_runs_here(monkeypatch: pytest.MonkeyPatch, here: dict) -> None:
    import rockcli.studies.parallel.executor as executor

    def no_semaphores(workers: int) -> None:
        raise OSError(38, "Function not implemented")

    monkeypatch.setattr(executor, "process_executor", no_semaphores)
    assert casebook_of({"casebook": "annex"}) == here


def test_one_core_runs_it_here(monkeypatch: pytest.MonkeyPatch, here: dict) -> None:
    import rockcli.studies.parallel.executor as executor

    def never(workers: int) -> None:
        raise AssertionError("no worker process on one core")

    monkeypatch.setattr(run, "usable_cores", lambda: 1)
    monkeypatch.setattr(executor, "process_executor", never)
    assert casebook_of({"casebook": "annex"}) == here


def test_none_runs_nothing() -> None:
    got = casebook_of({"casebook": "none"})
    assert got["casebook"] is None and got["casebook_place"] == "inline"
