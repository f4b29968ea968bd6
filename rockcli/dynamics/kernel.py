"""The fast rocking engine: a compiled Dormand–Prince 5(4) integrator with events.

Design (spec/engine.md, measured there on this machine):

- explicit Runge–Kutta Dormand–Prince 5(4) with its 4th-order dense output (Dormand &
  Prince 1980; Shampine 1986; the same tableau and interpolant as scipy's RK45);
- every step is clipped at the next record sample, so the right-hand side is smooth inside
  each step (the ground acceleration is piecewise linear); the clip does not shrink the
  controller's next step;
- impacts, overturning and restrainer failure are level crossings of a = s·θ, located on the
  dense output by a safeguarded secant (Illinois) search; peaks are the roots of θ̇;
- after an impact or an uplift the step starts at θ = 0: the crossing is then bracketed from
  the turning point (θ̇ = 0), never from the step start (engine.md, trap 1);
- the pivot side s is a mode variable, never sign(θ) in the right-hand side (trap 3);
- a rest rule ends Zeno cascades: after an impact, |θ̇⁺| < ω_rest → rest (trap 5);
- compiled with numba ``cache=True`` when a cache folder is writable (jitcache.py); no explicit
  signatures (they compile at import).

Everything here is numeric and silent. :mod:`rockcli.dynamics.simulate` packs the inputs and
unpacks the outputs.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from numba import njit
from numba.extending import register_jitable

from rockcli import jitcache, mechanics
from rockcli.dynamics import layout as L
from rockcli.dynamics import motion

#: numba's on-disk cache, when a writable folder exists (jitcache.py; keyed on the sources).
CACHE = jitcache.configure()

# The shared formulas are compiled from the very same Python functions. Those that take
# arrays are inlined at the numba IR level (a call boundary costs atomic reference-count
# updates per array argument); the scalar ones are left to LLVM.
for _fn in (
    mechanics.sin_minus,
    mechanics.cos_minus,
    mechanics.gravity_moment_ratio_trig,
    mechanics.ground_moment_ratio_trig,
    mechanics.versine,
    mechanics.spring_elongation_trig,
    mechanics.spring_moment_trig,
    mechanics.spring_elongation,
    mechanics.spring_failure_rotation,
    mechanics.point_moments,  # loaded blocks only; numba's IR inlining of its loop misfires
    mechanics.hermite_weights,  # inside chain_terms and path_terms
    mechanics.chain_terms,  # chains only
    mechanics.path_terms,  # members on a chain's upper block only
    mechanics.path_rotation,
    mechanics.friction_moment,  # rigid bodies with toothed return walls only
):
    register_jitable(_fn)
for _array_fn in (
    motion.spring_on_side,
    motion.spring_trig_on_side,
    motion.ground_acceleration,
    motion.has_path,
    motion.path_on_side,
):
    register_jitable(inline="always")(_array_fn)
register_jitable(motion.member_force)
register_jitable(motion.member_moment)
register_jitable(motion.side_index)
register_jitable(motion.spring_arm)
register_jitable(motion.chain_balance)
register_jitable(motion.friction_sense)
register_jitable(motion.stuck_thresholds)
# The member laws' state changes: called at events only.
for _law_fn in (
    motion.rotation_at_elongation,
    motion.set_levels,
    motion.plateau_slack_point,
    motion.plateau_work,
    motion.released_energy,
    motion.idle_energy,
    motion.cross_up,  # inside engage
    motion.cross_down,  # inside unload
):
    register_jitable(_law_fn)
_cross_up = njit(cache=CACHE)(motion.cross_up)
_cross_down = njit(cache=CACHE)(motion.cross_down)
_engage = njit(cache=CACHE)(motion.engage)
_unload = njit(cache=CACHE)(motion.unload)
_lose = njit(cache=CACHE)(motion.lose)
_any_plastic = njit(cache=CACHE)(motion.any_plastic)
_rest_moment = njit(cache=CACHE)(motion.rest_moment)
_member_force = njit(cache=CACHE, inline="always")(motion.member_force)
register_jitable(motion.elongation_on_side)
_restrainer_force = njit(cache=CACHE)(motion.restrainer_force)
_rhs = njit(cache=CACHE, inline="always")(motion.angular_acceleration)
_loaded_rhs = njit(cache=CACHE)(
    motion.loaded_angular_acceleration
)  # not inlined: keeps the free path lean
_chain_rhs = njit(cache=CACHE)(motion.chain_angular_acceleration)
_ground = njit(cache=CACHE, inline="always")(motion.ground_acceleration)
_uplift_in_interval = njit(cache=CACHE, inline="always")(motion.uplift_in_interval)
_after_impact = njit(cache=CACHE, inline="always")(motion.velocity_after_impact)
_spring_on_side = njit(cache=CACHE, inline="always")(motion.spring_on_side)
_elongation_on_side = njit(cache=CACHE, inline="always")(motion.elongation_on_side)
_collapse_rotation = njit(cache=CACHE, inline="always")(L.collapse_rotation)


#: Numba IR inlining of the small helpers that take arrays: a call boundary costs atomic
#: reference-count updates per array argument (measured: ≈ 45 ns for a 4-array helper, more
#: than the right-hand side itself).
INLINE: Literal["always"] = "always"
#: With a clipped step, the controller keeps its step unless the error asks to shrink it:
#: SAFETY·err^(−1/5) ≥ 1 ⇔ err ≤ SAFETY⁵ (saves the power on most steps).
KEEP_STEP_ERROR = 0.9**5
#: A step that starts at θ = 0 and whose first sub-sample is already back at θ ≤ 0 without a
#: resolvable turning point is retried with the step shrunk by UNRESOLVED_FACTOR, down to
#: UNRESOLVED_MIN_STEP [s]; below that the excursion is taken as none (rest) and the uplift
#: search resumes after it (tests/dynamics/test_uplift.py: uplift while |üg| > tan α for 0.1 ms).
UNRESOLVED_FACTOR = 0.125
UNRESOLVED_MIN_STEP = 1e-9
#: Sub-samples of each accepted step scanned for level crossings and turning points.
SCAN_POINTS = 8
#: Interior points where θ̇ is probed to accept a step as monotone (fast path of the scan).
MONOTONE_PROBES = 3
#: Step controller (Hairer, Nørsett & Wanner, Solving ODEs I, §II.4; scipy RK45 values).
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0
ERROR_EXPONENT = -1.0 / 5.0
#: Relative resolution of event times inside a step (fraction of the step).
ROOT_XTOL = 1e-13
ROOT_MAXITER = 100
#: A step whose remaining gap to the next sample is at most this fraction of the sample
#: interval moves straight to the sample (a rounding remnant, not a step worth taking). Relative
#: to the interval, never to the absolute time: a record timed from the Unix epoch (t ≈ 1.7e9 s,
#: 1 ms steps) must not have its every step swallowed.
GAP_FRACTION = 1e-9
#: A NaN error estimate may come from a step so large that its stages overflow: the step is
#: retried shrunk by MIN_FACTOR up to this many times in a row (0.2³⁰ ≈ 1e-21 of the step)
#: before the run ends as non-finite.
NONFINITE_RETRIES = 30

# Dormand–Prince 5(4) tableau (Dormand & Prince 1980, Table 2).
C2, C3, C4, C5 = 1 / 5, 3 / 10, 4 / 5, 8 / 9
A21 = 1 / 5
A31, A32 = 3 / 40, 9 / 40
A41, A42, A43 = 44 / 45, -56 / 15, 32 / 9
A51, A52, A53, A54 = 19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729
A61, A62, A63, A64, A65 = 9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656
B1, B3, B4, B5, B6 = 35 / 384, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84
# Error weights b − b̂ (scipy.integrate._ivp.rk.RK45.E).
E1, E3, E4, E5, E6, E7 = (
    71 / 57600,
    -71 / 16695,
    71 / 1920,
    -17253 / 339200,
    22 / 525,
    -1 / 40,
)
# Dense output (Shampine 1986; scipy.integrate._ivp.rk.RK45.P), rows k1..k7, powers x..x⁴.
DENSE_P = np.array(
    [
        [1.0, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
        [0.0, 0.0, 0.0, 0.0],
        [0.0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
        [0.0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
        [0.0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
        [0.0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
        [0.0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
    ]
)


@njit(cache=CACHE, inline=INLINE)
def _constants(par):
    """The constants of the equation of motion, read once a step: (α, sin α, cos α, p²,
    linearized, 1/I0, the own inertia the point table adds to, P_I0, then the friction's F,
    x from O, x from O′, z0, h, l: P_RUB*)."""
    return (
        par[L.P_ALPHA],
        par[L.P_SIN_ALPHA],
        par[L.P_COS_ALPHA],
        par[L.P_P2],
        par[L.P_LINEAR] != 0.0,
        par[L.P_INV_I0],
        par[L.P_I0],
        par[L.P_RUB],
        par[L.P_RUB_X_POS],
        par[L.P_RUB_X_NEG],
        par[L.P_RUB_Z0],
        par[L.P_RUB_H],
        par[L.P_RUB_L],
    )


@njit(cache=CACHE, inline=INLINE)
def _free_accel(a, s, om, ag, c, springs, alive, points, d):
    """θ̈ of the rectangle (paper Eq. 2, closed form) at rotation a = s·θ, velocity θ̇ = om,
    ground ag [g]; c: :func:`_constants`; d: the sense of the motion a friction resists
    (±1; 0: none; a rigid body's only)."""
    return _rhs(a, s, ag, c[0], c[1], c[2], c[3], c[4], springs, alive, c[5])


@njit(cache=CACHE, inline=INLINE)
def _loaded_accel(a, s, om, ag, c, springs, alive, points, d):
    """θ̈ of a rigid body given by its point table (motion.loaded_angular_acceleration), its
    friction against the sense d."""
    return _loaded_rhs(a, s, om, ag, points, c[6], springs, alive, d * c[7],
                       c[8] if s > 0 else c[9], c[10], c[11], c[12])  # fmt: skip


@njit(cache=CACHE, inline=INLINE)
def _chain_accel(a, s, om, ag, c, springs, alive, points, d):
    """θ̈ of a chain read from its table (motion.chain_angular_acceleration)."""
    return _chain_rhs(a, s, om, ag, points, springs, alive)


@njit(cache=CACHE, inline=INLINE)
def _stage(th, om, s, ag, par, springs, alive, points, d):
    """θ̈ at rotation θ, velocity θ̇ on side s under ground acceleration ag [g], by the
    equation of the input's kind (P_KIND), a friction resisting the sense d."""
    kind = par[L.P_KIND]
    c = _constants(par)
    if kind == L.K_CHAIN:
        return _chain_accel(s * th, s, om, ag, c, springs, alive, points, d)
    if kind == L.K_POINTS:
        return _loaded_accel(s * th, s, om, ag, c, springs, alive, points, d)
    return _free_accel(s * th, s, om, ag, c, springs, alive, points, d)


@njit(cache=CACHE, inline=INLINE)
def _stage_at(t, th, om, s, i, times, accel, pol, par, springs, alive, points, d):
    """θ̈ at (t, θ, θ̇) on side s, t inside sample interval i."""
    return _stage(th, om, s, _ground(t, i, times, accel, pol), par, springs, alive, points, d)


@njit(cache=CACHE, inline=INLINE)
def _dp5_step(th, om, f1, h, s, g0, gs, par, springs, alive, points, k_th, k_om, accel, d):
    """One Dormand–Prince step of size h; fills the stage slopes; returns (θ, θ̇, θ̈, error norm).

    The state is (θ, θ̇); slopes of θ are θ̇ at the stages, slopes of θ̇ are θ̈ (``accel``, the
    equation of the input's kind). The ground acceleration is g0 + gs·τ at time τ into the
    step (linear inside a sample interval).
    Error norm: RMS of err/(atol + rtol·max(|y0|, |y1|)) (Hairer et al. II.4 (4.11)).
    """
    c = _constants(par)
    k_th[0] = om
    k_om[0] = f1
    w2, v2 = th + h * A21 * k_th[0], om + h * A21 * k_om[0]
    k_th[1] = v2
    k_om[1] = accel(s * w2, s, v2, g0 + gs * (C2 * h), c, springs, alive, points, d)
    w3 = th + h * (A31 * k_th[0] + A32 * k_th[1])
    v3 = om + h * (A31 * k_om[0] + A32 * k_om[1])
    k_th[2] = v3
    k_om[2] = accel(s * w3, s, v3, g0 + gs * (C3 * h), c, springs, alive, points, d)
    w4 = th + h * (A41 * k_th[0] + A42 * k_th[1] + A43 * k_th[2])
    v4 = om + h * (A41 * k_om[0] + A42 * k_om[1] + A43 * k_om[2])
    k_th[3] = v4
    k_om[3] = accel(s * w4, s, v4, g0 + gs * (C4 * h), c, springs, alive, points, d)
    w5 = th + h * (A51 * k_th[0] + A52 * k_th[1] + A53 * k_th[2] + A54 * k_th[3])
    v5 = om + h * (A51 * k_om[0] + A52 * k_om[1] + A53 * k_om[2] + A54 * k_om[3])
    k_th[4] = v5
    k_om[4] = accel(s * w5, s, v5, g0 + gs * (C5 * h), c, springs, alive, points, d)
    w6 = th + h * (A61 * k_th[0] + A62 * k_th[1] + A63 * k_th[2] + A64 * k_th[3] + A65 * k_th[4])
    v6 = om + h * (A61 * k_om[0] + A62 * k_om[1] + A63 * k_om[2] + A64 * k_om[3] + A65 * k_om[4])
    k_th[5] = v6
    k_om[5] = accel(s * w6, s, v6, g0 + gs * h, c, springs, alive, points, d)
    th1 = th + h * (B1 * k_th[0] + B3 * k_th[2] + B4 * k_th[3] + B5 * k_th[4] + B6 * k_th[5])
    om1 = om + h * (B1 * k_om[0] + B3 * k_om[2] + B4 * k_om[3] + B5 * k_om[4] + B6 * k_om[5])
    k_th[6] = om1
    f7 = accel(s * th1, s, om1, g0 + gs * h, c, springs, alive, points, d)
    k_om[6] = f7
    rtol = par[L.P_RTOL]
    atol = par[L.P_ATOL]
    e_th = h * (
        E1 * k_th[0] + E3 * k_th[2] + E4 * k_th[3] + E5 * k_th[4] + E6 * k_th[5] + E7 * k_th[6]
    )
    e_om = h * (
        E1 * k_om[0] + E3 * k_om[2] + E4 * k_om[3] + E5 * k_om[4] + E6 * k_om[5] + E7 * k_om[6]
    )
    sc_th = atol + rtol * max(abs(th), abs(th1))
    sc_om = atol + rtol * max(abs(om), abs(om1))
    err = math.sqrt(0.5 * ((e_th / sc_th) ** 2 + (e_om / sc_om) ** 2))
    return th1, om1, f7, err


@njit(cache=CACHE, inline=INLINE)
def _step_of_kind(th, om, f, h, s, g0, gs, par, springs, alive, points, k_th, k_om, d):
    """:func:`_dp5_step` specialised for the input's kind (P_KIND): one compiled step each, so
    the rectangle's stays lean."""
    kind = par[L.P_KIND]
    if kind == L.K_CHAIN:
        return _dp5_step(th, om, f, h, s, g0, gs, par, springs, alive, points, k_th, k_om,
                         _chain_accel, d)  # fmt: skip
    if kind == L.K_POINTS:
        return _dp5_step(th, om, f, h, s, g0, gs, par, springs, alive, points, k_th, k_om,
                         _loaded_accel, d)  # fmt: skip
    return _dp5_step(th, om, f, h, s, g0, gs, par, springs, alive, points, k_th, k_om,
                     _free_accel, d)  # fmt: skip


@njit(cache=CACHE, inline=INLINE)
def _dense_coefficients(k, q):
    """q[j] = Σ_i k[i]·P[i, j]: the dense-output polynomial of one component (Shampine 1986)."""
    for j in range(4):
        acc = 0.0
        for r in range(7):
            acc += k[r] * DENSE_P[r, j]
        q[j] = acc


@njit(cache=CACHE, inline=INLINE)
def _dense(x, y0, h, q):
    """y(t0 + x·h) = y0 + h·(q0 x + q1 x² + q2 x³ + q3 x⁴), 0 ≤ x ≤ 1."""
    return y0 + h * x * (q[0] + x * (q[1] + x * (q[2] + x * q[3])))


@njit(cache=CACHE)
def _root(y0, h, q, level, s, xl, xr):
    """x in [xl, xr] where s·y(x) = level, given a sign change; Illinois false position.

    Dowell & Jarratt (1971), the Illinois modification of regula falsi: superlinear and
    always bracketed.
    """
    fl = s * _dense(xl, y0, h, q) - level
    fr = s * _dense(xr, y0, h, q) - level
    if fl == 0.0:
        return xl
    if fr == 0.0:
        return xr
    side = 0
    xm = xr
    for _ in range(ROOT_MAXITER):
        xm = (xl * fr - xr * fl) / (fr - fl)
        fm = s * _dense(xm, y0, h, q) - level
        if fm == 0.0 or (xr - xl) < ROOT_XTOL:
            return xm
        if (fm > 0.0) == (fr > 0.0):
            xr, fr = xm, fm
            if side == -1:
                fl *= 0.5
            side = -1
        else:
            xl, fl = xm, fm
            if side == 1:
                fr *= 0.5
            side = 1
    return xm


@njit(cache=CACHE)
def _turning_point(om0, h, q_om, s, xl, xr):
    """x of the root of s·θ̇ (from + to −) in [xl, xr], or −1 when θ̇ keeps its sign."""
    vl = s * _dense(xl, om0, h, q_om)
    vr = s * _dense(xr, om0, h, q_om)
    if vl > 0.0 and vr <= 0.0:
        return _root(om0, h, q_om, 0.0, s, xl, xr)
    return -1.0


@njit(cache=CACHE)
def _update_peak(a, s, peaks, spring_out, springs, alive, linearized):
    """Record the rotation a about pivot s: amplitude, signed extremes, restrainer demands."""
    if a > peaks[L.O_MAX_A]:
        peaks[L.O_MAX_A] = a
    if s > 0:
        if a > peaks[L.O_THETA_MAX]:
            peaks[L.O_THETA_MAX] = a
    elif -a < peaks[L.O_THETA_MIN]:
        peaks[L.O_THETA_MIN] = -a
    for j in range(springs.shape[0]):
        if alive[j] != 0:
            k, _, _, _ = _spring_on_side(springs, j, s)
            if k != 0.0:
                u = _elongation_on_side(springs, j, s, a, linearized)
                if u > spring_out[j, L.S_MAX_U]:
                    spring_out[j, L.S_MAX_U] = u
                force = _member_force(springs, j, s, k, u)
                if force > spring_out[j, L.S_MAX_FORCE]:
                    spring_out[j, L.S_MAX_FORCE] = force


@njit(cache=CACHE)
def _event_levels(s, par, springs, alive, levels, kinds):
    """Fill the levels of a that end the phase; return (number upward, number downward).

    Upward, from index 0: overturning (kind −1), each live failure at fails_at (kind j) and
    each live member law's upward level (kind n + j: yield, re-engage or anchor rupture).
    Downward, from index DOWN_BASE = 2n + 1: each live member's slack point (kind j). The
    impact at a = 0 is found apart. (One pair of arrays: each array argument of a call costs
    reference counting on the scan's path.)
    """
    n_rows = springs.shape[0]
    base = 2 * n_rows + 1
    n = 0
    levels[n] = _collapse_rotation(par, s)
    kinds[n] = -1
    n += 1
    n_down = 0
    col = motion.side_index(s)
    for j in range(n_rows):
        if alive[j] != 0:
            k, _, _, a_fail = _spring_on_side(springs, j, s)
            if k != 0.0 and a_fail < 1e300:
                levels[n] = a_fail
                kinds[n] = j
                n += 1
            if k != 0.0 and springs[j, motion.COL_MEMORY] != 0.0:
                up = springs[j, motion.COL_UP + col]
                if up < 1e300:
                    levels[n] = up
                    kinds[n] = n_rows + j
                    n += 1
                down = springs[j, motion.COL_DOWN + col]
                if down >= 0.0:
                    levels[base + n_down] = down
                    kinds[base + n_down] = j
                    n_down += 1
    return n, n_down


@njit(cache=CACHE, inline=INLINE)
def _stage_trend(k_th, s):
    """+1 if s·θ̇ > 0 at all seven stages of the step, −1 if < 0 at all, else 0.

    The stage slopes of θ are θ̇ at t0, t0 + c_i·h and t1: a step on which they all keep one
    sign has a monotone a = s·θ (no turning point), so only its end value can cross a level.
    """
    v = s * k_th[0]
    if v > 0.0:
        sign = 1.0
    elif v < 0.0:
        sign = -1.0
    else:
        return 0
    for r in range(1, 7):
        if sign * s * k_th[r] <= 0.0:
            return 0
    return int(sign)


@njit(cache=CACHE)
def _level_bounds(s, par, springs, alive):
    """(lowest upward, highest downward) event level of a on side s [rad].

    Upward: overturning, a live failure or a member law's level; downward: the impact at 0 or
    a live member's slack point, +inf while a member is on its yield plateau (its turning point
    is an event, so a step going down must be scanned).
    """
    lowest = _collapse_rotation(par, s)
    highest = 0.0
    col = motion.side_index(s)
    for j in range(springs.shape[0]):
        if alive[j] != 0:
            k, _, _, a_fail = _spring_on_side(springs, j, s)
            if k != 0.0 and a_fail < lowest:
                lowest = a_fail
            if k != 0.0 and springs[j, motion.COL_MEMORY] != 0.0:
                lowest = min(lowest, springs[j, motion.COL_UP + col])
                highest = max(highest, springs[j, motion.COL_DOWN + col])
                if springs[j, motion.COL_MODE + col] == motion.MODE_PLASTIC:
                    highest = math.inf
    return lowest, highest


@njit(cache=CACHE)
def _scan_sampled(
    th0,
    om0,
    th1,
    h,
    q_th,
    q_om,
    s,
    par,
    springs,
    alive,
    peaks,
    spring_out,
    levels,
    kinds,
    d,
):
    """Scan a step that may hold an event or a turning point; record the peaks before it.

    The step is sampled at SCAN_POINTS points of the dense output; a crossing of 0 (impact) or
    of an upward level (overturning, failure, a member's yield, re-engage or rupture) or of a
    downward one (a member's slack point) is located by _root between the samples that
    bracket it, and turning points (roots of θ̇) give the peaks; with a member on its yield
    plateau the turning point is itself an event (the member unloads). A step that starts at
    θ = 0 brackets the impact from its turning point (engine.md, trap 1). Under friction
    (P_RUB) the turning point of the motion's sense d (a peak opening, a trough closing) is
    an event, EV_TURN, and so is a motion found against d at a sample with no turning point
    before it (a start from a standstill too weak to tell).

    Returns (x_event, kind, spring_row): x_event in [0, 1] (2.0 when nothing happens),
    kind EV_*, spring_row the restrainer of the event (−1 otherwise).
    """
    lin = par[L.P_LINEAR] != 0.0
    n_rows = springs.shape[0]
    n_levels, n_down = _event_levels(s, par, springs, alive, levels, kinds)
    base = 2 * n_rows + 1
    plastic = n_rows > 0 and _any_plastic(springs, alive, s)
    rub = par[L.P_RUB] != 0.0
    x_prev = 0.0
    a_prev = s * th0
    for step in range(1, SCAN_POINTS + 1):
        x = step / SCAN_POINTS
        a = s * th1 if step == SCAN_POINTS else s * _dense(x, th0, h, q_th)
        x_best = 2.0
        kind = L.EV_NONE
        row = -1
        if a <= 0.0:
            x_left = x_prev
            if a_prev <= 0.0:
                x_left = _turning_point(om0, h, q_om, s, x_prev, x)
                if x_left < 0.0 or s * _dense(x_left, th0, h, q_th) <= 0.0:
                    return x_prev, L.EV_UNRESOLVED, -1  # excursion shorter than a sample
            x_best = _root(th0, h, q_th, 0.0, s, x_left, x)
            kind = L.EV_IMPACT
        for m in range(base, base + n_down):
            if a < levels[m] and a_prev >= levels[m]:
                xe = _root(th0, h, q_th, levels[m], s, x_prev, x)
                if xe < x_best:
                    x_best = xe
                    kind = L.EV_SLACK
                    row = kinds[m]
        for m in range(n_levels):
            if a >= levels[m] and a_prev < levels[m]:
                xe = _root(th0, h, q_th, levels[m], s, x_prev, x)
                if xe < x_best:
                    x_best = xe
                    if kinds[m] < 0:
                        kind, row = L.EV_OVERTURN, -1
                    elif kinds[m] < n_rows:
                        kind, row = L.EV_FAIL, kinds[m]
                    else:
                        kind, row = L.EV_LAW_UP, kinds[m] - n_rows
        x_end = x if kind == L.EV_NONE else x_best
        xp = _turning_point(om0, h, q_om, s, x_prev, x_end)
        if xp >= 0.0:
            _update_peak(s * _dense(xp, th0, h, q_th), s, peaks, spring_out, springs, alive, lin)
            if rub and d > 0:
                return xp, L.EV_TURN, -1
            if plastic:
                return xp, L.EV_UNLOAD, -1
        if rub and d < 0:
            xq = _turning_point(om0, h, q_om, -s, x_prev, x_end)
            if xq >= 0.0:
                return xq, L.EV_TURN, -1
        if rub and kind == L.EV_NONE and d * s * _dense(x, om0, h, q_om) <= 0.0:
            return x, L.EV_TURN, -1
        if kind != L.EV_NONE:
            return x_best, kind, row
        _update_peak(a, s, peaks, spring_out, springs, alive, lin)
        x_prev = x
        a_prev = a
    return 2.0, L.EV_NONE, -1


@njit(cache=CACHE)
def _uplift_thresholds(par, springs, alive, loaded, memory):
    """Ground acceleration [g] at which the block at rest starts to rock towards each side.

    tan α (α linearized) for the free block, (G − s·T)/H for a loaded one (P_UPLIFT_*), plus a
    pretensioned member's moment at rest times P_PRE_SCALE_* (statics at a = 0).
    """
    thr = par[L.P_ALPHA] if par[L.P_LINEAR] != 0.0 else math.tan(par[L.P_ALPHA])
    thr_pos = par[L.P_UPLIFT_POS] if loaded else thr
    thr_neg = par[L.P_UPLIFT_NEG] if loaded else thr
    if memory:
        thr_pos += _rest_moment(springs, alive, 1) * par[L.P_PRE_SCALE_POS]
        thr_neg += _rest_moment(springs, alive, -1) * par[L.P_PRE_SCALE_NEG]
    return thr_pos, thr_neg


@njit(cache=CACHE)
def _next_uplift(t, i, times, accel, pol, par, thr_pos, thr_neg):
    """From rest at time t in interval i: (τ, side, interval) of the next uplift, side 0 if none.

    The acceleration is linear between samples, so it can first exceed the threshold inside
    an interval only if it does at the interval's end sample: the samples are scanned, and the
    crossing is located exactly in the first interval whose end exceeds it.
    """
    return _next_crossing(t, i, times, accel, pol, thr_pos, thr_neg, int(par[L.P_ONE_SIDED]),
                          int(par[L.P_FREE_SIDE]))  # fmt: skip


@njit(cache=CACHE)
def _next_crossing(t, i, times, accel, pol, thr_pos, thr_neg, one_sided, free_side):
    """:func:`_next_uplift` with the motion's sides given (one_sided 0: either side)."""
    n = times.size
    tau, side = _uplift_in_interval(t, i, times, accel, pol, thr_pos, thr_neg, one_sided, free_side)
    if side != 0:
        return tau, side, i
    up = one_sided == 0 or free_side > 0
    down = one_sided == 0 or free_side < 0
    for k in range(i + 2, n):
        v = pol * accel[k]
        if (up and v > thr_pos) or (down and v < -thr_neg):
            tau, side = _uplift_in_interval(
                times[k - 1], k - 1, times, accel, pol, thr_pos, thr_neg, one_sided, free_side
            )
            return tau, side, k - 1
    return times[n - 1], 0, n - 1


@njit(cache=CACHE)
def _store(hist_th, hist_om, hist_f, i_from, i_to, th, om, s, springs, alive, lin):
    """History at samples i_from..i_to (inclusive): θ, θ̇ and each restrainer's force [N]: its
    member's on the pivot side s at rotation a = s·θ; at rest (s = 0) the larger of its two
    members' forces at a = 0 (a pretension). One compiled function for every store (each
    compiled function costs seconds of the first run)."""
    if hist_th.size <= 1:
        return
    a = s * th
    for k in range(i_from, i_to + 1):
        hist_th[k] = th
        hist_om[k] = om
        for j in range(hist_f.shape[1]):
            hist_f[k, j] = _restrainer_force(springs, alive, j, s, a, lin)


@njit(cache=CACHE)
def _apply_law_event(kind, row, s, a, t, springs, alive, spring_out, lin):
    """A member law's event at rotation a about pivot s, time t.

    EV_UNLOAD: the members on their yield plateau unload (plastic work added to their energy).
    EV_SLACK: member ``row`` goes slack. EV_LAW_UP: it yields (first yield time kept), re-engages
    or, at its anchor's rupture force, is lost (time and released energy kept).
    Returns True when the member was lost.
    """
    if kind == L.EV_UNLOAD:
        _unload(springs, alive, s, a, lin, spring_out, L.S_ENERGY)
        return False
    if kind == L.EV_SLACK:
        _cross_down(springs, row, s, lin)
        return False
    up = springs[row, motion.COL_UP_KIND + motion.side_index(s)]
    if up == motion.UP_ENGAGE:
        up = _engage(springs, row, s, a, lin)  # its yield or rupture too, if already reached
    if up == motion.UP_BREAK:
        _lose(springs, alive, row, s, a, lin, spring_out, L.S_ENERGY)
        spring_out[row, L.S_T_FAIL] = t
        return True
    if up == motion.UP_YIELD:
        _cross_up(springs, row, s, lin)
        if math.isnan(spring_out[row, L.S_T_YIELD]):
            spring_out[row, L.S_T_YIELD] = t
    return False


@njit(cache=CACHE, inline=INLINE)
def _inertia(par, s):
    """Polar moment of inertia about pivot s at rest [kg·m²] (0 at rest, s = 0)."""
    if s == 0:
        return 0.0
    return par[L.P_INERTIA_POS] if s > 0 else par[L.P_INERTIA_NEG]


@njit(cache=CACHE)
def _initial_side(th, om):
    """Pivot side of the initial state: sign of θ0, else of θ̇0, else 0 (at rest)."""
    if th != 0.0:
        return 1 if th > 0.0 else -1
    if om != 0.0:
        return 1 if om > 0.0 else -1
    return 0


@njit(cache=CACHE)
def _nonfinite_quantity(t, th, om, f, s, i, times, accel, pol, par, springs, alive):
    """NF_* code of the first non-finite quantity of the state (θ, θ̇, a force, üg, θ̈)."""
    if not math.isfinite(th):
        return L.NF_THETA
    if not math.isfinite(om):
        return L.NF_OMEGA
    row = _nonfinite_force(s * th, s, par, springs, alive)
    if row >= 0:
        return L.NF_FORCE + row
    if not math.isfinite(_ground(t, i, times, accel, pol)):
        return L.NF_GROUND
    return L.NF_ACCEL


@njit(cache=CACHE)
def _nonfinite_in_step(t, th, om, f, s, i, times, accel, pol, par, springs, alive, g_end):
    """NF_* code for a step whose error estimate stays NaN: the state's, else üg's, else its own."""
    code = _nonfinite_quantity(t, th, om, f, s, i, times, accel, pol, par, springs, alive)
    if code != L.NF_ACCEL or not math.isfinite(f):
        return code
    return L.NF_GROUND if not math.isfinite(g_end) else L.NF_ERROR


@njit(cache=CACHE)
def _nonfinite_force(a, s, par, springs, alive):
    """Row of the first live restrainer whose force K·u at rotation a is not finite, else −1."""
    for j in range(springs.shape[0]):
        if alive[j] != 0:
            k, _, _, _ = _spring_on_side(springs, j, s)
            if k != 0.0:
                u = _elongation_on_side(springs, j, s, a, par[L.P_LINEAR] != 0.0)
                if not math.isfinite(k * u):
                    return j
    return -1


@njit(cache=CACHE)
def _nonfinite_peak_force(spring_out):
    """Row of the first restrainer whose recorded peak force is not finite, else −1."""
    for j in range(spring_out.shape[0]):
        if not math.isfinite(spring_out[j, L.S_MAX_FORCE]):
            return j
    return -1


@njit(cache=CACHE)
def _pass_samples(
    i, t0, t1, th, om, h, q_th, q_om, times, s, hist_th, hist_om, hist_f, springs, alive, lin
):
    """The index of the last sample at or before t1 (the samples inside a free-tail step,
    which is not clipped at them), and, when the history is kept, θ and θ̇ stored there from
    the step's dense output (its 4th-order interpolant, as the events use)."""
    n = times.size
    j = i
    while j + 1 < n and times[j + 1] <= t1:
        j += 1
        if hist_th.size > 1:
            x = (times[j] - t0) / h
            th_j = _dense(x, th, h, q_th)
            om_j = _dense(x, om, h, q_om)
            _store(hist_th, hist_om, hist_f, j, j, th_j, om_j, s, springs, alive, lin)
    return j


@njit(cache=CACHE)
def _tail_samples(i, t0, t1, th, om, h, k_th, k_om, q_th, q_om, unscanned, times, s, hist_th,
                  hist_om, hist_f, springs, alive, lin):  # fmt: skip
    """:func:`_pass_samples` after a step of the free tail with no event; ``unscanned``: the
    step was not scanned, so its dense output is made first when the history is kept."""
    if hist_th.size > 1 and unscanned:
        _dense_coefficients(k_th, q_th)
        _dense_coefficients(k_om, q_om)
    return _pass_samples(i, t0, t1, th, om, h, q_th, q_om, times, s, hist_th, hist_om, hist_f,
                         springs, alive, lin)  # fmt: skip


@njit(cache=CACHE)
def integrate(
    times,
    accel,
    pol,
    par,
    springs,
    points,
    alive,
    hist_th,
    hist_om,
    hist_f,
    out_f,
    out_i,
    spring_out,
):
    """Integrate one rocking run over the sample times, from rest at times[0].

    Args:
        times, accel: sample times [s] and ground acceleration [g] (tail included).
        pol: polarity, +1 or −1 (multiplies the acceleration).
        par: parameter vector (P_* layout). springs: packed restrainer table (motion.py).
        points: flat point table of the block, its loads and thrusts (mechanics.point_table);
            empty for a block without loads and thrusts (the free block's equation).
        alive: int array, 1 per intact restrainer (updated on failure).
        hist_th, hist_om: θ and θ̇ at every sample time (size 1 when not wanted).
        hist_f: each restrainer's force at every sample time (shape (n, rows) when wanted).
        out_f, out_i, spring_out: outputs (O_*, I_*, S_* layouts).
    """
    integrate_sloped(times, accel, ground_slopes(times, accel), pol, par, springs, points, alive,
                     hist_th, hist_om, hist_f, out_f, out_i, spring_out)  # fmt: skip


@njit(cache=CACHE)
def ground_slopes(times, accel):
    """The slope of the ground acceleration over each interval between samples [g/s]."""
    n = times.size
    slopes = np.empty(max(n - 1, 0))
    for r in range(n - 1):
        slopes[r] = (accel[r + 1] - accel[r]) / (times[r + 1] - times[r])
    return slopes


@njit(cache=CACHE)
def integrate_sloped(times, accel, slopes, pol, par, springs, points, alive, hist_th, hist_om,
                     hist_f, out_f, out_i, spring_out):  # fmt: skip
    """:func:`integrate` with the ground's slopes given (ground_slopes of times and accel, or
    of a longer grid of which times is a prefix). The driver: standstills (:func:`_resume`),
    steps (:func:`_step_of_kind`) scanned for events (:func:`_scan_sampled`), the events
    (:func:`_apply_event`; under friction the sense d of the motion, :func:`_turn`)."""
    n = times.size
    k_th, k_om, q_th, q_om, levels, kinds = _work_arrays(springs)
    memory = _has_memory(springs)
    _reset_outputs(out_f, out_i)
    lin, max_steps = par[L.P_LINEAR] != 0.0, int(par[L.P_MAX_STEPS])
    t, i = times[0], 0
    th, om = par[L.P_THETA0], par[L.P_OMEGA0]
    s = _initial_side(th, om)
    f, d = 0.0, 1  # d: the sense of the motion a friction resists, opening
    h = times[1] - times[0]
    _store(hist_th, hist_om, hist_f, 0, 0, 0.0, 0.0, 0, springs, alive, lin)
    if s != 0:
        f, d = _start_moving(t, th, om, s, times, accel, pol, par, springs, alive, points,
                             hist_th, hist_om, hist_f, out_f, spring_out)  # fmt: skip
    status, nan_rejects = L.STATUS_COMPLETED, 0
    lowest, highest = _level_bounds(s, par, springs, alive)
    free_from = n if int(par[L.P_FREE_FROM]) <= 0 else int(par[L.P_FREE_FROM])
    rub = par[L.P_RUB] != 0.0
    while i < n - 1:
        if s == 0 or d == 0:  # at rest, or held by friction (d = 0)
            t, i, s, th, d = _resume(t, i, th, s, times, accel, pol, par, springs, alive, points,
                                     memory, hist_th, hist_om, hist_f, out_f, out_i, spring_out,
                                     free_from)  # fmt: skip
            om = 0.0
            if s == 0 or d == 0:
                break
            f = _stage_at(t, th, om, s, i, times, accel, pol, par, springs, alive, points, d)
            lowest, highest = _level_bounds(s, par, springs, alive)
            continue
        if not math.isfinite(f) or out_i[L.I_STEPS] + out_i[L.I_REJECTED] >= max_steps:
            status = _stop_status(t, th, om, f, s, i, times, accel, pol, par, springs, alive, out_i)
            break
        # In the free tail (ground at rest) the step runs to the end, not to the next sample.
        last = n - 1 if i >= free_from else i + 1
        t_next = times[last]
        gap = t_next - t
        if gap <= GAP_FRACTION * (t_next - times[i]):  # a rounding remnant: to the sample
            f = _at_sample(th, om, s, i, last, times, accel, pol, par, springs, alive, points,
                           hist_th, hist_om, hist_f, d)  # fmt: skip
            t = t_next
            i = last
            continue
        h_try = min(h, gap)
        gs = pol * slopes[i]
        g0 = pol * accel[i] + gs * (t - times[i])
        th1, om1, f1, err = _step_of_kind(
            th, om, f, h_try, s, g0, gs, par, springs, alive, points, k_th, k_om, d
        )
        if not err <= 1.0:  # too large, or NaN
            out_i[L.I_REJECTED] += 1
            h, nan_rejects = _after_rejection(err, h_try, nan_rejects)
            if nan_rejects > NONFINITE_RETRIES:
                status = L.STATUS_NONFINITE
                out_i[L.I_NONFINITE] = _nonfinite_in_step(
                    t, th, om, f, s, i, times, accel, pol, par, springs, alive, g0 + gs * h_try
                )
                break
            continue
        nan_rejects = 0
        trend = _stage_trend(k_th, s)  # no scan when a = s·θ moves one way, its sense's
        a1 = s * th1
        if (trend > 0 and a1 < lowest and (d > 0 or not rub)) or (
            trend < 0 and a1 > highest and (d < 0 or not rub)
        ):
            x_ev, kind, row = 2.0, L.EV_NONE, -1
        else:
            _dense_coefficients(k_th, q_th)
            _dense_coefficients(k_om, q_om)
            x_ev, kind, row = _scan_sampled(th, om, th1, h_try, q_th, q_om, s, par, springs,
                                            alive, out_f, spring_out, levels, kinds,
                                            d)  # fmt: skip
        if kind == L.EV_UNRESOLVED and h_try > UNRESOLVED_MIN_STEP:
            out_i[L.I_REJECTED] += 1
            h = h_try * UNRESOLVED_FACTOR
            continue
        out_i[L.I_STEPS] += 1
        if not (h_try < h and err <= KEEP_STEP_ERROR):  # a clipped step keeps its size
            h = h_try * _growth(err)
        if kind == L.EV_NONE:
            t1 = t_next if h_try == gap else t + h_try
            if last > i + 1:  # the free tail: the samples the step passed
                i = _tail_samples(i, t, t1, th, om, h_try, k_th, k_om, q_th, q_om, x_ev > 1.0,
                                  times, s, hist_th, hist_om, hist_f, springs, alive,
                                  lin)  # fmt: skip
            t = t1
            th, om, f = th1, om1, f1
            out_f[L.O_MAX_OMEGA] = max(out_f[L.O_MAX_OMEGA], abs(om))
            if t == t_next:
                i = last
                if hist_th.size > 1:
                    _store(hist_th, hist_om, hist_f, i, i, th, om, s, springs, alive, lin)
            continue
        t_ev = t + x_ev * h_try
        if last > i + 1:  # the free tail: the samples before the event
            i = _pass_samples(i, t, t_ev, th, om, h_try, q_th, q_om, times, s, hist_th, hist_om,
                              hist_f, springs, alive, lin)  # fmt: skip
        om_ev = _dense(x_ev, om, h_try, q_om)
        th_ev = _dense(x_ev, th, h_try, q_th)
        out_f[L.O_MAX_OMEGA] = max(out_f[L.O_MAX_OMEGA], abs(om_ev))
        if kind == L.EV_TURN:  # under friction: it sticks, or turns round
            t, th, om, d = t_ev, th_ev, 0.0, _turn(t_ev, th_ev, s, i, times, accel, pol, par,
                                                   springs, alive, points, memory,
                                                   spring_out)  # fmt: skip
        else:
            t, th, om, s, status = _apply_event(kind, row, t_ev, th_ev, om_ev, om, s, t_next,
                                                par, springs, alive, out_f, out_i,
                                                spring_out)  # fmt: skip
            if status != L.STATUS_COMPLETED:
                break
            d = 1 if kind == L.EV_IMPACT else d  # after an impact the new pivot's motion opens
        if s != 0 and d != 0:
            f = _stage_at(t, th, om, s, i, times, accel, pol, par, springs, alive, points, d)
            lowest, highest = _level_bounds(s, par, springs, alive)
    _finish(t, th, s, status, memory, par, springs, alive, out_f, out_i, spring_out)


@njit(cache=CACHE)
def _work_arrays(springs):
    """The driver's scratch arrays: the stages' slopes of θ and θ̇ (7 each), their dense
    output (4 each), the event levels and their kinds (3 per restrainer + 1)."""
    rows = 3 * springs.shape[0] + 1
    return (np.empty(7), np.empty(7), np.empty(4), np.empty(4), np.empty(rows),
            np.empty(rows, dtype=np.int64))  # fmt: skip


@njit(cache=CACHE)
def _stop_status(t, th, om, f, s, i, times, accel, pol, par, springs, alive, out_i):
    """The status of a run stopped before a step: STATUS_NONFINITE when θ̈ is not finite (its
    cause in I_NONFINITE: θ̈ is NaN when θ is; a bad θ̇ shows in the error estimate), else
    STATUS_STEP_LIMIT (the step budget is spent)."""
    if not math.isfinite(f):
        out_i[L.I_NONFINITE] = _nonfinite_quantity(
            t, th, om, f, s, i, times, accel, pol, par, springs, alive
        )
        return L.STATUS_NONFINITE
    return L.STATUS_STEP_LIMIT


@njit(cache=CACHE)
def _at_sample(th, om, s, i, last, times, accel, pol, par, springs, alive, points, hist_th,
               hist_om, hist_f, d):  # fmt: skip
    """The state (θ, θ̇) moved from interval i to sample ``last`` without a step (the gap is a
    rounding remnant): the history kept up to it; returns θ̈ there."""
    if hist_th.size > 1:
        lin = par[L.P_LINEAR] != 0.0
        _store(hist_th, hist_om, hist_f, i + 1, last, th, om, s, springs, alive, lin)
    return _stage_at(times[last], th, om, s, last, times, accel, pol, par, springs, alive, points,
                     d)  # fmt: skip


@njit(cache=CACHE)
def _has_memory(springs):
    """True when a restrainer's force depends on its history (motion.COL_MEMORY)."""
    for r in range(springs.shape[0]):
        if springs[r, motion.COL_MEMORY] != 0.0:
            return True
    return False


@njit(cache=CACHE)
def _reset_outputs(out_f, out_i):
    """The run's outputs before its start: no peak, no uplift, no overturning, no count."""
    out_f[L.O_MAX_A] = 0.0
    out_f[L.O_THETA_MAX] = 0.0
    out_f[L.O_THETA_MIN] = 0.0
    out_f[L.O_MAX_OMEGA] = 0.0
    out_f[L.O_T_OVERTURN] = np.nan
    out_f[L.O_T_UPLIFT] = np.nan
    out_f[L.O_IMPACT_LOSS] = 0.0
    for r in range(L.N_INT_OUT):
        out_i[r] = 0


@njit(cache=CACHE)
def _start_moving(t, th, om, s, times, accel, pol, par, springs, alive, points, hist_th,
                  hist_om, hist_f, out_f, spring_out):  # fmt: skip
    """A run that starts in motion (θ0 or θ̇0 given): its uplift time and first peak, its
    history's first sample; returns θ̈ there and the sense of its motion under friction
    (:func:`_initial_sense`; 0: held where it starts; +1 without friction)."""
    lin = par[L.P_LINEAR] != 0.0
    out_f[L.O_T_UPLIFT] = t
    _update_peak(s * th, s, out_f, spring_out, springs, alive, lin)
    d = 1
    if par[L.P_RUB] != 0.0:
        d = _initial_sense(t, th, om, s, times, accel, pol, par, springs, alive, points)
    f = _stage_at(t, th, om, s, 0, times, accel, pol, par, springs, alive, points, d)
    if hist_th.size > 1:
        _store(hist_th, hist_om, hist_f, 0, 0, th, om, s, springs, alive, lin)
    return f, d


@njit(cache=CACHE)
def _rest_until_uplift(t, i, times, accel, pol, par, springs, alive, memory, hist_th, hist_om,
                       hist_f, out_f, out_i):  # fmt: skip
    """At rest from time t in interval i: the history at rest up to the next uplift, counted
    (its time kept if the first); returns (τ, interval, side), side 0 when the record ends
    first (τ then its last time)."""
    lin = par[L.P_LINEAR] != 0.0
    loaded = par[L.P_KIND] != L.K_RECTANGLE
    thr_pos, thr_neg = _uplift_thresholds(par, springs, alive, loaded, memory)
    tau, side, j = _next_uplift(t, i, times, accel, pol, par, thr_pos, thr_neg)
    _store(hist_th, hist_om, hist_f, i + 1, j, 0.0, 0.0, 0, springs, alive, lin)
    if side == 0:
        return times[times.size - 1], j, 0
    out_i[L.I_UPLIFTS] += 1
    if out_i[L.I_UPLIFTS] == 1:
        out_f[L.O_T_UPLIFT] = tau
    return tau, j, side


@njit(cache=CACHE)
def _initial_sense(t, th, om, s, times, accel, pol, par, springs, alive, points):
    """The sense of the motion under friction of a run that starts in motion (θ0, θ̇0): its
    velocity's, or at a standstill the one the forces give (0: it sticks)."""
    if om != 0.0:
        return 1 if s * om > 0.0 else -1
    return _sense_at(t, th, s, 0, times, accel, pol, par, springs, alive, points)


@njit(cache=CACHE)
def _turn(t, th, s, i, times, accel, pol, par, springs, alive, points, memory, spring_out):
    """A turning point under friction at time t, rotation θ on side s: the motion's new sense
    (0: it sticks), and the members on their yield plateau unloaded when it turns back (a
    wall held at its peak keeps its members on the plateau)."""
    d = _sense_at(t, th, s, i, times, accel, pol, par, springs, alive, points)
    if memory and d < 0:
        lin = par[L.P_LINEAR] != 0.0
        _apply_law_event(L.EV_UNLOAD, -1, s, max(s * th, 0.0), t, springs, alive, spring_out,
                         lin)  # fmt: skip
    return d


@njit(cache=CACHE)
def _friction_terms(th, s, par, springs, alive, points):
    """(q0, k, mf) of a body at a standstill at θ on side s (motion.stuck_thresholds): its
    ä = s·θ̈ without the friction at üg = 0, its rate per g of s·üg, and the friction's
    moment over the inertia, all from the equation of motion itself (the latter raised by
    motion.FRICTION_MARGIN, so that a rounding tie sticks)."""
    q0 = s * _stage(th, 0.0, s, 0.0, par, springs, alive, points, 0)
    k = s * _stage(th, 0.0, s, s * 1.0, par, springs, alive, points, 0) - q0
    mf = q0 - s * _stage(th, 0.0, s, 0.0, par, springs, alive, points, 1)
    return q0, k, mf + motion.FRICTION_MARGIN * (abs(q0) + mf)


@njit(cache=CACHE)
def _sense_at(t, th, s, i, times, accel, pol, par, springs, alive, points):
    """The sense of the motion a body at a standstill at θ on side s takes at time t under
    friction (motion.friction_sense: +1 opens, −1 closes, 0 it sticks)."""
    q0, k, mf = _friction_terms(th, s, par, springs, alive, points)
    return motion.friction_sense(q0 + s * _ground(t, i, times, accel, pol) * k, mf)


@njit(cache=CACHE)
def _stuck_until_slip(t, i, th, s, times, accel, pol, par, springs, alive, points, hist_th,
                      hist_om, hist_f):  # fmt: skip
    """A body held by friction at θ on side s from time t in interval i: the history held up
    to the time the ground moves it again; returns (τ, interval, sense), sense 0 when the
    record ends first (τ then its last time)."""
    lin = par[L.P_LINEAR] != 0.0
    n = times.size
    q0, k, mf = _friction_terms(th, s, par, springs, alive, points)
    if not k > 0.0:  # the earthquake's moment does not reach it: held to the end
        _store(hist_th, hist_om, hist_f, i + 1, n - 1, th, 0.0, s, springs, alive, lin)
        return times[n - 1], n - 1, 0
    thr_pos, thr_neg = motion.stuck_thresholds(s, q0, k, mf)
    tau, side, j = _next_crossing(t, i, times, accel, pol, thr_pos, thr_neg, 0, 0)
    _store(hist_th, hist_om, hist_f, i + 1, j, th, 0.0, s, springs, alive, lin)
    if side == 0:
        return times[n - 1], j, 0
    return tau, j, side * s


@njit(cache=CACHE)
def _resume(t, i, th, s, times, accel, pol, par, springs, alive, points, memory, hist_th,
            hist_om, hist_f, out_f, out_i, spring_out, free_from):  # fmt: skip
    """From a standstill: at rest (s = 0) until the next uplift (:func:`_rest_until_uplift`;
    at rest on a ground at rest from sample ``free_from``: nothing more happens), or held by
    friction at θ until the ground moves it (:func:`_stuck_until_slip`; members on their
    plateau unload when it moves back). Returns (τ, interval, side, θ, sense): side 0 or
    sense 0 when the record ends first."""
    n = times.size
    if s == 0 and i >= free_from:
        lin = par[L.P_LINEAR] != 0.0
        _store(hist_th, hist_om, hist_f, i + 1, n - 1, 0.0, 0.0, 0, springs, alive, lin)
        return times[n - 1], n - 1, 0, 0.0, 1
    if s == 0:
        t, i, s = _rest_until_uplift(t, i, times, accel, pol, par, springs, alive, memory,
                                     hist_th, hist_om, hist_f, out_f, out_i)  # fmt: skip
        return t, i, s, 0.0, 1
    t, i, d = _stuck_until_slip(t, i, th, s, times, accel, pol, par, springs, alive, points,
                                hist_th, hist_om, hist_f)  # fmt: skip
    if memory and d < 0:
        lin = par[L.P_LINEAR] != 0.0
        _apply_law_event(L.EV_UNLOAD, -1, s, max(s * th, 0.0), t, springs, alive, spring_out,
                         lin)  # fmt: skip
    return t, i, s, th, d


@njit(cache=CACHE, inline=INLINE)
def _growth(err):
    """The controller's factor on the next step after an accepted one of error norm ``err``
    (Hairer et al. II.4): SAFETY·err^(−1/5), at most MAX_FACTOR."""
    return MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * err**ERROR_EXPONENT)


