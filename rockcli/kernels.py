"""Every compiled kernel of rock, compiled at once: the rocking engine (one run, and a study's
many runs in one call) and the response-spectrum recurrence of the code check.

The numeric packages (rockcli.dynamics, rockcli.codecheck) never import this module: they ask
rockcli.jitcache.ensure_compiled() before a kernel's first use, which compiles everything with
the function registered here when this module has been imported (the command line and the
study workers import it), so that numba's one-off compilation is announced on stderr; a
library caller that has not imported it gets each kernel compiled silently at its first call.
Imports run one way: this module → dynamics, codecheck, jitcache.
"""

from __future__ import annotations

import time

from rockcli import jitcache


def warmup() -> float:
    """Compile every kernel: one tiny rocking run with a failing restrainer, the same run
    through the study kernel (kernel.integrate_runs), and one response spectrum ordinate;
    returns the seconds it took.

    Loads them from numba's cache when they are there already (then well under a second)."""
    import numpy as np

    from rockcli.codecheck.response import peak_displacement_uniform
    from rockcli.dynamics import layout as L
    from rockcli.dynamics.kernel import integrate_runs
    from rockcli.dynamics.settings import SolverSettings
    from rockcli.dynamics.simulate import pack_parameters, pack_springs, simulate
    from rockcli.mechanics import Block, Restrainer

    start = time.perf_counter()
    spring = Restrainer("warmup", 1e5, 1e5, 2.0, 0.2, 2.0, 0.2, fails_at=0.01)
    block = Block(R=1.0, alpha=0.2, mass=1000.0, e=0.9, restrainers=(spring,))
    t = np.arange(0.0, 1.0, 0.01)
    accel = 0.5 * np.sin(2 * np.pi * t)
    simulate(block, t, accel, 0.01)
    par = pack_parameters(block, SolverSettings(), 1e-8, 1e-8)[None, :]
    par[0, L.P_MAX_STEPS] = 1e6
    springs = pack_springs(block)[None, :, :]
    out_s = np.zeros((1, 1, L.N_SPRING_OUT))
    integrate_runs(t, accel, np.array([t.size]), np.zeros(1, dtype=np.int64), np.ones(1), par,
                   springs, np.zeros(0), np.zeros((1, L.N_FLOAT_OUT)),
                   np.zeros((1, L.N_INT_OUT), dtype=np.int64), out_s)  # fmt: skip
    peak_displacement_uniform(accel * 9.81, 0.01, np.array([2 * np.pi]), 0.05)
    return time.perf_counter() - start


def compile_engine() -> float:
    """Compile every kernel into the cache and mark the cache complete for this machine
    (rockcli.jitcache.compiled); the seconds it took. `rock warmup`, and setup.py while the
    package is built."""
    seconds = warmup()
    jitcache.mark_compiled(seconds)
    return seconds


jitcache.compile_all = warmup
