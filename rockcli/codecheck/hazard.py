"""The NTC hazard grid: ag, F0, TC* at a site and a return period (DM 14/01/2008, Allegati A–B).

NTC 2008 §3.2 and NTC 2018 §3.2 both take the hazard from Allegati A and B of DM 14/01/2008.
The grid file is the user's (rock does not ship it): tab-separated, CRLF, a ``%`` header, then
29 columns per node: lon, lat, and (ag, F0, TC*) for TR = 30, 50, 72, 101, 140, 201, 475, 975,
2475 years, with **ag in g/10** (spec/ntc.md; ../shared/ntc/PROVENANCE.md). The islands of
Allegato B, Tabella 2 (Sardinia, Pantelleria, …) are not in it.

Interpolation (Allegato A):

- in space, inverse distance over the four vertices of the grid cell containing the site,
  p = Σ(p_i/d_i) / Σ(1/d_i), d_i great-circle (haversine) distances;
- in return period, log–log between the bracketing grid periods,
  log p = log p1 + log(p2/p1)·log(TR/TR1)/log(TR2/TR1), applied to the site values at TR1, TR2.

**Cell rule.** The grid is a square mesh of ≈ 0.05° (≈ 5.5 km) rotated by up to ≈ 5° and not
exactly regular, so "the cell containing the site" is found in the mesh's own axes: take the
node N0 nearest to the site; its edge neighbours (the nodes within 1.2 mesh spacings of it) give
the local axes u (east-ish) and v (north-ish); the site's coordinates (s, t) in those axes pick
the quadrant; the cell is N0, N0 + sign(s)·u, N0 + sign(t)·v, N0 + sign(s)·u + sign(t)·v, each
matched to the nearest node within 0.3 spacings, and it must contain the site (a site within
a hair of an edge may belong to the next quadrant: those are tried next). A site whose nearest
node is farther than one spacing, or that no such cell contains (beyond the grid's edge, the
sea, the islands), is refused. A site on a node returns that node's values. Checked on 20 000
random sites: every cell found contains its site; no site next to an interior node refused.

The file edge (:func:`read_grid`) is the one function here that touches the disk; the rest is
pure. The caller holds the grid: nothing is cached globally.
"""

from __future__ import annotations

import functools
import math
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

import numpy as np

from rockcli.errors import InputError
from rockcli.notes import Note
from rockcli.numbers import ascii_float
from rockcli.textfile import GRID_LIMIT, read_text

#: Environment variable naming the user's copy of the grid file.
ROCK_HAZARD_GRID = "ROCK_HAZARD_GRID"
#: The return periods of the grid, in column order [years] (DM 14/01/2008, Allegato B).
GRID_RETURN_PERIODS = (30.0, 50.0, 72.0, 101.0, 140.0, 201.0, 475.0, 975.0, 2475.0)
#: Columns per data line: lon, lat, then (ag, F0, TC*) per return period.
GRID_COLUMNS = 2 + 3 * len(GRID_RETURN_PERIODS)
#: The grid stores ag in tenths of g (PROVENANCE.md: max 2.78 at TR 475 is 0.278 g).
AG_FILE_SCALE = 10.0
#: Mesh spacing of the grid [deg of latitude] (≈ 5.5 km); the farthest a site may be from
#: its nearest node (a site inside a cell is within half a diagonal, 0.035°).
MESH_SPACING = 0.05
#: Edge neighbours of a node lie within this many spacings (diagonals at √2 ≈ 1.41).
EDGE_NEIGHBOUR = 1.2
#: A predicted cell vertex must match a node within this many spacings.
VERTEX_MATCH = 0.3
#: A site closer than this to a node is on it [deg] (≈ 1 mm).
ON_NODE = 1e-8
#: A site this close to a cell edge (as a share of the squared spacing) is on it.
EDGE_SLACK = 1e-9
#: Relative tolerance for a TR equal to a grid return period.
TR_MATCH = 1e-9


@dataclass(frozen=True, eq=False)
class HazardGrid:
    """The hazard grid in memory.

    Attributes:
        source: the file it was read from (as the user gave it).
        lon, lat: node coordinates [deg], shape (n,).
        return_periods: the grid's TR [years], shape (9,).
        ag: peak ground acceleration on rock [g] (the file's g/10 divided by 10), shape (n, 9).
        F0: maximum spectral amplification [-], shape (n, 9).
        Tc_star: TC* [s], shape (n, 9).
    """

    source: str
    lon: np.ndarray
    lat: np.ndarray
    return_periods: np.ndarray
    ag: np.ndarray
    F0: np.ndarray
    Tc_star: np.ndarray

    @property
    def extent(self) -> str:
        """The grid's bounding box, for messages."""
        return (
            f"lon {self.lon.min():g}–{self.lon.max():g} E, "
            f"lat {self.lat.min():g}–{self.lat.max():g} N"
        )


