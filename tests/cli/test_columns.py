"""What a person reads fits the width (issue 19, item 7): every command's tables in an
80-column terminal and in a pipe or a file (at most 100 columns), no number cut.

On main, `rock kinematic examples/altar.toml` drew its Demand and Checks tables 93 and 84
characters wide in an 80-column terminal (the terminal wrapped every row in two), and a
redirected output had no bound at all (303–381 characters a line; 1446 for
`rock validate > v.txt`).

Each command runs twice through the CLI: as in a terminal of 80 columns (rich reads
``$COLUMNS`` when the output is a terminal), and piped. Each time, every line must fit, and
every number the Report carries (each numeric cell at its format, each word of a text cell or
a note that reads as a number) must be in the text whole, on one line; and a sample of the
JSON document's numbers of the same run, formatted as the tables show them, too.
"""

from __future__ import annotations

import json
import os
import pty
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner
from rich.cells import cell_len

from rockcli.cli.main import cli
from rockcli.terminal import table as table_module
from rockcli.terminal.layout import NUMBER_WORD, ColumnText, fit, wrap_text
from rockcli.terminal.table import FILE_WIDTH, Column, Report, Table, format_value, render
from tests.cli.conftest import PULSES, ROOT

EXAMPLES = ROOT / "examples"
RECORDS = ROOT / "records"
RICKER = RECORDS / "ricker_Tp0.5s_0.5g.txt"
#: A default terminal's width.
TERMINAL = 80
#: The three shipped pulses as a suite (a folder of 3 records: the code's worst-of rule) on a
#: target given by its parameters (a plausible NTC SLV spectrum, no hazard grid needed).
TARGET = "ag=0.2,F0=2.4,Tc_star=0.3"
#: What separates the words of a rendered table: blanks and the frames' characters.
SEPARATORS = re.compile(r"[\s│┃┆┊║|]+")


def _kinematic(doc: dict[str, Any]) -> list[str]:
    """Each check's demand and capacity ({:.5g}) and ζ ({:.3f}), the Demand table's ag."""
    checks = [c for c in doc["checks"] if c["ratio"] is not None]
    out = [format_value(c[k], "{:.5g}") for c in checks for k in ("demand", "capacity")]
    out += [format_value(c["ratio"], "{:.3f}") for c in checks]
    return out + [format_value(d["ag"], "{:.4f}") for d in doc["demand"] if "ag" in d]


def _assess(doc: dict[str, Any]) -> list[str]:
    """Each run's max θ/α ({:.4f}) when it stands."""
    return [format_value(r["max_ratio"], "{:.4f}") for r in doc["runs"] if not r["overturned"]]


def _compare(doc: dict[str, Any]) -> list[str]:
    """The code side's ζ of its governing checks and the rocking side's max θ/α ({:.4f})."""
    return [format_value(doc["rocking"]["max_ratio"], "{:.4f}")]


def _retrofit(doc: dict[str, Any]) -> list[str]:
    """Each candidate's strength [kN] ({:.4g}) and, standing, max θ/α ({:.4f}) (one row per
    diameter; K and the code's ζ are in --details)."""
    rows = doc["candidates"]
    out = [format_value(r["strength"] / 1000, "{:.4g}") for r in rows]
    return out + [format_value(r["max_ratio"], "{:.4f}") for r in rows if not r["overturned"]]


def _record_info(doc: dict[str, Any]) -> list[str]:
    return [format_value(r["pga_g"]) for r in doc["records"]]


def _spectrum(doc: dict[str, Any]) -> list[str]:
    """Every Sa and Sd of every record ({:.4g})."""
    return [format_value(v) for r in doc["records"] for k in ("Sa_g", "Sd_m") for v in r[k]]


def _suite(doc: dict[str, Any]) -> list[str]:
    """The mean/target ratio at each period ({:.3f})."""
    return [format_value(r, "{:.3f}") for r in doc["ratio"]]


def _sweep(doc: dict[str, Any]) -> list[str]:
    return [str(r["cases"]) for r in doc["records"]]


def _validate(doc: dict[str, Any]) -> list[str]:
    """Each case's expected and obtained value ({:.7g})."""
    cases = doc["cases"]
    return [format_value(c[k], "{:.7g}") for c in cases for k in ("expected", "obtained")]


