"""The choice of a retrofit: the smallest diameter that passes every criterion, or why none.

A candidate passes when the code's ULS check is satisfied, the block survives the time
history (both polarities), the rod does not rupture and its largest force stays within its
strength (utilisation ≤ 1 within the rounding of a yield plateau, FORCE_RTOL; NTC 2018
§4.2.4.1.2 through rockcli.analyses.strength). A rod that yielded at its design strength and
held passes: the time history has taken its yielding into account.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.analyses.strength import FORCE_RTOL
from rockcli.notes import Items, Note

#: The largest utilisation (force / design strength) a rod may reach.
UTILISATION_LIMIT = 1.0


def failures(row: dict[str, Any]) -> list[Note]:
    """Why a candidate does not pass (empty: it passes), one phrase per criterion."""
    why = []
    if row["code_uls_passed"] is None:
        why.append(Note("retro_not_evaluated", "the code ULS is not evaluated (set "
                        "ntc.ultimate_displacement or a restrainer's fails_at)"))  # fmt: skip
    elif not row["code_uls_passed"]:
        zeta = row["code_zeta"]
        why.append(
            Note("retro_code_fails", "the code ULS fails (ζ = {zeta:.3f})", zeta=float(zeta))
            if zeta is not None
            else Note("retro_code_fails_unknown", "the code ULS fails")
        )
    mechanism = row.get("mechanism")
    if mechanism and not row.get("on_mechanism", True):
        why.append(Note("retro_not_on", "the rod is not on the governing mechanism "
                        "'{mechanism}'", mechanism=mechanism))  # fmt: skip
    if row["overturned"]:
        why.append(
            Note("retro_overturns", "'{mechanism}' overturns", mechanism=mechanism)
            if mechanism
            else Note("retro_block_overturns", "the block overturns")
        )
    elif row["rocking"] != "survives":
        why.append(Note("retro_undecided", "the time history is undecided"))
    if row["ruptured"]:
        why.append(Note("retro_ruptures", "the rod ruptures"))
    utilisation = row["utilisation"]
    if utilisation is not None and utilisation > UTILISATION_LIMIT + FORCE_RTOL:
        why.append(Note("retro_utilisation", "the rod's utilisation is {u:.2f} > {limit:g}",
                        u=utilisation, limit=UTILISATION_LIMIT))  # fmt: skip
    duct, anchor = row.get("ductility") or {}, row.get("anchor") or {}
    if duct.get("passed") is False:
        why.append(Note("retro_stretches", "the rod stretches {demand:.0f} mm, more than the "
                        "{capacity:.0f} mm it can take", demand=duct["demand"] * 1e3,
                        capacity=duct["capacity"] * 1e3))  # fmt: skip
    if anchor.get("passed") is False:
        why.append(Note("retro_anchor", "the anchor governs ({capacity:.0f} kN < γov·A·fy = "
                        "{demand:.0f} kN)", capacity=anchor["capacity"] / 1e3,
                        demand=anchor["demand"] / 1e3))  # fmt: skip
    return why


def choose(rows: Sequence[dict[str, Any]]) -> tuple[dict[str, Any] | None, Note]:
    """(the chosen candidate or None, the reason) over rows ascending in diameter."""
    if not rows:
        return None, Note("retro_none_tried", "no diameter tried")
    for row in rows:
        if not failures(row):
            return row, Note(
                "retro_chosen", "Ø{d:g} mm is the smallest diameter for which the code ULS "
                "passes, the block survives and the rod neither ruptures nor exceeds its "
                "strength, its ductility or its anchor's capacity", d=float(row["diameter_mm"]),
            )  # fmt: skip
    largest = rows[-1]
    why = Items(failures(largest), "; ")
    return None, Note("retro_none", "none in the range: at the largest, {d:g} mm, {why}",
                      d=float(largest["diameter_mm"]), why=why)  # fmt: skip
