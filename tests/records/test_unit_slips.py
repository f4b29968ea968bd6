"""A record in the wrong unit must not give a confident wrong verdict (issue 19, item 4).

El Centro scaled to 0.15 g and written in m/s² as two columns, read without ``--units``, is
read as g: its PGA becomes 0.15 × 9.80665 = 1.471 "g" and the verdict flips. Before this
change the warning fired only above 3 g and named only cm/s². Now a record whose unit nothing
declares warns above 1 g, naming both slips with their factors (9.81 and 981) and what the
PGA would then be; a plain-text file may declare its unit in a ``# units:`` line, which
``rock record convert`` writes and which a contradicting ``--units`` cannot override.

Numbers: 9.80665 m/s² is standard gravity (rockcli.units.STANDARD_GRAVITY), so values in m/s²
read as g are 9.80665 times too large and in cm/s² 980.665 times; the warning prints them to
3 digits (9.81, 981).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.records.files import read_record
from rockcli.records.parse import parse_text
from rockcli.records.plain import format_plain
from rockcli.records.transform import scale_to_pga
from rockcli.units import STANDARD_GRAVITY

ROOT = Path(__file__).resolve().parents[2]
ALTAR = str(ROOT / "examples" / "altar.toml")
WALL = str(ROOT / "examples" / "wall.toml")
#: The issue's record: El Centro scaled to this PGA [g], then written in m/s².
TARGET_PGA = 0.15
#: Its PGA read as g: 0.15 × 9.80665 = 1.4709975, printed to 4 digits.
PGA_AS_READ = "1.471 g"
#: The slips the warning must name: the factors and the PGA each would give (0.15 g and
#: 0.15/100 g), as printed to 3 digits.
SLIPS = ("÷ 9.81", "÷ 981", "0.15 g", "0.0015 g")


def run(*args: str) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of `rock ARGS`."""
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture
def elcentro_ms2(shared_records: Path, tmp_path: Path) -> Path:
    """ELC180.AT2 scaled to 0.15 g, written as two columns (t [s], a [m/s²]), no header."""
    record = scale_to_pga(read_record(shared_records / "ELC180.AT2"), TARGET_PGA)
    accel = record.accel * STANDARD_GRAVITY
    path = tmp_path / "elc_ms2.txt"
    path.write_text(
        "".join(f"{t:.2f} {float(a)!r}\n" for t, a in zip(record.time, accel, strict=True))
    )
    return path


def slip_warnings(warnings: list[str]) -> list[str]:
    """The warnings that flag the unit slip of the issue's record."""
    return [w for w in warnings if f"PGA {PGA_AS_READ} is above 1 g" in w]


@pytest.mark.parametrize(
    "command",
    [
        ("assess", WALL),
        ("assess", ALTAR),
        ("compare", ALTAR),
        ("kinematic", ALTAR),
        ("retrofit", str(ROOT / "examples" / "facade.toml")),
    ],
    ids=["assess-wall", "assess-altar", "compare", "kinematic", "retrofit"],
)
def test_el_centro_in_m_s2_read_as_g_warns_in_the_table_and_the_json(
    elcentro_ms2: Path, command: tuple[str, str]
) -> None:
    args = (*command, "--record", str(elcentro_ms2))
    code, out, err = run(*args, "--format", "json")
    assert code == 0, err
    (warning,) = slip_warnings(json.loads(out)["warnings"])
    assert all(part in warning for part in SLIPS) and "check the unit" in warning
    code, out, _ = run(*args)
    lines = [line for line in out.splitlines() if line.startswith("warning: PGA 1.471 g")]
    assert code == 0 and len(lines) == 1
    assert "÷ 9.81" in out and "÷ 981" in out


def test_record_info_names_the_unit_as_assumed(elcentro_ms2: Path) -> None:
    code, out, _ = run("record", "info", str(elcentro_ms2))
    assert code == 0 and "g (assumed)" in out and "warning: PGA 1.471 g" in out
    code, out, _ = run("record", "info", str(elcentro_ms2), "--format", "json")
    (data,) = json.loads(out)["records"]
    assert data["unit_declared"] is False and len(slip_warnings(data["warnings"])) == 1


