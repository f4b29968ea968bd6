"""The rocking cases: free rocking, releases, uplifts, the impulse and pulse thresholds.

Each case's block is its model's (``rockcli.model.derive.to_block``), run by
``rockcli.dynamics.simulate.simulate`` with the model's solver settings, as `rock assess` runs
it; the pulses are `rock record pulse`'s (``rockcli.records.pulses.make_pulse``); the ground
motion of an uplift case reaches a block at height through its floor
(``rockcli.analyses.floor.block_input``, as in `rock assess`). Thresholds are bisected: the
amplitude where the engine's verdict flips from survives to overturns, inside the case's
bracket.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from rockcli.analyses.assess import settings_from
from rockcli.analyses.floor import block_input
from rockcli.casebook.schema import (
    FreeRockingInput,
    ImpulseInput,
    PulseThresholdInput,
    ReleaseInput,
    UpliftRampInput,
    UpliftSineInput,
)
from rockcli.dynamics.result import RestrainerPeak, RockingRun
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.errors import InputError
from rockcli.mechanics import Rocker
from rockcli.model.derive import solver_options, to_block
from rockcli.model.schema import Model
from rockcli.records.pulses import make_pulse
from rockcli.records.record import Record

#: Bisection stops when the bracket is this narrow, relative to its upper end: 1e-6, ten
#: times below the tightest tolerance of a threshold case.
BISECT_RTOL = 1e-6
#: Free time after a release or a pulse, in units of 1/p: longer than the slowest case's
#: impacts (the linearized period from φ0 = 0.9 is 12/p) and than the overturning of a block
#: that passed α (the default tail is 20/p).
TAIL_OVER_P = 100.0
#: The sample interval of the quiet record of a free-rocking run [s].
QUIET_DT = 0.01


class NotObtained(Exception):
    """No value for the case: the verdict does not flip inside the bracket, or the run ends
    before the half-cycle asked for (the case fails; this is not bad input)."""


def model_settings(model: Model, block: Rocker, **changes: object) -> SolverSettings:
    """The model's solver settings with a long free tail and the given changes."""
    settings = settings_from(solver_options(model))
    return replace(settings, tail=TAIL_OVER_P / block.p, **changes)  # type: ignore[arg-type]


def case_block(model: Model, mechanism: str | None = None) -> Rocker:
    """What a case rocks: the catalogue's mechanism named, else its first (a block file's
    block; rockcli.model.catalogue.Mechanism.rocker)."""
    from rockcli.model.catalogue import first_mechanism, named_mechanism

    if mechanism is None:
        return first_mechanism(model).rocker
    return named_mechanism(model, mechanism).rocker


def release(
    model: Model, theta0: float, omega0: float, block: Rocker | None = None, **changes: object
) -> RockingRun:
    """Free rocking from θ0 [rad] with θ̇0 [rad/s], no ground motion (``block``: the case's,
    default the model's)."""
    block = to_block(model) if block is None else block
    time, accel = np.array([0.0, QUIET_DT]), np.zeros(2)
    settings = model_settings(model, block, **changes)
    return simulate(block, time, accel, QUIET_DT, settings=settings, theta0=theta0, omega0=omega0)


def free_period(model: Model, inputs: FreeRockingInput) -> float:
    """The time from the first to the third impact [s]: one full cycle (e = 1)."""
    block = case_block(model, inputs.mechanism)
    theta0 = inputs.phi0 * block.alpha
    first = release(model, theta0, 0.0, block, max_events=1).t_end
    third = release(model, theta0, 0.0, block, max_events=3).t_end
    return third - first


def free_amplitude(model: Model, inputs: FreeRockingInput) -> float:
    """|θ| at the peak of the half-cycle after the given number of impacts [rad]."""
    block = case_block(model, inputs.mechanism)
    theta0 = inputs.phi0 * block.alpha
    time = np.arange(0.0, QUIET_DT + inputs.dt / 2, inputs.dt)
    settings = model_settings(model, block, max_events=inputs.impacts + 1)
    run = simulate(block, time, np.zeros(time.size), inputs.dt, settings=settings,
                   theta0=theta0, history=True)  # fmt: skip
    assert run.history is not None
    peaks = half_cycle_peaks(run.history.theta)
    if len(peaks) < inputs.impacts:
        raise NotObtained(f"only {len(peaks)} complete half-cycles before the run ended")
    return peaks[inputs.impacts - 1]


