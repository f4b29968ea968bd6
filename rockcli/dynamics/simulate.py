"""Run the rocking time history of a block under a record: pack, integrate, unpack.

The ground motion is the record's samples, linear between them, followed by a free tail: the
last sample ramps to zero over one record interval (the record ends) and the block then moves
freely (spec/rocking.md, "Duration"). The tail keeps the record's interval up to TAIL_SAMPLES
samples and is sampled more coarsely past that (the error controller chooses the steps there;
the samples only mark where the history is stored).

Times are taken relative to the record's first sample inside the engines and shifted back in
the results, so a record timed from any origin (e.g. the Unix epoch) runs as if from zero.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from rockcli import interrupts
from rockcli.dynamics import layout as L
from rockcli.dynamics import motion
from rockcli.dynamics.result import (
    Assessment,
    History,
    RestrainerPeak,
    RockingRun,
    RunStatus,
)
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.mechanics import (
    NEGATIVE,
    PA_COLS,
    PA_HEAD,
    PA_N,
    PA_STEP_NEG,
    PA_STEP_POS,
    Chain,
    Restrainer,
    Rocker,
    chain_terms,
    collapse_rotations,
    frequency_parameter_sq,
    mirror_symmetric,
    point_moments,
    point_table,
    polar_inertia,
    spring_failure_rotation,
    uplift_accelerations,
)
from rockcli.notes import Note

#: Most samples of the free tail: up to this many, at the record's interval dt; past it, the
#: tail (from one dt after the record to its end) is split into TAIL_SAMPLES equal intervals.
#: The ground is at rest there, so the samples only mark where steps are clipped and where the
#: history is stored; the error controller chooses the steps. Bounds memory and work: 100
#: samples at dt = 1e-7 s with a 10 s tail held 1e8 tail samples (2.6 GB with the history).
TAIL_SAMPLES = 65_536
#: Work budget of a run: STEPS_PER_SAMPLE steps (accepted + rejected) per sample of the
#: integration grid (record and tail), plus STEP_BUDGET_BASE, and never more than the settings'
#: max_steps; past it the run ends as "step-limit". Measured on the benchmark's records with
#: top springs up to K = 1e11 N/m, at rtol = atol = 1e-12: at most 11 steps per sample (steps
#: grow like √(K/m)·dt). An absurdly stiff model (K = 1e15 N/m on a 50 kg block, ELC180 × 3)
#: took 6 600 per sample: 33 million steps, 204 s, to report "survives". The reference engine
#: counts a DOP853 step as 12 evaluations of the right-hand side and has the same budget.
STEPS_PER_SAMPLE = 200
STEP_BUDGET_BASE = 100_000


def extend_with_tail(
    time: np.ndarray, accel: np.ndarray, dt: float, tail: float
) -> tuple[np.ndarray, np.ndarray]:
    """Sample times and accelerations [g] with `tail` seconds of zeros after the record.

    The first tail sample is one dt after the record (the last sample ramps to zero). Up to
    TAIL_SAMPLES samples, the tail is sampled at dt and ends ceil(tail/dt)·dt after the record;
    past that, it ends `tail` after the record, in TAIL_SAMPLES equal intervals after the ramp.
    """
    ratio = tail / dt
    if ratio <= TAIL_SAMPLES:
        n_tail = max(1, math.ceil(ratio - 1e-9))
        t_tail = time[-1] + dt * np.arange(1, n_tail + 1)
    else:
        t_tail = time[-1] + dt + (tail - dt) * (np.arange(TAIL_SAMPLES + 1) / TAIL_SAMPLES)
    return (
        np.ascontiguousarray(np.concatenate([time, t_tail]), dtype=np.float64),
        np.ascontiguousarray(np.concatenate([accel, np.zeros(t_tail.size)]), dtype=np.float64),
    )


def samples_with_tail(
    time: np.ndarray, accel: np.ndarray, dt: float, tail: float
) -> tuple[np.ndarray, np.ndarray, int]:
    """The kernel's samples (extend_with_tail, the record timed from 0) and the first free
    sample (free_from). :func:`assess` makes them once for both polarities."""
    origin = float(time[0])
    times, acc = extend_with_tail(time - origin if origin else time, accel, dt, tail)
    return times, acc, free_from(acc, time.size)


def free_from(accel: np.ndarray, n_record: int) -> int:
    """The first sample from which the ground stays at rest to the end: one past the record's
    last non-zero sample (a zero-padded record rests before its tail), at most the first
    sample of the tail. The segment that ramps to zero before it is integrated as usual."""
    moving = np.flatnonzero(accel[:n_record])
    return int(moving[-1]) + 1 if moving.size else 0


def step_budget(n_samples: int, max_steps: int) -> int:
    """Steps a run may take over a grid of n_samples samples (STEPS_PER_SAMPLE, module doc)."""
    return min(max_steps, STEPS_PER_SAMPLE * n_samples + STEP_BUDGET_BASE)


def pack_parameters(
    block: Rocker, settings: SolverSettings, rtol: float, atol: float
) -> np.ndarray:
    """The kernel's parameter vector (layout P_* in layout.py): the settings and flags, then the
    constants of the input's kind (the rectangle's by :func:`rectangle_columns`, the form
    the batched path applies to many blocks at once)."""
    par = np.zeros(L.N_PARAMS)
    if block.kind == "rectangle":
        return rectangle_columns(
            flag_columns(par, block, settings, rtol, atol), block.R, block.alpha, block.mass,
            block.e, block.restitution(NEGATIVE), block.g, block.linearized, math_of,
        )  # fmt: skip
    par = flag_columns(par, block, settings, rtol, atol)
    par[L.P_ALPHA] = block.alpha
    par[L.P_SIN_ALPHA] = math.sin(block.alpha)
    par[L.P_COS_ALPHA] = math.cos(block.alpha)
    par[L.P_P2] = block.p2
    par[L.P_E] = block.e
    par[L.P_INV_I0] = 1.0 / block.inertia if block.mass is not None else 0.0
    par[L.P_I0] = block.own_inertia if block.mass is not None else 0.0
    par[L.P_UPLIFT_POS], par[L.P_UPLIFT_NEG] = uplift_accelerations(block)
    par[L.P_E_NEG] = block.restitution(NEGATIVE)
    for s, scale, inertia in (
        (1, L.P_PRE_SCALE_POS, L.P_INERTIA_POS),
        (-1, L.P_PRE_SCALE_NEG, L.P_INERTIA_NEG),
    ):
        par[scale], par[inertia] = rest_terms(block, s)
    return friction_columns(par, block)


def friction_columns(par: np.ndarray, block: Rocker) -> np.ndarray:
    """The toothed return walls' friction (P_RUB*): a rigid body's one friction, or none."""
    if not block.frictions:
        return par
    if block.kind != "points" or len(block.frictions) > 1:
        raise ValueError("the engines take one friction, on a rigid body")
    f = block.frictions[0]
    par[L.P_RUB], par[L.P_RUB_X_POS], par[L.P_RUB_X_NEG] = f.force, f.x_pos, f.x_neg
    par[L.P_RUB_Z0], par[L.P_RUB_H], par[L.P_RUB_L] = f.z0, f.height, f.overlap
    return par


def flag_columns(par: np.ndarray, block: Rocker, settings: SolverSettings, rtol: float,
                 atol: float) -> np.ndarray:  # fmt: skip
    """The columns every kind shares: its motion's flags, the run's settings, its kind."""
    par[L.P_ONE_SIDED] = 1.0 if block.one_sided else 0.0
    par[L.P_FREE_SIDE] = float(block.free_side)
    par[L.P_REBOUND] = block.rebound
    par[L.P_LINEAR] = 1.0 if block.linearized else 0.0
    par[L.P_KIND] = engine_kind(block)
    # a chain collapses where its table ends
    par[L.P_OVERTURN] = par[L.P_OVERTURN_NEG] = min(settings.overturn_angle, block.collapse_limit)
    par[L.P_RTOL] = rtol
    par[L.P_ATOL] = atol
    par[L.P_REST] = settings.rest_velocity
    par[L.P_MAX_EVENTS] = float(settings.max_events)
    par[L.P_MAX_STEPS] = float(settings.max_steps)
    return par


def math_of(fn, *x):
    """fn(x…) for one block (floats): :mod:`math` itself."""
    return fn(*x)


def rectangle_columns(par, R, alpha, mass, e, e_neg, g, linearized, apply):
    """The rectangle's constants in the parameter vector ``par`` (paper Eqs. 1–3, closed
    forms), written once for one block (floats, ``apply`` = :func:`math_of`) and for many at
    once (arrays of shape (n,) into ``par`` of shape (n, N_PARAMS), ``apply`` =
    rockcli.dynamics.batch.exactly: :mod:`math` value by value), so that a batched run is
    bit for bit the run of the same block: α with its sine and cosine, p² = 3g/(4R)
    (mechanics.frequency_parameter_sq), e on each side, the uplift tan α (α linearized:
    mechanics.uplift_threshold) on each side, and with a mass I0 = 4/3·m·R²
    (mechanics.polar_inertia), its inverse, the ground acceleration per N·m at rest 1/H(0),
    H(0) = m g R cos α (:func:`rest_terms`), and the inertia at rest on each side."""
    par[..., L.P_ALPHA] = alpha
    par[..., L.P_SIN_ALPHA] = apply(math.sin, alpha)
    cos_alpha = apply(math.cos, alpha)
    par[..., L.P_COS_ALPHA] = cos_alpha
    par[..., L.P_P2] = frequency_parameter_sq(R, g)
    par[..., L.P_E] = e
    par[..., L.P_E_NEG] = e_neg
    uplift = alpha if linearized else apply(math.tan, alpha)
    par[..., L.P_UPLIFT_POS] = uplift
    par[..., L.P_UPLIFT_NEG] = uplift
    if mass is None:
        return par
    inertia = polar_inertia(mass, R)
    h = mass * g * R * (1.0 if linearized else cos_alpha)
    par[..., L.P_INV_I0] = 1.0 / inertia
    par[..., L.P_I0] = inertia
    for scale, moment in ((L.P_PRE_SCALE_POS, L.P_INERTIA_POS),
                          (L.P_PRE_SCALE_NEG, L.P_INERTIA_NEG)):  # fmt: skip
        par[..., scale] = 1.0 / h
        par[..., moment] = inertia
    return par


#: The engine's code (layout K_*) of each kind of input (mechanics.Rocker.kind).
KINDS = {"rectangle": L.K_RECTANGLE, "points": L.K_POINTS, "chain": L.K_CHAIN}


def engine_kind(block: Rocker) -> int:
    """The equation the engine integrates (layout K_*): the rectangle's closed form, a rigid
    body's point table, or a chain's table."""
    return KINDS[block.kind]


def rest_terms(block: Rocker, s: int) -> tuple[float, float]:
    """(ground acceleration [g] per N·m of restoring moment, polar moment of inertia [kg·m²])
    about pivot s at rest; (0, 0) for a block without a mass.

    The uplift condition at a = 0 is üg·H(0) > G(0) − s·T(0) + M (loaded_angular_acceleration;
    for the free block H(0) = m·g·R·cos α, linearized m·g·R), so a restoring moment M at rest
    raises the uplift acceleration by M/H(0). The inertia is I0 + J(0) (docs/physics.md).
    """
    if block.mass is None:
        return 0.0, 0.0
    if isinstance(block, Chain):  # the table's node 0: the terms at rest
        g, h, _, m, _ = chain_terms(block.table.table, s, 0.0)
        return 1.0 / h, m
    if block.kind == "points":
        _, h, _, j, _ = point_moments(point_table(block), s, 0.0, 1.0)
        return 1.0 / h, block.own_inertia + j
    h = block.mass * block.g * block.R * (1.0 if block.linearized else math.cos(block.alpha))
    return 1.0 / h, block.inertia


def pack_points(block: Rocker) -> np.ndarray:
    """The flat point table of the block, its loads and thrusts (mechanics.point_table).

    Empty for a block without loads and thrusts: the kernel then integrates the free block's
    equation (paper Eq. 2) exactly as before loads existed.
    """
    if block.kind == "rectangle":
        return np.zeros(0)
    if isinstance(block, Chain):
        return np.ascontiguousarray(block.table.table, dtype=np.float64)
    if block.linearized:
        raise ValueError("the linearized equation does not take loads or thrusts")
    return np.ascontiguousarray(point_table(block), dtype=np.float64)


def pack_springs(block: Rocker) -> np.ndarray:
    """The packed restrainer table (columns in motion.py), failure rotations precomputed; as
    wide as the longest elongation path (from motion.COL_PATH) when a member has one."""
    width = motion.N_SPRING_COLS + max((len(sp.path) for sp in block.restrainers), default=0)
    table = np.zeros((len(block.restrainers), width))
    for j, sp in enumerate(block.restrainers):
        if block.mass is None and (sp.k_pos or sp.k_neg):
            raise ValueError("a block with restrainers needs a mass")
        table[j, motion.COL_K_POS] = sp.k_pos
        table[j, motion.COL_K_NEG] = sp.k_neg
        pack_point(table, j, sp, block.linearized)
        table[j, motion.COL_FAILS_AT] = sp.lost_at
        pack_law(table[j], sp)
    motion.reset_laws(table, block.linearized)
    return table


def pack_point(table: np.ndarray, j: int, sp: Restrainer, linearized: bool) -> None:
    """Row j's point: r, φ, their sines and cosines and the rotation at which it is lost, on
    each side; a member with an elongation path has it from motion.COL_PATH, with r = u′(0) and
    φ = 0 (the arm at rest: motion.py)."""
    if not sp.path:
        for s, r, phi in ((1, sp.r_pos, sp.phi_pos), (-1, sp.r_neg, sp.phi_neg)):
            polar_columns(table[j], s, r, phi, sp.lost_at, linearized, math_of)
        return
    table[j, motion.COL_PATH : motion.COL_PATH + len(sp.path)] = sp.path
    for s in (1, -1):
        col_r, col_phi, col_fail, col_sin = POINT_COLUMNS[s]
        table[j, col_r] = sp.arm_at_rest(s)
        table[j, col_phi] = 0.0
        table[j, col_sin] = math.sin(0.0)
        table[j, col_sin + 1] = math.cos(0.0)  # COL_COS_* follows COL_SIN_*
        table[j, col_fail] = motion.rotation_at_elongation(table, j, s, sp.lost_at, linearized)


#: The columns of a member's point on each side: r, φ, the rotation at which it is lost, sin φ
#: (cos φ follows).
POINT_COLUMNS = {
    1: (motion.COL_R_POS, motion.COL_PHI_POS, motion.COL_A_FAIL_POS, motion.COL_SIN_POS),
    -1: (motion.COL_R_NEG, motion.COL_PHI_NEG, motion.COL_A_FAIL_NEG, motion.COL_SIN_NEG),
}


def polar_columns(rows, s, r, phi, lost, linearized, apply):
    """Side s's point of a member turning rigidly with the body, at (r, φ) from the pivot:
    r, φ, sin φ, cos φ and the rotation at which its elongation reaches ``lost``
    (mechanics.spring_failure_rotation), into one packed row (floats, ``apply`` =
    :func:`math_of`) or a column of rows (arrays, ``apply`` = rockcli.dynamics.batch.exactly)."""
    col_r, col_phi, col_fail, col_sin = POINT_COLUMNS[s]
    rows[..., col_r] = r
    rows[..., col_phi] = phi
    rows[..., col_sin] = apply(math.sin, phi)
    rows[..., col_sin + 1] = apply(math.cos, phi)  # COL_COS_* follows COL_SIN_*
    rows[..., col_fail] = apply(
        lambda r_, phi_: spring_failure_rotation(r_, phi_, lost, linearized), r, phi
    )


def rest_offset(pretension: float, k, apply):
    """The elongation at which a pretensioned member's force is nil, −P0/K (0 where K = 0),
    for one member (float) or many (array)."""
    return apply(lambda k_: -pretension / k_ if k_ > 0.0 else 0.0, k)


def pack_law(row: np.ndarray, sp: Restrainer) -> None:
    """The member law's columns of one packed row (motion.py): yields, rupture force, c0.

    The state columns (c, mode, levels) are then set to rest by motion.reset_laws (pack_springs):
    a packed table holds the state of one run's members, which the engines update. A member
    without memory (elastic, no pretension, no anchor) keeps COL_MEMORY = 0 and runs the elastic
    spring's arithmetic.
    """
    row[motion.COL_YIELD] = sp.yield_pos
    row[motion.COL_YIELD + 1] = sp.yield_neg
    row[motion.COL_RUPTURE] = sp.rupture_force
    row[motion.COL_MEMORY] = 1.0 if sp.has_memory else 0.0
    for col, k in ((0, sp.k_pos), (1, sp.k_neg)):
        c0 = rest_offset(sp.pretension, k, math_of)
        row[motion.COL_C0 + col] = c0
        row[motion.COL_C + col] = c0
        row[motion.COL_UP + col] = math.inf
        row[motion.COL_DOWN + col] = motion.NO_LEVEL_DOWN


def simulate(
    block: Rocker,
    time: np.ndarray,
    accel: np.ndarray,
    dt: float,
    *,
    polarity: int = 1,
    settings: SolverSettings | None = None,
    engine: Engine = Engine.FAST,
    history: bool = False,
    theta0: float = 0.0,
    omega0: float = 0.0,
    samples: tuple[np.ndarray, np.ndarray, int] | None = None,
) -> RockingRun:
    """One rocking run of `block` under the ground acceleration `accel` [g] at `time` [s].

    Args:
        block: the block and its restrainers.
        time, accel: record samples (uniform or not); dt: the interval of the free tail [s].
        polarity: +1 as recorded, −1 reversed.
        settings: tolerances and thresholds (defaults: spec/engine.md).
        engine: FAST (compiled DP5(4)) or REFERENCE (scipy DOP853, tight tolerance).
        history: keep θ(t), θ̇(t) at the sample times.
        theta0, omega0: initial rotation [rad] and velocity [rad/s] (default: at rest).
        samples: :func:`samples_with_tail` of these arrays and this block's tail, when the
            caller has made them (both polarities share them); made here otherwise.
    """
    settings = settings or SolverSettings()
    time = np.asarray(time, float)
    origin = float(time[0])
    if samples is None:
        samples = samples_with_tail(time, np.asarray(accel, float), dt, settings.tail_for(block.p))
    times, acc, first_free = samples
    if engine is Engine.REFERENCE:
        rtol, atol = _reference_tolerances()
    else:
        from rockcli import jitcache
        from rockcli.dynamics import kernel  # noqa: F401  (configures the cache first)

        jitcache.ensure_compiled()
        rtol, atol = settings.rtol, settings.atol
    par = pack_parameters(block, settings, rtol, atol)
    par[L.P_THETA0] = theta0
    par[L.P_OMEGA0] = omega0
    par[L.P_MAX_STEPS] = float(step_budget(times.size, settings.max_steps))
    par[L.P_FREE_FROM] = float(first_free) if settings.free_tail else 0.0
    springs = pack_springs(block)
    points = pack_points(block)
    alive = np.ones(len(block.restrainers), dtype=np.int64)
    n_hist = times.size if history else 1
    hist_th = np.full(n_hist, np.nan)
    hist_om = np.full(n_hist, np.nan)
    hist_f = np.zeros((n_hist, len(block.restrainers)))
    out_f = np.zeros(L.N_FLOAT_OUT)
    out_i = np.zeros(L.N_INT_OUT, dtype=np.int64)
    spring_out = np.zeros((len(block.restrainers), L.N_SPRING_OUT))
    spring_out[:, L.S_T_FAIL] = np.nan
    spring_out[:, L.S_T_YIELD] = np.nan
    arrays = (times, acc, float(polarity), par, springs, points, alive)
    outputs = (hist_th, hist_om, hist_f, out_f, out_i, spring_out)
    if engine is Engine.REFERENCE:  # Python: Ctrl-C stops it where it is
        from rockcli.dynamics.reference import integrate_reference

        exact = None
        if isinstance(block, Chain):
            if block.table.exact is None:
                raise ValueError("the reference engine needs the chain's configuration function")
            exact = block.table.exact
        integrate_reference(*arrays, *outputs, exact=exact)
    else:  # compiled: Ctrl-C deferred to the end of the run (rockcli.interrupts)
        from rockcli.dynamics.kernel import integrate

        interrupts.call(integrate, *arrays, *outputs)
    hist = None
    if history:
        hist = _history(times, hist_th, hist_om, hist_f, out_f[L.O_T_END], origin)
        hist = replace(hist, elongations=elongations(block, hist.theta))
    if origin:
        out_f[[L.O_T_END, L.O_T_OVERTURN, L.O_T_UPLIFT]] += origin
        spring_out[:, [L.S_T_FAIL, L.S_T_YIELD]] += origin
    return _unpack(
        block, par, engine, rtol, atol, polarity, out_f, out_i, spring_out, springs, hist
    )


def _reference_tolerances() -> tuple[float, float]:
    from rockcli.dynamics.settings import REFERENCE_ATOL, REFERENCE_RTOL

    return REFERENCE_RTOL, REFERENCE_ATOL


def _history(
    times: np.ndarray,
    th: np.ndarray,
    om: np.ndarray,
    forces: np.ndarray,
    t_end: float,
    origin: float,
) -> History:
    keep = (times <= t_end) & np.isfinite(th)
    return History(
        time=times[keep] + origin, theta=th[keep], omega=om[keep], forces=forces[keep].T.copy()
    )


def elongations(block: Rocker, theta: np.ndarray) -> np.ndarray:
    """Each restrainer's elongation at the rotations θ [m], shape (restrainers, samples): the
    member of pivot O for θ > 0, of O′ for θ < 0, 0 at rest (for plots: the engine's geometry,
    Restrainer.elongation, evaluated on arrays)."""
    out = np.zeros((len(block.restrainers), theta.size))
    for j, sp in enumerate(block.restrainers):
        for s in (1, -1):
            on = s * theta > 0.0
            a = np.abs(theta[on])
            out[j, on] = (
                _path_elongation(sp.path, s, a)
                if sp.path
                else _polar_elongation(*sp.side(s)[1:], a, block.linearized)
            )
    return out


def _polar_elongation(r: float, phi: float, a: np.ndarray, linearized: bool) -> np.ndarray:
    """mechanics.spring_elongation on an array of rotations [m]."""
    if linearized:
        return r * math.cos(phi) * a
    return r * (math.cos(phi) * np.sin(a) + math.sin(phi) * 2.0 * np.sin(0.5 * a) ** 2)


def _path_elongation(path: tuple[float, ...], s: int, a: np.ndarray) -> np.ndarray:
    """mechanics.path_terms' u on an array of rotations [m]."""
    n = int(path[PA_N])
    step = path[PA_STEP_POS] if s > 0 else path[PA_STEP_NEG]
    rows = np.asarray(path[PA_HEAD:]).reshape(2, n, PA_COLS)[0 if s > 0 else 1]
    x = a / step
    k = np.clip(np.floor(x).astype(np.int64), 0, n - 2)
    u = x - k
    h00, h10 = 2 * u**3 - 3 * u**2 + 1, (u**3 - 2 * u**2 + u) * step
    h01, h11 = 3 * u**2 - 2 * u**3, (u**3 - u**2) * step
    return h00 * rows[k, 0] + h10 * rows[k, 1] + h01 * rows[k + 1, 0] + h11 * rows[k + 1, 1]


