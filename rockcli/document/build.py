"""The calculation report of a model under a record: the comparison's results as sections.

Everything shown comes from the results `rock compare` computes (its JSON document and the
runs with their histories) and from the model as analysed; this module computes nothing of
the verdicts, it only puts them in the order an engineer files them: identification, model,
site and demand, kinematic analysis, rocking analysis, comparison, and the software's own
section (NTC 2018 §10.2: theory, field of use, the validation casebook of this install).
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.document.code_check import (
    code_spectra_of,
    figure,
    floor_figure,
    hazard_grid,
    kilonewtons,
    kinematic_section,
    record_demand_grids,
)
from rockcli.document.content import Block, Document, Grid, Paragraph, Section
from rockcli.document.tolerance import other_warnings, tolerance_paragraphs
from rockcli.document.walls import Part, merged_files, rekeyed
from rockcli.document.words import Words

#: What the report says of the record, in order (keys of the rocking document's record).
RECORD_FACTS = ("name", "event", "station", "component", "npts", "dt", "duration", "pga_g",
                "t_pga")  # fmt: skip

if TYPE_CHECKING:
    from rockcli.analyses.compare import ComparisonOutput
    from rockcli.model.schema import Model
    from rockcli.records.record import Record


@dataclass(frozen=True)
class Inputs:
    """What the report is about and how it was made.

    Attributes:
        model_path: the model file. record: the record as analysed (None: a suite). files:
        (role, path) of
        every input file (model, record, hazard grid…), hashed in the identification.
        command: the command line that made the report. date: when (ISO 8601).
        casebook: the validation casebook's result on this install, or None when not run.
    """

    model_path: str
    model: Model
    record: Record | None
    files: tuple[tuple[str, str], ...]
    command: str
    date: str
    casebook: Any | None = None
    #: The project (rockcli.document.project), or None.
    project: Any | None = None
    #: Where the casebook's cases go: "annex" (after the signature), "inline" (in §10.2).
    casebook_place: str = "annex"


def build_document(parts: Sequence[Part], lang: str) -> Document:
    """The report of one wall or several (``parts``: each its inputs, its verification on the
    site's spectra, and with a record its comparison, JSON document and other mechanisms in
    full) in language ``lang``."""
    from rockcli.document.data import report_data
    from rockcli.document.walls import summary_section

    w = Words(lang)
    inputs = parts[0].inputs
    many = len(parts) > 1
    if many:
        inputs = replace(inputs, files=merged_files([part.inputs for part in parts]))
    summary = (summary_section(parts, w),) if many or catalogued(parts[0]) else ()
    body = [
        rekeyed(s, f"w{i}", part.name) if many else s
        for i, part in enumerate(parts, 1)
        for s in wall_sections(part, w)
    ]
    names = [part.name for part in parts]
    record = None if inputs.record is None else inputs.record.name
    subtitle = report_subtitle(names, record, w)
    document = assemble(inputs, w, subtitle, names, (*summary, *body))
    return replace(document, data=report_data(parts))


def catalogued(part: Part) -> bool:
    """Whether the wall has more than one mechanism (its report then sums them up first)."""
    from rockcli.document.walls import kinematic_of

    return len(kinematic_of(part).get("mechanisms", ())) > 1


def report_subtitle(names: Sequence[str], record: str | None, w: Words) -> str:
    """What the report is: the verification of one element or several on the site's spectra,
    and the record's scenario when there is one."""
    if len(names) > 1:
        text = w("report.subtitle_verify_many", n=len(names))
    else:
        text = w("report.subtitle_verify", model=names[0])
    return text if record is None else f"{text} {w('report.subtitle_scenario', record=record)}"


