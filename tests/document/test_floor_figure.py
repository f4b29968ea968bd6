"""The report's spectra at the mechanism's height: the floor curves are the code check's own
floor spectrum (Circolare 7/2019 §C7.2.3) at the check's own position, checked against the
clause's formula written out here; the 2009 edition's demand at height (Circolare 617/2009
§C8A.4.2.3); a block on the ground has no spectra at height."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rockcli.analyses.kinematic import check_settings, given_demands, kinematic_model
from rockcli.document.build import Inputs, demand_section
from rockcli.document.figures import (
    SPECTRUM_PERIODS,
    floor_curve,
    floor_spectra,
)
from rockcli.document.words import Words
from rockcli.model.load import load_model
from rockcli.records.files import read_record

pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")


ROOT = Path(__file__).resolve().parents[2]
TOP_STOREY = ROOT / "examples" / "top-storey-wall.toml"
ALTAR = ROOT / "examples" / "altar.toml"
FACADE = ROOT / "examples" / "facade.toml"
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: Periods at which the curve is compared [s]: on the rising branch, the plateau
#: 0.8·T1 ≤ T < 1.1·T1 (T1 = 0.215 s) and the falling branch.
PERIODS = (0.0, 0.05, 0.1, 0.18, 0.2, 0.23, 0.3, 0.5, 1.0, 2.0, 3.5)


def clause_floor_spectrum(T: float, Se_T1: float, T1: float, gamma_psi: float, xi: float) -> float:
    """S_eZ(T) [g] as Circolare 7/2019 §C7.2.3 writes it (C7.2.5–C7.2.10), ξ_k = 5 % read as
    0.05 in 1.1·ξ_k^−0.5 and as 5 in √(1 + 0.0004·ξ_k²) (docs/interpretations.md); the
    mechanism's damping ξ [%] through η = √(10/(5 + ξ)) ≥ 0.55 (NTC 2018 Eq. 3.2.6)."""
    a_z = Se_T1 * abs(gamma_psi) * math.sqrt(1.0 + 0.0004 * 5.0**2)
    amp = 1.1 * 0.05**-0.5 * max(math.sqrt(10.0 / (5.0 + xi)), 0.55)
    if T < 0.8 * T1:
        return a_z * amp / (1.0 + (amp - 1.0) * (1.0 - T / (0.8 * T1)) ** 1.6)
    if T < 1.1 * T1:
        return a_z * amp
    return a_z * amp / (1.0 + (amp - 1.0) * (T / (1.1 * T1) - 1.0) ** 1.2)


@pytest.fixture(scope="module")
def wall():
    """The top-storey wall (Z = 3.5 m, 2019), its check on the model's spectra, its position."""
    model = load_model(TOP_STOREY)
    kin = kinematic_model(model)
    return model, kin, kin.position


def test_the_position_is_the_checks_own(wall) -> None:
    # The check read the record's spectrum at the building's T1 (its spectral values).
    model, kin, pos = wall
    with_record = kinematic_model(model, record=read_record(PULSE))
    read_at = {v["at"]: v["T"] for v in with_record.demand["SLV"]["spectral_values"]}
    assert pos.at_height and pos.Z == 3.5
    assert pos.T1 == read_at["T1"] == pytest.approx(0.05 * 7.0**0.75, rel=1e-12)
    assert (pos.psi, pos.gamma, pos.damping) == (0.5, pytest.approx(1.2), 0.05)


def test_the_floor_curve_is_the_checks_floor_spectrum(wall) -> None:
    model, kin, pos = wall
    demands = given_demands(check_settings(model), model.analysis.g)
    T1 = 0.05 * 7.0**0.75  # 0.05·H^0.75 (NTC 2018 Eq. 7.3.5), H = 7 m
    for state, xi in (("SLD", 5.0), ("SLV", 8.0), ("SLC", 10.0)):
        spectrum = demands[state].spectrum
        T, values = floor_curve(spectrum, state, pos, "2019", np.array(PERIODS))
        # Eq. C7.2.5: not below the ground spectrum S_e(T, ξ) for T > T1.
        expected = [
            max(clause_floor_spectrum(t, spectrum.Se(T1), T1, 1.2 * 0.5, xi), spectrum.Se(t, xi))
            if t > T1
            else clause_floor_spectrum(t, spectrum.Se(T1), T1, 1.2 * 0.5, xi)
            for t in PERIODS
        ]
        assert list(T) == list(PERIODS)
        assert values == pytest.approx(expected, rel=1e-12), state


def test_the_floor_curve_at_rest_is_the_sld_checks_floor_acceleration(wall) -> None:
    # The SLD check at height: ag,SLD makes a_Z = S_eZ(0) equal to a0* (§C8.7.1.2.1).
    model, kin, pos = wall
    sld = next(c for c in kin.checks if c.limit_state == "SLD")
    assert str(sld.location) == "height"
    g = model.analysis.g
    spectrum = given_demands(check_settings(model), g)["SLD"].at_ag(sld.capacity)
    _, at_rest = floor_curve(spectrum, "SLD", pos, "2019", np.array([0.0]))
    assert at_rest[0] * g == pytest.approx(kin.a0_star, rel=1e-9)


