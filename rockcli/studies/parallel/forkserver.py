"""Preloaded by the fork server of a local study: importing it loads the compiled kernels.

`rock sweep --jobs N` starts its workers from a multiprocessing fork server (spec/engine.md:
spawn or forkserver, never fork). The server is a fresh, single-threaded interpreter that
imports this module once; every worker is then a fork of it, with numpy, numba and the
compiled rocking and response-spectrum kernels already loaded (≈ 0.6 s of start-up per
worker otherwise). No numba threads exist in the server (the kernels are not parallel), so
forking it is safe.

First, before those imports (a second, during which `rock sweep` may be killed): Ctrl-C is
ignored (the workers forked later inherit it) and the server is tied to the `rock sweep` that
started it (rockcli.process.die_with_creator).
"""

from __future__ import annotations

import os

from rockcli.process import SERVER_ENV, die_with_creator, ignore_interrupts, quick_exit


def prepare() -> None:
    """Tie the server to `rock sweep`, then load the kernels."""
    ignore_interrupts()
    die_with_creator()  # the server dies with `rock sweep`, and its workers with it
    os.environ[SERVER_ENV] = str(os.getpid())  # the workers' parent (init_worker)
    from rockcli.studies.parallel.setup import single_thread, warm

    single_thread()
    warm()
    quick_exit()


prepare()
