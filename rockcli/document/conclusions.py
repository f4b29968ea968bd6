"""The conclusions of a calculation report: what governs, the risk index per limit state, what
the time history adds, the restrainers' verification and what to do next.

Nothing is computed here that the analyses have not: the risk index of each limit state is
the smallest capacity/demand ratio of the code's checks of that state (the kinematic
document's ``checks``), which is ζ_E = PGA_C/PGA_D of Circ. 7/2019 §C8.3 because the demand of
each check scales with the site's PGA at a given spectral shape; the time history's verdict,
the classification and the restrainers' checks are the comparison's.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.document.code_check import risk_indices
from rockcli.document.content import Block, Grid, Paragraph, Section
from rockcli.document.words import Words


def code_blocks(kin: Mapping[str, Any], w: Words) -> tuple[list[Block], list[str]]:
    """The code's part of the conclusions: the risk index per limit state and the verdict in
    a sentence; and the limit states it fails."""
    indices = risk_indices(kin)
    rows = tuple((state, w.number(ratio, "{:.3f}"), w.passed(passed))
                 for state, ratio, passed in indices)  # fmt: skip
    blocks: list[Block] = []
    if rows:
        blocks.append(Grid(w("concl.zeta_caption"),
                           (w("concl.state"), "ζ_E", w("concl.verdict")), rows,
                           (False, True, False)))  # fmt: skip
    failing = [state for state, _, passed in indices if passed is False]
    states = ", ".join(w(f"ls.{s}") for s in failing)
    blocks.append(Paragraph(w("concl.code_unsafe", states=states) if failing
                            else w("concl.code_safe")))  # fmt: skip
    return blocks, failing


def is_unsafe(doc: Mapping[str, Any]) -> bool:
    """Whether the comparison asks for an intervention: a limit state of the code check of the
    mechanism shown fails, another mechanism fails the ULS, or a mechanism overturns in the
    time history (the one shown or another)."""
    failing = [state for state, _, passed in risk_indices(doc["kinematic"]) if passed is False]
    return bool(failing or unsafe_mechanisms(doc) or overturning_mechanisms(doc)) or (
        doc["rocking"]["verdict"] == "overturns"
    )


def needs_retrofit(doc: Mapping[str, Any]) -> bool:
    """Whether a tie-rod is to be sized (rock retrofit's criteria: the code's ULS and the time
    history; a damage limit state alone is not what a tie-rod is sized for)."""
    uls = [passed for state, _, passed in risk_indices(doc["kinematic"])
           if state in ("SLV", "SLC", "ULS")]  # fmt: skip
    return (False in uls or bool(unsafe_mechanisms(doc) or overturning_mechanisms(doc))
            or doc["rocking"]["verdict"] == "overturns")  # fmt: skip


def unsafe_mechanisms(doc: Mapping[str, Any]) -> list[Mapping[str, Any]]:
    """The wall's mechanisms whose code check fails at the ULS."""
    return [m for m in doc.get("mechanisms", ()) if m["code"].get("ULS") is False]


def overturning_mechanisms(doc: Mapping[str, Any]) -> list[Mapping[str, Any]]:
    """The wall's mechanisms that overturn in the time history."""
    return [m for m in doc.get("mechanisms", ())
            if m.get("rocking") and m["rocking"]["verdict"] == "overturns"]  # fmt: skip


def asks_intervention(
    verification: Any, doc: Mapping[str, Any] | None, states: Sequence[str] | None = None
) -> bool:
    """Whether the report asks for an intervention: a mechanism fails a limit state NTC 2018
    §8.3 requires (``states``: of those, these only) in the verification on the site's
    spectra; without a verification (the model sets no code
    spectrum), the record's comparison fails at the ULS or overturns (:func:`needs_retrofit`;
    the ULS alone, as §8.3 requires of every class but IV). A record's scenario never
    overrules the verification."""
    if verification is not None:
        from rockcli.document.verification import outcome

        return outcome(verification, states) == "fails"
    return doc is not None and needs_retrofit(doc)


