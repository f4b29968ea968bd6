"""The wall in its report: its geometry, materials, loads, thrusts and restrainers as tables,
and its vertical section to scale with each mechanism's moving bodies and hinge drawn.

Everything comes from the wall as the catalogue derived it (rockcli.mechanisms.wall.Wall, the
description both analyses read) and from the verification's own results (its mechanisms'
hinges, sides and α0): nothing is computed here but the drawing.
"""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from rockcli.document.content import Block, Grid
from rockcli.document.words import Words

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure as MplFigure

    from rockcli.mechanisms.wall import Wall

#: The colours of the drawing: the wall at rest, a mechanism's bodies (a flexure's two),
#: loads, thrusts, restrainers.
REST, MOVING, UPPER = "#e8e1d4", "#c8795a", "#d9a441"
LOAD, THRUST, TIE = "tab:blue", "tab:red", "tab:green"
#: Mechanism panels per row of the drawing, and the characters of a panel's title line.
PANELS_PER_ROW = 4
TITLE_WIDTH = 26


def wall_grids(wall: Wall, kin: Mapping[str, Any], w: Words, fc_rule: Any = None) -> list[Block]:
    """The wall's geometry and materials, then its loads, thrusts and restrainers (only the
    tables it has); ``fc_rule``: why FC is what it is (a note, in the report's language;
    default the check's text)."""
    n = w.number
    rows: list[tuple[str, str, str]] = [(w("wall.width"), n(wall.width, "{:.3f}"), "m")]
    bases = wall.storey_bases()
    for i, (storey, base) in enumerate(zip(wall.storeys, bases, strict=True), start=1):
        rows.append((w("wall.storey", n=i, base=n(base, "{:.2f}")),
                     f"{n(storey.height, '{:.3f}')} × {n(storey.thickness, '{:.3f}')}",
                     "m"))  # fmt: skip
    if wall.gable_height:
        rows.append((w("wall.gable"), n(wall.gable_height, "{:.3f}"), "m"))
    rows.append((w("wall.unit_weight"), n(wall.unit_weight / 1e3, "{:.2f}"), "kN/m³"))
    if wall.return_wall_thickness:
        rows.append((w("wall.return_walls"), n(wall.return_wall_thickness, "{:.3f}"), "m"))
    rows.append((w("wall.f_m"), "—" if wall.f_m is None else n(wall.f_m / 1e6, "{:.3g}"), "MPa"))
    rows.append((w("wall.E"), "—" if wall.E is None else n(wall.E / 1e6, "{:.4g}"), "MPa"))
    rule = w.note(fc_rule if fc_rule is not None else kin["FC_rule"])
    rows.append((w("wall.FC"), f"{n(kin['FC'], '{:.2f}')} ({rule})", ""))
    grids: list[Block] = [Grid(w("wall.caption"), (w("col.quantity"), w("col.value"),
                                                   w("col.unit")), tuple(rows),
                               (False, True, False))]  # fmt: skip
    if wall.loads:
        grids.append(Grid(
            w("wall.loads_caption"),
            (w("col.name"), w("col.weight_kn"), w("wall.x_face"), w("col.z_m"), w("col.bears"),
             w("wall.moves")),
            tuple((ld.name, n(ld.weight / 1e3, "{:.2f}"), n(ld.x, "{:.3f}"), n(ld.z, "{:.3f}"),
                   w.yes_no(ld.bears), w.yes_no(ld.moves)) for ld in wall.loads),
            (False, True, True, True, False, False),
        ))  # fmt: skip
    if wall.thrusts:
        grids.append(Grid(
            w("wall.thrusts_caption"),
            (w("col.name"), w("wall.force_kn"), w("wall.direction"), w("wall.x_face"),
             w("col.z_m")),
            tuple((t.name, n(t.force / 1e3, "{:.2f}"),
                   w("wall.outward" if t.direction > 0 else "wall.inward"),
                   n(t.x, "{:.3f}"), n(t.z, "{:.3f}")) for t in wall.thrusts),
            (False, True, False, True, True),
        ))  # fmt: skip
    if wall.restrainers:
        grids.append(Grid(
            w("wall.restrainers_caption"),
            (w("col.name"), w("wall.x_face"), w("col.z_m"), w("wall.stiffness"),
             w("col.strength_kn")),
            tuple((r.member.name, n(r.x, "{:.3f}"), n(r.z, "{:.3f}"),
                   n(max(r.member.k_pos, r.member.k_neg) / 1e3, "{:.4g}"),
                   n(r.member.strength / 1e3 if r.member.strength < float("inf") else None,
                     "{:.2f}"))
                  for r in wall.restrainers),
            (False, True, True, True, True),
        ))  # fmt: skip
    return grids


