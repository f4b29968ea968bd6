"""`--plot FILE` on assess, kinematic and compare writes a readable PNG or SVG (issue #4, 6).

Runs on the shipped examples and pulses, so on a fresh clone. The figures themselves are
looked at by a person; these tests check that every command and every example draws without
error, that the files are what their suffix says, and that plotting leaves the JSON unchanged.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.cli.conftest import EXAMPLES, PULSES, ROOT
from tests.plots.conftest import assert_png, assert_svg, needs_matplotlib, run

ALTAR = ROOT / "examples" / "altar.toml"
FACADE = ROOT / "examples" / "facade.toml"
CHECKS = {"png": assert_png, "svg": assert_svg}


@pytest.fixture(autouse=True)
def _matplotlib() -> None:
    needs_matplotlib()


def plotted(tmp_path: Path, suffix: str, *args: str) -> Path:
    """Run a command with --plot into tmp_path; the file, checked for its format."""
    out = tmp_path / f"figure.{suffix}"
    code, _, err = run(*args, "--plot", str(out), "--format", "json")
    assert code == 0, err
    CHECKS[suffix](out)
    return out


@pytest.mark.parametrize("suffix", ["png", "svg"])
def test_assess_plot(tmp_path: Path, suffix: str) -> None:
    plotted(tmp_path, suffix, "assess", str(ALTAR), "--record", str(PULSES[0]))


@pytest.mark.parametrize("suffix", ["png", "svg"])
@pytest.mark.parametrize("edition", ["2009", "2019"])
def test_kinematic_plot(tmp_path: Path, suffix: str, edition: str) -> None:
    # The 2019 rules ask a block for LC1's FC (§C8.7.1.2.1.3): the altar's copy with it.
    altar = ALTAR if edition == "2009" else ROOT / "tests" / "data" / "altar-2019.toml"
    plotted(tmp_path, suffix, "kinematic", str(altar), "--edition", edition)


@pytest.mark.parametrize("suffix", ["png", "svg"])
def test_compare_plot(tmp_path: Path, suffix: str) -> None:
    plotted(tmp_path, suffix, "compare", str(FACADE), "--record", str(PULSES[-1]))


@pytest.mark.parametrize("model", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_plots_its_comparison(tmp_path: Path, model: Path) -> None:
    # Covers the capacity curves with d0* (altar, wall, validation block) and without
    # (façade, positive stiffness), one- and two-sided rocking, overturning or not.
    plotted(tmp_path, "png", "compare", str(model), "--record", str(PULSES[0]))


def test_uppercase_suffix_is_accepted(tmp_path: Path) -> None:
    out = tmp_path / "FIGURE.PNG"
    code, _, err = run("kinematic", str(ALTAR), "--plot", str(out))
    assert code == 0, err
    assert_png(out)


@pytest.mark.parametrize(
    "args",
    [
        ("assess", str(ALTAR), "--record", str(PULSES[0])),
        ("kinematic", str(ALTAR)),
        ("compare", str(ALTAR), "--record", str(PULSES[0])),
    ],
    ids=["assess", "kinematic", "compare"],
)
def test_plot_leaves_the_json_unchanged(tmp_path: Path, args: tuple[str, ...]) -> None:
    code, plain, err = run(*args, "--format", "json")
    assert code == 0, err
    code, with_plot, err = run(*args, "--format", "json", "--plot", str(tmp_path / "f.png"))
    assert code == 0, err
    assert json.loads(with_plot) == json.loads(plain)


def test_history_and_plot_together(tmp_path: Path) -> None:
    # --history writes the worse run; --plot needs both: one run with history serves both.
    csv_path, png = tmp_path / "h.csv", tmp_path / "f.png"
    code, _, err = run(
        "assess", str(ALTAR), "--record", str(PULSES[0]),
        "--history", str(csv_path), "--plot", str(png),
    )  # fmt: skip
    assert code == 0, err
    assert csv_path.read_text(encoding="utf-8").startswith(
        "t_s,ground_acc_g,floor_acc_g,theta_rad,"
    )
    assert err == f"wrote {csv_path}\nwrote {png}\n"
    assert_png(png)


def test_the_lower_panel_names_the_motion_that_shook_the_block() -> None:
    # A block at height rocks on the floor motion (issue 8): the panel under θ/α says so.
    needs_matplotlib()
    from matplotlib.figure import Figure

    from rockcli.plots.histories import draw_record
    from rockcli.records.files import read_record

    rec = read_record(str(PULSES[0]))
    for floor, label in ((True, "floor acc. [g]"), (False, "ground acc. [g]")):
        ax = Figure().add_subplot()
        draw_record(ax, rec, 4.0, floor)
        assert ax.get_ylabel() == label


def test_a_yielded_restrainer_gets_its_force_elongation_loop() -> None:
    # Issue 9: the façade's tie-rod yields under the Ricker pulse; the loop panel draws the
    # engine's force against the elongation, never above the yield line, and names the law.
    needs_matplotlib()
    from matplotlib.figure import Figure

    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import to_block
    from rockcli.model.load import load_model
    from rockcli.plots.loops import acted, draw_loops
    from rockcli.records.files import read_record
    from rockcli.terminal.assess import model_document

    block = to_block(load_model(ROOT / "examples" / "facade.toml"))
    rec = read_record(str(ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"))
    result = assess(block, rec.time, rec.accel, rec.dt, history=True)
    rows = acted(result.runs)
    names = [sp.name for sp in block.restrainers]
    assert [names[j] for j in rows] == ["groin vault", "tie-rod"]  # lost at 1 mm; yielded
    rows = [names.index("tie-rod")]
    model = model_document("façade", "facade", block, "housner")
    ax = Figure().add_subplot()
    draw_loops(ax, model, result.runs, rows[0])
    assert ax.get_title() == "tie-rod (elastic-plastic)"
    f_y = model["restrainers"][rows[0]]["yield_pos"] / 1e3
    forces = [max(line.get_ydata()) for line in ax.get_lines() if line.get_label() in ("+1", "-1")]
    assert len(forces) == 2 and max(forces) <= f_y * (1 + 1e-12)
