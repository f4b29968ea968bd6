"""`rock risk MODEL`: the JSON document and the terminal Report of the risk class of a model's
local mechanisms (DM 58/2017 Allegato A, conventional method: rockcli.risk).

JSON: ``{"schema", "rock_version", "model": {"name", "file"}, "edition", "state",
"T_Rc": {"SLD", "SLV", "SLC"}, "T_Rc_used": {"SLO", "SLD", "SLV", "SLC"}, "capped",
"governing": {"SLD", "SLV", "SLC", "IS_V"}, "annual_rates": {"SLID" … "SLC"}, "PAM",
"PAM_class", "IS_V", "IS_V_class", "class", "mechanisms": [{"name", "T_Rc", "IS_V", "PAM",
"class"}], "hazard": {"source", "TR", "ag"}, "retrofit", "after", "notes"}``; ``retrofit``
(the rod, its steel, bars, chosen diameter [mm] and why) and ``after`` (the same keys as the
top level, with ``classes_gained``; null when no diameter passes) with --retrofit only.
PAM, IS-V as fractions (0.0113 is 1.13 %).
"""

from __future__ import annotations

from typing import Any

from rockcli.risk.classification import TR_SLID
from rockcli.risk.local import BuildingRisk
from rockcli.risk.model import Classified, Retrofit
from rockcli.terminal.table import Column, Report, Table, format_value
from rockcli.version import __version__

SCHEMA = 1

#: What every document says of a class from local mechanisms.
UPPER_BOUND = (
    "local mechanisms only: the building's global behaviour must be checked too, and its class "
    "from the local mechanisms is an upper bound of the building's (DM 58/2017 Allegato A "
    "classes the whole building)"
)
NOTES = (
    "DM 58/2017 Allegato A (text of DM 65/2017), conventional method: λ = 1/T_Rc; T_Rc of SLO "
    "and SLD no longer than the SLV's; SLID λ = 1/10 years, CR 0 %; SLR at λ(SLC), CR 100 %; "
    "PAM = Σ |Δλ|·(CR_i + CR_i−1)/2 + λ(SLC)·CR(SLR) (Tab. 3 CR: SLO 7 %, SLD 15 %, SLV "
    "50 %, SLC 80 %); IS-V = PGA_C(SLV)/PGA_D(SLV), PGA = ag·S; the class, the worse of "
    "the PAM's (Tab. 1) and the IS-V's (Tab. 2)",
    "SLO: the Circolare checks no SLO of a local mechanism: T_Rc(SLO) is its T_Rc(SLD), the "
    "action that first sets it in motion",
    "the building's T_Rc of each limit state: the lowest of its mechanisms' (the first to "
    "reach it); its IS-V the lowest",
)


def class_entry(risk: BuildingRisk) -> dict[str, Any]:
    """The keys of one state's class (null where the class is not evaluated)."""
    r = risk.risk
    return {
        "T_Rc": risk.T_Rc,
        "T_Rc_used": None if r is None else r.T_Rc,
        "capped": [] if r is None else list(r.capped),
        "governing": risk.governing,
        "annual_rates": None if r is None else r.rates,
        "PAM": None if r is None else r.PAM,
        "PAM_class": None if r is None else r.pam_class,
        "IS_V": risk.IS_V,
        "IS_V_class": None if r is None else r.isv_class,
        "class": None if r is None else r.risk_class,
        "not_evaluated": list(risk.missing),
        "mechanisms": [
            {
                "name": m.name,
                "T_Rc": m.T_Rc,
                "IS_V": m.IS_V,
                "PAM": None if m.risk is None else m.risk.PAM,
                "class": None if m.risk is None else m.risk.risk_class,
            }
            for m in risk.mechanisms
        ],  # fmt: skip
    }


def state_notes(state: Classified) -> list[str]:
    """The notes of one state: the hazard T_Rc were read on (and the values beyond its
    points), the mechanism that sets each state, a T_Rc below the SLID's, the capped states,
    the mechanisms without a class."""
    from rockcli.terminal.kinematic import hazard_document, return_period_notes

    risk = state.risk
    notes = [f"{state.label}: {text}"
             for text in return_period_notes(risk.T_Rc, hazard_document(risk.hazard))]  # fmt: skip
    sets = [f"{ls.replace('_', '-')} {risk.governing[ls]}"
            for ls in ("SLD", "SLV", "SLC", "IS_V") if ls in risk.governing]  # fmt: skip
    notes.append(f"{state.label}: {'; '.join(sets)} (the mechanism that sets each)")
    short = [f"{ls} {years:.3g} years" for ls, years in risk.T_Rc.items() if years < TR_SLID]
    if short and risk.risk is not None:
        notes.append(f"{state.label}: T_Rc shorter than the SLID's conventional {TR_SLID:g} "
                     f"years ({', '.join(short)}): the curve runs beyond λ = 1/{TR_SLID:g}, and "
                     "the area of Allegato A's formula (|Δλ|) counts it")  # fmt: skip
    if risk.risk is not None and risk.risk.capped:
        notes.append(f"{state.label}: T_Rc of {', '.join(risk.risk.capped)} lowered to the "
                     "SLV's (Allegato A, step 3)")  # fmt: skip
    if risk.missing:
        notes.append(f"{state.label}: no class: the code check of {'; '.join(risk.missing)} is "
                     "not evaluated there (its kinematic notes say why), and the class of the "
                     "other mechanisms could be better than the building's")  # fmt: skip
    return notes


def retrofit_entry(rod: Retrofit) -> dict[str, Any]:
    """The rod `rock retrofit` sized."""
    return {"rod": rod.rod, "grade": rod.grade, "bars": rod.bars,
            "diameter_mm": rod.diameter_mm, "reason": rod.reason, "rocked": rod.rocked}  # fmt: skip


