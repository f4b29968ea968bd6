"""`rock suite check`: the suite file, its records, the target spectrum and the check, as data."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from rockcli.codecheck.categories import Edition
from rockcli.codecheck.spectra import ElasticSpectrum, return_period
from rockcli.errors import InputError
from rockcli.notes import Note
from rockcli.records.record import Record
from rockcli.suites.compat import (
    AutoScale,
    Compatibility,
    FloorFilter,
    auto_scale,
    compatibility,
    count_rule,
    floor_records,
    floor_target,
    period_grid,
    record_spectra,
    target_spectrum,
)
from rockcli.suites.load import SuiteEntry, SuiteSettings, read_entries
from rockcli.suites.schema import Target
from rockcli.suites.twins import TWIN_CORRELATION, best_correlation, find_twins, twin_groups

#: The year of the code text of each edition (rock names editions by their Circolare).
CODE_YEAR = {Edition.E2009: "2008", Edition.E2019: "2018"}
#: Version of the JSON document of `rock suite check`.
SCHEMA_VERSION = 1


@dataclass(frozen=True)
class TargetSpectrum:
    """The target: the code spectrum, its return period [years] and where ag, F0, TC* came
    from."""

    spectrum: ElasticSpectrum
    TR: float
    source: str


def target_of(target: Target, grid_file: str | None) -> TargetSpectrum:
    """The elastic spectrum of the limit state's TR (NTC §3.2.1, §3.2.3.2.1).

    With a site, ag, F0 and TC* come from the hazard grid at TR = −VN·CU/ln(1 − P_VR)
    (DM 14/01/2008 Allegato A); with the parameters given, they are used as they are.
    """
    TR = return_period(target.VN, target.CU, target.limit_state, target.edition)
    site, given = target.site, target.parameters
    if given is not None:
        (ag, F0, Tc_star), source = given, Note("given_in_suite", "given in the suite")
    elif site is not None:
        from rockcli.codecheck.hazard import grid_path, grid_source, read_grid, site_parameters

        ag, F0, Tc_star = site_parameters(read_grid(grid_path(grid_file)), *site, TR)
        source = grid_source(site)
    else:  # the suite's rules refuse a target without either
        raise InputError("no site and no parameters", where="target")
    spectrum = ElasticSpectrum(ag, F0, Tc_star, target.soil, target.topography)
    return TargetSpectrum(spectrum, TR, source)


@dataclass(frozen=True)
class FloorCheck:
    """The check at a block's height: the floor, its acceleration a_Z [g] and each record's
    floor motion PGA [g]."""

    floor: FloorFilter
    a_z: float
    pga: list[float]


@dataclass(frozen=True)
class SuiteCheck:
    """Everything the command shows. records: the ground records, scaled (what a time
    history takes); spectra: of the motions checked (the floor motions at height)."""

    settings: SuiteSettings
    records: list[Record]
    target: TargetSpectrum
    spectra: np.ndarray
    check: Compatibility
    auto: AutoScale | None
    scaled: Compatibility | None
    at_height: FloorCheck | None = None
    twins: tuple[str, ...] = ()

    @property
    def warnings(self) -> tuple[str, ...]:
        """Every record's warnings (a PGA that suggests a unit slip…), each after its name,
        then the pairs of records that are one motion (twin_warnings)."""
        named = tuple(
            f"{entry.name}: {warning}"
            for entry, record in zip(self.settings.entries, self.records, strict=True)
            for warning in record.warnings
        )
        return named + self.twins


def twin_warnings(settings: SuiteSettings, records: Sequence[Record]) -> tuple[str, ...]:
    """A warning for each group of records that are one motion (rockcli.suites.twins: a copy
    flipped, shifted or scaled; exact copies are refused when the suite is read), with how
    many different records the suite then holds."""
    groups = twin_groups(len(records), find_twins(records))
    distinct = len(records) - sum(len(g) - 1 for g in groups)
    return tuple(twin_text(g, settings.entries, records, distinct) for g in groups)


def twin_text(
    group: Sequence[int], entries: Sequence[SuiteEntry], records: Sequence[Record], distinct: int
) -> str:
    """One warning: the records of a group, how each relates to the first, the count."""
    names = [repr(entries[i].name) for i in group]
    listed = ", ".join(names[:-1]) + " and " + names[-1]
    relations = []
    for i in group[1:]:
        rho, lag = best_correlation(records[group[0]], records[i])
        shift = f", {abs(lag):g} s {'later' if lag > 0 else 'earlier'}" if lag else ""
        relations.append(f"{entries[i].name!r} ρ = {rho:+.4f}{', flipped' if rho < 0 else ''}"
                         f"{shift}")  # fmt: skip
    text = (
        f"records {listed} are one motion (their accelerations correlate after alignment at "
        f"|ρ| > {TWIN_CORRELATION:g} with {entries[group[0]].name!r}: {'; '.join(relations)}): "
        f"the code asks for different records, and this suite holds {distinct} different "
        f"records, not {len(records)}"
    )
    if count_rule(distinct) is not count_rule(len(records)):
        text += f" — with {distinct} the worst effect governs, not the mean (NTC §3.2.3.6)"
    return text


def run_suite_check(
    settings: SuiteSettings,
    grid_file: str | None,
    *,
    scale_auto: bool = False,
    floor: FloorFilter | None = None,
) -> SuiteCheck:
    """Read the records, compute their spectra, the mean and the check (and the auto factor).

    floor: check at a block's height instead: each record's floor motion against the code's
    floor spectrum of the target (compat.floor_records, compat.floor_target).
    """
    try:
        target = target_of(settings.target, grid_file)
    except InputError as exc:  # a site outside the grid: name the suite file
        raise exc.with_file(settings.file) from None
    records = read_entries(settings)
    periods = period_grid(*settings.period_range)
    at_height = None
    if floor is None:
        spectra = record_spectra(records, periods)
        curve = target_spectrum(target.spectrum, periods)
    else:
        motions = floor_records(records, floor)
        spectra = record_spectra(motions, periods)
        curve, a_z = floor_target(target.spectrum, floor, periods)
        at_height = FloorCheck(floor, a_z, [float(m.pga) for m in motions])
    check = compatibility(periods, curve, spectra.mean(axis=0), settings.tolerance)
    twins = twin_warnings(settings, records)
    auto = scaled = None
    if scale_auto:
        auto = auto_scale(check.ratio, settings.tolerance)
        if auto.factor is not None:
            mean = check.mean * auto.factor
            scaled = compatibility(periods, check.target, mean, settings.tolerance)
    return SuiteCheck(settings, records, target, spectra, check, auto, scaled, at_height, twins)


def _bound(x: float) -> float | None:
    return x if math.isfinite(x) else None


def check_numbers(check: Compatibility) -> dict[str, Any]:
    """The verdict of one check: passed, the worst ratio and its period."""
    i = check.worst_index
    return {
        "passed": check.passed,
        "worst_ratio": float(check.ratio[i]),
        "worst_period": float(check.periods[i]),
        "min_ratio": float(check.ratio.min()),
        "max_ratio": float(check.ratio.max()),
    }


def suite_document(result: SuiteCheck) -> dict[str, Any]:
    """The JSON document of `rock suite check` (full precision)."""
    s, check, target = result.settings, result.check, result.target
    spectrum = target.spectrum
    doc: dict[str, Any] = {
        "schema": SCHEMA_VERSION,
        "suite": s.name,
        "passed": check.passed,
        "period_range": list(s.period_range),
        "tolerance": [_bound(s.tolerance[0]), _bound(s.tolerance[1])],
        "count": len(result.records),
        "count_rule": count_rule(len(result.records)).value,
        **{k: v for k, v in check_numbers(check).items() if k != "passed"},
        "target_parameters": {
            "limit_state": s.target.limit_state.value,
            "edition": CODE_YEAR[s.target.edition],
            "TR": target.TR,
            "ag": spectrum.ag,
            "F0": spectrum.F0,
            "Tc_star": spectrum.Tc_star,
            "soil": spectrum.soil.value,
            "topography": spectrum.topography.value,
            "S": spectrum.S,
            "source": target.source,
        },
        "periods": check.periods.tolist(),
        "target": check.target.tolist(),
        "mean": check.mean.tolist(),
        "ratio": check.ratio.tolist(),
        "within": check.within.tolist(),
        "records": [
            {"name": e.name, "scale": e.scale, "pga_g": r.pga, "file": str(e.path), "Sa": sa}
            for e, r, sa in zip(s.entries, result.records, result.spectra.tolist(), strict=True)
        ],
        "at_height": None,
        "warnings": list(result.warnings),
    }
    if result.at_height is not None:
        h = result.at_height
        doc["at_height"] = {
            "Z": h.floor.Z,
            "T1": h.floor.T1,
            "psi": h.floor.psi,
            "gamma": h.floor.gamma,
            "xi": h.floor.xi,
            "a_z": h.a_z,
        }
        for row, pga in zip(doc["records"], h.pga, strict=True):
            row["floor_pga_g"] = pga
    if result.auto is not None:
        scaled = check_numbers(result.scaled) if result.scaled is not None else {"passed": False}
        doc["scale_auto"] = {
            "factor": result.auto.factor,
            "feasible": result.auto.feasible,
            **scaled,
        }
    return doc
