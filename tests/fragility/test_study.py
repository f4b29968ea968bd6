"""`rock fragility STUDY.toml`: IDA and MSA end to end against Housner's closed form, the
intensity measures, resume, the JSON contract and each bad input as one line, exit 2.

The block and pulses are the casebook's (examples/validation/thresholds.toml, case
housner.rectangular-short): a linearized block R = 3 m, α = 0.2 rad, e = 0.9 under a
rectangular pulse of duration t1 overturns iff a/α ≥ 1/(1 − e^(−p·t1)) (Housner 1963, BSSA
53(2):403–417; derivation in docs/validation.md). The response to a single pulse is monotonic
in its amplitude (after the pulse the block rocks freely and only loses energy at impacts), so
each record's first exceedance of overturning in an IDA is that threshold. Tolerance: the
casebook's 1e-3 relative (a sample of the step down at dt = 1e-4 s) plus the bisection's 1e-4 g.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.studies.fragility.fit import ida_fit
from rockcli.studies.fragility.study import load_fragility

ALPHA, R, G = 0.2, 3.0, 9.81
P = math.sqrt(3.0 * G / (4.0 * R))  # Housner's p of a rectangular block, [rad/s]
DURATIONS = (0.32, 0.5)  # t1 [s] of the two records
DT = 1e-4
#: The casebook's tolerance (relative) and the bisection's (absolute, in g).
REL, BISECT = 1e-3, 1e-4

MODEL = f"""name = "Linearized block"
kind = "wall"
geometry = {{ R = {R}, alpha = {ALPHA} }}
restitution = {{ e = 0.9 }}
analysis = {{ linearized = true }}
"""


def threshold(t1: float) -> float:
    """Housner's overturning amplitude [g] of the rectangular pulse of duration t1."""
    return ALPHA / (1.0 - math.exp(-P * t1))