@njit(cache=CACHE, inline=INLINE)
def _after_rejection(err, h_try, nan_rejects):
    """(next step, NaN rejections in a row) after a step whose error is too large or NaN."""
    if err > 1.0:
        return h_try * max(MIN_FACTOR, SAFETY * err**ERROR_EXPONENT), nan_rejects
    return h_try * MIN_FACTOR, nan_rejects + 1


@njit(cache=CACHE)
def _apply_event(kind, row, t, th, om, om_start, s, t_next, par, springs, alive, out_f, out_i,
                 spring_out):  # fmt: skip
    """The event ``kind`` (EV_*; ``row`` its restrainer) at time t and state (θ, θ̇) on side s:
    overturning, a restrainer lost, a member law's change, an unresolved excursion (rest, the
    kinetic energy at the step's start θ̇ = om_start lost), or the impact. Returns (t, θ, θ̇,
    side, status): status COMPLETED while the run goes on."""
    lin = par[L.P_LINEAR] != 0.0
    if kind == L.EV_OVERTURN:
        collapse = _collapse_rotation(par, s)
        _update_peak(collapse, s, out_f, spring_out, springs, alive, lin)
        out_f[L.O_T_OVERTURN] = t
        return t, s * collapse, om, s, L.STATUS_OVERTURNED
    if kind == L.EV_FAIL:
        _update_peak(s * th, s, out_f, spring_out, springs, alive, lin)
        _lose(springs, alive, row, s, s * th, lin, spring_out, L.S_ENERGY)
        spring_out[row, L.S_T_FAIL] = t
        return t, th, om, s, L.STATUS_COMPLETED
    if kind >= L.EV_LAW_UP:
        a_ev = s * th
        if kind == L.EV_UNLOAD:
            a_ev = max(a_ev, 0.0)
        _update_peak(a_ev, s, out_f, spring_out, springs, alive, lin)
        _apply_law_event(kind, row, s, a_ev, t, springs, alive, spring_out, lin)
        return t, th, om, s, L.STATUS_COMPLETED
    if kind == L.EV_UNRESOLVED:
        # An excursion shorter than UNRESOLVED_MIN_STEP: rest, and look for the next uplift
        # after it, so that the run always moves on.
        out_f[L.O_IMPACT_LOSS] += 0.5 * _inertia(par, s) * om_start * om_start
        return min(t + UNRESOLVED_MIN_STEP, t_next), 0.0, 0.0, 0, L.STATUS_COMPLETED
    return _impact(t, om, s, par, out_f, out_i)


