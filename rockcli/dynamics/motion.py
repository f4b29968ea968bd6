"""The rules of the rocking motion, shared by the fast engine and the reference engine.

Plain scalar functions of floats and small arrays (no numpy calls), so that the compiled
engine (:mod:`rockcli.dynamics.kernel`) compiles this very code with numba and the reference
engine (:mod:`rockcli.dynamics.reference`) calls it as Python. The mechanics (gravity,
ground and spring moments) come from :mod:`rockcli.mechanics`, written once for both the
rocking and the kinematic analyses.

Sign convention of the source paper (spec/rocking.md): a positive ground acceleration drives
a positive rotation; s = ±1 is the active pivot side, a = s·θ ≥ 0 the rotation about it.

Packed restrainer table (one row per restrainer), columns:
``K+ [N/m], K− [N/m], r+ [m], φ+ [rad], r− [m], φ− [rad], a_fail+ [rad], a_fail− [rad],
fails_at [m], sin φ+, cos φ+, sin φ−, cos φ−`` (a_fail: rotation about the pivot at which the
elongation reaches fails_at; the sines and cosines are precomputed for the right-hand side),
then the member law (docs/physics.md, "Restrainers with strength"): yield force per side [N],
the anchor's rupture force [N], and the law's state per side, updated by the engines during a
run: the slack point c [m] (the elongation at which the member's force is zero: −P0/K with a
pretension P0, grown by yielding), the mode (elastic, plastic, slack), the next rotation levels
at which the law changes (upward: yield, re-engage or rupture at the anchor; downward: slack)
and the initial c. A row with COL_MEMORY = 0 is the elastic spring of unlimited strength: its
mode stays elastic and c = 0, so its force K·(u − 0) is K·u to the last bit.

Columns come in pairs (side +1, side −1): ``COL_X + side_index(s)``.

A member on the upper block of a two-block chain (mechanics.Restrainer.path) does not turn
about the pivot: its elongation u(a) and its slope u′(a) (the virtual displacement of its point,
the arm of its force) come from its tabulated path, stored from column COL_PATH in a table made
wide enough for it (mechanics.path_terms; a row without one, or a table without those columns,
is a polar member). Its r, φ columns hold u′(0) and 0, so that what reads the arm at rest
(rest_moment) reads the path's.
"""

from __future__ import annotations

import math

from rockcli.mechanics import (
    PA_N,
    chain_terms,
    cos_minus,
    friction_moment,
    gravity_moment_ratio_trig,
    ground_moment_ratio_trig,
    path_rotation,
    path_terms,
    point_moments,
    spring_elongation,
    spring_elongation_trig,
    spring_failure_rotation,
)

#: Columns of the packed restrainer table.
COL_K_POS, COL_K_NEG, COL_R_POS, COL_PHI_POS, COL_R_NEG, COL_PHI_NEG = 0, 1, 2, 3, 4, 5
COL_A_FAIL_POS, COL_A_FAIL_NEG, COL_FAILS_AT = 6, 7, 8
COL_SIN_POS, COL_COS_POS, COL_SIN_NEG, COL_COS_NEG = 9, 10, 11, 12
COL_YIELD, COL_RUPTURE, COL_C, COL_MODE = 13, 15, 16, 18
COL_UP, COL_UP_KIND, COL_DOWN, COL_MEMORY, COL_C0 = 20, 22, 24, 26, 27
N_SPRING_COLS = 29
#: First column of a member's elongation path (module docstring), in a wider table.
COL_PATH = N_SPRING_COLS

#: Modes of a member side (COL_MODE): F = K·(u − c); F = F_y (on the yield plateau); F = 0.
MODE_ELASTIC, MODE_PLASTIC, MODE_SLACK = 0.0, 1.0, 2.0
#: What happens at a member's upward level (COL_UP_KIND).
UP_NONE, UP_YIELD, UP_ENGAGE, UP_BREAK = 0.0, 1.0, 2.0, 3.0
#: No downward level (a ≥ 0 never falls below it).
NO_LEVEL_DOWN = -1.0
#: Lowest upward level of a member's law [rad]: the smallest positive double. A yield or
#: rupture elongation that rounds to zero (a force F with F/K below the rounding of the slack
#: point c) would put the level at a = 0, which a block leaving rest never crosses: both
#: engines find an upward level where a_start < level ≤ a_end. Just above zero, the first
#: step crosses it, and the member yields (or breaks) as the block leaves rest.
LOWEST_LEVEL_UP = 5e-324


