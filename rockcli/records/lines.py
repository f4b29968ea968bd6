"""Reading numbers out of record text, with errors that name the file, the line and the token.

Shared by every reader (spec/records.md, "Checks on every record"): line ends of any kind,
tokens that are not numbers, NaN/inf, the declared count, dt > 0. Nothing is truncated.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import replace
from decimal import Decimal
from typing import NamedTuple

import numpy as np

from rockcli.errors import InputError
from rockcli.records.record import Record
from rockcli.units import AccelUnit

#: A function that cuts one data line into number tokens.
Splitter = Callable[[str], list[str]]

#: What a value in a data line may look like (shown in errors).
NUMBER_ALLOWED = "a finite decimal number such as -.6403182E-02"

#: The one number grammar of every reader: ASCII digits, an optional sign, a decimal point and
#: an E exponent. Linear (no nested repetition), so a megabyte token costs a single pass.
_NUMBER = re.compile(
    r"[-+]?(?:\d+(?:\.(?P<frac>\d*))?|\.(?P<bare>\d+))(?:[eE][-+]?(?P<exp>\d+))?", re.ASCII
)
#: Words Python reads as non-finite floats (named as such in the error).
NON_FINITE = frozenset(
    sign + word for sign in ("", "+", "-") for word in ("nan", "inf", "infinity")
)
_COUNT = re.compile(r"\d+", re.ASCII)

#: (digits after the decimal point, digits of the exponent) of a number as printed.
Shape = tuple[int, int]

#: Largest |a| a record may hold [g]; 100 g is ~25 times the largest ground acceleration ever
#: recorded (about 4 g), so anything beyond is a damaged file or a unit slip, not a record.
MAX_ABS_ACCEL_G = 100.0
#: Above this PGA [g] a record whose unit is declared is implausible (a unit slip is likelier
#: than one of the handful of ground motions ever recorded above 3 g): it gets a warning.
PLAUSIBLE_PGA_G = 3.0
#: Above this PGA [g] a record whose unit nobody declared (a plain-text file read as g by
#: default) gets a warning: values in m/s² read as g are 9.81 times too large, so an ordinary
#: 0.1–0.4 g record becomes 1–4 g; records above 1 g are rare (docs/interpretations.md).
UNDECLARED_PGA_G = 1.0
#: What a value in m/s² or cm/s² read as g is too large by: g in those units (9.81, 981).
SLIP_FACTORS = tuple(1.0 / unit.to_g for unit in (AccelUnit.M_S2, AccelUnit.CM_S2))
#: Smallest time step [s] a record may declare (1 GHz): accelerographs sample at 50–1000 Hz,
#: so a smaller step is a damaged header (DT = 1e-320 would pass "dt > 0"), not a record.
MIN_DT = 1e-9
#: Largest time step [s] a record may have (1 Hz): accelerographs sample at 50–1000 Hz and
#: digitised analogue records at 50–100 Hz, so a larger step is a damaged header or a slip
#: (a step in milliseconds, 5 for 0.005 s) and no motion a block rocks on; far above it the
#: engines integrate over spans of 1e300 s.
MAX_DT = 1.0
#: Fewest samples a record may have: one sample is no motion (zero duration), and the
#: two-column text rock writes needs two to give its time step.
MIN_RECORD_SAMPLES = 2
#: Most samples a transformation or a pulse may produce (80 MB of floats per array).
MAX_SAMPLES = 10_000_000
#: Numbers of one shape needed before a file counts as fixed-format (a coincidence in a
#: free-form file becomes unlikely; real fixed-format records hold thousands).
MIN_FORMAT_EVIDENCE = 8
#: Relative slack of the PGA cross-check for the float parse and the unit factor: far above
#: double rounding (1e-16), far below any printed digit (8 significant digits: 1e-8).
PARSE_RTOL = 1e-9
#: Digits of the longest sample count read (a larger count cannot match any file's data).
MAX_COUNT_DIGITS = 12

#: Time tolerance, as a fraction of dt, for an edge (window, pulse end) that falls on a sample.
EDGE_TOL = 1e-9


def check_positive(value: float, *, where: str, unit: str) -> float:
    """Return value if it is finite and > 0; InputError naming the argument otherwise."""
    if not (math.isfinite(value) and value > 0.0):
        problem = "must be greater than 0" if math.isfinite(value) else "not a finite number"
        raise InputError(problem, where=where, value=value, allowed=f"a finite number > 0 {unit}")
    return value


def split_lines(text: str) -> list[str]:
    """Split text into lines for LF, CRLF, CR CR LF and lone-CR line ends.

    spec/records.md: "line ends may be LF, CRLF or even ``\\r\\r\\n``" (NORTHR_ARL360_CRCRLF.AT2);
    a plain ``splitlines`` would turn each CR CR LF into two lines and shift every line number.
    """
    text = text.replace("\r\r\n", "\n").replace("\r\n", "\n").replace("\r", "\n")
    return text.split("\n")


def match_number(token: str) -> re.Match[str] | None:
    """The strict number grammar's match of a whole token (ASCII decimal or E notation)."""
    return _NUMBER.fullmatch(token)


