"""The parts of a report that come from the project (rockcli.document.project): the cover's
facts, the engineer's own sections (Markdown, as paragraphs) and the signature block.

Every text is final, in the report's language (the labels from the message catalogues, the
values as the engineer wrote them).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rockcli.document.content import Paragraph, Section
from rockcli.document.words import Words

if TYPE_CHECKING:
    from rockcli.document.project import Project


def cover_rows(project: Project | None, date: str, w: Words) -> tuple[tuple[str, str], ...]:
    """(label, value) of the cover: client, subject, site, coordinates, designer, date."""
    if project is None:
        return ()
    t = project.table
    rows = [(w("project.client"), t.client), (w("project.subject"), t.subject),
            (w("project.comune"), t.comune)]  # fmt: skip
    if t.address:
        rows.append((w("project.address"), t.address))
    if t.lon is not None and t.lat is not None:
        rows.append((w("project.coordinates"), coordinates(project, w)))
    designer = t.designer + (f" — {t.designer_registration}" if t.designer_registration else "")
    rows.append((w("project.designer"), designer))
    rows.append((w("project.date"), signed_on(project, date, w)))
    return tuple(rows)


def signed_on(project: Project, date: str, w: Words) -> str:
    """The day the report is signed, in the report's language: the project's ``date``, or
    the day of the report (``date``: the report's time stamp, ISO 8601 first)."""
    import datetime

    day = project.table.date or datetime.date.fromisoformat(date[:10])
    return w.date(day)


def coordinates(project: Project, w: Words) -> str:
    """The site's coordinates in the datum given and, from WGS84, in ED50 (the grid's)."""
    t = project.table
    assert t.lon is not None and t.lat is not None
    text = w("project.lonlat", lat=f"{t.lat:.5f}", lon=f"{t.lon:.5f}", datum=t.datum)
    if t.datum != "ED50" and project.ed50 is not None:
        lon, lat = project.ed50
        text += "; " + w("project.lonlat_ed50", lat=f"{lat:.5f}", lon=f"{lon:.5f}")
    return text


def signature_lines(project: Project | None, date: str, w: Words) -> tuple[str, ...]:
    """The signature block: place and date, the designer, the order, room for the stamp."""
    if project is None:
        return ()
    t = project.table
    when = signed_on(project, date, w)
    lines = [w("project.place_date", comune=t.comune, date=when), w("project.the_designer"),
             t.designer]  # fmt: skip
    if t.designer_registration:
        lines.append(t.designer_registration)
    lines.append(w("project.sign_here"))
    return tuple(lines)


def own_sections(project: Project | None) -> tuple[Section, ...]:
    """The engineer's sections, each its Markdown as paragraphs (headings, list items and
    paragraphs kept; emphasis and links as their text)."""
    if project is None:
        return ()
    return tuple(
        Section(f"project-{k + 1}", title, tuple(markdown_paragraphs(text)))
        for k, (title, text) in enumerate(project.sections)
    )


def markdown_paragraphs(text: str) -> list[Paragraph]:
    """Markdown (CommonMark, markdown-it-py) as paragraphs: a heading as a ``subheading``,
    a list item with its bullet or number, every other block as a paragraph."""
    from markdown_it import MarkdownIt

    tokens = MarkdownIt("commonmark").parse(text)
    out: list[Paragraph] = []
    kind = ""
    lists: list[int | None] = []  # the open lists: None for a bullet list, else the next number
    for tok in tokens:
        if tok.type == "heading_open":
            kind = "subheading"
        elif tok.type == "bullet_list_open":
            lists.append(None)
        elif tok.type == "ordered_list_open":
            lists.append(int(tok.attrs.get("start", 1) or 1))
        elif tok.type in ("bullet_list_close", "ordered_list_close"):
            lists.pop()
        elif tok.type == "inline":
            prefix = ""
            if lists and kind != "subheading":
                number = lists[-1]
                prefix = "• " if number is None else f"{number}. "
                if number is not None:
                    lists[-1] = number + 1
            out.append(Paragraph(prefix + plain(tok), kind))
            kind = ""
        elif tok.type in ("fence", "code_block"):
            out.append(Paragraph(tok.content.rstrip("\n"), "note"))
    return out


def plain(token: object) -> str:
    """An inline token's text: its words, code spans, line breaks as spaces."""
    parts = []
    for child in getattr(token, "children", None) or ():
        if child.type in ("text", "code_inline"):
            parts.append(child.content)
        elif child.type in ("softbreak", "hardbreak"):
            parts.append(" ")
    return "".join(parts).strip()
