"""Elements free to vibrate: the elastic branch of their capacity curve and its period T0.

Circolare 7/2019 §C8.7.1.2.1.3: "Nel caso invece di elementi liberi di vibrare (quali
parapetti, porzioni svettanti di facciate, pinnacoli o merlature, ecc.) [...] è quindi
necessario introdurre un ramo elastico iniziale nella curva di capacità", with

- Eq. C8.7.1.6: a = 4π²·d / T0²;
- Eq. C8.7.1.7: T0 = κ·λ·L·√(W/(E·g)), κ = 6.2 for a cantilever ("elementi svettanti
  (mensola)"), 2.2 for a vertical flexure ("meccanismi flessionali verticali (trave
  appoggiata)"), L the element's length, λ = L/t its slenderness, W the masonry's unit weight,
  E its Young's modulus ("si suggerisce di introdurre un valore ridotto per considerare
  condizioni fessurate");

the branch runs to its intersection (a_y, d_y) with the rigid curve. §C8.7.1.2.1.5,
Eq. C8.7.1.9: the SLD check of such an element reads the spectrum at T0 (ξ = 5 %).

E from a masonry type: the mean of Tab. C8.5.I's range ("Moduli elastici: i valori medi degli
intervalli", §C8.5.4.1, for LC1 and LC2), times CRACKED.

Pure and silent: only :mod:`math` and :mod:`enum`.
"""

from __future__ import annotations

import math
from enum import StrEnum


class MasonryType(StrEnum):
    """The masonry types of Circolare 7/2019 Tab. C8.5.I, in rock's words."""

    RUBBLE = "rubble"  # pietrame disordinata (ciottoli, pietre erratiche e irregolari)
    ROUGH_CUT = "rough-cut-stone"  # conci sbozzati, con paramenti di spessore disomogeneo
    SPLIT_STONE = "split-stone"  # pietre a spacco con buona tessitura
    SOFT_STONE_IRREGULAR = "soft-stone-irregular"  # irregolare di pietra tenera (tufo, ...)
    SOFT_STONE_REGULAR = "soft-stone-regular"  # conci regolari di pietra tenera
    ASHLAR = "ashlar"  # blocchi lapidei squadrati
    SOLID_BRICK = "solid-brick"  # mattoni pieni e malta di calce
    HOLLOW_BRICK = "hollow-brick"  # mattoni semipieni con malta cementizia


#: Tab. C8.5.I: the range of the mean Young's modulus E of each type [Pa] (min, max).
MODULUS_RANGE = {
    MasonryType.RUBBLE: (690e6, 1050e6),
    MasonryType.ROUGH_CUT: (1020e6, 1440e6),
    MasonryType.SPLIT_STONE: (1500e6, 1980e6),
    MasonryType.SOFT_STONE_IRREGULAR: (900e6, 1260e6),
    MasonryType.SOFT_STONE_REGULAR: (1200e6, 1620e6),
    MasonryType.ASHLAR: (2400e6, 3300e6),
    MasonryType.SOLID_BRICK: (1200e6, 1800e6),
    MasonryType.HOLLOW_BRICK: (3500e6, 5600e6),
}
#: The names the model file accepts, for messages.
MASONRY_TYPES = tuple(f"'{t.value}'" for t in MasonryType)
#: The share of the uncracked stiffness a cracked element keeps: NTC 2018 §7.2.6 lets the
#: stiffness of cracked elements be taken "sino al 50%" of the uncracked one; the Circolare
#: asks for a reduced E without a number (§C8.7.1.2.1.3). rock takes the 50 %.
CRACKED = 0.5
#: κ of Eq. C8.7.1.7: a cantilever (a gable, a storey standing free above its hinge) and a
#: vertical flexure (a beam simply supported at its ends).
KAPPA_CANTILEVER, KAPPA_FLEXURE = 6.2, 2.2
#: Bisection steps for the branch's end (d resolved to d0·2⁻⁶⁰).
BRANCH_STEPS = 60


def type_modulus(kind: MasonryType) -> float:
    """E of a masonry type for T0 [Pa]: the mean of Tab. C8.5.I's range, times CRACKED."""
    lo, hi = MODULUS_RANGE[kind]
    return CRACKED * 0.5 * (lo + hi)


def elastic_period(
    kappa: float, length: float, thickness: float, unit_weight: float, E: float, g: float
) -> float:
    """T0 = κ·λ·L·√(W/(E·g)) [s], λ = L/t (Circolare 7/2019 Eq. C8.7.1.7).

    Args:
        kappa: 6.2 (cantilever) or 2.2 (vertical flexure). length: L [m]. thickness: t [m].
        unit_weight: W [N/m³]. E: Young's modulus [Pa]. g: gravity [m/s²].
    """
    return kappa * (length / thickness) * length * math.sqrt(unit_weight / (E * g))


def branch_acceleration(d: float, T0: float) -> float:
    """a = 4π²·d/T0² [m/s²] (Circolare 7/2019 Eq. C8.7.1.6)."""
    return 4.0 * math.pi**2 * d / T0**2


def branch_end(curve, T0: float, d_end: float) -> float:
    """d_y [m]: where the elastic branch meets the rigid curve a*(d) (decreasing from a0* at
    d = 0), by bisection on [0, d_end]; d_end if they do not meet before it."""
    if branch_acceleration(d_end, T0) < curve(d_end):
        return d_end
    lo, hi = 0.0, d_end
    for _ in range(BRANCH_STEPS):
        mid = 0.5 * (lo + hi)
        if branch_acceleration(mid, T0) < curve(mid):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
