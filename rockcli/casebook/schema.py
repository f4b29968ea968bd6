"""The case file: one TOML per topic, each ``[[cases]]`` a solved case with its source.

The common fields say what is checked and against what (``expected`` from ``source``, within
``tolerance`` for ``tolerance_reason``); ``kind`` names the computation and ``[cases.input]``
its parameters, validated by the kind's own table below. ``model`` is a model file (a path
relative to the case file) or an inline model table, for the kinds that need a block.
"""

from __future__ import annotations

from enum import StrEnum
from typing import Annotated, Any, Literal

from pydantic import Field

from rockcli.model.schema_base import Table

# Every number is strict: a TOML int or float, never a string ("0.09375" would be read as the
# number by pydantic's lax mode: a case's expected value must be the number the file shows)
# nor a boolean (true is not 1).
Positive = Annotated[float, Field(gt=0, allow_inf_nan=False, strict=True)]
Finite = Annotated[float, Field(allow_inf_nan=False, strict=True)]
#: A sample interval [s]: fine enough for any case, coarse enough to keep a case small.
SampleInterval = Annotated[float, Field(ge=1e-5, le=0.01, strict=True, description="[s]")]
#: A period or a duration [s]: a case is short (the casebook runs in seconds).
Seconds = Annotated[float, Field(gt=0, le=60, allow_inf_nan=False, strict=True, description="[s]")]
#: A bisection bracket's end: an amplitude [g] or a velocity [rad/s].
BracketEnd = Annotated[float, Field(gt=0, le=1e3, allow_inf_nan=False, strict=True)]


class Kind(StrEnum):
    """What a case computes (one runner each, rockcli.casebook.run)."""

    MODEL = "model"
    KINEMATIC = "kinematic"
    FREE_ROCKING = "free-rocking"
    IMPULSE = "impulse"
    PULSE_THRESHOLD = "pulse-threshold"
    SPECTRUM = "spectrum"
    HAZARD = "hazard"
    RESPONSE_SPECTRUM = "response-spectrum"
    FLOOR = "floor"
    SUITE = "suite"
    UPLIFT_RAMP = "uplift-ramp"
    UPLIFT_SINE = "uplift-sine"
    RELEASE = "release"
    RISK_CLASS = "risk-class"
    DAMAGE_RATE = "damage-rate"


class ToleranceType(StrEnum):
    """How the error is measured: |obtained − expected|, or that over |expected|."""

    ABSOLUTE = "absolute"
    RELATIVE = "relative"


#: The quantities of each kind and their units (the case's ``quantity`` is one of these).
QUANTITIES: dict[Kind, dict[str, str]] = {
    Kind.MODEL: {
        "R": "m",
        "alpha": "rad",
        "p": "rad/s",
        "e": "-",
        "k_pos": "N/m",
        "c_K": "1/s²",
        "c_E": "1/s²",
        "positive_stiffness_4KR_mg": "-",
        "theta_c_pos": "rad",
        "theta_c_neg": "rad",
    },
    Kind.KINEMATIC: {
        "alpha0": "-",
        "e_star": "-",
        "a0_star": "m/s²",
        "d0_star": "m",
        "du_star": "m",
        "Ts": "s",
        "M_star": "kg",
        "hinge_height": "m",
        "instability_displacement": "m",
        "T0": "s",
        "ag_SLD": "g",
        "d_SLV": "m",
        "e_rocking": "-",
    },
    Kind.FREE_ROCKING: {"period": "s", "amplitude": "rad"},
    Kind.IMPULSE: {"omega_threshold": "rad/s"},
    Kind.PULSE_THRESHOLD: {"amplitude_threshold": "g"},
    Kind.SPECTRUM: {"Se": "g", "SDe": "m", "S_S": "-", "C_C": "-", "TD": "s", "SeZ": "g"},
    Kind.HAZARD: {"ag": "g", "F0": "-", "Tc_star": "s"},
    Kind.RESPONSE_SPECTRUM: {"Sa": "g", "Sd": "m"},
    Kind.FLOOR: {"peak": "g"},
    Kind.SUITE: {"ratio": "-"},
    Kind.UPLIFT_RAMP: {"uplift_acceleration": "g", "uplift_time": "s"},
    Kind.UPLIFT_SINE: {"uplift_time": "s"},
    Kind.RISK_CLASS: {"PAM": "-", "IS_V_class": "-", "PAM_class": "-", "class": "-"},
    Kind.DAMAGE_RATE: {"annual_rate": "1/year", "return_period": "years"},
    Kind.RELEASE: {
        "max_rotation": "rad",
        "max_elongation": "m",
        "max_force": "N",
        "plastic_elongation": "m",
        "energy_dissipated": "J",
    },
}