def spring_on_side(springs, j, s):
    """(K, r, φ, a_fail) of restrainer row j for pivot side s = ±1."""
    if s > 0:
        return (
            springs[j, COL_K_POS],
            springs[j, COL_R_POS],
            springs[j, COL_PHI_POS],
            springs[j, COL_A_FAIL_POS],
        )
    return (
        springs[j, COL_K_NEG],
        springs[j, COL_R_NEG],
        springs[j, COL_PHI_NEG],
        springs[j, COL_A_FAIL_NEG],
    )


def spring_trig_on_side(springs, j, s):
    """(K, r, sin φ, cos φ) of restrainer row j for pivot side s = ±1."""
    if s > 0:
        return (
            springs[j, COL_K_POS],
            springs[j, COL_R_POS],
            springs[j, COL_SIN_POS],
            springs[j, COL_COS_POS],
        )
    return (
        springs[j, COL_K_NEG],
        springs[j, COL_R_NEG],
        springs[j, COL_SIN_NEG],
        springs[j, COL_COS_NEG],
    )


def has_path(springs, j):
    """True when row j's member has an elongation path (module docstring)."""
    return springs.shape[1] > COL_PATH and springs[j, COL_PATH + PA_N] > 0.0


def path_on_side(springs, j, s, a):
    """(u [m], u′ [m/rad]) of row j's path on pivot side s at rotation a."""
    return path_terms(springs[j], COL_PATH, s, a)


def side_index(s):
    """0 for pivot side +1, 1 for side −1: the offset of a side's column in a pair."""
    return 0 if s > 0 else 1


def member_force(springs, j, s, k, u):
    """Force of restrainer row j's member on side s at elongation u [N] (its law and state).

    Elastic–perfectly plastic in tension only, with memory (docs/physics.md, "Restrainers with
    strength"): elastic F = K·(u − c) above the slack point c; on the yield plateau F = F_y;
    slack F = 0. An elastic spring of unlimited strength has c = 0: F = K·u.
    """
    col = side_index(s)
    mode = springs[j, COL_MODE + col]
    if mode == MODE_ELASTIC:
        return k * (u - springs[j, COL_C + col])
    if mode == MODE_PLASTIC:
        return springs[j, COL_YIELD + col]
    return 0.0


def spring_arm(r, sin_phi, cos_phi, sin_a, cos_a, linearized):
    """r·cos(φ − a), the lever arm of a horizontal force at the point (r·cos φ linearized) [m].

    A function of scalars of its own (the engine compiles it without inlining its branch into
    the right-hand side: numba's IR inlining of a conditional expression misfires).
    """
    if linearized:
        return r * cos_phi
    return r * cos_minus(sin_phi, cos_phi, sin_a, cos_a)


def restrainer_force(springs, alive, j, s, a, linearized):
    """Restrainer row j's force in the current state [N]: its member's on pivot side s at
    rotation a; at rest (s = 0) the larger of its two members' forces at a = 0 (a
    pretension); 0 once it is lost. What the engines store in a run's history."""
    force = 0.0
    if alive[j] == 0:
        return force
    for side in (1, -1):
        if s == 0 or side == s:
            k, _, _, _ = spring_on_side(springs, j, side)
            if k != 0.0:
                u = elongation_on_side(springs, j, side, a, linearized)
                force = max(force, member_force(springs, j, side, k, u))
    return force


def member_moment(springs, j, s, k, r, sin_phi, cos_phi, a, sin_a, cos_a, linearized):
    """F·r·cos(φ − a): the restoring moment of row j's member on side s [N·m].

    Source: spec/rocking.md, M_k = K·u·r·cos(φ − |θ|) (paper Eq. 4), with the member's force F
    of :func:`member_force` in place of K·u (the same products, so an elastic spring gives the
    same bits as mechanics.spring_moment_trig).
    """
    u = spring_elongation_trig(r, sin_phi, cos_phi, a, sin_a, cos_a, linearized)
    return member_force(springs, j, s, k, u) * spring_arm(
        r, sin_phi, cos_phi, sin_a, cos_a, linearized
    )


