"""The code's symbols with their subscripts typeset: ζ_E, T_SLV, x_G are written in the
report's texts with an underscore (plain text, JSON, the terminal) and shown as ζ with a
subscript E in the HTML, the PDF and the Word copy.

Only the code's own subscripts are read as such (SUBSCRIPTS), after a single letter that does
not continue a word: a TOML key (``use_class``, ``Tc_star``) or a file name keeps its
underscore.
"""

from __future__ import annotations

import re

#: The subscripts the report's symbols use: the limit states, ζ_E, x_G/z_G, ξ_k, T_R, ζ_v.
SUBSCRIPTS = ("SLO", "SLD", "SLV", "SLC", "E", "G", "R", "k", "v")
SYMBOL = re.compile(r"(?<![\w\\/.\-])([A-Za-zα-ωΑ-Ω])_(" + "|".join(SUBSCRIPTS) + r")(?![\w])")


def pieces(text: str) -> list[tuple[str, bool]]:
    """``text`` as (piece, subscript) in order: the subscripts of the code's symbols apart."""
    out: list[tuple[str, bool]] = []
    at = 0
    for match in SYMBOL.finditer(text):
        out.append((text[at : match.start()] + match.group(1), False))
        out.append((match.group(2), True))
        at = match.end()
    out.append((text[at:], False))
    return [(piece, sub) for piece, sub in out if piece]
