"""A mechanism opening to one side, as both analyses read it: bodies, loads, thrusts and
restrainers on the links of one motion, in the side frame (rockcli.mechanisms.links).

From the one configuration function (the motion's link states) come, at any rotation θ:

- the virtual-work sums of the Circolare (Circ. 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.1;
  Circ. 617/2009 §C8A.4.1), written per unit virtual rotation δθ with the virtual
  displacements δx = −∂X/∂θ (outward, away from the wall in the side frame) and δy = ∂Z/∂θ
  (up):
  G = Σ_bearing P·δy (the weights' work against the opening), H = Σ_moving P·δx (the work of
  a unit horizontal load multiplier), T = Σ F_open·δx (the thrusts pushing the mechanism open),
  and the restrainers' F·δx; in equilibrium α(θ) = (G − T + Σ F_k δx_k) / H — at θ = 0 the
  Circolare's α0, along θ its capacity curve by finite rotations (§C8A.4.2.3);
- M* and e* from the δx of the masses at θ = 0 (Circ. 7/2019 §C8.7.1.2.1.3, Eq. C8.7.1.5,
  over the blocks; Circ. 617/2009 Eq. C8A.4.2–3, over the weights, each body lumped at its
  centroid or spread over its section);
- the control point's displacement d_k(θ) (the bodies' centre of mass) for d*;
- the equation of motion's M(θ), V(θ), Γ(θ) (rockcli.mechanisms.motion).

Pure and silent: :mod:`math`, numpy (the links take an array of rotations too, and so does
the toothing's friction), the package's own modules and :mod:`rockcli.searches`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rockcli.mechanics import Restrainer, WorkItem
from rockcli.mechanisms.bodies import Body
from rockcli.mechanisms.links import LinkState, Motion
from rockcli.searches import brent_root


@dataclass(frozen=True)
class Attached:
    """A point of a link: ``link`` index, rest position (x, z) in the side frame [m]."""

    link: int
    x: float
    z: float


@dataclass(frozen=True)
class SideLoad:
    """A weight on a link (a floor, the roof, an overburden) in the side frame.

    Attributes:
        name: label. weight: [N]. at: its point. bears: its weight rests on the mechanism
        (it is lifted). moves: its mass follows the mechanism horizontally (it pushes).
    """

    name: str
    weight: float
    at: Attached
    bears: bool = True
    moves: bool = True


@dataclass(frozen=True)
class SideThrust:
    """A horizontal force independent of the earthquake on a link.

    Attributes:
        name: label. force: its magnitude [N]. opens: +1 when it pushes the mechanism open
        (away from the wall in the side frame), −1 when it pushes it shut. at: its point.
    """

    name: str
    force: float
    opens: int
    at: Attached


#: Gauss–Legendre points of two-point quadrature on [0, 1] (exact for the friction's
#: integrand: a linear distribution times the affine virtual displacement of a rigid link).
_GAUSS = (0.5 - 0.5 / math.sqrt(3.0), 0.5 + 0.5 / math.sqrt(3.0))


@dataclass(frozen=True)
class SideFriction:
    """The friction of toothed return walls on a link, resisting the mechanism's motion.

    Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.2: the return walls' courses interlocked with
    the wall over the height h above the hinge resist its overturning with a horizontal force
    F (all walls together) applied at h/3. Taken here as the continuous form of the text's
    courses: the force per unit height grows linearly down from the top, as the weight
    pressing each course does, q(z) = 2F·(h − z)/h² (its resultant F at h/3, the Circolare's
    point). A course stays engaged while its horizontal slide is at most the overlap l; past
    it the course has left its tooth and no longer resists (the capacity curve's friction
    falls as the joints slide, docs/mechanisms/friction.md).

    Attributes:
        name: label. force: F of all the walls [N]. link: the link it acts on (a rigid
        one). x: the interface's x in the side frame [m]. z0: the toothing's bottom, the
        hinge, in the side frame [m]. height: h, the toothed height [m]. overlap: l [m].
    """

    name: str
    force: float
    link: int
    x: float
    z0: float
    height: float
    overlap: float

    def engaged(self, state: LinkState):
        """(u, v): the part of the toothed height whose slide is at most the overlap, as
        fractions of h from the bottom (u = v: none), at the link's ``state``."""
        bottom = -state.displacement(self.x, self.z0)[0]
        top = -state.displacement(self.x, self.z0 + self.height)[0]
        slope = top - bottom
        lo, hi = -self.overlap - bottom, self.overlap - bottom
        flat = np.abs(slope) <= 1e-300
        safe = np.where(flat, 1.0, slope)
        a, b = lo / safe, hi / safe
        u = np.where(flat, np.where(np.abs(bottom) <= self.overlap, 0.0, 1.0), np.minimum(a, b))
        v = np.where(flat, 1.0, np.maximum(a, b))
        u = np.clip(u, 0.0, 1.0)
        return u, np.maximum(np.clip(v, 0.0, 1.0), u)

    def work(self, state: LinkState) -> float:
        """∫ q·dX/dθ dz over the engaged courses [N·m per unit rotation] (negative when the
        mechanism opens: the friction resists), exact by two-point quadrature."""
        u, v = self.engaged(state)
        total = 0.0
        for g in _GAUSS:
            f = u + (v - u) * g
            dx = state.place(self.x, self.z0 + f * self.height)[2]
            total = total + 2.0 * self.force * (1.0 - f) * dx
        out = 0.5 * (v - u) * total
        return float(out) if np.ndim(out) == 0 else out

    @property
    def lever(self) -> float:
        """The resultant's height above the toothing's bottom, h/3 [m]."""
        return self.height / 3.0


