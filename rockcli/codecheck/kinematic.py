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

Pure and silent: :mod:`math`, numpy (a chain's curve over a grid of rotations),
:mod:`rockcli.mechanics` and :mod:`rockcli.searches`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from rockcli.codecheck.free import branch_acceleration, branch_end
from rockcli.codecheck.result import WorkTerm
from rockcli.mechanics import Restrainer, WorkItem
from rockcli.mechanisms.block import BlockSide, Polar, polar_of
from rockcli.mechanisms.links import Angle
from rockcli.mechanisms.side import ChainPoint, ChainSide
from rockcli.searches import brent_root

#: Rotation searched for the zero of the capacity curve [rad]: beyond π/2 the block is flat.
THETA_MAX = math.pi / 2
#: Points used to bracket sign changes of α(θ) before Brent's search (rockcli.searches).
BRACKET_POINTS = 400
#: Share of the capacity a restrainer failure must remove to end the mechanism in the 2019
#: rules (Circolare 7/2019 §C8.7.1.2.1: "riduzione della capacità superiore al 50%").
FAILURE_DROP = 0.5
#: Rotation at which the capacity curve is cut when α never vanishes [rad].
CURVE_END = math.pi / 4
#: Share of a chain's range of motion the curve is drawn to when α never vanishes: at the
#: end of the range the two-block chain locks and its virtual displacements grow without
#: bound (the block's range, π/2, leaves π/4 as it was).
LOCK_SHARE = 0.95


@dataclass(frozen=True)
class Mechanism:
    """A mechanism opening to one side, with its loads, thrusts and restrainers (the model's
    physical description, shared with the rocking analysis), and the edition's sums.

    Attributes:
        view: its geometry about the pivot of its side: the rectangle's closed forms
            (rockcli.mechanisms.block.BlockSide) or the general chain of bodies
            (rockcli.mechanisms.side.ChainSide), each with the side it opens to (+1: θ > 0,
            pivot O; −1: θ < 0, pivot O′).
        distributed: True when each body's mass is spread over its section for M* and e*
            (e* = 0.75 for a lone rectangle), False when lumped at its centroid (e* = 1).
        per_block: True for the 2019 sums of M*, e* and d* over the rigid blocks, each the
            resultant of its own and carried weights (Circ. 7/2019 Eqs. C8.7.1.4–C8.7.1.5
            of §C8.7.1.2.1.3, P_k of §C8.7.1.2.1.1); False for the 2009 sums over the
            weights (Circ. 617/2009 Eqs. C8A.4.2–C8A.4.3), where ``distributed`` applies.
    """

    view: BlockSide | ChainSide
    distributed: bool = False
    per_block: bool = False

    @property
    def side(self) -> int:
        """The side it overturns to (+1: θ > 0, pivot O; −1: θ < 0, pivot O′)."""
        return self.view.side

    @property
    def g(self) -> float:
        """Gravity [m/s²]."""
        return self.view.g

    @property
    def restrainers(self) -> tuple[Restrainer, ...]:
        """The restrainers, in the model's order."""
        return self.view.restrainers

    def placement(self, index: int) -> Polar | ChainPoint:
        """Restrainer ``index``'s point: its elongation and moment along the rotation."""
        return self.view.placement(index)

    @cached_property
    def loss_rotations(self) -> tuple[float, ...]:
        """Each restrainer's :func:`loss_rotation` on this side [rad] (inf: never lost), found
        once: the capacity curve asks for it at every rotation it evaluates."""
        return tuple(
            loss_rotation(sp, self.side, self.placement(i)) if can_be_lost(sp, self.side)
            else math.inf
            for i, sp in enumerate(self.restrainers)
        )  # fmt: skip


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
    g, t, h = mech.view.work_terms(0.0)
    restrainers = _spring_moments(mech, 0.0, False, False)
    return {
        "stabilising": g,
        "thrusts": t + 0.0,  # + 0.0: a side without thrust shows 0, not −0
        "restrainers": restrainers,
        "overturning": h,
        "alpha0": (g - t + restrainers) / h,
    }


def activation_work(mech: Mechanism) -> tuple[WorkTerm, ...]:
    """α0's virtual work per body, load, thrust and restrainer at θ = 0 (codecheck.result
    .WorkTerm): the terms :func:`activation_terms` sums, item by item, so that α0 =
    Σ resisting / Σ overturning can be recomputed from a printed table (Circolare 7/2019
    §C8.7.1.2.1.1, Eq. C8.7.1.1; Circolare 617/2009 §C8A.4.1)."""
    terms = []
    for it in mech.view.work_items():
        if it.kind in ("thrust", "friction"):
            resisting, overturning = -it.opens * it.force * it.dx, 0.0
        else:
            resisting = it.force * it.dy if it.bears else 0.0
            overturning = it.force * it.dx if it.moves else 0.0
        terms.append(WorkTerm(it, resisting + 0.0, overturning))
    for i, sp in enumerate(mech.restrainers):
        place = mech.placement(i)
        if can_be_lost(sp, mech.side) and 0.0 > loss_rotation(sp, mech.side, place):
            continue  # as _spring_moments at θ = 0
        arm = place.moment(1.0, 0.0)  # δx of its point per unit rotation
        moment = restrainer_moment(sp, mech.side, 0.0, place)
        x, z = mech.view.anchor(i)
        rod = WorkItem(sp.name, "restrainer", moment / arm if arm else 0.0, x, z, arm, 0.0)
        terms.append(WorkTerm(rod, moment, 0.0))
    return tuple(terms)


def _moments(mech: Mechanism) -> tuple[float, float]:
    """(Σ P δx, Σ P δx²) per unit virtual rotation [N·m, N·m²].

    2019 (``per_block``): over the rigid blocks, each one resultant at its point (Circ.
    7/2019 Eqs. C8.7.1.4–C8.7.1.5, k = 1…N blocks; P_k of §C8.7.1.2.1.1). 2009: over the weights,
    each body lumped or spread: the block spread over its height 2h gives Σ P δx = W h,
    Σ P δx² = W (2h)²/3 (integrals of z and z²); a body of the catalogue adds P·var_z
    (rockcli.mechanisms.side).
    """
    if mech.per_block:
        return mech.view.block_moments()
    return mech.view.first_moments(mech.distributed)


def participating_mass(mech: Mechanism) -> float:
    """M* = (Σ P δx)² / (g Σ P δx²) [kg]: over the weights (Circolare 617/2009 Eq. C8A.4.2),
    or over the rigid blocks for 2019, where M* = e*·Σ(P_k + Q_k)/g (Circolare 7/2019 defines
    only e*, Eq. C8.7.1.5, whose numerator and denominator these are).
    """
    first, second = _moments(mech)
    return first**2 / (mech.g * second)


def e_star(mech: Mechanism) -> float:
    """Participating mass fraction e* = g M* / Σ P_i [-], over the weights that move.

    Circolare 617/2009 Eq. C8A.4.3 (over the weights: a block alone 1 lumped, 0.75 spread over
    its height); Circolare 7/2019 Eq. C8.7.1.5 (over the blocks: one block 1).
    """
    total = mech.view.moving_weight
    return mech.g * participating_mass(mech) / total


def a0_star(alpha_0: float, e_s: float, FC: float, g: float) -> float:
    """Spectral acceleration of activation a0* = α0 g / (e* FC) [m/s²].

    Circolare 617/2009 Eq. C8A.4.4; Circolare 7/2019 Eq. C8.7.1.3 at α(d_C) = α0.
    """
    return alpha_0 * g / (e_s * FC)


def displacement_factor(mech: Mechanism) -> float:
    """d*/d_k = Σ P δx² / (δx_k Σ P δx), control point the block's centroid (δx_k = h) [-].

    Circolare 617/2009 Eq. C8A.4.5 (over the weights); Circolare 7/2019 Eq. C8.7.1.4 (over the
    blocks).
    """
    first, second = _moments(mech)
    return second / (mech.view.control_delta * first)


def control_displacement(mech: Mechanism, theta: float) -> float:
    """Horizontal displacement of the control point d_k [m]: the block's centroid,
    R[sin α − sin(α − θ)] (spec/ntc.md); a catalogue mechanism's bodies' centre of mass."""
    return mech.view.control_displacement(theta)


def rotation_at(mech: Mechanism, d_k: float) -> float:
    """The rotation θ at which the control point has moved d_k [m] (inverse of
    control_displacement)."""
    return mech.view.rotation_at(d_k)


#: The code_action of a restrainer taken as a constant force (mechanics.Restrainer; the
#: other, "spring", is its stiffness).
FORCE = "force"


def code_stiffness(sp: Restrainer, s: int) -> float:
    """K of restrainer ``sp`` on side s in the kinematic check [N/m]: its stiffness there, 0
    on the side where a tension-only member would push (a tie-rod goes slack: it adds
    nothing to α0 or the curve of that side; mechanics.Restrainer.slack_side)."""
    return 0.0 if s == sp.slack_side else sp.side(s)[0]


def force_at(
    sp: Restrainer, s: int, theta: float, place: Polar | ChainPoint | None = None
) -> float:
    """Horizontal force of restrainer ``sp`` in the check at rotation θ on side s, intact [N].

    code_action "force": its code_force F, constant from θ = 0 (Circolare 617/2009 §C8A.4.1 and
    Circolare 7/2019 §C8.7.1.1: a tie-rod is an external force in the virtual work of α0).
    "spring": P0 + K·u(θ) (pretension plus the spring, mechanics.spring_elongation), capped at
    :func:`force_cap`. 0 on a side where the member does not work (K = 0). ``place``: its
    point on a catalogue mechanism (default: its r, φ about the block's pivot of side s). A
    tie-rod on the side where it would push: 0 (:func:`code_stiffness`).
    """
    k = code_stiffness(sp, s)
    if k == 0.0:
        return 0.0
    if sp.code_action == FORCE:
        return sp.code_force
    u = (place or polar_of(sp, s)).elongation(theta)
    if isinstance(u, np.ndarray):  # a grid of rotations (zero_rotation's scan)
        return np.minimum(sp.pretension + k * u, force_cap(sp, s))
    return min(sp.pretension + k * u, force_cap(sp, s))


def force_cap(sp: Restrainer, s: int) -> float:
    """The most a spring can give the check on side s: min(strength, yield force) [N] (inf: none).

    NTC 2018 §4.2.4.1.2: the check relies on the member's design tension resistance, not on
    the elastic force of an ever-growing elongation (docs/interpretations.md).
    """
    return min(sp.strength, sp.yield_force(s))


def loss_elongation(sp: Restrainer, s: int) -> float:
    """Elongation from rest at which the member is lost in the check on side s [m] (inf: never).

    Its ``fails_at``; a steel bar's design elongation ε_u·L/γ_ε from its unstressed length,
    the pretension's P0/K included (the limit of its ductility check, codecheck.tie): a force
    or a spring, the bar cannot follow the mechanism further, so the Circolare's
    "rotture di elementi, quali catene" (§C8.7.1.2.1.6) happen where its own check says; for
    a spring also the elongation at which its elastic force P0 + K·u reaches the anchor's
    ``rupture_force`` before it yields (the anchor gives way). A force is constant, at most
    the anchor's capacity.
    """
    k = code_stiffness(sp, s)
    limit = min(sp.fails_at, ductile_elongation(sp, k))
    if sp.code_action == FORCE or k == 0.0 or sp.rupture_force > sp.yield_force(s):
        return limit
    return min(limit, max(0.0, (sp.rupture_force - sp.pretension) / k))


def ductile_elongation(sp: Restrainer, k: float) -> float:
    """The spring elongation from rest at which a bar reaches ε_u·L/γ_ε [m] (inf: not a bar of
    known steel): its capacity less the pretension's P0/K."""
    if not math.isfinite(sp.elongation_capacity):
        return math.inf
    preload = sp.pretension / k if k > 0.0 else 0.0
    return max(0.0, sp.elongation_capacity - preload)


def loss_rotation(sp: Restrainer, s: int, place: Polar | ChainPoint | None = None) -> float:
    """Rotation at which the member is lost on side s [rad] (inf: never)."""
    return (place or polar_of(sp, s)).rotation_at(loss_elongation(sp, s))


def can_be_lost(sp: Restrainer, s: int) -> bool:
    """True when the member can be lost on side s (it is left out of the curve of the members
    sure to last, the table's "α sure")."""
    return math.isfinite(loss_elongation(sp, s))


def restrainer_moment(
    sp: Restrainer, s: int, theta: float, place: Polar | ChainPoint | None = None
) -> float:
    """Restoring moment F·r·cos(φ − θ) of the member's force about the pivot of side s [N·m]
    (on a catalogue mechanism, F·δx of its point per unit rotation).

    The arm of mechanics.spring_moment (a horizontal force at the attachment point).
    """
    where = place or polar_of(sp, s)
    return where.moment(force_at(sp, s, theta, where), theta)


def _spring_moments(mech: Mechanism, theta: float, sure_only: bool, intact: bool) -> float:
    """Σ restrainer moments at rotation θ on the mechanism's side [N·m].

    sure_only: leave out every restrainer that can be lost (spec/ntc.md: d0* on actions sure
    to last until collapse). intact: ignore losses (the curve just before one).
    """
    total = 0.0
    for i, sp in enumerate(mech.restrainers):
        lost = can_be_lost(sp, mech.side)
        if sure_only and lost:
            continue
        place = mech.placement(i)
        if isinstance(theta, np.ndarray):  # a grid: each rotation with the member or not
            moment = restrainer_moment(sp, mech.side, theta, place)
            if lost and not intact:
                moment = np.where(lost_at_each(mech, i, place, theta), 0.0, moment)
            total = total + moment
            continue
        if lost and not intact and lost_at(mech, i, place, theta):
            continue
        total += restrainer_moment(sp, mech.side, theta, place)
    return total


def lost_at_each(
    mech: Mechanism, index: int, place: Polar | ChainPoint, theta: np.ndarray
) -> np.ndarray:
    """:func:`lost_at` at each rotation of an array."""
    past = theta > mech.loss_rotations[index]
    return past & (theta > 0.0) if isinstance(place, ChainPoint) else past


def lost_at(mech: Mechanism, index: int, place: Polar | ChainPoint, theta: float) -> bool:
    """Whether restrainer ``index`` is lost at rotation θ: past its loss rotation. A chain's
    loss rotation is never negative (ChainSide.invert gives 0 for an elongation ≤ 0), so at
    rest or before it none is sought (each costs an inversion of the chain's motion); a
    block's can be (a bar already broken by its pretension), and is always compared."""
    if theta <= 0.0 and isinstance(place, ChainPoint):
        return False
    return theta > mech.loss_rotations[index]


def load_multiplier(
    mech: Mechanism, theta: float, *, sure_only: bool = False, intact: bool = False
) -> float:
    """α(θ): the horizontal load multiplier in equilibrium at rotation θ [-].

    α(θ) = [G(θ) − s·T(θ) + Σ_k M_k(θ)] / H(θ), with G = Σ_bearing P_i (x_i cos θ − z_i sin θ),
    H = Σ_moving P_i (z_i cos θ + x_i sin θ) and T the thrusts' moment
    (:func:`rockcli.mechanics.point_moments`, the engine's own function; spec/ntc.md, "Capacity
    curve"; equilibrium in the rotated position, Circolare 617/2009 §C8A.4.2.3). The block
    alone: tan(α − θ). M_k: :func:`restrainer_moment`, a force (code_action "force") or a
    capped spring (mechanics.spring_moment's elongation and arm, as in the engine). A
    catalogue mechanism: the same sums with the virtual displacements of its chain
    (rockcli.mechanisms.side).
    """
    g, t, h = mech.view.work_terms(theta)
    return (g - t + _spring_moments(mech, theta, sure_only, intact)) / h


def zero_rotation(mech: Mechanism) -> float | None:
    """θ0 where the capacity curve first reaches α = 0, or None (positive stiffness).

    The curve of "solamente le azioni di cui è verificata la presenza fino al collasso"
    (Circolare 7/2019 §C8.7.1.2.1.6; Circolare 617/2009 §C8A.4.2.3): each restrainer until it
    is lost (:func:`loss_rotation`), where the curve drops. A member lost before the curve
    vanishes is absent at collapse and d0 is the zero of the curve without it; one that holds
    until the curve without it is already negative is present until collapse, which happens
    when it is lost (the curve drops through zero there). docs/interpretations.md.
    """

    def f(t: float) -> float:
        return load_multiplier(mech, t)

    if isinstance(mech.view, ChainSide):
        return chain_zero_rotation(mech, f)
    prev, f_prev = 0.0, math.inf
    limit = mech.view.limit
    for k in range(1, BRACKET_POINTS + 1):
        t = limit * k / BRACKET_POINTS
        if (f_t := f(t)) <= 0.0:
            return brent_root(f, prev, t, f_prev, f_t)
        prev, f_prev = t, f_t
    return None


#: Points of the bracket scan a chain's curve evaluates at once (most zeros lie among the
#: first: a chunk at a time, so that the scan stops near where the point-by-point one did).
SCAN_CHUNK = 40


def chain_zero_rotation(mech: Mechanism, f: Callable[[float], float]) -> float | None:
    """:func:`zero_rotation` of a catalogue mechanism: the same scan of BRACKET_POINTS
    rotations, SCAN_CHUNK of them at a time through the chain's functions of an array of
    rotations (rockcli.mechanisms.links.Angle), then Brent's search in the first bracket."""
    limit = mech.view.limit
    prev, f_prev = 0.0, math.inf
    for start in range(1, BRACKET_POINTS + 1, SCAN_CHUNK):
        ks = np.arange(start, min(start + SCAN_CHUNK, BRACKET_POINTS + 1))
        ts: Angle = limit * ks / BRACKET_POINTS
        with np.errstate(all="ignore"):  # at the chain's limit its chord lies flat (inf, nan)
            values: Angle = load_multiplier(mech, ts)
        hit = np.flatnonzero(values <= 0.0)
        if len(hit):
            k = int(hit[0])
            if k > 0:
                prev, f_prev = float(ts[k - 1]), float(values[k - 1])
            return brent_root(f, prev, float(ts[k]), f_prev, float(values[k]))
        prev, f_prev = float(ts[-1]), float(values[-1])
    return None


def failure_rotations(mech: Mechanism) -> list[tuple[str, float, float]]:
    """(name, θ_f, capacity drop) of each restrainer lost on the mechanism's side.

    The drop is the share of α lost with it: 1 − α_after/α_before at θ_f.
    """
    out = []
    for i, sp in enumerate(mech.restrainers):
        place = mech.placement(i)
        theta_f = loss_rotation(sp, mech.side, place)
        acts = code_stiffness(sp, mech.side) > 0.0
        if not acts or not math.isfinite(theta_f) or theta_f >= THETA_MAX:
            continue
        moment = restrainer_moment(sp, mech.side, theta_f, place)
        before = load_multiplier(mech, theta_f, intact=True)
        after = before - moment / _overturning(mech, theta_f)
        out.append((sp.name, theta_f, 1.0 - after / before if before > 0 else 1.0))
    return out


def _overturning(mech: Mechanism, theta: float) -> float:
    return mech.view.work_terms(theta)[2]


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
    T0: float | None = None
    d_y: float | None = None

    @property
    def free(self) -> bool:
        """True for an element free to vibrate: an elastic branch of period T0 before it
        activates (Circolare 7/2019 §C8.7.1.2.1.3, Eq. C8.7.1.6)."""
        return self.T0 is not None

    @property
    def a_y(self) -> float | None:
        """a_y [m/s²]: the end of the elastic branch, on the rigid curve (None: rigid)."""
        return None if self.d_y is None else self.rigid_a_star(self.d_y)

    def a_star(self, d_star: float) -> float:
        """Spectral acceleration a*(d*) on the capacity curve [m/s²]: the elastic branch
        4π²d/T0² up to d_y for an element free to vibrate (Circolare 7/2019 Eq. C8.7.1.6),
        then the rigid curve (:meth:`rigid_a_star`)."""
        if self.T0 is not None and self.d_y is not None and d_star < self.d_y:
            return branch_acceleration(d_star, self.T0)
        return self.rigid_a_star(d_star)

    def rigid_a_star(self, d_star: float) -> float:
        """a*(d*) of the mechanism rigid until activation [m/s²] (Eq. C8A.4.4 on α(d))."""
        if self.linear and self.d0_star is not None:
            return self.a0_star * (1.0 - d_star / self.d0_star)
        theta = rotation_at(self.mech, d_star / self.factor)
        alpha = load_multiplier(self.mech, theta)
        return alpha * self.mech.g / (self.e_star * self.FC)

    def d_star_at(self, theta: float) -> float:
        """Spectral displacement d* at rotation θ [m] (Eq. C8A.4.5)."""
        return control_displacement(self.mech, theta) * self.factor


def constant_forces_only(mech: Mechanism) -> bool:
    """True when the code's straight line holds: no restrainer acts on the side checked (a
    spring's force grows with the rotation, and any member ends where it is lost: the curve
    is then α(θ) itself)."""
    s = mech.side
    return not any(code_stiffness(sp, s) for sp in mech.restrainers)


def capacity(mech: Mechanism, FC: float, T0: float | None = None) -> Capacity:
    """α0, e*, a0*, d*/d_k and d0* of a mechanism, and which curve the code uses.

    The straight line a0*(1 − d*/d0*) is the Circolare's curve under constant forces
    (§C8A.4.2.3: "può essere assunta lineare"); with restrainers the curve α(θ) itself
    (spec/ntc.md). d0* is the zero of the curve with each restrainer until it is lost
    (:func:`zero_rotation`). ``T0``: the period of an element free to vibrate (Circolare
    7/2019 Eq. C8.7.1.7): the curve starts with the elastic branch to (a_y, d_y).
    """
    a_0 = alpha0(mech)
    e_s = e_star(mech)
    theta0 = zero_rotation(mech)
    factor = displacement_factor(mech)
    d0 = None if theta0 is None else control_displacement(mech, theta0) * factor
    linear = constant_forces_only(mech)
    rigid = Capacity(
        mech=mech,
        alpha0=a_0,
        e_star=e_s,
        FC=FC,
        a0_star=a0_star(a_0, e_s, FC, mech.g),
        factor=factor,
        d0_star=d0,
        linear=linear,
    )
    if T0 is None:
        return rigid
    d_end = d0 if d0 is not None else rigid.d_star_at(curve_end(mech))
    return replace(rigid, T0=T0, d_y=branch_end(rigid.rigid_a_star, T0, d_end))


def curve_end(mech: Mechanism) -> float:
    """The rotation the curve is drawn to when α never vanishes [rad]."""
    return min(CURVE_END, LOCK_SHARE * mech.view.limit)


def elastic_rows(cap: Capacity) -> list[dict[str, float]]:
    """The elastic branch of an element free to vibrate as the curve's first row, at rest
    (θ = 0, d_k = 0: it has not rocked yet; α = a·e*·FC/g); none for a rigid one. The
    branch's end (d_y, a_y) is the rigid curve's first row."""
    if cap.d_y is None:
        return []
    return [{"theta": 0.0, "d_k": 0.0, "d_star": 0.0, "alpha": 0.0, "alpha_sure": 0.0,
             "a_star": 0.0}]  # fmt: skip


class CapacityCurve(Sequence[dict[str, float]]):
    """The capacity curve's rows (:func:`curve_points`), computed when first read: a study's
    row, a retrofit's candidate and the verdicts read none of them, and each costs a dozen
    inversions of the chain's motion."""

    def __init__(self, cap: Capacity) -> None:
        self._cap = cap
        self._rows: tuple[dict[str, float], ...] | None = None

    def rows(self) -> tuple[dict[str, float], ...]:
        """Every row, computed once."""
        if self._rows is None:
            self._rows = tuple(curve_points(self._cap))
        return self._rows

    def __getitem__(self, index):
        return self.rows()[index]

    def __len__(self) -> int:
        return len(self.rows())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Sequence) and tuple(self) == tuple(other)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"CapacityCurve({'not computed' if self._rows is None else len(self._rows)})"


def curve_points(cap: Capacity, n: int = 11) -> list[dict[str, float]]:
    """The capacity curve as rows: θ, d_k, d*, α (all restrainers until failure), α sure, a*.

    Sampled uniformly in d* from 0 to d0* (or to the rotation at which α of the sure curve
    halves its growth limit, π/4, when there is no d0*).
    """
    mech = cap.mech
    d_end = cap.d0_star if cap.d0_star is not None else cap.d_star_at(curve_end(mech))
    rows = elastic_rows(cap)
    d_start = 0.0 if cap.d_y is None else cap.d_y
    for k in range(n):
        d_star = d_start + (d_end - d_start) * k / (n - 1)
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
