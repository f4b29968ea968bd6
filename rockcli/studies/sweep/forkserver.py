"""Preloaded by the fork server of a local study: importing it loads the compiled kernels.

`rock sweep --jobs N` starts its workers from a multiprocessing fork server (spec/engine.md:
spawn or forkserver, never fork). The server is a fresh, single-threaded interpreter that
imports this module once; every worker is then a fork of it, with numpy, numba and the
compiled rocking and response-spectrum kernels already loaded (≈ 0.6 s of start-up per
worker otherwise). No numba threads exist in the server (the kernels are not parallel), so
forking it is safe.
"""

from __future__ import annotations

from rockcli.process import quick_exit
from rockcli.studies.sweep.worker import die_with_parent, single_thread, warm

single_thread()
die_with_parent()  # the server dies with `rock sweep`, and its workers with it
warm()
quick_exit()
