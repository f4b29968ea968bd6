"""Malformed records: one InputError naming the file, the line or header key, and the value.

spec/records.md, "Checks on every record": count == declared, dt > 0, no NaN/inf, time
strictly increasing; "An error names the file, the line and what was expected".
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from rockcli.errors import InputError
from rockcli.records.files import read_record

Writer = Callable[[str, str], Path]

AT2_HEAD = "PEER STRONG MOTION DATABASE RECORD\nTEST\nACCELERATION TIME SERIES IN UNITS OF G\n"
ESM_HEAD = "EVENT_NAME: TEST\nEVENT_ID: X\nSAMPLING_INTERVAL_S: {dt}\nNDATA: {n}\nUNITS: {units}\n"
CORACC_HEAD = "".join(
    f"{label:<30}: {value}\n"
    for label, value in [
        ("Event Date & Time", "2009-04-06 01:32:39"), ("Station Code / Name", "X"),
        ("Network", "X"), ("Orientation", "WE"), ("Processing Info", "none"),
        ("Filter Cut-off Frequency (Hz)", "0.1 - 50"), ("Time Increment (s)", "0.005"),
        ("Number of Data", "5"), ("PGA (m/s/s)", "1.0"),
    ]
) + "Accelaration time series in m/s/s\n"  # fmt: skip


def read_error(path: Path, **kwargs: object) -> InputError:
    """The InputError read_record raises for path."""
    with pytest.raises(InputError) as caught:
        read_record(path, **kwargs)  # type: ignore[arg-type]
    return caught.value


def test_at2_shortfall_names_both_numbers(write_file: Writer) -> None:
    path = write_file(
        "short.AT2", AT2_HEAD + "NPTS=     8, DT= .0100 SEC\n .1 .2 .3 .4 .5\n .6 .7\n"
    )
    err = read_error(path)
    assert (err.file, err.where, err.value) == (str(path), "line 4 (NPTS)", 7)
    assert err.problem == "7 values read but the header declares 8"
    assert err.allowed == "exactly 8 values"


def test_at2_excess_is_not_truncated(write_file: Writer) -> None:
    path = write_file("long.AT2", AT2_HEAD + "NPTS=     2, DT= .0100 SEC\n .1 .2 .3\n")
    err = read_error(path)
    assert err.problem == "3 values read but the header declares 2"


def test_at2_bad_token_names_line_and_token(write_file: Writer) -> None:
    path = write_file("bad.AT2", AT2_HEAD + "NPTS=     3, DT= .0100 SEC\n .1\n .2 x.3\n")
    err = read_error(path)
    assert (err.file, err.where, err.value, err.problem) == (
        str(path), "line 6", "x.3", "not a number"
    )  # fmt: skip


@pytest.mark.parametrize("dt", ["0.0", "-.01"])
def test_at2_dt_not_positive(write_file: Writer, dt: str) -> None:
    path = write_file("dt.AT2", AT2_HEAD + f"NPTS=     1, DT= {dt} SEC\n .1\n")
    err = read_error(path)
    assert (err.where, err.value, err.problem) == (
        "line 4 (DT)", float(dt), "the time step must be greater than 0"
    )  # fmt: skip


def test_at2_without_units_of_g(write_file: Writer) -> None:
    head = AT2_HEAD.replace("UNITS OF G", "UNITS OF CM/SEC").replace("ACCELERATION", "VELOCITY")
    path = write_file("vel.AT2", head + "NPTS=     1, DT= .0100 SEC\n .1\n")
    err = read_error(path, fmt="at2")
    assert (err.where, err.value) == ("line 3", "VELOCITY TIME SERIES IN UNITS OF CM/SEC")


def test_at2_forced_on_a_file_without_npts(write_file: Writer) -> None:
    path = write_file("nonpts.AT2", AT2_HEAD + "4000 points\n .1\n")
    err = read_error(path, fmt="at2")
    assert (err.where, err.value, err.problem) == (
        "line 4", "4000 points", "no NPTS and DT in the AT2 header"
    )  # fmt: skip


def test_esm_nan_names_the_line(write_file: Writer) -> None:
    path = write_file("nan.ASC", ESM_HEAD.format(dt=0.01, n=3, units="cm/s^2") + "1.0\nNaN\n2.0\n")
    err = read_error(path)
    assert (err.file, err.where, err.value, err.problem) == (
        str(path), "line 7", "NaN", "not a finite number"
    )  # fmt: skip


def test_esm_inf_names_the_line(write_file: Writer) -> None:
    path = write_file("inf.ASC", ESM_HEAD.format(dt=0.01, n=2, units="cm/s^2") + "1.0\n-inf\n")
    assert read_error(path).where == "line 7"


def test_esm_missing_ndata(write_file: Writer) -> None:
    head = ESM_HEAD.format(dt=0.01, n=3, units="cm/s^2").replace("NDATA: 3\n", "")
    err = read_error(write_file("nondata.ASC", head + "1.0\n"))
    assert (err.where, err.problem) == ("NDATA", "missing header value")


def test_esm_zero_dt(write_file: Writer) -> None:
    path = write_file("dt0.ASC", ESM_HEAD.format(dt="0.000", n=1, units="cm/s^2") + "1.0\n")
    err = read_error(path)
    assert (err.where, err.value) == ("SAMPLING_INTERVAL_S", 0.0)


def test_esm_unknown_unit(write_file: Writer) -> None:
    path = write_file("vel.ASC", ESM_HEAD.format(dt=0.01, n=1, units="cm/s") + "1.0\n")
    err = read_error(path)
    assert (err.file, err.where, err.value, err.problem) == (
        str(path), "UNITS", "cm/s", "unknown acceleration unit"
    )  # fmt: skip


def test_coracc_bad_token_names_line_and_field(write_file: Writer) -> None:
    data = " 1.0000000E+00 2.0000000E+00-3.0000000E+00\n 4.0000000E+00 5.00000Q0E+00\n"
    path = write_file("bad.cor.acc", CORACC_HEAD + data)
    err = read_error(path)
    assert (err.file, err.where, err.value, err.problem) == (
        str(path), "line 12", "5.00000Q0E+00", "not a number"
    )  # fmt: skip


def test_coracc_shortfall(write_file: Writer) -> None:
    path = write_file("short.cor.acc", CORACC_HEAD + " 1.0000000E+00-2.0000000E+00\n")
    err = read_error(path)
    assert (err.where, err.problem) == ("Number of data", "2 values read but the header declares 5")


def test_plain_time_not_increasing(write_file: Writer) -> None:
    path = write_file("back.txt", "# t a\n0.0 0.1\n0.01 0.2\n0.01 0.3\n")
    err = read_error(path)
    assert (err.file, err.where, err.value, err.problem) == (
        str(path), "line 4", 0.01, "time does not increase"
    )  # fmt: skip
    assert err.allowed == "a time greater than 0.01 s (the line before)"


def test_plain_one_column_needs_dt(write_file: Writer) -> None:
    err = read_error(write_file("one.txt", "0.1\n0.2\n"))
    assert (err.where, err.problem) == ("dt", "a one-column file needs the time step")


def test_plain_one_column_dt_not_positive(write_file: Writer) -> None:
    err = read_error(write_file("one.txt", "0.1\n0.2\n"), dt=-0.01)
    assert (err.where, err.value, err.problem) == (
        "dt", -0.01, "the time step must be greater than 0"
    )  # fmt: skip


def test_plain_unknown_unit(write_file: Writer) -> None:
    err = read_error(write_file("two.txt", "0 0.1\n1 0.2\n"), units="furlong/s2")
    assert (err.where, err.value, err.problem) == (
        "units", "furlong/s2", "unknown acceleration unit"
    )  # fmt: skip


def test_plain_ragged_columns(write_file: Writer) -> None:
    err = read_error(write_file("ragged.txt", "0 0.1\n1 0.2 0.3\n"))
    assert (err.where, err.value) == ("line 2", 3)


def test_plain_two_columns_refuse_dt(write_file: Writer) -> None:
    err = read_error(write_file("two.txt", "0 0.1\n1 0.2\n"), dt=0.01)
    assert err.problem == "dt is given by the time column of a two-column file"


def test_header_formats_refuse_dt_and_units(write_file: Writer) -> None:
    path = write_file("ok.AT2", AT2_HEAD + "NPTS=     1, DT= .0100 SEC\n .1\n")
    assert read_error(path, units="g").where == "units"
    assert read_error(path, dt=0.02).where == "dt"


def test_missing_file() -> None:
    err = read_error(Path("no/such/record.AT2"))
    assert (err.file, err.problem) == ("no/such/record.AT2", "cannot read the record file")


def test_unrecognised_format(write_file: Writer) -> None:
    path = write_file("meta.csv", "station,component,pga\nAQV,WE,6.5\n")
    err = read_error(path)
    assert (err.file, err.where, err.value) == (str(path), None, None)
    assert err.problem.startswith("unrecognised record format")


def test_unrecognised_format_never_quotes_the_file(write_file: Writer) -> None:
    # On main the error quoted the first line: a suite naming /etc/passwd printed its first
    # entry. The error names the file and the formats rock reads, never the content.
    secret = "hunter2-SECRET-token-1f3c"
    path = write_file("notes.txt", f"{secret}\nsecond line {secret}\n")
    text = str(read_error(path))
    assert secret not in text and str(path) in text and "PEER AT2" in text


def test_unknown_forced_format(write_file: Writer) -> None:
    err = read_error(write_file("two.txt", "0 0.1\n1 0.2\n"), fmt="sac")
    assert (err.value, err.allowed) == ("sac", "at2, esm, coracc, plain")


def test_error_is_one_line_with_every_part(write_file: Writer) -> None:
    path = write_file("short.AT2", AT2_HEAD + "NPTS=     2, DT= .0100 SEC\n .1\n")
    assert str(read_error(path)) == (
        f"{path}: line 4 (NPTS): 1 values read but the header declares 2 "
        "(got 1; allowed: exactly 2 values)"
    )
