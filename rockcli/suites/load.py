"""Reading a suite file: TOML, the schema, the rules across keys, then the records.

Every problem is one :class:`~rockcli.errors.InputError` naming the suite file, the key or
record entry, the value and what is allowed.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError
from pydantic_core import ErrorDetails

from rockcli.codecheck.categories import Edition
from rockcli.errors import InputError, printable
from rockcli.model.bounds import MAX_PERIOD, MIN_PERIOD
from rockcli.model.load import TRANSLATION, read_toml
from rockcli.numbers import ascii_float, ascii_int
from rockcli.records.periods import MAX_PERIOD as MAX_SPECTRUM_PERIOD
from rockcli.records.periods import MIN_PERIOD as MIN_SPECTRUM_PERIOD
from rockcli.records.record import Record
from rockcli.suites.schema import Suite, Target

#: Fewest records of a suite (NTC §3.2.3.6: at least 3, the worst effect governing).
MIN_RECORDS = 3
#: The code's period range [s] (NTC 2008 and 2018 §3.2.3.6: 0.15–2.0 s, and 0.15 s–2T).
CODE_PERIOD_RANGE = (0.15, 2.0)
#: Lower tolerance on the mean spectrum, both editions (no point more than 10 % below).
CODE_LOWER_TOLERANCE = -0.10
#: Upper tolerance of NTC 2018 (no point more than 30 % above); NTC 2008 sets none.
CODE_UPPER_TOLERANCE_2018 = 0.30
#: Longest text value quoted back in an error line (characters).
MAX_QUOTED = 60
#: The lowest tolerance there can be: the mean at zero (−100 %).
TOLERANCE_FLOOR = -1.0


@dataclass(frozen=True)
class SuiteEntry:
    """One record of the suite: its label, file (resolved beside the suite file), scale."""

    name: str
    path: Path
    scale: float
    where: str


@dataclass(frozen=True)
class SuiteSettings:
    """A validated suite with every default resolved.

    Attributes:
        name: the suite's name. file: the suite file as the user gave it.
        entries: the records. target: the target table.
        period_range: (a, b) [s]. tolerance: (lo, hi) as fractions (hi may be inf).
        folder: the folder the records' paths are relative to (the suite file's, or the
            folder of records itself).
    """

    name: str
    file: str
    entries: tuple[SuiteEntry, ...]
    target: Target
    period_range: tuple[float, float]
    tolerance: tuple[float, float]
    folder: Path = Path()


#: The files a folder of records takes as its suite, by suffix (any case): PEER AT2, ESM
#: ASCII, ITACA cor.acc, plain text. Other files (notes, metadata) are not records.
RECORD_SUFFIXES = (".at2", ".asc", ".acc", ".txt", ".dat")
#: What --target takes.
TARGET_ALLOWED = (
    "KEY=VALUE pairs separated by commas, the keys of a suite's [target]: e.g. "
    "lon=13.40,lat=42.35,limit_state=SLV,soil=A or ag=0.25,F0=2.4,Tc_star=0.3"
)


def load_suite(
    path: str | os.PathLike[str],
    *,
    period: float | None = None,
    target: str | None = None,
    allow_outside: bool = False,
) -> SuiteSettings:
    """Read, validate and resolve a suite file, or a folder of records with its target.

    Args:
        path: the TOML suite file, or a folder whose record files (RECORD_SUFFIXES) are the
            suite, each at scale 1, named by its file.
        period: the structure's period T [s] (``--period``): the range becomes 0.15 s to
            max(2.0 s, 2T) (NTC §3.2.3.6); refused when the file gives ``period_range``.
        target: the ``--target`` text of a folder (a suite file has its own [target]).
        allow_outside: let the records lie outside the suite's folder (``--allow-outside``);
            by default each must resolve (``..`` and symlinks followed) inside it
            (rockcli.inside: a suite received from someone else reads only its own files).

    Raises:
        InputError: unreadable or malformed file, a bad key, a rule across keys broken, or a
            record outside the suite's folder.
    """
    file = os.fspath(path)
    if os.path.isdir(file):
        try:
            suite = validate_suite(folder_suite(file, target), file)
        except InputError as exc:
            raise on_target_option(exc) from None
        settings = resolve(suite, file, period, base=Path(file))
    else:
        if target is not None:
            raise InputError(
                "not used: a suite file has its own [target]",
                where="--target",
                value=target,
                allowed="--target only with a folder of records (--suite DIR)",
            )
        settings = resolve(validate_suite(read_toml(file), file), file, period)
    if not allow_outside:
        check_entries_inside(settings)
    return settings


#: What a record of a suite may be without --allow-outside.
INSIDE_ALLOWED = (
    "a record inside the suite's folder (a path relative to it, no link to elsewhere), "
    "or --allow-outside"
)


def check_entries_inside(settings: SuiteSettings) -> None:
    """Refuse a record that resolves outside the suite's folder (an absolute path, ``..``, a
    symlink to elsewhere), naming the entry."""
    from rockcli.inside import check_inside

    for entry in settings.entries:
        check_inside(
            entry.path, settings.folder, file=settings.file, where=f"{entry.where}.path",
            value=str(entry.path), problem="leaves the suite's folder", allowed=INSIDE_ALLOWED,
        )  # fmt: skip


def folder_suite(folder: str, target: str | None) -> dict[str, Any]:
    """The suite table of a folder: its record files, sorted by name, and --target."""
    if target is None:
        raise InputError(
            "a folder of records needs its target spectrum",
            file=folder,
            where="--target",
            allowed=TARGET_ALLOWED,
        )
    files = sorted(
        p
        for p in Path(folder).iterdir()
        if not p.name.startswith(".") and p.suffix.lower() in RECORD_SUFFIXES
    )
    for path in files:
        check_folder_record(path)
    name = Path(folder).resolve().name or folder
    records = [{"path": p.name} for p in files]
    return {"name": name, "records": records, "target": parse_target(target)}


def check_folder_record(path: Path) -> None:
    """A file of a folder suite with a record's suffix must be a record: a link to nothing (a
    record moved or not copied) or a subfolder is an error, never a record silently left out
    (with 7 records the code's rule is the mean; with 6, the worst)."""
    if path.is_symlink() and not path.exists():
        raise InputError(
            "a link to a file that does not exist (a record of the folder is missing)",
            file=str(path),
            value=os.readlink(path),
            allowed="a record file, or remove the link (each file with a record's suffix, "
            + ", ".join(RECORD_SUFFIXES)
            + ", is a record of the suite)",
        )


def parse_target(text: str) -> dict[str, Any]:
    """``lon=13.4,lat=42.35,soil=A`` → {"lon": 13.4, "lat": 42.35, "soil": "A"} (numbers as
    numbers, the rest as text; the schema then checks each key)."""
    out: dict[str, Any] = {}
    for item in text.split(","):
        key, sep, value = (part.strip() for part in item.partition("="))
        if not sep or not key or not value or key in out:
            raise InputError(
                "not a KEY=VALUE pair" if key not in out else "key given twice",
                where="--target",
                value=item.strip(),
                allowed=TARGET_ALLOWED,
            )
        out[key] = number_or_text(value)
    return out


def number_or_text(value: str) -> int | float | str:
    """An int, else a float, else the text (as a TOML value would be). Only ASCII digits make
    a number: ``０.３`` (fullwidth) stays text, which the schema then refuses for a number."""
    for kind in (ascii_int, ascii_float):
        try:
            return kind(value)
        except ValueError:
            continue
    return value


def on_target_option(exc: InputError) -> InputError:
    """An error in a folder suite's target, named as the option: ``--target soil``."""
    where = exc.where or ""
    if where == "target" or where.startswith("target."):
        where = "--target" + (" " + where.removeprefix("target.") if "." in where else "")
        return InputError(exc.problem, file=exc.file, where=where, value=exc.value,
                          allowed=exc.allowed)  # fmt: skip
    return exc


def validate_suite(data: Mapping[str, Any], file: str | None = None) -> Suite:
    """The schema and the rules across keys; InputError (the first problem) otherwise."""
    try:
        suite = Suite.model_validate(data)
    except ValidationError as exc:
        # A top-level key written under [target] first: it is the cause of the other errors.
        errors = sorted(exc.errors(), key=lambda err: misplaced_key(err) is None)
        raise translate(errors[0], file) from None
    check_rules(suite, file)
    return suite


#: The keys of a suite file outside [target]: written after the [target] line, TOML puts
#: them in that table.
TOP_LEVEL_KEYS = ("name", "period_range", "tolerance", "records")


def misplaced_key(err: ErrorDetails) -> str | None:
    """The top-level key an unknown key of [target] is (``period_range`` written under
    [target]), or None."""
    loc = err["loc"]
    if err["type"] == "extra_forbidden" and len(loc) == 2 and loc[0] == "target":
        return str(loc[1]) if loc[1] in TOP_LEVEL_KEYS else None
    return None


def translate(err: ErrorDetails, file: str | None) -> InputError:
    """One pydantic error of the suite file as one InputError."""
    key = misplaced_key(err)
    if key is not None:
        return InputError(
            "a top-level key, write it above [target]",
            file=file,
            where=f"target.{key}",
            allowed=f"{key} before the [target] line: TOML puts every key written after "
            "[target] inside that table",
        )
    problem, _ = TRANSLATION.get(err["type"], (None, None))
    ctx = err.get("ctx", {})
    limits = (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<="))
    bounds = " and ".join(f"{symbol} {ctx[key]:g}" for key, symbol in limits if key in ctx)
    allowed = f"a number {bounds}" if bounds else None
    value = None if err["type"] == "missing" else err.get("input")
    if isinstance(value, str) and len(value) > MAX_QUOTED:
        value = value[:MAX_QUOTED] + "…"
    return InputError(
        problem or " ".join(err["msg"].split()),
        file=file,
        where=dotted(err["loc"]) or None,
        value=value if isinstance(value, int | float | str) else None,
        allowed=allowed or _allowed(err),
    )


def dotted(loc: Sequence[str | int]) -> str:
    """``('records', 0, 'scale')`` → ``records[0].scale``."""
    text = ""
    for part in loc:
        text += f"[{part}]" if isinstance(part, int) else ("." if text else "") + printable(part)
    return text


def _allowed(err: ErrorDetails) -> str | None:
    ctx = err.get("ctx", {})
    if "expected" in ctx:
        return f"one of: {ctx['expected']}"
    if err["type"] == "extra_forbidden":
        return "name, records, target, period_range, tolerance and their keys"
    if err["type"] == "missing":
        return "required"
    if err["type"].startswith(("float", "int", "finite")):
        return "a number"
    return None


def check_rules(suite: Suite, file: str | None) -> None:
    """The rules across keys (InputError naming the first broken one)."""
    check_records(suite, file)
    check_target(suite.target, file)
    if suite.period_range is not None:
        check_period_range(suite.period_range, file)
    if suite.tolerance is not None:
        check_tolerance(suite.tolerance, file)


def check_records(suite: Suite, file: str | None) -> None:
    """At least MIN_RECORDS records, none listed twice (same file, or same name)."""
    if len(suite.records) < MIN_RECORDS:
        raise InputError(
            "too few records for the code's rule",
            file=file,
            where="records",
            value=len(suite.records),
            allowed=f"at least {MIN_RECORDS} [[records]] (7 or more for the mean)",
        )
    seen: dict[str, int] = {}
    for i, (entry, name) in enumerate(zip(suite.records, suite.record_names(), strict=True)):
        if "\x00" in entry.path:
            raise InputError(
                "a NUL character in the path",
                file=file,
                where=f"records[{i}].path",
                value=entry.path,
                allowed="a file name without NUL (\\u0000) characters",
            )
        for key in (f"path {os.path.normpath(entry.path)}", f"name {name}"):
            if key in seen:
                raise InputError(
                    f"record listed twice (the same {key.split()[0]} as records[{seen[key]}])",
                    file=file,
                    where=f"records[{i}]",
                    value=entry.path if key.startswith("path") else name,
                    allowed="each record once, with its own name",
                )
            seen[key] = i


def check_target(target: Target, file: str | None) -> None:
    """A site (lon and lat) or the parameters (ag, F0, Tc_star), all of one and none of the
    other."""
    site = {k: getattr(target, k) for k in ("lon", "lat")}
    params = {k: getattr(target, k) for k in ("ag", "F0", "Tc_star")}
    allowed = "either lon and lat (the hazard grid) or ag, F0 and Tc_star"
    has_site = any(v is not None for v in site.values())
    has_params = any(v is not None for v in params.values())
    if has_site == has_params:
        problem = "both a site and spectrum parameters" if has_site else "no site and no parameters"
        raise InputError(problem, file=file, where="target", allowed=allowed)
    group = site if has_site else params
    for key, value in group.items():
        if value is None:
            raise InputError("missing key", file=file, where=f"target.{key}", allowed=allowed)


#: The periods a suite may be checked at [s]: those of the response spectra
#: (rockcli.records.periods, as `rock record spectrum --periods`).
PERIODS_ALLOWED = (
    f"{MIN_SPECTRUM_PERIOD:g} s to {MAX_SPECTRUM_PERIOD:g} s, the periods of a response spectrum"
)


def check_period_range(values: Sequence[float], file: str | None) -> None:
    """[a, b] with 0.001 s ≤ a < b ≤ 100 s, the periods of a response spectrum (beyond, the
    exact-step coefficients lose their digits; rockcli.records.periods)."""
    if len(values) != 2 or not 0.0 < values[0] < values[1]:
        raise InputError(
            "not a period range",
            file=file,
            where="period_range",
            value=list(values),
            allowed=f"[a, b] with 0 < a < b [s], both from {PERIODS_ALLOWED}",
        )
    if not MIN_SPECTRUM_PERIOD <= values[0] < values[1] <= MAX_SPECTRUM_PERIOD:
        raise InputError(
            "period range out of bounds",
            file=file,
            where="period_range",
            value=list(values),
            allowed=f"[a, b] with a < b, both from {PERIODS_ALLOWED}",
        )


def check_tolerance(values: Sequence[float], file: str | None) -> None:
    """[lo, hi] with −1 < lo < hi (fractions; hi may be inf)."""
    if len(values) != 2 or not TOLERANCE_FLOOR < values[0] < values[1]:
        raise InputError(
            "not a tolerance band",
            file=file,
            where="tolerance",
            value=list(values),
            allowed="[lo, hi] as fractions with -1 < lo < hi, e.g. [-0.10, 0.30]",
        )


def resolve(
    suite: Suite, file: str, period: float | None, *, base: Path | None = None
) -> SuiteSettings:
    """The settings with the defaults of the edition and the period applied; record paths
    relative to ``base`` (default: the suite file's folder)."""
    base = Path(file).parent if base is None else base
    entries = tuple(
        SuiteEntry(name, base / r.path, r.scale, f"records[{i}]")
        for i, (r, name) in enumerate(zip(suite.records, suite.record_names(), strict=True))
    )
    return SuiteSettings(
        name=suite.name,
        file=file,
        entries=entries,
        target=suite.target,
        period_range=period_range(suite, file, period),
        tolerance=default_tolerance(suite),
        folder=base,
    )


def period_range(suite: Suite, file: str, period: float | None) -> tuple[float, float]:
    """The file's range, else 0.15 s to max(2.0 s, 2T) (NTC §3.2.3.6)."""
    if period is not None and suite.period_range is not None:
        raise InputError(
            "conflicts with the suite file's period_range",
            where="--period",
            value=period,
            allowed=f"--period T, or period_range in {file}, not both",
        )
    if suite.period_range is not None:
        return suite.period_range[0], suite.period_range[1]
    a, b = CODE_PERIOD_RANGE
    if period is None:
        return a, b
    if not MIN_PERIOD <= period <= MAX_PERIOD:  # a building's T1 (1e300 s overflowed)
        raise InputError(
            "out of range",
            where="--period",
            value=period,
            allowed=f"{MIN_PERIOD:g} s ≤ T ≤ {MAX_PERIOD:g} s, as a model's building.T1",
        )
    return a, max(b, 2.0 * period)


def default_tolerance(suite: Suite) -> tuple[float, float]:
    """The file's band, else −10 % and +30 % (2018) or no upper bound (2008)."""
    if suite.tolerance is not None:
        return suite.tolerance[0], suite.tolerance[1]
    if suite.target.edition is Edition.E2009:
        return CODE_LOWER_TOLERANCE, math.inf
    return CODE_LOWER_TOLERANCE, CODE_UPPER_TOLERANCE_2018


def read_entries(settings: SuiteSettings) -> list[Record]:
    """Every record of the suite, read and scaled; InputError naming the suite file and the
    record entry when one does not read, is zero everywhere, or scales out of bounds."""
    records = [read_entry(entry, settings.file) for entry in settings.entries]
    check_distinct(records, settings)
    return [
        scaled(record, entry, settings.file)
        for record, entry in zip(records, settings.entries, strict=True)
    ]


def check_distinct(records: Sequence[Record], settings: SuiteSettings) -> None:
    """Refuse two entries that hold the same motion (the same samples at the same times, as
    read, before scaling): two copies of a record, under two names or with other line ends,
    are one record for the code's count."""
    import hashlib

    seen: dict[str, int] = {}
    for i, record in enumerate(records):
        digest = hashlib.sha256(record.time.tobytes() + record.accel.tobytes()).hexdigest()
        if digest in seen:
            first, entry = settings.entries[seen[digest]], settings.entries[i]
            raise InputError(
                f"record {entry.name!r} is the same motion as {first.name!r} ({first.where})",
                file=settings.file,
                where=f"{entry.where}.path",
                value=str(entry.path),
                allowed="each record once (a record's copies count once for the code)",
            )
        seen[digest] = i


def read_entry(entry: SuiteEntry, file: str) -> Record:
    """One record as read (InputError naming the suite file and the entry)."""
    from rockcli.records.files import read_record

    try:
        record = read_record(entry.path)
    except InputError as exc:  # its message names the record file and what is allowed
        raise InputError(
            f"record {entry.name!r} does not read: {printable(exc.render())}",
            file=file,
            where=f"{entry.where}.path",
        ) from None
    if not record.pga > 0.0:
        raise InputError(
            f"record {entry.name!r} is zero everywhere (PGA 0)",
            file=file,
            where=f"{entry.where}.path",
            value=str(entry.path),
            allowed="a record with motion in it",
        )
    return record


def scaled(record: Record, entry: SuiteEntry, file: str) -> Record:
    """The record times its scale (InputError when the scaled PGA is implausible)."""
    from rockcli.records.transform import scale

    if entry.scale == 1.0:
        return record
    try:
        return scale(record, entry.scale)
    except InputError as exc:
        raise InputError(
            exc.problem,
            file=file,
            where=f"{entry.where}.scale",
            value=entry.scale,
            allowed=exc.allowed,
        ) from None