def _optional(x: float) -> float | None:
    return None if math.isnan(x) else float(x)


def plastic_elongation(springs: np.ndarray, j: int) -> float:
    """Row j's plastic elongation after a run [m]: the larger over its two members of c − c0."""
    return max(
        0.0,
        *(
            float(springs[j, motion.COL_C + col] - springs[j, motion.COL_C0 + col])
            for col in (0, 1)
        ),
    )


def side_ratio(block: Rocker, theta_max: float, theta_min: float) -> float:
    """max |θ|/θc over the run, each side's extreme over its own collapse rotation
    (mechanics.collapse_rotations): the damage measure every mechanism shares [-]. The
    rectangle's θc is α on both sides: max|θ|/α."""
    c_pos, c_neg = collapse_rotations(block)
    return float(max(theta_max / c_pos, -theta_min / c_neg, 0.0))


def _unpack(
    block, par, engine, rtol, atol, polarity, out_f, out_i, spring_out, springs, hist
) -> RockingRun:
    status = RunStatus(L.STATUS_NAMES[int(out_i[L.I_STATUS])])
    peaks = tuple(
        RestrainerPeak(
            name=sp.name,
            max_displacement=float(spring_out[j, L.S_MAX_U]),
            max_force=float(spring_out[j, L.S_MAX_FORCE]),
            t_fail=_optional(spring_out[j, L.S_T_FAIL]),
            t_yield=_optional(spring_out[j, L.S_T_YIELD]),
            plastic_elongation=plastic_elongation(springs, j),
            energy_dissipated=float(spring_out[j, L.S_ENERGY]),
        )
        for j, sp in enumerate(block.restrainers)
    )
    run = RockingRun(
        polarity=polarity,
        status=status,
        message=_message(status, out_f, out_i, par, block),
        max_ratio=side_ratio(block, out_f[L.O_THETA_MAX], out_f[L.O_THETA_MIN]),
        theta_max=float(out_f[L.O_THETA_MAX]),
        theta_min=float(out_f[L.O_THETA_MIN]),
        max_velocity=float(out_f[L.O_MAX_OMEGA]),
        t_overturn=_optional(out_f[L.O_T_OVERTURN]),
        t_uplift=_optional(out_f[L.O_T_UPLIFT]),
        impacts=int(out_i[L.I_IMPACTS]),
        uplifts=int(out_i[L.I_UPLIFTS]),
        steps=int(out_i[L.I_STEPS]),
        rejected=int(out_i[L.I_REJECTED]),
        t_end=float(out_f[L.O_T_END]),
        engine=str(engine),
        rtol=rtol,
        atol=atol,
        rest_velocity=float(par[L.P_REST]),
        restrainers=peaks,
        history=hist,
        impact_loss=float(out_f[L.O_IMPACT_LOSS]),
    )
    return _with_warnings(run)