def rotation_at_elongation(springs, j, s, u, linearized):
    """Rotation a ≥ 0 about pivot s at which row j's elongation is u [rad] (inf: never)."""
    if u <= 0.0:
        return 0.0
    if has_path(springs, j):
        return path_rotation(springs[j], COL_PATH, s, u)
    _, r, phi, _ = spring_on_side(springs, j, s)
    return spring_failure_rotation(r, phi, u, linearized)


def set_levels(springs, j, s, linearized):
    """Recompute the levels of a at which the law of row j's member on side s changes.

    Elastic: up at u = c + F/K with F the lower of the yield force (yield) and the anchor's
    rupture force (break); down at u = c (slack) when c > 0. Plastic: none (the turning point
    ends the plateau). Slack: up at u = c (re-engage).
    """
    col = side_index(s)
    k, _, _, _ = spring_on_side(springs, j, s)
    c = springs[j, COL_C + col]
    mode = springs[j, COL_MODE + col]
    up = math.inf
    kind = UP_NONE
    down = NO_LEVEL_DOWN
    if mode == MODE_ELASTIC:
        f_yield = springs[j, COL_YIELD + col]
        f_break = springs[j, COL_RUPTURE]
        if f_break <= f_yield and f_break < math.inf:
            up = max(rotation_at_elongation(springs, j, s, c + f_break / k, linearized),
                     LOWEST_LEVEL_UP)  # fmt: skip
            kind = UP_BREAK
        elif f_yield < math.inf:
            up = max(rotation_at_elongation(springs, j, s, c + f_yield / k, linearized),
                     LOWEST_LEVEL_UP)  # fmt: skip
            kind = UP_YIELD
        if c > 0.0:
            down = rotation_at_elongation(springs, j, s, c, linearized)
    elif mode == MODE_SLACK:
        up = rotation_at_elongation(springs, j, s, c, linearized)
        kind = UP_ENGAGE
    springs[j, COL_UP + col] = up
    springs[j, COL_UP_KIND + col] = kind
    springs[j, COL_DOWN + col] = down


def reset_laws(springs, linearized):
    """Every member back to its state at rest: elastic, c = c0, its levels."""
    for j in range(springs.shape[0]):
        if springs[j, COL_MEMORY] != 0.0:
            for s in (1, -1):
                col = side_index(s)
                springs[j, COL_MODE + col] = MODE_ELASTIC
                springs[j, COL_C + col] = springs[j, COL_C0 + col]
                k, _, _, _ = spring_on_side(springs, j, s)
                if k != 0.0:
                    set_levels(springs, j, s, linearized)
                else:
                    springs[j, COL_UP + col] = math.inf
                    springs[j, COL_DOWN + col] = NO_LEVEL_DOWN


def cross_up(springs, j, s, linearized):
    """Row j's member on side s reached its upward level: yield (→ plastic) or re-engage
    (→ elastic). Returns UP_YIELD or UP_ENGAGE (an UP_BREAK is handled as a failure)."""
    col = side_index(s)
    kind = springs[j, COL_UP_KIND + col]
    springs[j, COL_MODE + col] = MODE_PLASTIC if kind == UP_YIELD else MODE_ELASTIC
    set_levels(springs, j, s, linearized)
    return kind


def engage(springs, j, s, a, linearized):
    """Row j's slack member on side s re-engages at rotation a (→ elastic, F = K·(u − c)).

    Returns the kind of its next upward level when the rotation a is already at or past it
    (UP_YIELD or UP_BREAK: its force to yield or break, F/K, is below the rounding of c, so
    the member reaches it as it re-engages, and the engine applies it at once), else UP_NONE.
    """
    cross_up(springs, j, s, linearized)
    col = side_index(s)
    if springs[j, COL_UP + col] <= a:
        return springs[j, COL_UP_KIND + col]
    return UP_NONE


