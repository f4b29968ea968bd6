"""The wall's physical surroundings: loads, thrusts and the building it stands in.

`[[loads]]`, `[[thrusts]]` and `[building]` describe the element, not a code's settings, so
both analyses read them: the rocking time history and the NTC kinematic check. The loads are
the Circolare's weights (Circolare 617/2009 §C8A.4.1, Circolare 7/2019 §C8.7.1.1): P_i bear on
the block and move with it, P_j only push it (their mass follows the block, their weight rests
elsewhere). Validated here at the edge like every other table; the rules that need the block's
size (a point within it, a mass when there are loads) are :func:`check_points` and
:func:`check_mass`, called by the model.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from enum import StrEnum
from typing import Any

from pydantic import Field, model_validator

from rockcli.model.bounds import (
    MAX_LENGTH,
    MAX_MODE_SHAPE,
    MAX_PARTICIPATION,
    MAX_PERIOD,
    MAX_REACH,
    MAX_STOREYS,
    MAX_WEIGHT,
    MIN_LENGTH,
    MIN_MODAL,
    MIN_PERIOD,
    MIN_WEIGHT,
)
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import choose_group, number, rule_error

#: First-mode damping of the building, as a fraction of critical (NTC §3.2.3.2.1: the elastic
#: spectra are given for 5 %).
DEFAULT_DAMPING = 0.05
#: Largest damping fraction accepted: beyond half of critical a building does not oscillate
#: in any sense the code's spectra describe.
MAX_DAMPING = 0.5

#: The two ways of placing a load or a thrust.
POINT_ALLOWED = 'height [m] (optional from_pivot [m]), or position = "top"'


class Position(StrEnum):
    """Named points of the block."""

    TOP = "top"


class Direction(StrEnum):
    """The sense of rotation a thrust pushes the block towards."""

    POSITIVE = "positive"
    NEGATIVE = "negative"


def height_field() -> float | None:
    """The height of a point above the base of the block (or ``position``)."""
    return number(
        'Height of the point above the base of the block (or position = "top") [m]',
        ge=0,
        le=MAX_REACH,
    )


def from_pivot_field() -> float | None:
    """The horizontal distance of a point from the pivot of positive rotation."""
    return number(
        "Horizontal distance of the point from the pivot of positive rotation, at most the "
        "thickness; from the other pivot it is 2b − x; default: the mid-plane b [m]",
        ge=0,
        le=MAX_REACH,
    )


def position_field() -> Position | None:
    """A named point instead of a height."""
    return Field(None, description="'top': the top of the block, height 2h (instead of height)")


def check_one_height(values: Mapping[str, Any]) -> None:
    """Exactly one of height and position (a load's or a thrust's point)."""
    if choose_group(values, [("height",), ("position",)], POINT_ALLOWED) is None:
        raise rule_error(None, "missing the point of application", POINT_ALLOWED)


class Load(Table):
    """A weight on the block (floor, roof): the Circolare's P_i (bears and moves) or P_j.

    Circolare 617/2009 §C8A.4.1 and Circolare 7/2019 §C8.7.1.1: a weight P_i bears on the block
    (it restores and overturns) and its mass moves with it; a weight P_j does not bear on it
    (a floor resting on another wall, tied to this one) but its mass pushes it.
    """

    name: str | None = Field(None, min_length=1, description="Label; default 'load N'")
    weight: float = number("Weight [kN]", ..., ge=MIN_WEIGHT, le=MAX_WEIGHT)
    height: float | None = height_field()
    position: Position | None = position_field()
    from_pivot: float | None = from_pivot_field()
    bears: bool = Field(
        True,
        strict=True,
        description="true (default): its weight rests on the block; false: it rests elsewhere",
    )
    moves: bool = Field(
        True,
        strict=True,
        description="true (default): its mass follows the block horizontally and pushes it",
    )

    @model_validator(mode="after")
    def _placed_and_acting(self) -> Load:
        """One point; a load that neither bears nor moves has no effect: a slip, not a model."""
        check_one_height(self.__dict__)
        if not self.bears and not self.moves:
            raise rule_error(
                "moves",
                "a load that neither bears on the block nor moves with it does nothing",
                "bears = true, moves = true, or both (remove the load otherwise)",
                self.moves,
            )
        return self


class Thrust(Table):
    """A horizontal force independent of the earthquake (the thrust of a roof or an arch)."""

    name: str | None = Field(None, min_length=1, description="Label; default 'thrust N'")
    force: float = number("Horizontal force [kN]", ..., ge=MIN_WEIGHT, le=MAX_WEIGHT)
    direction: Direction = Field(
        ..., description="'positive' or 'negative': the sense of rotation it pushes towards"
    )
    height: float | None = height_field()
    position: Position | None = position_field()
    from_pivot: float | None = from_pivot_field()

    @model_validator(mode="after")
    def _placed(self) -> Thrust:
        """One point."""
        check_one_height(self.__dict__)
        return self


#: The base's friction coefficient: above 0, at most 1.5 (masonry on masonry or stone is
#: about 0.4–0.8; above 1.5 nothing slides).
MAX_BASE_FRICTION = 1.5


class Base(Table):
    """What the element stands on: the friction of its base joint, for whether it slides
    before it rocks."""

    mu: float = number(
        "Friction coefficient of the base joint: the element slides first where μ·g is below "
        "the acceleration that lifts it [-]",
        ...,
        gt=0.0,
        le=MAX_BASE_FRICTION,
    )


class Building(Table):
    """Where the element stands in the building: a property of the element, not of a code."""

    Z: float = number(
        "Height of the base of the mechanism above the foundation; 0 on the ground [m]",
        0.0,
        ge=0,
        le=MAX_LENGTH,
    )
    H: float | None = number(
        "Height of the building above the foundation, with Z > 0 [m]",
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    N: int | None = Field(
        None,
        strict=True,
        ge=1,
        le=MAX_STOREYS,
        description="Number of storeys, with Z > 0 (for γ = 3N/(2N+1))",
    )
    T1: float | None = number(
        "First period of the building, with Z > 0; default C1·H^0.75 with C1 = 0.05 "
        "(NTC §7.3.3.2) [s]",
        ge=MIN_PERIOD,
        le=MAX_PERIOD,
    )
    gamma: float | None = number(
        "Modal participation factor γ; default 3N/(2N+1) [-]",
        ge=MIN_MODAL,
        le=MAX_PARTICIPATION,
    )
    psi: float | None = number(
        "First mode shape ψ(Z), 1 at the top; default Z/H [-]", ge=MIN_MODAL, le=MAX_MODE_SHAPE
    )
    damping: float = number(
        "First-mode damping of the building, fraction of critical, > 0 (the 2019 floor "
        "spectrum divides by its root) and at most 0.5; default 0.05 [-]",
        DEFAULT_DAMPING,
        gt=0,
        le=MAX_DAMPING,
    )

    @model_validator(mode="after")
    def _complete(self) -> Building:
        """The position in the building complete when Z > 0."""
        if self.Z > 0:
            self._check_height()
        return self

    def _check_height(self) -> None:
        if self.Z < MIN_LENGTH:
            raise rule_error(
                "Z",
                "too small to be a height above the foundation",
                f"0 on the ground, or a height >= {MIN_LENGTH:g} and <= H [m]",
                self.Z,
            )
        if self.H is None:
            raise rule_error(
                "H",
                "required when Z > 0 (element at height)",
                f"a number >= {MIN_LENGTH:g} and <= {MAX_LENGTH:g} [m]",
            )
        if self.Z > self.H:
            raise rule_error(
                "Z", f"above the building height H = {self.H:g} m", "0 <= Z <= H [m]", self.Z
            )
        if self.N is None and self.gamma is None:
            raise rule_error(
                "N", "required when Z > 0 (for γ = 3N/(2N+1)), or give gamma", "an integer >= 1"
            )


def check_points(
    tables: dict[str, Sequence[Load | Thrust]], thickness: float, height: float, rtol: float
) -> None:
    """Every load's and thrust's point within the block (thickness 2b, height 2h) [m].

    ``rtol`` is the relative slack for dimensions rounded in the file.
    """
    for key, points in tables.items():
        for i, point in enumerate(points):
            if point.from_pivot is not None and point.from_pivot > thickness * (1 + rtol):
                raise rule_error(
                    (key, i, "from_pivot"),
                    "outside the block",
                    f"a number >= 0 and <= the thickness 2b = {thickness:.4g} [m]",
                    point.from_pivot,
                )
            if point.height is not None and point.height > height * (1 + rtol):
                raise rule_error(
                    (key, i, "height"),
                    "outside the block",
                    f"a number >= 0 and <= the height 2h = {height:.4g} [m]",
                    point.height,
                )


def check_mass(tables: dict[str, Sequence[Load | Thrust]], has_mass: bool) -> None:
    """A [mass] table when there are loads or thrusts: their effect is relative to W."""
    if has_mass:
        return
    for key, points in tables.items():
        if points:
            raise rule_error(
                "mass",
                f"required because of [[{key}]] (their effect is relative to the block's weight)",
                "a [mass] table with weight [kN] or unit_weight [kN/m³]",
            )
