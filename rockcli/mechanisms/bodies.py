"""The rigid bodies of a mechanism: weight, centroid and inertia from their shape.

Every body is a prism of constant thickness along the wall's plane (``width``, or a return
wall's thickness) whose section in the (x, z) plane is a rectangle or a triangle; its weight is
the unit weight times its volume. The inertia that matters is about an axis along the wall's
plane (the hinges' axis): the polar moment of the section about its centroid times the
thickness times the density. For the Circolare's M* and e* with the mass spread over a body
(rather than lumped at its centroid) the body also keeps the variance of z and of x over its
mass (∫(z − z_G)² dm / m and ∫(x − x_G)² dm / m).

Sources: the section properties of a rectangle and of a triangle (centroid at the mean of the
vertices; polar moment about the centroid m·(a² + b² + c²)/36 for a triangle of sides a, b, c
and m·(w² + h²)/12 for a rectangle w × h): Gere & Goodno, *Mechanics of Materials*,
Appendix D (cases 1 and 4–6), and any table of mass moments of inertia of thin plates.

Pure and silent: only :mod:`math`.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Body:
    """A rigid body of the wall, in the wall's frame (x inward from the outer face, z up).

    Attributes:
        name: label ("storey 1", "gable", "wedge (one return wall)").
        weight: its weight [N].
        x, z: its centroid [m].
        inertia: its moment of inertia about the axis through the centroid along the wall's
            plane [kg·m²].
        var_x, var_z: ∫(x − x_G)² dm / m and ∫(z − z_G)² dm / m [m²] (the mass spread over
            the section, for M* and e* of a distributed mass).
        mass: its mass [kg].
        bears: its weight acts against the mechanism's motion (False: a body of a mechanism
            in plan, whose weight is normal to its motion and does no work: a horizontal
            flexure's strip).
    """

    name: str
    weight: float
    x: float
    z: float
    inertia: float
    var_x: float
    var_z: float
    mass: float
    bears: bool = True

    def moved(self, x: float, z: float) -> Body:
        """The same body with its centroid at (x, z) [m] (another frame's coordinates)."""
        return Body(self.name, self.weight, x, z, self.inertia, self.var_x, self.var_z, self.mass,
                    self.bears)  # fmt: skip


def prism(
    name: str,
    x0: float,
    x1: float,
    z0: float,
    z1: float,
    depth: float,
    unit_weight: float,
    g: float,
) -> Body:
    """A rectangular prism, section [x0, x1] × [z0, z1], ``depth`` along the wall's plane.

    Weight γ·(x1 − x0)·(z1 − z0)·depth; centroid at the middle; I_G = m(w² + h²)/12;
    variances w²/12 and h²/12 (Gere & Goodno, App. D, case 1).
    """
    w, h = x1 - x0, z1 - z0
    weight = unit_weight * w * h * depth
    mass = weight / g
    return Body(
        name=name,
        weight=weight,
        x=0.5 * (x0 + x1),
        z=0.5 * (z0 + z1),
        inertia=mass * (w * w + h * h) / 12.0,
        var_x=w * w / 12.0,
        var_z=h * h / 12.0,
        mass=mass,
    )


def triangle(
    name: str,
    vertices: tuple[tuple[float, float], tuple[float, float], tuple[float, float]],
    depth: float,
    unit_weight: float,
    g: float,
) -> Body:
    """A triangular prism of section ``vertices`` [(x, z)] and ``depth`` along the wall's plane.

    Area |cross product|/2; centroid the mean of the vertices; polar moment about the
    centroid m(a² + b² + c²)/36 (a, b, c the sides); the variances of x and z over a uniform
    triangle are (Σ d_i²)/12 with d_i the vertices' offsets from the centroid (the second
    moments of a triangle, Gere & Goodno App. D, cases 4–6, written about the centroid; their
    sum is the polar moment, Σ|d_i|² = (a² + b² + c²)/3).
    """
    (xa, za), (xb, zb), (xc, zc) = vertices
    area = 0.5 * abs((xb - xa) * (zc - za) - (xc - xa) * (zb - za))
    weight = unit_weight * area * depth
    mass = weight / g
    xg = (xa + xb + xc) / 3.0
    zg = (za + zb + zc) / 3.0
    sides2 = (xb - xa) ** 2 + (zb - za) ** 2 + (xc - xb) ** 2 + (zc - zb) ** 2
    sides2 += (xa - xc) ** 2 + (za - zc) ** 2
    var_x = sum((x - xg) ** 2 for x in (xa, xb, xc)) / 12.0
    var_z = sum((z - zg) ** 2 for z in (za, zb, zc)) / 12.0
    return Body(
        name=name,
        weight=weight,
        x=xg,
        z=zg,
        inertia=mass * sides2 / 36.0,
        var_x=var_x,
        var_z=var_z,
        mass=mass,
    )


def gable(
    name: str,
    thickness: float,
    base_z: float,
    height: float,
    width: float,
    unit_weight: float,
    g: float,
) -> Body:
    """A triangular gable of base ``width`` (along the wall's plane) and ``height``, of constant
    ``thickness``, standing on the section [0, thickness] at ``base_z``.

    Its width along the plane shrinks linearly to the ridge, so in the (x, z) section it is a
    rectangle whose mass per unit height falls linearly: weight γ·t·width·h/2, centroid at
    h/3 above its base, var_z = h²/18 (a triangular distribution), var_x = t²/12,
    I_G = m(t²/12 + h²/18).
    """
    weight = unit_weight * thickness * width * height / 2.0
    mass = weight / g
    var_x = thickness * thickness / 12.0
    var_z = height * height / 18.0
    return Body(
        name=name,
        weight=weight,
        x=0.5 * thickness,
        z=base_z + height / 3.0,
        inertia=mass * (var_x + var_z),
        var_x=var_x,
        var_z=var_z,
        mass=mass,
    )