def cross_down(springs, j, s, linearized):
    """Row j's member on side s reached its slack point going down: → slack (F = 0)."""
    springs[j, COL_MODE + side_index(s)] = MODE_SLACK
    set_levels(springs, j, s, linearized)


def unload(springs, alive, s, a, linearized, energy, energy_col):
    """At a turning point a: every member on the yield plateau of side s unloads elastically.

    Its slack point becomes c = u(a) − F_y/K (so that F = F_y there, continuous); the plastic
    work of the plateau, F_y·(c_new − c_old) [J], is added to ``energy[j, energy_col]``. A
    member whose slack point is not below a (F_y/K below the rounding of u(a)) goes slack at
    once: the block turns down from a, and no level at or above a would be crossed going down.
    """
    col = side_index(s)
    for j in range(springs.shape[0]):
        if alive[j] != 0 and springs[j, COL_MODE + col] == MODE_PLASTIC:
            c_new = plateau_slack_point(springs, j, s, a, linearized)
            energy[j, energy_col] += springs[j, COL_YIELD + col] * (c_new - springs[j, COL_C + col])
            springs[j, COL_C + col] = c_new
            springs[j, COL_MODE + col] = MODE_ELASTIC
            set_levels(springs, j, s, linearized)
            if springs[j, COL_DOWN + col] >= a:
                cross_down(springs, j, s, linearized)


def plateau_slack_point(springs, j, s, a, linearized):
    """u(a) − F_y/K: the slack point of row j's member of side s on its yield plateau at
    rotation a [m] (where it unloads elastically from F_y to zero)."""
    k, _, _, _ = spring_on_side(springs, j, s)
    u = elongation_on_side(springs, j, s, a, linearized)
    return u - springs[j, COL_YIELD + side_index(s)] / k


def plateau_work(springs, j, s, a, linearized):
    """Plastic work done so far on row j's yield plateau of side s, up to rotation a [J]."""
    col = side_index(s)
    if springs[j, COL_MODE + col] != MODE_PLASTIC:
        return 0.0
    c_now = plateau_slack_point(springs, j, s, a, linearized)
    return springs[j, COL_YIELD + col] * (c_now - springs[j, COL_C + col])


def released_energy(springs, j, s, a, linearized):
    """Energy lost when row j's member on side s is lost at rotation a [J]: the plastic work of
    a plateau in progress and the elastic energy stored in it, ½·F²/K."""
    k, _, _, _ = spring_on_side(springs, j, s)
    if k == 0.0:
        return 0.0
    force = member_force(springs, j, s, k, elongation_on_side(springs, j, s, a, linearized))
    return plateau_work(springs, j, s, a, linearized) + 0.5 * force * force / k


def idle_energy(springs, j, s):
    """Elastic energy held by row j's member on side s at its rest, u = 0 [J]: ½·F²/K of a
    pretension not yet lost to slack (0 for a slack member or without stiffness). While the
    block turns about the other pivot this member is not stretched, and holds this."""
    k, _, _, _ = spring_on_side(springs, j, s)
    if k == 0.0:
        return 0.0
    force = member_force(springs, j, s, k, 0.0)
    return 0.5 * force * force / k if force > 0.0 else 0.0


def lose(springs, alive, j, s, a, linearized, energy, energy_col):
    """Restrainer row j is lost at rotation a about pivot s: the device, both its members.

    One restrainer is one device (a bar, a vault): when it breaks, or its anchor gives way, on
    either side, it acts on neither side again (docs/physics.md, "Restrainers with strength").
    ``energy[j, energy_col]`` gains what is released [J]: the plastic work of a plateau in
    progress and the elastic energy of the member of side s (released_energy), and the elastic
    energy the other side's member holds at rest (idle_energy). A plateau in progress ends where
    the member broke (c = u − F_y/K), so the plastic elongation (c − c0) includes it.
    """
    energy[j, energy_col] += released_energy(springs, j, s, a, linearized) + idle_energy(
        springs, j, -s
    )
    col = side_index(s)
    if springs[j, COL_MODE + col] == MODE_PLASTIC:
        springs[j, COL_C + col] = plateau_slack_point(springs, j, s, a, linearized)
        springs[j, COL_MODE + col] = MODE_ELASTIC
    alive[j] = 0


