"""The NTC hazard grid (rockcli.codecheck.hazard): reading, interpolation, refusals.

Sources: the grid file itself (../shared/ntc/AllegatoB.txt, DM 14/01/2008 Allegato B; format in
../shared/ntc/PROVENANCE.md), the L'Aquila vector of spec/ntc.md (half a unit of the last
printed digit), and Allegato A's formulas worked by hand on small synthetic grids.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.codecheck.hazard import (
    ROCK_HAZARD_GRID,
    HazardGrid,
    cell_nodes,
    grid_path,
    haversine,
    parse_grid,
    read_grid,
    site_parameters,
)
from rockcli.errors import InputError

#: The header line of AllegatoB.txt (a TR label every three columns).
HEADER = (
    "%\t\t"
    + "\t\t\t".join(f"TR={tr}" for tr in (30, 50, 72, 101, 140, 201, 475, 975, 2475))
    + "\t\t"
)


def grid_line(lon: float, lat: float, ag_tenths: float, F0: float = 2.5, Tc: float = 0.3) -> str:
    """One data line: the same (ag, F0, TC*) at every TR, ag scaled by TR/475 to vary."""
    cells = [f"{lon:g}", f"{lat:g}"]
    for TR in (30, 50, 72, 101, 140, 201, 475, 975, 2475):
        cells += [f"{ag_tenths * TR / 475:.6g}", f"{F0:g}", f"{Tc:g}"]
    return "\t".join(cells)


def small_grid_text() -> str:
    """A 3×3 axis-aligned mesh, ag [g/10] = 1 + 10·(lon − 10) + 20·(lat − 45).

    0.05° of latitude and 0.07° of longitude apart: ≈ 5.5 km both ways at 45° N, like the NTC
    mesh (the cell rule finds a node's edge neighbours within 1.2 spacings).
    """
    lines = [HEADER]
    for lon in (10.0, 10.07, 10.14):
        for lat in (45.1, 45.05, 45.0):
            lines.append(grid_line(lon, lat, 1.0 + 10 * (lon - 10) + 20 * (lat - 45)))
    return "\r\n".join(lines) + "\r\n"


@pytest.fixture
def small_grid() -> HazardGrid:
    return parse_grid(small_grid_text(), source="small.txt")


# --- the real grid ------------------------------------------------------------------------------


def test_real_grid_shape_and_units(ntc_grid: HazardGrid) -> None:
    # PROVENANCE.md: 10 751 nodes; TR 475 ag up to 2.78 g/10 = 0.278 g
    assert ntc_grid.lon.shape == (10751,)
    assert ntc_grid.ag.shape == ntc_grid.F0.shape == ntc_grid.Tc_star.shape == (10751, 9)
    assert list(ntc_grid.return_periods) == [30, 50, 72, 101, 140, 201, 475, 975, 2475]
    assert ntc_grid.ag[:, 6].max() == pytest.approx(0.278, rel=1e-12)


def test_node_values_from_the_file(ntc_grid: HazardGrid) -> None:
    # first data line of AllegatoB.txt, TR 475 columns: 0.943 (g/10), 2.44, 0.27
    ag, F0, Tc = site_parameters(ntc_grid, 6.5448, 45.134, 475)
    assert (ag, F0, Tc) == pytest.approx((0.0943, 2.44, 0.27), rel=1e-12)


def test_return_period_interpolation_at_a_node(ntc_grid: HazardGrid) -> None:
    # Allegato A Eq. 3 by hand with the file's values at TR 475 (0.943, 2.44, 0.27) and
    # TR 975 (1.267, 2.42, 0.27): x = ln(700/475)/ln(975/475) = 0.53949
    x = math.log(700 / 475) / math.log(975 / 475)
    expected = (0.0943 * (0.1267 / 0.0943) ** x, 2.44 * (2.42 / 2.44) ** x, 0.27)
    assert site_parameters(ntc_grid, 6.5448, 45.134, 700) == pytest.approx(expected, rel=1e-12)


def test_return_period_interpolation_off_node(ntc_grid: HazardGrid) -> None:
    # at a site, TR interpolation is log–log between the site's values at TR1 and TR2
    at_475 = site_parameters(ntc_grid, 13.40, 42.35, 475)
    at_975 = site_parameters(ntc_grid, 13.40, 42.35, 975)
    x = math.log(600 / 475) / math.log(975 / 475)
    expected = tuple(p1 * (p2 / p1) ** x for p1, p2 in zip(at_475, at_975, strict=True))
    assert site_parameters(ntc_grid, 13.40, 42.35, 600) == pytest.approx(expected, rel=1e-12)


def test_laquila_vector(ntc_grid: HazardGrid) -> None:
    # spec/ntc.md: (13.40 E, 42.35 N), TR 475, haversine distances → 0.2607 g, 2.36, 0.35 s
    ag, F0, Tc = site_parameters(ntc_grid, 13.40, 42.35, 475)
    assert ag == pytest.approx(0.2607, abs=0.00005)
    assert F0 == pytest.approx(2.36, abs=0.005)
    assert Tc == pytest.approx(0.35, abs=0.005)


def test_laquila_cell_is_the_four_surrounding_nodes(ntc_grid: HazardGrid) -> None:
    nodes = cell_nodes(ntc_grid, 13.40, 42.35)
    lons, lats = ntc_grid.lon[nodes], ntc_grid.lat[nodes]
    found = {(round(x, 3), round(y, 3)) for x, y in zip(lons, lats, strict=True)}
    assert found == {(13.355, 42.335), (13.423, 42.335), (13.355, 42.385), (13.422, 42.385)}


@pytest.mark.parametrize(("lon", "lat"), [(9.1, 39.2), (11.0, 40.0), (12.5, 44.5), (6.40, 45.10)])
def test_site_outside_the_grid(ntc_grid: HazardGrid, lon: float, lat: float) -> None:
    # Sardinia (Allegato B Tabella 2, not in the grid), the Tyrrhenian, the Adriatic off
    # Ravenna, just west of the westernmost column
    with pytest.raises(InputError) as info:
        site_parameters(ntc_grid, lon, lat, 475)
    message = str(info.value)
    assert f"lon {lon:g}, lat {lat:g}" in message
    assert "lon 6.5448–18.594 E, lat 36.573–47.178 N" in message


@pytest.mark.parametrize("TR", [20.0, 3000.0])
def test_return_period_outside_the_grid(ntc_grid: HazardGrid, TR: float) -> None:
    with pytest.raises(InputError) as info:
        site_parameters(ntc_grid, 13.40, 42.35, TR)
    assert info.value.where == "TR"
    assert info.value.value == TR
    assert "30 ≤ TR ≤ 2475" in str(info.value)


def test_grid_end_periods_accepted(ntc_grid: HazardGrid) -> None:
    assert site_parameters(ntc_grid, 6.5448, 45.134, 30).ag == pytest.approx(0.0263, rel=1e-12)
    assert site_parameters(ntc_grid, 6.5448, 45.134, 2475).ag == pytest.approx(0.1767, rel=1e-12)


# --- Allegato A on a small synthetic grid (always runs) ----------------------------------------


def test_inverse_distance_by_hand(small_grid: HazardGrid) -> None:
    lon, lat = 10.03, 45.03
    corners = [(10.0, 45.0), (10.07, 45.0), (10.0, 45.05), (10.07, 45.05)]
    values = [1.0 + 10 * (x - 10) + 20 * (y - 45) for x, y in corners]  # [g/10] at TR 475
    inverse = [1.0 / haversine(lon, lat, np.array([x]), np.array([y]))[0] for x, y in corners]
    expected = sum(v * w for v, w in zip(values, inverse, strict=True)) / sum(inverse) / 10
    assert site_parameters(small_grid, lon, lat, 475).ag == pytest.approx(expected, rel=1e-12)


def test_haversine_is_the_great_circle_angle() -> None:
    # one degree of latitude along a meridian is π/180 rad; 1° of longitude on the equator too
    assert haversine(10.0, 45.0, np.array([10.0]), np.array([46.0]))[0] == pytest.approx(
        math.pi / 180, rel=1e-12
    )
    assert haversine(0.0, 0.0, np.array([1.0]), np.array([0.0]))[0] == pytest.approx(
        math.pi / 180, rel=1e-12
    )


def test_site_on_a_cell_edge(small_grid: HazardGrid) -> None:
    # on the edge between (10.07, 45.0) and (10.07, 45.05): either adjacent cell contains it
    nodes = cell_nodes(small_grid, 10.07, 45.025)
    assert nodes.size == 4


def test_site_on_a_node_returns_the_node(small_grid: HazardGrid) -> None:
    # 1 + 10·0.07 + 20·0.05 = 2.7 g/10
    assert site_parameters(small_grid, 10.07, 45.05, 475).ag == pytest.approx(0.27, rel=1e-12)


def test_site_beyond_the_small_grid(small_grid: HazardGrid) -> None:
    with pytest.raises(InputError, match="outside"):
        site_parameters(small_grid, 10.16, 45.03, 475)  # east of the last column


# --- the grid file ------------------------------------------------------------------------------


def test_malformed_line_names_the_line(tmp_path: Path) -> None:
    lines = small_grid_text().split("\r\n")
    lines[2] = "\t".join(lines[2].split("\t")[:-1])  # line 3 loses its last column
    path = tmp_path / "grid.txt"
    path.write_bytes("\r\n".join(lines).encode())
    with pytest.raises(InputError) as info:
        read_grid(path)
    assert info.value.file == str(path)
    assert info.value.where == "line 3"
    assert "wrong number of columns (28)" in str(info.value)


def test_non_numeric_token_named(tmp_path: Path) -> None:
    text = small_grid_text().replace("\t2.5\t", "\t2,5\t", 1)
    with pytest.raises(InputError) as info:
        parse_grid(text, source="grid.txt")
    assert (info.value.where, info.value.value) == ("line 2", "2,5")


def test_non_positive_value_refused() -> None:
    text = small_grid_text().replace("\t0.3", "\t0", 1)
    with pytest.raises(InputError, match="> 0") as info:
        parse_grid(text, source="grid.txt")
    assert info.value.where == "line 2"


def test_header_with_other_return_periods_refused() -> None:
    text = small_grid_text().replace("TR=72", "TR=75", 1)
    with pytest.raises(InputError, match="return periods") as info:
        parse_grid(text, source="grid.txt")
    assert info.value.where == "line 1"


def test_unreadable_file(tmp_path: Path) -> None:
    missing = tmp_path / "nope.txt"
    with pytest.raises(InputError, match="cannot read") as info:
        read_grid(missing)
    assert info.value.file == str(missing)


def test_empty_file() -> None:
    with pytest.raises(InputError, match="no grid nodes"):
        parse_grid(HEADER + "\r\n", source="grid.txt")


def test_ag_divided_by_ten(small_grid: HazardGrid) -> None:
    # node (10, 45): 1.0 g/10 at TR 475 → 0.1 g
    assert small_grid.ag[2, 6] == pytest.approx(0.1, rel=1e-12)


# --- where the grid comes from ------------------------------------------------------------------


def test_grid_path_option_first(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(ROCK_HAZARD_GRID, "/env/grid.txt")
    assert grid_path("/opt/grid.txt") == "/opt/grid.txt"


def test_grid_path_from_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(ROCK_HAZARD_GRID, "/env/grid.txt")
    assert grid_path(None) == "/env/grid.txt"


def test_grid_path_missing_says_how(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ROCK_HAZARD_GRID, raising=False)
    with pytest.raises(InputError, match="--hazard-grid FILE or ROCK_HAZARD_GRID"):
        grid_path(None)


@pytest.mark.parametrize("label", ["TR=1.2.3", "TR=", "TR=3O"])
def test_header_with_a_malformed_return_period_names_the_line(label: str) -> None:
    # Issue 7, item 9: "TR=1.2.3" made float() raise ValueError (a traceback) on main.
    text = small_grid_text().replace("TR=72", label, 1)
    with pytest.raises(InputError, match="not a number") as info:
        parse_grid(text, source="grid.txt")
    assert (info.value.file, info.value.where) == ("grid.txt", "line 1")
    assert info.value.value == label.removeprefix("TR=")


def test_a_grid_file_is_read_once_and_again_when_edited(tmp_path: Path) -> None:
    # read_grid keeps the parsed grid of an unchanged file (a suite's limit states each ask
    # for it); an edited file (other size or time) is parsed again, never served stale.
    path = tmp_path / "grid.txt"
    path.write_text(small_grid_text(), encoding="utf-8")
    first = read_grid(path)
    assert read_grid(path) is first
    edited = small_grid_text().replace("\t2.5\t", "\t2.6\t", 1)
    path.write_text(edited + "\r\n", encoding="utf-8")
    again = read_grid(path)
    assert again is not first and again.F0.max() == pytest.approx(2.6)
    path.write_text("not a grid\n", encoding="utf-8")
    with pytest.raises(InputError):
        read_grid(path)


@settings(max_examples=100, deadline=None)
@given(
    token=st.text(alphabet="0123456789.-+eE０２٥ ,x", min_size=1, max_size=8),
    column=st.integers(2, 28),
)
def test_a_grid_token_is_an_ascii_number_or_one_error(token: str, column: int) -> None:
    """One cell of the small grid replaced: a grid, or one InputError naming the file and line;
    a token with a non-ASCII digit is never read (float() would read "０.２" as 0.2)."""
    lines = small_grid_text().split("\r\n")
    cells = lines[1].split("\t")
    cells[column] = token
    lines[1] = "\t".join(cells)
    try:
        grid = parse_grid("\r\n".join(lines), source="grid.txt")
    except InputError as exc:
        assert (exc.file, exc.where) == ("grid.txt", "line 2") and "\n" not in str(exc)
        return
    assert token.strip().isascii()
    assert np.all(np.isfinite(grid.ag)) and np.all(grid.ag > 0)
