"""`rock record spectrum` through click's CliRunner.

Independent references: the closed forms of the linear oscillator (Chopra, *Dynamics of
Structures*: harmonic force at resonance §3.2, suddenly applied force §4.3) and the rigid
limit Sa(T → 0) = PGA of a record that starts at rest.
"""

from __future__ import annotations

import io
import json
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from rich.console import Console

from rockcli.cli.main import cli
from rockcli.records.files import read_record
from rockcli.records.periods import ROUND_PERIODS, default_periods
from rockcli.terminal.spectrum import spectrum_report
from rockcli.terminal.table import render
from rockcli.units import DEFAULT_GRAVITY

RECORDS = Path(__file__).resolve().parents[2] / "records"
ONE_SINE = RECORDS / "one-sine_Tp1s_0.35g.txt"  # PGA 0.35 g, starts at 0 (its header)
ONE_COSINE = RECORDS / "one-cosine_Tp2s_0.31g.txt"  # starts at its PGA, 0.31 g (its header)
RICKER = RECORDS / "ricker_Tp0.5s_0.5g.txt"
#: The keys of each record of the JSON document (the command's fixed contract).
RECORD_KEYS = {"name", "damping", "periods", "Sa_g", "Sd_m"}


def run(*args: str) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of `rock record spectrum ARGS`."""
    result = CliRunner().invoke(cli, ["record", "spectrum", *args])
    return result.exit_code, result.stdout, result.stderr


def spectra(*args: str) -> list[dict]:
    """The records of the JSON document of `rock record spectrum ARGS --format json`."""
    code, out, err = run(*args, "--format", "json")
    assert code == 0, err
    return json.loads(out)["records"]


def harmonic_file(path: Path, amplitude: float, period: float, dt: float, duration: float) -> Path:
    """A plain-text record [g] of a_g = amplitude·sin(2πt/period), from rest at t = 0."""
    t = np.arange(round(duration / dt) + 1) * dt
    a = amplitude * np.sin(2 * math.pi * t / period)
    path.write_text(
        "".join(f"{ti!r} {ai!r}\n" for ti, ai in zip(t.tolist(), a.tolist(), strict=True))
    )
    return path


# --- against closed forms ------------------------------------------------------------------------


def test_resonance_is_the_steady_state_amplitude(tmp_path: Path) -> None:
    """Chopra §3.2: at ω = Ω the steady amplitude is u_st/(2ζ), u_st = A·g/ω², reached from rest
    as 1 − e^{−ζωt} (e^{−37.7} after 30 s at ζ = 0.1: nothing left).

    Tolerance 1e-4: the record is linear between samples, which shrinks a sine's amplitude by
    ≈ (ωdt)²/12 = 1.3e-5, and the peak is read at the samples, ≤ (ωdt)²/8 = 2.0e-5 low
    (ω = 4π rad/s, dt = 1 ms).
    """
    A, T, zeta = 0.2, 0.5, 0.1
    rec = harmonic_file(tmp_path / "harmonic.txt", A, T, dt=0.001, duration=30.0)
    (spec,) = spectra(str(rec), "--periods", str(T), "--damping", str(zeta))
    w = 2 * math.pi / T
    assert spec["Sd_m"][0] == pytest.approx(A * DEFAULT_GRAVITY / w**2 / (2 * zeta), rel=1e-4)
    assert spec["Sa_g"][0] == pytest.approx(A / (2 * zeta), rel=1e-4)
    assert spec["damping"] == zeta


def test_shortest_default_period_is_the_pga() -> None:
    """A stiff oscillator follows the ground: Sa(0.01 s) = PGA (0.35 g, the record's header).

    Tolerance 2e-4: its lag behind a 1 s pulse is of order (T/Tp)² = 1e-4.
    """
    (spec,) = spectra(str(ONE_SINE))
    assert spec["periods"][0] == 0.01
    assert spec["Sa_g"][0] == pytest.approx(0.35, rel=2e-4)


def test_record_starting_off_zero_overshoots_at_short_periods() -> None:
    """The one-cosine pulse starts at 0.31 g: a force applied suddenly on an oscillator at
    rest, whose peak is u_st·(1 + e^{−πζ/√(1−ζ²)}) (Chopra §4.3) = 1.8545·0.31 g at ζ = 5 %.

    Tolerance 1e-3: the pulse falls by 1 − cos(π·0.005) = 1.2e-4 of 0.31 g over the half period
    (5 ms) in which a 0.01 s oscillator reaches that peak.
    """
    zeta = 0.05
    overshoot = 1 + math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2))
    (spec,) = spectra(str(ONE_COSINE), "--periods", "0.01")
    assert spec["Sa_g"][0] == pytest.approx(overshoot * 0.31, rel=1e-3)
    code, out, _ = run(str(ONE_COSINE), "--periods", "0.01")
    assert code == 0
    # The note wraps at the output's width (100 columns), at a space.
    assert "starts at 0.31 g, a step from rest that stiff oscillators overshoot" in " ".join(
        out.split()
    )
    assert f"Sa → {overshoot * 0.31:.4g} g as T → 0" in out


def test_sa_is_omega_squared_sd() -> None:
    """Sa = ω²·Sd/g, ω = 2π/T (the definition the help states); to rounding, 1e-12."""
    for spec in spectra(str(ONE_SINE), str(RICKER)):
        for T, Sa, Sd in zip(spec["periods"], spec["Sa_g"], spec["Sd_m"], strict=True):
            assert Sa == pytest.approx((2 * math.pi / T) ** 2 * Sd / DEFAULT_GRAVITY, rel=1e-12)


def test_scale_and_pga_scale_the_spectrum() -> None:
    """The oscillator is linear: twice the record, twice Sa and Sd (to rounding, 1e-12);
    --pga 0.7 on a 0.35 g record is --scale 2."""
    (base,) = spectra(str(ONE_SINE), "--periods", "0.1,1,3")
    for option in (("--scale", "2"), ("--pga", "0.7")):
        (scaled,) = spectra(str(ONE_SINE), "--periods", "0.1,1,3", *option)
        for key in ("Sa_g", "Sd_m"):
            assert scaled[key] == pytest.approx([2 * x for x in base[key]], rel=1e-12)


# --- the outputs ---------------------------------------------------------------------------------


def test_json_contract() -> None:
    records = spectra(str(ONE_SINE), str(RICKER))
    assert [r["name"] for r in records] == ["one-sine_Tp1s_0.35g", "ricker_Tp0.5s_0.5g"]
    grid = default_periods().tolist()
    for rec in records:
        assert set(rec) == RECORD_KEYS
        assert rec["damping"] == 0.05 and rec["periods"] == grid
        assert len(rec["Sa_g"]) == len(rec["Sd_m"]) == len(grid)


def test_default_grid() -> None:
    """100 log-spaced periods 0.01–4 s and the round ones, sorted without repeats."""
    grid = default_periods()
    assert grid[0] == 0.01 and grid[-1] == 4.0
    assert set(ROUND_PERIODS) <= set(grid.tolist())
    assert np.all(np.diff(grid) > 0) and grid.size == 100 + len(ROUND_PERIODS)


def test_csv_header_and_rows() -> None:
    code, out, _ = run(str(ONE_SINE), str(RICKER), "--periods", "0.1,1", "--format", "csv")
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == (
        "period_s,one-sine_Tp1s_0.35g_Sa_g,one-sine_Tp1s_0.35g_Sd_m,"
        "ricker_Tp0.5s_0.5g_Sa_g,ricker_Tp0.5s_0.5g_Sd_m"
    )
    one, ricker = spectra(str(ONE_SINE), str(RICKER), "--periods", "0.1,1")
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    assert rows == [
        [T, one["Sa_g"][i], one["Sd_m"][i], ricker["Sa_g"][i], ricker["Sd_m"][i]]
        for i, T in enumerate([0.1, 1.0])
    ]  # full precision: the CSV's numbers are the JSON's


def test_repeated_name_gets_a_suffix() -> None:
    records = spectra(str(ONE_SINE), str(ONE_SINE), "--periods", "1")
    assert [r["name"] for r in records] == ["one-sine_Tp1s_0.35g", "one-sine_Tp1s_0.35g#2"]


def test_table_of_three_records_fits_100_columns() -> None:
    files = (ONE_COSINE, ONE_SINE, RICKER)
    records = [read_record(str(f)) for f in files]
    doc = {"records": spectra(*map(str, files))}
    console = Console(width=100, record=True, color_system=None, file=io.StringIO())
    render(spectrum_report(doc, records), console)
    text = console.export_text()
    tables = [line for line in text.splitlines() if line[:1] in "┏┃┡│└"]
    assert tables and max(len(line) for line in tables) <= 100
    assert "Pseudo-acceleration Sa [g], damping 0.05 of critical" in text
    assert "Displacement Sd [m], damping 0.05 of critical" in text


def test_plot_is_a_png(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    path = tmp_path / "sa.png"
    code, _, err = run(str(ONE_SINE), str(RICKER), "--plot", str(path), "--format", "csv")
    assert code == 0 and err == f"wrote {path}\n"
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"  # the PNG signature (RFC 2083)


# --- bad input: one line naming the option, exit 2 -----------------------------------------------


@pytest.mark.parametrize("damping", ["0", "1", "-0.05", "1.5", "nan"])
def test_damping_out_of_range(damping: str) -> None:
    code, out, err = run(str(ONE_SINE), "--damping", damping)
    assert code == 2 and out == ""
    assert err.startswith("error: --damping: out of range (got ")
    assert err.endswith("allowed: a fraction of critical, 0 < ζ < 1 (0.05 = 5 %))\n")


@pytest.mark.parametrize("periods", ["", " ", "0", "-1", "abc", "0.1,,0.2", "1:2", "4:0.05:10",
                                     "0.05:4:1", "0.05:4:x", "inf", "1000"])  # fmt: skip
def test_bad_periods(periods: str) -> None:
    code, out, err = run(str(ONE_SINE), "--periods", periods)
    assert code == 2 and out == ""
    assert err.startswith("error: --periods: ") and err.count("\n") == 1
    assert f"(got {periods!r}; allowed: periods in seconds, 0.001 to 100" in err


def test_file_that_does_not_read(write_file: Callable[[str, str], Path]) -> None:
    path = write_file("bad.txt", "0 0.1\n0.01 abc\n")
    code, out, err = run(str(path))
    assert code == 2 and out == ""
    assert err.startswith(f"error: {path}: line 2") and err.count("\n") == 1


def test_more_records_than_a_table_shows() -> None:
    code, out, err = run(*[str(ONE_SINE)] * 4)
    assert (code, out) == (2, "")
    assert err == (
        "error: --format: 4 records do not fit in a table (got 'table'; "
        "allowed: --format table with up to 3 files, or --format json|csv)\n"
    )


def test_scale_with_pga_is_refused() -> None:
    code, _, err = run(str(ONE_SINE), "--scale", "2", "--pga", "0.5")
    assert code == 2 and err.startswith("error: --scale: conflicts with --pga")


def test_plot_is_an_svg_with_the_mean(tmp_path: Path) -> None:
    """One line per record and, with two, their mean (its label in the SVG's legend)."""
    pytest.importorskip("matplotlib")
    path = tmp_path / "sa.svg"
    code, _, _ = run(str(ONE_SINE), str(RICKER), "--plot", str(path), "--format", "json")
    text = path.read_text(encoding="utf-8")
    assert code == 0 and text.startswith("<?xml") and "<svg" in text
    assert "mean of 2" in text and "ricker_Tp0.5s_0.5g" in text
