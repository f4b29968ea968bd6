"""The two-block vertical flexure as the rocking engine takes it: a Block carrying the chain's
table (mechanics.Chain).

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
top cannot be written as a polar spring and is refused (:class:`UpperMemberError`).

Pure and silent: only :mod:`math`, :mod:`rockcli.mechanics` and the package's modules.
"""

from __future__ import annotations

import math
from dataclasses import replace

from rockcli.mechanics import Block
from rockcli.mechanisms.catalogue import build, same_height
from rockcli.mechanisms.chain import TwoBlock
from rockcli.mechanisms.rigid import composite, placed
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.table import instability, tabulate
from rockcli.mechanisms.wall import MechanismSpec, Wall


class UpperMemberError(ValueError):
    """A restrainer on the upper block of a flexure, below its held top."""

    def __init__(self, member: str, z: float, hinge: float, top: float):
        super().__init__(member)
        self.member, self.z, self.hinge, self.top = member, z, hinge, top


def members(plus: ChainSide, minus: ChainSide, top: float):
    """The restrainers the motion carries, placed from each pivot (module docstring)."""
    out = []
    for member, at_pos, at_neg in zip(plus.restrainers, plus.anchors, minus.anchors, strict=True):
        if at_pos.link == 0:
            out.append(placed(member, at_pos.x, at_neg.x, at_pos.z))
        elif not same_height(at_pos.z, top):
            assert isinstance(plus.motion, TwoBlock)
            raise UpperMemberError(member.name, at_pos.z, plus.motion.hinge_z, top)
    return tuple(out)


def flexure_block(wall: Wall, spec: MechanismSpec, block: Block) -> Block:
    """The vertical flexure ``spec`` (its hinge height resolved) as a Block carrying its chain;
    ``block`` gives the model's settings the mechanism keeps (motion, rebound, e's rule).

    Its α, which max θ/α divides by, is the instability rotation of the side it can open to
    (one-sided), or the smaller of the two sides' (two-sided: a ratio of 1 on either side is
    then never past that side's instability)."""
    plus, minus = build(wall, spec, 1), build(wall, spec, -1)
    body = composite([b for _, b in plus.bodies])  # in the side frame of side +1
    x, z = body.x, body.z
    chain = replace(tabulate(plus, minus), centroid=(x, z))
    assert spec.storey is not None
    top = wall.storeys[spec.storey - 1].height  # in the side frame: above the storey's base
    sides = (plus, minus) if not block.one_sided else ((plus,) if block.free_side > 0 else (minus,))
    return replace(
        block,
        R=math.hypot(x, z),
        alpha=min(instability(side, chain.end) for side in sides),
        mass=body.mass,
        linearized=False,
        restrainers=members(plus, minus, top),
        loads=(),
        thrusts=(),
        body=None,
        chain=chain,
        e_neg=None,
    )
