"""Restrainers against their strength: the time history's largest force, as data.

The force demand is the largest over both polarities, against the member's design strength
(rockcli.model.derive.member_strength). An elastic-plastic member cannot pass its yield force
in the time history: its check fails when it yielded beyond the design strength (the design
strength has γ_M0, the yield force does not) or broke; the run stays valid. An elastic member
beyond its strength would have yielded or broken: the run beyond that is not valid.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from rockcli.codecheck.steel import CLAUSE
from rockcli.dynamics.result import Assessment
from rockcli.mechanics import Block


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
        rows.append(
            {
                "name": sp.name,
                "law": sp.law,
                "demand": demand,
                "strength": sp.strength,
                "utilisation": utilisation,
                "passed": bool(utilisation <= 1.0 and not ruptured),
                "rule": sp.strength_rule,
                "clause": CLAUSE if sp.strength_rule.endswith(f"({CLAUSE})") else None,
                "yielded": any(p.yielded for p in peaks),
                "t_yield": first_time(p.t_yield for p in peaks),
                "ruptured": ruptured,
                "t_rupture": first_time(p.t_fail for p in peaks),
                "time_history_valid": bool(sp.law != "elastic" or utilisation <= 1.0),
            }
        )
    return rows


def first_time(times: Iterable[float | None]) -> float | None:
    """The earliest of the times given, None when none is."""
    given = [t for t in times if t is not None]
    return min(given) if given else None
