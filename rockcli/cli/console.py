"""Output a terminal or a file can carry, whatever its encoding.

rock's tables use θ, α, ≤, ², — … . A standard output that is not UTF-8 (Windows writes cp1252
when the output is redirected, ``PYTHONIOENCODING=cp1252``, a C locale's ASCII) cannot encode
them and Python raises UnicodeEncodeError mid-table. :func:`make_output_encodable` keeps the
stream's encoding and spells each symbol it cannot carry in ASCII (θ → theta, ≤ → <=), so that
the text stays readable and every number stays intact.
"""

from __future__ import annotations

import codecs
import sys

from rockcli.terminal.text import spell_ascii

#: Name of the codecs error handler registered below.
HANDLER = "rock-ascii"


def _replace(error: UnicodeError) -> tuple[str, int]:
    if not isinstance(error, UnicodeEncodeError):
        raise error
    bad = error.object[error.start : error.end]
    return "".join(spell_ascii(c) for c in bad), error.end


codecs.register_error(HANDLER, _replace)


def make_output_encodable() -> None:
    """Make stdout and stderr spell in ASCII the characters their encoding cannot carry."""
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        encoding = (getattr(stream, "encoding", None) or "").lower().replace("_", "-")
        if reconfigure is None or encoding.startswith("utf"):
            continue
        try:
            reconfigure(errors=HANDLER)
        except (ValueError, OSError):  # a stream that cannot be reconfigured: leave it
            continue
