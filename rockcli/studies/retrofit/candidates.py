"""The candidate tie-rods of a retrofit: which rod, which diameters, each as a validated model.

Every candidate is the model file's table with the rod's diameter (and grade, count) set, then
validated by :func:`rockcli.model.load.validate_model` like any model file: its stiffness,
strength and yield forces come from the one derivation (rockcli.model.derive), never from a
formula of its own here.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rockcli.errors import InputError
from rockcli.model.schema import Model
from rockcli.numbers import ascii_float

#: Diameters tried by default [mm]: the nominal sizes of tie-rod bars and threaded rods, ISO 261
#: first and second choice from M10 to M36, and the 40 mm bar.
DEFAULT_DIAMETERS_MM = (10, 12, 14, 16, 18, 20, 22, 24, 27, 30, 33, 36, 40)
#: Grade of the rod when neither --grade nor the model's tie-rod gives one.
DEFAULT_GRADE = "S275"
#: The steel grades a rod can have (NTC 2018 Tab. 11.3.IX; rockcli.model.schema.SteelGrade).
GRADE_NAMES = ("S235", "S275", "S355")
#: Millimetres per metre (the CLI speaks mm, the model file m).
MM_PER_M = 1000.0
#: Name of a rod placed with --at.
PLACED_NAME = "retrofit tie-rod"
TIE_ROD = "tie-rod"
DIAMETERS_ALLOWED = "diameters in mm separated by commas, each > 0, e.g. 16,20,24"
#: The most diameters one `rock retrofit` tries (each is a code check and two time histories,
#: about 10 ms on a 40 s record: a thousand is ten seconds; a list of ten thousand is a slip).
MAX_DIAMETERS = 1000
AT_ALLOWED = "HEIGHT,FROM_PIVOT in m, e.g. 5.0,0.3"


@dataclass(frozen=True)
class Placement:
    """A new rod's point and free length [m] (``--at HEIGHT,FROM_PIVOT --length L``)."""

    height: float
    from_pivot: float
    length: float


@dataclass(frozen=True)
class RetrofitPlan:
    """What to try: the model file's table, the rod (its index in every candidate's
    restrainers), its steel and number of bars, and the diameters [mm], ascending.

    Attributes:
        base: the model file's table (as read). file: its path, for errors.
        placement: a new rod's point and length (None: the model's tie-rod).
        index: the rod's position in the candidate's restrainers.
        name: the rod's name. grade, count: its steel and bars.
        diameters_mm: the diameters to try [mm], ascending.
    """

    base: Mapping[str, Any]
    file: str | None
    placement: Placement | None
    index: int
    name: str
    grade: str
    count: int
    diameters_mm: tuple[float, ...]


def parse_diameters(text: str | None) -> tuple[float, ...]:
    """``--diameters 16,20,24`` → (16.0, 20.0, 24.0) [mm], ascending and each once; None: the
    default list. InputError for an empty list, more than :data:`MAX_DIAMETERS` items, a word,
    or a size ≤ 0."""
    if text is None:
        return tuple(float(d) for d in DEFAULT_DIAMETERS_MM)
    parts = [p.strip() for p in text.split(",")]
    if not any(parts):
        raise InputError(
            "no diameter given", where="--diameters", value=text, allowed=DIAMETERS_ALLOWED
        )
    if len(parts) > MAX_DIAMETERS:
        raise InputError(
            f"too many diameters: {len(parts)}",  # the list itself would fill the screen
            where="--diameters",
            allowed=f"at most {MAX_DIAMETERS} diameters",
        )
    values = [_positive_number(p, text) for p in parts]
    return tuple(sorted(set(values)))


def _positive_number(part: str, text: str) -> float:
    try:
        value = ascii_float(part)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        problem = "not a diameter" if part else "an empty item"
        raise InputError(
            f"{problem}: {part!r}", where="--diameters", value=text, allowed=DIAMETERS_ALLOWED
        )
    return value


def parse_at(text: str) -> tuple[float, float]:
    """``--at 5.0,0.3`` → (height, from_pivot) [m]; InputError unless two finite numbers."""
    parts = text.split(",")
    try:
        height, from_pivot = (ascii_float(p) for p in parts)
    except ValueError:
        raise InputError("not two numbers", where="--at", value=text, allowed=AT_ALLOWED) from None
    if not (math.isfinite(height) and math.isfinite(from_pivot)):
        raise InputError("not two finite numbers", where="--at", value=text, allowed=AT_ALLOWED)
    return height, from_pivot


def check_placement(model: Model, height: float, from_pivot: float, file: str | None) -> None:
    """The point of a new rod within the model's storeys (a block file's block: one storey of
    2b × 2h): 0 < height ≤ their height, 0 ≤ from_pivot ≤ the thickness of the storey at that
    height (InputError)."""
    from rockcli.model.wall_tables import thickness_at

    storeys = model.geometry.storey_list
    top = sum(s.height for s in storeys)
    b = 0.5 * thickness_at(storeys, min(max(height, 0.0), top))
    h = 0.5 * top
    value = f"{height:g},{from_pivot:g}"
    if not 0.0 < height <= 2.0 * h:
        raise InputError(
            "height outside the block",
            file=file,
            where="--at",
            value=value,
            allowed=f"a height > 0 and <= the block's height 2h = {2.0 * h:.4g} m",
        )
    if not 0.0 <= from_pivot <= 2.0 * b:
        raise InputError(
            "from_pivot outside the block",
            file=file,
            where="--at",
            value=value,
            allowed=f"a distance >= 0 and <= the block's thickness 2b = {2.0 * b:.4g} m",
        )


