"""`rock report`: run the comparison, build the report, write it as HTML (and PDF)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rockcli.document.content import Document
    from rockcli.records.record import Record


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
    model_path: str,
    record: Record,
    *,
    html_path: str,
    pdf_path: str | None,
    lang: str,
    command: str,
    files: Sequence[tuple[str, str]],
    options: dict[str, Any],
    front: dict[str, Any] | None = None,
    docx_path: str | None = None,
) -> list[tuple[str, str]]:
    """Run both analyses of the model under the record, write the report; what was written
    (``front``: the project and where the casebook goes, :func:`report_front`)."""
    from rockcli.document.build import Inputs, build_document
    from rockcli.model.load import load_model
    from rockcli.studies.compare import check_code_demand, compare_model_output
    from rockcli.terminal.compare import comparison_output_document, comparison_warnings

    model = load_model(model_path)
    check_code_demand(model, options["code_demand"], file=model_path)
    out = compare_model_output(model, record, file=model_path, history=True, **options)
    doc = comparison_output_document(out, record)
    doc["warnings"] = comparison_warnings(doc)
    front = report_front(front, options.get("grid_file"))
    inputs = Inputs(model_path, model, record, tuple(files), command, report_date(), **front)
    document = build_document(inputs, out, doc, lang)
    return write_document(document, html_path, pdf_path, doc["classification"], docx_path)


def write_document(
    document: Document,
    html_path: str,
    pdf_path: str | None,
    classification: str,
    docx_path: str | None = None,
) -> list[tuple[str, str]]:
    """Write the report as HTML (and PDF, and DOCX); what was written, for the "wrote" lines.

    All are made before any is written: when the PDF cannot be typeset, no HTML is left
    behind to be filed as if the run had ended well.
    """
    from rockcli.document.html import render_html
    from rockcli.outfile import write_bytes

    outputs = [(html_path, render_html(document).encode("utf-8"), "--output",
                f"calculation report ({document.lang}), {classification}")]  # fmt: skip
    if pdf_path is not None:
        from rockcli.document.pdf import render_pdf

        outputs.append((pdf_path, render_pdf(document), "--pdf", "the same report as PDF"))
    if docx_path is not None:
        from rockcli.document.docx import render_docx

        outputs.append((docx_path, render_docx(document), "--docx",
                        "the same report as an editable Word document"))  # fmt: skip
    for path, data, option, _ in outputs:
        write_bytes(path, data, where=option)
    return [(path, detail) for path, _, _, detail in outputs]


def write_suite_report(
    model_path: str,
    suite_path: str,
    target: str | None,
    grid_file: str | None,
    *,
    html_path: str,
    pdf_path: str | None,
    lang: str,
    command: str,
    options: dict[str, Any],
    allow_outside: bool = False,
    front: dict[str, Any] | None = None,
    docx_path: str | None = None,
) -> list[tuple[str, str]]:
    """Compare the model under the suite (as `rock compare --suite`), keep each record's
    history for the figures, write the report; what was written (allow_outside: the
    suite's records may lie outside its folder, --allow-outside)."""
    from rockcli.document.build import Inputs
    from rockcli.document.suite import build_suite_document
    from rockcli.studies.assess import assess_model_output
    from rockcli.studies.suite.assess import load_suite_and_model
    from rockcli.studies.suite.compare import compare_loaded
    from rockcli.suites.run import suite_document
    from rockcli.terminal.assess import assessment_output_document
    from rockcli.terminal.suite import suite_comparison_document

    loaded = load_suite_and_model(model_path, suite_path, grid_file, target, allow_outside)
    comparison = compare_loaded(loaded, grid_file, **options)
    doc = suite_comparison_document(comparison)
    records = loaded.check.records
    runs = []
    engine, ground = options["engine"], options["ground"]
    for record in records:
        out = assess_model_output(
            loaded.model, record, engine, ground=ground, file=model_path, history=True
        )
        runs.append((out, assessment_output_document(out, record), record))
    files = [("model", model_path)]
    if Path(suite_path).is_file():
        files.append(("suite", suite_path))
    files += [("record", str(entry.path)) for entry in loaded.settings.entries]
    files += [("hazard_grid", grid_file)] if grid_file else []
    front = report_front(front, grid_file)
    inputs = Inputs(model_path, loaded.model, None, tuple(files), command, report_date(), **front)
    document = build_suite_document(inputs, doc, suite_document(loaded.check), runs, lang)
    return write_document(document, html_path, pdf_path, doc["classification"], docx_path)
