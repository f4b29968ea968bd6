"""The code's categories (soil, topography, limit state, edition): numpy-free, so that the
model file can validate against them without loading the numeric stack."""

from __future__ import annotations

from enum import StrEnum

__all__ = ["USE_COEFFICIENT", "Edition", "LimitState", "Soil", "Topography", "UseClass"]


class Soil(StrEnum):
    """Subsoil category (NTC §3.2.2, Tab. 3.2.II)."""

    A = "A"
    B = "B"
    C = "C"
    D = "D"
    E = "E"


class Topography(StrEnum):
    """Topographic category (NTC §3.2.2, Tab. 3.2.III)."""

    T1 = "T1"
    T2 = "T2"
    T3 = "T3"
    T4 = "T4"


class LimitState(StrEnum):
    """Seismic limit state (NTC §3.2.1, Tab. 3.2.I)."""

    SLO = "SLO"
    SLD = "SLD"
    SLV = "SLV"
    SLC = "SLC"


class Edition(StrEnum):
    """Code edition, in rock's vocabulary (spec/ntc.md)."""

    E2009 = "2009"  # NTC 2008 + Circolare 617/2009
    E2019 = "2019"  # NTC 2018 + Circolare 7/2019


class UseClass(StrEnum):
    """Use class of the building (NTC 2018 §2.4.2)."""

    I = "I"  # noqa: E741 (the code's numeral)
    II = "II"
    III = "III"
    IV = "IV"


#: The use coefficient CU of each use class (NTC 2018 §2.4.3, Tab. 2.4.II).
USE_COEFFICIENT = {"I": 0.7, "II": 1.0, "III": 1.5, "IV": 2.0}
