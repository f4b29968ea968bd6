"""The calculation report says in words, in Italian and in English, when the time history
depends on the integration tolerance (rockcli.document.tolerance), and that it does not when
it does not.

Sources: the case of the project's issue 19 (item 5; tests/cli/test_tolerance_check.py gives
its numbers: 0.2727 at the default tolerance, 0.2524 at 1e-11, polarity −1), and the paper's
altar under the shipped Ricker pulse as the robust case.
"""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.test_tolerance_check import ISSUE_WALL, RECORD

ROOT = Path(__file__).resolve().parents[2]
SHARED_RECORDS = ROOT.parent / "shared" / "records"
ALTAR = ROOT / "examples" / "altar.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"

pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")

#: The sentence of the sensitive polarity, per language (numbers with the language's mark).
SENSITIVE = {
    "en": re.compile(
        r"Polarity −1: max θ/α depends on the integration tolerance: 0\.2727 \(\d+ impacts\) at "
        r"tolerance 1e-08, 0\.2524 \(\d+ impacts\) at 1e-11\. This rocking is chaotic"
    ),
    "it": re.compile(
        r"Polarità −1: max θ/α dipende dalla tolleranza di integrazione: 0,2727 \(\d+ urti\) "
        r"con tolleranza 1e-08, 0,2524 \(\d+ urti\) con 1e-11\. Questo moto di rocking è caotico"
    ),
}
ROBUST = {
    "en": "Each polarity was integrated again at tolerance 1e-11",
    "it": "Ciascuna polarità è stata integrata di nuovo con tolleranza 1e-11",
}


def report_text(tmp_path: Path, lang: str, *args: str) -> str:
    out = tmp_path / f"report-{lang}.html"
    result = CliRunner().invoke(cli, ["report", *args, "-o", str(out), "--lang", lang])
    assert result.exit_code == 0, result.stderr
    return html.unescape(re.sub(r"<[^>]+>", " ", out.read_text(encoding="utf-8")))


@pytest.mark.parametrize("lang", ["it", "en"])
def test_the_report_says_a_sensitive_result_in_words(tmp_path: Path, lang: str) -> None:
    if not SHARED_RECORDS.is_dir():
        pytest.skip(f"real records not available: {SHARED_RECORDS} is absent")
    model = tmp_path / "wall.toml"
    model.write_text(ISSUE_WALL, encoding="utf-8")
    record = SHARED_RECORDS / RECORD
    text = report_text(tmp_path, lang, str(model), "--record", str(record), "--scale", "0.8")
    assert SENSITIVE[lang].search(text), lang
    assert ROBUST[lang] not in text
    # Said once, in the report's words: the terminal's English warning is not repeated.
    assert "polarity -1: max θ/α depends" not in text and "at rtol 1e-8" not in text


@pytest.mark.parametrize("lang", ["it", "en"])
def test_the_report_says_a_robust_result_is_not_sensitive(tmp_path: Path, lang: str) -> None:
    text = report_text(tmp_path, lang, str(ALTAR), "--record", str(RICKER))
    assert ROBUST[lang] in text
    assert not SENSITIVE[lang].search(text)


def test_the_suite_report_names_the_sensitive_record(tmp_path: Path) -> None:
    if not SHARED_RECORDS.is_dir():
        pytest.skip(f"real records not available: {SHARED_RECORDS} is absent")
    from tests.suites.test_tolerance import suite_with_the_issues_record

    model = tmp_path / "wall.toml"
    model.write_text(ISSUE_WALL, encoding="utf-8")
    suite = suite_with_the_issues_record(tmp_path, SHARED_RECORDS)
    text = report_text(tmp_path, "it", str(model), "--suite", str(suite), "--code-demand",
                       "suite-mean")  # fmt: skip
    assert re.search(r"northr: " + SENSITIVE["it"].pattern, text)
    assert "record northr, polarity -1" not in text  # the English warning is not repeated
