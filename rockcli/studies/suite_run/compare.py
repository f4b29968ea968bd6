"""A model under a record suite, both ways: the code's kinematic check on the suite's target
spectrum (or on the suite's mean spectrum) and the rocking time history of every record by
the code's rule, with the classification of the two verdicts.

Like with like: the two sides are held to the same limit state, the suite target's. The code
check's verdict is the one of that limit state (2009: SLD → DLS, SLV → ULS; 2019: SLD, SLV,
SLC each), computed on the target's spectrum; the time history's is the suite measure against
the model's limit for that state (rockcli.studies.suite_run.assess.limit_for). The code check
still runs every limit state its edition has: the other states take their spectra from the
target's site (same soil, topography, VN, CU), or from the model's [ntc] when the target gives
parameters of one state only (docs/interpretations.md, "Record suites").

Results only: rockcli.terminal.suite renders them.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from enum import StrEnum
from typing import TYPE_CHECKING, Any

from rockcli.analyses.compare import Classification, classify
from rockcli.codecheck.demand import LimitStateDemand
from rockcli.errors import InputError
from rockcli.notes import Items, Note
from rockcli.studies.suite_run.assess import LoadedSuite, SuiteAssessment

if TYPE_CHECKING:
    from rockcli.codecheck.result import KinematicResult
    from rockcli.model.derive_ntc import NtcSettings
    from rockcli.records.record import Record
    from rockcli.suites.schema import Target


class SuiteCodeDemand(StrEnum):
    """Which spectrum the code check of a suite comparison sees (issue 10, item 3)."""

    TARGET = "target"  # the suite's target spectrum (the site's, for the other limit states)
    SUITE_MEAN = "suite-mean"  # the mean response spectrum of the suite's scaled records


#: The code check's verdict (KinematicResult.verdict()) of each limit state, per edition:
#: Circ. 617/2009 checks the damage (SLD) and the ultimate (SLV) limit states; Circ. 7/2019
#: gives SLD, SLV and SLC each.
VERDICT_KEY = {
    "2009": {"SLD": "DLS", "SLV": "ULS"},
    "2019": {"SLD": "SLD", "SLV": "SLV", "SLC": "SLC"},
}


@dataclass(frozen=True)
class SuiteComparison:
    """Both analyses of a model under a suite and their classification.

    Attributes:
        assessment: every record through the time history and the code's rule.
        kinematic: the code check on the chosen demand.
        limit_state: the suite target's limit state, the one both verdicts are of.
        verdict_key: the code check's verdict that decides (VERDICT_KEY).
        classification: how the two verdicts relate.
        code_demand: what the code check saw.
        notes: where each limit state's spectrum came from, and what differs from the model.
    """

    assessment: SuiteAssessment
    kinematic: KinematicResult
    limit_state: str
    verdict_key: str
    classification: Classification
    code_demand: SuiteCodeDemand
    notes: tuple[str, ...]


def verdict_key(edition: str, limit_state: str, file: str | None = None) -> str:
    """The code check's verdict of the limit state (InputError when the edition has none)."""
    keys = VERDICT_KEY[edition]
    if limit_state not in keys:
        raise InputError(
            f"the code check of this edition ({edition}) has no {limit_state} verdict to "
            "compare the suite with",
            file=file,
            where="target.limit_state",
            value=limit_state,
            allowed=", ".join(keys) + " (or rock assess --suite, the time history alone)",
        )
    return keys[limit_state]


def target_demand(
    target: Target, limit_state: str, grid_file: str | None, g: float, settings: NtcSettings
) -> LimitStateDemand:
    """The target's spectrum for one limit state: the target's own, or its site's at the
    state's return period (same VN, CU, soil, topography; rockcli.suites.run.target_of)."""
    from rockcli.analyses.kinematic import code_demand
    from rockcli.codecheck.categories import LimitState
    from rockcli.suites.run import target_of

    spec = target_of(target.model_copy(update={"limit_state": LimitState(limit_state)}), grid_file)
    params = (spec.spectrum.ag, spec.spectrum.F0, spec.spectrum.Tc_star)
    given = limit_state == target.limit_state.value
    source = (
        Note("suite_target", "the suite's target: {source}", source=spec.source)
        if given
        else Note("suite_site", "the suite's site: {source}", source=spec.source)
    )
    return code_demand(limit_state, params, settings, g, source, spec.TR)


def target_demands(
    target: Target, file: str | None, model: Any, grid_file: str | None
) -> Callable[[NtcSettings, float], dict[str, LimitStateDemand]]:
    """Every limit state's demand from the suite's target: its own state's spectrum; the other
    states' from its site, or, for a target given by parameters, from the model's [ntc].

    file: the suite file, for messages.
    """
    from rockcli.analyses.compare import code_sets_demand
    from rockcli.analyses.kinematic import LIMIT_STATES, demands

    own = target.limit_state.value

    def demand_of(settings: NtcSettings, g: float) -> dict[str, LimitStateDemand]:
        at_site = replace(
            settings,
            soil=target.soil.value,
            topography=target.topography.value,
            VN=target.VN,
            CU=target.CU,
        )
        states = LIMIT_STATES[settings.edition]
        if target.site is not None:
            return {ls: target_demand(target, ls, grid_file, g, at_site) for ls in states}
        if any(ls != own for ls in states) and not code_sets_demand(model):
            raise InputError(
                f"the target gives the {own} spectrum only; the code check also needs "
                + ", ".join(ls for ls in states if ls != own),
                file=file,
                where="target",
                value=f"ag, F0, Tc_star ({own})",
                allowed="lon, lat (every limit state from the hazard grid), [ntc.demand] or "
                "[ntc.site] in the model, or --code-demand suite-mean",
            )
        model_dem = demands(settings, g, None, None, grid_file)
        return {
            ls: target_demand(target, ls, grid_file, g, at_site) if ls == own else model_dem[ls]
            for ls in states
        }

    return demand_of


