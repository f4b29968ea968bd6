"""The tolerance check (rockcli.dynamics.tolerance): the tight settings, the rule that flags a
run, and the check attached to each polarity.

Sources: the rule as docs/interpretations.md states it ("Tolerance check": rtol and atol over
1000, never below the engine's floor 1e-12; sensitive when max θ/α moves by more than 1 %
relative or the overturning verdict changes; not known when a run ended at a guard), and the
engine's own agreement on a robust case (a Ricker pulse on a free block: spec/engine.md,
self-convergence to 1e-5 on non-chattering cases).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from rockcli.dynamics.result import Assessment, RockingRun, RunStatus
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import assess
from rockcli.dynamics.tolerance import (
    SENSITIVE_CHANGE,
    TIGHTEST,
    any_sensitive,
    can_tighten,
    check_tolerance,
    is_sensitive,
    sensitive,
    tight_settings,
)
from rockcli.mechanics import Block, Load
from rockcli.records.pulses import ricker

#: A run as the engine reports it; the tests change the fields the rule reads.
RUN = RockingRun(
    polarity=-1, status=RunStatus.COMPLETED, message="survived", max_ratio=0.5,
    theta_max=0.05, theta_min=-0.01, max_velocity=0.1, t_overturn=None, t_uplift=1.0,
    impacts=40, uplifts=1, steps=1000, rejected=0, t_end=20.0, engine="fast", rtol=1e-8,
    atol=1e-8, rest_velocity=1e-4,
)  # fmt: skip
OVERTURNED = replace(RUN, status=RunStatus.OVERTURNED, max_ratio=math.pi / 2 / 0.1)


def test_the_tight_run_is_three_digits_tighter_down_to_the_floor() -> None:
    tight = tight_settings(SolverSettings())  # the defaults, 1e-8
    assert (tight.rtol, tight.atol) == (1e-11, 1e-11)
    assert tight_settings(SolverSettings(rtol=1e-10, atol=1e-6)).rtol == TIGHTEST
    assert tight_settings(SolverSettings(rtol=1e-10, atol=1e-6)).atol == 1e-9
    # the other settings are the run's own
    assert tight_settings(SolverSettings(tail=3.0, rest_velocity=1e-5)).tail == 3.0
    assert not can_tighten(SolverSettings(rtol=TIGHTEST, atol=TIGHTEST))
    assert can_tighten(SolverSettings(rtol=TIGHTEST, atol=1e-8))


@pytest.mark.parametrize(
    ("tight", "expected"),
    [
        (replace(RUN, max_ratio=0.5 * (1 + 0.5 * SENSITIVE_CHANGE)), False),  # within 1 %
        (replace(RUN, max_ratio=0.5 * (1 - 2 * SENSITIVE_CHANGE)), True),  # 2 % lower
        (replace(RUN, max_ratio=0.5 * (1 + 2 * SENSITIVE_CHANGE), impacts=90), True),
        (OVERTURNED, True),  # the verdict changes
        (replace(RUN, status=RunStatus.STEP_LIMIT, max_ratio=0.2), None),  # a guard: not known
    ],
)
def test_the_rule_flags_a_moved_peak_or_a_changed_verdict(
    tight: RockingRun, expected: bool | None
) -> None:
    assert is_sensitive(RUN, tight) is expected


def test_two_overturns_are_not_sensitive_and_a_guard_is_not_known() -> None:
    assert is_sensitive(OVERTURNED, replace(OVERTURNED, t_overturn=3.0)) is False
    assert is_sensitive(replace(RUN, status=RunStatus.EVENT_LIMIT), RUN) is None
    assert is_sensitive(replace(RUN, max_ratio=0.0), replace(RUN, max_ratio=0.0)) is False


def test_any_sensitive_is_true_over_not_known_over_false() -> None:
    assert any_sensitive([False, None, True]) is True
    assert any_sensitive([False, None]) is None
    assert any_sensitive([False, False]) is False
    assert sensitive([RUN, RUN]) is None  # runs not checked: not known


def test_each_polarity_gets_its_check_and_a_robust_run_is_not_flagged() -> None:
    # A free block (R = 1.5 m, α = 0.15) under a 0.5 g Ricker pulse: large-amplitude rocking,
    # the case where rtol 1e-8 and 1e-11 agree to 1e-5 (spec/engine.md, self-convergence).
    rec = ricker(0.5, 0.5, dt=0.005)
    two_b, top = 2 * 1.5 * math.sin(0.15), 2 * 1.5 * math.cos(0.15)
    load = Load("floor", 2e3, 0.1, two_b - 0.1, top)  # off the mid-plane: both polarities run
    block = Block(R=1.5, alpha=0.15, mass=2000.0, e=0.9, loads=(load,))
    settings = SolverSettings()
    result = assess(block, rec.time, rec.accel, rec.dt, settings=settings)
    checked = check_tolerance(block, rec.time, rec.accel, rec.dt, settings, result)
    tight = assess(block, rec.time, rec.accel, rec.dt, settings=tight_settings(settings))
    assert [r.polarity for r in checked.runs] == [1, -1]
    # both integrated, rocking well past uplift (measured: max θ/α 0.38 and 0.34, 75 impacts)
    assert all(r.mirror_of is None and r.max_ratio > 0.3 for r in checked.runs)
    for run, again in zip(checked.runs, tight.runs, strict=True):
        check = run.tolerance
        assert check is not None
        assert (check.rtol, check.max_ratio, check.impacts) == (1e-11, again.max_ratio,
                                                                again.impacts)  # fmt: skip
        assert check.sensitive is False
        assert run.max_ratio == pytest.approx(check.max_ratio, rel=1e-5)
        assert replace(run, tolerance=None) == replace(
            next(r for r in result.runs if r.polarity == run.polarity), tolerance=None
        )  # the run itself is unchanged
    assert sensitive(checked.runs) is False


def test_a_mirror_symmetric_block_checks_its_mirrored_run_too() -> None:
    rec = ricker(0.5, 0.5, dt=0.005)
    block = Block(R=1.5, alpha=0.15, e=0.9)
    result = assess(block, rec.time, rec.accel, rec.dt)
    checked = check_tolerance(block, rec.time, rec.accel, rec.dt, SolverSettings(), result)
    first, mirror = checked.runs
    assert mirror.mirror_of == 1
    assert first.tolerance is not None and mirror.tolerance == first.tolerance


def test_tolerances_at_the_floor_are_not_checked_again() -> None:
    settings = SolverSettings(rtol=TIGHTEST, atol=TIGHTEST)
    time = np.arange(0.0, 1.0, 0.01)
    result = Assessment(runs=(RUN, replace(RUN, polarity=1)))
    block = Block(R=1.5, alpha=0.15, e=0.9)
    assert check_tolerance(block, time, 0 * time, 0.01, settings, result) is result
