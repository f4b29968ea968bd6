"""The verification a report files: the code's kinematic check of every mechanism on the
site's (or the model's) NTC spectra, the site's action, and the conclusions the assessment of
an existing building draws from it (NTC 2018 §8.3).

A record (``rock report --record``) never replaces this: it adds a scenario, its own sections
after these (rockcli.document.build), and the conclusions say what it adds.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rockcli.document.code_check import risk_indices
from rockcli.document.content import Block, Grid, Paragraph, Section
from rockcli.document.words import Words

if TYPE_CHECKING:
    from rockcli.codecheck.result import KinematicResult
    from rockcli.model.schema import Model


@dataclass(frozen=True)
class Verification:
    """The code check of a wall on the spectra the law asks for.

    Attributes:
        result: the kinematic analysis of the catalogue (the governing mechanism's result,
            the whole catalogue in it). doc: its `rock kinematic --format json` document.
        demand: "site" ([ntc.site] on the hazard grid) or "model" ([ntc.demand.*]).
        use_class: the building's use class ("I"–"IV"; None: CU is not one of Tab. 2.4.II's).
        required: the limit states NTC 2018 §8.3 requires for that class.
        mechanisms: the model's catalogue as derived (rockcli.model.catalogue), which the
            check read.
    """

    result: KinematicResult
    doc: Mapping[str, Any]
    demand: str
    use_class: str | None
    required: tuple[str, ...]
    mechanisms: tuple[Any, ...] = ()


def demand_kind(model: Model) -> str:
    """ "site" when the model's spectra come from a site on the hazard grid, else "model"."""
    return "site" if model.ntc is not None and model.ntc.site is not None else "model"


def zeta_by_state(kin: Mapping[str, Any]) -> dict[str, float | None]:
    """ζ_E of each limit state the check evaluated (rockcli.document.code_check.risk_indices)."""
    return {state: ratio for state, ratio, _ in risk_indices(kin)}


def site_section(model: Model, ver: Verification, w: Words) -> Section:
    """The site's seismic action: the hazard and the spectrum's parameters per limit state,
    the spectra, and at height the floor spectra the check read (the check's own rule)."""
    from rockcli.document.code_check import (
        code_spectra_of,
        figure,
        floor_figure,
        hazard_grid,
        record_demand_grids,
    )
    from rockcli.document.figures import spectra

    kin = ver.doc
    code_spectra = code_spectra_of(model, kin)
    code = [(state, sp) for state, sp, _ in code_spectra]
    marks = {"Ts": kin["Ts"]} if kin.get("Ts") else {}
    pos = ver.result.position
    assert pos is not None  # every catalogue check sets it (analyses.catalogue)
    blocks: list[Block] = [
        Paragraph(w(f"verify.site_intro_{ver.demand}")),
        hazard_grid(code_spectra, kin, w),
        figure("spectra", spectra(code, None, "", marks, w),
               w("verify.spectra_ground_caption" if pos.at_height else "verify.spectra_caption")),
    ]  # fmt: skip
    if pos.at_height:
        blocks += record_demand_grids(kin["demand"], w, "verify.spectral_caption")
        blocks.append(floor_figure(code, pos, kin["edition"], None, "", model.analysis.g, marks,
                                   w, rocked="verify.floor_caption"))  # fmt: skip
    return Section("demand", w("section.site"), tuple(blocks))


def verification_sections(model: Model, ver: Verification, w: Words) -> list[Section]:
    """The site's action and the kinematic check on it (the report's verification)."""
    from rockcli.document.code_check import kinematic_section

    check = kinematic_section(ver.result, ver.doc, w)
    intro = Paragraph(w(f"verify.kin_intro_{ver.demand}"))
    check = Section(check.key, w("section.verification"), (intro, *check.blocks))
    return [site_section(model, ver, w), check, virtual_work_section(ver.doc, w)]