def is_number(token: str) -> bool:
    """True when the token is a number of the strict grammar (``nan``, ``1_000`` are not)."""
    return _NUMBER.fullmatch(token) is not None


def parse_number(token: str, *, file: str | None, where: str) -> float:
    """One finite float from a token of the strict grammar; InputError naming where otherwise.

    Python's ``float`` also takes ``1_000``, ``0.1_2``, non-ASCII digits, ``nan`` and
    ``infinity``: a record that holds them is damaged, so only :data:`_NUMBER` is accepted.
    """
    if _NUMBER.fullmatch(token) is None:
        problem = "not a finite number" if token.strip().lower() in NON_FINITE else "not a number"
        raise InputError(problem, file=file, where=where, value=token, allowed=NUMBER_ALLOWED)
    value = float(token)
    if not math.isfinite(value):
        raise InputError(
            "not a finite number", file=file, where=where, value=token, allowed=NUMBER_ALLOWED
        )
    return value


def number_shape(token: str) -> Shape:
    """(digits after the decimal point, digits of the exponent) of a number token.

    Fixed-format files print every value with the same shape (``.9459335E-03``: 7 and 2); a
    value cut at the end of the file has fewer of either (``.9459335E-0``: 7 and 1).
    """
    return _shape(_NUMBER.fullmatch(token))


def _shape(found: re.Match[str] | None) -> Shape:
    """The shape of a matched number token ((0, 0) for no match)."""
    if found is None:
        return (0, 0)
    fraction = found.group("frac") or found.group("bare") or ""
    return (len(fraction), len(found.group("exp") or ""))


def check_last_number(
    shapes: list[Shape], *, unterminated: bool, file: str, where: str, token: str
) -> None:
    """Refuse a last number that may have been cut off by a truncated file.

    A truncated file ends inside its last number (``head -c -2`` turns ``.9459335E-03`` into
    ``.9459335E-0``, read as 0.946), and so without a line break after it. A last line that
    ends with its line break was finished by its writer: nothing to check. A last line
    without one is accepted only when the file has a fixed format, MIN_FORMAT_EVIDENCE or
    more other numbers of the column sharing one shape, and the last number has that shape
    too (the Peknold El Centro file ends so); otherwise it is an error: "shorter than the
    others" when the format is fixed, "no line break" when the numbers are free-form.
    """
    if not unterminated or not shapes:
        return
    *others, last = shapes
    common = set(others)
    if len(others) >= MIN_FORMAT_EVIDENCE and len(common) == 1:
        (expected,) = common
        if last[0] >= expected[0] and last[1] >= expected[1]:
            return
        raise InputError(
            "the last number is shorter than every other number in the file "
            "(the file looks cut off)",
            file=file,
            where=where,
            value=token,
            allowed=f"{expected[0]} decimals"
            + (f" and a {expected[1]}-digit exponent" if expected[1] else "")
            + " like the other values; a complete file",
        )
    raise InputError(
        "the last line has no line break, so its last number may be cut off",
        file=file,
        where=where,
        value=token,
        allowed="a complete file whose last line ends with a line break",
    )


