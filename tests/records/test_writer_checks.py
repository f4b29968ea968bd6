"""A writer checks what the reader checks (issue 20, item 9).

On main `rock record floor --T1 1e300` wrote 3 999 `nan` samples, `--gamma 1000` a 932 g
record, `rock record convert --resample 100` one sample and `--resample 1e308` dt = 1e308:
files that `rock record info` then refused. Every record written now passes the readers' own
checks first (:func:`rockcli.records.lines.check_record`, through
:func:`rockcli.records.files.check_to_write`), and the options have the bounds of their model
counterparts, so a refusal names the option.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.records.files import read_record, write_plain
from rockcli.records.lines import MIN_RECORD_SAMPLES
from rockcli.records.record import Record

ROOT = Path(__file__).resolve().parents[2]
PULSE = str(ROOT / "records" / "one-sine_Tp1s_0.35g.txt")

#: Values of the fuzzed options: ordinary ones, the bounds' neighbourhoods, the extremes.
NUMBERS = st.sampled_from(
    ["0.005", "0.01", "0.3", "1", "1.5", "3", "10", "100", "1000", "1e300", "1e-300", "5e-324",
     "-1", "0", "nan", "inf"]
)  # fmt: skip


def invoke(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.output


def reads_back(text: str, folder: Path) -> None:
    """What a writer gave with exit 0 is read by `rock record info` with exit 0."""
    path = folder / "written.txt"
    path.write_text(text, encoding="utf-8")
    code, output = invoke("record", "info", str(path))
    assert code == 0, output


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(t1=NUMBERS, psi=NUMBERS, gamma=NUMBERS, xi=st.sampled_from(["0", "0.05", "0.5", "0.99"]))
def test_what_record_floor_writes_reads_back(
    tmp_path_factory: pytest.TempPathFactory, t1: str, psi: str, gamma: str, xi: str
) -> None:
    args = ["--T1", t1, "--psi", psi, "--gamma", gamma, "--xi", xi]
    result = CliRunner().invoke(cli, ["record", "floor", PULSE, *args, "-o", "-"])
    assert result.exit_code in (0, 2), result.output
    if result.exit_code == 0:
        reads_back(result.stdout, tmp_path_factory.mktemp("floor"))
    else:
        assert result.stderr.startswith("error: --") and result.stderr.count("\n") == 1


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    resample=st.one_of(st.none(), NUMBERS),
    scale=st.one_of(st.none(), NUMBERS),
    trim=st.one_of(st.none(), st.sampled_from(["0,3", "0,0.01", "0.5,1", "2.99,3", "0,1e300"])),
)
def test_what_record_convert_writes_reads_back(
    tmp_path_factory: pytest.TempPathFactory, resample: str | None, scale: str | None,
    trim: str | None,
) -> None:  # fmt: skip
    options = {"--resample": resample, "--scale": scale, "--trim": trim}
    args = [x for option, value in options.items() if value is not None for x in (option, value)]
    result = CliRunner().invoke(cli, ["record", "convert", PULSE, *args, "-o", "-"])
    assert result.exit_code in (0, 2), result.output
    if result.exit_code == 0:
        reads_back(result.stdout, tmp_path_factory.mktemp("convert"))
    else:
        assert result.stderr.startswith("error: ") and result.stderr.count("\n") == 1


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    kind=st.sampled_from(["rectangular", "half-sine", "one-sine", "one-cosine", "ricker"]),
    amplitude=NUMBERS,
    period=NUMBERS,
    dt=st.sampled_from(["0.005", "0.02", "1", "2", "1e-300", "1e300", "nan"]),
    duration=st.one_of(st.none(), NUMBERS),
)
def test_what_record_pulse_writes_reads_back(
    tmp_path_factory: pytest.TempPathFactory, kind: str, amplitude: str, period: str, dt: str,
    duration: str | None,
) -> None:  # fmt: skip
    args = ["--amplitude", amplitude, "--period", period, "--dt", dt]
    args += [] if duration is None else ["--duration", duration]
    result = CliRunner().invoke(cli, ["record", "pulse", kind, *args, "-o", "-"])
    assert result.exit_code in (0, 2), result.output
    if result.exit_code == 0:
        reads_back(result.stdout, tmp_path_factory.mktemp("pulse"))
    else:
        assert result.stderr.startswith("error: --") and result.stderr.count("\n") == 1


def test_a_resonant_floor_motion_beyond_100_g_is_not_written(tmp_path: Path) -> None:
    # Within every option's bounds the floor motion can still leave the readers' range: a
    # 3 g sine at the building's own period (T1 = 0.5 s), undamped (ξ = 0), for 20 s grows
    # linearly, ẍ₁ reaching about π·(20 s / 0.5 s)·3 g ≈ 377 g (the undamped resonance
    # envelope π·n·a of n cycles), times γ·ψ = 4.5: far beyond 100 g. On main it was written.
    ground = tmp_path / "sine.txt"
    t = np.arange(0.0, 20.0, 0.005)
    ground.write_text("".join(f"{x:.3f} {3.0 * math.sin(2 * math.pi * x / 0.5)!r}\n" for x in t))
    out = tmp_path / "floor.txt"
    code, output = invoke("record", "floor", str(ground), "--T1", "0.5", "--psi", "1.5",
                          "--gamma", "3", "--xi", "0", "-o", str(out))  # fmt: skip
    assert code == 2, output
    assert output.startswith(
        "error: --T1, --psi, --gamma, --xi: the record it makes would not be a valid record: "
        "acceleration beyond 100 g at sample "
    )
    assert not out.exists()


def test_a_resampling_that_leaves_one_sample_is_refused(tmp_path: Path) -> None:
    # A 0.5 s window resampled at 0.9 s (within dt's bounds) has one sample: on main it was
    # written and `rock record info` refused it ("needs at least 2 samples").
    out = tmp_path / "c.txt"
    code, output = invoke("record", "convert", PULSE, "--trim", "0,0.5", "--resample", "0.9",
                          "-o", str(out))  # fmt: skip
    assert code == 2 and output.startswith(f"error: {PULSE}: --resample: resampling at dt = 0.9")
    assert not out.exists()


@pytest.mark.parametrize(
    ("change", "problem"),
    [
        ({"accel": np.array([0.1, math.nan, 0.2])}, "acceleration beyond 100 g at sample 2"),
        ({"accel": np.array([0.1, 932.0, 0.2])}, "acceleration beyond 100 g at sample 2"),
        ({"time": np.array([0.0]), "accel": np.array([0.1])}, "1 sample(s)"),
        ({"dt": 1e308}, "the time step is implausibly large"),
        ({"time": np.array([0.0, 0.01, 0.01])}, "time does not increase"),
    ],
    ids=["nan", "932 g", "one sample", "dt 1e308", "time not increasing"],
)
def test_write_plain_refuses_what_the_readers_refuse(
    tmp_path: Path, change: dict[str, object], problem: str
) -> None:
    from dataclasses import replace

    base = Record("r", "generated", "pulse", np.array([0.0, 0.01, 0.02]),
                  np.array([0.1, -0.3, 0.2]), 0.01)  # fmt: skip
    write_plain(base, tmp_path / "base.txt")  # the record as it is passes
    record = replace(base, **change)
    with pytest.raises(InputError) as caught:
        write_plain(record, tmp_path / "x.txt", made_by="--option")
    assert caught.value.where == "--option" and problem in caught.value.problem
    assert not (tmp_path / "x.txt").exists()


def test_a_record_of_one_sample_is_refused_on_reading(tmp_path: Path) -> None:
    # The same check on the reading side: one sample is no motion (on main it was read, and
    # `rock record spectrum` then refused it).
    path = tmp_path / "one.txt"
    path.write_text("0.1\n")
    with pytest.raises(InputError, match=f"a record needs at least {MIN_RECORD_SAMPLES}"):
        read_record(path, dt=0.01)
