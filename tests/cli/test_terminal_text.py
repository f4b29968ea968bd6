"""What reaches the terminal (issue 7, items 9, 14, 15): any output encoding, no control
character from a name, no number cut by a narrow terminal or a pipe."""

from __future__ import annotations

import io
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from rich.console import Console

from rockcli.cli.main import cli
from rockcli.errors import printable
from rockcli.terminal.assess import assessment_report
from rockcli.terminal.compare import comparison_report
from rockcli.terminal.kinematic import kinematic_report
from rockcli.terminal.layout import ColumnText, fit
from rockcli.terminal.table import FILE_WIDTH, Report, console_for, format_value, render
from rockcli.terminal.text import encodable
from tests.cli.conftest import EXAMPLES, PULSES, ROOT

ALTAR = ROOT / "examples" / "altar.toml"
#: The width of a default terminal, and of rich's console when it cannot tell.
NARROW = 80


def _doc(*args: str) -> dict:
    result = CliRunner().invoke(cli, [*args, "--format", "json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def _reports() -> list[tuple[str, Report, dict]]:
    """Every report of every example: kinematic, assess and compare (first pulse)."""
    out = []
    for model in EXAMPLES:
        sets_demand = "[ntc.demand" in model.read_text(encoding="utf-8")
        kin = _doc("kinematic", str(model), *([] if sets_demand else ["--record", str(PULSES[0])]))
        out.append((f"kinematic {model.name}", kinematic_report(kin), kin))
        for command, to_report in (("assess", assessment_report), ("compare", comparison_report)):
            doc = _doc(command, str(model), "--record", str(PULSES[0]))
            out.append((f"{command} {model.name}", to_report(doc), doc))
    return out


@pytest.fixture(scope="module")
def reports() -> list[tuple[str, Report, dict]]:
    return _reports()


def _rendered(report: Report, width: int | None) -> str:
    buffer = io.StringIO()
    console = console_for(buffer) if width is None else Console(file=buffer, width=width)
    render(report, console)
    return buffer.getvalue()


def _cell_words(report: Report) -> set[str]:
    return {
        word
        for table in report.tables
        for row in table.rows
        for col in table.columns
        for word in format_value(row.get(col.key), col.fmt).split()
    }


@pytest.mark.parametrize("width", [NARROW, None], ids=["80 columns", "piped"])
def test_no_cell_is_cut(reports, width: int | None) -> None:
    # Every word of every cell (each number whole, at its format) is in the text: rich
    # replaced the end of a too-wide number by "…" at 80 columns (the demand, the method and
    # the clause of `rock kinematic` were lost in a redirected output).
    for name, report, _ in reports:
        text = _rendered(report, width)
        assert "…" not in text, name
        words = set(re.split(r"[\s│┃]+", text))
        missing = {w for w in _cell_words(report) if w not in words}
        assert not missing, (name, sorted(missing)[:5])


def test_the_kinematic_json_numbers_are_in_the_piped_table(reports) -> None:
    # The numbers a reader of `rock kinematic > k.txt` needs: each check's demand, capacity
    # (format {:.5g}) and ratio ({:.3f}), as in the JSON document.
    for name, report, doc in reports:
        if not name.startswith("kinematic"):
            continue
        text = _rendered(report, NARROW)
        for check in doc["checks"]:
            for key, fmt in (("demand", "{:.5g}"), ("capacity", "{:.5g}"), ("ratio", "{:.3f}")):
                assert format_value(check[key], fmt) in text, (name, key)


def test_a_redirected_report_is_bounded_at_100_columns() -> None:
    # CliRunner's stdout is not a terminal, like `> k.txt`. Issue 19: a redirected report had
    # no width bound (303 characters a line for this one); now FILE_WIDTH (100) columns, wider
    # than a terminal's 80, and a note longer than that wraps, its later lines indented.
    result = CliRunner().invoke(cli, ["kinematic", str(ALTAR)])
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert max(len(line) for line in lines) <= FILE_WIDTH
    assert max(len(line) for line in lines) > NARROW  # the Demand table, on one line a row
    assert any("SLD" in line and "[ntc.demand.SLD]" in line for line in lines)
    assert any(
        line.startswith("note: ULS nonlinear height: demand") and line.endswith("]")
        for line in lines
    )


def test_a_redirected_report_has_no_trailing_blanks() -> None:
    # Item 15: a report written to a file is read and diffed; table titles padded to the
    # table's width left trailing blanks on every title line.
    result = CliRunner().invoke(cli, ["kinematic", str(ALTAR)])
    assert [line for line in result.stdout.splitlines() if line != line.rstrip()] == []


def test_column_widths_keep_every_word_whole() -> None:
    # Two columns (a long text, a number): the text wraps at spaces, the number keeps its 10
    # characters. The boxed frame of two columns takes 7 characters besides their content.
    columns = [
        ColumnText(("label",), ("a long label that wraps",), numeric=False),
        ColumnText(("value",), ("1.23456789",), numeric=True),
    ]
    assert fit(columns, 40).widths is None  # fits: rich's natural layout
    layout = fit(columns, 27)
    assert layout.frame.name == "boxed" and layout.widths is not None
    assert layout.widths[1] == len("1.23456789") and sum(layout.widths) <= 20
    assert layout.widths[0] >= len("label")
    # Narrower than the number alone: the number whole, the table wider than asked.
    narrow = fit(columns, 5)
    assert narrow.widths is not None and narrow.widths[1] == len("1.23456789")


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
@pytest.mark.parametrize("command", ["kinematic", "assess", "compare"])
def test_a_non_utf8_output_gets_the_report(encoding: str, command: str) -> None:
    # PYTHONIOENCODING=cp1252 is the Windows default when the output is redirected: θ, α, ≤
    # raised UnicodeEncodeError mid-table. Symbols the encoding lacks are spelled in ASCII.
    args = [sys.executable, "-m", "rockcli", command, str(ALTAR)]
    if command != "kinematic":
        args += ["--record", str(PULSES[0])]
    env = {**os.environ, "PYTHONIOENCODING": encoding}
    done = subprocess.run(args, capture_output=True, env=env, timeout=300, check=False)
    assert done.returncode == 0, done.stderr.decode(errors="replace")
    assert done.stderr == b""
    text = done.stdout.decode(encoding)
    assert "verdict:" in text and "…" not in text and "?" not in text
    if command == "kinematic":
        assert "load multiplier alpha0" in text


def test_an_error_line_in_a_non_utf8_output() -> None:
    # The error line carries no symbol the stream cannot encode: a UnicodeEncodeError there
    # was a traceback. (On a stream that claims ASCII, click writes UTF-8 on purpose.)
    env = {**os.environ, "PYTHONIOENCODING": "cp1252"}
    args = [sys.executable, "-m", "rockcli", "kinematic", "nowhere-θ≤.toml"]
    done = subprocess.run(args, capture_output=True, env=env, timeout=120, check=False)
    assert done.returncode == 2
    assert done.stderr.decode("cp1252").startswith("error: nowhere-theta<=.toml: ")


def test_encodable_spells_symbols_and_keeps_numbers() -> None:
    assert encodable("θ̇ ≤ 1.5 m/s² — α", "ascii") == "theta_dot <= 1.5 m/s2 - alpha"
    assert encodable("θ ≤ 1.5 m/s²", "cp1252") == "theta <= 1.5 m/s²"  # cp1252 has ²
    assert encodable("plain 1.5", "ascii") == "plain 1.5"


ESCAPE = "\x1b[2J"  # "clear the screen"


def test_printable_escapes_control_and_bidi_characters() -> None:
    assert printable(f"wall{ESCAPE}\nx\u202ey") == "wall\\x1b[2J\\x0ax\\u202ey"
    assert printable("Façade θ") == "Façade θ"


def test_a_model_name_cannot_drive_the_terminal(tmp_path: Path) -> None:
    # A model's name is shown in titles; an escape sequence in it reached the terminal raw.
    text = ALTAR.read_text(encoding="utf-8")
    name = re.search(r'^name = "(.*)"$', text, re.M)
    assert name is not None
    model = tmp_path / "m.toml"
    model.write_text(text.replace(name.group(0), 'name = "evil\\u001b[2J\\u202e"'), "utf-8")
    for args in (["kinematic", str(model)], ["assess", str(model), "--record", str(PULSES[0])]):
        result = CliRunner().invoke(cli, args)
        assert result.exit_code == 0, result.stderr
        assert "\x1b" not in result.stdout and "\u202e" not in result.stdout
        assert "evil\\x1b[2J\\u202e" in result.stdout


def test_a_record_name_cannot_drive_the_terminal(tmp_path: Path) -> None:
    record = tmp_path / f"pulse{ESCAPE}.txt"
    record.write_bytes(PULSES[0].read_bytes())
    result = CliRunner().invoke(cli, ["assess", str(ALTAR), "--record", str(record)])
    assert result.exit_code == 0, result.stderr
    assert "\x1b" not in result.stdout
    assert "pulse\\x1b[2J" in result.stdout


def test_a_file_name_in_an_error_line_is_escaped(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(tmp_path / f"x{ESCAPE}\nforged.toml")])
    assert result.exit_code == 2
    assert "\x1b" not in result.stderr and result.stderr.count("\n") == 1
    assert "x\\x1b[2J\\x0aforged.toml" in result.stderr
