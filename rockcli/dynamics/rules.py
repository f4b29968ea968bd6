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
elongation reaches fails_at; the sines and cosines are precomputed for the right-hand side).
"""

from __future__ import annotations

import math

from rockcli.mechanics import (
    gravity_moment_ratio_trig,
    ground_moment_ratio_trig,
    point_moments,
    spring_elongation,
    spring_moment_trig,
)

#: Columns of the packed restrainer table.
COL_K_POS, COL_K_NEG, COL_R_POS, COL_PHI_POS, COL_R_NEG, COL_PHI_NEG = 0, 1, 2, 3, 4, 5
COL_A_FAIL_POS, COL_A_FAIL_NEG, COL_FAILS_AT = 6, 7, 8
COL_SIN_POS, COL_COS_POS, COL_SIN_NEG, COL_COS_NEG = 9, 10, 11, 12
N_SPRING_COLS = 13


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


def angular_acceleration(
    a, s, ag, alpha, sin_alpha, cos_alpha, p2, linearized, springs, alive, inv_i0
):
    """θ̈ of the block on pivot side s at rotation a = s·θ under ground acceleration ag [g].

    Source: spec/rocking.md, θ̈ = −s p² sin(α − sθ) − Σ_k M_k(θ)/I0 + p² üg cos(α − sθ), with
    M_k = s·K·u·r·cos(φ − |θ|) (paper Eq. 2 and 4; linearized: sin x ≈ x, cos x ≈ 1).
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
                    * spring_moment_trig(k, r, sin_phi, cos_phi, a, sin_a, cos_a, linearized)
                    * inv_i0
                )
    return acc


def loaded_angular_acceleration(a, s, om, ag, points, i0, springs, alive):
    """θ̈ of a block with loads or thrusts on pivot side s at rotation a = s·θ, velocity θ̇ = om.

    Lagrange's equation for the one coordinate a (kinetic energy ½ [I0 + J(a)] ȧ², potential
    of the bearing weights, generalised forces of the earthquake, the thrusts and the springs;
    docs/physics.md, "Loads and thrusts"):

        [I0 + J(a)]·ä + ½ J′(a)·ȧ² = −G(a) + s·T(a) + s·üg·H(a) − Σ_k M_k(a),   θ̈ = s·ä

    with G, H, T, J, J′ from :func:`rockcli.mechanics.point_moments` (the very function of the
    capacity curve) and M_k the springs' restoring moments (spec/rocking.md). Without loads
    and thrusts it is paper Eq. (2): G = m g R sin(α − a), H = m g R cos(α − a), J = 0.

    Args:
        a: rotation about the active pivot [rad]. s: pivot side ±1. om: θ̇ [rad/s].
        ag: ground acceleration, polarity applied [g]. points: flat point table.
        i0: the block's own polar moment of inertia about a base corner [kg·m²].
        springs, alive: as in :func:`angular_acceleration`.
    """
    sin_a = math.sin(a)
    cos_a = math.cos(a)
    g, h, t, j, dj = point_moments(points, s, sin_a, cos_a)
    moment = -g + s * t + s * ag * h - 0.5 * dj * om * om
    for k in range(springs.shape[0]):
        if alive[k] != 0:
            kk, r, sin_phi, cos_phi = spring_trig_on_side(springs, k, s)
            if kk != 0.0:
                moment -= spring_moment_trig(kk, r, sin_phi, cos_phi, a, sin_a, cos_a, False)
    return s * moment / (i0 + j)


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
    """Spring elongation u of restrainer row j on pivot side s at rotation a [m]."""
    _, r, phi, _ = spring_on_side(springs, j, s)
    return spring_elongation(r, phi, a, linearized)
