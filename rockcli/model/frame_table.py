"""The rocking frame of the model file: ``kind = "frame"`` and its ``[frame]`` table.

Equal piers capped by a rigid roof (a bell cell; Makris & Vassiliou 2013): validated here at
the edge like every other table. A frame's [geometry] is its pier's (2b = ``pier_width``, 2h
= ``pier_height``, out-of-plane ``pier_depth``): the model writes it from [frame], so that
every reader of the block's sizes reads the pier's; the rules that need the whole model (a
frame has its piers and roof only, the piers' unit weight) are :func:`check_frame`.
"""

from __future__ import annotations

from typing import Any

from pydantic import Field

from rockcli.model.bounds import MAX_LENGTH, MIN_LENGTH
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import number, rule_error

#: The most piers a frame has (a bell cell has four; a colonnade a few tens).
MAX_PIERS = 100
#: The heaviest roof accepted [kg]: 10⁶ kg (a bell cell's roof and bells weigh tens of
#: tonnes; above, a slip of units).
MAX_ROOF_MASS = 1e6
#: What a frame does not take (for now): the keys of a wall or of a restrained block.
NOT_FOR_A_FRAME = ("mechanisms", "restrainers", "loads", "thrusts", "return_walls", "masonry")


class FrameTable(Table):
    """A rocking frame: equal piers capped by a rigid roof resting on their tops."""

    piers: int = Field(
        ..., strict=True, ge=2, le=MAX_PIERS, description="How many equal piers (at least 2)"
    )
    pier_width: float = number(
        "A pier's width 2b in the plane of rocking [m]", ..., ge=MIN_LENGTH, le=MAX_LENGTH
    )
    pier_depth: float = number(
        "A pier's depth out of the plane of rocking (its weight) [m]",
        ...,
        ge=MIN_LENGTH,
        le=MAX_LENGTH,
    )
    pier_height: float = number(
        "A pier's height 2h from its base to the roof [m]", ..., ge=MIN_LENGTH, le=MAX_LENGTH
    )
    roof_mass: float = number(
        "The roof's mass with what it carries (bells) [kg]", ..., ge=0.0, le=MAX_ROOF_MASS
    )
    roof_height: float = number(
        "The roof's centroid above the piers' tops; the roof translates, so it does not "
        "enter the motion [m]",
        0.0,
        ge=0.0,
        le=MAX_LENGTH,
    )


def frame_geometry(data: Any) -> Any:
    """A frame file's raw data with its [geometry] written from [frame] (the pier's sizes;
    a value [frame] refuses is replaced by 1 m, so that only [frame] names it). A [geometry]
    given with kind = "frame" is refused."""
    if not isinstance(data, dict):
        return data
    if data.get("kind") != "frame":
        if "frame" in data and "geometry" not in data:
            raise rule_error("frame", "only with kind = 'frame'",
                             "kind = 'frame', or no [frame] table")  # fmt: skip
        return data
    if "geometry" in data:
        raise rule_error("geometry", "a frame's sizes are its piers'", "[frame] pier_width, "
                         "pier_height, pier_depth and no [geometry] table")  # fmt: skip
    table = data.get("frame")
    table = table if isinstance(table, dict) else {}

    def size(key: str) -> float:
        value = table.get(key)
        if not isinstance(value, int | float) or isinstance(value, bool):
            return 1.0
        return float(value) if MIN_LENGTH <= value <= MAX_LENGTH else 1.0

    geometry = {"thickness": size("pier_width"), "height": size("pier_height"),
                "width": size("pier_depth")}  # fmt: skip
    return {**data, "geometry": geometry}


def check_frame(model: Any) -> None:
    """A frame: its [frame] table, the piers' unit weight, and nothing a frame does not take;
    a [frame] table only with kind = "frame" (raises a rule error)."""
    frame = str(model.kind) == "frame"
    if not frame:
        if model.frame is not None:
            raise rule_error("frame", "only with kind = 'frame'", "kind = 'frame', or no "
                             "[frame] table")  # fmt: skip
        return
    if model.frame is None:
        raise rule_error("frame", "required with kind = 'frame'", "a [frame] table with "
                         "piers, pier_width, pier_depth, pier_height and roof_mass")  # fmt: skip
    if model.mass is None or model.mass.unit_weight is None:
        raise rule_error(("mass", "unit_weight"), "required for a frame (the piers' weight)",
                         "a number [kN/m³]")  # fmt: skip
    for key in NOT_FOR_A_FRAME:
        if getattr(model, key):
            raise rule_error(key, "not taken by a frame (its piers and roof only, for now)",
                             "no " + key + " with kind = 'frame'")  # fmt: skip
