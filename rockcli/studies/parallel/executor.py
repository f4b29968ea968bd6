"""Where a study's chunks run: this process, a local process pool, or a dask cluster.

All three are :class:`concurrent.futures.Executor` objects (spec/engine.md, "Studies at
scale"):

- ``--jobs 1``: a thread of this process runs the chunks (no worker start-up, the records
  and compiled kernels loaded once), while the main thread writes rows and draws progress;
- ``--jobs N``: that thread and a :class:`~concurrent.futures.ProcessPoolExecutor` of N − 1
  processes, forks of a ``forkserver`` that has loaded numpy, numba and the compiled kernels
  once (``spawn`` where there is no fork server; never ``fork``: numba and threads), each
  with one thread (:func:`rockcli.studies.parallel.setup.init_worker`);
- ``--scheduler tcp://host:8786`` (or DASK_SCHEDULER_ADDRESS): ``distributed.Client(addr)
  .get_executor()``, from the ``dask`` extra (``pip install '.[dask]'`` from the
  repository's folder). The workers need rock installed and the record files at the same
  paths (a shared file system).
"""

from __future__ import annotations

import multiprocessing
import os
import re
import threading
from collections.abc import Callable, Iterator
from concurrent.futures import Executor, ProcessPoolExecutor, ThreadPoolExecutor
from contextlib import contextmanager, suppress
from typing import NamedTuple

from rockcli.errors import InputError, install_hint
from rockcli.process import CREATOR_ENV, interrupts_blocked, start_resource_tracker

#: Start methods of the local worker processes, in order of preference (never fork: numba).
START_METHODS = ("forkserver", "spawn")
#: Module the fork server imports before forking workers (loads the compiled kernels).
PRELOAD = "rockcli.studies.parallel.forkserver"
#: Seconds to wait for a dask scheduler to answer.
CONNECT_TIMEOUT = 10.0
#: Chunks in flight per worker process (one running, one queued).
IN_FLIGHT = 2


class Lane(NamedTuple):
    """An executor, the workers behind it and how many chunks to keep submitted to it;
    restart: a new executor for a process pool that broke (a worker was killed)."""

    executor: Executor
    workers: int
    capacity: int
    restart: Callable[[], Executor] | None = None


def start_method() -> str:
    """forkserver where the platform has it (workers are forks of a warm server), else spawn."""
    available = multiprocessing.get_all_start_methods()
    return next(m for m in START_METHODS if m in available)


def process_executor(workers: int) -> ProcessPoolExecutor:
    """A pool of worker processes, each with one thread and the kernels loaded.

    The processes start at once, from a background thread: the fork server (or each spawned
    worker) imports numpy and numba while this process validates the cases and reads the
    records, and the first chunks start in this process meanwhile.
    """
    from rockcli.studies.parallel.setup import init_worker

    method = start_method()
    context = multiprocessing.get_context(method)
    os.environ[CREATOR_ENV] = str(os.getpid())  # before any worker process starts
    start_resource_tracker()
    if method == "forkserver":
        start_fork_server(context)
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=init_worker)
    threading.Thread(target=_start, args=(pool, workers), daemon=True).start()
    return pool


def start_fork_server(context: multiprocessing.context.BaseContext) -> None:
    """Start the fork server with SIGINT blocked (it inherits the mask: a Ctrl-C during its
    second of imports reaches `rock sweep` alone, when the block ends).

    Started here, by the main thread: the server dies with its parent thread (prctl
    PR_SET_PDEATHSIG), which must live as long as the study.
    """
    from multiprocessing import forkserver

    context.set_forkserver_preload([PRELOAD])
    # The resource tracker runs already (process_executor): starting it unblocks SIGINT (it
    # blocks, then unblocks, rather than restoring the mask), which would leave the server
    # unprotected.
    with interrupts_blocked(), environment(server_environment()):
        forkserver.ensure_running()


def package_root() -> str:
    """The folder holding the ``rockcli`` package this process imported."""
    import rockcli.version

    return os.path.dirname(os.path.dirname(os.path.abspath(rockcli.version.__file__)))


def server_environment() -> dict[str, str]:
    """The variables the fork server starts with, so that it (and every worker, a fork of it)
    imports ``rockcli`` from where this process did, whatever the current folder.

    The server is ``python -c …``, whose sys.path starts with the current folder; Python 3.11
    does not give it this process's sys.path (multiprocessing.forkserver.main ignores the
    ``sys_path`` it is passed), so a clone's root as the current folder had the server import
    the working tree's ``rockcli`` (and compile the engine into it) instead of the installed
    one. PYTHONSAFEPATH=1 leaves the current folder out (Python ≥ 3.11); the package's folder
    goes first on PYTHONPATH unless it is a site folder, which the server reads anyway (a
    site folder ahead of the standard library could shadow it).
    """
    import site

    env = {"PYTHONSAFEPATH": "1"}
    root = package_root()
    sites = {os.path.abspath(p) for p in [*site.getsitepackages(), site.getusersitepackages()]}
    if root not in sites:
        rest = os.environ.get("PYTHONPATH")
        env["PYTHONPATH"] = root if not rest else os.pathsep.join((root, rest))
    return env


