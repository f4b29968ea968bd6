"""A mechanism of several bodies as the rocking engine reads it: a table of its equation of
motion (mechanics.ChainTable).

The two-block vertical flexure's terms M(θ), M′(θ), V′(θ) = G, g·Γ(θ) = H and the thrusts'
T(θ) come from its configuration function (rockcli.mechanisms.motion), which walks the chain
link by link — too slow to call inside the compiled step. They are evaluated once per
mechanism on a uniform grid of each side's rotation, with their derivatives, and the engine
interpolates them by cubic Hermite polynomials (mechanics.chain_terms). The grid of
:data:`NODES` nodes keeps the interpolation error h⁴·|f⁗|/384 far below the engine's tolerance
(measured against the configuration function in tests/mechanisms/test_flexure_dynamics.py:
G, H, T and M to about 1e-11 of their size, M′ to 1e-7 of M per radian near the table's end); the
reference engine reads the configuration function itself (ChainTable.exact), so the agreement of
the two engines measures the table's error too.

Pure and silent: :mod:`math`, numpy (the grid's nodes at once) and the package's own
modules.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache

import numpy as np

from rockcli.mechanics import CH_HEAD, PA_COLS, PA_HEAD, ChainTable
from rockcli.mechanisms.links import Angle
from rockcli.mechanisms.motion import (
    MASS_STEP,
    generalised_mass,
    impact_ratio,
    mass_slope,
)
from rockcli.mechanisms.side import ChainSide

#: Nodes of the grid of each side (the interpolation error falls as the fourth power of the
#: step: tests/mechanisms/test_flexure_dynamics.py measures it).
NODES = 1025
#: The table, and the run, end at this share of the motion's limit (where the upper block's
#: chord lies flat and M grows without bound): a chain that opens so far has collapsed.
END_SHARE = 0.9
#: Step of the central differences of G, H and T [rad] (as motion.MASS_STEP: truncation and
#: rounding balance near (3ε)^(1/3)).
SLOPE_STEP = MASS_STEP
#: Step of the central difference of M′ [rad]: M′ is itself a difference, with rounding
#: ε·|M|/MASS_STEP, so its own difference needs a longer step. Measured on the example's
#: flexure over 95 % of the table (the interpolated M′ against M's central difference at
#: 1e-6): worst error 3.8e-7·M at 1e-3, 3.2e-8·M at 3e-4, 6.7e-8·M at 1e-4.
CURVATURE_STEP = 3e-4
#: Bisection steps of the instability rotation.
BISECTION_STEPS = 80


def terms(side: ChainSide, a: float) -> tuple[float, float, float, float, float]:
    """(G, H, T, M, M′) at rotation a: the weights' V′, g·Γ (per g), the thrusts' opening
    work, the generalised mass and its slope (rockcli.mechanisms.motion)."""
    g, t, h = side.work_terms(a)
    return g, h, t, generalised_mass(side, a), mass_slope(side, a)


def slopes(side: ChainSide, a: float, mp: float) -> tuple[float, float, float, float, float]:
    """d/da of (G, H, T, M, M′) at a, by central differences (M′ is M's slope ``mp``)."""
    hs, hc = SLOPE_STEP, CURVATURE_STEP
    (g1, t1, h1), (g0, t0, h0) = side.work_terms(a + hs), side.work_terms(a - hs)
    curvature = (mass_slope(side, a + hc) - mass_slope(side, a - hc)) / (2.0 * hc)
    return (g1 - g0) / (2 * hs), (h1 - h0) / (2 * hs), (t1 - t0) / (2 * hs), mp, curvature


def nodes(end: float) -> Angle:
    """The NODES rotations of the table's grid on [0, end] [rad] (an array, which the chain's
    functions take in place of one rotation: rockcli.mechanisms.links.Angle)."""
    return end * np.arange(NODES) / (NODES - 1)


def columns(*values: float | np.ndarray) -> tuple[float, ...]:
    """Columns of values at the nodes (a number: the same at every node) as the table's
    rows, node after node."""
    grid = np.column_stack(np.broadcast_arrays(*values, np.empty(NODES)))[:, : len(values)]
    return tuple(grid.ravel().tolist())


def rows(side: ChainSide, end: float) -> tuple[float, ...]:
    """The side's NODES rows of the table on [0, end], every node at once (the configuration
    function of an array of rotations: numpy's sin and cos, which may differ from math's in
    the last bit, far below the interpolation's error)."""
    a = nodes(end)
    values = terms(side, a)
    return columns(*values, *slopes(side, a, values[4]))


def path_rows(side: ChainSide, index: int, end: float) -> tuple[float, ...]:
    """(u, u′, u″) of restrainer ``index``'s point on ``side`` at the NODES nodes of [0, end]:
    its displacement away from the wall, its virtual displacement δx per unit rotation (both
    from the configuration function, to a few ulps) and δx's central difference."""
    point = side.placement(index)
    a = nodes(end)
    slope = point.moment(1.0, a)  # F·δx for F = 1: δx
    ahead, behind = point.moment(1.0, a + SLOPE_STEP), point.moment(1.0, a - SLOPE_STEP)
    return columns(point.elongation(a), slope, (ahead - behind) / (2.0 * SLOPE_STEP))


@lru_cache(maxsize=256)
def shrinks_at(plus: ChainSide, minus: ChainSide, index: int) -> tuple[int, float] | None:
    """(side, rotation [rad]) of the first node of the chain's grid at which restrainer
    ``index``'s elongation stops growing (δx ≤ 0: its point turns back towards its anchor);
    None when it grows over the whole table on both sides."""
    end = end_of(plus, minus)
    a = nodes(end)
    for s, side in ((1, plus), (-1, minus)):
        turned = np.flatnonzero(side.placement(index).moment(1.0, a) <= 0.0)
        if len(turned):
            return s, float(a[turned[0]])
    return None


@lru_cache(maxsize=64)
def member_path(plus: ChainSide, minus: ChainSide, index: int) -> tuple[float, ...]:
    """The elongation path of restrainer ``index`` (mechanics.Restrainer.path: PA_* layout) on
    the grid of :func:`tabulate`: for a member whose point does not turn rigidly about the
    pivot (on the upper block of a two-block chain), whose force F enters the equation of
    motion by virtual work as F·u′(a). Its elongation must grow with the rotation of each side
    (:func:`shrinks_at` None): the member laws' levels are rotations."""
    end = end_of(plus, minus)
    step = end / (NODES - 1)
    rows = [*path_rows(plus, index, end), *path_rows(minus, index, end)]
    path = (float(NODES), step, step, *rows)
    assert len(path) == PA_HEAD + 2 * NODES * PA_COLS
    return path


def instability(side: ChainSide, end: float) -> float:
    """The rotation at which the weights' and thrusts' restoring moment G − T vanishes (the
    capacity curve's zero without restrainers; for a rectangle, α) [rad]; ``end`` if it does
    not within [0, end]."""

    def restoring(a: float) -> float:
        g, t, _ = side.work_terms(a)
        return g - t

    if restoring(end) > 0.0:
        return end
    lo, hi = 0.0, end
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if restoring(mid) > 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def uplift(side: ChainSide) -> float:
    """α0 = (G − T)/H at rest [g]: the code check's expression (rockcli.codecheck.kinematic
    .activation_terms without a pretension), so that the two agree bit for bit."""
    g, t, h = side.work_terms(0.0)
    return (g - t) / h


def end_of(plus: ChainSide, minus: ChainSide) -> float:
    """The rotation the table reaches on both sides [rad]."""
    return END_SHARE * min(plus.limit, minus.limit)


def tabulate(plus: ChainSide, minus: ChainSide) -> ChainTable:
    """The chain whose side +1 is ``plus`` and side −1 ``minus`` (the same bodies and loads,
    seen from each pivot) as the engine reads it: its bodies, loads and thrusts, whatever its
    restrainers (which enter the equation by their own paths, :func:`member_path`), so that
    a chain tabulated once serves every rod a retrofit tries on it."""
    return tabulate_weights(without_members(plus), without_members(minus))


def without_members(side: ChainSide) -> ChainSide:
    """The side without its restrainers (what the table does not read)."""
    return replace(side, restrainers=(), anchors=())


@lru_cache(maxsize=64)
def tabulate_weights(plus: ChainSide, minus: ChainSide) -> ChainTable:
    """:func:`tabulate` of sides without restrainers (cached by them)."""
    end = end_of(plus, minus)
    step = end / (NODES - 1)
    g0, h0, _, m0, _ = terms(plus, 0.0)

    def exact(s: int, a: float) -> tuple[float, float, float, float, float]:
        return terms(plus if s > 0 else minus, a)

    def stiffness(side: ChainSide) -> float:
        g, h, t, _, mp = terms(side, 0.0)
        dg, _, dt, _, _ = slopes(side, 0.0, mp)
        return dg - dt

    table = (float(NODES), step, step, *rows(plus, end), *rows(minus, end))
    assert len(table) == CH_HEAD + 2 * NODES * 10
    return ChainTable(
        table=table,
        uplift=(uplift(plus), uplift(minus)),
        restitution=(impact_ratio(plus, minus), impact_ratio(minus, plus)),
        inertia=(m0, generalised_mass(minus, 0.0)),
        stiffness=(stiffness(plus), stiffness(minus)),
        end=end,
        p2=math.hypot(g0, h0) / m0,
        exact=exact,
    )