def assemble(
    inputs: Any, w: Words, subtitle: str, names: Sequence[str], sections: Sequence[Section]
) -> Document:
    """A report: the identification, the project's own sections, then ``sections`` (the
    summary and each element's), the software's section; its front matter names the models."""
    from rockcli.document.front import own_sections

    return Document(
        lang=w.lang,
        title=w("report.title"),
        subtitle=subtitle,
        sections=(
            identification(inputs, w),
            *own_sections(inputs.project),
            *sections,
            software_section(inputs.casebook, w, inputs.casebook_place),
        ),  # fmt: skip
        **front_matter(inputs, ", ".join(names), w),
    )


def mechanism_sections(part: Part, record: Any, w: Words) -> list[Section]:
    """Each other mechanism of the wall in full under the record, one section each: the body
    as rocked, its code check, its time history and their classification."""
    sections = []
    for i, (out, doc) in enumerate(part.others, 1):
        name = w.note(doc["kinematic"]["mechanism"])
        body = model_section(part.inputs, doc["rocking"]["model"], w,
                             doc["rocking"].get("mechanism"))  # fmt: skip
        own = part.inputs.model.notes
        blocks: list[Block] = [Paragraph(w("summary.mechanism_intro", name=name))]
        blocks += [b for b in body.blocks[1:] if not (isinstance(b, Paragraph) and b.text == own)]
        blocks += kinematic_section(out.kinematic, doc["kinematic"], w, catalogue=False).blocks
        blocks += rocking_section(doc["rocking"], out, record, w).blocks
        blocks.append(Paragraph(w(f"class.{doc['classification']}"), "verdict"))
        title = w("scenario.prefix", record=record.name) + " — " + w("section.mechanism",
                                                                     name=name)  # fmt: skip
        section = Section(f"mechanism-{i}", title, tuple(blocks))
        sections.append(replace(rekeyed(section, f"m{i}"), key=section.key))
    return sections


def wall_sections(part: Part, w: Words) -> list[Section]:
    """One wall's sections: its model; the verification (the site's action and the code check
    on it); with a record, the scenario (the record, the code check on its spectrum, the time
    history, their comparison, the other mechanisms in full); the conclusions."""
    from rockcli.document.conclusions import conclusions_section
    from rockcli.document.verification import verification_sections

    sections = [*wall_description(part, w), wall_model_section(part, w)]
    if part.verification is not None:
        sections += verification_sections(part.inputs.model, part.verification, w)
    if part.doc is not None:
        sections += scenario_sections(part, w)
    sections.append(conclusions_section(part, w))
    return sections


def wall_description(part: Any, w: Words) -> list[Section]:
    """A wall's own section (rockcli.document.wall_section): its geometry, materials, loads,
    thrusts and restrainers, and its section drawn with each mechanism of the verification;
    none for a block file, whose block the model section draws (``part``: a wall of a
    record's report, walls.Part, or of a suite's, suite.SuitePart)."""
    from rockcli.document.wall_section import wall_drawing, wall_grids
    from rockcli.document.walls import kinematic_of

    ver = part.verification
    out = getattr(part, "out", None)  # a suite's part has no comparison of one record
    mechanisms = ver.mechanisms if ver is not None else getattr(out, "catalogue", ())
    walls = [m.wall for m in mechanisms]
    if not walls or walls[0] is None:
        return []
    kin = kinematic_of(part)
    blocks: list[Block] = [Paragraph(w("wall.intro", file=part.inputs.model_path))]
    from rockcli.model.derive_ntc import ntc_settings

    # FC's rule as the check applied it (its edition: the model's, or --edition's).
    rule = ntc_settings(part.inputs.model, kin.get("edition")).FC_rule
    blocks += wall_grids(walls[0], kin, w, rule)
    blocks.append(
        figure(
            "wall",
            wall_drawing(walls[0], kin, w),
            w("wall.drawing_caption"),
        )
    )
    return [Section("wall", w("section.wall"), tuple(blocks))]


def wall_model_section(part: Part, w: Words) -> Section:
    """The model section: the body the scenario rocks, or without a record the governing
    mechanism's body (the same description both analyses read)."""
    if part.doc is not None:
        rocked = part.doc["rocking"]
        return model_section(part.inputs, rocked["model"], w, rocked.get("mechanism"))
    from rockcli.document.data import governing_body

    body, mechanism = governing_body(part)
    return model_section(part.inputs, body, w, mechanism)