def test_the_right_unit_gives_the_record_and_no_warning(elcentro_ms2: Path) -> None:
    """--units m/s2 gives back 0.15 g (to the float rounding of × and ÷ 9.80665: 1e-12)."""
    record = read_record(elcentro_ms2, units="m/s2")
    assert record.pga == pytest.approx(TARGET_PGA, rel=1e-12)
    assert record.warnings == () and record.unit_declared


def test_a_declared_unit_above_1_g_is_a_real_record(shared_records: Path) -> None:
    """CPM000.AT2 (Cape Mendocino 1992) peaks at 1.497 g: its header declares g, no warning."""
    record = read_record(shared_records / "CPM000.AT2")
    assert record.pga > 1.0 and record.warnings == ()


def test_declared_units_warn_above_3_g_only() -> None:
    text = "0 2.5\n0.01 -1\n0.02 0.5\n"  # 2.5 g
    assert parse_text(text, units="g").warnings == ()
    assert parse_text("# units: g\n" + text).warnings == ()
    (warning,) = parse_text(text).warnings
    assert "above 1 g" in warning and "in m/s² it would be 0.255 g" in warning  # 2.5/9.80665


# The `# units:` line --------------------------------------------------------------------------

VALUES = "0 1.5\n0.01 -2\n0.02 0.25\n"


@pytest.mark.parametrize(
    ("line", "to_g"),
    [
        ("# units: m/s2", 1 / STANDARD_GRAVITY),
        ("# units: m/s^2", 1 / STANDARD_GRAVITY),
        ("# UNITS: M/S²", 1 / STANDARD_GRAVITY),
        ("#units:m/s/s", 1 / STANDARD_GRAVITY),
        ("# unit = m/s2", 1 / STANDARD_GRAVITY),
        ("# units: cm/s2", 0.01 / STANDARD_GRAVITY),
        ("# units: cm/s^2", 0.01 / STANDARD_GRAVITY),
        ("# units: gal", 0.01 / STANDARD_GRAVITY),
        ("# units: g", 1.0),
    ],
)
def test_the_units_line_declares_the_unit(line: str, to_g: float) -> None:
    record = parse_text(f"# a comment\n{line}\n{VALUES}")
    assert np.array_equal(record.accel, np.array([1.5, -2.0, 0.25]) * to_g)
    assert record.unit_declared and record.warnings == ()  # 2 m/s² read as g would warn


def test_a_one_column_file_honours_it_too() -> None:
    record = parse_text("# units: cm/s2\n150\n-200\n25\n", dt=0.01)
    assert record.unit == "cm/s2" and record.pga == 200 * (0.01 / STANDARD_GRAVITY)


def test_an_unknown_unit_names_the_line() -> None:
    with pytest.raises(InputError) as err:
        parse_text(f"# name: x\n# units: furlong/fortnight\n{VALUES}", source="x.txt")
    assert err.value.where == "line 2 (# units)" and err.value.value == "furlong/fortnight"
    assert "unknown acceleration unit" in err.value.problem


def test_a_contradicting_option_is_an_error_naming_both() -> None:
    with pytest.raises(InputError) as err:
        parse_text(f"# units: m/s2\n{VALUES}", units="g", source="x.txt")
    assert err.value.file == "x.txt" and err.value.where == "line 1 (# units)"
    assert "--units g contradicts the file's '# units: m/s2' line" in err.value.problem
    assert parse_text(f"# units: m/s2\n{VALUES}", units="m/s^2").unit == "m/s2"  # agrees


def test_two_contradicting_units_lines_are_an_error() -> None:
    with pytest.raises(InputError) as err:
        parse_text(f"# units: g\n# units: cm/s2\n{VALUES}")
    assert err.value.where == "line 2 (# units)"


def test_a_units_comment_after_the_data_is_not_the_header() -> None:
    """Like ``# npts:``, the header is the comment lines before the first number."""
    record = parse_text("0 0.1\n# units: m/s2\n0.01 0.2\n")
    assert record.unit == "g" and not record.unit_declared


