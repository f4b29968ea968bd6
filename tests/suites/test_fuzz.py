"""The suite reader on random TOML-ish tables: a valid suite or one InputError, never a
traceback (bounded: 150 examples, no record is read)."""

from __future__ import annotations

import copy
import shutil
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD
from rockcli.suites.load import load_suite, resolve, validate_suite
from rockcli.suites.schema import Suite
from tests.suites.conftest import PULSES
from tests.suites.conftest import TARGET as TARGET_TABLE

#: Values of every kind a TOML file can hold (and a few it cannot, e.g. None).
SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-10, 10),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=8),
    st.sampled_from(["SLV", "SLX", "A", "T5", "2018", "2008", "../x.AT2", ""]),
)
VALUES = st.recursive(
    SCALARS,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner),
    max_leaves=12,
)
RECORD = st.fixed_dictionaries(
    {"path": st.one_of(st.text(max_size=6), st.sampled_from(["a\x00b", "/etc/passwd"]), VALUES)},
    optional={"name": VALUES, "scale": VALUES, "extra": VALUES},
)
TARGET = st.fixed_dictionaries(
    {},
    optional={
        k: st.one_of(st.floats(-200, 200), VALUES)
        for k in ("lon", "lat", "ag", "F0", "Tc_star", "VN", "CU")
    }
    | {k: VALUES for k in ("limit_state", "edition", "soil", "topography")},
)
SUITES = st.fixed_dictionaries(
    {},
    optional={
        "name": st.one_of(st.text(max_size=6), VALUES),
        "records": st.one_of(st.lists(RECORD, max_size=8), VALUES),
        "target": st.one_of(TARGET, VALUES),
        "period_range": st.one_of(
            st.lists(st.floats(-1, 5), max_size=3),
            st.lists(st.floats(0, 1e300) | st.sampled_from([1e-300, 5e-324, 1e300]), max_size=3),
            VALUES,
        ),
        "tolerance": st.one_of(st.lists(st.floats(-2, 2), max_size=3), VALUES),
        "other": VALUES,
    },
)


def check_suite_table(data: dict[str, Any]) -> None:
    """A valid suite (every rule holds after resolving) or one InputError line naming the
    file."""
    try:
        suite = validate_suite(data, "fuzz.toml")
    except InputError as exc:
        line = str(exc)
        assert line.startswith("fuzz.toml: ") and "\n" not in line, line
        return
    assert isinstance(suite, Suite) and len(suite.records) >= 3
    settings_ = resolve(suite, "fuzz.toml", None)
    lo, hi = settings_.period_range
    assert MIN_PERIOD <= lo < hi <= MAX_PERIOD  # the response spectra's periods
    assert -1 < settings_.tolerance[0] < settings_.tolerance[1]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(SUITES)
def test_random_table_is_a_suite_or_one_input_error(data: dict[str, Any]) -> None:
    check_suite_table(data)


#: A valid suite table: the fuzz below damages one key of it at a time.
VALID = {
    "name": "s",
    "records": [{"path": f"r{i}.txt", "scale": 1.0} for i in range(3)],
    "target": {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3, "limit_state": "SLV"},
    "period_range": [0.15, 2.0],
    "tolerance": [-0.1, 0.3],
}
#: Where the fuzz can damage it: (table path, key).
SPOTS = [
    ((), "name"),
    ((), "period_range"),
    ((), "tolerance"),
    ((), "records"),
    (("records", 0), "path"),
    (("records", 1), "scale"),
    (("records", 2), "name"),
    (("target",), "ag"),
    (("target",), "lon"),
    (("target",), "limit_state"),
    (("target",), "edition"),
    (("target",), "soil"),
]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SPOTS), VALUES)
def test_damaged_valid_suite_is_a_suite_or_one_input_error(spot: Any, value: Any) -> None:
    data = copy.deepcopy(VALID)
    table: Any = data
    for part in spot[0]:
        table = table[part]
    table[spot[1]] = value
    check_suite_table(data)


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    st.lists(
        st.one_of(
            st.text(max_size=12),
            st.tuples(
                st.sampled_from(["lon", "lat", "ag", "F0", "Tc_star", "soil", "edition", "x"]),
                st.one_of(
                    st.text(max_size=6),
                    st.floats().map(str),
                    st.integers().map(str),
                    st.text(alphabet="0123456789.-e０１２５٠٢٥", min_size=1, max_size=5),
                ),
            ).map("=".join),
        ),
        max_size=6,
    ).map(",".join)
)
def test_target_text_is_a_suite_or_one_error(tmp_path: Path, text: str) -> None:
    # A folder suite with --target: a suite, or one InputError line (no record is read).
    from rockcli.suites.load import load_suite

    for pulse in PULSES:
        if not (tmp_path / pulse.name).exists():
            shutil.copyfile(pulse, tmp_path / pulse.name)
    try:
        settings_ = load_suite(tmp_path, target=text)
    except InputError as exc:
        assert "\n" not in str(exc)
        return
    # A number key read: its value was written in ASCII (０.２ is text, which the schema
    # refuses for a number; float() alone would have read it).
    for item in text.split(","):
        key, _, value = (part.strip() for part in item.partition("="))
        if key in ("lon", "lat", "ag", "F0", "Tc_star"):
            assert value.isascii(), (key, value)
    assert len(settings_.entries) == len(PULSES)


#: Record paths a suite file may write: inside, outside by '..', by a link, absolute, NUL.
PATHS = ["r.txt", "./r.txt", "sub/r2.txt", "sub/../r.txt", "../out.txt", "sub/../../out.txt",
         "link.txt", "sub/link2.txt", "ABSOLUTE", "a\x00b.txt", "..", "none.txt"]  # fmt: skip


@settings(max_examples=100, deadline=None)
@given(paths=st.lists(st.sampled_from(PATHS), min_size=3, max_size=5), allow=st.booleans())
def test_suite_paths_stay_inside_or_one_error(
    tmp_path_factory: pytest.TempPathFactory, paths: list[str], allow: bool
) -> None:
    """Without --allow-outside, every record of a loaded suite resolves inside the suite's
    folder (links and '..' followed); anything else is one InputError line naming the file."""
    root = tmp_path_factory.mktemp("paths")
    folder, outside = root / "suite", root / "out.txt"
    (folder / "sub").mkdir(parents=True)
    for path in (folder / "r.txt", folder / "sub" / "r2.txt", outside):
        path.write_text("0 0\n0.01 0.1\n0.02 0\n", encoding="utf-8")
    (folder / "link.txt").symlink_to(outside)
    (folder / "sub" / "link2.txt").symlink_to(folder / "r.txt")  # a link that stays inside
    records = [{"path": str(outside) if p == "ABSOLUTE" else p, "name": f"n{i}"}
               for i, p in enumerate(paths)]  # fmt: skip
    suite = folder / "suite.toml"
    suite.write_text(tomli_w.dumps({"name": "s", "target": TARGET_TABLE, "records": records}))
    try:
        settings_ = load_suite(suite, allow_outside=allow)
    except InputError as exc:
        line = str(exc)
        assert line.startswith(f"{suite}: ") and "\n" not in line, line
        return
    if not allow:
        assert all(e.path.resolve().is_relative_to(folder.resolve()) for e in settings_.entries)
