"""Every model as a catalogue of mechanisms, each derived once (a block file: a catalogue of one).

A :class:`Mechanism` is everything the code check and the time history read of one mechanism,
derived from the model once: its name and type, its hinge, the sides it can open to with the
code check's geometry of each (the block's closed forms, or the wall's placed bodies:
rockcli.mechanisms), where it stands in the building, whether it is free to vibrate and as
what member, the notes on how it was placed, and — built when first asked, as the chain's
table takes time — what the engines rock (``rocker``: the block itself, a RigidBody or a
Chain, with the e of its bodies). The catalogue is the one place that tells a block file from
a wall file; the analyses downstream read the values alone.

A vertical flexure's optimal hinge is searched here, once (the lowest α0 over the sides it can
open to: rockcli.mechanisms.catalogue.optimal_hinge), and every reader takes it from the value.

Pure: the model, the mechanisms and the code check's α0.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import cached_property, partial
from typing import TypeVar

from rockcli.codecheck.free import KAPPA_CANTILEVER, KAPPA_FLEXURE
from rockcli.codecheck.kinematic import Mechanism as SideCheck
from rockcli.codecheck.kinematic import alpha0
from rockcli.errors import InputError
from rockcli.mechanics import Block, Rocker
from rockcli.mechanisms.block import BlockSide
from rockcli.mechanisms.catalogue import (
    CrushingError,
    arch_numbers,
    build,
    flexure_at,
    flexure_range,
    hinge_of,
    optimal_hinge,
    overburden_above,
    overturning,
    sides_of,
    storey_of,
)
from rockcli.mechanisms.side import ChainSide
from rockcli.mechanisms.wall import (
    NOT_ROCKED,
    OPTIMAL,
    WHOLE_WALL,
    MechanismSpec,
    MechanismType,
    Wall,
)
from rockcli.model.schema import Model
from rockcli.notes import Note

T = TypeVar("T")

#: Unit mass given to a block without a [mass] table: the kinematic ratios (α0, e*, a0*, d0*)
#: of a block alone do not depend on its mass [kg].
UNIT_MASS = 1.0
#: An optimal hinge this close to an end of its range (a share of the range) is at the end.
RANGE_END = 1e-6


@dataclass(frozen=True)
class FreeMember:
    """A mechanism free to vibrate, as the member whose period T0 Circolare 7/2019 Eq.
    C8.7.1.7 gives: κ, its length L [m] and thickness t [m]; the masonry's unit weight
    [N/m³] and E [Pa] (None: not given); gravity [m/s²]."""

    kappa: float
    length: float
    thickness: float
    unit_weight: float
    E: float | None
    g: float


@dataclass(frozen=True)
class Opening:
    """One side of a mechanism as both analyses read it (:attr:`Mechanism.openings`).

    Attributes:
        side: +1 (θ > 0, outward for a wall) or −1.
        opens: True when the mechanism can open to this side (a side it cannot is still
            placed: the impact that ends a phase there).
        alpha0: the code check's α0 of this side (Circolare 7/2019 §C8.7.1.1; a restrainer
            as its ``code_action`` says: a tie-rod's design strength raises it).
        uplift: the ground acceleration that lifts it off this side from rest, in g (the
            engines' threshold; the restrainers' pretension alone enters, so without
            restrainers it is α0 to rounding).
        collapse: the rotation at which the weights stop restoring on this side [rad].
        restitution: the e applied at an impact that ends a phase on this side [-].
        e_rule: how e was set (the model's ``[restitution] rule``).
    """

    side: int
    opens: bool
    alpha0: float
    uplift: float
    collapse: float
    restitution: float
    e_rule: str


@dataclass(frozen=True)
class Mechanism:
    """One mechanism of a model, derived once (module docstring).

    Attributes:
        name, type: its label and which mechanism.
        hinge_height: its base hinge's height above the wall's base [m] (a vertical flexure:
            its intermediate hinge's, resolved).
        storey: a vertical flexure's storey (1 = ground), else None.
        sides: the sides it can open to (+1 outward, −1 inward).
        views: its geometry about each pivot, side +1 then side −1, which the code check reads
            and what the engines rock is built from: the block's closed forms
            (mechanisms.block.BlockSide) or the wall's bodies placed about the hinge
            (mechanisms.side.ChainSide). A side it cannot open to is placed too (the impact
            that ends a phase there).
        reported: the sides whose α0 the result reports (a block's: both, whichever it can
            open to).
        base: the height above the wall's base at which it stands in the building [m] (Z +
            base: ψ and the floor spectra there).
        wall_height, storey_count: the wall's height [m] and storeys (for a building's H and
            N not given).
        free: the member of a mechanism declared free to vibrate (None: rigid until it
            activates).
        notes: how it was placed: its optimal hinge, what a flexure carries.
        strength_notes: the hinges set back by the stress block (f_m given).
        model: the model it comes from (the engine's settings and e rule).
        wall, spec: the wall and its entry (None for a block file).
        block: what the engines rock, derived with the file: a block file's block, a
            frame's chain (None for a wall's mechanism: built when first asked).
    """

    name: str
    type: MechanismType
    hinge_height: float
    storey: int | None
    sides: tuple[int, ...]
    views: tuple[BlockSide | ChainSide, BlockSide | ChainSide]
    reported: tuple[int, ...]
    base: float
    wall_height: float
    storey_count: int
    free: FreeMember | None
    notes: tuple[Note, ...]
    strength_notes: tuple[Note, ...]
    model: Model
    wall: Wall | None = None
    spec: MechanismSpec | None = None
    block: Rocker | None = None

    def view(self, side: int) -> BlockSide | ChainSide:
        """Its geometry about the pivot of ``side``."""
        return self.views[0 if side > 0 else 1]

    def check(self, side: int, distributed: bool, per_block: bool) -> SideCheck:
        """The code check's view of ``side`` with the edition's sums (codecheck.kinematic)."""
        return SideCheck(self.view(side), distributed=distributed, per_block=per_block)

    @cached_property
    def openings(self) -> tuple[Opening, Opening]:
        """Side +1 then side −1, each with its α0, uplift, collapse rotation and e, read from
        its one placement (``views``) and what the engines rock of it (``rocker``)."""
        from rockcli.mechanics import collapse_rotations, uplift_accelerations

        rocker = self.rocker
        uplifts, collapses = uplift_accelerations(rocker), collapse_rotations(rocker)
        rule = self.model.restitution.rule.value
        return tuple(  # type: ignore[return-value]
            Opening(
                side=s,
                opens=s in self.sides,
                alpha0=alpha0(SideCheck(self.view(s))),
                uplift=uplifts[k],
                collapse=collapses[k],
                restitution=rocker.restitution(s),
                e_rule=rule,
            )
            for k, s in enumerate((1, -1))
        )

    @cached_property
    def rocker(self) -> Rocker:
        """What the engines rock, with the e of its bodies (rockcli.model.derive
        .with_system_restitution): the block file's Block; a wall's rigid mechanism as a
        RigidBody of its own shape; a vertical flexure as a Chain (its table built here)."""
        from rockcli.mechanisms.flexure import flexure_block
        from rockcli.mechanisms.rigid import rigid_block
        from rockcli.model.derive import derive_block, with_system_restitution

        if self.block is not None:
            return self.block
        if self.type in NOT_ROCKED:
            raise InputError(
                NOT_ROCKED[self.type],
                where="--mechanism",
                value=self.name,
                allowed="a mechanism that rocks (overturning, wedge, vertical flexure, gable)",
            )
        block = derive_block(self.model)
        plus, minus = self.views
        assert isinstance(plus, ChainSide) and isinstance(minus, ChainSide)
        if self.type is MechanismType.VERTICAL_FLEXURE:
            assert self.storey is not None and self.wall is not None
            top = self.wall.storeys[self.storey - 1].height  # above the storey's base
            rocker: Rocker = flexure_block(plus, minus, top, block)
        else:
            rocker = rigid_block(plus, minus, block, wedge=self.type is MechanismType.WEDGE)
        return with_system_restitution(rocker, self.model)


def named(items, name: str, where: str = "--mechanism", problem: str = "no such mechanism"):
    """The item of ``items`` (mechanisms, specs, results: anything with a ``name``) called
    ``name``; InputError naming ``where`` and every name there is otherwise."""
    for item in items:
        if item.name == name:
            return item
    raise InputError(
        problem,
        where=where,
        value=name,
        allowed="one of: " + "; ".join(f"'{item.name}'" for item in items),
    )


def catalogue(model: Model) -> tuple[Mechanism, ...]:
    """Every mechanism of the model in the file's order: a wall's ``[[mechanisms]]`` (none:
    its overturning about the base), or a block file's block (its overturning)."""
    if model.frame is not None:
        return (frame_mechanism(model),)
    if block_file(model):
        return (block_mechanism(model),)
    from rockcli.model.derive_wall import to_wall

    wall = to_wall(model)
    free = free_side_of(model)
    return tuple(wall_mechanism(model, wall, spec, free) for spec in wall.mechanisms)


