"""Bad plot paths and a missing matplotlib: one error line, exit code 2, before any run."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from rockcli import plots
from rockcli.errors import InputError
from tests.cli.conftest import PULSES, ROOT
from tests.plots.conftest import needs_matplotlib, run

ALTAR = ROOT / "examples" / "altar.toml"
COMMANDS = {
    "assess": ("assess", str(ALTAR), "--record", str(PULSES[0])),
    "kinematic": ("kinematic", str(ALTAR)),
    "compare": ("compare", str(ALTAR), "--record", str(PULSES[0])),
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("name", ["figure.pdf", "figure", "figure.png.txt"])
def test_bad_suffix_is_one_error_line(tmp_path: Path, command: str, name: str) -> None:
    out = tmp_path / name
    code, stdout, err = run(*COMMANDS[command], "--plot", str(out))
    suffix = Path(name).suffix or "a file without suffix"
    assert err == (
        f"error: --plot: cannot write a plot as {suffix} (got '{out}'; "
        "allowed: a file name ending in .png or .svg)\n"
    )
    assert code == 2
    assert stdout == ""  # refused before the analysis ran
    assert not out.exists()


def test_unwritable_plot_file(tmp_path: Path) -> None:
    needs_matplotlib()
    out = tmp_path / "no such folder" / "figure.png"
    code, stdout, err = run(*COMMANDS["kinematic"], "--plot", str(out))
    assert err == (
        f"error: {out}: --plot: the folder does not exist "
        f"(got '{out.parent}'; allowed: a path in an existing folder)\n"
    )
    assert code == 2
    assert stdout == ""  # refused before the analysis ran (issue 7, item 17)


def test_missing_matplotlib_is_refused_before_the_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = importlib.util.find_spec

    def find_spec(name: str, *args: object) -> object:
        return None if name == "matplotlib" else real(name, *args)

    monkeypatch.setattr(importlib.util, "find_spec", find_spec)
    code, stdout, err = run(*COMMANDS["assess"], "--plot", str(tmp_path / "f.png"))
    assert err == (
        "error: plots need matplotlib: pip install '.[plot]' from the repository's folder\n"
    )
    assert code == 2 and stdout == ""


def test_plot_function_without_matplotlib(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A None entry in sys.modules makes the import raise ImportError, as if not installed.
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    hint = r"pip install '\.\[plot\]' from the repository's folder"
    with pytest.raises(InputError, match=rf"^plots need matplotlib: {hint}$"):
        plots.plot_sweep(
            [{"R": 1.5, "alpha": 0.1, "record": "r", "code_collapse": True,
              "rocking_collapse": False}],
            tmp_path / "f.png",
        )  # fmt: skip


def test_plot_format_names_option_value_and_suffixes() -> None:
    with pytest.raises(InputError) as info:
        plots.plot_format("map.jpg", where="--sweep-plot")
    assert info.value.where == "--sweep-plot"
    assert info.value.value == "map.jpg"
    assert info.value.allowed == "a file name ending in .png or .svg"
    assert plots.plot_format("a/b.SVG") == "svg"
