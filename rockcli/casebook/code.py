"""The model, kinematic and spectrum cases, on the paths `rock` itself takes.

Model quantities come from the derived block (``rockcli.model.derive.to_block``), the
kinematic ones from ``rockcli.analyses.kinematic.kinematic_model`` (what `rock kinematic`
runs), of the mechanism of its catalogue the case names, the spectra from
``rockcli.codecheck`` (NTC spectrum, hazard grid, response spectrum, floor motion) and the
suite's ratio from ``rockcli.suites.compat`` (what `rock suite check` runs).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from rockcli.casebook.schema import (
    DamageRateInput,
    FloorInput,
    HazardInput,
    KinematicInput,
    ModelInput,
    ResponseSpectrumInput,
    RiskClassInput,
    SpectrumInput,
    SuiteInput,
)
from rockcli.errors import InputError
from rockcli.mechanics import (
    Block,
    collapse_rotations,
    linear_global_stiffness,
    stiffness_coefficient,
)
from rockcli.mechanisms.side import ChainSide
from rockcli.model.derive import to_block
from rockcli.model.schema import Model
from rockcli.records.record import Record

if TYPE_CHECKING:
    from rockcli.analyses.catalogue import MechanismResult
    from rockcli.codecheck.result import KinematicResult
    from rockcli.codecheck.spectra import ElasticSpectrum

#: NTC 2018 §3.2.3.6 band of the suite case (the ratio itself is what is checked).
SUITE_BAND = (-0.10, 0.30)


def model_quantity(model: Model, inputs: ModelInput, quantity: str) -> float:
    """A quantity of the derived block; restrainer ones of the chosen restrainer."""
    block = to_block(model)
    simple = {"R": block.R, "alpha": block.alpha, "p": block.p, "e": block.e, "c_E": block.p2}
    if quantity in simple:
        return simple[quantity]
    if quantity in ("theta_c_pos", "theta_c_neg"):
        return collapse_rotations(block)[0 if quantity == "theta_c_pos" else 1]
    if inputs.restrainer > len(block.restrainers):
        raise InputError(
            "no such restrainer in the model",
            where="input.restrainer",
            value=inputs.restrainer,
            allowed=f"1 to {len(block.restrainers)}",
        )
    spring = block.restrainers[inputs.restrainer - 1]
    if quantity == "k_pos":
        return spring.k_pos
    if quantity == "c_K":
        return stiffness_coefficient(spring.k_pos, block.R, block.inertia)
    return positive_stiffness_ratio(block, inputs.restrainer - 1)


def positive_stiffness_ratio(block: Block, index: int) -> float:
    """4KR/(mg) at which the linearized global stiffness of side θ > 0 changes sign.

    The stiffness is linear in the restrainer's K (mechanics.linear_global_stiffness): its
    value at K = 0 and its slope give the root K*.
    """

    def stiffness_with(k: float) -> float:
        springs = list(block.restrainers)
        springs[index] = replace(springs[index], k_pos=k, k_neg=k)
        return linear_global_stiffness(replace(block, restrainers=tuple(springs)))

    at_zero = stiffness_with(0.0)
    slope = stiffness_with(1.0) - at_zero
    k_star = -at_zero / slope
    assert block.mass is not None
    return 4.0 * k_star * block.R / (block.mass * block.g)


def kinematic_quantity(model: Model, inputs: KinematicInput, quantity: str) -> float | None:
    """A quantity of `rock kinematic` on the model (its own demand), of the mechanism named
    (default: the governing one): its check's, or M* and the hinge's height of the catalogue
    (rockcli.analyses.catalogue.MechanismResult), or a flexure's instability displacement."""
    from rockcli.analyses.kinematic import kinematic_model

    entry = catalogue_entry(kinematic_model(model, edition=inputs.edition), inputs.mechanism)
    if quantity == "e_rocking":
        return rocking_restitution(model, entry.name)
    if quantity == "instability_displacement":
        return instability_displacement(model, inputs.edition, entry)
    result = entry.result
    direct = {
        "alpha0": result.alpha0,
        "e_star": result.e_star,
        "a0_star": result.a0_star,
        "d0_star": result.d0_star,
        "M_star": entry.M_star,
        "hinge_height": entry.hinge_height,
    }
    return direct[quantity] if quantity in direct else result.quantities.get(quantity)