def block_file(model: Model) -> bool:
    """True for a model file of one block (no storeys, no ``[[mechanisms]]``): its catalogue
    is the block's overturning. The one place that tells the file's two forms apart."""
    return model.geometry.storeys is None and not model.mechanisms and model.frame is None


def rocks_its_block(model: Model) -> bool:
    """True when the model's catalogue is one mechanism that rocks as the paper's rectangle
    (a block file): its sizes are the block's R and α, which a spectrum over sizes varies."""
    mechanisms = catalogue(model)
    return len(mechanisms) == 1 and isinstance(mechanisms[0].block, Block)


def first_mechanism(model: Model) -> Mechanism:
    """The catalogue's first mechanism alone, derived as :func:`catalogue` derives it."""
    if model.frame is not None:
        return frame_mechanism(model)
    if block_file(model):
        return block_mechanism(model)
    from rockcli.model.derive_wall import to_wall

    wall = to_wall(model)
    return wall_mechanism(model, wall, wall.mechanisms[0], free_side_of(model))


def named_mechanism(model: Model, name: str) -> Mechanism:
    """The catalogue's mechanism ``name`` alone, derived as :func:`catalogue` derives it
    (InputError naming the catalogue's names)."""
    if model.frame is not None:
        return named((frame_mechanism(model),), name)
    if block_file(model):
        return named((block_mechanism(model),), name)
    from rockcli.model.derive_wall import to_wall

    wall = to_wall(model)
    return wall_mechanism(model, wall, named(wall.mechanisms, name), free_side_of(model))