@contextmanager
def environment(changes: dict[str, str]) -> Iterator[None]:
    """This process's environment with ``changes`` for the block (a process started in it
    inherits them), restored after."""
    before = {key: os.environ.get(key) for key in changes}
    os.environ.update(changes)
    try:
        yield
    finally:
        for key, value in before.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value


def _start(pool: ProcessPoolExecutor, workers: int) -> None:
    """Submit no-op tasks, which starts the processes (a pool starts one per submission);
    SIGINT blocked in this thread, so that a worker spawned from it (no fork server) starts
    with it blocked."""
    # Any error: the pool was shut down (RuntimeError), or its processes were stopped while
    # starting (Ctrl-C); the study's own submissions say what matters.
    with suppress(Exception), interrupts_blocked():
        for _ in range(workers):
            pool.submit(int)


@contextmanager
def local_executor(jobs: int) -> Iterator[list[Lane]]:
    """The lanes of `jobs` local workers: a thread of this process, and jobs − 1 processes.

    The thread runs chunks while the main thread waits, writes rows and draws the progress
    bar; it shares this process's records and compiled kernels (nothing to start for it).
    """
    thread = ThreadPoolExecutor(max_workers=1, thread_name_prefix="rock-sweep")
    lanes = [Lane(thread, 1, 1)]
    if jobs > 1:
        workers = jobs - 1
        lanes.append(
            Lane(
                process_executor(workers),
                workers,
                IN_FLIGHT * workers,
                lambda: process_executor(workers),
            )
        )
    try:
        yield lanes
    except BaseException:
        # Interrupted or failed: stop the worker processes now (their chunks are lost, the
        # finished ones are on disk); the thread finishes its chunk (about a second).
        for lane in reversed(lanes):
            stop(lane.executor)
        raise
    else:
        for lane in reversed(lanes):
            lane.executor.shutdown(wait=True, cancel_futures=True)


def stop(executor: Executor) -> None:
    """Cancel what is queued and end the worker processes of a pool without waiting."""
    executor.shutdown(wait=False, cancel_futures=True)
    if isinstance(executor, ProcessPoolExecutor):
        terminate = getattr(executor, "terminate_workers", None)  # Python 3.14
        if terminate is not None:
            terminate()
            return
        for process in list((getattr(executor, "_processes", None) or {}).values()):
            with suppress(OSError, ValueError, AttributeError):
                process.terminate()


#: A scheduler address rock connects to: [tcp://]HOST:PORT, HOST a name, IPv4 or [IPv6].
_ADDRESS = re.compile(
    r"^(?:(?P<scheme>[A-Za-z][A-Za-z0-9+.-]*)://)?"
    r"(?P<host>\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):(?P<port>[0-9]{1,5})/?$"
)
#: The address of a dask cluster inside this process.
_IN_PROCESS = re.compile(r"^inproc://[^\s]+$")
#: Schemes that need no security configuration (TLS needs certificates rock does not set).
PLAIN_SCHEMES = ("tcp", "ws")
ADDRESS_ALLOWED = "tcp://HOST:PORT (or HOST:PORT), e.g. tcp://10.0.0.5:8786 or tcp://[::1]:8786"
#: Highest TCP port number.
PORT_MAX = 65535


def check_address(address: str) -> None:
    """Refuse a scheduler address rock cannot use, before importing dask (one error line)."""
    if _IN_PROCESS.match(address):  # a cluster inside this process (tests, notebooks)
        return
    match = _ADDRESS.match(address)
    problem = None
    if match is None:
        problem = "not a scheduler address"
    elif match["scheme"] and match["scheme"].lower() not in PLAIN_SCHEMES:
        scheme = match["scheme"].lower()
        problem = (
            f"{scheme}:// needs TLS certificates, which rock does not configure"
            if scheme in ("tls", "wss")
            else f"unsupported scheme {scheme}://"
        )
    elif not 1 <= int(match["port"]) <= PORT_MAX:
        problem = f"port out of range (1 to {PORT_MAX})"
    if problem:
        raise InputError(problem, where="--scheduler", value=address, allowed=ADDRESS_ALLOWED)


@contextmanager
def dask_executor(address: str) -> Iterator[list[Lane]]:
    """The lane of a dask scheduler (its threads, IN_FLIGHT chunks each)."""
    check_address(address)
    try:
        from distributed import Client
    except ImportError:
        raise InputError(
            "--scheduler needs dask.distributed",
            where="--scheduler",
            value=address,
            allowed=f"{install_hint('dask')}, or run locally with --jobs",
        ) from None
    try:
        client = Client(address, timeout=CONNECT_TIMEOUT)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        raise InputError(
            f"cannot connect to the dask scheduler: {exc}",
            where="--scheduler",
            value=address,
            allowed="the address of a running scheduler, e.g. tcp://host:8786",
        ) from None
    try:
        threads = max(1, sum(client.nthreads().values()))
        yield [Lane(client.get_executor(), threads, IN_FLIGHT * threads)]
    finally:
        client.close()
