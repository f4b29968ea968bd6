"""The comparison: the code's kinematic check and the rocking time history on the same record.

The point of rock (paper §3.3, §4.4): one element, one record, the two verdicts side by side,
and a one-word classification of their agreement. Results only: the command layer builds the
document (rockcli.terminal.compare).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from enum import StrEnum
from typing import Any

from rockcli.analyses.assess import AssessmentOutput, Catalogue, assess_model_output
from rockcli.analyses.catalogue import main_mechanism, named_result
from rockcli.codecheck.demand import Spectrum
from rockcli.codecheck.result import KinematicResult
from rockcli.dynamics.result import Assessment, RockingRun, RunStatus, Verdict
from rockcli.mechanisms.wall import NOT_ROCKED, MechanismType
from rockcli.model.schema import Model
from rockcli.notes import Note
from rockcli.records.record import Record


class Classification(StrEnum):
    """How the code's ULS verdict and the rocking verdict relate."""

    CONSISTENT_SAFE = "consistent-safe"  # code passes, rocking survives
    CONSISTENT_UNSAFE = "consistent-unsafe"  # code fails, rocking overturns
    CODE_CONSERVATIVE = "code-conservative"  # code fails, rocking survives
    CODE_UNCONSERVATIVE = "code-unconservative"  # code passes, rocking overturns
    UNDETERMINED = "undetermined"  # a verdict could not be reached (see the notes)


def classify(code_collapse: bool | None, rocking_collapse: bool | None) -> Classification:
    """The classification of a case from the two collapse verdicts (paper §3.3: an
    inconsistency is a block unsafe by the code and safe by the rocking analysis)."""
    if code_collapse is None or rocking_collapse is None:
        return Classification.UNDETERMINED
    if code_collapse:
        return (
            Classification.CONSISTENT_UNSAFE
            if rocking_collapse
            else Classification.CODE_CONSERVATIVE
        )
    return (
        Classification.CODE_UNCONSERVATIVE if rocking_collapse else Classification.CONSISTENT_SAFE
    )


def code_collapse(result: KinematicResult) -> bool | None:
    """The code's collapse verdict: its ULS check not satisfied (None: not evaluated)."""
    uls = result.verdict()["ULS"]
    return None if uls is None else not uls


def rocking_collapse(result: Assessment) -> bool | None:
    """The rocking verdict: overturning in either polarity (None: undecided)."""
    verdict = result.verdict
    return None if verdict is Verdict.UNDECIDED else verdict is Verdict.OVERTURNS


#: A second integration of a run: (polarity) → that polarity by the reference engine.
Rerun = Callable[[int], RockingRun]


def decided_collapse(
    result: Assessment, reference: Rerun | None = None
) -> tuple[bool | None, str | None]:
    """The rocking verdict a classification reads, and why it is not decided when its runs
    ended: :func:`rocking_collapse`, or None when a second integration gives the other
    verdict (overturns against survives), with a note saying which.

    The second integrations are those the runs already carry, each polarity again at the
    tolerance check's rtol/1000 (rockcli.dynamics.tolerance), and, with ``reference``, the
    reference engine's run of an overturning polarity whose two fast runs overturned after
    different numbers of impacts (their histories parted before the overturn: the tolerance
    check does not flag two overturns, and a chaotic path to an overturn is where the two
    engines can disagree). A polarity that overturns after the same impacts at both
    tolerances decides the envelope alone, and then nothing else is run. A second run that
    stops at a guard decides nothing (the verdict stands).
    """
    collapse = rocking_collapse(result)
    if collapse is None:
        return None, None
    runs = result.runs
    checks = [r.tolerance for r in runs]
    if all(c is not None for c in checks):
        tight = envelope((c.overturned, c.status) for c in checks if c is not None)
        if tight is not None and tight != collapse:
            tight_rtol = next(c.rtol for c in checks if c is not None)
            return None, (
                f"not decided: the time history {said(collapse)} at rtol {short(runs[0].rtol)} "
                f"and {said(tight)} at rtol {short(tight_rtol)} (the tolerance check): the "
                "verdict depends on the integration, the rocking is chaotic at the edge of "
                "overturning"
            )
    if reference is None or not collapse:
        return collapse, None
    doubtful = [r for r in runs if diverged(r) and r.mirror_of is None]
    if not doubtful or any(r.overturned and not diverged(r) for r in runs):
        return collapse, None
    again = {r.polarity: reference(r.polarity) for r in doubtful}

    def second(r: RockingRun) -> tuple[bool, RunStatus]:
        other = again.get(r.polarity if r.mirror_of is None else r.mirror_of)
        return (r.overturned, r.status) if other is None else (other.overturned, other.status)

    ref = envelope(second(r) for r in runs)
    if ref is None or ref == collapse:
        return collapse, None
    polarities = " and ".join(f"{p:+d}" for p in again)
    return None, (
        f"not decided: the fast engine overturns polarity {polarities} (at both tolerances, "
        "after different numbers of impacts), the reference engine survives it: the two "
        "engines disagree, the rocking is chaotic at the edge of overturning"
    )