def study_text(method: str = "ida", measure: str = "pga", extra: str = "") -> str:
    body = f"""name = "Housner IDA"
model = "model.toml"
method = "{method}"

[intensity]
measure = "{measure}"

[[damage_states]]
level = 0.5

[[damage_states]]
level = "overturning"

[[records]]
path = "rect-0.32.txt"

[[records]]
path = "rect-0.5.txt"
"""
    if method == "ida":
        scan = {"pga": (0.2, 0.05, 1.0), "pgv": (0.2, 0.05, 3.0)}.get(measure, (0.5, 0.25, 5.0))
        tol = BISECT if measure == "pga" else 1e-4
        body += (
            f"\n[ida]\nfirst = {scan[0]}\nstep = {scan[1]}\nlast = {scan[2]}\ntolerance = {tol}\n"
        )
    return body + extra


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A study folder: the model, the two pulses (written by `rock record pulse`)."""
    here = tmp_path_factory.mktemp("fragility")
    (here / "model.toml").write_text(MODEL, encoding="utf-8")
    for t1 in DURATIONS:
        out = here / f"rect-{t1:g}.txt"
        args = ["record", "pulse", "rectangular", "--amplitude", "1", "--period", str(t1),
                "--dt", str(DT), "-o", str(out)]  # fmt: skip
        assert CliRunner().invoke(cli, args).exit_code == 0
    return here


def run(folder: Path, text: str, *args: str, name: str = "study.toml") -> tuple[int, str, str]:
    (folder / name).write_text(text, encoding="utf-8")
    result = CliRunner().invoke(
        cli, ["fragility", str(folder / name), "--format", "json", "--no-progress", *args]
    )
    return result.exit_code, result.stdout, result.stderr


def test_ida_finds_housners_thresholds_and_fits_them(folder: Path, tmp_path: Path) -> None:
    code, out, err = run(folder, study_text(), "--out", str(tmp_path / "o"), "--jobs", "1")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["method"] == "ida" and doc["im"] == "pga" and doc["scan_step"] == 0.05
    found = [r["first_exceedance"]["overturning"] for r in doc["records"]]
    for x, t1 in zip(found, DURATIONS, strict=True):
        assert x == pytest.approx(threshold(t1), rel=REL, abs=BISECT)
    over = doc["damage_states"][1]
    assert over["level"] == "overturning" and over["n_records"] == 2 and over["beta_ddof"] == 0
    # The fit is the lognormal of the two found intensities (numpy, by hand).
    logs = np.log(found)
    assert over["median"] == pytest.approx(math.exp(logs.mean()), rel=1e-12)
    assert over["beta"] == pytest.approx(logs.std(), rel=1e-12)
    # θ/α ≥ 0.5 is reached no later than the overturning.
    for r in doc["records"]:
        assert r["first_exceedance"]["θ/α ≥ 0.5"] <= r["first_exceedance"]["overturning"]
    assert {"name", "level", "median", "beta", "beta_ddof", "n_records", "n_runs", "ci"} <= set(
        over
    )
    assert over["band_method"].startswith("exact for a lognormal (noncentral t")


def test_pgv_scales_the_same_runs(folder: Path, tmp_path: Path) -> None:
    """PGV of a rectangular pulse is a·g·t1 (the velocity at its end): the first exceedance
    in PGV is the PGA threshold × g·t1 (tolerance: the casebook's, the trapezoid is exact for
    the step, and the bisection's 1e-4 m/s)."""
    code, out, err = run(folder, study_text(measure="pgv"), "--out", str(tmp_path / "v"))
    assert code == 0, err
    doc = json.loads(out)
    for r, t1 in zip(doc["records"], DURATIONS, strict=True):
        pgv = r["first_exceedance"]["overturning"]
        assert pgv == pytest.approx(threshold(t1) * G * t1, rel=REL, abs=1e-4)
        # The sampled pulse steps down over one sample: its trapezoid ends dt/2 short.
        assert r["im_at_scale_1"] == pytest.approx(G * (t1 - DT / 2), rel=1e-9)


def test_dimensionless_pga_is_pga_over_tan_alpha(folder: Path, tmp_path: Path) -> None:
    """PGA/(g·tan α): the linearized block uplifts at a = α·g (tan α in the full equation):
    its uplift acceleration is the block's own (rockcli.mechanics)."""
    code, out, err = run(folder, study_text(measure="pga-ratio"), "--out", str(tmp_path / "r"))
    assert code == 0, err
    doc = json.loads(out)
    for r, t1 in zip(doc["records"], DURATIONS, strict=True):
        x = r["first_exceedance"]["overturning"]
        assert x == pytest.approx(1.0 / (1.0 - math.exp(-P * t1)), rel=REL, abs=1e-4 / ALPHA)


def test_msa_counts_follow_the_thresholds(folder: Path, tmp_path: Path) -> None:
    """Levels below both thresholds, between them (twice), above both: 0, 1, 1, 2 overturn,
    and the binomial maximum likelihood fits them."""
    lo, hi = sorted(threshold(t1) for t1 in DURATIONS)
    levels = [0.9 * lo, lo + (hi - lo) / 3, lo + 2 * (hi - lo) / 3, 1.1 * hi]
    text = study_text("msa") + f"\n[msa]\nlevels = {levels}\n"
    code, out, err = run(folder, text, "--out", str(tmp_path / "m"))
    assert code == 0, err
    doc = json.loads(out)
    over = doc["damage_states"][1]
    assert [s["exceedances"] for s in over["stripes"]] == [0, 1, 1, 2]
    assert [s["runs"] for s in over["stripes"]] == [2, 2, 2, 2]
    assert over["beta_ddof"] is None and doc["levels"] == levels
    assert over["band_method"].startswith("profile likelihood of the binomial counts")
    assert lo < over["median"] < hi and over["beta"] > 0


def test_msa_counts_that_jump_from_none_to_all_are_no_fit(folder: Path, tmp_path: Path) -> None:
    """0, 1, 2 of 2 overturn at three levels: the binomial likelihood grows without bound
    towards a step at the middle level (β → 0), so no lognormal fits: the state says so and
    has no median (the search once stopped wherever it ran out, at some β of 0.05)."""
    lo, hi = sorted(threshold(t1) for t1 in DURATIONS)
    levels = [0.9 * lo, 0.5 * (lo + hi), 1.1 * hi]
    text = study_text("msa") + f"\n[msa]\nlevels = {levels}\n"
    code, out, err = run(folder, text, "--out", str(tmp_path / "m"))
    assert code == 0, err
    over = json.loads(out)["damage_states"][1]
    assert [s["exceedances"] for s in over["stripes"]] == [0, 1, 2]
    assert over["median"] is None and over["ci"] == [] and "step" in over["note"]


def test_resume_computes_only_what_is_missing(folder: Path, tmp_path: Path) -> None:
    out = tmp_path / "res"
    code, first, err = run(folder, study_text(), "--out", str(out))
    assert code == 0, err
    whole = json.loads(first)
    # Again into the same folder, complete: it runs again, as a sweep does (one folder
    # machinery, rockcli.studies.folder), to the same bytes.
    before = (out / "cases.csv").read_bytes()
    code, _, err = run(folder, study_text(), "--out", str(out))
    assert code == 0, err
    assert (out / "cases.csv").read_bytes() == before
    # The second record's lines lost (an interruption), and the last line cut in the middle.
    cases = out / "cases.csv"
    lines = cases.read_text(encoding="utf-8").splitlines(keepends=True)
    kept = [ln for ln in lines if not ln.startswith("1,")]
    cases.write_text("".join(kept) + kept[-1][:7], encoding="utf-8")
    (out / "fragility.json").unlink()
    code, again, err = run(folder, study_text(), "--out", str(out), "--resume")
    assert code == 0, err
    doc = json.loads(again)
    assert doc["run"]["resumed_runs"] == len(kept) - 1
    assert 0 < doc["run"]["computed_runs"] == whole["run"]["computed_runs"] - len(kept) + 1
    assert doc["damage_states"] == whole["damage_states"]
    assert doc["records"] == whole["records"]
    # Another study into that folder is refused.
    code, _, err = run(folder, study_text(measure="pgv"), "--out", str(out), "--resume")
    assert code == 2 and "another study" in err


def test_jobs_two_gives_the_same_fragility(folder: Path, tmp_path: Path) -> None:
    code, one, err = run(folder, study_text(), "--out", str(tmp_path / "j1"), "--jobs", "1")
    assert code == 0, err
    code, two, err = run(folder, study_text(), "--out", str(tmp_path / "j2"), "--jobs", "2")
    assert code == 0, err
    assert json.loads(one)["damage_states"] == json.loads(two)["damage_states"]
    assert (tmp_path / "j1" / "cases.csv").read_bytes() == (
        tmp_path / "j2" / "cases.csv"
    ).read_bytes()


def test_a_record_without_the_measure_is_refused(folder: Path, tmp_path: Path) -> None:
    """A record of zeros has no PGA to scale: every record fails, exit 2, one line."""
    (folder / "zeros.txt").write_text("0 0\n0.01 0\n0.02 0\n0.03 0\n0.04 0\n", encoding="utf-8")
    text = (
        study_text()
        .replace("rect-0.32.txt", "zeros.txt")
        .replace('[[records]]\npath = "rect-0.5.txt"\n', "")
    )
    code, _, err = run(folder, text, "--out", str(tmp_path / "z"), name="zeros.toml")
    assert code == 2, err
    assert err.count("\n") == 1 and "gives no PGA" in err


@pytest.mark.parametrize(
    ("change", "where"),
    [
        (('level = "overturning"', "level = 0.3"), "damage_states[1].level"),  # out of order
        (("level = 0.5", "level = -1.0"), "damage_states[0].level"),
        (("last = 1.0", "last = 0.1"), "ida.last"),  # an empty scan
        (("first = 0.2", "first = 0.0"), "ida.first"),  # non-positive
        (("step = 0.05", "step = -0.05"), "ida.step"),
        (('measure = "pga"', 'measure = "sa"\nperiod = 500.0'), "intensity.period"),
        (('measure = "pga"', 'measure = "sa"'), "intensity.period"),  # no period
        (('measure = "pga"', 'measure = "pga"\nperiod = 1.0'), "intensity.period"),
        (('measure = "pga"', 'measure = "arias"'), "intensity.measure"),
        (('method = "ida"', 'method = "ida"\ncolour = 1'), "colour"),
        (('model = "model.toml"', 'model = "absent.toml"'), "model"),
        (('path = "rect-0.5.txt"', 'path = "absent.txt"'), "records[1].path"),
    ],
)
def test_bad_studies_are_one_line(
    folder: Path, tmp_path: Path, change: tuple[str, str], where: str
) -> None:
    text = study_text().replace(*change, 1)
    assert text != study_text()
    code, out, err = run(folder, text, "--out", str(tmp_path / "bad"), name="bad.toml")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("error: ") and where in err, err


def test_msa_needs_increasing_levels(folder: Path, tmp_path: Path) -> None:
    text = study_text("msa") + "\n[msa]\nlevels = [0.3, 0.2]\n"
    code, _, err = run(folder, text, "--out", str(tmp_path / "l"), name="l.toml")
    assert code == 2 and "msa.levels[1]" in err and err.count("\n") == 1


def test_ida_fit_matches_scipy_on_the_study_data(folder: Path, tmp_path: Path) -> None:
    """The fit the study reports is rockcli.studies.fragility.fit's (tested against scipy there)."""
    code, out, _ = run(folder, study_text(), "--out", str(tmp_path / "f"))
    doc = json.loads(out)
    over = doc["damage_states"][1]
    fit = ida_fit(np.array(over["collapse_im"]))
    assert (fit.median, fit.beta) == (over["median"], over["beta"])


_TOP = st.sampled_from(["model", "method", "intensity", "damage_states", "ida", "msa", "x"])
_VALUES = st.recursive(
    st.none() | st.booleans() | st.floats(allow_nan=True) | st.integers() | st.text(max_size=8),
    lambda inner: (
        st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=6), inner, max_size=3)
    ),
    max_leaves=8,
)


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(data=st.dictionaries(_TOP, _VALUES, max_size=6))
def test_reader_never_fails_otherwise(folder: Path, data: dict[str, object]) -> None:
    """Whatever the study table holds, the reader gives a plan or one InputError."""
    import tomli_w

    base = {"model": "model.toml", "method": "ida", "intensity": {"measure": "pga"},
            "damage_states": [{"level": "overturning"}], "records": [{"path": "rect-0.5.txt"}],
            "ida": {"first": 0.1, "step": 0.1, "last": 1.0}}  # fmt: skip
    base.update({k: v for k, v in data.items() if v is not None})
    try:
        text = tomli_w.dumps(base)
    except (TypeError, ValueError):
        return
    path = folder / "fuzz.toml"
    path.write_text(text, encoding="utf-8")
    try:
        load_fragility(str(path))
    except InputError:
        pass