def virtual_work_section(kin: Mapping[str, Any], w: Words) -> Section:
    """α0 of every mechanism by virtual work, item by item: one table each, whose sums are α0's
    numerator and denominator (Circ. 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.1)."""
    blocks: list[Block] = [Paragraph(w("verify.work_intro"))]
    blocks += [work_grid(m, w) for m in kin.get("mechanisms", ())]
    return Section("virtual-work", w("section.virtual_work"), tuple(blocks))


#: The names the catalogue gives its bodies and a flexure's overburden
#: (rockcli.mechanisms.catalogue), and their key in the report's words; any other load's, a
#: thrust's and a restrainer's name is the model's own.
BODY_NAMES = {"gable": "body.gable", "wedge (both return walls)": "body.wedge_both",
              "wedge (one return wall)": "body.wedge_one", "lower block": "body.lower",
              "upper block": "body.upper", "block": "body.block",
              "the wall above": "body.above",
              "friction of the return walls": "body.friction", "half strip": "body.half_strip",
              "other half strip": "body.other_half_strip", "arch thrust": "body.arch_thrust",
              "roof": "body.roof", "corner wedge": "body.corner"}  # fmt: skip


#: The thrusts the catalogue names itself (a model's thrust keeps the model's name).
OWN_THRUSTS = {"hip beam thrust": "body.hip_thrust"}


def item_name(t: Mapping[str, Any], w: Words) -> str:
    """An item of the virtual-work table as the report's language names it."""
    name = str(t["item"])
    if t["kind"] == "thrust" and name in OWN_THRUSTS:
        return w(OWN_THRUSTS[name])
    if t["kind"] not in ("body", "load", "friction"):
        return name
    if t["kind"] == "body" and name.startswith("storey ") and name[7:].isdigit():
        return w("body.storey", n=name[7:])
    if t["kind"] == "body" and name.startswith("piers (") and name[7:-1].isdigit():
        return w("body.piers", n=name[7:-1])
    return w(BODY_NAMES[name]) if name in BODY_NAMES else name


def work_grid(m: Mapping[str, Any], w: Words) -> Grid:
    """One mechanism's virtual work on the side of its α0, with the sums and their ratio."""
    n = w.number
    terms = m["virtual_work"]
    rows = [
        (item_name(t, w), w(f"verify.kind_{t['kind']}"), n(t["weight_kN"], "{:.3f}"),
         n(t["x"], "{:.4f}"), n(t["z"], "{:.4f}"), n(t["dx"], "{:.4f}"), n(t["dy"], "{:.4f}"),
         n(t["resisting_kNm"], "{:.4f}"), n(t["overturning_kNm"], "{:.4f}"))
        for t in terms
    ]  # fmt: skip
    up = sum(t["resisting_kNm"] for t in terms)
    down = sum(t["overturning_kNm"] for t in terms)
    rows.append((w("verify.work_sum"), "", "", "", "", "", "", n(up, "{:.4f}"),
                 n(down, "{:.4f}")))  # fmt: skip
    pivot = "O" if m["side"] > 0 else "O′"
    caption = w("verify.work_caption", name=w.note(m["name"]), pivot=pivot,
                alpha0=n(m["alpha0"], "{:.5f}"), up=n(up, "{:.4f}"),
                down=n(down, "{:.4f}"))  # fmt: skip
    headers = (w("verify.work_item"), w("verify.work_kind"), "P, F [kN]", "x [m]", "z [m]",
               "δx [m/rad]", "δy [m/rad]", w("verify.work_resisting"),
               w("verify.work_overturning"))  # fmt: skip
    return Grid(caption, headers, tuple(rows), (False, False, *([True] * 7)))


def state_outcome(ver: Verification, state: str) -> tuple[bool | None, list[str]]:
    """A limit state over every mechanism of the catalogue: False with the mechanisms that
    fail it, None (not evaluated for one, none failing), or True."""
    mechanisms = ver.doc.get("mechanisms") or [ver.doc]
    verdicts = [(m.get("name") or "", m["verdict"].get(state)) for m in mechanisms]
    failing = [name for name, passed in verdicts if passed is False]
    if failing:
        return False, failing
    return (None if any(passed is None for _, passed in verdicts) else True), []