def outline(wall: Wall) -> list[tuple[float, float, float, float]]:
    """The wall's section as rectangles (x0, x1, z0, z1): each storey from the outer face
    (x = 0) to its thickness, and the gable (its section at the apex) on the last one."""
    parts = [(0.0, s.thickness, z, z + s.height)
             for s, z in zip(wall.storeys, wall.storey_bases(), strict=True)]  # fmt: skip
    if wall.gable_height:
        parts.append((0.0, wall.storeys[-1].thickness, wall.height, wall.height +
                      wall.gable_height))  # fmt: skip
    return parts


def clipped(parts: Sequence[tuple[float, float, float, float]], lo: float, hi: float
            ) -> list[tuple[float, float, float, float]]:  # fmt: skip
    """The parts between heights lo and hi."""
    return [(x0, x1, max(z0, lo), min(z1, hi)) for x0, x1, z0, z1 in parts
            if min(z1, hi) > max(z0, lo)]  # fmt: skip


def thickness_at(wall: Wall, z: float) -> float:
    """The wall's thickness at height z (the storey's there; the last one's above)."""
    for s, base in zip(wall.storeys, wall.storey_bases(), strict=True):
        if base <= z < base + s.height:
            return s.thickness
    return wall.storeys[-1].thickness


def moving_parts(wall: Wall, m: Mapping[str, Any]) -> list[tuple[list[Any], str]]:
    """A mechanism's moving bodies as rectangles with their colour (a flexure's lower block
    and upper block apart)."""
    parts = outline(wall)
    top = wall.height + (wall.gable_height or 0.0)
    if m["type"] == "gable":
        return [(clipped(parts, wall.height, top), MOVING)]
    if m["type"] == "horizontal-flexure":  # the strip, bending in plan
        return [(clipped(parts, m["hinge_height"], m["hinge_height"] + m["strip_height"]),
                 MOVING)]  # fmt: skip
    if m["type"] == "vertical-flexure":
        base = wall.storey_bases()[m["storey"] - 1]
        end = base + wall.storeys[m["storey"] - 1].height
        return [(clipped(parts, base, m["hinge_height"]), MOVING),
                (clipped(parts, m["hinge_height"], end), UPPER)]  # fmt: skip
    return [(clipped(parts, m.get("hinge_height") or 0.0, top), MOVING)]


def hinges(wall: Wall, m: Mapping[str, Any]) -> list[tuple[float, float]]:
    """Where a mechanism's hinges are drawn: at the face it turns about (θ > 0 outward: the
    outer face; θ < 0 the inner), a flexure's intermediate hinge on the opposite face."""
    side = m.get("side", 1)
    if m["type"] == "gable":
        z = wall.height
    elif m["type"] == "vertical-flexure":
        z = wall.storey_bases()[m["storey"] - 1]
    else:
        z = m.get("hinge_height") or 0.0
    face = 0.0 if side > 0 else thickness_at(wall, z)
    out = [(face, z)]
    if m["type"] == "vertical-flexure":
        zm = m["hinge_height"]
        out.append((thickness_at(wall, zm) if side > 0 else 0.0, zm))
    return out


