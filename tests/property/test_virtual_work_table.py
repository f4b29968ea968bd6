"""α0 from its virtual-work table, item by item, for every mechanism of random walls (issue 36).

The report prints, for every mechanism, each body, load, thrust and restrainer with its
virtual displacement and its term of α0's numerator and denominator
(codecheck.kinematic.activation_work). Their sums must give α0 as the check computes it
(Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.1), on every side, with the restrainers too —
otherwise a reviewer recomputing α0 from the page would not find the check's number. Each
item's terms must also follow from its own columns: P·δy and P·δx of a weight (where it bears
and moves), −F·δx of a thrust pushing open (+ pushing shut), F·δx of a restrainer.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings

from rockcli.codecheck.kinematic import activation_terms, activation_work, alpha0
from rockcli.errors import InputError
from rockcli.model.catalogue import catalogue
from rockcli.model.load import read_toml, validate_model
from tests.property.test_wall_fuzz import walls

ROOT = Path(__file__).resolve().parents[2]
#: The table's sums against the check's (the same terms, summed in the same order but for
#: the restrainers' moments, which the check adds in one sum).
REL = 1e-12


def check_tables(data: dict[str, Any]) -> int:
    """Every side of every mechanism of the model ``data``: the table's sums are α0's
    numerator and denominator; the number of sides checked."""
    try:
        mechanisms = catalogue(validate_model(data, file="w.toml"))
    except InputError:
        return 0
    checked = 0
    for mech in mechanisms:
        for side in mech.sides:
            check = mech.check(side, distributed=False, per_block=True)
            table = activation_work(check)
            terms = activation_terms(check)
            up = sum(t.resisting for t in table)
            down = sum(t.overturning for t in table)
            numerator = terms["stabilising"] - terms["thrusts"] + terms["restrainers"]
            assert math.isclose(up, numerator, rel_tol=REL, abs_tol=1e-9), (mech.name, side)
            assert math.isclose(down, terms["overturning"], rel_tol=REL), (mech.name, side)
            a0 = alpha0(check)
            assert math.isclose(up / down, a0, rel_tol=REL, abs_tol=1e-15), (mech.name, side)
            for t in table:
                it = t.item
                if it.kind in ("body", "load"):
                    assert t.resisting in (0.0, it.force * it.dy)
                    assert t.overturning in (0.0, it.force * it.dx)
                else:  # a thrust or a restrainer: a horizontal force, F·δx
                    assert t.overturning == 0.0
                    assert math.isclose(abs(t.resisting), abs(it.force * it.dx), rel_tol=1e-12,
                                        abs_tol=1e-9)  # fmt: skip
            checked += 1
    return checked


def test_the_facades_tables_give_its_alpha0() -> None:
    # Every type and both sides, with the roof thrust and the tie-rod.
    data = read_toml(str(ROOT / "examples" / "two-storey-facade.toml"))
    assert check_tables(data) == 11


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(walls())
def test_the_tables_give_alpha0_on_each_side(data: dict[str, Any]) -> None:
    check_tables(data)