def risk_class_document(name: str, path: str, before: Classified,
                        retrofit: tuple[Retrofit, Classified | None] | None = None
                        ) -> dict[str, Any]:  # fmt: skip
    """The `rock risk MODEL --format json` document."""
    from rockcli.terminal.kinematic import hazard_document

    doc: dict[str, Any] = {
        "schema": SCHEMA,
        "rock_version": __version__,
        "model": {"name": name, "file": path},
        "edition": before.result.edition,
        "state": before.label,
        **class_entry(before.risk),
        "hazard": hazard_document(before.risk.hazard),
    }
    notes = [UPPER_BOUND, *NOTES, *state_notes(before)]
    if retrofit is not None:
        rod, after = retrofit
        doc["retrofit"] = retrofit_entry(rod)
        doc["after"] = None
        if after is not None:
            from rockcli.risk.classification import classes_gained

            first, then = before.risk.risk, after.risk.risk
            gained = (None if first is None or then is None
                      else classes_gained(first.risk_class, then.risk_class))  # fmt: skip
            doc["after"] = {"state": after.label, **class_entry(after.risk),
                            "classes_gained": gained}  # fmt: skip
            notes += state_notes(after)
        else:
            notes.append(f"retrofit: {rod.reason}")
    doc["notes"] = notes
    return doc


#: The rows of the class table: label, unit, the key (and limit state) and format.
ROWS = (
    ("T_Rc,SLD", "years", ("T_Rc_used", "SLD"), "{:.4g}"),
    ("T_Rc,SLV", "years", ("T_Rc_used", "SLV"), "{:.4g}"),
    ("T_Rc,SLC", "years", ("T_Rc_used", "SLC"), "{:.4g}"),
    ("PAM", "%", ("PAM", None), "{:.3f}"),
    ("PAM class", "", ("PAM_class", None), "{}"),
    ("IS-V", "%", ("IS_V", None), "{:.1f}"),
    ("IS-V class", "", ("IS_V_class", None), "{}"),
    ("risk class", "", ("class", None), "{}"),
)
PERCENT = ("PAM", "IS_V")


def _cell(entry: dict[str, Any] | None, key: str, sub: str | None, fmt: str) -> str:
    """One cell: the value (T_Rc used by the class, else the building's), "—" for none."""
    if entry is None:
        return "—"
    value = entry[key] if sub is None else (entry[key] or entry["T_Rc"]).get(sub)
    if value is None:
        return "—"
    return format_value(100.0 * value if key in PERCENT else value, fmt)


def class_table(doc: dict[str, Any]) -> Table:
    """The class before (and after the retrofit)."""
    states = [("value", doc)] if "after" not in doc else [("before", doc), ("after", doc["after"])]
    rows = tuple(
        {"label": label, "unit": unit, **{col: _cell(e, key, sub, fmt) for col, e in states}}
        for label, unit, (key, sub), fmt in ROWS
    )
    columns = (Column("label", ""), Column("unit", "unit"),
               *(Column(col, col, align="right") for col, _ in states))  # fmt: skip
    return Table("Risk class (DM 58/2017 Allegato A)", columns, rows)


MECHANISM_COLUMNS = (
    Column("name", "mechanism"),
    Column("SLD", "T_Rc,SLD", "years", "{:.4g}", short="SLD"),
    Column("SLV", "T_Rc,SLV", "years", "{:.4g}", short="SLV"),
    Column("SLC", "T_Rc,SLC", "years", "{:.4g}", short="SLC"),
    Column("IS_V", "IS-V", "%", "{:.1f}"),
    Column("PAM", "PAM", "%", "{:.3f}"),
    Column("class", "class"),
)


def mechanism_rows(entry: dict[str, Any]) -> tuple[dict[str, Any], ...]:
    """Each mechanism's own T_Rc and class."""
    return tuple(
        {"name": m["name"], **(m["T_Rc"] or {}),
         "IS_V": None if m["IS_V"] is None else 100.0 * m["IS_V"],
         "PAM": None if m["PAM"] is None else 100.0 * m["PAM"], "class": m["class"]}
        for m in entry["mechanisms"]
    )  # fmt: skip


def verdict_of(doc: dict[str, Any]) -> str:
    """The class, and with a retrofit the class after and the classes gained."""
    text = (f"class {doc['class']} ({doc['state']}; PAM {doc['PAM_class']}, "
            f"IS-V {doc['IS_V_class']})" if doc["class"] else
            f"class not evaluated ({doc['state']}: see the notes)")  # fmt: skip
    after = doc.get("after")
    if after is not None:
        rod = doc["retrofit"]
        text += f"; with the tie-rod '{rod['rod']}' Ø{rod['diameter_mm']:g} mm: "
        text += f"class {after['class']}" if after["class"] else "class not evaluated"
        if after["classes_gained"] is not None:
            text += f", {after['classes_gained']:+d} class(es)"
    elif "retrofit" in doc:
        text += "; no diameter tried makes the mechanisms the rod restrains safe"
    return text + "; an upper bound of the building's class (local mechanisms only)"


def risk_class_report(doc: dict[str, Any]) -> Report:
    """The Report: the class (before and after), each mechanism's, the notes."""
    tables = [class_table(doc), Table(f"Mechanisms ({doc['state']})", MECHANISM_COLUMNS,
                                      mechanism_rows(doc))]  # fmt: skip
    if doc.get("after"):
        tables.append(Table(f"Mechanisms ({doc['after']['state']})", MECHANISM_COLUMNS,
                            mechanism_rows(doc["after"])))  # fmt: skip
    return Report(title=f"rock risk — {doc['model']['name']}", tables=tuple(tables),
                  notes=tuple(doc["notes"]), verdict=verdict_of(doc))  # fmt: skip
