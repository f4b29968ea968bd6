"""The tie-rod sized by the code check alone: `rock retrofit MODEL` without a record (each
diameter's code ULS on the model's own spectra, no time history), and the report's
--retrofit without a record and with a suite (the verification's spectra)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
WALL = ROOT / "examples" / "two-storey-facade.toml"
SHARED = ROOT.parent / "shared"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture(scope="module")
def strong(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The two-storey façade on a stronger site (SLV ag 0.25 g, SLC 0.30 g): its verification
    fails at the SLV, so the report asks for an intervention."""
    text = WALL.read_text(encoding="utf-8")
    text = text.replace("ag = 0.15", "ag = 0.25").replace("ag = 0.19", "ag = 0.30")
    assert text.count("ag = 0.25") == 1 and text.count("ag = 0.30") == 1
    path = tmp_path_factory.mktemp("strong") / "strong.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def sized(strong: Path) -> dict:
    code, out, err = run("retrofit", str(strong), "--format", "json")
    assert code == 0, err
    return json.loads(out)


def test_without_a_record_the_code_check_alone(sized: dict) -> None:
    assert sized["record"] is None and sized["code_demand"] == "model"
    for row in sized["candidates"]:
        for m in row["mechanisms"]:  # nothing rocked, so nothing the time history decides
            assert m["rocking"] is None and m["max_ratio"] is None and m["max_force"] is None


def test_the_choice_is_the_smallest_diameter_whose_restrained_mechanisms_pass(sized: dict) -> None:
    # Recomputed from the rows: the first diameter whose every mechanism the rod restrains
    # passes the code's ULS; those it does not restrain and that fail are named apart.
    def passes(row: dict) -> bool:
        return all(m["code_uls_passed"] for m in row["mechanisms"] if m["restrained"])

    first = next(r for r in sized["candidates"] if passes(r))
    assert sized["chosen"]["diameter_mm"] == first["diameter_mm"]
    failing_free = [m["name"] for m in first["mechanisms"]
                    if not m["restrained"] and not m["code_uls_passed"]]  # fmt: skip
    assert sized["another_intervention"] == failing_free
    assert "the code check alone: no record, no time history" in sized["reason"]


def test_the_terminal_table_has_no_time_history_columns(strong: Path) -> None:
    code, out, err = run("retrofit", str(strong))
    assert code == 0, err
    assert "on the model's own code spectra (no record)" in out
    assert "θ/α" not in out and "peak force" not in out


def test_the_plot_and_the_details_without_a_record(strong: Path, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib", reason="the plot extra (matplotlib) is not installed")
    png = tmp_path / "r.png"
    code, out, err = run("retrofit", str(strong), "--details", "--plot", str(png))
    assert code == 0, err
    assert png.stat().st_size > 0 and "each mechanism with each diameter" in out
    assert "elongation" not in out and "θ/α" not in out


def test_the_anchor_is_checked_without_a_record(strong: Path, tmp_path: Path) -> None:
    # γov·A·fy needs no time history: an anchor of 90 kN takes a Ø20 S275 bar (γov·A·fy =
    # 1.25 × 314.16 mm² × 275 MPa = 108.0 kN) no more, with or without a record.
    model = tmp_path / "anchored.toml"
    text = strong.read_text(encoding="utf-8")
    text = text.replace('kind = "tie-rod"\n', 'kind = "tie-rod"\nanchor_capacity = 90e3\n')
    assert "anchor_capacity" in text
    model.write_text(text, encoding="utf-8")
    code, out, err = run("retrofit", str(model), "--diameters", "16,20", "--format", "json")
    assert code == 0, err
    rows = {r["diameter_mm"]: r for r in json.loads(out)["candidates"]}
    held = [m for m in rows[20.0]["mechanisms"] if m["on_mechanism"]]
    assert held and all(m["anchor"]["passed"] is False for m in held)
    assert all(m["status"] == "fails" for m in held)
    assert 1.25 * 3.14159265 * 0.010**2 * 275e6 == pytest.approx(108.0e3, rel=1e-3)
    assert all(m["anchor"]["demand"] == pytest.approx(108.0e3, rel=1e-3) for m in held)


def test_a_model_without_spectra_needs_a_record() -> None:
    code, _, err = run("retrofit", str(ROOT / "examples" / "facade.toml"))
    assert code == 2 and err.count("\n") == 1, err
    assert "sets no code spectrum" in err and "--record FILE" in err


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--code-demand", "record"], "--code-demand: reads the spectrum of a record"),
        (["--scale", "2"], "--scale: applies only to a record"),
        (["--ground"], "--ground: acts on a time history"),
        (["--engine", "reference"], "--engine: acts on a time history"),
    ],
)
def test_bad_input_without_a_record(strong: Path, args: list[str], words: str) -> None:
    code, _, err = run("retrofit", str(strong), *args)
    assert code == 2 and words in err and err.count("\n") == 1, err


def conclusions(page: str) -> str:
    found = re.search(r'<section id="conclusions".*?</section>', page, flags=re.S)
    assert found is not None
    return found.group(0)


def test_the_filing_report_sizes_the_rod_on_the_sites_spectra(
    strong: Path, sized: dict, tmp_path: Path
) -> None:
    pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
    html = tmp_path / "r.html"
    code, _, err = run("report", str(strong), "--retrofit", "-o", str(html), "--lang", "en")
    assert code == 0, err
    text = conclusions(html.read_text(encoding="utf-8"))
    found = re.search(r"by the code check alone[^<]*?is Ø(\d+) mm", text)
    assert found is not None, text
    assert float(found.group(1)) == sized["chosen"]["diameter_mm"]
    # The code check alone: nothing said of a time history the sizing did not run.
    sentence = text[text.index("Intervention (sizing") :]
    assert "does not overturn" not in sentence and "under the same record" not in sentence


def test_a_suites_report_sizes_the_rod_on_the_verifications_spectra(
    strong: Path, sized: dict, tmp_path: Path
) -> None:
    if not (SHARED / "records").is_dir() or not (SHARED / "ntc" / "AllegatoB.txt").is_file():
        pytest.skip("../shared (the suite's records and the hazard grid) is not beside the clone")
    pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
    html = tmp_path / "r.html"
    suite = ROOT / "examples" / "suites" / "laquila-slv.toml"
    code, _, err = run("report", str(strong), "--suite", str(suite), "--allow-outside",
                       "--hazard-grid", str(SHARED / "ntc" / "AllegatoB.txt"), "--retrofit",
                       "-o", str(html), "--lang", "en")  # fmt: skip
    assert code == 0, err
    text = conclusions(html.read_text(encoding="utf-8"))
    found = re.search(r"by the code check alone[^<]*?is Ø(\d+) mm", text)
    assert found is not None, text
    assert float(found.group(1)) == sized["chosen"]["diameter_mm"]
    assert "and with it the suite" in text  # its time histories to run again


def test_a_suites_report_without_own_spectra_says_why_no_rod(tmp_path: Path) -> None:
    # rockcli.document.run.suite_sizing: no verification (the model sets no code spectrum):
    # the rod is not sized, and the reason says so (no analysis needed to find that).
    from rockcli.analyses.choices import Analyses
    from rockcli.document.run import suite_sizing

    sizing = suite_sizing(str(ROOT / "examples" / "facade.toml"), None, {}, Analyses(), None)
    assert not sizing.diameters_mm and sizing.reason.key == "retro_no_spectra"
