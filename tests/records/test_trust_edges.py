"""Issue 7 at the record edge: damaged files that parse are errors, never a wrong number.

Each test names the issue's item. Expected values are the numbers written in each text (exact
comparisons) unless a comment says where a number and its tolerance come from.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from rockcli.errors import InputError
from rockcli.records.files import read_record
from rockcli.records.lines import MAX_ABS_ACCEL_G, MAX_SAMPLES
from rockcli.records.parse import parse_text
from rockcli.records.plain import format_plain
from rockcli.records.pulses import make_pulse
from rockcli.records.transform import resample, scale, scale_to_pga
from rockcli.units import AccelUnit

Writer = Callable[[str, str], Path]

AT2_HEAD = (
    "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\n"
    "TEST 1/1/00, STATION, 000\n"
    "ACCELERATION TIME HISTORY IN UNITS OF G\n"
)
AT2_LINE4 = "NPTS=     7, DT= .01000 SEC\n"
AT2_VALUES = (
    "  -.6403182E-02  -.6028715E-02   .5304162E-03   .7743260E-02   .6890377E-02\n"
    "   .6876502E-02   .9459335E-03\n"
)
ESM_HEAD = (
    "EVENT_NAME: GREECE\nEVENT_ID: X\nEVENT_DATE_YYYYMMDD: 20190728\nNETWORK: HL\n"
    "STATION_CODE: DLFA\nSTREAM: HNE\nSAMPLING_INTERVAL_S: 0.005000\nNDATA: 3\nUNITS: cm/s^2\n"
)
CORACC_HEAD = (
    "Event Date & Time             : 2009-04-06 01:32:39\n"
    "Station Code / Name           : 3614 / L Aquila\n"
    "Network                       : DPC\n"
    "Orientation                   : WE\n"
    "Processing Info               : none\n"
    "Filter Cut-off Frequency (Hz) : 0.100 - 50.000\n"
    "Time Increment (s)            : 0.005\n"
    "Number of Data                : 5\n"
    "PGA (m/s/s)                   : {pga}\n"
    "Accelaration time series in {unit}\n"
)
CORACC_DATA = " 2.1491800E-07-4.0940000E-09 1.2500000E+00-4.1290000E-09-4.1470000E-09\n"

#: The real records of ../shared/records (PROVENANCE.md), each to be cut by the tests.
REAL_RECORDS = [
    "AQV_EW_ITACA.cor.acc", "CPM000.AT2", "ELC180.AT2", "ELC180_NGAW2_RSN6.AT2",
    "ELC_NS_Peknold_8F10.5.txt", "ESM_GREECE2019_HL.DLFA.HNE.ASC",
    "FRIULI76_TMZ000_NGAW2_RSN125.AT2", "KOBE95_NIS090_NGAW1.AT2", "LAZIO84_ISE-WE.AT2",
    "NORTHR_ALH360.AT2", "NORTHR_ARL360.AT2", "NORTHR_ARL360_CRCRLF.AT2",
    "RSN753_LOMAP_CLS000.AT2", "RSN808_LOMAP_TRI000.AT2",
]  # fmt: skip
#: Bytes cut from the end of each real file: the last token (≤ 15 characters in AT2, 14 in
#: cor.acc) and its line end (up to 3 bytes, CR CR LF), with the blank padding of NGA-West2.
CUTS = range(1, 17)


#: Lines of the big cor.acc file kept under its own header by :func:`real_tail`.
TAIL_LINES = 100


def real_tail(path: Path) -> bytes:
    """The bytes of a real record; for the 1.6 MB cor.acc file, its header and its last
    TAIL_LINES lines (5 values each), byte for byte, with "Number of Data" set to match and
    the PGA value blanked (the peak is not in the tail): its end is what the cuts test, and
    the whole file would take seconds per cut."""
    data = path.read_bytes()
    if not path.name.endswith(".cor.acc"):
        return data
    lines = data.split(b"\n")
    head = [
        b"Number of Data : %d" % (5 * TAIL_LINES) if line.startswith(b"Number of Data")
        else b"PGA (m/s/s) : " if line.startswith(b"PGA") else line
        for line in lines[:10]
    ]  # fmt: skip
    return b"\n".join(head + lines[-TAIL_LINES - 1 :])


def error_of(text: str, **kwargs: object) -> InputError:
    with pytest.raises(InputError) as caught:
        parse_text(text, **kwargs)  # type: ignore[arg-type]
    return caught.value


# Item 1: a record cut inside its last number -------------------------------------------------


def test_elc180_cut_by_two_bytes_is_an_error(shared_records: Path) -> None:
    """`head -c -2 ELC180.AT2` ends in `.9459335E-0`: read as 0.946 g on main."""
    data = (shared_records / "ELC180.AT2").read_bytes()[:-2]
    err = error_of(data.decode("latin-1"), source="ELC180.AT2")
    assert (err.file, err.where, err.value) == ("ELC180.AT2", "line 804", ".9459335E-0")
    assert "cut off" in err.problem


@pytest.mark.parametrize("name", REAL_RECORDS)
def test_every_cut_of_a_real_file_is_an_error_or_the_same_data(
    shared_records: Path, name: str
) -> None:
    """Cutting 1…16 bytes never gives other values: an error, or only a line end was lost."""
    data = real_tail(shared_records / name)
    full = parse_text(data.decode("latin-1"), source=name)
    for cut in CUTS:
        try:
            record = parse_text(data[:-cut].decode("latin-1"), source=name)
        except InputError:
            continue
        assert np.array_equal(record.accel, full.accel), f"{name} cut by {cut} bytes"


def test_at2_last_token_shorter_than_the_others() -> None:
    err = error_of(AT2_HEAD + AT2_LINE4 + AT2_VALUES[:-2])
    assert (err.where, err.value) == ("line 6", ".9459335E-0")


def test_at2_complete_file_without_final_line_break_is_read() -> None:
    """The Peknold El Centro file ends without a line break: a full last number is fine when
    the file has a fixed format (MIN_FORMAT_EVIDENCE numbers of one shape before it)."""
    values = AT2_VALUES.replace("\n   .6876502E-02", "   .6876502E-02\n") * 2
    head = AT2_HEAD + AT2_LINE4.replace("7", "14")
    record = parse_text(head + values[:-1])
    assert record.npts == 14 and record.accel[-1] == 9.459335e-4
    assert error_of(head + values[:-3]).value == ".9459335E-"  # not even a number
    assert "shorter" in error_of(head + values[:-2]).problem


def test_short_file_without_final_line_break_is_refused() -> None:
    """7 numbers are too few to prove a fixed format: the line break must be there."""
    err = error_of(AT2_HEAD + AT2_LINE4 + AT2_VALUES[:-1])
    assert "no line break" in err.problem


def test_esm_cut_last_value() -> None:
    text = ESM_HEAD + "0.000000\n-0.227973\n0.10000"
    assert error_of(text).where == "line 12"


def test_coracc_cut_last_field() -> None:
    text = CORACC_HEAD.format(pga="1.2500000E+00", unit="m/s/s") + CORACC_DATA[:-2]
    assert error_of(text).value == "-4.1470000E-0"


def test_plain_fixed_format_cut_last_value() -> None:
    err = error_of("0.00 0.125\n0.01 0.250\n0.02 0.37")
    assert (err.where, err.value) == ("line 3", "0.37")


def test_plain_free_form_without_final_line_break() -> None:
    """Numbers of varying length: a cut cannot be told from a value, the line end decides."""
    err = error_of("0 0.1\n0.01 -0.25\n0.02 0.3")
    assert "no line break" in err.problem
    assert parse_text("0 0.1\n0.01 -0.25\n0.02 0.3\n").npts == 3


def test_esm_header_pga_cross_checked() -> None:
    """Tolerance: half a unit of the header's last digit plus half of the sample's."""
    data = "0.000000\n-0.227973\n0.100000\n"
    # 5 decimals: |0.22797 − 0.227973| = 3e-6 ≤ 0.5e-5 + 0.5e-6
    assert parse_text(ESM_HEAD + "PGA_CM/S^2: -0.22797\n" + data).npts == 3
    # 1.3e-5 > 5.5e-6: a different peak
    err = error_of(ESM_HEAD + "PGA_CM/S^2: -0.22796\n" + data)
    assert err.where == "PGA_CM/S^2" and "does not match" in err.problem


def test_coracc_header_pga_cross_checked() -> None:
    good = CORACC_HEAD.format(pga="1.2500000E+00", unit="m/s/s") + CORACC_DATA
    assert parse_text(good).pga == pytest.approx(1.25 / 9.80665, rel=1e-15)
    bad = CORACC_HEAD.format(pga="1.2500010E+00", unit="m/s/s") + CORACC_DATA
    assert error_of(bad).where == "Pga (m/s/s)"


# Item 2: absolute times -----------------------------------------------------------------------


def test_epoch_times_are_rezeroed_exactly() -> None:
    """Unix-epoch times at 1 kHz: the steps come out as printed (decimal subtraction)."""
    rows = "".join(f"1700000000.{i:03d} {0.1 * (i % 3):.1f}\n" for i in range(50))
    record = parse_text(rows)
    assert record.time[0] == 0.0
    assert record.time.tolist() == [float(f"0.{i:03d}") for i in range(50)]
    assert record.uniform and record.dt == pytest.approx(0.001, rel=1e-12)
    assert any("re-zeroed" in note and "1700000000.000" in note for note in record.notes)


# Item 3: bounded accelerations ----------------------------------------------------------------


def test_acceleration_beyond_100_g_is_refused() -> None:
    err = error_of("0 0.1\n0.01 1e308\n0.02 0.3\n")
    assert err.where == "sample 2 (t = 0.01 s)" and f"{MAX_ABS_ACCEL_G:g} g" in err.problem


def test_scaling_beyond_100_g_is_refused() -> None:
    record = make_pulse("half-sine", 0.5, 1.0, dt=0.01)
    with pytest.raises(InputError, match="100 g"):
        scale(record, 1e6)
    with pytest.raises(InputError, match="100 g"):
        scale_to_pga(record, 1e300)


# Item 4: non-finite or overflowing time axes --------------------------------------------------


@pytest.mark.parametrize(
    ("text", "kwargs"),
    [
        (AT2_HEAD + "NPTS=     7, DT= 1e308 SEC\n" + AT2_VALUES, {}),
        (ESM_HEAD.replace("0.005000", "1e308") + "0.000000\n-0.227973\n0.100000\n", {}),
        ("-1e308 0.1\n1e308 0.2\n", {}),
        ("0.1\n0.2\n0.3\n", {"dt": 1e308}),
        ("0.1\n0.2\n0.3\n", {"dt": 1e-300}),
    ],
)
def test_time_axis_must_be_finite(text: str, kwargs: dict[str, float]) -> None:
    error_of(text, **kwargs)


# Item 5: one strict number grammar; units of headers ------------------------------------------


@pytest.mark.parametrize("token", ["1_000", "0.1_2", "\u0661\u0662", "nan", "infinity", "0x10"])
def test_lenient_tokens_are_refused(token: str) -> None:
    assert error_of(f"0 0.1\n0.01 {token}\n0.02 0.3\n", fmt="plain").value == token


def test_at2_dt_in_milliseconds_is_converted() -> None:
    record = parse_text(AT2_HEAD + "NPTS=     7, DT= 20 MSEC\n" + AT2_VALUES)
    assert record.dt == pytest.approx(0.02, rel=1e-15)  # 20 × 1e-3, one rounding
    assert any("msec" in note for note in record.notes)


def test_at2_dt_in_an_unknown_unit_is_refused() -> None:
    err = error_of(AT2_HEAD + "NPTS=     7, DT= .02 MIN\n" + AT2_VALUES)
    assert (err.where, err.value) == ("line 4 (DT unit)", "MIN")


def test_coracc_title_in_cm_is_honoured() -> None:
    text = CORACC_HEAD.format(pga="1.2500000E+00", unit="cm/s/s").replace("m/s/s)", "cm/s/s)")
    record = parse_text(text + CORACC_DATA)
    assert record.unit == "cm/s2"
    assert record.pga == 1.25 * AccelUnit.CM_S2.to_g


def test_coracc_two_units_are_refused() -> None:
    text = CORACC_HEAD.format(pga="1.2500000E+00", unit="cm/s/s") + CORACC_DATA
    assert "two acceleration units" in error_of(text).problem


def test_coracc_units_in_free_text_are_not_declarations() -> None:
    # Found in review: a station named "Gal" or a processing note "1 gal = 1 cm/s2" made a
    # valid m/s/s file "name two units"; only the labels and the title declare the unit.
    text = CORACC_HEAD.format(pga="1.2500000E+00", unit="m/s/s")
    text = text.replace("3614 / L Aquila", "3614 / Gal, Italy").replace(
        "Processing Info               : none", "Processing Info               : 1 gal = 1 cm/s2"
    )
    record = parse_text(text + CORACC_DATA)
    assert record.unit == "m/s2" and record.pga == 1.25 * AccelUnit.M_S2.to_g


def test_rock_plain_output_cut_at_a_line_boundary() -> None:
    text = format_plain(make_pulse("half-sine", 0.3, 0.5, dt=0.01))
    cut = text[: text.rstrip("\n").rindex("\n") + 1]  # the last line removed whole
    err = error_of(cut)
    assert err.where == "# npts" and "declares 26" in err.problem  # 0…0.25 s at 0.01 s


# Item 6: implausible magnitudes warn ----------------------------------------------------------


def test_pga_above_3_g_warns_with_the_fix() -> None:
    """Declared g (--units g): a PGA above 3 g warns; undeclared, above 1 g (issue 19)."""
    record = parse_text("0 24.5\n0.01 -12\n0.02 1.2\n", units="g")  # m/s² values read as g
    (warning,) = record.warnings
    assert "PGA 24.5 g is above 3 g" in warning and "check --units" in warning
    assert parse_text("0 2.45\n0.01 -1.2\n0.02 0.12\n", units="g").warnings == ()
    (warning,) = parse_text("0 24.5\n0.01 -12\n0.02 1.2\n").warnings
    assert "PGA 24.5 g is above 1 g" in warning and "check the unit" in warning


def test_cm_read_as_g_is_beyond_the_bound_and_names_the_fix() -> None:
    """The issue's 245 g (a cm/s² file read as g) is beyond 100 g: an error, not a verdict."""
    err = error_of("0 245\n0.01 -120\n0.02 12\n")
    assert err.where == "sample 1 (t = 0 s)" and "check --units" in str(err.allowed)