def parse_count(token: str, *, file: str, where: str) -> int:
    """A declared number of samples: an integer ≥ 1."""
    text = token.strip()
    count = int(text) if _COUNT.fullmatch(text) and len(text) <= MAX_COUNT_DIGITS else 0
    if count < 1:
        raise InputError(
            "the number of samples must be a whole number ≥ 1",
            file=file,
            where=where,
            value=token.strip(),
            allowed="an integer ≥ 1",
        )
    return count


def check_dt(dt: float, *, file: str | None, where: str | None) -> float:
    """Return dt if it is a finite number in [MIN_DT, MAX_DT] [s]; InputError otherwise."""
    allowed = f"{MIN_DT:g} s ≤ dt ≤ {MAX_DT:g} s"
    if math.isfinite(dt) and 0.0 < dt < MIN_DT:
        raise InputError(
            "the time step is implausibly small", file=file, where=where, value=dt, allowed=allowed
        )
    if math.isfinite(dt) and dt > MAX_DT:
        raise InputError(
            "the time step is implausibly large (a record samples at 50–1000 Hz)",
            file=file,
            where=where,
            value=dt,
            allowed=allowed,
        )
    if not (math.isfinite(dt) and dt > 0.0):
        raise InputError(
            "the time step must be greater than 0",
            file=file,
            where=where,
            value=dt,
            allowed=allowed,
        )
    return dt


def fixed_fields(line: str, width: int) -> list[str]:
    """Cut a line into fields of ``width`` characters (trailing blanks ignored).

    Fixed-width files let negative numbers touch (``-3.99E-09-4.00E-09``, spec/records.md,
    cor.acc), so such lines are sliced, never split on blanks.
    """
    body = line.rstrip()
    return [body[i : i + width].strip() for i in range(0, len(body), width)]


def read_values(
    lines: list[str], *, first_line: int, file: str, split: Splitter = str.split
) -> np.ndarray:
    """Every number in the data lines (see :func:`read_tokens`)."""
    return read_tokens(lines, first_line=first_line, file=file, split=split)[0]


def read_tokens(
    lines: list[str], *, first_line: int, file: str, split: Splitter = str.split
) -> tuple[np.ndarray, list[str]]:
    """Every number in the data lines, in order, and its token; blank lines are skipped.

    The last number is checked for a cut (:func:`check_last_number`): ``lines`` must run to
    the end of the file (the last item of :func:`split_lines`, empty when the file ends with a
    line break).

    Args:
        lines: the data lines (after the header), to the end of the file.
        first_line: the 1-based number of the first of them in the file (for errors).
        file: the file name, for errors.
        split: cuts a line into tokens (blank-separated by default).
    """
    values: list[float] = []
    tokens: list[str] = []
    shapes: list[Shape] = []
    last_line = first_line
    for number, line in enumerate(lines, start=first_line):
        for token in split(line):
            found = _NUMBER.fullmatch(token)
            value = float(token) if found else math.nan
            if not math.isfinite(value):
                parse_number(token, file=file, where=f"line {number}")  # raises, naming it
            values.append(value)
            tokens.append(token)
            shapes.append(_shape(found))
            last_line = number
    unterminated = bool(lines) and bool(lines[-1].strip())
    check_last_number(
        shapes,
        unterminated=unterminated,
        file=file,
        where=f"line {last_line}",
        token=tokens[-1] if tokens else "",
    )
    return np.asarray(values, dtype=float), tokens


def printed_ulp(token: str) -> float:
    """One unit of the last printed digit of a number token (``6.5065524E+00`` → 1e-7)."""
    exponent = Decimal(token).as_tuple().exponent
    return 10.0 ** int(exponent) if isinstance(exponent, int) else 0.0


def check_declared_pga(
    values: np.ndarray,
    tokens: list[str],
    declared: str,
    *,
    file: str,
    where: str,
    to_declared: float = 1.0,
) -> None:
    """The PGA a header declares must match the data's max|a| to the printed digits.

    Both numbers are rounded prints of the same peak: the header to its own digits, the
    sample to the data's. So they may differ by half a unit of the header's last digit plus
    half a unit of the peak sample's last digit (plus 1e-9 relative for the float parse).
    A header PGA may be signed (ESM writes the signed peak): its magnitude is compared.

    Args:
        values, tokens: the data as read and as printed.
        declared: the header's PGA token.
        to_declared: factor from the data's unit to the header PGA's unit.
    """
    if not values.size or not is_number(declared):
        return
    index = int(np.argmax(np.abs(values)))
    peak = abs(float(values[index])) * to_declared
    stated = abs(float(declared))
    tol = 0.5 * printed_ulp(declared) + 0.5 * printed_ulp(tokens[index]) * to_declared
    tol += PARSE_RTOL * max(peak, stated)
    if abs(peak - stated) > tol:
        raise InputError(
            "the header's PGA does not match the data (a damaged or cut file?)",
            file=file,
            where=where,
            value=declared,
            allowed=f"the data's peak {peak:.8g} ± {tol:.2g} (printed digits)",
        )


