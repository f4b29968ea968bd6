"""Run a casebook: each case's obtained value against its expected one, as data.

Silent: the CLI and the calculation report render :class:`CasebookResult`.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path

from rockcli.casebook import code, rocking, schema
from rockcli.casebook.load import LoadedCase, casebook_folder, load_casebook
from rockcli.casebook.schema import QUANTITIES, Kind, ToleranceType
from rockcli.errors import InputError


class Status(StrEnum):
    """A case's outcome: within its tolerance, not, or not run (and why)."""

    PASSED = "passed"
    FAILED = "failed"
    SKIPPED = "skipped"


@dataclass(frozen=True)
class CaseResult:
    """One case: what was expected, from where, what rock obtained, and the verdict.

    Attributes:
        error: |obtained − expected|, relative to |expected| for a relative tolerance (None
            when nothing was obtained).
        note: why a case was skipped, or why nothing was obtained.
        source_it: the source in Italian (the case file's ``source_it``), None without one.
    """

    id: str
    title: str
    kind: str
    source: str
    quantity: str
    unit: str
    expected: float
    obtained: float | None
    tolerance: float
    tolerance_type: str
    tolerance_reason: str
    file: str
    status: Status
    error: float | None = None
    note: str = ""
    source_it: str | None = None

    @property
    def passed(self) -> bool | None:
        """True or False; None for a skipped case."""
        return None if self.status is Status.SKIPPED else self.status is Status.PASSED


@dataclass(frozen=True)
class CasebookResult:
    """Every case of a casebook, in file and case order."""

    folder: str
    cases: tuple[CaseResult, ...]

    def count(self, status: Status) -> int:
        """How many cases have this status."""
        return sum(case.status is status for case in self.cases)

    @property
    def ok(self) -> bool:
        """No case failed (skipped ones allowed)."""
        return self.count(Status.FAILED) == 0


def run_casebook(folder: Path | str | None = None, grid_file: str | None = None) -> CasebookResult:
    """Load and run every case of the folder (default: the bundled casebook).

    Args:
        folder: a folder of case files; None for examples/validation.
        grid_file: the NTC hazard grid (else $ROCK_HAZARD_GRID); without one the hazard cases
            are skipped.

    Raises:
        InputError: a malformed case file, case or model.
    """
    cases = load_casebook(folder)
    grid = available_grid(grid_file)
    results = tuple(run_case(case, grid) for case in cases)
    return CasebookResult(folder=str(casebook_folder(folder)), cases=results)


#: Why a hazard case is skipped without a grid.
NO_GRID = "no hazard grid given (--hazard-grid FILE or ROCK_HAZARD_GRID); rock does not ship it"


def available_grid(grid_file: str | None) -> str | None:
    """The grid file of the option or the environment, None when neither names one."""
    from rockcli.codecheck.hazard import grid_path

    try:
        return grid_path(grid_file)
    except InputError:
        return None


def run_case(loaded: LoadedCase, grid_file: str | None) -> CaseResult:
    """One case: computed, compared, or skipped (a hazard case without a grid)."""
    case = loaded.case
    if case.kind in (Kind.HAZARD, Kind.DAMAGE_RATE) and grid_file is None:
        return result_of(loaded, None, Status.SKIPPED, note=NO_GRID)
    try:
        obtained = obtain(loaded, grid_file)
    except rocking.NotObtained as exc:
        return result_of(loaded, None, Status.FAILED, note=str(exc))
    except InputError as exc:
        raise exc.with_file(f"{loaded.file} (case {case.id})") from None
    if obtained is None:
        return result_of(loaded, None, Status.FAILED, note="rock gives no value")
    error = measured_error(obtained, case.expected, case.tolerance_type)
    status = Status.PASSED if error <= case.tolerance else Status.FAILED
    return result_of(loaded, obtained, status, error=error)


def measured_error(obtained: float, expected: float, kind: ToleranceType) -> float:
    """|obtained − expected|, over |expected| for a relative tolerance."""
    diff = abs(obtained - expected)
    if kind is ToleranceType.ABSOLUTE:
        return diff
    return diff / abs(expected) if expected != 0 else (0.0 if diff == 0 else float("inf"))


def obtain(loaded: LoadedCase, grid_file: str | None) -> float | None:
    """The case's obtained value, by its kind's runner (dispatched on its input's type)."""
    q, inputs = loaded.case.quantity, loaded.input
    if isinstance(inputs, schema.SpectrumInput):
        return code.spectrum_quantity(inputs, q)
    if isinstance(inputs, schema.HazardInput):
        assert grid_file is not None
        return code.hazard_quantity(inputs, q, grid_file)
    if isinstance(inputs, schema.ResponseSpectrumInput):
        return code.response_quantity(inputs, q)
    if isinstance(inputs, schema.FloorInput):
        return code.floor_quantity(inputs)
    if isinstance(inputs, schema.SuiteInput):
        return code.suite_quantity(inputs)
    if isinstance(inputs, schema.RiskClassInput):
        return code.risk_class_quantity(inputs, q)
    if isinstance(inputs, schema.DamageRateInput):
        assert grid_file is not None
        return code.damage_rate_quantity(inputs, q, grid_file)
    return obtain_on_model(loaded)


def obtain_on_model(loaded: LoadedCase) -> float | None:
    """The obtained value of a kind that runs on the case's block."""
    q, inputs, model = loaded.case.quantity, loaded.input, loaded.model
    assert model is not None
    if isinstance(inputs, schema.ModelInput):
        return code.model_quantity(model, inputs, q)
    if isinstance(inputs, schema.KinematicInput):
        return code.kinematic_quantity(model, inputs, q)
    if isinstance(inputs, schema.FreeRockingInput):
        free = rocking.free_period if q == "period" else rocking.free_amplitude
        return free(model, inputs)
    if isinstance(inputs, schema.ImpulseInput):
        return rocking.impulse_threshold(model, inputs)
    if isinstance(inputs, schema.ReleaseInput):
        return rocking.released(model, inputs, q)
    if isinstance(inputs, schema.UpliftRampInput):
        return rocking.ramp_uplift(model, inputs, q)
    if isinstance(inputs, schema.UpliftSineInput):
        return rocking.sine_uplift(model, inputs)
    assert isinstance(inputs, schema.PulseThresholdInput)
    return rocking.pulse_threshold(model, inputs)


def result_of(
    loaded: LoadedCase,
    obtained: float | None,
    status: Status,
    *,
    error: float | None = None,
    note: str = "",
) -> CaseResult:
    """The CaseResult of a loaded case."""
    case = loaded.case
    return CaseResult(
        id=case.id,
        title=case.title,
        kind=case.kind.value,
        source=case.source,
        quantity=case.quantity,
        unit=QUANTITIES[case.kind][case.quantity],
        expected=case.expected,
        obtained=obtained,
        tolerance=case.tolerance,
        tolerance_type=case.tolerance_type.value,
        tolerance_reason=case.tolerance_reason,
        file=loaded.file,
        status=status,
        error=error,
        note=note,
        source_it=case.source_it,
    )