def rocking_restitution(model: Model, name: str) -> float:
    """The coefficient of restitution the time history gives the mechanism named, side +1
    (rockcli.model.catalogue.Mechanism.rocker: Housner's about the new pivot, a chain's
    projection, or a one-sided mechanism's √(e₊·e₋))."""
    from rockcli.model.catalogue import named_mechanism

    return named_mechanism(model, name).rocker.restitution(1)


def catalogue_entry(result: KinematicResult, name: str | None) -> MechanismResult:
    """The mechanism of the catalogue named, the governing one (listed first) for None.

    As `rock kinematic --mechanism` (rockcli.terminal.kinematic.chosen_result); an unknown
    name is an InputError listing the catalogue.
    """
    from rockcli.analyses.catalogue import named

    if name is None:
        return result.catalogue[0]
    return named(
        result.catalogue, name, "input.mechanism", "no such mechanism in the model's catalogue"
    )


def instability_displacement(
    model: Model, edition: str | None, entry: MechanismResult
) -> float | None:
    """Horizontal displacement [m] of a vertical flexure's intermediate hinge where its
    capacity curve reaches zero (the instability displacement Δ_ins of Doherty, Griffith,
    Lam & Wilson 2002, EESD 31:833–850), on the side and at the hinge height checked.

    The mechanism is rebuilt as the catalogue builds it (rockcli.analyses.catalogue
    .mechanism_of); θ0 is rockcli.codecheck.kinematic.zero_rotation's, and the hinge's
    displacement away from the wall is its rest x less its x at θ0 (rockcli.mechanisms.links:
    the upper link's reference point is the hinge). None: the curve never reaches zero.
    """
    from rockcli.analyses.catalogue import mechanism_of
    from rockcli.analyses.kinematic import check_settings
    from rockcli.codecheck.kinematic import zero_rotation
    from rockcli.model.derive_wall import to_wall

    if entry.type != "vertical-flexure":
        raise InputError(
            "a quantity of a vertical flexure only",
            where="quantity",
            value=f"instability_displacement of '{entry.name}' ({entry.type})",
            allowed="input.mechanism naming a vertical-flexure mechanism",
        )
    wall = to_wall(model)
    spec = next(s for s in wall.mechanisms if s.name == entry.name)
    spec = replace(spec, hinge_height=entry.hinge_height)
    mech = mechanism_of(wall, spec, entry.result.side, check_settings(model, edition))
    theta0 = zero_rotation(mech)
    if theta0 is None:
        return None
    assert isinstance(mech.view, ChainSide)
    hinge = mech.view.states(theta0)[1]
    return hinge.px - hinge.cx


def spectrum_quantity(inputs: SpectrumInput, quantity: str) -> float:
    """A value of the NTC elastic spectrum (NTC §3.2.3.2)."""
    from rockcli.codecheck.spectra import ElasticSpectrum

    spectrum = ElasticSpectrum(
        ag=inputs.ag,
        F0=inputs.F0,
        Tc_star=inputs.Tc_star,
        soil=inputs.soil,  # type: ignore[arg-type]
        topography=inputs.topography,  # type: ignore[arg-type]
    )
    if quantity == "Se":
        return spectrum.Se(inputs.period, inputs.xi)
    if quantity == "SeZ":
        return floor_spectrum_quantity(spectrum, inputs)
    if quantity == "SDe":
        return spectrum.SDe(inputs.period, inputs.xi)
    return float(getattr(spectrum, quantity))


def floor_spectrum_quantity(spectrum: ElasticSpectrum, inputs: SpectrumInput) -> float:
    """S_eZ(T, ξ, z) [g]: the floor spectrum of the first mode, not below the ground's for
    T > T1 (Circolare 7/2019 §C7.2.3, Eq. C7.2.5), the building's damping 5 %."""
    from rockcli.codecheck.position import Position
    from rockcli.codecheck.rules2019 import bounded_floor_spectrum

    if inputs.T1 is None or inputs.gamma is None or inputs.psi is None:
        raise InputError(
            "SeZ needs the building's first mode",
            where="input",
            allowed="T1 [s], gamma and psi",
        )
    pos = Position(Z=1.0, T1=inputs.T1, gamma=inputs.gamma, psi=inputs.psi)
    return bounded_floor_spectrum(spectrum, inputs.period, pos, inputs.xi)


