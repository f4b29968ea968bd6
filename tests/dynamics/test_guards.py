"""Guards: a run that hits its event or step budget stops with a status, never an exception.

Source: spec/engine.md, trap 5 ("Guard the number of events (a status, never a hang)") and
spec/style.md, principle 3 ("A physics outcome is a result ... not an exception").

The case: free rocking with e = 1 from θ0 = α/2 never comes to rest, so it impacts every half
period (T/2 = (2/p)·arccosh 2 ≈ 0.97 s for R = 1 m) until the tail ends: 3 impacts happen
within the first 3 s, and a tail of 20 s guarantees the budget is reached.
"""

from __future__ import annotations

import numpy as np
import pytest

from rockcli.dynamics.result import RunStatus, Verdict
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import assess, simulate
from rockcli.mechanics import Block

ALPHA = 0.2
ELASTIC = Block(R=1.0, alpha=ALPHA, e=1.0)
QUIET = (np.array([0.0, 0.01]), np.zeros(2), 0.01)


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_event_budget_stops_with_a_status(engine: Engine) -> None:
    settings = SolverSettings(tail=20.0, max_events=3)
    run = simulate(ELASTIC, *QUIET, settings=settings, engine=engine, theta0=ALPHA / 2)
    assert run.status is RunStatus.EVENT_LIMIT
    assert run.impacts == 3
    assert not run.overturned
    assert run.t_end < 20.0  # stopped early, at the third impact
    assert any("too many impacts" in w for w in run.warnings)


def test_step_budget_stops_with_a_status() -> None:
    settings = SolverSettings(tail=20.0, max_steps=10)
    run = simulate(ELASTIC, *QUIET, settings=settings, theta0=ALPHA / 2)
    assert run.status is RunStatus.STEP_LIMIT
    assert run.steps + run.rejected == 10
    assert any("too many steps" in w for w in run.warnings)


def test_budget_hit_leaves_the_verdict_undecided() -> None:
    """A record that makes the block rock past the budget: no verdict is invented."""
    time = np.arange(51) * 0.01
    accel = 0.3 * np.sin(np.pi * time / 0.5)  # half-sine, 0.3 g > tan 0.2 = 0.2 g: rocks (e = 1)
    result = assess(ELASTIC, time, accel, 0.01, settings=SolverSettings(max_events=3))
    assert all(r.status is RunStatus.EVENT_LIMIT for r in result.runs)
    assert result.verdict is Verdict.UNDECIDED
