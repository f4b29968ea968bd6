"""The free tail after the record is bounded in memory: decimated past TAIL_SAMPLES samples.

Seen before the fix (issue 7, item 11): the tail was materialised at the record's dt, so 100
samples at dt = 1e-7 s with the default 10 s tail held 1e8 tail samples (times, ground
acceleration, slopes, θ and θ̇ histories: 2.6 GB); ``tail = 1e9`` asked for 745 GiB.
"""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from rockcli.dynamics import simulate as sim
from rockcli.dynamics.result import RunStatus
from rockcli.dynamics.settings import SolverSettings
from rockcli.mechanics import Block

ALPHA = 0.2
#: Free rocking released at θ0 = α/2 (no ground motion) with Housner-like e = 0.9: it rocks
#: for a few seconds in the tail, then rests (a real integration through the tail).
BLOCK = Block(R=1.0, alpha=ALPHA, e=0.9)
#: Peak traced memory allowed [bytes]: the decimated grid is 65 637 samples, ≈ 0.5 MB per
#: array and six arrays (times, accelerations, slopes, θ, θ̇, kept history) ≈ 3.2 MB; 32 MB
#: leaves room for numpy temporaries and is 80 times below what the record's dt would need.
MEMORY_BOUND = 32 * 2**20


@pytest.mark.parametrize("tail", [None, 3600.0])
def test_a_tiny_dt_record_runs_its_tail_in_bounded_memory(tail: float | None) -> None:
    dt = 1e-7
    time = np.arange(100) * dt
    settings = SolverSettings(tail=tail)
    sim.simulate(BLOCK, time[:2], np.zeros(2), dt, settings=SolverSettings(tail=0.0))  # load
    tracemalloc.start()
    try:
        run = sim.simulate(
            BLOCK, time, np.zeros(100), dt, settings=settings, history=True, theta0=ALPHA / 2
        )
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < MEMORY_BOUND
    assert run.status is RunStatus.COMPLETED and run.impacts > 0
    expected_end = time[-1] + settings.tail_for(BLOCK.p)
    assert run.history is not None
    assert run.history.time[-1] == pytest.approx(expected_end, rel=1e-9)
    assert run.history.time.size <= time.size + sim.TAIL_SAMPLES + 1


def test_a_decimated_tail_changes_only_where_the_history_is_kept(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The ground is at rest in the tail, so clipping steps at coarser samples changes nothing
    but the clip points: same impacts, peaks to the tolerance (1e-8: rtol of the run), same end.
    """
    dt = 0.01
    time = np.array([0.0, dt])
    full = sim.simulate(BLOCK, time, np.zeros(2), dt, history=True, theta0=ALPHA / 2)
    monkeypatch.setattr(sim, "TAIL_SAMPLES", 16)
    coarse = sim.simulate(BLOCK, time, np.zeros(2), dt, history=True, theta0=ALPHA / 2)
    assert full.history is not None and coarse.history is not None
    assert coarse.history.time.size == time.size + 17  # ramp sample + 16 intervals
    assert full.history.time.size > 1000  # 10 s at 0.01 s: not decimated
    assert coarse.impacts == full.impacts
    assert coarse.max_ratio == pytest.approx(full.max_ratio, rel=1e-8)
    assert coarse.t_end == full.t_end
    assert coarse.history.time[-1] == pytest.approx(full.history.time[-1], rel=1e-12)


def test_the_tail_keeps_the_record_interval_up_to_the_cap() -> None:
    """Typical records are not affected: a 20 s tail at 0.01 s is 2000 samples at dt."""
    times, acc = sim.extend_with_tail(np.arange(3) * 0.01, np.ones(3), 0.01, 20.0)
    assert np.allclose(np.diff(times), 0.01, rtol=1e-9, atol=0)
    assert times.size == 3 + 2000 and not acc[3:].any()
