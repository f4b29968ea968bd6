"""Session set-up: every compiled kernel in numba's cache before any test runs.

The first use of a kernel in a process compiles them all (about 45 s with an empty cache)
and, when it happens under `rock`, says so on stderr (rockcli.jitcache.ensure_compiled).
Compiling here keeps that one-off message out of whichever test comes first, and its time out
of any one test's.
"""

from __future__ import annotations


def pytest_configure(config: object) -> None:
    import rockcli.dynamics.kernel  # noqa: F401 - configures the cache folder (jitcache)
    from rockcli import jitcache
    from rockcli.kernels import compile_engine

    if not jitcache.compiled():
        compile_engine()
