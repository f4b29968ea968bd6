"""Text a terminal can show: control characters escaped, symbols spelled in ASCII when the
output's encoding cannot carry them (θ → theta, ≤ → <=)."""

from __future__ import annotations

import codecs
import unicodedata

#: ASCII spellings of the symbols rock prints (anything else: its base letter, else "?").
SPELLINGS = {
    "θ": "theta",
    "α": "alpha",
    "ζ": "zeta",
    "φ": "phi",
    "γ": "gamma",
    "Δ": "Delta",
    "ε": "eps",
    "π": "pi",
    "√": "sqrt",
    "≤": "<=",
    "≥": ">=",
    "≠": "!=",
    "≈": "~",
    "±": "+/-",
    "×": "x",
    "·": "*",
    "−": "-",
    "–": "-",
    "—": "-",
    "…": "...",
    "→": "->",
    "²": "2",
    "³": "3",
    "⁺": "+",
    "⁻": "-",
    "°": " deg",
    "§": "S",
    "‘": "'",
    "’": "'",
    "“": '"',
    "”": '"',
    "\u0307": "_dot",  # combining dot above: θ̇ → theta_dot
}


def spell_ascii(char: str) -> str:
    """An ASCII spelling of one character (its SPELLINGS entry, its base letter, or "?")."""
    if char in SPELLINGS:
        return SPELLINGS[char]
    greek = unicodedata.name(char, "").split("GREEK SMALL LETTER ")
    if len(greek) == 2 and greek[1].isalpha():
        return greek[1].lower()  # ψ → psi, β → beta
    base = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode("ascii")
    return base or "?"


def encodable(text: str, encoding: str) -> str:
    """``text`` with each character ``encoding`` cannot carry spelled by :func:`spell_ascii`."""
    try:
        codecs.encode(text, encoding)
    except UnicodeEncodeError:
        return "".join(_encodable_char(c, encoding) for c in text)
    except LookupError:  # an encoding Python does not know: plain ASCII is safe
        return encodable(text, "ascii")
    return text


def _encodable_char(char: str, encoding: str) -> str:
    try:
        codecs.encode(char, encoding)
    except UnicodeEncodeError:
        return spell_ascii(char)
    return char
