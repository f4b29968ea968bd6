"""The reference rocking engine: scipy DOP853 at tight tolerance, one sample interval at a time.

Used by the tests to check the fast engine and selectable with ``--engine reference``
(spec/engine.md, "Sensitivity": cross-implementation check). Independent of the compiled
kernel in everything but the rules of motion (:mod:`rockcli.dynamics.motion`, the spec's
physics): another integrator (DOP853, Hairer & Wanner), scipy's event location, its own loop.

Each call of :func:`scipy.integrate.solve_ivp` spans at most one sample interval, so the
right-hand side is smooth inside it. After an impact or an uplift the phase starts at θ = 0:
the restart takes a first step of REFERENCE_FIRST_STEP so that the impact event cannot be
bracketed from the start point (engine.md, trap 1).

Slow (hundreds of Python calls per second of record): meant for checks, not studies.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.integrate import solve_ivp

from rockcli.dynamics import layout as L
from rockcli.dynamics import motion

#: First step after a restart at θ = 0 [s] (keeps the impact event off the start point).
REFERENCE_FIRST_STEP = 1e-7
#: Right-hand side evaluations per DOP853 step (12 stages; the 13th is the next step's first).
EVALS_PER_STEP = 12
#: A remaining gap to the sample of at most this fraction of the sample interval is a rounding
#: remnant, not a step (relative to the interval, never to the absolute time: kernel.py).
GAP_FRACTION = 1e-9


class _OutOfBudget(Exception):
    """The run used up its work budget inside one solve (raised by the right-hand side)."""


class _Phase:
    """Mutable state of the reference run."""

    def __init__(
        self, par: np.ndarray, springs: np.ndarray, points: np.ndarray, alive: np.ndarray
    ) -> None:
        self.par = par
        self.springs = springs
        self.points = points
        self.alive = alive
        self.lin = bool(par[L.P_LINEAR])
        self.s = 0
        self.th = 0.0
        self.om = 0.0
        self.restart = True
        self.t = 0.0
        self.evals = 0
        self.max_evals = int(par[L.P_MAX_STEPS]) * EVALS_PER_STEP
        self.memory = bool(np.any(springs[:, motion.COL_MEMORY] != 0.0)) if springs.size else False
        #: Under friction (P_RUB): the sense of the motion it resists (+1 opening, −1
        #: closing), and whether the body is held at a standstill (kernel.py's modes).
        self.rub = par[L.P_RUB] != 0.0
        self.d = 1
        self.stuck = False
        #: A chain's terms from its configuration function (mechanics.Chain.exact), or None.
        self.exact: Callable[[int, float], tuple[float, float, float, float, float]] | None = None


def _rhs(phase: _Phase, t0: float, g0: float, gs: float):

    def f(t: float, y: np.ndarray) -> list[float]:
        phase.evals += 1
        if phase.evals > phase.max_evals:
            raise _OutOfBudget
        return [y[1], _acceleration(phase, g0 + gs * (t - t0), y[0], y[1], phase.d)]

    return f


def _acceleration(phase: _Phase, ag: float, th: float, om: float, d: int = 1) -> float:
    """θ̈ at rotation θ, velocity θ̇ under ground acceleration ag [g], a friction resisting
    the sense d (0: none); NaN where math refuses."""
    par = phase.par
    try:
        if phase.exact is not None:
            a = phase.s * th
            g, h, t, m, mp = phase.exact(phase.s, a)
            return float(
                motion.chain_balance(g, h, t, m, mp, a, phase.s, om, ag, phase.springs, phase.alive)
            )
        if par[L.P_KIND] == L.K_POINTS:
            return float(
                motion.loaded_angular_acceleration(
                    phase.s * th,
                    phase.s,
                    om,
                    ag,
                    phase.points,
                    par[L.P_I0],
                    phase.springs,
                    phase.alive,
                    d * par[L.P_RUB],
                    par[L.P_RUB_X_POS] if phase.s > 0 else par[L.P_RUB_X_NEG],
                    par[L.P_RUB_Z0],
                    par[L.P_RUB_H],
                    par[L.P_RUB_L],
                )
            )
        return float(
            motion.angular_acceleration(
                phase.s * th,
                phase.s,
                ag,
                par[L.P_ALPHA],
                par[L.P_SIN_ALPHA],
                par[L.P_COS_ALPHA],
                par[L.P_P2],
                phase.lin,
                phase.springs,
                phase.alive,
                par[L.P_INV_I0],
            )
        )
    except (ValueError, OverflowError):
        return math.nan


def _nonfinite_quantity(phase: _Phase, ag: float, th: float, om: float) -> int:
    """NF_* code of the first non-finite quantity of the state (same order as kernel.py)."""
    if not math.isfinite(th):
        return L.NF_THETA
    if not math.isfinite(om):
        return L.NF_OMEGA
    for j in range(phase.springs.shape[0]):
        k, _, _, _ = motion.spring_on_side(phase.springs, j, phase.s)
        if phase.alive[j] and k != 0.0:
            u = motion.elongation_on_side(phase.springs, j, phase.s, phase.s * th, phase.lin)
            if not math.isfinite(k * u):
                return L.NF_FORCE + j
    if not math.isfinite(ag):
        return L.NF_GROUND
    if not math.isfinite(_acceleration(phase, ag, th, om, phase.d)):
        return L.NF_ACCEL
    return L.NF_ERROR


#: Kinds of the reference's events: the block's, then the restrainers'.
K_IMPACT, K_OVERTURN, K_PEAK, K_FAIL, K_LAW_UP, K_SLACK, K_TURN = range(7)


def _events(phase: _Phase):
    """Impact, overturning, failures, the members' law levels (terminal) and the turning point
    (a peak; terminal while a member is on its yield plateau, where it unloads, and under
    friction, where the body sticks or turns: then a trough of a closing motion too)."""
    s = phase.s
    t_start = phase.t

    def impact(t: float, y: np.ndarray) -> float:
        return s * y[0]

    impact.terminal = True  # type: ignore[attr-defined]
    impact.direction = -1  # type: ignore[attr-defined]

    def overturn(t: float, y: np.ndarray) -> float:
        return s * y[0] - L.collapse_rotation(phase.par, s)

    overturn.terminal = True  # type: ignore[attr-defined]
    overturn.direction = 1  # type: ignore[attr-defined]

    def peak(t: float, y: np.ndarray) -> float:
        return s * y[1]

    unloads = phase.memory and not phase.rub and motion.any_plastic(phase.springs, phase.alive, s)
    peak.terminal = unloads  # type: ignore[attr-defined]
    peak.direction = -1  # type: ignore[attr-defined]
    events = [impact, overturn, peak]
    rows = [(K_IMPACT, -1), (K_OVERTURN, -1), (K_PEAK if unloads else -1, -1)]
    if phase.rub:
        d = phase.d

        def turn(t: float, y: np.ndarray) -> float:
            # positive at the solve's start: a start from a standstill is not a turning point
            return d * s * y[1] if t > t_start else 1.0

        turn.terminal = True  # type: ignore[attr-defined]
        turn.direction = -1  # type: ignore[attr-defined]
        events.append(turn)
        rows.append((K_TURN, -1))
    col = motion.side_index(s)
    for j in range(phase.springs.shape[0]):
        k, _, _, a_fail = motion.spring_on_side(phase.springs, j, s)
        if not phase.alive[j] or k == 0.0:
            continue
        if math.isfinite(a_fail):
            events.append(_level_event(s, a_fail, 1, phase.rub))
            rows.append((K_FAIL, j))
        if phase.springs[j, motion.COL_MEMORY] != 0.0:
            up = phase.springs[j, motion.COL_UP + col]
            down = phase.springs[j, motion.COL_DOWN + col]
            if math.isfinite(up):
                events.append(_level_event(s, up, 1, phase.rub))
                rows.append((K_LAW_UP, j))
            if down >= 0.0:
                events.append(_level_event(s, down, -1, phase.rub))
                rows.append((K_SLACK, j))
    return events, rows


def _level_event(s: int, level: float, direction: int, at_level_before: bool = False):
    """A terminal event where a = s·θ crosses ``level`` upwards (+1) or downwards (−1);
    ``at_level_before`` (under friction, a restart from a standstill may sit on a level):
    exactly on it counts as not yet crossed."""

    def cross(t: float, y: np.ndarray) -> float:
        v = s * y[0] - level
        if at_level_before and v == 0.0:
            return -float(direction)  # under friction, a start at the level has not crossed it
        return v

    cross.terminal = True  # type: ignore[attr-defined]
    cross.direction = direction  # type: ignore[attr-defined]
    return cross


def _peak(phase: _Phase, a: float, out_f: np.ndarray, spring_out: np.ndarray) -> None:
    s = phase.s
    out_f[L.O_MAX_A] = max(out_f[L.O_MAX_A], a)
    if s > 0:
        out_f[L.O_THETA_MAX] = max(out_f[L.O_THETA_MAX], a)
    else:
        out_f[L.O_THETA_MIN] = min(out_f[L.O_THETA_MIN], -a)
    for j in range(phase.springs.shape[0]):
        k, _, _, _ = motion.spring_on_side(phase.springs, j, s)
        if phase.alive[j] and k != 0.0:
            u = motion.elongation_on_side(phase.springs, j, s, a, phase.lin)
            spring_out[j, L.S_MAX_U] = max(spring_out[j, L.S_MAX_U], u)
            force = motion.member_force(phase.springs, j, s, k, u)
            spring_out[j, L.S_MAX_FORCE] = max(spring_out[j, L.S_MAX_FORCE], force)


def _solve(phase: _Phase, t: float, t1: float, g0: float, gs: float):
    events, rows = _events(phase)
    first = min(REFERENCE_FIRST_STEP, (t1 - t) / 2) if phase.restart else None
    sol = solve_ivp(
        _rhs(phase, t, g0, gs),
        (t, t1),
        [phase.th, phase.om],
        method="DOP853",
        rtol=phase.par[L.P_RTOL],
        atol=phase.par[L.P_ATOL],
        events=events,
        first_step=first,
    )
    phase.restart = False
    return sol, rows


def _first_terminal(sol, rows):
    """(time, state, kind, row) of the terminal event that stopped the solve, or None."""
    if sol.status != 1:
        return None
    best = None
    for k, (times, states) in enumerate(zip(sol.t_events, sol.y_events, strict=True)):
        if times.size == 0 or rows[k][0] < 0:
            continue
        if best is None or times[0] < best[0]:
            best = (times[0], states[0], k, rows[k])
    return best


def _interval(phase, i, times, accel, pol, out_f, out_i, spring_out):
    """Advance through sample interval i; returns a status code or None to go on."""
    par = phase.par
    t = times[i]
    t1 = times[i + 1]
    gs = pol * (accel[i + 1] - accel[i]) / (t1 - t)
    while t1 - t > GAP_FRACTION * (t1 - times[i]):
        phase.t = t
        if phase.s == 0:
            thr_pos, thr_neg = _uplift_thresholds(phase)
            tau, side = motion.uplift_in_interval(
                t,
                i,
                times,
                accel,
                pol,
                thr_pos,
                thr_neg,
                int(par[L.P_ONE_SIDED]),
                int(par[L.P_FREE_SIDE]),
            )
            if side == 0:
                return None
            phase.s, phase.th, phase.om, phase.restart, phase.d = side, 0.0, 0.0, True, 1
            out_i[L.I_UPLIFTS] += 1
            if out_i[L.I_UPLIFTS] == 1:
                out_f[L.O_T_UPLIFT] = tau
            t = tau
            continue
        if phase.stuck:
            thr_pos, thr_neg = motion.stuck_thresholds(phase.s, *_friction_terms(phase))
            tau, side = motion.uplift_in_interval(t, i, times, accel, pol, thr_pos, thr_neg, 0, 0)
            if side == 0:
                return None
            phase.d, phase.stuck, phase.om, phase.restart = side * phase.s, False, 0.0, True
            if phase.memory and phase.d < 0:
                a = max(phase.s * phase.th, 0.0)
                motion.unload(
                    phase.springs, phase.alive, phase.s, a, phase.lin, spring_out, L.S_ENERGY
                )
            t = tau
            continue
        g0 = motion.ground_acceleration(t, i, times, accel, pol)
        status = _check_start(phase, t, g0, gs, out_f, out_i)
        if status is not None:
            return status
        sol, rows = _solve(phase, t, t1, g0, gs)
        out_i[L.I_STEPS] += sol.nfev // EVALS_PER_STEP
        if sol.status == -1 or not np.all(np.isfinite(sol.y[:, -1])):
            return _failed(phase, sol, g0, gs, out_f, out_i)
        for y in sol.y_events[K_PEAK]:
            _peak(phase, phase.s * y[0], out_f, spring_out)
        out_f[L.O_MAX_OMEGA] = max(out_f[L.O_MAX_OMEGA], float(np.max(np.abs(sol.y[1]))))
        hit = _first_terminal(sol, rows)
        if hit is None:
            phase.th, phase.om = float(sol.y[0, -1]), float(sol.y[1, -1])
            _peak(phase, phase.s * phase.th, out_f, spring_out)
            return None
        t, y, kind, row = hit
        if row[0] == K_TURN:
            _turn(phase, t, float(y[0]), motion.ground_acceleration(t, i, times, accel, pol),
                  out_f, spring_out)  # fmt: skip
            continue
        status = _apply_event(phase, t, y, kind, row, out_f, out_i, spring_out)
        if status is not None:
            return status
    return None


def _friction_terms(phase: _Phase) -> tuple[float, float, float]:
    """(q0, k, mf) of the body at a standstill at phase.th (kernel.py's _friction_terms)."""
    s, th = phase.s, phase.th
    q0 = s * _acceleration(phase, 0.0, th, 0.0, 0)
    k = s * _acceleration(phase, float(s), th, 0.0, 0) - q0
    mf = q0 - s * _acceleration(phase, 0.0, th, 0.0, 1)
    return q0, k, mf + motion.FRICTION_MARGIN * (abs(q0) + mf)


def _sense(phase: _Phase, ag: float) -> int:
    """The sense of the motion from a standstill at phase.th under ground ag [g] (0: sticks)."""
    q0, k, mf = _friction_terms(phase)
    return motion.friction_sense(q0 + phase.s * ag * k, mf)


def _turn(phase: _Phase, t: float, th: float, ag: float, out_f: np.ndarray,
          spring_out: np.ndarray) -> None:  # fmt: skip
    """A turning point under friction: the peak kept, members on their plateau unload, the
    new sense (or a standstill: stuck, held until the ground moves it: :func:`_interval`)."""
    phase.th, phase.om, phase.restart, phase.t = th, 0.0, True, t
    _peak(phase, max(phase.s * th, 0.0), out_f, spring_out)
    phase.d = _sense(phase, ag)
    if phase.memory and phase.d < 0:
        a = max(phase.s * th, 0.0)
        motion.unload(phase.springs, phase.alive, phase.s, a, phase.lin, spring_out, L.S_ENERGY)
    phase.stuck = phase.d == 0
    if phase.stuck:
        phase.d = 1


def _uplift_thresholds(phase: _Phase) -> tuple[float, float]:
    """The ground accelerations [g] that start the block rocking from rest (kernel.py's rule)."""
    par = phase.par
    thr = par[L.P_ALPHA] if phase.lin else math.tan(par[L.P_ALPHA])
    thr_pos, thr_neg = (
        (par[L.P_UPLIFT_POS], par[L.P_UPLIFT_NEG]) if par[L.P_KIND] != L.K_RECTANGLE else (thr, thr)
    )
    if phase.memory:
        thr_pos += motion.rest_moment(phase.springs, phase.alive, 1) * par[L.P_PRE_SCALE_POS]
        thr_neg += motion.rest_moment(phase.springs, phase.alive, -1) * par[L.P_PRE_SCALE_NEG]
    return thr_pos, thr_neg


def _inertia(par: np.ndarray, s: int) -> float:
    if s == 0:
        return 0.0
    return float(par[L.P_INERTIA_POS] if s > 0 else par[L.P_INERTIA_NEG])


def _check_start(phase, t, g0, gs, out_f, out_i):
    """STATUS_NONFINITE if the state or the ground motion at the start of a solve is not finite.

    Needed before solve_ivp: its first-step selection from a NaN slope gives a NaN step size,
    and its step loop then never ends (scipy 1.17).
    """
    th, om = phase.th, phase.om
    if (
        math.isfinite(th)
        and math.isfinite(om)
        and math.isfinite(g0)
        and math.isfinite(gs)
        and math.isfinite(_acceleration(phase, g0, th, om))
    ):
        return None
    out_f[L.O_T_END] = t
    out_i[L.I_NONFINITE] = _nonfinite_quantity(phase, g0 + gs, th, om)
    return L.STATUS_NONFINITE


def _failed(phase, sol, g0, gs, out_f, out_i):
    """Status of a solve that could not reach the interval's end: non-finite or step-limit."""
    t = float(sol.t[-1])
    out_f[L.O_T_END] = t
    th, om = float(sol.y[0, -1]), float(sol.y[1, -1])
    ag = g0 + gs * (t - float(sol.t[0]))
    finite = math.isfinite(th) and math.isfinite(om) and math.isfinite(ag)
    if finite and math.isfinite(_acceleration(phase, ag, th, om)):
        return L.STATUS_STEP_LIMIT  # the step size fell below the spacing of the times
    out_i[L.I_NONFINITE] = _nonfinite_quantity(phase, ag, th, om)
    return L.STATUS_NONFINITE


def _apply_event(phase, t, y, kind, row, out_f, out_i, spring_out):
    par = phase.par
    kind, row = row
    if kind == K_OVERTURN:
        _peak(phase, L.collapse_rotation(par, phase.s), out_f, spring_out)
        out_f[L.O_T_OVERTURN] = t
        out_f[L.O_T_END] = t
        return L.STATUS_OVERTURNED
    if kind != K_IMPACT:
        _apply_restrainer_event(phase, t, y, kind, row, out_f, spring_out)
        phase.th, phase.om, phase.restart = float(y[0]), float(y[1]), True
        return None
    out_i[L.I_IMPACTS] += 1
    e = par[L.P_E] if phase.s > 0 else par[L.P_E_NEG]
    before = 0.5 * _inertia(par, phase.s) * float(y[1]) ** 2
    om, s = motion.velocity_after_impact(
        float(y[1]), phase.s, e, int(par[L.P_ONE_SIDED]), par[L.P_REBOUND]
    )
    phase.th, phase.om, phase.s, phase.restart, phase.d = 0.0, om, s, True, 1
    if abs(om) < par[L.P_REST]:
        phase.s, phase.om = 0, 0.0
    out_f[L.O_IMPACT_LOSS] += before - 0.5 * _inertia(par, phase.s) * phase.om**2
    if phase.s != 0 and out_i[L.I_IMPACTS] >= int(par[L.P_MAX_EVENTS]):
        out_f[L.O_T_END] = t
        return L.STATUS_EVENT_LIMIT
    return None


def _apply_restrainer_event(phase, t, y, kind, row, out_f, spring_out):
    """A failure at fails_at, a member law's level (yield, re-engage, anchor rupture), a slack
    point, or the turning point of a yield plateau (kernel.py's rules, motion.py's law)."""
    s, lin, springs = phase.s, phase.lin, phase.springs
    a = max(s * float(y[0]), 0.0)
    _peak(phase, a, out_f, spring_out)
    if kind == K_PEAK:
        motion.unload(springs, phase.alive, s, a, lin, spring_out, L.S_ENERGY)
    elif kind == K_SLACK:
        motion.cross_down(springs, row, s, lin)
    else:
        up = springs[row, motion.COL_UP_KIND + motion.side_index(s)]
        if kind == K_LAW_UP and up == motion.UP_ENGAGE:
            up = motion.engage(springs, row, s, a, lin)  # its next level too, if already reached
        if kind == K_FAIL or up == motion.UP_BREAK:
            motion.lose(springs, phase.alive, row, s, a, lin, spring_out, L.S_ENERGY)
            spring_out[row, L.S_T_FAIL] = t
        elif up == motion.UP_YIELD:
            motion.cross_up(springs, row, s, lin)
            if math.isnan(spring_out[row, L.S_T_YIELD]):
                spring_out[row, L.S_T_YIELD] = t


def integrate_reference(
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
    exact=None,
):
    """Same contract as :func:`rockcli.dynamics.kernel.integrate` (arrays filled in place);
    ``exact``: a chain's terms from its configuration function (mechanics.Chain.exact), read
    in place of its table.

    Overflows and NaNs are not warnings here: they end the run with status "non-finite".
    """
    with np.errstate(all="ignore"):
        _integrate(
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
            exact,
        )


def _integrate(
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
    exact,
):
    phase = _Phase(par, springs, points, alive)
    phase.exact = exact
    out_f[:] = 0.0
    out_f[L.O_T_OVERTURN] = math.nan
    out_f[L.O_T_UPLIFT] = math.nan
    out_i[:] = 0
    th0, om0 = par[L.P_THETA0], par[L.P_OMEGA0]
    if th0 != 0.0 or om0 != 0.0:
        phase.s = int(math.copysign(1, th0 if th0 != 0.0 else om0))
        phase.th, phase.om = th0, om0
        out_f[L.O_T_UPLIFT] = times[0]
        _peak(phase, phase.s * th0, out_f, spring_out)
        if phase.rub:
            if om0 != 0.0:
                phase.d = 1 if phase.s * om0 > 0.0 else -1
            else:
                _turn(phase, times[0], th0,
                      motion.ground_acceleration(times[0], 0, times, accel, pol), out_f,
                      spring_out)  # fmt: skip
    _store(hist_th, hist_om, hist_f, 0, phase)
    out_i[L.I_STATUS] = L.STATUS_COMPLETED
    out_f[L.O_T_END] = times[-1]
    for i in range(times.size - 1):
        try:
            status = _interval(phase, i, times, accel, pol, out_f, out_i, spring_out)
        except _OutOfBudget:
            status = L.STATUS_STEP_LIMIT
            out_f[L.O_T_END] = phase.t
            out_i[L.I_STEPS] = int(par[L.P_MAX_STEPS])
        if status is not None:
            out_i[L.I_STATUS] = status
            _close_plateaus(phase, status, spring_out)
            return
        _store(hist_th, hist_om, hist_f, i + 1, phase)
    _close_plateaus(phase, L.STATUS_COMPLETED, spring_out)
    out_i[L.I_REJECTED] = 0
    forces = spring_out[:, L.S_MAX_FORCE]
    row = int(np.argmin(np.isfinite(forces))) if forces.size else -1
    if row >= 0 and not np.isfinite(forces[row]):
        out_i[L.I_STATUS] = L.STATUS_NONFINITE
        out_i[L.I_NONFINITE] = L.NF_FORCE + row


def _close_plateaus(phase: _Phase, status: int, spring_out: np.ndarray) -> None:
    """A run that ends on a yield plateau: the member unloads where the run ended."""
    if phase.memory and phase.s != 0 and status != L.STATUS_NONFINITE:
        a = (
            L.collapse_rotation(phase.par, phase.s)
            if status == L.STATUS_OVERTURNED
            else phase.s * phase.th
        )
        motion.unload(phase.springs, phase.alive, phase.s, a, phase.lin, spring_out, L.S_ENERGY)


def _store(
    hist_th: np.ndarray, hist_om: np.ndarray, hist_f: np.ndarray, i: int, phase: _Phase
) -> None:
    if hist_th.size > 1:
        hist_th[i] = phase.th
        hist_om[i] = phase.om
        for j in range(hist_f.shape[1]):
            a = phase.s * phase.th if phase.s else 0.0
            hist_f[i, j] = motion.restrainer_force(
                phase.springs, phase.alive, j, phase.s, a, phase.lin
            )