# Item 7: AT2 line 4 with two bare numbers -----------------------------------------------------


def test_at2_bare_npts_dt() -> None:
    record = parse_text(AT2_HEAD + "  7    0.0050\n" + AT2_VALUES)
    assert (record.format, record.npts, record.dt) == ("at2", 7, 0.005)


@pytest.mark.parametrize("line4", ["  0.0050    7", "  7    2.5", "  7.0  0.005"])
def test_at2_bare_ambiguous_is_refused(line4: str) -> None:
    err = error_of(AT2_HEAD + line4 + "\n" + AT2_VALUES)
    assert err.where == "line 4" and "ambiguous" in err.problem


def test_plain_file_with_two_numbers_on_line_4_stays_plain() -> None:
    assert parse_text("0 0.1\n1 0.2\n2 0.3\n3 0.004\n").format == "plain"


def test_plain_file_whose_comment_says_units_of_g_stays_plain() -> None:
    # Found in review: a plain file whose third line is a comment mentioning "units of g" was
    # taken for an AT2 with a bare line 4 and refused as ambiguous; it read as plain before.
    text = (
        "# El Centro, converted\n# time [s], acceleration\n# acceleration in units of g\n"
        "0.00 0.0100\n0.01 0.0200\n0.02 -0.0150\n0.03 0.0000\n"
    )
    record = parse_text(text)
    assert record.format == "plain" and record.npts == 4


