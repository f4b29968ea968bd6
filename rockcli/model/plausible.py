"""Warnings on a valid model whose magnitudes look like a slip of units, not an element.

A thickness typed in millimetres (500 for 0.5 m) makes α = atan(250/2) = 1.563 rad, a block
that can hardly overturn: the file is valid, the verdict confident and wrong. These checks do
not refuse the file (a laboratory block or an unusual element may be meant); they name the
field, the value and the likely slip, for the reports to show next to the result.

Pure: the validated model only (no I/O, no printing).
"""

from __future__ import annotations

import math

from rockcli.model.derive import attachment, block_weight, steel_resistance, stiffness
from rockcli.model.schema import Model, Restrainer, RestrainerKind
from rockcli.notes import Items, Note

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
#: A restrainer's strength below this fraction of W·b/z (the force at its height whose moment
#: equals the block's own stabilising moment W·b) adds under 2 % to that moment, so it cannot
#: change a verdict; steel members on real blocks give 0.2 to 100 (docs/interpretations.md).
MIN_STRENGTH_FRACTION = 0.02
#: A stiffness whose c_K = K·r²/I0 is below this fraction of c_E = p² (paper §4.3) cannot
#: matter; the paper's own softest springs (K = 1e3 N/m, §4.4) reach 0.0077.
MIN_STIFFNESS_RATIO = 1e-3
#: Standard gravity [m/s²] and the relative difference tolerated (g varies by 0.5 % on
#: Earth; a laboratory may round it, to 10). A value farther off but within the schema's
#: bounds (9 to 10 m/s², rockcli.model.bounds) is a typo more likely than a place on Earth.
STANDARD_GRAVITY, GRAVITY_RTOL = 9.80665, 0.02


#: The sides a stiffness acts on, as a warning names them.
SIDE_WORDS = {
    "θ > 0": Note("side_pos", "θ > 0"),
    "θ < 0": Note("side_neg", "θ < 0"),
    "both sides": Note("side_both", "both sides"),
}


def model_warnings(model: Model) -> tuple[str, ...]:
    """Every warning of a model, in the order of the file (empty for a plausible model)."""
    return (
        *_geometry_warnings(model),
        *_mass_warnings(model),
        *_restrainer_warnings(model),
        *_gravity_warnings(model),
    )


def _geometry_warnings(model: Model) -> list[Note]:
    b, h = model.geometry.half_sizes
    R, alpha = model.geometry.polar
    found = []
    if 2 * b > MAX_THICKNESS:
        found.append(Note(
            "warn_thick", "geometry: thickness 2b = {t:g} m, thicker than any masonry wall "
            "(> {limit:g} m): a thickness in millimetres or centimetres?",
            t=2 * b, limit=MAX_THICKNESS,
        ))  # fmt: skip
    if 2 * h > MAX_HEIGHT:
        found.append(Note(
            "warn_tall", "geometry: height 2h = {h:g} m, taller than a plausible rocking block "
            "(> {limit:g} m): a height in millimetres or centimetres?",
            h=2 * h, limit=MAX_HEIGHT,
        ))  # fmt: skip
    if R > MAX_SEMI_DIAGONAL:
        found.append(Note(
            "warn_R", "geometry: semi-diagonal R = {R:g} m (> {limit:g} m): a length in "
            "millimetres or centimetres?", R=R, limit=MAX_SEMI_DIAGONAL,
        ))  # fmt: skip
    if alpha > SQUAT_ALPHA:
        found.append(Note(
            "warn_squat", "geometry: thickness 2b = {t:g} m exceeds height 2h = {h:g} m "
            "(α = {alpha:.4g} rad > π/4): thickness and height swapped, or one of them in "
            "other units?", t=2 * b, h=2 * h, alpha=alpha,
        ))  # fmt: skip
    return found


def _mass_warnings(model: Model) -> list[Note]:
    mass, width = model.mass, model.geometry.width
    if mass is None:
        return []
    if mass.unit_weight is not None:
        gamma = mass.unit_weight
        source = Note("unit_weight_given", "mass.unit_weight = {gamma:g} kN/m³",
                      gamma=float(gamma))  # fmt: skip
    elif mass.weight is not None and width is not None:
        b, h = model.geometry.half_sizes
        gamma = mass.weight / (2 * b * 2 * h * width)
        source = Note(
            "unit_weight_derived", "mass.weight = {weight:g} kN over the volume 2b·2h·width = "
            "{volume:.4g} m³ gives {gamma:.4g} kN/m³", weight=float(mass.weight),
            volume=2 * b * 2 * h * width, gamma=gamma,
        )  # fmt: skip
    else:
        return []
    if MIN_UNIT_WEIGHT <= gamma <= MAX_UNIT_WEIGHT:
        return []
    return [Note(
        "warn_unit_weight", "{source}, outside masonry's {lo:g}–{hi:g} kN/m³: a weight in kg or "
        "tonnes, a unit weight in kg/m³, or a wrong width?", source=source,
        lo=float(MIN_UNIT_WEIGHT), hi=float(MAX_UNIT_WEIGHT),
    )]  # fmt: skip