def test_sa_at_the_blocks_own_period(folder: Path, tmp_path: Path) -> None:
    """Sa(2π/p): the record's 5 %-damped Sa at the rocked block's 2π/p (rockcli.studies.fragility
    .intensity, itself tested against closed forms), computed here independently of the study."""
    from rockcli.records.files import read_record
    from rockcli.studies.fragility.intensity import sa

    text = study_text(measure="sa").replace(
        'measure = "sa"', 'measure = "sa"\nperiod = "mechanism"'
    )
    code, out, err = run(folder, text, "--out", str(tmp_path / "sa"))
    assert code == 0, err
    doc = json.loads(out)
    assert doc["im_label"] == "Sa(2π/p) [g]"
    for r, t1 in zip(doc["records"], DURATIONS, strict=True):
        rec = read_record(str(folder / f"rect-{t1:g}.txt"))
        assert r["im_at_scale_1"] == pytest.approx(
            sa(rec.time, rec.accel, 2 * math.pi / P), rel=1e-12
        )


def test_plot_draws_the_curves(folder: Path, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    for extra in ((), ("--extrapolate",)):
        png = tmp_path / f"c{len(extra)}.png"
        code, _, err = run(folder, study_text(), "--out", str(tmp_path / f"p{len(extra)}"),
                           "--plot", str(png), *extra)  # fmt: skip
        assert code == 0, err
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.skipif(
    __import__("importlib").util.find_spec("distributed") is None,
    reason="distributed not installed: pip install '.[dask]'",
)
def test_a_dask_cluster_gives_the_same_fragility(folder: Path, tmp_path: Path) -> None:
    """The records run as tasks on a dask LocalCluster (as rock sweep's chunks do): the same
    cases.csv and fragility as in this process."""
    from distributed import LocalCluster

    code, local, err = run(folder, study_text(), "--out", str(tmp_path / "local"), "--jobs", "1")
    assert code == 0, err
    with LocalCluster(
        n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None
    ) as cluster:
        code, remote, err = run(folder, study_text(), "--out", str(tmp_path / "dask"),
                                "--scheduler", cluster.scheduler_address)  # fmt: skip
    assert code == 0, err
    assert json.loads(remote)["run"]["scheduler"].startswith("inproc://")
    assert json.loads(remote)["damage_states"] == json.loads(local)["damage_states"]
    assert (tmp_path / "dask" / "cases.csv").read_bytes() == (
        tmp_path / "local" / "cases.csv"
    ).read_bytes()


def test_ctrl_c_keeps_the_finished_records_and_resume_ends_the_study(
    folder: Path, tmp_path: Path
) -> None:
    """SIGINT once the first record is on disk: exit 130, one line saying what is saved; the
    lines on disk stay and --resume computes only the rest (time bound: 60 s)."""
    import os
    import signal
    import subprocess
    import sys
    import time

    records = "".join(f'\n[[records]]\nname = "r{k}"\npath = "rect-0.5.txt"\n' for k in range(8))
    text = study_text().split("[[records]]")[0] + records
    text += "\n[ida]\nfirst = 0.2\nstep = 0.005\nlast = 1.0\ntolerance = 0.0001\n"
    (folder / "long.toml").write_text(text, encoding="utf-8")
    out = tmp_path / "long"
    args = [sys.executable, "-m", "rockcli", "fragility", str(folder / "long.toml"), "--out",
            str(out), "--jobs", "1", "--no-progress", "--format", "json"]  # fmt: skip
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)  # fmt: skip
    try:
        deadline = time.monotonic() + 60
        cases = out / "cases.csv"
        while time.monotonic() < deadline:
            if cases.exists() and "\n0," in cases.read_text(encoding="utf-8"):
                break
            assert proc.poll() is None, "the study ended before it was stopped"
            time.sleep(0.02)
        os.killpg(proc.pid, signal.SIGINT)
        _, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    text_err = err.decode()
    assert proc.returncode == 130, text_err
    assert text_err.count("\n") == 1 and text_err.startswith("interrupted: "), text_err
    assert "of 8 records saved" in text_err
    code, again, err2 = run(folder, (folder / "long.toml").read_text(), "--out", str(out),
                            "--resume", name="long.toml")  # fmt: skip
    assert code == 0, err2
    doc = json.loads(again)
    assert doc["run"]["resumed_runs"] > 0 and doc["damage_states"][1]["n_records"] == 8


