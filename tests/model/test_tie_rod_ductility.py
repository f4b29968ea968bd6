"""A tie-rod's elongation at break: given, or its grade's default, in the time history.

A tie-rod of a standard grade whose model gives neither ``fails_at`` nor
``elongation_at_break`` breaks in the time history when its whole elongation reaches
ε_u·L, ε_u the grade's minimum elongation after fracture of EN 10025-2 Table 7
(rockcli.codecheck.steel.ELONGATION_AT_BREAK); a bar of measured f_y, f_u has no grade and no
default; the code check relies on the model's own ``fails_at``/``elongation_at_break`` only
(docs/interpretations.md, "Restrainer laws").
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rockcli.codecheck.steel import ELONGATION_AT_BREAK, elongation_at_break
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import assess, simulate
from rockcli.mechanics import tie_rod_stiffness
from rockcli.model.derive import to_block
from rockcli.model.load import load_model
from tests.model.test_steel_restrainers import FACADE, PULSE, model_with

#: The event location's accuracy on a level of θ at rtol = atol = 1e-12: 1e-9 relative.
EVENT_RTOL = 1e-9
TIGHT = SolverSettings(rtol=1e-12, atol=1e-12, tail=0.0)


def test_the_grades_default_is_the_product_standards_elongation_after_fracture() -> None:
    """EN 10025-2 Table 7, longitudinal, 3 to 40 mm: A = 26 %, 23 %, 22 %."""
    assert ELONGATION_AT_BREAK == {"S235": 0.26, "S275": 0.23, "S355": 0.22}
    assert elongation_at_break("S355") == 0.22


@pytest.mark.parametrize("grade", ["S235", "S275", "S355"])
def test_a_graded_rod_without_an_elongation_at_break_gets_its_grades(
    tmp_path: Path, grade: str
) -> None:
    """breaks_at = ε_u·L − P0/K (the bar's whole elongation, the pretension's stretch
    included; K = E·π·d²/4/L), for the time history only: fails_at, which the code check
    reads, stays unset."""
    path = model_with(tmp_path, grade=grade, pretension=10e3)
    (rod,) = to_block(load_model(path)).restrainers
    k = tie_rod_stiffness(0.020, 3.0, 210e9)
    assert rod.breaks_at == pytest.approx(ELONGATION_AT_BREAK[grade] * 3.0 - 10e3 / k, rel=1e-15)
    assert math.isinf(rod.fails_at) and rod.lost_at == rod.breaks_at


@pytest.mark.parametrize(
    "rod",
    [
        {"elongation_at_break": 0.05},  # given: both analyses rely on it
        {"fails_at": 0.2},
        {"grade": None, "fy": 240e6, "fu": 380e6},  # measured: no grade, no default
    ],
    ids=["given", "fails_at", "measured"],
)
def test_no_default_where_the_model_says_or_has_no_grade(tmp_path: Path, rod: dict) -> None:
    (member,) = to_block(load_model(model_with(tmp_path, **rod))).restrainers
    assert math.isinf(member.breaks_at)
    given = {"elongation_at_break": 0.05 * 3.0, "fails_at": 0.2}
    key = next(iter(rod))
    assert member.fails_at == given.get(key, math.inf) == member.lost_at


def test_a_graded_rod_stretched_past_its_default_breaks(tmp_path: Path) -> None:
    """An S275 rod Ø20, 0.30 m long, at the top of the 80 kN wall, kicked with θ̇0 = 1 rad/s
    (12.5 kJ, twice what yielding the rod to 69 mm absorbs): it yields at N_pl,Rd and breaks
    where its elongation reaches 0.23·0.30 = 69 mm (the grade's default; the event's level,
    1e-9). It broke on its plateau, so its plastic elongation is 0.069 − N_pl,Rd/K (the law's
    closed form). Before the default, the rod had no elongation at break and never broke."""
    block = to_block(load_model(model_with(tmp_path, length=0.30)))
    (rod,) = block.restrainers
    time = np.arange(0.0, 1.0, 0.01)
    run = simulate(block, time, np.zeros(time.size), 0.01, settings=TIGHT, omega0=1.0)
    peak = run.restrainers[0]
    assert peak.yielded and peak.ruptured
    u_break = 0.23 * 0.30
    assert peak.max_displacement == pytest.approx(u_break, rel=EVENT_RTOL)
    n_pl = math.pi * 0.01**2 * 275e6 / 1.05
    assert peak.plastic_elongation == pytest.approx(u_break - n_pl / rod.k_pos, rel=EVENT_RTOL)


def test_the_facades_rod_is_far_from_its_default_under_the_ricker_pulse() -> None:
    """examples/facade.toml: the Ø20 S275 rod, 3 m long, breaks by default at 0.23·3 = 0.69 m;
    the Ricker pulse stretches it by about 0.11 m (its plastic elongation ≈ 106 mm), so it does
    not break, in either polarity."""
    block = to_block(load_model(FACADE))
    rod = next(r for r in block.restrainers if r.name == "tie-rod")
    assert rod.breaks_at == pytest.approx(0.69, rel=1e-15)
    data = np.loadtxt(PULSE, comments="#")
    time, accel = data[:, 0], data[:, 1]
    result = assess(block, time, accel, float(time[1] - time[0]))
    j = block.restrainers.index(rod)
    for run in result.runs:
        peak = run.restrainers[j]
        assert not peak.ruptured and peak.max_displacement < 0.2 * rod.breaks_at
    assert max(r.restrainers[j].plastic_elongation for r in result.runs) > 0.1
