"""The code's kinematic check as a report shows it, wherever its demand comes from (the site's
spectra, a record's, a suite's target): the demand's spectra and the values the check read,
the check's tables (every mechanism, α0 by virtual work per pivot, the oscillator, the checks,
the displacement demands, the restrainers' actions), ζ_E per limit state, and a figure as the
report holds it. The sections that put these in order are the callers' (document.build,
document.verification, document.suite).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from rockcli.document.content import Block, Figure, Grid, Paragraph, Section
from rockcli.document.words import Words

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MplFigure

    from rockcli.codecheck.position import Position
    from rockcli.codecheck.result import KinematicResult
    from rockcli.model.schema import Model
    from rockcli.records.record import Record

#: The limit states of the code's verdict per edition (2019's verdict also sums them up as
#: DLS and ULS, which the report does not repeat).
VERDICT_STATES = {"2009": ("DLS", "ULS"), "2019": ("SLD", "SLV", "SLC")}

#: The limit states of the verdict, in order (both editions' names).
STATES = ("SLD", "SLV", "SLC", "DLS", "ULS")


def risk_indices(kin: Mapping[str, Any]) -> list[tuple[str, float | None, bool | None]]:
    """(limit state, ζ_E, its verdict) per limit state of the check: ζ_E the smallest
    capacity/demand of the checks that decide the state's verdict — the non-linear ones where
    the analysis has them, else the linear ones (rockcli.codecheck.result.deciding) — and the
    verdict as the kinematic document gives it."""
    out = []
    verdicts = kin.get("verdict", {})
    for state in STATES:
        checks = [c for c in kin.get("checks", ()) if c.get("limit_state") == state]
        if not checks:
            continue
        nonlinear = [c for c in checks if c.get("method") == "nonlinear"]
        ratios = [c["ratio"] for c in nonlinear or checks if c.get("ratio") is not None]
        out.append((state, min(ratios) if ratios else None, verdicts.get(state)))
    return out


def floor_figure(
    code: Sequence[tuple[str, Any]], pos: Position, edition: str, shaking: Record | None,
    record_name: str, g: float, marks: Mapping[str, float], w: Words, rocked: str = "",
    of_record: bool = False,
) -> Figure:  # fmt: skip
    """The spectra at the mechanism's height (figures.floor_spectra): the code's demand there
    per limit state, and the response spectrum of the floor motion ``shaking`` the rocking
    analysis used (None: it used the record itself, --ground, whose spectrum is at the ground;
    ``rocked``: the caption's key for what was rocked, when the caller says it instead;
    ``of_record``: the ground spectra are a record's, to which the check applied the code's
    at-height rule)."""
    from rockcli.codecheck import rules2019
    from rockcli.codecheck.response import RecordSpectrum
    from rockcli.document.figures import floor_spectra

    n = w.number
    motion = None if shaking is None else RecordSpectrum.from_record(shaking, g=g)
    damping = ", ".join(f"{n(xi, '{:g}')} % {ls}" for ls, xi in rules2019.DAMPING.items())
    key = f"figure.floor_caption_{edition}" if not of_record else "figure.floor_caption_record"
    where = w(key, Z=n(pos.Z, "{:g}"), T1=n(pos.T1, "{:.3g}"),
              psi=n(pos.psi, "{:.3g}"), gamma=n(pos.gamma, "{:.3g}"),
              xi_k=n(100.0 * pos.damping, "{:g}"), damping=damping)  # fmt: skip
    rocked = rocked or (
        "figure.floor_caption_motion" if motion is not None else "figure.floor_caption_ground"
    )
    fig = floor_spectra(code, pos, edition, motion, record_name, marks, w)
    return figure("floor_spectra", fig, f"{where} {w(rocked)}")


def code_spectra_of(model: Model, kin: Mapping[str, Any]) -> list[tuple[str, Any, str]]:
    """The code's elastic spectrum of every limit state, with where its ag, F0, Tc* come from:
    the check's own demand when it used the code's spectra, else the model's [ntc.demand]
    (shown for reference beside a record's demand)."""
    from rockcli.codecheck.categories import Soil, Topography
    from rockcli.codecheck.spectra import ElasticSpectrum
    from rockcli.model.derive_ntc import ntc_settings

    settings = ntc_settings(model)
    given = {
        state: (d["ag"], d["F0"], d["Tc_star"], d["source"])
        for state, d in kin["demand"].items()
        if all(d.get(k) for k in ("ag", "F0", "Tc_star"))
    } or {state: (*v, "[ntc.demand]") for state, v in settings.demand.items()}
    return [
        (
            state,
            ElasticSpectrum(ag, F0, Tc, Soil(settings.soil), Topography(settings.topography)),
            source,
        )
        for state, (ag, F0, Tc, source) in given.items()
    ]


def hazard_grid(spectra: Sequence[tuple[str, Any, str]], kin: Mapping[str, Any], w: Words) -> Grid:
    """ag, F0, Tc*, S, TB, TC, TD of each limit state's code spectrum (TR when known)."""
    rows = []
    for state, sp, source in spectra:
        TR = kin["demand"].get(state, {}).get("TR")
        rows.append((state, w.number(TR, "{:.0f}"), w.number(sp.ag, "{:.4f}"),
                     w.number(sp.F0, "{:.3f}"), w.number(sp.Tc_star, "{:.3f}"),
                     w.number(sp.S, "{:.3f}"), w.number(sp.TB, "{:.3f}"),
                     w.number(sp.TC, "{:.3f}"), w.number(sp.TD, "{:.3f}"),
                     w.note(source)))  # fmt: skip
    headers = (w("col.limit_state"), "TR [a]", "ag [g]", "F0", "Tc* [s]", "S", "TB [s]",
               "TC [s]", "TD [s]", w("col.source"))  # fmt: skip
    return Grid(w("demand.hazard_caption"), headers, tuple(rows), (False, *([True] * 8), False))


def record_demand_grids(
    demand: Mapping[str, Any], w: Words, caption: str = "demand.spectral_caption"
) -> list[Block]:
    """The ground spectrum's values the check used, per limit state (at height, at T1, where
    the floor spectra are made from it: analyses.capacity_check.with_spectral_values)."""
    rows = [
        (state, w.note(s["at"]), w.number(s["T"]), w.number(s["damping"], "{:g}"),
         w.number(s["Se"]), w.number(s["SDe"]))
        for state, d in demand.items()
        for s in d.get("spectral_values", [])
    ]  # fmt: skip
    if not rows:
        return []
    headers = (w("col.limit_state"), w("col.at"), "T [s]", w("col.damping"), "Se [g]", "SDe [m]")
    return [Grid(w(caption), headers, tuple(rows),
                 (False, False, True, True, True, True))]  # fmt: skip


# --- kinematic analysis ---------------------------------------------------------------------


def kinematic_section(
    result: KinematicResult, kin: Mapping[str, Any], w: Words, catalogue: bool = True
) -> Section:
    """The code's check of the mechanism shown (``catalogue``: with the table of every
    mechanism of a wall, which the governing mechanism's section has and the others' need
    not repeat)."""
    from rockcli.document.figures import capacity

    n = w.number
    blocks: list[Block] = [Paragraph(w(f"kin.intro_{kin['edition']}"))]
    if catalogue and len(kin.get("mechanisms", ())) > 1:
        blocks.append(catalogue_grid(kin, w))
    blocks.append(activation_grid(result.activation_by_side, w))
    quantities = [
        ("M*", participating_mass_of(result), "kg", "kin.M_star"),
        ("e*", kin["e_star"], "", "kin.e_star"),
        ("a0*", kin["a0_star"], "m/s²", "kin.a0_star"),
        ("FC", kin["FC"], "", "kin.FC"),
        ("d0*", kin["d0_star"], "m", "kin.d0_star"),
    ]
    for key, unit in (("du_star", "m"), ("ds_star", "m"), ("as_star", "m/s²"), ("Ts", "s"),
                      ("d_SLV", "m"), ("a_SLV", "m/s²"), ("T_SLV", "s"), ("d_SLC", "m"),
                      ("a_SLC", "m/s²"), ("T_SLC", "s")):  # fmt: skip
        if key in kin:
            quantities.append((key.replace("_star", "*"), kin[key], unit, f"kin.{key}"))
    blocks.append(Grid(
        w("kin.quantities_caption"),
        (w("col.symbol"), w("col.quantity"), w("col.value"), w("col.unit")),
        tuple((sym, w(key), n(value), unit) for sym, value, unit, key in quantities),
        (False, False, True, False),
    ))  # fmt: skip
    blocks.append(figure("capacity", capacity(kin, w), w("figure.capacity_caption")))
    blocks.append(checks_grid(kin, w))
    demand = demand_grid(kin, w)
    if demand is not None:
        blocks += [demand, Paragraph(w(f"kin.periods_{kin['edition']}"), "note")]
    if kin.get("restrainer_actions"):
        blocks.append(actions_grid(kin["restrainer_actions"], w))
    blocks += [Paragraph(w.note(note), "note") for note in kin.get("notes", [])]
    blocks += [Paragraph(w.note(text), "warning") for text in kin.get("warnings", [])]
    verdict = kin["verdict"]
    states = VERDICT_STATES[kin["edition"]]
    blocks.append(Paragraph(
        "; ".join(f"{w(f'ls.{state}')}: {w.passed(verdict.get(state))}" for state in states),
        "verdict",
    ))  # fmt: skip
    return Section("kinematic", w("section.kinematic"), tuple(blocks))


def catalogue_grid(kin: Mapping[str, Any], w: Words) -> Grid:
    """Every mechanism of the catalogue in one table: α0, M*, e*, a0*, d0*, ζ_E of DLS and
    ULS, the governing one first (rockcli.analyses.catalogue)."""
    n = w.number
    rows = tuple(
        (w.note(m["name"]), n(m["hinge_height"], "{:.3g}"), n(m["alpha0"]), n(m["M_star"] / 1e3),
         n(m["e_star"], "{:.3f}"), n(m["a0_star"], "{:.3f}"), n(m["d0_star"]),
         n(m["zeta"]["DLS"], "{:.3f}"), n(m["zeta"]["ULS"], "{:.3f}"))
        for m in kin["mechanisms"]
    )  # fmt: skip
    uls = "ζ SLU" if w.lang == "it" else "ζ ULS"
    headers = (w("kin.catalogue_mechanism"), w("kin.catalogue_hinge"), "α0", "M* [t]", "e*",
               "a0* [m/s²]", "d0* [m]", "ζ SLD", uls)  # fmt: skip
    return Grid(w("kin.catalogue_caption", shown=w.note(kin["mechanism"])), headers, rows,
                (False, *([True] * 8)))  # fmt: skip


def participating_mass_of(result: KinematicResult) -> float:
    """M* of the mechanism shown, on the side the check governs (Circolare 617/2009 Eq.
    C8A.4.2; Circolare 7/2019 e*·Σ P/g of Eq. C8.7.1.5), as the check computed it
    (rockcli.analyses.catalogue.MechanismResult.M_star)."""
    from rockcli.model.catalogue import named

    return float(named(result.catalogue, result.mechanism or "").M_star)


def activation_grid(by_side: Mapping[str, Mapping[str, float]], w: Words) -> Grid:
    """α0 by virtual work, term by term, on each side the check looks at, as the check
    computed them (KinematicResult.activation_by_side: codecheck.kinematic.activation_terms,
    the same sums as α0 itself)."""
    rows = []
    for key, terms in by_side.items():
        rows.append((
            "O" if int(key) > 0 else "O′",
            *(w.number(terms[k] / 1e3, "{:.4g}") for k in ("stabilising", "thrusts",
                                                            "restrainers", "overturning")),
            w.number(terms["alpha0"]),
        ))  # fmt: skip
    headers = (w("col.pivot"), w("kin.work_stabilising"), w("kin.work_thrusts"),
               w("kin.work_restrainers"), w("kin.work_overturning"), "α0")  # fmt: skip
    return Grid(w("kin.activation_caption"), headers, tuple(rows), (False, *([True] * 5)))


def checks_grid(kin: Mapping[str, Any], w: Words) -> Grid:
    rows = tuple(
        (w(f"ls.{c['limit_state']}"), w(f"kin.method_{c['method']}"), w(f"where.{c['location']}"),
         w.number(c["demand"]), w.number(c["capacity"]), c["unit"], w.number(c["ratio"], "{:.3f}"),
         w.passed(c["passed"]), w.note(c["clause"]))
        for c in kin["checks"]
    )  # fmt: skip
    headers = (w("col.limit_state"), w("col.method"), w("col.location"), w("col.demand"),
               w("col.capacity"), w("col.unit"), "ζ", w("col.outcome"),
               w("col.clause"))  # fmt: skip
    return Grid(w("kin.checks_caption"), headers, rows,
                (False, False, False, True, True, False, True, False, False))  # fmt: skip


def demand_grid(kin: Mapping[str, Any], w: Words) -> Grid | None:
    """Where each displacement check read the spectrum: damping, period range, the period used
    and the spectral displacement there (None: no displacement check was evaluated)."""
    n = w.number
    rows = tuple(
        (w(f"ls.{c['limit_state']}"), w(f"where.{c['location']}"), n(c["demand_damping"], "{:g}"),
         "—" if c["demand_period_range"] is None
         else f"[{n(c['demand_period_range'][0], '{:g}')}; {n(c['demand_period_range'][1])}]",
         n(c["demand_period"]), n(c["demand_spectral"], "{:.5g}"),
         w("kin.rule_range" if c["demand_period_range"] else "kin.rule_period"))
        for c in kin["checks"]
        if c.get("demand_period") is not None
    )  # fmt: skip
    if not rows:
        return None
    headers = (w("col.limit_state"), w("col.location"), w("col.damping"), w("col.period_range"),
               w("col.period"), w("col.spectral_displacement"), w("col.rule"))  # fmt: skip
    return Grid(w("kin.demand_caption"), headers, rows,
                (False, False, True, True, True, True, False))  # fmt: skip


def actions_grid(actions: Sequence[Mapping[str, Any]], w: Words) -> Grid:
    n = w.number
    rows = tuple(
        (a["name"], w(f"model.action_{a['code_action']}"), n(kilonewtons(a["demand"])),
         n(kilonewtons(a["strength"])), n(a["utilisation"], "{:.3f}"), w.yes_no(a["lost"]),
         w.passed(a["passed"]), w.note(a["clause"]))
        for a in actions
    )  # fmt: skip
    headers = (w("col.name"), w("col.code_action"), w("col.demand_kn"), w("col.strength_kn"),
               w("col.utilisation"), w("col.lost"), w("col.outcome"), w("col.clause"))  # fmt: skip
    return Grid(w("kin.actions_caption"), headers, rows,
                (False, False, True, True, True, False, False, False))  # fmt: skip


def kilonewtons(force: float | None) -> float | None:
    return None if force is None else force / 1e3


def figure(key: str, fig: MplFigure, caption: str) -> Figure:
    from rockcli.document.figures import rendered

    svg, png = rendered(fig)
    return Figure(key, svg, caption, png)
