"""The calculation report as a Word document (rock report --docx), from the same Document as
the HTML and the PDF: Italian offices edit the *relazione* in Word.

python-docx writes it: the title and subtitle, the cover's facts as a table, a numbered
heading per section, paragraphs (notes, warnings and verdicts set apart by their style),
tables with a header row, figures as PNG images with their captions, the signature block and
the annexes. Numbers and words are the Document's own: nothing is computed here.
"""

from __future__ import annotations

import io

from rockcli.document.content import Document, Figure, Grid, Paragraph, Section
from rockcli.document.symbols import pieces

#: Width of a figure on an A4 page with 2 cm margins [cm] (the sketch: 62 %, as in the HTML).
FIGURE_WIDTH_CM = 16.5
SKETCH_SHARE = 0.62
ACCENT = (0x7A, 0x2E, 0x1D)


def render_docx(document: Document) -> bytes:
    """The report as the bytes of a .docx file."""
    from docx import Document as Word
    from docx.shared import Cm

    word = Word()
    for page in word.sections:
        page.page_height, page.page_width = Cm(29.7), Cm(21.0)
        page.left_margin = page.right_margin = Cm(2.0)
        page.top_margin = page.bottom_margin = Cm(2.0)
        page.header.paragraphs[0].text = document.header
        page_numbered(page.footer.paragraphs[0], document)
    word.core_properties.title = clipped(f"{document.title} — {document.header}")
    word.core_properties.language = LOCALES.get(document.lang, document.lang)
    set_language(word, LOCALES.get(document.lang, document.lang))
    word.add_heading(document.title, level=0)
    word.add_paragraph(document.subtitle)
    if document.cover:
        cover_table(word, document.cover)
    counters = {"figure": 0, "table": 0}
    for number, section in enumerate(document.sections, start=1):
        add_section(word, section, f"{number}. {section.title}", document, counters)
    if document.signature:
        signature(word, document.signature)
    for k, annex in enumerate(document.annexes):
        word.add_page_break()
        title = f"{document.labels.get('annex', 'Annex')} {'ABCDEFGH'[k]}. {annex.title}"
        add_section(word, annex, title, document, counters)
    buffer = io.BytesIO()
    word.save(buffer)
    return buffer.getvalue()


#: The language tag of each report language (the document's and its text's proofing language).
LOCALES = {"it": "it-IT", "en": "en-GB"}
#: The longest text a core property holds (OOXML: 255 characters).
PROPERTY_LENGTH = 255


def clipped(text: str) -> str:
    """A core property's text, cut to PROPERTY_LENGTH with an ellipsis."""
    return text if len(text) <= PROPERTY_LENGTH else text[: PROPERTY_LENGTH - 1] + "…"


def set_language(word, tag: str) -> None:
    """Every run's language by default (the styles' rPrDefault ``w:lang``): Word checks the
    spelling, hyphenates and writes dates of fields in the report's language."""
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    defaults = word.styles.element.find(qn("w:docDefaults"))
    rpr = defaults.find(qn("w:rPrDefault")).find(qn("w:rPr"))
    lang = rpr.find(qn("w:lang"))
    if lang is None:
        lang = OxmlElement("w:lang")
        rpr.append(lang)
    for key in ("w:val", "w:eastAsia", "w:bidi"):
        lang.set(qn(key), tag)


def page_numbered(paragraph, document: Document) -> None:
    """The footer's text, then "Pagina N / M" as fields Word and LibreOffice fill in."""
    paragraph.text = f"{document.footer} — {document.labels.get('page', 'Page')} "
    add_field(paragraph, "PAGE")
    paragraph.add_run(" / ")
    add_field(paragraph, "NUMPAGES")


def add_field(paragraph, instruction: str) -> None:
    """A simple field (PAGE, NUMPAGES) at the end of the paragraph."""
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    field = OxmlElement("w:fldSimple")
    field.set(qn("w:instr"), instruction)
    run = OxmlElement("w:r")
    text = OxmlElement("w:t")
    text.text = "1"
    run.append(text)
    field.append(run)
    paragraph._p.append(field)


def repeat_header(row) -> None:
    """The table's first row repeated at the top of every page the table runs onto."""
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    properties = row._tr.get_or_add_trPr()
    header = OxmlElement("w:tblHeader")
    header.set(qn("w:val"), "true")
    properties.append(header)


def cover_table(word, rows: tuple[tuple[str, str], ...]) -> None:
    """The project's facts, label and value, two columns."""
    table = word.add_table(rows=0, cols=2)
    table.style = "Table Grid"
    for label, value in rows:
        cells = table.add_row().cells
        cells[0].paragraphs[0].add_run(label).bold = True
        cells[1].text = value


def add_section(word, section: Section, title: str, document: Document, counters) -> None:
    """One section: its heading, then its blocks in order."""
    word.add_heading(title, level=1)
    for block in section.blocks:
        if isinstance(block, Figure):
            counters["figure"] += 1
            add_figure(word, block, f"{document.labels.get('figure', 'Figure')} "
                       f"{counters['figure']}. {block.caption}")  # fmt: skip
        elif isinstance(block, Grid):
            counters["table"] += 1
            add_grid(word, block, f"{document.labels.get('table', 'Table')} "
                     f"{counters['table']}. {block.caption}")  # fmt: skip
        else:
            add_paragraph(word, block)