def _message(
    status: RunStatus, out_f: np.ndarray, out_i: np.ndarray, par: np.ndarray, block: Rocker
) -> str:
    if status is RunStatus.OVERTURNED:
        return f"overturned at t = {out_f[L.O_T_OVERTURN]:.3f} s"
    if status is RunStatus.COMPLETED:
        if math.isnan(out_f[L.O_T_UPLIFT]):
            return "never uplifted"
        return "survived"
    if status is RunStatus.EVENT_LIMIT:
        return f"stopped at t = {out_f[L.O_T_END]:.3f} s: too many impacts (the event guard)"
    if status is RunStatus.NONFINITE:
        return (
            f"stopped at t = {out_f[L.O_T_END]:.6g} s: {_nonfinite_name(out_i, block)} is not "
            f"finite (NaN or infinite): an absurd magnitude in the model or the record"
        )
    return (
        f"stopped at t = {out_f[L.O_T_END]:.3f} s: too many steps (the step guard: "
        f"{int(par[L.P_MAX_STEPS]):,} steps for this record's length; a very stiff restrainer "
        f"or very tight tolerances)"
    )


def _nonfinite_name(out_i: np.ndarray, block: Rocker) -> str:
    code = int(out_i[L.I_NONFINITE])
    if code >= L.NF_FORCE:
        return f"the force of restrainer {block.restrainers[code - L.NF_FORCE].name!r}"
    return L.NONFINITE_NAMES.get(code, "a quantity of the run")


