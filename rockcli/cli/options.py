"""Options shared by several commands."""

from __future__ import annotations

import math

import click

from rockcli.cli.inputs import InputPath


class AsciiFloat(click.ParamType):
    """A number option written in ASCII: click's ``float`` reads ``０.５`` (fullwidth digits)
    as 0.5, like Python's ``float()`` (rockcli.numbers)."""

    name = "float"

    def convert(self, value, param, ctx):  # click.ParamType.convert
        if isinstance(value, float):
            return value
        from rockcli.numbers import ascii_float

        try:
            return ascii_float(str(value).strip())
        except ValueError:
            self.fail(f"{value!r} is not a number written in ASCII digits", param, ctx)


#: The type of a number option (rather than click's ``float``).
ASCII_FLOAT = AsciiFloat()


class AsciiIntRange(click.IntRange):
    """A whole-number option in a range, written in ASCII (click's ``IntRange`` reads
    ``４`` as 4, like Python's ``int()``; rockcli.numbers)."""

    def convert(self, value, param, ctx):  # click.ParamType.convert
        if isinstance(value, str) and not value.isascii():
            self.fail(f"{value!r} is not a number written in ASCII digits", param, ctx)
        return super().convert(value, param, ctx)


output_format = click.option(
    "--format",
    "output",
    type=click.Choice(["table", "json"]),
    default="table",
    show_default=True,
    help="Rich tables for people, one JSON document for machines.",
)


def output_format_csv(help_text: str):
    """``--format table|json|csv``: output_format with CSV, ``help_text`` saying what each
    gives."""
    return click.option(
        "--format",
        "output",
        type=click.Choice(["table", "json", "csv"]),
        default="table",
        show_default=True,
        help=help_text,
    )


record_format = click.option(
    "--as",
    "record_format",
    type=click.Choice(["at2", "esm", "coracc", "plain"]),
    default=None,
    help="Force the record format instead of detecting it from the content.",
)
plain_dt = click.option(
    "--dt",
    type=ASCII_FLOAT,
    default=None,
    help="Sample interval [s] of a one-column plain-text record, 1e-9 to 1.",
)
plain_units = click.option(
    "--units",
    default=None,
    metavar="g|m/s2|cm/s2",
    help="Acceleration unit of a plain-text record (default: its '# units:' line, else g).",
)


engine_option = click.option(
    "--engine",
    type=click.Choice(["fast", "reference"]),
    default="fast",
    show_default=True,
    help="Rocking engine. fast: compiled DP5(4); reference: scipy DOP853 at rtol 1e-10 "
    "(slow, for checks).",
)


def _circular_year(ctx: click.Context, param: click.Parameter, value: str | None) -> str | None:
    """--edition as the model file takes it: the code's year names its circular's (2008 →
    2009, 2018 → 2019; rockcli.model.ntc.EDITION_ALIASES)."""
    if value is None:
        return None
    from rockcli.model.ntc import EDITION_ALIASES

    return EDITION_ALIASES.get(value, value)


edition_option = click.option(
    "--edition",
    type=click.Choice(["2009", "2019", "2008", "2018"]),
    default=None,
    callback=_circular_year,
    help="Override [ntc].edition: 2009 (NTC 2008 + Circ. 617/2009) or 2019 (NTC 2018 + "
    "Circ. 7/2019); 2008 and 2018, the code's years, mean the same as in the model file.",
)


def hazard_grid(help_text: str):
    """``--hazard-grid FILE``: the NTC Allegato B grid, with what it serves in the command."""
    return click.option(
        "--hazard-grid", "grid_file", default=None, type=click.Path(dir_okay=False),
        help=help_text,
    )  # fmt: skip


hazard_grid_option = hazard_grid(
    "NTC Allegato B grid file, when a site sets the demand (default: $ROCK_HAZARD_GRID)."
)


def suite_option(help_text: str):
    """``--suite SUITE``: a suite file, or a folder of records (with --target)."""
    return click.option(
        "--suite",
        "suite_path",
        type=InputPath("either", folder_with="target"),
        default=None,
        help=help_text,
    )


def allow_outside(help_text: str):
    """``--allow-outside``: let the files a file names lie outside its folder, with what it
    applies to in the command."""
    return click.option("--allow-outside", is_flag=True, help=help_text)


allow_outside_option = allow_outside(
    "Let a suite's records lie outside the suite's folder (an absolute path, '..', a "
    "link to elsewhere); by default a suite reads only files inside its own folder."
)


