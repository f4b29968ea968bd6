"""Many rocking runs of plain blocks under one record in one compiled call (a study's chunk).

A *plain* block is the rectangular block of paper Eq. (1)–(2) on the ground, without loads,
thrusts, a body of another shape or a chain; its restrainers are any of rock's members
(motion.py: elastic, yielding, pretensioned, lost past an elongation, anchored, tie-rods),
packed as ``pack_springs`` packs them and set at rest by the same ``motion.reset_laws``. A study
that varies such a block's sizes, weight, restitution and spring stiffnesses gives each
case's kernel inputs here as arrays (:class:`Blocks`): the parameter vector and restrainer
table of :func:`rockcli.dynamics.simulate.pack_parameters` and ``pack_springs``, one row per
case, with the same arithmetic in the same order, so that every run is bit for bit the run
that :func:`rockcli.dynamics.simulate.assess` makes of the same block (a property test checks
it over random studies). The runs of a chunk are then one call of
:func:`rockcli.dynamics.kernel.integrate_runs`: no Python object per case.

The functions of :mod:`math` (sin, cos, tan, atan2, hypot) are applied with :mod:`math`
itself, value by value (:func:`exactly`): numpy's vectorised versions may differ from the C
library in the last bit, and then the same case would not give the same digits.

Pure and silent: numpy, the kernel, the layouts.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from rockcli import interrupts
from rockcli.dynamics import layout as L
from rockcli.dynamics import motion
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import (
    STEP_BUDGET_BASE,
    STEPS_PER_SAMPLE,
    TAIL_SAMPLES,
    extend_with_tail,
    free_from,
    pack_parameters,
    pack_springs,
    polar_columns,
    rectangle_columns,
    rest_offset,
)
from rockcli.mechanics import Block, frequency_parameter_sq, housner_restitution, polar_inertia


def exactly(fn: Callable[..., float], *args: np.ndarray) -> np.ndarray:
    """fn (a scalar function of floats) of every element, computed by fn itself.

    One argument: fn is called once per distinct value (by bit pattern, so −0.0 and 0.0 stay
    apart); several: once per element.
    """
    if len(args) == 1:
        x = np.ascontiguousarray(args[0], dtype=np.float64)
        bits, where = np.unique(x.view(np.int64), return_inverse=True)
        values = np.array([fn(float(v)) for v in bits.view(np.float64)], dtype=np.float64)
        return values[where.reshape(x.shape)]
    out = np.frompyfunc(lambda *a: float(fn(*a)), len(args), 1)(*args)
    return np.asarray(out, dtype=np.float64)


def python_max(a: np.ndarray, b: float | np.ndarray) -> np.ndarray:
    """Python's max(a, b) element by element (b unless b > a is false: a first)."""
    return np.where(np.greater(b, a), b, a)


@dataclass(frozen=True)
class Blocks:
    """Plain blocks, one per case (module docstring), as arrays.

    Attributes:
        base: one of the blocks, as rockcli.model.derive makes it: what no case changes (the
            flags, the rebound, the restrainers' names, laws and failure elongations) comes
            from it.
        R, alpha: semi-diagonal [m] and slenderness [rad], shape (n,).
        mass: [kg], shape (n,); None for blocks without a mass.
        e: coefficient of restitution [-], shape (n,).
        k_pos, k_neg, r_pos, phi_pos, r_neg, phi_neg: each restrainer's stiffness [N/m] and
            attachment (radius [m], angle [rad]) on each side, shape (n, restrainers).
    """

    base: Block
    R: np.ndarray
    alpha: np.ndarray
    mass: np.ndarray | None
    e: np.ndarray
    k_pos: np.ndarray
    k_neg: np.ndarray
    r_pos: np.ndarray
    phi_pos: np.ndarray
    r_neg: np.ndarray
    phi_neg: np.ndarray

    @property
    def size(self) -> int:
        """Number of blocks."""
        return int(self.R.size)

    @property
    def p2(self) -> np.ndarray:
        """p² = 3g/(4R) (mechanics.frequency_parameter_sq; paper Eq. 2)."""
        return frequency_parameter_sq(self.R, self.base.g)

    @property
    def inertia(self) -> np.ndarray:
        """I0 = 4/3·m·R² (mechanics.polar_inertia; paper §4.3)."""
        assert self.mass is not None
        return polar_inertia(self.mass, self.R)

    @property
    def mirror(self) -> np.ndarray:
        """mechanics.mirror_symmetric of each block: two-sided, each restrainer the same from
        either pivot (a plain block has one restitution and no loads)."""
        same = np.full(self.size, not self.base.one_sided)
        if not all(sp.yield_pos == sp.yield_neg for sp in self.base.restrainers):
            return np.zeros(self.size, dtype=bool)
        if self.k_pos.shape[1]:
            sides = (
                (self.k_pos == self.k_neg)
                & (self.r_pos == self.r_neg)
                & (self.phi_pos == self.phi_neg)
            )
            same &= sides.all(axis=1)
        return same


