"""Uplift = α0 on each side, for every mechanism of random walls (issue 35).

What the engines rock of a mechanism (``model.catalogue.Mechanism.rocker``) is built from the
very placement the code check reads (its ``views``), so the ground acceleration that starts
its motion from rest on each side it can open to is the check's α0 of that side
(Circolare 7/2019 §C8.7.1.1, Eq. C8.7.1.1's multiplier with the thrusts as external forces;
mechanics.uplift_accelerations). The walls are those of test_wall_fuzz (storeys, a gable,
return walls, f_m, loads, a thrust, every mechanism type) without restrainers: a tie that
enters the check as a force (its code_action) raises α0, not the uplift of the time history,
by design. The two are summed in another order (the centroid of the bodies against each body's
moment), so they agree to rounding, not to the bit.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings

from rockcli.codecheck.kinematic import alpha0
from rockcli.errors import InputError
from rockcli.mechanics import uplift_accelerations
from rockcli.model.catalogue import catalogue
from rockcli.model.load import read_toml, validate_model
from tests.property.test_wall_fuzz import walls

ROOT = Path(__file__).resolve().parents[2]
#: Relative agreement of the two sums (each a few dozen terms of similar size).
REL = 1e-12


def check_uplift_is_alpha0(data: dict[str, Any]) -> int:
    """Every mechanism of the model ``data`` (restrainers dropped) rocked: uplift = α0; the
    number of mechanisms checked."""
    data.pop("restrainers", None)
    try:
        mechanisms = catalogue(validate_model(data, file="w.toml"))
    except InputError:
        return 0  # a wall refused in one line: test_wall_fuzz's concern
    checked = 0
    for mech in mechanisms:
        try:
            rocker = mech.rocker
        except InputError:
            continue  # a mechanism the time history does not rock (said in one line)
        uplift = dict(zip((1, -1), uplift_accelerations(rocker), strict=True))
        for side in mech.sides:
            code = alpha0(mech.check(side, distributed=False, per_block=True))
            scale = max(abs(code), abs(uplift[side]), 1e-300)
            assert abs(uplift[side] - code) <= REL * scale, (mech.name, side, uplift, code)
        # The value's own record of each side says the same, computed the same way.
        for opening in mech.openings:
            assert opening.opens == (opening.side in mech.sides)
            assert opening.uplift == uplift[opening.side]
            if opening.opens:
                scale = max(abs(opening.alpha0), abs(opening.uplift), 1e-300)
                assert abs(opening.uplift - opening.alpha0) <= REL * scale, (mech.name, opening)
        checked += 1
    return checked


def test_uplift_is_alpha0_on_the_shipped_facade() -> None:
    # Every type: the whole wall, storey 2, the wedge, two flexures, the gable.
    data = read_toml(str(ROOT / "examples" / "two-storey-facade.toml"))
    assert check_uplift_is_alpha0(data) == 6


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(walls())
def test_uplift_is_alpha0_on_each_side(data: dict[str, Any]) -> None:
    check_uplift_is_alpha0(data)