def conclusions_section(part: Any, w: Words) -> Section:
    """The conclusions of a wall, in the report's language: the verification on the site's
    spectra and what §8.3 makes of it (rockcli.document.verification), then what the record's
    scenario adds (:func:`scenario_blocks`), what follows, and what rock retrofit found for
    the tie-rod (``part.sizing``: "not needed", a Sizing, or None when not asked)."""
    from rockcli.document.verification import verification_blocks

    blocks: list[Block] = []
    if part.verification is not None:
        blocks += verification_blocks(part.verification, w)[0]
    else:
        blocks.append(Paragraph(w("verify.none"), "warning"))
    if part.doc is not None:
        record = part.doc["rocking"]["record"]["name"]
        key = "scenario.concl_intro" if part.verification is not None else "scenario.concl_only"
        blocks.append(Paragraph(w(key, record=record), "subheading"))
        blocks += scenario_blocks(part.doc, w, single=not part.doc.get("mechanisms"))
    blocks.append(Paragraph(next_sentence(part.verification, part.doc, w)))
    if part.sizing is not None:
        blocks.append(sizing_paragraph(part.sizing, w))
    if part.verification is not None:
        from rockcli.document.risk_class import risk_class_blocks

        blocks += risk_class_blocks(part.verification, w)
    return Section("conclusions", w("section.conclusions"), tuple(blocks))


def next_sentence(verification: Any, doc: Mapping[str, Any] | None, w: Words) -> str:
    """What follows: an intervention, the use continuing, or (a required limit state not
    evaluated) an outcome still to be completed."""
    if verification is None:
        return w("concl.next_unsafe" if asks_intervention(None, doc) else "concl.next_safe")
    from rockcli.document.verification import outcome

    key = {"fails": "unsafe", "passes": "safe"}.get(outcome(verification), "unknown")
    return w(f"verify.next_{key}")


def scenario_blocks(doc: Mapping[str, Any], w: Words, single: bool) -> list[Block]:
    """What the record's comparison says: the code check on the record's spectrum (ζ_E per
    limit state), the rocking, the classification, the restrainers in the time history, the
    mechanisms that fail or overturn; the reference paper's systemic finding only for a
    single block (``single``) of the paper's range (:func:`in_papers_range`)."""
    n = w.number
    rocking = doc["rocking"]
    blocks: list[Block] = []
    if doc.get("mechanisms"):
        blocks.append(Paragraph(w("concl.governing", name=w.note(doc.get("governing") or ""))))
    blocks += code_blocks(doc["kinematic"], w)[0]
    blocks.append(Paragraph(w(f"concl.rocking_{rocking['verdict']}",
                              ratio=n(rocking["max_ratio"], "{:.3f}"))))  # fmt: skip
    blocks.append(Paragraph(w(f"class.{doc['classification']}"), "verdict"))
    if single and in_papers_range(rocking):
        blocks.append(Paragraph(w(f"concl.paper_{doc['classification']}")))
    blocks += [restrainer_sentence(c, w) for c in rocking.get("restrainer_checks", ())]
    others = unsafe_mechanisms(doc)
    if others:
        names = ", ".join(f"'{w.note(m['name'])}'" for m in others)
        blocks.append(Paragraph(w("concl.mechanisms_unsafe", names=names)))
    falling = overturning_mechanisms(doc)
    if falling:
        names = ", ".join(f"'{w.note(m['name'])}'" for m in falling)
        blocks.append(Paragraph(w("concl.mechanisms_overturn", names=names), "warning"))
    return blocks


#: The blocks of the reference paper's systemic study (§3.3, Fig. 8): semi-diagonal R and
#: slenderness α, to 1 % (the altar of its §3.2, R = 1.499 m, is the paper's own case).
PAPER_R_M = (1.5, 10.0)
PAPER_ALPHA_RAD = (0.05, 0.25)
PAPER_TOLERANCE = 0.01


def in_papers_range(rocking: Mapping[str, Any]) -> bool:
    """Whether a rocked element (a `rock assess` document: its ``model`` and ``mechanism``) is
    a block the paper's systemic study covers: a block file's one free-standing rectangular
    block rocking on both sides (not a wall's mechanism; no chain, load, thrust or
    restrainer) with R and α within the study's range, so its 100 cases speak for it."""
    model = rocking["model"]
    if rocking.get("mechanism") is not None or model.get("sides") != "two":
        return False
    if model.get("chain") or model.get("loads") or model.get("thrusts") or model.get("restrainers"):
        return False

    def within(value: float, bounds: tuple[float, float]) -> bool:
        lo, hi = bounds
        return lo * (1 - PAPER_TOLERANCE) <= value <= hi * (1 + PAPER_TOLERANCE)

    return within(model["R"], PAPER_R_M) and within(model["alpha"], PAPER_ALPHA_RAD)


