"""Units: gravity defined once, and the acceleration units records come in."""

from __future__ import annotations

from enum import StrEnum

from rockcli.errors import InputError

#: Standard gravity [m/s²] (CGPM 1901; ISO 80000-3). Used only to convert record
#: accelerations given in m/s² or cm/s² into fractions of g.
STANDARD_GRAVITY = 9.80665

#: Default gravity of the mechanics [m/s²]: the value the source paper and the NTC
#: worked examples use (p = √(3g/4R) = 1.566 rad/s for R = 3 m; the altar's
#: a0* = g·tan α / FC = 1.5365 m/s² in ntc.md). Settable per model (``analysis.g``).
DEFAULT_GRAVITY = 9.81


class AccelUnit(StrEnum):
    """Acceleration unit of a record file."""

    G = "g"
    M_S2 = "m/s2"
    CM_S2 = "cm/s2"

    @property
    def to_g(self) -> float:
        """Factor that turns a value in this unit into a fraction of standard gravity."""
        return {
            AccelUnit.G: 1.0,
            AccelUnit.M_S2: 1.0 / STANDARD_GRAVITY,
            AccelUnit.CM_S2: 0.01 / STANDARD_GRAVITY,
        }[self]


_ALIASES = {
    "g": AccelUnit.G,
    "m/s2": AccelUnit.M_S2,
    "m/s^2": AccelUnit.M_S2,
    "m/s**2": AccelUnit.M_S2,
    "m/s²": AccelUnit.M_S2,
    "m/s/s": AccelUnit.M_S2,
    "ms2": AccelUnit.M_S2,
    "cm/s2": AccelUnit.CM_S2,
    "cm/s^2": AccelUnit.CM_S2,
    "cm/s**2": AccelUnit.CM_S2,
    "cm/s²": AccelUnit.CM_S2,
    "cm/s/s": AccelUnit.CM_S2,
    "gal": AccelUnit.CM_S2,
}


def parse_unit(text: str, *, file: str | None = None, where: str | None = None) -> AccelUnit:
    """Read an acceleration unit name (case-insensitive); raise InputError if unknown."""
    unit = _ALIASES.get(text.strip().lower())
    if unit is None:
        raise InputError(
            "unknown acceleration unit",
            file=file,
            where=where,
            value=text,
            allowed="g, m/s2, cm/s2",
        )
    return unit
