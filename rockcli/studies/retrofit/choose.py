"""The choice of a retrofit: the smallest diameter that makes safe every mechanism the rod
restrains, or why none does.

A mechanism (a block file's block, or each mechanism of a wall's catalogue) is safe with a
diameter when the code's ULS check is satisfied, it survives the time history (both
polarities), the rod does not rupture and its largest force stays within its strength
(utilisation ≤ 1 within the rounding of a yield plateau, FORCE_RTOL; NTC 2018 §4.2.4.1.2
through rockcli.analyses.strength), its elongation and its anchor's capacity. A rod that
yielded at its design strength and held passes: the time history has taken its yielding into
account. A mechanism the rod does not restrain (the rod is not on it: below its hinge, at a
flexure's held top; or the rod goes slack on the side it fails on: a tie opening inward) and
that fails needs another intervention: it is said, and it does not fail the rod.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.analyses.strength import FORCE_RTOL
from rockcli.notes import Items, Note

#: The largest utilisation (force / design strength) a rod may reach.
UTILISATION_LIMIT = 1.0


def failures(row: dict[str, Any]) -> list[Note]:
    """Why a candidate does not pass (empty: it passes), one phrase per criterion: the code's
    (:func:`code_failures`), the rod not on the mechanism, the time history's and
    the rod's (:func:`history_failures`)."""
    why = code_failures(row)
    mechanism = row.get("mechanism")
    if mechanism and not row.get("on_mechanism", True):
        why.append(Note("retro_not_on", "the rod is not on the mechanism '{mechanism}'",
                        mechanism=mechanism))  # fmt: skip
    return why + history_failures(row)


def code_failures(row: dict[str, Any]) -> list[Note]:
    """The code's ULS check not satisfied, or not evaluated."""
    if row["code_uls_passed"] is None:
        return [Note("retro_not_evaluated", "the code ULS is not evaluated (set "
                     "ntc.ultimate_displacement or a restrainer's fails_at)")]  # fmt: skip
    if not row["code_uls_passed"]:
        zeta = row["code_zeta"]
        return [
            Note("retro_code_fails", "the code ULS fails (ζ = {zeta:.3f})", zeta=float(zeta))
            if zeta is not None
            else Note("retro_code_fails_unknown", "the code ULS fails")
        ]
    return []


def history_failures(row: dict[str, Any]) -> list[Note]:
    """The time history's and the rod's: overturning (or undecided), the rod's rupture, its
    utilisation, its elongation, its anchor (none where the mechanism was not rocked)."""
    why = []
    mechanism = row.get("mechanism")
    if row["overturned"]:
        why.append(
            Note("retro_overturns", "'{mechanism}' overturns", mechanism=mechanism)
            if mechanism
            else Note("retro_block_overturns", "the block overturns")
        )
    elif row["rocking"] not in ("survives", None):  # None: not rocked (the rod is not on it)
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


#: What a mechanism is with a diameter (:func:`mechanism_status`).
SAFE, FAILS, ANOTHER = "safe", "fails", "needs another intervention"


def mechanism_status(m: dict[str, Any]) -> str:
    """A mechanism with a diameter: SAFE (every criterion met), FAILS (the rod is on it and
    it overturns or the rod does not hold — the rod's concern —, or the rod restrains it and
    the code ULS still fails) or ANOTHER (the code ULS fails where the rod does not restrain
    it: not on it, or slack on the side it fails on)."""
    if m["on_mechanism"] and history_failures(m):
        return FAILS
    if code_failures(m):
        return FAILS if m["restrained"] else ANOTHER
    return SAFE


def candidate_failures(row: dict[str, Any]) -> list[Note]:
    """Why a diameter does not pass (empty: it passes): each mechanism the rod restrains that
    still fails, with why; a candidate without mechanisms (a synthetic row) by its own
    criteria."""
    if "mechanisms" not in row:
        return failures(row)
    return [Note("retro_mechanism_fails", "'{name}': {why}", name=m["name"],
                 why=Items(failures(m), "; "))
            for m in row["mechanisms"] if m["status"] == FAILS]  # fmt: skip


