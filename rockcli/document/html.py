"""A calculation report as one self-contained HTML page: inline CSS, figures as inline SVG,
no link to anything outside it; print CSS for A4 (a browser prints it as the report)."""

from __future__ import annotations

from rockcli.document.content import Document
from rockcli.document.symbols import pieces
from rockcli.errors import display_text


def render_html(doc: Document) -> str:
    """The HTML page of a Document (Jinja2, every text escaped except the figures' SVG).

    Every text is also shown through :func:`rockcli.errors.display_text` (the ``finalize`` of
    the environment): a control character in a model's or a record's name is written as
    ``\\x07``, never as the raw byte HTML escaping leaves in place.
    """
    from jinja2 import Environment, PackageLoader, StrictUndefined, select_autoescape

    env = Environment(
        loader=PackageLoader("rockcli.document", "templates"),
        autoescape=select_autoescape(("html", "j2")),
        undefined=StrictUndefined,
        trim_blocks=False,
        finalize=_shown,
    )
    env.tests["token"] = is_token
    env.filters["joined"] = slashes_joined
    return env.get_template("report.html.j2").render(doc=doc)


#: A run of characters without a space longer than this is an identifier, a path or a digest
#: (a case id, a file, a SHA-256), not a word: its cell may break it anywhere, while every
#: other cell breaks between words only (an Italian word is shorter).
TOKEN_LENGTH = 18


def is_token(cell: object) -> bool:
    """True when a table cell holds a run longer than TOKEN_LENGTH without a space."""
    return isinstance(cell, str) and any(len(part) > TOKEN_LENGTH for part in cell.split())


def slashes_joined(text: str) -> str:
    """A table header with no line break after a slash: "max θ/α", "[kN/m]" are one word
    (a browser would otherwise break after the slash of a narrow column)."""
    return text.replace("/", "/\u2060")


def _shown(value: object) -> object:
    """A text as the page shows it, the code's symbols with their subscripts (ζ<sub>E</sub>:
    rockcli.document.symbols); markup (the figures' SVG, already clean) as it is."""
    from markupsafe import Markup, escape

    if isinstance(value, str) and not isinstance(value, Markup):
        parts = pieces(display_text(value))
        if not any(sub for _, sub in parts):
            return "".join(piece for piece, _ in parts)
        return Markup("").join(
            Markup("<sub>{}</sub>").format(piece) if sub else escape(piece) for piece, sub in parts
        )
    return value
