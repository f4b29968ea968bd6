"""The free tail (rockcli.dynamics.kernel, settings.free_tail): once the ground is at rest for
good (the tail after the record, and a record's own trailing zeros), the steps are chosen by
the error controller alone instead of ending at every sample; the history is interpolated at
the samples from each step's dense output.

Both ways integrate the same equation with the same tolerances, so they agree to the
integration error: measured on the pulses below at rtol = atol = 1e-8, max θ/α to ≤ 4e-8
relative and θ(t) at the samples to ≤ 6e-7 rad; the bounds 1e-6 and 1e-5 rad leave a margin
of about 20.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import free_from, simulate
from rockcli.mechanics import Block, Restrainer

DT = 0.005
RATIO_RTOL = 1e-6
HISTORY_ATOL = 1e-5  # rad
FREE, CLIPPED = SolverSettings(), SolverSettings(free_tail=False)


def pulse(amplitude: float, period: float, rest: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    t = np.arange(0.0, period + rest, DT)
    return t, np.where(t < period, amplitude * np.sin(2 * np.pi * t / period), 0.0)


def both(block: Block, t: np.ndarray, a: np.ndarray):
    free = simulate(block, t, a, DT, settings=FREE, history=True)
    clipped = simulate(block, t, a, DT, settings=CLIPPED, history=True)
    return free, clipped


def test_a_block_rocking_into_the_tail_takes_fewer_steps_and_agrees() -> None:
    # A large, slender block with e = 0.99 rocks for 25 s after a 1 s pulse.
    block = Block(R=10.0, alpha=0.1, e=0.99)
    free, clipped = both(block, *pulse(0.5, 1.0))
    assert free.steps < clipped.steps / 5
    assert free.impacts == clipped.impacts and free.status == clipped.status
    assert free.max_ratio == pytest.approx(clipped.max_ratio, rel=RATIO_RTOL)
    assert free.t_end == pytest.approx(clipped.t_end, rel=1e-9)
    assert np.allclose(free.history.theta, clipped.history.theta, rtol=0, atol=HISTORY_ATOL)
    assert np.allclose(free.history.time, clipped.history.time, rtol=0, atol=0)


@settings(max_examples=20, deadline=None)
@given(
    st.floats(1.0, 8.0),
    st.floats(0.08, 0.25),
    st.floats(0.85, 0.99),
    st.floats(1.2, 4.0),
    st.floats(0.3, 1.5),
    st.sampled_from([0.0, 1e3, 1e5]),
)
def test_free_and_clipped_tails_agree(R, alpha, e, scale, period, k) -> None:
    springs = (Restrainer("top", k, k, 2 * R, alpha, 2 * R, alpha),) if k else ()
    block = Block(R=R, alpha=alpha, e=e, mass=1e3 * R**2, restrainers=springs)
    free, clipped = both(block, *pulse(scale * np.tan(alpha), period))
    assert free.status == clipped.status
    assert free.max_ratio == pytest.approx(clipped.max_ratio, rel=RATIO_RTOL)
    n = min(free.history.theta.size, clipped.history.theta.size)
    assert np.allclose(free.history.theta[:n], clipped.history.theta[:n], rtol=0,
                       atol=HISTORY_ATOL)  # fmt: skip


def test_a_block_at_rest_before_the_tail_gives_the_same_run_bit_for_bit() -> None:
    # The ground keeps moving, below the uplift threshold, until long after the block is at
    # rest: nothing is integrated in the free part, and the two ways are one.
    block = Block(R=1.0, alpha=0.25, e=0.7)
    t, a = pulse(1.5 * np.tan(0.25), 0.5, rest=8.0)
    a = a + np.where(t >= 0.5, 0.01 * np.sin(2 * np.pi * t), 0.0)
    free, clipped = both(block, t, a)
    assert free.t_uplift is not None and free.impacts > 0
    assert free.steps == clipped.steps and free.max_ratio == clipped.max_ratio
    assert np.array_equal(free.history.theta, clipped.history.theta)


def test_free_from_is_one_past_the_last_motion() -> None:
    accel = np.array([0.0, 0.1, -0.2, 0.0, 0.3, 0.0, 0.0, 0.0])
    assert free_from(accel, accel.size) == 5  # the ramp 4 → 5 stays an ordinary segment
    assert free_from(accel, 3) == 3  # the record is the first three samples
    assert free_from(np.zeros(4), 4) == 0  # no motion: nothing free (0 means none)
