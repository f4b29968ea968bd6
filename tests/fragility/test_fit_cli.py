"""`rock fragility fit DATA.csv`: its JSON contract, and each bad input as one line, exit 2.

The numbers are the fits' own (tests/fragility/test_fit.py checks those against independent
computations); here the command must give them, and refuse what defines no fragility."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.studies.fragility.data import read_data
from rockcli.studies.fragility.fit import ida_fit, msa_fit

ROOT = Path(__file__).resolve().parents[2]
MSA = ROOT / "examples" / "fragility" / "msa.csv"
IDA = ROOT / "examples" / "fragility" / "ida.csv"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["fragility", "fit", *args])
    return result.exit_code, result.stdout, result.stderr


def test_msa_json_is_the_contract() -> None:
    code, out, _ = run(str(MSA), "--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert {"method", "im", "damage_states", "records"} <= set(doc) and doc["method"] == "msa"
    state = doc["damage_states"][0]
    assert {"name", "level", "median", "beta", "beta_ddof", "n_records", "n_runs", "ci"} <= set(
        state
    )
    data = read_data(str(MSA), "msa")
    fit = msa_fit(data.im, data.runs, data.exceedances)
    assert state["median"] == fit.median and state["beta"] == fit.beta
    assert state["beta_ddof"] is None and state["n_runs"] == 140
    assert len(state["ci"]) == len(state["ci_im"]) == 7
    assert all(lo <= p <= hi for (lo, hi), p in zip(state["ci"], state["probability"],
                                                    strict=True))  # fmt: skip


@pytest.mark.parametrize("ddof", ["0", "1"])
def test_ida_json_says_its_divisor(ddof: str) -> None:
    code, out, _ = run(str(IDA), "--method", "ida", "--ddof", ddof, "--format", "json")
    assert code == 0
    state = json.loads(out)["damage_states"][0]
    fit = ida_fit(read_data(str(IDA), "ida").im, int(ddof))
    assert state["beta_ddof"] == int(ddof) and state["beta"] == fit.beta
    assert state["n_records"] == 10


def test_the_table_names_median_dispersion_and_band() -> None:
    code, out, _ = run(str(MSA))
    assert code == 0
    assert "median θ" in out and "dispersion β" in out and "95% band" in out


BAD = [
    ("im,runs\n0.1,20\n0.2,20\n", "no column 'exceedances'"),
    ("im,runs,exceedances\n0.1,20,0\n0.2,abc,1\n", "line 3: column runs"),
    ("im,runs,exceedances\n0.1,20,0\n-0.2,20,1\n", "line 3: column im"),
    ("im,runs,exceedances\n0.1,20,0\n0.2,20,21\n", "line 3: more exceedances than runs"),
    ("im,runs,exceedances\n0.1,20,0\n0.2,20,0\n", "every run exceeds, or none does"),
    ("im,runs,exceedances\n0.1,20,0\n", "fewer than two data rows"),
    ("im,runs,exceedances\n0.1,20,0\n0.2,20.5,1\n", "line 3: column runs"),
    ("", "no header row"),
]


@pytest.mark.parametrize(("text", "expected"), BAD, ids=[b[1] for b in BAD])
def test_bad_data_is_one_line_and_exit_2(tmp_path: Path, text: str, expected: str) -> None:
    path = tmp_path / "data.csv"
    path.write_text(text, encoding="utf-8")
    code, out, err = run(str(path))
    assert code == 2
    assert expected in err and len(err.strip().splitlines()) == 1 and str(path) in err


def test_a_missing_file_is_one_line_and_exit_2(tmp_path: Path) -> None:
    code, _, err = run(str(tmp_path / "nowhere.csv"))
    assert code == 2 and len(err.strip().splitlines()) == 1


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=st.text(alphabet="im,runsexcd0123456789.-e\n #", max_size=200),
       method=st.sampled_from(["msa", "ida"]))  # fmt: skip
def test_the_reader_reads_or_refuses_any_text(text: str, method: str) -> None:
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False, encoding="utf-8") as fh:
        fh.write(text)
    try:
        data = read_data(fh.name, method)
    except InputError:
        return
    finally:
        Path(fh.name).unlink()
    assert data.im.size >= 2 and np.all(np.isfinite(data.im)) and np.all(data.im > 0)
    if method == "msa":
        assert data.runs is not None and data.exceedances is not None
        assert np.all(data.exceedances <= data.runs) and np.all(data.runs >= 1)


def test_ida_with_censored_records_is_the_censored_fit(tmp_path: Path) -> None:
    """An IDA data set with a censored column: the fit is fit.ida_censored_fit's (itself
    tested against scipy's censored fit); the document counts the censored records."""
    from rockcli.studies.fragility.fit import ida_censored_fit

    data = tmp_path / "ida.csv"
    data.write_text("im,censored\n0.21,0\n0.34,0\n0.29,false\n0.45,0\n0.7,1\n0.7,true\n",
                    encoding="utf-8")  # fmt: skip
    code, out, _ = run(str(data), "--method", "ida", "--format", "json")
    assert code == 0
    state = json.loads(out)["damage_states"][0]
    fit = ida_censored_fit(np.array([0.21, 0.34, 0.29, 0.45]), np.array([0.7, 0.7]))
    assert (state["median"], state["beta"]) == (fit.median, fit.beta)
    assert (state["n_records"], state["not_reached"], state["beta_ddof"]) == (6, 2, 0)
    data.write_text("im,censored\n0.21,0\n0.34,maybe\n", encoding="utf-8")
    code, _, err = run(str(data), "--method", "ida")
    assert code == 2 and "line 3" in err and "censored" in err and err.count("\n") == 1
