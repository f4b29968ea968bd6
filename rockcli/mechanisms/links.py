"""One degree of freedom: where every body of a mechanism is for a finite rotation θ.

A mechanism is seen from the pivot of the side it opens to (its *side frame*): origin at that
pivot, x horizontal **into the wall** from it, z up. θ > 0 opens the mechanism: the driving
body turns about the origin so that a point (x, z) goes to (x cos θ − z sin θ, x sin θ +
z cos θ) — the top moves away from the wall (to x < 0), as the rocking block's does about its
pivot (spec of the block: docs/physics.md). Side 1 of a wall opens outward about the outer
edge of the hinge section; side −1 inward about the inner edge, with x measured outward from it.

A *motion* places each link (a rigid group of bodies) for any θ: the link's rest reference
point p0 goes to c(θ) and the link turns by φ(θ), so a point p of the link is at
P(θ) = c(θ) + Rot(φ)(p − p0), with the derivative P′ = c′ + φ′·(−v_z, v_x), v = Rot(φ)(p − p0).
Everything the two analyses need — the virtual displacements of the Circolare's virtual work
(Circ. 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.1; Circ. 617/2009 §C8A.4.1), the capacity curve by
finite rotations, and the terms M, V, Γ of the equation of motion — follows from these
positions and derivatives.

- :class:`Rotation`: one rigid body about the pivot (overturning, wedge, gable; the block).
- :class:`TwoBlock`: vertical flexure. The lower link turns by θ about the pivot; the upper
  link hangs from the intermediate hinge H (on the opposite face) and its top point T is held
  horizontally (x_T fixed) but free to rise. With a = x_T − x_H, c = z_T − z_H (the upper
  link's rest chord, length L, direction δ = atan2(c, a)) and the hinge at c_x(θ), the
  constraint a cos ψ + c sin ψ = x_T − c_x(θ) gives the upper link's rotation φ = −ψ with
  ψ = δ − acos((x_T − c_x)/L) and ψ′ = c_x′/(L sin(ψ − δ)); at θ = 0, ψ′ = z_H/(z_T − z_H)
  (the two-block chain of Sorrentino, Masiani & Griffith 2008, Struct. Eng. Mech. 29:433–453,
  and of Doherty et al. 2002, EESD 31:833–850).

Pure and silent: :mod:`math` (numpy for an array of rotations: the chain's table) and
:mod:`rockcli.mechanics`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from rockcli.mechanics import VERSINE_SERIES_BELOW, versine

#: A rotation [rad], or an array of rotations (the chain's table evaluates its grid at once):
#: the links' arithmetic is numpy's duck typing, so a state's fields are arrays then.
Angle = Any


def cos(a: Angle) -> Angle:
    """cos a: math's for a number, numpy's for an array."""
    return np.cos(a) if isinstance(a, np.ndarray) else math.cos(a)


def sin(a: Angle) -> Angle:
    """sin a: math's for a number, numpy's for an array."""
    return np.sin(a) if isinstance(a, np.ndarray) else math.sin(a)


def versines(a: Angle, cos_a: Angle) -> Angle:
    """mechanics.versine (1 − cos a by its series below VERSINE_SERIES_BELOW) of a number, or
    of every element of an array: the same series, written again with numpy because the
    engine compiles mechanics.versine for numbers only (tests/mechanisms/test_table_grid.py
    checks the two agree bit for bit)."""
    if not isinstance(a, np.ndarray) and not isinstance(cos_a, np.ndarray):
        return versine(a, cos_a)
    a2 = a * a
    series = a2 * (0.5 - a2 * (1.0 / 24.0 - a2 * (1.0 / 720.0)))
    return np.where(np.abs(a) < VERSINE_SERIES_BELOW, series, 1.0 - cos_a)


@dataclass(frozen=True)
class LinkState:
    """Where one link is at θ: rest reference point (px, pz) now at (cx, cz), turned by phi,
    the derivatives of c and φ with respect to θ, and c − p written without cancellation
    (ux, uz: for the displacements of small rotations)."""

    px: float
    pz: float
    cx: float
    cz: float
    phi: float
    dcx: float
    dcz: float
    dphi: float
    ux: float = 0.0
    uz: float = 0.0

    def displacement(self, x: float, z: float) -> tuple[float, float]:
        """(X − x, Z − z) of the link's point (x, z) since rest, to a few ulps at any
        rotation: c − p plus (Rot(φ) − I)(p − p0) with 1 − cos φ from mechanics.versine (the
        difference of the positions loses every digit below ε·|p|)."""
        vx, vz = x - self.px, z - self.pz
        s, vers = sin(self.phi), versines(self.phi, cos(self.phi))
        return self.ux - vx * vers - vz * s, self.uz + vx * s - vz * vers

    def place(self, x: float, z: float) -> tuple[float, float, float, float]:
        """(X, Z, dX/dθ, dZ/dθ) of the link's point (x, z) at rest (each an array for a
        state of an array of rotations)."""
        c, s = cos(self.phi), sin(self.phi)
        vx = (x - self.px) * c - (z - self.pz) * s
        vz = (x - self.px) * s + (z - self.pz) * c
        return (
            self.cx + vx,
            self.cz + vz,
            self.dcx - self.dphi * vz,
            self.dcz + self.dphi * vx,
        )


@dataclass(frozen=True)
class Rotation:
    """One link turning by θ about the origin (the pivot)."""

    links: int = 1

    @property
    def limit(self) -> float:
        """The largest rotation the motion is defined for [rad]."""
        return math.pi / 2

    def states(self, theta: Angle) -> tuple[LinkState, ...]:
        """The link at θ (a rotation, or an array of them)."""
        return (LinkState(0.0, 0.0, 0.0, 0.0, theta, 0.0, 0.0, 1.0),)


#: Fixed-point steps of the upper link's rotation (each gains far more than the digits the
#: first guess lacks: the step's slope is about ψ/2).
UPPER_ROTATION_STEPS = 4


@dataclass(frozen=True)
class TwoBlock:
    """Two links: the lower turns by θ about the origin, the upper hangs from the hinge
    (hinge_x, hinge_z) and its top point (top_x, top_z) keeps its x (held) and may rise."""

    hinge_x: float
    hinge_z: float
    top_x: float
    top_z: float
    links: int = 2

    @cached_property
    def chord(self) -> tuple[float, float]:
        """(L, δ): length and direction of the upper link's rest chord from H to T (found
        once: every position of the chain reads it)."""
        a, c = self.top_x - self.hinge_x, self.top_z - self.hinge_z
        return math.hypot(a, c), math.atan2(c, a)

    @cached_property
    def limit(self) -> float:
        """The rotation at which the upper link's chord lies flat (the chain cannot follow
        further with its top held): the lower link's hinge then is L from the top's line
        (found once, by bisection: the capacity curve and the table read it at every step)."""
        length, _ = self.chord
        lo, hi = 0.0, math.pi / 2
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            cx = self.hinge_x * math.cos(mid) - self.hinge_z * math.sin(mid)
            if abs(self.top_x - cx) <= length:
                lo = mid
            else:
                hi = mid
        return lo

    def upper_rotation(self, shift: float, length: float, delta: float) -> float:
        """ψ from the hinge's inward shift x_H(0) − x_H(θ) = ``shift`` [m]: the constraint
        cos(δ − ψ) − cos δ = shift/L, written 2·sin(δ − ψ/2)·sin(ψ/2) = shift/L (A&S 4.3.37)
        and solved by fixed-point steps from ψ = δ − acos(cos δ + shift/L), so that a small ψ
        keeps its digits (the difference δ − acos(…) alone loses them below ψ ≈ 1e-8)."""
        q = max(-1.0, min(1.0, math.cos(delta) + shift / length))
        psi = delta - math.acos(q)
        for _ in range(UPPER_ROTATION_STEPS):
            arg = shift / (2.0 * length * math.sin(delta - 0.5 * psi))
            if not -1.0 <= arg <= 1.0:
                break
            psi = 2.0 * math.asin(arg)
        return psi

    def upper_rotations(self, shift: np.ndarray, length: float, delta: float) -> np.ndarray:
        """:meth:`upper_rotation` of every element of an array of shifts (an element whose
        step leaves [−1, 1] keeps its last ψ, as the loop's break does)."""
        q = np.clip(math.cos(delta) + shift / length, -1.0, 1.0)
        psi = delta - np.arccos(q)
        live = np.ones(psi.shape, dtype=bool)
        for _ in range(UPPER_ROTATION_STEPS):
            with np.errstate(divide="ignore", invalid="ignore"):
                arg = shift / (2.0 * length * np.sin(delta - 0.5 * psi))
            live &= (arg >= -1.0) & (arg <= 1.0)
            psi = np.where(live, 2.0 * np.arcsin(np.where(live, arg, 0.0)), psi)
        return psi

    def upper_motion(
        self, shift: Angle, dhx: Angle, length: float, delta: float
    ) -> tuple[Angle, Angle]:
        """(ψ, ψ′) of the upper link for the hinge's inward shift and its x-velocity
        dx_H/dθ = ``dhx`` (ψ′ = dx_H/dθ / (L sin(ψ − δ)), inf where the chord is flat)."""
        if isinstance(shift, np.ndarray):
            psi_all = self.upper_rotations(shift, length, delta)
            denom_all = length * np.sin(psi_all - delta)
            with np.errstate(divide="ignore"):
                ratio = dhx / np.where(denom_all != 0.0, denom_all, 1.0)
            return psi_all, np.where(denom_all != 0.0, ratio, np.inf)
        assert not isinstance(dhx, np.ndarray)
        psi = self.upper_rotation(shift, length, delta)
        denom = length * math.sin(psi - delta)
        return psi, (dhx / denom if denom != 0.0 else math.inf)

    def states(self, theta: Angle) -> tuple[LinkState, LinkState]:
        """The two links at θ (a rotation, or an array of them: each field an array)."""
        c, s = cos(theta), sin(theta)
        hx = self.hinge_x * c - self.hinge_z * s
        hz = self.hinge_x * s + self.hinge_z * c
        dhx, dhz = -hz, hx
        length, delta = self.chord
        vers = versines(theta, c)
        ux = -self.hinge_x * vers - self.hinge_z * s
        uz = self.hinge_x * s - self.hinge_z * vers
        psi, dpsi = self.upper_motion(-ux, dhx, length, delta)
        lower = LinkState(0.0, 0.0, 0.0, 0.0, theta, 0.0, 0.0, 1.0)
        upper = LinkState(self.hinge_x, self.hinge_z, hx, hz, -psi, dhx, dhz, -dpsi, ux, uz)
        return lower, upper


@dataclass(frozen=True)
class CappedPiers:
    """Two links: the piers of a rocking frame turning by θ about the origin (a base corner
    of each, in the side frame), and the roof translating with the top corner (top_x, top_z)
    that carries it (the corner diagonally opposite the pivot: (2b, 2h); Makris & Vassiliou
    2013, rockcli.mechanisms.frame)."""

    top_x: float
    top_z: float
    links: int = 2

    @property
    def limit(self) -> float:
        """The largest rotation the motion is defined for [rad]."""
        return math.pi / 2

    def states(self, theta: Angle) -> tuple[LinkState, ...]:
        """The piers and the roof at θ (a rotation, or an array of them)."""
        c, s = cos(theta), sin(theta)
        vers = versines(theta, c)
        ux = -self.top_x * vers - self.top_z * s
        uz = self.top_x * s - self.top_z * vers
        still = 0.0 * theta
        roof = LinkState(self.top_x, self.top_z, self.top_x + ux, self.top_z + uz, still,
                         -self.top_x * s - self.top_z * c, self.top_x * c - self.top_z * s,
                         still, ux, uz)  # fmt: skip
        return (LinkState(0.0, 0.0, 0.0, 0.0, theta, 0.0, 0.0, 1.0), roof)


#: Every motion of a mechanism's links.
Motion = Rotation | TwoBlock | CappedPiers