class SiteHazard(NamedTuple):
    """ag [g], F0 [-], TC* [s] at a site for one return period."""

    ag: float
    F0: float
    Tc_star: float


def grid_path(option: str | None) -> str:
    """The grid file: the command-line option, else $ROCK_HAZARD_GRID, else an InputError.

    Args:
        option: the value of ``--hazard-grid`` (None when not given).
    """
    if option:
        return option
    env = os.environ.get(ROCK_HAZARD_GRID, "").strip()
    if env:
        return env
    raise InputError(
        "no hazard grid file given (rock does not ship the NTC grid, DM 14/01/2008 Allegato B)",
        where="hazard grid",
        allowed=f"--hazard-grid FILE or {ROCK_HAZARD_GRID}=FILE",
    )


def read_grid(path: str | Path) -> HazardGrid:
    """Read the grid file (the file edge of this module), once per process while the file is
    unchanged (a suite's limit states each read it; parsing its 10,751 lines takes ~0.3 s).

    Raises:
        InputError: the file cannot be read, or a line is malformed (names file and line).
    """
    try:
        stat = os.stat(path)
        key = (os.path.realpath(path), stat.st_mtime_ns, stat.st_size)
    except (OSError, ValueError):  # read_text says what is wrong with the path
        return parse_grid(read_text(path, "hazard grid file", GRID_LIMIT), source=str(path))
    return _read_grid_once(key, str(path))


@functools.lru_cache(maxsize=4)
def _read_grid_once(key: tuple[str, int, int], source: str) -> HazardGrid:
    """The grid of a file by its (real path, mtime, size): a file edited is read again."""
    return parse_grid(read_text(source, "hazard grid file", GRID_LIMIT), source=source)


def parse_grid(text: str, *, source: str = "<text>") -> HazardGrid:
    """Parse the text of a grid file (pure; see the module docstring for the format).

    Args:
        text: the whole file.
        source: the file name, for error messages.
    """
    rows: list[list[float]] = []
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith("%"):
            _check_header(stripped, source, number)
        elif stripped:
            rows.append(_parse_row(stripped, source, number))
    if not rows:
        raise InputError("no grid nodes in the file", file=source, allowed=_ROW_FORMAT)
    table = np.array(rows)
    values = table[:, 2:].reshape(len(rows), len(GRID_RETURN_PERIODS), 3)
    return HazardGrid(
        source=source,
        lon=table[:, 0].copy(),
        lat=table[:, 1].copy(),
        return_periods=np.array(GRID_RETURN_PERIODS),
        ag=values[:, :, 0] / AG_FILE_SCALE,
        F0=values[:, :, 1].copy(),
        Tc_star=values[:, :, 2].copy(),
    )


_ROW_FORMAT = f"{GRID_COLUMNS} numbers: lon, lat, then ag [g/10], F0, TC* [s] for TR = " + (
    ", ".join(f"{tr:g}" for tr in GRID_RETURN_PERIODS)
)


def _check_header(line: str, source: str, number: int) -> None:
    """A header naming return periods must name the grid's nine, in order."""
    tokens = re.findall(r"TR *= *([^\s,;]*)", line)
    bad = next((token for token in tokens if not _is_number(token)), None)
    if bad is not None:
        raise InputError(
            "a return period in the header is not a number",
            file=source,
            where=f"line {number}",
            value=bad,
            allowed="TR=<years> for " + ", ".join(f"{tr:g}" for tr in GRID_RETURN_PERIODS),
        )
    found = tuple(ascii_float(token) for token in tokens)
    if found and found != GRID_RETURN_PERIODS:
        raise InputError(
            "the header's return periods are not the grid's",
            file=source,
            where=f"line {number}",
            value=", ".join(f"{tr:g}" for tr in found),
            allowed=", ".join(f"{tr:g}" for tr in GRID_RETURN_PERIODS),
        )


def _parse_row(line: str, source: str, number: int) -> list[float]:
    tokens = line.split()
    if len(tokens) != GRID_COLUMNS:
        raise InputError(
            f"wrong number of columns ({len(tokens)})",
            file=source,
            where=f"line {number}",
            allowed=_ROW_FORMAT,
        )
    try:
        row = [ascii_float(token) for token in tokens]
    except ValueError:
        bad = next(t for t in tokens if not _is_number(t))
        raise InputError(
            "not a number", file=source, where=f"line {number}", value=bad, allowed=_ROW_FORMAT
        ) from None
    if not all(math.isfinite(x) for x in row) or min(row[2:]) <= 0.0:
        raise InputError(
            "ag, F0 and TC* must be finite numbers > 0",
            file=source,
            where=f"line {number}",
            allowed=_ROW_FORMAT,
        )
    return row


