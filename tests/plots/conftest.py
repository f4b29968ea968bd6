"""Shared checks of the plot tests: a file is a PNG or an SVG that a reader accepts."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

#: The eight signature bytes every PNG file starts with (PNG specification, §5.2).
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: A figure of a few inches at the plots' 150 dpi is hundreds of pixels across; a reader that
#: returns less has read something else.
MIN_PIXELS = 300


def run(*args: str) -> tuple[int, str, str]:
    """Run rock in-process: (exit code, stdout, stderr)."""
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def needs_matplotlib() -> None:
    """Skip (with the reason) where matplotlib is not installed."""
    pytest.importorskip("matplotlib", reason="plots need matplotlib: pip install '.[plot]'")


def assert_png(path: Path) -> None:
    """A non-empty PNG that matplotlib's reader decodes to an RGB(A) image."""
    from matplotlib.image import imread

    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, data[:8]
    assert len(data) > 0
    image = imread(path)
    assert image.ndim == 3 and image.shape[2] in (3, 4), image.shape
    assert min(image.shape[:2]) >= MIN_PIXELS, image.shape


def assert_svg(path: Path) -> None:
    """A well-formed XML document whose root is an SVG element with drawing in it."""
    root = ET.parse(path).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg", root.tag
    assert len(list(root.iter())) > 10
