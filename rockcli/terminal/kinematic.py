"""The `rock kinematic` result as data: the JSON document and the Report for the terminal."""

from __future__ import annotations

from typing import Any

from rockcli.codecheck.result import Check, KinematicResult, RestrainerAction, WorkTerm
from rockcli.terminal.table import Column, Report, Table, key_value
from rockcli.version import __version__

SCHEMA = 1


CIRCOLARE = {"2009": "Circolare 617/2009", "2019": "Circolare 7/2019"}


def _number(x: float | None) -> float | None:
    return None if x is None else float(x)


def check_document(c: Check, edition: str) -> dict[str, Any]:
    """One check, full precision; a displacement check also says where it read the spectrum:
    ``demand_damping`` [%], ``demand_period`` [s] (the maximum's, over a range),
    ``demand_period_range`` [T_lo, T_hi] [s] (None: read at one period), ``demand_spectral``
    [m] (the spectral displacement there at the limit state's own ag), ``demand_at_secant``
    [m] (the same at the secant period itself), ``demand_rule``."""
    sp = c.spectral
    return {
        "limit_state": c.limit_state,
        "method": str(c.method),
        "location": str(c.location),
        "demand": _number(c.demand),
        "capacity": _number(c.capacity),
        "unit": c.unit,
        "ratio": c.ratio,
        "passed": c.passed,
        "clause": f"{CIRCOLARE[edition]} {c.clause}",
        "note": c.note,
        "demand_damping": None if sp is None else sp.damping,
        "demand_period": None if sp is None else sp.period,
        "demand_period_range": None
        if sp is None or sp.period_range is None
        else list(sp.period_range),
        "demand_spectral": None if sp is None else sp.value,
        "demand_at_secant": None if sp is None else sp.at_secant,
        "demand_rule": None if sp is None else sp.rule,
    }


def kinematic_document(
    name: str,
    result: KinematicResult,
    warnings: tuple[str, ...] = (),
    mechanism: str | None = None,
) -> dict[str, Any]:
    """The whole `rock kinematic --format json` document (schema 1): the top-level keys are the
    governing mechanism's (or ``mechanism``'s, by name), ``mechanisms`` lists every one of the
    catalogue, the governing first, and ``governing`` names it."""
    chosen = chosen_result(result, mechanism)
    doc = mechanism_document(name, chosen, warnings)
    if result.catalogue:
        doc["mechanisms"] = [catalogue_entry(m) for m in result.catalogue]
        doc["governing"] = result.governing
        doc["mechanism"] = chosen.mechanism or result.governing
        shown = next(m for m in result.catalogue if m.name == doc["mechanism"])
        doc["T_Rc"] = shown.T_Rc
        doc["T_Rc_hazard"] = hazard_document(shown.hazard if shown.T_Rc else None)
    return doc


def hazard_document(curve) -> dict[str, Any] | None:
    """The hazard curve T_Rc was read on: where its points come from ("grid": the hazard
    grid at the site; "model": the ag of the model's [ntc.demand.*] at their return periods),
    their return periods [years] and ag [g]."""
    if curve is None:
        return None
    return {"source": curve.source, "TR": list(curve.periods), "ag": list(curve.im)}


def chosen_result(result: KinematicResult, mechanism: str | None) -> KinematicResult:
    """The result of the mechanism named (InputError naming the catalogue when unknown)."""
    from rockcli.analyses.catalogue import named

    return result if mechanism is None else named(result.catalogue, mechanism).result


def catalogue_entry(m: Any) -> dict[str, Any]:
    """One mechanism of the catalogue: what it is, its oscillator, its checks and ζ_E."""
    r = m.result
    return {
        "name": m.name,
        "type": m.type,
        "hinge_height": m.hinge_height,
        "storey": m.storey,
        "side": r.side,
        "alpha0": r.alpha0,
        "alpha0_by_side": r.alpha0_by_side,
        "M_star": m.M_star,
        "e_star": r.e_star,
        "a0_star": r.a0_star,
        "d0_star": r.d0_star,
        "zeta": {"DLS": m.zeta_dls, "ULS": m.zeta_uls},
        "T_Rc": m.T_Rc,
        "virtual_work": [work_document(t) for t in r.work_by_side.get(str(r.side), ())],
        "checks": [check_document(c, r.edition) for c in r.checks],
        "verdict": r.verdict(),
        "notes": list(r.notes),
        "friction": friction_document(m.friction),
        **arch_document(m.arch),
    }


