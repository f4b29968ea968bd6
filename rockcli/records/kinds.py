"""The categories of records: file formats and synthetic pulse kinds.

Kept free of numpy so that the CLI can list the choices without importing the numeric stack
(``rock --help`` stays fast; spec/engine.md, "Speed").
"""

from __future__ import annotations

from enum import StrEnum


class RecordFormat(StrEnum):
    """Layout of a record file (spec/records.md, table "What rock reads")."""

    AT2 = "at2"
    ESM = "esm"
    CORACC = "coracc"
    PLAIN = "plain"
    PULSE = "pulse"


#: The formats a file can be read as (``pulse`` is generated, never read).
FILE_FORMATS: tuple[RecordFormat, ...] = (
    RecordFormat.AT2,
    RecordFormat.ESM,
    RecordFormat.CORACC,
    RecordFormat.PLAIN,
)


class PulseKind(StrEnum):
    """Synthetic acceleration pulses (spec/records.md, "Record operations")."""

    RECTANGULAR = "rectangular"
    HALF_SINE = "half-sine"
    ONE_SINE = "one-sine"
    ONE_COSINE = "one-cosine"
    RICKER = "ricker"