#: Every command that prints tables: its arguments and the JSON numbers sampled.
COMMANDS: dict[str, tuple[list[str], Callable[[dict[str, Any]], list[str]]]] = {
    "kinematic altar": (["kinematic", str(EXAMPLES / "altar.toml")], _kinematic),
    "kinematic facade": (
        ["kinematic", str(EXAMPLES / "facade.toml"), "--record", str(RICKER)],
        _kinematic,
    ),
    "kinematic top storey": (["kinematic", str(EXAMPLES / "top-storey-wall.toml")], _kinematic),
    "assess facade": (["assess", str(EXAMPLES / "facade.toml"), "--record", str(RICKER)], _assess),
    "compare facade": (
        ["compare", str(EXAMPLES / "facade.toml"), "--record", str(RICKER)],
        _compare,
    ),
    "compare altar": (["compare", str(EXAMPLES / "altar.toml"), "--record", str(RICKER)], _compare),
    "compare --suite": (
        ["compare", str(EXAMPLES / "altar.toml"), "--suite", str(RECORDS), "--target", TARGET],
        lambda doc: [],
    ),
    "assess --suite": (
        ["assess", str(EXAMPLES / "altar.toml"), "--suite", str(RECORDS), "--target", TARGET],
        lambda doc: [format_value(r["max_ratio"], "{:.4f}") for r in doc["suite"]["records"]],
    ),
    "retrofit": (["retrofit", str(EXAMPLES / "facade.toml"), "--record", str(RICKER)], _retrofit),
    "record info": (["record", "info", *map(str, PULSES)], _record_info),
    "record spectrum": (["record", "spectrum", *map(str, PULSES)], _spectrum),
    "suite check": (["suite", "check", str(RECORDS), "--target", TARGET], _suite),
    "sweep": (
        ["sweep", str(EXAMPLES / "studies" / "pulses.toml"), "--records-dir", str(RECORDS)],
        _sweep,
    ),
    "validate": (["validate"], _validate),
}


def _run(
    args: list[str], monkeypatch: pytest.MonkeyPatch, terminal: bool, out: Path
) -> tuple[str, list[Report]]:
    """The command's standard output, as in a terminal of 80 columns or piped, and the
    Reports it rendered."""
    shown: list[Report] = []
    original = table_module.render

    def capture(report: Report, console: Any) -> None:
        shown.append(report)
        original(report, console)

    monkeypatch.setattr(table_module, "render", capture)
    monkeypatch.setattr(table_module, "is_terminal", lambda stream: terminal)
    monkeypatch.setenv("COLUMNS", str(TERMINAL))
    extra = ["--out", str(out), "--overwrite"] if args[0] == "sweep" else []
    result = CliRunner().invoke(cli, [*args, *extra])
    assert result.exit_code == 0, result.stderr
    assert shown, "no Report rendered"
    return result.stdout, shown


def _numbers(report: Report) -> set[str]:
    """Every number of a Report as it is shown: numeric cells whole, and each word of a
    text cell, a note, a warning or the verdict that reads as a number."""
    out: set[str] = set()
    for table in report.tables:
        for row in table.rows:
            for col in table.columns:
                cell = format_value(row.get(col.key), col.fmt)
                out.update(w for w in cell.split() if NUMBER_WORD.fullmatch(w))
    for line in (*report.notes, *report.warnings, report.verdict or ""):
        out.update(w for w in line.split() if NUMBER_WORD.fullmatch(w))
    return out