def free_side_of(model: Model) -> int | None:
    """The side a wall stopped on one side can open to (None: both)."""
    from rockcli.model.derive import free_side
    from rockcli.model.schema import Sides

    motion = model.motion
    return free_side(motion.stopped) if motion.sides is Sides.ONE else None


def block_view(block: Block, side: int) -> BlockSide:
    """The block's closed forms on ``side`` (a unit mass when the model gives none)."""
    if block.mass is None:
        block = replace(block, mass=UNIT_MASS)
    return BlockSide(block, side)


#: The name of a frame's one mechanism.
FRAME = Note("name_frame", "rocking frame")


def frame_mechanism(model: Model) -> Mechanism:
    """A frame file's one mechanism: the piers rocking under their roof (rockcli.mechanisms
    .frame), each side's chain for the code check and, derived here, the Chain the engines
    rock (its table) with the e of its impact (Housner's rule: the projection's)."""
    from rockcli.mechanisms.frame import FrameGeometry, frame_chain, frame_side
    from rockcli.model.derive import derive_block, with_system_restitution

    table = model.frame
    assert table is not None and model.mass is not None and model.mass.unit_weight is not None
    frame = FrameGeometry(table.piers, table.pier_width, table.pier_depth, table.pier_height,
                          model.mass.unit_weight * 1e3, table.roof_mass, table.roof_height,
                          model.analysis.g)  # fmt: skip
    plus, minus = frame_side(frame, 1), frame_side(frame, -1)
    block = derive_block(model)
    chain = with_system_restitution(frame_chain(plus, minus, block), model)
    return own_mechanism(model, FRAME, (plus, minus), chain, table.pier_height,
                         (frame_note(frame, plus, chain),))  # fmt: skip