def test_axes_give_one_fragility_per_grid_point(folder: Path, tmp_path: Path) -> None:
    """An axis over the block's R: each point's records reach overturning at Housner's
    threshold for its own p = √(3g/(4R)) (tolerances as above)."""
    axis = '\n[[axes]]\npath = "geometry.R"\nname = "R"\nvalues = [3.0, 1.5]\n'
    code, out, err = run(folder, study_text() + axis, "--out", str(tmp_path / "ax"))
    assert code == 0, err
    if __import__("importlib").util.find_spec("matplotlib") is not None:
        from rockcli.plots.fragility import plot_fragility

        assert plot_fragility(json.loads(out), tmp_path / "panels.png") == 2  # one per point
    doc = json.loads(out)
    assert [s["point"] for s in doc["damage_states"]] == [{"R": 3.0}] * 2 + [{"R": 1.5}] * 2
    for r in doc["records"]:
        t1 = DURATIONS[0] if r["name"] == "rect-0.32" else DURATIONS[1]
        p = math.sqrt(3.0 * G / (4.0 * r["point"]["R"]))
        expected = ALPHA / (1.0 - math.exp(-p * t1))
        assert r["first_exceedance"]["overturning"] == pytest.approx(expected, rel=REL, abs=BISECT)


def test_a_suite_entry_is_its_records_at_their_scales(folder: Path, tmp_path: Path) -> None:
    """A [[records]] suite (the code's rule needs three records or more) = its records, each at
    the suite's scale: an IDA on PGA finds the
    same first exceedances (the PGA is the scaled record's), and each record's PGA at scale 1
    is its suite scale × 1 g."""
    args = ["record", "pulse", "rectangular", "--amplitude", "1", "--period", "0.4", "--dt",
            str(DT), "-o", str(folder / "rect-0.4.txt"), "--force"]  # fmt: skip
    assert CliRunner().invoke(cli, args).exit_code == 0
    (folder / "pulses.toml").write_text(
        'name = "pulses"\n[target]\nag = 0.2\nF0 = 2.5\nTc_star = 0.3\n'
        '[[records]]\npath = "rect-0.32.txt"\nscale = 1.0\n'
        '[[records]]\npath = "rect-0.5.txt"\nscale = 2.0\n'
        '[[records]]\npath = "rect-0.4.txt"\nscale = 0.5\n',
        encoding="utf-8",
    )
    text = study_text().split("[[records]]")[0] + '[[records]]\nsuite = "pulses.toml"\n'
    text += "\n[ida]\nfirst = 0.2\nstep = 0.05\nlast = 1.0\ntolerance = 0.0001\n"
    code, out, err = run(folder, text, "--out", str(tmp_path / "suite"), name="suite.toml")
    assert code == 0, err
    doc = json.loads(out)
    names = ["pulses/rect-0.32", "pulses/rect-0.5", "pulses/rect-0.4"]
    assert [r["name"] for r in doc["records"]] == names
    assert [r["im_at_scale_1"] for r in doc["records"]] == [1.0, 2.0, 0.5]
    for r, t1 in zip(doc["records"], (*DURATIONS, 0.4), strict=True):
        x = r["first_exceedance"]["overturning"]
        assert x == pytest.approx(threshold(t1), rel=REL, abs=BISECT)