def check_allow_outside(
    allow_outside: bool,
    *paths: str | None,
    applies_to: str = "a suite",
    usage: str = "--suite SUITE --allow-outside",
) -> None:
    """Refuse --allow-outside when none of ``paths`` (the options of the files it applies to:
    --suite, and for rock report --project) is given (InputError).

    Args:
        allow_outside: the flag.
        paths: the values of the options it applies to.
        applies_to: what they are, for the message; usage: how the flag is meant.
    """
    from rockcli.errors import InputError

    if allow_outside and all(path is None for path in paths):
        raise InputError(
            f"applies only to {applies_to}",
            where="--allow-outside",
            allowed=f"{usage}, or no --allow-outside",
        )


target_option = click.option(
    "--target",
    "target",
    default=None,
    metavar="KEY=VALUE,…",
    help="With a folder of records as the suite: its target spectrum, the keys of a suite "
    "file's [target] (lon=13.40,lat=42.35,limit_state=SLV,soil=A, or ag=…,F0=…,Tc_star=…).",
)


def jobs_option(help_text: str):
    """``--jobs/-j N``: local workers, this process and N − 1 worker processes."""
    return click.option(
        "--jobs", "-j", type=AsciiIntRange(min=1), default=1, show_default=True, help=help_text
    )


def record_options(required: bool, optional_help: str | None = None) -> list:
    """The options that name a record and transform it (``optional_help``: what an optional
    record does, by default that its spectrum becomes the demand)."""
    optional_help = optional_help or " (its response spectrum becomes the demand)."
    return [
        click.option(
            "--record",
            "record_path",
            required=required,
            type=InputPath(),
            help="Accelerogram: PEER AT2, ESM ASCII, ITACA cor.acc or plain text"
            + ("." if required else optional_help),
        ),
        record_format,
        plain_dt,
        plain_units,
        click.option(
            "--scale", type=ASCII_FLOAT, default=None, help="Multiply the record by this factor."
        ),
        click.option(
            "--pga", type=ASCII_FLOAT, default=None, help="Scale the record to this PGA [g]."
        ),
    ]


def with_record_options(required: bool = True, optional_help: str | None = None):
    """Decorate a command with the record options."""

    def decorate(func):
        for option in reversed(record_options(required, optional_help)):
            func = option(func)
        return func

    return decorate


#: The options that describe or transform a record: they need --record.
RECORD_ONLY = ("--as", "--dt", "--units", "--scale", "--pga")


def check_record_options(record_path, record_format, dt, units, scale, pga) -> None:
    """Refuse a record option without --record, and --scale with --pga (InputError)."""
    from rockcli.errors import InputError

    given = dict(zip(RECORD_ONLY, (record_format, dt, units, scale, pga), strict=True))
    if record_path is None:
        for option, value in given.items():
            if value is not None:
                raise InputError(
                    "applies only to a record",
                    where=option,
                    value=value,
                    allowed=f"--record FILE with {option}, or no {option}",
                )
    if scale is not None and pga is not None:
        raise InputError(
            "conflicts with --pga (both set the record's amplitude)",
            where="--scale",
            value=scale,
            allowed="either --scale FACTOR or --pga PGA",
        )


#: The options that act on a time history only: they need a record (or a suite).
ROCKING_ONLY = {"engine": "--engine", "ground": "--ground", "mechanism_name": "--mechanism"}


def check_rocking_options(*params: str) -> None:
    """Refuse, without a record, an option given on the command line that only a time history
    uses (``params``: their parameter names, keys of ROCKING_ONLY; InputError)."""
    from click.core import ParameterSource

    from rockcli.errors import InputError

    ctx = click.get_current_context()
    for param in params:
        if ctx.get_parameter_source(param) is ParameterSource.COMMANDLINE:
            option = ROCKING_ONLY[param]
            raise InputError(
                "acts on a time history, and without a record there is none",
                where=option,
                value=None if isinstance(ctx.params[param], bool) else ctx.params[param],
                allowed=f"--record FILE with {option}, or no {option}",
            )


def check_hazard_grid(grid_file, model_path, *, demand_from: str | None) -> None:
    """Refuse --hazard-grid when no site sets the demand (InputError).

    Args:
        grid_file: the --hazard-grid value.
        model_path: the model, whose [ntc.site] is a site.
        demand_from: the option that sets the demand instead of a site (``--record``,
            ``--record-demand``), or None.
    """
    from rockcli.errors import InputError

    if grid_file is None:
        return
    allowed = "--hazard-grid only with a site: --site LON,LAT or the model's [ntc.site]"
    if demand_from is not None:
        raise InputError(
            f"not used: {demand_from} sets the demand", where="--hazard-grid", allowed=allowed
        )
    from rockcli.model.load import load_model

    model = load_model(model_path)
    if model.ntc is None or model.ntc.site is None:
        raise InputError(
            "not used: no site sets the demand",
            file=model_path,
            where="--hazard-grid",
            allowed=allowed,
        )


