"""The catalogue: every local mechanism of a wall, as one geometry per side.

From the wall (rockcli.mechanisms.wall, its frame: x inward from the outer face, z up from the
base) each ``[[mechanisms]]`` entry becomes, for each side it can open to, a
:class:`rockcli.mechanisms.side.ChainSide` in the side frame of its base hinge:

- **overturning** about a storey's base (Circ. 7/2019 §C8.7.1 and its commentary's
  "ribaltamento semplice"; Circ. 617/2009 §C8A.4): the storeys above the hinge, the gable,
  and the loads, thrusts and restrainers above the hinge, one rigid body turning about the
  outer edge (side 1) or the inner edge (side −1) of the hinge section;
- **wedge** ("ribaltamento composto"): the whole wall with a triangular wedge of each return
  wall, bounded by a crack from the base corner at ``angle`` from the vertical, turning with
  the façade about its outer base edge (side 1 only);
- **vertical flexure** ("flessione verticale"): a storey as two blocks — the lower about the
  outer edge of the storey's base, an intermediate hinge on the inner face, the upper about
  the outer face at the top, which is held horizontally and free to rise (side −1 mirrors it)
  (Doherty et al. 2002, EESD 31:833–850; Sorrentino, Masiani & Griffith 2008);
- **gable** ("ribaltamento del timpano"): the triangular gable about its base;
- **corner** ("ribaltamento del cantonale"): the corner of the wall and a return wall,
  cracked in each along a line from the outer base corner at ``angle`` from the vertical,
  turning out about the horizontal axis through that corner normal to its bisector (see
  :func:`corner`);
- **horizontal flexure** ("flessione orizzontale", the arch effect in plan): a strip of the
  wall between the return walls as a three-hinge flat arch, each half turning about its
  abutment's hinge on one face towards the mid-span hinge on the other, held by the arch's
  thrust H (see :func:`horizontal_flexure`).

A load, thrust or restrainer exactly at a hinge's height belongs to the part below it. With a
masonry strength f_m each hinge moves inward from its edge by half the depth a = N/(f_m·width)
of the stress block that carries the weight N above it (*arretramento della cerniera*).

Pure and silent: only :mod:`math`, the package's own modules and :mod:`rockcli.searches`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from rockcli.mechanisms.bodies import Body, gable, prism, triangle
from rockcli.mechanisms.links import Rotation, TwoBlock
from rockcli.mechanisms.side import Attached, ChainSide, SideFriction, SideLoad, SideThrust
from rockcli.mechanisms.wall import MechanismSpec, MechanismType, Toothing, Wall
from rockcli.searches import brent_minimum

#: Relative tolerance of "at a hinge's height" (heights typed in the file and sums of storey
#: heights agree to far better than this).
SAME_HEIGHT = 1e-9


class CrushingError(ValueError):
    """The stress block at a hinge is deeper than the section: the wall crushes first."""

    def __init__(self, hinge: str, depth: float, thickness: float):
        super().__init__(hinge)
        self.hinge, self.depth, self.thickness = hinge, depth, thickness


def same_height(a: float, b: float) -> bool:
    """True when two heights are the same to SAME_HEIGHT (relative, and 1e-9 m absolute)."""
    return math.isclose(a, b, rel_tol=SAME_HEIGHT, abs_tol=SAME_HEIGHT)


def above(z: float, hinge: float) -> bool:
    """True when a point at height z is above the hinge (one at the hinge is below it): z > hinge
    and not :func:`same_height` — written out, as the catalogue asks it of every load at every
    hinge it tries."""
    return z - hinge > SAME_HEIGHT * max(abs(z), abs(hinge), 1.0)


def storey_bodies(wall: Wall, from_storey: int) -> list[Body]:
    """The storeys from index ``from_storey`` (0-based) up, and the gable, in the wall frame."""
    bases = wall.storey_bases()
    out = [
        prism(f"storey {i + 1}", 0.0, s.thickness, bases[i], bases[i] + s.height, wall.width,
              wall.unit_weight, wall.g)
        for i, s in enumerate(wall.storeys) if i >= from_storey
    ]  # fmt: skip
    if wall.gable_height is not None:
        out.append(gable_body(wall))
    return out


def gable_body(wall: Wall) -> Body:
    """The gable: a triangle of base ``width`` on the last storey, of its thickness."""
    t = wall.storeys[-1].thickness
    return gable("gable", t, wall.height, wall.gable_height or 0.0, wall.width,
                 wall.unit_weight, wall.g)  # fmt: skip


def wedge_body(wall: Wall, angle: float, sides: int) -> Body:
    """The return walls' wedges: a triangle from the base corner at the façade's inner face
    (the ground storey's), up the wall's height, opening at ``angle`` from the vertical
    (h·tan β wide at the top), of the return walls' thickness times ``sides``."""
    t, h = wall.storeys[0].thickness, wall.height
    depth = (wall.return_wall_thickness or 0.0) * sides
    name = "wedge (both return walls)" if sides == 2 else "wedge (one return wall)"
    return triangle(name, ((t, 0.0), (t, h), (t + h * math.tan(angle), h)), depth,
                    wall.unit_weight, wall.g)  # fmt: skip


@dataclass(frozen=True)
class Frame:
    """The side frame of a pivot at (x0, z0) of the wall: x into the wall from it, z up."""

    x0: float
    z0: float
    side: int

    def x(self, x: float) -> float:
        """x in the side frame."""
        return (x - self.x0) if self.side > 0 else (self.x0 - x)

    def z(self, z: float) -> float:
        """z in the side frame."""
        return z - self.z0

    def body(self, b: Body) -> Body:
        """A body in the side frame."""
        return b.moved(self.x(b.x), self.z(b.z))


def stress_block(wall: Wall, weight: float) -> float:
    """Depth a = N/(f_m·width) of the stress block carrying N [N] [m] (0 without f_m)."""
    return 0.0 if wall.f_m is None else weight / (wall.f_m * wall.width)


def weight_above(wall: Wall, bodies: list[Body], hinge: float) -> float:
    """The weight bearing on a hinge: the bodies given and the bearing loads above it [N]."""
    loads = sum(ld.weight for ld in wall.loads if ld.bears and above(ld.z, hinge))
    return sum(b.weight for b in bodies) + loads


def set_back(wall: Wall, bodies: list[Body], hinge: float, thickness: float, name: str) -> float:
    """How far the hinge moves in from the section's edge: half the stress block [m]."""
    return half_block(wall, weight_above(wall, bodies, hinge), thickness, name)


def rigid(wall: Wall, bodies: list[Body], hinge: float, thickness: float, side: int,
          name: str, friction: bool = False) -> ChainSide:  # fmt: skip
    """One rigid body (``bodies`` together) about the edge of a hinge section at ``hinge`` of
    ``thickness``, with everything above the hinge on it (and, with ``friction``, the toothed
    return walls' friction over the storeys above the hinge)."""
    a = set_back(wall, bodies, hinge, thickness, name)
    frame = Frame(a if side > 0 else thickness - a, hinge, side)

    def on(z: float) -> int | None:
        return 0 if above(z, hinge) else None

    placed = attach(wall, frame, Rotation(), [(0, frame.body(b)) for b in bodies], on)
    if not friction or wall.toothing is None:
        return placed
    height = wall.height - hinge
    force = friction_force(wall.toothing, height) * wall.toothing.walls
    rub = SideFriction(FRICTION, force, 0, frame.x(0.5 * thickness), frame.z(hinge), height,
                       wall.toothing.overlap)  # fmt: skip
    return replace(placed, frictions=(rub,))


#: The name of the toothed return walls' friction on a mechanism.
FRICTION = "friction of the return walls"


def friction_force(toothing: Toothing, height: float) -> float:
    """F = 0.4·n(n+1)·Φ·μ·l²·t_s·W of one return wall toothed over ``height`` h [N]
    (Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.2): n = h/h_b the courses the vertical
    crack crosses, Φ = h_b/l the toothing coefficient, l the overlap, μ the friction
    coefficient, t_s the return wall's thickness, W the masonry's unit weight. Applied at
    h/3 (the same clause). n is h/h_b as the text writes it, not rounded to whole courses
    (docs/interpretations.md)."""
    n = height / toothing.course_height
    phi = toothing.course_height / toothing.overlap
    return (0.4 * n * (n + 1.0) * phi * toothing.mu * toothing.overlap**2
            * toothing.thickness * toothing.unit_weight)  # fmt: skip


def attach(wall: Wall, frame: Frame, motion, bodies, link_of: Callable[[float], int | None]):
    """The mechanism with the wall's loads, thrusts and restrainers on the link ``link_of``
    their height (None: not on the mechanism)."""
    loads, thrusts, members, anchors = [], [], [], []
    for ld in wall.loads:
        if (k := link_of(ld.z)) is not None:
            at = Attached(k, frame.x(ld.x), frame.z(ld.z))
            loads.append(SideLoad(ld.name, ld.weight, at, ld.bears, ld.moves))
    for th in wall.thrusts:
        if (k := link_of(th.z)) is not None:
            at = Attached(k, frame.x(th.x), frame.z(th.z))
            thrusts.append(SideThrust(th.name, th.force, th.direction * frame.side, at))
    for rs in wall.restrainers:
        if (k := link_of(rs.z)) is not None:
            members.append(rs.member)
            anchors.append(Attached(k, frame.x(rs.x), frame.z(rs.z)))
    return ChainSide(motion=motion, bodies=tuple(bodies), g=wall.g, loads=tuple(loads),
                     thrusts=tuple(thrusts), restrainers=tuple(members),
                     anchors=tuple(anchors), side=frame.side)  # fmt: skip


def storey_at(wall: Wall, hinge: float) -> int:
    """The index (0-based) of the storey whose base is at ``hinge`` [m]."""
    return next(i for i, b in enumerate(wall.storey_bases()) if same_height(b, hinge))


def storey_of(wall: Wall, z: float) -> int:
    """The index (0-based) of the storey a section at height ``z`` cuts (at a storey's base,
    the storey above it; at the top or above, the last)."""
    bases = wall.storey_bases()
    return max(i for i, b in enumerate(bases) if i == 0 or not above(b, z))


def parts_above(wall: Wall, hinge: float) -> list[Body]:
    """The wall above a section at ``hinge`` [m]: each storey's part above it (whole above a
    storey's base) and the gable, in the wall frame."""
    bases = wall.storey_bases()
    out = []
    for i, s in enumerate(wall.storeys):
        top = bases[i] + s.height
        if not above(top, hinge):
            continue
        bottom = bases[i] if not above(hinge, bases[i]) else hinge
        out.append(prism(f"storey {i + 1}", 0.0, s.thickness, bottom, top, wall.width,
                         wall.unit_weight, wall.g))  # fmt: skip
    if wall.gable_height is not None:
        out.append(gable_body(wall))
    return out


def rigid_parts(wall: Wall, spec: MechanismSpec) -> tuple[list[Body], float, float]:
    """(bodies, hinge height [m], thickness of the hinge section [m]) of a mechanism of one
    rigid body: the storeys above the hinge and the gable (overturning), the whole wall and
    the return walls' wedge (wedge), the gable alone (gable)."""
    hinge = hinge_of(spec, wall)
    if spec.type is MechanismType.GABLE:
        return [gable_body(wall)], hinge, wall.storeys[-1].thickness
    if spec.type is MechanismType.WEDGE:
        assert spec.angle is not None and spec.sides is not None
        bodies = [*storey_bodies(wall, 0), wedge_body(wall, spec.angle, spec.sides)]
        return bodies, hinge, wall.storeys[0].thickness
    return parts_above(wall, hinge), hinge, wall.storeys[storey_of(wall, hinge)].thickness


def overturning(wall: Wall, hinge: float, side: int, name: str, friction: bool = False
                ) -> ChainSide:  # fmt: skip
    """The part of the wall above a section at ``hinge`` [m] (a storey's base, or any height
    an optimal hinge is searched at), about that section; with ``friction``, resisted by the
    toothed return walls over its height."""
    spec = MechanismSpec(name, MechanismType.OVERTURNING, hinge)
    return rigid(wall, *rigid_parts(wall, spec), side, name, friction)


def wedge(wall: Wall, angle: float, sides: int, name: str, side: int = 1) -> ChainSide:
    """The whole wall and its return walls' wedge about the façade's outer base edge (it
    opens outward only: side −1, about the inner edge, places it for its impact there)."""
    spec = MechanismSpec(name, MechanismType.WEDGE, angle=angle, sides=sides)
    return rigid(wall, *rigid_parts(wall, spec), side, name)


def gable_mechanism(wall: Wall, side: int, name: str) -> ChainSide:
    """The gable about its base on the last storey."""
    spec = MechanismSpec(name, MechanismType.GABLE)
    return rigid(wall, *rigid_parts(wall, spec), side, name)


def flexure(wall: Wall, storey: int, hinge: float, side: int, name: str) -> ChainSide:
    """Vertical flexure of ``storey`` (1 = ground) with the intermediate hinge at ``hinge``
    [m above the wall's base]: two blocks between the storey's base and its held top."""
    return flexure_at(wall, storey, side, name)(hinge)


def flexure_at(wall: Wall, storey: int, side: int, name: str) -> Callable[[float], ChainSide]:
    """:func:`flexure` as a function of the hinge's height, what does not depend on it found
    once (the search for the optimal hinge tries some hundred heights)."""
    base = wall.storey_bases()[storey - 1]
    s = wall.storeys[storey - 1]
    top = base + s.height
    w_above, x_above = overburden_above(wall, storey)
    a_top = half_block(wall, bearing(wall, top, top, at_top=True) + w_above, s.thickness, name)
    outer = side > 0
    top_x = a_top if outer else s.thickness - a_top

    def at(hinge: float) -> ChainSide:
        lower = prism("lower block", 0.0, s.thickness, base, hinge, wall.width,
                      wall.unit_weight, wall.g)  # fmt: skip
        upper = prism("upper block", 0.0, s.thickness, hinge, top, wall.width,
                      wall.unit_weight, wall.g)  # fmt: skip
        on_upper = bearing(wall, hinge, top) + w_above
        on_lower = bearing(wall, base, hinge)
        a_mid = half_block(wall, upper.weight + on_upper, s.thickness, name)
        a_base = half_block(wall, lower.weight + upper.weight + on_upper + on_lower,
                            s.thickness, name)  # fmt: skip
        frame = Frame(a_base if outer else s.thickness - a_base, base, side)
        mid_x = s.thickness - a_mid if outer else a_mid
        motion = TwoBlock(frame.x(mid_x), frame.z(hinge), frame.x(top_x), frame.z(top))

        def link_of(z: float) -> int | None:
            if not above(z, base) or above(z, top):
                return None
            return 1 if above(z, hinge) else 0

        side_view = attach(wall, frame, motion,
                           [(0, frame.body(lower)), (1, frame.body(upper))], link_of)  # fmt: skip
        if w_above <= 0.0:
            return side_view
        load = SideLoad(ABOVE, w_above, Attached(1, frame.x(x_above), frame.z(top)), bears=True,
                        moves=False)  # fmt: skip
        return replace(side_view, loads=(*side_view.loads, load))

    return at


#: The name of a vertical flexure's overburden from the wall above.
ABOVE = "the wall above"


def overburden_above(wall: Wall, storey: int) -> tuple[float, float]:
    """(N [N], x [m]) of what bears on the top of ``storey`` from above: the storeys above,
    the gable and the bearing loads above its top, and the x of their centroid (where the
    chain takes it, bearing on the held top without horizontal inertia: the floor holds the
    top, docs/mechanisms/vertical-flexure.md). (0, 0) for the last storey without a gable."""
    top = wall.storey_bases()[storey - 1] + wall.storeys[storey - 1].height
    items = [(b.weight, b.x) for b in storey_bodies(wall, storey)]
    items += [(ld.weight, ld.x) for ld in wall.loads if ld.bears and above(ld.z, top)]
    total = sum(w for w, _ in items)
    if total <= 0.0:
        return 0.0, 0.0
    return total, sum(w * x for w, x in items) / total


def bearing(wall: Wall, lo: float, hi: float, at_top: bool = False) -> float:
    """The bearing loads above ``lo`` up to ``hi`` included [N] (``at_top``: only those at
    ``hi``, a storey's overburden)."""
    if at_top:
        return sum(ld.weight for ld in wall.loads if ld.bears and same_height(ld.z, hi))
    return sum(
        ld.weight for ld in wall.loads if ld.bears and above(ld.z, lo) and not above(ld.z, hi)
    )


def half_block(wall: Wall, weight: float, thickness: float, name: str) -> float:
    """Half the stress block carrying ``weight`` [N] on a section of ``thickness`` [m]."""
    depth = stress_block(wall, weight)
    if depth >= thickness:
        raise CrushingError(name, depth, thickness)
    return 0.5 * depth


def sides_of(spec: MechanismSpec, one_sided: int | None) -> tuple[int, ...]:
    """The sides a mechanism can open to: the wedge outward only; a one-sided wall its free
    side; the others both."""
    if spec.type in (MechanismType.WEDGE, MechanismType.CORNER):
        return (1,)
    return (one_sided,) if one_sided is not None else (1, -1)


def hinge_of(spec: MechanismSpec, wall: Wall) -> float:
    """The hinge's height above the wall's base [m]: overturning and flexure as given, the
    wedge at the base, the gable on the last storey."""
    if spec.type is MechanismType.GABLE:
        return wall.height
    if spec.type in (MechanismType.WEDGE, MechanismType.CORNER):
        return 0.0
    if spec.type is MechanismType.HORIZONTAL_FLEXURE:
        assert spec.level is not None
        return spec.level
    assert isinstance(spec.hinge_height, float)
    return spec.hinge_height


def build(wall: Wall, spec: MechanismSpec, side: int) -> ChainSide:
    """The mechanism ``spec`` of the wall opening to ``side`` (flexure: hinge height resolved)."""
    if spec.type is MechanismType.OVERTURNING:
        return overturning(wall, hinge_of(spec, wall), side, spec.name, spec.friction)
    if spec.type is MechanismType.WEDGE:
        assert spec.angle is not None and spec.sides is not None
        return wedge(wall, spec.angle, spec.sides, spec.name, side)
    if spec.type is MechanismType.GABLE:
        return gable_mechanism(wall, side, spec.name)
    if spec.type is MechanismType.HORIZONTAL_FLEXURE:
        return horizontal_flexure(wall, spec, side)
    if spec.type is MechanismType.CORNER:
        return corner(wall, spec, side)
    assert spec.storey is not None and isinstance(spec.hinge_height, float)
    return flexure(wall, spec.storey, spec.hinge_height, side, spec.name)


#: Gauss–Legendre nodes and weights on [−1, 1], four points: exact for polynomials of degree
#: up to 7 (the corner's sections: piecewise polynomials of degree 4 in z, times z²).
_OUTER = math.sqrt(3 / 7 + 2 / 7 * math.sqrt(6 / 5))
_INNER = math.sqrt(3 / 7 - 2 / 7 * math.sqrt(6 / 5))
_NODES = (-_OUTER, -_INNER, _INNER, _OUTER)
_WEIGHTS = ((18 - math.sqrt(30)) / 36, (18 + math.sqrt(30)) / 36,
            (18 + math.sqrt(30)) / 36, (18 - math.sqrt(30)) / 36)  # fmt: skip


def rectangle_moments(x: float, y: float) -> tuple[float, float, float]:
    """(∫dA, ∫(x + y) dA, ∫(x + y)² dA) over the rectangle [0, x] × [0, y] [m², m³, m⁴]."""
    area = x * y
    return area, 0.5 * area * (x + y), area * (x * x / 3 + x * y / 2 + y * y / 3)


def corner_section(z: float, wall_t: float, return_t: float, tb: float):
    """(∫dA, ∫u dA, ∫u² dA) of the corner's horizontal section at height z above its base:
    the wall's piece [0, z·tan β] × [0, wall_t] and the return wall's [0, return_t] ×
    [0, z·tan β] (x along the wall, y along the return wall, from the outer corner), counted
    once where they overlap; u = (x + y)/√2 the distance inward along the bisector."""
    a = z * tb
    parts = (rectangle_moments(a, wall_t), rectangle_moments(return_t, a),
             rectangle_moments(min(a, return_t), min(a, wall_t)))  # fmt: skip
    area = parts[0][0] + parts[1][0] - parts[2][0]
    first = parts[0][1] + parts[1][1] - parts[2][1]
    second = parts[0][2] + parts[1][2] - parts[2][2]
    return area, first / math.sqrt(2.0), second / 2.0


def corner_body(storeys: Sequence[tuple[float, float, float]], return_t: float,
                angle: float, unit_weight: float, g: float) -> Body:  # fmt: skip
    """The corner wedge as one body in the plane of its bisector: x = u inward from the outer
    corner along the bisector, z up from its base; its weight, centroid, inertia about the
    axis through the centroid normal to that plane and its variances, integrated exactly
    (four-point Gauss–Legendre on each piece between the storeys' bases and the heights
    where the pieces' widths reach the walls' thicknesses). ``storeys``: (base, top,
    thickness) of each storey the wedge spans, bottom up."""
    tb = math.tan(angle)
    top = storeys[-1][1]
    breaks = {0.0, top, *(base for base, _, _ in storeys)}
    breaks |= {t / tb for t in (return_t, *(t for _, _, t in storeys)) if t / tb < top}
    ordered = sorted(breaks)
    sums = [0.0] * 5  # ∫A, ∫A z, ∫A z², ∫U, ∫U2 (sections' first and second in u)
    for lo, hi in zip(ordered, ordered[1:], strict=False):
        half, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
        wall_t = next(t for base, end, t in storeys if base <= mid < end)
        for node, weight in zip(_NODES, _WEIGHTS, strict=True):
            z = mid + half * node
            area, first, second = corner_section(z, wall_t, return_t, tb)
            w = weight * half
            sums[0] += w * area
            sums[1] += w * area * z
            sums[2] += w * area * z * z
            sums[3] += w * first
            sums[4] += w * second
    volume = sums[0]
    u, z = sums[3] / volume, sums[1] / volume
    var_u, var_z = sums[4] / volume - u * u, sums[2] / volume - z * z
    weight = unit_weight * volume
    mass = weight / g
    return Body("corner wedge", weight, u, z, mass * (var_u + var_z), var_u, var_z, mass)


def corner(wall: Wall, spec: MechanismSpec, side: int) -> ChainSide:
    """The corner of the wall and a return wall ("ribaltamento del cantonale"): cracked in
    each from the outer base corner at ``angle`` β from the vertical (the wall's piece
    z·tan β wide at height z, the return wall's the same, the corner counted once), over the
    storeys' height with each storey's thickness, turning out about the horizontal axis
    through the outer base corner normal to the corner's bisector (side 1). In the plane of
    the bisector it is one rigid body about a pivot: a point at depth u inward along the
    bisector and height z moves δx = z out and δy = u up per unit rotation, so α0 = Σ W u /
    Σ W z (less a hip beam's thrust H at the top: − H·h) — the Circolare's virtual work
    (Eq. C8.7.1.1) on this body. Side −1 (inward, about the inner corner) is placed only as
    every mechanism's is; the corner opens outward only."""
    assert spec.angle is not None and spec.return_thickness is not None
    bases = wall.storey_bases()
    storeys = [(b, b + st.height, st.thickness) for b, st in zip(bases, wall.storeys, strict=True)]
    body = corner_body(storeys, spec.return_thickness, spec.angle, wall.unit_weight, wall.g)
    inner = (wall.storeys[0].thickness + spec.return_thickness) / math.sqrt(2.0)
    frame = Frame(0.0 if side > 0 else inner, 0.0, side)
    thrusts: tuple[SideThrust, ...] = ()
    if spec.hip_thrust:
        at = Attached(0, frame.x(0.0), wall.height)
        thrusts = (SideThrust("hip beam thrust", spec.hip_thrust, side, at),)
    return ChainSide(Rotation(), ((0, frame.body(body)),), wall.g, thrusts=thrusts, side=side)


#: The name of the arch's thrust on each half of a horizontal flexure.
ARCH_THRUST = "arch thrust"


def arch_thrust(f_m: float, strip: float, thickness: float, limit: float | None) -> float:
    """The thrust H of a horizontal flexure's arch [N]: the one of the largest moment
    H·(s − a), a = H/(f_m·b) the stress block's depth, H* = f_m·b·s/2 (rigid abutments: the
    masonry's crushing limits it), or the abutments' limit (a tie, a ring beam) when lower."""
    best = 0.5 * f_m * strip * thickness
    return best if limit is None else min(best, limit)


def arch_numbers(wall: Wall, spec: MechanismSpec) -> tuple[float, float, float, float]:
    """(s [m], H [N], the masonry's H* [N], a [m]) of a horizontal flexure's arch: the strip's
    thickness (its storey's), its thrust (:func:`arch_thrust`), the rigid abutments' and the
    stress block's depth a = H/(f_m·b)."""
    assert wall.f_m is not None and spec.level is not None and spec.strip_height is not None
    s = wall.storeys[storey_of(wall, spec.level)].thickness
    thrust = arch_thrust(wall.f_m, spec.strip_height, s, spec.thrust_limit)
    best = arch_thrust(wall.f_m, spec.strip_height, s, None)
    return s, thrust, best, thrust / (wall.f_m * spec.strip_height)


def horizontal_flexure(wall: Wall, spec: MechanismSpec, side: int) -> ChainSide:
    """A strip of the wall of height b at ``level`` between the return walls, of span L, as a
    three-hinge flat arch in plan (the arch effect of "flessione orizzontale", the horizontal
    bending of a wall held by its return walls; hinges set back by their stress blocks as in
    the vertical mechanisms).

    In plan, x through the wall's thickness s from the face the abutment hinge sits on
    (side 1: the outer face, the strip bulging outward), "z" along the span from the
    abutment: each half (L/2 long, weight γ·s·b·L/2) turns by θ about its abutment hinge,
    set back a/2 from its face, towards the mid-span hinge, set back a/2 from the other face.
    The arch's thrust H pushes each half back along the span at the mid-span hinge, a lever
    (s − a)·cos θ − (L/2)·sin θ about the abutment: with the half's inertia α·P at its
    centroid, α = 8·H·(s − a − δ)/(γ·s·b·L²), δ = (L/2)·sin θ the mid-span's outward
    displacement, and at rest α0 = 8·H·(s − a)/(γ·s·b·L²) (2·f_m·s/(γ·L²) with rigid
    abutments). The two halves are one link: by symmetry each point of the other half
    moves as its mirror. H and a stay as at rest along the curve (the catalogue's hinges are
    fixed, as a stress block's set-back is for every mechanism), so the lever closes at
    δ ≈ s − a. As a chain: H is a weight bearing at the mid-span hinge that does not move
    (it does the work H·dZ/dθ), the halves two bodies of the link."""
    assert spec.strip_height is not None and spec.span is not None
    b, span = spec.strip_height, spec.span
    s, thrust, _, a = arch_numbers(wall, spec)
    frame = Frame(0.5 * a if side > 0 else s - 0.5 * a, 0.0, side)
    mid = frame.x(s - 0.5 * a if side > 0 else 0.5 * a)
    half = replace(prism("half strip", 0.0, s, 0.0, 0.5 * span, b, wall.unit_weight, wall.g),
                   bears=False)  # in plan: its weight does no work  # fmt: skip
    halves = ((0, frame.body(half)), (0, frame.body(replace(half, name="other half strip"))))
    push = SideLoad(ARCH_THRUST, thrust, Attached(0, mid, 0.5 * span), bears=True, moves=False)
    return ChainSide(Rotation(), halves, wall.g, loads=(push, push), side=side)


def flexure_range(wall: Wall, storey: int) -> tuple[float, float]:
    """Where the optimal intermediate hinge is searched [m above the wall's base]: the
    storey's height less, at each end, the larger of its thickness and a tenth of its height
    (a block squatter than the wall is thick is not the slender block the chain assumes, and
    a hinge at an end is no flexure: docs/interpretations.md)."""
    base = wall.storey_bases()[storey - 1]
    s = wall.storeys[storey - 1]
    margin = max(s.thickness, 0.1 * s.height)
    return base + margin, base + s.height - margin


#: Points of the uniform scan of the optimal hinge, beside the heights where something is
#: attached (then Brent's refinement between the best one's neighbours). Measured: on 314
#: flexures of the two-storey façade with one to three loads at random heights, weights and
#: levers inside its storeys and random thicknesses, the scan of 41 points and those heights
#: finds the lowest α0 of a 4001-point scan every time (to 2e-16; benchmarks/hinge_scan.py).
HINGE_SCAN = 41
#: The hinge height's resolution beyond √ε·z, as a share of the range searched.
HINGE_RESOLUTION = 1e-10


def optimal_hinge(
    lo: float, hi: float, alpha0: Callable[[float], float], breaks: Sequence[float] = ()
) -> float:
    """The hinge height in [lo, hi] that minimises ``alpha0``: the lowest of a uniform scan
    and of the heights ``breaks`` inside the range (where a load, thrust or restrainer
    changes block as the hinge passes it, α0 jumps: a dip narrower than the scan's step can
    lie there), refined by Brent's parabolic search between its neighbours
    (rockcli.searches; kept only if lower)."""
    uniform = [lo + (hi - lo) * k / (HINGE_SCAN - 1) for k in range(HINGE_SCAN)]
    zs = sorted({*uniform, *(z for z in breaks if lo < z < hi)})
    values = [alpha0(z) for z in zs]
    k = min(range(len(zs)), key=values.__getitem__)
    a, b = zs[max(k - 1, 0)], zs[min(k + 1, len(zs) - 1)]
    best, value = brent_minimum(alpha0, a, b, HINGE_RESOLUTION * (hi - lo))
    return best if value <= values[k] else zs[k]
