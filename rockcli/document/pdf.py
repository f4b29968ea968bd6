"""A calculation report as PDF, typeset by Typst (the ``typst`` package, a self-contained
binary wheel: no system libraries, fonts included). The Document is written as Typst markup
(templates/report.typ.j2) beside its figures' SVG files in a temporary folder and compiled.

Chosen over WeasyPrint, which renders the HTML itself but needs the Pango system libraries
(not installable from PyPI), and over a headless browser (a system package).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from rockcli.document.content import Document, Figure
from rockcli.document.symbols import pieces
from rockcli.errors import DOCUMENT_WHITESPACE, display_text

#: Characters with a meaning in Typst markup, escaped with a backslash in text.
TYPST_SPECIAL = "\\#$*_`<>@[]~/=-+'\"."


def typst_text(text: object) -> str:
    """Text as literal Typst markup: every character with a meaning escaped, control
    characters shown as ``\\xNN`` (:func:`rockcli.errors.display_text`), the code's symbols
    with their subscripts (``#sub[E]``: rockcli.document.symbols)."""
    return "".join(
        f"#sub[{escaped(piece)}]" if sub else escaped(piece)
        for piece, sub in pieces(display_text(str(text)))
    )


def escaped(text: str) -> str:
    """Text with every character that has a meaning in Typst markup escaped."""
    out = []
    for ch in text:
        if ch in TYPST_SPECIAL:
            out.append("\\" + ch)
        elif ch in DOCUMENT_WHITESPACE:  # a line break or tab: a space in running text
            out.append(" ")
        else:
            out.append(ch)
    return "".join(out)


def typst_string(text: object) -> str:
    """Text as a Typst string literal (control characters shown as ``\\xNN``)."""
    shown = "".join(" " if c in DOCUMENT_WHITESPACE else c for c in display_text(str(text)))
    return '"' + shown.replace("\\", "\\\\").replace('"', '\\"') + '"'


def typst_source(doc: Document) -> str:
    """The Typst markup of a Document (its figures referred to as ``<key>.svg``)."""
    from jinja2 import Environment, PackageLoader, StrictUndefined

    env = Environment(
        loader=PackageLoader("rockcli.document", "templates"),
        autoescape=False,
        undefined=StrictUndefined,
    )
    env.filters["typst_text"] = typst_text
    env.filters["typst_string"] = typst_string
    return env.get_template("report.typ.j2").render(doc=doc)


def render_pdf(doc: Document) -> bytes:
    """The PDF of a Document."""
    import typst

    with tempfile.TemporaryDirectory(prefix="rock-report-") as tmp:
        folder = Path(tmp)
        for section in doc.sections:
            for block in section.blocks:
                if isinstance(block, Figure):
                    (folder / f"{block.key}.svg").write_text(block.svg, encoding="utf-8")
        source = folder / "report.typ"
        source.write_text(typst_source(doc), encoding="utf-8")
        return bytes(typst.compile(str(source), root=str(folder)))
