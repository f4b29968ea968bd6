"""The project a calculation report belongs to: client, subject, site, designer, the engineer's
own text sections (``[project]`` of a project file, ``rock init project``).

A *relazione di calcolo* filed with the Genio Civile or a municipality opens with who asked for
it (*committente*), what it is about (*oggetto*), where (*comune*, address, coordinates with
their datum) and who signs it (*progettista*, with the professional order and number), and
carries the designer's own premises, survey, materials and knowledge level. rock reads them
from a TOML file and places them: the cover, the sections before the analyses, the signature
block at the end.

Coordinates: the NTC hazard grid (DM 14/01/2008, Allegato B) is given in ED50; a phone or a
map gives WGS84. ``datum`` says which; WGS84 coordinates are converted to ED50 with pyproj
(PROJ's transformation between EPSG:4326 and EPSG:4230, the one PROJ picks for Italy), and the
report gives both.
"""

from __future__ import annotations

import datetime
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from rockcli.errors import InputError
from rockcli.inside import check_inside
from rockcli.textfile import check_size, open_regular, reason, too_large

#: The hazard grid's extent (DM 14/01/2008, Allegato B: nodes from 6.5 E to 18.5 E and from
#: 36.6 N to 47.1 N), widened by a tenth of a degree: a site outside it has no hazard.
LON_RANGE = (6.4, 18.6)
LAT_RANGE = (36.5, 47.2)
#: Markdown sections: each at most this size (a chapter of text, not a book).
SECTION_LIMIT = 256 * 1024
#: Where a section's file may be without --allow-outside.
INSIDE_ALLOWED = "a file inside the project file's folder, or --allow-outside"
#: What a section's file must be, wherever it is.
SECTION_ALLOWED = (
    "a Markdown file (UTF-8, at most 256 KiB, a regular file, not one of /proc or /sys), "
    "relative to the project file"
)
#: The kernel's own file systems: their "files" are the system's state (a process's
#: environment and its tokens, its memory map), never an engineer's text.
KERNEL_FOLDERS = ("/proc", "/sys")


