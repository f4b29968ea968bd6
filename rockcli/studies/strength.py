"""Restrainers against their strength: the time history's largest force, as data.

The force demand is the largest over both polarities, against the member's design strength
(rockcli.model.derive.member_strength). An elastic-plastic tie-rod yields at its design
plastic resistance and breaks at its net section's or its anchor's (derive.member_law), so its
force never exceeds its strength: its check fails only when it broke; whether it yielded, and
its plastic elongation, are reported beside. An elastic member beyond its strength would have
yielded or broken: the run beyond that is not valid.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from rockcli.codecheck.steel import CLAUSE
from rockcli.dynamics.result import Assessment
from rockcli.mechanics import Block

#: A member on its yield plateau carries F_y exactly; on its elastic branch K·(u − c) can pass
#: F_y by the rounding of c (measured 3e-14 relative in tests/dynamics/test_hysteresis.py):
#: a utilisation within this of 1 is the strength itself.
FORCE_RTOL = 1e-9


def restrainer_checks(block: Block, result: Assessment) -> list[dict[str, Any]]:
    """Each restrainer with a strength: the largest force of the time history (over both
    polarities) against it, the utilisation and pass/fail (NTC 2018 §4.2.4.1.2 for a steel
    member; its anchor's capacity otherwise), whether it yielded or was lost (first time over
    the polarities), and whether the time history is valid for it (module docstring).
    """
    rows = []
    for j, sp in enumerate(block.restrainers):
        if not math.isfinite(sp.strength):
            continue
        peaks = [run.restrainers[j] for run in result.runs]
        demand = max(p.max_force for p in peaks)
        utilisation = demand / sp.strength
        ruptured = any(p.ruptured for p in peaks)
        within = utilisation <= 1.0 + FORCE_RTOL
        rows.append(
            {
                "name": sp.name,
                "law": sp.law,
                "demand": demand,
                "strength": sp.strength,
                "utilisation": utilisation,
                "passed": bool(within and not ruptured),
                "rule": sp.strength_rule,
                "clause": CLAUSE if sp.strength_rule.endswith(f"({CLAUSE})") else None,
                "yielded": any(p.yielded for p in peaks),
                "t_yield": first_time(p.t_yield for p in peaks),
                "plastic_elongation": max(p.plastic_elongation for p in peaks),
                "ruptured": ruptured,
                "t_rupture": first_time(p.t_fail for p in peaks),
                "time_history_valid": bool(sp.law != "elastic" or within),
            }
        )
    return rows


def first_time(times: Iterable[float | None]) -> float | None:
    """The earliest of the times given, None when none is."""
    given = [t for t in times if t is not None]
    return min(given) if given else None