def check_count(values: np.ndarray, declared: int, *, file: str, where: str) -> None:
    """The number of values read must equal the declared count (spec/records.md, "Checks")."""
    if values.size != declared:
        raise InputError(
            f"{values.size} values read but the header declares {declared}",
            file=file,
            where=where,
            value=values.size,
            allowed=f"exactly {declared} values",
        )


def check_sample_count(count: float, *, where: str, what: str) -> int:
    """floor(count) samples to generate, capped at MAX_SAMPLES (InputError beyond)."""
    if not (math.isfinite(count) and count < MAX_SAMPLES + 1):
        raise InputError(
            f"{what} would need {count:.3g} samples",
            where=where,
            value=count,
            allowed=f"at most {MAX_SAMPLES:,} samples (a larger time step or a shorter record)",
        )
    return math.floor(count)


def check_time_axis(time: np.ndarray, *, file: str | None) -> None:
    """Times must be finite, strictly increasing, with a finite duration."""
    finite = np.isfinite(time)
    if not finite.all():
        index = int(np.argmin(finite))
        raise InputError(
            "the time axis overflows (a time is not finite)",
            file=file,
            where=f"sample {index + 1}",
            value=float(time[index]),
            allowed="finite times (a plausible dt and number of samples)",
        )
    span = float(time[-1]) - float(time[0])
    if not math.isfinite(span):
        raise InputError(
            "the record's duration overflows",
            file=file,
            value=span,
            allowed="a finite duration (times between ±1e300 s)",
        )
    if time.size > 1 and not bool((np.diff(time) > 0.0).all()):
        index = int(np.argmin(np.diff(time) > 0.0)) + 1
        raise InputError(
            "time does not increase (the steps vanish at this magnitude of time)",
            file=file,
            where=f"sample {index + 1}",
            value=float(time[index]),
            allowed="strictly increasing times",
        )


class Reading(NamedTuple):
    """How a record was read, for the error of a value out of range: the unit the file's
    values were taken in, and whether the unit came from ``--units`` (a plain file)."""

    unit: str
    plain: bool


def check_accel(
    accel: np.ndarray, time: np.ndarray, *, file: str | None, reading: Reading | None
) -> None:
    """|a| ≤ MAX_ABS_ACCEL_G (NaN fails too). For a record read, the message names the likely
    cause (a damaged file or a wrong unit) and the unit to check; ``reading`` None: a record
    made by rock (a transformation, a pulse, a floor motion), whose values have no unit slip.
    """
    bad = ~(np.abs(accel) <= MAX_ABS_ACCEL_G)
    if not bad.any():
        return
    index = int(np.argmax(bad))
    value = f"{float(accel[index]):.6g} g"
    problem = f"acceleration beyond {MAX_ABS_ACCEL_G:g} g"
    allowed = f"|a| ≤ {MAX_ABS_ACCEL_G:g} g"
    if reading is not None:
        value += f" (read as {reading.unit})"
        problem += " (a damaged file or a wrong unit)"
        allowed += "; " + (
            "check --units" if reading.plain else "check the unit the file's header declares"
        )
    raise InputError(
        problem,
        file=file,
        where=f"sample {index + 1} (t = {float(time[index]):g} s)",
        value=value,
        allowed=allowed,
    )


