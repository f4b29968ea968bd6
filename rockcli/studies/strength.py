"""Restrainers against their strength: the time history's largest force, as data.

The restrainer is elastic in the time history (its law with yielding is not modelled yet);
this says where its force passes the member's strength (rockcli.model.derive.member_strength).
"""

from __future__ import annotations

import math
from typing import Any

from rockcli.dynamics.result import Assessment
from rockcli.mechanics import Block


def restrainer_checks(block: Block, result: Assessment) -> list[dict[str, Any]]:
    """Each restrainer with a strength: the largest force of the time history (over both
    polarities) against it, the utilisation and pass/fail (NTC 2018 §4.2.4.1.2 for a steel
    member; its anchor's capacity otherwise).

    The restrainer is elastic in the time history: a utilisation above 1 means the member
    would have yielded or its anchorage given way, and the run beyond that is not valid.
    """
    rows = []
    for j, sp in enumerate(block.restrainers):
        if not math.isfinite(sp.strength):
            continue
        demand = max(run.restrainers[j].max_force for run in result.runs)
        utilisation = demand / sp.strength
        rows.append(
            {
                "name": sp.name,
                "demand": demand,
                "strength": sp.strength,
                "utilisation": utilisation,
                "passed": bool(utilisation <= 1.0),
                "rule": sp.strength_rule,
            }
        )
    return rows
