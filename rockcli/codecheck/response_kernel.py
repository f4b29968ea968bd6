"""The compiled Nigam–Jennings recurrence of :mod:`rockcli.codecheck.response`, uniform steps.

The same equations as :func:`rockcli.codecheck.response.peak_displacement` (Chopra, *Dynamics
of Structures*, §5.2, Table 5.2.1), with the same coefficients (computed by
:func:`~rockcli.codecheck.response.step_coefficients`, passed in) and the same arithmetic in
the same order, so the result is the numpy loop's to the last bit; but one compiled loop over
time per period instead of one numpy operation per time step. Measured on this machine
(2 cores, AQV_EW_ITACA.cor.acc, 112,600 samples, one period): 0.67 s for the numpy loop,
about 0.4 ms here; a record study evaluates one or two periods per case.

Only the numeric path imports this module (it imports numba): ``rock --help`` and model
validation never do (spec/engine.md, "Speed").
"""

from __future__ import annotations

import numpy as np
from numba import njit

from rockcli import jitcache

#: numba's on-disk cache, when a writable folder exists (jitcache.py; keyed on the sources).
CACHE = jitcache.configure()


@njit(cache=CACHE)
def peak_response(
    load: np.ndarray, coefficients: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """max |u| and the final state (u, u̇) of oscillators at rest under a uniform load history.

    Nigam & Jennings (1969); Chopra Table 5.2.1: x_{i+1} = A·x_i + b0·p_i + b1·p_{i+1}.

    Args:
        load: p_i = −a_g,i at the samples, uniform steps [m/s²].
        coefficients: (8, n) array, the rows A, B, C, D, A′, B′, C′, D′ of the step, one
            column per oscillator.

    Returns:
        (peak |u| [m], u at the last sample [m], u̇ at the last sample [m/s]), one per column.
    """
    n = coefficients.shape[1]
    peak = np.zeros(n)
    u_end = np.zeros(n)
    v_end = np.zeros(n)
    for j in range(n):
        A, B, C, D = coefficients[0, j], coefficients[1, j], coefficients[2, j], coefficients[3, j]
        A1, B1 = coefficients[4, j], coefficients[5, j]
        C1, D1 = coefficients[6, j], coefficients[7, j]
        u = 0.0
        v = 0.0
        top = 0.0
        for i in range(load.size - 1):
            p0 = load[i]
            p1 = load[i + 1]
            u, v = A * u + B * v + C * p0 + D * p1, A1 * u + B1 * v + C1 * p0 + D1 * p1
            if abs(u) > top:
                top = abs(u)
        peak[j] = top
        u_end[j] = u
        v_end[j] = v
    return peak, u_end, v_end
