"""Restrainers against their strength: the time history's largest force, as data.

The force demand is the largest over both polarities, against the member's design strength
(rockcli.model.derive.member_strength). An elastic-plastic tie-rod yields at its design
plastic resistance and breaks at its net section's or its anchor's (derive.member_law), so its
force never exceeds its strength: the force check alone cannot fail once it yields. A steel
bar is therefore also verified for its ductility (its largest elongation against ε_u·L/γ_ε)
and its anchorage (capacity design: the anchor's capacity against γ_ov·A·f_y), codecheck.tie;
``passed`` is all of them. A member with only a failure elongation (``fails_at``, the paper's
vault) is verified on displacement: its largest elongation against fails_at (the paper's
§4.2, Eq. 9–10). An elastic member beyond its strength would have yielded or broken: the run
beyond that is not valid.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from rockcli.codecheck.restrainer_check import DISPLACEMENT_BASIS
from rockcli.codecheck.steel import CLAUSE
from rockcli.codecheck.tie import Verification, anchorage, ductility
from rockcli.dynamics.result import Assessment
from rockcli.mechanics import Restrainer, Rocker, linear_global_stiffness, restrainer_coefficient

#: A member on its yield plateau carries F_y exactly; on its elastic branch K·(u − c) can pass
#: F_y by the rounding of c (measured 3e-14 relative in tests/dynamics/test_hysteresis.py):
#: a utilisation within this of 1 is the strength itself.
FORCE_RTOL = 1e-9


def restrainer_checks(block: Rocker, result: Assessment) -> list[dict[str, Any]]:
    """Each restrainer with a strength or a failure elongation: the largest force of the time
    history (over both polarities) against its strength, its ductility and its anchorage
    (module docstring), whether it yielded or was lost (first time over the polarities), and
    whether the time history is valid for it. ``index`` is the restrainer's place in the
    model.
    """
    rows = []
    for j, sp in enumerate(block.restrainers):
        if not (math.isfinite(sp.strength) or sp.can_fail):
            continue
        peaks = [run.restrainers[j] for run in result.runs]
        rows.append({"index": j, **check_row(sp, peaks)})
    return rows


def check_row(sp: Restrainer, peaks: list[Any]) -> dict[str, Any]:
    """One restrainer's row of :func:`restrainer_checks`."""
    demand = max(p.max_force for p in peaks)
    has_strength = math.isfinite(sp.strength)
    utilisation = demand / sp.strength if has_strength else None
    ruptured = any(p.ruptured for p in peaks)
    within = utilisation is None or utilisation <= 1.0 + FORCE_RTOL
    duct = member_ductility(sp, max(p.max_displacement for p in peaks))
    anchor = anchorage(sp.overstrength, sp.anchor_capacity) if sp.overstrength > 0 else None
    verdicts = [within and not ruptured, duct.passed, None if anchor is None else anchor.passed]
    return {
        "name": sp.name,
        "law": sp.law,
        "demand": demand,
        "strength": sp.strength if has_strength else None,
        "utilisation": utilisation,
        "ductility": verification_document(duct),
        "anchor": None if anchor is None else verification_document(anchor),
        "passed": all(v is not False for v in verdicts),
        "rule": sp.strength_rule if has_strength else DISPLACEMENT_BASIS,
        "clause": CLAUSE if sp.strength_rule.endswith(f"({CLAUSE})") else None,
        "yielded": any(p.yielded for p in peaks),
        "t_yield": first_time(p.t_yield for p in peaks),
        "plastic_elongation": max(p.plastic_elongation for p in peaks),
        "ruptured": ruptured,
        "t_rupture": first_time(p.t_fail for p in peaks),
        "time_history_valid": bool(sp.law != "elastic" or within),
    }


def member_ductility(sp: Restrainer, max_displacement: float) -> Verification:
    """The member's largest elongation against what it can take: a steel bar's elongation from
    its unstressed length (the spring's peak plus the pretension's P0/K) against ε_u·L/γ_ε; a
    member with only a failure elongation, its peak against fails_at; else not verified."""
    k = max(sp.k_pos, sp.k_neg)
    if math.isfinite(sp.elongation_capacity):
        elongation = max_displacement + (sp.pretension / k if k > 0 else 0.0)
        return ductility(elongation, sp.elongation_capacity, sp.ductility_rule)
    if sp.can_fail and not math.isfinite(sp.strength):
        return ductility(max_displacement, sp.fails_at, DISPLACEMENT_BASIS)
    return ductility(max_displacement, math.inf, "")


def verification_document(v: Verification) -> dict[str, Any]:
    """A verification as data: demand, capacity (None: not known), passed (None: not
    verified), rule."""
    return {"demand": v.demand, "capacity": v.capacity, "passed": v.passed, "rule": v.rule}


def first_time(times: Iterable[float | None]) -> float | None:
    """The earliest of the times given, None when none is."""
    given = [t for t in times if t is not None]
    return min(given) if given else None


def restrainer_effectiveness(block: Rocker) -> list[dict[str, Any]]:
    """The paper's §4.3 quick check of every restrainer, per side.

    c_K = K r²/I0 against c_E = p² (c_K should exceed c_E by one or two orders of magnitude
    to matter), and the sign of the linearized global stiffness on that side with all
    restrainers acting (paper Eq. 16–18; mechanics.linear_global_stiffness).
    """
    if not block.restrainers or block.mass is None:
        return []
    rows = []
    sides = (
        ((block.free_side, "θ > 0" if block.free_side > 0 else "θ < 0"),)
        if block.one_sided
        else ((1, "θ > 0"), (-1, "θ < 0"))
    )
    for side, label in sides:
        stiff = linear_global_stiffness(block, side)
        for sp in block.restrainers:
            k, r, _ = sp.side(side)
            if sp.path:  # on a chain's upper block: the radius of a point with its arm at rest
                r = sp.arm_at_rest(side)
            c_k = restrainer_coefficient(k, r, block.inertia)
            rows.append(
                {
                    "name": sp.name,
                    "side": label,
                    "K": k,
                    "c_K": c_k,
                    "c_E": block.p2,
                    "ratio": c_k / block.p2,
                    "global_stiffness": "positive" if stiff > 0 else "negative",
                }
            )
    return rows