def hazard_quantity(inputs: HazardInput, quantity: str, grid_file: str) -> float:
    """ag [g], F0 or Tc* [s] of the grid at the site and return period (Allegato A)."""
    from rockcli.codecheck.hazard import read_grid, site_parameters

    values = site_parameters(read_grid(grid_file), inputs.lon, inputs.lat, inputs.TR)
    return float(getattr(values, quantity))


def risk_class_quantity(inputs: RiskClassInput, quantity: str) -> float:
    """PAM (a fraction), or a class's rank (A+ = 0 … G = 7), of DM 58/2017 Allegato A."""
    from rockcli.risk.classification import CLASSES, classify

    periods = {ls: getattr(inputs, f"T_Rc_{ls}") for ls in ("SLO", "SLD", "SLV", "SLC")}
    result = classify(periods, inputs.IS_V)
    if quantity == "PAM":
        return result.PAM
    name = {"PAM_class": result.pam_class, "IS_V_class": result.isv_class}
    return float(CLASSES.index(name.get(quantity, result.risk_class)))


def damage_rate_quantity(inputs: DamageRateInput, quantity: str, grid_file: str) -> float | None:
    """The annual rate [1/year] of a lognormal fragility on the site's surface PGA, or its
    return period [years] (rock risk --fragility)."""
    from rockcli.codecheck.hazard import read_grid
    from rockcli.risk.curve import curve_of, damage_rate, site_points

    points = site_points(read_grid(grid_file), inputs.lon, inputs.lat, inputs.soil,
                         inputs.topography)  # fmt: skip
    rate = damage_rate(curve_of(points), inputs.median, inputs.beta)
    if rate is None:  # beyond e^±700 a year
        return None
    return rate.rate if quantity == "annual_rate" else rate.return_period


def response_quantity(inputs: ResponseSpectrumInput, quantity: str) -> float:
    """Sa [g] or Sd [m] of a linear oscillator under a generated pulse."""
    from rockcli.codecheck.response import response_spectrum
    from rockcli.records.pulses import make_pulse

    rec = make_pulse(inputs.pulse, inputs.amplitude, inputs.period, dt=inputs.dt)
    Sa, Sd = response_spectrum(rec.time, rec.accel, [inputs.oscillator_period], inputs.damping)
    return float(Sa[0] if quantity == "Sa" else Sd[0])


def sine(amplitude: float, period: float, cycles: int, samples: int) -> tuple[np.ndarray, ...]:
    """amplitude·sin(2πt/period) [g] over whole cycles, ``samples`` per period."""
    dt = period / samples
    time = np.arange(0.0, cycles * period + dt / 2, dt)
    return time, amplitude * np.sin(2.0 * math.pi * time / period)


def floor_quantity(inputs: FloorInput) -> float:
    """The peak floor acceleration [g] over the last cycles of a sine at the building's T1."""
    from rockcli.codecheck.floor import floor_motion

    time, accel = sine(inputs.amplitude, inputs.T1, inputs.cycles, inputs.samples_per_period)
    floor = floor_motion(time, accel, T1=inputs.T1, psi=inputs.psi, gamma=inputs.gamma,
                         xi=inputs.xi)  # fmt: skip
    last = time >= (inputs.cycles - inputs.last_cycles) * inputs.T1
    return float(np.max(np.abs(floor[last])))


def suite_quantity(inputs: SuiteInput) -> float:
    """The suite's mean Sa over the code's Se at the sines' period (NTC §3.2.3.6)."""
    from rockcli.codecheck.spectra import ElasticSpectrum, Soil
    from rockcli.suites.compat import compatibility, record_spectra, target_spectrum

    time, accel = sine(inputs.amplitude, inputs.period, inputs.cycles, inputs.samples_per_period)
    dt = inputs.period / inputs.samples_per_period
    records = [
        Record(f"sine x{s:g}", "generated", "pulse", time, s * accel, dt) for s in inputs.scales
    ]
    periods = np.array([inputs.period])
    spectrum = ElasticSpectrum(ag=inputs.ag, F0=inputs.F0, Tc_star=inputs.Tc_star,
                               soil=Soil(inputs.soil))  # fmt: skip
    mean = record_spectra(records, periods).mean(axis=0)
    check = compatibility(periods, target_spectrum(spectrum, periods), mean, SUITE_BAND)
    return float(check.ratio[0])
