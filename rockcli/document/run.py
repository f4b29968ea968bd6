"""`rock report`: run the comparison, build the report, write it as HTML (and PDF)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from datetime import UTC, datetime
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rockcli.records.record import Record


def report_date() -> str:
    """The report's date: now (UTC), or $SOURCE_DATE_EPOCH when set (reproducible documents,
    as reproducible builds date them)."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    moment = datetime.fromtimestamp(int(epoch), UTC) if epoch.isdigit() else datetime.now(UTC)
    return moment.strftime("%Y-%m-%d %H:%M UTC")


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
) -> list[tuple[str, str]]:
    """Run both analyses of the model under the record, write the report; what was written."""
    from rockcli.document.build import Inputs, build_document
    from rockcli.document.html import render_html
    from rockcli.model.load import load_model
    from rockcli.outfile import write_bytes, write_text
    from rockcli.report.compare import comparison_output_document, comparison_warnings
    from rockcli.studies.compare import check_code_demand, compare_model_output

    model = load_model(model_path)
    check_code_demand(model, options["code_demand"], file=model_path)
    out = compare_model_output(model, record, file=model_path, history=True, **options)
    doc = comparison_output_document(out, record)
    doc["warnings"] = comparison_warnings(doc)
    inputs = Inputs(model_path, model, record, tuple(files), command, report_date())
    document = build_document(inputs, out, doc, lang)
    write_text(html_path, render_html(document), where="--output")
    written = [(html_path, f"calculation report ({lang}), {doc['classification']}")]
    if pdf_path is not None:
        from rockcli.document.pdf import render_pdf

        write_bytes(pdf_path, render_pdf(document), where="--pdf")
        written.append((pdf_path, "the same report as PDF"))
    return written