def test_records_that_do_not_reach_a_state_are_censored(folder: Path, tmp_path: Path) -> None:
    """A scan that ends at 0.45 g: the t1 = 0.5 s pulse overturns at 0.368 g, the 0.32 s one
    (0.507 g) is censored at the scan's last intensity, 0.45 g; with a third record (t1 =
    0.4 s, 0.430 g) the fit is the censored maximum likelihood of the two collapses and one
    censored record (rockcli.studies.fragility.fit.ida_censored_fit, tested against scipy)."""
    from rockcli.studies.fragility.fit import ida_censored_fit

    args = ["record", "pulse", "rectangular", "--amplitude", "1", "--period", "0.4", "--dt",
            str(DT), "-o", str(folder / "rect-0.4.txt"), "--force"]  # fmt: skip
    assert CliRunner().invoke(cli, args).exit_code == 0
    text = study_text().replace("last = 1.0", "last = 0.45")
    text += '\n[[records]]\npath = "rect-0.4.txt"\n'
    code, out, err = run(folder, text, "--out", str(tmp_path / "cens"), name="cens.toml")
    assert code == 0, err
    over = json.loads(out)["damage_states"][1]
    assert (over["n_records"], over["not_reached"]) == (3, 1)
    found = np.array(over["collapse_im"])
    assert found == pytest.approx([threshold(0.5), threshold(0.4)], rel=REL, abs=BISECT)
    fit = ida_censored_fit(found, np.array([0.45]))
    assert (over["median"], over["beta"]) == (fit.median, fit.beta)
    assert over["median"] > math.exp(np.log(found).mean())
    assert over["band_method"].startswith("parametric bootstrap of the fitted censored")