def arch_document(arch: Any) -> dict[str, Any]:
    """A horizontal flexure's arch: its thrust H [kN] and stress block depth a [m] (the two
    numbers a checker looks for), its span and strip [m]; nothing for another type."""
    if arch is None:
        return {}
    return {"thrust_kN": arch.thrust / 1e3, "stress_block_depth": arch.depth,
            "span": arch.span, "strip_height": arch.strip}  # fmt: skip


def friction_document(friction: Any) -> dict[str, Any] | None:
    """The toothed return walls' friction on a mechanism: F of one wall [kN], its lever above
    the hinge (h/3) [m], the walls, the toothed height h [m] and its courses n."""
    if friction is None:
        return None
    return {"F_kN": friction.force / 1e3, "lever": friction.lever, "walls": friction.walls,
            "height": friction.height, "n": friction.courses}  # fmt: skip


def work_document(t: WorkTerm) -> dict[str, Any]:
    """One item of α0's virtual work (codecheck.result.WorkTerm) in kN, m and kN·m: α0 =
    Σ resisting_kNm / Σ overturning_kNm over the items of a side."""
    it = t.item
    return {"item": str(it.name), "kind": it.kind, "weight_kN": it.force / 1e3, "x": it.x,
            "z": it.z, "dx": it.dx, "dy": it.dy, "resisting_kNm": t.resisting / 1e3,
            "overturning_kNm": t.overturning / 1e3}  # fmt: skip


def mechanism_document(
    name: str, result: KinematicResult, warnings: tuple[str, ...] = ()
) -> dict[str, Any]:
    """The document of one mechanism's result (today's top-level keys)."""
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "model": {"name": name},
        "edition": result.edition,
        "side": result.side,
        "alpha0": result.alpha0,
        "alpha0_by_side": result.alpha0_by_side,
        "e_star": result.e_star,
        "a0_star": result.a0_star,
        "FC": result.FC,
        "FC_rule": result.FC_rule,
        "d0_star": result.d0_star,
        **{k: _number(v) for k, v in result.quantities.items()},
        "linear_curve": result.linear_curve,
        "checks": [check_document(c, result.edition) for c in result.checks],
        "curve": list(result.curve),
        "demand": result.demand,
        "notes": list(result.notes),
        "warnings": list(warnings),
        "verdict": result.verdict(),
        "restrainer_actions": [action_document(a) for a in result.restrainer_actions],
    }


def action_document(a: RestrainerAction) -> dict[str, Any]:
    """How one restrainer entered the check and its verification, SI units (N)."""
    return {
        "name": a.name,
        "code_action": a.code_action,
        "force": a.force,
        "strength": _number(a.strength),
        "demand": a.demand,
        "demand_at": a.demand_at,
        "utilisation": _number(a.utilisation),
        "lost": a.lost,
        "passed": a.passed,
        "clause": a.clause,
        "lost_at_d_star": a.lost_at_d_star,
        "slack": a.slack,
    }


CHECK_COLUMNS = (
    Column("limit_state", "LS"),
    Column("method", "method"),
    Column("location", "at"),
    Column("demand", "demand", "", "{:.5g}"),
    Column("capacity", "capacity", "", "{:.5g}"),
    Column("unit", "unit"),
    Column("ratio", "ζ = C/D", "", "{:.3f}", short="ζ"),
    Column("passed", "ok"),
    Column("clause_short", "clause"),
)
CURVE_COLUMNS = (
    Column("theta", "θ", "rad", "{:.5f}"),
    Column("d_star", "d*", "m", "{:.5f}"),
    Column("alpha", "α", "", "{:.5f}"),
    Column("alpha_sure", "α sure", "", "{:.5f}"),
    Column("a_star", "a*", "m/s²", "{:.4f}"),
)
#: The code spectrum's numbers per limit state (NTC 2018 §3.2.3.2.1).
SPECTRUM_COLUMNS = (
    Column("limit_state", "LS"),
    Column("TR", "TR", "years", "{:.0f}"),
    Column("ag", "ag", "g", "{:.4f}"),
    Column("F0", "F0", "", "{:.3f}"),
    Column("Tc_star", "Tc*", "s", "{:.3f}"),
    Column("S", "S", "", "{:.3f}"),
    Column("TB", "TB", "s", "{:.3f}"),
    Column("TC", "TC", "s", "{:.3f}"),
    Column("TD", "TD", "s", "{:.3f}"),
    Column("source", "source", align="left"),
)
#: A record as the demand of each limit state.
RECORD_COLUMNS = (
    Column("limit_state", "LS"),
    Column("record", "record", align="left"),
    Column("PGA", "PGA", "g", "{:.4f}"),
    Column("source", "source", align="left"),
)
#: The restrainers in the check (forces in kN on the terminal, N in the JSON).
ACTION_COLUMNS = (
    Column("name", "restrainer"),
    Column("code_action", "action"),
    Column("force_kN", "force in α0", "kN", "{:.4g}"),
    Column("demand_kN", "demand", "kN", "{:.4g}"),
    Column("strength_kN", "strength", "kN", "{:.4g}"),
    Column("utilisation", "use", "", "{:.3f}"),
    Column("lost_at_d_star", "lost at d*", "m", "{:.4g}"),
    Column("passed", "ok"),
)
#: N → kN for the terminal.
KILO = 1e3