def own_mechanism(
    model: Model,
    name: str,
    views: tuple[BlockSide | ChainSide, ...],
    rocker: Rocker,
    height: float,
    notes: tuple[Note, ...] = (),
) -> Mechanism:
    """The one mechanism of a file that is its element (a block, a frame): its overturning
    about its base, its views and what the engines rock derived with the file."""
    sides = (rocker.free_side,) if rocker.one_sided else (1, -1)
    return Mechanism(
        name=name,
        type=MechanismType.OVERTURNING,
        hinge_height=0.0,
        storey=None,
        sides=sides,
        views=(views[0], views[1]),
        block=rocker,
        reported=(1, -1),
        base=0.0,
        wall_height=height,
        storey_count=1,
        free=None,
        notes=notes,
        strength_notes=(),
        model=model,
    )


def frame_note(frame, plus: ChainSide, chain: Rocker) -> Note:
    """The frame in a sentence: its piers and roof, γ, and what the roof does to p and e."""
    piers = plus.bodies[0][1]  # the piers' joint body (rockcli.mechanisms.frame.frame_side)
    gamma = frame.roof_mass / piers.mass
    return Note("frame", "rocking frame of {n} piers {w:g} × {d:g} × {h:g} m capped by a roof "
                "of {m:.4g} t (γ = m_roof/Σ m_pier = {gamma:.4g}): uplift at g·tan α of a "
                "pier, p = {p:.5g} rad/s, e = {e:.5g} (Makris & Vassiliou 2013)",
                n=frame.piers, w=frame.width, d=frame.depth, h=frame.height,
                m=frame.roof_mass / 1e3, gamma=gamma, p=chain.p, e=chain.e)  # fmt: skip


def block_mechanism(model: Model) -> Mechanism:
    """The block file's one mechanism: the block's overturning about its base edge (the block
    derived once: the code check's views and what the engines rock)."""
    from rockcli.model.derive import to_block

    block: Block = to_block(model)
    views = (block_view(block, 1), block_view(block, -1))
    return own_mechanism(model, WHOLE_WALL, views, block, 2.0 * block.h)


def wall_mechanism(model: Model, wall: Wall, spec: MechanismSpec, free: int | None) -> Mechanism:
    """One mechanism of a wall: its hinge resolved, each side placed, its notes."""
    sides = sides_of(spec, free)
    spec, hinge_notes = resolved(wall, spec, sides)
    strength: tuple[Note, ...] = ()
    if wall.f_m is not None and spec.type not in (MechanismType.HORIZONTAL_FLEXURE,
                                                  MechanismType.CORNER):  # fmt: skip
        strength = (Note("set_back", "hinges set back by half the stress block "
                         "a = N/(f_m·width), f_m = {f_m:g} MPa", f_m=wall.f_m / 1e6),)  # fmt: skip
    hinge = spec.hinge_height if isinstance(spec.hinge_height, float) else hinge_of(spec, wall)
    return Mechanism(
        name=spec.name,
        type=spec.type,
        hinge_height=hinge,
        storey=spec.storey,
        sides=sides,
        views=(placed(wall, spec, 1), placed(wall, spec, -1)),
        reported=sides,
        base=spec_base(wall, spec),
        wall_height=wall.height,
        storey_count=len(wall.storeys),
        free=free_member(wall, spec) if spec.free else None,
        notes=(
            *hinge_notes,
            *flexure_notes(wall, spec),
            *arch_notes(wall, spec),
            *corner_notes(wall, spec),
        ),
        strength_notes=strength,
        model=model,
        wall=wall,
        spec=spec,
    )