def scenario_sections(part: Part, w: Words) -> list[Section]:
    """The record's scenario: its demand and the code check on its spectrum (keys prefixed
    "scenario-", which the verification's own sections do not collide with), the time
    history, the comparison, the other mechanisms in full; every title says it is the
    scenario of that record."""
    inputs, out, doc = part.inputs, part.out, part.doc
    assert doc is not None and inputs.record is not None
    record = inputs.record
    prefix = w("scenario.prefix", record=record.name)
    intro = w("scenario.intro" if part.verification is not None else "scenario.intro_only",
              record=record.name)  # fmt: skip
    demand = demand_section(inputs, doc, record, w, out)
    demand = replace(
        demand, title=w("section.scenario_demand"), blocks=(Paragraph(intro), *demand.blocks)
    )
    return [
        rekeyed(demand, "scenario", prefix),
        rekeyed(kinematic_section(out.kinematic, doc["kinematic"], w), "scenario", prefix),
        rekeyed(rocking_section(doc["rocking"], out, record, w), "", prefix),
        rekeyed(comparison_section(doc, w), "", prefix),
        *mechanism_sections(part, record, w),
    ]


def front_matter(inputs: Inputs, name: str, w: Words) -> dict[str, Any]:
    """The Document's running header and footer, labels, cover, signature and annexes."""
    from rockcli.document.front import cover_rows, signature_lines
    from rockcli.version import __version__

    labels = ("contents", "figure", "table", "page", "annex")
    return {
        "header": f"rock {__version__} — {name}",
        "footer": w("report.footer", date=w.moment(inputs.date)),
        "labels": {k: w(f"label.{k}") for k in labels},
        "cover": cover_rows(inputs.project, inputs.date, w),
        "signature": signature_lines(inputs.project, inputs.date, w),
        "annexes": annex_sections(inputs.casebook, w, inputs.casebook_place),
    }


# --- identification -------------------------------------------------------------------------


