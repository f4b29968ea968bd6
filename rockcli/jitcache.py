"""Where numba caches rock's compiled kernels: a folder keyed on the kernels' own sources.

numba invalidates a cached function when *its* source file changes, not when a function it
compiles in from another file does: the kernel inlines the formulas of mechanics.py and
dynamics/rules.py, so an edit there would leave a stale kernel in the cache and give silently
wrong numbers (seen: doubling a spring moment in mechanics.py changed nothing). The cache
folder is therefore named after a digest of every source the kernels compile, so any edit
starts a fresh cache.

The folder is under ``$NUMBA_CACHE_DIR`` when set, else under the package's ``__pycache__``
when writable, else under the user's cache folder (``$XDG_CACHE_HOME`` or ``~/.cache``).
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
#: Every file whose code the compiled kernels contain.
KERNEL_SOURCES = (
    "mechanics.py",
    "dynamics/rules.py",
    "dynamics/layout.py",
    "dynamics/kernel.py",
    "codecheck/response_kernel.py",
)


def sources_digest() -> str:
    """A short digest of the kernels' sources."""
    from rockcli import __version__

    digest = hashlib.sha256(__version__.encode())
    for name in KERNEL_SOURCES:
        digest.update(name.encode())
        try:
            digest.update((PACKAGE / name).read_bytes())
        except OSError:  # an install without sources: the version alone keys the cache
            pass
    return digest.hexdigest()[:16]


def cache_base() -> Path:
    """The folder under which the keyed cache folder goes."""
    env = os.environ.get("NUMBA_CACHE_DIR")
    if env:
        return Path(env)
    local = PACKAGE / "__pycache__"
    try:
        local.mkdir(exist_ok=True)
        if os.access(local, os.W_OK):
            return local
    except OSError:
        pass
    user = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(user) / "rock"


def configure() -> None:
    """Point numba's cache at the keyed folder; call before any ``njit(cache=True)``."""
    from numba.core import config

    base = cache_base()
    folder = base / f"numba-{sources_digest()}"
    if base == PACKAGE / "__pycache__":
        prune(base, keep=folder)
    config.CACHE_DIR = str(folder)  # type: ignore[attr-defined]


def prune(base: Path, keep: Path) -> None:
    """Remove the package's caches of earlier sources (this install's own folder only)."""
    import shutil

    for old in base.glob("numba-*"):
        if old != keep:
            shutil.rmtree(old, ignore_errors=True)