def sizing_paragraph(sizing: Any, w: Words, suite: bool = False) -> Paragraph:
    """What rock retrofit found for the model's tie-rod, in a sentence: under the record, or
    by the code check alone (no record; ``suite``: a suite's report, whose time histories are
    to be run again with the rod)."""
    if sizing == "not needed":
        return Paragraph(w("concl.retrofit_not_needed"))
    if not sizing.diameters_mm:
        return Paragraph(w("concl.retrofit_skipped", reason=w.note(sizing.reason)))
    values = {"rod": sizing.rod, "grade": sizing.grade, "bars": sizing.bars,
              "lo": w.number(sizing.diameters_mm[0], "{:g}"),
              "hi": w.number(sizing.diameters_mm[-1], "{:g}")}  # fmt: skip
    installed = "" if sizing.installed_mm is None else " " + w(
        "concl.retrofit_installed", d=w.number(sizing.installed_mm, "{:g}"))  # fmt: skip
    if sizing.chosen is None:  # the failures of the largest diameter
        why = getattr(sizing.reason, "values", {}).get("why", sizing.reason)
        key = "concl.retrofit_none" if sizing.rocked else "concl.retrofit_none_code"
        text = w(key, reason=w.note(why), **values)
        return Paragraph(text + installed, "warning")
    d = w.number(sizing.chosen["diameter_mm"], "{:g}")
    if sizing.rocked:
        demand = w(f"concl.retrofit_demand_{sizing.code_demand}")
        text = w("concl.retrofit_found", d=d, demand=demand, **values)
    else:
        again = w("concl.retrofit_found_code_suite") if suite else ""
        text = w("concl.retrofit_found_code", d=d, suite=again, **values)
    if sizing.others:
        names = ", ".join(f"'{w.note(name)}'" for name in sizing.others)
        text += " " + w("concl.retrofit_others", names=names)
    return Paragraph(text + installed, "verdict")


def suite_conclusions_section(
    doc: Mapping[str, Any], w: Words, verification: Any = None,
    rocked: Mapping[str, Any] | None = None, sizing: Any = None,
) -> Section:  # fmt: skip
    """The conclusions of a suite's report: the verification on the model's own spectra when
    it has one (rockcli.document.verification), the code's risk index per limit state on the
    suite's target, the suite's time histories by the code's rule (NTC 2018 §7.3.5), the
    classification, the reference paper's finding for a block of its range (``rocked``: a
    record's `rock assess` document) and what to do next (an intervention when the
    verification or the suite fails), and the tie-rod's sizing when asked (``sizing``: "not
    needed", a Sizing, or None)."""
    from rockcli.document.verification import verification_blocks

    n = w.number
    kin, suite = doc["kinematic"], doc["suite"]
    blocks: list[Block] = []
    verified = "passes"
    if verification is not None:
        own, verified = verification_blocks(verification, w)
        blocks += own
        blocks.append(Paragraph(w("suite.concl_intro", suite=doc["suite_name"]), "subheading"))
    code, failing = code_blocks(kin, w)
    blocks += code
    blocks.append(Paragraph(w(f"concl.suite_{suite['verdict']}", n=suite["n"],
                              measure=n(suite["measure"], "{:.3f}"),
                              limit=n(suite["limit_ratio"], "{:.3g}"),
                              overturned=suite["overturned_records"])))  # fmt: skip
    blocks.append(Paragraph(w(f"class.{doc['classification']}"), "verdict"))
    single = not kin.get("mechanisms") or len(kin["mechanisms"]) == 1
    if single and rocked is not None and in_papers_range(rocked):
        blocks.append(Paragraph(w(f"concl.paper_{doc['classification']}")))
    if verification is not None:
        key = ("unsafe" if verified == "fails" or suite["verdict"] != "passes"
               else "unknown" if verified == "unknown" else "safe")  # fmt: skip
        blocks.append(Paragraph(w(f"verify.next_{key}")))
    else:
        unsafe = bool(failing) or suite["verdict"] != "passes"
        blocks.append(Paragraph(w("concl.next_unsafe" if unsafe else "concl.next_safe")))
    if sizing is not None:
        blocks.append(sizing_paragraph(sizing, w, suite=True))
    return Section("conclusions", w("section.conclusions"), tuple(blocks))


def restrainer_sentence(check: Mapping[str, Any], w: Words) -> Paragraph:
    """One restrainer's verification in the time history, in a sentence."""
    u = check.get("utilisation")
    if check.get("passed"):
        return Paragraph(w("concl.restrainer_ok", name=check["name"],
                           use=w.number(u, "{:.2f}")))  # fmt: skip
    return Paragraph(w("concl.restrainer_fail", name=check["name"], use=w.number(u, "{:.2f}")),
                     "warning")  # fmt: skip
