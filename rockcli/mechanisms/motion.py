"""The equation of motion of a mechanism opening to one side: M(θ), V(θ), V′(θ), Γ(θ), M′(θ).

A mechanism (:class:`rockcli.mechanisms.side.ChainSide`) has one degree of freedom θ; every
point of it is at (X(θ), Z(θ)) in the side frame (origin at the pivot, x into the wall, z up;
rockcli.mechanisms.links). On a ground moving horizontally by u_g(t) along the side frame's
+x, Lagrange's equation of the kinetic energy T = ½ M(θ) θ̇² (relative to the ground) and the
potential V(θ) reads (Goldstein, *Classical Mechanics*, §1.4; the rocking block's Eq. 1 of
Housner 1963 is the case of one rectangle):

    M(θ) θ̈ + ½ M′(θ) θ̇² + V′(θ) = Γ(θ) ü_g  (+ the thrusts' T and the restrainers' −F·δx)

with

- M(θ) = Σ_bodies [m |∂r_G/∂θ|² + I_G (∂φ/∂θ)²] + Σ_loads m_l [(∂X/∂θ)² if it moves
  + (∂Z/∂θ)² if it bears] [kg·m²]: a load that bears and moves is a rigid point mass, one
  that only moves (the Circolare's P_j) follows the mechanism horizontally, one that only
  bears follows it vertically (rockcli.mechanics.point_moments' J, the same three cases);
- V(θ) = Σ_bodies m g [Z_G(θ) − Z_G(0)] + Σ_bearing loads P [Z(θ) − Z(0)] [J]: zero at rest;
- V′(θ) = dV/dθ = Σ m g ∂Z_G/∂θ + Σ_bearing P ∂Z/∂θ [N·m/rad], which is G of
  ChainSide.work_terms (the weights' virtual work per unit rotation);
- Γ(θ) = Σ_moving m (−∂X/∂θ) [kg·m]: the generalised force of a unit ground acceleration
  (1 m/s²) along +x, i.e. towards the wall from the pivot, whose inertia forces push the
  mechanism open; a ground acceleration of a·g (a in g) gives g·Γ·a [N·m], and g·Γ is H of
  ChainSide.work_terms, so at rest α0 = V′(0)/(g Γ(0)) without thrusts and restrainers
  (Circ. 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.1; Circ. 617/2009 Eq. C8A.4.1);
- M′(θ) = dM/dθ [kg·m²/rad], by a central difference of M (:data:`MASS_STEP`).

The thrusts (T of work_terms, opening) and the restrainers (minus the virtual work F·δx of
their forces, ChainPoint.moment) are external generalised forces, not in V.

Pure and silent: :mod:`math`, numpy (a grid of rotations at once) and the package's own
modules.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from rockcli.mechanisms.links import LinkState
from rockcli.mechanisms.side import ChainSide

#: Step of the central difference of M′ [rad]: the truncation error h²·|M‴|/6 and the
#: rounding ε·|M|/h (ε = 2.2e-16) balance near h = (3ε)^(1/3) ≈ 1e-5 when |M‴| ~ |M|
#: (Press et al., *Numerical Recipes*, 3rd ed., §5.7). Measured on two-block chains
#: (tests/mechanisms/test_motion.py): 1e-10 relative at rest, 1e-8 at 0.9 of the motion's
#: limit, where M grows steepest.
MASS_STEP = 1e-5


def rise(state: LinkState, x: float, z: float) -> float:
    """Z(θ) − Z(0) of the link's point at rest at (x, z) [m].

    At θ = 0 every point is at rest (c(0) = p0, φ(0) = 0; rockcli.mechanisms.links), so
    Z(θ) − z = (c_z − p_z) + (x − p_x) sin φ − (z − p_z)(1 − cos φ), with 1 − cos φ written
    2 sin²(φ/2) so that a small rotation keeps its digits (no difference of large heights).
    """
    versine = 2.0 * math.sin(0.5 * state.phi) ** 2
    return (state.cz - state.pz) + (x - state.px) * math.sin(state.phi) - (z - state.pz) * versine


def masses(side: ChainSide, theta: float) -> Iterator[tuple[float, float, float, float, float]]:
    """Every mass of the mechanism at θ: (m following X [kg], m following Z [kg], I_G φ′²
    [kg·m²], ∂X/∂θ [m], ∂Z/∂θ [m]): the bodies (rigid, with their inertia about the centroid)
    and the loads (by what they do; a thrust has no mass)."""
    states = side.states(theta)
    for link, body in side.bodies:
        st = states[link]
        _, _, dx, dz = st.place(body.x, body.z)
        yield body.mass, body.mass, body.inertia * st.dphi**2, dx, dz
    for ld in side.loads:
        m = ld.weight / side.g
        _, _, dx, dz = states[ld.at.link].place(ld.at.x, ld.at.z)
        yield (m if ld.moves else 0.0), (m if ld.bears else 0.0), 0.0, dx, dz


def generalised_mass(side: ChainSide, theta: float) -> float:
    """M(θ) = Σ [m_x (∂X/∂θ)² + m_z (∂Z/∂θ)² + I_G φ′²] [kg·m²] (module docstring).

    One rectangle about its corner: I0 = 4/3 m R² at every θ (Housner 1963).
    """
    return sum(mx * dx * dx + mz * dz * dz + rot for mx, mz, rot, dx, dz in masses(side, theta))


def potential(side: ChainSide, theta: float) -> float:
    """V(θ) = Σ_bodies W [Z_G(θ) − Z_G(0)] + Σ_bearing loads P [Z(θ) − Z(0)] [J].

    One rectangle about its corner: m g R [cos(α − θ) − cos α] (Housner 1963).
    """
    states = side.states(theta)
    total = sum(body.weight * rise(states[k], body.x, body.z) for k, body in side.bodies)
    for ld in side.loads:
        if ld.bears:
            total += ld.weight * rise(states[ld.at.link], ld.at.x, ld.at.z)
    return total


def potential_slope(side: ChainSide, theta: float) -> float:
    """V′(θ) = Σ_bodies W ∂Z_G/∂θ + Σ_bearing loads P ∂Z/∂θ [N·m/rad]: G of
    ChainSide.work_terms. One rectangle about its corner: m g R sin(α − θ)."""
    return side.work_terms(theta)[0]


def participation(side: ChainSide, theta: float) -> float:
    """Γ(θ) = Σ_moving m (−∂X/∂θ) [kg·m]: the generalised force of a unit ground acceleration
    [m/s²] along +x of the side frame (g·Γ is H of ChainSide.work_terms). One rectangle about
    its corner: m R cos(α − θ)."""
    return -sum(mx * dx for mx, _, _, dx, _ in masses(side, theta))


def mass_slope(side: ChainSide, theta: float) -> float:
    """M′(θ) = dM/dθ [kg·m²/rad], by the central difference [M(θ + h) − M(θ − h)]/(2h) with
    h = :data:`MASS_STEP` (error O(h²)); within h of the motion's limit, the one-sided
    [3M(θ) − 4M(θ − h) + M(θ − 2h)]/(2h), of the same order (Press et al., §5.7)."""
    h = MASS_STEP
    if isinstance(theta, np.ndarray):  # a grid of rotations: each by its own formula
        with np.errstate(invalid="ignore", divide="ignore"):
            central = (generalised_mass(side, theta + h) - generalised_mass(side, theta - h)) / (
                2 * h
            )
            m0, m1, m2 = (generalised_mass(side, theta - k * h) for k in range(3))
        return np.where(theta + h <= side.limit, central, (3.0 * m0 - 4.0 * m1 + m2) / (2.0 * h))
    if theta + h <= side.limit:
        return (generalised_mass(side, theta + h) - generalised_mass(side, theta - h)) / (2 * h)
    m0, m1, m2 = (generalised_mass(side, theta - k * h) for k in range(3))
    return (3.0 * m0 - 4.0 * m1 + m2) / (2.0 * h)


def velocities(side: ChainSide) -> list[tuple[float, float, float, float, float, float]]:
    """Every mass of the mechanism at rest with its velocity per unit opening rate ȧ = 1:
    (m following X [kg], m following Z [kg], I_G [kg·m²], ∂X/∂a, ∂Z/∂a [m], ∂φ/∂a), in the
    side frame; the bodies first, then the loads, in the mechanism's order."""
    states = side.states(0.0)
    out = []
    for link, body in side.bodies:
        st = states[link]
        _, _, dx, dz = st.place(body.x, body.z)
        out.append((body.mass, body.mass, body.inertia, dx, dz, st.dphi))
    for ld in side.loads:
        m = ld.weight / side.g
        _, _, dx, dz = states[ld.at.link].place(ld.at.x, ld.at.z)
        out.append((m if ld.moves else 0.0, m if ld.bears else 0.0, 0.0, dx, dz, 0.0))
    return out


