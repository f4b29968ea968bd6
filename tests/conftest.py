"""Session set-up: every compiled kernel in numba's cache before any test runs.

The first use of a kernel in a process compiles them all (about 45 s with an empty cache)
and, when it happens under `rock`, says so on stderr (rockcli.jitcache.ensure_compiled).
Compiling here keeps that one-off message out of whichever test comes first, and its time out
of any one test's.

Hypothesis draws the same examples on every run (profile "repeatable": derandomized, no
example database), so that `python -m pytest` passes or fails the same way on every machine
and every run, CI's included. ``HYPOTHESIS_PROFILE=explore`` draws new examples each run (1000 of
them where a test does not set its own number): how a contributor looks for the inputs no fixed
seed reaches; a failing draw it finds goes into its test as an ``@example``.
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("repeatable", derandomize=True, database=None)
settings.register_profile("explore", derandomize=False, max_examples=1000)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))


def pytest_configure(config: object) -> None:
    import rockcli.dynamics.kernel  # noqa: F401 - configures the cache folder (jitcache)
    from rockcli import jitcache
    from rockcli.kernels import compile_engine

    if not jitcache.compiled():
        compile_engine()