def diverged(run: RockingRun) -> bool:
    """True when a run overturned at both tolerances of its check after different numbers of
    impacts (its histories parted before the overturn)."""
    check = run.tolerance
    return (
        run.overturned and check is not None and check.overturned
        and check.impacts != run.impacts
    )  # fmt: skip


def short(tolerance: float) -> str:
    """A tolerance as the outputs write it: 1e-8, not 1e-08."""
    return f"{tolerance:g}".replace("e-0", "e-")


def envelope(runs: Iterable[tuple[bool, RunStatus]]) -> bool | None:
    """Overturning in either polarity from (overturned, status) of each, as
    Assessment.verdict: None when a run met a non-finite number, or none overturned and one
    stopped at a guard."""
    seen = list(runs)
    if any(status is RunStatus.NONFINITE for _, status in seen):
        return None
    if any(over for over, _ in seen):
        return True
    return None if any(status is not RunStatus.COMPLETED for _, status in seen) else False


def said(collapse: bool) -> str:
    """ "overturns" or "survives"."""
    return "overturns" if collapse else "survives"


def reference_rerun(model: Model, record: Record, ground: bool, file: str | None,
                    mechanism: str | None, mechanisms: Catalogue | None = None,
                    ) -> Rerun:  # fmt: skip
    """The reference engine's run of one polarity of what assess_model_output rocks (the same
    block, motion and settings)."""

    def run(polarity: int) -> RockingRun:
        from rockcli.analyses.assess import rocked_input, settings_from
        from rockcli.dynamics.settings import Engine
        from rockcli.dynamics.simulate import simulate
        from rockcli.model.derive import solver_options

        block, shaking, _, _ = rocked_input(model, record, ground, file, mechanism, mechanisms)
        settings = settings_from(solver_options(model))
        return simulate(block, shaking.time, shaking.accel, shaking.dt, polarity=polarity,
                        settings=settings, engine=Engine.REFERENCE)  # fmt: skip

    return run


def code_sets_demand(model: Model) -> bool:
    """True when the model's [ntc] gives a code spectrum (parameters or a site)."""
    ntc = model.ntc
    return ntc is not None and (ntc.demand is not None or ntc.site is not None)


class CodeDemand(StrEnum):
    """Which earthquake the code check of a comparison sees (issue #8 item 4)."""

    RECORD = "record"  # the record's response spectrum: one earthquake on both sides
    MODEL = "model"  # the model's own code spectrum ([ntc.demand] or [ntc.site])


#: What --code-demand / code_demand accept when the model sets no code spectrum.
CODE_DEMAND_ALLOWED = (
    '"record" (the default), or "model" with a model that sets [ntc.demand] or [ntc.site]'
)


def check_code_demand(
    model: Model, code_demand: str, *, file: str | None = None, where: str = "--code-demand"
) -> None:
    """Refuse the model's code spectrum on a model that sets none (InputError naming where)."""
    from rockcli.errors import InputError

    if code_demand == CodeDemand.MODEL and not code_sets_demand(model):
        raise InputError(
            "the model sets no code spectrum ([ntc.demand] or [ntc.site])",
            file=file,
            where=where,
            value=str(code_demand),
            allowed=CODE_DEMAND_ALLOWED,
        )


