"""A worker process's set-up: one thread, an exit with its parent, the compiled kernels.

A local worker is a fork of the fork server (:mod:`rockcli.studies.parallel.forkserver`),
or a spawned interpreter where there is none; either way it runs :func:`init_worker` first.
The module imports nothing heavy at the top, so a spawned worker can set its environment
(one numba/BLAS thread) before numpy and numba load.
"""

from __future__ import annotations

import os

from rockcli.process import (
    SERVER_ENV,
    exit_with_parent,
    expected_parent,
    ignore_interrupts,
    quick_exit,
    set_death_signal,
)

#: One thread per worker process: the pool is the parallelism (spec/engine.md: never numba
#: threads inside a process pool).
SINGLE_THREAD = {
    "NUMBA_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "OPENBLAS_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
}


def init_worker() -> None:
    """Process-pool initializer: Ctrl-C ignored (`rock sweep` handles it), an exit with the
    parent (a killed `rock sweep` leaves no worker behind), one thread, the compiled kernels
    loaded, a quick exit."""
    ignore_interrupts()
    if os.environ.get(SERVER_ENV):  # a fork of the single-threaded server: prctl is safe
        set_death_signal()
    exit_with_parent(expected_parent())
    single_thread()
    warm()
    quick_exit()


def single_thread() -> None:
    """One numba/BLAS thread in this process (set before numpy and numba load)."""
    for key, value in SINGLE_THREAD.items():
        os.environ.setdefault(key, value)


def warm() -> None:
    """Load (or compile) the rocking engine and the response-spectrum recurrence."""
    from rockcli.kernels import warmup

    warmup()
