"""The options of `rock spectrum overturning` read into the plan of its runs: the scan, what
rocks (a block of --alpha, or --model) and its points (the pulses' ratios, or each record at
each size or building period), every value checked here, at the edge (one InputError naming
the option, the value and what is allowed)."""

from __future__ import annotations

import math

from rockcli.errors import InputError
from rockcli.studies.fragility.search import MAX_SCAN_POINTS, MIN_TOLERANCE_SHARE

#: Most values of --ratios, --p or --R.
MAX_VALUES = 200
PULSES = ("one-sine", "one-cosine", "ricker")
DEFAULT_RATIOS = "1,2,3,4,6,8"


def make_scan(first: float, step: float, last: float, tolerance: float):
    """The Scan of the options (InputError naming the option at fault)."""
    from rockcli.studies.fragility.spectrum import Scan

    for option, value in (
        ("--scan-from", first),
        ("--scan-step", step),
        ("--tolerance", tolerance),
    ):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(
                "not a positive number", where=option, value=value, allowed="a finite number > 0"
            )
    if not (math.isfinite(last) and last >= first):
        raise InputError(
            "ends before the scan starts",
            where="--scan-to",
            value=last,
            allowed=f"a finite number ≥ --scan-from ({first:g})",
        )
    if (last - first) / step + 1.0 > MAX_SCAN_POINTS:
        raise InputError(
            "too many scan points",
            where="--scan-step",
            value=step,
            allowed=f"a step ≥ (scan-to − scan-from)/{MAX_SCAN_POINTS - 1}",
        )
    if tolerance < MIN_TOLERANCE_SHARE * last:
        raise InputError(
            "narrower than a float can resolve at the scan's end: the bisection would not end",
            where="--tolerance",
            value=tolerance,
            allowed=f"a tolerance ≥ {MIN_TOLERANCE_SHARE:g} × --scan-to "
            f"({MIN_TOLERANCE_SHARE * last:.3g})",
        )
    if tolerance >= step:
        raise InputError(
            "not below the scan step",
            where="--tolerance",
            value=tolerance,
            allowed=f"0 < tolerance < --scan-step ({step:g})",
        )
    return Scan(first, step, last, tolerance)


#: What each way of naming the rocked thing takes.
MODES = {
    "--pulse": "--pulse with --ratios and --alpha or --model; --record with --p, --R or "
    "--floor-periods",
    "--record": "--record FILE with --alpha A [--e E] or --model MODEL, and --p, --R or "
    "--floor-periods (--ratios goes with --pulse)",
    "--alpha": "--alpha A [--e E] [--linearized]; --mechanism, --ground and --floor-periods go "
    "with --model",
    "--model": "--model MODEL [--mechanism NAME] [--ground]; --alpha, --e and --linearized go "
    "with a block (a model sets its own)",
}


def check_mode(mode: str, **given) -> None:
    """Refuse the options that do not go with ``mode`` (InputError)."""
    for name, value in given.items():
        if value:
            raise InputError(f"not used with {mode}", where=f"--{name}", allowed=MODES[mode])


def parse_values(text: str, option: str) -> list[float]:
    """``2,4,6`` → [2.0, 4.0, 6.0]: finite, > 0, at most MAX_VALUES (InputError)."""
    from rockcli.numbers import ascii_float

    items = [item.strip() for item in text.split(",")]
    try:
        values = [ascii_float(item) for item in items]
    except ValueError:
        values = []
    if (
        not values
        or len(values) > MAX_VALUES
        or not all(math.isfinite(v) and v > 0.0 for v in values)
    ):
        raise InputError(
            "not a list of positive numbers",
            where=option,
            value=text,
            allowed=f"1 to {MAX_VALUES} numbers > 0, comma-separated: 2,4,6",
        )
    return values


#: Where the block table's errors point: its fields → the options that set them.
BLOCK_OPTIONS = {"geometry.alpha": "--alpha", "restitution.e": "--e", "geometry.R": "--R"}


def block_table(alpha: float, e: float | None, linearized: bool, R: float = 1.0) -> dict:
    """The model table of a free block (as the casebook's threshold cases write it)."""
    restitution = {"model": "housner"} if e is None else {"model": "explicit", "e": e}
    return {
        "name": f"block alpha = {alpha:g} rad",
        "kind": "wall",
        "geometry": {"R": R, "alpha": alpha},
        "restitution": restitution,
        "analysis": {"linearized": linearized},
    }


