"""Which force each restrainer gave the kinematic check, verified against its strength.

A restrainer enters the check as its ``code_action`` says (:mod:`rockcli.codecheck.kinematic`):
a constant force, its design strength (Circolare 617/2009 §C8A.4.1; Circolare 7/2019
§C8.7.1.1), or a spring P0 + K·u capped at its strength. Either way the check relies on a
force the member must carry: its design tension resistance N_t,Rd (NTC 2018 §4.2.4.1.2) is
the limit (docs/interpretations.md, "Restrainers in the kinematic check").

Pure and silent: only :mod:`math` and the code-check package.
"""

from __future__ import annotations

import math

from rockcli.codecheck.kinematic import (
    FORCE,
    Capacity,
    code_stiffness,
    force_at,
    loss_rotation,
    rotation_at,
)
from rockcli.codecheck.result import Check, Method, RestrainerAction
from rockcli.mechanics import Restrainer
from rockcli.notes import Note

#: The clause of the members' strength.
STRENGTH_CLAUSE = "NTC 2018 §4.2.4.1.2"
#: What ``demand_at`` says of a force.
CONSTANT = "constant force"
#: What ``demand_at`` says of a member that does not work on the side checked.
NOT_ACTING = "does not act on the side checked"


def nonlinear_displacement_demand(checks: tuple[Check, ...] | list[Check]) -> float | None:
    """The governing displacement demand d* [m] of the 2009 non-linear ULS checks: the largest
    of the ground and height demands (Circolare 617/2009 §C8A.4.2.3); None when not computed."""
    demands = [
        c.demand
        for c in checks
        if c.method is Method.NONLINEAR and c.unit == "m" and c.demand is not None
    ]
    return max(demands) if demands else None


def demand_rotation(cap: Capacity, d_star: float) -> float:
    """The rotation θ [rad] at which the mechanism reaches the spectral displacement d* [m]."""
    return rotation_at(cap.mech, d_star / cap.factor)


def restrainer_action(
    sp: Restrainer, cap: Capacity, theta: float | None, at: str, index: int | None = None
) -> RestrainerAction:
    """The action of one restrainer and its verification at rotation θ [rad] (``at`` says which;
    θ None: the check reaches no displacement, a spring's demand is not evaluated).

    force: what it gives α0 (θ = 0). demand: a force's code_force; a spring's force at θ
    (capped at its strength; intact: ``lost`` says if it broke before θ). ``index``: its place
    among the mechanism's restrainers (None: its r, φ about the block's pivot).
    """
    s = cap.mech.side
    place = None if index is None else cap.mech.placement(index)
    strength = sp.strength if math.isfinite(sp.strength) else None
    acts = code_stiffness(sp, s) > 0.0
    force = force_at(sp, s, 0.0, place)
    theta_lost = loss_rotation(sp, s, place) if acts else math.inf
    demand: float | None
    if sp.code_action == FORCE:
        demand = sp.code_force
    else:
        demand = None if theta is None else force_at(sp, s, theta, place)
    lost = acts and theta is not None and theta > theta_lost
    use = None if strength is None or demand is None else demand / strength
    passed = False if lost else (None if use is None or not acts else use <= 1.0)
    return RestrainerAction(
        name=sp.name,
        code_action=sp.code_action,
        force=force,
        strength=strength,
        demand=demand if acts else 0.0,
        demand_at=(CONSTANT if sp.code_action == FORCE else at) if acts else NOT_ACTING,
        utilisation=use if acts else None,
        lost=lost,
        passed=passed,
        clause=member_clause(sp),
        lost_at_d_star=lost_at(cap, theta_lost),
        slack=sp.slack_side == s,
    )


def lost_at(cap: Capacity, theta: float) -> float | None:
    """The spectral displacement d* [m] at which a member lost at rotation θ is lost (None:
    never within the mechanism's range)."""
    if not math.isfinite(theta) or theta >= cap.mech.view.limit:
        return None
    return cap.d_star_at(theta)


#: The basis of the check of a member known only by its failure elongation (the paper's vault).
DISPLACEMENT_BASIS = Note(
    "basis_elongation", "its failure elongation fails_at (the paper's §4.2, Eq. 9–10)"
)
#: The basis of a member's given strength (yield forces, anchor capacity), not a steel's.
GIVEN_BASIS = Note(
    "basis_given", "its strength as given in the model (yield_pos/yield_neg, anchor_capacity)"
)
#: A member with neither a strength nor a failure elongation: nothing to verify it against.
NO_BASIS = Note("basis_none", "no strength and no failure elongation in the model: not verified")


def member_clause(sp: Restrainer) -> str:
    """What a member's check rests on: the steel clause for a tie-rod of known steel (its
    strength rule names it), the model's own values for any other member."""
    if sp.strength_rule.endswith(f"({STRENGTH_CLAUSE})"):
        return STRENGTH_CLAUSE
    if math.isfinite(sp.strength):
        return GIVEN_BASIS
    return DISPLACEMENT_BASIS if sp.can_fail else NO_BASIS


def restrainer_actions(
    cap: Capacity, d_star: float | None, at: str
) -> tuple[RestrainerAction, ...]:
    """Every restrainer's action, the springs read at the spectral displacement d* [m] (None:
    no displacement to read them at)."""
    theta = None if d_star is None else demand_rotation(cap, d_star)
    return tuple(
        restrainer_action(sp, cap, theta, at, i) for i, sp in enumerate(cap.mech.restrainers)
    )
