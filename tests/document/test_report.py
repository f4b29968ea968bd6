"""`rock report`: the calculation report as HTML and PDF, every section and figure in it, and
its bad input refused before the analyses run."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
ALTAR = ROOT / "examples" / "altar.toml"
FACADE = ROOT / "examples" / "facade.toml"
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: The façade sets no code spectrum: its report is the record's scenario alone (issue 36).
SECTIONS = ("identification", "model", "scenario-demand", "scenario-kinematic", "rocking",
            "comparison", "conclusions", "software")  # fmt: skip
#: A suite's report: the code check on the suite's target and the time histories.
SUITE_SECTIONS = ("identification", "model", "demand", "kinematic", "rocking", "comparison",
                  "software")  # fmt: skip
#: The figures every report has (a restrainer's forces only where the model has one).
FIGURES = ("sketch", "scenario-spectra", "scenario-capacity", "histories")

pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["report", *args])
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture(scope="module")
def facade(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, bytes]:
    """The façade (a tie-rod, one-sided) under the Ricker pulse, in Italian, HTML and PDF."""
    pytest.importorskip("typst", reason="the report extra (typst) is not installed")
    folder = tmp_path_factory.mktemp("report")
    html, pdf = folder / "facade.html", folder / "facade.pdf"
    code, _, err = run(str(FACADE), "--record", str(PULSE), "-o", str(html), "--pdf", str(pdf))
    assert code == 0, err
    assert f"wrote {html}" in err and f"wrote {pdf}" in err
    return html.read_text(encoding="utf-8"), pdf.read_bytes()


def test_the_html_report_holds_every_section_and_figure(facade: tuple[str, bytes]) -> None:
    html, _ = facade
    for key in SECTIONS:
        assert f'<section id="{key}"' in html, key
    for key in (*FIGURES, "forces"):
        assert f'id="figure-{key}"' in html, key
    assert html.count("<svg") == len(FIGURES) + 1


def test_the_html_report_is_self_contained(facade: tuple[str, bytes]) -> None:
    # Nothing fetched from elsewhere: no external stylesheet, script, image or font; the one
    # script element is the report's data, JSON (never run).
    html, _ = facade
    assert not re.search(r'<link\b|\bsrc="http|url\(http|@import', html)
    assert re.findall(r"<script\b[^>]*>", html) == [
        '<script type="application/json" id="rock-data">'
    ]


def test_the_html_report_identifies_its_inputs(facade: tuple[str, bytes]) -> None:
    import hashlib

    html, _ = facade
    for path in (FACADE, PULSE):
        assert hashlib.sha256(path.read_bytes()).hexdigest() in html
    assert f"rock report {FACADE} --record {PULSE} -o " in html  # the command line, re-runnable


def test_the_italian_report_speaks_the_codes_terms(facade: tuple[str, bytes]) -> None:
    html, _ = facade
    assert '<html lang="it">' in html
    for words in ("Relazione di calcolo", "Moltiplicatore di attivazione", "SLV"):
        assert words in html, words


def test_the_pdf_has_the_reports_pages_and_text(facade: tuple[str, bytes]) -> None:
    pdfium = pytest.importorskip("pypdfium2", reason="pypdfium2 (test extra) is not installed")
    _, data = facade
    pdf = pdfium.PdfDocument(data)
    # 21 pages with the 79 cases of the casebook's annex (which grows with the casebook), the
    # conclusions and the bibliography
    assert 5 <= len(pdf) <= 25
    text = " ".join(pdf[i].get_textpage().get_text_range() for i in range(len(pdf)))
    for title in ("Identificazione", "Il modello", "L'accelerogramma e la domanda",
                  "Analisi cinematica",
                  "Analisi del rocking", "Confronto dei due esiti", "NTC 2018 §10.2"):  # fmt: skip
        assert title in text, title
    # The first page is not blank: rasterised, it has ink.
    page = pdf[0].render(scale=0.5).to_pil().convert("L")
    assert page.getextrema()[0] < 100


def blank_stretch(page: object) -> float:
    """The longest run of blank lines between the header and the footer of a rendered page, as
    a fraction of that height."""
    import numpy as np

    gray = np.asarray(page.render(scale=0.5).to_pil().convert("L"))  # type: ignore[attr-defined]
    body = gray[int(gray.shape[0] * 0.06) : int(gray.shape[0] * 0.93)]
    longest = run = 0
    for inked in (body < 230).any(axis=1):
        run = 0 if inked else run + 1
        longest = max(longest, run)
    return longest / body.shape[0]


def test_no_page_is_left_half_empty(facade: tuple[str, bytes]) -> None:
    # A figure that does not fit floats to the next page's top while the text fills this one;
    # only the page before the annex (a new page by rule) and the last may end early.
    pdfium = pytest.importorskip("pypdfium2", reason="pypdfium2 (test extra) is not installed")
    pdf = pdfium.PdfDocument(facade[1])
    texts = [pdf[i].get_textpage().get_text_range() for i in range(len(pdf))]
    annex = next(i for i, t in enumerate(texts) if i > 0 and "Allegato A." in t)  # not the index
    gaps = {i + 1: round(blank_stretch(pdf[i]), 2) for i in range(len(pdf) - 1) if i != annex - 1}
    assert max(gaps.values()) < 0.3, gaps


def places(pdf: object, text: str) -> list[tuple[int, float]]:
    """(page, minus the top of its first character) of every occurrence of the text, in
    reading order (a later page, or lower on the page, sorts after)."""
    found = []
    for number in range(len(pdf)):  # type: ignore[arg-type]
        page = pdf[number].get_textpage()  # type: ignore[index]
        search = page.search(text)
        while (hit := search.get_next()) is not None:
            found.append((number, -page.get_charbox(hit[0])[3]))
    assert found, f"not in the PDF: {text}"
    return sorted(found)


@pytest.fixture(scope="module")
def strong_wall(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, bytes]:
    """The two-storey façade with every ag doubled (its verification fails), HTML and PDF:
    pages where a figure placed at a page's top rose above its section's heading."""
    pytest.importorskip("typst", reason="the report extra (typst) is not installed")
    folder = tmp_path_factory.mktemp("strong")
    text = (ROOT / "examples" / "two-storey-facade.toml").read_text(encoding="utf-8")
    for ag in ("0.06", "0.15", "0.19"):
        text = text.replace(f"ag = {ag}", f"ag = {2 * float(ag):g}")
    model = folder / "strong.toml"
    model.write_text(text, encoding="utf-8")
    html, pdf = folder / "r.html", folder / "r.pdf"
    code, _, err = run(str(model), "-o", str(html), "--pdf", str(pdf), "--casebook", "none")
    assert code == 0, err
    return html.read_text(encoding="utf-8"), pdf.read_bytes()


@pytest.mark.parametrize("which", ["facade", "strong_wall"])
def test_no_figure_rises_above_its_sections_heading(
    which: str, request: pytest.FixtureRequest
) -> None:
    # Figures float to the bottom of a page: each caption comes after its section's heading
    # (a later page, or lower on the same page), never above it.
    pdfium = pytest.importorskip("pypdfium2", reason="pypdfium2 (test extra) is not installed")
    html, data = request.getfixturevalue(which)
    pdf = pdfium.PdfDocument(data)
    checked = 0
    for section in re.findall(r"<section id=.*?</section>", html, flags=re.S):
        heading = re.search(r"<h2[^>]*>(\d+)\. ([^<]{1,30})", section)
        if heading is None:
            continue
        # The heading's last occurrence: the index on the first page lists it too.
        where = places(pdf, f"{heading.group(1)}. {heading.group(2)}")[-1]
        for number in re.findall(r"<figcaption>Figura (\d+)\.", section):
            assert places(pdf, f"Figura {number}:")[0] > where, (number, heading.group(0))
            checked += 1
    assert checked >= len(FIGURES)


def test_the_english_report(tmp_path: Path) -> None:
    html = tmp_path / "altar.html"
    code, _, err = run(str(ALTAR), "--record", str(PULSE), "-o", str(html), "--lang", "en")
    assert code == 0, err
    text = html.read_text(encoding="utf-8")
    assert '<html lang="en">' in text and "Calculation report" in text
    assert "Load multiplier at activation" in text


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--lang", "fr"], "'fr' is not one of 'it', 'en'"),
        (["-o", "{tmp}/missing/r.html"], "the folder does not exist"),
        (["-o", "{tmp}/r.pdf"], "must end in .html"),
        (["--pdf", "{tmp}/r.html"], "must end in .pdf"),
        (["-o", "{tmp}/exists.html"], "file exists"),
    ],
)
def test_bad_input_exits_2_before_the_analyses(tmp_path: Path, args: list[str], words: str) -> None:
    (tmp_path / "exists.html").write_text("keep me")
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    if "-o" not in args:
        args += ["-o", str(tmp_path / "r.html")]
    code, out, err = run(str(ALTAR), "--record", str(PULSE), *args)
    assert code == 2 and words in err and "Traceback" not in err
    assert (tmp_path / "exists.html").read_text() == "keep me"
    assert not (tmp_path / "r.html").exists()


def test_pdf_without_the_extra_names_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util, "find_spec", lambda name, *a: None if name == "typst" else real(name, *a)
    )
    code, _, err = run(str(ALTAR), "--record", str(PULSE), "-o", str(tmp_path / "r.html"),
                       "--pdf", str(tmp_path / "r.pdf"))  # fmt: skip
    assert code == 2
    assert err.strip().splitlines() == [
        "error: --pdf: the PDF report needs typst, not installed (allowed: "
        "pip install '.[report]' from the repository's folder)"
    ]
    assert not (tmp_path / "r.html").exists()


def test_the_report_of_a_suite(tmp_path: Path) -> None:
    # The project's three pulses as a folder suite (3 records: the code's rule takes the
    # worst), the target given by its parameters; the verdicts are those of
    # `rock compare --suite` on the same input.
    import json

    from markupsafe import escape

    from rockcli.document.words import Words

    suite = ["--suite", str(ROOT / "records"), "--target",
             "ag=0.25,F0=2.5,Tc_star=0.3,limit_state=SLV"]  # fmt: skip
    html = tmp_path / "suite.html"
    code, _, err = run(str(ALTAR), *suite, "-o", str(html), "--lang", "en")
    assert code == 0, err
    page = html.read_text(encoding="utf-8")
    for key in SUITE_SECTIONS:
        assert f'<section id="{key}"' in page, key
    # The altar sets its own spectra: the verification's sections are "demand" and
    # "kinematic", the suite's own keyed apart (issue 36).
    for key in ("suite-demand", "suite-kinematic", "virtual-work"):
        assert f'<section id="{key}"' in page, key
    assert 'id="figure-suite-compatibility"' in page
    assert all(f'id="figure-histories-{k}"' in page for k in (1, 2, 3))
    compared = CliRunner().invoke(cli, ["compare", str(ALTAR), *suite, "--format", "json"])
    doc = json.loads(compared.stdout)
    assert str(escape(Words("en")(f"class.{doc['classification']}"))) in page
    for record in doc["suite"]["records"]:
        assert record["name"] in page
        assert f"{record['max_ratio']:.4g}" in page
    assert "the largest over the records" in page  # the rule for 3 records


def test_record_and_suite_exclude_each_other(tmp_path: Path) -> None:
    code, _, err = run(str(ALTAR), "--record", str(PULSE), "--suite", str(ROOT / "records"),
                       "-o", str(tmp_path / "r.html"))  # fmt: skip
    assert code == 2 and "give one record or one suite" in err


def test_the_software_section_holds_the_casebook_run_here(facade: tuple[str, bytes]) -> None:
    # The §10.2 section runs `rock validate`'s casebook on this install: its count agrees with
    # rock validate's own, and every case is in the annex after it, with its outcome.
    import json

    from rockcli.casebook.load import load_casebook

    html, _ = facade
    software = html[html.index('<section id="software"') :]
    ids = [loaded.case.id for loaded in load_casebook()]
    annex = html[html.index('<section id="annex-casebook"') :]
    assert all(f">{case_id}</td>" in annex for case_id in ids)
    result = CliRunner().invoke(cli, ["validate", "--format", "json"])
    doc = json.loads(result.stdout)
    assert f"{doc['passed']} superati, {doc['failed']} non superati" in software


def test_the_sketch_draws_each_thrust_towards_its_side() -> None:
    # docs/conventions.md: O is the pivot of θ > 0, x is measured from O into the block, and a
    # thrust's direction is the sense of rotation it pushes towards: towards θ > 0 the block
    # tips over O, so the arrow points to −x (it starts on the +x side of its point).
    from rockcli.document.figures import block_sketch
    from rockcli.document.words import Words

    model = {"b": 0.25, "h": 1.6, "loads": [], "restrainers": [],
             "thrusts": [{"name": "push", "force": 1e3, "direction": d, "x_pos": 0.2, "z": 3.0}
                         for d in (1, -1)]}  # fmt: skip
    ax = block_sketch(model, Words("en")).axes[0]
    arrows = [a for a in ax.texts if getattr(a, "arrow_patch", None) is not None]
    starts = sorted(a.xyann[0] - a.xy[0] for a in arrows)
    assert starts[0] < 0 < starts[1]  # one from +x (towards θ > 0), one from −x
    assert arrows[0].xyann[0] > arrows[0].xy[0]  # the first is direction = 1


def test_the_kinematic_verdict_names_each_limit_state_once(facade: tuple[str, bytes]) -> None:
    # The façade is checked by the 2019 rules: SLD, SLV and SLC, each once (its verdict
    # document also sums them up as DLS and ULS, which in Italian are SLD and SLV again).
    html, _ = facade
    kinematic = html[html.index('<section id="scenario-kinematic"') :
                     html.index('<section id="rocking"')]  # fmt: skip
    line = re.findall(r'<p class="verdict">([^<]*)</p>', kinematic)[-1]
    assert [part.split(":")[0] for part in line.split("; ")] == ["SLD", "SLV", "SLC"]
