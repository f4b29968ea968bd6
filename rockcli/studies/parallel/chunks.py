"""Run chunks of cases on the lanes of executors, each chunk's rows as it completes.

Each lane (an executor and its capacity) holds at most its capacity of submitted chunks; a
process pool that breaks (a worker killed) is restarted and its chunks submitted again. What a
chunk is and how its cases run is the caller's: a study's, a suite's, a retrofit's.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator, MutableSequence, Sequence
from concurrent.futures import FIRST_COMPLETED, BrokenExecutor, Future, wait
from typing import Any, Protocol, TypeVar

from rockcli.studies.parallel.executor import Lane

#: Times a chunk is run when the worker running it dies (then its cases are error rows).
CHUNK_ATTEMPTS = 3
#: Pool breaks a study survives (a pool that breaks at every start is a broken setup).
MAX_RESTARTS = 20
WORKER_DIED = (
    "the worker process running this case died {} times (killed, or out of memory); "
    "rerun the study, or run this case alone"
)


class Batch(Protocol):
    """Work for one submission: its cases, each with an ``id`` (a :class:`Chunk`, or the
    chunk of another study run on the same lanes, e.g. rockcli.studies.retrofit.run)."""

    @property
    def cases(self) -> Sequence[Any]: ...


B = TypeVar("B", bound=Batch)
R = TypeVar("R")


def run_chunks(
    lanes: MutableSequence[Lane],
    chunks: Sequence[B],
    work: Callable[[B], R],
) -> Iterator[R | list[dict[str, Any]]]:
    """What ``work(chunk)`` gives for each chunk as it completes (any order), run on a lane
    (a module-level function, so that a worker process can import it: a study's
    :func:`~rockcli.studies.sweep.worker.run_chunk_lines`, a suite's, a retrofit's rows).

    Each lane (an executor and its capacity) holds at most its capacity of submitted chunks;
    the next chunk goes to the first lane with room. A process pool that breaks (a worker
    killed: the OOM killer, a signal) is restarted and its chunks submitted again, up to
    :data:`CHUNK_ATTEMPTS` times each; then the chunk gives a row with an error for each of
    its cases (a list of dicts with ``case`` and ``error``, whatever work gives). Any
    other error cancels what is queued and is raised.
    """
    run = work
    pending: dict[Future[R], tuple[int, B]] = {}
    load = [0] * len(lanes)
    todo: deque[B] = deque(chunks)
    attempts: dict[int, int] = {}
    restarts = 0
    try:
        while True:
            for i, lane in enumerate(lanes):
                while load[i] < lane.capacity and todo:
                    chunk = todo.popleft()
                    try:
                        future = lanes[i].executor.submit(run, chunk)
                    except BrokenExecutor:  # broke before one of its futures said so
                        if lanes[i].restart is None or restarts >= MAX_RESTARTS:
                            raise
                        restarts += _restart(lanes, i)
                        todo.appendleft(chunk)
                        continue
                    pending[future] = (i, chunk)
                    load[i] += 1
            if not pending:
                return
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                i, chunk = pending.pop(future)
                load[i] -= 1
                rows: R | list[dict[str, Any]]
                try:
                    rows = future.result()
                except BrokenExecutor:
                    if lanes[i].restart is None or restarts >= MAX_RESTARTS:
                        raise
                    restarts += _restart(lanes, i)
                    attempts[id(chunk)] = tries = attempts.get(id(chunk), 0) + 1
                    if tries < CHUNK_ATTEMPTS:
                        todo.appendleft(chunk)
                        continue
                    rows = [{"case": c.id, "error": WORKER_DIED.format(tries)} for c in chunk.cases]
                yield rows
    finally:
        for future in pending:
            future.cancel()


def _restart(lanes: MutableSequence[Lane], i: int) -> bool:
    """A new executor in lane i when its pool broke (once per break: a pool already replaced
    is not replaced again by the other chunks it failed)."""
    lane = lanes[i]
    if lane.restart is None or not getattr(lane.executor, "_broken", True):
        return False
    lane.executor.shutdown(wait=False, cancel_futures=True)
    lanes[i] = lane._replace(executor=lane.restart())
    return True
