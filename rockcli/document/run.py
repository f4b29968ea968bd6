"""`rock report`: run the comparison, build the report, write it as HTML (and PDF)."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.analyses.choices import Analyses, ComparisonChoices

if TYPE_CHECKING:
    from rockcli.document.content import Document
    from rockcli.records.record import Record


@dataclass(frozen=True)
class ReportChoices:
    """What `rock report` on a record chooses: the comparison of each model; ``shown``: "all"
    gives every mechanism of a wall its full section, "governing" only the one compared;
    ``retrofit``: size the tie-rod where the comparison asks for an intervention."""

    comparison: ComparisonChoices
    shown: str = "all"
    retrofit: bool = False


def report_date() -> str:
    """The report's date: now (UTC), or $SOURCE_DATE_EPOCH when set (reproducible documents,
    as reproducible builds date them)."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    moment = datetime.fromtimestamp(int(epoch), UTC) if epoch.isdigit() else datetime.now(UTC)
    return moment.strftime("%Y-%m-%d %H:%M UTC")


def casebook_document(grid_file: str | None) -> dict[str, Any] | None:
    """The validation casebook run on this install (`rock validate --format json`'s document);
    None when the install has no casebook (the report then says so). Its hazard-grid cases
    run when the report has the grid, else they are skipped, as in `rock validate`."""
    from rockcli.casebook.run import run_casebook
    from rockcli.errors import InputError
    from rockcli.terminal.validate import validate_document

    try:
        return validate_document(run_casebook(grid_file=grid_file))
    except InputError:
        return None


def report_front(front: dict[str, Any] | None, grid_file: str | None) -> dict[str, Any]:
    """Inputs' project, casebook and its place: ``front`` gives "project" (None) and
    "casebook" ("annex", "inline" or "none": the casebook is then not run)."""
    front = front or {}
    place = front.get("casebook", "annex")
    casebook = None if place == "none" else casebook_document(grid_file)
    return {"project": front.get("project"), "casebook": casebook,
            "casebook_place": "inline" if place == "none" else place}  # fmt: skip


