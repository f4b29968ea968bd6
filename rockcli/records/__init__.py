"""Ground-motion records: readers on text, synthetic pulses, transforms (scale, flip, trim).

Modules: :mod:`~rockcli.records.record` (the Record), :mod:`~rockcli.records.kinds` (format and
pulse enums), :mod:`~rockcli.records.at2`, :mod:`~rockcli.records.esm`,
:mod:`~rockcli.records.coracc`, :mod:`~rockcli.records.plain` (one reader per format, on text),
:mod:`~rockcli.records.parse` (detection and dispatch), :mod:`~rockcli.records.files` (the only
disk access: ``read_record``, ``write_plain``), :mod:`~rockcli.records.transform` and
:mod:`~rockcli.records.pulses`.

The names below are imported on first use (PEP 562), so that ``import rockcli.records.kinds``
(the CLI's choices) does not pull in numpy.
"""

from __future__ import annotations

from importlib import import_module

_EXPORTS = {
    "Record": "record",
    "RecordFormat": "kinds",
    "PulseKind": "kinds",
    "read_record": "files",
    "write_plain": "files",
    "parse_text": "parse",
    "detect_format": "parse",
    "scale": "transform",
    "scale_to_pga": "transform",
    "flip": "transform",
    "trim": "transform",
    "resample": "transform",
    "make_pulse": "pulses",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> object:
    """Import an exported name from its module on first access."""
    if name not in _EXPORTS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(import_module(f"{__name__}.{_EXPORTS[name]}"), name)