def source_digest() -> str:
    """A SHA-256 over the package's Python sources and data (relative path and bytes, sorted):
    it names the code that made the report, beyond its version number."""
    root = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*")):
        if path.suffix in (".py", ".toml", ".j2") and "__pycache__" not in path.parts:
            digest.update(path.relative_to(root).as_posix().encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()


def identification(inputs: Inputs, w: Words) -> Section:
    from rockcli.studies.folder.folder import file_digest
    from rockcli.version import __version__

    software = Grid(
        caption=w("ident.software_caption"),
        headers=(w("col.item"), w("col.value")),
        rows=(
            (w("ident.software"), w("ident.software_value")),
            (w("ident.version"), __version__),
            (w("ident.source_digest"), source_digest()),
            (w("ident.date"), w.moment(inputs.date)),
            (w("ident.command"), inputs.command),
        ),
    )
    files = Grid(
        caption=w("ident.files_caption"),
        headers=(w("col.role"), w("col.file"), "SHA-256"),
        rows=tuple((w(f"role.{role}"), path, file_digest(path)) for role, path in inputs.files),
    )
    return Section("identification", w("section.identification"),
                   (Paragraph(w("ident.intro")), software, files))  # fmt: skip


# --- model ----------------------------------------------------------------------------------


def model_section(
    inputs: Inputs, m: Mapping[str, Any], w: Words, mechanism: Mapping[str, str] | None = None
) -> Section:
    """The model as both analyses read it: the block (or the wall's mechanism rocked, a body
    of its own shape: its centroid instead of 2b × 2h, and no rectangle drawn)."""
    from rockcli.document.figures import block_sketch

    n = w.number
    shape = [("2b", n(2 * m["b"]), "m"), ("2h", n(2 * m["h"]), "m")]
    intro = w("model.intro", file=inputs.model_path)
    if mechanism is not None:
        shape = [(w("model.centroid_x"), n(m["b"]), "m"), (w("model.centroid_z"), n(m["h"]), "m")]
        name, kind = w.note(mechanism["name"]), w(f"mtype.{mechanism['type']}")
        intro = w("model.intro_mechanism", file=inputs.model_path, name=name,
                  type=kind if kind != name else w("model.default_name"))  # fmt: skip
    geometry = [("R", n(m["R"]), "m"), ("α", n(m["alpha"]), "rad")]
    if mechanism is not None and m.get("chain") is not None:  # two blocks: α where V′ = 0
        intro = w("model.intro_flexure", file=inputs.model_path, name=w.note(mechanism["name"]))
        geometry = [(w("model.instability"), n(m["alpha"]), "rad"),
                    ("M(0)", n(m["chain"]["inertia_by_side"]["1"]), "kg·m²")]  # fmt: skip
    rows = [
        (w("model.name"), m["name"], ""),
        (w("model.kind"), w(f"model.kind_{m['kind']}"), ""),
        *geometry,
        *shape,
        ("p", n(m["p"]), "rad/s"),
        (w("model.mass"), n(m["mass"], "{:.1f}") if m["mass"] else "—", "kg"),
        (w("model.restitution"), f"{n(m['e'])} ({w.note(m['e_rule'])})", ""),
        (w("model.sides"), w(f"model.sides_{m['sides']}"), ""),
        (w("model.uplift"), n(m["uplift_acceleration_g"]), "g"),
    ]
    blocks: list[Block] = [
        Paragraph(intro),
        Grid(
            w("model.geometry_caption"),
            (w("col.quantity"), w("col.value"), w("col.unit")),
            tuple(rows),
        ),  # fmt: skip
    ]
    if inputs.model.notes:
        blocks.insert(1, Paragraph(inputs.model.notes, "note"))
    blocks += loads_grids(m, w)
    if mechanism is None:  # the rectangle to scale; a wall's mechanism is not a rectangle
        blocks.append(figure("sketch", block_sketch(m, w), w("figure.sketch_caption")))
    return Section("model", w("section.model"), tuple(blocks))


def loads_grids(m: Mapping[str, Any], w: Words) -> list[Block]:
    """The loads, thrusts and restrainers of the model, a table each (only those it has)."""
    n = w.number
    grids: list[Block] = []
    if m["loads"]:
        grids.append(Grid(
            w("model.loads_caption"),
            (w("col.name"), w("col.weight_kn"), w("col.x_m"), w("col.z_m"), w("col.bears"),
             w("col.moves")),
            tuple((ld["name"], n(ld["weight"] / 1e3), n(ld["x_pos"]), n(ld["z"]),
                   w.yes_no(ld["bears"]), w.yes_no(ld["moves"])) for ld in m["loads"]),
            (False, True, True, True, False, False),
        ))  # fmt: skip
    if m["thrusts"]:
        grids.append(Grid(
            w("model.thrusts_caption"),
            (w("col.name"), w("col.force_kn"), w("col.direction"), w("col.x_m"), w("col.z_m")),
            tuple((t["name"], n(t["force"] / 1e3), w(f"model.direction_{t['direction']}"),
                   n(t["x_pos"]), n(t["z"]))
                  for t in m["thrusts"]),
            (False, True, False, True, True),
        ))  # fmt: skip
    if m["restrainers"]:
        grids.append(Grid(
            w("model.restrainers_caption"),
            (w("col.name"), w("col.law"), "K⁺ [kN/m]", "K⁻ [kN/m]", "r [m]", "φ [rad]",
             w("col.strength_kn"), w("col.code_action")),
            tuple(restrainer_row(r, w) for r in m["restrainers"]),
            (False, False, True, True, True, True, True, False),
        ))  # fmt: skip
        rules = [
            f"{r['name']}: {w.note(r['strength_rule'])}"
            for r in m["restrainers"]
            if r["strength_rule"]
        ]
        grids += [Paragraph(w("model.strength_rule", rule=rule), "note") for rule in rules]
    return grids


def restrainer_row(r: Mapping[str, Any], w: Words) -> tuple[str, ...]:
    n = w.number
    action = w(f"model.action_{r['code_action']}")
    if r["code_action"] == "force":
        action += f" ({n(r['code_force'] / 1e3)} kN)"
    return (
        r["name"], w(f"law.{r['law']}"), n(r["k_pos"] / 1e3), n(r["k_neg"] / 1e3), n(r["r_pos"]),
        n(r["phi_pos"]), n(r["strength"] / 1e3) if r["strength"] else "—", action,
    )  # fmt: skip


# --- site and demand ------------------------------------------------------------------------


def demand_section(
    inputs: Inputs, doc: Mapping[str, Any], record: Record, w: Words, out: ComparisonOutput
) -> Section:
    """The record, the code's hazard, the spectral values the check used, the spectra (and the
    spectra at the mechanism's height when it stands above the ground: :func:`floor_figure`)."""
    from rockcli.codecheck.response import RecordSpectrum
    from rockcli.document.figures import spectra

    kin, rocking = doc["kinematic"], doc["rocking"]
    rec = rocking["record"]
    n = w.number
    blocks: list[Block] = [Paragraph(w(f"demand.intro_{doc['code_demand']}"))]
    shown = [(k, v) for k, v in rec.items() if k in RECORD_FACTS and v not in (None, "")]
    blocks.append(Grid(
        w("demand.record_caption"),
        (w("col.quantity"), w("col.value")),
        tuple((w(f"record.{k}"), n(v) if isinstance(v, float) else str(v)) for k, v in shown),
    ))  # fmt: skip
    if rec.get("input_note"):
        blocks.append(Paragraph(w.note(rec["input_note"]), "note"))
    code_spectra = code_spectra_of(inputs.model, kin)
    if code_spectra:
        blocks.append(hazard_grid(code_spectra, kin, w))
        if doc["code_demand"] == "record":
            blocks.append(Paragraph(w("demand.hazard_reference"), "note"))
    blocks += record_demand_grids(kin["demand"], w)
    record_spectrum = RecordSpectrum.from_record(record, g=rocking["model"]["g"])
    marks = {"Ts": kin["Ts"]} if kin.get("Ts") else {}
    code = [(st, sp) for st, sp, _ in code_spectra]
    pos = out.kinematic.position  # where the check put the mechanism shown
    assert pos is not None  # every catalogue check sets it (analyses.catalogue)
    blocks.append(figure(
        "spectra",
        spectra(code, record_spectrum, record.name, marks, w),
        w("figure.spectra_ground_caption" if pos.at_height else "figure.spectra_caption"),
    ))  # fmt: skip
    if pos.at_height:
        shaking = out.rocking.shaking  # the floor motion rocked; None: the record (--ground)
        # The floor spectra the check read: made from the record's spectrum when it is the
        # demand (the code's at-height rule applied to it), else from the code's.
        ground = ([(state, record_spectrum) for state in kin["demand"]]
                  if doc["code_demand"] == "record" else code)  # fmt: skip
        blocks.append(floor_figure(ground, pos, kin["edition"], shaking, record.name,
                                   rocking["model"]["g"], marks, w,
                                   of_record=doc["code_demand"] == "record"))  # fmt: skip
    return Section("demand", w("section.demand"), tuple(blocks))


# --- rocking analysis -----------------------------------------------------------------------


def rocking_section(
    rocking: Mapping[str, Any], out: ComparisonOutput, record: Record, w: Words
) -> Section:
    """Both polarities: the runs, θ/α(t) over the motion the block stood on, the restrainers."""
    from rockcli.document.figures import histories, restrainer_forces

    n = w.number
    engine = rocking["engine"]
    chain = rocking["model"].get("chain")
    key, extra = ("rock.intro", {}) if chain is None else (
        "rock.intro_chain", {"collapse": n(out.rocking.overturn_angle, "{:.3f}")})  # fmt: skip
    rest = n(engine["rest_velocity"], "{:.0e}")
    blocks: list[Block] = [Paragraph(w(key, rtol=n(engine["rtol"], "{:.0e}"), rest=rest, **extra))]
    rows = tuple(
        (polarity_label(r, w), w(f"status.{r['status']}"), w.ratio(r["max_ratio"], r["overturned"]),
         n(r["t_uplift"], "{:.3f}"), n(r["t_overturn"], "{:.3f}"), str(r["impacts"]),
         n(r["impact_energy_loss"] / 1e3, "{:.3g}"))
        for r in rocking["runs"]
    )  # fmt: skip
    headers = (w("col.polarity"), w("col.status"), "max θ/α", w("col.t_uplift"),
               w("col.t_overturn"), w("col.impacts"), w("col.energy_kj"))  # fmt: skip
    blocks.append(Grid(w("rock.runs_caption"), headers, rows,
                       (False, False, True, True, True, True, True)))  # fmt: skip
    blocks += tolerance_paragraphs(rocking, w)
    result = out.rocking
    runs = result.result.runs
    shaken = result.shaking or record  # a block at height rocks on the floor's motion
    blocks.append(figure("histories", histories(rocking, runs, shaken, result.overturn_angle, w),
                         w("figure.histories_caption")))  # fmt: skip
    if rocking["restrainer_checks"]:
        blocks.append(restrainer_checks_grid(rocking["restrainer_checks"], w))
        blocks += restrainer_check_notes(rocking["restrainer_checks"], w)
    forces = restrainer_forces(rocking["model"], runs, w)
    if forces is not None:
        blocks.append(figure("forces", forces, w("figure.forces_caption")))
    warnings = other_warnings(rocking.get("warnings", []), rocking)
    blocks += [Paragraph(w.note(text), "warning") for text in warnings]
    blocks.append(Paragraph(w(f"rock.verdict_{rocking['verdict']}",
                              ratio=n(rocking["max_ratio"])), "verdict"))  # fmt: skip
    blocks += other_mechanisms(out, w)
    return Section("rocking", w("section.rocking"), tuple(blocks))


def other_mechanisms(out: ComparisonOutput, w: Words) -> list[Block]:
    """A wall's other mechanisms' time histories (rockcli.analyses.compare.catalogue_comparisons):
    each polarity's status, max θ/α, first uplift, overturning and impacts."""
    shown = out.kinematic.mechanism
    others = [(m.name, m.rocking) for m in out.mechanisms if m.name != shown and m.rocking]
    if not others:
        return []
    n = w.number
    rows = tuple(
        (w.note(name), polarity_label({"polarity": r.polarity, "mirror_of": r.mirror_of}, w),
         w(f"status.{r.status}"), w.ratio(r.max_ratio, r.overturned), n(r.t_uplift, "{:.3f}"),
         n(r.t_overturn, "{:.3f}"), str(r.impacts))
        for name, rocking in others
        for r in rocking.runs
    )  # fmt: skip
    headers = (w("cmp.mechanism"), w("col.polarity"), w("col.status"), "max θ/α",
               w("col.t_uplift"), w("col.t_overturn"), w("col.impacts"))  # fmt: skip
    return [Paragraph(w("rock.others_intro")),
            Grid(w("rock.others_caption"), headers, rows,
                 (False, False, False, True, True, True, True))]  # fmt: skip


def polarity_label(run: Mapping[str, Any], w: Words) -> str:
    sign = "+1" if run["polarity"] > 0 else "−1"
    if run.get("mirror_of") is not None:
        return w("rock.mirror", sign=sign)
    return sign


def restrainer_checks_grid(checks: Sequence[Mapping[str, Any]], w: Words) -> Grid:
    n = w.number
    rows = tuple(
        (c["name"], n(kilonewtons(c["demand"])), n(kilonewtons(c["strength"])),
         n(c["utilisation"], "{:.3f}"), n(_mm(c["ductility"]["demand"]), "{:.1f}"),
         n(_mm(c["ductility"]["capacity"]), "{:.1f}"),
         n(kilonewtons((c["anchor"] or {}).get("demand"))),
         n(kilonewtons((c["anchor"] or {}).get("capacity"))),
         w.yes_no(c["ruptured"]), w.passed(c["passed"]))
        for c in checks
    )  # fmt: skip
    headers = (w("col.name"), w("col.force_kn"), w("col.strength_kn"),
               w("col.utilisation"), w("col.elongation_mm"), w("col.elongation_capacity_mm"),
               w("col.overstrength_kn"), w("col.anchor_kn"), w("col.ruptured"),
               w("col.outcome"))  # fmt: skip
    return Grid(w("rock.restrainers_caption"), headers, rows,
                (False, *([True] * 7), False, False))  # fmt: skip


def restrainer_check_notes(checks: Sequence[Mapping[str, Any]], w: Words) -> list[Paragraph]:
    """What each restrainer check rests on: the strength's rule and clause, the elongation it
    can take, the anchor's capacity design (or the force to design it for)."""
    out = []
    for c in checks:
        duct, anchor = c["ductility"], c["anchor"]
        key = "rock.check_strength" if c["strength"] is not None else "rock.check_displacement"
        parts = [w(key, name=c["name"], rule=w.note(c["rule"]))]
        if duct["capacity"] is not None and duct["rule"] != c["rule"]:
            parts.append(w("rock.check_ductility", rule=w.note(duct["rule"])))
        if anchor is not None:
            key = "rock.check_anchor_missing" if anchor["capacity"] is None else "rock.check_anchor"
            parts.append(w(key, force=w.number(anchor["demand"] / 1e3)))
        out.append(Paragraph(" ".join(parts), "note"))
    return out


def _mm(length: float | None) -> float | None:
    return None if length is None else length * 1e3


# --- comparison -----------------------------------------------------------------------------


def comparison_section(doc: Mapping[str, Any], w: Words) -> Section:
    n = w.number
    act, col = doc["activation"], doc["collapse"]
    rows = (
        (w("cmp.activation"), w.yes_no(act["code"]), w.yes_no(act["rocking"])),
        (w("cmp.collapse"), w.yes_no(col["code"]), w.yes_no(col["rocking"])),
    )
    classification = doc["classification"]
    blocks: list[Block] = [
        Paragraph(w("cmp.intro")),
        Grid(w("cmp.caption"), ("", w("cmp.code"), w("cmp.rocking")), rows),
        Paragraph(w(f"class.{classification}"), "verdict"),
    ]
    if act.get("t_uplift") is not None:
        blocks.insert(2, Paragraph(w("cmp.uplift_at", t=n(act["t_uplift"], "{:.2f}"))))
    if doc.get("mechanisms"):
        blocks += [Paragraph(w("cmp.not_rocked_why", name=w.note(m["name"]),
                               reason=w.note(m["not_rocked"])), "note")
                   for m in doc["mechanisms"] if m.get("not_rocked")]  # fmt: skip
    blocks.append(Paragraph(w("cmp.unlike")))
    warnings = other_warnings(doc.get("warnings", []), doc["rocking"])
    blocks += [Paragraph(w.note(text), "warning") for text in warnings]
    return Section("comparison", w("section.comparison"), tuple(blocks))


# --- the software (NTC 2018 §10.2) ----------------------------------------------------------


def software_section(casebook: Any | None, w: Words, place: str = "inline") -> Section:
    """NTC 2018 §10.2: the theory, the field of use and the validation casebook of this
    install (its table here with ``place`` "inline"; with "annex" its summary here and the
    cases in the annex)."""
    blocks: list[Block] = [Paragraph(w(f"soft.theory_{k}")) for k in range(1, 5)]
    blocks += [Paragraph(w(f"soft.limits_{k}")) for k in range(1, 5)]
    blocks += bibliography(w)
    if casebook is None:
        blocks.append(Paragraph(w("soft.casebook_missing"), "warning"))
    elif place == "inline":
        blocks += casebook_blocks(casebook, w)
    else:
        blocks.append(casebook_blocks(casebook, w)[0])
        blocks.append(Paragraph(w("soft.casebook_in_annex")))
    return Section("software", w("section.software"), tuple(blocks))


def bibliography(w: Words) -> list[Block]:
    """The works the report cites, in full, numbered (rockcli.document.bibliography), each
    with what it is to rock where the report's words say it."""
    from rockcli.document.bibliography import REFERENCES
    from rockcli.document.words import catalogue

    blocks: list[Block] = [Paragraph(w("bib.heading"), "subheading")]
    for k, (key, text) in enumerate(REFERENCES, start=1):
        role = catalogue(w.lang).get(f"bib.role_{key}")
        blocks.append(Paragraph(f"[{k}] {text}" + (f" {role}" if role else "")))
    return blocks


def annex_sections(casebook: Any | None, w: Words, place: str) -> tuple[Section, ...]:
    """The casebook's annex (none unless ``place`` is "annex" and it was run)."""
    if casebook is None or place != "annex":
        return ()
    return (Section("annex-casebook", w("section.annex_casebook"),
                    (casebook_blocks(casebook, w)[1],)),)  # fmt: skip


#: The project's documents a case's source may point to, and their names in a report (a
#: reviewer has the report, not the repository).
GUIDES = {"docs/validation.md": "validation", "docs/physics.md": "physics",
          "docs/mechanisms.md": "mechanisms"}  # fmt: skip


def case_source(case: Mapping[str, Any], w: Words) -> str:
    """A case's source in the report's language: its Italian text in an Italian report (the
    case file's ``source_it``), else as the case file gives it."""
    if w.lang == "it" and case.get("source_it"):
        return str(case["source_it"])
    return str(case["source"])


def cited(source: str, w: Words) -> str:
    """A case's source with the project's documents named, not given as repository paths."""
    for path, guide in GUIDES.items():
        source = source.replace(path, w(f"case.guide_{guide}"))
    return source


def casebook_blocks(casebook: Mapping[str, Any], w: Words) -> list[Block]:
    """The validation casebook's cases as run on this install (`rock validate`'s document),
    and the count."""
    n = w.number
    rows = tuple(
        (c["id"], cited(case_source(c, w), w),
         f"{c['quantity']} [{c['unit']}]" if c.get("unit") else c["quantity"],
         n(c["expected"], "{:.6g}"), n(c["obtained"], "{:.6g}"), error_text(c.get("error"), w),
         f"{n(c['tolerance'], '{:.1e}')} ({w('tol.' + c['tolerance_type'])})",
         w(f"case.{c['status']}"))
        for c in casebook["cases"]
    )  # fmt: skip
    headers = (w("col.case"), w("col.source"), w("col.quantity"), w("col.expected"),
               w("col.obtained"), w("col.error"), w("col.tolerance"), w("col.outcome"))  # fmt: skip
    skipped = casebook.get("skipped", 0)
    summary = w("soft.casebook_summary", passed=casebook["passed"], failed=casebook["failed"],
                skipped=skipped)  # fmt: skip
    if skipped:
        summary += " " + w("soft.casebook_skipped")
    return [Paragraph(summary, "verdict" if not casebook["failed"] else "warning"),
            Grid(w("soft.casebook_caption"), headers, rows,
                 (False, False, False, True, True, True, False, False))]  # fmt: skip


#: Errors below this are shown as "< TINY_ERROR" (rounding; their digits differ by machine).
TINY_ERROR = 1e-12


def error_text(error: float | None, w: Words) -> str:
    """A case's error, one significant digit; rounding-level errors as "< 1e-12"."""
    if error is not None and 0.0 <= error < TINY_ERROR:
        return "< " + w.number(TINY_ERROR, "{:.0e}")
    return w.number(error, "{:.1e}")
