"""Properties of every reader, whatever the text:

* it returns a Record or raises one InputError (never a raw ValueError/IndexError);
* a Record has finite, strictly increasing times, a finite duration and finite accelerations
  bounded by MAX_ABS_ACCEL_G;
* a valid file cut anywhere never yields a Record with the declared count but other values;
* a plain file's ``# units:`` line reads the values as ``--units`` would, and a ``--units``
  that contradicts it is always an error.

The alphabet holds the characters of the record headers, so hypothesis reaches deep into every
reader. Bounded (max_examples, no deadline) so the module runs in a few seconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.records.lines import MAX_ABS_ACCEL_G
from rockcli.records.parse import parse_text
from rockcli.records.record import Record

ALPHABET = "0123456789 .-+eE:\n\r#NPTSDTUNITSOFGnaif,=()ms/c^²"
HEADERS = st.sampled_from([
    "",
    "# units: m/s2\n",
    "# units: CM/S^2\n",
    "#units=g\n# npts: 3\n",
    "# units: m/s\n",
    "# units:\n",
    "# units: g\n# units: gal\n",
    "A\nB\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n",
    "A\nB\nThe units are (g)\n3  0.01  NPTS, DT\n",
    "EVENT_NAME: X\nEVENT_ID: Y\nSAMPLING_INTERVAL_S: 0.01\nNDATA: 3\nUNITS: cm/s^2\n",
    "a:1\nb:2\nc:3\nd:4\ne:5\nf:6\nTime Increment (s) : 0.01\nNumber of Data : 3\ni:9\nj\n",
])  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(head=HEADERS, body=st.text(alphabet=ALPHABET, max_size=200),
       fmt=st.sampled_from([None, "at2", "esm", "coracc", "plain"]),
       dt=st.sampled_from([None, 0.01, -1.0, float("nan")]),
       units=st.sampled_from([None, "g", "m/s2", "cm/s^2", "furlong"]))  # fmt: skip
def test_readers_raise_only_input_error(
    head: str, body: str, fmt: str | None, dt: float, units: str | None
) -> None:
    try:
        record = parse_text(head + body, fmt=fmt, dt=dt, units=units)
    except InputError:
        return
    check_invariants(record)


UNITS = ["g", "m/s2", "cm/s2"]
#: Spellings a ``# units:`` line may use for each unit (rockcli.units.parse_unit).
SPELLINGS = {"g": ["g", "G"], "m/s2": ["m/s2", "M/S^2", "m/s²"], "cm/s2": ["cm/s^2", "gal"]}


@settings(max_examples=200, deadline=None)
@given(values=st.lists(st.floats(-50.0, 50.0, allow_nan=False), min_size=2, max_size=12),
       declared=st.sampled_from(UNITS), spelling=st.integers(0, 2),
       option=st.sampled_from([None, *UNITS]), comments=st.sampled_from(["", "# x\n"]))  # fmt: skip
def test_the_units_line_reads_as_the_option_would(
    values: list[float], declared: str, spelling: int, option: str | None, comments: str
) -> None:
    """A ``# units:`` line gives the record ``--units`` gives for the bare file (the same
    floats: the same product); ``--units`` naming another unit is an error, never a read."""
    body = "".join(f"{0.01 * i:.2f} {v!r}\n" for i, v in enumerate(values))
    names = SPELLINGS[declared]
    text = f"{comments}# units: {names[spelling % len(names)]}\n{body}"
    try:
        bare = parse_text(body, units=declared)
    except InputError:  # beyond 100 g in this unit: the declared file must fail alike
        with pytest.raises(InputError):
            parse_text(text)
        return
    if option is not None and option != declared:
        with pytest.raises(InputError, match="contradicts"):
            parse_text(text, units=option)
        return
    record = parse_text(text, units=option)
    assert record.unit == declared and record.unit_declared
    assert np.array_equal(record.accel, bare.accel)


def check_invariants(record: Record) -> None:
    """What every Record guarantees to the engines."""
    assert record.npts >= 1 and np.isfinite(record.dt) and record.dt > 0
    assert np.isfinite(record.time).all() and np.isfinite(record.duration)
    assert (np.diff(record.time) > 0).all()
    assert (np.abs(record.accel) <= MAX_ABS_ACCEL_G).all()


def at2_text(values: list[float]) -> str:
    """A PEER AT2 file of the values (E15.7 style, five a line)."""
    body = "".join(
        f"{v: .7E}" + ("\n" if i % 5 == 4 else "  ") for i, v in enumerate(values)
    ).rstrip(" ")
    head = f"PEER\nX, Y, 000\nACCELERATION IN UNITS OF G\nNPTS= {len(values)}, DT= .0100 SEC\n"
    return head + body + ("" if body.endswith("\n") else "\n")


def esm_text(values: list[float]) -> str:
    """An ESM file of the values in cm/s² (six decimals, one a line), with its PGA."""
    peak = max(values, key=abs)
    head = (
        "EVENT_NAME: X\nEVENT_ID: Y\nSAMPLING_INTERVAL_S: 0.005\n"
        f"NDATA: {len(values)}\nUNITS: cm/s^2\nPGA_CM/S^2: {peak:.6f}\n"
    )
    return head + "".join(f"{v:.6f}\n" for v in values)


def coracc_text(values: list[float]) -> str:
    """A cor.acc file of the values in m/s² (5E14.7, touching negatives)."""
    labels = ["a", "b", "c", "d", "e", "f"]
    head = "".join(f"{label} : x\n" for label in labels)
    head += f"Time Increment (s) : 0.005\nNumber of Data : {len(values)}\nPGA (m/s/s) : \n"
    head += "Accelaration time series in m/s/s\n"
    rows = [values[i : i + 5] for i in range(0, len(values), 5)]
    return head + "".join("".join(f"{v:14.7E}" for v in row) + "\n" for row in rows)


def plain_text(values: list[float]) -> str:
    """rock's own plain output (``# npts:`` header, repr floats)."""
    from rockcli.records.plain import format_plain

    time = np.arange(len(values)) * 0.01
    record = Record("x", "x", "plain", time, np.asarray(values), 0.01)
    return format_plain(record)


