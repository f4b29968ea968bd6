"""The readers on small texts: every header layout and line-end of spec/records.md.

Expected values are the numbers written in each text, so the comparisons are exact.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from rockcli.records.files import read_record, write_plain
from rockcli.records.parse import detect_format, parse_text
from rockcli.records.pulses import make_pulse
from rockcli.units import STANDARD_GRAVITY, AccelUnit

AT2_HEAD = (
    "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\n"
    "TEST 1/1/00, STATION, 000\n"
    "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.2 Hz LP=15.0 Hz\n"
)
AT2_VALUES = (
    "  -.6403182E-02  -.6028715E-02   .5304162E-03   .7743260E-02   .6890377E-02\n"
    "   .6876502E-02   .6705057E-02\n"
)
AT2_FLOATS = [-6.403182e-3, -6.028715e-3, 5.304162e-4, 7.743260e-3, 6.890377e-3, 6.876502e-3,
              6.705057e-3]  # fmt: skip

#: Line 4 layouts of spec/records.md ("Line 4 of AT2 files comes in many layouts, all real").
LINE4_LAYOUTS = [
    "NPTS=     7, DT= .01000 SEC",
    "NPTS=      7, DT=   .0100 SEC,                                             ",
    "NPTS=      7, dt=  .01000",
    "7    0.0100    NPTS, DT",
    "DT=   .0100 SEC, NPTS=      7",
    "NPTS      7   DT   .0100",
]


@pytest.mark.parametrize("line4", LINE4_LAYOUTS)
def test_at2_line4_layouts(line4: str) -> None:
    record = parse_text(AT2_HEAD + line4 + "\n" + AT2_VALUES)
    assert record.format == "at2"
    assert (record.npts, record.dt) == (7, 0.01)
    assert record.accel.tolist() == AT2_FLOATS


@pytest.mark.parametrize("end", ["\n", "\r\n", "\r\r\n"])
def test_at2_line_ends(end: str) -> None:
    text = (AT2_HEAD + LINE4_LAYOUTS[0] + "\n" + AT2_VALUES).replace("\n", end)
    assert parse_text(text).accel.tolist() == AT2_FLOATS


def test_at2_padded_last_line_and_blank_tail() -> None:
    padded = AT2_VALUES.replace("   .6705057E-02\n", "   .6705057E-02" + " " * 45 + "\n\n  \n")
    record = parse_text(AT2_HEAD + LINE4_LAYOUTS[1] + "\n" + padded)
    assert record.accel.tolist() == AT2_FLOATS


def test_at2_time_is_index_times_dt() -> None:
    record = parse_text(AT2_HEAD + LINE4_LAYOUTS[0] + "\n" + AT2_VALUES)
    assert record.time.tolist() == [i * 0.01 for i in range(7)]


def test_peknold_header_reads_as_at2() -> None:
    """ELC_NS_Peknold_8F10.5.txt: free text on lines 1–3 ("The units are (g)"), 8F10.5."""
    text = (
        "Data for El Centro 1940 North South Component (Peknold Version)\n"
        "9 points at equal spacing of 0.02 sec Points are listed in the format of 8F10.5\n"
        "The units are (g)\n"
        "NPTS=     9, DT= .02000 SEC\n"
        "   0.00630   0.00364   0.00099   0.00428   0.00758   0.01087   0.00682   0.00277\n"
        "  -0.00128"
    )
    record = parse_text(text)
    assert (record.format, record.npts, record.dt) == ("at2", 9, 0.02)
    assert record.accel[-1] == -0.00128


CORACC_HEAD = (
    "Event Date & Time             : 2009-04-06 01:32:39\n"
    "Station Code / Name           : 3614 / L Aquila - V. Aterno - Centro Valle, Italy\n"
    "Network                       : DPC (Italian Civil Protection Authority)\n"
    "Orientation                   : WE\n"
    "Processing Info               : Acausal Butterworth bandpass filtering\n"
    "Filter Cut-off Frequency (Hz) : 0.100 - 50.000\n"
    "Time Increment (s)            : 0.005\n"
    "Number of Data                : {n}\n"
    "PGA (m/s/s)                   : 1.0000000E+00\n"
    "Accelaration time series in m/s/s\n"
)  # the PGA line is cross-checked: every text below has max|a| = 1 m/s²


def test_coracc_touching_negatives_are_sliced() -> None:
    """spec/records.md: "negative numbers touch (-3.99E-09-4.00E-09): slice, don't split"."""
    # ends with its line break: 6 numbers are too few to prove a fixed format without one
    data = (
        "-4.0760000E-09-4.0940000E-09 2.1491800E-07-4.1290000E-09-4.1470000E-09\n-1.0000000E+00\n"
    )
    record = parse_text(CORACC_HEAD.format(n=6) + data)
    assert record.format == "coracc"
    expected_m_s2 = [-4.076e-9, -4.094e-9, 2.149180e-7, -4.129e-9, -4.147e-9, -1.0]
    assert record.accel.tolist() == [v / STANDARD_GRAVITY for v in expected_m_s2]


ESM_TEXT = (
    "EVENT_NAME: GREECE\n"
    "EVENT_ID: EMSC-20190728_0000106\n"
    "VS30_M/S: \n"
    "DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS: 20190728_160905.700\n"
    "SAMPLING_INTERVAL_S: 0.005000\n"
    "NDATA: 3\n"
    "UNITS: cm/s^2\n"
    "PGA_CM/S^2: -0.227973\n"
    "USER1: /tmp/x --he 30.000: a value with colons\n"
    "0.000000\n"
    "-0.227973\n"
    "0.100000\n"
)


def test_esm_header_split_on_first_colon_and_read_to_first_number() -> None:
    record = parse_text(ESM_TEXT)
    assert (record.format, record.unit, record.npts, record.dt) == ("esm", "cm/s2", 3, 0.005)
    assert record.accel.tolist() == [v * AccelUnit.CM_S2.to_g for v in (0.0, -0.227973, 0.1)]


def test_plain_two_columns_with_comments() -> None:
    text = "# t a\n0.0 0.1\n\n# middle comment\n0.01 -0.2\n0.02 0.3\n"
    record = parse_text(text)
    assert (record.format, record.npts, record.dt, record.notes) == ("plain", 3, 0.01, ())
    assert record.accel.tolist() == [0.1, -0.2, 0.3]


def test_plain_non_uniform_time_is_noted_with_median_step() -> None:
    record = parse_text("0 0\n0.01 1\n0.02 2\n0.04 3\n")
    assert record.dt == pytest.approx(0.01, rel=1e-12)  # median of 0.01, 0.01, 0.02
    assert len(record.notes) == 1 and "non-uniform time step" in record.notes[0]


def test_plain_one_column_with_dt_and_units() -> None:
    record = parse_text("100\n-200\n", dt=0.02, units="cm/s2")
    assert record.time.tolist() == [0.0, 0.02]
    assert record.accel.tolist() == [100 * AccelUnit.CM_S2.to_g, -200 * AccelUnit.CM_S2.to_g]
    assert record.unit == "cm/s2"


@pytest.mark.parametrize(
    ("text", "fmt"),
    [(AT2_HEAD + LINE4_LAYOUTS[3] + "\n" + AT2_VALUES, "at2"), (ESM_TEXT, "esm"),
     (CORACC_HEAD.format(n=1) + " 1.0000000E+00", "coracc"), ("0 1\n1 2\n", "plain")],
)  # fmt: skip
def test_detect_format(text: str, fmt: str) -> None:
    assert detect_format(text) == fmt


def test_plain_comment_with_npts_is_not_an_at2_header() -> None:
    assert detect_format("# a\n# b\n# c\n# NPTS= 2, DT= .01\n0 1\n0.01 2\n") == "plain"


def test_forced_format_skips_detection() -> None:
    """A one-column file of numbers read as plain even though it has no header."""
    assert parse_text("1\n2\n", fmt="plain", dt=0.1).format == "plain"


def test_record_name_is_the_file_stem(write_file: Callable[[str, str], Path]) -> None:
    path = write_file("AQV_EW.cor.acc", CORACC_HEAD.format(n=2) + " 1.0000000E+00 5.0000000E-01\n")
    assert read_record(path).name == "AQV_EW"
    assert read_record(path).source == str(path)


def test_write_plain_round_trip(tmp_path: Path) -> None:
    """Accelerations are written with repr, so they come back bit for bit; times are written
    as i·dt with dt's 3 decimals (clean: 0.009, never 0.009000000000000001), so they come back
    as the doubles nearest to those decimals: within 1e-15 s of i·dt computed in floats (the
    float product's rounding, a few ulp of t ≤ 1.3 s, ulp = 2.2e-16)."""
    pulse = make_pulse("ricker", 0.37, 0.3, dt=0.003, total=1.3)
    path = tmp_path / "ricker.txt"
    write_plain(pulse, path)
    back = read_record(path)
    assert np.allclose(back.time, pulse.time, rtol=0.0, atol=1e-15)
    assert back.time.tolist() == [float(f"{i * 0.003:.3f}") for i in range(pulse.npts)]
    assert np.array_equal(back.accel, pulse.accel)
    assert back.dt == pytest.approx(pulse.dt, rel=1e-12)  # span/(n−1) of the written times
    assert (back.format, back.unit, back.notes) == ("plain", "g", ())
    text = path.read_text()
    assert text.startswith("# rock record: time [s], acceleration [g]\n")
    assert "\n0.009 " in text and "0.009000000000000001" not in text
