"""A record timed from any origin runs as from zero: no tolerance scales with the absolute time.

Seen before the fix (issue 7, item 2): a two-column record with Unix-epoch times (t ≈ 1.7e9 s)
at 1 kHz was skipped by both engines, because the zero-gap test ``gap <= 1e-12·(|t| + 1)``
(1.7e-3 s at the epoch) swallowed every 1 ms step: "survives, 0.0". The readers re-zero time
on read; the engines must not depend on that.
"""

from __future__ import annotations

import numpy as np
import pytest

from rockcli.dynamics import layout as L
from rockcli.dynamics.kernel import integrate
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import (
    extend_with_tail,
    pack_parameters,
    pack_springs,
    simulate,
)
from rockcli.mechanics import Block

#: Unix time of a 2023 record [s]; its float64 spacing is 2.4e-7 s.
EPOCH = 1.7e9
DT = 1e-3
STEPS = np.arange(1000)
#: 0.25 g one-sine of 1 s > tan 0.2 = 0.203 g: the block rocks and survives (checked below).
ACCEL = 0.25 * np.sin(2 * np.pi * STEPS * DT)
BLOCK = Block(R=1.0, alpha=0.2, e=0.9)
#: The epoch times carry float64 rounding: 1.7e9 + k·1e-3 is off by up to 1.2e-7 s, i.e. the
#: sample intervals vary by ±1.2e-4 of dt. The response to such a record differs from the
#: exact one by that order, so results are compared to 1e-3 (relative); event times to 1e-6 s.
REL = 1e-3


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_epoch_times_give_the_result_of_times_from_zero(engine: Engine) -> None:
    zero = simulate(BLOCK, STEPS * DT, ACCEL, DT, engine=engine, history=True)
    epoch = simulate(BLOCK, EPOCH + STEPS * DT, ACCEL, DT, engine=engine, history=True)
    assert zero.impacts > 0 and not zero.overturned  # the case rocks and survives
    assert epoch.status is zero.status
    assert epoch.impacts == zero.impacts
    assert epoch.max_ratio == pytest.approx(zero.max_ratio, rel=REL)
    assert epoch.t_uplift == pytest.approx(EPOCH + zero.t_uplift, abs=1e-6)
    assert epoch.t_end == pytest.approx(EPOCH + zero.t_end, abs=1e-6)
    assert epoch.history is not None and zero.history is not None
    assert epoch.history.time[0] == EPOCH  # results are in the record's own times


def test_the_kernel_itself_steps_through_epoch_times() -> None:
    """The compiled kernel called directly on epoch times (no re-zeroing): it still rocks."""
    settings = SolverSettings()
    zero = simulate(BLOCK, STEPS * DT, ACCEL, DT, settings=settings)
    times, acc = extend_with_tail(EPOCH + STEPS * DT, ACCEL, DT, settings.tail_for(BLOCK.p))
    par = pack_parameters(BLOCK, settings, settings.rtol, settings.atol)
    out_f = np.zeros(L.N_FLOAT_OUT)
    out_i = np.zeros(L.N_INT_OUT, dtype=np.int64)
    springs = pack_springs(BLOCK)
    integrate(
        times,
        acc,
        1.0,
        par,
        springs,
        np.zeros(0),
        np.ones(0, dtype=np.int64),
        np.full(1, np.nan),
        np.full(1, np.nan),
        np.zeros((1, 0)),
        out_f,
        out_i,
        np.zeros((0, L.N_SPRING_OUT)),
    )
    assert L.STATUS_NAMES[int(out_i[L.I_STATUS])] == str(zero.status)
    assert out_i[L.I_IMPACTS] == zero.impacts
    assert out_f[L.O_MAX_A] / BLOCK.alpha == pytest.approx(zero.max_ratio, rel=REL)