def any_plastic(springs, alive, s):
    """True when a live member of side s is on its yield plateau."""
    col = side_index(s)
    for j in range(springs.shape[0]):
        if alive[j] != 0 and springs[j, COL_MODE + col] == MODE_PLASTIC:
            return True
    return False


def rest_moment(springs, alive, s):
    """Σ F·r·cos φ of the members of side s at rest (a = 0): their pretension's moment [N·m].

    Only an elastic member with c < 0 pulls at a = 0 (F = −K·c); it raises the ground
    acceleration the block needs to start rocking about pivot s (statics at a = 0).
    """
    total = 0.0
    col = side_index(s)
    for j in range(springs.shape[0]):
        if alive[j] != 0 and springs[j, COL_MEMORY] != 0.0:
            c = springs[j, COL_C + col]
            if c < 0.0 and springs[j, COL_MODE + col] == MODE_ELASTIC:
                k, r, _, _ = spring_on_side(springs, j, s)
                cos_phi = springs[j, COL_COS_POS] if s > 0 else springs[j, COL_COS_NEG]
                total += -k * c * r * cos_phi
    return total


def angular_acceleration(
    a, s, ag, alpha, sin_alpha, cos_alpha, p2, linearized, springs, alive, inv_i0
):
    """θ̈ of the block on pivot side s at rotation a = s·θ under ground acceleration ag [g].

    Source: spec/rocking.md, θ̈ = −s p² sin(α − sθ) − Σ_k M_k(θ)/I0 + p² üg cos(α − sθ), with
    M_k = s·F·r·cos(φ − |θ|) (paper Eq. 2 and 4, F = K·u for an elastic spring; the member's
    law otherwise, :func:`member_force`; linearized: sin x ≈ x, cos x ≈ 1).
    sin a and cos a are evaluated once; gravity and every spring reuse them.

    Args:
        a: rotation about the active pivot s·θ [rad].
        s: pivot side, +1 or −1.
        ag: ground acceleration, polarity applied [g].
        alpha, sin_alpha, cos_alpha: slenderness [rad] and its sine and cosine.
        p2: p² [rad²/s²]. linearized: small-angle form.
        springs: packed restrainer table. alive: 1 for a restrainer still acting, 0 if failed.
        inv_i0: 1/I0 [1/(kg·m²)] (0 when there are no restrainers and no mass).
    """
    sin_a = math.sin(a)
    cos_a = math.cos(a)
    acc = -s * p2 * gravity_moment_ratio_trig(
        alpha, sin_alpha, cos_alpha, a, sin_a, cos_a, linearized
    ) + p2 * ag * ground_moment_ratio_trig(sin_alpha, cos_alpha, sin_a, cos_a, linearized)
    for j in range(springs.shape[0]):
        if alive[j] != 0:
            k, r, sin_phi, cos_phi = spring_trig_on_side(springs, j, s)
            if k != 0.0:
                acc -= (
                    s
                    * member_moment(
                        springs, j, s, k, r, sin_phi, cos_phi, a, sin_a, cos_a, linearized
                    )
                    * inv_i0
                )
    return acc