def placed(wall: Wall, spec: MechanismSpec, side: int) -> ChainSide:
    """The mechanism's bodies about its hinge on ``side`` (InputError when the wall crushes
    first: the stress block deeper than the section)."""
    return uncrushed(wall, lambda: build(wall, spec, side))


def uncrushed(wall: Wall, make: Callable[[], T]) -> T:
    """``make()``, its CrushingError (a stress block deeper than the section) said as the
    wall's bad input."""
    try:
        return make()
    except CrushingError as exc:
        raise InputError(
            f"the wall crushes before it rocks: at a hinge of '{exc.hinge}' the stress block "
            f"is {exc.depth:.3g} m deep, the section {exc.thickness:.3g} m",
            where="masonry.f_m",
            value=wall.f_m,
            allowed="a strength at which the weight above each hinge needs a stress block "
            "thinner than the wall (a = N/(f_m·width))",
        ) from None


#: The optimal hinge's note: where it was found, and why its range.
FLEXURE_FOUND = ("optimal hinge at {z:.3f} m (the lowest α0 between {lo:.3f} and {hi:.3f} m: "
                 "the storey less max(thickness, a tenth of its height) at each end)")  # fmt: skip
OVERTURNING_FOUND = ("optimal hinge at {z:.3f} m (the lowest α0 between {lo:.3f} and {hi:.3f} "
                     "m: the wall's base up to its top less max(the top storey's thickness, a "
                     "tenth of the wall's height))")  # fmt: skip
#: ... and when it lies at an end of its range.
AT_END = ("; the optimum lies at the end of the range, which decides it (α0 keeps falling "
          "towards it): give hinge_height where a crack shows the hinge")  # fmt: skip


def resolved(wall: Wall, spec: MechanismSpec, sides: tuple[int, ...]):
    """The spec with an optimal hinge found: the height that minimises the smaller α0 of its
    sides (rockcli.mechanisms.catalogue.optimal_hinge), and its note. A vertical flexure's
    intermediate hinge inside its storey; an overturning's base hinge anywhere up the wall
    (Circolare 7/2019 §C8.7.1.2.1.1: the hinge's position, and the height h of a toothing's
    friction, "dovrebbe derivare ... da un processo di minimizzazione")."""
    if spec.hinge_height != OPTIMAL:
        return spec, ()
    flexure = spec.type is MechanismType.VERTICAL_FLEXURE
    if flexure:
        assert spec.storey is not None
        lo, hi = flexure_range(wall, spec.storey)
        families = [uncrushed(wall, partial(flexure_at, wall, spec.storey, s, spec.name))
                    for s in sides]  # fmt: skip
    else:
        lo, hi = overturning_range(wall)
        families = [partial(_overturning_at, wall, spec, s) for s in sides]

    def smallest(z: float) -> float:
        return min(alpha0(SideCheck(uncrushed(wall, partial(f, z)))) for f in families)

    attached = [*(ld.z for ld in wall.loads), *(th.z for th in wall.thrusts),
                *(rs.z for rs in wall.restrainers), *wall.storey_bases()]  # fmt: skip
    z = optimal_hinge(lo, hi, smallest, attached)
    return replace(spec, hinge_height=z), (hinge_note(flexure, z, lo, hi),)