def test_the_figure_draws_the_floor_curve(wall) -> None:
    model, kin, pos = wall
    w = Words("it")
    demands = given_demands(check_settings(model), model.analysis.g)
    code = [(state, d.spectrum) for state, d in demands.items()]
    fig = floor_spectra(code, pos, "2019", None, "pulse", {}, w)
    lines = {line.get_label(): line for line in fig.axes[0].get_lines()}
    periods = np.linspace(*SPECTRUM_PERIODS)
    for state, spectrum in code:
        line = lines[w("figure.floor_spectrum_2019", Z="3,5", state=state)]
        T, values = floor_curve(spectrum, state, pos, "2019", periods)
        assert np.array_equal(line.get_xdata(), T)
        assert np.array_equal(line.get_ydata(), values)
    assert "spettro di piano a Z = 3,5 m, SLV" in lines
    assert not any("moto di piano" in label for label in lines)  # no floor motion given


def test_the_2009_demand_at_height_is_the_circolare_617s() -> None:
    # Circ. 617/2009 §C8A.4.2.3: SDe(T1)·ψ·γ·(T/T1)²/√[(1 − T/T1)² + 0.02·T/T1], drawn as
    # d·(2π/T)²/g: Se(T1)·ψ·γ as T → 0 (the linear checks), ÷ √0.02 at T = T1.
    model = load_model(ALTAR)
    kin = kinematic_model(model)
    pos = kin.position
    demands = given_demands(check_settings(model), model.analysis.g)
    spectrum = demands["SLV"].spectrum
    T, values = floor_curve(spectrum, "SLV", pos, "2009", np.array([0.0, 1e-6, 1.09]))
    at_height = spectrum.Se(1.09) * 0.51 * 1.0
    assert list(T) == [1e-6, 1.09]
    assert values[0] == pytest.approx(at_height, rel=1e-5)
    assert values[1] == pytest.approx(at_height / math.sqrt(0.02), rel=1e-12)
    no_slc = floor_curve(spectrum, "SLC", pos, "2009", np.array([0.5]))
    assert len(no_slc[0]) == 0  # the 2009 edition checks SLD and SLV only


def demand_figures(model_path: Path, ground: bool = False) -> list:
    """The figures of the report's demand section of the model under the pulse."""
    from rockcli.analyses.compare import compare_model_output
    from rockcli.terminal.compare import comparison_output_document

    model, record = load_model(model_path), read_record(PULSE)
    out = compare_model_output(model, record, ground=ground)
    doc = comparison_output_document(out, record)
    inputs = Inputs(str(model_path), model, record, (), "rock report", "2025-01-01")
    section = demand_section(inputs, doc, record, Words("it"), out)
    return [b for b in section.blocks if hasattr(b, "svg")]


def test_a_block_on_the_ground_has_no_floor_curve() -> None:
    figures = demand_figures(FACADE)
    assert [f.key for f in figures] == ["spectra"]
    assert figures[0].caption == Words("it")("figure.spectra_caption")


def test_a_block_at_height_has_its_spectra_at_height_after_the_ground_ones() -> None:
    w = Words("it")
    figures = demand_figures(TOP_STOREY)
    assert [f.key for f in figures] == ["spectra", "floor_spectra"]
    assert figures[0].caption == w("figure.spectra_ground_caption")
    assert "Z = 3,5 m" in figures[1].caption and "T1 = 0,215 s" in figures[1].caption
    assert figures[1].caption.endswith(w("figure.floor_caption_motion"))
    on_record = demand_figures(TOP_STOREY, ground=True)  # --ground: no floor motion
    assert on_record[1].caption.endswith(w("figure.floor_caption_ground"))


def test_a_suites_report_at_height_has_the_floor_spectra(tmp_path: Path) -> None:
    # The altar stands at Z = 3.04 m: the suite's report draws the code's demand there too,
    # and says that each record's floor motion was rocked.
    from click.testing import CliRunner

    from rockcli.cli.main import cli

    shared = ROOT.parent / "shared"
    if not (shared / "records").is_dir() or not (shared / "ntc" / "AllegatoB.txt").is_file():
        pytest.skip("../shared (the suite's records and the hazard grid) is not beside the clone")
    out = tmp_path / "suite.html"
    result = CliRunner().invoke(cli, [
        "report", str(ROOT / "examples" / "altar.toml"), "--suite",
        str(ROOT / "examples" / "suites" / "laquila-slv.toml"), "--allow-outside",
        "--hazard-grid", str(shared / "ntc" / "AllegatoB.txt"), "-o", str(out),
        "--casebook", "none", "--lang", "en",
    ])  # fmt: skip
    assert result.exit_code == 0, result.stderr
    page = out.read_text(encoding="utf-8")
    assert 'id="figure-floor_spectra"' in page
    assert "each record&#39;s floor motion at Z" in page


def test_a_figure_is_drawn_as_png_only_for_a_word_copy() -> None:
    # rockcli.document.run.built: a report without --docx does not render its figures twice.
    pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")
    from rockcli.document.figures import PNG_WANTED, new_figure, rendered
    from rockcli.document.words import Words

    def drawn() -> tuple[str, bytes]:
        fig = new_figure(3.0, 2.0, Words("en"))
        fig.subplots().plot([0, 1], [0, 1])
        return rendered(fig)

    token = PNG_WANTED.set(False)
    try:
        svg, png = drawn()
    finally:
        PNG_WANTED.reset(token)
    assert svg.startswith("<svg") and png == b""
    svg, png = drawn()  # the default: a Word copy may want it
    assert png.startswith(b"\x89PNG")