def loaded_angular_acceleration(a, s, om, ag, points, i0, springs, alive, rub, rub_x, rub_z0,
                                rub_h, rub_l):  # fmt: skip
    """θ̈ of a block with loads or thrusts on pivot side s at rotation a = s·θ, velocity θ̇ = om.

    Lagrange's equation for the one coordinate a (kinetic energy ½ [I0 + J(a)] ȧ², potential
    of the bearing weights, generalised forces of the earthquake, the thrusts, the springs
    and the friction of toothed return walls; docs/physics.md, "Loads and thrusts"):

        [I0 + J(a)]·ä + ½ J′(a)·ȧ² = −G(a) + s·T(a) + s·üg·H(a) − Σ_k M_k(a) − d·M_F(a),

    θ̈ = s·ä, with G, H, T, J, J′ from :func:`rockcli.mechanics.point_moments` (the very
    function of the capacity curve), M_k the springs' restoring moments (spec/rocking.md) and
    M_F the friction's moment (:func:`rockcli.mechanics.friction_moment`), a Coulomb moment
    against the sense d = sign(ȧ) of the motion, which the engines hold as a mode (kernel.py).
    Without loads and thrusts it is paper Eq. (2): G = m g R sin(α − a), H = m g R cos(α − a),
    J = 0.

    Args:
        a: rotation about the active pivot [rad]. s: pivot side ±1. om: θ̇ [rad/s].
        ag: ground acceleration, polarity applied [g]. points: flat point table.
        i0: the block's own polar moment of inertia about a base corner [kg·m²].
        springs, alive: as in :func:`angular_acceleration`.
        rub: d·F, the friction's force signed by the sense of the motion it resists [N]
            (0: none). rub_x: the interface's x from the pivot; rub_z0, rub_h, rub_l: the
            toothing's bottom, height and overlap [m].
    """
    sin_a = math.sin(a)
    cos_a = math.cos(a)
    g, h, t, j, dj = point_moments(points, s, sin_a, cos_a)
    moment = -g + s * t + s * ag * h - 0.5 * dj * om * om
    if rub != 0.0:
        moment -= friction_moment(rub, rub_x, rub_z0, rub_h, rub_l, a, sin_a, cos_a)
    for k in range(springs.shape[0]):
        if alive[k] != 0:
            kk, r, sin_phi, cos_phi = spring_trig_on_side(springs, k, s)
            if kk != 0.0:
                moment -= member_moment(
                    springs, k, s, kk, r, sin_phi, cos_phi, a, sin_a, cos_a, False
                )
    return s * moment / (i0 + j)


def chain_angular_acceleration(a, s, om, ag, table, springs, alive):
    """θ̈ of a chain of bodies (the two-block vertical flexure) on side s at rotation a = s·θ,
    velocity θ̇ = om, its terms read from the chain's table (mechanics.chain_terms):
    :func:`chain_balance`.

    Args:
        a: rotation about the active pivot [rad]. s: pivot side ±1. om: θ̇ [rad/s].
        ag: ground acceleration, polarity applied [g]. table: the chain's flat table.
        springs, alive: as in :func:`angular_acceleration`.
    """
    g, h, t, m, mp = chain_terms(table, s, a)
    return chain_balance(g, h, t, m, mp, a, s, om, ag, springs, alive)


def chain_balance(g, h, t, m, mp, a, s, om, ag, springs, alive):
    """θ̈ of a chain from its terms at a: G = V′ [N·m], H = g·Γ [N·m per g], T the thrusts'
    opening work [N·m] (signed for side s), M [kg·m²] and M′ [kg·m²/rad].

    Lagrange's equation of the one-degree-of-freedom mechanism (rockcli.mechanisms.motion;
    Sorrentino, Masiani & Griffith 2008 for the two-block wall):

        M(a)·ä + ½ M′(a)·ȧ² = −G(a) + T(a) + s·üg·H(a) − Σ_k M_k(a),   θ̈ = s·ä

    with M_k the generalised forces of the restrainers, F·du/da by virtual work: on the lower
    block, which turns rigidly about the pivot, F·r·cos(φ − a) (their polar arm is exact:
    :func:`member_moment`); on the upper block, F·u′(a) with u and u′ from the member's path.
    """
    moment = -g + t + s * ag * h - 0.5 * mp * om * om
    if springs.shape[0] > 0:
        sin_a = math.sin(a)
        cos_a = math.cos(a)
        for k in range(springs.shape[0]):
            if alive[k] != 0:
                kk, r, sin_phi, cos_phi = spring_trig_on_side(springs, k, s)
                if kk != 0.0:
                    if has_path(springs, k):
                        u, du = path_on_side(springs, k, s, a)
                        moment -= member_force(springs, k, s, kk, u) * du
                    else:
                        moment -= member_moment(
                            springs, k, s, kk, r, sin_phi, cos_phi, a, sin_a, cos_a, False
                        )
    return s * moment / m


#: Relative margin on the friction's moment in the stick/slip decisions of both engines: a
#: rounding tie between "slips" and "sticks" sticks (the three predicates, the threshold on
#: üg, the sense and the equation of motion, round differently).
FRICTION_MARGIN = 1e-12