@njit(cache=CACHE)
def _impact(t, om, s, par, out_f, out_i):
    """The impact at θ = 0 with velocity θ̇ = om on side s: the velocity after it (or rest
    under P_REST), its energy loss; (t, θ, θ̇, side, status), status EVENT_LIMIT at the most
    impacts."""
    out_i[L.I_IMPACTS] += 1
    e = par[L.P_E] if s > 0 else par[L.P_E_NEG]
    before = 0.5 * _inertia(par, s) * om * om
    om, s = _after_impact(om, s, e, int(par[L.P_ONE_SIDED]), par[L.P_REBOUND])
    if abs(om) < par[L.P_REST]:
        s = 0
        om = 0.0
    out_f[L.O_IMPACT_LOSS] += before - 0.5 * _inertia(par, s) * om * om
    if s != 0 and out_i[L.I_IMPACTS] >= int(par[L.P_MAX_EVENTS]):
        return t, 0.0, om, s, L.STATUS_EVENT_LIMIT
    return t, 0.0, om, s, L.STATUS_COMPLETED


@njit(cache=CACHE)
def _finish(t, th, s, status, memory, par, springs, alive, out_f, out_i, spring_out):
    """The run's end at time t: the last peak, a yield plateau in progress unloaded, a
    non-finite peak force made the run's status, the end time and the status."""
    lin = par[L.P_LINEAR] != 0.0
    if s != 0 and status != L.STATUS_OVERTURNED:  # a NaN state updates no peak
        _update_peak(s * th, s, out_f, spring_out, springs, alive, lin)
    if memory and s != 0 and status != L.STATUS_NONFINITE:
        # a plateau in progress at the end unloads there (its plastic work counted)
        _apply_law_event(L.EV_UNLOAD, -1, s, s * th, t, springs, alive, spring_out, lin)
    if status != L.STATUS_NONFINITE:
        row = _nonfinite_peak_force(spring_out)
        if row >= 0:
            status = L.STATUS_NONFINITE
            out_i[L.I_NONFINITE] = L.NF_FORCE + row
    out_f[L.O_T_END] = t
    out_i[L.I_STATUS] = status


