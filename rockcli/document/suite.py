"""The calculation report of a model under a record suite (`rock report MODEL --suite S`).

The verdicts are those of `rock compare MODEL --suite S` (the suite's time histories by the
code's rule, NTC 2018 §7.3.5, against the code check on the suite's target at the same limit
state); the figures of each record come from its time history run again with its history
kept (the same function, the same numbers).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from rockcli.document.build import Inputs, assemble, model_section
from rockcli.document.code_check import (
    code_spectra_of,
    figure,
    floor_figure,
    hazard_grid,
    kinematic_section,
)
from rockcli.document.content import Block, Document, Grid, Paragraph, Section
from rockcli.document.tolerance import other_suite_warnings, suite_paragraphs
from rockcli.document.words import Words

if TYPE_CHECKING:
    from rockcli.analyses.assess import AssessmentOutput
    from rockcli.codecheck.result import KinematicResult
    from rockcli.records.record import Record


@dataclass(frozen=True)
class SuitePart:
    """One model of a suite's report.

    Attributes:
        inputs: the model, the files, the command line (``record`` None).
        doc: the `rock compare --suite` JSON document.
        check: the `rock suite check` JSON document of the suite (its compatibility).
        records: each record's time history with its history kept, its `rock assess`
            document and the scaled record, in the suite's order.
        kinematic: the code check on the suite's demand (its position, the virtual work of
            each side: the values the sections show).
    """

    inputs: Inputs
    doc: Mapping[str, Any]
    check: Mapping[str, Any]
    records: Sequence[tuple[AssessmentOutput, Mapping[str, Any], Record]]
    kinematic: KinematicResult
    #: The code check on the model's own spectra (rockcli.document.verification), the
    #: report's verification; None when the model sets no code spectrum.
    verification: Any = None
    #: The tie-rod's sizing (rockcli.document.run.suite_sizing): "not needed", a Sizing, or
    #: None when not asked.
    sizing: Any = None

    @property
    def name(self) -> str:
        """The model's name."""
        return str(self.inputs.model.name)


def build_suite_document(parts: Sequence[SuitePart], lang: str) -> Document:
    """The report of a suite comparison of one model or several (a building's walls: one
    summary over them, then each model's sections titled with its name)."""
    from rockcli.document.walls import merged_files, rekeyed

    w = Words(lang)
    inputs = parts[0].inputs
    many = len(parts) > 1
    if many:
        inputs = replace(inputs, files=merged_files([part.inputs for part in parts]))
    names = [part.doc["model"]["name"] for part in parts]
    body = [
        rekeyed(s, f"w{i}", names[i - 1]) if many else s
        for i, part in enumerate(parts, 1)
        for s in suite_sections(part, w)
    ]
    summary = (suite_summary_section(parts, w),) if many else ()
    suite = parts[0].doc["suite_name"]
    subtitle = (w("report.subtitle_suite_many", n=len(parts), suite=suite) if many
                else w("report.subtitle_suite", model=names[0], suite=suite))  # fmt: skip
    document = assemble(inputs, w, subtitle, names, (*summary, *body))
    return replace(document, data=suite_data(parts))


def suite_data(parts: Sequence[SuitePart]) -> str:
    """The report's data (rockcli.document.data): each model's verification on its own
    spectra, its mechanisms, and the suite's comparison in place of a record's scenario."""
    import json

    from rockcli.document.data import mechanism_data
    from rockcli.document.verification import verification_data, zeta_by_state

    walls = []
    for part in parts:
        ver, doc = part.verification, part.doc
        kin = ver.doc if ver is not None else doc["kinematic"]
        walls.append({
            "model": part.name,
            "verification": None if ver is None else verification_data(ver),
            "mechanisms": [mechanism_data(m) for m in kin.get("mechanisms", ())],
            "scenario": None,
            "suite": {"name": doc["suite_name"], "code_demand": doc.get("code_demand"),
                      "zeta_E": zeta_by_state(doc["kinematic"]),
                      "rule": {k: doc["suite"][k] for k in ("n", "measure", "limit_ratio",
                                                            "verdict")},
                      "classification": doc["classification"]},
        })  # fmt: skip
    data: dict[str, Any] = walls[0] if len(walls) == 1 else {"walls": walls}
    return json.dumps(data, allow_nan=False).replace("</", "<\\/")