def impact_ratio(before: ChainSide, after: ChainSide) -> float:
    """θ̇⁺/θ̇⁻ of an impact at θ = 0 that ends a phase on ``before``'s side and starts one on
    ``after``'s (the same masses, in the same order, seen from the other pivot).

    Every hinge changes face: the velocity field per unit rate of the side frame is w_s(P) =
    (s·∂X_s/∂a, ∂Z_s/∂a) in the wall's frame and the bodies turn at s·∂φ_s/∂a (the side frame of
    side −1 is the mirror image). The impulsive reactions act at the new hinges — the new pivot
    (at rest), the intermediate hinge (equal and opposite on the two blocks, which share its
    velocity) and the held top (no horizontal velocity) — so they do no work in the
    post-impact field w⁺, and the balance of momentum projected on it gives
    ∫ w⁻·w⁺ dm · ȧ⁻ = ∫ |w⁺|² dm · ȧ⁺ (Sorrentino, Masiani & Griffith 2008, who write it as the
    angular momentum of each block about its new hinge; for one rigid body it is Housner's
    balance about the new pivot, mechanics.impact_restitution). With θ̇ = s·ȧ on each side:

        θ̇⁺/θ̇⁻ = Σ [m_x X′_s X′_s′ − m_z Z′_s Z′_s′ + I_G φ′_s φ′_s′] / Σ [m_x X′_s′² + m_z Z′_s′²
        + I_G φ′_s′²]

    (one rectangle: (I_G + m(z² − x·x′))/(I_G + m(x′² + z²)) = 1 − 1.5 sin²α).
    """
    num = den = 0.0
    for (mx, mz, i_g, dx, dz, dp), (_, _, _, dx2, dz2, dp2) in zip(
        velocities(before), velocities(after), strict=True
    ):
        num += mx * dx * dx2 - mz * dz * dz2 + i_g * dp * dp2
        den += mx * dx2 * dx2 + mz * dz2 * dz2 + i_g * dp2 * dp2
    return num / den