def mean_demands(
    records: Sequence[Record], name: str
) -> Callable[[NtcSettings, float], dict[str, LimitStateDemand]]:
    """Every limit state's demand: the mean response spectrum of the suite's scaled records
    (as one record's spectrum is with --code-demand record). name: the suite's."""
    from rockcli.analyses.kinematic import LIMIT_STATES
    from rockcli.codecheck.demand import MeanSpectrum, record_demand
    from rockcli.codecheck.response import RecordSpectrum

    source = (
        f"the mean response spectrum of the suite's {len(records)} records (as scaled), "
        "mean PGA in place of ag·S"
    )

    def demand_of(settings: NtcSettings, g: float) -> dict[str, LimitStateDemand]:
        mean = MeanSpectrum(tuple(RecordSpectrum.from_record(r, g=g) for r in records))
        return {
            ls: record_demand(ls, mean, f"mean of {name}", source)
            for ls in LIMIT_STATES[settings.edition]
        }

    return demand_of


def demand_notes(
    loaded: LoadedSuite, settings: NtcSettings, code_demand: SuiteCodeDemand
) -> tuple[str, ...]:
    """What the code check's demand is, and the model's [ntc] settings it does not use."""
    target = loaded.settings.target
    if code_demand is SuiteCodeDemand.SUITE_MEAN:
        return (Note("suite_mean_demand", "code demand: the suite's mean spectrum at every limit "
                     "state"),)  # fmt: skip
    notes = []
    differ = [
        Note(
            "target_differs",
            "{name} {mine} (target: {theirs})",
            name=name,
            mine=mine,
            theirs=theirs,
        )
        for name, mine, theirs in (
            ("soil", settings.soil, target.soil.value),
            ("topography", settings.topography, target.topography.value),
            ("VN", f"{settings.VN:g}", f"{target.VN:g}"),
            ("CU", f"{settings.CU:g}", f"{target.CU:g}"),
        )
        if str(mine) != str(theirs)
    ]
    if differ:
        notes.append(Note(
            "target_sets_demand", "the suite's target sets the code demand: the model's [ntc] "
            "{differ} is not used for it", differ=Items(differ)))  # fmt: skip
    return tuple(notes)


def compare_suite(
    model_path: str,
    suite_path: str,
    grid_file: str | None,
    *,
    code_demand: str = SuiteCodeDemand.TARGET,
    edition: str | None = None,
    engine: str = "fast",
    ground: bool = False,
    jobs: int = 1,
    progress: Callable[[int, int], None] | None = None,
    target: str | None = None,
    allow_outside: bool = False,
) -> SuiteComparison:
    """The code check on the suite's target (or mean) spectrum, the suite through the time
    history, and the classification of the two verdicts of the target's limit state.

    The code check runs first: its bad input (a state the edition lacks, a target that gives
    too little) stops the command before the time histories.
    """
    from rockcli.studies.suite_run.assess import load_suite_and_model

    loaded = load_suite_and_model(model_path, suite_path, grid_file, target, allow_outside)
    return compare_loaded(
        loaded, grid_file, code_demand=code_demand, edition=edition, engine=engine,
        ground=ground, jobs=jobs, progress=progress,
    )  # fmt: skip


def compare_loaded(
    loaded: LoadedSuite,
    grid_file: str | None,
    *,
    code_demand: str = SuiteCodeDemand.TARGET,
    edition: str | None = None,
    engine: str = "fast",
    ground: bool = False,
    jobs: int = 1,
    progress: Callable[[int, int], None] | None = None,
) -> SuiteComparison:
    """:func:`compare_suite` on a model and suite already read (the calculation report keeps
    the suite's scaled records for its figures)."""
    from rockcli.analyses.kinematic import check_settings, kinematic_model
    from rockcli.studies.suite_run.assess import assess_loaded

    which = SuiteCodeDemand(code_demand)
    settings = check_settings(loaded.model, edition)
    state = loaded.settings.target.limit_state.value
    key = verdict_key(settings.edition, state, loaded.settings.file)
    suite = loaded.settings
    demand_of = (
        mean_demands(loaded.check.records, suite.name)
        if which is SuiteCodeDemand.SUITE_MEAN
        else target_demands(suite.target, suite.file, loaded.model, grid_file)
    )
    kin = kinematic_model(loaded.model, edition=edition, demand_of=demand_of)
    assessment = assess_loaded(loaded, engine=engine, ground=ground, jobs=jobs, progress=progress)
    passed = kin.verdict()[key]
    kind = classify(None if passed is None else not passed, not assessment.measure.passed)
    return SuiteComparison(
        assessment, kin, state, key, kind, which, demand_notes(loaded, settings, which)
    )