def add_paragraph(word, block: Paragraph) -> None:
    """A paragraph; a subheading as a level-2 heading, a verdict in bold, a note and a warning
    in smaller (the warning in red) type."""
    from docx.shared import Pt, RGBColor

    if block.kind == "subheading":
        word.add_heading(block.text, level=2)
        return
    for run in add_text(word.add_paragraph(), block.text):
        if block.kind == "verdict":
            run.bold = True
        elif block.kind in ("note", "warning"):
            run.font.size = Pt(9)
            if block.kind == "warning":
                run.font.color.rgb = RGBColor(0x8A, 0x1C, 0x00)


def add_text(paragraph, text: str) -> list:
    """``text`` as runs of the paragraph, the code's symbols with their subscripts
    (rockcli.document.symbols); the runs added."""
    runs = []
    for piece, sub in pieces(text):
        run = paragraph.add_run(piece)
        run.font.subscript = sub or None
        runs.append(run)
    return runs


def add_grid(word, grid: Grid, caption: str) -> None:
    """A table with its caption above and its header row; numbers right-aligned."""
    from docx.enum.text import WD_ALIGN_PARAGRAPH
    from docx.shared import Cm, Pt

    add_text(word.add_paragraph(style="Caption"), caption)
    table = word.add_table(rows=1, cols=len(grid.headers))
    table.style = "Table Grid"
    for cell, header in zip(table.rows[0].cells, grid.headers, strict=True):
        for run in add_text(cell.paragraphs[0], header):
            run.bold = True
    repeat_header(table.rows[0])
    numeric = grid.numeric or (False,) * len(grid.headers)
    for row in grid.rows:
        cells = table.add_row().cells
        for cell, text, right in zip(cells, row, numeric, strict=True):
            paragraph = cell.paragraphs[0]
            add_text(paragraph, text)
            if right:
                paragraph.alignment = WD_ALIGN_PARAGRAPH.RIGHT
    table.autofit = False
    widths = column_widths(grid)
    for column, width in zip(table.columns, widths, strict=True):  # the grid LibreOffice reads
        column.width = Cm(width)
    for row in table.rows:  # and each cell's, which Word reads
        for cell, width in zip(row.cells, widths, strict=True):
            cell.width = Cm(width)
            for run in cell.paragraphs[0].runs:
                run.font.size = Pt(table_pt(grid))


#: A column's share of the page grows with its text up to this many characters.
COLUMN_TEXT_CAP = 30
#: A word longer than this is an identifier, a path, a digest or a TOML key: it may break; a
#: shorter one (a number, an Italian word) never does.
WORD_CAP = 14
#: What a cell's margins take, in characters of its text.
COLUMN_PADDING = 3
#: The width of a character of the tables' text per point of its size [cm] (an average
#: glyph of the serif text, measured on LibreOffice's rendering: 0.176 cm at 8 pt).
CHAR_CM_PER_PT = 0.022
#: The tables' text [pt]; a table of WIDE_COLUMNS or more (the casebook's annex) smaller, as
#: the HTML's table.wide.
TABLE_PT, WIDE_TABLE_PT, WIDE_COLUMNS = 8, 7, 8


def table_pt(grid: Grid) -> int:
    """The size of a table's text [pt]."""
    return WIDE_TABLE_PT if len(grid.headers) >= WIDE_COLUMNS else TABLE_PT


def column_widths(grid: Grid, total: float = FIGURE_WIDTH_CM) -> list[float]:
    """Each column's width [cm], the page's ``total`` shared out: first every column gets
    its longest word (never broken: a number, "Classificazione"), then what is left goes to
    the columns whose typical cell is longer than that (text that wraps), in proportion; a
    table whose words alone do not fit shares the page in proportion to them."""
    columns = list(zip(grid.headers, *grid.rows, strict=True))
    char = CHAR_CM_PER_PT * table_pt(grid)
    least, wanted = [], []
    for texts in columns:
        words = [len(word) for text in texts for word in str(text).split()] or [1]
        lengths = sorted(len(str(text)) for text in texts)
        word = min(max(words), WORD_CAP)
        typical = min(lengths[len(lengths) // 2], COLUMN_TEXT_CAP)
        least.append((word + COLUMN_PADDING) * char)
        wanted.append((max(word, typical) + COLUMN_PADDING) * char)
    if sum(wanted) <= total:
        return [w * total / sum(wanted) for w in wanted]
    if sum(least) >= total:
        return [w * total / sum(least) for w in least]
    share = (total - sum(least)) / (sum(wanted) - sum(least))
    return [lo + (hi - lo) * share for lo, hi in zip(least, wanted, strict=True)]


def add_figure(word, figure: Figure, caption: str) -> None:
    """The figure as its PNG image, full width (the sketch narrower), its caption below."""
    from docx.shared import Cm

    share = SKETCH_SHARE if figure.key == "sketch" else 1.0
    word.add_picture(io.BytesIO(figure.png), width=Cm(FIGURE_WIDTH_CM * share))
    add_text(word.add_paragraph(style="Caption"), caption)


def signature(word, lines: tuple[str, ...]) -> None:
    """The signature block, right-aligned, with room for the stamp, kept on one page (each
    paragraph kept with the next: a page never holds its last line alone)."""
    from docx.enum.text import WD_ALIGN_PARAGRAPH

    block = [word.add_paragraph()]
    for line in lines:
        block.append(word.add_paragraph(line))
        block[-1].alignment = WD_ALIGN_PARAGRAPH.RIGHT
    block += [word.add_paragraph() for _ in range(4)]
    for paragraph in block[:-1]:
        paragraph.paragraph_format.keep_with_next = True
