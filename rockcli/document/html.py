"""A calculation report as one self-contained HTML page: inline CSS, figures as inline SVG,
no link to anything outside it; print CSS for A4 (a browser prints it as the report)."""

from __future__ import annotations

from rockcli.document.content import Document


def render_html(doc: Document) -> str:
    """The HTML page of a Document (Jinja2, every text escaped except the figures' SVG)."""
    from jinja2 import Environment, PackageLoader, StrictUndefined, select_autoescape

    env = Environment(
        loader=PackageLoader("rockcli.document", "templates"),
        autoescape=select_autoescape(("html", "j2")),
        undefined=StrictUndefined,
        trim_blocks=False,
    )
    return env.get_template("report.html.j2").render(doc=doc)
