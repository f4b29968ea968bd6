"""A work budget tied to the record's length: absurd models end fast with "step-limit".

Seen before the fix (issue 7, item 12): a restrainer of K = 1e15 N/m on a 50 kg block ran 33
million steps (204 s here, under load) through ELC180 and reported "completed, survives"; the
only guard was the fixed 5e7-step limit. The budget is now STEPS_PER_SAMPLE steps per sample
of the grid plus STEP_BUDGET_BASE (rockcli/dynamics/simulate.py), and the verdict undecided.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from rockcli.dynamics.result import RunStatus, Verdict
from rockcli.dynamics.settings import DEFAULT_MAX_STEPS, Engine, SolverSettings
from rockcli.dynamics.simulate import (
    STEP_BUDGET_BASE,
    STEPS_PER_SAMPLE,
    assess,
    extend_with_tail,
    simulate,
    step_budget,
)
from rockcli.mechanics import Block, Restrainer

DT = 0.01
TIME = np.arange(200) * DT
#: 0.5 g > tan 0.2: the block uplifts, and the stiff spring then needs ~1e-8 s steps.
ACCEL = 0.5 * np.sin(2 * np.pi * TIME)
ABSURD_K = 1e15  # N/m, on a 50 kg block: √(K/m) ≈ 4.5e6 rad/s
STIFF = Block(
    R=0.25,
    alpha=0.2,
    e=0.9,
    mass=50.0,
    restrainers=(Restrainer("top", ABSURD_K, ABSURD_K, 0.5, 0.2, 0.5, 0.2),),
)
#: Wall-clock bound for both polarities [s]: the budget is 2.6e5 + 1e5 ≈ 0.36 M steps here
#: (≈ 0.15 s at 0.4 µs a step; ten times that on a loaded machine); before the fix, > 60 s.
WALL_BOUND = 15.0


def test_an_absurdly_stiff_model_ends_on_the_budget_quickly() -> None:
    start = time.perf_counter()
    result = assess(STIFF, TIME, ACCEL, DT)
    elapsed = time.perf_counter() - start
    n_grid = extend_with_tail(TIME, ACCEL, DT, SolverSettings().tail_for(STIFF.p))[0].size
    budget = STEPS_PER_SAMPLE * n_grid + STEP_BUDGET_BASE
    assert budget < DEFAULT_MAX_STEPS / 10  # the budget, not the old fixed guard, stops it
    for run in result.runs:
        assert run.status is RunStatus.STEP_LIMIT
        assert run.steps + run.rejected == budget
        assert f"{budget:,} steps" in run.message and "stiff restrainer" in run.message
    assert result.verdict is Verdict.UNDECIDED
    assert elapsed < WALL_BOUND


def test_the_reference_engine_keeps_the_budget_too() -> None:
    """A budget of 50 steps (explicit max_steps) stops the scipy engine inside its solve."""
    run = simulate(
        STIFF, TIME, ACCEL, DT, settings=SolverSettings(max_steps=50), engine=Engine.REFERENCE
    )
    assert run.status is RunStatus.STEP_LIMIT
    assert run.t_end < TIME[-1]


@pytest.mark.parametrize(
    ("n", "max_steps", "expected"),
    [
        (1000, DEFAULT_MAX_STEPS, STEPS_PER_SAMPLE * 1000 + STEP_BUDGET_BASE),
        (10**9, DEFAULT_MAX_STEPS, DEFAULT_MAX_STEPS),  # never above the settings' guard
        (1000, 10, 10),
    ],
)
def test_step_budget(n: int, max_steps: int, expected: int) -> None:
    assert step_budget(n, max_steps) == expected