def check_record(record: Record, *, file: str | None, reading: Reading | None = None) -> None:
    """What every record is, read from a file or about to be written (one set of checks).

    At least MIN_RECORD_SAMPLES samples, dt in [MIN_DT, MAX_DT], a finite strictly
    increasing time axis, |a| ≤ MAX_ABS_ACCEL_G with no NaN. The readers call it on what they
    read (:func:`finish_record`), the writer on what it is about to write
    (:func:`rockcli.records.files.check_to_write`), so a file rock writes is one rock reads.

    Args:
        record: the record.
        file: the file named in the errors (the one read; None for a record to write).
        reading: how a record read was read (its unit, plain or not), for the hint of an
            acceleration out of range; None for a record about to be written.
    """
    if record.npts < MIN_RECORD_SAMPLES:
        raise InputError(
            f"{record.npts} sample(s): a record needs at least {MIN_RECORD_SAMPLES}",
            file=file,
            value=record.npts,
            allowed=f"{MIN_RECORD_SAMPLES} samples or more",
        )
    check_dt(record.dt, file=file, where="dt")
    check_time_axis(record.time, file=file)
    check_accel(record.accel, record.time, file=file, reading=reading)


def pga_warnings(
    accel: np.ndarray, *, unit: str, plain: bool, declared: bool = True
) -> tuple[str, ...]:
    """A warning when the PGA suggests a unit slip (none for a plausible PGA).

    A record whose unit nothing declared (``declared`` False: a plain-text file read as g by
    default) warns above UNDECLARED_PGA_G, naming both slips and their factors; a record whose
    unit a header or the user declared warns above PLAUSIBLE_PGA_G only (real records exceed
    1 g, docs/interpretations.md, "Records").
    """
    pga = float(np.max(np.abs(accel))) if accel.size else 0.0
    if not declared and pga > UNDECLARED_PGA_G:
        return (undeclared_unit_warning(pga),)
    if pga <= PLAUSIBLE_PGA_G:
        return ()
    fix = "check the unit the file's header declares"
    if plain:
        fix = "check --units and the file's '# units:' line"
    return (f"PGA {pga:.4g} g is above {PLAUSIBLE_PGA_G:g} g, implausible for a ground motion "
            f"(read as {unit}): {fix}",)  # fmt: skip


def slips_text(pga: float) -> str:
    """What the PGA would be if the values were in m/s² or in cm/s², with the factors."""
    f_m, f_cm = SLIP_FACTORS
    return (
        f"in m/s² it would be {pga / f_m:.3g} g (÷ {f_m:.3g}), "
        f"in cm/s² {pga / f_cm:.3g} g (÷ {f_cm:.3g})"
    )


def undeclared_unit_warning(pga: float) -> str:
    """The warning of a record above UNDECLARED_PGA_G whose unit was assumed to be g."""
    return (
        f"PGA {pga:.4g} g is above {UNDECLARED_PGA_G:g} g and nothing declares the file's unit "
        f"(read as g, the default): check the unit: {slips_text(pga)}. Real records can "
        "exceed 1 g: declare the unit with --units or a '# units:' line in the file"
    )


def finish_record(record: Record) -> Record:
    """Check a record just read (time axis, bounded accelerations) and add its warnings."""
    plain = record.format == "plain"
    check_record(record, file=record.source, reading=Reading(record.unit, plain))
    warnings = pga_warnings(
        record.accel, unit=record.unit, plain=plain, declared=record.unit_declared
    )
    return replace(record, warnings=(*record.warnings, *warnings)) if warnings else record


class Origin(NamedTuple):
    """What a record's header says it is: the event, the station and the component."""

    event: str = ""
    station: str = ""
    component: str = ""


def uniform_record(
    values: np.ndarray,
    *,
    dt: float,
    unit: AccelUnit,
    fmt: str,
    name: str,
    source: str,
    notes: tuple[str, ...] = (),
    origin: Origin | None = None,
    unit_declared: bool = True,
) -> Record:
    """A checked Record sampled at t = i·dt, with values converted from ``unit`` to g.

    ``origin`` holds the event, station and component the file's header names, if any.
    """
    origin = origin or Origin()
    with np.errstate(over="ignore", invalid="ignore"):
        time = np.arange(values.size) * dt
        accel = values * unit.to_g
    return finish_record(
        Record(
            name=name,
            source=source,
            format=str(fmt),
            time=time,
            accel=accel,
            dt=dt,
            unit=str(unit),
            notes=notes,
            event=origin.event,
            station=origin.station,
            component=origin.component,
            unit_declared=unit_declared,
        )
    )