def actions_table(actions: list[dict[str, Any]]) -> Table:
    """ "Restrainers in the check": each restrainer's action, force, demand and strength."""
    rows = tuple(
        {
            **a,
            "force_kN": a["force"] / KILO,
            "demand_kN": None if a["demand"] is None else a["demand"] / KILO,
            "strength_kN": None if a["strength"] is None else a["strength"] / KILO,
        }
        for a in actions
    )
    return Table("Restrainers in the check", ACTION_COLUMNS, rows)


def action_notes(actions: list[dict[str, Any]]) -> list[str]:
    """Where each spring's demand is read (a force's is itself), and which member is lost
    before it."""
    out = [
        f"{a['name']}: {a['code_action']}, demand at {a['demand_at']} ({a['clause']})"
        if a["demand"] is not None
        else f"{a['name']}: {a['code_action']}, demand not evaluated: {a['demand_at']}"
        for a in actions
        if a["code_action"] != "force"
    ]
    out += [f"{a['name']}: lost (rupture) before {a['demand_at']}" for a in actions if a["lost"]]
    return out


QUANTITIES = {
    "du_star": ("ultimate displacement du*", "m"),
    "ds_star": ("ds* = 0.4 du*", "m"),
    "as_star": ("as* = a*(ds*)", "m/s²"),
    "Ts": ("secant period Ts", "s"),
    "d_SLV": ("d_SLV", "m"),
    "T_SLV": ("T_SLV", "s"),
    "d_SLC": ("d_SLC", "m"),
    "T_SLC": ("T_SLC", "s"),
    "ag_SLD": ("capacity ag,SLD", "g"),
    "T0": ("T0, free to vibrate [C8.7.1.7]", "s"),
    "d_y": ("d_y, end of the elastic branch", "m"),
    "a_y": ("a_y, end of the elastic branch", "m/s²"),
}


#: The code texts of each edition, as the reports name them.
EDITION_TEXT = {"2009": "NTC 2008 + Circ. 617/2009", "2019": "NTC 2018 + Circ. 7/2019"}


SUMMARY_COLUMNS = (
    Column("name", "mechanism", align="left"),
    Column("hinge_height", "hinge", "m", "{:.3g}"),
    Column("alpha0", "α0", "", "{:.4f}"),
    Column("M_star_t", "M*", "t", "{:.4g}"),
    Column("e_star", "e*", "", "{:.3f}"),
    Column("a0_star", "a0*", "m/s²", "{:.3f}"),
    Column("d0_star", "d0*", "m", "{:.4f}"),
    Column("zeta_dls", "ζ_E DLS", "", "{:.3f}", short="ζ DLS"),
    Column("zeta_uls", "ζ_E ULS", "", "{:.3f}", short="ζ ULS"),
    Column("verdict_text", "DLS/ULS", align="left"),
)


def summary_table(doc: dict[str, Any]) -> Table:
    """The catalogue in one table, the governing mechanism first."""
    rows = tuple(
        {
            **m,
            "M_star_t": m["M_star"] / KILO,
            "zeta_dls": m["zeta"]["DLS"],
            "zeta_uls": m["zeta"]["ULS"],
            "verdict_text": short_verdict(m["verdict"]),
        }
        for m in doc["mechanisms"]
    )
    return Table("Mechanisms (governing first)", SUMMARY_COLUMNS, rows)