def suite_sections(part: SuitePart, w: Words) -> list[Section]:
    """One model's sections: the model; with a code spectrum of its own, the verification
    on it (the site's action, the code check, α0 by virtual work); the suite and its demand,
    the code check on the target, every record's time history by the code's rule (NTC 2018
    §7.3.5), the comparison; the conclusions."""
    from rockcli.document.build import wall_description
    from rockcli.document.conclusions import suite_conclusions_section
    from rockcli.document.verification import verification_sections

    inputs, doc, records = part.inputs, part.doc, part.records
    first = records[0][1]
    verified: list[Section] = []
    if part.verification is not None:
        verified = [*wall_description(part, w),
                    model_section(inputs, first["model"], w, first.get("mechanism")),
                    *verification_sections(inputs.model, part.verification, w)]  # fmt: skip
    else:
        verified = [model_section(inputs, first["model"], w, first.get("mechanism"))]
    return [
        *verified,
        rekeyed_once(suite_demand_section(inputs, doc, part.check, w, first, part.kinematic), part),
        rekeyed_once(kinematic_section(part.kinematic, doc["kinematic"], w), part),
        suite_rocking_section(doc, records, w),
        suite_comparison_section(doc, w, named(doc, records)),
        suite_conclusions_section(doc, w, part.verification, first, part.sizing),
    ]


def rekeyed_once(section: Section, part: SuitePart) -> Section:
    """A section of the suite's (its demand, the code check on its target), keyed apart from
    the verification's own ("suite-demand", "suite-kinematic") when the report has one."""
    if part.verification is None:
        return section
    from rockcli.document.walls import rekeyed

    return rekeyed(section, "suite")


def suite_summary_section(parts: Sequence[SuitePart], w: Words) -> Section:
    """Every model under the suite in one table: the mechanism its comparison shows (a
    wall's governing one), α0, ζ_E at SLD and SLV on the target, the records' θ/α by the
    code's rule and its verdict, the classification."""
    from rockcli.document.walls import zeta_pair

    n = w.number
    rows = []
    for part in parts:
        doc = part.doc
        kin, suite = doc["kinematic"], doc["suite"]
        dls, uls = zeta_pair(kin)
        shown = kin.get("mechanism") if len(kin.get("mechanisms", ())) > 1 else None
        rows.append((doc["model"]["name"],
                     w.note(shown) if shown else w("summary.whole_block"),
                     n(kin["alpha0"]), n(dls, "{:.3f}"), n(uls, "{:.3f}"),
                     n(suite["measure"], "{:.3f}"), w(f"suite.verdict_short_{suite['verdict']}"),
                     w(f"kind.{doc['classification']}")))  # fmt: skip
    headers = (w("summary.element"), w("cmp.mechanism"), "α0", w("summary.zeta_dls"),
               w("summary.zeta_uls"), "θ/α", w("cmp.rocking_verdict"),
               w("cmp.classification"))  # fmt: skip
    grid = Grid(w("summary.suite_caption"), headers, tuple(rows),
                (False, False, True, True, True, True, False, False))  # fmt: skip
    return Section("summary", w("section.summary"),
                   (Paragraph(w("summary.suite_intro")), grid))  # fmt: skip


