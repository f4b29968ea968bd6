"""`rock risk MODEL`: the risk class of a model's local mechanisms (rockcli.risk.local) from
the code check of its catalogue on the site's hazard, and with a retrofit the class before
(without the tie-rod) and after (with the diameter `rock retrofit` chooses)."""

from __future__ import annotations

import copy
from dataclasses import dataclass
from typing import Any

from rockcli.analyses.choices import Analyses
from rockcli.codecheck.result import KinematicResult
from rockcli.errors import InputError
from rockcli.model.schema import Model
from rockcli.records.record import Record
from rockcli.risk.local import BuildingRisk, building_risk

#: The edition whose checks give the capacity ag of SLD, SLV and SLC.
EDITION = "2019"


@dataclass(frozen=True)
class Classified:
    """One state of the model: what it is, its code check and its class."""

    label: str
    result: KinematicResult
    risk: BuildingRisk


@dataclass(frozen=True)
class Retrofit:
    """The rod `rock retrofit` sizes: its name, steel, bars, the chosen diameter [mm] (None:
    none of the diameters tried makes the mechanisms it restrains safe) and why."""

    rod: str
    grade: str
    bars: int
    diameter_mm: float | None
    reason: str
    rocked: bool


def check_model(model: Model, edition: str | None, file: str, site: bool) -> None:
    """The class needs T_Rc at SLD, SLV and SLC: the 2019 edition's checks, on a code spectrum
    with a hazard (InputError otherwise; ``site``: --site is given)."""
    from rockcli.analyses.compare import code_sets_demand
    from rockcli.analyses.kinematic import check_settings

    settings = check_settings(model, edition)
    if settings.edition != EDITION:
        raise InputError(
            "a T_Rc at SLC, and capacities in ag, are not in this edition's checks of a local "
            "mechanism (Circolare 617/2009 checks DLS and ULS on a0* and spectral values)",
            file=None if edition else file,
            where="--edition" if edition else "ntc.edition",
            value=edition or settings.edition,
            allowed="2019 (NTC 2018 + Circolare 7/2019), whose SLD, SLV and SLC give T_Rc",
        )
    if not site and not code_sets_demand(model):
        raise InputError(
            "the model sets no code spectrum to read T_Rc on", file=file, where="ntc",
            allowed="[ntc.demand.SLD/SLV/SLC] or [ntc.site] in the model (or --site LON,LAT "
            "without --retrofit)",
        )  # fmt: skip


def classified(label: str, model: Model, analyses: Analyses, site, grid_file, file: str
               ) -> Classified:  # fmt: skip
    """The code check of the model's catalogue on its own (or the site's) demand, and its
    class (InputError when no mechanism has a T_Rc of each limit state)."""
    from rockcli.analyses.kinematic import kinematic_model

    result = kinematic_model(model, edition=analyses.edition, site=site, grid_file=grid_file)
    risk = building_risk(result.catalogue)
    if risk is None:
        raise InputError(
            "no hazard curve to read T_Rc on: the ag of the model's limit states does not "
            "grow with their return periods (or grows so little that a segment is steeper "
            "than λ ∝ ag^−30)",
            file=file,
            where="ntc.demand",
            allowed="[ntc.demand.SLD/SLV/SLC] whose ag grows from SLD to SLC, or [ntc.site] "
            "with a hazard grid, or --site LON,LAT",
        )
    return Classified(label, result, risk)


def model_risk(path: str, analyses: Analyses, site, grid_file) -> Classified:
    """`rock risk MODEL`: the model as it is described."""
    from rockcli.model.load import load_model

    model = load_model(path)
    check_model(model, analyses.edition, path, site is not None)
    return classified("the model as described", model, analyses, site, grid_file, path)


def retrofit_risk(path: str, record: Record | None, analyses: Analyses, grid_file
                  ) -> tuple[Classified, Retrofit, Classified | None]:  # fmt: skip
    """`rock risk MODEL --retrofit`: the class without the model's tie-rod, the rod `rock
    retrofit` sizes (on the model's own spectra, rocked under ``record`` when given), and the
    class with it (None: no diameter tried passes)."""
    from rockcli.model.load import read_toml, validate_model
    from rockcli.studies.retrofit.candidates import build_candidate, make_plan, tie_rods
    from rockcli.studies.retrofit.run import size_rod

    table = read_toml(path)
    model = validate_model(table, file=path)
    check_model(model, analyses.edition, path, False)
    rods = tie_rods(model)
    if len(rods) != 1:
        raise InputError(f"{len(rods)} tie-rods: --retrofit sizes the model's only tie-rod",
                         file=path, where="restrainers",
                         allowed='a model with one tie-rod (kind = "tie-rod") to size')  # fmt: skip
    sizing = size_rod(path, record, analyses, "model", grid_file)
    bare = validate_model(without_rod(table, rods[0]), file=path)
    before = classified(f"without its tie-rod '{sizing.rod}'", bare, analyses, None, grid_file,
                        path)  # fmt: skip
    chosen = None if sizing.chosen is None else float(sizing.chosen["diameter_mm"])
    rod = Retrofit(sizing.rod, sizing.grade, sizing.bars, chosen, str(sizing.reason),
                   sizing.rocked)  # fmt: skip
    if chosen is None:
        return before, rod, None
    with_rod = build_candidate(make_plan(table, model, file=path, diameters_mm=(chosen,)), chosen)
    after = classified(f"with '{sizing.rod}' Ø{chosen:g} mm", with_rod, analyses, None,
                       grid_file, path)  # fmt: skip
    return before, rod, after


def without_rod(table: Any, index: int) -> dict[str, Any]:
    """The model's table without its restrainer ``index`` (the wall before the retrofit)."""
    out = copy.deepcopy(dict(table))
    rods = [r for k, r in enumerate(out.get("restrainers", [])) if k != index]
    if rods:
        out["restrainers"] = rods
    else:
        out.pop("restrainers", None)
    return out
