"""Whether an element slides on its base before it rocks (``[base] mu``).

A rigid body on a joint of friction coefficient μ starts to slide when the horizontal force
on it exceeds μ times the force pressing it on the joint, and to rock when the horizontal
load multiplier reaches the one that lifts it. With the weights W_i that bear on the joint
(the normal force N = Σ W_i), the masses that move (Σ P_j, shaken by α·P_j) and the thrusts
pushing it towards the side it opens to (Σ F), it slides at

    α_s = (μ·N + F_t − Σ F) / Σ P_j

(a lone block: α_s = μ), F_t the toothed return walls' friction (Circolare 7/2019 Eq.
C8.7.1.2: the same courses hold the wall from sliding out as from turning out). Where α_s
is below the multiplier that lifts it on a side it can open to, it slides first, and a
rocking verdict does not describe what it does (Shenton 1996,
J. Eng. Mech. 122(7):690–693: a rigid block on a shaken base slides first where μ < tan α,
its width over its height). Checked for the mechanisms that turn about the element's base
(a block file's block, the overturning of the whole wall, the wedge); the restrainers' hold
on sliding is not counted (on the safe side: it may say "slides" where a tie would hold
it).

Pure: the catalogue's mechanisms and their placements.
"""

from __future__ import annotations

from collections.abc import Callable

from rockcli.mechanisms.wall import MechanismType
from rockcli.model.catalogue import Mechanism
from rockcli.notes import Note

#: The mechanisms whose base is the element's base joint (hinge at 0).
AT_THE_BASE = (MechanismType.OVERTURNING, MechanismType.WEDGE)

#: What the output says of a mechanism that slides first.
SLIDES_FIRST = (
    "'{name}' slides first: its base joint's μ = {mu:g} holds it only up to {slide:.4g} g, "
    "below the {lift:.4g} g that lifts it (θ {side} 0); the rocking verdict does not apply to "
    "an element that slides: check its sliding"
)


def sliding_multiplier(view, mu: float) -> float:
    """α_s = (μ·N − Σ F) / Σ P_j of a mechanism's placement on one side (module docstring)."""
    every = view.work_items()
    items = [it for it in every if it.kind in ("body", "load")]
    normal = sum(it.force for it in items if it.bears)
    moving = sum(it.force for it in items if it.moves)
    pushing = sum(it.opens * it.force for it in every if it.kind == "thrust")
    toothing = sum(it.force for it in every if it.kind == "friction")
    return (mu * normal + toothing - pushing) / moving


def at_the_base(mech: Mechanism) -> bool:
    """True for a mechanism turning about the element's base joint."""
    return mech.type in AT_THE_BASE and mech.hinge_height == 0.0


def slides_first(
    mech: Mechanism, mu: float, lifts: Callable[[int], float]
) -> tuple[int, float, float] | None:
    """(side, α_s, the multiplier that lifts it) of the first side it can open to on which it
    slides before it lifts (``lifts(side)``: the code check's α0, or the engines' uplift
    acceleration in g), the lowest α_s first; None: it lifts first on every side."""
    if not at_the_base(mech):
        return None
    found = []
    for side in mech.sides:
        slide, lift = sliding_multiplier(mech.view(side), mu), lifts(side)
        if slide < lift:
            found.append((slide, -side, lift))
    if not found:
        return None
    slide, side, lift = min(found)  # the lowest α_s; θ > 0 first on a tie
    side = -side
    return side, slide, lift


def sliding_note(mech: Mechanism, lifts: Callable[[int], float]) -> tuple[Note, ...]:
    """The note of a mechanism that slides first on the model's ``[base] mu`` (none without
    a ``[base]`` table, or where it lifts first)."""
    base = mech.model.base
    if base is None:
        return ()
    found = slides_first(mech, base.mu, lifts)
    if found is None:
        return ()
    side, slide, lift = found
    return (Note("slides_first", SLIDES_FIRST, name=mech.name, mu=base.mu, slide=slide,
                 lift=lift, side=">" if side > 0 else "<"),)  # fmt: skip


def uplift_of(mech: Mechanism) -> Callable[[int], float]:
    """The engines' uplift acceleration of each side [g]."""
    return lambda side: mech.openings[0 if side > 0 else 1].uplift


def alpha0_of(mech: Mechanism) -> Callable[[int], float]:
    """The code check's α0 of each side."""
    return lambda side: mech.openings[0 if side > 0 else 1].alpha0
