"""What a calculation report holds, as data: sections of paragraphs, tables and figures.

Every text is final (words of the report's language, numbers formatted): the renderers
(:mod:`rockcli.document.html`, :mod:`rockcli.document.pdf`) only lay them out.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Paragraph:
    """A paragraph of text; ``kind`` "note", "warning" or "verdict" sets it apart."""

    text: str
    kind: str = ""


@dataclass(frozen=True)
class Grid:
    """A table: a caption, column headers and rows of cell texts (numbers right-aligned)."""

    caption: str
    headers: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    #: Per column: True where the cells are numbers (aligned right).
    numeric: tuple[bool, ...] = ()


@dataclass(frozen=True)
class Figure:
    """A figure as SVG markup (matplotlib's, text drawn as paths) and its caption."""

    key: str
    svg: str
    caption: str
    #: The same figure as PNG (the Word copy's image).
    png: bytes = b""


Block = Paragraph | Grid | Figure


@dataclass(frozen=True)
class Section:
    """A numbered section of the report: its anchor key, title and blocks in order."""

    key: str
    title: str
    blocks: tuple[Block, ...]


@dataclass(frozen=True)
class Document:
    """The whole report."""

    lang: str
    title: str
    subtitle: str
    sections: tuple[Section, ...]
    #: Running header of every printed page (software, version, model).
    header: str = ""
    footer: str = ""
    labels: dict[str, str] = field(default_factory=dict)
    #: The project's facts on the cover, (label, value) in order (none without a project).
    cover: tuple[tuple[str, str], ...] = ()
    #: The signature block's lines, after the last section (none without a project).
    signature: tuple[str, ...] = ()
    #: Sections after the signature (the validation casebook's annex).
    annexes: tuple[Section, ...] = ()
    #: The numbers the report shows, as JSON (the HTML's rock-data script; "" for none).
    data: str = ""