@dataclass(frozen=True)
class ComparisonOutput:
    """Both analyses of a model under a record and their classification.

    Attributes:
        kinematic: the code's check. rocking: both polarities and the block.
        classification: how the two collapse verdicts relate.
        code_demand: the earthquake the code check saw (the record, or the model's spectrum).
        mechanisms: each mechanism of a wall's catalogue compared (empty for a block).
        classification_note: why the rocking verdict is not decided though its runs ended
            (:func:`decided_collapse`), or None.
        catalogue: the model's mechanisms as derived for this comparison
            (rockcli.model.catalogue), which a report's further sections rock again.
    """

    kinematic: KinematicResult
    rocking: AssessmentOutput
    classification: Classification
    code_demand: CodeDemand = CodeDemand.RECORD
    mechanisms: tuple[MechanismComparison, ...] = ()
    classification_note: str | None = None
    catalogue: Catalogue = ()


@dataclass(frozen=True)
class MechanismComparison:
    """One mechanism of a wall's catalogue under the record: its code check, its rocking and
    the classification.

    Attributes:
        name, type: the mechanism's.
        code: its kinematic result.
        rocking: both polarities (None: the time history cannot rock it, ``not_rocked``).
        classification: how its two collapse verdicts relate (None: not rocked).
        not_rocked: why the time history does not rock it (a vertical flexure with a
            restrainer on its upper block), or None.
        classification_note: why its rocking verdict is not decided though its runs ended
            (:func:`decided_collapse`), or None.
    """

    name: str
    type: str
    code: KinematicResult
    rocking: Assessment | None
    classification: Classification | None
    not_rocked: str | None = None
    classification_note: str | None = None


def compare_model_output(
    model: Model,
    record: Record,
    *,
    engine: str = "fast",
    edition: str | None = None,
    spectrum: Spectrum | None = None,
    grid_file: str | None = None,
    code_demand: str = CodeDemand.RECORD,
    history: bool = False,
    ground: bool = False,
    file: str | None = None,
    mechanism: str | None = None,
    mechanisms: Catalogue | None = None,
) -> ComparisonOutput:
    """Both analyses of a validated model under a record, and their classification.

    One earthquake on both sides: the code's demand is the record's response spectrum, even
    when the model sets a code spectrum; code_demand "model" uses the model's spectrum instead
    (InputError when it sets none). spectrum: the record's, when the caller has it already;
    history: keep θ(t) of both polarities (for plots). A block at height rocks on the floor
    motion of the record (the code check applies the code's at-height rules to the record's
    spectrum); ground: rock it on the record itself. mechanisms: the model's catalogue when
    the caller has derived it.
    """
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.model.catalogue import catalogue

    check_code_demand(model, code_demand)
    own = code_demand == CodeDemand.RECORD
    if mechanisms is None:  # derived once: both analyses read these values
        mechanisms = catalogue(model)
    kin = kinematic_model(
        model,
        edition=edition,
        record=record if own else None,
        spectrum=spectrum if own else None,
        grid_file=grid_file,
        mechanisms=mechanisms,
    )
    main = main_mechanism(kin, mechanism)
    name = None if main is None else main.name
    rocking = assess_model_output(model, record, engine, history=history, ground=ground,
                                  file=file, mechanism=name, mechanisms=mechanisms)  # fmt: skip
    kin = shown_result(kin, main)
    collapse, why = decided_collapse(rocking.result, rerun(model, record, engine, ground, file,
                                                           name, mechanisms))  # fmt: skip
    kind = classify(code_collapse(kin), collapse)
    others = catalogue_comparisons(model, record, engine, kin, main, (rocking, why), ground,
                                   mechanisms)  # fmt: skip
    return ComparisonOutput(kin, rocking, kind, CodeDemand(code_demand), others, why, mechanisms)


