"""`rock report MODEL --record FILE -o REPORT.html [--pdf REPORT.pdf]`: the calculation report."""

from __future__ import annotations

import importlib.util
import shlex

import click

from rockcli.cli.options import (
    announce_written,
    check_hazard_grid,
    check_outputs,
    edition_option,
    engine_option,
    force_option,
    ground_option,
    hazard_grid_option,
    load_record,
    with_record_options,
)

#: The report's languages (rockcli.document.words.LANGUAGES, kept here so that `rock --help`
#: imports nothing of the report), the filing language first.
LANGUAGES = ("it", "en")
#: What each output needs, and the extra that installs it.
NEEDS = {"html": ("jinja2", "matplotlib"), "pdf": ("jinja2", "matplotlib", "typst")}
EXTRA = "pip install 'rockcli[report]'"


@click.command()
@click.argument("model_path", metavar="MODEL", type=click.Path(dir_okay=False))
@with_record_options(required=True)
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
    type=click.Choice(("record", "model")),
    default="record",
    show_default=True,
    help="The code check's demand: the record's response spectrum, or the model's own code "
    "spectrum ([ntc.demand] or [ntc.site]).",
)
@edition_option
@engine_option
@ground_option
@hazard_grid_option
@force_option
def report(
    model_path, record_path, record_format, dt, units, scale, pga, html_path, pdf_path, lang,
    code_demand, edition, engine, ground, grid_file, force,
):  # fmt: skip
    """The calculation report of MODEL under a record: identification and input digests, the
    model and its sketch, the site and demand, the kinematic analysis, the rocking analysis,
    the comparison, and the software's section (theory, field of use, the validation
    casebook run on this install), in Italian or English."""
    from rockcli.cli.main import INVOKED
    from rockcli.document.run import write_report

    check_report_paths(html_path, pdf_path, force)
    check_hazard_grid(
        grid_file, model_path, demand_from="--record" if code_demand == "record" else None
    )
    record = load_record(record_path, record_format, dt, units, scale, pga)
    written = write_report(
        model_path,
        record,
        html_path=html_path,
        pdf_path=pdf_path,
        lang=lang,
        command=shlex.join(INVOKED),
        files=(("model", model_path), ("record", record_path))
        + ((("hazard_grid", grid_file),) if grid_file else ()),
        options={"code_demand": code_demand, "edition": edition, "engine": engine,
                 "ground": ground, "grid_file": grid_file},
    )  # fmt: skip
    for path, detail in written:
        announce_written(path, detail)


def check_report_paths(html_path: str, pdf_path: str | None, force: bool) -> None:
    """Before the analyses: the suffixes, the folders writable, the libraries installed."""
    from rockcli.errors import InputError

    for option, path, suffix in (("--output", html_path, ".html"), ("--pdf", pdf_path, ".pdf")):
        if path is not None and not path.lower().endswith(suffix):
            raise InputError(
                f"the file name must end in {suffix}",
                where=option,
                value=path,
                allowed=f"a path ending in {suffix}",
            )
    check_outputs(force, output=html_path, pdf=pdf_path)
    for kind, option in (("html", "--output"), ("pdf", "--pdf")):
        if kind == "pdf" and pdf_path is None:
            continue
        missing = [name for name in NEEDS[kind] if importlib.util.find_spec(name) is None]
        if missing:
            raise InputError(
                f"the {kind.upper()} report needs {', '.join(missing)}, not installed",
                where=option,
                allowed=EXTRA,
            )
