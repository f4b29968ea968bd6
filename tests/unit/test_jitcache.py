"""numba's cache is keyed on every source the kernels compile (rockcli.jitcache).

Seen before the fix: an edit of mechanics.py (a formula the kernel compiles in) left the
cached kernel in use, and the run's numbers did not change.
"""

from __future__ import annotations

import shutil
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
