"""The two-block vertical flexure as the rocking engine takes it: a mechanics.Chain carrying
its table (mechanics.ChainTable).

The flexure of a storey (rockcli.mechanisms.catalogue.flexure) is two blocks and one degree
of freedom: the lower block about the edge of the storey's base, the upper one hanging from the
intermediate hinge with its top held horizontally by the floor above and free to rise
(Doherty et al. 2002, EESD 31:833–850; Sorrentino, Masiani & Griffith 2008, Struct. Eng. Mech.
29:433–453). Its equation of motion is read from the one configuration function of both sides
(rockcli.mechanisms.table): the same bodies, loads and thrusts the code check's α0 and
capacity curve read, so the uplift acceleration of each side is the code's α0.

Restrainers. A member on the lower block (at or below the intermediate hinge) turns rigidly
with it about the pivot: it enters the engine exactly as a block's member, at its polar
position from each pivot. A member at the storey's top is where the floor holds the chain: its
point does not move horizontally at rest and by (x − x_top)·(1 − cos φ) only — the chain's
premise is that the top is held, so it is not a spring of the motion
(docs/mechanisms/vertical-flexure.md). A member on the upper block between the hinge and the
top does not turn about the pivot: its elongation u(θ) (its point's displacement away from the
wall) and u′(θ) = δx, the arm of its force in the chain's equation of motion by virtual work,
come from the configuration function, tabulated on the chain's grid
(rockcli.mechanisms.table.member_path; mechanics.Restrainer.path), and its member law is the
one every restrainer has. The member laws need an elongation that grows as the chain opens: a
point that turns back towards its anchor before the table's end — only a point all but at the
held top, outward of its hinge, does, its elongation at most its small distance below the top
times the rotation — is taken as at the top (:func:`held_at_top`; the studies say so in a
note).

Pure and silent: only :mod:`math`, :mod:`rockcli.mechanics` and the package's modules.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from rockcli.mechanics import Chain, Rocker, rocker_fields
from rockcli.mechanisms.catalogue import build, same_height
from rockcli.mechanisms.rigid import composite, placed
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.table import end_of, instability, member_path, shrinks_at, tabulate
from rockcli.mechanisms.wall import MechanismSpec, Wall


@dataclass(frozen=True)
class HeldMember:
    """A member on the upper block all but at the held top, whose elongation stops growing at
    ``rotation`` [rad] of side ``side`` before the table's end ``end``: taken as at the top."""

    name: str
    z: float
    side: int
    rotation: float
    end: float


def upper_members(plus: ChainSide, minus: ChainSide, top: float):
    """(index, member, point from O, point from O′) of each member on the upper block below
    its held top."""
    anchors = zip(plus.restrainers, plus.anchors, minus.anchors, strict=True)
    for index, (member, at_pos, at_neg) in enumerate(anchors):
        if at_pos.link == 1 and not same_height(at_pos.z, top):
            yield index, member, at_pos, at_neg


def members(plus: ChainSide, minus: ChainSide, top: float):
    """The restrainers the motion carries, placed from each pivot, in the model's order
    (module docstring): on the upper block with its elongation path, but for one held at the
    top (:func:`held_at_top`)."""
    out = {
        index: placed(member, at_pos.x, at_neg.x, at_pos.z)
        for index, (member, at_pos, at_neg) in enumerate(
            zip(plus.restrainers, plus.anchors, minus.anchors, strict=True)
        )
        if at_pos.link == 0
    }
    for index, member, at_pos, at_neg in upper_members(plus, minus, top):
        if shrinks_at(plus, minus, index) is None:
            path = member_path(plus, minus, index)
            out[index] = replace(placed(member, at_pos.x, at_neg.x, at_pos.z), path=path)
    return tuple(out[index] for index in sorted(out))


def held_at_top(wall: Wall, spec: MechanismSpec) -> tuple[HeldMember, ...]:
    """The members on the upper block of the flexure ``spec`` (its hinge height resolved)
    whose elongation stops growing before the table's end: the point, all but at the held
    top and outward of its hinge, turns back towards its anchor as the chain opens. The
    time history takes such a member as at the top, where the floor holds the chain (not a
    spring of the motion, as a member at the top: module docstring)."""
    plus, minus = build(wall, spec, 1), build(wall, spec, -1)
    assert spec.storey is not None
    top = wall.storeys[spec.storey - 1].height
    out = []
    for index, member, at_pos, _ in upper_members(plus, minus, top):
        found = shrinks_at(plus, minus, index)
        if found is not None:
            out.append(HeldMember(member.name, at_pos.z, *found, end_of(plus, minus)))
    return tuple(out)


def flexure_block(plus: ChainSide, minus: ChainSide, top: float, block: Rocker) -> Chain:
    """The vertical flexure placed about each pivot (``plus``, ``minus``: the code check's
    two-block chain of each side, its hinge resolved; ``top``: its storey's height, where the
    floor holds it) as a Chain carrying its table; ``block`` gives the model's settings the
    mechanism keeps (motion, rebound, e's rule).

    Its α, which max θ/α divides by, is the instability rotation of the side it can open to
    (one-sided), or the smaller of the two sides' (two-sided: a ratio of 1 on either side is
    then never past that side's instability)."""
    body = composite([b for _, b in plus.bodies])  # in the side frame of side +1
    x, z = body.x, body.z
    table = replace(tabulate(plus, minus), centroid=(x, z))
    sides = (plus, minus) if not block.one_sided else ((plus,) if block.free_side > 0 else (minus,))
    return Chain(
        **rocker_fields(
            block,
            R=math.hypot(x, z),
            alpha=min(instability(side, table.end) for side in sides),
            mass=body.mass,
            linearized=False,
            restrainers=members(plus, minus, top),
            loads=(),
            thrusts=(),
            e_neg=None,
        ),
        table=table,
    )