def validate_block(table: dict, size_option: str = "--R"):
    """The validated block model (the loader's errors, naming the options)."""
    from rockcli.model.load import validate_model

    try:
        return validate_model(table)
    except InputError as exc:
        where = BLOCK_OPTIONS.get(exc.where or "", exc.where)
        where = size_option if where == "--R" else where
        if where == "--p":  # the loader saw R = 3g/(4p²): say it in p
            raise InputError(
                "out of range",
                where=where,
                value=p_of(table["geometry"]["R"]),
                allowed=_p_allowed(),
            ) from None
        raise InputError(exc.problem, where=where, value=exc.value, allowed=exc.allowed) from None


def p_of(R: float) -> float:
    """p = √(3g/(4R)) [rad/s] (Housner 1963), g = DEFAULT_GRAVITY."""
    from rockcli.units import DEFAULT_GRAVITY

    return math.sqrt(3.0 * DEFAULT_GRAVITY / (4.0 * R))


def _p_allowed() -> str:
    from rockcli.model.bounds import MAX_LENGTH, MIN_LENGTH

    return (
        f"{p_of(MAX_LENGTH):.4g} ≤ p ≤ {p_of(MIN_LENGTH):.4g} rad/s, the blocks of "
        f"{MIN_LENGTH:g} m ≤ R ≤ {MAX_LENGTH:g} m"
    )


def pulse_plan(pulse, ratios, alpha, e, linearized, model_path, mechanism, ground, engine, scan):
    """(target, subject, cases) of a pulse spectrum, every ratio's period checked."""
    from rockcli.studies.fragility.overturning import PulseCase, pulse_period_of, rocked_block

    values = parse_values(DEFAULT_RATIOS if ratios is None else ratios, "--ratios")
    target = pulse_target(alpha, e, linearized, model_path, mechanism, ground, engine)
    block, floor = rocked_block(validated(target), target)
    for ratio in values:
        check_ratio(ratio, pulse_period_of(ratio, block))
    check_top(scan.last * block.uplift_acceleration)
    subject = {
        "kind": "block" if model_path is None else "model",
        "alpha": alpha,
        "model": model_path,
        "mechanism": target.mechanism,
        "floor": floor is not None,
    }
    return target, subject, [PulseCase(i, pulse, r) for i, r in enumerate(values)]


def pulse_target(alpha, e, linearized, model_path, mechanism, ground, engine):
    """The Target of --alpha/--e/--linearized or of --model/--mechanism/--ground."""
    from rockcli.studies.fragility.overturning import Target

    if (alpha is None) == (model_path is None):
        raise InputError(
            "needs a block or a model",
            where="--pulse",
            allowed="--alpha A [--e E] or --model MODEL, one of them",
        )
    if model_path is None:
        check_mode("--alpha", mechanism=mechanism, ground=ground)
        return Target(validate_block_table(alpha, e, linearized), engine=engine)
    check_mode("--model", e=e is not None, linearized=linearized)
    from rockcli.model.load import read_toml, validate_model

    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    name = wall_mechanism(model, model_path, mechanism)
    return Target(table, model_path, name, ground, engine)


def validate_block_table(alpha, e, linearized, R: float = 1.0, size_option: str = "--R") -> dict:
    table = block_table(alpha, e, linearized, R)
    validate_block(table, size_option)
    return table


def wall_mechanism(model, model_path: str, mechanism: str | None) -> str | None:
    """The mechanism the model rocks: the one named, the only one of its catalogue (None),
    else the governing one under the model's own demand; a catalogue of several mechanisms
    without a demand of its own needs --mechanism (InputError)."""
    from rockcli.model.catalogue import catalogue

    if mechanism is not None:
        return mechanism
    mechanisms = catalogue(model)
    if len(mechanisms) == 1:
        return None
    if model.ntc is None or model.ntc.demand is None:
        names = ", ".join(m.name for m in mechanisms)
        raise InputError(
            "a wall needs the mechanism to rock (no demand of its own chooses one)",
            file=model_path,
            where="--mechanism",
            allowed=f"--mechanism NAME: {names}",
        )
    from rockcli.analyses.assess import rocked_input
    from rockcli.records.pulses import make_pulse

    probe = make_pulse("one-sine", 0.1, 1.0, dt=0.01)  # the model's demand chooses, not it
    rocked = rocked_input(model, probe, False, model_path, None)[3]
    return None if rocked is None else rocked[0]


def check_ratio(ratio: float, period: float) -> None:
    from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD

    if not MIN_PERIOD <= period <= MAX_PERIOD:
        raise InputError(
            f"gives a pulse period Tp = {period:.4g} s",
            where="--ratios",
            value=ratio,
            allowed=f"ratios whose Tp = 2π/(ratio·p) lies in [{MIN_PERIOD:g}, {MAX_PERIOD:g}] s",
        )


def check_top(amplitude: float) -> None:
    from rockcli.records.lines import MAX_ABS_ACCEL_G

    if amplitude > MAX_ABS_ACCEL_G:
        raise InputError(
            f"reaches ap = {amplitude:.4g} g",
            where="--scan-to",
            allowed=f"a scan whose pulses stay ≤ {MAX_ABS_ACCEL_G:g} g",
        )