def hinge_note(flexure: bool, z: float, lo: float, hi: float) -> Note:
    """Where the optimal hinge was found in its range [lo, hi], and whether at an end."""
    values = {"z": z, "lo": lo, "hi": hi}
    # an overturning's range starts at the wall's base, a hinge the wall has: only its top
    # end is the range's own
    low = z - lo if flexure else math.inf
    at_end = min(low, hi - z) <= RANGE_END * (hi - lo)
    if flexure:
        if at_end:
            return Note("hinge_at_end", FLEXURE_FOUND + AT_END, **values)
        return Note("hinge_optimal", FLEXURE_FOUND, **values)
    if at_end:
        return Note("hinge_at_end_overturning", OVERTURNING_FOUND + AT_END, **values)
    return Note("hinge_optimal_overturning", OVERTURNING_FOUND, **values)


def _overturning_at(wall: Wall, spec: MechanismSpec, side: int, hinge: float) -> ChainSide:
    """The overturning of ``spec`` about a section at ``hinge`` [m], opening to ``side``."""
    return overturning(wall, hinge, side, spec.name, spec.friction)


def overturning_range(wall: Wall) -> tuple[float, float]:
    """Where an overturning's optimal hinge is searched [m above the wall's base]: from the
    base up to the top less the larger of the top storey's thickness and a tenth of the
    wall's height (a part squatter than the wall is thick is no overturning block)."""
    margin = max(wall.storeys[-1].thickness, 0.1 * wall.height)
    return 0.0, wall.height - margin


def spec_base(wall: Wall, spec: MechanismSpec) -> float:
    """The height above the wall's base at which the mechanism stands in the building [m].

    Circolare 617/2009 §C8A.4.2.2 defines Z as "l'altezza, rispetto alla fondazione
    dell'edificio, del baricentro delle linee di vincolo tra i blocchi interessati dal
    meccanismo ed il resto della struttura": a rigid mechanism's one line, its base hinge; a
    vertical flexure's two, its storey's base and its held top, whose centroid is the middle
    of the storey. Circolare 7/2019 names only "la quota z a cui si colloca il meccanismo"
    (§C8.7.1.2.1.5) and is read the same way (docs/interpretations.md).
    """
    if spec.type is MechanismType.VERTICAL_FLEXURE:
        assert spec.storey is not None
        storey = wall.storeys[spec.storey - 1]
        return wall.storey_bases()[spec.storey - 1] + 0.5 * storey.height
    if spec.type is MechanismType.HORIZONTAL_FLEXURE:  # the strip's middle
        assert spec.level is not None and spec.strip_height is not None
        return spec.level + 0.5 * spec.strip_height
    return hinge_of(spec, wall)


def free_member(wall: Wall, spec: MechanismSpec) -> FreeMember:
    """The member of a mechanism free to vibrate (Circolare 7/2019 Eq. C8.7.1.7): the gable,
    a cantilever of its height on the last storey's thickness (κ = 6.2); an overturning, a
    cantilever of the wall above its hinge, gable included, on the hinge section's thickness
    (κ = 6.2); a vertical flexure, a beam of its storey's height and thickness simply
    supported at its ends (κ = 2.2)."""
    gable = wall.gable_height or 0.0
    if spec.type is MechanismType.GABLE:
        kappa, length, thickness = KAPPA_CANTILEVER, gable, wall.storeys[-1].thickness
    elif spec.type is MechanismType.VERTICAL_FLEXURE:
        assert spec.storey is not None
        storey = wall.storeys[spec.storey - 1]
        kappa, length, thickness = KAPPA_FLEXURE, storey.height, storey.thickness
    else:
        hinge = hinge_of(spec, wall)
        k = storey_of(wall, hinge)
        kappa, length = KAPPA_CANTILEVER, wall.height - hinge + gable
        thickness = wall.storeys[k].thickness
    return FreeMember(kappa, length, thickness, wall.unit_weight, wall.E, wall.g)