def outcome(ver: Verification, states: Sequence[str] | None = None) -> str:
    """The verification over the limit states required (``states``: those only): "fails"
    when a mechanism fails one, "unknown" when one is not evaluated for a mechanism, else
    "passes"."""
    results = [state_outcome(ver, s)[0] for s in (ver.required if states is None else states)]
    if False in results:
        return "fails"
    return "unknown" if None in results else "passes"


def verification_blocks(ver: Verification, w: Words) -> tuple[list[Block], str]:
    """The conclusions of the verification: the governing mechanism, ζ_E per limit state on
    the site's spectra (the governing mechanism's) with what §8.3 requires for the use class,
    the verdict over every mechanism of the catalogue; and the outcome (:func:`outcome`)."""
    kin = ver.doc
    n = w.number
    blocks: list[Block] = []
    if kin.get("governing"):
        blocks.append(Paragraph(w("verify.governing", name=w.note(kin["governing"]))))
    zeta = zeta_by_state(kin)
    verdicts = {state: passed for state, _, passed in risk_indices(kin)}
    periods = kin.get("T_Rc") or {}
    rows = tuple(
        (w(f"ls.{state}"), n(ratio, "{:.3f}"),
         *((n(periods.get(state), "{:.4g}"),) if periods else ()),
         w.passed(verdicts.get(state)), w.yes_no(state in ver.required))
        for state, ratio in zeta.items()
    )  # fmt: skip
    headers = (w("concl.state"), "ζ_E", *((w("risk.period"),) if periods else ()),
               w("concl.verdict"), w("verify.required"))  # fmt: skip
    caption = w("verify.zeta_caption", demand=w(f"verify.demand_{ver.demand}"))
    if periods:
        caption += w("verify.period_caption")
    blocks.append(Grid(caption, headers, rows,
                       (False, True, *((True,) if periods else ()), False, False)))  # fmt: skip
    blocks.append(Paragraph(required_sentence(ver, w)))
    others = [s for s in zeta if s not in ver.required and state_outcome(ver, s)[0] is False]
    if others:
        blocks.append(Paragraph(w("verify.not_required_fails",
                                  states=", ".join(w(f"ls.{s}") for s in others))))  # fmt: skip
    result = outcome(ver)
    if result == "fails":
        said = []
        for s in ver.required:
            passed, names = state_outcome(ver, s)
            if passed is False:
                listed = ", ".join(f"'{w.note(name)}'" for name in names)
                said.append(f"{w(f'ls.{s}')} ({listed})")
        blocks.append(Paragraph(w("verify.fails", states="; ".join(said)), "verdict"))
    elif result == "unknown":
        blocks.append(Paragraph(w("verify.unknown"), "warning"))
    else:
        blocks.append(Paragraph(w("verify.passes"), "verdict"))
    return blocks, result


def required_sentence(ver: Verification, w: Words) -> str:
    """What §8.3 requires of an existing building of the model's use class, in a sentence."""
    states = ", ".join(w(f"ls.{s}") for s in ver.required)
    if ver.use_class is None:
        return w("verify.required_unknown_class", states=states)
    return w("verify.required_class", use_class=ver.use_class, states=states)


def verification_data(ver: Verification) -> dict[str, Any]:
    """The verification as the report's data carries it (rock-data ``verification``)."""
    return {
        "governing": ver.doc.get("governing") or ver.doc.get("mechanism"),
        "demand": ver.demand,
        "zeta_E": zeta_by_state(ver.doc),
        "use_class": ver.use_class,
        "required": list(ver.required),
        "verdict": {state: passed for state, _, passed in risk_indices(ver.doc)},
    }
