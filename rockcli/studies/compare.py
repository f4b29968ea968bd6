"""The comparison: the code's kinematic check and the rocking time history on the same record.

The point of rock (spec/README.md; paper §3.3, §4.4): one element, one record, the two verdicts
side by side, and a one-word classification of their agreement.
"""

from __future__ import annotations

from enum import StrEnum
from typing import TYPE_CHECKING, Any

from rockcli import __version__
from rockcli.codecheck.demand import Spectrum
from rockcli.model.schema import Model
from rockcli.records.record import Record

if TYPE_CHECKING:
    from rockcli.studies.assess import AssessmentOutput

SCHEMA = 1


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


def code_sets_demand(model: Model) -> bool:
    """True when the model's [ntc] gives a code spectrum (parameters or a site)."""
    ntc = model.ntc
    return ntc is not None and (ntc.demand is not None or ntc.site is not None)


def _negate(value: bool | None) -> bool | None:
    return None if value is None else not value


def comparison_document(kin: dict[str, Any], roc: dict[str, Any]) -> dict[str, Any]:
    """Both documents, the activation and collapse rows, and the classification."""
    code_collapse = _negate(kin["verdict"]["ULS"])
    rocking_collapse = None if roc["verdict"] == "undecided" else roc["verdict"] == "overturns"
    uplifts = [r["t_uplift"] for r in roc["runs"] if r["t_uplift"] is not None]
    overturns = [r["t_overturn"] for r in roc["runs"] if r["t_overturn"] is not None]
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "kinematic": kin,
        "rocking": roc,
        "activation": {
            "code": _negate(kin["verdict"]["DLS"]),
            "rocking": bool(uplifts),
            "t_uplift": min(uplifts) if uplifts else None,
        },
        "collapse": {
            "code": code_collapse,
            "rocking": rocking_collapse,
            "t_overturn": min(overturns) if overturns else None,
        },
        "classification": str(classify(code_collapse, rocking_collapse)),
    }


def compare_model_output(
    model: Model,
    record: Record,
    *,
    engine: str = "fast",
    edition: str | None = None,
    spectrum: Spectrum | None = None,
    grid_file: str | None = None,
    record_demand: bool = False,
    history: bool = False,
) -> tuple[dict[str, Any], AssessmentOutput]:
    """The comparison document of a validated model under a record, and the rocking runs.

    The code's demand is the record's response spectrum unless the model sets a code spectrum
    (spec/README.md, `rock compare`), or record_demand asks for the record's anyway;
    spectrum: the record's, when the caller has it already; history: keep θ(t) of both
    polarities (for plots).
    """
    from rockcli.studies.assess import assess_model_output
    from rockcli.studies.kinematic import kinematic_model

    own = record_demand or not code_sets_demand(model)
    kin = kinematic_model(
        model,
        edition=edition,
        record=record if own else None,
        spectrum=spectrum if own else None,
        grid_file=grid_file,
    )
    rocking = assess_model_output(model, record, engine, history=history)
    return comparison_document(kin, rocking.doc), rocking


def compare_model(
    model: Model,
    record: Record,
    *,
    engine: str = "fast",
    edition: str | None = None,
    spectrum: Spectrum | None = None,
    grid_file: str | None = None,
    record_demand: bool = False,
) -> dict[str, Any]:
    """The comparison document of a validated model under a record (see
    :func:`compare_model_output`)."""
    doc, _ = compare_model_output(
        model,
        record,
        engine=engine,
        edition=edition,
        spectrum=spectrum,
        grid_file=grid_file,
        record_demand=record_demand,
    )
    return doc


def run_comparison_output(
    model_path: str, record: Record, **options: Any
) -> tuple[dict[str, Any], AssessmentOutput]:
    """Load the model file and run :func:`compare_model_output`."""
    from rockcli.model.load import load_model

    return compare_model_output(load_model(model_path), record, **options)


def run_comparison(model_path: str, record: Record, **options: Any) -> dict[str, Any]:
    """Load the model file and run :func:`compare_model`."""
    return run_comparison_output(model_path, record, **options)[0]