def rerun(model: Model, record: Record, engine: str, ground: bool, file: str | None,
          mechanism: str | None, mechanisms: Catalogue | None = None) -> Rerun | None:  # fmt: skip
    """The reference engine's second run of a fast comparison (:func:`decided_collapse`);
    None when the comparison runs the reference engine itself."""
    if engine != "fast":
        return None
    return reference_rerun(model, record, ground, file, mechanism, mechanisms)


def shown_result(kin: KinematicResult, main: Any) -> KinematicResult:
    """The main mechanism's code check, the catalogue kept; a note names the governing one
    when it is another (like with like)."""
    from dataclasses import replace

    if main is None or main.name == kin.mechanism:
        return kin

    notes = main.result.notes
    if main.name != kin.governing:
        notes = (*notes, Note("shows_other", "the comparison shows '{shown}'; the governing "
                              "mechanism is '{governing}'", shown=main.name,
                              governing=kin.governing))  # fmt: skip
    return replace(main.result, catalogue=kin.catalogue, governing=kin.governing, notes=notes)


def mechanism_output(
    model: Model,
    record: Record,
    whole: ComparisonOutput,
    name: str,
    *,
    engine: str = "fast",
    ground: bool = False,
    file: str | None = None,
) -> ComparisonOutput:
    """The comparison of one more mechanism of a wall ``whole`` has checked: its code check
    from ``whole``'s catalogue, its rocking run again with its histories (for its full section
    of a report); the catalogue's comparisons are ``whole``'s, not repeated."""
    main = named_result(whole.kinematic, name)
    mechanisms = whole.catalogue or None
    rocking = assess_model_output(model, record, engine, history=True, ground=ground, file=file,
                                  mechanism=name, mechanisms=mechanisms)  # fmt: skip
    kin = shown_result(whole.kinematic, main)
    collapse, why = decided_collapse(
        rocking.result, rerun(model, record, engine, ground, file, name, mechanisms)
    )
    kind = classify(code_collapse(kin), collapse)
    return ComparisonOutput(kin, rocking, kind, whole.code_demand, (), why, whole.catalogue)


def catalogue_comparisons(model, record, engine, kin, main, shown, ground, mechanisms=None):
    """Every mechanism of a wall's catalogue: the main one's comparison as made (``shown``:
    its rocking and the note of its decision), each other one run with its tolerance check
    and classified (one the time history refuses is listed with the reason). mechanisms:
    the catalogue's values, derived once by the caller."""
    from rockcli.errors import InputError

    if main is None:
        return ()
    rocking, main_why = shown
    out = []
    for m in kin.catalogue:
        if m.name == main.name:
            run: Assessment = rocking.result
            why = main_why
            collapse = None if why is not None else rocking_collapse(run)
        elif MechanismType(m.type) in NOT_ROCKED:
            reason = NOT_ROCKED[MechanismType(m.type)]
            out.append(MechanismComparison(m.name, m.type, m.result, None, None, reason))
            continue
        else:
            try:
                run = assess_model_output(model, record, engine, ground=ground, mechanism=m.name,
                                          mechanisms=mechanisms).result  # fmt: skip
            except InputError as exc:
                reason = exc.note()
                out.append(MechanismComparison(m.name, m.type, m.result, None, None, reason))
                continue
            collapse, why = decided_collapse(run, rerun(model, record, engine, ground, None,
                                                        m.name, mechanisms))  # fmt: skip
        kind = classify(code_collapse(m.result), collapse)
        out.append(MechanismComparison(m.name, m.type, m.result, run, kind, None, why))
    return tuple(out)


def run_comparison_output(
    model_path: str,
    record: Record,
    *,
    engine: str = "fast",
    edition: str | None = None,
    grid_file: str | None = None,
    code_demand: str = CodeDemand.RECORD,
    history: bool = False,
    ground: bool = False,
    mechanism: str | None = None,
) -> ComparisonOutput:
    """Load the model file and run :func:`compare_model_output` (its arguments)."""
    from rockcli.model.load import load_model

    model = load_model(model_path)
    check_code_demand(model, code_demand, file=model_path)
    return compare_model_output(
        model, record, engine=engine, edition=edition, grid_file=grid_file,
        code_demand=code_demand, history=history, ground=ground, file=model_path,
        mechanism=mechanism,
    )  # fmt: skip