@dataclass(frozen=True)
class ChainPoint:
    """A restrainer's attachment point on a link of a mechanism: elongation, moment and the
    inverse, from the motion (the general form of rockcli.mechanisms.block.Polar)."""

    side: ChainSide
    at: Attached

    def elongation(self, theta: float) -> float:
        """The point's displacement away from the wall since rest, X(0) − X(θ) [m], to a few
        ulps at any rotation (chain.LinkState.displacement)."""
        state = self.side.states(theta)[self.at.link]
        return -state.displacement(self.at.x, self.at.z)[0]

    def moment(self, force: float, theta: float) -> float:
        """The virtual work of a horizontal force F [N] pulling the point back, per unit δθ:
        F·δx [N·m] (the block's F·r·cos(φ − θ))."""
        return -force * self.side.place(self.at, theta)[2]

    def rotation_at(self, elongation: float) -> float:
        """The rotation at which the elongation reaches ``elongation`` [rad] (inf: never
        within the motion's range)."""
        if not math.isfinite(elongation):
            return math.inf
        return self.side.invert(self.elongation, elongation)


@dataclass(frozen=True)
class ChainSide:
    """One mechanism opening to one side (the code check's and the equation of motion's view).

    Attributes:
        motion: how its links move (chain.Rotation, chain.TwoBlock).
        bodies: (link, body) with the body in the side frame.
        loads, thrusts: on the links, in the side frame.
        restrainers: the members, in the model's order; ``anchors`` their points.
        g: gravity [m/s²].
        side: the side it opens to (+1: θ > 0; −1: θ < 0), which the frame's x was turned to.
        frictions: the toothed return walls' friction on its links (the code check's; the
            equation of motion does not carry it, docs/mechanisms/friction.md).
    """

    motion: Motion
    bodies: tuple[tuple[int, Body], ...]
    g: float
    loads: tuple[SideLoad, ...] = ()
    thrusts: tuple[SideThrust, ...] = ()
    restrainers: tuple[Restrainer, ...] = ()
    anchors: tuple[Attached, ...] = field(default_factory=tuple)
    side: int = 1
    frictions: tuple[SideFriction, ...] = ()

    @property
    def limit(self) -> float:
        """The largest rotation the motion is defined for [rad]."""
        return self.motion.limit

    def states(self, theta: float) -> tuple[LinkState, ...]:
        """Every link at θ (a rotation, or an array of them: rockcli.mechanisms.links.Angle)."""
        return self.motion.states(theta)

    def place(self, at: Attached, theta: float) -> tuple[float, float, float, float]:
        """(X, Z, dX/dθ, dZ/dθ) of a point at θ."""
        return self.states(theta)[at.link].place(at.x, at.z)

    def placement(self, index: int) -> ChainPoint:
        """Restrainer ``index``'s point."""
        return ChainPoint(self, self.anchors[index])

    def work_terms(self, theta: float) -> tuple[float, float, float]:
        """(G, T, H) at θ [N·m] per unit virtual rotation (module docstring)."""
        states = self.states(theta)
        g = h = t = 0.0
        for link, body in self.bodies:
            _, _, dx, dz = states[link].place(body.x, body.z)
            if body.bears:
                g += body.weight * dz
            h -= body.weight * dx
        for ld in self.loads:
            _, _, dx, dz = states[ld.at.link].place(ld.at.x, ld.at.z)
            if ld.bears:
                g += ld.weight * dz
            if ld.moves:
                h -= ld.weight * dx
        for th in self.thrusts:
            dx = states[th.at.link].place(th.at.x, th.at.z)[2]
            t -= th.opens * th.force * dx
        for fr in self.frictions:
            t += fr.work(states[fr.link])  # it pushes shut: opens = −1
        return g, t, h

    def work_items(self) -> tuple[WorkItem, ...]:
        """Every body, load and thrust at rest with its virtual displacement per unit rotation
        (δx = −dX/dθ outward, δy = dZ/dθ up), as :meth:`work_terms` sums them at θ = 0."""
        states = self.states(0.0)
        items = []
        for link, body in self.bodies:
            _, _, dx, dz = states[link].place(body.x, body.z)
            items.append(WorkItem(body.name, "body", body.weight, body.x, body.z, -dx, dz,
                                  body.bears))  # fmt: skip
        for ld in self.loads:
            _, _, dx, dz = states[ld.at.link].place(ld.at.x, ld.at.z)
            items.append(WorkItem(ld.name, "load", ld.weight, ld.at.x, ld.at.z, -dx, dz,
                                  ld.bears, ld.moves))  # fmt: skip
        for th in self.thrusts:
            _, _, dx, dz = states[th.at.link].place(th.at.x, th.at.z)
            items.append(WorkItem(th.name, "thrust", th.force, th.at.x, th.at.z, -dx, dz,
                                  opens=th.opens))  # fmt: skip
        for fr in self.frictions:  # its resultant at h/3, every course engaged at rest
            z = fr.z0 + fr.lever
            _, _, dx, dz = states[fr.link].place(fr.x, z)
            items.append(WorkItem(fr.name, "friction", fr.force, fr.x, z, -dx, dz, opens=-1))
        return tuple(items)

    def anchor(self, index: int) -> tuple[float, float]:
        """Restrainer ``index``'s point in the side frame [m]."""
        at = self.anchors[index]
        return at.x, at.z

    def masses_at_rest(self) -> list[tuple[int, float, float, float]]:
        """(link, P, δx, P·δx² spread) of every moving weight at θ = 0: the bodies (δx of the
        centroid; the spread adds P·φ′²·var_z, ∫(z − z_G)² dm of a rotation) and the loads
        that move (point masses)."""
        states = self.states(0.0)
        out = []
        for link, body in self.bodies:
            dx = -states[link].place(body.x, body.z)[2]
            spread = body.weight * states[link].dphi ** 2 * body.var_z
            out.append((link, body.weight, dx, spread))
        for ld in self.loads:
            if ld.moves:
                at = ld.at
                out.append((at.link, ld.weight, -states[at.link].place(at.x, at.z)[2], 0.0))
        return out

    def first_moments(self, distributed: bool) -> tuple[float, float]:
        """(Σ P δx, Σ P δx²) per unit virtual rotation over the weights [N·m, N·m²]
        (Circ. 617/2009 Eqs. C8A.4.2–C8A.4.3, the sums over the n+m weights P_i): each body
        lumped at its centroid, or spread over its section."""
        first = second = 0.0
        for _, p, dx, spread in self.masses_at_rest():
            first += p * dx
            second += p * dx * dx + (spread if distributed else 0.0)
        return first, second

    def block_moments(self) -> tuple[float, float]:
        """(Σ_k P_k δx_k, Σ_k P_k δx_k²) over the rigid blocks [N·m, N·m²] (Circ. 7/2019
        Eqs. C8.7.1.4–C8.7.1.5 with §C8.7.1.2.1.1): each link's moving weights as one
        resultant P_k at its point, whose virtual displacement is the P-weighted mean of
        theirs (δx is affine in the position on a rigid link). One block: e* = 1."""
        per_link: dict[int, list[float]] = {}
        for link, p, dx, _ in self.masses_at_rest():
            w = per_link.setdefault(link, [0.0, 0.0])
            w[0] += p
            w[1] += p * dx
        first = sum(f for _, f in per_link.values())
        second = sum(f * f / p for p, f in per_link.values() if p > 0.0)
        return first, second

    @property
    def moving_weight(self) -> float:
        """Σ P of the weights that move [N]."""
        return sum(p for _, p, _, _ in self.masses_at_rest())

    def _centre(self, theta: float) -> tuple[float, float]:
        """(X, dX/dθ) of the bodies' centre of mass (the control point)."""
        states = self.states(theta)
        total = x = dx = 0.0
        for link, body in self.bodies:
            bx, _, bdx, _ = states[link].place(body.x, body.z)
            total += body.weight
            x += body.weight * bx
            dx += body.weight * bdx
        return x / total, dx / total

    @property
    def control_delta(self) -> float:
        """δx_k of the control point per unit rotation at rest [m]."""
        return -self._centre(0.0)[1]

    def control_displacement(self, theta: float) -> float:
        """d_k(θ): the control point's displacement away from the wall [m] (the bodies'
        weighted displacements, without the cancellation of a difference of positions)."""
        states = self.states(theta)
        total = moved = 0.0
        for link, body in self.bodies:
            total += body.weight
            moved -= body.weight * states[link].displacement(body.x, body.z)[0]
        return moved / total

    def rotation_at(self, d_k: float) -> float:
        """The rotation at which the control point has moved d_k [m] (inverse of
        :meth:`control_displacement`, by :meth:`invert` within the motion's range)."""
        return self.invert(self.control_displacement, d_k, clamp=True)

    def invert(self, f, value: float, clamp: bool = False) -> float:
        """The θ in [0, limit] where the increasing f(θ), zero at rest, reaches ``value``
        (Brent's search, rockcli.searches: the θ a bisection finds, in about a dozen
        evaluations); inf (or the limit, with ``clamp``) when it never does."""
        hi = self.limit
        if value <= 0.0:
            return 0.0
        short_hi = value - f(hi)
        if short_hi > 0.0:
            return hi if clamp else math.inf
        return brent_root(lambda theta: value - f(theta), 0.0, hi, value, short_hi)