# Item 11: capped sample counts ----------------------------------------------------------------


def test_resample_is_capped() -> None:
    # 0.25 s at dt = 1e-8 s (within a record's dt bounds): 2.5e7 samples.
    record = make_pulse("half-sine", 0.3, 0.5, dt=0.01)
    with pytest.raises(InputError) as caught:
        resample(record, 1e-8)
    assert f"{MAX_SAMPLES:,}" in str(caught.value.allowed)


def test_pulse_is_capped() -> None:
    with pytest.raises(InputError, match="samples"):
        make_pulse("half-sine", 0.3, 0.5, dt=1e-8)


# Item 12: linear header patterns --------------------------------------------------------------


@pytest.mark.parametrize("line4", ["1" * 1_000_000, "NPTS= " + "1" * 1_000_000, " " * 1_000_000])
def test_megabyte_header_line_is_fast(line4: str) -> None:
    """A 20 kB line 4 took 21 s (quadratic pattern); 1 MB must take well under a second."""
    start = time.perf_counter()
    with pytest.raises(InputError):
        parse_text(AT2_HEAD + line4 + "\n" + AT2_VALUES)
    assert time.perf_counter() - start < 1.0


# Item 18: clean times, resampling warnings, header names ---------------------------------------


def test_written_times_are_clean() -> None:
    text = format_plain(make_pulse("rectangular", 0.3, 1.0, dt=0.1, total=2.0))
    assert "\n0.3 " in text and "0.30000000000000004" not in text


