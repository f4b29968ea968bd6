"""Control characters in names reach no figure raw (issue 20, item 10).

On main a record whose file name holds an escape (ESC, 0x1b) or a model named with a bell
(0x07) made matplotlib warn "UserWarning: Glyph 27 () missing from font(s) DejaVu Sans." on
stderr, with the absolute path of rock's source and a line of its code, and the SVG of the
report carried the raw byte. Every text of a figure now shows them as the terminal does,
``\\x1b`` (rockcli.plots.files.printable_text). pytest turns any warning into an
error here (pyproject: filterwarnings = error), so a warning fails the run.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from tests.cli.conftest import PULSES, ROOT
from tests.plots.conftest import assert_png, needs_matplotlib, run

ESC, BEL = "\x1b", "\x07"


@pytest.fixture(autouse=True)
def _matplotlib() -> None:
    needs_matplotlib()


@pytest.fixture
def named_badly(tmp_path: Path) -> tuple[Path, Path]:
    """(model named "wall ESC[31m red BEL", record file named "recESCesc.txt")."""
    text = (ROOT / "examples" / "wall.toml").read_text(encoding="utf-8")
    lines = [
        'name = "wall \\u001b[31m red \\u0007"' if line.startswith("name =") else line
        for line in text.splitlines()
    ]
    model = tmp_path / "m.toml"
    model.write_text("\n".join(lines) + "\n", encoding="utf-8")
    record = tmp_path / f"rec{ESC}esc.txt"
    shutil.copy(PULSES[0], record)
    return model, record


@pytest.mark.parametrize("command", ["assess", "kinematic", "compare"])
def test_plots_of_badly_named_inputs_warn_nothing(
    named_badly: tuple[Path, Path], tmp_path: Path, command: str
) -> None:
    model, record = named_badly
    out = tmp_path / "figure.png"
    code, _, err = run(command, str(model), "--record", str(record), "--plot", str(out))
    assert code == 0, err
    assert "Warning" not in err and "Glyph" not in err
    assert_png(out)


def test_record_spectrum_plot_of_a_badly_named_record_warns_nothing(
    named_badly: tuple[Path, Path], tmp_path: Path
) -> None:
    _, record = named_badly
    out = tmp_path / "spectrum.png"
    code, _, err = run("record", "spectrum", str(record), "--plot", str(out))
    assert code == 0, err
    assert "Warning" not in err
    assert_png(out)


def test_report_svg_shows_control_characters_escaped() -> None:
    from rockcli.document.figures import new_figure, svg_markup
    from rockcli.document.words import Words

    fig = new_figure(3.0, 2.0, Words("en"))
    ax = fig.add_subplot()
    ax.set_title(f"wall {ESC}[31m red {BEL}\nsecond line")
    ax.plot([0, 1], [0, 1], label=f"rec{ESC}esc")
    ax.legend()
    svg = svg_markup(fig)
    assert ESC not in svg and BEL not in svg
    assert "\\x1b" in svg  # matplotlib keeps each text as a comment beside its paths