def tie_rods(model: Model) -> list[int]:
    """The indices of the model's ``kind = "tie-rod"`` restrainers."""
    return [i for i, r in enumerate(model.restrainers) if r.kind.value == TIE_ROD]


def restrainer_name(model: Model, index: int) -> str:
    """A restrainer's name as reports show it (its own, or ``restrainer N``)."""
    return model.restrainers[index].name or f"restrainer {index + 1}"


def find_tie_rod(model: Model, name: str | None, file: str | None) -> int:
    """The index of the rod to size: the one tie-rod, or the one ``--name`` names."""
    rods = tie_rods(model)
    names = [restrainer_name(model, i) for i in rods]
    listed = ", ".join(repr(n) for n in names)
    if name is not None:
        if name not in names:
            raise InputError(
                "no tie-rod of that name",
                file=file,
                where="--name",
                value=name,
                allowed=f"one of {listed}" if names else 'a model with a kind = "tie-rod"',
            )
        return rods[names.index(name)]
    if not rods:
        raise InputError(
            'no kind = "tie-rod" restrainer to size',
            file=file,
            where="restrainers",
            allowed='a [[restrainers]] table with kind = "tie-rod", or --at HEIGHT,FROM_PIVOT '
            "--length L to place a new one",
        )
    if len(rods) > 1:
        raise InputError(
            "several tie-rods",
            file=file,
            where="--name",
            allowed=f"--name with one of {listed}",
        )
    return rods[0]


def steel_of(
    model: Model, index: int | None, grade: str | None, count: int | None
) -> tuple[str, int]:
    """(grade, bars): as given, else the model's tie-rod's, else S275 and one bar."""
    rod = model.restrainers[index] if index is not None else None
    if grade is None:
        grade = rod.grade.value if rod is not None and rod.grade is not None else DEFAULT_GRADE
    grade = grade.upper()
    if grade not in GRADE_NAMES:
        raise InputError(
            "unknown steel grade", where="--grade", value=grade, allowed=", ".join(GRADE_NAMES)
        )
    if count is None:
        count = rod.count if rod is not None and rod.count is not None else 1
    return grade, count


def make_plan(
    base: Mapping[str, Any],
    model: Model,
    *,
    file: str | None = None,
    diameters_mm: Sequence[float],
    name: str | None = None,
    placement: Placement | None = None,
    grade: str | None = None,
    count: int | None = None,
) -> RetrofitPlan:
    """The plan of a retrofit of a validated model (``base``: its table as read).

    The rod: a new one at ``placement`` (added to the restrainers), else the model's tie-rod
    (``name`` picks one of several). InputError for a rod that cannot be found or placed. A
    wall's candidates are each checked and rocked for their governing mechanism
    (rockcli.studies.retrofit.run).
    """
    if placement is not None:
        if name is not None:
            raise InputError(
                "not with --at (--at adds a new rod)",
                where="--name",
                value=name,
                allowed="--name to size a tie-rod of the model, or --at for a new one",
            )
        check_placement(model, placement.height, placement.from_pivot, file)
        index, rod_name, own = len(model.restrainers), PLACED_NAME, None
    else:
        index = own = find_tie_rod(model, name, file)
        rod_name = restrainer_name(model, index)
    steel, bars = steel_of(model, own, grade, count)
    plan = RetrofitPlan(base, file, placement, index, rod_name, steel, bars, tuple(diameters_mm))
    for d in plan.diameters_mm:  # every candidate valid before any run
        build_candidate(plan, d)
    return plan


def candidate_table(plan: RetrofitPlan, diameter_mm: float) -> dict[str, Any]:
    """The model table of one candidate: the base with the rod of this diameter."""
    table = copy.deepcopy(dict(plan.base))
    rods = list(table.get("restrainers", []))
    rod = {"name": PLACED_NAME, "kind": TIE_ROD} if plan.placement is not None else rods[plan.index]
    rod = {k: v for k, v in rod.items() if k not in ("fy", "fu")}
    rod.update(diameter=diameter_mm / MM_PER_M, grade=plan.grade, count=plan.count)
    if plan.placement is not None:
        p = plan.placement
        rod.update(length=p.length, height=p.height, from_pivot=p.from_pivot)
        rods.append(rod)
    else:
        rods[plan.index] = rod
    table["restrainers"] = rods
    return table


def build_candidate(plan: RetrofitPlan, diameter_mm: float) -> Model:
    """The validated model of one candidate; InputError naming the diameter otherwise."""
    from rockcli.model.load import validate_model

    try:
        return validate_model(candidate_table(plan, diameter_mm))
    except InputError as exc:
        lines = getattr(exc, "lines", None) or (exc.render(),)
        raise InputError(
            f"the rod of {diameter_mm:g} mm makes the model invalid: {lines[0]}",
            file=plan.file,
            where="--diameters",
        ) from None