#: The kinds that need a block (``model``).
NEEDS_MODEL = frozenset(
    {
        Kind.MODEL,
        Kind.KINEMATIC,
        Kind.FREE_ROCKING,
        Kind.IMPULSE,
        Kind.PULSE_THRESHOLD,
        Kind.UPLIFT_RAMP,
        Kind.UPLIFT_SINE,
        Kind.RELEASE,
    }
)


class Case(Table):
    """One solved case."""

    id: str = Field(min_length=1, pattern=r"^[A-Za-z0-9][A-Za-z0-9._-]*$", description="unique id")
    title: str = Field(min_length=1, description="what the case checks")
    kind: Kind
    quantity: str = Field(min_length=1, description="the quantity checked (one of the kind's)")
    expected: Finite
    tolerance: Positive
    tolerance_type: ToleranceType
    tolerance_reason: str = Field(min_length=1, description="why this tolerance")
    source: str = Field(min_length=1, description="where the expected value comes from")
    source_it: str | None = Field(
        None, min_length=1, description="the source in Italian, as an Italian report prints it"
    )
    model: str | dict[str, Any] | None = None
    input: dict[str, Any] = Field(default_factory=dict)


class CaseFile(Table):
    """A case file: its cases."""

    cases: list[Case] = Field(min_length=1)


# --- the inputs of each kind --------------------------------------------------------------------


class ModelInput(Table):
    """``model``: which restrainer (1-based) the restrainer quantities read."""

    restrainer: int = Field(strict=True, default=1, ge=1)


class KinematicInput(Table):
    """``kinematic``: the edition (default: the model's) and the mechanism of the catalogue
    read (its name as `rock kinematic` prints it; default: the governing one)."""

    edition: Literal["2009", "2019"] | None = None
    mechanism: str | None = Field(
        None, min_length=1, description="a mechanism's name (default: the governing one)"
    )


class FreeRockingInput(Table):
    """``free-rocking``: released from rest at θ0 = φ0·α; the amplitude after n impacts. A
    wall's model names the mechanism rocked (default: its first; α of a vertical flexure is
    its instability rotation, where the weights' restoring moment vanishes)."""

    phi0: float = Field(strict=True, gt=0, lt=1, description="θ0/α [-]")
    impacts: int = Field(
        strict=True, default=1, ge=1, le=20, description="impacts before the amplitude"
    )
    dt: SampleInterval = 1e-3
    mechanism: str | None = Field(None, min_length=1, description="a wall's mechanism, by name")


class ImpulseInput(Table):
    """``impulse``: the initial velocity from θ = 0 that overturns, bisected in a bracket."""

    bracket: tuple[BracketEnd, BracketEnd] = Field(description="[lo, hi] of θ̇0 [rad/s]")


PulseKind = Literal["rectangular", "one-sine", "one-cosine", "half-sine"]


class PulseThresholdInput(Table):
    """``pulse-threshold``: the pulse amplitude that overturns, bisected in a bracket."""

    pulse: PulseKind
    period: Seconds = Field(description="the pulse's period Tp (rectangular: duration) [s]")
    dt: SampleInterval = 1e-3
    bracket: tuple[BracketEnd, BracketEnd] = Field(description="[lo, hi] of the amplitude [g]")


class SpectrumInput(Table):
    """``spectrum``: the NTC elastic spectrum at one period."""

    ag: Positive
    F0: Positive
    Tc_star: Positive
    soil: Literal["A", "B", "C", "D", "E"] = "A"
    topography: Literal["T1", "T2", "T3", "T4"] = "T1"
    period: float = Field(strict=True, ge=0, le=100, allow_inf_nan=False, description="T [s]")
    xi: Positive = Field(default=5.0, description="damping [%]")
    T1: Positive | None = Field(default=None, description="SeZ: the building's T1 [s]")
    gamma: Positive | None = Field(default=None, description="SeZ: the first mode's γ")
    psi: Positive | None = Field(default=None, description="SeZ: the first mode's ψ(z)")


class HazardInput(Table):
    """``hazard``: ag, F0, Tc* of the grid at a site and a return period."""

    lon: Finite
    lat: Finite
    TR: Positive


class RiskClassInput(Table):
    """``risk-class``: DM 58/2017 Allegato A's class of four return periods of the capacity
    [years] and an IS-V (a fraction); a class is checked as its rank, A+ = 0 … G = 7."""

    T_Rc_SLO: Positive = Field(description="[years]")
    T_Rc_SLD: Positive = Field(description="[years]")
    T_Rc_SLV: Positive = Field(description="[years]")
    T_Rc_SLC: Positive = Field(description="[years]")
    IS_V: Positive = 1.0