def others(row: dict[str, Any]) -> list[str]:
    """The mechanisms that need another intervention with this diameter."""
    return [m["name"] for m in row.get("mechanisms", ()) if m["status"] == ANOTHER]


def choose(
    rows: Sequence[dict[str, Any]], rocked: bool = True
) -> tuple[dict[str, Any] | None, Note]:
    """(the chosen candidate or None, the reason) over rows ascending in diameter;
    ``rocked`` False: the candidates had the code check alone (no record, no time history)."""
    if not rows:
        return None, Note("retro_none_tried", "no diameter tried")
    restrained = any(m["restrained"] for r in rows for m in r.get("mechanisms", ()))
    if rows[0].get("mechanisms") is not None and not restrained:
        names = [f"'{m['name']}'" for m in rows[-1]["mechanisms"] if m["status"] != SAFE]
        if not names:  # nothing fails: any diameter does, the smallest first
            return rows[0], Note("retro_restrains_none_safe", "no mechanism fails and the rod "
                                 "restrains none: the smallest diameter tried, Ø{d:g} mm, is "
                                 "as good as any (the rod is not needed)",
                                 d=float(rows[0]["diameter_mm"]))  # fmt: skip
        return None, Note("retro_restrains_none", "the rod restrains none of the mechanisms "
                          "(each needs another intervention where it fails: {names})",
                          names=Items(names, ", "))  # fmt: skip
    for row in rows:
        if not candidate_failures(row):
            return row, chosen_note(row, rocked)
    largest = rows[-1]
    why = Items(candidate_failures(largest), "; ")
    return None, Note("retro_none", "none in the range: at the largest, {d:g} mm, {why}",
                      d=float(largest["diameter_mm"]), why=why)  # fmt: skip


def chosen_note(row: dict[str, Any], rocked: bool) -> Note:
    """Why this diameter is chosen: what it satisfies (a block's or every mechanism's
    criteria; the code check's alone without a record) and the mechanisms it leaves to
    another intervention."""
    d = float(row["diameter_mm"])
    names = others(row)
    wall = any(m.get("mechanism") for m in row.get("mechanisms", ()))
    if not rocked:
        if names:
            return Note("retro_chosen_code_others", "Ø{d:g} mm is the smallest diameter for "
                        "which the code ULS of every mechanism the rod restrains passes and "
                        "its anchor holds (the code check alone: no record, no time history); "
                        "another intervention "
                        "is needed for: {names}", d=d,
                        names=Items([f"'{n}'" for n in names], ", "))  # fmt: skip
        return Note("retro_chosen_code", "Ø{d:g} mm is the smallest diameter for which the "
                    "code ULS of every mechanism passes and the rod's anchor holds (the code "
                    "check alone: no record, no time history)", d=d)  # fmt: skip
    if names:
        return Note("retro_chosen_others", "Ø{d:g} mm is the smallest diameter that makes safe "
                    "every mechanism the rod restrains (the code ULS passes, it survives, the "
                    "rod holds); another intervention is needed for: {names}", d=d,
                    names=Items([f"'{n}'" for n in names], ", "))  # fmt: skip
    if wall:
        return Note("retro_chosen_wall", "Ø{d:g} mm is the smallest diameter for which every "
                    "mechanism passes the code ULS, every one the rod is on survives the time "
                    "history, and the rod neither ruptures nor exceeds its strength, its "
                    "ductility or its anchor's capacity", d=d)  # fmt: skip
    return Note("retro_chosen", "Ø{d:g} mm is the smallest diameter for which the code ULS "
                "passes, the block survives and the rod neither ruptures nor exceeds its "
                "strength, its ductility or its anchor's capacity", d=d)  # fmt: skip