def test_resampling_that_lowers_the_pga_warns() -> None:
    """A half-sine of Tp = 1 s peaks at t = 0.25 s; at dt = 0.2 s the samples (0.2, 0.4)
    reach sin(0.4π) = 0.951: the PGA drops by 4.9 %."""
    record = resample(make_pulse("half-sine", 0.3, 1.0, dt=0.01), 0.2)
    (warning,) = record.warnings
    assert "lowered the PGA by 4.89%" in warning
    assert resample(make_pulse("half-sine", 0.3, 1.0, dt=0.01), 0.05).warnings == ()


def test_header_names_of_each_format(shared_records: Path) -> None:
    esm = read_record(shared_records / "ESM_GREECE2019_HL.DLFA.HNE.ASC")
    assert (esm.event, esm.station, esm.component) == ("GREECE 20190728", "HL.DLFA", "HNE")
    coracc = read_record(shared_records / "AQV_EW_ITACA.cor.acc")
    assert (coracc.station, coracc.component) == ("3614 / L Aquila - V. Aterno - Centro Valle, "
                                                  "Italy", "WE")  # fmt: skip
    at2 = read_record(shared_records / "RSN753_LOMAP_CLS000.AT2")
    assert (at2.event, at2.station, at2.component) == ("Loma Prieta, 10/18/1989", "Corralitos", "0")
    assert read_record(shared_records / "ELC_NS_Peknold_8F10.5.txt").event == ""  # free text
