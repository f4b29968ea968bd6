"""A mechanism that is one rigid body, as the rocking engine takes it: a RigidBody.

Overturning about a storey's base, the wedge and the gable each turn as one rigid body about
the edge of their hinge section (rockcli.mechanisms.catalogue). The rocking engine's loaded
equation of motion is already Lagrange's equation of one rigid body of any shape about a pivot
on each side (rockcli.dynamics.motion.loaded_angular_acceleration: [I + J(a)]·ä + ½J′ȧ² =
−G + s·T + s·üg·H − ΣM_k). So the mechanism enters the engine as a
:class:`rockcli.mechanics.RigidBody` whose ``shape`` is the composite of its bodies: its weight at
their centroid (a rigid point mass in the point table) plus its own moment of inertia about
that centroid, I_G = Σ [I_Gi + m_i·|r_i − r_G|²] (parallel axes). The loads, thrusts,
restrainers and the toothed return walls' friction above the hinge go in from each pivot (x
from O, x′ from O′, z above the hinge).
Each side's coefficient of restitution is Housner's, from the angular momentum about the new
pivot (mechanics.impact_restitution); a one-sided mechanism's (the wedge's always) is that of
its one-sided impact, √(e₊·e₋) (mechanics.rebound_restitution; rockcli.model.derive
.with_system_restitution sets both).

Pure and silent: only :mod:`math`, :mod:`rockcli.mechanics` and the package's modules.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from rockcli.mechanics import (
    Friction,
    Load,
    Restrainer,
    RigidBody,
    Rocker,
    Thrust,
    point_polar,
    rocker_fields,
)
from rockcli.mechanisms.bodies import Body
from rockcli.mechanisms.side import ChainSide


@dataclass(frozen=True)
class Composite:
    """Bodies turning together: weight [N], mass [kg], centroid (x, z) [m], I_G [kg·m²]."""

    weight: float
    mass: float
    x: float
    z: float
    inertia: float


def composite(bodies: list[Body]) -> Composite:
    """The bodies as one rigid body (centroid by weights; I_G by parallel axes)."""
    weight = sum(b.weight for b in bodies)
    mass = sum(b.mass for b in bodies)
    x = sum(b.weight * b.x for b in bodies) / weight
    z = sum(b.weight * b.z for b in bodies) / weight
    inertia = sum(b.inertia + b.mass * ((b.x - x) ** 2 + (b.z - z) ** 2) for b in bodies)
    return Composite(weight, mass, x, z, inertia)


def rigid_block(plus: ChainSide, minus: ChainSide, block: Rocker, wedge: bool) -> RigidBody:
    """The rigid mechanism as a RigidBody of its own shape, from the code check's placement
    of it about each pivot (``plus`` about O, ``minus`` about O′: the same bodies, loads,
    thrusts and members, rockcli.mechanisms.catalogue.rigid), so that its uplift on each side
    is the check's α0 of that side by construction; ``block`` gives the model's settings the
    mechanism keeps (restitution rule through ``e``, motion, rebound); ``wedge``: it opens
    outward only."""
    body = composite([b for _, b in plus.bodies])
    x_pos, z = body.x, body.z
    x_neg = composite([b for _, b in minus.bodies]).x
    loads = tuple(
        Load(ld.name, ld.weight, ld.at.x, other.at.x, ld.at.z, ld.bears, ld.moves)
        for ld, other in zip(plus.loads, minus.loads, strict=True)
    )
    thrusts = tuple(
        Thrust(th.name, th.force, th.opens, th.at.x, other.at.x, th.at.z)
        for th, other in zip(plus.thrusts, minus.thrusts, strict=True)
    )
    members = tuple(
        placed(member, at_pos.x, at_neg.x, at_pos.z)
        for member, at_pos, at_neg in zip(plus.restrainers, plus.anchors, minus.anchors,
                                          strict=True)
    )  # fmt: skip
    frictions = tuple(
        Friction(fr.name, fr.force, fr.x, other.x, fr.z0, fr.height, fr.overlap)
        for fr, other in zip(plus.frictions, minus.frictions, strict=True)
    )
    return RigidBody(
        **rocker_fields(
            block,
            R=math.hypot(x_pos, z),
            alpha=math.atan2(x_pos, z),
            mass=body.mass,
            one_sided=block.one_sided or wedge,
            free_side=1 if wedge else block.free_side,
            linearized=False,
            restrainers=members,
            loads=loads,
            thrusts=thrusts,
            frictions=frictions,
            e_neg=None,
        ),
        shape=(x_pos, x_neg, z, body.inertia),
    )


def placed(member: Restrainer, x_pos: float, x_neg: float, z: float) -> Restrainer:
    """The member attached at (x from O, x′ from O′, z above the hinge)."""
    (r_pos, phi_pos), (r_neg, phi_neg) = point_polar(x_pos, z), point_polar(x_neg, z)
    return replace(member, r_pos=r_pos, phi_pos=phi_pos, r_neg=r_neg, phi_neg=phi_neg)
