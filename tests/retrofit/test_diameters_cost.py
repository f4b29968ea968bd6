"""What `rock retrofit --diameters` costs (issue 34, F15): a capped list, and each further
diameter computing a few ordinates of the record's spectrum rather than all of them again.

The guard counts work, not time: the ordinates the response spectrum computes
(rockcli.codecheck.response.response_spectrum, the compiled oscillator) and the array reads of
the record's spectrum (RecordSpectrum._values: every ordinate not already cached). Since the
2019 demand of a record became the maximum of its spectrum over [T0, T_SLV] (Circ. 7/2019
§C8.7.1.2.1.8; rockcli.codecheck.demand.range_maximum), each check reads a few hundred
ordinates on an absolute period grid. Each candidate made its own spectrum and computed them
all again (about 600 ordinates and 1000 to 7500 array reads per diameter, 15 times the time);
one spectrum shared by the candidates computes only those of each candidate's golden-section
search and its range's ends (a few dozen).
"""

from __future__ import annotations

from collections import OrderedDict
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.analyses.choices import Analyses
from rockcli.cli.main import cli
from rockcli.codecheck import response
from rockcli.codecheck.response import RecordSpectrum
from rockcli.errors import InputError
from rockcli.model.load import read_toml, validate_model
from rockcli.records import files
from rockcli.studies.parallel.executor import local_executor
from rockcli.studies.retrofit import run as retrofit_run
from rockcli.studies.retrofit.candidates import MAX_DIAMETERS, make_plan, parse_diameters
from rockcli.studies.retrofit.run import run_retrofit, shared_spectrum
from tests.cli.conftest import ROOT

FACADE = ROOT / "examples" / "facade.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: The most ordinates (and array reads) a further diameter may add: a golden-section search
#: to 1e-5 s in a 0.02 s bracket takes about 18, for the SLV and the SLC check each, and the
#: ends of their ranges; the grid's own ordinates (a few hundred) are the first candidate's.
PER_DIAMETER = 60


# --- the cap ---------------------------------------------------------------------------------


def test_at_most_max_diameters() -> None:
    sizes = ",".join(f"{10 + 0.01 * i:g}" for i in range(MAX_DIAMETERS))
    assert len(parse_diameters(sizes)) == MAX_DIAMETERS
    with pytest.raises(InputError) as info:
        parse_diameters(sizes + ",50")
    assert (info.value.where, info.value.problem) == ("--diameters", "too many diameters: 1001")
    assert info.value.value is None  # the list itself is not echoed


def test_the_help_says_the_cap() -> None:
    result = CliRunner().invoke(cli, ["retrofit", "--help"], terminal_width=200)
    assert f"Diameters to try [mm], at most {MAX_DIAMETERS} [default:" in result.stdout


def test_too_many_diameters_is_one_line_and_exit_2() -> None:
    sizes = ",".join(["16"] * (MAX_DIAMETERS + 1))
    result = CliRunner().invoke(
        cli, ["retrofit", str(FACADE), "--record", str(RICKER), "--diameters", sizes]
    )
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr == (
        "error: --diameters: too many diameters: 1001 (allowed: at most 1000 diameters)\n"
    )


# --- the work per diameter -------------------------------------------------------------------


def work(
    monkeypatch: pytest.MonkeyPatch, model: str, diameters: tuple[float, ...]
) -> dict[str, int]:
    """The ordinates computed and the array reads of the record's spectrum while the
    candidates run in this process, from no spectrum kept."""
    counts = {"ordinates": 0, "reads": 0}
    compute, read = response.response_spectrum, RecordSpectrum._values

    def computing(time: Any, accel: Any, periods: Any, *args: Any, **kwargs: Any) -> Any:
        counts["ordinates"] += len(periods)
        return compute(time, accel, periods, *args, **kwargs)

    def reading(self: RecordSpectrum, *args: Any) -> Any:
        counts["reads"] += 1
        return read(self, *args)

    table = read_toml(model)
    plan = make_plan(table, validate_model(table), diameters_mm=diameters)
    with monkeypatch.context() as patch, local_executor(1) as lanes:
        patch.setattr(response, "response_spectrum", computing)
        patch.setattr(RecordSpectrum, "_values", reading)
        patch.setattr(retrofit_run, "_spectra", OrderedDict())
        run_retrofit(plan, files.read_record(str(RICKER)), lanes, Analyses())
    return counts


@pytest.mark.parametrize(
    "model",
    [FACADE, ROOT / "examples" / "two-storey-facade.toml"],
    ids=["block on the ground", "wall, its storey on the floor motion"],
)
def test_a_further_diameter_computes_a_few_ordinates(
    monkeypatch: pytest.MonkeyPatch, model: Any
) -> None:
    one = work(monkeypatch, str(model), (12.0,))
    five = work(monkeypatch, str(model), (12.0, 13.0, 14.0, 15.0, 16.0))
    assert one["ordinates"] > 10 * PER_DIAMETER  # the grid over [T0, T_SLV]: what is shared
    for what in ("ordinates", "reads"):
        assert (five[what] - one[what]) / 4 <= PER_DIAMETER, (what, one, five)


def test_one_spectrum_per_record_and_gravity(monkeypatch: pytest.MonkeyPatch) -> None:
    # A worker process gets a new copy of the record with every chunk: the key is its samples.
    monkeypatch.setattr(retrofit_run, "_spectra", OrderedDict())
    record = files.read_record(str(RICKER))
    copy = files.read_record(str(RICKER))
    assert copy is not record
    spectrum = shared_spectrum(record, 9.81)
    assert shared_spectrum(copy, 9.81) is spectrum
    assert spectrum.g == 9.81
    assert shared_spectrum(record, 9.80) is not spectrum
    for k in range(retrofit_run.SPECTRA_KEPT + 2):  # a few kept, the oldest dropped
        shared_spectrum(record, 9.0 + 0.1 * k)
    assert len(retrofit_run._spectra) == retrofit_run.SPECTRA_KEPT
