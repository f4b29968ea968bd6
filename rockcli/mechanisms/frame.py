"""A rocking frame: equal piers capped by a rigid roof (a bell cell), as one mechanism.

N equal free-standing piers of width 2b and height 2h, capped by a rigid roof of mass m_b
that rests on their tops, rock together (Makris & Vassiliou 2013, "Planar rocking response
and stability analysis of an array of free-standing columns capped with a freely supported
rigid beam", Earthquake Engng Struct. Dyn. 42:431–449): every pier turns by θ about the
corner of its base on the side it opens to, its top rocking on the roof about the opposite
top corner, and the roof translates without turning, carried by those corners. As one
degree of freedom the frame is a chain of two links (:class:`CappedPiers`): the piers (all
turning alike, one body of their joint weight about the pivot) and the roof (translating
with the top corner (2b, 2h) of a pier, from its pivot). Its equation of motion, its α0,
M* and e* all come from this one configuration (rockcli.mechanisms.motion, .table and the
code check), and its impact is the chain's projection (rockcli.mechanisms.motion
.impact_ratio). The closed forms it gives, with γ = m_b/(N·m_c):

- uplift at g·tan α whatever the roof's mass (the roof is lifted by 2b and pushed over 2h
  per unit rotation, in the ratio of the piers' own b and h);
- p̂² = p²·(1 + 2γ)/(1 + 3γ), p² = 3g/(4R) of one pier: the roof slows the frame;
- e = [1 − (3/2)·sin²α + 3γ·cos 2α]/(1 + 3γ) (Housner's for γ = 0).

Pure and silent: only :mod:`math`, numpy (arrays of rotations) and the package's modules.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from rockcli.mechanics import Chain, Rocker, rocker_fields
from rockcli.mechanisms.bodies import Body, prism
from rockcli.mechanisms.links import CappedPiers
from rockcli.mechanisms.rigid import composite
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.table import instability, tabulate


@dataclass(frozen=True)
class FrameGeometry:
    """A rocking frame as the model gives it, in SI units.

    Attributes:
        piers: how many (at least 2). width: a pier's width 2b in the plane of rocking [m].
        depth: its depth out of that plane [m]. height: its height 2h [m]. unit_weight: the
        piers' [N/m³]. roof_mass: the roof's [kg]. roof_height: the roof's centroid above
        the piers' tops [m] (it translates: its height does not enter the motion). g: [m/s²].
    """

    piers: int
    width: float
    depth: float
    height: float
    unit_weight: float
    roof_mass: float
    roof_height: float
    g: float


def frame_side(frame: FrameGeometry, side: int) -> ChainSide:
    """The frame opening to ``side``, in its side frame (x into the pier from the pivot,
    z up): the piers as one body of their joint weight on link 0, the roof on link 1."""
    piers = prism(f"piers ({frame.piers})", 0.0, frame.width, 0.0, frame.height,
                  frame.depth * frame.piers, frame.unit_weight, frame.g)  # fmt: skip
    roof = Body("roof", frame.roof_mass * frame.g, 0.5 * frame.width,
                frame.height + frame.roof_height, 0.0, 0.0, 0.0, frame.roof_mass)  # fmt: skip
    motion = CappedPiers(frame.width, frame.height)
    return ChainSide(motion, ((0, piers), (1, roof)), frame.g, side=side)


def frame_chain(plus: ChainSide, minus: ChainSide, block: Rocker) -> Chain:
    """The frame as the engines rock it: a Chain carrying its table (its M(θ), V(θ), Γ(θ)
    from the configuration, its impact by projection); ``block`` gives the model's settings
    (motion, rebound, e's rule). Its α, which max θ/α divides by, is a pier's: where the
    weights' restoring moment vanishes."""
    body = composite([b for _, b in plus.bodies])
    table = replace(tabulate(plus, minus), centroid=(body.x, body.z))
    return Chain(
        **rocker_fields(
            block,
            R=math.hypot(body.x, body.z),
            alpha=min(instability(side, table.end) for side in (plus, minus)),
            mass=body.mass,
            linearized=False,
            restrainers=(),
            loads=(),
            thrusts=(),
            e_neg=None,
        ),
        table=table,
    )