def housner_e(alpha: np.ndarray, factor: float | np.ndarray) -> np.ndarray:
    """e = max(1 − 1.5 sin²α, 0) × factor (rockcli.model.derive.restitution; paper Eq. 3)."""
    return python_max(exactly(housner_restitution, alpha), 0.0) * factor


def pack_parameter_rows(
    blocks: Blocks, settings: SolverSettings, rtol: float, atol: float
) -> np.ndarray:
    """The kernel's parameter vector of every block, shape (n, N_PARAMS): simulate.
    pack_parameters of the base block, its rectangle's columns made again for every block by
    the same function (simulate.rectangle_columns, value by value through :func:`exactly`)."""
    b = blocks
    par = np.tile(pack_parameters(b.base, settings, rtol, atol), (b.size, 1))
    return rectangle_columns(par, b.R, b.alpha, b.mass, b.e, b.e, b.base.g, b.base.linearized,
                             exactly)  # fmt: skip


def pack_spring_tables(blocks: Blocks) -> np.ndarray:
    """Every block's restrainer table, shape (n, restrainers, N_SPRING_COLS): simulate.
    pack_springs of the base block, each member's stiffness, point and rest offset made again
    for every block by the same functions (simulate.polar_columns, simulate.rest_offset)."""
    b = blocks
    table = np.tile(pack_springs(b.base), (b.size, 1, 1))
    lin = b.base.linearized
    for j, sp in enumerate(b.base.restrainers):
        for col, s, k, r, phi in ((0, 1, b.k_pos, b.r_pos, b.phi_pos),
                                  (1, -1, b.k_neg, b.r_neg, b.phi_neg)):  # fmt: skip
            table[:, j, motion.COL_K_POS + col] = k[:, j]
            polar_columns(table[:, j], s, r[:, j], phi[:, j], sp.lost_at, lin, exactly)
            c0 = rest_offset(sp.pretension, k[:, j], exactly)
            table[:, j, motion.COL_C0 + col] = c0
            table[:, j, motion.COL_C + col] = c0
    if any(sp.has_memory for sp in b.base.restrainers):  # each member's state at rest
        motion.reset_laws(table.reshape(-1, table.shape[2]), lin)
    return table


@dataclass(frozen=True)
class Runs:
    """Both polarities of every block under one record.

    Attributes:
        out_f, out_i: the kernel's float and integer outputs of each block and polarity
            (shape (n, 2, N_FLOAT_OUT), (n, 2, N_INT_OUT); index 0 the record as given, 1
            reversed), times shifted back to the record's origin.
        spring_out: each restrainer's peaks, shape (n, 2, restrainers, N_SPRING_OUT).
        mirrored: True where the reversed run is the mirror image of the first (not
            integrated; its outputs are the first's, θ extremes swapped and negated).
    """

    out_f: np.ndarray
    out_i: np.ndarray
    spring_out: np.ndarray
    mirrored: np.ndarray


