"""`rock report MODEL... --record FILE -o REPORT.html [--pdf REPORT.pdf]`: the calculation
report (of several models, a building's walls, in one)."""

from __future__ import annotations

import importlib.util
import shlex

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    allow_outside,
    announce_written,
    check_allow_outside,
    check_outputs,
    check_record_options,
    check_rocking_options,
    edition_option,
    engine_option,
    force_option,
    ground_option,
    hazard_grid,
    load_record,
    suite_option,
    target_option,
    with_record_options,
)
from rockcli.errors import install_hint

#: The report's languages (rockcli.document.words.LANGUAGES, kept here so that `rock --help`
#: imports nothing of the report), the filing language first.
LANGUAGES = ("it", "en")
#: What each output needs, and the extra that installs it.
NEEDS = {"html": ("jinja2", "matplotlib"), "pdf": ("jinja2", "matplotlib", "typst"),
         "docx": ("matplotlib", "docx")}  # fmt: skip
EXTRA = install_hint("report")


@click.command(
    cls=RockCommand, short_help="The calculation report of one model or more, as HTML (and PDF)."
)
@click.argument("model", nargs=-1, required=True, type=InputPath())
@with_record_options(required=False)
@suite_option(
    "A record suite file (TOML; rock suite check), or a folder of records with --target: the "
    "report of `rock compare --suite` (the suite's compatibility, every record's time history "
    "by the code's rule, the code check on the suite's target)."
)
@target_option
@allow_outside(
    "Let a suite's records and a project file's sections lie outside their file's folder (an "
    "absolute path, '..', a link to elsewhere); by default each reads only files inside its "
    "own folder. A pipe, a device or a file of /proc or /sys is refused either way."
)
@click.option(
    "-o",
    "--output",
    "html_path",
    required=True,
    type=click.Path(dir_okay=False),
    help="The report as one self-contained HTML page (figures inline, prints on A4).",
)
@click.option(
    "--pdf", "pdf_path", type=click.Path(dir_okay=False), help="Also the report as PDF (Typst)."
)
@click.option(
    "--lang",
    type=click.Choice(LANGUAGES),
    default=LANGUAGES[0],
    show_default=True,
    help="Language of the report: it (the filing language, the code's own terms) or en.",
)
@click.option(
    "--code-demand",
    type=click.Choice(("record", "model", "target", "suite-mean")),
    default=None,
    help="The code check's demand. With --record: record (default), the record's response "
    "spectrum, or model, the model's own code spectrum. With --suite: target (default), or "
    "suite-mean, the mean spectrum of its records.",
)
@edition_option
@engine_option
@ground_option
@hazard_grid(
    "NTC Allegato B grid file: for a site in the model or the suite's target, and for the "
    "validation casebook's hazard-grid cases (default: $ROCK_HAZARD_GRID)."
)
@click.option(
    "--docx",
    "docx_path",
    type=click.Path(dir_okay=False),
    default=None,
    help="Also the report as an editable Word document (.docx): headings, tables, figures "
    "as images, captions.",
)
@click.option(
    "--project",
    "project_path",
    type=click.Path(dir_okay=False),
    default=None,
    help="A project file ([project]: client, subject, site, designer, date, your own "
    "sections in Markdown; rock init project writes one): the cover, your sections and the "
    "signature block.",
)
@click.option(
    "--casebook",
    "casebook_place",
    type=click.Choice(["annex", "inline", "none"]),
    default="annex",
    show_default=True,
    help="Where the validation casebook run on this install goes: an annex after the "
    "signature, inline in the software's section, or not run (the report then says so).",
)
@click.option(
    "--mechanism",
    "mechanism_name",
    default=None,
    metavar="NAME",
    help="A wall's mechanism to compare first (default: the governing one); every mechanism "
    "is listed either way.",
)
@click.option(
    "--retrofit",
    is_flag=True,
    help="Where the verification (or the record's scenario) asks for an intervention, size "
    "the model's tie-rod as rock retrofit does (its defaults): each diameter's code check on "
    "the verification's spectra, and with --record its time history under the record; the "
    "smallest diameter in the conclusions.",
)
@click.option(
    "--mechanisms",
    "mechanisms_shown",
    type=click.Choice(["all", "governing"]),
    default="all",
    show_default=True,
    help="A wall's mechanisms in full: all (a section each after the governing one's) or only "
    "the governing one (the summary table lists every one either way).",
)
@force_option
def report(
    model, record_path, record_format, dt, units, scale, pga, suite_path, target,
    allow_outside, html_path, pdf_path, lang, code_demand, edition, engine, ground, grid_file,
    docx_path, project_path, casebook_place, mechanism_name, retrofit, mechanisms_shown, force,
):  # fmt: skip
    """The calculation report of MODEL: the safety verification of every mechanism by the
    code's kinematic analysis on the site's (or the model's) NTC spectra, with the conclusions
    NTC 2018 §8.3 draws for the use class; with --record, the scenario of that record (the
    rocking time history, the code check on its spectrum, their comparison) in its own
    sections; with --suite, the suite's time histories by the code's rule. Identification and
    input digests, a summary of every mechanism, the model, the software's section (theory,
    field of use, the validation casebook run on this install), in Italian or English.
    Several models (a building's walls) make one report with one summary over all."""
    from rockcli.analyses.choices import Analyses, ComparisonChoices
    from rockcli.cli.assess import one_record_or_suite
    from rockcli.cli.compare import demand_for
    from rockcli.cli.invocation import command_line
    from rockcli.document.run import ReportChoices, write_report, write_suite_report

    model_paths = model  # MODEL... in the usage, MODEL in a message

    check_allow_outside(allow_outside, suite_path, project_path,
                        applies_to="a suite or a project file",
                        usage="--suite SUITE or --project FILE with --allow-outside")  # fmt: skip
    # No record and no suite: the verification alone, on the site's spectra (the filing form).
    alone = record_path is None and suite_path is None
    with_suite = not alone and one_record_or_suite(record_path, suite_path, None, None, None,
                                                   target)  # fmt: skip
    if alone and code_demand is not None:
        from rockcli.errors import InputError

        raise InputError("chooses the demand of a record's or a suite's code check",
                         where="--code-demand", value=code_demand,
                         allowed="--code-demand with --record or --suite (without them the "
                         "code check is on the model's own spectra)")  # fmt: skip
    code_demand = demand_for(code_demand, with_suite)
    check_report_paths(html_path, pdf_path, force, docx_path)
    front = {"project": None, "casebook": casebook_place}
    if project_path is not None:  # before any analysis runs
        from rockcli.document.project import load_project

        front["project"] = load_project(project_path, allow_outside=allow_outside)
    common = {"html_path": html_path, "pdf_path": pdf_path, "lang": lang, "front": front,
              "command": shlex.join(command_line()), "docx_path": docx_path}  # fmt: skip
    if with_suite:
        check_record_options(None, record_format, dt, units, scale, pga)
        from rockcli.errors import InputError

        if mechanism_name is not None:
            raise InputError("not with --suite yet", where="--mechanism", value=mechanism_name,
                             allowed="--mechanism with --record")  # fmt: skip
        written = write_suite_report(
            model_paths, suite_path, target, grid_file, **common, allow_outside=allow_outside,
            analyses=Analyses(engine, edition, ground), code_demand=code_demand,
            retrofit=retrofit,
        )  # fmt: skip
        for path, detail in written:
            announce_written(path, detail)
        return
    # No check_hazard_grid: besides a site of the model, the grid serves the casebook's
    # hazard-grid cases in the report's §10.2 section.
    from rockcli.errors import InputError

    if mechanism_name is not None and len(model_paths) > 1:
        raise InputError("names a mechanism of one model", where="--mechanism",
                         value=mechanism_name, allowed="--mechanism with one model")  # fmt: skip
    if alone:
        check_record_options(None, record_format, dt, units, scale, pga)
        check_rocking_options("engine", "ground", "mechanism_name")
        if target is not None:
            raise InputError("applies only to a folder of records given as the suite",
                             where="--target", value=target,
                             allowed="--suite DIR --target KEY=VALUE,…")  # fmt: skip
    record = None if alone else load_record(record_path, record_format, dt, units, scale, pga)
    from rockcli.terminal.sweep import progress_bar

    with progress_bar(None, "report") as progress:
        written = write_report(
            model_paths,
            record,
            **common,
            files=((() if alone else (("record", record_path),))
                   + ((("hazard_grid", grid_file),) if grid_file else ())),
            progress=progress,
            choices=ReportChoices(
                ComparisonChoices(Analyses(engine, edition, ground), code_demand, grid_file,
                                  mechanism_name),
                shown=mechanisms_shown, retrofit=retrofit),
        )  # fmt: skip
    for path, detail in written:
        announce_written(path, detail)


def check_report_paths(
    html_path: str, pdf_path: str | None, force: bool, docx_path: str | None = None
) -> None:
    """Before the analyses: the suffixes, the folders writable, the libraries installed."""
    from rockcli.errors import InputError

    for option, path, suffix in (("--output", html_path, ".html"), ("--pdf", pdf_path, ".pdf"),
                                 ("--docx", docx_path, ".docx")):  # fmt: skip
        if path is not None and not path.lower().endswith(suffix):
            raise InputError(
                f"the file name must end in {suffix}",
                where=option,
                value=path,
                allowed=f"a path ending in {suffix}",
            )
    check_outputs(force, output=html_path, pdf=pdf_path, docx=docx_path)
    for kind, option, path in (("html", "--output", html_path), ("pdf", "--pdf", pdf_path),
                               ("docx", "--docx", docx_path)):  # fmt: skip
        if path is None:
            continue
        missing = [name for name in NEEDS[kind] if importlib.util.find_spec(name) is None]
        if missing:
            raise InputError(
                f"the {kind.upper()} report needs {', '.join(missing)}, not installed",
                where=option,
                allowed=EXTRA,
            )
