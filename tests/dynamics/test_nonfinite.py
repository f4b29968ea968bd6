"""A non-finite number inside a run ends it with status "non-finite", never "completed".

Seen before the fix (issue 7, item 3): a finite record sample of 1e308 g makes the ground
acceleration's slope overflow (1e308 g over 0.01 s), the error estimate of the step is NaN,
``err > 1`` is false for NaN, the step was accepted and the run reported "completed,
survives". A restrainer of K = 1.8e308 N/m (read as +inf) did the same. Both engines.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.dynamics.result import Assessment, RunStatus, Verdict
from rockcli.dynamics.settings import Engine
from rockcli.dynamics.simulate import assess
from rockcli.mechanics import Block, Restrainer

ALPHA = 0.2
DT = 0.01
TIME = np.arange(100) * DT
#: 0.5 g > tan 0.2 = 0.203 g: the block uplifts in the first quarter period (t ≈ 0.07 s).
WAVE = 0.5 * np.sin(2 * np.pi * TIME)
#: The sample made absurd, and the interval that leads to it [s].
SPIKE_INDEX = 50
SPIKE = 1e308
ENGINES = [Engine.FAST, Engine.REFERENCE]


@pytest.mark.parametrize("engine", ENGINES)
def test_an_overflowing_sample_ends_the_run_as_non_finite(engine: Engine) -> None:
    accel = WAVE.copy()
    accel[SPIKE_INDEX] = SPIKE
    result = assess(Block(R=1.0, alpha=ALPHA, e=0.9), TIME, accel, DT, engine=engine)
    for run in result.runs:
        assert run.status is RunStatus.NONFINITE, run.message
        assert "ground acceleration is not finite" in run.message
        # the slope overflows in the interval before the spike: the run stops inside it
        assert TIME[SPIKE_INDEX - 1] <= run.t_end <= TIME[SPIKE_INDEX]
        assert f"t = {run.t_end:.6g} s" in run.message
        assert any("not finite" in w for w in run.warnings)
    assert result.verdict is Verdict.UNDECIDED


@pytest.mark.parametrize("engine", ENGINES)
def test_an_infinite_restrainer_ends_the_run_as_non_finite(engine: Engine) -> None:
    k = float("1.8e308")  # past the largest double: +inf, as a TOML reader gives it
    assert math.isinf(k)
    spring = Restrainer("tie", k, k, 2.0, ALPHA, 2.0, ALPHA)
    block = Block(R=1.0, alpha=ALPHA, e=0.9, mass=1000.0, restrainers=(spring,))
    result = assess(block, TIME, WAVE, DT, engine=engine)
    for run in result.runs:
        assert run.status is RunStatus.NONFINITE, run.message
        assert "the force of restrainer 'tie' is not finite" in run.message
        assert run.t_end < TIME[-1]  # stopped at the first uplift, not at the end
    assert result.verdict is Verdict.UNDECIDED


def test_a_non_finite_run_leaves_the_verdict_undecided_even_beside_an_overturn() -> None:
    """One polarity overturned, the other met a NaN: the numbers decide nothing."""
    base = assess(Block(R=1.0, alpha=ALPHA, e=0.9), TIME, WAVE, DT).runs[0]
    from dataclasses import replace

    overturned = replace(base, status=RunStatus.OVERTURNED)
    broken = replace(base, status=RunStatus.NONFINITE, polarity=-1)
    assert Assessment(runs=(overturned, base)).verdict is Verdict.OVERTURNS
    assert Assessment(runs=(overturned, broken)).verdict is Verdict.UNDECIDED


def test_the_peak_before_the_stop_is_kept_by_both_engines() -> None:
    """The block is still rising when the spike stops the run: both engines report θ at the stop.

    Before the fix the fast engine reported 7.6e-7 (only peaks at turning points were kept) and
    the reference 0.675; tolerance 1e-6: the reference runs at rtol 1e-10, the fast engine at
    1e-8, and the two agree to 1e-8 on this smooth rise (same θ at 0.49 s to 8 digits).
    """
    accel = WAVE.copy()
    accel[SPIKE_INDEX] = SPIKE
    block = Block(R=1.0, alpha=ALPHA, e=0.9)
    fast, ref = (assess(block, TIME, accel, DT, engine=e).runs[0] for e in ENGINES)
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
    assert fast.max_ratio > 0.5  # rocking: θ(0.49 s) ≈ 0.135 rad = 0.67 α


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize(
    ("theta0", "omega0", "name"),
    [(math.nan, 0.0, "the rotation θ"), (0.1, math.inf, "the angular velocity θ̇")],
)
def test_a_non_finite_state_is_named(
    engine: Engine, theta0: float, omega0: float, name: str
) -> None:
    """A NaN θ shows at once in θ̈; an infinite θ̇ in the error estimate, which stays NaN
    through NONFINITE_RETRIES shrunk retries: either way the message names the quantity."""
    from rockcli.dynamics.simulate import simulate

    run = simulate(
        Block(R=1.0, alpha=ALPHA, e=0.9),
        TIME,
        WAVE,
        DT,
        engine=engine,
        theta0=theta0,
        omega0=omega0,
    )
    assert run.status is RunStatus.NONFINITE
    assert f"{name} is not finite" in run.message
    assert run.t_end == 0.0
