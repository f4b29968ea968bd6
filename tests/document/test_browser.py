"""The HTML report as a person sees it: rendered by a real browser (Debian's chromium,
headless), the screenshot is not blank, and every section and figure is in the rendered page.

Skips with its reason where chromium is not installed (.ci/run installs it with apt)."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
ALTAR = ROOT / "examples" / "altar.toml"
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
SECTIONS = ("identification", "model", "demand", "kinematic", "rocking", "comparison", "software")
FIGURES = ("sketch", "spectra", "capacity", "histories")
BROWSER = shutil.which("chromium") or shutil.which("chromium-browser")
#: Seconds a headless chromium may take to render the page.
TIMEOUT = 120

pytestmark = pytest.mark.skipif(BROWSER is None, reason="chromium is not installed (apt)")


def chromium(*args: str) -> subprocess.CompletedProcess[bytes]:
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             "--no-first-run", "--disable-dev-shm-usage"]  # fmt: skip
    return subprocess.run(
        [str(BROWSER), *flags, *args], capture_output=True, timeout=TIMEOUT, check=False
    )


@pytest.fixture(scope="module")
def browser_runs(tmp_path_factory: pytest.TempPathFactory) -> None:
    """Skip, with chromium's own words, where it is installed but cannot run (a sandbox
    without the kernel features it needs): a blank page must render first."""
    blank = tmp_path_factory.mktemp("probe") / "blank.html"
    blank.write_text("<!DOCTYPE html><title>probe</title><p>probe</p>", encoding="utf-8")
    try:
        done = chromium("--dump-dom", blank.as_uri())
    except subprocess.TimeoutExpired:
        pytest.skip(f"chromium did not render a blank page in {TIMEOUT} s here")
    if done.returncode != 0 or b"probe" not in done.stdout:
        tail = done.stderr.decode(errors="replace").strip().splitlines()[-1:] or ["no output"]
        pytest.skip(f"chromium cannot run here: {tail[0]}")


@pytest.fixture(scope="module")
def page(tmp_path_factory: pytest.TempPathFactory, browser_runs: None) -> Path:
    pytest.importorskip("matplotlib", reason="the report extra is not installed")
    pytest.importorskip("jinja2", reason="the report extra is not installed")
    html = tmp_path_factory.mktemp("browser") / "altar.html"
    result = CliRunner().invoke(
        cli, ["report", str(ALTAR), "--record", str(PULSE), "-o", str(html)]
    )
    assert result.exit_code == 0, result.stderr
    return html


def test_the_rendered_page_has_every_section_and_figure(page: Path) -> None:
    # --dump-dom prints the DOM after the browser parsed and laid out the page.
    done = chromium("--dump-dom", page.as_uri())
    assert done.returncode == 0, done.stderr.decode(errors="replace")[-2000:]
    dom = done.stdout.decode()
    for key in SECTIONS:
        assert f'id="{key}"' in dom, key
    for key in FIGURES:
        assert f'id="figure-{key}"' in dom, key
    assert dom.count("<svg") >= len(FIGURES)


def test_the_screenshot_is_not_blank(page: Path, tmp_path: Path) -> None:
    from PIL import Image

    shot = tmp_path / "first.png"
    done = chromium(f"--screenshot={shot}", "--window-size=1000,1400", page.as_uri())
    assert done.returncode == 0 and shot.exists(), done.stderr.decode(errors="replace")[-2000:]
    image = Image.open(shot).convert("L")
    histogram = image.histogram()
    ink = sum(histogram[:128]) / (image.width * image.height)
    # The first screen holds the title, the contents and the first tables: a few per cent of
    # it is dark (text, rules); a blank or failed page is all white.
    assert ink > 0.01
    assert image.getextrema()[0] < 60