def _is_number(token: str) -> bool:
    try:
        ascii_float(token)
    except ValueError:
        return False
    return True


def grid_source(site: tuple[float, float]) -> Note:
    """Where a spectrum's ag, F0 and Tc* come from: the grid at the site (lon, lat)."""
    return Note("grid_source", "hazard grid at {lon:.4f} E, {lat:.4f} N", lon=site[0], lat=site[1])


def site_parameters(grid: HazardGrid, lon: float, lat: float, TR: float) -> SiteHazard:
    """ag [g], F0, TC* [s] at a site and return period, interpolated as in Allegato A.

    DM 14/01/2008, Allegato A (Eqs. 1 and 3); cell rule in the module docstring.

    Args:
        grid: the grid (:func:`read_grid`).
        lon: longitude, east [deg].
        lat: latitude, north [deg].
        TR: return period [years], 30 ≤ TR ≤ 2475.

    Raises:
        InputError: the site is outside the grid, or TR outside 30–2475 years.
    """
    lo, hi = _bracket(grid, TR)
    nodes = cell_nodes(grid, lon, lat)
    weights = _inverse_distance_weights(grid, nodes, lon, lat)
    at_lo = _in_space(grid, nodes, weights, lo)
    if hi == lo:
        return at_lo
    at_hi = _in_space(grid, nodes, weights, hi)
    TR1, TR2 = grid.return_periods[lo], grid.return_periods[hi]
    return SiteHazard(*(log_log(p1, p2, TR1, TR2, TR) for p1, p2 in zip(at_lo, at_hi, strict=True)))


def log_log(p1: float, p2: float, TR1: float, TR2: float, TR: float) -> float:
    """Return-period interpolation log p = log p1 + log(p2/p1)·log(TR/TR1)/log(TR2/TR1).

    DM 14/01/2008, Allegato A, Eq. 3.

    Args:
        p1, p2: the parameter at TR1 and TR2 (ag [g], F0 [-] or TC* [s]).
        TR1, TR2: the bracketing return periods [years].
        TR: the return period wanted [years].
    """
    exponent = math.log(TR / TR1) / math.log(TR2 / TR1)
    return p1 * (p2 / p1) ** exponent


def haversine(lon1: float, lat1: float, lon2: np.ndarray, lat2: np.ndarray) -> np.ndarray:
    """Great-circle angle between points [rad] (multiply by a radius for a length).

    Allegato A asks for the distance between site and vertices; the radius cancels in the
    inverse-distance weights.

    Args:
        lon1, lat1: one point [deg]. lon2, lat2: others [deg].
    """
    phi1, phi2 = math.radians(lat1), np.radians(lat2)
    dphi = phi2 - phi1
    dlam = np.radians(lon2) - math.radians(lon1)
    h = np.sin(dphi / 2) ** 2 + math.cos(phi1) * np.cos(phi2) * np.sin(dlam / 2) ** 2
    return 2.0 * np.arcsin(np.sqrt(np.clip(h, 0.0, 1.0)))


def _bracket(grid: HazardGrid, TR: float) -> tuple[int, int]:
    """Indices of the grid periods bracketing TR (equal when TR is a grid period)."""
    periods = grid.return_periods
    if not (
        math.isfinite(TR) and periods[0] * (1 - TR_MATCH) <= TR <= periods[-1] * (1 + TR_MATCH)
    ):
        raise InputError(
            "return period outside the hazard grid",
            where="TR",
            value=TR,
            allowed=f"{periods[0]:g} ≤ TR ≤ {periods[-1]:g} years (DM 14/01/2008, Allegato A)",
        )
    exact = np.flatnonzero(np.abs(periods - TR) <= TR_MATCH * periods)
    if exact.size:
        return int(exact[0]), int(exact[0])
    hi = int(np.searchsorted(periods, TR))
    return hi - 1, hi


def cell_nodes(grid: HazardGrid, lon: float, lat: float) -> np.ndarray:
    """Indices of the four vertices of the grid cell containing the site (one if on a node).

    DM 14/01/2008, Allegato A ("i 4 vertici della maglia elementare del reticolo"); the rule is
    in the module docstring.

    Args:
        grid: the grid. lon, lat: the site [deg].

    Raises:
        InputError: no cell of the grid contains the site.
    """
    x, y = _local_xy(grid, lon, lat)
    distance = np.hypot(x, y)
    n0 = int(np.argmin(distance))
    if distance[n0] <= ON_NODE:
        return np.array([n0])
    if distance[n0] > MESH_SPACING:
        raise _outside(grid, lon, lat)
    u, v = _mesh_axes(x, y, n0)
    if u is None or v is None:
        raise _outside(grid, lon, lat)
    s, t = np.linalg.solve(np.column_stack([u, v]), -np.array([x[n0], y[n0]]))
    for su, tv in _quadrants(s, t):
        cell = _match_vertices(x, y, n0, su * u, tv * v)
        if cell is not None and _contains_site(x[cell], y[cell]):
            return cell
    raise _outside(grid, lon, lat)


