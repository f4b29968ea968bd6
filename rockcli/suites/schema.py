"""The suite file: records, their scale factors and the target spectrum (validated at the edge).

pydantic checks each key (type, range, choice); :mod:`rockcli.suites.load` then checks the
rules that involve several keys (the number of records, a record listed twice, the order of
the period range and of the tolerances, a target given by a site *or* by its parameters).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import BeforeValidator, Field

from rockcli.codecheck.categories import Edition, LimitState, Soil, Topography
from rockcli.model.bounds import MAX_NOMINAL_LIFE, MAX_USE_COEFFICIENT, MIN_USE_COEFFICIENT
from rockcli.model.ntc import edition_name
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import number

#: A finite number in an array (TOML int or float, never a bool or a string).
FiniteNumber = Annotated[float, Field(strict=True, allow_inf_nan=False)]
#: A number in an array that may be ``inf`` (the open upper tolerance of NTC 2008).
OpenNumber = Annotated[float, Field(strict=True, allow_inf_nan=True)]


class SuiteRecord(Table):
    """One record of the suite."""

    path: str = Field(..., min_length=1, description="Record file, relative to the suite file")
    name: str | None = Field(
        None, min_length=1, description="Label in the tables; default the file's stem"
    )
    scale: float = number("Factor on the record's accelerations; default 1 [-]", 1.0, gt=0)


class Target(Table):
    """The target spectrum: a site on the hazard grid, or its three parameters."""

    lon: float | None = number("Longitude of the site, east [deg]", ge=-180, le=180)
    lat: float | None = number("Latitude of the site, north [deg]", ge=-90, le=90)
    ag: float | None = number("Peak ground acceleration on rock ag [g]", gt=0, le=2)
    F0: float | None = number("Maximum spectral amplification F0 [-]", ge=1.5, le=4)
    Tc_star: float | None = number("TC* [s]", gt=0, le=2)
    limit_state: LimitState = Field(LimitState.SLV, description="SLO, SLD, SLV or SLC")
    edition: Annotated[Edition, BeforeValidator(edition_name)] = Field(
        Edition.E2019, description="2008 (NTC 2008) or 2018 (NTC 2018); default 2018"
    )
    soil: Soil = Field(Soil.A, description="Subsoil category A–E; default A")
    topography: Topography = Field(Topography.T1, description="T1–T4; default T1")
    VN: float = number("Nominal life VN; default 50 [years]", 50.0, gt=0, le=MAX_NOMINAL_LIFE)
    CU: float = number(
        "Use coefficient CU; default 1 [-]",
        1.0,
        ge=MIN_USE_COEFFICIENT,
        le=MAX_USE_COEFFICIENT,
    )

    @property
    def site(self) -> tuple[float, float] | None:
        """(lon, lat) when the target is a site."""
        if self.lon is None or self.lat is None:
            return None
        return self.lon, self.lat

    @property
    def parameters(self) -> tuple[float, float, float] | None:
        """(ag, F0, Tc_star) when the target gives them."""
        if self.ag is None or self.F0 is None or self.Tc_star is None:
            return None
        return self.ag, self.F0, self.Tc_star


class Suite(Table):
    """A suite file."""

    name: str = Field(..., min_length=1, description="Name of the suite")
    records: list[SuiteRecord] = Field(..., description="The records, [[records]] tables")
    target: Target = Field(..., description="The target spectrum")
    period_range: list[FiniteNumber] | None = Field(
        None, description="[a, b]: periods checked [s]; default [0.15, 2.0]"
    )
    tolerance: list[OpenNumber] | None = Field(
        None,
        description="[lo, hi]: allowed deviation of the mean from the target, as fractions; "
        "default [-0.10, 0.30] (2018), [-0.10, inf] (2008)",
    )

    def record_names(self) -> list[str]:
        """Each record's label (its name, else the file's stem)."""
        from rockcli.records.files import record_name

        return [r.name or record_name(Path(r.path)) for r in self.records]
