"""numba's cache is keyed on every source the kernels compile (rockcli.jitcache).

Seen before the fix: an edit of mechanics.py (a formula the kernel compiles in) left the
cached kernel in use, and the run's numbers did not change.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from rockcli import jitcache


@pytest.fixture
def package_copy(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    for name in jitcache.KERNEL_SOURCES:
        target = tmp_path / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(jitcache.PACKAGE / name, target)
    monkeypatch.setattr(jitcache, "PACKAGE", tmp_path)
    return tmp_path


def test_digest_follows_every_kernel_source(package_copy: Path) -> None:
    before = jitcache.sources_digest()
    for name in jitcache.KERNEL_SOURCES:
        path = package_copy / name
        original = path.read_bytes()
        path.write_bytes(original + b"\n# edited\n")
        assert jitcache.sources_digest() != before, name
        path.write_bytes(original)
    assert jitcache.sources_digest() == before


def test_cache_base_honours_numba_cache_dir(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    assert jitcache.cache_base() == tmp_path


def test_prune_keeps_only_the_current_folder(tmp_path: Path) -> None:
    for name in ("numba-old1", "numba-old2", "numba-new", "other"):
        (tmp_path / name).mkdir()
    jitcache.prune(tmp_path, keep=tmp_path / "numba-new")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["numba-new", "other"]


# A read-only install with an unwritable home (issue 7, item 10). Root ignores permission bits,
# so "unwritable" is a path under a regular file: mkdir fails there for everyone.
UNDER_A_FILE = "/etc/passwd/rock-cache"
ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "one-sine_Tp1s_0.35g.txt"
#: Run ``rock assess`` as a read-only install would: numba's fallback beside the sources
#: (its in-tree locator) is unavailable, as in a read-only site-packages; then report NOTE.
READ_ONLY_RUN = """
import runpy, sys, tempfile
import numba.core.caching as caching
caching.InTreeCacheLocator.from_function = classmethod(lambda cls, f, p: None)
if sys.argv[1] == "no-temp":
    tempfile.tempdir = sys.argv[2]
sys.argv = ["rock", "assess", sys.argv[3], "--record", sys.argv[4]]
try:
    runpy.run_module("rockcli", run_name="__main__")
finally:
    from rockcli import jitcache
    print("NOTE:", jitcache.NOTE, file=sys.stderr)
"""


@pytest.fixture
def fresh_configure(monkeypatch: pytest.MonkeyPatch) -> None:
    """Let configure() probe again, and restore numba's cache folder afterwards."""
    from numba.core import config

    monkeypatch.setattr(config, "CACHE_DIR", config.CACHE_DIR)
    monkeypatch.setattr(jitcache, "_configured", False)
    monkeypatch.setattr(jitcache, "CACHE", True)
    monkeypatch.setattr(jitcache, "NOTE", None)


def test_writable_is_probed_by_writing(tmp_path: Path) -> None:
    assert jitcache.writable(tmp_path / "a" / "b")
    assert not jitcache.writable(Path(UNDER_A_FILE) / "x")


@pytest.mark.usefixtures("fresh_configure")
def test_an_unwritable_cache_falls_back_to_a_private_temporary_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from numba.core import config

    monkeypatch.setenv("NUMBA_CACHE_DIR", UNDER_A_FILE)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    assert jitcache.configure() is True
    folder = Path(config.CACHE_DIR)
    assert folder.parent == tmp_path and folder.name.startswith("rock-numba-")
    assert folder.stat().st_mode & 0o777 == jitcache.PRIVATE_MODE
    assert (
        jitcache.NOTE is not None
        and UNDER_A_FILE in jitcache.NOTE
        and str(folder) in (jitcache.NOTE)
    )


@pytest.mark.usefixtures("fresh_configure")
def test_no_writable_folder_at_all_compiles_uncached(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NUMBA_CACHE_DIR", UNDER_A_FILE)
    monkeypatch.setattr(tempfile, "tempdir", UNDER_A_FILE)
    assert jitcache.configure() is False
    assert jitcache.CACHE is False
    assert jitcache.NOTE is not None and "compiled again in every run" in jitcache.NOTE


@pytest.mark.skipif(not hasattr(os, "getuid"), reason="POSIX ownership and permission bits")
def test_a_temporary_folder_others_can_write_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """numba's cache files are pickles: a planted folder or link must not be used."""
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    planted = tmp_path / f"rock-numba-{os.getuid()}-abc"
    planted.mkdir()
    planted.chmod(0o777)
    assert jitcache.private_temp_folder("abc") is None
    (tmp_path / "elsewhere").mkdir(mode=0o700)
    (tmp_path / f"rock-numba-{os.getuid()}-lnk").symlink_to(tmp_path / "elsewhere")
    assert jitcache.private_temp_folder("lnk") is None
    assert jitcache.private_temp_folder("fresh") == tmp_path / f"rock-numba-{os.getuid()}-fresh"


@pytest.mark.parametrize("mode", ["temp", "no-temp"])
def test_assess_runs_from_a_read_only_install(tmp_path: Path, mode: str) -> None:
    env = {k: v for k, v in os.environ.items() if k not in ("XDG_CACHE_HOME", "NUMBA_CACHE_DIR")}
    env.update(NUMBA_CACHE_DIR=UNDER_A_FILE, HOME=UNDER_A_FILE + "/home", TMPDIR=str(tmp_path))
    args = [mode, UNDER_A_FILE + "/tmp", str(ROOT / "examples" / "wall.toml"), str(PULSE)]
    done = subprocess.run(
        [sys.executable, "-c", READ_ONLY_RUN, *args],
        env=env,
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert "Traceback" not in done.stderr
    note = done.stderr.rsplit("NOTE:", 1)[1]
    # The CLI tells the user, on stderr, once (cli/main.py show_cache_note).
    shown = done.stderr.rsplit("NOTE:", 1)[0]
    assert shown.count("note: ") == 1 and ("cache" in shown.split("note: ")[1])
    if mode == "temp":
        assert f"cached in {tmp_path}" in note
        # numba's cache index, written there
        assert any(next(tmp_path.glob("rock-numba-*")).rglob("*.nbi"))
    else:
        assert "compiled again in every run" in note
