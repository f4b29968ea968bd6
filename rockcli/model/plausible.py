"""Warnings on a valid model whose magnitudes look like a slip of units, not an element.

A thickness typed in millimetres (500 for 0.5 m) makes α = atan(250/2) = 1.563 rad, a block
that can hardly overturn: the file is valid, the verdict confident and wrong. These checks do
not refuse the file (a laboratory block or an unusual element may be meant); they name the
field, the value and the likely slip, for the reports to show next to the result.

Pure: the validated model only (no I/O, no printing).
"""

from __future__ import annotations

import math

from rockcli.model.schema import Model, RestrainerKind

#: Thickest plausible masonry element [m] (the thickest walls of fortresses are ~ 5 m).
MAX_THICKNESS = 5.0
#: Tallest plausible rocking block [m] (a whole bell tower rocking on one crack is ~ 50 m).
MAX_HEIGHT = 50.0
#: Largest plausible semi-diagonal R [m] (issue 7: "R > 100 m" is a slip).
MAX_SEMI_DIAGONAL = 100.0
#: Slenderness above which the block is squatter than a cube: thickness > height.
SQUAT_ALPHA = math.pi / 4
#: Range of masonry unit weights [kN/m³] (Circolare 7/2019 Tab. C8.5.I: 12 to 22 kN/m³;
#: widened to 10–30 for stone and filled walls).
MIN_UNIT_WEIGHT, MAX_UNIT_WEIGHT = 10.0, 30.0
#: Thickest plausible tie-rod [m] (bars of 16–40 mm; 0.1 m is a slip of mm for m).
MAX_TIE_ROD_DIAMETER = 0.1
#: Standard gravity [m/s²] and the relative difference tolerated (g varies by 0.5 % on
#: Earth; a laboratory may round it).
STANDARD_GRAVITY, GRAVITY_RTOL = 9.80665, 0.02


def model_warnings(model: Model) -> tuple[str, ...]:
    """Every warning of a model, in the order of the file (empty for a plausible model)."""
    return (
        *_geometry_warnings(model),
        *_mass_warnings(model),
        *_restrainer_warnings(model),
        *_gravity_warnings(model),
    )


def _geometry_warnings(model: Model) -> list[str]:
    b, h = model.geometry.half_sizes
    R, alpha = model.geometry.polar
    found = []
    if 2 * b > MAX_THICKNESS:
        found.append(
            f"geometry: thickness 2b = {2 * b:g} m, thicker than any masonry wall "
            f"(> {MAX_THICKNESS:g} m): a thickness in millimetres or centimetres?"
        )
    if 2 * h > MAX_HEIGHT:
        found.append(
            f"geometry: height 2h = {2 * h:g} m, taller than a plausible rocking block "
            f"(> {MAX_HEIGHT:g} m): a height in millimetres or centimetres?"
        )
    if R > MAX_SEMI_DIAGONAL:
        found.append(
            f"geometry: semi-diagonal R = {R:g} m (> {MAX_SEMI_DIAGONAL:g} m): "
            "a length in millimetres or centimetres?"
        )
    if alpha > SQUAT_ALPHA:
        found.append(
            f"geometry: thickness 2b = {2 * b:g} m exceeds height 2h = {2 * h:g} m "
            f"(α = {alpha:.4g} rad > π/4): thickness and height swapped, or one of them "
            "in other units?"
        )
    return found


def _mass_warnings(model: Model) -> list[str]:
    mass, width = model.mass, model.geometry.width
    if mass is None:
        return []
    if mass.unit_weight is not None:
        gamma, source = mass.unit_weight, f"mass.unit_weight = {mass.unit_weight:g} kN/m³"
    elif mass.weight is not None and width is not None:
        b, h = model.geometry.half_sizes
        gamma = mass.weight / (2 * b * 2 * h * width)
        source = (
            f"mass.weight = {mass.weight:g} kN over the volume 2b·2h·width = "
            f"{2 * b * 2 * h * width:.4g} m³ gives {gamma:.4g} kN/m³"
        )
    else:
        return []
    if MIN_UNIT_WEIGHT <= gamma <= MAX_UNIT_WEIGHT:
        return []
    return [
        f"{source}, outside masonry's {MIN_UNIT_WEIGHT:g}–{MAX_UNIT_WEIGHT:g} kN/m³: "
        "a weight in kg or tonnes, a unit weight in kg/m³, or a wrong width?"
    ]


def _restrainer_warnings(model: Model) -> list[str]:
    return [
        f"restrainers[{i}].diameter = {r.diameter:g} m, thicker than a tie-rod "
        f"(> {MAX_TIE_ROD_DIAMETER:g} m): a diameter in millimetres?"
        for i, r in enumerate(model.restrainers)
        if r.kind is RestrainerKind.TIE_ROD
        and r.diameter is not None
        and r.diameter > MAX_TIE_ROD_DIAMETER
    ]


def _gravity_warnings(model: Model) -> list[str]:
    g = model.analysis.g
    if math.isclose(g, STANDARD_GRAVITY, rel_tol=GRAVITY_RTOL):
        return []
    return [
        f"analysis.g = {g:g} m/s², not the Earth's {STANDARD_GRAVITY:g} m/s²: "
        "g in cm/s², in g, or in ft/s²?"
    ]