def suite_demand_section(
    inputs: Inputs, doc: Mapping[str, Any], check: Mapping[str, Any], w: Words,
    first: Mapping[str, Any], result: KinematicResult,
) -> Section:  # fmt: skip
    """The suite: its records and scales, its target, its compatibility (table and figure);
    for a mechanism at height, the code's spectra there (``first``: the first record's
    `rock assess` document, for g and whether the records were rocked at height)."""
    from rockcli.document.figures import compatibility

    n = w.number
    suite = doc["suite"]
    blocks: list[Block] = [Paragraph(w("suite.intro", state=w(f"ls.{doc['limit_state']}")))]
    blocks.append(Grid(
        w("suite.records_caption"),
        (w("col.record"), w("col.scale"), "PGA [g]"),
        tuple((r["name"], n(r["scale"], "{:.3g}"), n(r["pga_g"])) for r in suite["records"]),
        (False, True, True),
    ))  # fmt: skip
    code_spectra = code_spectra_of(inputs.model, doc["kinematic"])
    if code_spectra:
        blocks.append(hazard_grid(code_spectra, doc["kinematic"], w))
    compat = suite["compatibility"]
    lo, hi = compat["period_range"]
    blocks.append(Paragraph(w(
        "suite.compatible" if compat["passed"] else "suite.not_compatible",
        lo=n(lo), hi=n(hi), low=n(compat["min_ratio"], "{:.3f}"),
        high=n(compat["max_ratio"], "{:.3f}"),
    ), "verdict" if compat["passed"] else "warning"))  # fmt: skip
    blocks.append(figure("compatibility", compatibility(check, w),
                         w("figure.compatibility_caption")))  # fmt: skip
    kin = doc["kinematic"]
    pos = result.position  # where the check put the mechanism
    assert pos is not None  # every catalogue check sets it (analyses.catalogue)
    if pos.at_height and code_spectra:
        code = [(st, sp) for st, sp, _ in code_spectra]
        # Each record's floor motion was rocked (not drawn: one curve per record), or with
        # --ground each record itself.
        rocked = "suite" if first["record"].get("input") == "floor" else "ground"
        blocks.append(floor_figure(code, pos, kin["edition"], None, "", first["model"]["g"], {},
                                   w, rocked=f"figure.floor_caption_{rocked}"))  # fmt: skip
    blocks += [Paragraph(w.note(note), "note") for note in doc.get("notes", [])]
    return Section("demand", w("section.demand"), tuple(blocks))


def suite_rocking_section(
    doc: Mapping[str, Any],
    records: Sequence[tuple[AssessmentOutput, Mapping[str, Any], Record]],
    w: Words,
) -> Section:  # fmt: skip
    """Every record's max θ/α and overturning, the code's rule over them, θ/α(t) of each."""
    from rockcli.document.figures import histories

    n = w.number
    suite = doc["suite"]
    blocks: list[Block] = [Paragraph(w(f"suite.rule_{suite['rule']}", n=suite["n"]))]
    blocks.append(Grid(
        w("suite.runs_caption"),
        (w("col.record"), w("col.scale"), "max θ/α", w("col.overturned")),
        tuple((r["name"], n(r["scale"], "{:.3g}"), w.ratio(r["max_ratio"], r["overturned"]),
               w.yes_no(r["overturned"]))
              for r in suite["records"]),
        (False, True, True, False),
    ))  # fmt: skip
    blocks += suite_paragraphs(named(doc, records), w)
    blocks.append(Paragraph(w(
        "suite.measure", measure=n(suite["measure"]), limit=n(suite["limit_ratio"]),
        verdict=w(f"suite.verdict_{suite['verdict']}"), overturned=suite["overturned_records"],
        n=suite["n"],
    ), "verdict"))  # fmt: skip
    for k, (out, rocking, record) in enumerate(records, start=1):
        shaken = out.shaking or record  # a block at height rocks on the floor's motion
        fig = histories(rocking, out.result.runs, shaken, out.overturn_angle, w)
        name = suite["records"][k - 1]["name"]
        blocks.append(figure(f"histories-{k}", fig, w("figure.suite_histories_caption",
                                                       record=name)))  # fmt: skip
    return Section("rocking", w("section.rocking"), tuple(blocks))


def named(
    doc: Mapping[str, Any], records: Sequence[tuple[AssessmentOutput, Mapping[str, Any], Record]]
) -> list[tuple[str, Mapping[str, Any]]]:
    """Each record's name and its `rock assess` document, in the suite's order."""
    return [(r["name"], rocking) for r, (_, rocking, _) in
            zip(doc["suite"]["records"], records, strict=True)]  # fmt: skip


def suite_comparison_section(
    doc: Mapping[str, Any], w: Words, records: Sequence[tuple[str, Mapping[str, Any]]] = ()
) -> Section:
    collapse = doc["collapse"]
    rows = ((w("cmp.collapse"), w.yes_no(collapse["code"]), w.yes_no(collapse["rocking"])),)
    blocks: list[Block] = [
        Paragraph(w("suite.cmp_intro", state=w(f"ls.{doc['limit_state']}"))),
        Grid(w("cmp.caption"), ("", w("cmp.code"), w("cmp.rocking")), rows),
        Paragraph(w(f"class.{doc['classification']}"), "verdict"),
        Paragraph(w("cmp.unlike")),
    ]
    blocks += [Paragraph(w.note(text), "warning")
               for text in other_suite_warnings(doc.get("warnings", []), records)]  # fmt: skip
    return Section("comparison", w("section.comparison"), tuple(blocks))