def friction_sense(q, mf):
    """The sense of the motion that starts from a standstill under friction: +1 (opening),
    −1 (closing), or 0 (it sticks), from q, the opening moment of everything but the friction
    over the inertia [rad/s²], and mf, the friction's over the inertia (Coulomb: it moves only
    where |q| exceeds mf)."""
    if q > mf:
        return 1
    if q < -mf:
        return -1
    return 0


def stuck_thresholds(s, q0, k, mf):
    """(thr_pos, thr_neg) [g]: the ground accelerations at which a body stuck by friction on
    side s starts to move, in :func:`uplift_in_interval`'s form (side +1 when üg > thr_pos,
    side −1 when üg < −thr_neg); the side found, times s, is the sense of the motion.

    q0: the opening moment over the inertia at üg = 0 (ä without the friction); k: its rate
    per g of s·üg (H/I > 0); mf: the friction's moment over the inertia. It opens where
    s·üg·k > mf − q0 and closes where s·üg·k < −mf − q0.
    """
    opening = (mf - q0) / k
    closing = (mf + q0) / k
    return (opening, closing) if s > 0 else (closing, opening)


def ground_acceleration(t, i, times, accel, polarity):
    """Ground acceleration at time t inside sample interval i, linear between samples [g].

    Source: spec/rocking.md, "The ground motion between samples is linear".
    """
    t0 = times[i]
    t1 = times[i + 1]
    w = (t - t0) / (t1 - t0)
    return polarity * (accel[i] + (accel[i + 1] - accel[i]) * w)


def uplift_in_interval(t, i, times, accel, polarity, thr_pos, thr_neg, one_sided, free_side):
    """Earliest time τ ≥ t in sample interval i at which the block at rest starts to rock.

    The block leaves rest when the ground acceleration exceeds the threshold of a side (tan α
    for the free block; thr_pos towards θ > 0, thr_neg towards θ < 0, in g) towards a side it
    may rotate to (spec/rocking.md, "Uplift from rest"); the acceleration is
    linear in the interval, so the crossing is exact. Tested on the interpolated value at t
    first (engine.md, trap 2), so a spike is never skipped.

    Returns:
        (τ, side): side = ±1 the side it rotates to, or (inf, 0) when it stays at rest.
    """
    g_now = ground_acceleration(t, i, times, accel, polarity)
    if g_now > thr_pos and (one_sided == 0 or free_side > 0):
        return t, 1
    if g_now < -thr_neg and (one_sided == 0 or free_side < 0):
        return t, -1
    t1 = times[i + 1]
    g_end = ground_acceleration(t1, i, times, accel, polarity)
    best_t = 1e300
    best_side = 0
    for side in (1, -1):
        if one_sided != 0 and side != free_side:
            continue
        threshold = thr_pos if side > 0 else thr_neg
        level = side * threshold
        if (side * g_end > threshold) and (side * g_now <= threshold):
            tau = t + (level - g_now) / (g_end - g_now) * (t1 - t)
            tau = min(max(tau, t), t1)
            if tau < best_t:
                best_t = tau
                best_side = side
    if best_side == 0:
        return 1e300, 0
    return best_t, best_side


def velocity_after_impact(omega, s, e, one_sided, rebound):
    """(θ̇⁺, new side) at θ = 0 from θ̇⁻ on side s.

    Source: spec/rocking.md, "Impacts": two-sided θ̇⁺ = e·θ̇⁻, sign kept, the pivot switches
    (paper §3.1; Housner 1963); one-sided θ̇⁺ = −r_f·e·θ̇⁻ about the same pivot (paper §3.1,
    ref. [26]).
    """
    if one_sided != 0:
        return -rebound * e * omega, s
    return e * omega, -s


def elongation_on_side(springs, j, s, a, linearized):
    """Spring elongation u of restrainer row j on pivot side s at rotation a [m] (its path's,
    when it has one)."""
    if has_path(springs, j):
        return path_on_side(springs, j, s, a)[0]
    _, r, phi, _ = spring_on_side(springs, j, s)
    return spring_elongation(r, phi, a, linearized)
