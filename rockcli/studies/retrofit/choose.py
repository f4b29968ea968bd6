"""The choice of a retrofit: the smallest diameter that passes every criterion, or why none.

A candidate passes when the code's ULS check is satisfied, the block survives the time
history (both polarities), the rod does not rupture and its largest force stays within its
strength (utilisation ≤ 1 within the rounding of a yield plateau, FORCE_RTOL; NTC 2018
§4.2.4.1.2 through rockcli.studies.strength). A rod that yielded at its design strength and
held passes: the time history has taken its yielding into account.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.studies.strength import FORCE_RTOL

#: The largest utilisation (force / design strength) a rod may reach.
UTILISATION_LIMIT = 1.0
#: How to have the code's ULS evaluated (as `rock kinematic` says it).
ULTIMATE_FIX = "set ntc.ultimate_displacement or a restrainer's fails_at"


def failures(row: dict[str, Any]) -> list[str]:
    """Why a candidate does not pass (empty: it passes), one phrase per criterion."""
    why = []
    if row["code_uls_passed"] is None:
        why.append(f"the code ULS is not evaluated ({ULTIMATE_FIX})")
    elif not row["code_uls_passed"]:
        why.append(f"the code ULS fails (ζ = {_number(row['code_zeta'])})")
    body = "the block" if not row.get("mechanism") else f"'{row['mechanism']}'"
    if row.get("mechanism") and not row.get("on_mechanism", True):
        why.append(f"the rod is not on the governing mechanism '{row['mechanism']}'")
    if row["overturned"]:
        why.append(f"{body} overturns")
    elif row["rocking"] != "survives":
        why.append(f"the time history is {row['rocking']}")
    if row["ruptured"]:
        why.append("the rod ruptures")
    utilisation = row["utilisation"]
    if utilisation is not None and utilisation > UTILISATION_LIMIT + FORCE_RTOL:
        why.append(f"the rod's utilisation is {utilisation:.2f} > {UTILISATION_LIMIT:g}")
    duct, anchor = row.get("ductility") or {}, row.get("anchor") or {}
    if duct.get("passed") is False:
        why.append(
            f"the rod stretches {duct['demand'] * 1e3:.0f} mm, more than the "
            f"{duct['capacity'] * 1e3:.0f} mm it can take"
        )
    if anchor.get("passed") is False:
        why.append(
            f"the anchor governs ({anchor['capacity'] / 1e3:.0f} kN < γov·A·fy = "
            f"{anchor['demand'] / 1e3:.0f} kN)"
        )
    return why


def choose(rows: Sequence[dict[str, Any]]) -> tuple[dict[str, Any] | None, str]:
    """(the chosen candidate or None, the reason) over rows ascending in diameter."""
    if not rows:
        return None, "no diameter tried"
    for row in rows:
        if not failures(row):
            return row, (
                f"Ø{row['diameter_mm']:g} mm is the smallest diameter for which the code ULS "
                "passes, the block survives and the rod neither ruptures nor exceeds its strength, "
                "its ductility or its anchor's capacity"
            )
    largest = rows[-1]
    return None, (
        f"none in the range: at the largest, {largest['diameter_mm']:g} mm, "
        + "; ".join(failures(largest))
    )


def _number(value: float | None) -> str:
    return "not evaluated" if value is None else f"{value:.3f}"