def write_report(
    model_paths: Sequence[str],
    record: Record | None,
    *,
    html_path: str,
    pdf_path: str | None,
    lang: str,
    command: str,
    files: Sequence[tuple[str, str]],
    choices: ReportChoices,
    front: dict[str, Any] | None = None,
    docx_path: str | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> list[tuple[str, str]]:
    """The report of each model: the code check on the site's (or the model's) spectra, the
    verification (:func:`verification_of`), and with a record the scenario of that record
    (both analyses under it, :func:`wall_comparisons`); write it, say what was written
    (``front``: the project and where the casebook goes, :func:`report_front`; ``files``:
    the record's and the grid's, each model's added).

    Every model is read and checked before any analysis runs."""
    from rockcli.analyses.compare import check_code_demand
    from rockcli.document.build import Inputs, build_document
    from rockcli.document.walls import Part
    from rockcli.model.catalogue import catalogue
    from rockcli.model.load import load_model

    comparison = choices.comparison
    models = [load_model(path) for path in model_paths]
    for path, model in zip(model_paths, models, strict=True):
        check_verifiable(model, path, record, comparison.grid_file)
        if record is not None:
            check_code_demand(model, comparison.code_demand, file=path)
    outputs = 1 + (pdf_path is not None) + (docx_path is not None)
    step = Steps(len(models) * (2 if record is None else 3) + 1 + outputs, progress)
    front = report_front(front, comparison.grid_file)
    step()
    parts = []
    for path, model in zip(model_paths, models, strict=True):
        mechanisms = catalogue(model)  # derived once: the verification and the scenario
        verification = verification_of(model, comparison.analyses.edition,
                                       comparison.grid_file, mechanisms)  # fmt: skip
        step()
        out, doc, others = (None, None, ()) if record is None else wall_comparisons(
            model, record, path, comparison, choices.shown, mechanisms)  # fmt: skip
        if record is not None:
            step()
        inputs = Inputs(path, model, record, (("model", path), *files), command, report_date(),
                        **front)  # fmt: skip
        sizing = None
        if choices.retrofit:
            sizing = wall_sizing(
                path, record, verification, doc, comparison.analyses, comparison.grid_file
            )
        parts.append(Part(inputs, out, doc, others, sizing, verification))
        step()
    document = built(lambda: build_document(parts, lang), docx_path is not None)
    verdict = ", ".join(part_verdict(part) for part in parts)
    return write_document(document, html_path, pdf_path, verdict, docx_path, step)


def built(build: Callable[[], Any], word: bool) -> Any:
    """``build()``'s document, its figures drawn as PNG too only for a Word copy (``word``:
    rockcli.document.figures.PNG_WANTED)."""
    from rockcli.document.figures import PNG_WANTED

    token = PNG_WANTED.set(word)
    try:
        return build()
    finally:
        PNG_WANTED.reset(token)


class Steps:
    """A report's progress: ``progress(done, total)`` after each step (None: silent)."""

    def __init__(self, total: int, progress: Callable[[int, int], None] | None) -> None:
        self.total, self.done, self.progress = total, 0, progress
        if progress is not None:
            progress(0, total)

    def __call__(self) -> None:
        """One step done."""
        self.done = min(self.total, self.done + 1)
        if self.progress is not None:
            self.progress(self.done, self.total)


def check_verifiable(
    model: Any, path: str, record: Record | None, grid_file: str | None = None
) -> None:
    """Without a record, the model must give the code's spectra the report verifies on
    (InputError naming the file and what to give)."""
    from rockcli.analyses.compare import code_sets_demand
    from rockcli.errors import InputError

    if model.ntc is not None and model.ntc.site is not None and model.ntc.demand is None:
        from rockcli.codecheck.hazard import grid_path

        grid_path(grid_file)  # the verification needs the grid: InputError before any run
    if record is None and not code_sets_demand(model):
        raise InputError(
            "sets no code spectrum for the verification",
            file=path,
            where="ntc",
            allowed="[ntc.site] (with --hazard-grid) or [ntc.demand.SLD/SLV/SLC] in the model; "
            "or --record FILE for a report of that record alone",
        )


def verification_of(
    model: Any, edition: str | None, grid_file: str | None, mechanisms: Any = None
) -> Any:
    """The code check of every mechanism on the model's own spectra (its site on the hazard
    grid, or its [ntc.demand]): the report's verification; None when the model sets none."""
    from rockcli.analyses.compare import code_sets_demand
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.codecheck.existing import required_limit_states
    from rockcli.document.verification import Verification, demand_kind
    from rockcli.model.derive_ntc import ntc_settings
    from rockcli.model.plausible import model_warnings
    from rockcli.terminal.kinematic import kinematic_document

    if not code_sets_demand(model):
        return None
    if mechanisms is None:
        from rockcli.model.catalogue import catalogue

        mechanisms = catalogue(model)
    result = kinematic_model(model, edition=edition, grid_file=grid_file,
                             mechanisms=mechanisms)  # fmt: skip
    doc = kinematic_document(model.name, result, model_warnings(model))
    use_class = ntc_settings(model).use_class
    required = required_limit_states(use_class, result.edition)
    return Verification(result, doc, demand_kind(model), use_class, required,
                        mechanisms)  # fmt: skip


def part_verdict(part: Any) -> str:
    """What the "wrote" line says of a wall: the verification's outcome, and the scenario's
    classification when there is one."""

    from rockcli.document.verification import outcome

    said = []
    if part.verification is not None:
        said.append(
            "verification "
            + {"fails": "not satisfied", "passes": "satisfied"}.get(
                outcome(part.verification), "without an outcome at a required limit state"
            )
        )
    if part.doc is not None:
        said.append(f"scenario {part.doc['classification']}")
    return ", ".join(said)


def wall_comparisons(
    model: Any, record: Record, path: str, choices: ComparisonChoices, shown: str,
    mechanisms: Any = None,
) -> tuple[Any, dict[str, Any], tuple[tuple[Any, dict[str, Any]], ...]]:  # fmt: skip
    """A model's comparison under the record (the scenario) and its document, and each other
    mechanism's that the time history rocks (with ``shown`` "all"), each with its document."""
    from rockcli.analyses.compare import compare_model_output, mechanism_output

    analyses = choices.analyses
    out = compare_model_output(
        model, record, engine=analyses.engine, edition=analyses.edition,
        grid_file=choices.grid_file, code_demand=choices.code_demand, history=True,
        ground=analyses.ground, file=path, mechanism=choices.mechanism, mechanisms=mechanisms,
    )  # fmt: skip
    doc = comparison_document(out, record)
    if shown != "all":
        return out, doc, ()
    others = []
    for m in out.mechanisms:
        if m.name == out.kinematic.mechanism or m.rocking is None:
            continue
        one = mechanism_output(model, record, out, m.name, engine=analyses.engine,
                               ground=analyses.ground, file=path)  # fmt: skip
        others.append((one, comparison_document(one, record)))
    return out, doc, tuple(others)


def wall_sizing(
    path: str,
    record: Record | None,
    verification: Any,
    doc: dict[str, Any] | None,
    analyses: Analyses,
    grid_file: str | None = None,
) -> Any:
    """What rock retrofit finds for the model's tie-rod when the report asks for an
    intervention (rockcli.document.conclusions.asks_intervention; "not needed" otherwise):
    each diameter's code check on the verification's spectra (on the record's without a
    verification), and its time history under the record (none without one: the code check
    alone)."""
    from rockcli.codecheck.existing import ultimate_states
    from rockcli.document.conclusions import asks_intervention
    from rockcli.studies.retrofit.run import size_rod

    # A tie-rod is sized for the ultimate limit state (its candidates are checked at the ULS).
    uls = None if verification is None else ultimate_states(verification.result.edition)
    if not asks_intervention(verification, doc, uls):
        return "not needed"
    # The code check of each diameter on the spectra of the verification, when there is one.
    return size_rod(
        path, record, analyses, "record" if verification is None else "model", grid_file
    )


def suite_sizing(
    path: str, verification: Any, doc: dict[str, Any], analyses: Analyses, grid_file: str | None
) -> Any:
    """The tie-rod of a suite's report: sized by the code check alone on the verification's
    spectra where the verification asks for an intervention; where only the suite's time
    histories fail, not sized (the suite's records are not run again with each diameter: the
    reason says so); "not needed" when neither fails."""
    from rockcli.codecheck.existing import ultimate_states
    from rockcli.document.conclusions import asks_intervention
    from rockcli.notes import Note
    from rockcli.studies.retrofit.run import Sizing, size_rod

    if verification is None:
        return Sizing(Note("retro_no_spectra", "the model sets no code spectrum of its own "
                           "([ntc.site] or [ntc.demand]) to size the rod on"))  # fmt: skip
    uls = ultimate_states(verification.result.edition)
    if asks_intervention(verification, None, uls):
        return size_rod(path, None, analyses, "model", grid_file)
    if doc["suite"]["verdict"] != "passes":
        return Sizing(Note("retro_suite_only", "the verification on the site's spectrum needs "
                           "no tie-rod, and the suite's time histories, which fail, are not "
                           "run again with each diameter: the rod is not sized"))  # fmt: skip
    return "not needed"


def comparison_document(out: Any, record: Record) -> dict[str, Any]:
    """`rock compare --format json`'s document with its warnings."""
    from rockcli.terminal.compare import comparison_output_document, comparison_warnings

    doc = comparison_output_document(out, record)
    doc["warnings"] = comparison_warnings(doc)
    return doc


def write_document(
    document: Document,
    html_path: str,
    pdf_path: str | None,
    classification: str,
    docx_path: str | None = None,
    step: Callable[[], None] | None = None,
) -> list[tuple[str, str]]:
    """Write the report as HTML (and PDF, and DOCX); what was written, for the "wrote" lines.

    All are made before any is written: when the PDF cannot be typeset, no HTML is left
    behind to be filed as if the run had ended well.
    """
    from rockcli.document.html import render_html
    from rockcli.outfile import write_bytes

    step = step or (lambda: None)
    outputs = [(html_path, render_html(document).encode("utf-8"), "--output",
                f"calculation report ({document.lang}), {classification}")]  # fmt: skip
    step()
    if pdf_path is not None:
        from rockcli.document.pdf import render_pdf

        outputs.append((pdf_path, render_pdf(document), "--pdf", "the same report as PDF"))
        step()
    if docx_path is not None:
        from rockcli.document.docx import render_docx

        outputs.append((docx_path, render_docx(document), "--docx",
                        "the same report as an editable Word document"))  # fmt: skip
        step()
    for path, data, option, _ in outputs:
        write_bytes(path, data, where=option)
    return [(path, detail) for path, _, _, detail in outputs]


def write_suite_report(
    model_paths: Sequence[str],
    suite_path: str,
    target: str | None,
    grid_file: str | None,
    *,
    html_path: str,
    pdf_path: str | None,
    lang: str,
    command: str,
    analyses: Analyses,
    code_demand: str,
    allow_outside: bool = False,
    front: dict[str, Any] | None = None,
    docx_path: str | None = None,
    retrofit: bool = False,
) -> list[tuple[str, str]]:
    """Compare each model under the suite (as `rock compare --suite`), keep each record's
    history for the figures, write one report; what was written (allow_outside: the suite's
    records may lie outside its folder, --allow-outside; ``retrofit``: size each model's
    tie-rod, :func:`suite_sizing`). Every model and the suite are read and checked before any
    analysis runs."""
    from rockcli.document.build import Inputs
    from rockcli.document.suite import SuitePart, build_suite_document
    from rockcli.studies.suite_run.assess import load_suite_and_model
    from rockcli.suites.run import suite_document

    loads = [load_suite_and_model(path, suite_path, grid_file, target, allow_outside)
             for path in model_paths]  # fmt: skip
    front = report_front(front, grid_file)
    parts = []
    for path, loaded in zip(model_paths, loads, strict=True):
        doc, runs, kin = suite_comparison(loaded, path, grid_file, analyses, code_demand)
        files = [("model", path)]
        if Path(suite_path).is_file():
            files.append(("suite", suite_path))
        files += [("record", str(entry.path)) for entry in loaded.settings.entries]
        files += [("hazard_grid", grid_file)] if grid_file else []
        inputs = Inputs(path, loaded.model, None, tuple(files), command, report_date(), **front)
        verification = verification_of(loaded.model, analyses.edition, grid_file)
        sizing = suite_sizing(path, verification, doc, analyses, grid_file) if retrofit else None
        parts.append(SuitePart(inputs, doc, suite_document(loaded.check), runs, kin,
                               verification, sizing))  # fmt: skip
    document = built(lambda: build_suite_document(parts, lang), docx_path is not None)
    verdict = ", ".join(str(part.doc["classification"]) for part in parts)
    return write_document(document, html_path, pdf_path, verdict, docx_path)


def suite_comparison(
    loaded: Any, path: str, grid_file: str | None, analyses: Analyses, code_demand: str
) -> tuple[dict[str, Any], list[tuple[Any, dict[str, Any], Record]], Any]:
    """`rock compare --suite`'s document of a loaded model and suite (the code check's
    ``code_demand``: the suite's target or mean), and each record's time history with its
    history kept (its `rock assess` document, the scaled record); and the code check's
    result."""
    from rockcli.analyses.assess import assess_model_output
    from rockcli.studies.suite_run.compare import compare_loaded
    from rockcli.terminal.assess import assessment_output_document
    from rockcli.terminal.suite import suite_comparison_document

    result = compare_loaded(loaded, grid_file, code_demand=code_demand, edition=analyses.edition,
                            engine=analyses.engine, ground=analyses.ground)  # fmt: skip
    doc = suite_comparison_document(result)
    runs = []
    for record in loaded.check.records:
        out = assess_model_output(loaded.model, record, analyses.engine, ground=analyses.ground,
                                  file=path, history=True)  # fmt: skip
        runs.append((out, assessment_output_document(out, record), record))
    return doc, runs, result.kinematic