class DamageRateInput(Table):
    """``damage-rate``: the annual rate of a lognormal fragility on PGA at a site of the grid."""

    lon: Finite
    lat: Finite
    median: Positive = Field(description="θ [g]")
    beta: Positive = Field(description="β")
    soil: Literal["A", "B", "C", "D", "E"] = "A"
    topography: Literal["T1", "T2", "T3", "T4"] = "T1"


class ResponseSpectrumInput(Table):
    """``response-spectrum``: a linear oscillator under a generated pulse."""

    pulse: PulseKind
    amplitude: Positive = Field(description="[g]")
    period: Seconds = Field(description="the pulse's period (rectangular: duration) [s]")
    dt: SampleInterval = 1e-3
    oscillator_period: Seconds = Field(description="Tn [s]")
    damping: float = Field(strict=True, default=0.0, ge=0, lt=1, description="fraction of critical")


class FloorInput(Table):
    """``floor``: the floor motion of a resonant sine through the building's first mode."""

    T1: Seconds
    psi: Positive
    gamma: Positive
    xi: float = Field(strict=True, default=0.05, gt=0, lt=1)
    amplitude: Positive = Field(description="[g]")
    cycles: int = Field(strict=True, ge=10, le=200)
    samples_per_period: int = Field(strict=True, default=400, ge=20, le=4000)
    last_cycles: int = Field(
        strict=True, default=2, ge=1, le=10, description="cycles read for the peak"
    )


class SuiteInput(Table):
    """``suite``: resonant sines as a suite; their mean spectrum against the code's target."""

    period: Seconds = Field(description="the sines' period, the period checked [s]")
    amplitude: Positive = Field(description="[g]")
    cycles: int = Field(strict=True, ge=10, le=200)
    samples_per_period: int = Field(strict=True, default=400, ge=20, le=4000)
    scales: list[Positive] = Field(min_length=1, max_length=30)
    ag: Positive
    F0: Positive
    Tc_star: Positive
    soil: Literal["A", "B", "C", "D", "E"] = "A"


class UpliftRampInput(Table):
    """``uplift-ramp``: the first uplift under a ground acceleration growing linearly from 0."""

    slope: Positive = Field(le=10, description="d(üg)/dt [g/s]")
    duration: Seconds = Field(description="the ramp's length [s]")
    dt: SampleInterval = 1e-3
    direction: Literal[1, -1] = Field(default=1, description="the ramp's sign")
    mechanism: str | None = Field(None, min_length=1, description="a wall's mechanism, by name")


class UpliftSineInput(Table):
    """``uplift-sine``: the first uplift under a ground sine, from rest."""

    amplitude: Positive = Field(le=10, description="[g]")
    period: Seconds = Field(description="[s]")
    cycles: int = Field(strict=True, ge=1, le=200)
    samples_per_period: int = Field(strict=True, default=400, ge=20, le=4000)
    direction: Literal[1, -1] = Field(default=1, description="the sine's sign")


class ReleaseInput(Table):
    """``release``: free rocking from θ0 with θ̇0, no ground motion, up to the nth impact."""

    theta0: float = Field(
        strict=True, default=0.0, ge=-1.5, le=1.5, allow_inf_nan=False, description="[rad]"
    )
    omega0: float = Field(
        strict=True, ge=-100, le=100, allow_inf_nan=False, description="θ̇0 [rad/s]"
    )
    impacts: int = Field(
        strict=True, default=1, ge=1, le=20, description="the run ends at this impact"
    )
    restrainer: int = Field(strict=True, default=1, ge=1, description="1-based, for its quantities")


INPUTS: dict[Kind, type[Table]] = {
    Kind.MODEL: ModelInput,
    Kind.KINEMATIC: KinematicInput,
    Kind.FREE_ROCKING: FreeRockingInput,
    Kind.IMPULSE: ImpulseInput,
    Kind.PULSE_THRESHOLD: PulseThresholdInput,
    Kind.SPECTRUM: SpectrumInput,
    Kind.HAZARD: HazardInput,
    Kind.RESPONSE_SPECTRUM: ResponseSpectrumInput,
    Kind.FLOOR: FloorInput,
    Kind.SUITE: SuiteInput,
    Kind.UPLIFT_RAMP: UpliftRampInput,
    Kind.UPLIFT_SINE: UpliftSineInput,
    Kind.RELEASE: ReleaseInput,
    Kind.RISK_CLASS: RiskClassInput,
    Kind.DAMAGE_RATE: DamageRateInput,
}