def _restrainer_warnings(model: Model) -> list[Note]:
    found: list[Note] = [
        Note(
            "warn_diameter",
            "restrainers[{i}].diameter = {d:g} m, thicker than a tie-rod "
            "(> {limit:g} m): a diameter in millimetres?",
            i=i,
            d=float(r.diameter),
            limit=MAX_TIE_ROD_DIAMETER,
        )  # fmt: skip
        for i, r in enumerate(model.restrainers)
        if r.kind is RestrainerKind.TIE_ROD
        and r.diameter is not None
        and r.diameter > MAX_TIE_ROD_DIAMETER
    ]
    weight = block_weight(model)
    if weight is None:
        return found
    for i, table in enumerate(model.restrainers):
        found += _weak_strengths(model, i, table, weight)
        found += _soft_stiffnesses(model, i, table, weight)
    return found


def _strengths(model: Model, table: Restrainer) -> list[tuple[str, float]]:
    """(field, force [N]) of every strength the restrainer's table gives or implies."""
    given = [
        (key, value)
        for key in ("yield_pos", "yield_neg", "anchor_capacity")
        if (value := getattr(table, key)) is not None
    ]
    steel = steel_resistance(model, table)
    if steel is not None:
        given.append(("its design yield force N_pl,Rd", steel[0].plastic))
    return given


def _weak_strengths(model: Model, i: int, table: Restrainer, weight: float) -> list[Note]:
    """A warning when a strength is below MIN_STRENGTH_FRACTION · W·b/z (all such named).

    W·b is the block's stabilising moment about either pivot at rest (paper Eq. 1: the weight
    at the half-thickness b); a horizontal force F at height z adds F·z to it, so F·z/(W·b) is
    the relative rise of the uplift acceleration, and of the code's α0, that the restrainer can
    give (Circ. 7/2019 §C8.7.1.2: α0 from the balance of moments at the onset).
    """
    b = model.geometry.half_sizes[0]
    (r, phi), _ = attachment(model, table)
    z = r * math.cos(phi)
    if z <= 0.0:
        return []
    reference = weight * b / z
    weak = [
        Note("strength_value", "{key} = {force:.4g} N", key=key, force=float(force))
        for key, force in _strengths(model, table)
        if force < MIN_STRENGTH_FRACTION * reference
    ]
    if not weak:
        return []
    return [Note(
        "warn_weak", "restrainers[{i}]: {weak}, below {share:.0%} of W·b/z = {reference:.4g} N "
        "(the force at its height z = {z:.3g} m whose moment equals the block's W·b, W = "
        "{W:.4g} kN, b = {b:.3g} m): too weak to change the verdict; a force in kN where N is "
        "asked (1000 times too small)?", i=i, weak=Items(weak), share=MIN_STRENGTH_FRACTION,
        reference=reference, z=z, W=weight / 1e3, b=b,
    )]  # fmt: skip


def _soft_stiffnesses(model: Model, i: int, table: Restrainer, weight: float) -> list[Note]:
    """A warning when a side's c_K/c_E = K·r²/(W·R) is below MIN_STIFFNESS_RATIO.

    c_K = K·r²/I0 and c_E = p² = m·g·R/I0 (paper §4.3; r = 2R at the top corner gives the
    paper's 4KR²/I0), so c_K/c_E = K·r²/(W·R): a restrainer matters when it is 10 to 100.
    A side without stiffness (K = 0: no spring there) is not a slip.
    """
    R = model.geometry.polar[0]
    sides = {
        side: (k, k * r * r / (weight * R))
        for side, k, (r, _) in zip(
            ("θ > 0", "θ < 0"), stiffness(table), attachment(model, table), strict=True
        )
    }
    soft = {side: kr for side, kr in sides.items() if kr[0] > 0.0 and kr[1] < MIN_STIFFNESS_RATIO}
    if len(soft) == 2 and len(set(soft.values())) == 1:
        soft = {"both sides": next(iter(soft.values()))}
    return [
        Note(
            "warn_soft",
            "restrainers[{i}]: stiffness K = {k:.4g} N/m ({side}) gives c_K/c_E "
            "= K·r²/(W·R) = {ratio:.3g}, below {limit:g} (paper §4.3: a restrainer matters at "
            "10 to 100): a stiffness in kN/m or N/mm where N/m is asked (1000 times too "
            "small)?",
            i=i,
            k=float(k),
            side=SIDE_WORDS[side],
            ratio=float(ratio),
            limit=float(MIN_STIFFNESS_RATIO),
        )  # fmt: skip
        for side, (k, ratio) in soft.items()
    ]


def _gravity_warnings(model: Model) -> list[Note]:
    g = model.analysis.g
    if math.isclose(g, STANDARD_GRAVITY, rel_tol=GRAVITY_RTOL):
        return []
    return [Note(
        "warn_gravity", "analysis.g = {g:g} m/s², more than {share:.0%} from the Earth's "
        "standard {standard:g} m/s² (its surface gravity is 9.76 to 9.83 m/s²): a typo?",
        g=float(g), share=GRAVITY_RTOL, standard=STANDARD_GRAVITY,
    )]  # fmt: skip