def validated(target):
    from rockcli.model.load import validate_model

    return validate_model(target.table, file=target.file)


def read_records(record_paths, record_format, dt, units) -> list:
    """The --record files, each with some motion (InputError otherwise)."""
    from rockcli.cli.options import load_record

    if not record_paths:
        raise InputError(
            "needs --pulse or --record",
            where="spectrum overturning",
            allowed="--pulse one-sine|one-cosine|ricker, or --record FILE",
        )
    records = [load_record(path, record_format, dt, units, None, None) for path in record_paths]
    for path, rec in zip(record_paths, records, strict=True):
        if not (abs(rec.accel).max() > 0.0):
            raise InputError(
                "the record is all zeros",
                file=path,
                where="--record",
                allowed="a record with some motion",
            )
    return records


def block_sizes(records, alpha, e, linearized, p_values, R_values, engine):
    """(target, subject, cases, (option, sizes)) of a record spectrum of free blocks of
    slenderness --alpha: every size validated as a block."""
    from rockcli.studies.fragility.overturning import Target

    if alpha is None:
        raise InputError(
            "needs a block or a model",
            where="--record",
            allowed="--alpha A or --model MODEL, with --p or --R",
        )
    option, sizes, radii = parse_sizes(p_values, R_values)
    tables = [validate_block_table(alpha, e, linearized, R, option) for R in radii]
    subject = {"kind": "block", "alpha": alpha}
    cases = record_cases(records, radii, "R")
    return Target(tables[0], engine=engine), subject, cases, (option, sizes)


def parse_sizes(p_values, R_values) -> tuple[str, list[float], list[float]]:
    """(option, its values, the semi-diagonals R [m]) of --p or --R, exactly one given."""
    from rockcli.studies.fragility.overturning import radius_of
    from rockcli.units import DEFAULT_GRAVITY

    if (p_values is None) == (R_values is None):
        raise InputError(
            "needs the sizes", where="--record", allowed="--p P1,P2,… or --R R1,R2,…, one of them"
        )
    option = "--p" if p_values is not None else "--R"
    sizes = parse_values(p_values or R_values, option)
    radii = [radius_of(p, DEFAULT_GRAVITY) for p in sizes] if option == "--p" else sizes
    return option, sizes, radii


def model_sizes(records, model_path, mechanism, ground, p_values, R_values, periods, engine):
    """(target, subject, cases, (option, values)) of a record spectrum of MODEL: its block at
    each size (--p or --R, α kept: a model of one block), or in a building of each period
    (--floor-periods: a model at height, on its floor motion)."""
    from rockcli.model.catalogue import rocks_its_block
    from rockcli.model.load import read_toml, validate_model
    from rockcli.studies.fragility.overturning import Target, sized_table, with_period

    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    if periods is not None:
        check_mode("--floor-periods", p=p_values, R=R_values)
        if model.building is None or not model.building.Z > 0.0 or ground:
            raise InputError(
                "needs a model at height on its floor motion",
                file=model_path,
                where="--floor-periods",
                allowed="a model with [building] Z > 0, without --ground",
            )
        option, values, key = "--floor-periods", parse_values(periods, "--floor-periods"), "T1"
        tables = [with_period(table, T1) for T1 in values]
    else:
        if not rocks_its_block(model):
            raise InputError(
                "a frame's size is its piers'"
                if model.frame is not None
                else "a wall's size is its storeys'",
                file=model_path,
                where="--p" if p_values is not None else "--R",
                allowed="a model of one block for --p or --R; --floor-periods for a wall at height",
            )
        option, values, radii = parse_sizes(p_values, R_values)
        key = "R"
        tables = [sized_table(table, R) for R in radii]
        values_run = radii
    for value, sized in zip(values, tables, strict=True):
        try:
            validate_model(sized, file=model_path)
        except InputError as exc:
            raise InputError(
                f"gives a model the loader refuses: {exc.where}: {exc.problem}",
                file=model_path,
                where=option,
                value=value,
                allowed=exc.allowed,
            ) from None
    name = wall_mechanism(model, model_path, mechanism)
    target = Target(table, model_path, name, ground, engine)
    subject = {"kind": "model", "model": model_path, "mechanism": name}
    run_values = values if key == "T1" else values_run
    return target, subject, record_cases(records, run_values, key), (option, values)


def record_cases(records, values, key: str) -> list:
    """One case per record and value, records outermost."""
    from rockcli.studies.fragility.overturning import RecordCase

    return [
        RecordCase(i * len(values) + j, rec, v, key)
        for i, rec in enumerate(records)
        for j, v in enumerate(values)
    ]