def short_verdict(verdict: dict[str, bool | None]) -> str:
    """'ok/fails': the DLS and ULS verdicts in a few letters (n/e: not evaluated)."""
    word = {True: "ok", False: "fails", None: "n/e"}
    return "/".join(word[verdict[ls]] for ls in ("DLS", "ULS"))


def catalogue_reports(doc: dict[str, Any], all_mechanisms: bool) -> list[Report]:
    """The summary, then the detail of the mechanism shown (or of every one, ``all``)."""
    if len(doc.get("mechanisms", ())) < 2:
        return [kinematic_report(doc)]
    first = kinematic_report(doc)
    governing = f"governing mechanism: {doc['governing']}"
    shown = f"{governing}; detail below: {doc['mechanism']}"
    head = Report(
        title=f"rock kinematic — {doc['model']['name']}",
        tables=(summary_table(doc),),
        notes=(
            shown,
            "ζ_E = capacity/demand of the deciding checks (< 1: not satisfied); "
            "DLS/ULS: the verdicts (n/e: not evaluated)",
        ),
    )
    return [head, first]


def return_period_notes(T_Rc: dict[str, float] | None,  # noqa: N803
                        hazard: dict[str, Any] | None) -> tuple[str, ...]:  # fmt: skip
    """How T_Rc was read from the site's hazard, and which lie beyond its points."""
    if not T_Rc or not hazard:
        return ()
    from rockcli.codecheck.hazard_curve import TR_BOUNDS

    first, last = hazard["TR"][0], hazard["TR"][-1]
    low, high = TR_BOUNDS
    bound = {low: f"{low:g} year or less, taken as {low:g}",
             high: f"{high:g} years or more, taken as {high:g}"}  # fmt: skip
    outside = [f"{ls} {bound.get(years, f'{years:.4g} years')}" for ls, years in T_Rc.items()
               if not first <= years <= last]  # fmt: skip
    points = (
        f"the grid's points at the site, {first:.4g}–{last:.4g} years"
        if hazard["source"] == "grid"
        else "the ag the model gives each limit state, at its return period: "
        + ", ".join(f"{TR:.4g}" for TR in hazard["TR"])
        + " years ([ntc.site] reads the grid's nine points)"
    )
    text = (
        f"T_Rc: the return period whose ag equals the capacity ag of the limit state's deciding "
        f"checks, on the hazard curve through {points}, log–log between them as Allegato A "
        "interpolates"
    )
    if outside:
        text += (f"; beyond {first:.4g}–{last:.4g} years, extrapolated with the power law of "
                 "the end segment: " + ", ".join(outside))  # fmt: skip
    return (text,)


def kinematic_report(doc: dict[str, Any]) -> Report:
    """The terminal report of a kinematic document."""
    edition = EDITION_TEXT[doc["edition"]]
    items = [
        ("edition", edition, "", ""),
        ("side of overturning", "θ > 0" if doc["side"] > 0 else "θ < 0", "", ""),
        ("load multiplier α0", doc["alpha0"], "", "{:.5f}"),
        *_alpha0_by_side(doc),
        ("participating mass fraction e*", doc["e_star"], "", "{:.4f}"),
        ("confidence factor FC", doc["FC"], "", "{:.3g}"),
        ("activation acceleration a0*", doc["a0_star"], "m/s²", "{:.4f}"),
        ("d0* (a* = 0)", doc["d0_star"], "m", "{:.5f}"),
        *(
            (label, doc[key], unit, "{:.5g}")
            for key, (label, unit) in QUANTITIES.items()
            if key in doc
        ),
        *(
            (f"return period of the capacity T_Rc,{ls}", years, "years", "{:.4g}")
            for ls, years in (doc.get("T_Rc") or {}).items()
        ),
    ]
    demand = demand_table(doc["demand"])
    actions = doc.get("restrainer_actions", [])
    tables = (
        key_value("Mechanism and equivalent oscillator", items),
        Table("Capacity curve", CURVE_COLUMNS, tuple(doc["curve"])),
        demand,
        Table(
            f"Checks ({CIRCOLARE[doc['edition']]})",
            CHECK_COLUMNS,
            tuple({**c, "clause_short": c["clause"].split(" ")[-1]} for c in doc["checks"]),
        ),
        *((actions_table(actions),) if actions else ()),
    )
    notes = [
        *doc["notes"],
        *return_period_notes(doc.get("T_Rc"), doc.get("T_Rc_hazard")),
        *action_notes(actions),
        *(
            f"demand {demand_line(ls, numbers, spectral=True)}"
            for ls, numbers in doc["demand"].items()
            if numbers.get("spectral_values")
        ),
        *(
            f"{c['limit_state']} {c['method']} {c['location']}: {c['note']}"
            for c in doc["checks"]
            if c["note"]
        ),
    ]
    title = f"rock kinematic — {doc['model']['name']}"
    if "mechanism" in doc and len(doc.get("mechanisms", ())) > 1:
        title = f"{title}: {doc['mechanism']}"
    return Report(
        title=title,
        tables=tables,
        notes=tuple(notes),
        warnings=tuple(doc.get("warnings", ())),
        verdict=verdict_line(doc["edition"], doc["verdict"]),
    )