def corner_notes(wall: Wall, spec: MechanismSpec) -> tuple[Note, ...]:
    """What a corner leaves out: the model's loads, thrusts and restrainers (its own hip
    thrust aside), and the masonry's stress block at its point pivot (none for other
    types)."""
    if spec.type is not MechanismType.CORNER:
        return ()
    return (Note("corner_alone", "corner: the wedge alone with its hip_thrust; the model's "
                 "loads, thrusts and restrainers are not on it (give a roof's push at the "
                 "corner as hip_thrust) and its pivot is the outer corner, not set back by a "
                 "stress block"),)  # fmt: skip


def arch_notes(wall: Wall, spec: MechanismSpec) -> tuple[Note, ...]:
    """A horizontal flexure's arch in a sentence: its thrust, stress block and what limits
    the thrust (none for other types)."""
    if spec.type is not MechanismType.HORIZONTAL_FLEXURE:
        return ()
    arch = arch_of(wall, spec)
    if spec.thrust_limit is not None and arch.thrust < arch.best:
        return (Note("arch_limited", "horizontal flexure: a three-hinge arch in plan of span "
                     "{span:g} m on a strip {b:g} m high and {s:g} m thick, its thrust "
                     "H = {H:.4g} kN limited by {by} (below the masonry's H* = f_m·b·s/2 = "
                     "{best:.4g} kN), stress blocks a = H/(f_m·b) = {a:.4g} m deep, lever "
                     "s − a = {lever:.4g} m", span=arch.span, b=arch.strip, s=arch.thickness,
                     H=arch.thrust / 1e3, by=str(spec.limit_by), best=arch.best / 1e3,
                     a=arch.depth, lever=arch.thickness - arch.depth),)  # fmt: skip
    return (Note("arch_rigid", "horizontal flexure: a three-hinge arch in plan of span {span:g} "
                 "m on a strip {b:g} m high and {s:g} m thick between rigid abutments, its "
                 "thrust H* = f_m·b·s/2 = {H:.4g} kN (the largest moment H·(s − a)), stress "
                 "blocks a = H/(f_m·b) = {a:.4g} m deep, lever s − a = {lever:.4g} m",
                 span=arch.span, b=arch.strip, s=arch.thickness, H=arch.thrust / 1e3,
                 a=arch.depth, lever=arch.thickness - arch.depth),)  # fmt: skip


@dataclass(frozen=True)
class Arch:
    """A horizontal flexure's arch: span, strip height, thickness [m], its thrust and the
    masonry's best thrust f_m·b·s/2 [N], the stress block's depth a [m]."""

    span: float
    strip: float
    thickness: float
    thrust: float
    best: float
    depth: float


def arch_of(wall: Wall, spec: MechanismSpec) -> Arch:
    """The arch of a horizontal flexure, as rockcli.mechanisms.catalogue.horizontal_flexure
    places it (its ``arch_numbers``)."""
    assert spec.strip_height is not None and spec.span is not None
    s, thrust, best, depth = arch_numbers(wall, spec)
    return Arch(spec.span, spec.strip_height, s, thrust, best, depth)


def flexure_notes(wall: Wall, spec: MechanismSpec) -> tuple[Note, ...]:
    """What a vertical flexure carries from above, in a sentence (none for other types)."""
    if spec.type is not MechanismType.VERTICAL_FLEXURE or spec.storey is None:
        return ()
    weight, x = overburden_above(wall, spec.storey)
    if weight <= 0.0:
        return (Note("flexure_nothing_above", "vertical flexure: nothing above the storey's top "
                     "but the loads at it"),)  # fmt: skip
    return (Note("flexure_above", "vertical flexure: the wall above (storeys, gable, bearing "
                 "loads) bears on the held top, {weight:.4g} kN at {x:.3f} m from the outer "
                 "face, without horizontal inertia", weight=weight / 1e3, x=x),)  # fmt: skip
