"""Losing a restrainer in the time history: what is lost, and what it leaves behind.

docs/physics.md, "Restrainers with strength": one restrainer is one device (a bar, a vault),
acting through one member per pivot; when it breaks, or its anchor gives way, on either side,
the device is lost on both sides. A member that breaks on its yield plateau keeps the plastic
elongation of that plateau. Checked here against closed forms and the energy balance:

- a member broken on its plateau at u_break has c = u_break − F_y/K (the plateau's law), so its
  plastic elongation is u_break − F_y/K − c0 whatever yielded before, and the energy it
  dissipated is F_y·(plastic elongation) + ½F_y²/K (plastic work and the elastic energy let
  go) on a single excursion;
- a two-sided pretensioned restrainer lost on one side pulls on neither afterwards, and the
  energy of free rocking balances with both members' stored energy counted as released.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from rockcli.dynamics.settings import Engine
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Restrainer
from tests.dynamics.test_hysteresis import (
    ENERGY_RTOL,
    I0,
    TIGHT,
    K,
    block,
    free,
    potential,
    ricker,
    tie,
)

#: The yield force of the test tie [N]: yield at u = F_y/K = 10 mm.
F_YIELD = 20e3
#: The event location's accuracy on a level of θ at rtol = atol = 1e-12 (tests of
#: test_hysteresis.py use the same): 1e-9 relative.
EVENT_RTOL = 1e-9


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_a_break_on_the_plateau_keeps_the_plateau_in_the_plastic_elongation(engine) -> None:
    """1734 J of kinetic energy from rest (θ̇0 = 0.17 rad/s): the tie yields at 10 mm and breaks
    at fails_at = 40 mm on the same excursion, on its plateau (it takes 700 J to get there).

    Closed form of the elastic–perfectly plastic law: on the plateau c = u − F_y/K, so at the
    break c = 0.04 − 0.01 = 0.03 m, the plastic elongation; the energy dissipated is the
    plastic work F_y·0.03 = 600 J plus the elastic energy let go, ½F_y²/K = 100 J. (Before the
    fix the plastic elongation read 0: the plateau in progress was counted in the energy only.)
    """
    sp = tie(law="elastic-plastic", yield_pos=F_YIELD, yield_neg=F_YIELD, fails_at=0.04)
    run = free(block(sp), 0.0, 0.17, 3.0, engine)
    peak = run.restrainers[0]
    assert peak.yielded and peak.ruptured and peak.t_yield < peak.t_fail
    expected = 0.04 - F_YIELD / K
    assert peak.plastic_elongation == pytest.approx(expected, rel=EVENT_RTOL)
    invariant = F_YIELD * peak.plastic_elongation + 0.5 * F_YIELD**2 / K
    assert peak.energy_dissipated == pytest.approx(invariant, rel=EVENT_RTOL)


def test_a_break_after_earlier_yielding_keeps_the_last_plateau() -> None:
    """Under the Ricker pulse the tie yields at 0.78 s, unloads and goes slack (its force
    falls to 0), and breaks at 60 mm at 2.5 s, on a later plateau (it re-yields only past its
    previous peak, so a break beyond it is on a plateau): its plastic elongation is
    u_break − F_y/K = 0.05 m whatever the cycles before (closed form of the law: c = u − F_y/K
    on the plateau), to the event location's accuracy. Before the fix it read the first
    plateau's alone (the issue's 0.0322 m where the bar had reached 0.0357 m)."""
    time, accel, dt = ricker()
    sp = tie(law="elastic-plastic", yield_pos=F_YIELD, yield_neg=F_YIELD, fails_at=0.06)
    run = under_record(sp, time, accel, dt)
    peak = run.restrainers[0]
    assert peak.t_yield is not None and peak.t_fail is not None
    hist = run.history
    assert hist is not None
    between = (hist.time > peak.t_yield) & (hist.time < peak.t_fail)
    assert np.min(hist.forces[0, between]) == 0.0  # it unloaded in between
    assert peak.plastic_elongation == pytest.approx(0.06 - F_YIELD / K, rel=EVENT_RTOL)


def under_record(sp: Restrainer, time: np.ndarray, accel: np.ndarray, dt: float):
    """The test block with ``sp`` under the record, at the tight tolerances."""
    return simulate(block(sp), time, accel, dt, settings=TIGHT, history=True)


def both_sides(**law: float | str) -> Restrainer:
    """A restrainer at the top corner acting about both pivots (k_pos = k_neg = K)."""
    return replace(tie(**law), k_neg=K)


@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_a_restrainer_lost_on_one_side_is_lost_on_both(engine) -> None:
    """A two-sided elastic restrainer, pretensioned with P0 = 5 kN on each member, whose anchor
    gives way at 25 kN while the block rocks about O (θ > 0, from θ̇0 = 0.1 rad/s).

    Afterwards the block rocks about O′ too (θ < 0) and the restrainer pulls on neither side:
    every force of the history after the loss is 0. The energy balances (to ENERGY_RTOL, the
    balance of test_hysteresis.py) with both members' elastic energy at rest, ½P0²/K each,
    in the initial energy, and the loss releasing the member of O (½F²/K at 25 kN) and the
    member of O′ (its pretension's ½P0²/K, which it held while the block turned about O).
    """
    p0 = 5e3
    sp = both_sides(rupture_force=25e3, pretension=p0)
    run = free(block(sp, e=0.9), 0.0, 0.1, 6.0, engine)
    peak = run.restrainers[0]
    assert peak.ruptured and peak.t_fail is not None
    hist = run.history
    assert hist is not None
    after = hist.time > peak.t_fail
    assert np.any(hist.theta[after] < 0.0)  # it rocks about O′ after the loss
    assert np.all(hist.forces[0, after] == 0.0)
    initial = 0.5 * I0 * 0.1**2 + 2 * 0.5 * p0**2 / K
    th, om = float(hist.theta[-1]), float(hist.omega[-1])
    final = 0.5 * I0 * om**2 + potential(abs(th))
    released = 0.5 * 25e3**2 / K + 0.5 * p0**2 / K
    assert peak.energy_dissipated == pytest.approx(released, rel=EVENT_RTOL)
    balance = final + peak.energy_dissipated + run.impact_loss
    assert balance == pytest.approx(initial, rel=ENERGY_RTOL)