def _local_xy(grid: HazardGrid, lon: float, lat: float) -> tuple[np.ndarray, np.ndarray]:
    """Node positions relative to the site, east and north [deg of latitude]."""
    if not (math.isfinite(lon) and math.isfinite(lat)):
        raise _outside(grid, lon, lat)
    return (grid.lon - lon) * math.cos(math.radians(lat)), grid.lat - lat


def _mesh_axes(
    x: np.ndarray, y: np.ndarray, n0: int
) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Local mesh vectors u (east-ish) and v (north-ish), averaged over N0's edge neighbours."""
    dx, dy = x - x[n0], y - y[n0]
    gap = np.hypot(dx, dy)
    gap[n0] = np.inf
    near = np.flatnonzero(gap <= EDGE_NEIGHBOUR * gap.min())
    east, north = [], []
    for k in near:
        w = np.array([dx[k], dy[k]])
        if abs(w[0]) >= abs(w[1]):
            east.append(w * math.copysign(1.0, w[0]))
        else:
            north.append(w * math.copysign(1.0, w[1]))
    u = np.mean(east, axis=0) if east else None
    v = np.mean(north, axis=0) if north else None
    return u, v


def _quadrants(s: float, t: float) -> list[tuple[float, float]]:
    """Sides of N0 to try along (u, v): the site's own quadrant first, then the others.

    The others matter only for a site within a hair of a cell edge: the mesh is not exactly
    regular, so the averaged axes can point to the neighbouring cell there.
    """
    su, tv = (1.0 if s >= 0 else -1.0), (1.0 if t >= 0 else -1.0)
    return [(su, tv), (-su, tv), (su, -tv), (-su, -tv)]


def _contains_site(x: np.ndarray, y: np.ndarray) -> bool:
    """Whether the quadrilateral N0, N0+u, N0+v, N0+u+v (relative to the site) contains it."""
    ring = [0, 1, 3, 2]  # N0 → N0+u → N0+u+v → N0+v
    cross = [
        x[ring[i]] * y[ring[(i + 1) % 4]] - y[ring[i]] * x[ring[(i + 1) % 4]] for i in range(4)
    ]
    slack = EDGE_SLACK * MESH_SPACING**2
    return min(cross) >= -slack or max(cross) <= slack


def _match_vertices(
    x: np.ndarray, y: np.ndarray, n0: int, u: np.ndarray, v: np.ndarray
) -> np.ndarray | None:
    """N0 and the nodes at N0 + u, N0 + v, N0 + u + v; None if one is missing."""
    cell = [n0]
    tolerance = VERTEX_MATCH * math.hypot(*u)
    for offset in (u, v, u + v):
        gap = np.hypot(x - (x[n0] + offset[0]), y - (y[n0] + offset[1]))
        k = int(np.argmin(gap))
        if gap[k] > tolerance:
            return None
        cell.append(k)
    return np.array(cell)


def _outside(grid: HazardGrid, lon: float, lat: float) -> InputError:
    return InputError(
        "site outside the NTC hazard grid (no grid cell contains it)",
        where="site",
        value=f"lon {lon:g}, lat {lat:g}",
        allowed=f"a site inside the grid ({grid.extent}; the islands of Allegato B, "
        "Tabella 2 such as Sardinia are not in it)",
    )


def _inverse_distance_weights(
    grid: HazardGrid, nodes: np.ndarray, lon: float, lat: float
) -> np.ndarray:
    """w_i = (1/d_i) / Σ(1/d_j), d_i haversine (Allegato A, Eq. 1); one node: weight 1."""
    if nodes.size == 1:
        return np.ones(1)
    inverse = 1.0 / haversine(lon, lat, grid.lon[nodes], grid.lat[nodes])
    return inverse / inverse.sum()


def _in_space(grid: HazardGrid, nodes: np.ndarray, weights: np.ndarray, k: int) -> SiteHazard:
    return SiteHazard(
        ag=float(weights @ grid.ag[nodes, k]),
        F0=float(weights @ grid.F0[nodes, k]),
        Tc_star=float(weights @ grid.Tc_star[nodes, k]),
    )