@pytest.mark.parametrize("terminal", [True, False], ids=["terminal 80", "piped"])
@pytest.mark.parametrize("name", list(COMMANDS))
def test_every_line_fits_and_no_number_is_cut(
    name: str, terminal: bool, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    args, sample = COMMANDS[name]
    text, reports = _run(args, monkeypatch, terminal, tmp_path / "sweep")
    limit = TERMINAL if terminal else FILE_WIDTH
    long = [line for line in text.splitlines() if cell_len(line) > limit]
    assert long == [], f"{len(long)} lines wider than {limit}: {long[0]!r}"
    assert "…" not in text
    words = set(SEPARATORS.split(text))
    missing = {n for report in reports for n in _numbers(report)} - words
    assert not missing, sorted(missing)[:10]
    doc = json.loads(CliRunner().invoke(cli, [*args, "--format", "json"]).stdout)
    expected = sample(doc)
    assert not set(expected) - words, sorted(set(expected) - words)[:10]


def test_the_numbers_are_the_json_documents(monkeypatch: pytest.MonkeyPatch) -> None:
    # The sample is not empty where a command has numbers (a sample that finds nothing would
    # pass whatever the text).
    for name in ("kinematic altar", "retrofit", "validate", "record spectrum", "suite check"):
        args, sample = COMMANDS[name]
        doc = json.loads(CliRunner().invoke(cli, [*args, "--format", "json"]).stdout)
        assert len(sample(doc)) >= 3, name


def test_a_real_terminal_of_80_columns(tmp_path: Path) -> None:
    # The terminal found as rich finds it (stdout a tty, its width from $COLUMNS): the
    # altar's kinematic report, whose Demand and Checks tables were 93 and 84 wide on main.
    primary, secondary = pty.openpty()
    env = {**os.environ, "COLUMNS": str(TERMINAL), "TERM": "dumb", "NO_COLOR": "1"}
    args = [sys.executable, "-m", "rockcli", "kinematic", str(EXAMPLES / "altar.toml")]
    with subprocess.Popen(args, stdout=secondary, stderr=subprocess.PIPE, env=env) as proc:
        os.close(secondary)
        chunks = []
        while True:
            try:
                chunk = os.read(primary, 65536)
            except OSError:  # the child closed its end (Linux raises EIO)
                break
            if not chunk:
                break
            chunks.append(chunk)
        proc.wait(timeout=120)
    os.close(primary)
    assert proc.returncode == 0
    text = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", b"".join(chunks).decode("utf-8"))
    lines = text.replace("\r\n", "\n").splitlines()
    assert max(len(line) for line in lines) <= TERMINAL
    assert any(line.split()[:2] == ["ULS", "nonlinear"] and "0.097303" in line for line in lines)


# --- the mechanism, on made-up columns -------------------------------------------------------


def test_a_short_header_is_used_only_when_the_full_one_does_not_fit() -> None:
    # Two numeric columns of 5-character numbers under long headers: the boxed frame of two
    # columns takes 7 characters, so the full headers (one word of 11 each) need 29.
    columns = [
        ColumnText(("utilisation", "use"), ("1.000",), numeric=True),
        ColumnText(("measurement", "meas."), ("2.000",), numeric=True),
    ]
    assert fit(columns, 29).headers == ("utilisation", "measurement")
    narrower = fit(columns, 25)
    assert narrower.frame.name == "boxed"
    assert narrower.headers == ("use", "measurement")  # the one that saves most first
    assert fit(columns, 19).headers == ("use", "meas.")


def test_a_lighter_frame_before_a_word_is_broken() -> None:
    # Ten 5-character numbers: 81 characters boxed, 68 with two blanks between columns.
    columns = [ColumnText((f"c{i}",), ("1.234",), numeric=True) for i in range(10)]
    assert fit(columns, 81).frame.name == "boxed"
    layout = fit(columns, 80)
    assert layout.frame.name == "plain" and not layout.fold
    assert fit(columns, 60).frame.name == "tight"


def test_a_number_is_wider_than_the_width_sooner_than_cut() -> None:
    columns = [ColumnText(("x",), ("123456.789",), numeric=True)]
    layout = fit(columns, 5)
    assert layout.widths == (len("123456.789"),) and layout.total() > 5


def test_long_text_words_break_at_punctuation_and_numbers_stay_whole() -> None:
    assert wrap_text("free-rocking.rebound-housner-e", 14) == "free-rocking.\nrebound-\nhousner-e"
    # A number inside an identifier is not split at its decimal point.
    assert wrap_text("ricker_Tp0.5s_0.5g", 12).split("\n") == ["ricker_", "Tp0.5s_0.5g"]
    # A number longer than the width stays whole (the caller's width is at least its length).
    assert wrap_text("e = 0.99630001 (Housner)", 6).split("\n") == [
        "e =",
        "0.99630001",
        "(Housner)"[:6],
        "(Housner)"[6:],
    ]
    assert wrap_text("note: a b c d", 7, indent=2) == "note: a\n  b c d"


def test_folding_keeps_short_words_and_numbers(monkeypatch: pytest.MonkeyPatch) -> None:
    # A long id folds, a short word ("skipped") and a number do not, at the narrowest fit.
    columns = [
        ColumnText(("case",), ("makris-konstantinidis.one-cosine-mode2",), numeric=False),
        ColumnText(("result",), ("skipped",), numeric=False),
        ColumnText(("value",), ("0.06013567",), numeric=True),
    ]
    layout = fit(columns, 40)
    assert layout.fold and layout.widths is not None and layout.total() <= 40
    assert layout.widths[1] >= len("skipped") and layout.widths[2] == len("0.06013567")


def test_a_rendered_table_has_no_trailing_blank_in_any_frame() -> None:
    import io

    from rich.console import Console

    report = Report(
        "t",
        (Table("x", tuple(Column(f"c{i}", f"c{i}", align="left") for i in range(10)),
               ({f"c{i}": "ab" for i in range(10)}, {f"c{i}": "a" for i in range(10)})),),
    )  # fmt: skip
    for width in (80, 45, 30):
        buffer = io.StringIO()
        render(report, Console(file=buffer, width=width))
        assert all(line == line.rstrip() for line in buffer.getvalue().splitlines()), width
