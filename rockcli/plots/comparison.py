"""The comparison: the capacity curve and the rocking time histories side by side."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.plots.capacity import draw_capacity
from rockcli.plots.files import new_figure, save
from rockcli.plots.histories import OVERTURN_ANGLE, draw_time_panels

if TYPE_CHECKING:
    from rockcli.dynamics.result import RockingRun
    from rockcli.records.record import Record


def plot_comparison(
    doc: Mapping[str, Any],
    runs: Sequence[RockingRun],
    path: str | Path,
    *,
    record: Record,
    overturn_angle: float = OVERTURN_ANGLE,
) -> None:
    """The code's capacity curve (left) and the rocking time histories (right).

    Args:
        doc: the `rock compare` JSON document.
        runs: both polarities, with their history.
        path: the file to write, .png or .svg.
        record: the record of the runs (acceleration [g]).
        overturn_angle: |θ| at which a run counts as overturned [rad].
    """
    fig = new_figure(path, (16.0, 7.5))
    outer = fig.add_gridspec(1, 2, width_ratios=(1.0, 1.25))
    draw_capacity(fig.add_subplot(outer[0]), doc["kinematic"])
    right = outer[1].subgridspec(2, 1, height_ratios=(3, 1))
    draw_time_panels(fig, [right[0], right[1]], doc["rocking"], runs, record, overturn_angle)
    name = doc["rocking"]["model"]["name"]
    fig.suptitle(f"rock compare — {name} under {record.name}: {doc['classification']}")
    save(fig, path)