def half_cycle_peaks(theta: np.ndarray) -> list[float]:
    """|θ| at the peak of each complete half-cycle, refined by the parabola's vertex.

    The sampled peak and its two neighbours fix a parabola; its vertex is off the true peak
    by O(dt⁴p⁴α) (θ⃛ vanishes there), far below the cases' tolerances at dt = 1e-3 s.
    """
    sign = np.sign(theta)
    edges = np.flatnonzero(np.diff(sign) != 0) + 1
    peaks = []
    for run in np.split(np.arange(theta.size), edges):
        a = np.abs(theta[run])
        k = int(np.argmax(a))
        if sign[run[0]] == 0 or k == 0 or k == run.size - 1:
            continue  # at rest, the release, or the cut end: not a complete half-cycle
        y0, y1, y2 = a[k - 1], a[k], a[k + 1]
        peaks.append(float(y1 + (y0 - y2) ** 2 / (8.0 * (2.0 * y1 - y0 - y2))))
    return peaks


def released(model: Model, inputs: ReleaseInput, quantity: str) -> float:
    """A quantity of free rocking from (θ0, θ̇0) up to the case's impact: the largest |θ|
    [rad], or its restrainer's peak elongation [m], peak force [N], plastic elongation [m] or
    energy dissipated [J]."""
    run = release(model, inputs.theta0, inputs.omega0, max_events=inputs.impacts)
    if quantity == "max_rotation":
        return max(run.theta_max, -run.theta_min)
    peak = restrainer_peak(run, inputs.restrainer)
    values = {
        "max_elongation": peak.max_displacement,
        "max_force": peak.max_force,
        "plastic_elongation": peak.plastic_elongation,
        "energy_dissipated": peak.energy_dissipated,
    }
    return values[quantity]


def restrainer_peak(run: RockingRun, number: int) -> RestrainerPeak:
    """The demand on restrainer ``number`` (1-based) of the run (InputError: no such one)."""
    if number > len(run.restrainers):
        raise InputError(
            "no such restrainer in the model",
            where="input.restrainer",
            value=number,
            allowed=f"1 to {len(run.restrainers)}" if run.restrainers else "a model with one",
        )
    return run.restrainers[number - 1]


def ramp_uplift(model: Model, inputs: UpliftRampInput, quantity: str) -> float:
    """The ground acceleration |üg| [g] at the first uplift under the ramp, or its time [s]."""
    time = np.arange(0.0, inputs.duration + inputs.dt / 2, inputs.dt)
    accel = inputs.direction * inputs.slope * time
    t_uplift = first_uplift(model, time, accel, inputs.dt, inputs.mechanism)
    return t_uplift if quantity == "uplift_time" else inputs.slope * t_uplift


def sine_uplift(model: Model, inputs: UpliftSineInput) -> float:
    """The time [s] of the first uplift under the ground sine, from rest."""
    dt = inputs.period / inputs.samples_per_period
    time = np.arange(0.0, inputs.cycles * inputs.period + dt / 2, dt)
    accel = inputs.direction * inputs.amplitude * np.sin(2.0 * np.pi * time / inputs.period)
    return first_uplift(model, time, accel, dt)


def first_uplift(
    model: Model, time: np.ndarray, accel: np.ndarray, dt: float, mechanism: str | None = None
) -> float:
    """The first uplift [s] of the model's block (a wall's mechanism: ``mechanism``, else its
    first) under the ground motion, which reaches a block at height through its floor as in
    `rock assess` (the run stops at the first impact).

    Raises:
        NotObtained: the block does not uplift.
    """
    ground = Record("casebook ground motion", "generated", "pulse", time, accel, dt)
    motion, _ = block_input(model, ground)
    block = case_block(model, mechanism)
    settings = model_settings(model, block, max_events=1)
    run = simulate(block, motion.time, motion.accel, motion.dt, settings=settings)
    if run.t_uplift is None:
        raise NotObtained("the block does not uplift under this motion")
    return run.t_uplift


def impulse_threshold(model: Model, inputs: ImpulseInput) -> float:
    """The initial velocity θ̇0 [rad/s] from θ = 0 above which the block overturns."""
    return bisect(lambda omega0: release(model, 0.0, omega0).overturned, *inputs.bracket)


def pulse_threshold(model: Model, inputs: PulseThresholdInput) -> float:
    """The pulse amplitude [g] above which the block overturns."""
    block = to_block(model)
    settings = model_settings(model, block)

    def overturns(amplitude: float) -> bool:
        rec = make_pulse(inputs.pulse, amplitude, inputs.period, dt=inputs.dt)
        return simulate(block, rec.time, rec.accel, rec.dt, settings=settings).overturned

    return bisect(overturns, *inputs.bracket)


def bisect(overturns: Callable[[float], bool], lo: float, hi: float) -> float:
    """The value in [lo, hi] where ``overturns`` flips from False to True.

    Raises:
        NotObtained: it overturns at lo already, or survives at hi.
    """
    if overturns(lo) or not overturns(hi):
        raise NotObtained(f"the verdict does not flip between {lo:.6g} and {hi:.6g}")
    while hi - lo > BISECT_RTOL * hi:
        mid = 0.5 * (lo + hi)
        if overturns(mid):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)
