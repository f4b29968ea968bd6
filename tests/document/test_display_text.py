"""Names with control characters reach neither the report nor a figure raw, and the report's
outputs are written only once all of them are made (issue 20, items 8 and 10).

On main a control character in a suite record's name made `rock report --suite --pdf` exit 3
(Typst: "failed to parse SVG (a non-XML character '\\u{7}')") after the HTML was written;
the bytes of a model's name (an escape sequence, a bell) were written raw into the HTML; and
a name holding ``$\\frac$`` made matplotlib raise while drawing a plot (exit 3).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import display_text

ROOT = Path(__file__).resolve().parents[2]
ALTAR = ROOT / "examples" / "altar.toml"
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: A bell, an escape sequence, a C1 control, a bidirectional override and an XML noncharacter.
NASTY = "Alt\x07ar \x1b[31m \x85 \u202e \ufffe"
#: Every C0 control byte but tab, line feed and carriage return (XML 1.0 allows only those).
C0 = re.compile(rb"[\x00-\x08\x0b\x0c\x0e-\x1f]")

pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")


def test_display_text_shows_controls_and_keeps_line_breaks() -> None:
    assert display_text(NASTY) == "Alt\\x07ar \\x1b[31m \\x85 \\u202e \\ufffe"
    assert display_text("notes\non two lines\tand a tab") == "notes\non two lines\tand a tab"
    assert display_text("θ/α, Façade n° 2") == "θ/α, Façade n° 2"


def nasty_altar(tmp_path: Path) -> Path:
    import tomllib

    data = tomllib.loads(ALTAR.read_text(encoding="utf-8"))
    data["name"] = NASTY
    path = tmp_path / "nasty.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


def test_a_models_control_characters_are_shown_not_written(tmp_path: Path) -> None:
    pytest.importorskip("typst", reason="the report extra (typst) is not installed")
    html, pdf = tmp_path / "r.html", tmp_path / "r.pdf"
    args = [str(nasty_altar(tmp_path)), "--record", str(PULSE), "-o", str(html), "--pdf", str(pdf)]
    result = CliRunner().invoke(cli, ["report", *args])
    assert result.exit_code == 0, result.output
    page = html.read_bytes()
    assert not C0.search(page) and "\x85".encode() not in page
    assert b"Alt\\x07ar \\x1b[31m \\x85 \\u202e \\ufffe" in page
    assert pdf.read_bytes().startswith(b"%PDF")


def write_suite(tmp_path: Path) -> Path:
    """The project's three pulses as a suite file, one of them named with a bell."""
    records = sorted((ROOT / "records").glob("*.txt"))
    suite = {
        "name": "three pulses",
        "target": {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3, "limit_state": "SLV"},
        "records": [
            {"path": str(path), "name": f"pulse\x07{i}", "scale": 1.0}
            for i, path in enumerate(records)
        ],
    }
    path = tmp_path / "suite.toml"
    path.write_text(tomli_w.dumps(suite), encoding="utf-8")
    return path


def test_a_suite_record_named_with_a_bell_gives_both_outputs(tmp_path: Path) -> None:
    pytest.importorskip("typst", reason="the report extra (typst) is not installed")
    pdfium = pytest.importorskip("pypdfium2", reason="pypdfium2 (test extra) is not installed")
    html, pdf = tmp_path / "s.html", tmp_path / "s.pdf"
    args = [
        str(ALTAR),
        "--suite",
        str(write_suite(tmp_path)),
        "-o",
        str(html),
        "--pdf",
        str(pdf),
        "--allow-outside",
    ]
    result = CliRunner().invoke(cli, ["report", *args, "--lang", "en"])
    assert result.exit_code == 0, result.output
    page = html.read_bytes()
    assert not C0.search(page) and b"pulse\\x070" in page
    document = pdfium.PdfDocument(pdf.read_bytes())
    text = " ".join(document[i].get_textpage().get_text_range() for i in range(len(document)))
    assert "pulse\\x070" in text


def test_no_output_is_written_when_the_pdf_cannot_be_made(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The PDF fails (as Typst did on a control character): neither file is left behind.
    pytest.importorskip("typst", reason="the report extra (typst) is not installed")
    import rockcli.document.pdf

    def refuse(document: object) -> bytes:
        raise RuntimeError("typst refused the document")

    monkeypatch.setattr(rockcli.document.pdf, "render_pdf", refuse)
    html, pdf = tmp_path / "r.html", tmp_path / "r.pdf"
    args = [str(ALTAR), "--record", str(PULSE), "-o", str(html), "--pdf", str(pdf)]
    result = CliRunner().invoke(cli, ["report", *args])
    assert result.exit_code == 3, result.output
    assert "internal error: RuntimeError: typst refused the document" in result.stderr
    assert not html.exists() and not pdf.exists()


@pytest.mark.parametrize("name", ["a $\\frac$ b", "cost $5 and $6", NASTY])
def test_a_plot_draws_any_name_literally(tmp_path: Path, name: str) -> None:
    # `rock assess --plot` puts the model's name in its title: mathematics markup raised in
    # matplotlib, a control character reached the SVG (and a missing-glyph warning stderr).
    import tomllib

    data = tomllib.loads(ALTAR.read_text(encoding="utf-8"))
    data["name"] = name
    model = tmp_path / "m.toml"
    model.write_text(tomli_w.dumps(data), encoding="utf-8")
    plot = tmp_path / "p.svg"
    args = ["assess", str(model), "--record", str(PULSE), "--plot", str(plot)]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output
    svg = plot.read_bytes()
    assert not C0.search(svg)
    assert display_text(name).encode() in svg  # matplotlib keeps each text as an SVG comment
    # Drawn as typed: a pair of $ made mathematics of "5 and " in the oblique face on main
    # (rock's own labels use none).
    assert b"DejaVuSans-Oblique" not in svg
