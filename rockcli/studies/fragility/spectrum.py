"""Overturning spectra: the lowest intensity that overturns a block, against its size or the
pulse's frequency.

For a pulse of period Tp = 2π/ωp and peak ap, a rigid block's equation of motion written in
τ = p·t (Housner 1963, BSSA 53(2):403–417; Makris & Roussos 2000, Géotechnique 50(3):243–262)
is

    d²θ/dτ² = −sin(α·sgn θ − θ) − (ap/g)·f((ωp/p)·τ)·cos(α·sgn θ − θ),

with impacts θ̇⁺ = e·θ̇⁻: with x = ap/(g·tan α) it depends on α, e and ωp/p only, not on R
(the linearized equation, with x = ap/(g·α), on ωp/p and e only). The threshold x against
ωp/p is one curve for every block of that α and e (Zhang & Makris 2001, J. Eng. Mech.
127(5):473–483; Makris & Konstantinidis 2003, EESD 32(2):265–289, the "overturning spectrum").

The lowest overturning x is found by the first-exceedance search
(:func:`rockcli.studies.fragility.search.first_exceedances`): a scan up at a fixed step, a bisection
inside the first step that overturns. Above the lowest overturning amplitude a block can
survive again (the safe region of Zhang & Makris 2001): a bisection between the scan's ends
would find any boundary, the scan finds the lowest one it can see.

Pure and silent: no output, no files; the runs are :func:`rockcli.dynamics.simulate.assess`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from rockcli.dynamics.result import RunStatus
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import assess
from rockcli.mechanics import Rocker
from rockcli.records.pulses import make_pulse
from rockcli.records.record import Record
from rockcli.studies.fragility.search import first_exceedances

#: Samples per pulse period: a sine joined linearly between samples shrinks by (2π/N)²/12
#: ≈ 2e-5 at N = 400 (the threshold moves by as much), far below a scan step of 0.05.
SAMPLES_PER_PERIOD = 400
#: A pulse that ends off zero (the one-cosine ends at ap) steps to zero over this fraction of a
#: sample, not over a whole sample: a ramp over dt adds an impulse ap·dt/2, which moved the
#: Makris–Konstantinidis mode-2 threshold by 3e-4 at N = 400 (2e-5 with the step).
STEP_FRACTION = 1e-6
#: Free time after the motion, in units of 1/p (the casebook's: rockcli.casebook.rocking):
#: longer than a block takes to settle or to leave the unstable equilibrium θ = α.
TAIL_OVER_P = 100.0
#: Times the tail is doubled for a run still rocking at its end, before it is undecided.
TAIL_DOUBLINGS = 3
#: The level of the search that an overturn reaches (the response is +inf then).
OVERTURN = math.inf


class UndecidedRun(ValueError):
    """A run that decides nothing: a non-finite state, a guard reached, or still rocking at
    the end of the longest tail."""


@dataclass(frozen=True)
class Scan:
    """The intensities the search tries, in units of the block's uplift acceleration
    (ap/(g tan α) for a pulse, PGA·s/(g tan α) for a record scaled by s).

    Attributes:
        first, step, last: the scan's first intensity, its step and its end [-].
        tolerance: the width of the bisection's last bracket [-].
    """

    first: float = 1.0
    step: float = 0.05
    last: float = 20.0
    tolerance: float = 1e-3


@dataclass(frozen=True)
class Threshold:
    """The lowest overturning intensity of one point of a spectrum.

    Attributes:
        value: the lowest intensity found that overturns [-] (None: none up to scan.last).
        below: the highest intensity known not to overturn under it (None: the first tried
            overturns, or none does).
        runs: the intensities run (each both polarities).
        unsettled: the runs taken as survivals although the block still moved at the end
            of the tail (a block vibrating on its restrainers).
        undecided: why the point has no value when a run decided nothing (else None).
    """

    value: float | None
    below: float | None
    runs: int
    unsettled: int = 0
    undecided: str | None = None


def pulse_period(ratio: float, p: float) -> float:
    """Tp = 2π/ωp [s] of the pulse with ωp/p = ratio, for a block of frequency p [rad/s]."""
    return 2.0 * math.pi / (ratio * p)


def sampled_pulse(kind: str, amplitude: float, period: float, total: float | None = None) -> Record:
    """The pulse ``kind`` of peak ``amplitude`` [g] and period [s] (as `rock record pulse`
    makes it), SAMPLES_PER_PERIOD samples per period, ending in a sharp step to zero."""
    record = make_pulse(kind, amplitude, period, dt=period / SAMPLES_PER_PERIOD, total=total)
    return sharp_end(record)


def sharp_end(record: Record) -> Record:
    """The record with its last non-zero sample followed, STEP_FRACTION·dt later, by a zero:
    the ground stops there rather than ramping to zero over a sample."""
    nonzero = np.flatnonzero(record.accel)
    if nonzero.size == 0:
        return record
    k = int(nonzero[-1])
    at = record.time[k] + STEP_FRACTION * record.dt
    time = np.insert(record.time, k + 1, at)
    accel = np.insert(record.accel, k + 1, 0.0)
    return replace(record, time=time, accel=accel)


def overturn_response(
    block: Rocker,
    time: np.ndarray,
    accel: np.ndarray,
    dt: float,
    settings: SolverSettings,
    engine: Engine = Engine.FAST,
) -> tuple[float, bool]:
    """max|θ|/α over both polarities of the motion ``accel`` [g] at ``time`` [s] (``dt``:
    the tail's interval [s]), +inf when either polarity overturns; and whether the runs
    settled (overturned, or at rest on a ground at rest at the end of the tail).

    A free block still rocking at the end of its tail is run again with the tail doubled (up
    to TAIL_DOUBLINGS times): it comes to rest (impacts dissipate) unless it is on its way
    over. A block with restrainers can vibrate on them for ever without impacts: its run,
    not overturned at the end of the tail, is a survival that did not settle (as `rock
    assess` reads it).

    Raises:
        UndecidedRun: a run met a non-finite number or a guard, or a free block never settled.
    """
    tail = max(settings.tail_for(block.p), TAIL_OVER_P / block.p)
    for _ in range(TAIL_DOUBLINGS + 1):
        result = assess(
            block,
            time,
            accel,
            dt,
            settings=replace(settings, tail=tail),
            engine=engine,
            history=True,
        )
        if any(run.status is RunStatus.NONFINITE for run in result.runs):
            raise UndecidedRun(next(r.message for r in result.runs if r.message))
        if any(run.overturned for run in result.runs):
            return OVERTURN, True
        if any(run.status is not RunStatus.COMPLETED for run in result.runs):
            raise UndecidedRun(next(r.message for r in result.runs if r.message))
        settled = all(_at_rest(run.history) for run in result.runs)
        if settled or block.restrainers:
            return result.max_ratio, settled
        tail *= 2.0
    raise UndecidedRun(f"still rocking {tail / 2.0:.4g} s after the motion")


def _at_rest(history: object) -> bool:
    """Whether the run's last sample is the block at rest (θ = θ̇ = 0)."""
    theta = getattr(history, "theta", None)
    omega = getattr(history, "omega", None)
    if theta is None or omega is None or theta.size == 0:
        return False
    return bool(theta[-1] == 0.0 and omega[-1] == 0.0)


def lowest_overturn(response: Callable[[float], tuple[float, bool]], scan: Scan) -> Threshold:
    """The lowest intensity of the scan at which ``response`` overturns (+inf), bisected to
    scan.tolerance inside the first step that does (``response``: the response and whether
    its runs settled, as :func:`overturn_response`); an undecided run ends the search."""
    unsettled: set[float] = set()

    def measure(intensity: float) -> float:
        value, settled = response(intensity)
        if not settled:
            unsettled.add(intensity)
        return value

    try:
        (found,), runs = first_exceedances(
            measure,
            [OVERTURN],
            first=scan.first,
            step=scan.step,
            last=scan.last,
            tolerance=scan.tolerance,
        )
    except UndecidedRun as exc:
        return Threshold(None, None, 0, undecided=str(exc))
    return Threshold(found.scale, found.below, runs, len(unsettled))