def wall_drawing(wall: Wall, kin: Mapping[str, Any], w: Words) -> MplFigure:
    """The wall's section to scale, then one panel per mechanism of the verification: its
    moving bodies coloured, its hinges, the loads, thrusts and restrainers at their points."""
    from rockcli.document.figures import PAGE_WIDTH, new_figure

    mechanisms = list(kin.get("mechanisms", ()))
    panels = 1 + len(mechanisms)
    columns = min(panels, PANELS_PER_ROW)
    rows = -(-panels // columns)
    fig = new_figure(PAGE_WIDTH, 3.6 * rows, words=w)
    axes = fig.subplots(rows, columns, squeeze=False, sharey=True)
    draw_wall(axes[0][0], wall, None, w)
    axes[0][0].set_title(w("wall.drawing_title"), fontsize="small")
    for k, m in enumerate(mechanisms, start=1):
        ax = axes[k // columns][k % columns]
        draw_wall(ax, wall, m, w)
        name = textwrap.fill(str(w.note(m["name"])), TITLE_WIDTH)
        ax.set_title(f"{name}\nα0 = {w.number(m['alpha0'], '{:.4f}')}", fontsize="x-small")
    for k in range(panels, rows * columns):
        axes[k // columns][k % columns].set_axis_off()
    return fig


def draw_wall(ax: Axes, wall: Wall, m: Mapping[str, Any] | None, w: Words) -> None:
    """One panel: the section at rest, and a mechanism's bodies and hinges when given."""
    top = wall.height + (wall.gable_height or 0.0)
    depth = max(s.thickness for s in wall.storeys)
    for x0, x1, z0, z1 in outline(wall):
        ax.fill([x0, x1, x1, x0], [z0, z0, z1, z1], color=REST, ec="0.35", lw=0.8)
    if m is not None:
        for parts, colour in moving_parts(wall, m):
            for x0, x1, z0, z1 in parts:
                ax.fill([x0, x1, x1, x0], [z0, z0, z1, z1], color=colour, ec="k", lw=1.0)
        for x, z in hinges(wall, m):
            ax.plot([x], [z], "o", color="k", ms=5, zorder=5)
    reach = 0.9 * depth
    for ld in wall.loads:
        ax.annotate("", (ld.x, ld.z), xytext=(ld.x, ld.z + 0.06 * top),
                    arrowprops={"arrowstyle": "-|>", "color": LOAD, "lw": 1.0})  # fmt: skip
    for t in wall.thrusts:
        ax.annotate("", (t.x, t.z), xytext=(t.x + t.direction * reach, t.z),
                    arrowprops={"arrowstyle": "-|>", "color": THRUST, "lw": 1.0})  # fmt: skip
    for r in wall.restrainers:
        ax.plot([r.x, depth + reach], [r.z, r.z], color=TIE, lw=1.2)
        ax.plot([depth + reach] * 2, [r.z - 0.02 * top, r.z + 0.02 * top], color="k", lw=2)
    if m is None:  # the first panel names what is drawn
        for ld in wall.loads:
            ax.annotate(ld.name, (ld.x, ld.z + 0.06 * top), fontsize="xx-small", color=LOAD,
                        ha="center", va="bottom")  # fmt: skip
        for r in wall.restrainers:
            ax.annotate(r.member.name, (depth + reach, r.z), fontsize="xx-small", color=TIE,
                        xytext=(2, 2), textcoords="offset points")  # fmt: skip
    ax.plot([-reach, depth + 1.6 * reach], [0, 0], color="k", lw=0.8)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(-1.2 * reach, depth + 2.0 * reach)
    ax.set_ylim(-0.03 * top, 1.1 * top)
    ax.tick_params(labelsize="x-small")
    ax.set_xlabel(w("figure.x_m"), fontsize="x-small")
