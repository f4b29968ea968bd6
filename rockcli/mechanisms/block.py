"""The rectangular block about one base edge: the catalogue's simplest mechanism, closed forms.

Today's block (:class:`rockcli.mechanics.Block`, the paper's Housner block) is the mechanism
"overturning of the whole wall" of a one-storey wall without a gable; it keeps its closed
forms, which the rocking engine compiles too, so the code check's α0 stays the engine's uplift
acceleration bit for bit (spec of the block: docs/physics.md). The general mechanisms
(:class:`rockcli.mechanisms.side.ChainSide`) give the same numbers to rounding
(tests/mechanisms/test_block_as_chain.py).

Pure and silent: only :mod:`math` and :mod:`rockcli.mechanics`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from rockcli.mechanics import (
    Block,
    Restrainer,
    WorkItem,
    point_moments,
    point_table,
    spring_elongation,
    spring_failure_rotation,
)


@dataclass(frozen=True)
class Polar:
    """A restrainer's attachment point by its radius r [m] and angle φ [rad] from the vertical
    about the active pivot (spec of the block, "Restrainers"; the paper's Eq. 4–8)."""

    r: float
    phi: float

    def elongation(self, theta: float) -> float:
        """u(θ) = r[sin φ − sin(φ − θ)] [m] (mechanics.spring_elongation)."""
        return spring_elongation(self.r, self.phi, theta)

    def moment(self, force: float, theta: float) -> float:
        """F·r·cos(φ − θ): the moment of a horizontal force F [N] at the point [N·m]."""
        return force * self.r * math.cos(self.phi - theta)

    def rotation_at(self, elongation: float) -> float:
        """The rotation at which u reaches ``elongation`` [rad] (inf: never)."""
        return spring_failure_rotation(self.r, self.phi, elongation)


def polar_of(sp: Restrainer, side: int) -> Polar:
    """The point of restrainer ``sp`` about the pivot of ``side``."""
    _, r, phi = sp.side(side)
    return Polar(r, phi)


@dataclass(frozen=True)
class BlockSide:
    """The block turning about the base edge of ``side`` (+1: pivot O, −1: pivot O′), with
    its loads, thrusts and restrainers: the virtual-work sums of the Circolare in the closed
    forms of the rectangle (Circ. 617/2009 §C8A.4; Circ. 7/2019 §C8.7.1.2.1.1 and §C8.7.1.2.1.3)."""

    block: Block
    side: int

    @cached_property
    def points(self) -> tuple[float, ...]:
        """The block, its loads and thrusts as the point table (mechanics.point_table)."""
        return point_table(self.block)

    @property
    def g(self) -> float:
        """Gravity [m/s²]."""
        return self.block.g

    @property
    def restrainers(self) -> tuple[Restrainer, ...]:
        """The restrainers, in the model's order."""
        return self.block.restrainers

    @property
    def limit(self) -> float:
        """The largest rotation searched [rad]: the block lies flat at π/2."""
        return math.pi / 2

    def placement(self, index: int) -> Polar:
        """Restrainer ``index``'s point about the side's pivot."""
        return polar_of(self.block.restrainers[index], self.side)

    def work_terms(self, theta: float) -> tuple[float, float, float]:
        """(G, T, H) at θ [N·m]: the weights' restoring moment, the moment of the thrusts
        pushing towards the side (s·T of mechanics.point_moments) and the overturning moment
        of a unit horizontal acceleration (1 g) of the moving masses."""
        g, h, t, _, _ = point_moments(self.points, self.side, math.sin(theta), math.cos(theta))
        return g, self.side * t, h

    def work_items(self) -> tuple[WorkItem, ...]:
        """The block, its loads and thrusts at rest about the side's pivot: a point (x, z)
        inward and up from the pivot moves δx = z outward and δy = x up per unit rotation."""
        b, s = self.block, self.side
        items = [WorkItem("block", "body", b.weight, b.b, b.h, b.h, b.b)]
        for ld in b.loads:
            x = ld.x_pos if s > 0 else ld.x_neg
            items.append(WorkItem(ld.name, "load", ld.weight, x, ld.z, ld.z, x, ld.bears,
                                  ld.moves))  # fmt: skip
        for th in b.thrusts:
            x = th.x_pos if s > 0 else th.x_neg
            items.append(WorkItem(th.name, "thrust", th.force, x, th.z, th.z, x,
                                  opens=th.direction * s))  # fmt: skip
        return tuple(items)

    def anchor(self, index: int) -> tuple[float, float]:
        """Restrainer ``index``'s point (x inward, z up) from the side's pivot [m]."""
        p = self.placement(index)
        return p.r * math.sin(p.phi), p.r * math.cos(p.phi)

    @property
    def moving(self) -> tuple[tuple[float, float], ...]:
        """(P, δx per unit rotation) of the weights whose masses move: the block at h, then
        every load that moves (Circolare's P_i and P_j)."""
        own = (self.block.weight, self.block.h)
        return (own, *((ld.weight, ld.z) for ld in self.block.loads if ld.moves))

    def first_moments(self, distributed: bool) -> tuple[float, float]:
        """(Σ P δx, Σ P δx²) per unit virtual rotation [N·m, N·m²], the block lumped or spread.

        Spread over the height 2h: Σ P δx = W h, Σ P δx² = W (2h)²/3 (integrals of z and z²).
        """
        b = self.block
        own_1, own_2 = (
            (b.weight * b.h, b.weight * 4.0 * b.h**2 / 3.0)
            if distributed
            else (
                b.weight * b.h,
                b.weight * b.h**2,
            )
        )
        loads = self.moving[1:]
        first = own_1 + sum(w * z for w, z in loads)
        second = own_2 + sum(w * z**2 for w, z in loads)
        return first, second

    def block_moments(self) -> tuple[float, float]:
        """(Σ_k P_k δx_k, Σ_k P_k δx_k²) over the rigid blocks [N·m, N·m²] (Circ. 7/2019
        Eqs. C8.7.1.4–C8.7.1.5 with §C8.7.1.2.1.1): the block and the loads that move with it
        as one resultant P at its point, δx = Σ P_i z_i / P; e* = 1."""
        first = sum(w * z for w, z in self.moving)
        return first, first * first / self.moving_weight

    @property
    def moving_weight(self) -> float:
        """Σ P of the weights that move [N]."""
        return sum(w for w, _ in self.moving)

    @property
    def control_delta(self) -> float:
        """δx_k of the control point (the block's centroid) per unit rotation: h [m]."""
        return self.block.h

    def control_displacement(self, theta: float) -> float:
        """d_k = R[sin α − sin(α − θ)] [m], the centroid's horizontal displacement."""
        b = self.block
        return b.R * (math.sin(b.alpha) - math.sin(b.alpha - theta))

    def rotation_at(self, d_k: float) -> float:
        """The rotation θ at which the centroid has moved d_k [m]."""
        b = self.block
        return b.alpha - math.asin(max(-1.0, min(1.0, math.sin(b.alpha) - d_k / b.R)))