@njit(cache=CACHE, nogil=True)
def integrate_runs(
    times, accel, n_samples, run_case, run_pol, pars, springs, points, out_f, out_i, spring_out
):
    """Integrate many rocking runs in one call: run j is case run_case[j] at polarity
    run_pol[j] (+1.0 or −1.0), over the first n_samples[case] samples of times and accel.

    Each run is exactly :func:`integrate` with the case's parameter vector pars[case] and a
    fresh copy of its restrainer table springs[case] (the table holds the members' state),
    every restrainer intact and no history kept: the same arithmetic as one run of
    rockcli.dynamics.simulate, so the outputs are bit for bit the same (a study's chunk:
    rockcli.dynamics.batch). It releases the GIL: a study's own process runs chunks on a
    thread while its main thread writes the other workers' results. out_f[j], out_i[j],
    spring_out[j]: run j's outputs (O_*, I_*, S_* layouts; spring_out's S_T_FAIL and S_T_YIELD
    columns set to nan by the caller). The slopes of the ground acceleration are computed once
    for all the runs (each run's grid is a prefix of times).
    """
    n_rows = springs.shape[1]
    slopes = ground_slopes(times, accel)
    for j in range(run_case.size):
        c = run_case[j]
        n = n_samples[c]
        table = springs[c].copy()
        alive = np.ones(n_rows, dtype=np.int64)
        hist_th = np.full(1, np.nan)
        hist_om = np.full(1, np.nan)
        hist_f = np.zeros((1, n_rows))
        integrate_sloped(
            times[:n],
            accel[:n],
            slopes,
            run_pol[j],
            pars[c],
            table,
            points,
            alive,
            hist_th,
            hist_om,
            hist_f,
            out_f[j],
            out_i[j],
            spring_out[j],
        )
