"""The calculation report (`rock report`): one self-contained document an engineer files.

:mod:`rockcli.document.build` gathers the analyses' results into a :class:`~rockcli.document.
content.Document` (sections of paragraphs, tables and figures, every word from the language's
message catalogue, :mod:`rockcli.document.words`); :mod:`rockcli.document.html` and
:mod:`rockcli.document.pdf` render any Document, the first as HTML with inline SVG figures,
the second as PDF through Typst.
"""
