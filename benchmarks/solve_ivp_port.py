"""A straight scipy `solve_ivp` port of the usual MATLAB `ode45` rocking loop (the baseline).

This is what engineers write first, and what spec/engine.md measured at 92–187 ms per case:
RK45 with rtol = atol = 1e-6, events for impact and overturning, the integration restarted at
every impact, the ground acceleration interpolated with np.interp inside the right-hand side,
uplift found at the first sample where |üg| > tan α. It is here only to be timed against the
fast engine; it is not part of rock (its accuracy problems are documented in engine.md).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from rockcli.mechanics import Block


def _rhs(block: Block, times: np.ndarray, accel: np.ndarray, s: int):  # type: ignore[no-untyped-def]
    alpha, p2 = block.alpha, block.p2
    inv_i0 = 1.0 / block.inertia if block.mass else 0.0

    def f(t: float, y: np.ndarray) -> list[float]:
        ag = np.interp(t, times, accel)
        a = s * y[0]
        acc = -s * p2 * math.sin(alpha - a) + p2 * ag * math.cos(alpha - a)
        for sp in block.restrainers:
            k, r, phi = sp.side(s)
            u = r * (math.sin(phi) - math.sin(phi - a))
            acc -= s * k * u * r * math.cos(phi - a) * inv_i0
        return [y[1], acc]

    return f


def _events(s: int, overturn: float):  # type: ignore[no-untyped-def]
    def impact(t: float, y: np.ndarray) -> float:
        return s * y[0]

    def topple(t: float, y: np.ndarray) -> float:
        return s * y[0] - overturn

    impact.terminal, impact.direction = True, -1  # type: ignore[attr-defined]
    topple.terminal, topple.direction = True, 1  # type: ignore[attr-defined]
    return [impact, topple]


def _next_uplift(times: np.ndarray, accel: np.ndarray, t: float, thr: float) -> tuple[float, int]:
    idx = np.nonzero((times >= t) & (np.abs(accel) > thr))[0]
    if idx.size == 0:
        return math.inf, 0
    k = idx[0]
    return float(times[k]), int(np.sign(accel[k]))


def run_port(
    block: Block,
    times: np.ndarray,
    accel: np.ndarray,
    t_end: float,
    overturn: float = math.pi / 2,
    rtol: float = 1e-6,
    max_step: float = math.inf,
) -> dict[str, float]:
    """Max |θ|/α and overturning of one run, the MATLAB-loop way.

    ``max_step = dt`` is the usual first attempt at fixing its accuracy (engine.md: it does
    not fix it); the benchmark times both variants.
    """
    thr = math.tan(block.alpha)
    t, y, s, peak, impacts = float(times[0]), [0.0, 0.0], 0, 0.0, 0
    while t < t_end:
        if s == 0:
            t, s = _next_uplift(times, accel, t, thr)
            if s == 0 or t >= t_end:
                break
            y = [0.0, 0.0]
        sol = solve_ivp(
            _rhs(block, times, accel, s),
            (t, t_end),
            y,
            method="RK45",
            rtol=rtol,
            atol=rtol,
            events=_events(s, overturn),
            max_step=max_step,
        )
        peak = max(peak, float(np.max(np.abs(sol.y[0]))))
        if sol.status != 1:
            break
        if sol.t_events[1].size:
            return {"max_ratio": overturn / block.alpha, "overturned": 1.0, "impacts": impacts}
        t_hit, y_hit = float(sol.t_events[0][0]), sol.y_events[0][0]
        impacts += 1
        om = block.e * y_hit[1]
        if abs(om) < 1e-4 or t_hit - t < 1e-12:
            s, t = 0, t_hit + 1e-9
            continue
        t, y, s = t_hit, [0.0, om], -s
    return {"max_ratio": peak / block.alpha, "overturned": 0.0, "impacts": impacts}