def check_outputs(force: bool, **paths: str | None) -> None:
    """Check every output file before the analysis runs (outfile.check_writable).

    Args:
        force: overwrite existing files.
        paths: option name (``plot``, ``history``) → the path given, or None; ``-`` is
            refused (standard output is the report's).
    """
    from rockcli.errors import InputError
    from rockcli.outfile import check_writable, is_stdout

    for option, path in paths.items():
        if is_stdout(path):
            raise InputError(
                "standard output carries the report",
                where=f"--{option}",
                value=path,
                allowed="a file path",
            )
        if path is not None:
            check_writable(path, force=force, where=f"--{option}")


def load_record(record_path, record_format, dt, units, scale, pga):
    """Read and transform the record the options describe (InputError on bad input)."""
    from rockcli.records import files

    check_record_options(record_path, record_format, dt, units, scale, pga)
    record = files.read_record(record_path, fmt=record_format, dt=dt, units=units)
    return scale_record(record, scale, pga)


def scale_record(record, scale, pga):
    """Scale by a factor and/or to a PGA; errors name --scale or --pga."""
    from rockcli.errors import InputError
    from rockcli.records import transform

    try:
        if scale is not None:
            record = transform.scale(record, scale)
        if pga is not None:
            record = transform.scale_to_pga(record, pga)
    except InputError as exc:
        option = "--scale" if exc.where == "factor" else "--pga"
        raise InputError(exc.problem, where=option, value=exc.value, allowed=exc.allowed) from None
    return record


#: Where a study runs: a dask cluster instead of this machine's processes.
scheduler_option = click.option(
    "--scheduler",
    default=None,
    envvar="DASK_SCHEDULER_ADDRESS",
    show_envvar=True,
    metavar="ADDRESS",
    help="Run on a dask cluster, e.g. tcp://host:8786 (needs the dask extra: pip install "
    "'.[dask]' from the repository's folder).",
)
#: A progress bar on stderr (default: when stderr is a terminal).
progress_option = click.option(
    "--progress/--no-progress",
    default=None,
    help="Progress bar on stderr [default: when stderr is a terminal].",
)
#: The folder a study's record paths are relative to.
records_dir_option = click.option(
    "--records-dir",
    default=None,
    envvar="ROCK_RECORDS_DIR",
    show_envvar=True,
    type=InputPath("folder"),
    help="Folder the study's record paths are relative to (replaces records_dir).",
)
#: Continue a study an interruption left, or start it over.
resume_option = click.option(
    "--resume", is_flag=True, help="Keep what an interrupted run of the study finished."
)
overwrite_option = click.option(
    "--force",
    "--overwrite",
    "overwrite",
    is_flag=True,
    help="Start over in an output folder that holds another or an unfinished study, and "
    "replace an existing --plot file.",
)

ground_option = click.option(
    "--ground",
    is_flag=True,
    help="For a block at height ([building] Z > 0): rock it on the record itself instead of "
    "the record's floor motion at its height (the default).",
)
force_option = click.option(
    "--force", is_flag=True, help="Overwrite output files that already exist."
)


def announce_written(path: object, detail: str = "") -> None:
    """The one "wrote …" line of every command, on stderr (stdout stays the result's)."""
    from rockcli.errors import printable

    line = f"wrote {path}" + (f": {detail}" if detail else "")
    click.echo(printable(line), err=True)


def exit_if_non_finite(runs: list[dict]) -> None:
    """After the report: exit 3 with one line when a rocking run ended in a non-finite state."""
    from rockcli.cli.exits import EXIT_INTERNAL, non_finite_line

    line = non_finite_line(runs)
    if line is not None:
        click.echo(line, err=True)
        raise SystemExit(EXIT_INTERNAL)


#: What --site takes.
SITE_ALLOWED = "LON,LAT in decimal degrees, e.g. 13.40,42.35"


def parse_site(value: str) -> tuple[float, float]:
    """(lon, lat) of ``--site LON,LAT`` [deg] (InputError naming --site otherwise)."""
    from rockcli.errors import InputError
    from rockcli.numbers import ascii_float

    try:
        lon, lat = (ascii_float(x) for x in value.split(","))
    except ValueError:
        lon = lat = math.nan
    if not (-180.0 <= lon <= 180.0 and -90.0 <= lat <= 90.0):
        raise InputError("not a site", where="--site", value=value, allowed=SITE_ALLOWED)
    return lon, lat