def _with_warnings(run: RockingRun) -> RockingRun:
    notes = []
    if run.chattering:
        notes.append(Note(
            "chattering", "polarity {polarity:+d}: small-amplitude chattering (max θ/α = "
            "{ratio:.3g} with {impacts} impacts): the peak is sensitive to α and e; read it as an "
            "order of magnitude; impact count depends on the rest threshold {rest:g} rad/s",
            polarity=run.polarity, ratio=float(run.max_ratio), impacts=run.impacts,
            rest=float(run.rest_velocity),
        ))  # fmt: skip
    if run.status in (RunStatus.EVENT_LIMIT, RunStatus.STEP_LIMIT, RunStatus.NONFINITE):
        notes.append(Note("run_stopped", "polarity {polarity:+d}: {message}",
                          polarity=run.polarity, message=run.message))  # fmt: skip
    if not notes:
        return run
    from dataclasses import replace

    return replace(run, warnings=tuple(notes))


def assess(
    block: Rocker,
    time: np.ndarray,
    accel: np.ndarray,
    dt: float,
    *,
    settings: SolverSettings | None = None,
    engine: Engine = Engine.FAST,
    history: bool = False,
    mirror: bool = True,
) -> Assessment:
    """Both polarities of the record (the response to +üg and −üg differ: spec/rocking.md).

    A mirror-symmetric block (mechanics.mirror_symmetric) is integrated for +üg only: its
    response to −üg is the mirror image, θ → −θ (mirror_run), marked ``mirror_of = 1``.
    mirror=False integrates both (the property tests check the two agree).
    """
    settings = settings or SolverSettings()
    time = np.asarray(time, float)
    samples = samples_with_tail(time, np.asarray(accel, float), dt, settings.tail_for(block.p))
    polarities = (1,) if mirror and mirror_symmetric(block) else (1, -1)
    runs = tuple(
        simulate(
            block,
            time,
            accel,
            dt,
            polarity=pol,
            settings=settings,
            engine=engine,
            history=history,
            samples=samples,
        )
        for pol in polarities
    )
    if len(runs) == 1:
        return Assessment(runs=(runs[0], mirror_run(runs[0])))
    return Assessment(runs=runs)


def mirror_run(run: RockingRun) -> RockingRun:
    """The run of the reversed record of a mirror-symmetric block: ``run`` with θ → −θ.

    Extremes swap and change sign, the history's θ and θ̇ change sign; amplitudes, times,
    counts, energies and restrainer demands are the same (each restrainer is the same on both
    sides). Its warnings name its own polarity.
    """
    from dataclasses import replace

    history = run.history
    if history is not None:
        history = replace(history, theta=-history.theta, omega=-history.omega)
    polarity = -run.polarity
    warnings = tuple(
        Note(w.key, w.template, **{**w.values, "polarity": polarity})
        if isinstance(w, Note) and "polarity" in w.values
        else w.replace(f"polarity {run.polarity:+d}:", f"polarity {polarity:+d}:")
        for w in run.warnings
    )
    return replace(
        run,
        polarity=polarity,
        theta_max=-run.theta_min,
        theta_min=-run.theta_max,
        history=history,
        warnings=warnings,
        mirror_of=run.polarity,
    )
