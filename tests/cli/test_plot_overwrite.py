"""`--plot FILE` on every command that draws (issue 34, F17): an existing FILE is refused
before any work (one line, exit 2, the file untouched) and replaced with the command's
--force, as every other output file (rockcli.outfile.check_writable). `rock sweep` and
`rock fragility` wrote over it after the study, whatever --force said.

The commands are found by walking the command tree, so a new command with --plot must be
added here.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import PULSES, ROOT

ALTAR = str(ROOT / "examples" / "altar.toml")
FACADE = str(ROOT / "examples" / "facade.toml")
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
KEEP = b"keep me"

#: A small wall the sweep and the fragility study rock (tests/sweep/conftest.py's, no spring).
WALL = """\
name = "test wall"
kind = "wall"
geometry = { R = 1.5, alpha = 0.1, width = 3.0 }
mass = { unit_weight = 18.0 }
ntc = { edition = "2009", FC = 1.0 }
"""
SWEEP = """\
base = "wall.toml"

[[axes]]
path = "geometry.R"
name = "R"
values = [1.5, 3.0]

[[records]]
path = "ricker.txt"
"""
FRAGILITY = """\
name = "tiny MSA"
model = "wall.toml"
method = "msa"
intensity = { measure = "pga" }
damage_states = [{ level = "overturning" }]
msa = { levels = [0.2, 0.6] }
records = [{ path = "ricker.txt" }]
"""


def study(tmp_path: Path, text: str) -> str:
    """A study file in tmp_path with its wall and the Ricker pulse beside it."""
    (tmp_path / "wall.toml").write_text(WALL, encoding="utf-8")
    shutil.copy(RICKER, tmp_path / "ricker.txt")
    path = tmp_path / "study.toml"
    path.write_text(text, encoding="utf-8")
    return str(path)


#: Each command with --plot: its arguments (before --plot), run quickly on shipped inputs.
COMMANDS: dict[str, Callable[[Path], list[str]]] = {
    "assess": lambda tmp: ["assess", ALTAR, "--record", str(PULSES[0])],
    "compare": lambda tmp: ["compare", ALTAR, "--record", str(PULSES[0])],
    "kinematic": lambda tmp: ["kinematic", ALTAR],
    "retrofit": lambda tmp: ["retrofit", FACADE, "--record", str(RICKER), "--diameters", "20"],
    "record spectrum": lambda tmp: ["record", "spectrum", str(RICKER)],
    "spectrum overturning": lambda tmp: (
        "spectrum overturning --pulse ricker --alpha 0.2 --ratios 2".split()
    ),
    "suite check": lambda tmp: [
        *("suite", "check", str(ROOT / "records")),
        *("--target", "ag=0.2,F0=2.4,Tc_star=0.3"),
    ],
    "sweep": lambda tmp: ["sweep", study(tmp, SWEEP), "--out", str(tmp / "out")],
    "fragility run": lambda tmp: ["fragility", study(tmp, FRAGILITY), "--out", str(tmp / "out")],
}


def plotting_commands(group: click.Group, prefix: str = "") -> Iterator[str]:
    for name, command in group.commands.items():
        if isinstance(command, click.Group):
            yield from plotting_commands(command, f"{prefix}{name} ")
        elif any(p.name == "plot_path" for p in command.params):
            yield prefix + name


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_every_command_with_plot_is_here() -> None:
    assert sorted(plotting_commands(cli)) == sorted(COMMANDS)


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_an_existing_plot_needs_force(tmp_path: Path, command: str) -> None:
    pytest.importorskip("matplotlib")
    plot = tmp_path / "figure.png"
    plot.write_bytes(KEEP)
    args = [*COMMANDS[command](tmp_path), "--plot", str(plot), "--format", "json"]
    code, out, err = run(*args)
    assert (code, out) == (2, "")  # refused before the analysis ran: no report
    assert err == f"error: {plot}: --plot: file exists (allowed: another path, or --force)\n"
    assert plot.read_bytes() == KEEP
    assert not (tmp_path / "out").exists()  # a study made no output folder either
    code, _, err = run(*args, "--force")
    assert code == 0, err
    assert f"wrote {plot}\n" in err
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("command", ["sweep", "fragility run"])
def test_a_study_plot_inside_its_new_output_folder(tmp_path: Path, command: str) -> None:
    # The run makes the folder: the plot there is not refused for a missing folder, and is
    # refused as any existing file when the study runs again into the same folder.
    pytest.importorskip("matplotlib")
    plot = tmp_path / "out" / "figure.png"
    args = [*COMMANDS[command](tmp_path), "--plot", str(plot), "--format", "json"]
    code, _, err = run(*args)
    assert code == 0, err
    drawn = plot.read_bytes()
    code, out, err = run(*args)
    assert (code, out) == (2, "")
    assert err.endswith(f"{plot}: --plot: file exists (allowed: another path, or --force)\n")
    assert plot.read_bytes() == drawn
