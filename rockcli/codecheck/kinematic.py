"""The kinematic analysis of the rocking mechanism: α0, M*, e*, a0*, the capacity curve, d0*.

Circolare 617/2009 §C8A.4 and Circolare 7/2019 §C8.7.1.1–C8.7.1.5 (the same formulas in both
editions; spec/ntc.md, "Common"). The block turns about its base edge on side s; weights P_i
at points (x_i, z_i) from the pivot (x into the block, z up) have virtual displacements
δx_i = z_i·δθ (horizontal) and δy_i = x_i·δθ (up). The moments of the weights, loads and
thrusts (:func:`rockcli.mechanics.point_moments`) and of the restrainers are the very functions
the rocking engine integrates, so α0 of each side equals the engine's uplift acceleration of
that side by construction when no restrainer enters as a force. A restrainer enters as its
``code_action`` says: a constant stabilising force (a tie-rod's design strength) or a spring
with its pretension, capped at its strength; either until it is lost.

Pure and silent: only :mod:`math` and :mod:`rockcli.mechanics`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from rockcli.mechanics import (
    Block,
    Restrainer,
    point_moments,
    point_table,
    spring_elongation,
    spring_failure_rotation,
)

#: Rotation searched for the zero of the capacity curve [rad]: beyond π/2 the block is flat.
THETA_MAX = math.pi / 2
#: Points used to bracket sign changes of α(θ) before bisection.
BRACKET_POINTS = 400
#: Bisection iterations (θ resolved to π/2·2⁻⁶⁰, far below any printed digit).
BISECTION_STEPS = 60
#: Share of the capacity a restrainer failure must remove to end the mechanism in the 2019
#: rules (Circolare 7/2019 §C8.7.1.2.1: "riduzione della capacità superiore al 50%").
FAILURE_DROP = 0.5
#: Rotation at which the capacity curve is cut when α never vanishes [rad].
CURVE_END = math.pi / 4


@dataclass(frozen=True)
class Mechanism:
    """The block turning about one base edge, with its loads and thrusts (``block.loads``,
    ``block.thrusts``: the model's physical description, shared with the rocking analysis).

    Attributes:
        block: the rigid block, its restrainers, loads and thrusts (mass required).
        side: the side it overturns to (+1: θ > 0, pivot O; −1: θ < 0, pivot O′).
        distributed: True when the block's mass is spread over its height for M* and e*
            (e* = 0.75 for a lone rectangle), False when lumped at the centroid (e* = 1).
    """

    block: Block
    side: int = 1
    distributed: bool = False

    @cached_property
    def points(self) -> tuple[float, ...]:
        """The block, its loads and thrusts as the point table (mechanics.point_table)."""
        return point_table(self.block)

    @property
    def moving(self) -> tuple[tuple[float, float], ...]:
        """(P, z) of the weights whose masses move with the block: the block's own at h, then
        every load that moves (the Circolare's P_i and P_j; a load that only bears is carried
        horizontally by something else and has no horizontal inertia here)."""
        own = (self.block.weight, self.block.h)
        return (own, *((ld.weight, ld.z) for ld in self.block.loads if ld.moves))


def alpha0(mech: Mechanism) -> float:
    """Load multiplier at activation α0 = (Σ_bearing P_i x_i − s·Σ d_h F_h z_h) / Σ_moving P_i z_i.

    Circolare 617/2009 Eq. C8A.4.1 (virtual work α0 ΣP δx − ΣP δy − ΣF_h δ_h = 0 with
    δx = z δθ, δy = x δθ; internal work zero); Circolare 7/2019 §C8.7.1.1 (weights that do not
    bear on the block only in the denominator). A thrust pushing towards the side checked does
    positive work (it lowers α0), one pushing back restores. The block alone: tan α.
    A restrainer taken as a force (code_action "force": a tie-rod's design strength T at
    height h_T) or a pretensioned spring (P0) does the work T·h_T = T·r·cos φ: the lone block
    gives α0 = (W b + T h_T)/(W h_G) (Circolare 617/2009 §C8A.4.1; Circolare 7/2019
    §C8.7.1.2); a spring without pretension does no work at θ = 0 (spec/ntc.md). It is
    :func:`load_multiplier` at θ = 0; without forces, the rocking engine's uplift acceleration.
    """
    return load_multiplier(mech, 0.0)


def activation_terms(mech: Mechanism) -> dict[str, float]:
    """The virtual work of activation per unit virtual rotation, term by term [N·m].

    Circolare 617/2009 Eq. C8A.4.1 (Circolare 7/2019 §C8.7.1.1) at θ = 0, as
    :func:`load_multiplier` sums it: ``stabilising`` = Σ_bearing P_i x_i (the weights' work
    against the rotation), ``thrusts`` = s·Σ F_h z_h (thrusts towards the side checked do
    positive work), ``restrainers`` = Σ_k M_k(0) (tie-rod forces and pretensions),
    ``overturning`` = Σ_moving P_i z_i (the horizontal forces' work per unit α), and
    α0 = (stabilising − thrusts + restrainers) / overturning, which is :func:`alpha0`.
    """
    g, h, t, _, _ = point_moments(mech.points, mech.side, 0.0, 1.0)
    restrainers = _spring_moments(mech, 0.0, False, False)
    return {
        "stabilising": g,
        "thrusts": mech.side * t,
        "restrainers": restrainers,
        "overturning": h,
        "alpha0": (g - mech.side * t + restrainers) / h,
    }


def _moments(mech: Mechanism) -> tuple[float, float]:
    """(Σ P δx, Σ P δx²) per unit virtual rotation [N·m, N·m²], the block lumped or spread.

    Spread over the height 2h: Σ P δx = W h, Σ P δx² = W (2h)²/3 (integrals of z and z²).
    """
    b = mech.block
    own_1, own_2 = (
        (b.weight * b.h, b.weight * 4.0 * b.h**2 / 3.0)
        if mech.distributed
        else (
            b.weight * b.h,
            b.weight * b.h**2,
        )
    )
    loads = mech.moving[1:]
    first = own_1 + sum(w * z for w, z in loads)
    second = own_2 + sum(w * z**2 for w, z in loads)
    return first, second


def participating_mass(mech: Mechanism) -> float:
    """M* = (Σ P_i δx,i)² / (g Σ P_i δx,i²) [kg].

    Circolare 617/2009 Eq. C8A.4.2; Circolare 7/2019 Eq. C8.7.1.2.
    """
    first, second = _moments(mech)
    return first**2 / (mech.block.g * second)


def e_star(mech: Mechanism) -> float:
    """Participating mass fraction e* = g M* / Σ P_i [-], over the weights that move.

    Circolare 617/2009 Eq. C8A.4.3; Circolare 7/2019 Eq. C8.7.1.3. Block alone: 1 lumped,
    0.75 spread over the height (spec/ntc.md).
    """
    total = sum(w for w, _ in mech.moving)
    return mech.block.g * participating_mass(mech) / total


def a0_star(alpha_0: float, e_s: float, FC: float, g: float) -> float:
    """Spectral acceleration of activation a0* = α0 g / (e* FC) [m/s²].

    Circolare 617/2009 Eq. C8A.4.4; Circolare 7/2019 Eq. C8.7.1.4.
    """
    return alpha_0 * g / (e_s * FC)


def displacement_factor(mech: Mechanism) -> float:
    """d*/d_k = Σ P δx² / (δx_k Σ P δx), control point the block's centroid (δx_k = h) [-].

    Circolare 617/2009 Eq. C8A.4.5; Circolare 7/2019 Eq. C8.7.1.5.
    """
    first, second = _moments(mech)
    return second / (mech.block.h * first)


def control_displacement(mech: Mechanism, theta: float) -> float:
    """Horizontal displacement of the centroid d_k = R[sin α − sin(α − θ)] [m] (spec/ntc.md)."""
    b = mech.block
    return b.R * (math.sin(b.alpha) - math.sin(b.alpha - theta))


def rotation_at(mech: Mechanism, d_k: float) -> float:
    """The rotation θ at which the centroid has moved d_k [m] (inverse of control_displacement)."""
    b = mech.block
    return b.alpha - math.asin(max(-1.0, min(1.0, math.sin(b.alpha) - d_k / b.R)))


#: The code_action of a restrainer taken as a constant force (mechanics.Restrainer; the
#: other, "spring", is its stiffness).
FORCE = "force"


def force_at(sp: Restrainer, s: int, theta: float) -> float:
    """Horizontal force of restrainer ``sp`` in the check at rotation θ on side s, intact [N].

    code_action "force": its code_force F, constant from θ = 0 (Circolare 617/2009 §C8A.4.1 and
    Circolare 7/2019 §C8.7.1.1: a tie-rod is an external force in the virtual work of α0).
    "spring": P0 + K·u(θ) (pretension plus the spring, mechanics.spring_elongation), capped at
    :func:`force_cap`. 0 on a side where the member does not work (K = 0).
    """
    k, r, phi = sp.side(s)
    if k == 0.0:
        return 0.0
    if sp.code_action == FORCE:
        return sp.code_force
    return min(sp.pretension + k * spring_elongation(r, phi, theta), force_cap(sp, s))


def force_cap(sp: Restrainer, s: int) -> float:
    """The most a spring can give the check on side s: min(strength, yield force) [N] (inf: none).

    NTC 2018 §4.2.4.1.2: the check relies on the member's design tension resistance, not on
    the elastic force of an ever-growing elongation (docs/interpretations.md).
    """
    return min(sp.strength, sp.yield_force(s))


def loss_elongation(sp: Restrainer, s: int) -> float:
    """Elongation from rest at which the member is lost in the check on side s [m] (inf: never).

    Its ``fails_at``; for a spring also the elongation at which its elastic force P0 + K·u
    reaches the anchor's ``rupture_force`` before it yields (the anchor gives way). A force
    is constant, at most the anchor's capacity: only ``fails_at`` ends it.
    """
    k = sp.side(s)[0]
    if sp.code_action == FORCE or k == 0.0 or sp.rupture_force > sp.yield_force(s):
        return sp.fails_at
    return min(sp.fails_at, max(0.0, (sp.rupture_force - sp.pretension) / k))


def loss_rotation(sp: Restrainer, s: int) -> float:
    """Rotation at which the member is lost on side s [rad] (inf: never)."""
    _, r, phi = sp.side(s)
    return spring_failure_rotation(r, phi, loss_elongation(sp, s))


def can_be_lost(sp: Restrainer, s: int) -> bool:
    """True when the member can be lost on side s (it is left out of the sure curve)."""
    return math.isfinite(loss_elongation(sp, s))


def restrainer_moment(sp: Restrainer, s: int, theta: float) -> float:
    """Restoring moment F·r·cos(φ − θ) of the member's force about the pivot of side s [N·m].

    The arm of mechanics.spring_moment (a horizontal force at the attachment point).
    """
    _, r, phi = sp.side(s)
    return force_at(sp, s, theta) * r * math.cos(phi - theta)


def _spring_moments(mech: Mechanism, theta: float, sure_only: bool, intact: bool) -> float:
    """Σ restrainer moments at rotation θ on the mechanism's side [N·m].

    sure_only: leave out every restrainer that can be lost (spec/ntc.md: d0* on actions sure
    to last until collapse). intact: ignore losses (the curve just before one).
    """
    total = 0.0
    for sp in mech.block.restrainers:
        lost = can_be_lost(sp, mech.side)
        if sure_only and lost:
            continue
        if lost and not intact and theta > loss_rotation(sp, mech.side):
            continue
        total += restrainer_moment(sp, mech.side, theta)
    return total


def load_multiplier(
    mech: Mechanism, theta: float, *, sure_only: bool = False, intact: bool = False
) -> float:
    """α(θ): the horizontal load multiplier in equilibrium at rotation θ [-].

    α(θ) = [G(θ) − s·T(θ) + Σ_k M_k(θ)] / H(θ), with G = Σ_bearing P_i (x_i cos θ − z_i sin θ),
    H = Σ_moving P_i (z_i cos θ + x_i sin θ) and T the thrusts' moment
    (:func:`rockcli.mechanics.point_moments`, the engine's own function; spec/ntc.md, "Capacity
    curve"; equilibrium in the rotated position, Circolare 617/2009 §C8A.4.2.3). The block
    alone: tan(α − θ). M_k: :func:`restrainer_moment`, a force (code_action "force") or a
    capped spring (mechanics.spring_moment's elongation and arm, as in the engine).
    """
    g, h, t, _, _ = point_moments(mech.points, mech.side, math.sin(theta), math.cos(theta))
    return (g - mech.side * t + _spring_moments(mech, theta, sure_only, intact)) / h


def _bisect(f, lo: float, hi: float) -> float:
    """Root of f in [lo, hi] given f(lo) > 0 ≥ f(hi)."""
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def zero_rotation(mech: Mechanism) -> float | None:
    """θ0 where the sure capacity curve first reaches α = 0, or None (positive stiffness).

    The sure curve leaves out restrainers that can fail (spec/ntc.md, d0*).
    """

    def f(t: float) -> float:
        return load_multiplier(mech, t, sure_only=True)

    prev = 0.0
    for k in range(1, BRACKET_POINTS + 1):
        t = THETA_MAX * k / BRACKET_POINTS
        if f(t) <= 0.0:
            return _bisect(f, prev, t)
        prev = t
    return None


def failure_rotations(mech: Mechanism) -> list[tuple[str, float, float]]:
    """(name, θ_f, capacity drop) of each restrainer lost on the mechanism's side.

    The drop is the share of α lost with it: 1 − α_after/α_before at θ_f.
    """
    out = []
    for sp in mech.block.restrainers:
        theta_f = loss_rotation(sp, mech.side)
        if sp.side(mech.side)[0] == 0.0 or not math.isfinite(theta_f) or theta_f >= THETA_MAX:
            continue
        before = load_multiplier(mech, theta_f, intact=True)
        after = before - restrainer_moment(sp, mech.side, theta_f) / _overturning(mech, theta_f)
        out.append((sp.name, theta_f, 1.0 - after / before if before > 0 else 1.0))
    return out


def _overturning(mech: Mechanism, theta: float) -> float:
    return point_moments(mech.points, mech.side, math.sin(theta), math.cos(theta))[1]


@dataclass(frozen=True)
class Capacity:
    """The equivalent SDOF capacity of a mechanism (Circolare 617/2009 §C8A.4.2.3).

    Attributes:
        alpha0, e_star, FC, g: as in the Circolare. a0_star [m/s²].
        factor: d*/d_k. d0_star: d* where a* vanishes [m] (None: positive global stiffness).
        linear: True when the curve is the code's straight line a0*(1 − d*/d0*) (constant
            forces: no restrainers); False when it is the curve α(θ) itself.
    """

    mech: Mechanism
    alpha0: float
    e_star: float
    FC: float
    a0_star: float
    factor: float
    d0_star: float | None
    linear: bool

    def a_star(self, d_star: float) -> float:
        """Spectral acceleration a*(d*) on the capacity curve [m/s²] (Eq. C8A.4.4 on α(d))."""
        if self.linear and self.d0_star is not None:
            return self.a0_star * (1.0 - d_star / self.d0_star)
        theta = rotation_at(self.mech, d_star / self.factor)
        alpha = load_multiplier(self.mech, theta, sure_only=True)
        return alpha * self.mech.block.g / (self.e_star * self.FC)

    def d_star_at(self, theta: float) -> float:
        """Spectral displacement d* at rotation θ [m] (Eq. C8A.4.5)."""
        return control_displacement(self.mech, theta) * self.factor


def constant_forces_only(mech: Mechanism) -> bool:
    """True when the code's straight line holds: no restrainer on the sure curve and none
    giving a force at rest (a force or a pretension that can be lost would start the line at
    an a0* the sure curve does not have)."""
    s = mech.side
    return not any(
        sp.side(s)[0] and (not can_be_lost(sp, s) or force_at(sp, s, 0.0) > 0.0)
        for sp in mech.block.restrainers
    )


def capacity(mech: Mechanism, FC: float) -> Capacity:
    """α0, e*, a0*, d*/d_k and d0* of a mechanism, and which curve the code uses.

    The straight line a0*(1 − d*/d0*) is the Circolare's curve under constant forces
    (§C8A.4.2.3: "può essere assunta lineare"); with restrainers the curve α(θ) itself
    (spec/ntc.md). d0* is the zero of the sure curve (restrainers that can fail left out).
    """
    a_0 = alpha0(mech)
    e_s = e_star(mech)
    theta0 = zero_rotation(mech)
    factor = displacement_factor(mech)
    d0 = None if theta0 is None else control_displacement(mech, theta0) * factor
    linear = constant_forces_only(mech)
    return Capacity(
        mech=mech,
        alpha0=a_0,
        e_star=e_s,
        FC=FC,
        a0_star=a0_star(a_0, e_s, FC, mech.block.g),
        factor=factor,
        d0_star=d0,
        linear=linear,
    )


def curve_points(cap: Capacity, n: int = 11) -> list[dict[str, float]]:
    """The capacity curve as rows: θ, d_k, d*, α (all restrainers until failure), α sure, a*.

    Sampled uniformly in d* from 0 to d0* (or to the rotation at which α of the sure curve
    halves its growth limit, π/4, when there is no d0*).
    """
    mech = cap.mech
    d_end = cap.d0_star if cap.d0_star is not None else cap.d_star_at(CURVE_END)
    rows = []
    for k in range(n):
        d_star = d_end * k / (n - 1)
        theta = rotation_at(mech, d_star / cap.factor)
        rows.append(
            {
                "theta": theta,
                "d_k": d_star / cap.factor,
                "d_star": d_star,
                "alpha": load_multiplier(mech, theta),
                "alpha_sure": load_multiplier(mech, theta, sure_only=True),
                "a_star": cap.a_star(d_star),
            }
        )
    return rows