@pytest.mark.parametrize(
    ("content", "problem"),
    [
        ("0 0.1\n0.01 0.2\n0.02\n", "line 3"),  # a row cut short
        ("0 0.1\n0.01 abc\n", "line 2"),
        ("", "unrecognised record format"),
    ],
)
def test_a_bad_record_is_refused_before_any_run(
    folder: Path, tmp_path: Path, content: str, problem: str
) -> None:
    (folder / "bad.txt").write_text(content, encoding="utf-8")
    text = study_text().replace("rect-0.5.txt", "bad.txt")
    out = tmp_path / "badrec"
    code, stdout, err = run(folder, text, "--out", str(out), name="badrec.toml")
    assert code == 2 and stdout == "" and err.count("\n") == 1, err
    assert "bad.txt" in err and problem in err, err
    assert not (out / "cases.csv").exists() or (out / "cases.csv").read_text().count("\n") <= 1


def test_a_folder_of_another_run_is_not_overwritten(folder: Path, tmp_path: Path) -> None:
    """A cases.csv that no fragility study wrote (a sweep's folder): refused without --force."""
    out = tmp_path / "sweep"
    out.mkdir()
    (out / "cases.csv").write_text("case,record\n0,x\n", encoding="utf-8")
    code, _, err = run(folder, study_text(), "--out", str(out))
    assert code == 2 and "another run" in err and err.count("\n") == 1
    assert (out / "cases.csv").read_text(encoding="utf-8") == "case,record\n0,x\n"
    code, _, err = run(folder, study_text(), "--out", str(out), "--force")
    assert code == 0, err