def test_a_conflict_exits_2_with_one_line(write_file: Callable[[str, str], Path]) -> None:
    path = write_file("r.txt", f"# units: m/s2\n{VALUES}")
    code, out, err = run("record", "info", str(path), "--units", "cm/s2")
    assert code == 2 and out == ""
    assert err.strip() == (
        f"error: {path}: line 1 (# units): --units cm/s2 contradicts the file's "
        "'# units: m/s2' line (got 'cm/s2'; allowed: no --units (the file declares m/s2), "
        "or --units m/s2)"
    )


# `rock record convert` writes the line; reading honours it -----------------------------------


def test_convert_writes_the_unit_and_the_file_reads_back(
    elcentro_ms2: Path, tmp_path: Path
) -> None:
    out = tmp_path / "elc_g.txt"
    code, _, err = run("record", "convert", str(elcentro_ms2), "--units", "m/s2", "-o", str(out))
    assert code == 0, err
    assert "# units: g" in out.read_text().splitlines()
    back, original = read_record(out), read_record(elcentro_ms2, units="m/s2")
    assert back.unit_declared and np.array_equal(back.accel, original.accel)  # bit for bit
    code, _, err = run("record", "info", str(out), "--units", "m/s2")
    assert code == 2 and "contradicts the file's '# units: g' line" in err


def test_a_converted_slip_keeps_its_warning(elcentro_ms2: Path, tmp_path: Path) -> None:
    """Converted without --units, the file says `# units: g` (its values are in g now): the
    warning of the read goes into its header and comes back with it, so the slip is not
    laundered into a declared unit."""
    out = tmp_path / "elc_g.txt"
    code, _, err = run("record", "convert", str(elcentro_ms2), "-o", str(out))
    said = [line.removeprefix("warning: ") for line in err.splitlines()]
    assert code == 0 and len(slip_warnings(said)) == 1
    record = read_record(out)
    assert record.unit_declared and record.warnings == tuple(slip_warnings(said))
    again = [line for line in format_plain(record).splitlines() if line.startswith("# warning")]
    assert len(again) == 1  # written again, read again: still one warning, not two


# Suites and sweeps read records too -----------------------------------------------------------


def test_suites_and_sweeps_carry_the_warning(
    elcentro_ms2: Path, shared_records: Path, tmp_path: Path
) -> None:
    """`rock suite check`, `assess`/`compare --suite` and `rock sweep` show the record's
    warning, named by the record, under their tables and in their JSON."""
    suite = tmp_path / "suite.toml"
    records = [("elc ms2", elcentro_ms2), ("elc", shared_records / "ELC180.AT2")]
    records.append(("cpm", shared_records / "CPM000.AT2"))
    suite.write_text(
        tomli_w.dumps({
            "name": "s",
            "target": {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3},
            "records": [{"name": name, "path": str(path)} for name, path in records],
        })
    )  # fmt: skip
    # The real records are in ../shared, outside the suite's folder: --allow-outside.
    for args in (("suite", "check"), ("assess", ALTAR, "--suite"), ("compare", ALTAR, "--suite")):
        code, out, err = run(*args, str(suite), "--allow-outside", "--format", "json")
        assert code == 0, err
        (warning,) = slip_warnings(json.loads(out)["warnings"])
        assert warning.startswith("elc ms2: PGA 1.471 g") and "÷ 981" in warning
        assert "warning: elc ms2: PGA 1.471 g" in run(*args, str(suite), "--allow-outside")[1]
    study = tmp_path / "study.toml"
    study.write_text(
        tomli_w.dumps({
            "name": "units",
            "base": WALL,
            "analyses": ["rocking"],
            "axes": [{"path": "geometry.height", "name": "h", "values": [4.0]}],
            "records": [{"name": "elcms2", "path": str(elcentro_ms2)}],
        })
    )  # fmt: skip
    out_dir = tmp_path / "sweep"
    code, out, err = run(
        "sweep", str(study), "--out", str(out_dir), "-j", "1", "--allow-outside", "--format", "json"
    )
    assert code == 0, err
    (warning,) = slip_warnings(json.loads(out)["warnings"])
    assert warning.startswith("record elcms2: PGA 1.471 g")