def sample_counts(n_record: int, dt: float, tails: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(samples of each run's grid, True where its tail is sampled at dt): extend_with_tail's
    sizes. Grids sampled at dt are prefixes of the longest one."""
    ratio = tails / dt
    fine = ratio <= TAIL_SAMPLES
    n_tail = np.where(fine, np.maximum(1.0, np.ceil(ratio - 1e-9)), TAIL_SAMPLES + 1)
    return (n_record + n_tail).astype(np.int64), fine


def run_blocks(
    time: np.ndarray,
    accel: np.ndarray,
    dt: float,
    blocks: Blocks,
    settings: SolverSettings,
) -> Runs:
    """Both polarities of every block under the record: the runs of simulate.assess (the
    fast engine, no history), in one compiled call per tail grid."""
    from rockcli import jitcache
    from rockcli.dynamics import kernel

    jitcache.ensure_compiled()
    n = blocks.size
    time = np.asarray(time, float)
    accel = np.asarray(accel, float)
    origin = float(time[0])
    shifted = time - origin if origin else time
    tails = tails_for(blocks, settings)
    counts, fine = sample_counts(time.size, dt, tails)
    par = pack_parameter_rows(blocks, settings, settings.rtol, settings.atol)
    # simulate.step_budget of each grid
    budget = np.minimum(settings.max_steps, STEPS_PER_SAMPLE * counts + STEP_BUDGET_BASE)
    par[:, L.P_MAX_STEPS] = budget.astype(float)
    springs = pack_spring_tables(blocks)
    rows = springs.shape[1]
    mirrored = blocks.mirror
    out_f = np.zeros((n, 2, L.N_FLOAT_OUT))
    out_i = np.zeros((n, 2, L.N_INT_OUT), dtype=np.int64)
    spring_out = np.zeros((n, 2, rows, L.N_SPRING_OUT))
    spring_out[..., L.S_T_FAIL] = np.nan
    spring_out[..., L.S_T_YIELD] = np.nan
    points = np.zeros(0)
    for cases, tail in tail_groups(tails, fine):
        grid, acc = extend_with_tail(shifted, accel, dt, tail)
        par[cases, L.P_FREE_FROM] = float(free_from(acc, time.size)) if settings.free_tail else 0.0
        run_case = np.concatenate([cases, cases[~mirrored[cases]]])
        run_pol = np.concatenate([np.ones(cases.size), -np.ones(run_case.size - cases.size)])
        f = np.zeros((run_case.size, L.N_FLOAT_OUT))
        i = np.zeros((run_case.size, L.N_INT_OUT), dtype=np.int64)
        s = np.zeros((run_case.size, rows, L.N_SPRING_OUT))
        s[..., L.S_T_FAIL] = np.nan
        s[..., L.S_T_YIELD] = np.nan
        interrupts.call(kernel.integrate_runs, grid, acc, counts, run_case, run_pol, par,
                        springs, points, f, i, s)  # fmt: skip
        side = (run_pol < 0).astype(np.int64)
        out_f[run_case, side] = f
        out_i[run_case, side] = i
        spring_out[run_case, side] = s
    if origin:
        out_f[..., [L.O_T_END, L.O_T_OVERTURN, L.O_T_UPLIFT]] += origin
        spring_out[..., [L.S_T_FAIL, L.S_T_YIELD]] += origin
    first = out_f[mirrored, 0]
    out_f[mirrored, 1] = first
    out_f[mirrored, 1, L.O_THETA_MAX] = -first[:, L.O_THETA_MIN]
    out_f[mirrored, 1, L.O_THETA_MIN] = -first[:, L.O_THETA_MAX]
    out_i[mirrored, 1] = out_i[mirrored, 0]
    spring_out[mirrored, 1] = spring_out[mirrored, 0]
    return Runs(out_f, out_i, spring_out, mirrored)


def tails_for(blocks: Blocks, settings: SolverSettings) -> np.ndarray:
    """SolverSettings.tail_for of every block: the tail given, else max(DEFAULT_TAIL_MIN,
    TAIL_PERIODS/p) with p = √p² (mechanics.Block.p)."""
    from rockcli.dynamics.settings import DEFAULT_TAIL_MIN, TAIL_PERIODS

    if settings.tail is not None:
        return np.full(blocks.size, float(settings.tail))
    return python_max(np.full(blocks.size, DEFAULT_TAIL_MIN), TAIL_PERIODS / np.sqrt(blocks.p2))


def tail_groups(tails: np.ndarray, fine: np.ndarray) -> list[tuple[np.ndarray, float]]:
    """(cases, tail whose grid serves them): the cases of tails sampled at dt together on the
    longest one's grid (the others' are its prefixes); each other tail with its own grid."""
    groups = []
    if fine.any():
        cases = np.flatnonzero(fine)
        groups.append((cases, float(tails[cases[np.argmax(tails[cases])]])))
    coarse = np.flatnonzero(~fine)
    for tail in np.unique(tails[coarse]):
        groups.append((coarse[tails[coarse] == tail], float(tail)))
    return groups
