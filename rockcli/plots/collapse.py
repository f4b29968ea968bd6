"""The collapse map of a systemic study: code against rocking per record over R × α
(paper §3.3, §4.4; Fig. 8, 15–17)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.plots.files import new_figure, save

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

#: Outcome of a case → (legend label, marker, colour, filled), paper §3.3 and Fig. 8, 17.
OUTCOMES = {
    "both": ("both collapse", "s", "tab:red", True),
    "code": ("code only (code conservative)", "^", "tab:orange", True),
    "rocking": ("rocking only (code unconservative)", "v", "tab:purple", True),
    "neither": ("neither collapses", "o", "tab:green", False),
    "undetermined": ("a verdict is missing", "x", "0.4", True),
    "error": ("the case failed (cases.csv: error)", "X", "black", True),
}
#: Where each outcome sits in a cell holding several cases (offsets in cell units).
SLOTS = {
    "both": (-0.22, 0.2),
    "code": (0.18, 0.2),
    "rocking": (-0.22, -0.2),
    "neither": (0.18, -0.2),
    "undetermined": (0.0, 0.0),
    "error": (0.0, 0.0),
}
SWEEP_KEYS = ("R", "alpha", "record", "code_collapse", "rocking_collapse")
#: Panel size [in] and panels per figure row when there is no `by` column.
PANEL_SIZE = (3.6, 3.0)
PANEL_COLUMNS = 3


def outcome(row: Mapping[str, Any]) -> str:
    """The outcome of one case: both, code, rocking, neither, undetermined or error."""
    if row.get("error"):
        return "error"
    code, rocking = row["code_collapse"], row["rocking_collapse"]
    if code is None or rocking is None:
        return "undetermined"
    if code and rocking:
        return "both"
    return "code" if code else ("rocking" if rocking else "neither")


def _check_rows(rows: Iterable[Mapping[str, Any]]) -> list[Mapping[str, Any]]:
    out = list(rows)
    if not out:
        raise ValueError("plot_sweep: no cases to plot")
    for k, row in enumerate(out):
        missing = [key for key in SWEEP_KEYS if key not in row]
        if missing:
            raise ValueError(f"plot_sweep: case {k} has no {', '.join(missing)}")
    return out


def _unique(values: Iterable[Any]) -> list[Any]:
    """The distinct values in the order they first appear."""
    return list(dict.fromkeys(values))


def _draw_cell(ax: Axes, x: int, y: int, counts: dict[str, int]) -> None:
    """The outcomes of the cases in one (R, α) cell: one marker, or one per outcome with n."""
    single = sum(counts.values()) == 1
    for key, n in counts.items():
        _, marker, color, filled = OUTCOMES[key]
        dx, dy = (0.0, 0.0) if single else SLOTS[key]
        face = color if filled else "none"
        ax.plot([x + dx], [y + dy], marker, color=color, mfc=face, ms=9 if single else 6, mew=1.5)
        if not single:
            ax.annotate(
                str(n), (x + dx, y + dy), xytext=(5, 0), textcoords="offset points",
                va="center", fontsize="xx-small",
            )  # fmt: skip


def _draw_map(
    ax: Axes, cases: list[Mapping[str, Any]], Rs: list[float], alphas: list[float], title: str
) -> None:
    """One panel: R across, α up, a marker per outcome; collapses counted in the title."""
    cells: dict[tuple[int, int], dict[str, int]] = {}
    for row in cases:
        cell = cells.setdefault((Rs.index(row["R"]), alphas.index(row["alpha"])), {})
        key = outcome(row)
        cell[key] = cell.get(key, 0) + 1
    for (x, y), counts in cells.items():
        _draw_cell(ax, x, y, counts)
    ax.set_xticks(range(len(Rs)), [f"{R:g}" for R in Rs])
    ax.set_yticks(range(len(alphas)), [f"{a:g}" for a in alphas])
    ax.set_xlim(-0.6, len(Rs) - 0.4)
    ax.set_ylim(-0.6, len(alphas) - 0.4)
    ax.set_xlabel("semi-diagonal R [m]")
    ax.set_ylabel("slenderness α [rad]")
    code = sum(bool(r["code_collapse"]) for r in cases)
    rocking = sum(bool(r["rocking_collapse"]) for r in cases)
    unknown = sum(outcome(r) in ("undetermined", "error") for r in cases)
    ax.set_title(
        f"{title}\ncollapses: code {code}, rocking {rocking} of {len(cases)}"
        + (f"; no verdict {unknown}" if unknown else ""),
        fontsize="small",
    )
    # Cell borders, not lines through the markers: a cell may hold several markers.
    ax.set_xticks([x + 0.5 for x in range(len(Rs) - 1)], minor=True)
    ax.set_yticks([y + 0.5 for y in range(len(alphas) - 1)], minor=True)
    ax.tick_params(which="minor", length=0)
    ax.grid(which="minor", color="0.8", lw=0.8)


def _panels(
    cases: list[Mapping[str, Any]], by: str | None
) -> list[tuple[str, list[Mapping[str, Any]]]]:
    """(title, cases) of each panel: per record, and per value of `by` if given."""
    out = []
    for rec in _unique(r["record"] for r in cases):
        mine = [r for r in cases if r["record"] == rec]
        if by is None:
            out.append((str(rec), mine))
            continue
        for value in _unique(r[by] for r in mine):
            shown = f"{value:g}" if isinstance(value, float) else str(value)
            out.append((f"{rec}, {by} = {shown}", [r for r in mine if r[by] == value]))
    return out


def plot_sweep(
    rows: Iterable[Mapping[str, Any]], path: str | Path, *, by: str | None = None
) -> None:
    """Collapse map of a systemic study: per record, R × α, code against rocking (paper Fig. 8,
    15–17).

    Each (R, α) cell shows the outcome of its case: both collapse (red square), the code only
    (orange triangle up: the code is conservative, paper §3.3's inconsistency), the rocking
    analysis only (purple triangle down: the code is unconservative), neither (green circle),
    a verdict missing (grey cross). A cell holding several cases (a dimension of the study not
    split into panels, e.g. the stiffness K) shows one marker per outcome with its count.

    Args:
        rows: one mapping per case, with at least
            "R": semi-diagonal [m] (float); "alpha": slenderness [rad] (float);
            "record": the record's name (str);
            "code_collapse": the code's ULS verdict is "collapses" (bool, None if not evaluated);
            "rocking_collapse": the time history overturns (bool, None if undecided).
            Further keys are ignored unless named by `by`.
        path: the file to write, .png or .svg.
        by: a further key of the rows (e.g. "K") whose values get a panel each: one figure row
            per record, one column per value. None: one panel per record.

    Raises:
        InputError: bad suffix, matplotlib missing, file not writable.
        ValueError: no rows, or a row without one of the keys above.
    """
    # A case whose block could not be computed has no place on the map (the tables count it).
    cases = [r for r in _check_rows(rows) if r["R"] is not None and r["alpha"] is not None]
    if not cases:
        raise ValueError("plot_sweep: no case with a block to plot")
    Rs = sorted(_unique(r["R"] for r in cases))
    alphas = sorted(_unique(r["alpha"] for r in cases))
    panels = _panels(cases, by)
    if by is None:
        ncols = min(PANEL_COLUMNS, len(panels))
    else:
        ncols = len(_unique(r[by] for r in cases))
    nrows = math.ceil(len(panels) / ncols)
    fig = new_figure(path, (PANEL_SIZE[0] * ncols, PANEL_SIZE[1] * nrows + 0.8))
    axes = fig.subplots(nrows, ncols, squeeze=False).ravel()
    for ax, (title, mine) in zip(axes, panels, strict=False):
        _draw_map(ax, mine, Rs, alphas, title)
    for ax in axes[len(panels) :]:
        ax.set_visible(False)
    _sweep_legend(fig, cases)
    fig.suptitle(f"Collapse map: code (NTC kinematic) against rocking, {len(cases)} cases")
    save(fig, path)


def _sweep_legend(fig: Figure, cases: list[Mapping[str, Any]]) -> None:
    from matplotlib.lines import Line2D

    seen = {outcome(r) for r in cases}
    handles = [
        Line2D([], [], ls="none", marker=m, color=c, mfc=c if f else "none", mew=1.5, label=label)
        for key, (label, m, c, f) in OUTCOMES.items()
        if key in seen or key not in ("undetermined", "error")
    ]
    fig.legend(handles=handles, loc="outside lower center", ncols=len(handles), fontsize="small")