class _Table(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class SectionEntry(_Table):
    """``[[project.sections]]``: a chapter of the engineer's own text."""

    title: str = Field(min_length=1, max_length=200, description="the section's title")
    file: str = Field(
        min_length=1, description="a Markdown file inside the project file's folder, relative to it"
    )


class ProjectTable(_Table):
    """``[project]``: who, what, where, by whom."""

    client: str = Field(min_length=1, max_length=300, description="committente")
    subject: str = Field(min_length=1, max_length=600, description="oggetto")
    comune: str = Field(min_length=1, max_length=200)
    address: str | None = Field(None, max_length=300)
    lon: float | None = Field(None, ge=LON_RANGE[0], le=LON_RANGE[1],
                              description="longitude [degrees east], in its datum")  # fmt: skip
    lat: float | None = Field(None, ge=LAT_RANGE[0], le=LAT_RANGE[1],
                              description="latitude [degrees north], in its datum")  # fmt: skip
    datum: Literal["WGS84", "ED50"] = "WGS84"
    designer: str = Field(min_length=1, max_length=200, description="progettista")
    designer_registration: str | None = Field(
        None, max_length=300, description="the designer's order and number"
    )
    date: datetime.date | None = None
    sections: tuple[SectionEntry, ...] = ()


class ProjectFile(_Table):
    """A project file: one ``[project]`` table."""

    project: ProjectTable


@dataclass(frozen=True)
class Project:
    """A project as the report uses it: the table, its sections' text and, for a site given
    in WGS84, its ED50 coordinates (the hazard grid's)."""

    table: ProjectTable
    sections: tuple[tuple[str, str], ...]
    ed50: tuple[float, float] | None


def load_project(path: str | os.PathLike[str], *, allow_outside: bool = False) -> Project:
    """Read and check a project file and its Markdown sections (InputError, one line each:
    unknown keys, a datum that is neither WGS84 nor ED50, coordinates outside Italy's grid,
    a section that is not a readable file or, unless ``allow_outside``, lies outside the
    project file's folder).

    Args:
        path: the project file.
        allow_outside: let a section's file lie outside the project file's folder (an
            absolute path, ``..``, a link to elsewhere: ``--allow-outside``). A project file
            received from someone else otherwise reads only its own folder's files. A file
            of the kernel (``/proc``, ``/sys``) or one that is not a regular file is refused
            either way.
    """
    from rockcli.model.load import read_toml, translate_errors

    file = os.fspath(path)
    data = read_toml(file)
    try:
        table = ProjectFile.model_validate(data).project
    except ValidationError as exc:
        raise translate_errors(exc.errors(), file) from None
    if (table.lon is None) != (table.lat is None):
        raise InputError("give both lon and lat, or neither", file=file,
                         where="project.lon" if table.lon is None else "project.lat")  # fmt: skip
    base = Path(file).parent
    sections = tuple(
        (entry.title, section_text(base, entry.file, file, k, allow_outside))
        for k, entry in enumerate(table.sections)
    )
    ed50 = None
    if table.lon is not None and table.lat is not None:
        ed50 = (table.lon, table.lat) if table.datum == "ED50" else to_ed50(table.lon, table.lat)
    return Project(table, sections, ed50)


def section_text(base: Path, given: str, file: str, index: int, allow_outside: bool) -> str:
    """The text of section ``index``, whose file is ``given`` relative to ``base`` (the project
    file's folder): refused outside it (``..`` and every symlink resolved, rockcli.inside)
    unless ``allow_outside``."""
    path = base / given
    if not allow_outside:
        check_inside(
            path, base, file=file, where=f"project.sections[{index}].file", value=given,
            problem="leaves the project file's folder", allowed=INSIDE_ALLOWED,
        )  # fmt: skip
    return read_section(path, file, index)


def read_section(path: Path, file: str, index: int) -> str:
    """The Markdown text of section ``index`` (InputError naming its key)."""
    try:
        return read_markdown(path).decode("utf-8")
    except (OSError, ValueError) as exc:
        problem = reason(exc)
    except InputError as exc:  # not a regular file, too large, the kernel's
        problem = exc.problem
    raise InputError(
        f"cannot read the section's file: {problem}",
        file=file,
        where=f"project.sections[{index}].file",
        value=str(path),
        allowed=SECTION_ALLOWED,
    )


def read_markdown(path: Path) -> bytes:
    """The bytes of a regular file of at most :data:`SECTION_LIMIT` bytes that is not the
    kernel's (rockcli.textfile.read_limited, and :func:`kernel_file` on the descriptor read).

    Raises:
        InputError: not a regular file, too large, or a file of ``/proc`` or ``/sys``.
        OSError, ValueError: the system refuses the path.
    """
    what = "Markdown file"
    fd = open_regular(path, what)
    with os.fdopen(fd, "rb") as handle:
        info = os.fstat(fd)
        if kernel_file(info.st_dev):
            raise InputError("a file of the kernel (/proc, /sys): the system's state, not text")
        check_size(info.st_size, path, what, SECTION_LIMIT)
        data = handle.read(SECTION_LIMIT + 1)
    if len(data) > SECTION_LIMIT:
        raise too_large(f"more than {SECTION_LIMIT:,}", path, what, SECTION_LIMIT)
    if data and info.st_size == 0:  # a pseudo file system the device test does not know
        raise InputError("its size says 0 bytes but it holds some: a file the system makes")
    return data


def kernel_file(device: int) -> bool:
    """Whether a file on ``device`` is one of the kernel's file systems (/proc, /sys, where
    mounted)."""
    for folder in KERNEL_FOLDERS:
        try:
            if os.path.ismount(folder) and os.stat(folder).st_dev == device:
                return True
        except OSError:
            continue
    return False


def to_ed50(lon: float, lat: float) -> tuple[float, float]:
    """WGS84 (EPSG:4326) → ED50 (EPSG:4230) longitude and latitude [degrees] (pyproj)."""
    from rockcli.errors import install_hint

    try:
        from pyproj import Transformer
    except ImportError:
        raise InputError(
            "WGS84 coordinates need pyproj to be converted to ED50 (the hazard grid's datum)",
            where="project.datum",
            value="WGS84",
            allowed=f'{install_hint("report")}, or give the coordinates in ED50 (datum = "ED50")',
        ) from None
    transformer = Transformer.from_crs("EPSG:4326", "EPSG:4230", always_xy=True)
    x, y = transformer.transform(lon, lat)
    return float(x), float(y)


TEMPLATE = """\
# The project of a calculation report (rock report --project project.toml).
# Every key below is read; delete the optional ones you do not need.

[project]
client = "Parrocchia di San Pietro"             # committente
subject = "Verifica dei meccanismi locali della facciata della chiesa di San Pietro"
comune = "L'Aquila (AQ)"
address = "Piazza San Pietro 1"                  # optional
lon = 13.3995                                    # optional, degrees east
lat = 42.3498                                    # optional, degrees north
datum = "WGS84"                                  # "WGS84" (a phone, a map) or "ED50" (the grid)
designer = "Ing. Maria Rossi"                    # progettista
designer_registration = "Ordine degli Ingegneri della Provincia dell'Aquila, n. 1234"
# date = 2027-01-15                              # optional; default: the day of the report

# The engineer's own text, in Markdown, placed before the analyses in this order. Each file
# lies in this file's folder or below it (rock report --allow-outside lifts that).
# [[project.sections]]
# title = "Premessa"
# file = "premessa.md"
"""
