"""The project of a calculation report (issue 23): the project file, its checks, the cover,
the engineer's sections, the conclusions, the signature and the casebook's annex."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.document.front import markdown_paragraphs
from rockcli.document.project import TEMPLATE, load_project

ROOT = Path(__file__).resolve().parents[2]
PROJECT = ROOT / "examples" / "project" / "project.toml"
FACADE = ROOT / "examples" / "two-storey-facade.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_the_example_project_loads_with_its_sections_and_ed50_coordinates() -> None:
    pytest.importorskip("pyproj")
    project = load_project(PROJECT)
    titles = [title for title, _ in project.sections]
    assert titles == ["Premessa", "Materiali e livello di conoscenza"]
    assert "LC1" in project.sections[1][1]
    # WGS84 → ED50 in central Italy: ED50 coordinates lie some 100 m north-east (about 1e-3
    # degrees in each), and the inverse transformation returns the input.
    from pyproj import Transformer

    lon, lat = project.ed50 or (0.0, 0.0)
    t = project.table
    assert t.lon is not None and t.lat is not None
    assert 5e-4 < lon - t.lon < 2e-3 and 5e-4 < lat - t.lat < 2e-3
    back = Transformer.from_crs("EPSG:4230", "EPSG:4326", always_xy=True).transform(lon, lat)
    # PROJ's round trip through the Helmert transformation: within 1e-7 degrees (1 cm).
    assert back == pytest.approx((t.lon, t.lat), abs=1e-7)


def test_the_template_loads(tmp_path: Path) -> None:
    pytest.importorskip("pyproj")
    path = tmp_path / "project.toml"
    path.write_text(TEMPLATE, encoding="utf-8")
    project = load_project(path)
    assert project.table.designer and project.sections == ()
    # No fixed day: a report is signed on the day it is made unless the engineer sets one.
    assert project.table.date is None


def test_the_signature_is_dated_in_the_reports_language(tmp_path: Path, monkeypatch) -> None:
    pytest.importorskip("jinja2")
    pytest.importorskip("pyproj")
    # 2026-12-07 09:30 UTC, the report's time stamp; the example project sets no date.
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1796635800")
    for lang, day in (("it", "7 dicembre 2026"), ("en", "7 December 2026")):
        html = tmp_path / f"r-{lang}.html"
        code, _, err = run("report", str(FACADE), "--record", str(RICKER), "--project",
                           str(PROJECT), "--lang", lang, "-o", str(html))  # fmt: skip
        assert code == 0, err
        text = html.read_text(encoding="utf-8")
        assert f"L&#39;Aquila (AQ), {day}" in text, lang
        cover = text[: text.index("</table>")]  # the cover's facts, the date among them
        assert day in cover and "2026-12-07" not in cover, lang


BAD = [
    ("unknown key", 'colour = "red"\n', "project.colour"),
    ("datum", 'datum = "NAD83"\n', "project.datum"),
    ("outside the grid", "lon = 25.0\nlat = 42.0\n", "project.lon"),
    ("lon without lat", "lon = 13.4\n", "project.lat"),
    (
        "missing section",
        '[[project.sections]]\ntitle = "X"\nfile = "nowhere.md"\n',
        "project.sections[0].file",
    ),
]

HEAD = '[project]\nclient = "C"\nsubject = "S"\ncomune = "M"\ndesigner = "D"\n'


@pytest.mark.parametrize(("label", "extra", "key"), BAD, ids=[b[0] for b in BAD])
def test_a_bad_project_is_one_line_before_any_analysis(tmp_path: Path, label: str, extra: str,
                                                       key: str) -> None:  # fmt: skip
    pytest.importorskip("jinja2")
    path = tmp_path / "project.toml"
    if extra.startswith("[["):
        path.write_text(HEAD + extra, encoding="utf-8")
    else:
        path.write_text(HEAD.replace('designer = "D"\n', 'designer = "D"\n' + extra),
                        encoding="utf-8")  # fmt: skip
    code, _, err = run("report", str(FACADE), "--record", str(RICKER), "--project", str(path),
                       "-o", str(tmp_path / "r.html"))  # fmt: skip
    assert code == 2, (label, err)
    assert key in err and len(err.strip().splitlines()) == 1, (label, err)
    assert not (tmp_path / "r.html").exists()


def test_markdown_becomes_paragraphs() -> None:
    text = "# Title\n\nSome *emphasis* and `code`.\n\n- one\n- two\n\n1. first\n2. second\n"
    got = [(p.text, p.kind) for p in markdown_paragraphs(text)]
    assert got == [("Title", "subheading"), ("Some emphasis and code.", ""), ("• one", ""),
                   ("• two", ""), ("1. first", ""), ("2. second", "")]  # fmt: skip


def test_the_report_with_a_project(tmp_path: Path) -> None:
    pytest.importorskip("jinja2")
    pytest.importorskip("pyproj")
    html = tmp_path / "r.html"
    code, _, err = run("report", str(FACADE), "--record", str(RICKER), "--project", str(PROJECT),
                       "-o", str(html))  # fmt: skip
    assert code == 0, err
    text = html.read_text(encoding="utf-8")
    # The cover, the engineer's sections, the conclusions, the signature, the annex.
    for words in ("Committente", "Parrocchia di San Pietro", "ED50", "Premessa",
                  "Materiali e livello di conoscenza", "Conclusioni", "Il progettista",
                  "Ing. Maria Rossi", "firma e timbro", 'id="annex-casebook"'):  # fmt: skip
        assert words in text, words
    # The conclusions' risk index follows the verdict of the verification, the code check on
    # the model's own spectra (`rock kinematic`), not the record's: a state shown
    # "soddisfatta" there is satisfied in the kinematic document.
    kin = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--format", "json"])
    import json

    verdict = json.loads(kin.stdout)["verdict"]
    conclusions = text[text.index('id="conclusions"') : text.index('id="software"')]
    for state in ("SLD", "SLV", "SLC"):
        row = conclusions[conclusions.index(f"<td>{state}</td>") :]
        row = row[: row.index("</tr>")]
        assert ("non soddisfatta" not in row) == bool(verdict[state]), (state, row)


def test_the_casebook_inline_or_not_run(tmp_path: Path) -> None:
    pytest.importorskip("jinja2")
    annex = 'id="annex-casebook"'
    for place, present, absent in (("inline", "Tabella", annex),
                                   ("none", "non sono stati eseguiti", annex)):  # fmt: skip
        html = tmp_path / f"{place}.html"
        code, _, err = run("report", str(FACADE), "--record", str(RICKER), "--casebook", place,
                           "-o", str(html))  # fmt: skip
        assert code == 0, err
        text = html.read_text(encoding="utf-8")
        assert present in text and absent not in text, place


def test_init_project_writes_the_template(tmp_path: Path) -> None:
    out = tmp_path / "p.toml"
    done = subprocess.run([sys.executable, "-m", "rockcli", "init", "project", "-o", str(out)],
                          capture_output=True, text=True, check=False)  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert out.read_text(encoding="utf-8") == TEMPLATE


def test_the_word_copy_holds_the_same_report(tmp_path: Path) -> None:
    # The DOCX from the same Document as the HTML: every section a numbered heading, the
    # annex, the cover's facts, every table and figure, and the numbers as the HTML has them.
    pytest.importorskip("docx")
    pytest.importorskip("pyproj")
    from docx import Document as Word

    html, docx = tmp_path / "r.html", tmp_path / "r.docx"
    code, _, err = run("report", str(FACADE), "--record", str(RICKER), "--project", str(PROJECT),
                       "-o", str(html), "--docx", str(docx))  # fmt: skip
    assert code == 0, err
    text = html.read_text(encoding="utf-8")
    word = Word(str(docx))
    headings = [p.text for p in word.paragraphs if p.style.name == "Heading 1"]
    assert headings[0] == "1. Identificazione" and headings[-1].startswith("Allegato A.")
    import html as markup

    shown = markup.unescape(text)  # a heading's apostrophe is &#39; in the HTML
    assert all(h.split(". ", 1)[1] in shown for h in headings)
    assert text.count("<table") == len(word.tables)  # the cover and every grid
    assert text.count("<figure") == len(word.inline_shapes) > 0
    cells = {c.text for t in word.tables for row in t.rows for c in row.cells}
    joined = " | ".join(cells)
    assert "Parrocchia di San Pietro" in cells and "Ing. Maria Rossi" in joined
    # A number of the report, the same in both: the first run's max θ/α in the runs table.
    import re

    ratio = re.search(r"<td class=\"num\">(0,\d{4})</td>", text)
    assert ratio is not None and ratio.group(1) in cells
    # The signature block stays on one page: each of its paragraphs kept with the next, from
    # the blank line before the place and date to the room for the stamp.
    texts = [p.text for p in word.paragraphs]
    first = next(i for i, t in enumerate(texts) if "Ing. Maria Rossi" in t) - 3
    block = word.paragraphs[first : first + 8]
    assert all(p.paragraph_format.keep_with_next for p in block[:-1]), [p.text for p in block]


@pytest.mark.skipif(not (ROOT.parent / "shared" / "ntc" / "AllegatoB.txt").is_file(),
                    reason="the NTC hazard grid (../shared/ntc) is absent")  # fmt: skip
def test_a_suites_report_has_its_conclusions(tmp_path: Path) -> None:
    pytest.importorskip("jinja2")
    grid = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
    suite = ROOT / "examples" / "suites" / "laquila-slv-scaled.toml"
    html = tmp_path / "s.html"
    code, _, err = run("report", str(ROOT / "examples" / "altar.toml"), "--suite", str(suite),
                       "--allow-outside", "--hazard-grid", str(grid), "--casebook", "none",
                       "-o", str(html))  # fmt: skip
    assert code == 0, err
    text = html.read_text(encoding="utf-8")
    conclusions = text[text.index('id="conclusions"') : text.index('id="software"')]
    assert "NTC 2018 §7.3.5" in conclusions and "Classificazione" in conclusions


def test_a_word_tables_columns_share_the_page_by_their_text() -> None:
    # The page's width is shared out whole; a column is never narrower than its longest word
    # needs relative to the others ("Classificazione" stays one word, not "Classificazio-ne").
    from rockcli.document.content import Grid
    from rockcli.document.docx import FIGURE_WIDTH_CM, column_widths

    grid = Grid("c", ("Meccanismo", "α0", "Classificazione"),
                (("ribaltamento semplice del piano 2", "0,4054", "coerente, sicuro"),))  # fmt: skip
    widths = column_widths(grid)
    assert sum(widths) == pytest.approx(FIGURE_WIDTH_CM, rel=1e-12)
    # All fits: each by its typical text plus the margins, "coerente, sicuro" (16) against
    # the mechanism (33, capped at 30).
    assert widths[2] / widths[0] == pytest.approx((16 + 3) / (30 + 3))
    # Too wide for the page: every column keeps at least its longest word.
    wide = Grid("c", ("Caso", "Fonte", "Esito"),
                (("a" * 12, " ".join(["parola"] * 60), "superato"),))  # fmt: skip
    widths = column_widths(wide, total=8.0)
    assert sum(widths) == pytest.approx(8.0, rel=1e-12)
    assert widths[0] >= (12 + 3) * 0.176 and widths[2] >= (8 + 3) * 0.176  # 8 pt text
