"""The block derived from a valid model must be finite: checked once, at the edge.

Every number of the file is bounded (:mod:`rockcli.model.bounds`), but a quantity derived
from several (m = W/g, p² = 3g/(4R), c_K = K r²/I0) can still leave double precision when the
inputs sit at opposite ends of their ranges, or come from a table whose bounds are looser
(``analysis.g``). Such a block would reach the engine and end in OverflowError, a division by
zero or a NaN that no guard catches; here it is an :class:`~rockcli.errors.InputError`
naming the keys it comes from.

Pure: :mod:`math`, the block and the error type only.
"""

from __future__ import annotations

import math

from rockcli.errors import InputError
from rockcli.mechanics import Block, Restrainer, restrainer_coefficient, uplift_accelerations
from rockcli.model.bounds import MAX_STIFFNESS, PRETENSION_ALLOWED

#: What a derived quantity must be.
FINITE_POSITIVE = "a finite number > 0 (the inputs it comes from are out of scale)"


def check_block(block: Block) -> None:
    """Raise InputError when a quantity the engine derives from the block is not usable.

    Checked: b, h, R, α, g, p² = 3g/(4R) (paper Eq. 2); with a mass, m, W = m g and
    I0 = 4/3 m R²; for each restrainer and side, c_K = K r²/I0 (paper §4.3) finite and
    r > 0.
    """
    _positive("the semi-diagonal R", block.R, "geometry")
    _positive("the half-thickness b = R sin α", block.b, "geometry")
    _positive("the half-height h = R cos α", block.h, "geometry")
    _positive("gravity g", block.g, "analysis.g")
    _positive("p² = 3g/(4R)", block.p2, "geometry, analysis.g")
    if block.mass is None:
        return
    _positive("the mass m = W/g", block.mass, "mass, analysis.g")
    _positive("the weight W = m g", block.weight, "mass, analysis.g")
    _positive("the polar inertia I0 = 4/3 m R²", block.inertia, "mass, geometry")
    if block.loaded:
        _check_loaded(block)
    for i, restrainer in enumerate(block.restrainers):
        _check_pretension(restrainer, f"restrainers[{i}].pretension")
        for side in (1, -1):
            k, r, _ = restrainer.side(side)
            where = f"restrainers[{i}]"
            if k > MAX_STIFFNESS:  # a tie-rod's E·A/L is derived, not bounded by the schema
                raise InputError(
                    "the stiffness E·A/L of this restrainer is out of range",
                    where=where,
                    value=k,
                    allowed=f"at most {MAX_STIFFNESS:g} N/m (check diameter, length and E)",
                )
            _positive("the distance r of the attachment point from the pivot", r, where)
            coefficient = restrainer_coefficient(k, r, block.inertia)
            if not math.isfinite(coefficient):
                raise InputError(
                    "the stiffness term K r²/I0 is not finite",
                    where=f"{where}, mass",
                    value=coefficient,
                    allowed="a stiffness and a weight of the same order as a real element's",
                )


def _check_pretension(restrainer: Restrainer, where: str) -> None:
    """The pretension below the yield force the member really has: a measured f_y is divided
    by FC where the block is derived, after the file's own check (schema) with f_y as given."""
    p0 = restrainer.pretension
    limit = min(restrainer.yield_pos, restrainer.yield_neg, restrainer.rupture_force)
    if p0 > 0.0 and p0 >= limit:
        raise InputError(
            f"not below the member's yield force {limit:g} N (its measured fy divided by FC)",
            where=where,
            value=p0,
            allowed=PRETENSION_ALLOWED,
        )


def _check_loaded(block: Block) -> None:
    """A block with loads or thrusts: not linearized, and standing at rest without an
    earthquake on every side it may turn to (α0 > 0; docs/physics.md, "Uplift, and α0")."""
    if block.linearized:
        raise InputError(
            "the linearized equation is written for the lone block",
            where="analysis.linearized",
            value=True,
            allowed="false with [[loads]] or [[thrusts]]",
        )
    sides = (block.free_side,) if block.one_sided else (1, -1)
    for side, a0 in zip((1, -1), uplift_accelerations(block), strict=True):
        if side in sides and not a0 > 0.0:
            raise InputError(
                f"the thrusts overturn the block towards θ {'>' if side > 0 else '<'} 0 "
                f"with no earthquake (uplift acceleration {a0:.4g} g)",
                where="thrusts",
                allowed="thrusts whose moment about the pivot is less than that of the "
                "weights (α0 > 0 on each side the block can turn to)",
            )


def _positive(what: str, value: float, where: str) -> None:
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"{what} is not usable", where=where, value=value, allowed=FINITE_POSITIVE)
