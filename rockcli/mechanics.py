"""Mechanics of the rocking block, written once for both analyses.

The rocking engine (``rockcli.dynamics``) and the kinematic check (``rockcli.codecheck``) both
read the block through the functions here, so the uplift acceleration of a time history equals
α0·g of the code check by construction (spec/README.md, "Architecture").

Pure and silent: only :mod:`math`. The scalar formulas are plain functions of floats so the
engine can compile the very same code with numba.

Notation (spec/rocking.md): half-thickness b, half-height h, semi-diagonal R = √(b²+h²),
slenderness α = atan(b/h), mass m, I0 = 4/3·m·R², p² = m g R / I0 = 3g/(4R); rotation θ,
pivot side s = ±1, a = s·θ = |θ| the rotation about the active pivot.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

#: Side of rotation / pivot: +1 for θ > 0 (pivot O), −1 for θ < 0 (pivot O′).
POSITIVE = 1
NEGATIVE = -1


@dataclass(frozen=True)
class Restrainer:
    """A horizontal spring between a point of the block and a fixed support.

    The attachment point is described, for each pivot, by its distance ``r`` from the pivot and
    the angle ``phi`` of that radius from the vertical at rest, measured into the block
    (spec/rocking.md, "Restrainers"). The paper's spring at the top corner is r = 2R, φ = α.

    Attributes:
        name: label shown in reports.
        k_pos: stiffness while θ > 0 [N/m].
        k_neg: stiffness while θ < 0 [N/m].
        r_pos, phi_pos: radius [m] and angle [rad] of the point about pivot O (θ > 0).
        r_neg, phi_neg: radius [m] and angle [rad] of the point about pivot O′ (θ < 0).
        fails_at: spring elongation at which it is lost for the rest of the run [m]
            (``math.inf``: never): as the model gives it (``fails_at``, or a tie-rod's
            ``elongation_at_break``), in both analyses.
        breaks_at: spring elongation at which a tie-rod of a standard grade breaks by its
            steel's default elongation at break when the model gives neither [m] (``math.inf``:
            none). The time history only (:attr:`lost_at`); the code check relies on
            ``fails_at`` alone (docs/interpretations.md, "Restrainer laws").
        strength: the force the member can carry [N] (``math.inf``: not given): its design
            tension resistance and its anchorage's capacity. Checked against the force of the
            time history.
        strength_rule: what sets the strength (for reports; "" when not given).
        law: "elastic" or "elastic-plastic".
        yield_pos, yield_neg: yield force of the elastic-plastic law on each side [N] (inf:
            elastic).
        pretension: force in the member at rest [N].
        rupture_force: force at which the member is lost [N] (inf: never): its anchorage's
            capacity, or a tie-rod's net section N_u,Rd when lower than its yield force.
        anchor_capacity: the anchorage's capacity as given [N] (inf: not given).
        code_action: "force" (the kinematic check takes ``code_force`` as a stabilising force
            in α0) or "spring" (its stiffness, no force at rest).
        code_force: the force the kinematic check relies on with code_action "force" [N].
        elongation_capacity: a steel bar's design elongation from its unstressed length,
            ε_u·L/γ_ε [m] (``math.inf``: not a bar of known steel; codecheck.tie).
        overstrength: a steel bar's γ_ov·A·f_y, the force its anchorage must exceed [N]
            (0: not a bar of known steel; codecheck.tie).
        ductility_rule: where ε_u comes from (for reports; "" when not a bar).
        slack_side: the side on which a tension-only member would push and goes slack in the
            kinematic check (−1: a tie-rod acting both ways, which can only pull the wall
            back from outward; 0: none). The time history keeps its spring on both sides.
        path: the elongation of a point that does not turn rigidly about the pivot (on the
            upper block of a two-block chain), tabulated along the rotation of each side
            (PA_* layout below; :func:`path_terms`); r and φ are then its position at rest,
            for reports. Empty: the polar point (r, φ) of a rigid block, exact.
    """

    name: str
    k_pos: float
    k_neg: float
    r_pos: float
    phi_pos: float
    r_neg: float
    phi_neg: float
    fails_at: float = math.inf
    strength: float = math.inf
    strength_rule: str = ""
    law: str = "elastic"
    yield_pos: float = math.inf
    yield_neg: float = math.inf
    pretension: float = 0.0
    rupture_force: float = math.inf
    anchor_capacity: float = math.inf
    code_action: str = "spring"
    code_force: float = 0.0
    breaks_at: float = math.inf
    elongation_capacity: float = math.inf
    overstrength: float = 0.0
    ductility_rule: str = ""
    slack_side: int = 0
    path: tuple[float, ...] = ()

    def side(self, s: int) -> tuple[float, float, float]:
        """(K [N/m], r [m], φ [rad]) for pivot side s = ±1."""
        if s > 0:
            return self.k_pos, self.r_pos, self.phi_pos
        return self.k_neg, self.r_neg, self.phi_neg

    def arm_at_rest(self, s: int) -> float:
        """du/da at rest on side s [m/rad]: the virtual displacement of its point per unit
        rotation, the arm of its force (r·cos φ for a polar point)."""
        if self.path:
            return path_terms(self.path, 0, s, 0.0)[1]
        _, r, phi = self.side(s)
        return r * math.cos(phi)

    def elongation(self, s: int, a: float, linearized: bool = False) -> float:
        """Its elongation at rotation a about pivot s [m] (the engine's: :func:`path_terms`, or
        :func:`spring_elongation` of its polar point)."""
        if self.path:
            return path_terms(self.path, 0, s, a)[0]
        _, r, phi = self.side(s)
        return spring_elongation(r, phi, a, linearized)

    @property
    def can_fail(self) -> bool:
        """True when the restrainer has a finite failure elongation."""
        return math.isfinite(self.fails_at)

    @property
    def lost_at(self) -> float:
        """Spring elongation at which the time history loses it [m]: the lower of ``fails_at``
        and ``breaks_at`` (``math.inf``: never)."""
        return min(self.fails_at, self.breaks_at)

    def yield_force(self, s: int) -> float:
        """Yield force of the side s = ±1 [N] (inf: elastic)."""
        return self.yield_pos if s > 0 else self.yield_neg

    @property
    def has_memory(self) -> bool:
        """True when its force depends on its history: it yields, is pretensioned or breaks."""
        return (
            math.isfinite(self.yield_pos)
            or math.isfinite(self.yield_neg)
            or self.pretension > 0.0
            or math.isfinite(self.rupture_force)
        )


@dataclass(frozen=True)
class WorkItem:
    """A body, load, thrust or restrainer of a mechanism at rest, with its virtual
    displacement per unit rotation about the hinge (the code check's virtual-work table,
    codecheck.kinematic).

    Attributes:
        name: its label. kind: "body", "load", "thrust", "friction" (the toothed return
        walls', its resultant) or "restrainer". force: its weight, or a thrust's, friction's
        or restrainer's horizontal force [N]. x, z: its point [m]. dx, dy: its
        virtual displacement outward and up [m/rad].
        bears: its weight rests on the mechanism. moves: its mass follows it horizontally.
        opens: a thrust's direction, +1 pushing the mechanism open, −1 shut (0: a weight).
    """

    name: str
    kind: str
    force: float
    x: float
    z: float
    dx: float
    dy: float
    bears: bool = True
    moves: bool = True
    opens: int = 0


@dataclass(frozen=True)
class Load:
    """A weight carried by or pushing on the block, as a point of the block.

    Circolare 617/2009 §C8A.4.1 and Circolare 7/2019 §C8.7.1.1: the weights P_i bear on the
    blocks (their weight restores, their mass is shaken with the block), the weights P_j do not
    bear on them but their masses push them. ``bears`` and ``moves`` say which of the two a
    load does (both: the load rests on the block and moves with it, a rigid point mass).

    Attributes:
        name: label shown in reports.
        weight: weight [N] (mass = weight / g).
        x_pos: horizontal distance of its point from pivot O (θ > 0), into the block [m].
        x_neg: the same from pivot O′ (θ < 0), 2b − x_pos [m].
        z: height of its point above the base [m].
        bears: its weight rests on the block (vertical load and vertical inertia).
        moves: its mass follows the block horizontally (horizontal inertia).
    """

    name: str
    weight: float
    x_pos: float
    x_neg: float
    z: float
    bears: bool = True
    moves: bool = True


@dataclass(frozen=True)
class Friction:
    """The friction of toothed return walls on a rigid body (Circolare 7/2019 §C8.7.1.2.1.1,
    Eq. C8.7.1.2): the courses interlocked with the body over the height h above ``z0`` resist
    its rotation with a horizontal force F in all, spread as q(ζ) = 2F(h − ζ)/h² over the
    height (its resultant at h/3, the clause's point), each course while its slide is at most
    the overlap l (:func:`friction_moment`; rockcli.mechanisms.side.SideFriction is the same
    law on a link of a chain).

    Attributes:
        name: label. force: F of all the walls [N]. x_pos, x_neg: the interface's horizontal
        distance from pivot O and from O′ [m]. z0: the toothing's bottom above the base [m].
        height: h [m]. overlap: l [m].
    """

    name: str
    force: float
    x_pos: float
    x_neg: float
    z0: float
    height: float
    overlap: float


def friction_moment(force, x, z0, height, overlap, a, sin_a, cos_a):
    """The moment [N·m] about the pivot of the friction of :class:`Friction` at rotation
    a ≥ 0, resisting the rotation (positive: it acts towards a = 0 when the body opens).

    A point (x, z) of the interface slides x·(1 − cos a) + z·sin a outward; the courses up to
    ζ_e = (l − x·(1 − cos a))/sin a − z0 above the toothing's bottom are engaged (v = ζ_e/h,
    clipped to [0, 1]), and the force per unit height q(ζ) works through dX/da = −(x sin a +
    z cos a). Integrated over the engaged part by hand:

        M = (x sin a + z0 cos a)·F·(2v − v²) + cos a·F·h·(v² − 2v³/3),

    F·(x sin a + (z0 + h/3) cos a) with every course engaged (at rest: F at h/3 above z0).
    ``force`` may be signed (the sense of the motion it resists) and scales M.
    """
    slide = x * versine(a, cos_a)
    if sin_a <= 0.0:
        v = 1.0 if slide <= overlap else 0.0
    else:
        v = ((overlap - slide) / sin_a - z0) / height
        v = min(max(v, 0.0), 1.0)
    return force * (
        (x * sin_a + z0 * cos_a) * (2.0 * v - v * v)
        + cos_a * height * (v * v - 2.0 * v * v * v / 3.0)
    )


@dataclass(frozen=True)
class Thrust:
    """A horizontal force independent of the earthquake (roof or arch thrust) on the block.

    Attributes:
        name: label shown in reports.
        force: its magnitude [N], > 0.
        direction: the sense of rotation it pushes towards, +1 (θ > 0) or −1 (θ < 0).
        x_pos, x_neg: horizontal distance of its point from pivot O and from O′ [m].
        z: height of its point above the base [m].
    """

    name: str
    force: float
    direction: int
    x_pos: float
    x_neg: float
    z: float


# The table of a chain (ChainTable.table): a header (n nodes per side; the grid step of side +1 and
# of side −1 [rad]), then side +1's n rows and side −1's n rows, each row
# the five terms of the equation of motion at a = k·step and their five derivatives in a:
# G = V′ [N·m], H = g·Γ [N·m per g], T (the thrusts' opening work) [N·m], M [kg·m²],
# M′ [kg·m²/rad].
CH_N, CH_STEP_POS, CH_STEP_NEG = 0, 1, 2
CH_HEAD = 3
CH_TERMS = 5
CH_COLS = 2 * CH_TERMS


@dataclass(frozen=True)
class ChainTable:
    """The table of a mechanism of several bodies with one degree of freedom, as the rocking
    engine reads it: the terms of its equation of motion about each side's pivot tabulated on
    a uniform grid of the rotation a = s·θ ∈ [0, end] (cubic Hermite between nodes:
    :func:`chain_terms`), and the constants of each side at rest (index 0: side +1, index 1:
    side −1).

    Attributes:
        table: the flat table (CH_* layout above).
        uplift: the ground acceleration that starts the motion from rest [g], per side: the
            code check's α0 = (G − T)/H at rest, computed by the same expression.
        restitution: θ̇⁺/θ̇⁻ of an impact that ends a phase on each side.
        inertia: M(0) per side [kg·m²] (the kinetic energy ½·M(0)·θ̇² at an impact).
        stiffness: d(G − T)/da at rest per side [N·m/rad] (negative: the weights' restoring
            moment falls as the chain opens).
        end: the largest rotation tabulated, where the run counts the mechanism collapsed [rad].
        p2: G(0)/M(0)·(1 + (H(0)/G(0))²)^½ [rad²/s²]: a rigid block's m g R/I_O, the scale of
            the free-vibration tail.
        centroid: the bodies' centroid at rest from pivot O, (x, z) [m] (for reports).
        exact: the five terms at (s, a) from the configuration function itself, for the
            reference engine (the table's error is measured against it).
    """

    table: tuple[float, ...]
    uplift: tuple[float, float]
    restitution: tuple[float, float]
    inertia: tuple[float, float]
    stiffness: tuple[float, float]
    end: float
    p2: float
    centroid: tuple[float, float] = (0.0, 0.0)
    exact: Callable[[int, float], tuple[float, float, float, float, float]] | None = field(
        default=None, compare=False, hash=False
    )

    def side(self, s: int) -> int:
        """The index of side s in the per-side pairs."""
        return 0 if s > 0 else 1

    def mirrored(self) -> ChainTable:
        """The table with its two sides swapped."""
        n = int(self.table[CH_N])
        rows = self.table[CH_HEAD:]
        half = n * CH_COLS
        head = (self.table[CH_N], self.table[CH_STEP_NEG], self.table[CH_STEP_POS])
        exact = self.exact

        def swapped(s: int, a: float) -> tuple[float, float, float, float, float]:
            assert exact is not None
            return exact(-s, a)

        def pair(v: tuple[float, float]) -> tuple[float, float]:
            return v[1], v[0]

        return ChainTable(
            table=head + rows[half:] + rows[:half],
            uplift=pair(self.uplift),
            restitution=pair(self.restitution),
            inertia=pair(self.inertia),
            stiffness=pair(self.stiffness),
            end=self.end,
            p2=self.p2,
            centroid=self.centroid,
            exact=None if exact is None else swapped,
        )


# The elongation path of a member whose point does not turn rigidly about the pivot
# (Restrainer.path), stored in a flat table from an offset: a header (n nodes per side, the grid
# step of side +1 and of side −1 [rad]), then side +1's n rows and side −1's n rows, each the
# point's elongation u [m], its slope u′ = du/da [m/rad] (the point's virtual displacement per
# unit rotation: the arm of the member's force in the equation of motion) and u″ [m/rad²], at
# a = k·step. The packed restrainer table of the engines holds it from a column of its own.
PA_N, PA_STEP_POS, PA_STEP_NEG = 0, 1, 2
PA_HEAD = 3
PA_COLS = 3
#: Most halvings of the bisection of :func:`path_rotation` (it stops at the last bit first).
PATH_BISECTIONS = 2000


def hermite_weights(a, step, n):
    """The interval k of a grid of n nodes spaced ``step`` from 0 that holds a (the end
    intervals past the grid's ends), and the cubic Hermite weights (h00, h10, h01, h11) of
    the values and slopes at its two nodes (h10 and h11 scaled by the step): the value at a
    is h00·f(k) + h10·f′(k) + h01·f(k+1) + h11·f′(k+1) (de Boor 2001, ch. IV)."""
    x = a / step
    k = int(math.floor(x))
    k = min(max(k, 0), n - 2)
    u = x - k
    u2 = u * u
    u3 = u2 * u
    h00 = 2.0 * u3 - 3.0 * u2 + 1.0
    h10 = (u3 - 2.0 * u2 + u) * step
    h01 = 3.0 * u2 - 2.0 * u3
    h11 = (u3 - u2) * step
    return k, h00, h10, h01, h11


def path_terms(table, offset, s, a):
    """(u, u′) of the elongation path stored in ``table`` from ``offset`` (PA_* layout) on
    side s at rotation a: cubic Hermite between the two nodes around a, u from the values and
    slopes, u′ from the slopes and curvatures (as :func:`chain_terms`; exact at a node, the
    end interval's cubic past the table's end)."""
    n = int(table[offset + PA_N])
    step = table[offset + PA_STEP_POS] if s > 0 else table[offset + PA_STEP_NEG]
    base = offset + PA_HEAD + (0 if s > 0 else n * PA_COLS)
    k, h00, h10, h01, h11 = hermite_weights(a, step, n)
    r0 = base + k * PA_COLS
    r1 = r0 + PA_COLS
    value = h00 * table[r0] + h10 * table[r0 + 1] + h01 * table[r1] + h11 * table[r1 + 1]
    slope = h00 * table[r0 + 1] + h10 * table[r0 + 2] + h01 * table[r1 + 1] + h11 * table[r1 + 2]
    return value, slope


def path_rotation(table, offset, s, u):
    """The least rotation a ≥ 0 at which the path's elongation on side s reaches u [rad]: 0
    for u ≤ 0, inf when the table's end falls short. The path grows with a (checked where it
    is tabulated, rockcli.mechanisms.table.member_path): the interval of nodes by bisection on
    the stored values, then the cubic's by bisection to the last bit, so that an elongation
    however small has its own rotation (as :func:`spring_failure_rotation`)."""
    if u <= 0.0:
        return 0.0
    n = int(table[offset + PA_N])
    step = table[offset + PA_STEP_POS] if s > 0 else table[offset + PA_STEP_NEG]
    base = offset + PA_HEAD + (0 if s > 0 else n * PA_COLS)
    if table[base + (n - 1) * PA_COLS] < u:
        return math.inf
    lo_k = 0
    hi_k = n - 1
    while hi_k - lo_k > 1:
        mid_k = (lo_k + hi_k) // 2
        if table[base + mid_k * PA_COLS] < u:
            lo_k = mid_k
        else:
            hi_k = mid_k
    lo = lo_k * step
    hi = hi_k * step
    for _ in range(PATH_BISECTIONS):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        if path_terms(table, offset, s, mid)[0] < u:
            lo = mid
        else:
            hi = mid
    return hi


def mirrored_path(path: tuple[float, ...]) -> tuple[float, ...]:
    """The path with its two sides swapped."""
    if not path:
        return path
    n = int(path[PA_N])
    rows = path[PA_HEAD:]
    half = n * PA_COLS
    return (path[PA_N], path[PA_STEP_NEG], path[PA_STEP_POS]) + rows[half:] + rows[:half]


def chain_terms(table, s, a):
    """(G, H, T, M, M′) of a chain's table (:class:`ChainTable`) on side s at rotation a [rad].

    Cubic Hermite interpolation between the two nodes around a, from the values and the
    derivatives stored at each (de Boor, *A Practical Guide to Splines*, 2001, ch. IV; error
    h⁴·max|f⁗|/384 for a grid step h). At a node it returns the stored values exactly, so the
    terms at rest are the configuration function's own. A rotation outside [0, end] (a step's
    trial stage past the impact) is extrapolated by the end interval's cubic. ``table`` is any
    flat sequence indexable by integers (a tuple, or a numpy array in the compiled engine).
    """
    n = int(table[CH_N])
    step = table[CH_STEP_POS] if s > 0 else table[CH_STEP_NEG]
    base = CH_HEAD if s > 0 else CH_HEAD + n * CH_COLS
    k, h00, h10, h01, h11 = hermite_weights(a, step, n)
    r0 = base + k * CH_COLS
    r1 = r0 + CH_COLS
    e0 = r0 + CH_TERMS
    e1 = r1 + CH_TERMS
    g = h00 * table[r0] + h10 * table[e0] + h01 * table[r1] + h11 * table[e1]
    h = h00 * table[r0 + 1] + h10 * table[e0 + 1] + h01 * table[r1 + 1] + h11 * table[e1 + 1]
    t = h00 * table[r0 + 2] + h10 * table[e0 + 2] + h01 * table[r1 + 2] + h11 * table[e1 + 2]
    m = h00 * table[r0 + 3] + h10 * table[e0 + 3] + h01 * table[r1 + 3] + h11 * table[e1 + 3]
    mp = h00 * table[r0 + 4] + h10 * table[e0 + 4] + h01 * table[r1 + 4] + h11 * table[e1 + 4]
    return g, h, t, m, mp


@dataclass(frozen=True)
class Rocker:
    """What both engines rock and the code check reads at rest: a system of one degree of
    freedom on a rigid base, turning about a pivot on each side, with its restrainers, loads
    and thrusts. One of three kinds, each with its own equation of motion: the paper's
    rectangle (:class:`Block`), one rigid body of another shape (:class:`RigidBody`), or a
    chain of bodies tabulated along its rotation (:class:`Chain`).

    Attributes:
        R: the distance of the centroid from pivot O [m] (the rectangle's semi-diagonal).
        alpha: the rotation at which the weights stop restoring on side +1 [rad], the
            amplitude ratio's divisor (the rectangle's slenderness atan(b/h), 0 < α < π/2;
            a body's centroid angle from the vertical at O; a chain's instability rotation).
        mass: mass [kg] (``None`` allowed only for a rectangle without restrainers: the free
            block's motion does not depend on it, paper §4.3).
        g: gravity [m/s²].
        e: coefficient of restitution at impact, ratio of angular velocities [-].
        one_sided: True when transverse walls stop the rotation towards one side.
        free_side: with ``one_sided``, the side the system can rotate to (+1 or −1).
        rebound: r_f, the rebound reduction factor of one-sided motion [-].
        e_neg: e after an impact from side −1, when it differs from ``e`` (loads off the
            mid-plane change the angular momentum balance of each side); ``None``: ``e``.
        linearized: use sin x ≈ x, cos x ≈ 1 (the slender rectangle's approximation).
        restrainers: the horizontal springs.
        loads: weights carried by or pushing on the system (mass required).
        thrusts: horizontal forces independent of the earthquake (mass required).
        frictions: the toothed return walls' friction resisting the rotation (a rigid body's
            only: :class:`RigidBody`; at most one).
    """

    R: float
    alpha: float
    mass: float | None = None
    g: float = 9.81
    e: float = 1.0
    one_sided: bool = False
    free_side: int = POSITIVE
    rebound: float = 1.0
    linearized: bool = False
    e_neg: float | None = None
    restrainers: tuple[Restrainer, ...] = field(default_factory=tuple)
    loads: tuple[Load, ...] = field(default_factory=tuple)
    thrusts: tuple[Thrust, ...] = field(default_factory=tuple)
    frictions: tuple[Friction, ...] = field(default_factory=tuple)

    @property
    def kind(self) -> str:
        """The equation the engines integrate: "rectangle" (paper Eq. 2, closed form),
        "points" (the point table of :func:`point_table`) or "chain" (the chain's table)."""
        raise NotImplementedError

    def uplifts(self) -> tuple[float, float]:
        """(α0⁺, α0⁻) from the point table (:func:`uplift_accelerations`)."""
        points = point_table(self)
        out = []
        for s in (POSITIVE, NEGATIVE):
            g, h, t, _, _ = point_moments(points, s, 0.0, 1.0)
            out.append((g + self.friction_at(s, 0.0) - s * t) / h)
        return out[0], out[1]

    def friction_at(self, s: int, a: float) -> float:
        """The frictions' moment resisting the rotation a about pivot s [N·m]
        (:func:`friction_moment`; 0 without)."""
        sin_a, cos_a = math.sin(a), math.cos(a)
        return sum(
            friction_moment(f.force, f.x_pos if s > 0 else f.x_neg, f.z0, f.height, f.overlap,
                            a, sin_a, cos_a)
            for f in self.frictions
        )  # fmt: skip

    def collapses(self) -> tuple[float, float]:
        """(θc⁺, θc⁻) from the point table (:func:`collapse_rotations`)."""
        points = point_table(self)
        out = []
        for s in (POSITIVE, NEGATIVE):
            g0, _, t0, _, _ = point_moments(points, s, 0.0, 1.0)  # A: G − s·T at a = 0
            g1, _, t1, _, _ = point_moments(points, s, 1.0, 0.0)  # −B: G − s·T at a = π/2
            out.append(min(math.atan2(g0 - s * t0, -(g1 - s * t1)), 0.5 * math.pi))
        return out[0], out[1]

    def weights_stiffness(self, s: int) -> float:
        """d(G − s·T)/da at rest on side s [N·m/rad] (:func:`linear_global_stiffness`)."""
        return loaded_stiffness(point_table(self), s)

    def weights_moment(self, s: int, a: float) -> float:
        """G − s·T at rotation a about pivot s [N·m] (:func:`restoring_moment`)."""
        g, _, t, _, _ = point_moments(point_table(self), s, math.sin(a), math.cos(a))
        return g - s * t

    def own_momentum(self, s: int) -> tuple[float, float]:
        """(N, D′) of its own mass in Housner's impact ending side s
        (:func:`impact_restitution`)."""
        raise NotImplementedError

    def impact_restitution(self, s: int) -> float:
        """Housner's θ̇⁺/θ̇⁻ of an impact ending side s, with its loads
        (:func:`impact_restitution`)."""
        num, den = self.own_momentum(s)
        for ld in self.loads:
            mass = ld.weight / self.g
            x, x_new = (ld.x_pos, ld.x_neg) if s > 0 else (ld.x_neg, ld.x_pos)
            if ld.moves:
                num += mass * ld.z * ld.z
                den += mass * ld.z * ld.z
            if ld.bears:
                num -= mass * x * x_new
                den += mass * x_new * x_new
        return num / den

    @property
    def b(self) -> float:
        """Half-thickness R·sin α [m] (the rectangle's; the centroid's x from O otherwise)."""
        return self.R * math.sin(self.alpha)

    @property
    def h(self) -> float:
        """Half-height R·cos α [m] (the rectangle's; the centroid's height otherwise)."""
        return self.R * math.cos(self.alpha)

    @property
    def p2(self) -> float:
        """p² = m g R / I_O [rad²/s²] (Housner 1963's frequency parameter, squared)."""
        raise NotImplementedError

    @property
    def p(self) -> float:
        """Frequency parameter p [rad/s] (paper Eq. 2: √(3g/(4R)) for the rectangle)."""
        return math.sqrt(self.p2)

    @property
    def inertia(self) -> float:
        """The polar moment of inertia about pivot O at rest [kg·m²]."""
        raise NotImplementedError

    @property
    def own_inertia(self) -> float:
        """The inertia the equation of motion adds to the point table's J [kg·m²]."""
        raise NotImplementedError

    @property
    def weight(self) -> float:
        """W = m g [N]."""
        if self.mass is None:
            raise ValueError("the block has no mass")
        return self.mass * self.g

    @property
    def uplift_acceleration(self) -> float:
        """Ground acceleration that starts rocking from rest [g]: the lower of the two sides,
        or the free side's when the system can rotate to one side only (the stopped side's
        threshold, possibly negative for a wedge leaning on its return walls, is no uplift)."""
        pos, neg = uplift_accelerations(self)
        if self.one_sided:
            return pos if self.free_side == POSITIVE else neg
        return min(pos, neg)

    @property
    def loaded(self) -> bool:
        """True when the general equation of motion is needed (loads, thrusts, another shape)."""
        return True

    def restitution(self, s: int) -> float:
        """Coefficient of restitution of an impact that ends a phase on side s [-]."""
        return self.e if s > 0 or self.e_neg is None else self.e_neg

    @property
    def centroid(self) -> tuple[float, float]:
        """Its centroid from pivot O at rest, (x, z) [m] (for reports): (b, h)."""
        return self.b, self.h

    @property
    def collapse_limit(self) -> float:
        """The largest rotation its equation of motion holds to [rad] (a chain's table
        ends; inf: none)."""
        return math.inf

    def centroid_row(self) -> tuple[float, ...]:
        """The system's own row of the point table (:func:`point_table`)."""
        raise NotImplementedError

    def mirrored_shape(self) -> dict:
        """The fields of its own shape seen in a mirror (:func:`mirrored`)."""
        return {}

    def shape_symmetric(self) -> bool:
        """True when its own shape is its mirror image (:func:`mirror_symmetric`)."""
        return True


@dataclass(frozen=True)
class Block(Rocker):
    """The paper's rigid rectangular block rocking on a rigid base, with its restrainers:
    half-thickness b = R sin α, half-height h = R cos α, I0 = 4/3·m·R² (paper Eqs. 1–3)."""

    @property
    def kind(self) -> str:
        return "points" if self.loaded else "rectangle"

    @property
    def p2(self) -> float:
        """p² = m g R / I0 = 3g/(4R) [rad²/s²] (paper Eq. 2)."""
        return frequency_parameter_sq(self.R, self.g)

    @property
    def inertia(self) -> float:
        """I0 = 4/3·m·R² [kg·m²], polar moment about a base corner."""
        if self.mass is None:
            raise ValueError("the block has no mass")
        return polar_inertia(self.mass, self.R)

    @property
    def own_inertia(self) -> float:
        """I0: its row of the point table carries no mass."""
        return self.inertia

    @property
    def loaded(self) -> bool:
        """True when loads or thrusts act on the block (the general equation of motion)."""
        return bool(self.loads or self.thrusts)

    def centroid_row(self) -> tuple[float, ...]:
        """Its weight bears and moves at its centroid (b, h) from either pivot; its I0 is
        added apart."""
        w = self.weight
        return (w, w, 0.0, self.b, self.b, self.h, 0.0, 0.0, 0.0)

    def uplifts(self) -> tuple[float, float]:
        """tan α on both sides (α linearized) without loads and thrusts."""
        if self.loaded:
            return super().uplifts()
        a0 = uplift_threshold(self.alpha, self.linearized)
        return a0, a0

    def collapses(self) -> tuple[float, float]:
        """α on both sides without loads and thrusts."""
        if self.loaded:
            return super().collapses()
        return self.alpha, self.alpha

    def weights_moment(self, s: int, a: float) -> float:
        """m g R sin(α − a) without loads and thrusts (paper Eq. 1)."""
        if self.loaded:
            return super().weights_moment(s, a)
        return self.weight * self.R * gravity_moment_ratio(self.alpha, a, self.linearized)

    def weights_stiffness(self, s: int) -> float:
        """−m g R cos α without loads and thrusts (paper Eq. 16 without springs)."""
        if self.loaded:
            return super().weights_stiffness(s)
        return -self.weight * self.R * (1.0 if self.linearized else math.cos(self.alpha))

    def own_momentum(self, s: int) -> tuple[float, float]:
        """m(4h² − 2b²)/3 and I0: (I0 − 2 m b²)/I0 = 1 − 1.5 sin²α alone (paper Eq. 3)."""
        m = self.mass
        assert m is not None
        b, h = self.b, self.h
        return m * (4.0 * h * h - 2.0 * b * b) / 3.0, self.inertia


@dataclass(frozen=True)
class RigidBody(Rocker):
    """One rigid body of any shape (a mechanism of the catalogue: a storey above a floor, a
    wall with its wedge, a gable), run by the general equation of motion as a rigid point
    mass at its centroid plus its own moment of inertia I_G (docs/physics.md). R and α are its
    centroid's distance and angle from the vertical about pivot O.

    Attributes:
        shape: (x_pos, x_neg, z, I_G): its centroid's distances from pivot O and O′ and its
            height [m], and its moment of inertia about the centroid [kg·m²].
    """

    shape: tuple[float, float, float, float] = field(kw_only=True)

    @property
    def kind(self) -> str:
        return "points"

    @property
    def p2(self) -> float:
        """m g R / I_O with its own I_O about O (Housner 1963's definition)."""
        return self.weight * self.R / self.inertia

    @property
    def inertia(self) -> float:
        """I_G + m·R² about pivot O (parallel axes)."""
        if self.mass is None:
            raise ValueError("the body has no mass")
        return self.shape[3] + self.mass * self.R * self.R

    @property
    def own_inertia(self) -> float:
        """I_G: its row of the point table carries its mass, so that J holds m·r_G²."""
        return self.shape[3]

    def centroid_row(self) -> tuple[float, ...]:
        """A rigid point mass at its centroid, plus I_G apart."""
        x_pos, x_neg, z, _ = self.shape
        w = self.weight
        return (w, w, 0.0, x_pos, x_neg, z, self.mass or 0.0, 0.0, 0.0)

    def mirrored_shape(self) -> dict:
        x_pos, x_neg, z, i_g = self.shape
        return {"shape": (x_neg, x_pos, z, i_g)}

    def own_momentum(self, s: int) -> tuple[float, float]:
        """I_G + m(z² − x·x′) and I_G + m(x′² + z²), as a load below."""
        m = self.mass
        assert m is not None
        x_pos, x_neg, z, i_g = self.shape
        x, x_new = (x_pos, x_neg) if s > 0 else (x_neg, x_pos)
        return i_g + m * (z * z - x * x_new), i_g + m * (x_new * x_new + z * z)

    def shape_symmetric(self) -> bool:
        return self.shape[0] == self.shape[1]


@dataclass(frozen=True)
class Chain(Rocker):
    """A mechanism of several bodies with one degree of freedom (the two-block vertical
    flexure), as the engines read it: its table (:class:`ChainTable`). R is its bodies'
    centroid's distance from O and α its instability rotation (where the weights' restoring
    moment vanishes, as α for the rectangle); its loads and thrusts are inside the table.

    Attributes:
        table: the terms of its equation of motion along the rotation, and its constants.
    """

    table: ChainTable = field(kw_only=True)

    @property
    def kind(self) -> str:
        return "chain"

    @property
    def p2(self) -> float:
        """The table's G(0)/M(0)·(1 + (H(0)/G(0))²)^½ [rad²/s²]."""
        return self.table.p2

    @property
    def inertia(self) -> float:
        """M(0) of side +1 [kg·m²]."""
        if self.mass is None:
            raise ValueError("the chain has no mass")
        return self.table.inertia[0]

    @property
    def own_inertia(self) -> float:
        """0: its table holds the whole generalised mass."""
        return 0.0

    @property
    def centroid(self) -> tuple[float, float]:
        """Its bodies' centroid at rest from pivot O (the table's)."""
        return self.table.centroid

    @property
    def collapse_limit(self) -> float:
        """Where its table ends: the run counts it collapsed there."""
        return self.table.end

    def mirrored_shape(self) -> dict:
        return {"table": self.table.mirrored()}

    def shape_symmetric(self) -> bool:
        return False

    def uplifts(self) -> tuple[float, float]:
        """The table's: the code check's α0 = (G − T)/H at rest of each side."""
        return self.table.uplift

    def collapses(self) -> tuple[float, float]:
        """The first zero of the tabulated G − T of each side."""
        return _chain_collapse(self.table, POSITIVE), _chain_collapse(self.table, NEGATIVE)

    def weights_moment(self, s: int, a: float) -> float:
        """The table's G − T at a."""
        g, _, t, _, _ = chain_terms(self.table.table, s, a)
        return g - t

    def weights_stiffness(self, s: int) -> float:
        """The table's d(G − T)/da at rest."""
        return self.table.stiffness[self.table.side(s)]

    def impact_restitution(self, s: int) -> float:
        """The table's (the projection of rockcli.mechanisms.motion.impact_ratio)."""
        return self.table.restitution[self.table.side(s)]


def rocker_fields(system: Rocker, **changes) -> dict:
    """The fields every kind of :class:`Rocker` has, as a dict, with ``changes`` applied (to
    build a system of another kind with the same settings)."""
    from dataclasses import fields

    return {f.name: getattr(system, f.name) for f in fields(Rocker)} | changes


def frequency_parameter_sq(R: Any, g: float) -> Any:
    """p² = 3g/(4R) [rad²/s²] (R a float, or an array of them: the batched path's).

    Source: paper Eq. (2); Housner (1963). Rectangular block, I0 = 4/3·m·R².
    """
    return 3.0 * g / (4.0 * R)


def polar_inertia(mass: Any, R: Any) -> Any:
    """I0 = 4/3·m·R² [kg·m²], rectangular block about a base corner (floats, or arrays of
    them: the batched path's).

    Source: paper §4.3 (I0 = 4/3·m(h² + b²)).
    """
    return 4.0 / 3.0 * mass * R * R


def housner_restitution(alpha: float) -> float:
    """e = 1 − 1.5·sin²α, Housner's coefficient of restitution (may be ≤ 0 for α ≥ 54.74°).

    Source: paper Eq. (3); Housner (1963), conservation of angular momentum at impact.
    """
    return 1.0 - 1.5 * math.sin(alpha) ** 2


def uplift_threshold(alpha: float, linearized: bool = False) -> float:
    """Ground acceleration [g] at which the free block at rest starts to rock: tan α.

    Source: spec/rocking.md, "Uplift from rest": at θ = 0, θ̈ > 0 iff üg > tan α (from
    Eq. 2 with sin(α)/cos(α)); linearized (sin x ≈ x, cos x ≈ 1) the threshold is α.
    A restrainer with no initial force does not change it (ntc.md, "Common").
    """
    return alpha if linearized else math.tan(alpha)


def sin_minus(sin_c: float, cos_c: float, sin_a: float, cos_a: float) -> float:
    """sin(c − a) from the sines and cosines of c and a (angle-difference identity)."""
    return sin_c * cos_a - cos_c * sin_a


def cos_minus(sin_c: float, cos_c: float, sin_a: float, cos_a: float) -> float:
    """cos(c − a) from the sines and cosines of c and a (angle-difference identity)."""
    return cos_c * cos_a + sin_c * sin_a


def spring_elongation_trig(
    r: float,
    sin_phi: float,
    cos_phi: float,
    a: float,
    sin_a: float,
    cos_a: float,
    linearized: bool = False,
) -> float:
    """u = r[sin φ − sin(φ − a)] from precomputed sines and cosines [m] (see spring_elongation).

    The engine evaluates sin a and cos a once per right-hand side and every spring and gravity
    reuse them; this is the same formula, not a second one. It is evaluated as

        sin φ − sin(φ − a) = cos φ·sin a + sin φ·(1 − cos a)

    (the angle-difference identity; Abramowitz & Stegun 4.3.16), a sum of two non-negative
    terms for 0 ≤ φ ≤ π/2, with 1 − cos a from :func:`versine`: its relative error is below
    3e-13 at every rotation. The difference sin φ − sin(φ − a) as written loses every digit
    below ε·r·sin φ (ε = 2.2e-16): an elongation of 1e-20 m came out as 0.
    """
    if linearized:
        return r * cos_phi * a
    return r * (cos_phi * sin_a + sin_phi * versine(a, cos_a))


#: Below this |a| [rad], 1 − cos a comes from its Taylor series: see :func:`versine`.
VERSINE_SERIES_BELOW = 0.03


def versine(a: float, cos_a: float) -> float:
    """1 − cos a, to 3e-13 relative at every a, without a division (the engine's hot path).

    Below |a| = 0.03 the Taylor series a²/2 − a⁴/24 + a⁶/720 (Abramowitz & Stegun 4.3.66),
    whose first omitted term a⁸/8! is below a⁶/20160 ≈ 4e-14 of the sum there; above, the
    difference 1 − cos a, whose rounding (ε/2 of cos a ≈ 1) is below 2.5e-13 of it. The
    difference alone is 0 below a ≈ 1e-8; the exact sin²a/(1 + cos a) costs a division that
    slowed the engine by 40 % (tests/dynamics/test_tiny_strength.py measures the accuracy).
    """
    if abs(a) < VERSINE_SERIES_BELOW:
        a2 = a * a
        return a2 * (0.5 - a2 * (1.0 / 24.0 - a2 * (1.0 / 720.0)))
    return 1.0 - cos_a


def spring_moment_trig(
    k: float,
    r: float,
    sin_phi: float,
    cos_phi: float,
    a: float,
    sin_a: float,
    cos_a: float,
    linearized: bool = False,
) -> float:
    """K·u·r·cos(φ − a) from precomputed sines and cosines [N·m] (see spring_moment)."""
    u = spring_elongation_trig(r, sin_phi, cos_phi, a, sin_a, cos_a, linearized)
    arm = r * cos_phi if linearized else r * cos_minus(sin_phi, cos_phi, sin_a, cos_a)
    return k * u * arm


def spring_elongation(r: float, phi: float, a: float, linearized: bool = False) -> float:
    """Outward horizontal displacement u of the attachment point for a rotation a = |θ| [m].

    Source: spec/rocking.md, u(θ) = r[sin φ − sin(φ − |θ|)]; paper Eq. (6) for r = 2R, φ = α.
    Linearized: u = r cos φ · |θ|.
    """
    return spring_elongation_trig(
        r, math.sin(phi), math.cos(phi), a, math.sin(a), math.cos(a), linearized
    )


def spring_moment(k: float, r: float, phi: float, a: float, linearized: bool = False) -> float:
    """Restoring moment magnitude K·u·r·cos(φ − |θ|) of one spring about the active pivot [N·m].

    Source: spec/rocking.md, M(θ) = s·K·u(θ)·r·cos(φ − |θ|); paper Eq. (4) and (8) for the top
    corner (4KR² cos(α − θ)[sin α − sin(α − θ)]). Linearized: K r² cos²φ · |θ|.
    """
    return spring_moment_trig(
        k, r, math.sin(phi), math.cos(phi), a, math.sin(a), math.cos(a), linearized
    )


def spring_failure_rotation(
    r: float, phi: float, fails_at: float, linearized: bool = False
) -> float:
    """Rotation a = |θ| at which the spring elongation reaches ``fails_at`` [rad] (inf: never).

    Inverse of :func:`spring_elongation`: sin(φ − a) = q = sin φ − x with x = u_f/r (u grows
    with a up to a = φ + π/2, beyond any rotation a block survives). Written as
    a = atan2(sin a, cos a) with, from the angle-difference identities and
    cos(φ − a) = √(1 − q²) = √(cos²φ + w), w = x·(2 sin φ − x) = sin²φ − q²,

        sin a = sin φ·cos(φ − a) − cos φ·q = x·cos φ + sin φ·w / (cos(φ − a) + cos φ)
        cos a = cos φ·cos(φ − a) + sin φ·q

    (Abramowitz & Stegun 4.3.16–4.3.17; the difference cos(φ − a) − cos φ rewritten as
    w/(cos(φ − a) + cos φ)), so that a small elongation gives its rotation to a few ulps: the
    form φ − asin(sin φ − x) returned 0 for any x below ε·sin φ (ε = 2.2e-16), and a member
    whose yield or rupture elongation was that small never yielded nor broke.
    """
    if not math.isfinite(fails_at):
        return math.inf
    if linearized:
        c = r * math.cos(phi)
        return fails_at / c if c > 0.0 else math.inf
    sin_phi = math.sin(phi)
    cos_phi = math.cos(phi)
    x = fails_at / r
    if sin_phi - x < -1.0:
        return math.inf
    w = x * (2.0 * sin_phi - x)
    cos_q = math.sqrt(max(cos_phi * cos_phi + w, 0.0))
    sin_a = x * cos_phi + sin_phi * w / (cos_q + cos_phi)
    cos_a = cos_phi * cos_q + sin_phi * (sin_phi - x)
    return math.atan2(sin_a, cos_a)


def gravity_moment_ratio(alpha: float, a: float, linearized: bool = False) -> float:
    """Restoring moment of gravity divided by m g R: sin(α − |θ|) (α − |θ| linearized) [-].

    Source: paper Eq. (1), (14).
    """
    return (alpha - a) if linearized else math.sin(alpha - a)


def gravity_moment_ratio_trig(
    alpha: float,
    sin_alpha: float,
    cos_alpha: float,
    a: float,
    sin_a: float,
    cos_a: float,
    linearized: bool = False,
) -> float:
    """sin(α − a) (α − a linearized) from precomputed sines and cosines [-] (paper Eq. 1)."""
    return (alpha - a) if linearized else sin_minus(sin_alpha, cos_alpha, sin_a, cos_a)


def ground_moment_ratio_trig(
    sin_alpha: float, cos_alpha: float, sin_a: float, cos_a: float, linearized: bool = False
) -> float:
    """cos(α − a) (1 linearized) from precomputed sines and cosines [-] (paper Eq. 1, 13)."""
    return 1.0 if linearized else cos_minus(sin_alpha, cos_alpha, sin_a, cos_a)


def ground_moment_ratio(alpha: float, a: float, linearized: bool = False) -> float:
    """Moment of a unit ground acceleration divided by m g R: cos(α − |θ|) (1 linearized) [-].

    Source: paper Eq. (1), (13).
    """
    return 1.0 if linearized else math.cos(alpha - a)


def restoring_moment(
    block: Rocker, s: int, a: float, alive: tuple[bool, ...] | None = None
) -> float:
    """Total restoring moment about the active pivot, gravity plus restrainers [N·m].

    M_r = m g R sin(α − a) + Σ_k K_k u_k r_k cos(φ_k − a), a = |θ| ≥ 0 on side s (paper Eq. 14,
    generalised to any attachment point as in spec/rocking.md). ``alive`` masks failed springs.
    With loads and thrusts the weights' part is G − s·T of :func:`point_moments`.
    """
    total = block.weights_moment(s, a)
    for i, spring in enumerate(block.restrainers):
        if alive is not None and not alive[i]:
            continue
        k, r, phi = spring.side(s)
        if spring.path:  # K·u·u′: the force times the point's virtual displacement
            u, du = path_terms(spring.path, 0, s, a)
            total += k * u * du
        else:
            total += spring_moment(k, r, phi, a, block.linearized)
    return total


def tie_rod_stiffness(diameter: float, length: float, modulus: float = 210e9) -> float:
    """Axial stiffness of a steel tie-rod K = E·π·d²/4 / L [N/m].

    Source: spec/README.md (model file, convenience forms); paper Table 2 (Ø20, L = 3 m:
    2.2e7 N/m).
    """
    return modulus * math.pi * diameter**2 / 4.0 / length


def point_polar(x: float, z: float) -> tuple[float, float]:
    """(r, φ) of a point at horizontal distance x from the pivot and height z above the base.

    Source: spec/rocking.md: r = √(x² + z²), φ = atan(x/z) (angle from the vertical, into the
    block).
    """
    return math.hypot(x, z), math.atan2(x, z)


def stiffness_coefficient(k: float, R: float, inertia: float) -> float:
    """c_K = 4 K R² / I0 [1/s²], the paper's quick effectiveness term of a restrainer.

    Source: paper §4.3 (c_K should exceed c_E = p² by one or two orders of magnitude).
    """
    return 4.0 * k * R * R / inertia


def linear_global_stiffness(
    block: Rocker, s: int = POSITIVE, alive: tuple[bool, ...] | None = None
) -> float:
    """dM_r/dθ at θ = 0⁺ on side s [N·m/rad]: negative for the free block, positive if restrained.

    Source: paper Eq. (16)–(18) for the top spring (positive iff 4KR/(mg) > 1/cos α); for any
    attachment point the same derivative of :func:`restoring_moment`:
    −m g R cos α + Σ K r² cos²φ (the spring's u is r cos φ·θ, its arm r cos φ, at θ = 0; a
    member with a path: K·u′(0)², Restrainer.arm_at_rest).
    With loads and thrusts the weights' part is :func:`loaded_stiffness`.
    """
    total = block.weights_stiffness(s)
    for i, spring in enumerate(block.restrainers):
        if alive is not None and not alive[i]:
            continue
        total += spring.side(s)[0] * spring.arm_at_rest(s) ** 2
    return total


def restrainer_coefficient(k: float, r: float, inertia: float) -> float:
    """c_K = K r² / I0 [1/s²] for a spring at distance r from the pivot.

    Source: paper §4.3, c_K = 4KR²/I0 for the top spring (r = 2R): the coefficient of the
    KSTAB term of Eq. (12), written for any attachment radius (spec/rocking.md, M(θ)).
    """
    return k * r * r / inertia


def mirrored(block: Rocker) -> Rocker:
    """The block seen in a mirror through its vertical mid-plane: pivot O becomes O′.

    Each restrainer's two sides are swapped (stiffness, arm, angle, yield), each load's and
    thrust's distances from the two pivots, each thrust's direction, and the restitution of
    the two sides. One-sided motion swaps its free side (two-sided motion ignores it).
    """
    from dataclasses import replace

    return replace(
        block,
        free_side=-block.free_side if block.one_sided else block.free_side,
        e=block.e if block.e_neg is None else block.e_neg,
        e_neg=None if block.e_neg is None else block.e,
        restrainers=tuple(
            replace(
                r,
                k_pos=r.k_neg,
                k_neg=r.k_pos,
                r_pos=r.r_neg,
                r_neg=r.r_pos,
                phi_pos=r.phi_neg,
                phi_neg=r.phi_pos,
                yield_pos=r.yield_neg,
                yield_neg=r.yield_pos,
                path=mirrored_path(r.path),
            )
            for r in block.restrainers
        ),
        loads=tuple(replace(ld, x_pos=ld.x_neg, x_neg=ld.x_pos) for ld in block.loads),
        thrusts=tuple(
            replace(th, x_pos=th.x_neg, x_neg=th.x_pos, direction=-th.direction)
            for th in block.thrusts
        ),
        frictions=tuple(replace(f, x_pos=f.x_neg, x_neg=f.x_pos) for f in block.frictions),
        **block.mirrored_shape(),
    )


def mirror_symmetric(block: Rocker) -> bool:
    """True when the block is its own mirror image (:func:`mirrored`), so that its response
    to −üg is exactly its response to +üg with θ → −θ.

    The equations of motion of the two pivots (paper Eq. 1 with the restrainers of §4.1, the
    loads and thrusts of docs/physics.md) map onto each other under θ → −θ, üg → −üg when
    every quantity of side +1 equals its counterpart of side −1: two-sided motion, each
    restrainer the same on both sides, each load as far from O as from O′, the same
    restitution after impacts on either side, and no thrust (a thrust pushes one way). Exact
    equality: a difference in the last digit makes the block asymmetric.
    """
    if block.one_sided or block.thrusts or not block.shape_symmetric():
        return False
    if block.e_neg is not None and block.e_neg != block.e:
        return False
    # mirrored(block) == block, field by field without building the mirror (once per case of
    # a study): each restrainer and load the same from either pivot.
    return (
        all(
            r.k_pos == r.k_neg
            and r.r_pos == r.r_neg
            and r.phi_pos == r.phi_neg
            and r.yield_pos == r.yield_neg
            for r in block.restrainers
        )
        and all(ld.x_pos == ld.x_neg for ld in block.loads)
        and all(f.x_pos == f.x_neg for f in block.frictions)
    )


# Columns of a row of the point table (point_table): the block at its centroid, each load,
# each thrust. Weights [N] that bear on the block and that move with it horizontally, the
# thrust d·F [N] (d = ±1 its direction), the point's x from pivot O and from O′ [m], its height
# z [m], and its mass [kg] by how it follows the block: rigidly (full), horizontally only, or
# vertically only. The block's own rotational inertia I0 is not in the table.
PT_BEARS, PT_MOVES, PT_PUSH, PT_X_POS, PT_X_NEG, PT_Z = 0, 1, 2, 3, 4, 5
PT_M_FULL, PT_M_HOR, PT_M_VER = 6, 7, 8
N_POINT_COLS = 9


def point_table(block: Rocker) -> tuple[float, ...]:
    """The block, its loads and its thrusts as a flat table of N_POINT_COLS columns per row.

    Row 0 is the block: its weight bears and moves, at its centroid (b, h) from either pivot
    (its inertia I0 is added apart). A load of mass m = P/g that bears and moves is a rigid
    point mass; one that only moves (Circolare's P_j) follows the block horizontally; one that
    only bears follows it vertically. A thrust has no mass. Needs the block's mass.
    """
    rows: list[float] = list(block.centroid_row())
    for ld in block.loads:
        m = ld.weight / block.g
        rows += [
            ld.weight if ld.bears else 0.0,
            ld.weight if ld.moves else 0.0,
            0.0,
            ld.x_pos,
            ld.x_neg,
            ld.z,
            m if ld.bears and ld.moves else 0.0,
            m if ld.moves and not ld.bears else 0.0,
            m if ld.bears and not ld.moves else 0.0,
        ]
    for th in block.thrusts:
        rows += [0.0, 0.0, th.direction * th.force, th.x_pos, th.x_neg, th.z, 0.0, 0.0, 0.0]
    return tuple(rows)


def point_moments(points, s, sin_a, cos_a):
    """Moments about pivot s of the weights, the earthquake and the thrusts at rotation a.

    A point at (x, z) from the pivot at rest is, after a rotation a about it, at horizontal
    distance X = x cos a − z sin a inside the pivot and at height Y = z cos a + x sin a; its
    horizontal velocity is −Y·ȧ and its vertical velocity X·ȧ (rigid rotation; Sorrentino,
    Masiani & Griffith 2008 and DeJong & Dimitrakopoulos 2014 write the overburden wall the
    same way). Hence, summed over the rows of ``points`` (point_table):

    - G = Σ P_bears·X: restoring moment of the weights that bear (the block: m g R sin(α − a),
      paper Eq. 1);
    - H = Σ P_moves·Y: overturning moment of a unit horizontal acceleration (1 g) of the masses
      that move with the block (the block: m g R cos(α − a));
    - T = Σ d·F·Y: moment of the thrusts towards θ > 0 (times s: towards side s);
    - J = Σ m_full (X² + Y²) + m_hor Y² + m_ver X²: rotational inertia added to I0 (kinetic
      energy ½ J ȧ²);
    - dJ = dJ/da = 2 Σ (m_hor − m_ver) X Y.

    ``points`` is any flat sequence indexable by integers (a tuple, or a numpy array in the
    compiled engine). Returns (G, H, T, J, dJ) [N·m, N·m per g, N·m, kg·m², kg·m²/rad].
    """
    col = PT_X_POS if s > 0 else PT_X_NEG
    g = 0.0
    h = 0.0
    t = 0.0
    j = 0.0
    dj = 0.0
    for k in range(0, len(points), N_POINT_COLS):
        x = points[k + col]
        z = points[k + PT_Z]
        big_x = x * cos_a - z * sin_a
        big_y = z * cos_a + x * sin_a
        g += points[k + PT_BEARS] * big_x
        h += points[k + PT_MOVES] * big_y
        t += points[k + PT_PUSH] * big_y
        m_hor = points[k + PT_M_HOR]
        m_ver = points[k + PT_M_VER]
        j += (
            points[k + PT_M_FULL] * (big_x * big_x + big_y * big_y)
            + m_hor * big_y * big_y
            + m_ver * big_x * big_x
        )
        dj += 2.0 * (m_hor - m_ver) * big_x * big_y
    return g, h, t, j, dj


def uplift_accelerations(block: Rocker) -> tuple[float, float]:
    """(α0⁺, α0⁻): the ground acceleration [g] that starts rocking from rest towards each side.

    Free block: tan α on both sides (α linearized; spec/rocking.md, "Uplift from rest"). With
    loads and thrusts, from the equation of motion at a = 0 (point_moments): the block leaves
    rest towards s when s·üg·H(0) + s·T(0) > G(0), so α0_s = (G(0) − s·T(0)) / H(0) — the
    Circolare's virtual-work multiplier (Circ. 617/2009 Eq. C8A.4.1; Circ. 7/2019 C8.7.1.1)
    with the thrust as an external force F_h, the same expression by construction.
    A restrainer with no initial force does not change it.
    """
    return block.uplifts()


#: Points that bracket the zero of a chain's restoring moment before bisection, and the
#: bisection's steps (the rotation resolved to end·2⁻⁶⁰/COLLAPSE_POINTS).
COLLAPSE_POINTS, COLLAPSE_STEPS = 200, 60


def collapse_rotations(block: Rocker) -> tuple[float, float]:
    """(θc⁺, θc⁻): the rotation of each side at which the restoring moment of the weights,
    loads and thrusts vanishes [rad] — where the mechanism, left alone, stops returning and
    falls (the rectangle: α on both sides; a chain: its instability rotation of each side).

    The damage measure max θ/θc of every mechanism divides by it, side by side
    (docs/interpretations.md). Restrainers are left out: a tie holding the mechanism beyond
    it (a positive stiffness) does not move the mechanism's own collapse rotation, so the
    measure stays the same with and without the tie. With loads and thrusts (point_moments)
    the restoring moment about pivot s is G − s·T = A·cos a − B·sin a, A = Σ P_bears·x −
    s·Σ d·F·z, B = Σ P_bears·z + s·Σ d·F·x, which vanishes at a = atan2(A, B) (capped at π/2,
    where the run counts the block overturned). A chain: the zero of its tabulated G − T by
    bracketing and bisection on [0, end] (end when it never vanishes there).
    """
    return block.collapses()


def _chain_collapse(chain: ChainTable, s: int) -> float:
    """The first zero of the chain's G − T on side s in [0, end] [rad] (end: none there)."""

    def restoring(a: float) -> float:
        g, _, t, _, _ = chain_terms(chain.table, s, a)
        return g - t

    lo = 0.0
    for k in range(1, COLLAPSE_POINTS + 1):
        hi = chain.end * k / COLLAPSE_POINTS
        if restoring(hi) <= 0.0:
            for _ in range(COLLAPSE_STEPS):
                mid = 0.5 * (lo + hi)
                if restoring(mid) > 0.0:
                    lo = mid
                else:
                    hi = mid
            return 0.5 * (lo + hi)
        lo = hi
    return chain.end


def impact_restitution(block: Rocker, s: int) -> float:
    """Housner's coefficient of restitution for an impact ending a phase on side s, with loads.

    Conservation of angular momentum about the new pivot O′ (Housner 1963; paper Eq. 3): a
    particle at (x, z) from the old pivot, x′ = 2b − x from the new one, brings
    m(z² − x·x′)·θ̇⁻ to the momentum about O′ if it moves rigidly (z² alone if it follows the
    block horizontally only, −x·x′ if vertically only); after the impact the whole turns about
    O′ with the inertia J′(0) = I0 + Σ m(x′² + z²) (its horizontal and vertical parts likewise).
    The block alone gives (I0 − 2 m b²)/I0 = 1 − 1.5 sin²α. Returns the ratio θ̇⁺/θ̇⁻
    (may be ≤ 0 for squat systems; the model clips it at 0). A chain: its own
    (ChainTable.restitution, the projection of rockcli.mechanisms.motion.impact_ratio).
    """
    return block.impact_restitution(s)


def rebound_restitution(block: Rocker) -> float:
    """θ̇⁺/θ̇⁻ of a one-sided system's impact before its rebound factor r_f: the ratio that keeps
    the kinetic energy Housner's impact at the other pivot keeps, the system turning back
    about the same pivot (docs/physics.md, "One-sided impacts").

    Per unit rate, the velocity field about O is w and about O′ is w′; with N = ∫ w·w′ dm
    (the numerator of :func:`impact_restitution`, the same for both sides) and the inertias
    D = ∫ |w|² dm about O and D′ about O′, the impact at O′ keeps N²/(D·D′) of the kinetic
    energy (Housner's e = N/D′, times (D′/D) for the inertia), and the system turning back
    about O with that energy has |θ̇⁺/θ̇⁻| = N/√(D·D′) = √(e₊·e₋), e_s of each side
    (:func:`impact_restitution`). Cauchy–Schwarz: |N| ≤ √(D·D′), equal only for fields that
    are parallel, so the impact always dissipates; a body symmetric about its mid-plane
    (D = D′) gives Housner's e itself. Signed as N (e₊ and e₋ share N's sign).
    """
    e_pos, e_neg = impact_restitution(block, 1), impact_restitution(block, -1)
    return math.copysign(math.sqrt(e_pos * e_neg), e_pos)


def loaded_stiffness(points: tuple[float, ...], s: int) -> float:
    """d(G − s·T)/da at a = 0 on side s [N·m/rad]: −Σ_bears P z − s·Σ d F x_s.

    The derivative of point_moments' restoring terms (dX/da = −z, dY/da = x at a = 0); the
    block alone gives −m g h = −m g R cos α (paper Eq. 16 without springs).
    """
    col = PT_X_POS if s > 0 else PT_X_NEG
    total = 0.0
    for k in range(0, len(points), N_POINT_COLS):
        total -= points[k + PT_BEARS] * points[k + PT_Z] + s * points[k + PT_PUSH] * points[k + col]
    return total
