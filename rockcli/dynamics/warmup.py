"""Compile the fast engine into the numba cache ahead of time (CI images, workers)."""

from __future__ import annotations

import time

import numpy as np

from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, Restrainer


def warmup() -> float:
    """Compile every kernel: one tiny rocking run with a failing restrainer and one response
    spectrum ordinate (the code check's record demand); returns the seconds it took.

    Loads them from numba's cache when they are there already (then well under a second)."""
    from rockcli.codecheck.response import peak_displacement_uniform

    start = time.perf_counter()
    spring = Restrainer("warmup", 1e5, 1e5, 2.0, 0.2, 2.0, 0.2, fails_at=0.01)
    block = Block(R=1.0, alpha=0.2, mass=1000.0, e=0.9, restrainers=(spring,))
    t = np.arange(0.0, 1.0, 0.01)
    accel = 0.5 * np.sin(2 * np.pi * t)
    simulate(block, t, accel, 0.01)
    peak_displacement_uniform(accel * 9.81, 0.01, np.array([2 * np.pi]), 0.05)
    return time.perf_counter() - start


def compile_engine() -> float:
    """Compile every kernel into the cache and mark the cache complete for this machine
    (rockcli.jitcache.compiled); the seconds it took. `rock warmup`, and setup.py while the
    package is built."""
    from rockcli import jitcache

    seconds = warmup()
    jitcache.mark_compiled(seconds)
    return seconds
