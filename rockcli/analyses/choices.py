"""What a command chooses for its analyses, as typed values handed down (never ``**options``).

Pure data: the command line (rockcli.cli) builds them from its options; the studies and the
report read their fields by name.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Analyses:
    """How both analyses run: the rocking engine ("fast" or "reference"), the code edition
    ("2009", "2019"; None: the model's) and ``ground`` (a mechanism at height rocks on the
    record itself instead of its floor motion)."""

    engine: str = "fast"
    edition: str | None = None
    ground: bool = False


@dataclass(frozen=True)
class ComparisonChoices:
    """A comparison of both analyses under one record, as `rock compare` and `rock report`
    choose it: how they run; the code check's demand ("record": the record's spectrum;
    "model": the model's own); the hazard grid for a site ([ntc.site]; None: the
    ROCK_HAZARD_GRID variable); the wall's mechanism shown in full (None: the governing)."""

    analyses: Analyses = field(default_factory=Analyses)
    code_demand: str = "record"
    grid_file: str | None = None
    mechanism: str | None = None