def _alpha0_by_side(doc: dict[str, Any]) -> list[tuple[str, Any, str, str]]:
    """α0 towards each side, when loads or thrusts make them differ."""
    by_side = doc.get("alpha0_by_side", {})
    if len(set(by_side.values())) < 2:
        return []
    text = f"{by_side['1']:.5f} (θ > 0), {by_side['-1']:.5f} (θ < 0)"
    return [("α0 of each side", text, "", "")]


def demand_table(demand: dict[str, dict[str, Any]]) -> Table:
    """The demand of each limit state as numbers: the code spectrum's, or the record's."""
    rows = tuple({"limit_state": ls, **numbers} for ls, numbers in demand.items())
    is_record = any("record" in row for row in rows)
    return Table("Demand", RECORD_COLUMNS if is_record else SPECTRUM_COLUMNS, rows)


def demand_line(ls: str, numbers: dict[str, Any], spectral: bool = False) -> str:
    """One limit state's demand in a sentence: "SLV ag 0.15 g, F0 2.5, Tc* 0.3 s, S 1.2 …";
    a record's name and PGA, and with ``spectral`` its spectrum where the checks read it."""
    if "record" in numbers:
        values = "".join(
            f", Se({v['at']}: T = {v['T']:.4g} s, ξ = {v['damping']:g} %) {v['Se']:.4g} g, "
            f"SDe {v['SDe']:.4g} m"
            for v in (numbers.get("spectral_values", ()) if spectral else ())
        )
        return f"{ls} record {numbers['record']}, PGA {numbers['PGA']:.4g} g{values}"
    tr = "" if numbers["TR"] is None else f"TR {numbers['TR']:.0f} years, "
    return (
        f"{ls} {tr}ag {numbers['ag']:.4g} g, F0 {numbers['F0']:.4g}, "
        f"Tc* {numbers['Tc_star']:.4g} s, S {numbers['S']:.4g} ({numbers['source']})"
    )


#: The limit states the verdict line names, once each: 2019 names SLD, SLV and SLC (DLS is
#: SLD and ULS is SLV with SLC, so naming them too would say each twice).
VERDICT_STATES = {"2009": ("DLS", "ULS"), "2019": ("SLD", "SLV", "SLC")}
#: Limit states whose "not evaluated" the ultimate displacement decides.
ULTIMATE_STATES = frozenset({"ULS", "SLV", "SLC"})
#: What makes a non-linear ULS check evaluable (codecheck.result.deciding).
ULTIMATE_FIX = "set ntc.ultimate_displacement or a restrainer's fails_at"


def verdict_line(edition: str, verdict: dict[str, bool | None]) -> str:
    """ "DLS satisfied, ULS NOT satisfied": each limit state of the edition once."""
    states = [ls for ls in VERDICT_STATES[edition] if ls in verdict]
    line = ", ".join(f"{ls} {_word(verdict[ls])}" for ls in states)
    if any(verdict[ls] is None for ls in states if ls in ULTIMATE_STATES):
        line += f" ({ULTIMATE_FIX})"
    return line


def _word(value: bool | None) -> str:
    return "not evaluated" if value is None else ("satisfied" if value else "NOT satisfied")