WRITERS = {"at2": at2_text, "esm": esm_text, "coracc": coracc_text, "plain": plain_text}
VALUES = st.lists(
    st.floats(min_value=-2.0, max_value=2.0, allow_nan=False).filter(lambda v: abs(v) > 1e-3),
    min_size=2,
    max_size=23,
)


@settings(max_examples=300, deadline=None)
@given(values=VALUES, fmt=st.sampled_from(sorted(WRITERS)), cut=st.integers(1, 40))
def test_a_cut_file_never_gives_the_declared_count_with_other_values(
    values: list[float], fmt: str, cut: int
) -> None:
    text = WRITERS[fmt](values)
    full = parse_text(text)
    try:
        record = parse_text(text[:-cut])
    except InputError:
        return
    check_invariants(record)
    assert record.npts == full.npts  # fewer samples is an error: the count is declared
    assert np.array_equal(record.accel, full.accel)


@pytest.mark.parametrize("text", ["", "\n\n", "#only comments\n", "\r\r\n"])
def test_empty_texts(text: str) -> None:
    with pytest.raises(InputError):
        parse_text(text)


@settings(max_examples=100, deadline=None)
@given(lines=st.lists(st.text(alphabet="abcxyz:/=_ 0123456789.,;", max_size=30), min_size=1,
                      max_size=6),
       fmt=st.sampled_from([None, "plain"]))  # fmt: skip
def test_a_file_no_reader_recognises_is_never_quoted(lines: list[str], fmt: str | None) -> None:
    """Whatever a file that is not a record holds (a suite may name /etc/passwd or a key
    file), the error names it and the formats, never its first line: every line starts with
    a marker that no message may show. A forced format may quote a bad token of a line it
    reads; detection quotes nothing."""
    text = "\n".join(f"SECRET{line}" for line in lines)
    try:
        parse_text(text, fmt=fmt, source="notes.txt")
    except InputError as exc:
        assert "notes.txt" in str(exc)
        if fmt is None:
            assert "SECRET" not in str(exc), str(exc)