def test_a_walls_named_mechanism_is_rocked(tmp_path: Path) -> None:
    """A wall (examples/two-storey-facade.toml) rocks the mechanism the study names, on the
    Ricker pulse of the repository's records; an unknown name is refused up front."""
    root = Path(__file__).resolve().parents[2]
    here = tmp_path / "wall"
    here.mkdir()
    for name in ("two-storey-facade.toml",):
        (here / name).write_text((root / "examples" / name).read_text("utf-8"), "utf-8")
    ricker = root / "records" / "ricker_Tp0.5s_0.5g.txt"
    (here / "ricker.txt").write_bytes(ricker.read_bytes())
    text = """model = "two-storey-facade.toml"
method = "ida"
mechanism = "gable"
[intensity]
measure = "pga"
[[damage_states]]
level = "overturning"
[[records]]
path = "ricker.txt"
[ida]
first = 0.05
step = 0.05
last = 3.0
"""
    code, out, err = run(here, text, "--out", str(tmp_path / "o"))
    assert code == 0, err
    assert [r["mechanism"] for r in json.loads(out)["records"]] == ["gable"]
    code, _, err = run(here, text.replace('"gable"', '"roof"'), "--out", str(tmp_path / "p"))
    assert code == 2 and "mechanism" in err and "gable" in err and err.count("\n") == 1


@pytest.mark.parametrize(
    ("scan", "key"),
    [
        ("first = 0.2\nstep = 1e-9\nlast = 1.0\ntolerance = 0.001", "ida.step"),
        ("first = 0.2\nstep = 0.05\nlast = 1e300\ntolerance = 0.001", "ida.last"),  # F16
        ("first = 0.2\nstep = 0.05\nlast = 1.0\ntolerance = 1e-300", "ida.tolerance"),
    ],
)
def test_an_unbounded_scan_is_one_line(folder: Path, tmp_path: Path, scan: str, key: str) -> None:
    """Issue 34, F5 and F6: a step that lists 10⁹ intensities (MemoryError after minutes), or
    a tolerance below the float spacing (a bisection that never ends), are refused at once."""
    text = study_text().split("[ida]")[0] + f"[ida]\n{scan}\n"
    code, _, err = run(folder, text, "--out", str(tmp_path / "u"))
    assert code == 2 and err.count("\n") == 1 and key in err, err
